// SPDX-License-Identifier: MIT
#include "inference/priors.hpp"

#include "core/errors.hpp"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace admitgen {
namespace {

constexpr std::pair<Family, const char*> kFamilyKeys[] = {
    {Family::g_inf, "G_inf"}, {Family::a, "A"},         {Family::lambda, "lambda"}, {Family::b, "B"},
    {Family::c, "C"},         {Family::alpha, "alpha"}, {Family::beta, "beta"}};

/// Sorts the real poles (λ_q, A_q) of `v` by λ (θ, or u where λ is monotone): their canonical labels.
void sort_real_poles(const Order& order, double* v) {
  std::vector<std::pair<double, double>> poles;  // (λ, A)
  for (int q = 0; q < order.q(); ++q) poles.emplace_back(v[Order::lambda(q)], v[Order::a(q)]);
  std::sort(poles.begin(), poles.end());
  for (int q = 0; q < order.q(); ++q) {
    v[Order::lambda(q)] = poles[static_cast<std::size_t>(q)].first;
    v[Order::a(q)] = poles[static_cast<std::size_t>(q)].second;
  }
}

/// Φ⁻¹(u), the standard normal quantile; u is kept inside (0, 1) so that θ stays finite.
double normal_quantile(double u) {
  const double v = std::clamp(u, 1e-300, 1.0 - 0x1.0p-53);
  return -std::sqrt(2.0) * boost::math::erfc_inv(2.0 * v);
}

}  // namespace

PriorRanges PriorRanges::band(double omega_max, double admittance_scale) {
  if (!(std::isfinite(omega_max) && omega_max > 0.0))
    throw InputError(fmt::format("band priors need a positive highest frequency, got omega_max = {}", omega_max));
  PriorRanges p;
  p.lambda = {0.0, kBandPoleFactor * omega_max};
  p.alpha = {0.0, kBandPoleFactor * omega_max};
  p.beta = {-kBandResonanceFactor * omega_max, kBandResonanceFactor * omega_max};
  p.residues = ResiduePrior::gaussian;
  p.admittance_scale = admittance_scale;
  return p;
}

PriorRanges PriorRanges::band_of_the_data(double admittance_scale) {
  PriorRanges p = band(2.0 * 3.14159265358979323846 * 4000.0, admittance_scale);  // the seed paper's 4 kHz
  p.band_of_data = true;
  return p;
}

void gaussian_residue_scales(const Order& order, const double* poles, double admittance_scale, double* sd) {
  // Docs/method.md, "The Gaussian residue prior": G∞ itself, A_q/(λ_q + jω) at ω = 0, and a pair's
  // (B + jC)/(α + j(ω − β)) at its resonance ω = β are each of size s.
  int k = 0;
  sd[k++] = admittance_scale;
  for (int q = 0; q < order.q(); ++q) sd[k++] = admittance_scale * poles[q];
  for (int s = 0; s < order.s(); ++s) {
    const double alpha = poles[order.q() + 2 * s];
    sd[k++] = admittance_scale * alpha;
    sd[k++] = admittance_scale * alpha;
  }
}

const Range& PriorRanges::of(Family f) const { return const_cast<PriorRanges*>(this)->of(f); }

Range& PriorRanges::of(Family f) {
  switch (f) {
    case Family::g_inf: return g_inf;
    case Family::a: return a;
    case Family::lambda: return lambda;
    case Family::b: return b;
    case Family::c: return c;
    case Family::alpha: return alpha;
    case Family::beta: return beta;
  }
  throw InternalError("unhandled Family");
}

void PriorRanges::validate(const std::string& origin) const {
  if (residues == ResiduePrior::gaussian && !(std::isfinite(admittance_scale) && admittance_scale > 0.0))
    throw InputError(fmt::format("{}: the admittance scale of the Gaussian residue prior is {}; need a finite value > 0",
                                 origin, admittance_scale));
  for (const auto& [family, key] : kFamilyKeys) {
    if (residues == ResiduePrior::gaussian && is_residue(family)) continue;
    const Range& r = of(family);
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo < r.hi))
      throw InputError(fmt::format("{}: prior range of {} is [{}, {}]; need finite lo < hi", origin, key, r.lo, r.hi));
  }
  if (lambda.lo < 0.0 || alpha.lo < 0.0)
    throw InputError(fmt::format("{}: lambda and alpha priors must start at >= 0 (causality: poles in the left "
                                 "half plane)", origin));
}

Range* PriorRanges::find(const std::string& key) {
  for (const auto& [family, name] : kFamilyKeys)
    if (key == name) return &of(family);
  return nullptr;
}

std::vector<std::pair<std::string, Range>> PriorRanges::named() const {
  std::vector<std::pair<std::string, Range>> out;
  for (const auto& [family, key] : kFamilyKeys)
    if (residues == ResiduePrior::uniform || !is_residue(family)) out.emplace_back(key, of(family));
  return out;
}

PriorTransform::PriorTransform(const Order& order, const PriorRanges& ranges, bool reduce_symmetry)
    : order_(order), ranges_(ranges), reduced_(reduce_symmetry) {
  ranges_.validate("priors");
  const bool c_symmetric = ranges_.residues == ResiduePrior::gaussian || ranges_.c.lo == -ranges_.c.hi;
  if (reduced_ && order.s() > 0 && (ranges_.beta.lo != -ranges_.beta.hi || !c_symmetric))
    throw InputError("symmetry reduction needs beta and C prior ranges symmetric about 0; "
                     "make them symmetric or pass " + setting("reduce_symmetry = false"));
}

void PriorTransform::operator()(const double* u, double* theta) const {
  const auto families = order_.families();
  for (std::size_t k = 0; k < families.size(); ++k) {
    if (ranges_.residues == ResiduePrior::gaussian && is_residue(families[k])) continue;
    const Range& r = ranges_.of(families[k]);
    theta[k] = r.lo + r.width() * u[k];
  }
  if (ranges_.residues == ResiduePrior::uniform) return;
  const double s = ranges_.admittance_scale;
  theta[Order::g_inf()] = s * normal_quantile(u[Order::g_inf()]);
  for (int q = 0; q < order_.q(); ++q) theta[Order::a(q)] = s * theta[Order::lambda(q)] * normal_quantile(u[Order::a(q)]);
  for (int p = 0; p < order_.s(); ++p) {
    const double sd = s * theta[order_.alpha(p)];
    theta[order_.b(p)] = sd * normal_quantile(u[order_.b(p)]);
    theta[order_.c(p)] = sd * normal_quantile(u[order_.c(p)]);
  }
}

void PriorTransform::fold(double* u) const {
  if (!reduced_) return;
  // In u the symmetric β and C ranges make the sign flip u → 1 − u, and λ, β are monotone in u, so
  // the θ-space fold carries over coordinate for coordinate.
  for (int s = 0; s < order_.s(); ++s)
    if (u[order_.beta(s)] < 0.5) {
      u[order_.beta(s)] = 1.0 - u[order_.beta(s)];
      u[order_.c(s)] = 1.0 - u[order_.c(s)];
    }
  // Pairs take their canonical labels by damping α (λ for real poles): a sharp and a broad
  // resonance then keep their labels wherever their β lie, so each live-point cluster stays compact.
  std::vector<std::array<double, 4>> pairs;  // (α, B, C, β) in u
  for (int s = 0; s < order_.s(); ++s)
    pairs.push_back({u[order_.alpha(s)], u[order_.b(s)], u[order_.c(s)], u[order_.beta(s)]});
  std::sort(pairs.begin(), pairs.end());
  for (int s = 0; s < order_.s(); ++s) {
    const auto& p = pairs[static_cast<std::size_t>(s)];
    u[order_.alpha(s)] = p[0];
    u[order_.b(s)] = p[1];
    u[order_.c(s)] = p[2];
    u[order_.beta(s)] = p[3];
  }
  sort_real_poles(order_, u);  // λ is monotone in u
}

void fold_to_reduced(const Order& order, double* theta) {
  sort_real_poles(order, theta);
  std::vector<std::array<double, 4>> pairs;  // (β, B, C, α) with β ≥ 0
  for (int s = 0; s < order.s(); ++s) {
    const double sign = theta[order.beta(s)] < 0.0 ? -1.0 : 1.0;
    pairs.push_back({sign * theta[order.beta(s)], theta[order.b(s)], sign * theta[order.c(s)], theta[order.alpha(s)]});
  }
  std::sort(pairs.begin(), pairs.end());
  for (int s = 0; s < order.s(); ++s) {
    const auto& p = pairs[static_cast<std::size_t>(s)];
    theta[order.beta(s)] = p[0];
    theta[order.b(s)] = p[1];
    theta[order.c(s)] = p[2];
    theta[order.alpha(s)] = p[3];
  }
}

}  // namespace admitgen
