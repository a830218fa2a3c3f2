// SPDX-License-Identifier: MIT
/// @file
/// How much of the gap each pipeline stage adds (docs/physics.md §5.2 n-q), with `--fit FIT.json --fs HZ
/// --format F`. The chain of admittances, each evaluated at the measurement's frequencies:
///
///   y_real ─fit─► G(jω) ─discretization─► H(e^{jωT}) ─quantization─► H_F(e^{jωT}) ─simulation─► y_FDTD
///
///  * fit: the continuous multipole of the fit (selected order, posterior mean), model-order truncation;
///  * discretization: the double-precision discrete model `emit` computes at fs (codegen/discrete_model);
///  * quantization: the coefficients of the format as emitted (f32: rounded to float; q31/q15: the
///    fixed-point tables, dequantised exactly — codegen/coefficients);
///  * simulation: the admittance a 1D FDTD impedance tube "measures" with two virtual microphones when
///    the C runtime, running the emitted tables, terminates it (simulation/impedance_tube_fdtd.hpp).
///
/// A stage's gap is the gap between its input and its output (gap_metrics, normalised by ‖y_real‖),
/// so stages compare directly; the cumulative gap is y_real against the stage's output.
#pragma once

#include "codegen/coefficients.hpp"
#include "diagnosis/gap_metrics.hpp"
#include "physics/synthetic_measurement.hpp"
#include "simulation/impedance_tube_fdtd.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace admitgen::diagnosis {

struct StageRequest {
  nlohmann::json fit;    ///< the parsed fit.json
  std::string fit_path;  ///< for messages
  double fs_hz = 48000.0;
  codegen::Format format = codegen::Format::q31;
  /// Geometry of the simulated tube (--tube-diameter, --mic-spacing, --mic-distance, --temperature).
  /// Absent spacing/distance: s = min(50 mm, 0.4 c0/f_max) rounded down to whole cells (≥ 1), so the
  /// data stay below ISO's 0.45 c0/s, and x1 = 2s. The diameter plays no role (1D lossless tube).
  TubeSetup tube;
  double sim_window_s = 0.0;  ///< FDTD record length; 0 = automatic (until the response has decayed)
};

struct StageGap {
  std::string stage;  ///< fit | discretization | quantization | simulation
  Gap gap;            ///< this stage alone: its input against its output
  Gap cumulative;     ///< y_real against this stage's output
  std::string detail;  ///< how the stage was run (simulation: grid, microphones, window)
};

/// The four stages in order. Throws InputError if fs/format are unusable or a measured frequency is
/// not below 0.45 fs.
std::vector<StageGap> attribute_stages(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                       const StageRequest& request);

}  // namespace admitgen::diagnosis
