// SPDX-License-Identifier: MIT
/// @file
/// Evidence arithmetic shared by every model comparison (orders in selection/, effects in diagnosis/):
/// Bayes factors on the deciban scale (method.md, "Model selection").
#pragma once

namespace admitgen {

/// Bayes factor in deciban: 10 log10(Z_i / Z_j) = 10 (ln Z_i − ln Z_j)/ln 10.
double deciban(double log_z_i, double log_z_j);

}  // namespace admitgen
