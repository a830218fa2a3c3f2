/// @file
/// Fuzz target: the priors JSON reader (io/priors_file.hpp) and its
/// validation. Bad input must end in InputError.
#include "core/errors.hpp"
#include "fuzz_input_file.hpp"
#include "io/priors_file.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace admitgen;
  const std::string& path = fuzz::write_input_file(data, size, ".json");
  try {
    const auto ranges = io::read_priors_file(path);
    ranges.validate(path);
    (void)ranges.named();
  } catch (const InputError&) {
  }
  return 0;
}
