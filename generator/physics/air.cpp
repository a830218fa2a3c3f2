// SPDX-License-Identifier: MIT
#include "physics/air.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace admitgen {

Air Air::at_celsius(double temperature_c) {
  if (!(temperature_c > -100.0 && temperature_c < 200.0))
    throw InputError(fmt::format("air temperature {} °C is outside -100..200 °C", temperature_c));
  const double kelvin = 273.15 + temperature_c;
  return Air{temperature_c,
             101325.0 / (287.05 * kelvin),
             20.047 * std::sqrt(kelvin),
             1.458e-6 * kelvin * std::sqrt(kelvin) / (kelvin + 110.4),
             0.71,
             1.4,
             101325.0};
}

}  // namespace admitgen
