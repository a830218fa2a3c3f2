// SPDX-License-Identifier: MIT
// A probe for tools/check-library-flags (never compiled): a library message that names a command-line flag,
// which the check must reject at line 8, and lines it must accept (a flag in a comment, a CSS custom property,
// a digit separator, a decrement, a character literal holding a quote).
// "--comment" in a comment is not a literal: allowed.
#include <string>

std::string bad(double fs) { return "--fs " + std::to_string(fs) + " is not a sample rate"; }
std::string good(int n) {
  const char quote = '"';  // not the start of a literal
  --n;
  return std::string(1, quote) + std::to_string(100'000 - n) + R"CSS(:root{--ag-bg:#fff})CSS" + "a -- b";
}
