// SPDX-License-Identifier: MIT
/// @file
/// Per-band absorption from the continuous model, for engines that take band absorption instead of a
/// filter (Steam Audio, FMOD/Wwise-style material tables; docs/physics.md §4.2 "Geometric engines").
///  * normal incidence: R = (1 − G)/(1 + G), α₀ = 1 − |R|² (G the normalised admittance);
///  * random incidence, locally reacting (London/Kuttruff; Paris integral in closed form), ζ = 1/G = ξ + jη:
///      α_st = 8ξ/|ζ|² [1 − ξ/|ζ|² ln(1 + 2ξ + |ζ|²) + (ξ² − η²)/(η|ζ|²) atan(η/(1 + ξ))]
///    (η → 0 limit: the last term → ξ²/(|ζ|²(1 + ξ))); maximum 0.9512 at ζ = 1.567.
/// Band values are the mean over 32 log-spaced frequencies between the band edges (IEC 61260 base-10:
/// centres 1000·10^{3k/10} for octaves, 1000·10^{k/10} for one-third octaves, edges at G^{±1/2} of the
/// band ratio). Bands outside the fit's data range are extrapolations of the model and flagged.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace admitgen::codegen {

struct BandAbsorption {
  double center_hz = 0.0, lo_hz = 0.0, hi_hz = 0.0;
  double alpha_normal = 0.0;
  double alpha_random = 0.0;
  bool in_data = false;  ///< the band lies inside the fit's data range [f_min, f_max]
};

double alpha_normal(std::complex<double> g);
double alpha_random(std::complex<double> g);

/// A band: its nominal centre and its edges [lo, hi] in Hz (0 < lo < hi).
struct BandEdges {
  double center_hz, lo_hz, hi_hz;
};

/// The mean absorption over each of `edges` (32 log-spaced frequencies between the edges, as above).
std::vector<BandAbsorption> band_absorption(const Order& order, const Eigen::VectorXd& theta,
                                            const std::vector<BandEdges>& edges, double data_f_min, double data_f_max);

/// Octave (fraction 1: 31.5 Hz–16 kHz) or one-third-octave (fraction 3: 25 Hz–20 kHz) bands.
std::vector<BandAbsorption> band_absorption(const Order& order, const Eigen::VectorXd& theta, int fraction,
                                            double data_f_min, double data_f_max);

}  // namespace admitgen::codegen
