// SPDX-License-Identifier: MIT
#include "diagnosis/effect_candidates.hpp"

#include "core/errors.hpp"
#include "physics/effects.hpp"
#include "physics/material_spec.hpp"
#include "physics/noise.hpp"
#include "physics/two_microphone.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

namespace admitgen::diagnosis {

constexpr double kMm = 1e-3;

using Shape = ParameterPrior::Shape;

/// Everything an effect model reads, shared by the candidates (held by shared_ptr in their closures).
struct EffectContext {
  Eigen::ArrayXd f;
  Eigen::ArrayXcd y_sim;
  Air air;
  TubeSetup tube;
  SimulatedSide sim;
  std::optional<TwoMicrophoneChain> chain;  ///< y_sim through the tube (full geometry only)
  TabulatedSlitModel slit;                  ///< the edge gap's slit on this grid (tabulated fluid)
  Eigen::ArrayXd sin_ks;                    ///< |sin ks| of the microphones (full geometry only)
};

namespace {

using ContextPtr = std::shared_ptr<const EffectContext>;

EffectPrediction plain(Eigen::ArrayXcd y) { return {std::move(y), {}}; }

/// The simulated side after the simulated-stage changes (a SPEC re-evaluated, or a table at f·ratio).
Eigen::ArrayXcd simulated(const EffectContext& c, const SimulatedChange& change) {
  if (change.layers) return surface_admittance(Material{*change.layers}, c.air, c.f * change.frequency_ratio);
  return c.sim.admittance(c.f * change.frequency_ratio);
}

SimulatedChange no_change(const EffectContext& c) {
  SimulatedChange out;
  if (c.sim.material() && std::holds_alternative<LayeredAbsorber>(*c.sim.material()))
    out.layers = std::get<LayeredAbsorber>(*c.sim.material());
  return out;
}

}  // namespace

/// The simulated side under one simulated-stage member of one parameter θ (a catalogue ratio, an air
/// gap, a frequency ratio), tabulated on the data grid: a joint candidate that holds such a member
/// evaluates it tens of thousands of times, and re-evaluating a layered SPEC costs far more than the
/// other members. y(θ) is smooth in the prior's coordinate v (ln θ for a log-uniform prior, θ for a
/// uniform one): the table holds y at equally spaced v over the prior, read by 4-point Lagrange
/// interpolation (one-sided in the end cells). Built on first use from 33 nodes, doubled (the new
/// nodes are the old midpoints, where the interpolation error of the coarser table is largest) until
/// every midpoint agrees with the exact side to kSimulatedTableTolerance of the rms simulated
/// admittance (tested in tests/diagnosis/test_combined_effects.cpp); a side needing more than
/// kSimulatedTableMaxNodes nodes is not tabulated (evaluated exactly each time).
class SimulatedTable {
 public:
  static constexpr double kSimulatedTableTolerance = 1e-8;
  static constexpr int kSimulatedTableMaxNodes = 1025;

  /// The side under `change` at θ, θ over `prior` (the member's own prior and change).
  SimulatedTable(std::shared_ptr<const EffectContext> c, ParameterPrior prior,
                 std::function<void(SimulatedChange&, const double* theta)> change)
      : c_(std::move(c)), prior_(std::move(prior)), change_(std::move(change)) {}

  /// The simulated side at θ (to the tolerance above).
  Eigen::ArrayXcd operator()(double theta) const {
    std::call_once(built_, [this] { build(); });
    if (nodes_.empty()) return exact(theta);
    return lookup(prior_.shape == ParameterPrior::Shape::log_uniform ? std::log(theta) : theta);
  }

  /// Nodes of the table once built (0 when not tabulated).
  std::size_t nodes() const {
    std::call_once(built_, [this] { build(); });
    return nodes_.size();
  }

 private:
  Eigen::ArrayXcd exact(double theta) const {
    SimulatedChange s = no_change(*c_);
    change_(s, &theta);
    return simulated(*c_, s);
  }
  double theta_at(double v) const {
    return prior_.shape == ParameterPrior::Shape::log_uniform ? std::exp(v) : v;
  }
  void build() const {
    const ParameterPrior& p = prior_;
    const bool log = p.shape == ParameterPrior::Shape::log_uniform;
    v_lo_ = log ? std::log(p.lo) : p.lo;
    const double v_hi = log ? std::log(p.hi) : p.hi;
    const double scale = std::sqrt(c_->y_sim.abs2().mean());
    std::vector<Eigen::ArrayXcd> nodes;
    for (int k = 0; k < 33; ++k) nodes.push_back(exact(theta_at(v_lo_ + (v_hi - v_lo_) * k / 32.0)));
    while (nodes.size() <= static_cast<std::size_t>(kSimulatedTableMaxNodes)) {
      nodes_ = std::move(nodes);
      step_ = (v_hi - v_lo_) / static_cast<double>(nodes_.size() - 1);
      nodes.clear();
      double worst = 0.0;
      for (std::size_t k = 0; k + 1 < nodes_.size(); ++k) {
        const double v = v_lo_ + (static_cast<double>(k) + 0.5) * step_;
        Eigen::ArrayXcd mid = exact(theta_at(v));
        worst = std::max(worst, (lookup(v) - mid).abs().maxCoeff());
        nodes.push_back(nodes_[k]);
        nodes.push_back(std::move(mid));
      }
      nodes.push_back(nodes_.back());
      if (worst <= kSimulatedTableTolerance * scale) return;
    }
    nodes_.clear();  // too wiggly to tabulate within the budget: exact every time
  }
  Eigen::ArrayXcd lookup(double v) const {
    const double q = std::clamp((v - v_lo_) / step_, 0.0, static_cast<double>(nodes_.size() - 1));
    const Eigen::Index k = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(q) - 1, 0,
                                                    static_cast<Eigen::Index>(nodes_.size()) - 4);
    const double t = q - static_cast<double>(k);  // nodes k … k + 3 sit at t = 0 … 3
    const double w0 = -(t - 1) * (t - 2) * (t - 3) / 6, w1 = t * (t - 2) * (t - 3) / 2,
                 w2 = -t * (t - 1) * (t - 3) / 2, w3 = t * (t - 1) * (t - 2) / 6;
    const auto at = [&](Eigen::Index j) -> const Eigen::ArrayXcd& { return nodes_[static_cast<std::size_t>(j)]; };
    return w0 * at(k) + w1 * at(k + 1) + w2 * at(k + 2) + w3 * at(k + 3);
  }

  std::shared_ptr<const EffectContext> c_;
  ParameterPrior prior_;
  std::function<void(SimulatedChange&, const double* theta)> change_;
  mutable std::once_flag built_;
  mutable std::vector<Eigen::ArrayXcd> nodes_;
  mutable double v_lo_ = 0.0, step_ = 1.0;
};

namespace {

EffectCandidate simulated_effect(std::string name, std::string check, std::vector<ParameterPrior> priors,
                                 const ContextPtr& c, std::function<void(SimulatedChange&, const double*)> change) {
  EffectCandidate e{std::move(name), std::move(priors), {}, {}, EffectStage::simulated, change, {}, {}, {}, c, {}, {},
                    std::move(check)};
  e.predict = [c, change](const double* t) {
    SimulatedChange s = no_change(*c);
    change(s, t);
    return plain(simulated(*c, s));
  };
  return e;
}

EffectCandidate sample_effect(std::string name, std::string check, std::vector<ParameterPrior> priors,
                              const ContextPtr& c,
                              std::function<Eigen::ArrayXcd(const Eigen::ArrayXcd&, const double*)> apply) {
  EffectCandidate e{std::move(name), std::move(priors), {}, {}, EffectStage::sample, {}, apply, {}, {}, c, {}, {},
                    std::move(check)};
  e.predict = [c, apply](const double* t) { return plain(apply(c->y_sim, t)); };
  return e;
}

/// A chain effect: the true chain deviates from the processed one (two_microphone.hpp).
EffectCandidate chain_effect(std::string name, std::string check, std::vector<ParameterPrior> priors,
                             const ContextPtr& c, std::function<ChainDeviation(const double*)> deviation) {
  EffectCandidate e{std::move(name), std::move(priors), {}, {}, EffectStage::chain, {}, {},
                    [deviation](ChainDeviation& d, const double* t) {
                      const ChainDeviation own = deviation(t);
                      d.spacing_error_m += own.spacing_error_m;
                      d.temperature_offset_k += own.temperature_offset_k;
                      d.tube_losses = d.tube_losses || own.tube_losses;
                      d.mic_ratio *= own.mic_ratio;
                      d.reference_plane_m += own.reference_plane_m;
                    },
                    {}, c, {}, {}, std::move(check)};
  e.predict = [c, deviation](const double* t) { return plain(c->chain->measure(deviation(t))); };
  return e;
}

bool full_geometry(const TubeSetup& t) { return t.diameter_m && t.spacing_m && t.mic1_distance_m; }

/// Whether the two-microphone inversion is regular at every frequency (sin ks ≠ 0).
bool regular_transfer(const EffectContext& c) {
  return (c.sin_ks > 1e-6).all();
}

void add_chain_effects(std::vector<EffectCandidate>& out, const ContextPtr& c) {
  out.push_back(chain_effect("mic_spacing", "measure the microphone spacing", {{"delta_m", Shape::uniform, -3 * kMm, 3 * kMm}}, c,
                             [](const double* t) {
                               ChainDeviation d;
                               d.spacing_error_m = t[0];
                               return d;
                             }));
  out.push_back(chain_effect("mic_mismatch", "calibrate the microphones (swap them, ISO 10534-2)",
                             {{"gain", Shape::uniform, -0.25, 0.25}, {"phase_deg", Shape::uniform, -5, 5}},
                             c, [](const double* t) {
                               ChainDeviation d;
                               d.mic_ratio = (1.0 + t[0]) * std::polar(1.0, t[1] * static_cast<double>(EIGEN_PI) / 180.0);
                               return d;
                             }));
  out.push_back(chain_effect("temperature", "measure the air temperature in the tube", {{"delta_k", Shape::uniform, -10, 10}}, c, [](const double* t) {
    ChainDeviation d;
    d.temperature_offset_k = t[0];
    return d;
  }));
  out.push_back(chain_effect("tube_losses", "check the tube diameter given", {}, c, [](const double*) {
    ChainDeviation d;
    d.tube_losses = true;
    return d;
  }));
}

/// reference_plane: alone by its closed form R e^{−2jkδ} (no geometry needed); in a composition one
/// deviation of the chain, which reproduces the closed form exactly (two_microphone.hpp).
EffectCandidate reference_plane(const ContextPtr& c) {
  EffectCandidate e = chain_effect("reference_plane", "measure where the sample face sits",
                                   {{"delta_m", Shape::uniform, -10 * kMm, 10 * kMm}}, c,
                                   [](const double* t) {
                                     ChainDeviation d;
                                     d.reference_plane_m = t[0];
                                     return d;
                                   });
  e.predict = [c](const double* t) { return plain(apply_reference_plane(ReferencePlane{t[0]}, c->air, c->f, c->y_sim)); };
  return e;
}

EffectCandidate heteroscedastic_noise(const ContextPtr& c) {
  const auto shape = [c](const double* t) { return heteroscedastic_std(1.0, t[0], c->sin_ks); };
  return {"heteroscedastic_noise",
          {{"scale", Shape::uniform, 0.0, 0.5}},
          {},
          [c, shape](const double* t) { return EffectPrediction{c->y_sim, shape(t)}; },
          EffectStage::noise,
          {},
          {},
          {},
          shape,
          c, {}, {}, "check the microphones' noise"};
}

EffectCandidate edge_gap(const ContextPtr& c) {
  return sample_effect(
      "edge_gap", "check how the sample fits its holder",
      {{"width_m", Shape::log_uniform, 0.05 * kMm, 3 * kMm}, {"depth_m", Shape::log_uniform, 5 * kMm, 200 * kMm}}, c,
      [c](const Eigen::ArrayXcd& y, const double* t) { return c->slit.edge_gap(EdgeGap{t[0], t[1]}, *c->tube.diameter_m, y); });
}

EffectCandidate frame_resonance(const ContextPtr& c) {
  const double f_min = c->f[0], f_max = c->f[c->f.size() - 1];
  return sample_effect("frame_resonance",
                       "check the sample's mounting (a resonance at a band edge may lie outside the data)",
                       {{"f0_hz", Shape::log_uniform, f_min, f_max}, {"q", Shape::log_uniform, 1, 100},
                        {"y_peak", Shape::log_uniform, 1e-3, 3}},
                       c, [c](const Eigen::ArrayXcd& y, const double* t) {
                         return apply_frame_resonance(FrameResonance{t[0], t[1], t[2]}, c->f, y);
                       });
}

EffectCandidate fractional_order(const ContextPtr& c) {
  const double f_ref = std::sqrt(c->f[0] * c->f[c->f.size() - 1]);
  EffectCandidate e = sample_effect("fractional_order", "check the sample's frame and its mounting",
                                    {{"c_plus", Shape::uniform, 0.0, 0.5}, {"c_minus", Shape::uniform, 0.0, 0.5}}, c,
                                    [c, f_ref](const Eigen::ArrayXcd& y, const double* t) {
                                      return apply_fractional_order(FractionalOrder{t[0], t[1], f_ref}, c->f, y);
                                    });
  e.fixed = {{"f_ref_hz", f_ref}};
  return e;
}

EffectCandidate air_gap(const ContextPtr& c) {
  return simulated_effect("air_gap", "check what is behind the sample", {{"gap_m", Shape::log_uniform, 0.1 * kMm, 30 * kMm}}, c,
                          [](SimulatedChange& s, const double* t) { s.layers->layers.push_back(AirLayer{t[0]}); });
}

/// One catalogue parameter of the SPEC, times a free ratio.
EffectCandidate material(const ContextPtr& c, const SpecParameter& p) {
  return simulated_effect("material", "measure that catalogue value on the sample", {{p.name, Shape::log_uniform, p.ratio_lo, p.ratio_hi}}, c,
                          [in = p.in](SimulatedChange& s, const double* t) { in(*s.layers) *= t[0]; });
}

/// The prior of ratio is log-uniform on [0.8, 1.25], narrowed to where the simulated side is known
/// (a table covers only its own band); std::nullopt when that leaves less than ±2 % around 1.
std::optional<ParameterPrior> frequency_scale_prior(const EffectContext& c) {
  const double f_min = c.f[0], f_max = c.f[c.f.size() - 1];
  double lo = 0.8, hi = 1.25;
  while (lo < 0.98 && !c.sim.covers(f_min * lo)) lo += 0.005;
  while (hi > 1.02 && !c.sim.covers(f_max * hi)) hi -= 0.005;
  if (!(c.sim.covers(f_min * lo) && c.sim.covers(f_max * hi)) || lo > 0.98 || hi < 1.02) return std::nullopt;
  return ParameterPrior{"ratio", Shape::log_uniform, lo, hi};
}

EffectCandidate frequency_scale(const ContextPtr& c, const ParameterPrior& prior) {
  EffectCandidate e = simulated_effect("frequency_scale", "check the simulated side's frequency axis", {prior}, c,
                                       [](SimulatedChange& s, const double* t) { s.frequency_ratio *= t[0]; });
  e.predict = [c](const double* t) { return plain(c->sim.admittance(c->f * t[0])); };
  return e;
}

/// The composition of combine_effects; `members` sorted by stage, then candidate order, so the simulated
/// side is changed first, then the sample effects act on it, then the chain measures it.
EffectPrediction compose(const EffectContext& c, const std::vector<EffectCandidate>& members,
                         const std::vector<std::size_t>& offset, const SimulatedTable* table, const double* theta) {
  // With a table, the one simulated member is read from it (the table holds that member's change).
  const auto simulated_side = [&](const SimulatedChange& change) {
    return table ? (*table)(theta[offset.front()]) : simulated(c, change);
  };
  SimulatedChange change = no_change(c);
  bool changed = false, chain = false;
  ChainDeviation deviation;
  EffectPrediction out;
  out.y = c.y_sim;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const EffectCandidate& m = members[k];
    const double* t = theta + offset[k];
    if (m.stage != EffectStage::simulated && k > 0 && members[k - 1].stage == EffectStage::simulated)
      out.y = simulated_side(change);
    switch (m.stage) {
      case EffectStage::simulated: m.change(change, t); break;
      case EffectStage::sample: out.y = m.apply(out.y, t); break;
      case EffectStage::chain:
        m.deviate(deviation, t);
        chain = true;
        break;
      case EffectStage::noise: out.noise_shape = m.noise_shape(t); break;
    }
    changed = changed || m.stage == EffectStage::simulated || m.stage == EffectStage::sample;
  }
  if (members.back().stage == EffectStage::simulated) out.y = simulated_side(change);
  if (chain && c.chain)
    out.y = changed ? c.chain->measure(out.y, deviation) : c.chain->measure(deviation);
  else if (chain)
    out.y = apply_reference_plane(ReferencePlane{deviation.reference_plane_m}, c.air, c.f, out.y);
  return out;
}

}  // namespace

double ParameterPrior::transform(double u) const {
  return shape == Shape::uniform ? lo + u * (hi - lo) : lo * std::pow(hi / lo, u);
}

double ParameterPrior::cdf(double theta) const {
  const double u = shape == Shape::uniform ? (theta - lo) / (hi - lo) : std::log(theta / lo) / std::log(hi / lo);
  return std::clamp(u, 0.0, 1.0);
}

std::string ParameterPrior::describe() const {
  return fmt::format("{} [{:g}, {:g}]", shape == Shape::uniform ? "uniform" : "log-uniform", lo, hi);
}

std::string EffectCandidate::label() const {
  return name == "material" && !priors.empty() ? name + " " + priors.front().name : name;
}

std::vector<EffectCandidate> effect_candidates(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_sim,
                                               const SimulatedSide& sim, const TubeSetup& tube) {
  const Air air = Air::at_celsius(tube.temperature_c);
  std::optional<TwoMicrophoneChain> chain;
  if (full_geometry(tube)) chain.emplace(y_sim, f_hz, air, tube.geometry("the chain effects"));
  Eigen::ArrayXd sin_ks;
  if (full_geometry(tube)) sin_ks = microphone_sin_ks(air, *tube.spacing_m, f_hz);
  const auto c = std::make_shared<const EffectContext>(
      EffectContext{f_hz, y_sim, air, tube, sim, std::move(chain), TabulatedSlitModel(air, f_hz), std::move(sin_ks)});
  const LayeredAbsorber* layered =
      sim.material() ? std::get_if<LayeredAbsorber>(&*sim.material()) : nullptr;
  std::vector<EffectCandidate> out;
  out.push_back(reference_plane(c));
  if (full_geometry(tube)) add_chain_effects(out, c);
  if (tube.diameter_m) out.push_back(edge_gap(c));
  out.push_back(frame_resonance(c));
  out.push_back(fractional_order(c));
  if (layered && !(!layered->layers.empty() && std::holds_alternative<AirLayer>(layered->layers.back())))
    out.push_back(air_gap(c));
  if (full_geometry(tube) && regular_transfer(*c)) out.push_back(heteroscedastic_noise(c));
  if (const auto prior = frequency_scale_prior(*c)) out.push_back(frequency_scale(c, *prior));
  if (layered)
    for (const auto& p : spec_parameters(*layered)) out.push_back(material(c, p));
  for (auto& e : out)
    if (e.stage == EffectStage::simulated && e.priors.size() == 1)
      e.table = std::make_shared<const SimulatedTable>(c, e.priors.front(), e.change);
  return out;
}

EffectCandidate combine_effects(const std::vector<const EffectCandidate*>& members) {
  ADMITGEN_ENSURE(!members.empty(), "a combination needs at least one effect");
  if (members.size() == 1) return *members.front();
  std::vector<EffectCandidate> sorted;
  std::vector<std::size_t> offset, order(members.size());
  std::vector<std::size_t> start(members.size(), 0);
  for (std::size_t k = 1; k < members.size(); ++k) start[k] = start[k - 1] + members[k - 1]->priors.size();
  for (std::size_t k = 0; k < members.size(); ++k) order[k] = k;
  // By stage, then by place in the candidates' vector (the table's order; all members point into it).
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (members[a]->stage != members[b]->stage)
      return static_cast<int>(members[a]->stage) < static_cast<int>(members[b]->stage);
    return std::less<const EffectCandidate*>()(members[a], members[b]);
  });
  EffectCandidate out;
  out.context = members.front()->context;
  for (std::size_t k = 0; k < members.size(); ++k) {
    ADMITGEN_ENSURE(members[k]->context == out.context, "combined effects come from different diagnoses");
    out.name += (k ? "+" : "") + members[k]->label();
    out.priors.insert(out.priors.end(), members[k]->priors.begin(), members[k]->priors.end());
    out.fixed.insert(out.fixed.end(), members[k]->fixed.begin(), members[k]->fixed.end());
  }
  for (std::size_t k : order) {
    sorted.push_back(*members[k]);
    offset.push_back(start[k]);
  }
  out.stage = sorted.front().stage;
  // One simulated member of one parameter (sorted first): tabulated (SimulatedTable above).
  std::shared_ptr<const SimulatedTable> table;
  if (sorted[0].stage == EffectStage::simulated && sorted[0].priors.size() == 1 && sorted[1].stage != EffectStage::simulated)
    table = sorted[0].table ? sorted[0].table
                            : std::make_shared<const SimulatedTable>(out.context, sorted[0].priors.front(), sorted[0].change);
  out.predict = [c = out.context, sorted, offset, table](const double* t) {
    return compose(*c, sorted, offset, table.get(), t);
  };
  return out;
}

}  // namespace admitgen::diagnosis
