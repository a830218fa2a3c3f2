// SPDX-License-Identifier: MIT
#include "inference/residue_gram.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <array>
#include <complex>

// One clone per instruction set, chosen by the dynamic loader (GCC and Clang function multi-versioning).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(ADMITGEN_NO_MULTIVERSIONING)
#define ADMITGEN_GRAM_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define ADMITGEN_GRAM_CLONES
#endif

namespace admitgen {

namespace {

using Complex = std::complex<double>;

/// The sums T_a = Σ z_a of the pass, index 0 for z_0 = 1 (T_0 = N is set by the caller), 1 … Q + 2S for the poles.
using PoleSums = std::array<Complex, kMaxGramResidues>;
/// g_u = Re Σ conj(φ_u) D per residue u (φ_u its basis function, model/residue_basis.hpp): Re Σ D for G∞,
/// Re Σ conj(z_a) D for A_q, Re Σ conj(z_θ + z_θ*) D for B_s and Im Σ conj(z_θ − z_θ*) D for C_s. Only these
/// combinations enter the normal equations, so the pass sums them instead of Σ conj(z_a) D per pole.
using ResidueSums = std::array<double, kMaxGramResidues>;

/// Sum of the lanes in a fixed order.
double lane_sum(const double* x) {
  double t = 0.0;
  for (int l = 0; l < kGramLanes; ++l) t += x[l];
  return t;
}

/// Lane sums of one real pole: T (re, im) and g = Re Σ conj(z) D = Σ (zr D_re + zi D_im).
struct RealPoleSums {
  alignas(64) double t_re[kGramLanes] = {}, t_im[kGramLanes] = {}, g[kGramLanes] = {};
};

/// Lane sums of one pair: T of θ and of θ*, and the B and C combinations of g with
/// conj(z) D = (zr D_re + zi D_im) + j (zr D_im − zi D_re):
///   g_B = Σ (zr₊ + zr₋) D_re + (zi₊ + zi₋) D_im,   g_C = Σ (zr₊ − zr₋) D_im − (zi₊ − zi₋) D_re.
struct PairSums {
  alignas(64) double tp_re[kGramLanes] = {}, tp_im[kGramLanes] = {}, tm_re[kGramLanes] = {}, tm_im[kGramLanes] = {};
  alignas(64) double g_b[kGramLanes] = {}, g_c[kGramLanes] = {};
};

/// The pass over the points, pole by pole: z_a(ω) = 1/(P_a + jω) for every pole (one division per real
/// pole, one per pair, as model/multipole.hpp) summed into T_a and into g of each residue, each lane summing
/// the points i ≡ l mod kGramLanes. Padding points carry weight 0 (GramPoints::mask) and zero data.
ADMITGEN_GRAM_CLONES
void sum_over_points(const GramPoints& points, int q, int s, const double* poles, PoleSums& t, ResidueSums& g) {
  constexpr int L = kGramLanes;
  const Eigen::Index padded = points.padded();
  const double* w = points.omega();
  const double* w2 = points.omega2();
  const double* mask = points.mask();
  const double* b_re = points.b_re();
  const double* b_im = points.b_im();
  //   1/(λ + jω) = (λ − jω)/d,  d = λ² + ω²;
  //   1/(α + j(ω ± β)) = (α − j(ω ± β))/d±,  d± = α² + (ω ± β)²,  1/d+ = d−/(d+ d−),  1/d− = d+/(d+ d−).
  for (int j = 0; j < q; ++j) {
    const double lam = poles[j], lam2 = lam * lam;
    RealPoleSums acc;
    for (Eigen::Index i0 = 0; i0 < padded; i0 += L)
      for (int l = 0; l < L; ++l) {
        const Eigen::Index i = i0 + l;
        const double inv = mask[i] / (lam2 + w2[i]);
        const double zr = lam * inv, zi = -w[i] * inv;
        acc.t_re[l] += zr;
        acc.t_im[l] += zi;
        acc.g[l] += zr * b_re[i] + zi * b_im[i];
      }
    t[static_cast<std::size_t>(1 + j)] = Complex(lane_sum(acc.t_re), lane_sum(acc.t_im));
    g[static_cast<std::size_t>(1 + j)] = lane_sum(acc.g);
  }
  for (int j = 0; j < s; ++j) {
    const double al = poles[q + 2 * j], be = poles[q + 2 * j + 1], al2 = al * al;
    PairSums acc;
    for (Eigen::Index i0 = 0; i0 < padded; i0 += L)
      for (int l = 0; l < L; ++l) {
        const Eigen::Index i = i0 + l;
        const double wp = w[i] + be, wm = w[i] - be;
        const double d_plus = al2 + wp * wp, d_minus = al2 + wm * wm;
        const double inv = mask[i] / (d_plus * d_minus);
        const double dp = d_minus * inv, dm = d_plus * inv;
        const double zr_p = al * dp, zi_p = -wp * dp, zr_m = al * dm, zi_m = -wm * dm;
        acc.tp_re[l] += zr_p;
        acc.tp_im[l] += zi_p;
        acc.tm_re[l] += zr_m;
        acc.tm_im[l] += zi_m;
        acc.g_b[l] += (zr_p + zr_m) * b_re[i] + (zi_p + zi_m) * b_im[i];
        acc.g_c[l] += (zr_p - zr_m) * b_im[i] - (zi_p - zi_m) * b_re[i];
      }
    const auto a = static_cast<std::size_t>(1 + q + 2 * j);
    t[a] = Complex(lane_sum(acc.tp_re), lane_sum(acc.tp_im));
    t[a + 1] = Complex(lane_sum(acc.tm_re), lane_sum(acc.tm_im));
    g[a] = lane_sum(acc.g_b);
    g[a + 1] = lane_sum(acc.g_c);
  }
  alignas(64) double b_sum[L] = {};
  for (Eigen::Index i0 = 0; i0 < padded; i0 += L)
    for (int l = 0; l < L; ++l) b_sum[l] += b_re[i0 + l];
  g[0] = lane_sum(b_sum);
}

/// How residue u enters the pole functions: G = Σ_u r_u Σ_(a, κ) κ z_a (z_0 = 1 for G∞). B_s puts 1 on
/// θ_s and on θ_s*, C_s puts j on θ_s and −j on θ_s* (model/residue_basis.hpp); the others one 1.
struct Loading {
  int count;
  std::array<int, 2> pole;
  std::array<Complex, 2> weight;
};

Loading loading(int u, int q) {
  if (u <= q) return {1, {u, 0}, {Complex(1.0, 0.0), Complex()}};
  const int first = q + 1 + 2 * ((u - q - 1) / 2);  // z index of θ_s; θ_s* follows
  if ((u - q - 1) % 2 == 0) return {2, {first, first + 1}, {Complex(1.0, 0.0), Complex(1.0, 0.0)}};
  return {2, {first, first + 1}, {Complex(0.0, 1.0), Complex(0.0, -1.0)}};
}

}  // namespace

GramPoints::GramPoints(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& data) : n_(omega.size()) {
  ADMITGEN_ENSURE(n_ > 0 && data.size() == n_, "{} frequencies for {} data", n_, data.size());
  const Eigen::Index padded = (n_ + kGramLanes - 1) / kGramLanes * kGramLanes;
  for (Eigen::Index i = 0; i < padded; ++i) {
    // Padding repeats the last frequency (finite basis values, masked out) with zero data.
    const Eigen::Index k = std::min(i, n_ - 1);
    omega_.push_back(omega[k]);
    omega2_.push_back(omega[k] * omega[k]);
    mask_.push_back(i < n_ ? 1.0 : 0.0);
    b_re_.push_back(i < n_ ? data[i].real() : 0.0);
    b_im_.push_back(i < n_ ? data[i].imag() : 0.0);
  }
}

void residue_gram(const GramPoints& points, int q, int s, const double* poles, double* m, double* g) {
  const int p = 1 + q + 2 * s;
  ADMITGEN_ENSURE(p <= kMaxGramResidues, "{} residues", p);
  // Pole functions z_0 = 1, z_a = 1/(P_a + jω): P of each, T_a = Σ z_a, and g.
  PoleSums pole{}, t{};
  ResidueSums g_sums{};
  sum_over_points(points, q, s, poles, t, g_sums);
  t[0] = Complex(static_cast<double>(points.size()), 0.0);
  for (int j = 0; j < q; ++j) pole[static_cast<std::size_t>(1 + j)] = Complex(poles[j], 0.0);
  for (int j = 0; j < s; ++j) {
    const double al = poles[q + 2 * j], be = poles[q + 2 * j + 1];
    pole[static_cast<std::size_t>(1 + q + 2 * j)] = Complex(al, be);
    pole[static_cast<std::size_t>(2 + q + 2 * j)] = Complex(al, -be);
  }
  // H_ab = Σ conj(z_a) z_b. By partial fractions (docs/method.md, "Residues given the poles"):
  //   conj(z_a) z_b = 1/((P̄_a − jω)(P_b + jω)) = [1/(P̄_a − jω) + 1/(P_b + jω)]/(P̄_a + P_b),
  // so H_ab = (conj T_a + T_b)/(P̄_a + P_b), Re(P̄_a + P_b) > 0; H_0b = T_b, H_00 = N. H is Hermitian
  // (H_ba = conj H_ab): the lower triangle a ≥ b is computed once, each entry then used by every M_uv whose
  // loadings name it (a pair's B and C both load θ and θ*).
  const int poles_with_one = 1 + q + 2 * s;
  // Real and imaginary parts side by side, left uninitialised (a std::complex array would be zeroed on every
  // call, 20 kB at the largest order): only entries a ≥ b < poles_with_one are written, and only they are read.
  std::array<double, kMaxGramResidues * (kMaxGramResidues + 1)> lower;
  const auto at = [](int a, int b) { return static_cast<std::size_t>(a * (a + 1) + 2 * b); };
  const auto put = [&](int a, int b, Complex h) {
    lower[at(a, b)] = h.real();
    lower[at(a, b) + 1] = h.imag();
  };
  for (int a = 0; a < poles_with_one; ++a) {
    const std::size_t i = static_cast<std::size_t>(a);
    put(a, 0, a == 0 ? t[0] : std::conj(t[i]));
    for (int b = 1; b <= a; ++b) {
      const std::size_t k = static_cast<std::size_t>(b);
      // Division by c = P̄_a + P_b as multiplication by c̄/|c|² (c is never tiny, never infinite: no need of the
      // scaled complex division of C99 Annex G).
      const Complex c = std::conj(pole[i]) + pole[k];
      put(a, b, (std::conj(t[i]) + t[k]) * std::conj(c) / std::norm(c));
    }
  }
  const auto gram = [&](int a, int b) -> Complex {
    return a >= b ? Complex(lower[at(a, b)], lower[at(a, b) + 1]) : Complex(lower[at(b, a)], -lower[at(b, a) + 1]);
  };
  // M_uv = Re Σ conj(κ_u) κ_v H_ab over the loadings of u and v (g came from the pass).
  for (int u = 0; u < p; ++u) {
    const Loading lu = loading(u, q);
    g[u] = g_sums[static_cast<std::size_t>(u)];
    for (int v = 0; v <= u; ++v) {
      const Loading lv = loading(v, q);
      Complex muv;
      for (int i = 0; i < lu.count; ++i)
        for (int k = 0; k < lv.count; ++k)
          muv += std::conj(lu.weight[static_cast<std::size_t>(i)]) * lv.weight[static_cast<std::size_t>(k)] *
                 gram(lu.pole[static_cast<std::size_t>(i)], lv.pole[static_cast<std::size_t>(k)]);
      m[u + v * p] = m[v + u * p] = muv.real();
    }
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
