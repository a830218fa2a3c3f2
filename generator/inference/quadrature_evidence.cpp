// SPDX-License-Identifier: MIT
#include "inference/quadrature_evidence.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace admitgen {
namespace {

constexpr double kMinusInf = -std::numeric_limits<double>::infinity();

/// 15-point Gauss-Kronrod nodes (positive half, the last one 0) and weights, and the weights of the
/// embedded 7-point Gauss rule at nodes 1, 3, 5, 7 (Piessens et al. 1983, QUADPACK qk15).
constexpr std::array<double, 8> kXgk{0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                     0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                     0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                     0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kWgk{0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                     0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                     0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                     0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kWg{0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/// ln L as a function of u, counting calls.
class Integrand {
 public:
  explicit Integrand(const Model& model) : model_(model) {}
  double operator()(double u, double& theta) {
    ++calls;
    model_.prior_transform(&u, &theta);
    return model_.log_likelihood(&theta);
  }
  double operator()(double u) {
    double theta = 0.0;
    return (*this)(u, theta);
  }
  long calls = 0;

 private:
  const Model& model_;
};

struct Panel {
  double a = 0.0, b = 0.0;
  double kronrod = 0.0, gauss = 0.0;  ///< ∫ e^{ln L − ref} du over [a, b] by each rule
  std::array<double, 15> theta{}, log_l{}, log_w{};  ///< nodes: θ, ln L, ln(Kronrod weight · half-width)
  double error() const { return std::abs(kronrod - gauss); }
};

Panel integrate_panel(Integrand& f, double a, double b, double ref) {
  Panel p;
  p.a = a;
  p.b = b;
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < 15; ++i) {
    const int k = i < 8 ? i : 14 - i;  // node index into the half tables, mirrored
    const double x = i < 8 ? -kXgk[static_cast<std::size_t>(k)] : kXgk[static_cast<std::size_t>(k)];
    const std::size_t n = static_cast<std::size_t>(i);
    p.log_l[n] = f(mid + half * x, p.theta[n]);
    const double value = std::exp(p.log_l[n] - ref);
    p.kronrod += kWgk[static_cast<std::size_t>(k)] * value;
    if (k % 2 == 1) p.gauss += kWg[static_cast<std::size_t>(k / 2)] * value;
    p.log_w[n] = std::log(kWgk[static_cast<std::size_t>(k)] * half);
  }
  p.kronrod *= half;
  p.gauss *= half;
  return p;
}

struct Mode {
  double u = 0.0, log_l = kMinusInf, theta = 0.0;
  double left = 0.0, right = 0.0;  ///< widths d on each side
};

/// Golden-section search for the maximum of ln L on [a, b] (unimodal there), starting from the best
/// known point (u, ln L); returns the best point seen.
Mode refine_maximum(Integrand& f, double a, double b, Mode best) {
  constexpr int kIterations = 50;  // 0.618^50 ≈ 3e-11 of the bracket
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a);
  double tc = 0.0, td = 0.0;
  double fc = f(c, tc), fd = f(d, td);
  const auto keep = [&best](double u, double l, double theta) {
    if (l > best.log_l) best.u = u, best.log_l = l, best.theta = theta;
  };
  keep(c, fc, tc);
  keep(d, fd, td);
  for (int i = 0; i < kIterations; ++i) {
    if (fc >= fd) {
      b = d, d = c, fd = fc;
      c = b - r * (b - a);
      fc = f(c, tc);
      keep(c, fc, tc);
    } else {
      a = c, c = d, fc = fd;
      d = a + r * (b - a);
      fd = f(d, td);
      keep(d, fd, td);
    }
  }
  return best;
}

/// Distance from u* towards `limit` (direction sign) at which ln L has dropped by kDrop nats, to a
/// factor 1.03, between 1e-12 of the scan step and the scan step; the scan step if it has not dropped
/// that far there.
double mode_width(Integrand& f, const Mode& m, double step, double direction) {
  constexpr double kDrop = 2.0;
  const double limit = direction > 0 ? 1.0 - m.u : m.u;
  if (limit <= 0.0) return step;
  double hi = std::log(std::min(step, limit)), lo = hi + std::log(1e-12);
  if (f(m.u + direction * std::exp(hi)) > m.log_l - kDrop) return std::exp(hi);
  for (int i = 0; i < 10; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(m.u + direction * std::exp(mid)) > m.log_l - kDrop ? lo : hi) = mid;
  }
  return std::exp(hi);
}

/// The modes of ln L: the local maxima of the scan (at most kMaxModes, the highest scanned first), each
/// refined; those whose refined ln L lies within kModeWindow of the best are kept. (A narrow mode shows in
/// the scan far below its peak, so the window applies after the refinement.)
std::vector<Mode> find_modes(Integrand& f) {
  constexpr std::size_t kMaxModes = 16;
  const double step = 1.0 / kScanPoints;
  std::vector<double> log_l(kScanPoints + 1), theta(kScanPoints + 1);
  for (int j = 0; j <= kScanPoints; ++j)
    log_l[static_cast<std::size_t>(j)] = f(j * step, theta[static_cast<std::size_t>(j)]);
  std::vector<int> peaks;
  for (int j = 0; j <= kScanPoints; ++j) {
    const std::size_t i = static_cast<std::size_t>(j);
    const double left = j > 0 ? log_l[i - 1] : kMinusInf, right = j < kScanPoints ? log_l[i + 1] : kMinusInf;
    if (log_l[i] > kMinusInf && log_l[i] >= left && log_l[i] > right) peaks.push_back(j);
  }
  std::stable_sort(peaks.begin(), peaks.end(), [&](int a, int b) {
    return log_l[static_cast<std::size_t>(a)] > log_l[static_cast<std::size_t>(b)];
  });
  if (peaks.size() > kMaxModes) peaks.resize(kMaxModes);
  std::vector<Mode> modes;
  for (int j : peaks) {
    const std::size_t i = static_cast<std::size_t>(j);
    modes.push_back(refine_maximum(f, std::max(0.0, (j - 1) * step), std::min(1.0, (j + 1) * step),
                                   Mode{j * step, log_l[i], theta[i], 0.0, 0.0}));
  }
  double top = kMinusInf;
  for (const Mode& m : modes) top = std::max(top, m.log_l);
  modes.erase(std::remove_if(modes.begin(), modes.end(), [top](const Mode& m) { return m.log_l < top - kModeWindow; }),
              modes.end());
  for (Mode& m : modes) {
    m.left = mode_width(f, m, step, -1.0);
    m.right = mode_width(f, m, step, +1.0);
  }
  return modes;
}

/// Panel edges: 0, 1 and u* − 4d, u* − d, u*, u* + d, u* + 4d of every mode, inside [0, 1].
std::vector<double> breakpoints(const std::vector<Mode>& modes) {
  std::vector<double> x{0.0, 1.0};
  for (const Mode& m : modes)
    for (double t : {m.u - 4.0 * m.left, m.u - m.left, m.u, m.u + m.right, m.u + 4.0 * m.right})
      x.push_back(std::clamp(t, 0.0, 1.0));
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end(), [](double a, double b) { return b - a <= 1e-15; }), x.end());
  return x;
}

/// The run of a model without parameters: Z = L at the one point.
NestedRun analytic_run(const Model& model) {
  NestedRun run;
  run.dim = 0;
  const double log_l = model.log_likelihood(nullptr);
  run.log_likelihood.push_back(log_l);
  run.log_weight.push_back(log_l);
  run.log_z = run.max_log_likelihood = log_l;
  run.calls = 1;
  run.stopped_by = "analytic";
  return run;
}

}  // namespace

NestedRun evidence_by_quadrature(const Model& model, const QuadratureSettings& settings) {
  ADMITGEN_ENSURE(model.dim() <= 1, "quadrature is for 0 or 1 parameters, not {}", model.dim());
  if (model.dim() == 0) return analytic_run(model);
  Integrand f(model);
  const std::vector<Mode> modes = find_modes(f);
  if (modes.empty())
    throw InputError("the likelihood is zero over the whole prior of " + model.parameter_names.front());
  const Mode best = *std::max_element(modes.begin(), modes.end(),
                                      [](const Mode& a, const Mode& b) { return a.log_l < b.log_l; });
  const double ref = best.log_l;

  const std::vector<double> x = breakpoints(modes);
  std::vector<Panel> panels;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) panels.push_back(integrate_panel(f, x[i], x[i + 1], ref));
  const auto totals = [&panels](double& z, double& error) {
    z = error = 0.0;
    for (const Panel& p : panels) z += p.kronrod, error += p.error();
  };
  double z = 0.0, error = 0.0;
  totals(z, error);
  while (error > settings.tolerance * z && f.calls + 30 <= settings.max_calls) {
    const auto worst = std::max_element(panels.begin(), panels.end(),
                                        [](const Panel& a, const Panel& b) { return a.error() < b.error(); });
    const double a = worst->a, b = worst->b, mid = 0.5 * (a + b);
    *worst = integrate_panel(f, a, mid, ref);
    panels.push_back(integrate_panel(f, mid, b, ref));
    totals(z, error);
  }
  std::sort(panels.begin(), panels.end(), [](const Panel& a, const Panel& b) { return a.a < b.a; });

  NestedRun run;
  run.dim = 1;
  run.log_z = ref + std::log(z);
  for (const Panel& p : panels)
    for (std::size_t n = 0; n < 15; ++n) {
      run.samples.push_back(p.theta[n]);
      run.log_likelihood.push_back(p.log_l[n]);
      run.log_weight.push_back(p.log_w[n] + p.log_l[n]);
    }
  double h = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i)
    if (run.log_likelihood[i] > kMinusInf) h += std::exp(run.log_weight[i] - run.log_z) * (run.log_likelihood[i] - run.log_z);
  run.samples.push_back(best.theta);  // the refined maximum, zero weight
  run.log_likelihood.push_back(best.log_l);
  run.log_weight.push_back(kMinusInf);
  run.information = std::max(h, 0.0);
  run.log_z_error = std::log1p(error / z);
  run.max_log_likelihood = *std::max_element(run.log_likelihood.begin(), run.log_likelihood.end());
  run.calls = f.calls;
  run.iterations = static_cast<long>(panels.size());
  run.stopped_by = "quadrature";
  return run;
}

}  // namespace admitgen
