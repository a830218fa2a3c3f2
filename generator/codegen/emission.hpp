// SPDX-License-Identifier: MIT
/// @file
/// `admitgen emit` as a library: a fit's record (model/fit_record.hpp) → discrete models per sample
/// rate → quantised tables → the generated C header (templates/admitgen_boundary.h.in), band
/// absorption, golden vectors, and EmittedHeader, the typed record of a header's model block (what
/// `admitgen check` verifies). The block's JSON writer and reader are io/model_block.hpp (docs/formats.md).
#pragma once

#include "codegen/band_absorption.hpp"
#include "codegen/coefficients.hpp"
#include "codegen/discrete_model.hpp"
#include "codegen/fidelity.hpp"
#include "model/multipole_surface.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace admitgen::codegen {

/// Runtime ABI the generated headers are written for (must equal ADMITGEN_RT_ABI_VERSION).
inline constexpr int kRuntimeAbi = 1;

struct EmitSettings {
  std::vector<double> fs_hz;
  Format format = Format::f32;
  std::string name;   ///< C identifier prefix of everything emitted
  std::string order;  ///< empty: the fit's selected order
  Estimate estimate = Estimate::passive;
  int fir_taps = 0;   ///< 0: automatic
  /// Passivity certifier and margin of the discrete refit at each rate (see DiscretiseOptions; the emit
  /// pipeline, emit/emit.hpp, passes the discrete Hamiltonian test).
  std::function<std::vector<double>(const DiscreteModel&)> passivity_violations;
  /// false: the emit pipeline neither repairs a non-passive estimate nor constrains the refit (experts).
  bool enforce_passivity = true;
  double passive_margin = 1e-9;
  /// Refit the numerators to the poles as the format stores them (DiscretiseOptions::store_poles); emit
  /// turns it on only when the refit to the exact poles cannot be certified after rounding.
  bool refit_to_stored_poles = false;
  /// q15 only: 32-bit coefficients (codegen/coefficients.hpp, coefficient_bits); emit chooses it when the 16-bit
  /// header fails a check (docs/runtime.md, "Q formats and rounding").
  bool wide_coefficients = false;
  /// Tolerance of the fidelity check the header must pass (codegen/fidelity.hpp).
  double fidelity_tolerance = kDefaultFidelityTolerance;
};

/// What emit changed to make the continuous model passive (stamped in the header's model block).
struct PassivityEnforcement {
  std::string applied_to;             ///< the estimate changed: passive | mean | max_likelihood
  std::string negative_bands_before;  ///< where Re G < 0 before
  bool certified = false;             ///< the result passes the Hamiltonian test
  int constraint_rounds = 0;
  double max_rel_change_in_data_band = 0.0, max_rel_change_outside_data_band = 0.0;
};

/// The continuous model to emit and where it came from (the fit), before discretisation.
struct EmissionSource {
  MultipoleSurface surface{Order(0, 0), Eigen::VectorXd::Zero(1)};
  Estimate estimate = Estimate::passive;  ///< the estimate actually taken from the fit
  std::string fit_name;  ///< file name of the fit (no directories: headers stay machine-independent)
  std::string fit_version, input_sha256;
  std::uint64_t seed = 0;
  std::vector<double> data_f_hz;
  /// Lines stamped into the header comment and the model block (e.g. how passivity was enforced).
  std::vector<std::string> notes;
  std::optional<PassivityEnforcement> enforcement;  ///< how passivity was enforced (none: it was not needed)
};

struct EmittedRate {
  int fs_hz = 0;
  DiscreteModel model;                      ///< double precision, before rounding to the format
  FloatCoefficients f32;                    ///< format f32
  std::optional<FixedCoefficients> fixed;   ///< formats q31, q15
  Fidelity fidelity;                        ///< of the coefficients as emitted (codegen/fidelity.hpp)

  /// The filter the kernel runs, in exact arithmetic: the dequantised tables (q31/q15) or the float values (f32).
  DiscreteModel emitted_model() const;
};

struct Emission : EmissionSource {
  EmitSettings settings;
  std::vector<EmittedRate> rates;
  std::vector<BandAbsorption> octave, third_octave;
};

/// Takes the model to emit from a fit: settings.order (empty: the selected one) and settings.estimate.
/// Throws InputError if the fit lacks it.
EmissionSource read_emission_source(const FitRecord& fit, const std::string& fit_path, const EmitSettings& settings);

/// Validates the settings (rates integral in [1 kHz, 1 MHz], distinct; name a C identifier) and
/// computes everything. Throws InputError on bad input.
Emission prepare_emission(const EmissionSource& source, const EmitSettings& settings);
/// read_emission_source, then prepare_emission.
Emission prepare_emission(const FitRecord& fit, const std::string& fit_path, const EmitSettings& settings);

/// The header text from the template text (deterministic: no timestamp; byte-identical on re-run).
/// `model_block` is the header's machine-readable block, one line of JSON carried between "admitgen:model"
/// and "admitgen:end" (written by io::model_block; io::header_text renders a header with it).
std::string render_header(const Emission& emission, const std::string& template_text, const std::string& file_name,
                          const std::string& model_block);

/// Bit-exact golden vectors of the first rate (q31/q15 only): impulse, worst-case sign, uniform noise at
/// −6 dBFS from Rng(seed), zeros; input and expected output in decimal with a hex comment.
std::string golden_vectors(const Emission& emission, std::uint64_t seed);

/// What a header emitted, as its model block states it (read by io::read_emitted_header).
struct EmittedHeader {
  Format format = Format::f32;
  std::string name;
  MultipoleSurface surface{Order(0, 0), Eigen::VectorXd::Zero(1)};
  double data_f_min_hz = 0.0, data_f_max_hz = 0.0;  ///< band of the fitted data
  struct Rate {
    int fs_hz = 0;
    DiscreteModel model;  ///< exactly the emitted (rounded/quantised) coefficients, in double
    std::optional<FixedCoefficients> fixed;
  };
  std::vector<Rate> rates;
};

}  // namespace admitgen::codegen
