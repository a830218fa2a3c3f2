/// @file
/// Fuzz target: the reader of an emitted header's admitgen:model block (io/model_block.hpp,
/// read_emitted_header) as `admitgen check` uses it, then the check subject built from it and the
/// header integrity check (C tables against the block). Bad input must end in InputError.
#include "checks/check_suite.hpp"
#include "io/check_input.hpp"
#include "core/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace admitgen;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto subject = io::header_subject(text, "fuzz.h");
    (void)checks::check_causality(subject);
    (void)checks::check_header_integrity(subject);
  } catch (const InputError&) {
  }
  return 0;
}
