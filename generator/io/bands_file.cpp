// SPDX-License-Identifier: MIT
#include "io/bands_file.hpp"

#include "core/version.hpp"
#include "io/record_fields.hpp"

#include <fmt/format.h>

namespace admitgen::io {
namespace {

constexpr const char* kMethod =
    "mean over 32 log-spaced frequencies per band; normal incidence 1-|R|^2, R=(1-G)/(1+G); random incidence: "
    "locally reacting, London/Kuttruff closed form";

/// What `emit --bands-json` writes.
struct BandsDocument {
  std::string schema = "admitgen.bands/1", version = kVersion, name, order, input_sha256, method = kMethod;
  std::vector<codegen::BandAbsorption> octave, third_octave;
};

/// A library's bands.json.
struct LibraryBandsDocument {
  std::string schema = "admitgen.library-bands/1", version = kVersion, library, method = kMethod;
  std::vector<MaterialBands> materials;
};

/// One row of bands.csv: the values of a band's field list, the booleans as 1 or 0.
class CsvRow {
 public:
  explicit CsvRow(std::string& out) : out_(&out) {}
  template <class M>
  void operator()(const char*, const M& m, unsigned = 0) {
    if constexpr (std::is_same_v<M, bool>)
      *out_ += m ? ",1" : ",0";
    else
      *out_ += fmt::format(",{}", m);
  }

 private:
  std::string* out_;
};

}  // namespace

// ---- the field lists of the band files (docs/formats.md, "Band absorption") ------------------------

template <class V>
void fields(V& v, codegen::BandAbsorption& b) {
  v("center_hz", b.center_hz);
  v("lo_hz", b.lo_hz);
  v("hi_hz", b.hi_hz);
  v("alpha_normal", b.alpha_normal);
  v("alpha_random", b.alpha_random);
  v("in_data", b.in_data);
}

template <class V>
void fields(V& v, BandsDocument& d) {
  v("schema", d.schema);
  v("version", d.version);
  v("name", d.name);
  v("order", d.order);
  v("input_sha256", d.input_sha256);
  v("method", d.method);
  v("octave", d.octave);
  v("third_octave", d.third_octave);
}

template <class V>
void fields(V& v, MaterialBands& m) {
  v("name", m.material);
  v("order", m.order);
  v("input_sha256", m.input_sha256);
  v.named(m.sets);
}

template <class V>
void fields(V& v, LibraryBandsDocument& d) {
  v("schema", d.schema);
  v("version", d.version);
  v("library", d.library);
  v("method", d.method);
  v("materials", d.materials);
}

// ---- writers --------------------------------------------------------------------------------------

std::string bands_text(const codegen::Emission& e) {
  BandsDocument d;
  d.name = e.settings.name;
  d.order = e.surface.order.name();
  d.input_sha256 = e.input_sha256;
  d.octave = e.octave;
  d.third_octave = e.third_octave;
  return write_record(d).dump(2) + "\n";
}

std::string library_bands_text(const std::string& library, const std::vector<MaterialBands>& materials) {
  LibraryBandsDocument d;
  d.library = library;
  d.materials = materials;
  return write_record(d).dump(2) + "\n";
}

std::string library_bands_csv(const std::vector<MaterialBands>& materials) {
  std::string out = "material,band_set";
  for (const auto& k : record_keys<codegen::BandAbsorption>()) out += "," + k.key;
  out += "\n";
  for (const auto& m : materials)
    for (const auto& [name, bands] : m.sets)
      for (auto band : bands) {
        out += m.material + "," + name;
        CsvRow row(out);
        fields(row, band);
        out += "\n";
      }
  return out;
}

std::vector<KeyNode> bands_keys() { return record_keys<BandsDocument>(); }

std::vector<KeyNode> library_bands_keys() { return record_keys<LibraryBandsDocument>(); }

}  // namespace admitgen::io
