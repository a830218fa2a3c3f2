// SPDX-License-Identifier: MIT
/// @file
/// Likelihood of a multipole model given complex admittance data, with the noise variance
/// marginalised under a Jeffreys prior (docs/method.md; paper eq. 10-11):
///   ln L(ϑ) = ln Γ(K/2) − ln 2 − (K/2) ln(π Σ_k ε_k²),
///   Σ_k ε_k² = Σ_i [Re²(D_i − G_i) + Im²(D_i − G_i)].
/// (∫ (2πσ²)^{−K/2} e^{−E/2σ²} dσ/σ = ½ Γ(K/2) (πE)^{−K/2}.)
#pragma once

#include "data/measurement.hpp"
#include "model/multipole.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <string>

namespace admitgen {

/// How many real data a complex point counts for. K = 2N is consistent (each point holds two real
/// numbers) and is the default; K = N is how the paper's text can be read, offered as an option.
enum class DataCount { two_per_point, one_per_point };

DataCount parse_data_count(const std::string& text);  ///< "2N" | "N"
std::string describe(DataCount count);                 ///< e.g. "marginal-gaussian, K = 2N"
/// K, the number of real data in `points` complex points under `count`.
int real_data_count(DataCount count, Eigen::Index points);

/// Holds the data and work buffers: one instance per thread (operator() is not reentrant).
class Likelihood {
 public:
  Likelihood(const Measurement& data, const Order& order, DataCount count);

  /// ln L(θ); θ packed as model/order.hpp. Σε² is floored at 1e-300 so ln L stays finite.
  double operator()(const double* theta) const;
  /// Σ_k ε_k² alone (for residual figures).
  double sum_squared_residual(const double* theta) const;

  const Order& order() const { return order_; }
  int k() const { return k_; }
  Eigen::Index points() const { return d_re_.size(); }

 private:
  Order order_;
  MultipoleGrid grid_;
  Eigen::ArrayXd d_re_, d_im_;
  int k_;
  double constant_;  ///< ln Γ(K/2) − ln 2 − (K/2) ln π
  mutable Eigen::ArrayXd re_, im_;
};

}  // namespace admitgen
