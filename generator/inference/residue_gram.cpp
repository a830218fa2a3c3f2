// SPDX-License-Identifier: MIT
#include "inference/residue_gram.hpp"

#include "core/errors.hpp"

#include <algorithm>

// One clone per instruction set, chosen by the dynamic loader (GCC and Clang function multi-versioning).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(ADMITGEN_NO_MULTIVERSIONING)
#define ADMITGEN_GRAM_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define ADMITGEN_GRAM_CLONES
#endif

namespace admitgen {

GramPoints::GramPoints(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& data) : n_(omega.size()) {
  ADMITGEN_ENSURE(n_ > 0 && data.size() == n_, "{} frequencies for {} data", n_, data.size());
  const Eigen::Index padded = (n_ + kGramLanes - 1) / kGramLanes * kGramLanes;
  for (Eigen::Index i = 0; i < padded; ++i) {
    // Padding repeats the last frequency (finite basis values, masked out) with zero data.
    const Eigen::Index k = std::min(i, n_ - 1);
    omega_.push_back(omega[k]);
    omega2_.push_back(omega[k] * omega[k]);
    b_re_.push_back(i < n_ ? data[i].real() : 0.0);
    b_im_.push_back(i < n_ ? data[i].imag() : 0.0);
  }
}

std::size_t residue_gram_work_size(int p) {
  return static_cast<std::size_t>(p * (p + 1) / 2 + p) * kGramLanes;
}

ADMITGEN_GRAM_CLONES
void residue_gram(const GramPoints& points, int q, int s, const double* poles, double* work, double* m, double* g) {
  constexpr int L = kGramLanes;
  const int p = 1 + q + 2 * s;
  ADMITGEN_ENSURE(p <= kMaxGramResidues, "{} residues", p);
  const int pairs = p * (p + 1) / 2;
  double* __restrict acc = work;              // M's lower triangle, row by row, L partial sums each
  double* __restrict g_acc = work + pairs * L;  // g, L partial sums each
  std::fill(work, work + (pairs + p) * L, 0.0);
  alignas(64) double re[kMaxGramResidues][L], im[kMaxGramResidues][L];
  for (int l = 0; l < L; ++l) re[0][l] = 1.0, im[0][l] = 0.0;  // G∞
  const Eigen::Index n = points.size(), padded = points.padded();
  for (Eigen::Index i0 = 0; i0 < padded; i0 += L) {
    const double* w = points.omega() + i0;
    const double* w2 = points.omega2() + i0;
    // Basis values (the arithmetic of model/multipole.hpp, one division per term):
    //   1/(λ + jω) = (λ − jω)/d,  d = λ² + ω²
    //   φ_B = α/d+ + α/d− − j[(ω+β)/d+ + (ω−β)/d−],  φ_C = (ω+β)/d+ − (ω−β)/d− + jα(1/d+ − 1/d−),
    //   d± = α² + (ω ± β)², 1/d+ = d−/(d+ d−), 1/d− = d+/(d+ d−).
    int k = 1;
    for (int j = 0; j < q; ++j, ++k) {
      const double lam = poles[j], lam2 = lam * lam;
      for (int l = 0; l < L; ++l) {
        const double inv = 1.0 / (lam2 + w2[l]);
        re[k][l] = lam * inv;
        im[k][l] = -w[l] * inv;
      }
    }
    for (int j = 0; j < s; ++j, k += 2) {
      const double al = poles[q + 2 * j], be = poles[q + 2 * j + 1], al2 = al * al;
      for (int l = 0; l < L; ++l) {
        const double wp = w[l] + be, wm = w[l] - be;
        const double d_plus = al2 + wp * wp, d_minus = al2 + wm * wm;
        const double inv = 1.0 / (d_plus * d_minus);
        const double dp = d_minus * inv, dm = d_plus * inv;
        re[k][l] = al * (dp + dm);
        im[k][l] = -(wp * dp + wm * dm);
        re[k + 1][l] = wp * dp - wm * dm;
        im[k + 1][l] = al * (dp - dm);
      }
    }
    if (i0 + L > n)  // the last block: padding lanes contribute nothing
      for (int j = 0; j < p; ++j)
        for (int l = static_cast<int>(n - i0); l < L; ++l) re[j][l] = im[j][l] = 0.0;
    const double* b_re = points.b_re() + i0;
    const double* b_im = points.b_im() + i0;
    double* a = acc;
    for (int j = 0; j < p; ++j) {
      for (int c = 0; c <= j; ++c, a += L)
        for (int l = 0; l < L; ++l) a[l] += re[j][l] * re[c][l] + im[j][l] * im[c][l];
      for (int l = 0; l < L; ++l) g_acc[j * L + l] += re[j][l] * b_re[l] + im[j][l] * b_im[l];
    }
  }
  // Lanes combined in a fixed order.
  const auto lane_sum = [](const double* x) {
    double t = 0.0;
    for (int l = 0; l < L; ++l) t += x[l];
    return t;
  };
  const double* a = acc;
  for (int j = 0; j < p; ++j) {
    for (int c = 0; c <= j; ++c, a += L) m[j + c * p] = m[c + j * p] = lane_sum(a);
    g[j] = lane_sum(g_acc + j * L);
  }
}

std::string residue_gram_isa() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(ADMITGEN_NO_MULTIVERSIONING)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return "avx512f";
  if (__builtin_cpu_supports("avx2")) return "avx2";
  return "x86-64 baseline";
#else
  return "portable";
#endif
}

}  // namespace admitgen
