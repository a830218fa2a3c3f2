#include "data/read_options.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <sstream>

namespace admitgen {

Quantity parse_quantity(const std::string& text) {
  if (text == "admittance") return Quantity::admittance;
  if (text == "impedance") return Quantity::impedance;
  if (text == "reflection") return Quantity::reflection;
  throw InputError(fmt::format("--quantity '{}': expected admittance, impedance or reflection", text));
}

Band Band::parse(const std::string& text) {
  const auto colon = text.find(':');
  const auto bad = [&](const char* why) {
    return InputError(fmt::format("--band '{}': {} (expected FMIN:FMAX in Hz, e.g. 200:1600)", text, why));
  };
  if (colon == std::string::npos) throw bad("missing ':'");
  const auto lo = parse_double(text.substr(0, colon));
  const auto hi = parse_double(text.substr(colon + 1));
  if (!lo || !hi) throw bad("not two numbers");
  if (!(*lo > 0.0)) throw bad("FMIN must be positive");
  if (!(*hi > *lo)) throw bad("FMAX must exceed FMIN");
  return Band{*lo, *hi};
}

ColumnMap ColumnMap::parse(const std::string& spec) {
  ColumnMap map{-1, -1, -1, 0, spec};
  std::stringstream ss(spec);
  std::string item;
  int index = 0;
  const auto bad = [&](const std::string& why) {
    return InputError(fmt::format("--columns '{}': {} (expected names f, re, im and _ for skipped "
                                  "columns, e.g. f,_,_,_,_,re,im,_)", spec, why));
  };
  while (std::getline(ss, item, ',')) {
    int* slot = item == "f" ? &map.f : item == "re" ? &map.re : item == "im" ? &map.im : nullptr;
    if (slot == nullptr && item != "_") throw bad(fmt::format("unknown column name '{}'", item));
    if (slot != nullptr) {
      if (*slot >= 0) throw bad(fmt::format("column '{}' named twice", item));
      *slot = index;
    }
    ++index;
  }
  if (map.f < 0 || map.re < 0 || map.im < 0) throw bad("f, re and im must each be named once");
  map.count = index;
  return map;
}

}  // namespace admitgen
