// SPDX-License-Identifier: MIT
#include "cli/library_manifest.hpp"

#include "cli/emit_command.hpp"
#include "cli/fit_command.hpp"
#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "core/sha256.hpp"
#include "library/slurm.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace admitgen::cli {
namespace {
namespace fs = std::filesystem;

/// Options of `fit` that a unit's run does not depend on (only the merge uses them): changing them
/// re-runs no unit.
const std::set<std::string> kMergeOnlyFitKeys{"qmax",        "smax",       "select",     "missed-mode-retries",
                                               "grid-growth", "target-alpha", "target-rms", "max-buffers"};
/// Keys of a material that are not options of fit or emit.
const std::set<std::string> kMaterialKeys{"name", "data"};
/// Options of fit and emit that a manifest may not set, and why.
const std::map<std::string, std::string> kRefusedKeys{
    {"threads", "the thread count is a property of the run: `admitgen library run DIR --threads N`"},
    {"name", "a material's C prefix is LIBRARY_MATERIAL (the library's name and the material's)"},
    {"out", "outputs go to the library's folder"}};

/// One manifest entry: a key, its value as command-line arguments, and where it is.
struct Entry {
  std::string key;
  std::vector<std::string> args;  ///< the value(s): one per repeated option; empty for a flag
  bool flag = false;
  std::string shown;              ///< the value as written, for messages
  long line = 0;
};

long line_of(const toml::node& n) { return static_cast<long>(n.source().begin.line); }

bool c_identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

class ManifestReader {
 public:
  explicit ManifestReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(long line, const std::string& what, const std::string& value = {}) const {
    throw FileError(path_, line, what, value);
  }

  /// A scalar or an array of scalars as argument strings.
  Entry entry(const std::string& key, const toml::node& node) const {
    Entry e{key, {}, false, "", line_of(node)};
    const auto scalar = [&](const toml::node& n) -> std::string {
      if (auto v = n.value<std::string>(); v && n.is_string()) return *v;
      if (n.is_integer()) return std::to_string(*n.value<std::int64_t>());
      if (n.is_floating_point()) return fmt::format("{}", *n.value<double>());
      fail(line_of(n), fmt::format("'{}' must be a string, a number, true or an array of them", key),
           toml_text(n));
    };
    if (node.is_boolean()) {
      e.flag = true;
      e.shown = *node.value<bool>() ? "true" : "false";
      if (!*node.value<bool>()) e.args.push_back("false");  // marks "flag off": no argument
      return e;
    }
    if (const toml::array* a = node.as_array()) {
      for (const auto& n : *a) e.args.push_back(scalar(n));
      e.shown = toml_text(node);
      if (e.args.empty()) fail(e.line, fmt::format("'{}' is an empty array", key), e.shown);
      return e;
    }
    e.args.push_back(scalar(node));
    e.shown = e.args.back();
    return e;
  }

  static std::string toml_text(const toml::node& n) {
    std::ostringstream s;
    n.visit([&](const auto& v) { s << v; });
    return s.str();
  }

  std::vector<Entry> entries(const toml::table& table, bool material) const {
    std::vector<Entry> out;
    for (const auto& [k, v] : table) {
      const std::string key(k.str());
      if (material && kMaterialKeys.count(key)) continue;
      out.push_back(entry(key, v));
    }
    return out;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The command-line arguments of `entries` (flags as "--key", values as "--key VALUE" per value).
std::vector<std::string> arguments(const std::vector<Entry>& entries) {
  std::vector<std::string> args;
  for (const auto& e : entries) {
    if (e.flag) {
      if (e.args.empty()) args.push_back("--" + e.key);
      continue;
    }
    for (const auto& a : e.args) {
      args.push_back("--" + e.key);
      args.push_back(a);
    }
  }
  return args;
}

/// Parses `args` into a fresh option set; CLI11 wants them last-first.
template <class Bind>
void parse(Bind bind, std::vector<std::string> args, bool all_required) {
  CLI::App app;
  bind(app);
  if (!all_required)
    for (CLI::Option* o : app.get_options()) o->required(false);
  std::reverse(args.begin(), args.end());
  app.parse(args);
}

}  // namespace

library::Library read_manifest(const std::string& path) {
  const ManifestReader reader(path);
  const std::string text = read_bounded(path, kMaxDocumentBytes, "library manifest");
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    reader.fail(static_cast<long>(e.source().begin.line), fmt::format("not TOML: {}", e.description()));
  }
  const fs::path folder = fs::path(path).parent_path();
  library::Library lib;
  lib.manifest = path;
  lib.name = fs::path(path).stem().string();
  for (auto& c : lib.name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  for (const auto& [k, v] : doc) {
    const std::string key(k.str());
    if (key == "name") {
      if (!v.is_string() || !c_identifier(*v.value<std::string>()))
        reader.fail(line_of(v), "the library's name must be a C identifier", ManifestReader::toml_text(v));
      lib.name = *v.value<std::string>();
    } else if (key != "defaults" && key != "material") {
      reader.fail(line_of(v), fmt::format("unknown top-level key '{}' (expected name, [defaults], [[material]])", key));
    }
  }
  std::vector<Entry> defaults;
  if (const toml::node* d = doc.get("defaults")) {
    if (!d->is_table()) reader.fail(line_of(*d), "[defaults] must be a table");
    defaults = reader.entries(*d->as_table(), false);
  }
  const toml::node* list = doc.get("material");
  if (!list || !list->is_array_of_tables() || list->as_array()->empty())
    reader.fail(list ? line_of(*list) : 0, "the manifest declares no [[material]]");

  // Which command each option belongs to (fit: reading options and fit settings; emit: header settings).
  ReadOptions probe_read;
  FitSettings probe_fit;
  codegen::EmitSettings probe_emit;
  CLI::App fit_app, emit_app;
  add_fit_options(fit_app, probe_read, probe_fit);
  add_emit_options(emit_app, probe_emit);
  const auto owner = [&](const Entry& e) -> int {  // 0 fit, 1 emit
    if (kRefusedKeys.count(e.key))
      reader.fail(e.line, fmt::format("'{}' cannot be set in a manifest: {}", e.key, kRefusedKeys.at(e.key)), e.shown);
    if (fit_app.get_option_no_throw("--" + e.key)) return 0;
    if (emit_app.get_option_no_throw("--" + e.key)) return 1;
    reader.fail(e.line, fmt::format("unknown key '{}': not an option of admitgen fit or admitgen emit "
                                    "(docs/library.md, \"Manifest\")", e.key), e.shown);
  };

  std::set<std::string> names;
  for (const auto& node : *list->as_array()) {
    const toml::table& t = *node.as_table();
    const long line = line_of(node);
    library::Material m;
    m.line = line;
    const toml::node* name = t.get("name");
    if (!name || !name->is_string()) reader.fail(line, "a [[material]] needs name = \"...\"");
    m.name = *name->value<std::string>();
    if (m.name.empty() || !std::all_of(m.name.begin(), m.name.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        }))
      reader.fail(line_of(*name), "a material's name may hold only letters, digits and _", m.name);
    if (!names.insert(m.name).second) reader.fail(line_of(*name), "a second material of this name", m.name);
    const toml::node* data = t.get("data");
    if (!data || !data->is_string()) reader.fail(line, fmt::format("material {} needs data = \"FILE\"", m.name));
    m.data_as_written = *data->value<std::string>();
    m.data = (folder / m.data_as_written).string();
    if (!fs::is_regular_file(m.data))
      reader.fail(line_of(*data), fmt::format("material {}: no such data file ({})", m.name, m.data), m.data_as_written);

    // The material's entries override the defaults, key by key.
    std::map<std::string, Entry> merged;
    for (const auto& e : defaults) merged[e.key] = e;
    for (const auto& e : reader.entries(t, true)) merged[e.key] = e;
    std::vector<Entry> fit_entries, emit_entries;
    std::string priors_as_written;
    for (auto& [key, e] : merged) {
      if (owner(e) == 0) {
        if (key == "priors") {
          priors_as_written = e.args.at(0);
          e.args.at(0) = (folder / priors_as_written).string();
        }
        fit_entries.push_back(e);
      } else {
        emit_entries.push_back(e);
      }
    }
    // Each entry alone first, so an error names its line; then all together.
    const auto check = [&](const Entry& e, bool is_fit) {
      ReadOptions r;
      FitSettings f;
      codegen::EmitSettings es;
      try {
        if (is_fit)
          parse([&](CLI::App& app) { add_fit_options(app, r, f); }, arguments({e}), false);
        else
          parse([&](CLI::App& app) { add_emit_options(app, es); }, arguments({e}), false);
      } catch (const CLI::ParseError& x) {
        reader.fail(e.line, fmt::format("material {}: {}: {}", m.name, e.key, x.what()), e.shown);
      } catch (const InputError& x) {
        reader.fail(e.line, fmt::format("material {}: {}: {}", m.name, e.key, x.what()), e.shown);
      }
    };
    for (const auto& e : fit_entries) check(e, true);
    for (const auto& e : emit_entries) check(e, false);
    try {
      parse([&](CLI::App& app) { add_fit_options(app, m.read, m.fit); }, arguments(fit_entries), true);
      parse([&](CLI::App& app) { add_emit_options(app, m.emit); }, arguments(emit_entries), true);
    } catch (const CLI::ParseError& x) {
      reader.fail(line, fmt::format("material {}: {}", m.name, x.what()));
    } catch (const InputError& x) {
      reader.fail(line, fmt::format("material {}: {}", m.name, x.what()));
    }
    if (!priors_as_written.empty()) m.fit.priors_origin = priors_as_written;
    m.emit.name = lib.name + "_" + m.name;

    // The unit's inputs: every fit option but the merge-only ones, in key order, and the prior file's bytes.
    for (const auto& e : fit_entries) {
      if (kMergeOnlyFitKeys.count(e.key)) continue;
      m.unit_inputs += e.key;
      for (const auto& a : e.args) m.unit_inputs += " " + a;
      if (e.key == "priors") m.unit_inputs += " sha256 " + sha256_file_hex(e.args.at(0));
      m.unit_inputs += "\n";
    }
    std::string fit_args, emit_args;
    for (auto e : fit_entries) {
      if (e.key == "priors") e.args = {priors_as_written};
      for (const auto& a : arguments({e})) fit_args += " " + library::shell_quote(a);
    }
    for (const auto& a : arguments(emit_entries)) emit_args += " " + library::shell_quote(a);
    m.fit_command = fmt::format("admitgen fit {}{} --out OUT", library::shell_quote(m.data_as_written), fit_args);
    m.emit_command = fmt::format("admitgen emit OUT/fit.json{} --name {} --out {}.h", emit_args, m.emit.name, m.name);
    lib.materials.push_back(std::move(m));
  }
  // One header holds every material: one format and one rate list.
  const auto& first = lib.materials.front().emit;
  for (const auto& m : lib.materials)
    if (m.emit.format != first.format || m.emit.fs_hz != first.fs_hz)
      reader.fail(m.line, fmt::format("material {}: every material of a library needs the same format and fs (the "
                                      "library header holds one table); set them in [defaults]", m.name));
  return lib;
}

}  // namespace admitgen::cli
