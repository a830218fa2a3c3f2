/// @file
/// Fuzz target: the CSV reader (data/csv_reader.hpp) under every reading option. The first 4 bytes of
/// the input choose the options (delimiter, decimal separator, skipped rows, quantity, columns,
/// magnitude scale, phase unit, time convention, ρc, band, plausibility as warnings); the rest is the
/// file. Bad input must end in InputError (exit 2 in the CLI); any other exception or a sanitizer
/// report is a finding.
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "fuzz_input_file.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace {

using namespace admitgen;

/// Column specs by position and by header name, each role combination the reader accepts.
constexpr std::array<const char*, 8> kColumnSpecs = {
    "f,re,im", "f,mag,phase", "f,_,re,im", "f,re,im,_", "f,mag,phase,_,_",
    "f=frequency,re=real,im=imag", "f=Frequency [Hz],mag=|Z|,phase=Phase [deg]", "f=f,re=Re(Z/Z0),im=Im(Z/Z0)"};

template <typename T, std::size_t N>
std::optional<T> pick(std::uint8_t bits, const std::array<T, N>& values) {  // value 0 = not given
  const std::size_t i = bits % (N + 1);
  return i == 0 ? std::nullopt : std::optional<T>(values[i - 1]);
}

ReadOptions options_from(const std::uint8_t* o) {
  ReadOptions r;
  r.format.delimiter = pick<char, 4>(o[0] & 7, {',', ';', '\t', ' '});
  r.format.decimal = pick<char, 2>((o[0] >> 3) & 3, {'.', ','});
  r.format.skip_rows = (o[0] >> 5) & 3;
  r.quantity = pick<Quantity, 3>(o[1] & 3, {Quantity::admittance, Quantity::impedance, Quantity::reflection});
  if (const auto spec = pick<const char*, kColumnSpecs.size()>((o[1] >> 2) & 15, kColumnSpecs)) r.columns = ColumnMap::parse(*spec);
  r.magnitude = pick<MagnitudeScale, 2>(o[2] & 3, {MagnitudeScale::linear, MagnitudeScale::decibel});
  r.phase = pick<PhaseUnit, 2>((o[2] >> 2) & 3, {PhaseUnit::degrees, PhaseUnit::radians});
  r.time_convention = pick<TimeConvention, 2>((o[2] >> 4) & 3, {TimeConvention::plus_jwt, TimeConvention::minus_jwt});
  if (o[2] & 64) r.rho_c = 413.3;
  if (o[3] & 1) r.band = Band{100.0 * (1 + ((o[3] >> 1) & 7)), 1000.0 * (1 + ((o[3] >> 4) & 7))};
  r.plausibility_errors = (o[2] & 128) == 0;
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  const ReadOptions options = options_from(data);
  const std::string& path = fuzz::write_input_file(data + 4, size - 4, ".csv");
  try {
    (void)read_measurement(path, options);
  } catch (const InputError&) {
  }
  return 0;
}
