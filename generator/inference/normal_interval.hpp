// SPDX-License-Identifier: MIT
/// @file
/// The standard normal restricted to an interval: its probability in logs and a draw from it by
/// inversion (the step of the GHK simulator, inference/residue_draws.hpp). Both work from upper tails on
/// the side of the interval away from 0, so no probability near 1 is subtracted.
#pragma once

namespace admitgen {

/// ln P(a ≤ Z ≤ b), Z standard normal (a or b may be infinite). Beyond the range of erfc the
/// asymptotic series ln Q(x) = −x²/2 − ln(x√(2π)) + ln(1 − 1/x² + 3/x⁴) (relative error < 2e-8 for x > 30)
/// keeps it finite.
double log_normal_interval(double a, double b);

/// ln P(l ≤ Z ≤ h) as log_normal_interval, and z = Φ⁻¹(Φ(l) + uniform·(Φ(h) − Φ(l))), a draw of Z given
/// l ≤ Z ≤ h from a uniform in [0, 1). Where the interval lies beyond double precision (its probability
/// underflows in linear terms) z is the end nearer to 0: the conditional law lies within 1/|end| of it.
double normal_interval_draw(double l, double h, double uniform, double& z);

}  // namespace admitgen
