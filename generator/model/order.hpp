// SPDX-License-Identifier: MIT
/// @file
/// A multipole model order "QxSy" and the one packing of its parameter vector, used by inference,
/// reports, codegen and diagnosis alike (never re-derive the packing elsewhere).
///
/// Packing (docs/method.md, paper eq. 2), interleaved per term in the order fit.json names them:
///   θ = [G∞, A_1, λ_1, …, A_Q, λ_Q, B_1, C_1, α_1, β_1, …, B_S, C_S, α_S, β_S],
/// so dim = 1 + 2Q + 4S, and a time-domain solver needs Q + 2S state buffers per boundary node.
#pragma once

#include <string>
#include <vector>

namespace admitgen {

/// The family a parameter belongs to; its prior range is set per family.
enum class Family { g_inf, a, lambda, b, c, alpha, beta };

/// The linear parameters (residues): G∞, A, B, C; the others are poles.
constexpr bool is_residue(Family f) { return f == Family::g_inf || f == Family::a || f == Family::b || f == Family::c; }

class Order {
 public:
  static constexpr int kMaxPoles = 16;  ///< per kind; far above any useful order

  /// Throws InputError if Q or S is negative or above kMaxPoles.
  Order(int q, int s);
  /// Parses "Q1S1" (case-insensitive); throws InputError otherwise.
  static Order parse(const std::string& text);

  int q() const { return q_; }
  int s() const { return s_; }
  int dim() const { return 1 + 2 * q_ + 4 * s_; }
  int buffers() const { return q_ + 2 * s_; }
  std::string name() const;

  // Indices into θ.
  static constexpr int g_inf() { return 0; }
  static constexpr int a(int q) { return 1 + 2 * q; }
  static constexpr int lambda(int q) { return 2 + 2 * q; }
  int b(int s) const { return 1 + 2 * q_ + 4 * s; }
  int c(int s) const { return b(s) + 1; }
  int alpha(int s) const { return b(s) + 2; }
  int beta(int s) const { return b(s) + 3; }

  /// Contract names: G_inf, A_1, lambda_1, B_1, C_1, alpha_1, beta_1 (1-based), in packing order.
  std::vector<std::string> parameter_names() const;
  /// Family of each entry of θ, in packing order.
  std::vector<Family> families() const;

  friend bool operator==(const Order& x, const Order& y) { return x.q_ == y.q_ && x.s_ == y.s_; }
  friend bool operator!=(const Order& x, const Order& y) { return !(x == y); }

 private:
  int q_;
  int s_;
};

/// All orders of the grid Q ∈ [0, qmax] × S ∈ [0, smax], Q-major (Q0S0, Q0S1, …).
std::vector<Order> order_grid(int qmax, int smax);

}  // namespace admitgen
