// SPDX-License-Identifier: MIT
#include "model/passivity.hpp"

#include "core/errors.hpp"
#include "core/log_grid.hpp"
#include "model/multipole.hpp"
#include "model/multipole_surface.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace admitgen {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
/// An eigenvalue λ of M counts as imaginary when |Re λ| ≤ kImagTolerance |λ|. Rounding moves a true
/// crossing off the axis by ~ε‖M‖; 1e-5 is far above that, and extra candidates cost one evaluation each.
constexpr double kImagTolerance = 1e-5;
/// |D| (or |G(0)|) below this fraction of the model's scale is treated as zero (R⁻¹ would be ill-conditioned).
constexpr double kSingularFraction = 1e-6;
/// Re G below −kSignTolerance · scale counts as negative (Re G is evaluated to ~1e-15 of the scale).
constexpr double kSignTolerance = 1e-12;
/// Points per decade of the decision's net of direct evaluations (see decide()): 32 for the certificates
/// (continuous_passivity, hamiltonian_passivity), 4 over [λ_min/10, 10 λ_max] for the fitter's is_passive, which
/// runs at every likelihood call of `fit --passive` (32 made that fit 4.6x slower) and whose samples are
/// certified again before anything is shipped.
constexpr int kNetPerDecade = 32;
constexpr int kFitterNetPerDecade = 4;

/// G(0) = D − C A⁻¹ B.
double dc_gain(const StateSpace& ss) {
  if (ss.states() == 0) return ss.D;
  return ss.D - ss.C.dot(ss.A.partialPivLu().solve(ss.B));
}

/// Realisation of G(1/s): Ã = A⁻¹, B̃ = A⁻¹B, C̃ = −CA⁻¹, D̃ = G(0) (docs/physics.md §2.3).
StateSpace reciprocal(const StateSpace& ss) {
  const Eigen::MatrixXd inv = ss.A.partialPivLu().inverse();
  StateSpace r;
  r.A = inv;
  r.B = inv * ss.B;
  r.C = -ss.C * inv;
  r.D = ss.D + r.C.dot(ss.B);
  return r;
}

/// Boundary between {Re G ≥ −tol} and {Re G < −tol} inside [a, b] (exactly one side at each end),
/// by bisection (geometric when a > 0) to 1e-14 relative width.
double polish(const RealPartFn& re, double a, double b, double tol) {
  const bool a_negative = re(a) < -tol;
  for (int it = 0; it < 200 && b - a > 1e-14 * b; ++it) {
    const double m = a > 0.0 ? std::sqrt(a * b) : 0.25 * b;
    ((re(m) < -tol) == a_negative ? a : b) = m;
  }
  return 0.5 * (a + b);
}

/// Minimum of Re G on [lo, hi] (hi finite): log scan, then golden-section refinement of the best cell.
std::pair<double, double> minimum_on(const RealPartFn& re, double lo, double hi) {
  constexpr int kScan = 48;
  const double a0 = lo > 0.0 ? lo : hi * 1e-9;
  double best_w = lo, best = re(lo);
  std::vector<double> w(kScan + 1);
  for (int i = 0; i <= kScan; ++i) w[i] = a0 * std::pow(hi / a0, double(i) / kScan);
  int k = 0;
  for (int i = 0; i <= kScan; ++i) {
    const double v = re(w[i]);
    if (v < best) best = v, best_w = w[i], k = i;
  }
  double a = w[std::max(0, k - 1)], b = w[std::min(kScan, k + 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (re(x1) < re(x2))
      b = x2;
    else
      a = x1;
  }
  const double m = 0.5 * (a + b), vm = re(m);
  if (vm < best) best = vm, best_w = m;
  return {best_w, best};
}

/// Crossing candidates of ss (R = 2D, or the reciprocal / ε-shifted realisation when D vanishes).
std::vector<double> candidates(const StateSpace& ss, double scale, std::string& method) {
  const double g0 = dc_gain(ss);
  if (std::abs(ss.D) >= kSingularFraction * scale) {
    method = "hamiltonian";
    return hamiltonian_crossings(ss);
  }
  if (std::abs(g0) >= kSingularFraction * scale) {
    method = "hamiltonian of the reciprocal realisation G(1/s) (G at infinite frequency is 0)";
    std::vector<double> w;
    for (double v : hamiltonian_crossings(reciprocal(ss)))
      if (v > 0.0) w.push_back(1.0 / v);
    std::sort(w.begin(), w.end());
    return w;
  }
  StateSpace shifted = ss;
  shifted.D += kSingularFraction * scale;
  method = fmt::format("hamiltonian of G + {:.3g} (G(0) = G(inf) = 0: proves Re G >= -{:.3g})",
                       kSingularFraction * scale, kSingularFraction * scale);
  return hamiltonian_crossings(shifted);
}

/// The exact decision: crossings → sign per interval → polished negative bands, over [lo, hi] and beyond.
/// A net of kNetPerDecade log-spaced points per decade over [lo, hi] joins the sample points: where residues
/// cancel by many orders of magnitude (|A| ~ 1e9 for |G| ~ 1e3, a posterior sample along a nearly degenerate
/// residue direction), rounding moves the Hamiltonian's imaginary-axis eigenvalues off the axis and the
/// crossings are lost; every negative band at least a net spacing wide is still found, by direct evaluation of
/// Re G. (Such a sample, certified before the net, had Re G = −1225 at 5359 Hz: tests/checks/test_passivity.cpp.)
PassivityResult decide(const StateSpace& ss, const RealPartFn& re, double scale, double lo, double hi,
                       int net_per_decade = kNetPerDecade) {
  PassivityResult r;
  const double w_ref = std::sqrt(lo * hi);
  const double tol = kSignTolerance * scale;
  const std::vector<double> cand = candidates(ss, scale, r.method);
  // Sample points: 0, every candidate, the midpoint of each gap, one point beyond the last, the net, and ∞ (= D).
  std::vector<double> w{0.0};
  double prev = 0.0;
  for (double c : cand) {
    if (c <= 0.0) continue;
    w.push_back(prev > 0.0 ? std::sqrt(prev * c) : 0.5 * c);
    w.push_back(c);
    prev = c;
  }
  w.push_back(prev > 0.0 ? 2.0 * prev : w_ref);
  const std::vector<double> net = log_grid(lo, hi, net_per_decade);
  w.insert(w.end(), net.begin(), net.end());
  std::sort(w.begin(), w.end());
  w.erase(std::unique(w.begin(), w.end()), w.end());
  std::vector<double> v;
  for (double x : w) v.push_back(re(x));
  w.push_back(kInf);
  v.push_back(ss.D);
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(v[i] < -tol)) continue;
    std::size_t j = i;
    while (j + 1 < w.size() && v[j + 1] < -tol) ++j;
    NegativeBand b;
    b.lo = i == 0 ? 0.0 : polish(re, w[i - 1], w[i], tol);
    if (j + 1 < w.size()) {
      b.hi = w[j + 1] == kInf ? kInf : polish(re, w[j], w[j + 1], tol);
    } else {
      b.hi = kInf;
    }
    if (b.hi == kInf && j + 1 == w.size() - 1) {
      // Negative up to the last finite sample but G(∞) ≥ 0: the band ends further out; bracket it.
      double x = w[j];
      for (int k = 0; k < 200 && re(x) < -tol; ++k) x *= 2.0;
      if (!(re(x) < -tol)) b.hi = polish(re, w[j], x, tol);
    }
    const double hi = b.hi == kInf ? std::max(1e6 * std::max(b.lo, w_ref), 1e6) : b.hi;
    std::tie(b.at, b.min_re) = minimum_on(re, b.lo, hi);
    if (b.hi == kInf && ss.D < b.min_re) b.min_re = ss.D, b.at = kInf;
    r.bands.push_back(b);
    i = j;
  }
  for (double c : cand)
    if (c > 0.0 && std::abs(re(c)) <= 1e-6 * scale) r.crossings.push_back(c);
  for (const auto& b : r.bands) {
    if (b.lo > 0.0) r.crossings.push_back(b.lo);
    if (b.hi < kInf) r.crossings.push_back(b.hi);
  }
  std::sort(r.crossings.begin(), r.crossings.end());
  r.crossings.erase(std::unique(r.crossings.begin(), r.crossings.end(),
                                [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; }),
                    r.crossings.end());
  r.passive = r.bands.empty();
  return r;
}

/// Scale of G: an upper bound of |G(jω)| for the block-diagonal realisations used here, else the
/// largest |Re G| on a coarse grid, |D| and |G(0)|.
double model_scale(const StateSpace& ss, const RealPartFn& re, double lo, double hi) {
  double s = std::max(std::abs(ss.D), std::abs(dc_gain(ss)));
  for (int i = 0; i <= 64; ++i) s = std::max(s, std::abs(re(lo * std::pow(hi / lo, i / 64.0))));
  return s > 0.0 ? s : 1.0;
}

/// Dense log scan (reporting the minimum only; the decision above does not depend on it).
void scan_minimum(PassivityResult& r, const RealPartFn& re, double lo, double hi, double d) {
  r.min_re = d;
  r.min_at = kInf;
  constexpr int kScan = 2000;
  for (int i = 0; i <= kScan; ++i) {
    const double w = lo * std::pow(hi / lo, double(i) / kScan), v = re(w);
    if (v < r.min_re) r.min_re = v, r.min_at = w;
  }
  const double v0 = re(0.0);
  if (v0 < r.min_re) r.min_re = v0, r.min_at = 0.0;
  for (const auto& b : r.bands)
    if (b.min_re < r.min_re) r.min_re = b.min_re, r.min_at = b.at;
}

double re_multipole(const Order& order, const double* theta, double omega) {
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta, Eigen::ArrayXd::Constant(1, omega), re, im);
  return re[0];
}

/// |G∞| + Σ |A|/λ + Σ 2|B + jC|/α ≥ max |G(jω)|.
double multipole_bound(const Order& order, const double* theta) {
  double s = std::abs(theta[Order::g_inf()]);
  for (int q = 0; q < order.q(); ++q) s += std::abs(theta[Order::a(q)]) / theta[Order::lambda(q)];
  for (int k = 0; k < order.s(); ++k)
    s += 2.0 * std::hypot(theta[order.b(k)], theta[order.c(k)]) / theta[order.alpha(k)];
  return s > 0.0 ? s : 1.0;
}

/// Slowest and fastest pole magnitudes (rad/s).
std::pair<double, double> pole_range(const Order& order, const double* theta) {
  double lo = kInf, hi = 0.0;
  for (int q = 0; q < order.q(); ++q) lo = std::min(lo, theta[Order::lambda(q)]), hi = std::max(hi, theta[Order::lambda(q)]);
  for (int k = 0; k < order.s(); ++k) {
    const double m = std::hypot(theta[order.alpha(k)], theta[order.beta(k)]);
    lo = std::min(lo, m), hi = std::max(hi, m);
  }
  return {lo, hi};
}

}  // namespace

std::vector<double> hamiltonian_crossings(const StateSpace& ss) {
  const Eigen::Index n = ss.states();
  if (n == 0) return {};
  ADMITGEN_ENSURE(ss.D != 0.0, "Hamiltonian test needs D != 0");
  // Frequency normalisation s = w s' (A/w, B/√w, C/√w) keeps M's entries of order one.
  const double w = std::max(ss.A.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  const Eigen::MatrixXd A = ss.A / w;
  const Eigen::VectorXd B = ss.B / std::sqrt(w);
  const Eigen::RowVectorXd C = ss.C / std::sqrt(w);
  const double r_inv = 1.0 / (2.0 * ss.D);
  Eigen::MatrixXd M(2 * n, 2 * n);
  M.topLeftCorner(n, n) = A - r_inv * B * C;
  M.topRightCorner(n, n) = -r_inv * B * B.transpose();
  M.bottomLeftCorner(n, n) = r_inv * C.transpose() * C;
  M.bottomRightCorner(n, n) = -A.transpose() + r_inv * C.transpose() * B.transpose();
  // The real Schur iteration first; where it does not converge in its default 40 sweeps per row (badly
  // scaled M: nearly coincident poles with large opposite residues), the complex Schur iteration (other
  // shifts) with ten times the sweeps.
  Eigen::VectorXcd eigenvalues;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(M, false);
  if (es.info() == Eigen::Success) {
    eigenvalues = es.eigenvalues();
  } else {
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ces;
    ces.setMaxIterations(400 * M.rows());
    ces.compute(M.cast<std::complex<double>>(), false);
    ADMITGEN_ENSURE(ces.info() == Eigen::Success, "Hamiltonian eigenvalues did not converge");
    eigenvalues = ces.eigenvalues();
  }
  std::vector<double> out;
  for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) {
    const auto l = eigenvalues[i];
    if (std::abs(l.real()) <= kImagTolerance * std::abs(l) + 1e-14 && l.imag() >= 0.0) out.push_back(w * l.imag());
  }
  std::sort(out.begin(), out.end());
  return out;
}

PassivityResult hamiltonian_passivity(const StateSpace& ss, const RealPartFn& re, double scan_lo, double scan_hi,
                                      bool scan) {
  const double scale = model_scale(ss, re, scan_lo, scan_hi);
  PassivityResult r = decide(ss, re, scale, scan_lo, scan_hi);
  if (scan) {
    scan_minimum(r, re, scan_lo, scan_hi, ss.D);
  } else {
    r.min_re = ss.D, r.min_at = kInf;
    for (const auto& b : r.bands)
      if (b.min_re < r.min_re) r.min_re = b.min_re, r.min_at = b.at;
  }
  return r;
}

PassivityResult continuous_passivity(const Order& order, const double* theta) {
  const StateSpace ss = continuous_realisation(order, theta);
  const RealPartFn re = [&](double w) { return re_multipole(order, theta, w); };
  PassivityResult r;
  if (ss.states() == 0) {
    r.method = "constant G = G_inf";
    r.min_re = ss.D;
    r.min_at = 0.0;
    if (ss.D < 0.0) r.bands.push_back({0.0, kInf, ss.D, 0.0});
  } else {
    const auto [lo, hi] = pole_range(order, theta);
    ADMITGEN_ENSURE(lo > 0.0, "continuous passivity needs a causal model (every lambda, alpha > 0)");
    r = decide(ss, re, multipole_bound(order, theta), 1e-3 * lo, 1e3 * hi);
    scan_minimum(r, re, 1e-3 * lo, 1e3 * hi, ss.D);
  }
  r.passive = r.bands.empty();
  const auto hz = [](double w) { return w / (2.0 * kPi); };
  for (auto& c : r.crossings) c = hz(c);
  for (auto& b : r.bands) b.lo = hz(b.lo), b.hi = hz(b.hi), b.at = hz(b.at);
  r.min_at = hz(r.min_at);
  return r;
}

bool is_passive(const Order& order, const double* theta) {
  if (!is_causal(order, theta)) return false;
  const double g_inf = theta[Order::g_inf()];
  if (g_inf < 0.0) return false;
  bool termwise = true;
  double g0 = g_inf;
  for (int q = 0; q < order.q(); ++q) {
    termwise = termwise && theta[Order::a(q)] >= 0.0;
    g0 += theta[Order::a(q)] / theta[Order::lambda(q)];
  }
  for (int k = 0; k < order.s(); ++k) {
    const double b = theta[order.b(k)], c = theta[order.c(k)], al = theta[order.alpha(k)], be = theta[order.beta(k)];
    termwise = termwise && std::abs(c * be) <= b * al;
    g0 += 2.0 * (b * al + c * be) / (al * al + be * be);
  }
  if (termwise) return true;
  if (g0 < 0.0) return false;
  const RealPartFn re = [&](double w) { return re_multipole(order, theta, w); };
  const auto [lo, hi] = pole_range(order, theta);
  return decide(continuous_realisation(order, theta), re, multipole_bound(order, theta), 0.1 * lo, 10.0 * hi,
                kFitterNetPerDecade)
      .passive;
}

std::vector<double> resonance_points(double centre, double half) {
  constexpr int kPoints = 32;  // 31 interior nodes of φ
  std::vector<double> out;
  for (int i = 1; i < kPoints; ++i) out.push_back(centre + half * std::tan(kPi * (double(i) / kPoints - 0.5)));
  return out;
}

}  // namespace admitgen
