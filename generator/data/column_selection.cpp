// SPDX-License-Identifier: MIT
#include "data/column_selection.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <array>

namespace admitgen {
namespace {

const std::vector<std::string>& header_fields(const TextTable& t) {
  static const std::vector<std::string> none;
  return t.header ? t.header->fields : none;
}

std::string header_list(const TextTable& t) {
  std::string out;
  for (const auto& h : header_fields(t)) out += (out.empty() ? "'" : ", '") + h + "'";
  return out;
}

/// Unit of column i: from its header name ("[Hz]", "(deg)", "f_kHz"), else from the last unit row.
UnitKind unit_of(const TextTable& t, std::size_t i) {
  const auto& h = header_fields(t);
  if (i < h.size()) {
    if (const auto implied = classify_column(h[i]).implied_unit; implied != UnitKind::none) return implied;
    const auto from_name = unit_kind(normalise_unit(split_name_unit(h[i]).second, false));
    if (from_name && *from_name != UnitKind::none) return *from_name;
  }
  if (!t.unit_rows.empty() && i < t.unit_rows.back().fields.size())
    return unit_kind(normalise_unit(t.unit_rows.back().fields[i], true)).value_or(UnitKind::none);
  return UnitKind::none;
}

long header_line(const TextTable& t) { return t.header ? t.header->number : 0; }

ColumnSelection by_position(const ColumnMap& map) {
  ColumnSelection s;
  s.width = map.positions.size();
  s.polar = map.polar();
  for (std::size_t i = 0; i < map.positions.size(); ++i) {
    const Role r = map.positions[i];
    if (r == Role::f) s.f = i;
    if (r == Role::re || r == Role::mag) s.first = i;
    if (r == Role::im || r == Role::phase) s.second = i;
  }
  return s;
}

ColumnSelection by_name(const std::string& path, const TextTable& t, const ColumnMap& map) {
  if (!t.header)
    throw FileError(path, 0, fmt::format("{} '{}' names header columns, but the file has no header line of "
                                         "column names: give the columns by position (e.g. f,re,im)",
                                         setting("columns"), map.spec));
  const auto& h = t.header->fields;
  ColumnSelection s;
  s.width = h.size();
  s.polar = map.polar();
  for (const auto& [role, wanted] : map.names) {
    std::vector<std::size_t> hits;
    for (std::size_t i = 0; i < h.size(); ++i)
      if (normalise_name(h[i]) == normalise_name(wanted)) hits.push_back(i);
    if (hits.size() != 1)
      throw FileError(path, header_line(t),
                      fmt::format("{} header column matches '{}' (the header names {})",
                                  hits.empty() ? "no" : "more than one", wanted, header_list(t)));
    (role == Role::f ? s.f : role == Role::re || role == Role::mag ? s.first : s.second) = hits[0];
  }
  return s;
}

struct Found {
  std::array<std::optional<std::size_t>, 4> part;  ///< indexed by Part
  bool complete_cartesian() const { return part[0] && part[1]; }
  bool complete_polar() const { return part[2] && part[3]; }
};

/// Columns from the header's names alone; nullopt when the header names no complex quantity.
std::optional<ColumnSelection> from_header(const std::string& path, const TextTable& t, const ReadOptions& o) {
  const auto& h = header_fields(t);
  std::array<Found, 3> found;  // indexed by Quantity
  std::vector<std::size_t> freq;
  bool absorption = false;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const ColumnMeaning m = classify_column(h[i]);
    if (m.kind == ColumnMeaning::Kind::frequency) freq.push_back(i);
    if (m.kind == ColumnMeaning::Kind::absorption) absorption = true;
    auto& slot = found[static_cast<std::size_t>(m.quantity)].part[static_cast<std::size_t>(m.part)];
    if (m.kind == ColumnMeaning::Kind::value && !slot) slot = i;
  }
  std::optional<Quantity> chosen;
  for (Quantity q : {Quantity::admittance, Quantity::impedance, Quantity::reflection}) {
    const Found& f = found[static_cast<std::size_t>(q)];
    if ((!o.quantity || *o.quantity == q) && !chosen && (f.complete_cartesian() || f.complete_polar())) chosen = q;
  }
  if (!chosen) {
    if (absorption) throw FileError(path, header_line(t), absorption_only_message());
    if (o.quantity)
      for (Quantity q : {Quantity::admittance, Quantity::impedance, Quantity::reflection}) {
        const Found& f = found[static_cast<std::size_t>(q)];
        if (f.complete_cartesian() || f.complete_polar())
          throw FileError(path, header_line(t),
                          fmt::format("{} {} but the header names {} columns, not {} ones (the header names "
                                      "{}): drop {} or select the columns with {}",
                                      setting("quantity"), quantity_name(*o.quantity), quantity_name(q),
                                      quantity_name(*o.quantity), header_list(t), setting("quantity"),
                                      setting("columns")));
      }
    return std::nullopt;
  }
  if (freq.size() != 1)
    throw FileError(path, header_line(t),
                    fmt::format("{} frequency column in the header (names {}): select the columns with {}",
                                freq.empty() ? "no" : "more than one", header_list(t), setting("columns")));
  const Found& f = found[static_cast<std::size_t>(*chosen)];
  ColumnSelection s;
  s.width = h.size();
  s.f = freq[0];
  s.polar = !f.complete_cartesian();
  s.first = *f.part[s.polar ? 2 : 0];
  s.second = *f.part[s.polar ? 3 : 1];
  s.quantity = *chosen;
  s.quantity_from_header = !o.quantity;
  return s;
}

/// A header that names the selected value column as another quantity than the one in force: adopt
/// it when --quantity was not given, refuse when it was.
void reconcile_quantity(const std::string& path, const TextTable& t, const ReadOptions& o, ColumnSelection& s) {
  const auto& h = header_fields(t);
  if (s.first >= h.size()) return;
  const ColumnMeaning m = classify_column(h[s.first]);
  s.named_normalised = m.normalised || (s.second < h.size() && classify_column(h[s.second]).normalised);
  if (m.kind != ColumnMeaning::Kind::value || m.quantity == s.quantity) return;
  if (o.quantity)
    throw FileError(path, header_line(t),
                    fmt::format("{} {} but the header calls column {} '{}' (a {}): drop {} or correct it",
                                setting("quantity"), quantity_name(*o.quantity), s.first + 1, h[s.first],
                                quantity_name(m.quantity), setting("quantity")));
  s.quantity = m.quantity;
  s.quantity_from_header = true;
}

std::string describe(const TextTable& t, const ColumnSelection& s) {
  const auto& h = header_fields(t);
  const auto col = [&](const char* role, std::size_t i) {
    return i < h.size() ? fmt::format("{} = column {} '{}'", role, i + 1, h[i]) : fmt::format("{} = column {}", role, i + 1);
  };
  return fmt::format("{}, {}, {} ({}{})", col("f", s.f), col(s.polar ? "mag" : "re", s.first),
                     col(s.polar ? "phase" : "im", s.second), quantity_name(s.quantity),
                     s.quantity_from_header ? ", from the header" : "");
}

}  // namespace

std::string absorption_only_message() {
  return "the file holds frequency and absorption coefficient only: alpha = 1 - |R|^2 fixes the magnitude of the "
         "reflection factor R at each frequency but not its phase, and a complex admittance needs both (two numbers "
         "per frequency; e.g. y = 0.5 and y = 0.8 + 0.6j both give alpha = 8/9 but are different surfaces). "
         "Export the complex reflection factor, impedance or admittance (re/im or magnitude/phase, which the "
         "two-microphone method of ISO 10534-2 measures) and read it with " + setting("quantity") +
         "; alpha alone cannot be fitted";
}

ColumnSelection select_columns(const std::string& path, const TextTable& t, const ReadOptions& o) {
  const std::size_t width = t.rows.front().fields.size();
  std::optional<ColumnSelection> s;
  if (o.columns) s = o.columns->by_name() ? by_name(path, t, *o.columns) : by_position(*o.columns);
  if (!s && t.header) s = from_header(path, t, o);
  if (!s) {
    if (width == 2) {
      const bool unit_interval = std::all_of(t.rows.begin(), t.rows.end(), [&](const TextLine& l) {
        const auto v = l.fields.size() == 2 ? parse_field(t, l.fields[1]) : std::nullopt;
        return v && *v >= -0.05 && *v <= 1.05;
      });
      throw FileError(path, t.rows.front().number,
                      unit_interval ? absorption_only_message()
                                    : "the file has 2 columns, but a complex quantity needs a frequency and two more "
                                      "(re and im, or mag and phase)");
    }
    s = by_position(ColumnMap::parse("f,re,im"));
  }
  if (!s->quantity_from_header) s->quantity = o.quantity.value_or(Quantity::admittance);
  reconcile_quantity(path, t, o, *s);
  s->f_unit = unit_of(t, s->f);
  s->first_unit = unit_of(t, s->first);
  s->second_unit = unit_of(t, s->second);
  s->describe = describe(t, *s);
  return *s;
}

}  // namespace admitgen
