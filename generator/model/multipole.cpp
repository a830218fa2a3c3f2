#include "model/multipole.hpp"

#include "core/errors.hpp"

namespace admitgen {

void evaluate_multipole(const Order& order, const double* theta, const Eigen::ArrayXd& omega,
                        Eigen::ArrayXd& re, Eigen::ArrayXd& im) {
  re.setConstant(omega.size(), theta[Order::g_inf()]);
  im.setZero(omega.size());
  for (int q = 0; q < order.q(); ++q) {
    const double a = theta[Order::a(q)], lam = theta[Order::lambda(q)];
    const Eigen::ArrayXd inv = (lam * lam + omega.square()).inverse();
    re += (a * lam) * inv;
    im -= a * omega * inv;
  }
  for (int s = 0; s < order.s(); ++s) {
    const double b = theta[order.b(s)], c = theta[order.c(s)];
    const double al = theta[order.alpha(s)], be = theta[order.beta(s)];
    const Eigen::ArrayXd wp = omega + be, wm = omega - be;
    const Eigen::ArrayXd ip = (al * al + wp.square()).inverse();
    const Eigen::ArrayXd im_ = (al * al + wm.square()).inverse();
    re += (b * al + c * wp) * ip + (b * al - c * wm) * im_;
    im += (c * al - b * wp) * ip - (c * al + b * wm) * im_;
  }
}

Eigen::ArrayXcd evaluate_multipole(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega) {
  ADMITGEN_ENSURE(theta.size() == order.dim(), "{} needs {} parameters, got {}", order.name(), order.dim(),
                  theta.size());
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta.data(), omega, re, im);
  Eigen::ArrayXcd g(omega.size());
  g.real() = re;
  g.imag() = im;
  return g;
}

}  // namespace admitgen
