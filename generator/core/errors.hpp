// SPDX-License-Identifier: MIT
/// @file
/// Error types. Bad input and impossible options are exceptions that carry what a user needs to fix
/// them (file, line, offending value); only `main` turns them into exit code 2 (1 for UnsafeModelError). Broken internal
/// invariants go through ADMITGEN_ENSURE and are programming errors.
#pragma once

#include <fmt/format.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace admitgen {

/// Names a setting inside a message: `key` is the settings field as a library caller writes it
/// ("rho_c", "tube.diameter_m", "fs_hz"; a condition such as "enforce_passivity = false" for a boolean
/// turned off). The message keeps a mark around the key, so that a front end can respell it (the CLI writes
/// its flag, "--rho-c": cli::flag_for) and everyone else reads the bare key (plain_settings()). Library
/// text never spells a command-line flag itself (docs/architecture.md, "Settings named in library text").
std::string setting(const std::string& key);
/// A setting with the value to give it ("quantity", "impedance"): plain "quantity=impedance", the CLI
/// "--quantity impedance".
std::string setting(const std::string& key, const std::string& value);

/// `text` with each setting it names (setting()) spelled by `spell_key(key)`; a setting given with a value
/// reads `spell_key(key) + value_separator + value`.
std::string spell_settings(const std::string& text, const std::function<std::string(const std::string& key)>& spell_key,
                           const std::string& value_separator);
/// `text` with each setting by its bare key ("rho_c", "quantity=impedance"): what files and library
/// callers read (InputError::what(), the warnings written to fit.json and diagnosis.json).
std::string plain_settings(const std::string& text);
/// The keys of the settings `text` names, in order of appearance (repeats kept).
std::vector<std::string> named_settings(const std::string& text);

/// Bad user input: a malformed data file, an impossible option, an unwritable path. Exit code 2.
/// The message may name settings (setting()); what() spells each by its key.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  explicit InputError(const char* message) : InputError(std::string(message)) {}

  /// The keys of the settings the message names, in order of appearance (repeats kept).
  std::vector<std::string> settings() const { return named_settings(marked_); }
  /// The message with each named setting spelled by `spell(key)` (a value follows after a space).
  std::string spelled(const std::function<std::string(const std::string& key)>& spell) const {
    return spell_settings(marked_, spell, " ");
  }
  /// The message with its marks, for an error that quotes another one's (keeps its settings named).
  const std::string& marked() const { return marked_; }

 private:
  std::string marked_;
};

/// An InputError located in a file: message reads "FILE:LINE: what (value 'VALUE')".
class FileError : public InputError {
 public:
  FileError(const std::string& path, long line, const std::string& what, const std::string& value = {})
      : InputError(format(path, line, what, value)), path_(path), line_(line) {}
  const std::string& path() const { return path_; }
  long line() const { return line_; }

 private:
  static std::string format(const std::string& path, long line, const std::string& what,
                            const std::string& value) {
    std::string where = line > 0 ? fmt::format("{}:{}", path, line) : path;
    return value.empty() ? fmt::format("{}: {}", where, what)
                         : fmt::format("{}: {} (value '{}')", where, what, value);
  }
  std::string path_;
  long line_;
};

/// A model that was read but is unsafe (a pole outside the open left half-plane): the readers of `emit`,
/// `synth` and `diagnose` refuse it with the failing check named, as `admitgen check` reports it. Exit
/// code 1 ("a check failed"), unlike the other InputErrors (2, "unusable input").
class UnsafeModelError : public InputError {
 public:
  using InputError::InputError;
};

/// A violated internal invariant: a bug in admitgen, never the user's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace admitgen

/// Checks an invariant in every build type (unlike assert) and throws InternalError with context.
#define ADMITGEN_ENSURE(expr, ...)                                                              \
  do {                                                                                          \
    if (!(expr))                                                                                \
      throw ::admitgen::InternalError(fmt::format("{}:{}: invariant '{}' failed: {}", __FILE__, \
                                                  __LINE__, #expr, fmt::format(__VA_ARGS__)));  \
  } while (false)
