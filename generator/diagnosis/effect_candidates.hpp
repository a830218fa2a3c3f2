// SPDX-License-Identifier: MIT
/// @file
/// The effects `diagnose` tries, each as a model of the measurement built on the simulated side:
/// y_model(f; ϑ) = T_e[y_sim](f; ϑ), with ϑ free under a physically plausible prior. The documented
/// effects (docs/cli.md "Effects") use the physics layer's own closed forms and chain
/// (physics/effects.hpp, physics/two_microphone.hpp), so `diagnose` tests exactly what `synth` makes.
///
/// Priors (ranges a real tube measurement can plausibly show; "log" = log-uniform):
///
/// | effect | parameter | prior | applies when |
/// |---|---|---|---|
/// | reference_plane | delta_m | uniform [−10, 10] mm | always (closed form R e^{−2jkδ}) |
/// | mic_spacing | delta_m | uniform [−3, 3] mm | tube geometry given |
/// | mic_mismatch | gain, phase_deg | uniform [−0.1, 0.1], uniform [−5, 5]° | tube geometry given |
/// | temperature | delta_k | uniform [−10, 10] K | tube geometry given |
/// | tube_losses | — | Kirchhoff losses of diameter d (no free parameter) | tube geometry given |
/// | edge_gap | width_m, depth_m | log [0.05, 3] mm, log [5, 200] mm | tube diameter given |
/// | frame_resonance | f0_hz, q, y_peak | log [f_min, f_max] of the data, log [1, 100], log [1e−3, 3] | always |
/// | fractional_order | c_plus, c_minus (f_ref_hz fixed) | uniform [0, 0.5] each; f_ref = √(f_min f_max) | always |
/// | air_gap | gap_m | log [0.1, 30] mm | the simulated side is a layered material SPEC |
/// | heteroscedastic_noise | scale | uniform [0, 0.5] | tube geometry given, no sin ks = 0 in band |
/// | frequency_scale (own) | ratio | log [0.8, 1.25], narrowed to where a table is known | ≥ ±2 % of it covered |
/// | material (own) | "<layer>.<key>" ratio | log [0.5, 2], kept physical (material_spec.hpp SpecParameter) | --sim is a layered SPEC; one candidate per numeric parameter |
///
/// air_gap is not offered when the SPEC's deepest layer is already air: a gap behind an air cavity is
/// that cavity made deeper, which is the material candidate of its "d" (the two would be one model).
///
/// frequency_scale, y' (f) = y_sim(f · ratio), is admitgen's own addition: a material whose thickness,
/// stiffness or flow resistivity differs from the simulated one shifts its λ/4 resonances (docs/physics.md
/// §5.1 i: "derivative-shaped" residual ∝ ω dY/dω); it applies to any simulated side.
#pragma once

#include "diagnosis/reference_prior.hpp"
#include "diagnosis/simulated_side.hpp"
#include "physics/synthetic_measurement.hpp"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace admitgen::diagnosis {

struct ParameterPrior {
  enum class Shape { uniform, log_uniform };
  std::string name;
  Shape shape = Shape::uniform;
  double lo = 0.0;
  double hi = 1.0;

  /// θ from u ∈ [0, 1]: lo + u (hi − lo), or lo (hi/lo)^u.
  double transform(double u) const;
  /// u from θ (the inverse of transform), clamped to [0, 1].
  double cdf(double theta) const;
  /// e.g. "uniform [-0.01, 0.01]".
  std::string describe() const;
};

/// What the measurement would show under an effect: y, and the relative noise std s_i of each point
/// (empty: the same at every point).
struct EffectPrediction {
  Eigen::ArrayXcd y;
  Eigen::ArrayXd noise_shape;
};

/// Where an effect acts, in the order effects compose (docs/diagnosis.md, "Combined explanations"; the
/// order of physics/synthetic_measurement.hpp): the simulated side itself (its catalogue parameters, an
/// air gap behind its layers, the frequency it is evaluated at), the sample's surface, the measurement
/// chain, the noise.
enum class EffectStage { simulated, sample, chain, noise };

/// What the simulated-stage effects change: the layers of a SPEC, the frequency y_sim is evaluated at.
struct SimulatedChange {
  std::optional<LayeredAbsorber> layers;  ///< set when the simulated side is a layered SPEC
  double frequency_ratio = 1.0;
};

struct EffectContext;  ///< what the candidates of one diagnosis share (effect_candidates.cpp)
class SimulatedTable;  ///< a simulated side tabulated over one parameter's prior (effect_candidates.cpp)

struct EffectCandidate {
  std::string name;  ///< the documented effect name ("material" for every catalogue parameter)
  std::vector<ParameterPrior> priors;
  std::vector<std::pair<std::string, double>> fixed;  ///< parameters held fixed, e.g. f_ref_hz
  std::function<EffectPrediction(const double* theta)> predict;
  EffectStage stage = EffectStage::sample;
  /// The effect as one step of a composition; the one matching `stage` is set.
  std::function<void(SimulatedChange&, const double* theta)> change;
  std::function<Eigen::ArrayXcd(const Eigen::ArrayXcd& y, const double* theta)> apply;
  std::function<void(ChainDeviation&, const double* theta)> deviate;
  std::function<Eigen::ArrayXd(const double* theta)> noise_shape;
  std::shared_ptr<const EffectContext> context;
  /// Empty: nested sampling draws from the prior. Else one reference density per parameter
  /// (diagnosis/reference_prior.hpp; set by the combined search from earlier posteriors): the sampler
  /// draws u from q and weighs the likelihood by 1/q, the same evidence (effect_model).
  std::vector<ReferenceDensity> reference;
  /// A simulated-stage effect of one parameter: its simulated side tabulated over the prior, for the
  /// joint candidates that hold it (combine_effects). Built on first use and shared by every joint
  /// candidate of the diagnosis, so built once however many rounds of the combined search use it.
  std::shared_ptr<const SimulatedTable> table;
  /// What to check on the tube or the sample when the data ask for more of this effect than its prior
  /// allows (diagnosis/prior_bound.hpp), in words; set for every effect, empty for a joint candidate.
  std::string check;

  /// The name, and for material the parameter ("material 1.sigma"): unique among the candidates.
  std::string label() const;
};

/// Every effect that applies to this simulated side, frequencies and tube (table above), in the
/// table's order. y_sim is the simulated side at f_hz (computed once by the caller); the candidates
/// share it and the tube chain's fixed quantities (physics/two_microphone.hpp TwoMicrophoneChain).
std::vector<EffectCandidate> effect_candidates(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_sim,
                                               const SimulatedSide& sim, const TubeSetup& tube);

/// The members acting together, as one candidate (all from one effect_candidates() call, each effect at
/// most once): priors concatenated in the members' order; the prediction composes them by stage
/// (EffectStage), within a stage in the order of the candidates vector the members point into (the
/// table's), every chain deviation in one true chain.
EffectCandidate combine_effects(const std::vector<const EffectCandidate*>& members);

}  // namespace admitgen::diagnosis
