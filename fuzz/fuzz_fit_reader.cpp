/// @file
/// Fuzz target: the fit.json reader (output/fit_reader.hpp) and what `emit`, `check` and `diagnose`
/// take from the document: the check subject (checks/check_suite.hpp) and the multipole of each
/// estimate (physics/multipole_surface.hpp). Bad input must end in InputError.
#include "checks/check_suite.hpp"
#include "core/errors.hpp"
#include "fuzz_input_file.hpp"
#include "output/fit_reader.hpp"
#include "physics/multipole_surface.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace admitgen;
  const std::string& path = fuzz::write_input_file(data, size, ".json");
  try {
    const auto fit = read_fit_file(path);
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
    (void)checks::load_subject(path);
  } catch (const InputError&) {
  }
  return 0;
}
