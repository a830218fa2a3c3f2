// SPDX-License-Identifier: MIT
#include "emit/emit.hpp"

#include "checks/check_suite.hpp"
#include "checks/passivity.hpp"
#include "core/errors.hpp"
#include "io/check_input.hpp"
#include "io/model_block.hpp"
#include "model/multipole.hpp"
#include "model/multipole_surface.hpp"
#include "model/passivity.hpp"
#include "passivity/passive_residues.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace admitgen::emit {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Margins (relative to max|G| over the data) of the discrete constraints, tried in turn when rounding
/// the coefficients to the format breaks the certificate: f32 rounding moves Re H by ~1e-7 of the
/// coefficient sum, q15 by ~3e-5; 1e-3 changes the response by far less than the refit error tolerated.
constexpr double kMargins[] = {1e-9, 1e-6, 1e-5, 1e-4, 1e-3};

std::string hz(double f) { return std::isinf(f) ? "infinity" : fmt::format("{:.4g} Hz", f); }

/// max |ΔG|/|G| over frequencies f (Hz).
double max_relative_change(const Order& order, const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                           const Eigen::ArrayXd& f_hz) {
  const Eigen::ArrayXd w = 2.0 * kPi * f_hz;
  const Eigen::ArrayXcd g0 = evaluate_multipole(order, before, w), g1 = evaluate_multipole(order, after, w);
  return ((g1 - g0).abs() / g0.abs().max(1e-300)).maxCoeff();
}

bool discrete_passivity_failed(const checks::CheckReport& report) {
  const auto failed = report.failed_checks();
  return std::find(failed.begin(), failed.end(), "passivity_discrete") != failed.end();
}

}  // namespace

std::vector<double> discrete_passivity_violations(const codegen::DiscreteModel& m) {
  const auto r = checks::discrete_passivity(m, false);
  std::vector<double> f;
  for (const auto& b : r.bands) {
    const double hi = std::min(b.hi, 0.5 * m.fs_hz);
    f.push_back(std::min(b.at, 0.5 * m.fs_hz));
    for (int i = 0; i <= 8; ++i) f.push_back(b.lo + (hi - b.lo) * i / 8.0);
  }
  return f;
}

void enforce_continuous_passivity(codegen::EmissionSource& source) {
  const Order& order = source.surface.order;
  if (!is_causal(order, source.surface.theta.data())) return;  // non-causal: the causality check refuses it
  const PassivityResult before = continuous_passivity(order, source.surface.theta.data());
  if (before.passive) return;
  const Eigen::ArrayXd f = Eigen::Map<const Eigen::ArrayXd>(source.data_f_hz.data(), Eigen::Index(source.data_f_hz.size()));
  const Eigen::ArrayXd omega = 2.0 * kPi * f;
  // "Data-weighted": the change is measured where the data were, every data frequency counting equally,
  // relative to |G| there (a relative change is what the refit error and the checks speak in).
  const Eigen::ArrayXcd g = evaluate_multipole(order, source.surface.theta, omega);
  const passivity::ResidueTarget target{omega, g, g.abs().max(1e-300).inverse()};
  const passivity::PassiveResidues p = passivity::passive_residues(order, source.surface.theta, target);
  const double f_lo = f.minCoeff(), f_hi = f.maxCoeff();
  Eigen::ArrayXd outside(128);
  for (Eigen::Index i = 0; i < 64; ++i) {
    outside[i] = f_lo * std::pow(1e-2, double(i + 1) / 64.0);
    outside[64 + i] = f_hi * std::pow(1e2, double(i + 1) / 64.0);
  }
  const double in_band = max_relative_change(order, source.surface.theta, p.theta, f);
  const double out_band = max_relative_change(order, source.surface.theta, p.theta, outside);
  std::string bands;
  for (const auto& b : before.bands)
    bands += fmt::format("{}{} to {} (min Re G {:.3g})", bands.empty() ? "" : ", ", hz(b.lo), hz(b.hi), b.min_re);
  source.notes.push_back(fmt::format(
      "passivity enforced: the {} estimate has Re G < 0 from {}; residues changed minimally (least squares at the "
      "data frequencies, Re G >= 0 at every frequency, {}): max |dG|/|G| = {:.3g} in the data band, {:.3g} outside "
      "it ({:.4g} Hz/100 to {:.4g} Hz x 100)",
      estimate_name(source.estimate), bands, p.certified ? "certified by the Hamiltonian test" : "NOT certified",
      in_band, out_band, f_lo, f_hi));
  source.enforcement = codegen::PassivityEnforcement{estimate_name(source.estimate), bands, p.certified, p.rounds,
                                                     in_band, out_band};
  source.surface.theta = p.theta;
}

namespace {

/// Steps 2-3 at the settings' coefficient width: first the refit to the exact discrete poles, at rising margins;
/// where rounding the poles themselves breaks every certificate (a narrow pair whose stored pole moves its
/// resonance), the refit to the poles as stored (docs/passivity.md, "Refit to the stored poles"). (Without
/// enforcement the first candidate is returned as it is.)
EmitResult emit_at_width(const codegen::EmissionSource& source, codegen::EmitSettings settings,
                         const std::string& template_text, const std::string& header_file_name) {
  EmitResult r;
  for (bool stored : {false, true}) {
    settings.refit_to_stored_poles = stored;
    for (double margin : kMargins) {
      settings.passive_margin = margin;
      r.emission = codegen::prepare_emission(source, settings);
      r.header = io::header_text(r.emission, template_text, header_file_name);
      auto subject = io::header_subject(r.header, header_file_name);
      subject.fidelity_tolerance = settings.fidelity_tolerance;
      r.report = checks::run_checks(subject);
      if (!settings.enforce_passivity || !discrete_passivity_failed(r.report)) return r;
    }
  }
  return r;
}

}  // namespace

EmitResult emit(const FitRecord& fit, const std::string& fit_path, codegen::EmitSettings settings,
                const std::string& template_text, const std::string& header_file_name) {
  codegen::EmissionSource source;
  if (settings.estimate == Estimate::passive && !fit_has_passive_estimate(fit, settings.order, fit_path)) {
    codegen::EmitSettings mean = settings;
    mean.estimate = Estimate::mean;
    source = codegen::read_emission_source(fit, fit_path, mean);
    source.notes.push_back("the fit holds no passive estimate (written by an older admitgen): the posterior mean is "
                           "emitted, made passive below if it is not");
  } else {
    source = codegen::read_emission_source(fit, fit_path, settings);
  }
  return emit(std::move(source), std::move(settings), template_text, header_file_name);
}

EmitResult emit(codegen::EmissionSource source, codegen::EmitSettings settings, const std::string& template_text,
                const std::string& header_file_name) {
  if (settings.enforce_passivity) {
    enforce_continuous_passivity(source);
    settings.passivity_violations = discrete_passivity_violations;
  } else {
    source.notes.push_back("emitted without passivity enforcement (" + setting("enforce_passivity = false") + ")");
  }
  // q15: 16-bit coefficients first; a header that fails a check with them is emitted with 32-bit coefficients
  // (docs/runtime.md, "Q formats and rounding"), and the header says why.
  EmitResult narrow = emit_at_width(source, settings, template_text, header_file_name);
  if (narrow.safe() || settings.format != codegen::Format::q15) return narrow;
  source.notes.push_back(fmt::format("q15 with 32-bit coefficients: with 16-bit ones the header failed admitgen check "
                                     "({})", fmt::join(narrow.report.failed_checks(), ", ")));
  settings.wide_coefficients = true;
  EmitResult wide = emit_at_width(source, settings, template_text, header_file_name);
  return wide.safe() ? wide : narrow;
}

std::string EmitResult::refusal(const std::string& out) const {
  if (safe()) return {};
  std::string why;
  for (const auto& c : report.checks)
    for (const auto& f : c.failures) why += fmt::format("\n  {}: {}", c.name, f);
  const auto failed = report.failed_checks();
  const auto has = [&](const char* name) { return std::find(failed.begin(), failed.end(), name) != failed.end(); };
  std::string next;
  if (has("causality"))
    next = "the model has a pole with lambda or alpha <= 0: re-run admitgen fit (the default estimate is always causal)";
  else if ((has("passivity_discrete") || has("passivity_continuous")) && !emission.settings.enforce_passivity)
    next = "drop " + setting("enforce_passivity = false") + ": emit then makes the model and the refit passive";
  else if (has("passivity_discrete") || has("passivity_continuous"))
    next = fmt::format("the passive refit could not be certified at this rate and format: try a higher {}, {}, or {}; "
                       "`admitgen check` on the written header shows the bands",
                       setting("fs_hz"), setting("format", "f32"), setting("fir_taps", "1..8"));
  else if (has("headroom") || has("limit_cycle"))
    next = "fixed-point range: try " + setting("format", "q31") + " (or f32) instead of q15";
  else if (has("fidelity"))
    next = fmt::format("the filter as stored is further from its model than {} (the header's fidelity line says where): "
                       "a higher {} when the deviation sits near the band's top (the discretisation), {} or f32 when it "
                       "is rounding, a smaller {} when the model is ill-conditioned (fit.json's conditioning of each "
                       "order), or a looser {} if that accuracy is enough",
                       setting("fidelity_tolerance"), setting("fs_hz"), setting("format", "q31"), setting("order"),
                       setting("fidelity_tolerance"));
  else
    next = "re-run admitgen emit; if it persists, report it with the fit.json";
  return fmt::format("refusing to write {}: the filter fails admitgen check ({}){}\nnext step: {}", out,
                     fmt::join(failed, ", "), why, next);
}

}  // namespace admitgen::emit
