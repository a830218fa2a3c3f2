// SPDX-License-Identifier: MIT
#include "data/plausibility.hpp"

#include "core/errors.hpp"
#include "numerics/passive_bound.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <complex>

namespace admitgen {
namespace {

struct Candidate {
  Quantity quantity;
  std::optional<double> rho_c;
};

/// y from the file's values under a candidate reading (docs/reading-data.md, "Options": y = v·ρc for SI
/// admittance, ρc/v for impedance, (1 − R)/(1 + R) for a reflection factor).
Eigen::ArrayXcd admittance_as(const Eigen::ArrayXcd& v, const Candidate& c) {
  const double rc = c.rho_c.value_or(1.0);
  switch (c.quantity) {
    case Quantity::admittance: return v * rc;
    case Quantity::impedance: return rc / v;
    case Quantity::reflection: return (1.0 - v) / (1.0 + v);
  }
  throw InternalError("unhandled Quantity");
}

bool too_small(const Eigen::ArrayXcd& y) { return y.abs().maxCoeff() < 1.0 / kPlausibleAdmittanceRatio; }
bool too_large(const Eigen::ArrayXcd& y) { return y.abs().minCoeff() > kPlausibleAdmittanceRatio; }
bool plausible_scale(const Eigen::ArrayXcd& y) { return y.allFinite() && !too_small(y) && !too_large(y); }

std::string flags(const Candidate& c, bool rho_c_given) {
  std::string out = setting("quantity", quantity_name(c.quantity));
  if (c.rho_c)
    out += rho_c_given ? " " + setting("rho_c", fmt::format("{:g}", *c.rho_c))
                       : fmt::format(" {} (rho0*c0 of the air in the tube in Pa s/m, {} at 20 C)",
                                     setting("rho_c", "RHO_C"), kTypicalRhoC);
  return out;
}

/// The readings of the same numbers whose |y| is plausible, as option lists the user can paste.
std::string scale_hint(const ReadingForChecks& r) {
  const double rc = r.options.rho_c.value_or(kTypicalRhoC);
  std::vector<Candidate> candidates{{Quantity::impedance, rc},  {Quantity::impedance, std::nullopt},
                                    {Quantity::admittance, rc}, {Quantity::admittance, std::nullopt}};
  if (r.values.abs().maxCoeff() <= 1.0) candidates.push_back({Quantity::reflection, std::nullopt});
  std::vector<std::string> fits;
  for (const auto& c : candidates)
    if ((c.quantity != r.quantity || c.rho_c.has_value() != r.options.rho_c.has_value()) &&
        plausible_scale(admittance_as(r.values, c)))
      fits.push_back(flags(c, r.options.rho_c.has_value()));
  if (fits.empty())
    return fmt::format("no other reading of these numbers is plausible either: check {}, {} and {}", setting("columns"),
                       setting("quantity"), setting("rho_c"));
  std::string out = "read as ";
  for (std::size_t i = 0; i < fits.size(); ++i) out += (i > 0 ? ", or as " : "") + fits[i];
  return out + (fits.size() > 1 ? ", they are plausible (the first is the usual case)" : ", they are plausible");
}

std::string reading_name(const ReadingForChecks& r) {
  return fmt::format("{} {}", r.options.rho_c ? fmt::format("SI ({})", setting("rho_c", fmt::format("{:g}", *r.options.rho_c)))
                                             : "normalised",
                     quantity_name(r.quantity));
}

void report(bool error, const std::string& path, const std::string& what, std::vector<std::string>& warnings) {
  if (error) throw FileError(path, 0, what);
  warnings.push_back(fmt::format("{}: {}", path, what));
}

void check_scale(const ReadingForChecks& r, std::vector<std::string>& warnings) {
  const Eigen::ArrayXd mag = r.y.abs();
  if (too_small(r.y))
    report(r.options.plausibility_errors, r.path,
           fmt::format("read as {}, |normalised admittance| stays below 1/{:g} (|z| > {:g}) at every frequency "
                       "(largest |y| {:.3g}): the values look like SI units or the wrong quantity, or the surface is "
                       "almost rigid (alpha < 0.13 everywhere); {}",
                       reading_name(r), kPlausibleAdmittanceRatio, kPlausibleAdmittanceRatio, mag.maxCoeff(), scale_hint(r)),
           warnings);
  else if (too_large(r.y))
    report(r.options.plausibility_errors, r.path,
           fmt::format("read as {}, |normalised admittance| exceeds {:g} (|z| < 1/{:g}) at every frequency "
                       "(smallest |y| {:.3g}): the values look like SI units or the wrong quantity; {}",
                       reading_name(r), kPlausibleAdmittanceRatio, kPlausibleAdmittanceRatio, mag.minCoeff(), scale_hint(r)),
           warnings);
}

/// Re y does not depend on the time convention (it conjugates y), so Re y < 0 is never fixed by
/// --time-convention: it means the wrong columns, quantity or sign.
void check_passive(const ReadingForChecks& r, std::vector<std::string>& warnings) {
  const auto negative = (r.y.real() < 0.0).count();
  if (2 * negative > r.y.size())
    report(r.options.plausibility_errors, r.path,
           fmt::format("Re y < 0 at {} of {} frequencies: a passive surface absorbs (Re y >= 0, in either time "
                       "convention); check that {} selects the right re and im (or mag and phase) columns "
                       "and that {} is right",
                       negative, r.y.size(), setting("columns"), setting("quantity")),
           warnings);
}

/// How near the data come to a causal passive wall as read and in the other time convention (y conjugated): the
/// relative RMS residual of the best passive fit of each (numerics/passive_bound.hpp). A passive wall's Re and Im
/// parts are tied by the Kramers-Kronig relations in its own convention only, so the reading with the clearly
/// smaller residual is the physical one, whatever Im y's sign at low frequency suggests.
struct ConventionEvidence {
  double as_read = 0.0, other = 0.0;
};
ConventionEvidence convention_evidence(const ReadingForChecks& r) {
  constexpr double kTwoPi = 6.283185307179586;
  const Eigen::ArrayXd omega = kTwoPi * r.f_hz, ones = Eigen::ArrayXd::Ones(r.y.size());
  return {numerics::passive_bound(omega, r.y, ones).relative_rms_residual,
          numerics::passive_bound(omega, r.y.conjugate(), ones).relative_rms_residual};
}

/// One reading is "clearly" nearer a passive wall when its best passive fit leaves at most half the other's residual.
constexpr double kClearlyNearer = 0.5;

/// In e^{+jωt} a layer on a rigid backing is stiffness-controlled below its first resonance:
/// z ≈ 1/(jωC), Im z < 0, Im y > 0 (the reference data and every sample here start so). Im y < 0
/// at all of the lowest frequencies is the e^{−jωt} reading of such a layer, or a mass-like surface, or a phase
/// error (calibration, reference plane). Which one the passive bounds of both readings tell (docs/reading-data.md,
/// "Plausibility checks"): a real file read in its own convention, with +40° of phase error at low frequency, looked
/// like the other convention by the sign test and was 9.4 % from a passive wall as read against 36 % conjugated.
void check_time_convention(const ReadingForChecks& r, std::vector<std::string>& warnings) {
  const Eigen::Index n = r.y.size(), low = std::max<Eigen::Index>(3, n / 10);
  if (n < low || !(r.y.head(low).imag() < 0.0).all() || !(r.f_hz > 0.0).all()) return;
  const bool minus = r.options.time_convention == TimeConvention::minus_jwt;
  const char* read = minus ? "-jwt" : "+jwt";
  const char* other = minus ? "+jwt" : "-jwt";
  const ConventionEvidence e = convention_evidence(r);
  const std::string sign = fmt::format(
      "Im y < 0 at the {} lowest frequencies ({:g}-{:g} Hz) read in the e^{{{}jwt}} convention, where a porous or "
      "resonant layer on a rigid backing has Im y > 0 (stiffness-controlled)",
      low, r.f_hz[0], r.f_hz[low - 1], minus ? "-" : "+");
  const std::string bounds = fmt::format("the best passive fit leaves {:.3g} % as read and {:.3g} % in e^{{{}jwt}}",
                                         100.0 * e.as_read, 100.0 * e.other, minus ? "+" : "-");
  if (e.as_read <= kClearlyNearer * e.other) {
    // The sign test points to the other convention, but the data are a causal passive wall as read.
    if (r.options.time_convention) return;  // the user chose the reading the data support
    report(r.options.plausibility_errors, r.path,
           fmt::format("{}; but the data as read are much nearer a causal passive wall ({}), so the convention is "
                       "probably right and the surface mass-like at low frequency or its phase off (a calibration or "
                       "reference-plane error): give {} to fit them as read",
                       sign, bounds, setting("time_convention", read)),
           warnings);
    return;
  }
  const std::string verdict = e.other <= kClearlyNearer * e.as_read
                                  ? fmt::format("the data are much nearer a causal passive wall in the other "
                                                "convention ({})",
                                                bounds)
                                  : fmt::format("the passive bounds do not decide ({})", bounds);
  const std::string what = fmt::format("{}; {}. The file probably uses the other time convention: give {}", sign,
                                       verdict, setting("time_convention", other));
  if (r.options.time_convention)  // the user chose the convention: say it, do not refuse
    warnings.push_back(fmt::format("{}: {} (or keep it if the surface is mass-like at low frequency)", r.path, what));
  else
    report(r.options.plausibility_errors, r.path,
           what + "; if the surface really is mass-like at low frequency, give " + setting("time_convention", "+jwt") +
               " to confirm",
           warnings);
}

}  // namespace

void check_plausibility(const ReadingForChecks& r, std::vector<std::string>& warnings) {
  check_scale(r, warnings);
  check_passive(r, warnings);
  check_time_convention(r, warnings);
}

}  // namespace admitgen
