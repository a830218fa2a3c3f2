// SPDX-License-Identifier: MIT
#include "io/posterior_export.hpp"

#include "core/atomic_file.hpp"
#include "core/rng.hpp"
#include "core/version.hpp"
#include "inference/posterior.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace admitgen {
namespace {

using Json = nlohmann::ordered_json;

/// Seed stream of the equal-weight draws of an order (distinct from the sampler's rounds 0, 1, 2, …).
constexpr std::uint64_t kSampleStream = 0x706f7374ULL;

std::string number(double v) { return fmt::format("{:.17g}", v); }

std::string join(const std::vector<std::string>& fields) {
  std::string line;
  for (const auto& f : fields) line += (line.empty() ? "" : ",") + f;
  return line + "\n";
}

std::string samples_file_name(const Order& order) { return "posterior_" + order.name() + ".csv"; }

std::string samples_csv(const Order& order, const Eigen::MatrixXd& s) {
  std::string out = join(order.parameter_names());
  for (Eigen::Index r = 0; r < s.rows(); ++r) {
    std::vector<std::string> row;
    for (Eigen::Index c = 0; c < s.cols(); ++c) row.push_back(number(s(r, c)));
    out += join(row);
  }
  return out;
}

Json matrix_json(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(row);
  }
  return rows;
}

Json order_json(const ModelResult& m, Eigen::Index draws) {
  Eigen::VectorXd mean;
  const Eigen::MatrixXd cov = posterior_covariance(m.run, mean);
  return Json{{"order", m.order.name()},
              {"parameters", m.order.parameter_names()},
              {"samples_csv", samples_file_name(m.order)},
              {"draws", draws},
              {"effective_sample_size", effective_sample_size(posterior_weights(m.run))},
              {"mean", std::vector<double>(mean.data(), mean.data() + mean.size())},
              {"covariance", matrix_json(cov)}};
}

std::string predictive_csv(const Measurement& data, const PredictiveBand& b) {
  std::string out = join({"f_hz", "re_G_data", "im_G_data", "alpha_data", "re_G_median", "re_G_lo95", "re_G_hi95",
                          "im_G_median", "im_G_lo95", "im_G_hi95", "alpha_median", "alpha_lo95", "alpha_hi95"});
  const Eigen::ArrayXd alpha = absorption(data.y);
  for (Eigen::Index k = 0; k < data.size(); ++k)
    out += join({number(data.f_hz[k]), number(data.y[k].real()), number(data.y[k].imag()), number(alpha[k]),
                 number(b.re_median[k]), number(b.re_lo[k]), number(b.re_hi[k]), number(b.im_median[k]),
                 number(b.im_lo[k]), number(b.im_hi[k]), number(b.alpha_median[k]), number(b.alpha_lo[k]),
                 number(b.alpha_hi[k])});
  return out;
}

}  // namespace

Eigen::MatrixXd posterior_covariance(const NestedRun& run, Eigen::VectorXd& mean) {
  const Eigen::ArrayXd w = posterior_weights(run);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> theta(
      run.samples.data(), static_cast<Eigen::Index>(run.size()), run.dim);
  mean = theta.transpose() * w.matrix();
  const Eigen::MatrixXd centred = theta.rowwise() - mean.transpose();
  const Eigen::MatrixXd cov = centred.transpose() * w.matrix().asDiagonal() * centred;
  return 0.5 * (cov + cov.transpose());  // exactly symmetric (the product is so only up to rounding)
}

Eigen::MatrixXd equal_weight_samples(const NestedRun& run, std::uint64_t seed) {
  const Eigen::ArrayXd w = posterior_weights(run);
  const auto count = static_cast<std::size_t>(std::max(1.0, std::round(effective_sample_size(w))));
  Rng rng(seed);
  const std::vector<std::size_t> idx = resample_indices(w, count, rng);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(count), run.dim);
  for (std::size_t r = 0; r < count; ++r)
    for (int c = 0; c < run.dim; ++c) out(static_cast<Eigen::Index>(r), c) = run.point(idx[r])[c];
  return out;
}

std::vector<std::pair<std::string, std::string>> posterior_export_files(const Measurement& data,
                                                                       const FitSettings& settings,
                                                                       const FitResult& fit) {
  std::vector<std::pair<std::string, std::string>> files;
  Json orders = Json::array();
  for (const ModelResult& m : fit.models) {
    const std::uint64_t seed = derive_seed(order_seed(settings.sampler.seed, m.order), kSampleStream);
    const Eigen::MatrixXd samples = equal_weight_samples(m.run, seed);
    orders.push_back(order_json(m, samples.rows()));
    files.emplace_back(samples_file_name(m.order), samples_csv(m.order, samples));
  }
  const Json index{{"schema", "admitgen.posterior/1"},
                   {"version", kVersion},
                   {"fit", "fit.json"},
                   {"selected", fit.models[fit.selected].order.name()},
                   {"samples", "equal-weight draws: systematic resampling of the nested-sampling weights, "
                               "round(effective_sample_size) per order; reduced form (beta >= 0, lambda and beta "
                               "ascending)"},
                   {"predictive_csv", "predictive.csv"},
                   {"predictive_draws", fit.predictive.draws},
                   {"orders", orders}};
  files.emplace_back("predictive.csv", predictive_csv(data, fit.predictive));
  files.insert(files.begin(), {kPosteriorIndexFile, index.dump(2) + "\n"});
  return files;
}

std::string write_posterior_export(const std::string& dir, const Measurement& data, const FitSettings& settings,
                                   const FitResult& fit) {
  for (const auto& [name, content] : posterior_export_files(data, settings, fit))
    write_file_atomically((std::filesystem::path(dir) / name).string(), content);
  return kPosteriorIndexFile;
}

}  // namespace admitgen
