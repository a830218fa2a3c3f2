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
/// Points per decade of the decision's net of direct evaluations (see decide()): 200 for the certificates
/// (continuous_passivity, hamiltonian_passivity: the net is also the reported minimum's scan), 4 over
/// [λ_min/10, 10 λ_max] for the fitter's is_passive, which runs at every likelihood call of `fit --passive`
/// (32 made that fit 4.6x slower) and whose samples are certified again before anything is shipped.
constexpr int kNetPerDecade = 200;
constexpr int kFitterNetPerDecade = 4;
/// The net of a certifier in a loop (hamiltonian_passivity without the scan: emit's constraint rounds, whose
/// final candidate is certified again with the full net).
constexpr int kLoopNetPerDecade = 32;
/// A Hamiltonian eigenvalue λ with |Re λ| ≤ kWindowSlope · Im λ gets a window of samples centred at Im λ
/// (half width max(|Re λ|, kWindowFloor · |λ|)): a pair of crossings closer than rounding can resolve
/// leaves the axis as ±δ + jω_m, ω_m inside the negative band between them (docs/passivity.md, "What the
/// certificate guarantees").
constexpr double kWindowSlope = 1.0;
constexpr double kWindowFloor = 1e-7;

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

/// Boundary between {Re G ≥ 0} and {Re G < 0} inside [a, b] (exactly one side at each end), by bisection
/// (geometric when a > 0) to 1e-14 relative width.
double polish(const RealPartFn& re, double a, double b) {
  const bool a_negative = re(a) < 0.0;
  for (int it = 0; it < 200 && b - a > 1e-14 * b; ++it) {
    const double m = a > 0.0 ? std::sqrt(a * b) : 0.25 * b;
    ((re(m) < 0.0) == a_negative ? a : b) = m;
  }
  return 0.5 * (a + b);
}

/// Golden-section minimum of Re G on [a, b] (60 steps: the bracket shrinks by 0.618^60 ≈ 3e-13).
std::pair<double, double> golden_minimum(const RealPartFn& re, double a, double b) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (re(x1) < re(x2))
      b = x2;
    else
      a = x1;
  }
  const double m = 0.5 * (a + b);
  return {m, re(m)};
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
  const auto [m, vm] = golden_minimum(re, w[std::max(0, k - 1)], w[std::min(kScan, k + 1)]);
  if (vm < best) best = vm, best_w = m;
  return {best_w, best};
}

/// Whether a Hamiltonian eigenvalue counts as a crossing candidate: |Re λ| ≤ kImagTolerance |λ|.
bool near_axis(std::complex<double> l) { return std::abs(l.real()) <= kImagTolerance * std::abs(l); }

/// Hamiltonian eigenvalues of ss (R = 2D, or the reciprocal / ε-shifted realisation when D vanishes), mapped
/// to the s-plane of G (Im ≥ 0), and the crossing candidates among them (|Re λ| ≤ kImagTolerance |λ|).
struct Spectrum {
  std::vector<std::complex<double>> eigenvalues;
  std::vector<double> crossings;
};

Spectrum spectrum(const StateSpace& ss, double scale, std::string& method) {
  const double g0 = dc_gain(ss);
  Spectrum out;
  if (std::abs(ss.D) >= kSingularFraction * scale) {
    method = "hamiltonian";
    out.eigenvalues = hamiltonian_eigenvalues(ss);
  } else if (std::abs(g0) >= kSingularFraction * scale) {
    method = "hamiltonian of the reciprocal realisation G(1/s) (G at infinite frequency is 0)";
    // s = 1/s': an eigenvalue s' of the reciprocal's Hamiltonian is the point 1/s' of G's s-plane.
    for (const auto l : hamiltonian_eigenvalues(reciprocal(ss)))
      if (std::abs(l) > 0.0) {
        const auto m = 1.0 / l;
        out.eigenvalues.emplace_back(m.real(), std::abs(m.imag()));
      }
  } else {
    StateSpace shifted = ss;
    shifted.D += kSingularFraction * scale;
    method = fmt::format("hamiltonian of G + {:.3g} (G(0) = G(inf) = 0), with the sign of Re G itself sampled",
                         kSingularFraction * scale);
    out.eigenvalues = hamiltonian_eigenvalues(shifted);
  }
  for (const auto l : out.eigenvalues)
    if (near_axis(l) && l.imag() > 0.0) out.crossings.push_back(l.imag());
  std::sort(out.crossings.begin(), out.crossings.end());
  return out;
}

/// The sample points of the decision (native frequency, ascending, distinct, all ≥ 0): 0, every crossing
/// candidate and the midpoint of each gap, one point beyond the last, the net over [lo, hi], the windows of the
/// eigenvalues near the axis and the caller's feature windows.
std::vector<double> sample_points(const Spectrum& sp, const std::vector<FeatureWindow>& features, double lo, double hi,
                                  int net_per_decade) {
  std::vector<double> w{0.0};
  double prev = 0.0;
  for (double c : sp.crossings) {
    w.push_back(prev > 0.0 ? std::sqrt(prev * c) : 0.5 * c);
    w.push_back(c);
    prev = c;
  }
  w.push_back(prev > 0.0 ? 2.0 * prev : std::sqrt(lo * hi));
  const std::vector<double> net = log_grid(lo, hi, net_per_decade);
  w.insert(w.end(), net.begin(), net.end());
  const auto add_window = [&w](double centre, double half) {
    w.push_back(centre);
    for (double x : resonance_points(centre, half))
      if (x > 0.0) w.push_back(x);
  };
  for (const auto l : sp.eigenvalues)
    if (l.imag() > 0.0 && std::abs(l.real()) <= kWindowSlope * l.imag())
      add_window(l.imag(), std::max(std::abs(l.real()), kWindowFloor * std::abs(l)));
  for (const auto& f : features)
    if (f.centre > 0.0 && f.half > 0.0) add_window(f.centre, f.half);
  std::sort(w.begin(), w.end());
  w.erase(std::unique(w.begin(), w.end()), w.end());
  return w;
}

/// Re G at many frequencies at once (the bulk of the decision's samples); empty: one call of the scalar one each.
using RealPartsFn = std::function<std::vector<double>(const std::vector<double>& omega)>;

/// The decision (docs/passivity.md, "What the certificate guarantees"). Re G is evaluated at the sample points
/// (sample_points); every local minimum among them is refined by golden section between its neighbours; every
/// run of samples with Re G < 0 (strictly: no tolerance, so a reported minimum below 0 is always a band) is a
/// negative band, its edges polished by bisection. The Hamiltonian's eigenvalues supply the crossings and the
/// windows where narrow bands hide (between two crossings closer than rounding resolves, the pair of
/// eigenvalues leaves the axis); the net catches bands that rounding hides from the eigenvalues entirely (where
/// residues cancel by many orders of magnitude, |A| ~ 1e9 for |G| ~ 1e3: such a sample, certified before the
/// net, had Re G = −1225 at 5359 Hz: tests/checks/test_passivity.cpp).
PassivityResult decide(const StateSpace& ss, const RealPartFn& re, double scale, double lo, double hi,
                       const std::vector<FeatureWindow>& features, int net_per_decade = kNetPerDecade,
                       const RealPartsFn& res = {}) {
  PassivityResult r;
  const Spectrum sp = spectrum(ss, scale, r.method);
  std::vector<double> w = sample_points(sp, features, lo, hi, net_per_decade);
  std::vector<double> v;
  if (res) {
    v = res(w);
  } else {
    for (const double x : w) v.push_back(re(x));
  }
  // Refine every interior local minimum that is not already negative: a dip narrower than the spacing.
  std::vector<std::pair<double, double>> refined;
  for (std::size_t i = 1; i + 1 < w.size(); ++i)
    if (v[i] <= v[i - 1] && v[i] <= v[i + 1] && v[i] >= 0.0) {
      const auto m = golden_minimum(re, w[i - 1], w[i + 1]);
      if (m.second < v[i]) refined.push_back(m);
    }
  // The samples and the refined minima in frequency order.
  std::vector<std::pair<double, double>> merged;
  for (std::size_t i = 0; i < w.size(); ++i) merged.emplace_back(w[i], v[i]);
  merged.insert(merged.end(), refined.begin(), refined.end());
  std::sort(merged.begin(), merged.end());
  std::vector<double> ws, vs;
  for (const auto& [x, y] : merged) ws.push_back(x), vs.push_back(y);
  ws.push_back(kInf);
  vs.push_back(ss.D);
  r.min_re = ss.D, r.min_at = kInf;
  for (std::size_t i = 0; i + 1 < ws.size(); ++i)
    if (vs[i] < r.min_re) r.min_re = vs[i], r.min_at = ws[i];
  for (std::size_t i = 0; i < ws.size(); ++i) {
    if (!(vs[i] < 0.0)) continue;
    std::size_t j = i;
    while (j + 1 < ws.size() && vs[j + 1] < 0.0) ++j;
    NegativeBand b;
    b.lo = i == 0 ? 0.0 : polish(re, ws[i - 1], ws[i]);
    b.hi = j + 1 < ws.size() ? (ws[j + 1] == kInf ? kInf : polish(re, ws[j], ws[j + 1])) : kInf;
    if (b.hi == kInf && j + 1 == ws.size() - 1) {
      // Negative up to the last finite sample but G(∞) ≥ 0: the band ends further out; bracket it.
      double x = ws[j];
      for (int k = 0; k < 200 && re(x) < 0.0; ++k) x *= 2.0;
      if (!(re(x) < 0.0)) b.hi = polish(re, ws[j], x);
    }
    const double top = b.hi == kInf ? std::max(1e6 * std::max(b.lo, std::sqrt(lo * hi)), 1e6) : b.hi;
    std::tie(b.at, b.min_re) = minimum_on(re, b.lo, top);
    for (std::size_t k = i; k <= j && k + 1 < ws.size(); ++k)
      if (vs[k] < b.min_re) b.min_re = vs[k], b.at = ws[k];
    if (b.hi == kInf && ss.D < b.min_re) b.min_re = ss.D, b.at = kInf;
    if (b.min_re < r.min_re) r.min_re = b.min_re, r.min_at = b.at;
    r.bands.push_back(b);
    i = j;
  }
  for (double c : sp.crossings)
    if (std::abs(re(c)) <= 1e-6 * scale) r.crossings.push_back(c);
  for (const auto& b : r.bands) {
    if (b.lo > 0.0) r.crossings.push_back(b.lo);
    if (b.hi < kInf) r.crossings.push_back(b.hi);
  }
  std::sort(r.crossings.begin(), r.crossings.end());
  r.crossings.erase(std::unique(r.crossings.begin(), r.crossings.end(),
                                [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; }),
                    r.crossings.end());
  r.passive = r.bands.empty() && r.min_re >= 0.0;
  return r;
}

/// Scale of G: an upper bound of |G(jω)| for the block-diagonal realisations used here, else the
/// largest |Re G| on a coarse grid, |D| and |G(0)|.
double model_scale(const StateSpace& ss, const RealPartFn& re, double lo, double hi) {
  double s = std::max(std::abs(ss.D), std::abs(dc_gain(ss)));
  for (int i = 0; i <= 64; ++i) s = std::max(s, std::abs(re(lo * std::pow(hi / lo, i / 64.0))));
  return s > 0.0 ? s : 1.0;
}

/// Re G of a multipole at every ω of `omega` (one vectorised pass per term).
std::vector<double> re_multipole_at(const Order& order, const double* theta, const std::vector<double>& omega) {
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta, Eigen::Map<const Eigen::ArrayXd>(omega.data(), Eigen::Index(omega.size())), re, im);
  return {re.data(), re.data() + re.size()};
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

std::vector<std::complex<double>> hamiltonian_eigenvalues(const StateSpace& ss) {
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
  std::vector<std::complex<double>> out;
  for (Eigen::Index i = 0; i < eigenvalues.size(); ++i)
    if (eigenvalues[i].imag() >= 0.0) out.push_back(w * eigenvalues[i]);
  return out;
}

PassivityResult hamiltonian_passivity(const StateSpace& ss, const RealPartFn& re, double scan_lo, double scan_hi,
                                      bool scan, const std::vector<FeatureWindow>& features) {
  const double scale = model_scale(ss, re, scan_lo, scan_hi);
  return decide(ss, re, scale, scan_lo, scan_hi, features, scan ? kNetPerDecade : kLoopNetPerDecade);
}

std::vector<FeatureWindow> resonance_windows(const Order& order, const double* theta) {
  std::vector<FeatureWindow> out;
  for (int k = 0; k < order.s(); ++k)
    out.push_back({std::abs(theta[order.beta(k)]), theta[order.alpha(k)]});
  return out;
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
    r.passive = r.bands.empty();
  } else {
    const auto [lo, hi] = pole_range(order, theta);
    ADMITGEN_ENSURE(lo > 0.0, "continuous passivity needs a causal model (every lambda, alpha > 0)");
    r = decide(ss, re, multipole_bound(order, theta), 1e-3 * lo, 1e3 * hi, resonance_windows(order, theta),
               kNetPerDecade, [&](const std::vector<double>& w) { return re_multipole_at(order, theta, w); });
  }
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
  return decide(continuous_realisation(order, theta), re, multipole_bound(order, theta), 0.1 * lo, 10.0 * hi, {},
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
