// SPDX-License-Identifier: MIT
#include "report/diagnosis_report.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "plot/format.hpp"
#include "report/page.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace admitgen::report {
namespace {

using Json = nlohmann::ordered_json;
using plot::escape_xml;
using plot::number;

std::string text_of(const Json& j, const char* key, const std::string& fallback = "?") {
  if (!j.contains(key) || j[key].is_null()) return fallback;
  return j[key].is_string() ? j[key].get<std::string>() : j[key].dump();
}

/// A band's nominal centre in Hz without trailing zeros: 630, 1250, 31.5.
std::string nominal(double f_center) { return fmt::format("{:.6g}", plot::nominal_band(f_center)); }

std::string band_text(const Json& band) {
  return fmt::format("{} Hz band ({}–{} Hz)", nominal(band.value("f_center", 1.0)),
                     number(band.value("f_lo", 0.0), 3), number(band.value("f_hi", 0.0), 3));
}

/// Bars of one gap-per-band list on a log axis, each shrunk around its band's log-centre by `keep`
/// (fraction of the band's log-width), so that before and after sit side by side in one band.
plot::Series band_bars(const std::string& name, const std::string& label, const std::string& tone, const Json& bands,
                       double keep) {
  std::vector<double> lo, hi, gap;
  for (const auto& b : bands) {
    const double a = b.value("f_lo", std::nan("")), c = b.value("f_hi", std::nan(""));
    const double half = 0.5 * keep * std::log(c / a), mid = 0.5 * std::log(a * c);
    lo.push_back(std::exp(mid - half));
    hi.push_back(std::exp(mid + half));
    gap.push_back(b.value("gap", std::nan("")));
  }
  return plot::bars(name, label, tone, lo, hi, gap);
}

plot::Figure gap_figure(const Json& d) {
  plot::Figure fig("fig-gap", "Gap per one-third-octave band before and after the best effect");
  fig.x.label = "one-third-octave band [Hz]";
  fig.x.kind = plot::ScaleKind::log;
  fig.x.style = plot::LabelStyle::hertz;
  fig.y.label = "gap (relative complex error)";
  fig.y.kind = plot::ScaleKind::linear;
  fig.y.style = plot::LabelStyle::plain;
  fig.y.include_zero = true;
  const Json& bands = d["gap"]["bands"];
  if (!bands.empty()) {  // the axis spans the bands' edges, not just the bars, and names each band
    fig.x.lo = bands.front().value("f_lo", 1.0);
    fig.x.hi = bands.back().value("f_hi", 2.0);
    for (const auto& b : bands) {
      const double centre = b.value("f_center", 1.0);
      fig.x.ticks.push_back({centre, plot::hz_label(plot::nominal_band(centre)), false});
    }
  }
  fig.add(band_bars("before", "no effect", "data", bands, 0.84));
  const Json effects = d.value("effects", Json::array());
  if (!effects.empty())
    fig.add(band_bars("after", "with " + effects[0].value("effect", std::string("?")), "c1",
                      effects[0].value("bands_after", Json::array()), 0.46));
  return fig;
}

plot::Figure stage_figure(const Json& stages) {
  plot::Figure fig("fig-stages", "Gap added by each pipeline stage and cumulative gap", 720.0, 300.0);
  std::vector<double> lo, hi, own, x, cumulative;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const double c = static_cast<double>(i);
    fig.x.categories.push_back(stages[i].value("stage", std::string("?")));
    lo.push_back(c - 0.3);
    hi.push_back(c + 0.3);
    own.push_back(stages[i].value("gap", std::nan("")));
    x.push_back(c);
    cumulative.push_back(stages[i].contains("cumulative") ? stages[i]["cumulative"].value("gap", std::nan("")) : std::nan(""));
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

std::string parameters_text(const Json& effect) {
  std::string out;
  const Json summary = effect.value("parameter_summary", Json::object());
  const Json fixed = effect.value("fixed_parameters", Json::object());
  for (const auto& [name, s] : summary.items()) {
    const auto ci = s.value("ci95", std::vector<double>{});
    out += fmt::format("{}<code>{}</code> = {} ± {}", out.empty() ? "" : "<br/>", escape_xml(name),
                       number(s.value("mean", 0.0)), number(s.value("std", 0.0), 2));
    if (ci.size() == 2) out += fmt::format(" <span class=\"muted\">[{}, {}]</span>", number(ci[0]), number(ci[1]));
  }
  for (const auto& [name, v] : fixed.items())
    out += fmt::format("{}<code>{}</code> = {} (fixed)", out.empty() ? "" : "<br/>", escape_xml(name),
                       number(v.get<double>()));
  return out.empty() ? "—" : out;
}

std::string effect_table(const Json& d) {
  Table t{{"rank", "effect", "Bayes factor [dB]", "gap after", "shrink", "explained", "worst band [Hz]", "parameters (posterior)"},
          {}, {0, 2, 3, 4, 5}, {}, {}};
  const std::string chosen = d["verdict"].value("effect", std::string("none"));
  int rank = 1;
  for (const auto& e : d.value("effects", Json::array())) {
    const std::string name = e.value("effect", std::string("?"));
    const bool stopped = e.value("stopped_early", false);
    t.rows.push_back({std::to_string(rank++), "<code>" + escape_xml(name) + "</code>",
                      fmt::format("{:.1f}{}", e.value("log_bayes_factor_deciban", 0.0), stopped ? " (stopped early)" : ""),
                      number(e.value("gap_after", 0.0), 4),
                      fmt::format("{:.2f}×", e.value("shrink", 1.0)),
                      fmt::format("{:.0f} %", 100.0 * e.value("explained_fraction", 0.0)),
                      nominal(e["band"].value("f_center", 1.0)), parameters_text(e)});
    t.row_classes.push_back(name == chosen ? "selected" : "");
  }
  t.caption = fmt::format(
      "Effects ranked by the Bayes factor of the simulated side plus the effect against the simulated side alone. "
      "Gap before: {}. Shrink = gap before / gap after over the whole data; explained = share of the squared gap "
      "removed. Decision rule: {}. An effect marked \"stopped early\" stayed far below the leading evidence, so its "
      "sampling was cut short and its Bayes factor is the estimate at the stop.",
      number(d["gap"].value("total", 0.0), 4), escape_xml(text_of(d["verdict"], "rule")));
  return html(t);
}

std::string stage_table(const Json& stages) {
  Table t{{"stage", "gap of this stage", "cumulative gap", "worst band", "detail"}, {}, {1, 2}, {}, {}};
  for (const auto& s : stages)
    t.rows.push_back({escape_xml(s.value("stage", std::string("?"))), number(s.value("gap", 0.0), 4),
                      s.contains("cumulative") ? number(s["cumulative"].value("gap", 0.0), 4) : "—",
                      s.contains("worst_band") ? escape_xml(band_text(s["worst_band"])) : "—",
                      escape_xml(text_of(s, "detail", ""))});
  return html(t);
}

std::string gap_summary(const Json& gap) {
  const Json w = gap.value("whiteness", Json::object());
  return definitions(
      {{"gap", fmt::format("{} (real part {}, imaginary part {})", number(gap.value("total", 0.0), 4),
                           number(gap.value("total_re", 0.0), 4), number(gap.value("total_im", 0.0), 4))},
       {"metric", escape_xml(text_of(gap, "metric"))},
       {"largest |Δα|", number(gap.value("delta_alpha_max", 0.0), 3)},
       {"worst band", escape_xml(band_text(gap.value("worst_band", Json::object())))},
       {"residual", fmt::format("{} (lag-1 autocorrelation {}, z = {})", w.value("white", false) ? "white" : "structured",
                                number(w.value("lag1", 0.0), 3), number(w.value("z", 0.0), 3))}});
}

std::string provenance(const Json& d) {
  const Json in = d.value("input", Json::object()), s = d.value("settings", Json::object());
  const Json real = in.value("real", Json::object());
  return definitions(
      {{"measured", "<code>" + escape_xml(text_of(real, "path")) + "</code>"},
       {"SHA-256", "<code>" + escape_xml(text_of(real, "sha256")) + "</code>"},
       {"simulated", escape_xml(text_of(in, "sim"))},
       {"points", fmt::format("{} from {} Hz to {} Hz", text_of(in, "points"), number(in.value("f_min_hz", 0.0)),
                              number(in.value("f_max_hz", 0.0)))},
       {"sampler", fmt::format("nested sampling, {} live points, Δln Z {}, seed {}", text_of(s, "live"), text_of(s, "dlogz"),
                               text_of(s, "seed"))},
       {"likelihood", escape_xml(text_of(s, "likelihood"))},
       {"admitgen", escape_xml(text_of(d, "version"))}});
}

}  // namespace

std::string verdict_sentence(const Json& d) {
  const Json v = d.value("verdict", Json::object());
  const std::string effect = v.value("effect", std::string("none"));
  const Json effects = d.value("effects", Json::array());
  if (effect == "none") {
    if (effects.empty()) return "No effect was tested, so the gap stays unexplained.";
    return fmt::format(
        "No tested effect is decisively supported: the best, {}, reaches {} dB against no effect (the rule asks for 20 dB), "
        "so the gap of {} is left unexplained.",
        effects[0].value("effect", std::string("?")), number(effects[0].value("log_bayes_factor_deciban", 0.0), 3),
        number(d["gap"].value("total", 0.0), 3));
  }
  const bool white = v.value("residual_white_after", false);
  return fmt::format(
      "The gap is best explained by {} (Bayes factor {} dB against no effect{}): adding it shrinks the gap {}× "
      "({} % of the squared gap), most in the {}{}.",
      effect, number(v.value("log_bayes_factor_deciban", 0.0), 4),
      v.value("margin_deciban", Json()).is_number() ? fmt::format(", {} dB ahead of the next", number(v["margin_deciban"].get<double>(), 3))
                                                    : std::string(),
      fmt::format("{:.2f}", v.value("shrink", 1.0)), fmt::format("{:.0f}", 100.0 * v.value("explained_fraction", 0.0)),
      band_text(v.value("band", Json::object())), white ? "; the residual left is white" : "; structure is left in the residual");
}

std::vector<plot::Figure> diagnosis_figures(const Json& d) {
  std::vector<plot::Figure> out{gap_figure(d)};
  const Json stages = d.value("stages", Json::array());
  if (!stages.empty()) out.push_back(stage_figure(stages));
  return out;
}

std::string diagnosis_report_html(const Json& d) {
  if (!d.contains("gap") || !d["gap"].contains("bands") || d["gap"]["bands"].empty() || !d.contains("verdict"))
    throw InputError("diagnosis report: no gap bands or verdict (is it an admitgen.diagnosis/1 file?)");
  const auto figures = diagnosis_figures(d);
  const Json in = d.value("input", Json::object());
  const std::string real = std::filesystem::path(text_of(in.value("real", Json::object()), "path")).filename().string();
  const Json effects = d.value("effects", Json::array());
  std::string body = fmt::format("<h1>Diagnosis of <code>{}</code></h1>\n", escape_xml(real));
  body += fmt::format("<p class=\"muted\">Measured against {}.</p>\n", escape_xml(text_of(in, "sim")));
  body += "<p class=\"verdict\"><strong>Verdict.</strong> " + escape_xml(verdict_sentence(d)) + "</p>\n";
  body += warnings_box(in.value("warnings", std::vector<std::string>{}));
  body += "<h2>Gap per one-third-octave band</h2>\n" +
          figure(figures[0].svg(),
                 effects.empty() ? std::string("Gap between measured and simulated admittance in each band.")
                                 : fmt::format("Gap between measured and simulated admittance in each band, without an "
                                               "effect and with the best-supported one (<code>{}</code>) added at its "
                                               "posterior mean.",
                                               escape_xml(effects[0].value("effect", std::string("?"))))) +
          gap_summary(d["gap"]);
  const Json stages = d.value("stages", Json::array());
  body += "<h2>Pipeline stages</h2>\n";
  if (stages.empty())
    body += "<p class=\"muted\">No stage attribution: run <code>admitgen diagnose --fit FIT.json --fs HZ</code> to see how "
            "much the fit, discretization, quantization and simulation each add.</p>\n";
  else
    body += figure(figures[1].svg(), "Gap that each stage of fit → filter → fixed point → simulation adds on its own, and "
                                     "the cumulative gap after it.") +
            stage_table(stages);
  body += "<h2>Effects</h2>\n" + effect_table(d);
  body += "<h2>Input and settings</h2>\n" + provenance(d);
  return page("admitgen diagnosis: " + real, body);
}

std::string write_diagnosis_report(const std::string& dir, const Json& d) {
  const std::string path = (std::filesystem::path(dir) / "diagnosis.html").string();
  write_file_atomically(path, diagnosis_report_html(d));
  return path;
}

std::string write_diagnosis_report_from_file(const std::string& diagnosis_json_path) {
  std::ifstream in(diagnosis_json_path, std::ios::binary);
  if (!in) throw FileError(diagnosis_json_path, 0, "cannot read the diagnosis");
  Json d;
  try {
    d = Json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number overflow
    throw FileError(diagnosis_json_path, 0, fmt::format("not JSON ({})", e.what()));
  }
  const auto dir = std::filesystem::path(diagnosis_json_path).parent_path();
  return write_diagnosis_report(dir.empty() ? "." : dir.string(), d);
}

}  // namespace admitgen::report
