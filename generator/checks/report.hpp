// SPDX-License-Identifier: MIT
/// @file
/// The result of `admitgen check`: one entry per check, each failure named with where it is, and the
/// figures that decided it as a typed record per check kind. The files and the printed text are written by
/// io/check_report.hpp (schema "admitgen.check/1", docs/formats.md); nothing here knows their keys.
#pragma once

#include "model/passivity.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace admitgen::checks {

enum class Status { pass, fail, not_applicable };

/// causality: the slowest continuous decay rate min(λ_q, α_s) in 1/s (none: no poles, G = G_inf).
struct CausalityDetails {
  std::optional<double> slowest_rate_per_s;
};

/// discrete_stability at one rate: 1 − max |z| over its poles and the time constant of that pole.
struct StabilityRate {
  int fs_hz = 0;
  std::optional<double> min_margin;               ///< none: FIR only (every pole at z = 0)
  std::optional<double> slowest_time_constant_s;  ///< 1/(margin fs); −1 when the margin is not positive
};
struct DiscreteStabilityDetails {
  std::vector<StabilityRate> rates;
};

/// Where a band of Re G < 0 lies relative to the fitted data band.
enum class BandPlace { data_band_unknown, below, above, inside, overlapping };
/// "below the data band", "inside the data band", ... (failure messages and the report say the same).
const char* band_place_text(BandPlace place);

/// passivity_continuous (and each rate of passivity_discrete): the Hamiltonian test's result, with where
/// each negative band lies (`places[i]` for `test.bands[i]`).
struct PassivityDetails {
  PassivityResult test;
  std::vector<BandPlace> places;
};

/// passivity_discrete at one rate: the test, or none when the rate was skipped (its filter is unstable).
struct DiscretePassivityRate {
  int fs_hz = 0;
  std::optional<PassivityDetails> passivity;
};
struct DiscretePassivityDetails {
  std::vector<DiscretePassivityRate> rates;
};

/// headroom at one rate (q31/q15): worst state L1 norm (range 1), output L1 norm against its range
/// 2^out_shift, and the output table's sum of |mantissa| (the 64-bit accumulator bound is 2^bits).
struct HeadroomRate {
  int fs_hz = 0;
  double max_state_l1 = 0.0, output_l1 = 0.0, output_range = 0.0, output_table_mantissa_sum = 0.0;
};
struct HeadroomDetails {
  std::vector<HeadroomRate> rates;
};

/// limit_cycle at one rate: zero-input samples simulated (none: not simulated, a pole is outside the
/// unit circle) and, fixed point only, the proven bound on the samples to reach exactly 0.
struct LimitCycleRate {
  int fs_hz = 0;
  std::optional<long> zero_decay_bound;
  std::optional<long> simulated_samples;
};
struct LimitCycleDetails {
  std::vector<LimitCycleRate> rates;
};

/// header_integrity: how many table values and struct fields were compared with the block (the summary
/// states it; schema admitgen.check/1 has no figures for this check).
struct HeaderIntegrityDetails {
  std::size_t values_compared = 0;
};

/// fidelity at one rate (codegen/fidelity.hpp): the emitted filter against its continuous model.
struct FidelityRate {
  int fs_hz = 0;
  double max_rel_deviation = 0.0, at_hz = 0.0;  ///< in the data band
  double max_rel_deviation_above_band = 0.0;    ///< data band's top to 0.45 fs (reported, not judged)
  double noise_floor = 0.0;                     ///< rounding bound at the output for |u| ≤ 1
  double min_full_scale_snr_db = 0.0, snr_at_hz = 0.0;
};
struct FidelityDetails {
  double tolerance = 0.0;  ///< of the in-band deviation
  double min_full_scale_snr_db = 0.0;
  std::vector<FidelityRate> rates;
};

/// The figures of one check; std::monostate when the check did not apply.
using CheckDetails = std::variant<std::monostate, CausalityDetails, DiscreteStabilityDetails, PassivityDetails,
                                  DiscretePassivityDetails, HeadroomDetails, LimitCycleDetails, HeaderIntegrityDetails,
                                  FidelityDetails>;

struct CheckResult {
  std::string name;     ///< stable identifier: causality, discrete_stability, passivity_continuous, ...
  std::string method;   ///< how it was decided
  Status status = Status::pass;
  std::string summary;  ///< one line with the deciding figure (margin, minimum of Re G, ...)
  std::vector<std::string> failures;  ///< each names the failure and where it is
  CheckDetails details;

  /// Records a failure (and marks the check failed).
  void fail(std::string what);
  /// Marks the check as not applying to the subject, `why` as its summary; returns the result.
  CheckResult not_applicable(std::string why);
};

struct CheckReport {
  std::string subject;  ///< the file checked
  std::string kind;     ///< "header" or "fit"
  std::vector<CheckResult> checks;

  bool passed() const;
  /// Names of the failed checks, in order.
  std::vector<std::string> failed_checks() const;
};

}  // namespace admitgen::checks
