// SPDX-License-Identifier: MIT
/// @file
/// `admitgen check` as a library: what is checked (a header's machine-readable block and C tables, or a
/// fit's continuous model) and the six safety checks plus the header's self-consistency:
///
///  causality             every λ_q, α_s > 0 (continuous poles in the left half-plane)
///  discrete_stability    every emitted, quantised pole |z| < 1, exactly (integer arithmetic for q31/q15)
///  passivity_continuous  Re G(jω) ≥ 0 ∀ω ≥ 0 by the Hamiltonian eigenvalue test (model/passivity.hpp)
///  passivity_discrete    Re H(e^{jθ}) ≥ 0 on [0, π] for the emitted, quantised filter (bilinear map z → s)
///  headroom              L1 norm of each state's and the output's impulse response within its Q range,
///                        64-bit accumulator bounds (q31/q15)
///  limit_cycle           zero input after full-scale states reaches exactly 0 (the runtime's own kernels,
///                        codegen/runtime_filter.hpp) — no limit cycle, no deadband
///  fidelity              the emitted coefficients, as the kernel runs them, within the tolerance of the header's
///                        continuous model in the data band, and a full-scale tone's output above the kernel's
///                        rounding noise by 20 dB (codegen/fidelity.hpp)
///  header_integrity      the C tables and model structs equal the machine-readable block
#pragma once

#include "checks/report.hpp"
#include "codegen/emission.hpp"
#include "model/fit_record.hpp"
#include "model/multipole_surface.hpp"

#include <optional>
#include <string>

namespace admitgen::checks {

struct CheckSubject {
  std::string origin;
  std::string kind;  ///< "header" or "fit"
  MultipoleSurface surface{Order(0, 0), Eigen::VectorXd::Zero(1)};
  double data_f_min_hz = 0.0, data_f_max_hz = 0.0;
  std::optional<codegen::EmittedHeader> header;  ///< headers only
  std::string header_text;                       ///< headers only
  std::string note;  ///< e.g. which estimate was checked when the requested one is absent
  double fidelity_tolerance = codegen::kDefaultFidelityTolerance;  ///< `--fidelity-tolerance`
};

/// From an emitted header: its model block as read (io::read_emitted_header) and its text, whose C tables
/// header_integrity compares with the block (io::header_subject reads both from the text).
CheckSubject subject_from_header(const codegen::EmittedHeader& header, const std::string& text,
                                 const std::string& origin);
/// From a fit: the selected order, or `order`, and the estimate (a fit without a passive
/// estimate, written by an older admitgen, is checked at its posterior mean, and `note` says so).
CheckSubject subject_from_fit(const FitRecord& fit, const std::string& origin, const std::string& order,
                              Estimate estimate);
CheckResult check_causality(const CheckSubject& subject);
CheckResult check_discrete_stability(const CheckSubject& subject);
CheckResult check_continuous_passivity(const CheckSubject& subject);
CheckResult check_discrete_passivity(const CheckSubject& subject);
CheckResult check_headroom(const CheckSubject& subject);
CheckResult check_limit_cycles(const CheckSubject& subject);
CheckResult check_fidelity(const CheckSubject& subject);
CheckResult check_header_integrity(const CheckSubject& subject);

/// Every check, in the order above (header_integrity last).
CheckReport run_checks(const CheckSubject& subject);

/// "fs 48000 Hz, pair 2 (alpha 310 1/s, beta 6283 1/s = 1000 Hz)" and the like, for failure messages.
std::string term_location(int fs_hz, const codegen::DiscreteModel& model, bool pair, std::size_t index);

}  // namespace admitgen::checks
