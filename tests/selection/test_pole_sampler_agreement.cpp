// SPDX-License-Identifier: MIT
// The pole sampler (residues and noise integrated out exactly, inference/poles_sampler.hpp; docs/method.md,
// "Sampling the poles only") against the full sampler, which samples the residues as coordinates under the
// same prior (PriorTransform: r_k = s_k(ψ)·Φ⁻¹(u_k), the Gaussian residue prior of docs/method.md, "The
// closed-form marginal"), in the doctest suite "statistical" (sampler runs). Both run under the band priors
// of the data (PriorRanges::band at its highest angular frequency). Tolerance: 3 combined standard errors
// √(e_poles² + e_full²), a 99.7 % band for two independent estimates. Sizes: 300 live points, seed 1.
#include "data/csv_reader.hpp"
#include "inference/evidence.hpp"
#include "inference/residue_evidence.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

void check_agreement(const Measurement& data, const Order& order, FitSettings settings) {
  settings.sampler_kind = SamplerKind::full;
  const ModelResult full = fit_order(data, order, settings);
  settings.sampler_kind = SamplerKind::poles;
  const ModelResult poles = fit_order(data, order, settings);
  const double tol = 3.0 * std::hypot(poles.run.log_z_error, full.run.log_z_error);
  MESSAGE(order.name(), ": poles ", poles.run.log_z, " ± ", poles.run.log_z_error, " (", poles.run.calls, " calls, ",
          poles.cpu_seconds, " s), full ", full.run.log_z, " ± ", full.run.log_z_error, " (", full.run.calls, " calls, ",
          full.cpu_seconds, " s)");
  CHECK(poles.sampler == "poles_analytic_residues");
  CHECK(full.sampler == "full");
  CHECK(std::abs(poles.run.log_z - full.run.log_z) <= tol);
  // The complete posterior: the residues' posterior means agree too (within 3 combined posterior
  // standard errors of a mean, σ/√ESS with ESS ≥ 100 for these runs: 0.5 σ is generous).
  for (std::size_t k = 0; k < full.parameters.size(); ++k) {
    const ParameterSummary &a = poles.parameters[k], &b = full.parameters[k];
    INFO(a.name, ": poles ", a.mean, " ± ", a.std, ", full ", b.mean, " ± ", b.std);
    CHECK(std::abs(a.mean - b.mean) <= 0.5 * std::max(a.std, b.std) + 1e-12);
  }
}

/// Z of Q0S1 by a 2-D tensor Gauss-Legendre rule over the poles (α, β): L(ψ) the closed-form marginal
/// (checked against brute force over the residues in tests/inference/test_residue_evidence.cpp), the prior
/// uniform on α ∈ [0, a], β ∈ [−b, b]; by the symmetry β → −β, Z = 2/(4ab) ∫_{β>0} L dα dβ. The window is
/// ±`half` around (α₀, β₀) in units (sα, sβ): the posterior's mass outside it is negligible when two windows
/// agree (checked by the caller).
double q0s1_quadrature(const Measurement& data, const PriorRanges& priors, double a0, double b0, double sa, double sb,
                       double half, int panels) {
  const ResidueEvidence evidence(data, Order(0, 1), DataCount::two_per_point, priors.admittance_scale);
  constexpr int m = 16;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m, m);
  for (int k = 1; k < m; ++k) j(k, k - 1) = j(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(j);
  std::vector<double> x, w;
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < m; ++k) {
      x.push_back(-half + 2.0 * half / panels * (p + 0.5 * (es.eigenvalues()[k] + 1.0)));
      w.push_back(half / panels * 2.0 * es.eigenvectors()(0, k) * es.eigenvectors()(0, k));
    }
  double acc = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t k = 0; k < x.size(); ++k) {
      const double psi[2] = {a0 + sa * x[i], b0 + sb * x[k]};
      acc = log_add_exp(acc, std::log(w[i] * w[k] * sa * sb) + evidence(psi));
    }
  return acc + std::log(2.0 / (priors.alpha.width() * priors.beta.width()));
}

Measurement reference() { return read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{}); }

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("pole sampler: ln Z agrees with the full sampler under the same Gaussian residue prior (Q0S0, Q1S1)") {
    const Measurement data = reference();
    FitSettings settings;
    settings.priors = PriorRanges::band(data.omega().maxCoeff());
    settings.sampler.live = 300;
    for (const Order& o : {Order(0, 0), Order(1, 1)}) check_agreement(data, o, settings);
  }

  TEST_CASE("pole sampler: Q0S1 ln Z equals 2-D quadrature over the poles, and so does the full sampler") {
    // The one pair of Q0S1 sits at the data's resonance (α ≈ 1530, β ≈ 10060 s⁻¹, posterior widths a few s⁻¹): the
    // window ±60 widths of 20 s⁻¹ around the pole run's posterior mean holds it; two rule sizes and two windows
    // agree to 1e-4 nats (the prior's mass elsewhere carries likelihoods hundreds of nats lower). Both samplers
    // at 300 live points, seed 1. The pole sampler within 3 of its reported errors of the quadrature. The full sampler
    // (11-13 slices in 5 dimensions) came out 1.39 nats low (quadrature 697.64, poles 697.52 ± 0.21, full 696.26 ±
    // 0.31): the low bias of the full sampler that docs/validation.md records, and why it is not the default;
    // it may lose mass, never create it, so only its upper side is asserted.
    const Measurement data = reference();
    FitSettings settings;
    settings.priors = PriorRanges::band(data.omega().maxCoeff());
    settings.sampler.live = 300;
    const ModelResult poles = fit_order(data, Order(0, 1), settings);
    const double a0 = poles.parameters[static_cast<std::size_t>(Order(0, 1).alpha(0))].mean;
    const double b0 = poles.parameters[static_cast<std::size_t>(Order(0, 1).beta(0))].mean;
    const double ref = q0s1_quadrature(data, settings.priors, a0, b0, 20.0, 20.0, 60.0, 24);
    REQUIRE(std::abs(ref - q0s1_quadrature(data, settings.priors, a0, b0, 20.0, 20.0, 60.0, 18)) < 1e-4);
    REQUIRE(std::abs(ref - q0s1_quadrature(data, settings.priors, a0, b0, 20.0, 20.0, 40.0, 18)) < 1e-4);
    settings.sampler_kind = SamplerKind::full;
    const ModelResult full = fit_order(data, Order(0, 1), settings);
    MESSAGE("Q0S1: quadrature ", ref, ", poles ", poles.run.log_z, " ± ", poles.run.log_z_error, ", full ", full.run.log_z,
            " ± ", full.run.log_z_error);
    CHECK(std::abs(poles.run.log_z - ref) <= 3.0 * poles.run.log_z_error);
    CHECK(full.run.log_z - ref <= 3.0 * full.run.log_z_error);
  }
}
