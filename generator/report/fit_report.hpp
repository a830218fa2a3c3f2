// SPDX-License-Identifier: MIT
/// @file
/// report.html of `admitgen fit`: what an acoustician looks at to judge a fit. Built from the fit's
/// record (model/fit_record.hpp, what fit.json holds) and the measured data, so the same page can be
/// rebuilt from a saved fit. Figures: (a) absorption α(f) of data and selected model with its
/// 95 % posterior band, (b) Re G and Im G likewise, (c) ln Z of every order with error bars; tables of
/// Bayes factors, parameters and sampler diagnostics; input, settings and version. Deterministic: equal
/// inputs give equal bytes.
#pragma once

#include "data/measurement.hpp"
#include "model/fit_record.hpp"
#include "plot/figure.hpp"

#include <string>
#include <vector>

namespace admitgen::report {

/// The report's figures in page order: absorption, Re G, Im G, evidence.
std::vector<plot::Figure> fit_figures(const FitRecord& fit, const Measurement& data);

/// The whole page.
std::string fit_report_html(const FitRecord& fit, const Measurement& data);

/// Writes DIR/report.html atomically; returns its path.
std::string write_fit_report(const std::string& dir, const FitRecord& fit, const Measurement& data);

}  // namespace admitgen::report
