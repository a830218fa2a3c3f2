// SPDX-License-Identifier: MIT
#include "numerics/passive_bound.hpp"

#include "core/errors.hpp"
#include "core/log_grid.hpp"
#include "numerics/least_squares_inequality.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace admitgen::numerics {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// ln|x|, floored so that a data frequency that falls exactly on a node gives a finite term: there the two
/// pieces of a hat meet with equal u, and their logarithmic terms cancel (x ln x → 0).
double log_abs(double x) { return std::log(std::max(std::abs(x), 1e-300)); }

/// Im G(jω) of u = a + b ω' on [w0, w1] and 0 elsewhere (the file comment's integral, term by term):
/// ∫ a/(ω'² − ω²) dω' = a/(2ω) ln|(ω' − ω)/(ω' + ω)|, ∫ b ω'/(ω'² − ω²) dω' = (b/2) ln|ω'² − ω²|.
double piece_imag(double a, double b, double w0, double w1, double w) {
  const double l1 = log_abs(w1 - w) - log_abs(w1 + w) - log_abs(w0 - w) + log_abs(w0 + w);
  const double l2 = log_abs(w1 - w) + log_abs(w1 + w) - log_abs(w0 - w) - log_abs(w0 + w);
  return (a * l1 + b * w * l2) / kPi;
}

/// The hat with nodes w0 < w1 < w2 (u(w1) = 1) at ω.
std::complex<double> hat(double w0, double w1, double w2, double w) {
  const double rise = 1.0 / (w1 - w0), fall = 1.0 / (w2 - w1);
  double re = 0.0;
  if (w > w0 && w < w1) re = (w - w0) * rise;
  else if (w >= w1 && w < w2) re = (w2 - w) * fall;
  return {re, piece_imag(-w0 * rise, rise, w0, w1, w) + piece_imag(w2 * fall, -fall, w1, w2, w)};
}

}  // namespace

PassiveBound passive_bound(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& values, const Eigen::ArrayXd& weights) {
  const Eigen::Index m = omega.size();
  ADMITGEN_ENSURE(m > 0 && values.size() == m && weights.size() == m, "passive bound: {} frequencies", m);
  ADMITGEN_ENSURE(omega.minCoeff() > 0.0, "passive bound: frequencies must be positive");
  const double w_lo = omega.minCoeff(), w_hi = omega.maxCoeff();
  std::vector<std::complex<double>> columns;  // column-major, m values per term
  const auto add = [&](auto term) {
    for (Eigen::Index i = 0; i < m; ++i) columns.push_back(term(omega[i]));
  };
  add([](double) { return std::complex<double>(1.0, 0.0); });
  for (const double l : log_grid(w_lo / 1000.0, 1000.0 * w_hi, PassiveBound::kFarPerDecade)) {
    add([l](double w) { return l / std::complex<double>(l, w); });
    add([l](double w) { return std::complex<double>(0.0, w) / std::complex<double>(l, w); });
  }
  const std::vector<double> nodes = log_grid(w_lo / 10.0, 10.0 * w_hi, PassiveBound::kHatsPerDecade);
  for (std::size_t k = 1; k + 1 < nodes.size(); ++k)
    add([&, k](double w) { return hat(nodes[k - 1], nodes[k], nodes[k + 1], w); });

  const Eigen::Index n = static_cast<Eigen::Index>(columns.size()) / m;
  Eigen::MatrixXd a(2 * m, n);
  Eigen::VectorXd b(2 * m);
  for (Eigen::Index i = 0; i < m; ++i) {
    b[i] = weights[i] * values[i].real();
    b[m + i] = weights[i] * values[i].imag();
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::complex<double> g = columns[static_cast<std::size_t>(j * m + i)];
      a(i, j) = weights[i] * g.real();
      a(m + i, j) = weights[i] * g.imag();
    }
  }
  const Eigen::VectorXd x = numerics::non_negative_least_squares(a, b);
  PassiveBound out;
  out.relative_rms_residual = (a * x - b).norm() / b.norm();
  out.terms = static_cast<int>((x.array() > 0.0).count());
  out.dictionary = static_cast<int>(n);
  const Eigen::VectorXd ax = a * x;
  out.fitted.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) out.fitted[i] = std::complex<double>(ax[i], ax[m + i]) / weights[i];
  return out;
}

}  // namespace admitgen::numerics
