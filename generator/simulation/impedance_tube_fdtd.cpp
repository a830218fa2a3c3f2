// SPDX-License-Identifier: MIT
#include "simulation/impedance_tube_fdtd.hpp"

#include "codegen/runtime_filter.hpp"
#include "core/errors.hpp"
#include "physics/two_microphone.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

namespace admitgen::simulation {
namespace {

using cd = std::complex<double>;

/// Incident amplitude. The wall pressure of a sinusoid is 2A/|1 + Y_d| ≤ 2A for a passive Y_d; sweep
/// transients can overshoot that, so A = 0.3 leaves |p_M| ≤ 0.6 plus margin below full scale 1
/// (inputs beyond it are clipped and counted: TubeSimulationResult::saturated_inputs).
constexpr double kDriveAmplitude = 0.3;

/// One wall node terminated by the C runtime: y^{n} = h0 u^n + s^{n−1}.
class RuntimeWall {
 public:
  virtual ~RuntimeWall() = default;
  virtual double h0() const = 0;
  /// s: the output the next frame gives for u = 0 (state untouched).
  virtual double history() = 0;
  /// Runs one frame with wall pressure p; returns the runtime's output.
  virtual double commit(double p) = 0;
  /// The runtime's signal quantum (0 for float): the stop test cannot ask for less.
  virtual double quantum() const { return 0.0; }
  long saturated = 0;
};

class WallF32 final : public RuntimeWall {
 public:
  WallF32(const codegen::FloatCoefficients& c, int fs) : node_(c, fs), h0_(c.h0) {}
  double h0() const override { return h0_; }
  double history() override { return node_.history(); }
  double commit(double p) override { return node_.commit(static_cast<float>(p)); }

 private:
  codegen::RuntimeNodeF32 node_;
  double h0_;
};

/// q31 (T = int32_t, B = 31) or q15 (T = int16_t, B = 15): the runtime's history/commit pair (history = the
/// output of a u = 0 frame, bit-exact, state untouched).
template <typename T, int B>
class WallFixed final : public RuntimeWall {
 public:
  WallFixed(const codegen::FixedCoefficients& c, int fs)
      : node_(c, fs), out_scale_(std::ldexp(1.0, c.out_shift - B)), h0_(c.dequantised(fs).h0()) {}
  double h0() const override { return h0_; }
  double quantum() const override { return std::max(out_scale_, std::ldexp(1.0, -B)); }
  double history() override { return static_cast<double>(node_.history()) * out_scale_; }
  double commit(double p) override {
    constexpr double full = static_cast<double>(std::int64_t{1} << B);
    double q = std::nearbyint(p * full);
    if (q > full - 1.0 || q < -full) {
      ++saturated;
      q = std::clamp(q, -full, full - 1.0);
    }
    return static_cast<double>(node_.commit(static_cast<T>(q))) * out_scale_;
  }

 private:
  codegen::RuntimeNode<T> node_;
  double out_scale_, h0_;
};

std::unique_ptr<RuntimeWall> runtime_wall(const codegen::EmittedRate& rate, codegen::Format format) {
  switch (format) {
    case codegen::Format::f32:
      return std::make_unique<WallF32>(rate.f32, rate.fs_hz);
    case codegen::Format::q31:
      if (!rate.fixed) break;
      return std::make_unique<WallFixed<std::int32_t, 31>>(*rate.fixed, rate.fs_hz);
    case codegen::Format::q15:
      if (!rate.fixed) break;
      return std::make_unique<WallFixed<std::int16_t, 15>>(*rate.fixed, rate.fs_hz);
  }
  throw InputError(fmt::format("no {} tables were emitted for {} Hz", codegen::format_name(format), rate.fs_hz));
}

/// Exact DTFT Σ x^n e^{−jωn} at each ω = 2πf/fs; the phasor is advanced by rotation and re-set from
/// std::polar every 256 samples (rotation drift stays ~1e-14).
Eigen::ArrayXcd dtft(const std::vector<double>& x, const Eigen::ArrayXd& f_hz, double fs) {
  Eigen::ArrayXcd out(f_hz.size());
  for (Eigen::Index k = 0; k < f_hz.size(); ++k) {
    const double w = 2.0 * EIGEN_PI * f_hz[k] / fs;
    const cd rot = std::polar(1.0, -w);
    cd acc = 0.0, ph = 1.0;
    for (std::size_t n = 0; n < x.size(); ++n) {
      if (n % 256 == 0) ph = std::polar(1.0, -w * static_cast<double>(n));
      acc += x[n] * ph;
      ph *= rot;
    }
    out[k] = acc;
  }
  return out;
}

/// Exponential sine sweep f_lo → f_hi over T_s = 1 s (Farina), amplitude kDriveAmplitude, with 5 ms
/// raised-cosine fades: a smooth, dip-free spectrum over the data band, its energy spread over fs
/// samples so that a fixed-point runtime's signal rounding is √fs below what a single pulse gives.
std::vector<double> excitation(double fs, double f_min, double f_max) {
  const double f_lo = 0.5 * f_min, f_hi = std::min(0.49 * fs, 2.0 * f_max);
  const auto n = static_cast<std::size_t>(std::lround(fs));
  const double duration = static_cast<double>(n) / fs, rate = std::log(f_hi / f_lo);
  const auto fade = static_cast<std::size_t>(std::lround(0.005 * fs));
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    const double phase = 2.0 * EIGEN_PI * f_lo * duration / rate * std::expm1(t * rate / duration);
    double w = 1.0;
    if (i < fade) w = 0.5 - 0.5 * std::cos(EIGEN_PI * static_cast<double>(i) / static_cast<double>(fade));
    if (n - 1 - i < fade) w = 0.5 - 0.5 * std::cos(EIGEN_PI * static_cast<double>(n - 1 - i) / static_cast<double>(fade));
    x[i] = kDriveAmplitude * w * std::sin(phase);
  }
  return x;
}

}  // namespace

TubeSimulationResult simulate_impedance_tube(const codegen::EmittedRate& rate, codegen::Format format,
                                             const Eigen::ArrayXd& f_hz, const TubeSimulationSettings& settings) {
  const double fs = rate.fs_hz;
  const double h = settings.c0 / fs;
  TubeSimulationResult res;
  res.m1 = static_cast<int>(std::lround(settings.mic1_distance_m / h));
  const int cells_s = std::max(1, static_cast<int>(std::lround(settings.spacing_m / h)));
  res.m2 = res.m1 - cells_s;
  if (res.m2 < 0 || res.m1 < 1)
    throw InputError(fmt::format("the simulated tube at {:g} Hz has cells of {:.3g} mm: microphones at {:g} m and "
                                 "{:g} m from the sample do not fall on two distinct grid nodes in front of it",
                                 fs, 1e3 * h, settings.mic1_distance_m, settings.mic1_distance_m - settings.spacing_m));
  res.x1_m = res.m1 * h;
  res.spacing_m = cells_s * h;

  auto wall = runtime_wall(rate, format);
  const double h0 = wall->h0();
  const int M = res.m1 + 2;  // source node 0, far mic at M − m1 ≥ 2, wall at M
  const std::vector<double> drive = excitation(fs, f_hz[0], f_hz[f_hz.size() - 1]);
  std::vector<double> p(static_cast<std::size_t>(M) + 1, 0.0), u(static_cast<std::size_t>(M), 0.0);
  std::vector<double> far, near;
  const long fixed_n = settings.window_s > 0.0 ? std::max(1L, std::lround(settings.window_s * fs)) : 0;
  const long n_max = fixed_n > 0 ? fixed_n : TubeSimulationSettings::kMaxSamples;
  const long n_min = static_cast<long>(drive.size()) + 2L * M + 8;  // the drive has passed the wall and both mics
  const double quantum_floor = 4.0 * wall->quantum();
  double w_prev = 0.0, pm_prev = 0.0, peak = 0.0, block_peak = 0.0;
  constexpr long kBlock = 1024;
  for (long n = 0; n < n_max; ++n) {
    for (int i = 0; i < M; ++i) u[i] -= p[i + 1] - p[i];
    // q^{n+1} = f^{n+1} + f^n injects the right-going wave f (f^0 = 0, f^{k} = drive[k − 1])
    const auto f_at = [&](long k) { return k >= 1 && k <= static_cast<long>(drive.size()) ? drive[k - 1] : 0.0; };
    const double q = f_at(n + 1) + f_at(n);
    const double p0 = -u[0] + q;
    for (int i = 1; i < M; ++i) p[i] -= u[i] - u[i - 1];
    const double s = wall->history();
    const double pm = (p[M] - s - w_prev + 2.0 * u[M - 1]) / (1.0 + h0);
    w_prev = wall->commit(pm);
    p[0] = p0;
    p[M] = pm;
    far.push_back(p[M - res.m1]);
    near.push_back(p[M - res.m2]);
    res.peak_wall_pressure = std::max(res.peak_wall_pressure, std::abs(pm));
    // Decay is judged on the pairwise sums x^n + x^{n−1}, which remove z = −1: the trapezoidal wall
    // coupling leaves the Nyquist mode undamped ((z + 1) factor in the header's derivation), so rounding
    // keeps a ~1e-17 Nyquist ripple alive that is outside every data band and must not stop the stop test.
    const std::size_t last = far.size() - 1;
    const auto pair_sum = [last](const std::vector<double>& x) { return last ? std::abs(x[last] + x[last - 1]) : std::abs(x[last]); };
    const double now = std::max({pair_sum(far), pair_sum(near), std::abs(pm + pm_prev)});
    pm_prev = pm;
    peak = std::max(peak, now);
    block_peak = std::max(block_peak, now);
    if ((n + 1) % kBlock == 0) {
      if (fixed_n == 0 && n >= n_min && block_peak <= std::max(1e-14 * peak, quantum_floor)) {
        res.decayed = true;
        break;
      }
      block_peak = 0.0;
    }
  }
  res.samples = static_cast<long>(far.size());
  res.saturated_inputs = wall->saturated;

  const Eigen::ArrayXcd h12 = dtft(near, f_hz, fs) / dtft(far, f_hz, fs);
  const Eigen::ArrayXcd k = (2.0 * EIGEN_PI * f_hz / settings.c0).cast<cd>();
  res.r = reflection_from_transfer(h12, k, res.x1_m, res.spacing_m);
  res.y = admittance_from_reflection(res.r);
  return res;
}

}  // namespace admitgen::simulation
