// SPDX-License-Identifier: MIT
/// @file
/// Writes synthetic admittance as a CSV that `admitgen fit DATA` reads with its defaults (columns
/// f,re,im; normalised admittance): `#` comment lines saying how the data were made (generator
/// version, material SPEC, effects, noise, seed, grid, tube), one header line, then one row per
/// frequency with every number printed %.17g so that it reads back bit for bit.
#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace admitgen {

/// The provenance lines, as (key, value) pairs: written "# key: value" in this order.
using CsvProvenance = std::vector<std::pair<std::string, std::string>>;

/// The whole file as text. Values must not contain line breaks (ENSURE).
std::string format_admittance_csv(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y, const CsvProvenance& provenance);

/// Formats and writes `path` atomically (no partial file on failure; InputError if unwritable).
void write_admittance_csv(const std::string& path, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y,
                          const CsvProvenance& provenance);

}  // namespace admitgen
