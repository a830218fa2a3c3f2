// SPDX-License-Identifier: MIT
#include "physics/material_spec.hpp"

#include "core/errors.hpp"
#include "physics/parameter_list.hpp"

#include <fmt/format.h>

#include <cctype>
#include <map>
#include <string_view>

namespace admitgen {
namespace {

/// One `name(params)` item of the SPEC, as text.
struct Item {
  std::string name;
  std::string params;
};

std::vector<Item> split_items(const std::string& spec, const std::string& context) {
  std::vector<Item> items;
  std::size_t i = 0;
  const auto skip_blanks = [&] {
    while (i < spec.size() && (spec[i] == ' ' || spec[i] == '\t')) ++i;
  };
  const auto bad = [&](const std::string& what) { return InputError(fmt::format("{}: {}", context, what)); };
  while (true) {
    skip_blanks();
    const std::size_t start = i;
    while (i < spec.size() && (std::isalnum(static_cast<unsigned char>(spec[i])) || spec[i] == '_')) ++i;
    if (i == start) throw bad(fmt::format("expected a layer name at column {}", i + 1));
    Item item{spec.substr(start, i - start), {}};
    skip_blanks();
    if (i >= spec.size() || spec[i] != '(') throw bad(fmt::format("expected '(' after '{}'", item.name));
    const auto close = spec.find(')', i);
    if (close == std::string::npos) throw bad(fmt::format("no ')' closing '{}('", item.name));
    item.params = spec.substr(i + 1, close - i - 1);
    items.push_back(item);
    i = close + 1;
    skip_blanks();
    if (i == spec.size()) return items;
    if (spec[i] != '+') throw bad(fmt::format("expected '+' or the end after '{}(...)' at column {}", item.name, i + 1));
    ++i;
  }
}

double fraction(ParameterList& p, const std::string& key, bool one_allowed) {
  const double v = p.number(key, Dimension::ratio);
  if (!(v > 0.0 && (one_allowed ? v <= 1.0 : v < 1.0)))
    throw InputError(p.error(fmt::format("'{}' must be in (0, 1{} (got {})", key, one_allowed ? "]" : ")", v)));
  return v;
}

PorousLayer porous(PorousModel model, ParameterList& p) { return {std::move(model), p.positive("d", Dimension::length)}; }

Layer parse_layer(const Item& item, const std::string& context) {
  ParameterList p(fmt::format("{}, layer '{}'", context, item.name), item.params);
  const auto layer = [&]() -> Layer {
    if (item.name == "delany_bazley") return porous(DelanyBazley{p.positive("sigma")}, p);
    if (item.name == "miki") return porous(Miki{p.positive("sigma")}, p);
    if (item.name == "jca") {
      JohnsonChampouxAllard m{fraction(p, "phi", true), p.positive("sigma"), p.number("alpha_inf"),
                              p.positive("lambda", Dimension::length), p.positive("lambda_th", Dimension::length)};
      if (!(m.tortuosity >= 1.0)) throw InputError(p.error(fmt::format("'alpha_inf' must be >= 1 (got {})", m.tortuosity)));
      return porous(m, p);
    }
    if (item.name == "horoshenkov") {
      Horoshenkov2019 m{fraction(p, "phi", true), p.positive("pore", Dimension::length), p.number("sigma_s")};
      if (!(m.pore_size_deviation >= 0.0))
        throw InputError(p.error(fmt::format("'sigma_s' must be >= 0 (got {})", m.pore_size_deviation)));
      return porous(m, p);
    }
    if (item.name == "mpp")
      return MicroPerforatedPanel{p.positive("hole", Dimension::length), p.positive("t", Dimension::length),
                                  fraction(p, "p", false)};
    if (item.name == "air") return AirLayer{p.positive("d", Dimension::length)};
    throw InputError(fmt::format("{}: unknown layer '{}' (known: delany_bazley, miki, jca, horoshenkov, mpp, air; "
                                 "or a lone multipole(...) or fit(...))",
                                 context, item.name));
  }();
  p.finish();
  return layer;
}

MultipoleSurface parse_multipole(const Item& item, const std::string& context) {
  const std::string where = fmt::format("{}, multipole", context);
  ParameterList p(where, item.params);
  std::map<std::string, double> values;
  for (const auto& key : p.keys()) values[key] = p.number(key);
  return multipole_from_parameters(values, where);
}

MultipoleSurface parse_fit(const Item& item, const std::string& context, const FitReader& read_fit) {
  ParameterList p(fmt::format("{}, fit", context), item.params);
  const auto file = p.text("file");
  if (!file) throw InputError(p.error("missing parameter 'file' (the fit.json to read)"));
  const std::string order = p.text("order").value_or("");
  const std::string estimate = p.text("estimate").value_or("mean");
  p.finish();
  if (estimate != "mean" && estimate != "max_likelihood")
    throw InputError(p.error(fmt::format("estimate '{}': expected mean or max_likelihood", estimate)));
  if (!read_fit) throw InputError(p.error("fit(...) is not available here (no fit reader)"));
  return multipole_from_fit(read_fit(*file), order, estimate == "mean" ? Estimate::mean : Estimate::max_likelihood, *file);
}

}  // namespace

Material parse_material_spec(const std::string& spec, const FitReader& read_fit) {
  const std::string context = fmt::format("material '{}'", spec);
  for (const char c : spec)
    if (std::iscntrl(static_cast<unsigned char>(c)))
      throw InputError(fmt::format("{}: control characters are not allowed", context));
  const auto items = split_items(spec, context);
  const bool whole_surface = items.front().name == "multipole" || items.front().name == "fit";
  if (whole_surface) {
    if (items.size() != 1)
      throw InputError(fmt::format("{}: {}(...) is a whole surface and cannot be combined with layers", context,
                                   items.front().name));
    return items.front().name == "multipole" ? parse_multipole(items.front(), context) : parse_fit(items.front(), context, read_fit);
  }
  LayeredAbsorber absorber;
  for (const auto& item : items) {
    if (item.name == "multipole" || item.name == "fit")
      throw InputError(fmt::format("{}: {}(...) is a whole surface and cannot be combined with layers", context,
                                   item.name));
    absorber.layers.push_back(parse_layer(item, context));
  }
  return absorber;
}

}  // namespace admitgen
