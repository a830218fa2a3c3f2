/// @file
/// Fuzz target: the fit.json reader (io/fit_file.hpp) and what `emit`, `check` and `diagnose` take from
/// the record: the check subject (checks/check_suite.hpp, io/check_input.hpp) and the multipole of each
/// estimate (model/multipole_surface.hpp). Bad input must end in InputError.
#include "checks/check_suite.hpp"
#include "core/errors.hpp"
#include "fuzz_input_file.hpp"
#include "io/check_input.hpp"
#include "io/fit_file.hpp"
#include "model/multipole_surface.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace admitgen;
  const std::string& path = fuzz::write_input_file(data, size, ".json");
  try {
    const auto fit = io::read_fit_file(path);
    for (const Estimate e : {Estimate::passive, Estimate::mean, Estimate::max_likelihood}) {
      try {
        (void)checks::subject_from_fit(fit, path, "", e);
      } catch (const InputError&) {
      }
      try {
        (void)multipole_from_fit(fit, "Q1S1", e, path);
      } catch (const InputError&) {
      }
    }
    (void)io::load_check_subject(path);
  } catch (const InputError&) {
  }
  return 0;
}
