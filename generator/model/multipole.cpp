// SPDX-License-Identifier: MIT
#include "model/multipole.hpp"

#include "core/errors.hpp"

#include <complex>

namespace admitgen {

MultipoleGrid::MultipoleGrid(const Eigen::ArrayXd& omega)
    : omega_(omega), omega2_(omega.square()), dp_(omega.size()), dm_(omega.size()), inv_(omega.size()) {}

void MultipoleGrid::evaluate(const Order& order, const double* theta, Eigen::ArrayXd& re, Eigen::ArrayXd& im) const {
  re.setConstant(omega_.size(), theta[Order::g_inf()]);
  im.setZero(omega_.size());
  for (int q = 0; q < order.q(); ++q) {
    const double a = theta[Order::a(q)], lam = theta[Order::lambda(q)];
    inv_ = (lam * lam + omega2_).inverse();
    re += (a * lam) * inv_;
    im -= a * omega_ * inv_;
  }
  for (int s = 0; s < order.s(); ++s) {
    const double b = theta[order.b(s)], c = theta[order.c(s)];
    const double al = theta[order.alpha(s)], be = theta[order.beta(s)];
    dp_ = al * al + (omega_ + be).square();
    dm_ = al * al + (omega_ - be).square();
    inv_ = (dp_ * dm_).inverse();
    re += ((b * al + c * (omega_ + be)) * dm_ + (b * al - c * (omega_ - be)) * dp_) * inv_;
    im += ((c * al - b * (omega_ + be)) * dm_ - (c * al + b * (omega_ - be)) * dp_) * inv_;
  }
}

void evaluate_multipole(const Order& order, const double* theta, const Eigen::ArrayXd& omega,
                        Eigen::ArrayXd& re, Eigen::ArrayXd& im) {
  MultipoleGrid(omega).evaluate(order, theta, re, im);
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

double term_conditioning(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega) {
  using C = std::complex<double>;
  const Eigen::ArrayXcd jw = C(0.0, 1.0) * omega.cast<C>();
  Eigen::ArrayXd sum = Eigen::ArrayXd::Constant(omega.size(), std::abs(theta[Order::g_inf()]));
  for (int q = 0; q < order.q(); ++q) sum += (theta[Order::a(q)] / (theta[Order::lambda(q)] + jw)).abs();
  for (int s = 0; s < order.s(); ++s) {
    const C r(theta[order.b(s)], theta[order.c(s)]), p(theta[order.alpha(s)], theta[order.beta(s)]);
    sum += (r / (p + jw) + std::conj(r) / (std::conj(p) + jw)).abs();
  }
  const double g = evaluate_multipole(order, theta, omega).abs().maxCoeff();
  return g > 0.0 ? sum.maxCoeff() / g : 1.0;
}

}  // namespace admitgen
