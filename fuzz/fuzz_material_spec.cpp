/// @file
/// Fuzz target: the material SPEC parser (physics/material_spec.hpp), then the parsed material's
/// admittance at three frequencies. Bad input must end in InputError.
#include "core/errors.hpp"
#include "io/fit_file.hpp"
#include "physics/air.hpp"
#include "physics/material_spec.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace admitgen;
  const std::string spec(reinterpret_cast<const char*>(data), size);
  try {
    const Material material = parse_material_spec(spec, io::read_fit_file);
    Eigen::ArrayXd f(3);
    f << 100.0, 1000.0, 4000.0;
    (void)surface_admittance(material, Air::at_celsius(20.0), f);
  } catch (const InputError&) {
  }
  return 0;
}
