// SPDX-License-Identifier: MIT
/// @file
/// Evidence arithmetic shared by every model comparison (orders in selection/, effects in diagnosis/):
/// sums of evidences in log space and Bayes factors on the deciban scale (docs/method.md, "Model
/// selection" and "One comparison stack").
///
///   log_add_exp(a, b) = ln(e^a + e^b), exact for a or b = −∞;
///   deciban(ln Z_i, ln Z_j) = 10 log₁₀(Z_i/Z_j) = 10 (ln Z_i − ln Z_j)/ln 10;
///   deciban_error(σ_i, σ_j) = 10/ln 10 · √(σ_i² + σ_j²), the error of that difference for independent
///   runs with ln Z errors σ_i, σ_j (nats).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {

inline double log_add_exp(double a, double b) {
  if (a == -std::numeric_limits<double>::infinity()) return b;
  if (b == -std::numeric_limits<double>::infinity()) return a;
  const double m = std::max(a, b);
  return m + std::log1p(std::exp(-std::abs(a - b)));
}

/// Bayes factor in deciban: 10 log10(Z_i / Z_j) = 10 (ln Z_i − ln Z_j)/ln 10.
inline double deciban(double log_z_i, double log_z_j) { return 10.0 * (log_z_i - log_z_j) / std::log(10.0); }

/// The error of deciban(ln Z_i, ln Z_j) from independent ln Z errors (nats).
inline double deciban_error(double log_z_error_i, double log_z_error_j) {
  return 10.0 / std::log(10.0) * std::hypot(log_z_error_i, log_z_error_j);
}

/// Running evidence and information of weighted points (Skilling 2006, eq. 17 for H): add(ln w_i, ln L_i)
/// per point; log_z = ln Σ w_i and h = Σ (w_i/Z) ln(L_i/Z).
struct EvidenceAccumulator {
  double log_z = -std::numeric_limits<double>::infinity();
  double h = 0.0;
  void add(double log_w, double log_l) {
    const double new_log_z = log_add_exp(log_z, log_w);
    const double h_part = std::exp(log_w - new_log_z) * log_l;
    const double h_prev = log_z == -std::numeric_limits<double>::infinity() ? 0.0 : std::exp(log_z - new_log_z) * (h + log_z);
    h = h_part + h_prev - new_log_z;
    log_z = new_log_z;
  }
};

}  // namespace admitgen
