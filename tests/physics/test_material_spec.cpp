// SPDX-License-Identifier: MIT
// The material SPEC grammar (physics/material_spec.hpp): what parses to what, and what is rejected.
#include "core/errors.hpp"
#include "model/multipole.hpp"
#include "physics/material_spec.hpp"
#include "physics_test_support.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <string>

namespace admitgen {
namespace {

TEST_CASE("material SPEC: layers, units and order front to back") {
  const Material m = parse_material_spec(
      "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=5cm) + air(d=20mm)");
  const auto& layers = std::get<LayeredAbsorber>(m).layers;
  REQUIRE(layers.size() == 2);
  const auto& porous = std::get<PorousLayer>(layers[0]);
  const auto& jca = std::get<JohnsonChampouxAllard>(porous.model);
  CHECK(jca.viscous_length == doctest::Approx(56e-6).epsilon(1e-15));
  CHECK(jca.thermal_length == doctest::Approx(110e-6).epsilon(1e-15));
  CHECK(porous.thickness == doctest::Approx(0.05).epsilon(1e-15));
  CHECK(std::get<AirLayer>(layers[1]).thickness == doctest::Approx(0.02).epsilon(1e-15));
  CHECK(std::get<LayeredAbsorber>(m).depth() == doctest::Approx(0.07).epsilon(1e-15));

  const Material mpp = parse_material_spec("mpp(hole=0.4mm,t=0.4mm,p=1%)+air(d=0.05)");
  const auto& panel = std::get<MicroPerforatedPanel>(std::get<LayeredAbsorber>(mpp).layers[0]);
  CHECK(panel.perforation == doctest::Approx(0.01).epsilon(1e-15));
  CHECK(panel.hole_diameter == doctest::Approx(0.4e-3).epsilon(1e-15));

  // The same absorber written two ways gives the same admittance, bit for bit.
  const Eigen::ArrayXd f = Eigen::ArrayXd::LinSpaced(5, 100.0, 2000.0);
  const Air air = Air::at_celsius(20.0);
  CHECK((surface_admittance(parse_material_spec("miki(sigma=10000,d=50mm)"), air, f) ==
         surface_admittance(parse_material_spec("  miki( d = 0.05 , sigma = 1e4 )  "), air, f))
            .all());
}

TEST_CASE("material SPEC: multipole by parameters evaluates model/multipole with the contract packing") {
  const Material m = parse_material_spec(
      "multipole(G_inf=0.469, A_1=-26062, lambda_1=55250, B_1=2019, C_1=-263, alpha_1=1530, beta_1=10063)");
  const auto& surface = std::get<MultipoleSurface>(m);
  CHECK(surface.order == Order(1, 1));
  Eigen::VectorXd theta(7);
  theta << 0.469, -26062, 55250, 2019, -263, 1530, 10063;
  CHECK(surface.theta.isApprox(theta, 0.0));
  // docs/materials.md §3.1 (derived): Y(1 kHz) = 0.1248 − 0.4122i in e^{−iωt}, i.e. 0.1248 + 0.4122j here.
  const std::complex<double> y = surface_admittance(m, Air::at_celsius(20.0), test::at(1000.0))[0];
  CHECK(std::abs(y - std::complex<double>(0.1248, 0.4122)) <= 1e-4);
}

TEST_CASE("material SPEC: fit(file=...) takes the selected order's posterior mean from a fit.json") {
  const std::string path = test::sample("synthetic/glass_beads_40mm_fit/fit.json");
  const Material material = parse_material_spec("fit(file=" + path + ")");
  const auto& surface = std::get<MultipoleSurface>(material);
  const nlohmann::json doc = nlohmann::json::parse(test::read_text(path));
  CHECK(surface.order == Order::parse(doc["selected"]["order"].get<std::string>()));
  const auto names = surface.order.parameter_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    CHECK(doc["parameters"][i]["name"] == names[i]);
    CHECK(surface.theta[static_cast<Eigen::Index>(i)] == doc["parameters"][i]["mean"].get<double>());
  }
  const Material q0s2 = parse_material_spec("fit(file=" + path + ", order=Q0S2, estimate=max_likelihood)");
  CHECK(std::get<MultipoleSurface>(q0s2).order == Order(0, 2));
}

TEST_CASE("material SPEC: errors name the problem") {
  test::check_input_errors([](const std::string& spec) { return parse_material_spec(spec); }, {
      {"mikki(sigma=1,d=1)", "unknown layer 'mikki'"},
      {"miki(sigma=10000)", "missing parameter 'd'"},
      {"miki(sigma=10000,d=5cm,phi=0.9)", "unknown parameter 'phi'"},
      {"miki(sigma=-1,d=5cm)", "'sigma' must be positive"},
      {"miki(sigma=1e4,d=5%)", "unit '%' does not fit"},
      {"jca(phi=1.2,sigma=1,alpha_inf=1,lambda=1um,lambda_th=1um,d=1)", "'phi' must be in (0, 1]"},
      {"mpp(hole=0.4mm,t=0.4mm,p=100%)", "'p' must be in (0, 1)"},
      {"miki(sigma=1e4,d=5cm) air(d=1cm)", "expected '+'"},
      {"miki(sigma=1e4,d=5cm", "no ')'"},
      {"", "expected a layer name"},
      {"miki(sigma=1e4,d=5cm) + multipole(G_inf=1)", "cannot be combined"},
      {"multipole(G_inf=0.5, A_1=1)", "needs parameter 'lambda_1'"},
      {"multipole(G_inf=0.5, A_1=1, lambda_1=-5)", "lambda_1 = -5 1/s is not positive"},
      {"multipole(G_inf=0.5, A_2=1, lambda_2=5)", "'A_2' is not a parameter of Q0S0"},
      {"fit(file=/nonexistent/fit.json)", "cannot open fit.json"},
      {"fit(file=" + test::sample("synthetic/glass_beads_40mm_fit/fit.json") + ", order=Q3S3)", "order Q3S3 was not fitted"},
  });
}

}  // namespace
}  // namespace admitgen
