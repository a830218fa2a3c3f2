// SPDX-License-Identifier: MIT
#include "checks/state_space.hpp"

namespace admitgen::checks {

StateSpace discrete_realisation(const codegen::DiscreteModel& m) {
  const Eigen::Index taps = static_cast<Eigen::Index>(m.fir.size());
  const Eigen::Index delay = taps > 1 ? taps - 1 : 0;
  const Eigen::Index n = static_cast<Eigen::Index>(m.real.size() + 2 * m.pair.size()) + delay;
  StateSpace ss{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), Eigen::RowVectorXd::Zero(n),
                taps > 0 ? m.fir[0] : 0.0};
  Eigen::Index i = 0;
  for (const auto& r : m.real) {
    const double a = 1.0 - r.eps;
    ss.A(i, i) = a;
    ss.B[i] = r.eps;
    ss.C[i] = r.c * a;
    ss.D += r.c * r.eps;
    ++i;
  }
  for (const auto& p : m.pair) {
    // ψ = ξ + jη; π ψ = [(1+e_r)ξ − p_i η] + j[p_i ξ + (1+e_r) η]; output 2 Re(c ψ) = 2c_r ξ − 2c_i η.
    Eigen::Matrix2d pi;
    pi << 1.0 + p.e_r, -p.p_i, p.p_i, 1.0 + p.e_r;
    const Eigen::RowVector2d out(2.0 * p.c.real(), -2.0 * p.c.imag());
    ss.A.block<2, 2>(i, i) = pi;
    ss.B[i] = p.g;
    ss.C.segment<2>(i) = out * pi;
    ss.D += out[0] * p.g;
    i += 2;
  }
  // Delay line: state k holds u^{n−1−k}; y += d_{k+1} · state k.
  for (Eigen::Index k = 0; k < delay; ++k) {
    if (k == 0)
      ss.B[i] = 1.0;
    else
      ss.A(i + k, i + k - 1) = 1.0;
    ss.C[i + k] = m.fir[static_cast<std::size_t>(k + 1)];
  }
  return ss;
}

}  // namespace admitgen::checks
