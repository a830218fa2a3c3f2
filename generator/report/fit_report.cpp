// SPDX-License-Identifier: MIT
#include "report/fit_report.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "plot/format.hpp"
#include "report/page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

namespace admitgen::report {
namespace {

using plot::escape_xml;
using plot::json_number;
using plot::number;

constexpr double kTwoPi = 6.283185307179586;

std::vector<double> to_vector(const Eigen::ArrayXd& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

/// The quantile rows (2.5 %, median, 97.5 %) of a predictive quantity.
using QuantileRows = std::array<std::vector<double>, 3> FitPredictive::*;

/// Quantile row `i` (0: 2.5 %, 1: median, 2: 97.5 %) of a predictive quantity, empty if absent.
std::vector<double> quantile(const FitRecord& fit, QuantileRows key, std::size_t i) {
  if (!fit.predictive) return {};
  return ((*fit.predictive).*key)[i];
}

/// Largest width (97.5 % minus 2.5 % quantile) of a predictive band; NaN if absent.
double widest_band(const FitRecord& fit, QuantileRows key) {
  const auto lo = quantile(fit, key, 0), hi = quantile(fit, key, 2);
  if (lo.empty() || lo.size() != hi.size()) return std::nan("");
  double widest = 0.0;
  for (std::size_t i = 0; i < lo.size(); ++i) widest = std::max(widest, hi[i] - lo[i]);
  return widest;
}

/// Data markers, model median and 95 % band of one quantity (absorption, Re G or Im G).
plot::Figure quantity_figure(const std::string& id, const std::string& title, const std::string& y_label,
                             const std::vector<double>& f, const std::vector<double>& measured, const FitRecord& fit,
                             QuantileRows key) {
  plot::Figure fig(id, title);
  fig.x.label = "frequency [Hz]";
  fig.x.kind = plot::ScaleKind::log;
  fig.x.style = plot::LabelStyle::hertz;
  fig.y.label = y_label;
  const std::string& order = fit.selected_order;
  const auto model_f = fit.predictive ? fit.predictive->f_hz : std::vector<double>{};
  const auto lo = quantile(fit, key, 0), median = quantile(fit, key, 1), hi = quantile(fit, key, 2);
  if (!lo.empty() && lo.size() == model_f.size() && hi.size() == model_f.size())
    fig.add(plot::band("band", "95 % posterior band", "c1", model_f, lo, hi));
  fig.add(plot::markers("data", "measured", "data", f, measured));
  if (!median.empty() && median.size() == model_f.size())
    fig.add(plot::line("model", fmt::format("{} posterior median", order), "c1", model_f, median));
  return fig;
}

plot::Figure evidence_figure(const FitRecord& fit) {
  plot::Figure fig("fig-evidence", "Log-evidence of every order with ±1σ error bars", 720.0, 300.0);
  const std::string& selected = fit.selected_order;
  std::vector<double> x, z, lo, hi, sx, sz, slo, shi;
  double i = 0.0;
  for (const auto& m : fit.models) {
    const double v = m.log_evidence, e = m.log_evidence_error;
    const bool chosen = m.order == selected;
    (chosen ? sx : x).push_back(i);
    (chosen ? sz : z).push_back(v);
    (chosen ? slo : lo).push_back(v - e);
    (chosen ? shi : hi).push_back(v + e);
    fig.x.categories.push_back(m.order);
    i += 1.0;
  }
  fig.x.label = "order (Q real poles, S complex pairs)";
  fig.y.label = "ln Z";
  fig.add(plot::error_bars("models", "ln Z ± 1σ", "c1", x, z, lo, hi));
  fig.add(plot::error_bars("selected", fmt::format("selected ({})", selected), "c2", sx, sz, slo, shi));
  return fig;
}

/// Accuracy against cost (selection/accuracy_target.hpp): each order's passive estimate, max |Δα| per one-third-
/// octave band against its buffers (Q + 2S), the target as a dashed line and the selected order marked. Empty
/// (no series) for fits written before accuracy was recorded.
plot::Figure accuracy_figure(const FitRecord& fit) {
  plot::Figure fig("fig-accuracy", "Largest |Δα| per band of each order's passive estimate against its buffers", 720.0,
                   300.0);
  fig.x.label = "buffers per node (Q + 2S)";
  fig.y.label = "max |Δα| in a band";
  fig.y.kind = plot::ScaleKind::log;
  std::vector<double> x, y, sx, sy;
  double most = 0.0;
  for (const auto& m : fit.models) {
    if (!m.accuracy) continue;
    const bool chosen = m.order == fit.selected_order;
    // A floor keeps an exact fit (|Δα| = 0) on the logarithmic axis.
    (chosen ? sy : y).push_back(std::max(m.accuracy->max_band_delta_alpha, 1e-6));
    (chosen ? sx : x).push_back(static_cast<double>(m.accuracy->buffers));
    most = std::max(most, static_cast<double>(m.accuracy->buffers));
  }
  if (x.empty() && sx.empty()) return fig;
  fig.add(plot::markers("orders", "fitted orders", "c1", x, y));
  fig.add(plot::markers("selected", fmt::format("selected ({})", fit.selected_order), "c2", sx, sy));
  if (fit.settings.target) {
    const double t = fit.settings.target->max_band_delta_alpha;
    plot::Series target = plot::line("target", fmt::format("target |Δα| ≤ {}", number(t, 3)), "c3", {0.0, most}, {t, t});
    target.dashed = true;
    fig.add(std::move(target));
  }
  return fig;
}

/// The accuracy of a model entry's passive estimate, one figure ("—" in fits written before it was recorded).
std::string accuracy(const FitModel& model, double FitAccuracy::*key, int digits) {
  return model.accuracy ? number((*model.accuracy).*key, digits) : "—";
}

/// One goodness-of-fit figure of a model entry ("—" in fits written before it was recorded).
std::string goodness(const FitModel& model, double FitGoodness::*key) {
  return model.goodness_of_fit ? number((*model.goodness_of_fit).*key, 3) : "—";
}

/// The value of `order` in a by-order table of the fit, formatted with one decimal ("—" if absent).
std::string by_order(const std::vector<std::pair<std::string, double>>& table, const std::string& order) {
  for (const auto& [name, v] : table)
    if (name == order) return fmt::format("{:.1f}", v);
  return "—";
}

std::string evidence_table(const FitRecord& fit) {
  const bool lower_bound = fit.log_evidence_error_meaning && fit.log_evidence_error_meaning->find("lower bound") != std::string::npos;
  Table t{{"order", "buffers", "ln Z", lower_bound ? "± σ (lower bound)" : "± σ", "Bayes factor [dB]", "± σ [dB]",
           "max ln L", "rel. RMS residual", "max |Δα|", "passive: rel. RMS", "passive: max |Δα| per band",
           "meets target", "conditioning"},
          {}, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12}, {}, {}};
  const std::string& selected = fit.selected_order;
  for (const auto& m : fit.models) {
    const std::string& order = m.order;
    t.rows.push_back({escape_xml(order), std::to_string(m.q + 2 * m.s), fmt::format("{:.2f}", m.log_evidence),
                      fmt::format("{:.2f}", m.log_evidence_error), by_order(fit.bayes_factors_deciban, order),
                      by_order(fit.bayes_factor_errors_deciban, order), fmt::format("{:.2f}", m.max_log_likelihood),
                      goodness(m, &FitGoodness::relative_rms_residual), goodness(m, &FitGoodness::max_abs_delta_alpha),
                      accuracy(m, &FitAccuracy::relative_rms_residual, 3),
                      accuracy(m, &FitAccuracy::max_band_delta_alpha, 3),
                      m.accuracy ? (m.accuracy->meets_target ? "yes" : "no") : "—",
                      accuracy(m, &FitAccuracy::conditioning, 3)});
    t.row_classes.push_back(order == selected ? "selected" : "");
  }
  t.caption = fmt::format(
      "Bayes factor of each order against the selected one, 10·log₁₀(Z/Z<sub>sel</sub>) in deciban: −10 dB is odds "
      "10:1 against, −20 dB 100:1 (decisive). Buffers: state variables of the filter (Q + 2S). Goodness of fit at "
      "each order's maximum-likelihood parameters: relative RMS residual ‖D − G‖/‖D‖ of the complex admittance and "
      "the largest absorption error max |Δα| over the data frequencies. Passive: the same of each order's passive "
      "estimate (what emit ships), |Δα| as its largest in any one-third-octave band; it meets the target {}; conditioning: Σ over terms of max |term| / max |G| over the data band (docs/passivity.md). {}"
      "Selection rule: {}.",
      fit.settings.target ? "|Δα| ≤ " + number(fit.settings.target->max_band_delta_alpha, 3) : std::string("—"),
      fit.log_evidence_error_meaning ? "Error of ln Z: " + escape_xml(*fit.log_evidence_error_meaning) + ". " : std::string(),
      escape_xml(fit.selected_rule));
  return html(t);
}

/// Unit and a reading aid of a parameter: rates are angular (s⁻¹); a pole at rate r sits near r/2π Hz.
std::pair<std::string, std::string> unit_and_note(const std::string& name, double mean) {
  if (name == "G_inf") return {"—", "normalised admittance at high frequency"};
  const std::string stem = name.substr(0, name.find('_'));
  if (stem == "lambda" || stem == "alpha") return {"s⁻¹", "decay rate; /2π = " + plot::frequency(mean / kTwoPi)};
  if (stem == "beta") return {"rad/s", "resonance; /2π = " + plot::frequency(mean / kTwoPi)};
  return {"s⁻¹", "residue"};
}

std::string pretty_name(const std::string& name) {
  if (name == "G_inf") return "G<sub>∞</sub>";
  const auto cut = name.find('_');
  if (cut == std::string::npos) return escape_xml(name);
  std::string stem = name.substr(0, cut);
  if (stem == "lambda") stem = "λ";
  else if (stem == "alpha") stem = "α";
  else if (stem == "beta") stem = "β";
  return escape_xml(stem) + "<sub>" + escape_xml(name.substr(cut + 1)) + "</sub>";
}

/// The selected order's passive estimate (docs/passivity.md) as name → value (empty for older fits).
std::vector<std::pair<std::string, double>> selected_passive_parameters(const FitRecord& fit) {
  for (const auto& m : fit.models)
    if (m.order == fit.selected_order && m.passive_estimate) return m.passive_estimate->parameters;
  return {};
}

std::string parameter_table(const FitRecord& fit) {
  Table t{{"parameter", "mean", "std", "95 % interval", "max likelihood", "passive (emitted)", "unit", "note"},
          {}, {1, 2, 3, 4, 5}, {}, {}};
  const auto passive = selected_passive_parameters(fit);
  const auto passive_value = [&](const std::string& name) {
    for (const auto& [n, v] : passive)
      if (n == name) return number(v, 5);
    return std::string("–");
  };
  for (const auto& p : fit.parameters) {
    const auto [unit, note] = unit_and_note(p.name, p.mean);
    t.rows.push_back({pretty_name(p.name), number(p.mean, 5), number(p.std, 3),
                      fmt::format("[{}, {}]", number(p.ci95_lo, 5), number(p.ci95_hi, 5)), number(p.max_likelihood, 5),
                      passive_value(p.name), unit, escape_xml(note)});
  }
  t.caption = fmt::format(
      "Posterior of the selected order {}, G(ω) = G<sub>∞</sub> + Σ A<sub>q</sub>/(λ<sub>q</sub> + jω) + Σ "
      "[Θ<sub>s</sub>/(θ<sub>s</sub> + jω) + c.c.], Θ = B + jC, θ = α + jβ (e<sup>+jωt</sup>); symmetry-reduced "
      "form (β ≥ 0, λ and β ascending). The passive estimate is what admitgen emit uses by default: a best "
      "sample's poles with residues refitted under Re G ≥ 0 at every frequency.",
      escape_xml(fit.selected_order));
  return html(t);
}

std::string sampler_table(const FitRecord& fit) {
  Table t{{"order", "live points", "likelihood calls", "iterations", "stopped by", "H [nats]"}, {}, {1, 2, 3, 5}, {}, {}};
  for (const auto& m : fit.models) {
    t.rows.push_back({escape_xml(m.order), std::to_string(m.live.value_or(fit.settings.live)),
                      std::to_string(m.likelihood_calls), std::to_string(m.iterations), escape_xml(m.stopped_by),
                      fmt::format("{:.2f}", m.information_nats)});
    t.row_classes.push_back(m.order == fit.selected_order ? "selected" : "");
  }
  t.caption =
      "H is the information (KL divergence of posterior from prior); the evidence error is about √(H/live). A run "
      "stopped by max_iterations has not converged.";
  return html(t);
}

std::string provenance(const FitRecord& fit) {
  const FitInput& in = fit.input;
  const FitSettingsRecord& s = fit.settings;
  const std::string band = in.band ? fmt::format("[{},{}]", json_number((*in.band)[0]), json_number((*in.band)[1])) : "";
  std::vector<std::pair<std::string, std::string>> items{
      {"input file", "<code>" + escape_xml(in.path) + "</code>"},
      {"SHA-256", "<code>" + escape_xml(in.sha256) + "</code>"},
      {"points", fmt::format("{} from {} Hz to {} Hz", in.points, number(in.f_min_hz), number(in.f_max_hz))},
      {"read as", fmt::format("columns <code>{}</code>, {}{}{}", escape_xml(in.columns), escape_xml(in.quantity),
                              !in.rho_c ? ", normalised" : ", ρc = " + escape_xml(json_number(*in.rho_c)),
                              !in.band ? "" : ", band " + escape_xml(band))},
      {"layout", escape_xml(in.read_as.value_or("—"))},
      {"orders", !fit.grid || fit.grid->steps.empty()
                     ? fmt::format("Q0–{} × S0–{}", s.qmax, s.smax)
                     : fmt::format("Q0–{} × S0–{}, grown around the selection: {}", s.qmax, s.smax,
                                   escape_xml(fmt::format("{}", fmt::join(fit.grid->steps, "; "))))},
      {"sampler", fmt::format("{}; {} live points{}, seed {}, Δln Z {} , slices {}", escape_xml(s.sampler.method), s.live,
                              s.sampler.runs.value_or(1) > 1
                                  ? fmt::format(" in {} independent runs per order (error from their scatter)",
                                                *s.sampler.runs)
                                  : std::string(),
                              s.seed, escape_xml(json_number(s.sampler.dlogz)),
                              s.sampler.slices ? std::to_string(*s.sampler.slices) : std::string(kAutomaticSlices))},
      {"priors", fmt::format("{}{}", escape_xml(s.priors_source), s.symmetry_reduced ? ", symmetry-reduced" : "")},
      {"likelihood", escape_xml(s.likelihood)},
      {"selection", escape_xml(s.select)},
      {"admitgen", escape_xml(fit.version)}};
  if (s.passive) items.emplace_back("passivity", escape_xml(*s.passive));
  return definitions(items);
}

}  // namespace

std::vector<plot::Figure> fit_figures(const FitRecord& fit, const Measurement& data) {
  const std::vector<double> f = to_vector(data.f_hz);
  std::vector<plot::Figure> out;
  out.push_back(quantity_figure("fig-absorption", "Absorption coefficient against frequency", "absorption α", f,
                                to_vector(absorption(data.y)), fit, &FitPredictive::alpha));
  out.push_back(quantity_figure("fig-re-g", "Real part of the admittance against frequency", "Re G (normalised)", f,
                                to_vector(data.y.real()), fit, &FitPredictive::re_G));
  out.push_back(quantity_figure("fig-im-g", "Imaginary part of the admittance against frequency", "Im G (normalised)", f,
                                to_vector(data.y.imag()), fit, &FitPredictive::im_G));
  out.push_back(evidence_figure(fit));
  out.push_back(accuracy_figure(fit));
  return out;
}

std::string fit_report_html(const FitRecord& fit, const Measurement& data) {
  if (fit.models.empty() || fit.selected_order.empty())
    throw InputError("fit report: the fit has no models or no selection (is it an admitgen.fit/1 file?)");
  const auto figures = fit_figures(fit, data);
  const std::string file = std::filesystem::path(data.path).filename().string();
  const std::string& order = fit.selected_order;
  std::string body = fmt::format("<h1>Fit of <code>{}</code></h1>\n", escape_xml(file));
  body += fmt::format(
      "<p class=\"lead\">Selected <strong>{}</strong> ({}) among {} orders, fitted to {} points from {} Hz to {} Hz.</p>\n",
      escape_xml(order), escape_xml(fit.selected_rule), fit.models.size(), data.size(),
      number(data.f_hz[0]), number(data.f_hz[data.size() - 1]));
  body += warnings_box(fit.warnings.value_or(std::vector<std::string>{}));
  std::string band_note =
      fmt::format("The band holds 95 % of the posterior of the model curve ({} draws) at each frequency, without the "
                  "measurement noise (data scatter about it by that noise); the line is its median.",
                  fit.predictive ? fit.predictive->draws : 0);
  const double alpha_width = widest_band(fit, &FitPredictive::alpha);
  if (std::isfinite(alpha_width))
    band_note += fmt::format(" Its width is at most {} in α, so where the posterior is tight it hides behind the line.",
                             number(alpha_width, 2));
  body += "<h2>Absorption</h2>\n" +
          figure(figures[0].svg(), "(a) Normal-incidence absorption α = 1 − |R|², R = (1 − G)/(1 + G). " + band_note);
  body += "<h2>Admittance</h2>\n" + figure(figures[1].svg() + "\n" + figures[2].svg(),
                                           "(b) Real and imaginary part of the normalised surface admittance G "
                                           "(e<sup>+jωt</sup>). " + band_note);
  body += "<h2>Evidence of each order</h2>\n" +
          figure(figures[3].svg(),
                 "(c) Natural-log evidence ln Z of every order; error bars ±1σ (often smaller than the marker).") +
          evidence_table(fit);
  if (!figures[4].series().empty())
    body += "<h2>Accuracy against cost</h2>\n" +
            figure(figures[4].svg(),
                   "(d) What each order's passive estimate (what emit ships) buys: the largest |Δα| in any "
                   "one-third-octave band against the buffers per node it costs; the dashed line is the accuracy "
                   "target, the selected order is marked.");
  body += "<h2>Parameters</h2>\n" + parameter_table(fit);
  body += "<h2>Sampler diagnostics</h2>\n" + sampler_table(fit);
  body += "<h2>Input and settings</h2>\n" + provenance(fit);
  return page(fmt::format("admitgen fit: {} ({})", file, order), body);
}

std::string write_fit_report(const std::string& dir, const FitRecord& fit, const Measurement& data) {
  const std::string path = (std::filesystem::path(dir) / "report.html").string();
  write_file_atomically(path, fit_report_html(fit, data));
  return path;
}

}  // namespace admitgen::report
