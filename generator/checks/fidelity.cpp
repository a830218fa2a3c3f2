// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"
#include "codegen/fidelity.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen::checks {

/// codegen/fidelity.hpp, from the header alone: the coefficients its model block holds (the C tables equal them:
/// header_integrity) against the continuous model it names, over its data band.
CheckResult check_fidelity(const CheckSubject& s) {
  CheckResult r;
  r.name = "fidelity";
  if (!s.header) return r.not_applicable("a fit has no emitted coefficients (check the header made by admitgen emit)");
  r.method = fmt::format("max |H - G|/|G| of the coefficients as the kernel runs them (exact arithmetic), {} log-spaced "
                         "frequencies over the data band, <= {:.3g}; full-scale SNR over the kernel's rounding bound "
                         ">= {:g} dB in band",
                         codegen::kFidelityPoints, s.fidelity_tolerance, codegen::kMinFullScaleSnrDb);
  FidelityDetails d{s.fidelity_tolerance, codegen::kMinFullScaleSnrDb, {}};
  double worst = 0.0, worst_snr = INFINITY;
  for (const auto& rate : s.header->rates) {
    if (!rate.model.stable()) {
      r.fail(fmt::format("fs {} Hz: not decidable, the filter is unstable (see discrete_stability)", rate.fs_hz));
      continue;
    }
    const codegen::Fidelity f = codegen::fidelity(s.surface, rate.model, rate.fixed ? &*rate.fixed : nullptr,
                                                  s.data_f_min_hz, s.data_f_max_hz);
    d.rates.push_back({rate.fs_hz, f.max_rel_deviation, f.at_hz, f.max_rel_deviation_above, f.noise_floor,
                       f.min_snr_db, f.snr_at_hz});
    if (!(f.max_rel_deviation <= s.fidelity_tolerance))
      r.fail(fmt::format("fs {} Hz: the filter is {:.3g} off its model at {:.5g} Hz (tolerance {:.3g}): the coefficients "
                         "as stored do not reproduce the model",
                         rate.fs_hz, f.max_rel_deviation, f.at_hz, s.fidelity_tolerance));
    if (!(f.min_snr_db >= codegen::kMinFullScaleSnrDb))
      r.fail(fmt::format("fs {} Hz: at {:.5g} Hz a full-scale tone comes out only {:.1f} dB above the kernel's rounding "
                         "noise ({:.3g}): the output can round to zero there",
                         rate.fs_hz, f.snr_at_hz, f.min_snr_db, f.noise_floor));
    worst = std::max(worst, f.max_rel_deviation);
    worst_snr = std::min(worst_snr, f.min_snr_db);
  }
  r.summary = fmt::format("max |H - G|/|G| in band {:.3g} (tolerance {:.3g}); min full-scale SNR {:.1f} dB", worst,
                          s.fidelity_tolerance, worst_snr);
  r.details = d;
  return r;
}

}  // namespace admitgen::checks
