// SPDX-License-Identifier: MIT
/// @file
/// Log-spaced frequency grids with a stated density: the constraint grid of the passive residues, the net of the
/// exact passivity test and the nodes of the passive bound.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace admitgen {

/// n + 1 points lo·(hi/lo)^(k/n), k = 0 … n, with n = max(1, ⌈per_decade · log10(hi/lo)⌉).
inline std::vector<double> log_grid(double lo, double hi, int per_decade) {
  const int n = std::max(1, static_cast<int>(std::ceil(per_decade * std::log10(hi / lo))));
  std::vector<double> g(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) g[static_cast<std::size_t>(k)] = lo * std::pow(hi / lo, static_cast<double>(k) / n);
  return g;
}

}  // namespace admitgen
