// SPDX-License-Identifier: MIT
#include "core/errors.hpp"

namespace admitgen {
namespace {

// ASCII record/group/unit separators: never part of a message's own text.
constexpr char kOpen = '\x1e';
constexpr char kValue = '\x1d';
constexpr char kClose = '\x1f';

/// Calls `text(piece)` for the plain pieces and `key(name, value)` for each marked setting (value empty
/// when none was given), in order.
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
    const std::string inside = marked.substr(open + 1, close - open - 1);
    const std::size_t split = inside.find(kValue);
    if (split == std::string::npos)
      key(inside, std::string());
    else
      key(inside.substr(0, split), inside.substr(split + 1));
    pos = close + 1;
  }
}

}  // namespace

std::string setting(const std::string& key) { return kOpen + key + kClose; }

std::string setting(const std::string& key, const std::string& value) {
  return kOpen + key + kValue + value + kClose;
}

std::string spell_settings(const std::string& text, const std::function<std::string(const std::string&)>& spell_key,
                           const std::string& value_separator) {
  std::string out;
  walk(
      text, [&](const std::string& t) { out += t; },
      [&](const std::string& k, const std::string& v) {
        out += spell_key(k);
        if (!v.empty()) out += value_separator + v;
      });
  return out;
}

std::string plain_settings(const std::string& text) {
  return spell_settings(text, [](const std::string& key) { return key; }, "=");
}

std::vector<std::string> named_settings(const std::string& text) {
  std::vector<std::string> keys;
  walk(text, [](const std::string&) {}, [&](const std::string& k, const std::string&) { keys.push_back(k); });
  return keys;
}

InputError::InputError(const std::string& message) : std::runtime_error(plain_settings(message)), marked_(message) {}

}  // namespace admitgen
