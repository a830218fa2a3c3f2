// SPDX-License-Identifier: MIT
/// @file
/// A synthetic "measured" admittance: material → sample effects → measurement chain → noise, the
/// pipeline behind `admitgen synth` (and `diagnose --sim SPEC`). Order of application, whatever the
/// order of the effects on the command line:
///   1. air_gap: an air layer inserted between the layered material and its rigid backing;
///   2. y of the material (Air at the setup temperature);
///   3. sample effects on y, in the order given: edge_gap, frame_resonance, fractional_order;
///   4. chain effects, all in one true chain (two_microphone.hpp): reference_plane, mic_spacing,
///      mic_mismatch, temperature, tube_losses (reference_plane alone uses its closed form, which the
///      chain reproduces exactly);
///   5. noise: complex Gaussian of std σ, heteroscedastic if heteroscedastic_noise is given.
#pragma once

#include "physics/effects.hpp"
#include "physics/material.hpp"
#include "physics/two_microphone.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace admitgen {

/// The tube as the user described it; any of the lengths may be absent.
struct TubeSetup {
  std::optional<double> diameter_m;
  std::optional<double> spacing_m;
  std::optional<double> mic1_distance_m;
  double temperature_c = 20.0;

  /// The full geometry; throws InputError naming the missing options and `why` they are needed.
  TubeGeometry geometry(const std::string& why) const;
};

struct SynthesisRequest {
  Material material;
  std::vector<Effect> effects;
  Eigen::ArrayXd f_hz;     ///< ascending, > 0
  double noise_std = 0.0;  ///< σ of the complex noise (0 = clean)
  std::uint64_t seed = 1;
  TubeSetup tube;
};

struct Synthesis {
  Eigen::ArrayXcd y;                  ///< at request.f_hz
  std::vector<std::string> warnings;  ///< e.g. band outside the ISO working range of the tube
};

/// n points from lo to hi (inclusive), equally spaced in log f: f_i = lo (hi/lo)^{i/(n−1)}.
/// Throws InputError unless 0 < lo < hi and n ≥ 2.
Eigen::ArrayXd log_spaced_frequencies(double lo_hz, double hi_hz, int n);

/// Checks every effect against the material and the setup before any work: each effect at most once,
/// geometry given where an effect needs it, air_gap only on a layered material, heteroscedastic_noise
/// only with noise. Throws InputError.
void validate(const SynthesisRequest& request);

/// Runs the pipeline above (validates first). Deterministic: same request → same bits.
Synthesis synthesize(const SynthesisRequest& request);

}  // namespace admitgen
