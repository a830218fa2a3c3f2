// SPDX-License-Identifier: MIT
#include "core/errors.hpp"

namespace admitgen {
namespace {

// ASCII record/unit separators: never part of a message's own text.
constexpr char kOpen = '\x1e';
constexpr char kClose = '\x1f';

/// Calls `text(piece)` for the plain pieces and `key(name)` for each marked setting, in order.
template <class Text, class Key>
void walk(const std::string& marked, Text text, Key key) {
  std::size_t pos = 0;
  while (pos < marked.size()) {
    const std::size_t open = marked.find(kOpen, pos);
    const std::size_t close = open == std::string::npos ? std::string::npos : marked.find(kClose, open);
    if (close == std::string::npos) {
      text(marked.substr(pos));
      return;
    }
    text(marked.substr(pos, open - pos));
    key(marked.substr(open + 1, close - open - 1));
    pos = close + 1;
  }
}

std::string spell(const std::string& marked, const std::function<std::string(const std::string&)>& spelling) {
  std::string out;
  walk(marked, [&](const std::string& t) { out += t; }, [&](const std::string& k) { out += spelling(k); });
  return out;
}

}  // namespace

std::string setting(const std::string& key) { return kOpen + key + kClose; }

InputError::InputError(const std::string& message)
    : std::runtime_error(spell(message, [](const std::string& key) { return key; })), marked_(message) {}

std::vector<std::string> InputError::settings() const {
  std::vector<std::string> keys;
  walk(marked_, [](const std::string&) {}, [&](const std::string& k) { keys.push_back(k); });
  return keys;
}

std::string InputError::spelled(const std::function<std::string(const std::string& key)>& spelling) const {
  return spell(marked_, spelling);
}

}  // namespace admitgen
