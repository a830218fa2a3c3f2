#include "checks/check_suite.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace admitgen::checks {

/// Continuous causality and stability: every pole −λ_q, −α_s ± jβ_s in the open left half-plane
/// (physics.md §2.1). The margin is the slowest decay rate.
CheckResult check_causality(const CheckSubject& s) {
  CheckResult r;
  r.name = "causality";
  r.method = "continuous poles: every lambda_q > 0 and alpha_s > 0";
  const Order& o = s.surface.order;
  const auto& th = s.surface.theta;
  double slowest = std::numeric_limits<double>::infinity();
  for (int q = 0; q < o.q(); ++q) {
    const double l = th[Order::lambda(q)];
    slowest = std::min(slowest, l);
    if (!(l > 0.0)) r.fail(fmt::format("lambda_{} = {:.6g} 1/s is not positive: the kernel A e^(-lambda t) grows "
                                       "(pole in the right half-plane or on the axis)", q + 1, l));
  }
  for (int k = 0; k < o.s(); ++k) {
    const double a = th[o.alpha(k)];
    slowest = std::min(slowest, a);
    if (!(a > 0.0)) r.fail(fmt::format("alpha_{} = {:.6g} 1/s is not positive: the pair's kernel grows "
                                       "(beta_{} = {:.6g} 1/s)", k + 1, a, k + 1, th[o.beta(k)]));
  }
  r.details["slowest_rate_per_s"] = std::isinf(slowest) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(slowest);
  r.summary = o.buffers() == 0 ? "no poles (G = G_inf)"
                               : fmt::format("{} pole(s); slowest decay rate {:.6g} 1/s", o.q() + o.s(), slowest);
  return r;
}

}  // namespace admitgen::checks
