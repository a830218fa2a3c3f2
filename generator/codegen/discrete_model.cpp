// SPDX-License-Identifier: MIT
#include "codegen/discrete_model.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"
#include "numerics/least_squares_inequality.hpp"

#include <Eigen/QR>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::codegen {
namespace {

using cplx = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;
/// Weight of the baseband points outside the data relative to the data points: small enough not to
/// cost accuracy at the data (1e-5 leaves the in-band error within 2x of the unregularised fit),
/// large enough to keep the response out of band near G (no wild FIR taps).
constexpr double kOutOfBandWeight = 1e-5;
/// A refit whose coefficients sum (in magnitude) beyond this multiple of max|G| is rejected: it trades
/// FIR taps against a fast pole's near-FIR response (ill-conditioned) and would waste fixed-point range.
constexpr double kMaxCoefficientGrowth = 16.0;
/// Constraint-generation rounds of the passive refit (each adds the violations the certifier found; a
/// handful suffice in practice, see docs/passivity.md).
constexpr int kMaxPassiveRounds = 30;

/// 1 − e^{−jθ} without cancellation: 2 sin²(θ/2) + j sin θ.
cplx one_minus_unit(double theta) {
  const double s = std::sin(0.5 * theta);
  return {2.0 * s * s, std::sin(theta)};
}

/// 1/(1 − z e^{−jθ}) for a pole z = 1 + δ (δ = z − 1 given accurately).
cplx resolvent(cplx delta, double theta) {
  const cplx e = std::polar(1.0, -theta);
  return 1.0 / (one_minus_unit(theta) - delta * e);
}

/// PLRC (Kelley–Luebbers; FOH) numerator of K/(a + s) at period T (docs/physics.md §1.2):
/// χ = (1 − e^{−aT})/a, ξ = (1 − (1 + aT)e^{−aT})/(a²T), b0 = K(χ − ξ), b1 = Kξ.
/// Series for small |aT| (the closed forms cancel catastrophically there).
void plrc_numerator(cplx k, cplx a, double t, cplx& b0, cplx& b1) {
  const cplx x = a * t;
  cplx chi_t, xi_t;  // χ/T and ξ/T
  if (std::abs(x) < 0.1) {
    // (1 − e^{−x})/x = Σ (−x)^n/(n+1)!,  (1 − (1 + x)e^{−x})/x² = Σ (−x)^n (n+1)/(n+2)!
    cplx pow = 1.0;
    double fact = 1.0;  // (n+1)!
    chi_t = 0.0;
    xi_t = 0.0;
    for (int n = 0; n < 12; ++n) {
      chi_t += pow / fact;
      xi_t += pow * double(n + 1) / (fact * double(n + 2));
      pow *= -x;
      fact *= double(n + 2);
    }
  } else {
    const cplx ex = std::exp(-x);
    chi_t = (1.0 - ex) / x;
    xi_t = (1.0 - (1.0 + x) * ex) / (x * x);
  }
  b0 = k * t * (chi_t - xi_t);
  b1 = k * t * xi_t;
}

struct Pole {
  bool is_pair;
  int index;       // q or s
  cplx rate;       // λ or α + jβ
};

}  // namespace

double DiscreteModel::h0() const {
  double h = fir.empty() ? 0.0 : fir[0];
  for (const auto& r : real) h += r.c * r.eps;
  for (const auto& p : pair) h += 2.0 * p.c.real() * p.g;
  return h;
}

cplx DiscreteModel::response(double f_hz) const {
  const double theta = 2.0 * kPi * f_hz / fs_hz;
  cplx h = 0.0;
  for (std::size_t k = 0; k < fir.size(); ++k) h += fir[k] * std::polar(1.0, -double(k) * theta);
  for (const auto& r : real) h += r.c * r.eps * resolvent(-r.eps, theta);
  for (const auto& p : pair) {
    const cplx delta(p.e_r, p.p_i);
    h += p.c * p.g * resolvent(delta, theta) + std::conj(p.c) * p.g * resolvent(std::conj(delta), theta);
  }
  return h;
}

std::vector<double> DiscreteModel::filter(const std::vector<double>& u) const {
  std::vector<double> y(u.size());
  std::vector<double> x(real.size(), 0.0), xi(pair.size(), 0.0), eta(pair.size(), 0.0);
  for (std::size_t n = 0; n < u.size(); ++n) {
    double acc = 0.0;
    for (std::size_t k = 0; k < fir.size() && k <= n; ++k) acc += fir[k] * u[n - k];
    for (std::size_t q = 0; q < real.size(); ++q) {
      x[q] += real[q].eps * (u[n] - x[q]);
      acc += real[q].c * x[q];
    }
    for (std::size_t s = 0; s < pair.size(); ++s) {
      const auto& p = pair[s];
      const double a = xi[s], b = eta[s];
      xi[s] = a + (p.e_r * a - p.p_i * b + p.g * u[n]);
      eta[s] = b + (p.e_r * b + p.p_i * a);
      acc += 2.0 * (p.c.real() * xi[s] - p.c.imag() * eta[s]);
    }
    y[n] = acc;
  }
  return y;
}

std::vector<double> DiscreteModel::impulse_response(int n) const {
  std::vector<double> u(static_cast<std::size_t>(n), 0.0);
  if (n > 0) u[0] = 1.0;
  return filter(u);
}

int DiscreteModel::tail_samples(double decades) const {
  double slowest = 1e300;  // decay per sample (nepers)
  for (const auto& r : real) slowest = std::min(slowest, -std::log1p(-r.eps));
  for (const auto& p : pair) slowest = std::min(slowest, -std::log1p(-p.g));
  const double n = slowest >= 1e300 ? 0.0 : decades * std::log(10.0) / slowest;
  return static_cast<int>(std::min(n, double(1 << 26))) + static_cast<int>(fir.size()) + 1;
}

bool inside_unit_circle(const RealTerm& t) { return t.eps > 0.0 && t.eps < 2.0; }
bool inside_unit_circle(const PairTerm& p) { return p.e_r * (2.0 + p.e_r) + p.p_i * p.p_i < 0.0; }

bool DiscreteModel::stable() const {
  return std::all_of(real.begin(), real.end(), [](const RealTerm& t) { return inside_unit_circle(t); }) &&
         std::all_of(pair.begin(), pair.end(), [](const PairTerm& p) { return inside_unit_circle(p); });
}

std::pair<double, double> state_l1(const PairTerm& p) {
  constexpr long kMaxTerms = 1L << 22;
  const std::complex<double> pi(1.0 + p.e_r, p.p_i);
  const double r = std::abs(pi);
  if (!(r < 1.0)) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double xi = 0.0, eta = 0.0, tail = 0.0;
  std::complex<double> psi(p.g, 0.0);
  for (long n = 0; n < kMaxTerms; ++n) {
    xi += std::abs(psi.real());
    eta += std::abs(psi.imag());
    psi *= pi;
    tail = std::abs(psi) / (1.0 - r);
    if (tail < 1e-13) break;
  }
  return {xi + tail, eta + tail};
}

double DiscreteModel::l1_norm() const {
  if (!stable()) return std::numeric_limits<double>::infinity();
  const auto h = impulse_response(tail_samples(12.0));
  double s = 0.0;
  for (double v : h) s += std::abs(v);
  return s;
}

namespace {

/// Candidate order: one meeting the options' constraint beats one that does not; between equals, a
/// refit error below half the incumbent's (the margin keeps the simpler candidate on near-ties).
bool better(const DiscreteModel& candidate, const DiscreteModel* incumbent, const DiscretiseOptions& options) {
  if (incumbent == nullptr) return true;
  if (options.passivity_violations && candidate.passive_certified != incumbent->passive_certified)
    return candidate.passive_certified;
  return candidate.refit_max_rel_error < 0.5 * incumbent->refit_max_rel_error;
}

/// Throws InputError unless fs is a positive rate that represents every data frequency (below 0.45 fs).
void require_representable(const Order& order, const Eigen::VectorXd& theta, double fs_hz,
                           const std::vector<double>& data_f_hz) {
  ADMITGEN_ENSURE(theta.size() == order.dim(), "theta has {} entries for {}", theta.size(), order.name());
  if (!(fs_hz > 0.0) || !std::isfinite(fs_hz)) throw InputError(fmt::format("sample rate {} Hz is not positive", fs_hz));
  if (data_f_hz.empty()) throw InputError("the fit lists no data frequencies to refit at");
  const double f_top = *std::max_element(data_f_hz.begin(), data_f_hz.end());
  if (f_top >= 0.45 * fs_hz)
    throw InputError(fmt::format("{} Hz: the fit's data reach {:g} Hz, beyond 0.45 fs = {:g} Hz; a discrete "
                                 "filter at this rate cannot reproduce them (use fs > {:g} Hz)",
                                 setting("fs_hz", fmt::format("{:g}", fs_hz)), f_top, 0.45 * fs_hz, f_top / 0.45));
}

/// The discrete poles (numerators still zero): each pole's exact image e^{−aT} in delta / coupled form, or
/// its name in `folded` when its rate exceeds 2π fold_factor fs.
DiscreteModel discrete_poles(const Order& order, const Eigen::VectorXd& theta, double fs_hz, double fold_factor) {
  const double t = 1.0 / fs_hz;
  const double fold_rate = 2.0 * kPi * fold_factor * fs_hz;
  DiscreteModel m;
  m.fs_hz = fs_hz;
  for (int q = 0; q < order.q(); ++q) {
    const double lam = theta[Order::lambda(q)];
    ADMITGEN_ENSURE(lam > 0.0, "lambda_{} = {} is not causal", q + 1, lam);
    if (lam > fold_rate) {
      m.folded.push_back(fmt::format("lambda_{} = {:.6g} 1/s", q + 1, lam));
      continue;
    }
    RealTerm r;
    r.lambda = lam;
    r.eps = -std::expm1(-lam * t);
    m.real.push_back(r);
  }
  for (int s = 0; s < order.s(); ++s) {
    const double al = theta[order.alpha(s)], be = theta[order.beta(s)];
    ADMITGEN_ENSURE(al > 0.0, "alpha_{} = {} is not causal", s + 1, al);
    if (al > fold_rate) {
      m.folded.push_back(fmt::format("alpha_{} = {:.6g} 1/s (beta {:.6g})", s + 1, al, be));
      continue;
    }
    PairTerm p;
    p.alpha = al;
    p.beta = be;
    const double em1 = std::expm1(-al * t), r = std::exp(-al * t), sh = std::sin(0.5 * be * t);
    p.e_r = em1 * std::cos(be * t) - 2.0 * sh * sh;
    p.p_i = -r * std::sin(be * t);
    p.g = -em1;
    m.pair.push_back(p);
  }
  return m;
}

/// What the numerators are refitted to: the continuous model G at the data frequencies (weight 1/|G|:
/// relative error) plus a sparse baseband grid outside the data (weight kOutOfBandWeight/|G|) that keeps the
/// refit sane where there are no data. The data points come first (n_data of them).
struct RefitTarget {
  std::vector<double> f, w;  ///< frequencies (Hz) and row weights
  Eigen::ArrayXd omega;      ///< 2π f
  Eigen::ArrayXcd g;         ///< G(jω)
  std::size_t n_data = 0;
  double g_data_max = 0.0;  ///< max |G| over the data
};

RefitTarget refit_target(const Order& order, const Eigen::VectorXd& theta, double fs_hz,
                         const std::vector<double>& data_f_hz) {
  RefitTarget tg;
  tg.f = data_f_hz;
  tg.w.assign(tg.f.size(), 1.0);
  const double f_lo = *std::min_element(data_f_hz.begin(), data_f_hz.end());
  const double f_top = *std::max_element(data_f_hz.begin(), data_f_hz.end());
  for (int i = 0; i < 48; ++i) {
    const double fi = 1e-4 * fs_hz * std::pow(0.45 / 1e-4, i / 47.0);
    if (fi < f_lo || fi > f_top) {
      tg.f.push_back(fi);
      tg.w.push_back(kOutOfBandWeight);
    }
  }
  tg.omega.resize(static_cast<Eigen::Index>(tg.f.size()));
  for (std::size_t i = 0; i < tg.f.size(); ++i) tg.omega[static_cast<Eigen::Index>(i)] = 2.0 * kPi * tg.f[i];
  tg.g = evaluate_multipole(order, theta, tg.omega);
  for (std::size_t i = 0; i < tg.f.size(); ++i) {
    const double mag = std::abs(tg.g[static_cast<Eigen::Index>(i)]);
    tg.w[i] /= std::max(mag, 1e-12);
  }
  tg.n_data = data_f_hz.size();
  for (std::size_t i = 0; i < tg.n_data; ++i) tg.g_data_max = std::max(tg.g_data_max, std::abs(tg.g[static_cast<Eigen::Index>(i)]));
  return tg;
}

/// Max relative error at the data of plain PLRC, for the record: G∞ + Σ (b0 + b1 z^{-1})/(1 − z_a z^{-1})
/// (+ conjugate for pairs), every pole kept.
double plrc_max_rel_error(const Order& order, const Eigen::VectorXd& theta, double t, const RefitTarget& tg) {
  double worst = 0.0;
  for (std::size_t i = 0; i < tg.n_data; ++i) {
    const double th = tg.omega[static_cast<Eigen::Index>(i)] * t;
    cplx h = theta[Order::g_inf()];
    auto add = [&](cplx k, cplx a, bool conj_too) {
      cplx b0, b1;
      plrc_numerator(k, a, t, b0, b1);
      const cplx za = std::exp(-a * t);
      const cplx e = std::polar(1.0, -th), ep = std::polar(1.0, th);
      const cplx term = (b0 + b1 * e) / (1.0 - za * e);
      h += term;
      if (conj_too) h += std::conj((b0 + b1 * ep) / (1.0 - za * ep));
    };
    for (int q = 0; q < order.q(); ++q) add(theta[Order::a(q)], theta[Order::lambda(q)], false);
    for (int s = 0; s < order.s(); ++s)
      add(cplx(theta[order.b(s)], theta[order.c(s)]), cplx(theta[order.alpha(s)], theta[order.beta(s)]), true);
    const cplx gi = tg.g[static_cast<Eigen::Index>(i)];
    worst = std::max(worst, std::abs(h - gi) / std::abs(gi));
  }
  return worst;
}

/// H is linear in the numerators x = [d_0..d_{L-1}, c_q, (c_r, c_i)_s]: H(e^{jθ}) = Σ_j x_j φ_j(θ).
std::vector<cplx> numerator_basis(double th, int taps, const DiscreteModel& d) {
  std::vector<cplx> phi;
  for (int k = 0; k < taps; ++k) phi.push_back(std::polar(1.0, -double(k) * th));
  for (const auto& r : d.real) phi.push_back(r.eps * resolvent(-r.eps, th));
  for (const auto& p : d.pair) {
    const cplx dl(p.e_r, p.p_i);
    const cplx u1 = p.g * resolvent(dl, th), u2 = p.g * resolvent(std::conj(dl), th);
    phi.push_back(u1 + u2);
    phi.push_back(cplx(0.0, 1.0) * (u1 - u2));
  }
  return phi;
}

/// Writes the numerators x (numerator_basis order) into `out`.
void assign_numerators(const Eigen::VectorXd& x, int taps, DiscreteModel& out) {
  out.fir.assign(x.data(), x.data() + taps);
  int j = taps;
  for (auto& r : out.real) r.c = x[j++];
  for (auto& p : out.pair) {
    p.c = cplx(x[j], x[j + 1]);
    j += 2;
  }
}

/// Constraint grid (Hz) for Re H ≥ margin: θ = 0 and π, 160 log-spaced from 1e-5 fs, 63 linear up to
/// Nyquist and 21 approaching it (Re H varies on the scale of the poles, which these resolve; the certifier adds what they miss),
/// and the points across each pair's resonance (model/passivity.hpp, resonance_points) at f_p = arg(z)/2π · fs
/// with half width −ln|z|/2π · fs (a narrow pair, α ≪ β, is otherwise stepped over).
std::vector<double> passive_grid_hz(const DiscreteModel& m) {
  const double fs_hz = m.fs_hz;
  std::vector<double> grid{0.0, 0.5 * fs_hz};
  for (int i = 0; i < 160; ++i) grid.push_back(1e-5 * fs_hz * std::pow(0.5 / 1e-5, i / 159.0));
  for (int i = 1; i < 64; ++i) grid.push_back(0.5 * fs_hz * i / 64.0);
  // Towards Nyquist, 4 points per decade of the distance to it down to 1e-7 of fs/2 (the discrete certificate's
  // net reaches as close: checks/passivity.hpp); FIR taps bend Re H there faster than the linear points follow.
  for (int k = 8; k <= 28; ++k) grid.push_back(0.5 * fs_hz * (1.0 - std::pow(10.0, -k / 4.0)));
  for (const PairTerm& p : m.pair) {
    const cplx z(1.0 + p.e_r, p.p_i);
    const double centre = std::abs(std::arg(z)) * fs_hz / (2.0 * kPi), half = -std::log(std::abs(z)) * fs_hz / (2.0 * kPi);
    for (const double f : resonance_points(centre, half))
      if (f > 0.0 && f < 0.5 * fs_hz) grid.push_back(f);
  }
  return grid;
}

/// The weighted least-squares system A x ≈ b for `taps` FIR taps (stacked real/imaginary rows).
void least_squares_system(const RefitTarget& tg, double t, int taps, const DiscreteModel& poles, Eigen::MatrixXd& a,
                          Eigen::VectorXd& b) {
  const int cols = taps + static_cast<int>(poles.real.size() + 2 * poles.pair.size());
  const Eigen::Index rows = static_cast<Eigen::Index>(2 * tg.f.size());
  a.resize(rows, cols);
  b.resize(rows);
  for (std::size_t i = 0; i < tg.f.size(); ++i) {
    const auto phi = numerator_basis(tg.omega[static_cast<Eigen::Index>(i)] * t, taps, poles);
    const Eigen::Index r0 = static_cast<Eigen::Index>(2 * i);
    for (int j = 0; j < cols; ++j) {
      a(r0, j) = tg.w[i] * phi[static_cast<std::size_t>(j)].real();
      a(r0 + 1, j) = tg.w[i] * phi[static_cast<std::size_t>(j)].imag();
    }
    b[r0] = tg.w[i] * tg.g[static_cast<Eigen::Index>(i)].real();
    b[r0 + 1] = tg.w[i] * tg.g[static_cast<Eigen::Index>(i)].imag();
  }
}

/// Constraint generation (docs/passivity.md): while the certifier finds violations, solve A x ≈ b under
/// Re H ≥ δ on the grid plus every violation found, and re-certify; sets passive_rounds and
/// passive_certified. Certified means Re H ≥ δ up to Nyquist: the certifier sees H − δ (d_0 lowered by δ),
/// so a refit that is passive only by a hair still gets the margin that coefficient rounding needs.
void constrain_passive(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double t, int taps, double delta,
                       const DiscretiseOptions& options, DiscreteModel& out) {
  const auto violations_with_margin = [&](const DiscreteModel& d) {
    DiscreteModel shifted = d;
    if (shifted.fir.empty()) shifted.fir.push_back(0.0);
    shifted.fir[0] -= delta;
    return options.passivity_violations(shifted);
  };
  std::vector<double> where = passive_grid_hz(out), bad = violations_with_margin(out);
  out.passive_rounds = 0;
  for (int round = 1; !bad.empty() && round <= kMaxPassiveRounds; ++round) {
    where.insert(where.end(), bad.begin(), bad.end());
    Eigen::MatrixXd c(static_cast<Eigen::Index>(where.size()), a.cols());
    for (std::size_t i = 0; i < where.size(); ++i) {
      const auto phi = numerator_basis(2.0 * kPi * where[i] * t, taps, out);
      for (Eigen::Index j = 0; j < a.cols(); ++j) c(static_cast<Eigen::Index>(i), j) = phi[static_cast<std::size_t>(j)].real();
    }
    // Solved with 2δ, certified at δ: the slack absorbs the dips of Re H between constraint points,
    // which would otherwise each cost a round.
    const auto sol = numerics::least_squares_inequality(a, b, c, Eigen::VectorXd::Constant(c.rows(), 2.0 * delta));
    if (!sol.feasible) break;
    assign_numerators(sol.x, taps, out);
    out.passive_rounds = round;
    bad = violations_with_margin(out);
  }
  out.passive_certified = bad.empty();
}

/// Refits the numerators of `out` (its poles kept) with `taps` FIR taps: weighted linear least squares
/// (columns scaled to unit norm), then, with a certifier, constrained until passive; records the error.
void refit_numerators(const RefitTarget& tg, int taps, const DiscretiseOptions& options, DiscreteModel& out) {
  const double t = 1.0 / out.fs_hz;
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
  least_squares_system(tg, t, taps, out, a, b);
  const Eigen::VectorXd scale = a.colwise().norm().transpose().cwiseMax(1e-300);
  assign_numerators((a * scale.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(b).cwiseQuotient(scale), taps, out);
  if (options.passivity_violations) constrain_passive(a, b, t, taps, options.passive_margin * tg.g_data_max, options, out);
  double worst = 0.0;
  for (std::size_t i = 0; i < tg.n_data; ++i) {
    const cplx gi = tg.g[static_cast<Eigen::Index>(i)];
    worst = std::max(worst, std::abs(out.response(tg.f[i]) - gi) / std::abs(gi));
  }
  out.refit_max_rel_error = worst;
}

/// Σ of the coefficient magnitudes (FIR taps, c_q, 2|c_s|).
double coefficient_sum(const DiscreteModel& d) {
  double s = 0.0;
  for (double v : d.fir) s += std::abs(v);
  for (const auto& r : d.real) s += std::abs(r.c);
  for (const auto& p : d.pair) s += 2.0 * std::abs(p.c);
  return s;
}

/// The best refit of `poles` over 1..kMaxFirTaps FIR taps (stopping at the first meeting the target), a
/// refit whose coefficients grow beyond kMaxCoefficientGrowth max|G| excluded.
DiscreteModel best_fir_length(const DiscreteModel& poles, const RefitTarget& tg, const DiscretiseOptions& options) {
  double g_max = 1.0;
  for (Eigen::Index i = 0; i < tg.g.size(); ++i) g_max = std::max(g_max, std::abs(tg.g[i]));
  DiscreteModel best;
  for (int taps = 1; taps <= DiscretiseOptions::kMaxFirTaps; ++taps) {
    DiscreteModel trial = poles;
    refit_numerators(tg, taps, options, trial);
    if (taps > 1 && coefficient_sum(trial) > kMaxCoefficientGrowth * g_max) continue;
    if (better(trial, taps == 1 ? nullptr : &best, options)) best = trial;
    if (best.refit_max_rel_error <= options.target_rel_error && (!options.passivity_violations || best.passive_certified))
      break;
  }
  return best;
}

/// discretise at the options' fold_factor (> 0).
DiscreteModel discretise_with_fold(const Order& order, const Eigen::VectorXd& theta, double fs_hz,
                                   const std::vector<double>& data_f_hz, const DiscretiseOptions& options) {
  require_representable(order, theta, fs_hz, data_f_hz);
  DiscreteModel m = discrete_poles(order, theta, fs_hz, options.fold_factor);
  if (options.store_poles) options.store_poles(m);
  const RefitTarget tg = refit_target(order, theta, fs_hz, data_f_hz);
  m.plrc_max_rel_error = plrc_max_rel_error(order, theta, 1.0 / fs_hz, tg);
  if (options.fir_taps > 0) {
    refit_numerators(tg, options.fir_taps, options, m);
    return m;
  }
  return best_fir_length(m, tg, options);
}

}  // namespace

DiscreteModel discretise(const Order& order, const Eigen::VectorXd& theta, double fs_hz,
                         const std::vector<double>& data_f_hz, const DiscretiseOptions& options) {
  if (options.fold_factor > 0.0) return discretise_with_fold(order, theta, fs_hz, data_f_hz, options);
  // Automatic folding: the best of three fold factors.
  DiscreteModel best;
  bool have = false;
  for (double factor : {4.0, 0.5, 0.25}) {
    DiscretiseOptions o = options;
    o.fold_factor = factor;
    DiscreteModel m = discretise_with_fold(order, theta, fs_hz, data_f_hz, o);
    if (better(m, have ? &best : nullptr, options)) best = std::move(m), have = true;
  }
  return best;
}

}  // namespace admitgen::codegen
