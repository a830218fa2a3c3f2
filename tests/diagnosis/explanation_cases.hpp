// SPDX-License-Identifier: MIT
/// @file
/// The validation cases of combined explanations, catalogue parameters and out-of-vocabulary gaps
/// (docs/diagnosis.md, "Validation"), generated like the single-effect cases (validation_cases.hpp), and
/// how each is scored. Shared by the compact CTest (tests/diagnosis/test_explanation_suite.cpp) and the
/// full sweep (bench/diagnose/bench_validation.cpp, which prints the tables).
#pragma once

#include "validation_cases.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace admitgen::test {

/// Two effects at their clear sizes (validation_cases.hpp effect_sizes), every pair of the ten
/// documented effects, on the porous base (the one where air_gap is an effect of its own: on the others
/// the deepest layer is air and a gap behind it is the material candidate of that layer's d). Pairs with
/// tube_losses use its clear tube (29 mm, x1 = 0.3 m).
inline std::vector<ValidationCase> two_effect_cases() {
  const BaseMaterial& m = base_materials()[0];
  const auto sizes = effect_sizes(m, 600.0);
  std::vector<ValidationCase> out;
  std::uint64_t seed = 500;
  for (std::size_t a = 0; a < sizes.size(); ++a)
    for (std::size_t b = a + 1; b < sizes.size(); ++b) {
      ValidationCase c;
      c.material = m;
      c.truth = sizes[a].name;
      c.effect = sizes[a].clear;
      c.truth_second = sizes[b].name;
      c.second = sizes[b].clear;
      c.clear = true;
      c.seed = ++seed;
      if (c.truth == "tube_losses" || c.truth_second == "tube_losses") {
        c.tube_diameter_m = 0.029;
        c.mic_distance_m = 0.3;
      }
      c.label = fmt::format("two {} + {}", c.effect, c.second);
      out.push_back(c);
    }
  return out;
}

/// Two of reference_plane, mic_spacing and temperature in one case: to first order a temperature offset
/// is a reference-plane shift by −x1·ΔT/2T plus a spacing change by −s·ΔT/2T, so the three span two
/// directions and a pair of them can be re-expressed by the third with the other (docs/diagnosis.md,
/// "Combined explanations": the two pairs the search misses).
inline bool chain_degenerate(const std::vector<std::string>& effects) {
  return std::count_if(effects.begin(), effects.end(), [](const std::string& e) {
           return e == "reference_plane" || e == "mic_spacing" || e == "temperature";
         }) >= 2;
}

/// A case of `effects` (two to four) at their clear sizes on `m`, in that order (truth, truth_second, …);
/// with tube_losses among them the case uses its clear tube (29 mm, x1 = 0.3 m).
inline ValidationCase clear_effects_case(const BaseMaterial& m, const std::vector<const EffectSizes*>& effects,
                                         std::uint64_t seed) {
  ValidationCase c;
  c.material = m;
  const std::array<std::pair<std::string*, std::string*>, 4> slots{
      {{&c.truth, &c.effect}, {&c.truth_second, &c.second}, {&c.truth_third, &c.third}, {&c.truth_fourth, &c.fourth}}};
  for (std::size_t k = 0; k < effects.size() && k < slots.size(); ++k) {
    *slots[k].first = effects[k]->name;
    *slots[k].second = effects[k]->clear;
    if (effects[k]->name == "tube_losses") {
      c.tube_diameter_m = 0.029;
      c.mic_distance_m = 0.3;
    }
  }
  c.clear = true;
  c.seed = seed;
  return c;
}

/// Three effects at their clear sizes on the porous base (every effect applies there), drawn without
/// repetition from the 120 triples of the ten effects in an order shuffled by a fixed seed, those with
/// two of the chain-degenerate trio left out (chain_degenerate), the first `count`; every effect
/// appears at least once in the default 20 (checked by the bench, which prints the counts). Triples
/// with tube_losses use its clear tube (29 mm, x1 = 0.3 m).
inline std::vector<ValidationCase> three_effect_cases(std::size_t count = 20) {
  const BaseMaterial& m = base_materials()[0];
  const auto sizes = effect_sizes(m, 600.0);
  std::vector<std::array<std::size_t, 3>> triples;
  for (std::size_t a = 0; a < sizes.size(); ++a)
    for (std::size_t b = a + 1; b < sizes.size(); ++b)
      for (std::size_t c = b + 1; c < sizes.size(); ++c) triples.push_back({a, b, c});
  Rng rng(1300);
  for (std::size_t i = triples.size() - 1; i > 0; --i) std::swap(triples[i], triples[rng.next() % (i + 1)]);
  std::vector<ValidationCase> out;
  std::uint64_t seed = 1300;
  for (const auto& t : triples) {
    if (out.size() == count) break;
    if (chain_degenerate({sizes[t[0]].name, sizes[t[1]].name, sizes[t[2]].name})) continue;
    ValidationCase c = clear_effects_case(m, {&sizes[t[0]], &sizes[t[1]], &sizes[t[2]]}, ++seed);
    c.label = fmt::format("three {} + {} + {}", c.effect, c.second, c.third);
    out.push_back(c);
  }
  return out;
}

/// A catalogue parameter off (one of four layer models) together with one measurement or mounting
/// effect at its clear size (effect_sizes of that material): both must be named.
inline std::vector<ValidationCase> catalogue_effect_cases() {
  struct Off {
    BaseMaterial material;
    std::string real_spec, parameter;
    double ratio;
  };
  const std::string jca = "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)";
  const std::vector<Off> offs{
      {{"miki", "miki(sigma=10000, d=50mm)", 0.05}, "miki(sigma=14000, d=50mm)", "1.sigma", 1.4},
      {{"jca+air", jca, 0.03},
       "jca(phi=0.94, sigma=60000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)", "1.sigma", 1.5},
      {{"mpp+air", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", 0.05},
       "mpp(hole=0.52mm, t=0.4mm, p=1%) + air(d=50mm)", "1.hole", 1.3},
      {{"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=40mm)", 0.04},
       "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=50mm)", "1.d", 1.25},
  };
  const std::vector<std::string> effects{"reference_plane", "mic_spacing", "mic_mismatch", "temperature", "edge_gap",
                                         "frame_resonance"};
  std::vector<ValidationCase> out;
  std::uint64_t seed = 1500;
  for (const auto& o : offs)
    for (const auto& name : effects) {
      const auto sizes = effect_sizes(o.material, 600.0);
      const auto size = *std::find_if(sizes.begin(), sizes.end(), [&](const EffectSizes& e) { return e.name == name; });
      ValidationCase c;
      c.material = o.material;
      c.real_spec = o.real_spec;
      c.truth = "material";
      c.parameter = o.parameter;
      c.ratio = o.ratio;
      c.truth_second = name;
      c.second = size.clear;
      c.clear = true;
      c.seed = ++seed;
      c.label = fmt::format("catalogue {} {} x{:.3g} + {}", o.material.name, o.parameter, o.ratio, c.second);
      out.push_back(c);
    }
  return out;
}

/// Single effects that have a known mimic, at clear sizes, on the porous base, two sizes and two seeds
/// each: edge_gap ↔ frame_resonance (a resonance at the slit's quarter-wave frequency c0/4h ≈ 1.7 kHz for
/// h = 50 mm), air_gap ↔ thickness (material 1.d), temperature ↔ reference_plane. The verdict must name
/// the truth alone.
inline std::vector<ValidationCase> mimic_cases() {
  const BaseMaterial& m = base_materials()[0];
  // Two sizes of each: synth --effect texts, or for the thickness the real sample's SPEC (material 1.d).
  const std::vector<std::pair<std::string, std::array<std::string, 2>>> effects{
      {"edge_gap", {"edge_gap:width_m=1mm,depth_m=0.05", "edge_gap:width_m=2mm,depth_m=0.05"}},
      {"frame_resonance", {"frame_resonance:f0_hz=1700,q=8,y_peak=0.1", "frame_resonance:f0_hz=1700,q=4,y_peak=0.2"}},
      {"air_gap", {"air_gap:gap_m=3mm", "air_gap:gap_m=6mm"}},
      {"material", {"miki(sigma=10000, d=55mm)", "miki(sigma=10000, d=45mm)"}},
      {"temperature", {"temperature:delta_k=8", "temperature:delta_k=-6"}},
      {"reference_plane", {"reference_plane:delta_m=3mm", "reference_plane:delta_m=-2mm"}}};
  std::vector<ValidationCase> out;
  std::uint64_t seed = 1700;
  for (int repeat = 0; repeat < 2; ++repeat)
    for (const auto& [truth, sizes] : effects)
      for (std::size_t k = 0; k < 2; ++k) {
        ValidationCase c;
        c.material = m;
        c.truth = truth;
        (truth == "material" ? c.real_spec : c.effect) = sizes[k];
        if (truth == "material") {
          c.parameter = "1.d";
          c.ratio = k == 0 ? 1.1 : 0.9;
        }
        c.clear = true;
        c.seed = ++seed;
        c.label = fmt::format("mimic {} (seed {})", sizes[k], c.seed);
        out.push_back(c);
      }
  return out;
}

/// The bases of the sweeps composed by another route (ValidationCase::other_route): layered SPECs the
/// other sweeps do not use, each rigid-backed so that air_gap is an effect of its own; `off` is the
/// same sample with the catalogue parameter `parameter` that sets its flow resistivity (σ, or the pore
/// size of horoshenkov's law) at 0.75 of the catalogue value.
struct OtherRouteBase {
  BaseMaterial material;
  std::string off, parameter;
};

inline const std::vector<OtherRouteBase>& other_route_bases() {
  static const std::vector<OtherRouteBase> b{
      {{"delany_bazley", "delany_bazley(sigma=20000, d=40mm)", 0.04}, "delany_bazley(sigma=15000, d=40mm)", "1.sigma"},
      {{"jca", "jca(phi=0.95, sigma=15000, alpha_inf=1.2, lambda=90um, lambda_th=180um, d=40mm)", 0.04},
       "jca(phi=0.95, sigma=11250, alpha_inf=1.2, lambda=90um, lambda_th=180um, d=40mm)", "1.sigma"},
      {{"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=45mm)", 0.045},
       "horoshenkov(phi=0.9, pore=112.5um, sigma_s=0.3, d=45mm)", "1.pore"}};
  return b;
}

/// Four effects at their clear sizes (effect_sizes, the frame resonance at 800 Hz), composed by the other
/// route on the other bases in turn: drawn without repetition from the 210 quadruples of the ten effects
/// in an order shuffled by a fixed seed, those with two of the chain-degenerate trio left out
/// (chain_degenerate: such a set has no unique answer), the first `count`. Quadruples with tube_losses use
/// its clear tube (29 mm, x1 = 0.3 m).
inline std::vector<ValidationCase> four_effect_cases(std::size_t count = 20) {
  std::vector<std::array<std::size_t, 4>> quadruples;
  for (std::size_t a = 0; a < 10; ++a)
    for (std::size_t b = a + 1; b < 10; ++b)
      for (std::size_t c = b + 1; c < 10; ++c)
        for (std::size_t d = c + 1; d < 10; ++d) quadruples.push_back({a, b, c, d});
  Rng rng(1900);
  for (std::size_t i = quadruples.size() - 1; i > 0; --i) std::swap(quadruples[i], quadruples[rng.next() % (i + 1)]);
  std::vector<ValidationCase> out;
  std::uint64_t seed = 1900;
  for (const auto& q : quadruples) {
    if (out.size() == count) break;
    const BaseMaterial& m = other_route_bases()[out.size() % other_route_bases().size()].material;
    const auto sizes = effect_sizes(m, 800.0);
    if (chain_degenerate({sizes[q[0]].name, sizes[q[1]].name, sizes[q[2]].name, sizes[q[3]].name})) continue;
    ValidationCase c = clear_effects_case(m, {&sizes[q[0]], &sizes[q[1]], &sizes[q[2]], &sizes[q[3]]}, ++seed);
    c.other_route = true;
    c.label = fmt::format("four {}: {} + {} + {} + {}", m.name, c.effect, c.second, c.third, c.fourth);
    out.push_back(c);
  }
  return out;
}

/// Two effects, one of which has a known mimic that can ride beside it as a passenger member
/// (docs/diagnosis.md, "Four effects and mimics beside their partners"): edge_gap (mimic frame_resonance)
/// with a flow resistivity (or pore size) at 0.75 of the catalogue value, with a frame resonance, with temperature and
/// with a microphone calibration off by 15 % (a real fault, beyond the former gain prior of 0.1);
/// mic_mismatch with reference_plane (mimic mic_spacing); temperature (mimic of reference_plane and
/// mic_spacing) with mic_mismatch; air_gap (mimic material 1.d) with a frame resonance; a reference plane
/// with a frame resonance at the slit's quarter-wave frequency (edge_gap's mimic). Composed by the other
/// route on each of the other bases.
inline std::vector<ValidationCase> partner_cases() {
  const std::vector<std::pair<std::string, std::string>> pairs{
      {"edge_gap:width_m=1mm,depth_m=DEPTH", "material"},
      {"edge_gap:width_m=1mm,depth_m=DEPTH", "frame_resonance:f0_hz=600,q=8,y_peak=0.1"},
      {"mic_mismatch:gain=0.03,phase_deg=1", "reference_plane:delta_m=3mm"},
      {"mic_mismatch:gain=0.15,phase_deg=2", "edge_gap:width_m=1mm,depth_m=DEPTH"},
      {"temperature:delta_k=8", "edge_gap:width_m=1mm,depth_m=DEPTH"},
      {"temperature:delta_k=-6", "mic_mismatch:gain=0.03,phase_deg=1"},
      {"air_gap:gap_m=3mm", "frame_resonance:f0_hz=600,q=8,y_peak=0.1"},
      {"reference_plane:delta_m=-2mm", "frame_resonance:f0_hz=1700,q=8,y_peak=0.1"}};
  std::vector<ValidationCase> out;
  std::uint64_t seed = 2100;
  for (const auto& b : other_route_bases())
    for (const auto& [first, second] : pairs) {
      const auto depth = [&](std::string text) {
        const auto at = text.find("DEPTH");
        return at == std::string::npos ? text : text.replace(at, 5, fmt::format("{}", b.material.thickness_m));
      };
      ValidationCase c;
      c.material = b.material;
      c.other_route = true;
      c.effect = depth(first);
      c.truth = effect_name(parse_effect(c.effect));
      if (second == "material") {
        c.real_spec = b.off;
        c.truth_second = "material";
        c.parameter = b.parameter;
        c.ratio = 0.75;
      } else {
        c.second = depth(second);
        c.truth_second = effect_name(parse_effect(c.second));
      }
      c.clear = true;
      c.seed = ++seed;
      c.label = fmt::format("partner {}: {} + {}", b.material.name, c.effect,
                            second == "material" ? fmt::format("{} x{:.3g}", c.parameter, c.ratio) : c.second);
      out.push_back(c);
    }
  return out;
}

/// One catalogue parameter off, for each layer model and for multi-layer SPECs (`parameter` in SPEC
/// naming, `ratio` the true value over the catalogue value).
inline std::vector<ValidationCase> material_cases() {
  struct Off {
    std::string name, spec, real_spec, parameter;
    double ratio;
  };
  const std::string jca = "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)";
  const std::vector<Off> offs{
      {"miki", "miki(sigma=10000, d=50mm)", "miki(sigma=14000, d=50mm)", "1.sigma", 1.4},
      {"miki", "miki(sigma=10000, d=50mm)", "miki(sigma=10000, d=40mm)", "1.d", 0.8},
      {"delany_bazley", "delany_bazley(sigma=20000, d=40mm)", "delany_bazley(sigma=14000, d=40mm)", "1.sigma", 0.7},
      {"delany_bazley", "delany_bazley(sigma=20000, d=40mm)", "delany_bazley(sigma=20000, d=50mm)", "1.d", 1.25},
      {"jca+air", jca, "jca(phi=0.94, sigma=60000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)",
       "1.sigma", 1.5},
      {"jca+air", jca, "jca(phi=0.94, sigma=40000, alpha_inf=1.38, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)",
       "1.alpha_inf", 1.3},
      {"jca+air", jca, "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=24mm) + air(d=20mm)",
       "1.d", 0.8},
      {"jca+air", jca, "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=26mm)",
       "2.d", 1.3},
      {"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=40mm)",
       "horoshenkov(phi=0.9, pore=210um, sigma_s=0.3, d=40mm)", "1.pore", 1.4},
      {"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=40mm)",
       "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=50mm)", "1.d", 1.25},
      {"mpp+air", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", "mpp(hole=0.52mm, t=0.4mm, p=1%) + air(d=50mm)",
       "1.hole", 1.3},
      {"mpp+air", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", "mpp(hole=0.4mm, t=0.4mm, p=0.7%) + air(d=50mm)",
       "1.p", 0.7},
      {"mpp+air", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=40mm)", "2.d",
       0.8},
      {"miki+miki", "miki(sigma=20000, d=20mm) + miki(sigma=5000, d=30mm)",
       "miki(sigma=20000, d=20mm) + miki(sigma=7500, d=30mm)", "2.sigma", 1.5},
      {"miki+miki", "miki(sigma=20000, d=20mm) + miki(sigma=5000, d=30mm)",
       "miki(sigma=20000, d=26mm) + miki(sigma=5000, d=30mm)", "1.d", 1.3},
      {"mpp+air+miki", "mpp(hole=0.5mm, t=0.5mm, p=2%) + air(d=20mm) + miki(sigma=10000, d=30mm)",
       "mpp(hole=0.5mm, t=0.5mm, p=2%) + air(d=20mm) + miki(sigma=15000, d=30mm)", "3.sigma", 1.5},
      // The remaining parameters of each layer model (appended, so the seeds above stay as they were).
      {"jca+air", jca, "jca(phi=0.80, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)",
       "1.phi", 0.80 / 0.94},
      {"jca+air", jca, "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=34um, lambda_th=110um, d=30mm) + air(d=20mm)",
       "1.lambda", 34.0 / 56.0},
      {"jca+air", jca, "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=180um, d=30mm) + air(d=20mm)",
       "1.lambda_th", 180.0 / 110.0},
      {"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=40mm)",
       "horoshenkov(phi=0.75, pore=150um, sigma_s=0.3, d=40mm)", "1.phi", 0.75 / 0.9},
      {"horoshenkov", "horoshenkov(phi=0.9, pore=150um, sigma_s=0.3, d=40mm)",
       "horoshenkov(phi=0.9, pore=150um, sigma_s=0.45, d=40mm)", "1.sigma_s", 1.5},
      {"mpp+air", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", "mpp(hole=0.4mm, t=0.6mm, p=1%) + air(d=50mm)", "1.t",
       1.5},
      {"delany_bazley+air", "delany_bazley(sigma=20000, d=30mm) + air(d=30mm)",
       "delany_bazley(sigma=26000, d=30mm) + air(d=30mm)", "1.sigma", 1.3},
  };
  std::vector<ValidationCase> out;
  std::uint64_t seed = 700;
  for (const auto& o : offs) {
    ValidationCase c;
    c.material = {o.name, o.spec, 0.05};
    c.real_spec = o.real_spec;
    c.truth = "material";
    c.parameter = o.parameter;
    c.ratio = o.ratio;
    c.clear = true;
    c.seed = ++seed;
    c.label = fmt::format("material {} {} x{:.3g}", o.name, o.parameter, o.ratio);
    out.push_back(c);
  }
  return out;
}

/// y − a resonance of admittance: an absorption dip, which frame_resonance (y_peak > 0) cannot make.
inline Distortion absorption_dip(double f0_hz, double q, double depth) {
  return [=](const Eigen::ArrayXd& f, const Eigen::ArrayXcd& y) {
    const Eigen::ArrayXd detuning = q * (f / f0_hz - f0_hz / f);
    Eigen::ArrayXcd out = y;
    for (Eigen::Index i = 0; i < f.size(); ++i) out[i] -= depth / std::complex<double>(1.0, detuning[i]);
    return out;
  };
}

/// A running mean over 2·half + 1 points along frequency (smoothing by the tube's software).
inline Distortion smoothing(int half) {
  return [=](const Eigen::ArrayXd&, const Eigen::ArrayXcd& y) {
    Eigen::ArrayXcd out(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      const Eigen::Index lo = std::max<Eigen::Index>(0, i - half), hi = std::min<Eigen::Index>(y.size() - 1, i + half);
      out[i] = y.segment(lo, hi - lo + 1).mean();
    }
    return out;
  };
}

/// Microphone ratio drifting with frequency, (1 + g (f/f_top)²) e^{jφ f/f_top}, through the reference
/// tube's chain (a constant mismatch is mic_mismatch; a drift is not in the vocabulary).
inline Distortion mic_drift(double gain, double phase_deg, const ValidationCase& c) {
  const TubeSetup tube = case_tube(c);
  return [=](const Eigen::ArrayXd& f, const Eigen::ArrayXcd& y) {
    const Air air = Air::at_celsius(tube.temperature_c);
    const TubeGeometry g = tube.geometry("mic drift");
    Eigen::ArrayXcd out(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      const double x = f[i] / f[f.size() - 1];
      ChainDeviation d;
      d.mic_ratio = (1.0 + gain * x * x) * std::polar(1.0, phase_deg * x * static_cast<double>(EIGEN_PI) / 180.0);
      out[i] = measure_through_chain(y.segment(i, 1), f.segment(i, 1), air, g, d)[0];
    }
    return out;
  };
}

/// Gaps outside the vocabulary: a different material law than the SPEC's, a sample thicker or thinner
/// than the simulated table assumed, smoothing by the tube software, a frequency-dependent microphone
/// drift, an absorption dip.
inline std::vector<ValidationCase> out_of_vocabulary_cases() {
  std::vector<ValidationCase> out;
  std::uint64_t seed = 900;
  const auto add = [&](ValidationCase c, const std::string& what) {
    c.truth = "unexplained";
    c.clear = true;
    c.seed = ++seed;
    c.label = fmt::format("oov {} {}", c.material.name, what);
    out.push_back(c);
  };
  const auto& bases = base_materials();
  for (const auto* law : {"jca(phi=0.95, sigma=10000, alpha_inf=1.4, lambda=80um, lambda_th=160um, d=50mm)",
                          "horoshenkov(phi=0.95, pore=300um, sigma_s=0.5, d=50mm)"}) {
    ValidationCase c;
    c.material = bases[0];
    c.real_spec = law;
    add(c, fmt::format("law {}", law));
  }
  for (const char* d : {"40mm", "65mm"}) {
    ValidationCase c;
    c.material = bases[0];
    c.real_spec = fmt::format("miki(sigma=10000, d={})", d);
    c.sim_table = true;
    add(c, fmt::format("thickness {} against a 50mm table", d));
  }
  for (const auto& m : bases) {
    ValidationCase c;
    c.material = m;
    c.distort = smoothing(6);
    add(c, "smoothing 13 points");
    c.distort = absorption_dip(m.name == "porous" ? 900.0 : 1400.0, 6.0, 0.15);
    add(c, "absorption dip");
    c.distort = mic_drift(0.15, 4.0, c);
    add(c, "mic drift 15 % / 4 deg at the top");
  }
  // Further cases, appended so the seeds above stay as they were: another law under the layered base, a
  // sharper dip higher up, a drift of the other sign.
  {
    ValidationCase c;
    c.material = bases[1];
    c.real_spec = "horoshenkov(phi=0.95, pore=200um, sigma_s=0.4, d=30mm) + air(d=20mm)";
    add(c, "law horoshenkov(phi=0.95, pore=200um, sigma_s=0.4, d=30mm) + air(d=20mm)");
    c = ValidationCase{};
    c.material = bases[0];
    c.distort = absorption_dip(1500.0, 12.0, 0.1);
    add(c, "absorption dip at 1500 Hz, q 12");
    for (const BaseMaterial* m : {&bases[0], &bases[1]}) {
      c = ValidationCase{};
      c.material = *m;
      c.distort = mic_drift(-0.12, -3.0, c);
      add(c, "mic drift -12 % / -3 deg at the top");
    }
  }
  return out;
}

/// Whether the verdict's explanation holds `effect` (for material: with `parameter`).
inline bool explains(const diagnosis::Verdict& v, const std::string& effect, const std::string& parameter = "") {
  return std::any_of(v.explanation.begin(), v.explanation.end(), [&](const diagnosis::VerdictMember& m) {
    return m.effect == effect && (parameter.empty() || (!m.parameters.empty() && m.parameters.front().first == parameter));
  });
}

/// The ratio the explanation gives to `parameter` (0 when absent).
inline double material_ratio(const diagnosis::Verdict& v, const std::string& parameter) {
  for (const auto& m : v.explanation)
    if (m.effect == "material" && m.parameters.front().first == parameter) return m.parameters.front().second;
  return 0.0;
}

/// The effects a case holds (its documented names; material for a catalogue parameter off).
inline std::vector<std::string> case_truths(const ValidationCase& c) {
  std::vector<std::string> out;
  for (const auto* t : {&c.truth, &c.truth_second, &c.truth_third, &c.truth_fourth})
    if (!t->empty() && *t != "none" && *t != "unexplained") out.push_back(*t);
  return out;
}

/// No passenger: every member of the verdict's explanation is one of the case's effects (a material
/// member with the case's parameter), whatever the verdict; missing effects are not counted here.
inline bool no_passenger(const diagnosis::Verdict& v, const ValidationCase& c) {
  const std::vector<std::string> truths = case_truths(c);
  return std::all_of(v.explanation.begin(), v.explanation.end(), [&](const diagnosis::VerdictMember& m) {
    if (std::find(truths.begin(), truths.end(), m.effect) == truths.end()) return false;
    return m.effect != "material" || (!m.parameters.empty() && m.parameters.front().first == c.parameter);
  });
}

/// Named exactly: the verdict names the explanation (its residual is white, not unexplained) and its
/// members are the case's effects, each once and nothing else; a material member with the case's
/// parameter, its ratio within 30 % in log.
inline bool named_exactly(const diagnosis::Verdict& v, const ValidationCase& c) {
  const std::vector<std::string> truths = case_truths(c);
  if (v.effect == "none" || v.effect == "unexplained" || v.explanation.size() != truths.size()) return false;
  for (const auto& t : truths) {
    if (!explains(v, t, t == "material" ? c.parameter : "")) return false;
    if (t == "material" && std::abs(std::log(material_ratio(v, c.parameter) / c.ratio)) > std::log(1.3)) return false;
  }
  return true;
}

/// Gap before / gap left by the exact model of the case (the truth without noise).
inline double exact_shrink(const ValidationCase& c, const diagnosis::Diagnosis& d) {
  const auto request = case_request(c);
  return d.gap.total / diagnosis::measure_gap(request.real.f_hz, request.real.y, exact_y(c), d.level).total;
}

/// Gap before / gap left by the exact model, without running the diagnosis (the same data and gap as
/// run_case's): how far above the noise the case's own gap lies (≈ 1 when the gap is noise).
inline double exact_shrink(const ValidationCase& c) {
  const auto request = case_request(c);
  const Eigen::ArrayXcd& y = request.real.y;
  const double level = diagnosis::rms_level(y);
  const Eigen::ArrayXcd y_sim = request.sim.admittance(request.real.f_hz);
  return diagnosis::measure_gap(request.real.f_hz, y, y_sim, level).total /
         diagnosis::measure_gap(request.real.f_hz, y, exact_y(c), level).total;
}

/// The largest shrink of any single effect.
inline double best_single_shrink(const diagnosis::Diagnosis& d) {
  double best = 1.0;
  for (const auto& e : d.identification.effects) best = std::max(best, e.shrink);
  return best;
}

}  // namespace admitgen::test
