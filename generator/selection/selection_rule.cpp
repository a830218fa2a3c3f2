// SPDX-License-Identifier: MIT
#include "selection/selection_rule.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <cmath>

namespace admitgen {

SelectionRule SelectionRule::parse(const std::string& text) {
  if (text == "best") return best();
  for (const auto& [prefix, kind] : {std::pair{std::string("cheapest:"), Kind::cheapest},
                                     std::pair{std::string("simplest:"), Kind::simplest}})
    if (text.rfind(prefix, 0) == 0) {
      const auto db = parse_double(text.substr(prefix.size()));
      if (db && std::isfinite(*db) && *db >= 0.0) return SelectionRule(kind, *db);
    }
  throw InputError(fmt::format("{} '{}': expected 'best', 'cheapest:DB' or 'simplest:DB' with a margin DB >= 0 in "
                               "deciban (e.g. simplest:10)", setting("rule"), text));
}

std::size_t SelectionRule::select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                                  const std::vector<int>& buffers) const {
  ADMITGEN_ENSURE(!log_z.empty() && log_z.size() == buffers.size() && log_z.size() == log_z_error.size(),
                  "{} vs {} vs {}", log_z.size(), log_z_error.size(), buffers.size());
  std::size_t top = 0;
  for (std::size_t i = 1; i < log_z.size(); ++i)
    if (log_z[i] > log_z[top]) top = i;
  if (kind_ == Kind::best) return top;
  std::size_t pick = top;
  for (std::size_t i = 0; i < log_z.size(); ++i) {
    // Below the best by more than the margin, plus, for simplest, two errors of the difference (deciban).
    const double allowed_db =
        margin_db_ + (kind_ == Kind::simplest ? kSimplestErrors * deciban_error(log_z_error[i], log_z_error[top]) : 0.0);
    if (deciban(log_z[i], log_z[top]) < -allowed_db) continue;
    if (buffers[i] < buffers[pick] || (buffers[i] == buffers[pick] && log_z[i] > log_z[pick])) pick = i;
  }
  return pick;
}

std::string SelectionRule::describe() const {
  switch (kind_) {
    case Kind::cheapest:
      return fmt::format("cheapest (fewest Q+2S buffers) within {} dB of the best evidence", margin_db_);
    case Kind::simplest:
      return fmt::format("simplest (fewest Q+2S buffers) not below the best evidence by more than {} dB plus {} "
                         "errors of the difference", margin_db_, kSimplestErrors);
    case Kind::best:
      break;
  }
  return "best evidence";
}

std::string SelectionRule::spelling() const {
  switch (kind_) {
    case Kind::cheapest: return fmt::format("cheapest:{}", margin_db_);
    case Kind::simplest: return fmt::format("simplest:{}", margin_db_);
    case Kind::best: break;
  }
  return "best";
}

}  // namespace admitgen
