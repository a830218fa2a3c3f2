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

/// Names the setting at fault inside an error message: `key` is the settings field as a library caller
/// writes it ("rho_c", "tube.diameter_m", "fs_hz"; "settings struct field" spelled as in the struct).
/// The message keeps a mark around the key, so that InputError can tell which settings it names and a
/// front end can respell them (the CLI writes its flag, "--rho-c"); what() shows the bare key.
std::string setting(const std::string& key);

/// Bad user input: a malformed data file, an impossible option, an unwritable path. Exit code 2.
/// The message may name settings (setting()); what() spells each by its key.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  explicit InputError(const char* message) : InputError(std::string(message)) {}

  /// The keys of the settings the message names, in order of appearance (repeats kept).
  std::vector<std::string> settings() const;
  /// The message with each named setting spelled by `spell(key)`.
  std::string spelled(const std::function<std::string(const std::string& key)>& spell) const;
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
