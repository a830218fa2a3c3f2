// SPDX-License-Identifier: MIT
/// @file
/// The normal equations of the residues (docs/method.md, "Residues given the poles", which derives the
/// partial fractions used here): with A = [Re Φ; Im Φ] and b = [Re D; Im D],
///   M = AᵀA,   g = Aᵀb,
/// from the sums T_a = Σ_i z_a(ω_i) of the pole functions z_a = 1/(P_a + jω) over the Q + 2S poles,
/// Σ_i conj z_a z_b = (conj T_a + T_b)/(P̄_a + P_b), and g_u = Re Σ_i conj φ_u(ω_i) D_i summed per residue. One pass over
/// the points per pole, O(N (Q + 2S)), instead of forming AᵀA, O(N p²); A is never stored.
///
/// Runtime SIMD dispatch: the pass is compiled for AVX-512, AVX2 and the x86-64 baseline and the best
/// the CPU supports is chosen at load time (function multi-versioning). Every path performs the same
/// IEEE operations in the same order (lane l sums the points i ≡ l mod kGramLanes; no fused multiply-add,
/// the file is compiled with -ffp-contract=off; the lanes are combined in a fixed order), so M and g are
/// bit-identical whichever path runs.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen {

/// Points per block: the partial sums of a block are one AVX-512 register, two AVX2 or four SSE2 ones.
constexpr int kGramLanes = 8;
/// Most residues an order can have (Q, S ≤ 16: 1 + 16 + 2·16).
constexpr int kMaxGramResidues = 49;

/// The frequency points and data, padded to a multiple of kGramLanes (the padding is masked out).
class GramPoints {
 public:
  GramPoints(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& data);
  Eigen::Index size() const { return n_; }  ///< points without the padding
  Eigen::Index padded() const { return static_cast<Eigen::Index>(omega_.size()); }
  const double* omega() const { return omega_.data(); }
  const double* omega2() const { return omega2_.data(); }
  const double* mask() const { return mask_.data(); }  ///< 1 for a point, 0 for padding
  const double* b_re() const { return b_re_.data(); }
  const double* b_im() const { return b_im_.data(); }

 private:
  Eigen::Index n_;
  std::vector<double> omega_, omega2_, mask_, b_re_, b_im_;
};

/// M (p × p, column-major, both triangles) and g (p) for Q real poles and S pairs at ψ
/// (inference/pole_space.hpp packing), p = 1 + Q + 2S ≤ kMaxGramResidues. Allocates nothing.
void residue_gram(const GramPoints& points, int q, int s, const double* poles, double* m, double* g);

/// The instruction set residue_gram runs with on this CPU: "avx512f", "avx2" or "x86-64 baseline"
/// ("portable" off x86-64).
std::string residue_gram_isa();

}  // namespace admitgen
