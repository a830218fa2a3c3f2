// SPDX-License-Identifier: MIT
#include "physics/material_spec.hpp"

#include "core/errors.hpp"
#include "physics/overloaded.hpp"
#include "physics/parameter_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <type_traits>
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

namespace {

/// The parameter `member` of the layer model M of layer k (a porous model inside a PorousLayer, or a
/// layer type itself).
template <class M>
std::function<double&(LayeredAbsorber&)> model_field(std::size_t k, double M::*member) {
  return [k, member](LayeredAbsorber& a) -> double& {
    if constexpr (std::is_same_v<M, MicroPerforatedPanel> || std::is_same_v<M, AirLayer>)
      return std::get<M>(a.layers[k]).*member;
    else
      return std::get<M>(std::get<PorousLayer>(a.layers[k]).model).*member;
  };
}

std::function<double&(LayeredAbsorber&)> porous_depth(std::size_t k) {
  return [k](LayeredAbsorber& a) -> double& { return std::get<PorousLayer>(a.layers[k]).thickness; };
}

/// Ratio limits: a fraction stays ≤ 1, a tortuosity ≥ 1.
SpecParameter spec_parameter(std::size_t k, const std::string& key, double value,
                             std::function<double&(LayeredAbsorber&)> in) {
  SpecParameter p{fmt::format("{}.{}", k + 1, key), value, 0.5, 2.0, std::move(in)};
  if (key == "phi" || key == "p") p.ratio_hi = std::min(2.0, 1.0 / value);
  if (key == "alpha_inf") p.ratio_lo = std::max(0.5, 1.0 / value);
  return p;
}

}  // namespace

std::vector<SpecParameter> spec_parameters(const LayeredAbsorber& absorber) {
  std::vector<SpecParameter> out;
  for (std::size_t k = 0; k < absorber.layers.size(); ++k) {
    const auto add = [&](const std::string& key, double value, std::function<double&(LayeredAbsorber&)> in) {
      out.push_back(spec_parameter(k, key, value, std::move(in)));
    };
    std::visit(Overloaded{[&](const PorousLayer& l) {
                            std::visit(Overloaded{[&](const DelanyBazley& m) {
                                                    add("sigma", m.flow_resistivity,
                                                        model_field<DelanyBazley>(k, &DelanyBazley::flow_resistivity));
                                                  },
                                                  [&](const Miki& m) {
                                                    add("sigma", m.flow_resistivity, model_field<Miki>(k, &Miki::flow_resistivity));
                                                  },
                                                  [&](const JohnsonChampouxAllard& m) {
                                                    using J = JohnsonChampouxAllard;
                                                    add("phi", m.porosity, model_field<J>(k, &J::porosity));
                                                    add("sigma", m.flow_resistivity, model_field<J>(k, &J::flow_resistivity));
                                                    add("alpha_inf", m.tortuosity, model_field<J>(k, &J::tortuosity));
                                                    add("lambda", m.viscous_length, model_field<J>(k, &J::viscous_length));
                                                    add("lambda_th", m.thermal_length, model_field<J>(k, &J::thermal_length));
                                                  },
                                                  [&](const Horoshenkov2019& m) {
                                                    using H = Horoshenkov2019;
                                                    add("phi", m.porosity, model_field<H>(k, &H::porosity));
                                                    add("pore", m.median_pore_size, model_field<H>(k, &H::median_pore_size));
                                                    add("sigma_s", m.pore_size_deviation,
                                                        model_field<H>(k, &H::pore_size_deviation));
                                                  }},
                                       l.model);
                            add("d", l.thickness, porous_depth(k));
                          },
                          [&](const AirLayer& l) { add("d", l.thickness, model_field<AirLayer>(k, &AirLayer::thickness)); },
                          [&](const MicroPerforatedPanel& l) {
                            using P = MicroPerforatedPanel;
                            add("hole", l.hole_diameter, model_field<P>(k, &P::hole_diameter));
                            add("t", l.thickness, model_field<P>(k, &P::thickness));
                            add("p", l.perforation, model_field<P>(k, &P::perforation));
                          }},
               absorber.layers[k]);
  }
  out.erase(std::remove_if(out.begin(), out.end(),
                           [](const SpecParameter& p) { return !(p.value > 0.0) || p.ratio_lo > 0.98 || p.ratio_hi < 1.02; }),
            out.end());
  return out;
}

}  // namespace admitgen
