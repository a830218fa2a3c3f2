// SPDX-License-Identifier: MIT
#include "selection/selection_rule.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace admitgen {

SelectionRule SelectionRule::parse(const std::string& text) {
  if (text == "best") return best();
  if (text == "target") return target();
  for (const auto& [prefix, kind] : {std::pair{std::string("cheapest:"), Kind::cheapest},
                                     std::pair{std::string("simplest:"), Kind::simplest}})
    if (text.rfind(prefix, 0) == 0) {
      const auto db = parse_double(text.substr(prefix.size()));
      if (db && std::isfinite(*db) && *db >= 0.0) return SelectionRule(kind, *db);
    }
  throw InputError(fmt::format("{} '{}': expected 'best', 'target', 'cheapest:DB' or 'simplest:DB' with a margin DB >= 0 in "
                               "deciban (e.g. simplest:10)", setting("rule"), text));
}

std::size_t SelectionRule::select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                                  const std::vector<int>& buffers) const {
  return select(log_z, log_z_error, buffers, std::vector<bool>(log_z.size(), false),
                std::vector<bool>(log_z.size(), true));
}

std::size_t SelectionRule::select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                                  const std::vector<int>& buffers, const std::vector<bool>& meets,
                                  const std::vector<bool>& usable) const {
  const std::size_t n = log_z.size();
  ADMITGEN_ENSURE(n > 0 && n == buffers.size() && n == log_z_error.size() && n == meets.size() && n == usable.size(),
                  "{} vs {} vs {} vs {} vs {}", n, log_z_error.size(), buffers.size(), meets.size(), usable.size());
  const auto first = static_cast<std::size_t>(std::find(usable.begin(), usable.end(), true) - usable.begin());
  ADMITGEN_ENSURE(first < n, "no usable order among {}", n);
  if (kind_ == Kind::target) {
    std::optional<std::size_t> cheapest;
    for (std::size_t i = 0; i < n; ++i)
      if (usable[i] && meets[i] &&
          (!cheapest || buffers[i] < buffers[*cheapest] || (buffers[i] == buffers[*cheapest] && log_z[i] > log_z[*cheapest])))
        cheapest = i;
    if (cheapest) return *cheapest;
    return simplest(kTargetFallbackMarginDb).select(log_z, log_z_error, buffers, meets, usable);
  }
  std::size_t top = first;
  for (std::size_t i = first + 1; i < n; ++i)
    if (usable[i] && log_z[i] > log_z[top]) top = i;
  if (kind_ == Kind::best) return top;
  std::size_t pick = top;
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable[i]) continue;
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
    case Kind::target:
      return fmt::format("cheapest (fewest Q+2S buffers) whose passive estimate meets the accuracy target; when none "
                         "does, simplest within {} dB", kTargetFallbackMarginDb);
    case Kind::best:
      break;
  }
  return "best evidence";
}

std::string SelectionRule::spelling() const {
  switch (kind_) {
    case Kind::cheapest: return fmt::format("cheapest:{}", margin_db_);
    case Kind::simplest: return fmt::format("simplest:{}", margin_db_);
    case Kind::target: return "target";
    case Kind::best: break;
  }
  return "best";
}

}  // namespace admitgen
