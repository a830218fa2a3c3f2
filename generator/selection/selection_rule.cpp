// SPDX-License-Identifier: MIT
#include "selection/selection_rule.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <cmath>

namespace admitgen {

SelectionRule SelectionRule::parse(const std::string& text) {
  if (text == "best") return best();
  const std::string prefix = "cheapest:";
  if (text.rfind(prefix, 0) == 0) {
    const auto db = parse_double(text.substr(prefix.size()));
    if (db && std::isfinite(*db) && *db >= 0.0) return SelectionRule(true, *db);
  }
  throw InputError(fmt::format("{} '{}': expected 'best' or 'cheapest:DB' with a margin DB >= 0 in deciban "
                               "(e.g. cheapest:10)", setting("rule"), text));
}

std::size_t SelectionRule::select(const std::vector<double>& log_z, const std::vector<int>& buffers) const {
  ADMITGEN_ENSURE(!log_z.empty() && log_z.size() == buffers.size(), "{} vs {}", log_z.size(), buffers.size());
  std::size_t top = 0;
  for (std::size_t i = 1; i < log_z.size(); ++i)
    if (log_z[i] > log_z[top]) top = i;
  if (!cheapest_) return top;
  std::size_t pick = top;
  for (std::size_t i = 0; i < log_z.size(); ++i) {
    if (deciban(log_z[i], log_z[top]) < -margin_db_) continue;
    if (buffers[i] < buffers[pick] || (buffers[i] == buffers[pick] && log_z[i] > log_z[pick])) pick = i;
  }
  return pick;
}

std::string SelectionRule::describe() const {
  return cheapest_ ? fmt::format("cheapest (fewest Q+2S buffers) within {} dB of the best evidence", margin_db_)
                   : "best evidence";
}

std::string SelectionRule::spelling() const { return cheapest_ ? fmt::format("cheapest:{}", margin_db_) : "best"; }

}  // namespace admitgen
