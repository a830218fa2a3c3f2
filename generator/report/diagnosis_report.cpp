// SPDX-License-Identifier: MIT
#include "report/diagnosis_report.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "plot/format.hpp"
#include "report/page.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

namespace admitgen::report {
namespace {

using diagnosis::BandEdges;
using diagnosis::BandGapRecord;
using diagnosis::DiagnosisRecord;
using diagnosis::StageRecord;
using plot::escape_xml;
using plot::number;

/// A band's nominal centre in Hz without trailing zeros: 630, 1250, 31.5.
std::string nominal(double f_center) { return fmt::format("{:.6g}", plot::nominal_band(f_center)); }

std::string band_text(const BandEdges& band) {
  return fmt::format("{} Hz band ({}–{} Hz)", nominal(band.f_center), number(band.f_lo, 3), number(band.f_hi, 3));
}

/// Bars of one gap-per-band list on a log axis, each shrunk around its band's log-centre by `keep`
/// (fraction of the band's log-width), so that before and after sit side by side in one band.
plot::Series band_bars(const std::string& name, const std::string& label, const std::string& tone,
                       const std::vector<BandGapRecord>& bands, double keep) {
  std::vector<double> lo, hi, gap;
  for (const auto& b : bands) {
    const double a = b.band.f_lo, c = b.band.f_hi;
    const double half = 0.5 * keep * std::log(c / a), mid = 0.5 * std::log(a * c);
    lo.push_back(std::exp(mid - half));
    hi.push_back(std::exp(mid + half));
    gap.push_back(b.gap);
  }
  return plot::bars(name, label, tone, lo, hi, gap);
}

plot::Figure gap_figure(const DiagnosisRecord& d) {
  plot::Figure fig("fig-gap", "Gap per one-third-octave band before and after the best effect");
  fig.x.label = "one-third-octave band [Hz]";
  fig.x.kind = plot::ScaleKind::log;
  fig.x.style = plot::LabelStyle::hertz;
  fig.y.label = "gap (relative complex error)";
  fig.y.kind = plot::ScaleKind::linear;
  fig.y.style = plot::LabelStyle::plain;
  fig.y.include_zero = true;
  const auto& bands = d.gap.bands;
  if (!bands.empty()) {  // the axis spans the bands' edges, not just the bars, and names each band
    fig.x.lo = bands.front().band.f_lo;
    fig.x.hi = bands.back().band.f_hi;
    for (const auto& b : bands) {
      const double centre = b.band.f_center;
      fig.x.ticks.push_back({centre, plot::hz_label(plot::nominal_band(centre)), false});
    }
  }
  fig.add(band_bars("before", "no effect", "data", bands, 0.84));
  if (!d.effects.empty())
    fig.add(band_bars("after", "with " + d.effects[0].effect, "c1", d.effects[0].bands_after, 0.46));
  return fig;
}

plot::Figure stage_figure(const std::vector<StageRecord>& stages) {
  plot::Figure fig("fig-stages", "Gap added by each pipeline stage and cumulative gap", 720.0, 300.0);
  std::vector<double> lo, hi, own, x, cumulative;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const double c = static_cast<double>(i);
    fig.x.categories.push_back(stages[i].stage);
    lo.push_back(c - 0.3);
    hi.push_back(c + 0.3);
    own.push_back(stages[i].gap);
    x.push_back(c);
    cumulative.push_back(stages[i].cumulative_gap);
  }
  fig.x.label = "pipeline stage";
  fig.y.label = "gap (relative complex error)";
  fig.y.kind = plot::ScaleKind::linear;
  fig.y.style = plot::LabelStyle::plain;
  fig.y.include_zero = true;
  fig.add(plot::bars("stage", "gap of this stage", "c1", lo, hi, own));
  fig.add(plot::line("cumulative", "cumulative gap up to this stage", "c2", x, cumulative));
  fig.add(plot::markers("cumulative-points", "", "c2", x, cumulative));
  return fig;
}

std::string parameters_text(const diagnosis::EffectRecord& effect) {
  std::string out;
  for (const auto& s : effect.parameter_summary) {
    out += fmt::format("{}<code>{}</code> = {} ± {}", out.empty() ? "" : "<br/>", escape_xml(s.name), number(s.mean),
                       number(s.std, 2));
    out += fmt::format(" <span class=\"muted\">[{}, {}]</span>", number(s.ci95_lo), number(s.ci95_hi));
  }
  for (const auto& [name, v] : effect.fixed_parameters)
    out += fmt::format("{}<code>{}</code> = {} (fixed)", out.empty() ? "" : "<br/>", escape_xml(name), number(v));
  return out.empty() ? "—" : out;
}

/// "edge_gap (width_m = 0.001, depth_m = 0.05)".
std::string explanation_member_text(const diagnosis::ExplanationMemberRecord& m) {
  std::string params;
  for (const auto& [name, value] : m.parameters) params += fmt::format("{}{} = {}", params.empty() ? "" : ", ", name, number(value));
  return params.empty() ? m.effect : fmt::format("{} ({})", m.effect, params);
}

std::string explanation_table(const DiagnosisRecord& d) {
  Table t{{"step", "effect", "parameters (joint posterior mean)", "Bayes factor against the explanation without it [dB]",
           "shrink it adds", "share of the squared gap"},
          {}, {0, 3, 4, 5}, {}, {}};
  const auto share_of = [&d](std::size_t k) {
    for (const auto& s : d.verdict.shares)
      if (static_cast<std::size_t>(s.member) == k) return fmt::format("{:.2f}", s.share);
    return std::string("—");
  };
  for (std::size_t k = 0; k < d.verdict.explanation.size(); ++k) {
    const auto& m = d.verdict.explanation[k];
    std::string params;
    for (const auto& [name, value] : m.parameters)
      params += fmt::format("{}<code>{}</code> = {}", params.empty() ? "" : "<br/>", escape_xml(name), number(value));
    t.rows.push_back({std::to_string(k + 1), "<code>" + escape_xml(m.effect) + "</code>", params.empty() ? "—" : params,
                      fmt::format("{:.1f}", m.log_bayes_factor_deciban), fmt::format("{:.2f}×", m.shrink_added),
                      share_of(k)});
  }
  t.caption = fmt::format(
      "Effects added one at a time, each fitted jointly with those before it and kept only if decisively (≥ 20 dB) "
      "better than the explanation without it (a member that stops earning its place is dropped again); the share "
      "is the member's part of the squared gap at the joint fit (its Shapley value; the shares add up to the "
      "explained fraction). Whole "
      "explanation: shrink {}×, {} % of the squared gap, residual {}.",
      fmt::format("{:.2f}", d.verdict.shrink), fmt::format("{:.0f}", 100.0 * d.verdict.explained_fraction),
      d.verdict.residual_white_after ? "white" : "structured");
  return html(t);
}

std::string effect_table(const DiagnosisRecord& d) {
  Table t{{"rank", "effect", "Bayes factor [dB]", "gap after", "shrink", "explained", "worst band [Hz]", "parameters (posterior)"},
          {}, {0, 2, 3, 4, 5}, {}, {}};
  int rank = 1;
  for (const auto& e : d.effects) {
    t.rows.push_back({std::to_string(rank++), "<code>" + escape_xml(e.effect) + "</code>",
                      fmt::format("{:.1f}{}", e.log_bayes_factor_deciban, e.stopped_early.value_or(false) ? " (stopped early)" : ""),
                      number(e.gap_after, 4),
                      fmt::format("{:.2f}×", e.shrink), fmt::format("{:.0f} %", 100.0 * e.explained_fraction),
                      nominal(e.band.f_center), parameters_text(e)});
    t.row_classes.push_back(e.effect == d.verdict.effect ? "selected" : "");
  }
  t.caption = fmt::format(
      "Effects ranked by the Bayes factor of the simulated side plus the effect against the simulated side alone. "
      "Gap before: {}. Shrink = gap before / gap after over the whole data; explained = share of the squared gap "
      "removed. Decision rule: {}. An effect marked \"stopped early\" stayed far below the leading evidence, so its "
      "sampling was cut short and its Bayes factor is the estimate at the stop.",
      number(d.gap.total, 4), escape_xml(d.verdict.rule));
  return html(t);
}

std::string stage_table(const std::vector<StageRecord>& stages) {
  Table t{{"stage", "gap of this stage", "cumulative gap", "worst band", "detail"}, {}, {1, 2}, {}, {}};
  for (const auto& s : stages)
    t.rows.push_back({escape_xml(s.stage), number(s.gap, 4), number(s.cumulative_gap, 4),
                      escape_xml(band_text(s.worst_band)), escape_xml(s.detail.value_or(""))});
  return html(t);
}

std::string gap_summary(const diagnosis::GapRecord& gap) {
  const auto& w = gap.whiteness;
  return definitions(
      {{"gap", fmt::format("{} (real part {}, imaginary part {})", number(gap.total, 4), number(gap.total_re, 4),
                           number(gap.total_im, 4))},
       {"metric", escape_xml(gap.metric)},
       {"largest |Δα|", number(gap.delta_alpha_max, 3)},
       {"worst band", escape_xml(band_text(gap.worst_band))},
       {"residual", fmt::format("{} (lag-1 autocorrelation {}, z = {})", w.white ? "white" : "structured",
                                number(w.lag1, 3), number(w.z, 3))}});
}

std::string provenance(const DiagnosisRecord& d) {
  const auto& in = d.input;
  const auto& s = d.settings;
  return definitions(
      {{"measured", "<code>" + escape_xml(in.real_path) + "</code>"},
       {"SHA-256", "<code>" + escape_xml(in.real_sha256) + "</code>"},
       {"simulated", escape_xml(in.sim)},
       {"points", fmt::format("{} from {} Hz to {} Hz", in.points, number(in.f_min_hz), number(in.f_max_hz))},
       {"sampler", fmt::format("nested sampling, {} live points, Δln Z {}, seed {}", s.live, plot::json_number(s.dlogz),
                               s.seed)},
       {"likelihood", escape_xml(s.likelihood)},
       {"admitgen", escape_xml(d.version)}});
}

/// "mic_mismatch", or "material 1.sigma" for a catalogue member.
std::string share_member_text(const diagnosis::VerdictRecord& v, const diagnosis::ShareRecord& s) {
  const auto& m = v.explanation[static_cast<std::size_t>(s.member)];
  return m.effect == "material" && !m.parameters.empty() ? m.effect + " " + m.parameters.front().first : m.effect;
}

/// " Dropped: …" naming the members the backward step took out ("" when none).
std::string dropped_text(const diagnosis::VerdictRecord& v) {
  std::string out;
  for (const auto& d : v.dropped)
    out += fmt::format("{}{}{} ({} dB)", out.empty() ? "" : ", ", d.effect, d.parameter ? " " + *d.parameter : "",
                       number(d.log_bayes_factor_deciban, 3));
  return out.empty() ? out
                     : " Dropped, because the explanation with them was within the 20 dB decision margin of the one "
                       "without them (the one with fewer parameters is kept): " + out + ".";
}

}  // namespace

std::string verdict_sentence(const DiagnosisRecord& d) {
  const auto& v = d.verdict;
  if (v.effect == "none") {
    if (d.effects.empty()) return "No effect was tested, so the gap stays unexplained.";
    return fmt::format(
        "No tested effect is decisively supported: the best, {}, reaches {} dB against no effect (the rule asks for 20 dB), "
        "so the gap of {} is left unexplained.",
        d.effects[0].effect, number(d.effects[0].log_bayes_factor_deciban, 3), number(d.gap.total, 3));
  }
  if (v.effect == "unexplained" && v.explanation.empty())
    return fmt::format(
        "The gap of {} is real but unexplained: its residual is structured, and no tested effect is decisively supported "
        "({}), so the cause lies outside the tested effects.",
        number(d.gap.total, 3),
        d.effects.empty() ? std::string("none was tested")
                          : fmt::format("the best, {}, reaches {} dB against no effect; the rule asks for 20 dB",
                                        d.effects[0].effect, number(d.effects[0].log_bayes_factor_deciban, 3)));
  std::string members;
  for (std::size_t k = 0; k < v.explanation.size(); ++k)
    members += (k == 0 ? "" : k + 1 == v.explanation.size() ? " and " : ", ") + explanation_member_text(v.explanation[k]);
  if (v.effect == "unexplained" && v.main_cause)
    return fmt::format(
        "Main cause {} ({} of the squared gap), structure left: the best explanation the vocabulary offers, {}, "
        "shrinks the gap {}× ({} % of the squared gap) and still leaves structure in the residual, so part of the "
        "cause lies outside the tested effects.{}",
        share_member_text(v, *v.main_cause), fmt::format("{:.2f}", v.main_cause->share), members,
        fmt::format("{:.2f}", v.shrink), fmt::format("{:.0f}", 100.0 * v.explained_fraction), dropped_text(v));
  if (v.effect == "unexplained")
    return fmt::format(
        "The gap is real but unexplained: the best explanation the vocabulary offers, {}, shrinks it {}× ({} % of the "
        "squared gap) and still leaves structure in the residual, so the cause lies outside the tested effects.{}",
        members, fmt::format("{:.2f}", v.shrink), fmt::format("{:.0f}", 100.0 * v.explained_fraction), dropped_text(v));
  return fmt::format(
      "The gap is explained by {} (the first alone: Bayes factor {} dB against no effect{}): together they shrink the "
      "gap {}× ({} % of the squared gap), most in the {}{}.",
      members, number(v.log_bayes_factor_deciban, 4),
      v.margin_deciban ? fmt::format(", {} dB ahead of the next", number(*v.margin_deciban, 3)) : std::string(),
      fmt::format("{:.2f}", v.shrink), fmt::format("{:.0f}", 100.0 * v.explained_fraction), band_text(v.band),
      v.residual_white_after ? "; the residual left is white" : "; structure is left in the residual") +
         dropped_text(v);
}

std::vector<plot::Figure> diagnosis_figures(const DiagnosisRecord& d) {
  std::vector<plot::Figure> out{gap_figure(d)};
  if (!d.stages.empty()) out.push_back(stage_figure(d.stages));
  return out;
}

std::string diagnosis_report_html(const DiagnosisRecord& d) {
  if (d.gap.bands.empty()) throw InputError("diagnosis report: no gap bands (is it an admitgen.diagnosis file?)");
  const auto figures = diagnosis_figures(d);
  const std::string real = std::filesystem::path(d.input.real_path).filename().string();
  std::string body = fmt::format("<h1>Diagnosis of <code>{}</code></h1>\n", escape_xml(real));
  body += fmt::format("<p class=\"muted\">Measured against {}.</p>\n", escape_xml(d.input.sim));
  body += "<p class=\"verdict\"><strong>Verdict.</strong> " + escape_xml(verdict_sentence(d)) + "</p>\n";
  body += warnings_box(d.input.warnings);
  body += "<h2>Gap per one-third-octave band</h2>\n" +
          figure(figures[0].svg(),
                 d.effects.empty() ? std::string("Gap between measured and simulated admittance in each band.")
                                   : fmt::format("Gap between measured and simulated admittance in each band, without an "
                                                 "effect and with the best-supported one (<code>{}</code>) added at its "
                                                 "posterior mean.",
                                                 escape_xml(d.effects[0].effect))) +
          gap_summary(d.gap);
  body += "<h2>Pipeline stages</h2>\n";
  if (d.stages.empty())
    body += "<p class=\"muted\">No stage attribution: a diagnosis against a fit (fit.json) at a sample rate shows how "
            "much the fit, discretization, quantization and simulation each add.</p>\n";
  else
    body += figure(figures[1].svg(), "Gap that each stage of fit → filter → fixed point → simulation adds on its own, and "
                                     "the cumulative gap after it.") +
            stage_table(d.stages);
  if (!d.verdict.explanation.empty())
    body += std::string("<h2>") + (d.verdict.effect == "unexplained" ? "Best attempt at an explanation" : "Explanation") +
            "</h2>\n" + explanation_table(d);
  body += "<h2>Effects</h2>\n" + effect_table(d);
  body += "<h2>Input and settings</h2>\n" + provenance(d);
  return page("admitgen diagnosis: " + real, body);
}

std::string write_diagnosis_report(const std::string& dir, const DiagnosisRecord& d) {
  const std::string path = (std::filesystem::path(dir) / "diagnosis.html").string();
  write_file_atomically(path, diagnosis_report_html(d));
  return path;
}

}  // namespace admitgen::report
