// SPDX-License-Identifier: MIT
#include "inference/priors.hpp"

#include "core/errors.hpp"

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

}  // namespace

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
  for (const auto& [family, key] : kFamilyKeys) {
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
  for (const auto& [family, key] : kFamilyKeys) out.emplace_back(key, of(family));
  return out;
}

PriorTransform::PriorTransform(const Order& order, const PriorRanges& ranges, bool reduce_symmetry)
    : order_(order), ranges_(ranges), reduced_(reduce_symmetry) {
  ranges_.validate("priors");
  if (reduced_ && order.s() > 0 && (ranges_.beta.lo != -ranges_.beta.hi || ranges_.c.lo != -ranges_.c.hi))
    throw InputError("symmetry reduction needs beta and C prior ranges symmetric about 0; "
                     "make them symmetric or pass " + setting("reduce_symmetry = false"));
}

void PriorTransform::operator()(const double* u, double* theta) const {
  const auto families = order_.families();
  for (std::size_t k = 0; k < families.size(); ++k) {
    const Range& r = ranges_.of(families[k]);
    theta[k] = r.lo + r.width() * u[k];
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
