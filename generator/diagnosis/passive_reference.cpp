// SPDX-License-Identifier: MIT
#include "diagnosis/passive_reference.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "diagnosis/effect_identification.hpp"
#include "diagnosis/third_octave_bands.hpp"
#include "numerics/passive_bound.hpp"
#include "physics/two_microphone.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>

namespace admitgen::diagnosis {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDecibanPerNat = 10.0 / 2.302585092994046;

/// Coarse cells per parameter and the refinement of the 3^d cells around the best, done twice
/// (docs/diagnosis.md, "Physics as the reference"): 21 and 6 for one parameter, 9 and 2 for two.
int coarse_cells(std::size_t dims) { return dims == 1 ? 21 : 9; }
int refinement(std::size_t dims) { return dims == 1 ? 6 : 2; }

struct Cell {
  std::vector<double> u;
  double log_volume = 0.0;
  double log_l = -std::numeric_limits<double>::infinity();
};

/// Every k-th point, at most kPassiveScanPoints.
std::vector<Eigen::Index> scan_indices(Eigen::Index n) {
  const Eigen::Index step = std::max<Eigen::Index>(1, (n + kPassiveScanPoints - 1) / kPassiveScanPoints);
  std::vector<Eigen::Index> out;
  for (Eigen::Index i = 0; i < n; i += step) out.push_back(i);
  return out;
}

Eigen::ArrayXcd passive_residual(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y) {
  const numerics::PassiveBound b = numerics::passive_bound(2.0 * kPi * f_hz, y, Eigen::ArrayXd::Ones(y.size()));
  return y - b.fitted;
}

std::vector<double> theta_of(const std::vector<ParameterPrior>& priors, const std::vector<double>& u) {
  std::vector<double> t(priors.size());
  for (std::size_t k = 0; k < priors.size(); ++k) t[k] = priors[k].transform(u[k]);
  return t;
}

/// The cells of a d-dimensional grid of n cells per side over [lo, lo + n·h]^d (centres), inside [0, 1].
std::vector<Cell> grid(const std::vector<double>& lo, double h, int n) {
  const std::size_t d = lo.size();
  std::vector<Cell> out;
  std::vector<int> idx(d, 0);
  for (;;) {
    Cell c;
    bool inside = true;
    for (std::size_t k = 0; k < d; ++k) {
      const double u = lo[k] + (idx[k] + 0.5) * h;
      inside = inside && u > 0.0 && u < 1.0;
      c.u.push_back(u);
    }
    c.log_volume = static_cast<double>(d) * std::log(h);
    if (inside) out.push_back(c);
    std::size_t k = 0;
    while (k < d && ++idx[k] == n) idx[k++] = 0;
    if (k == d) break;
  }
  return out;
}

}  // namespace

double estimate_noise_variance(const Eigen::ArrayXcd& y) {
  ADMITGEN_ENSURE(y.size() >= 3, "noise estimate: {} points", y.size());
  std::vector<double> d2;
  for (Eigen::Index i = 1; i + 1 < y.size(); ++i) d2.push_back(std::norm(y[i - 1] - 2.0 * y[i] + y[i + 1]));
  const auto mid = d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2);
  std::nth_element(d2.begin(), mid, d2.end());
  return *mid / (6.0 * std::log(2.0));
}

std::vector<std::pair<std::string, std::vector<ParameterPrior>>> passive_reference_effects(const TubeSetup& tube) {
  using Shape = ParameterPrior::Shape;
  // Wider than the priors with a simulation (effect_candidates.hpp): with physics as the reference a real
  // reference plane was found 2-4 cm off, and a microphone calibration 10-25 % off is a real fault.
  std::vector<std::pair<std::string, std::vector<ParameterPrior>>> out{
      {"reference_plane", {{"delta_m", Shape::uniform, -0.05, 0.05}}}};
  if (tube.diameter_m && tube.spacing_m && tube.mic1_distance_m) {
    out.push_back({"mic_spacing", {{"delta_m", Shape::uniform, -0.005, 0.005}}});
    out.push_back({"mic_mismatch", {{"gain", Shape::uniform, -0.25, 0.25}, {"phase_deg", Shape::uniform, -5.0, 5.0}}});
    out.push_back({"temperature", {{"delta_k", Shape::uniform, -10.0, 10.0}}});
    out.push_back({"tube_losses", {}});
  }
  return out;
}

Eigen::ArrayXcd correct_effect(const std::string& name, const double* theta, const Eigen::ArrayXcd& y,
                               const Eigen::ArrayXd& f_hz, const TubeSetup& tube) {
  const Air air = Air::at_celsius(tube.temperature_c);
  if (name == "reference_plane") {
    // R measured = R e^{−2jkδ} (docs/cli.md "Effects"), so R = R_measured e^{2jkδ}.
    const Eigen::ArrayXcd turn = (std::complex<double>(0.0, 2.0 * theta[0]) * lossless_wavenumber(air, f_hz)).exp();
    return admittance_from_reflection(reflection_from_admittance(y) * turn);
  }
  ChainDeviation dev;
  if (name == "mic_spacing") dev.spacing_error_m = theta[0];
  else if (name == "mic_mismatch") dev.mic_ratio = std::polar(1.0 + theta[0], theta[1] * kPi / 180.0);
  else if (name == "temperature") dev.temperature_offset_k = theta[0];
  else if (name == "tube_losses") dev.tube_losses = true;
  else ADMITGEN_ENSURE(false, "no passive-reference correction for effect {}", name);
  return correct_through_chain(y, f_hz, air, tube.geometry("the chain corrections"), dev);
}

PassiveDiagnosis diagnose_against_passivity(const Measurement& real, const TubeSetup& tube, int threads) {
  if (real.size() < 10)
    throw InputError(fmt::format("{}: {} points; the passive reference needs at least 10", real.path, real.size()));
  PassiveDiagnosis d;
  d.real_path = real.path;
  d.real_sha256 = real.sha256;
  d.points = real.size();
  d.f_hz = real.f_hz;
  d.corrected = real.y;
  const std::vector<Eigen::Index> idx = scan_indices(real.size());
  d.scan_points = static_cast<Eigen::Index>(idx.size());
  Eigen::ArrayXd f(d.scan_points);
  Eigen::ArrayXcd y(d.scan_points);
  for (std::size_t i = 0; i < idx.size(); ++i) f[static_cast<Eigen::Index>(i)] = real.f_hz[idx[i]], y[static_cast<Eigen::Index>(i)] = real.y[idx[i]];
  const double sigma2 = std::max(estimate_noise_variance(real.y), 1e-300);
  d.noise_std = std::sqrt(sigma2);
  const Eigen::ArrayXcd r0 = passive_residual(f, y);
  const double log_l0 = -r0.abs2().sum() / sigma2;
  d.bound_before = std::sqrt(r0.abs2().sum() / y.abs2().sum());
  d.noise_ratio_before = std::sqrt(r0.abs2().mean() / sigma2);
  for (const auto& band : covered_bands(f)) {
    if (band.count < 2) continue;
    const double ratio = std::sqrt(r0.segment(band.first, band.count).abs2().mean() / sigma2);
    if (ratio > d.band_noise_ratio)
      d.band_noise_ratio = ratio, d.band_lo_hz = band.f_lo, d.band_hi_hz = band.f_hi, d.band_center_hz = band.f_center;
  }

  for (const auto& [name, priors] : passive_reference_effects(tube)) {
    PassiveEffect e;
    e.name = name;
    e.priors = priors;
    const std::size_t dims = priors.size();
    const auto log_likelihood = [&, name = name](Cell& c) {
      const std::vector<double> theta = theta_of(priors, c.u);
      try {
        c.log_l = -passive_residual(f, correct_effect(name, theta.data(), y, f, tube)).abs2().sum() / sigma2;
      } catch (const InputError&) {
        c.log_l = -std::numeric_limits<double>::infinity();  // a microphone behind the face: no such chain
      }
    };
    const auto evaluate = [&](std::vector<Cell>& cells) {
      std::vector<std::size_t> queue(cells.size());
      std::iota(queue.begin(), queue.end(), std::size_t{0});
      run_in_parallel(queue, threads, [&](std::size_t k) { log_likelihood(cells[k]); });
      e.evaluations += static_cast<int>(cells.size());
    };
    std::vector<Cell> cells;
    if (dims == 0) {
      cells.push_back(Cell{});
      evaluate(cells);
    } else {
      const int n = coarse_cells(dims), r = refinement(dims);
      const double h = 1.0 / n;
      cells = grid(std::vector<double>(dims, 0.0), h, n);
      evaluate(cells);
      // Twice: the 3^d cells of width w around the best are replaced by (3r)^d cells of width w/r.
      for (double w = h; w > h / (r * r) * 1.5; w /= r) {
        const Cell best = *std::max_element(cells.begin(), cells.end(),
                                            [](const Cell& a, const Cell& b) { return a.log_l < b.log_l; });
        const auto near = [&](const Cell& c) {
          for (std::size_t k = 0; k < dims; ++k)
            if (std::abs(c.u[k] - best.u[k]) > 1.5 * w) return false;
          return true;
        };
        cells.erase(std::remove_if(cells.begin(), cells.end(), near), cells.end());
        std::vector<double> lo(dims);
        for (std::size_t k = 0; k < dims; ++k) lo[k] = best.u[k] - 1.5 * w;
        std::vector<Cell> fine = grid(lo, w / r, 3 * r);
        evaluate(fine);
        cells.insert(cells.end(), fine.begin(), fine.end());
      }
    }
    double max_l = -std::numeric_limits<double>::infinity();
    std::size_t arg = 0;
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (cells[k].log_l > max_l) max_l = cells[k].log_l, arg = k;
    double z = 0.0;
    std::vector<double> w(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) z += w[k] = std::exp(cells[k].log_l - max_l + cells[k].log_volume);
    e.bayes_factor_deciban = kDecibanPerNat * (max_l + std::log(z) - log_l0);
    e.best = theta_of(priors, cells[arg].u);
    for (std::size_t p = 0; p < dims; ++p) {
      std::vector<std::size_t> order(cells.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cells[a].u[p] < cells[b].u[p]; });
      double mean = 0.0, cum = 0.0, lo = e.best[p], hi = e.best[p];
      bool lo_set = false, hi_set = false;
      for (const std::size_t k : order) {
        const double t = priors[p].transform(cells[k].u[p]);
        mean += w[k] / z * t;
        cum += w[k] / z;
        if (!lo_set && cum >= 0.025) lo = t, lo_set = true;
        if (!hi_set && cum >= 0.975) hi = t, hi_set = true;
      }
      // A posterior narrower than a fine cell is reported as that cell: the grid's resolution.
      const double half = 0.5 / (coarse_cells(dims) * refinement(dims) * refinement(dims));
      lo = std::min(lo, priors[p].transform(std::max(0.0, cells[arg].u[p] - half)));
      hi = std::max(hi, priors[p].transform(std::min(1.0, cells[arg].u[p] + half)));
      e.mean.push_back(mean);
      e.lo95.push_back(lo);
      e.hi95.push_back(hi);
      const double edge = 1.0 / coarse_cells(dims);
      if (cells[arg].u[p] < edge || cells[arg].u[p] > 1.0 - edge) e.at_bound.push_back(priors[p].name);
    }
    const Eigen::ArrayXcd corrected = correct_effect(name, e.best.data(), y, f, tube);
    const Eigen::ArrayXcd r1 = passive_residual(f, corrected);
    e.bound_after = std::sqrt(r1.abs2().sum() / corrected.abs2().sum());
    e.noise_ratio_after = std::sqrt(r1.abs2().mean() / sigma2);
    d.effects.push_back(std::move(e));
  }
  std::stable_sort(d.effects.begin(), d.effects.end(), [](const PassiveEffect& a, const PassiveEffect& b) {
    return a.bayes_factor_deciban > b.bayes_factor_deciban;
  });
  const bool named = !d.effects.empty() && d.effects.front().bayes_factor_deciban >= kDecisiveDeciban;
  if (named) {
    const PassiveEffect& e = d.effects.front();
    d.verdict = e.name;
    d.corrected = correct_effect(e.name, e.best.data(), real.y, real.f_hz, tube);
    for (const auto& p : e.at_bound)
      d.warnings.push_back(fmt::format("{} {} presses on its prior's bound: the correction may be larger than the prior "
                                       "allows; check the tube's {} directly",
                                       e.name, p, e.name == "mic_mismatch" ? "microphone calibration" : "geometry"));
    if (e.noise_ratio_after > kConsistentNoiseRatio)
      d.warnings.push_back(fmt::format("after the {} correction the passive residual is still {:.1f}x the noise: "
                                       "another effect or a non-passive sample remains",
                                       e.name, e.noise_ratio_after));
  } else {
    d.verdict = d.noise_ratio_before <= kConsistentNoiseRatio ? "consistent" : "unexplained";
  }
  return d;
}

}  // namespace admitgen::diagnosis
