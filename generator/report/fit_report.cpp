// SPDX-License-Identifier: MIT
#include "report/fit_report.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "plot/format.hpp"
#include "report/page.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace admitgen::report {
namespace {

using Json = nlohmann::ordered_json;
using plot::escape_xml;
using plot::number;

constexpr double kTwoPi = 6.283185307179586;

std::vector<double> to_vector(const Eigen::ArrayXd& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

/// Quantile row `i` (0: 2.5 %, 1: median, 2: 97.5 %) of a predictive quantity, empty if absent.
std::vector<double> quantile(const Json& predictive, const char* key, std::size_t i) {
  if (!predictive.contains(key) || predictive[key].size() <= i) return {};
  return predictive[key][i].get<std::vector<double>>();
}

/// Largest width (97.5 % minus 2.5 % quantile) of a predictive band; NaN if absent.
double widest_band(const Json& predictive, const char* key) {
  const auto lo = quantile(predictive, key, 0), hi = quantile(predictive, key, 2);
  if (lo.empty() || lo.size() != hi.size()) return std::nan("");
  double widest = 0.0;
  for (std::size_t i = 0; i < lo.size(); ++i) widest = std::max(widest, hi[i] - lo[i]);
  return widest;
}

/// Data markers, model median and 95 % band of one quantity (absorption, Re G or Im G).
plot::Figure quantity_figure(const std::string& id, const std::string& title, const std::string& y_label,
                             const std::vector<double>& f, const std::vector<double>& measured, const Json& fit,
                             const char* key) {
  plot::Figure fig(id, title);
  fig.x.label = "frequency [Hz]";
  fig.x.kind = plot::ScaleKind::log;
  fig.x.style = plot::LabelStyle::hertz;
  fig.y.label = y_label;
  const std::string order = fit["selected"].value("order", std::string("?"));
  const Json predictive = fit.value("predictive", Json::object());
  const auto model_f = predictive.value("f_hz", std::vector<double>{});
  const auto lo = quantile(predictive, key, 0), median = quantile(predictive, key, 1), hi = quantile(predictive, key, 2);
  if (!lo.empty() && lo.size() == model_f.size() && hi.size() == model_f.size())
    fig.add(plot::band("band", "95 % posterior band", "c1", model_f, lo, hi));
  fig.add(plot::markers("data", "measured", "data", f, measured));
  if (!median.empty() && median.size() == model_f.size())
    fig.add(plot::line("model", fmt::format("{} posterior median", order), "c1", model_f, median));
  return fig;
}

plot::Figure evidence_figure(const Json& fit) {
  plot::Figure fig("fig-evidence", "Log-evidence of every order with ±1σ error bars", 720.0, 300.0);
  const std::string selected = fit["selected"].value("order", std::string());
  std::vector<double> x, z, lo, hi, sx, sz, slo, shi;
  double i = 0.0;
  for (const auto& m : fit["models"]) {
    const double v = m.value("log_evidence", std::nan("")), e = m.value("log_evidence_error", 0.0);
    const bool chosen = m.value("order", std::string()) == selected;
    (chosen ? sx : x).push_back(i);
    (chosen ? sz : z).push_back(v);
    (chosen ? slo : lo).push_back(v - e);
    (chosen ? shi : hi).push_back(v + e);
    fig.x.categories.push_back(m.value("order", std::string("?")));
    i += 1.0;
  }
  fig.x.label = "order (Q real poles, S complex pairs)";
  fig.y.label = "ln Z";
  fig.add(plot::error_bars("models", "ln Z ± 1σ", "c1", x, z, lo, hi));
  fig.add(plot::error_bars("selected", fmt::format("selected ({})", selected), "c2", sx, sz, slo, shi));
  return fig;
}

/// One goodness-of-fit figure of a model entry ("—" in fits written before it was recorded).
std::string goodness(const Json& model, const char* key) {
  const Json g = model.value("goodness_of_fit", Json::object());
  return g.contains(key) ? number(g[key].get<double>(), 3) : "—";
}

std::string evidence_table(const Json& fit) {
  Table t{{"order", "buffers", "ln Z", "± σ", "Bayes factor [dB]", "± σ [dB]", "max ln L", "rel. RMS residual", "max |Δα|"},
          {}, {1, 2, 3, 4, 5, 6, 7, 8}, {}, {}};
  const std::string selected = fit["selected"].value("order", std::string());
  const Json factors = fit.value("bayes_factors_deciban", Json::object());
  const Json errors = fit.value("bayes_factor_errors_deciban", Json::object());
  for (const auto& m : fit["models"]) {
    const std::string order = m.value("order", std::string("?"));
    const int q = m.value("Q", 0), s = m.value("S", 0);
    t.rows.push_back({escape_xml(order), std::to_string(q + 2 * s), fmt::format("{:.2f}", m.value("log_evidence", 0.0)),
                      fmt::format("{:.2f}", m.value("log_evidence_error", 0.0)),
                      factors.contains(order) ? fmt::format("{:.1f}", factors[order].get<double>()) : "—",
                      errors.contains(order) ? fmt::format("{:.1f}", errors[order].get<double>()) : "—",
                      fmt::format("{:.2f}", m.value("max_log_likelihood", 0.0)),
                      goodness(m, "relative_rms_residual"), goodness(m, "max_abs_delta_alpha")});
    t.row_classes.push_back(order == selected ? "selected" : "");
  }
  t.caption = fmt::format(
      "Bayes factor of each order against the selected one, 10·log₁₀(Z/Z<sub>sel</sub>) in deciban: −10 dB is odds "
      "10:1 against, −20 dB 100:1 (decisive). Buffers: state variables of the filter (Q + 2S). Goodness of fit at "
      "each order's maximum-likelihood parameters: relative RMS residual ‖D − G‖/‖D‖ of the complex admittance and "
      "the largest absorption error max |Δα| over the data frequencies. Selection rule: {}.",
      escape_xml(fit["selected"].value("rule", std::string("?"))));
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
Json selected_passive_parameters(const Json& fit) {
  const std::string order = fit["selected"].value("order", std::string());
  for (const auto& m : fit.value("models", Json::array()))
    if (m.value("order", std::string()) == order && m.contains("passive_estimate"))
      return m["passive_estimate"].value("parameters", Json::object());
  return Json::object();
}

std::string parameter_table(const Json& fit) {
  Table t{{"parameter", "mean", "std", "95 % interval", "max likelihood", "passive (emitted)", "unit", "note"},
          {}, {1, 2, 3, 4, 5}, {}, {}};
  const Json passive = selected_passive_parameters(fit);
  for (const auto& p : fit.value("parameters", Json::array())) {
    const std::string name = p.value("name", std::string("?"));
    const double mean = p.value("mean", 0.0);
    const auto ci = p.value("ci95", std::vector<double>{0.0, 0.0});
    const auto [unit, note] = unit_and_note(name, mean);
    t.rows.push_back({pretty_name(name), number(mean, 5), number(p.value("std", 0.0), 3),
                      fmt::format("[{}, {}]", number(ci.at(0), 5), number(ci.at(1), 5)),
                      number(p.value("max_likelihood", 0.0), 5),
                      passive.contains(name) ? number(passive[name].get<double>(), 5) : std::string("–"), unit,
                      escape_xml(note)});
  }
  t.caption = fmt::format(
      "Posterior of the selected order {}, G(ω) = G<sub>∞</sub> + Σ A<sub>q</sub>/(λ<sub>q</sub> + jω) + Σ "
      "[Θ<sub>s</sub>/(θ<sub>s</sub> + jω) + c.c.], Θ = B + jC, θ = α + jβ (e<sup>+jωt</sup>); symmetry-reduced "
      "form (β ≥ 0, λ and β ascending). The passive estimate is what admitgen emit uses by default: a best "
      "sample's poles with residues refitted under Re G ≥ 0 at every frequency.",
      escape_xml(fit["selected"].value("order", std::string("?"))));
  return html(t);
}

std::string sampler_table(const Json& fit) {
  Table t{{"order", "live points", "likelihood calls", "iterations", "stopped by", "H [nats]"}, {}, {1, 2, 3, 5}, {}, {}};
  const std::string selected = fit["selected"].value("order", std::string());
  for (const auto& m : fit["models"]) {
    const std::string order = m.value("order", std::string("?"));
    t.rows.push_back({escape_xml(order), std::to_string(m.value("live", fit["settings"].value("live", 0))),
                      std::to_string(m.value("likelihood_calls", 0L)), std::to_string(m.value("iterations", 0L)),
                      escape_xml(m.value("stopped_by", std::string("?"))), fmt::format("{:.2f}", m.value("information_nats", 0.0))});
    t.row_classes.push_back(order == selected ? "selected" : "");
  }
  t.caption =
      "H is the information (KL divergence of posterior from prior); the evidence error is about √(H/live). A run "
      "stopped by max_iterations has not converged.";
  return html(t);
}

std::string provenance(const Json& fit) {
  const Json in = fit.value("input", Json::object()), s = fit.value("settings", Json::object());
  const Json priors = s.value("priors", Json::object()), sampler = s.value("sampler", Json::object());
  const auto text = [](const Json& j) { return escape_xml(j.is_string() ? j.get<std::string>() : j.dump()); };
  std::vector<std::pair<std::string, std::string>> items{
      {"input file", "<code>" + text(in.value("path", Json("?"))) + "</code>"},
      {"SHA-256", "<code>" + text(in.value("sha256", Json("?"))) + "</code>"},
      {"points", fmt::format("{} from {} Hz to {} Hz", in.value("points", 0), number(in.value("f_min_hz", 0.0)),
                             number(in.value("f_max_hz", 0.0)))},
      {"read as", fmt::format("columns <code>{}</code>, {}{}{}", text(in.value("columns", Json("?"))),
                              text(in.value("quantity", Json("?"))),
                              in.value("rho_c", Json()).is_null() ? ", normalised" : ", ρc = " + text(in["rho_c"]),
                              in.value("band", Json()).is_null() ? "" : ", band " + text(in["band"]))},
      {"layout", text(in.value("read_as", Json("—")))},
      {"orders", fmt::format("Q0–{} × S0–{}", s.value("qmax", 0), s.value("smax", 0))},
      {"sampler", fmt::format("{}; {} live points, seed {}, Δln Z {} , slices {}", text(sampler.value("method", Json("?"))),
                              s.value("live", 0), text(s.value("seed", Json(0))), text(sampler.value("dlogz", Json("?"))),
                              text(sampler.value("slices", Json("?"))))},
      {"priors", fmt::format("{}{}", text(priors.value("source", Json("?"))),
                             priors.value("symmetry_reduced", false) ? ", symmetry-reduced" : "")},
      {"likelihood", text(s.value("likelihood", Json("?")))},
      {"selection", text(s.value("select", Json("?")))},
      {"admitgen", text(fit.value("version", Json("?")))}};
  if (s.contains("passive")) items.emplace_back("passivity", text(s["passive"]));
  return definitions(items);
}

}  // namespace

std::vector<plot::Figure> fit_figures(const Json& fit, const Measurement& data) {
  const std::vector<double> f = to_vector(data.f_hz);
  std::vector<plot::Figure> out;
  out.push_back(quantity_figure("fig-absorption", "Absorption coefficient against frequency", "absorption α", f,
                                to_vector(absorption(data.y)), fit, "alpha"));
  out.push_back(quantity_figure("fig-re-g", "Real part of the admittance against frequency", "Re G (normalised)", f,
                                to_vector(data.y.real()), fit, "re_G"));
  out.push_back(quantity_figure("fig-im-g", "Imaginary part of the admittance against frequency", "Im G (normalised)", f,
                                to_vector(data.y.imag()), fit, "im_G"));
  out.push_back(evidence_figure(fit));
  return out;
}

std::string fit_report_html(const Json& fit, const Measurement& data) {
  if (!fit.contains("models") || fit["models"].empty() || !fit.contains("selected"))
    throw InputError("fit report: the fit has no models or no selection (is it an admitgen.fit/1 file?)");
  const auto figures = fit_figures(fit, data);
  const std::string file = std::filesystem::path(data.path).filename().string();
  const std::string order = fit["selected"].value("order", std::string("?"));
  const Json predictive = fit.value("predictive", Json::object());
  std::string body = fmt::format("<h1>Fit of <code>{}</code></h1>\n", escape_xml(file));
  body += fmt::format(
      "<p class=\"lead\">Selected <strong>{}</strong> ({}) among {} orders, fitted to {} points from {} Hz to {} Hz.</p>\n",
      escape_xml(order), escape_xml(fit["selected"].value("rule", std::string("?"))), fit["models"].size(), data.size(),
      number(data.f_hz[0]), number(data.f_hz[data.size() - 1]));
  body += warnings_box(fit.value("warnings", std::vector<std::string>{}));
  std::string band_note =
      fmt::format("The band holds 95 % of the posterior predictive ({} draws) at each frequency; the line is its median.",
                  predictive.value("draws", 0));
  const double alpha_width = widest_band(predictive, "alpha");
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
  body += "<h2>Parameters</h2>\n" + parameter_table(fit);
  body += "<h2>Sampler diagnostics</h2>\n" + sampler_table(fit);
  body += "<h2>Input and settings</h2>\n" + provenance(fit);
  return page(fmt::format("admitgen fit: {} ({})", file, order), body);
}

std::string write_fit_report(const std::string& dir, const Json& fit, const Measurement& data) {
  const std::string path = (std::filesystem::path(dir) / "report.html").string();
  write_file_atomically(path, fit_report_html(fit, data));
  return path;
}

}  // namespace admitgen::report
