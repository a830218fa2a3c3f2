// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::checks {

/// Continuous causality and stability: every pole −λ_q, −α_s ± jβ_s in the open left half-plane
/// (docs/physics.md §2.1). The margin is the slowest decay rate.
CheckResult check_causality(const CheckSubject& s) {
  CheckResult r;
  r.name = "causality";
  r.method = "continuous poles: every lambda_q > 0 and alpha_s > 0";
  const Order& o = s.surface.order;
  const auto& th = s.surface.theta;
  double slowest = std::numeric_limits<double>::infinity();
  for (int q = 0; q < o.q(); ++q) slowest = std::min(slowest, th[Order::lambda(q)]);
  for (int k = 0; k < o.s(); ++k) slowest = std::min(slowest, th[o.alpha(k)]);
  for (auto& violation : causality_violations(s.surface)) r.fail(std::move(violation));
  CausalityDetails d;
  if (!std::isinf(slowest)) d.slowest_rate_per_s = slowest;
  r.details = d;
  r.summary = o.buffers() == 0 ? "no poles (G = G_inf)"
                               : fmt::format("{} pole(s); slowest decay rate {:.6g} 1/s", o.q() + o.s(), slowest);
  return r;
}

}  // namespace admitgen::checks
