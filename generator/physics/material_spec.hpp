// SPDX-License-Identifier: MIT
/// @file
/// The material SPEC of `admitgen synth --material` and `diagnose --sim`: a readable one-line
/// description of a layered absorber or a multipole surface. Grammar (blanks allowed between tokens):
///
///   spec   := layer { "+" layer }                 layers from the exposed face to the rigid backing
///           | "multipole(" params ")"             a surface given by its multipole parameters
///           | "fit(" params ")"                   the multipole of a fit.json
///   layer  := name "(" params ")"
///   params := [ key "=" value { "," key "=" value } ]
///   value  := number [ unit ]                     lengths: m (default), cm, mm, um; ratios: % or a fraction
///
/// | layer | parameters | model |
/// |---|---|---|
/// | `delany_bazley` | `sigma` [Pa·s/m²], `d` | Delany & Bazley 1970 |
/// | `miki` | `sigma`, `d` | Miki 1990 |
/// | `jca` | `phi`, `sigma`, `alpha_inf`, `lambda` (Λ), `lambda_th` (Λ'), `d` | Johnson-Champoux-Allard |
/// | `horoshenkov` | `phi`, `pore` (median pore size s̄), `sigma_s` (log2 deviation), `d` | Horoshenkov et al. 2019 |
/// | `mpp` | `hole` (diameter), `t` (thickness), `p` (perforation ratio) | Maa 1998 panel (put an `air` cavity behind it) |
/// | `air` | `d` | lossless air layer (cavity, gap) |
///
/// `multipole(G_inf=…, A_1=…, lambda_1=…, B_1=…, C_1=…, alpha_1=…, beta_1=…)` takes fit.json's
/// parameter names (s⁻¹); the order follows from the names given. `fit(file=PATH[, order=QxSy]
/// [, estimate=mean|max_likelihood])` reads PATH (a fit.json; the selected order and the posterior
/// mean by default). Neither can be combined with layers.
///
/// Examples: `miki(sigma=10000, d=50mm)`; a porous layer over an air gap
/// `jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=50mm) + air(d=20mm)`;
/// a three-layer MPP absorber `mpp(hole=0.4mm,t=0.4mm,p=1%) + air(d=30mm) + mpp(…) + air(…) + mpp(…) + air(…)`.
#pragma once

#include "model/fit_record.hpp"
#include "physics/material.hpp"

#include <functional>
#include <string>
#include <vector>

namespace admitgen {

/// Reads the fit file at a path (the command line passes io::read_fit_file).
using FitReader = std::function<FitRecord(const std::string& path)>;

/// Parses SPEC (reading the fit.json a `fit(...)` names with `read_fit`; without it, `fit(...)` is
/// refused). Throws InputError quoting the SPEC and saying what is wrong: unknown layer, missing, unknown
/// or out-of-range parameter, bad syntax.
Material parse_material_spec(const std::string& spec, const FitReader& read_fit = {});

/// One numeric parameter of a layered SPEC, as `diagnose` varies it (a catalogue value that may be off):
/// named "<layer index from 1>.<SPEC key>" (e.g. "1.sigma", "2.d"), with the range [ratio_lo, ratio_hi]
/// of factors that keep the layer physical inside [0.5, 2] (porosity and perforation ≤ 1, tortuosity ≥ 1).
struct SpecParameter {
  std::string name;
  double value = 0.0;
  double ratio_lo = 0.5, ratio_hi = 2.0;
  /// The parameter inside a copy of the absorber (same layer structure).
  std::function<double&(LayeredAbsorber&)> in;
};

/// Every numeric parameter of the layers, in SPEC order (layer by layer, keys in the table's order);
/// a parameter whose physical range leaves less than ±2 % around 1 is left out (e.g. phi = 1).
std::vector<SpecParameter> spec_parameters(const LayeredAbsorber& absorber);

}  // namespace admitgen
