// SPDX-License-Identifier: MIT
/// @file
/// The usual visitor helper for std::visit over the physics variants (materials, layers, effects):
/// std::visit(Overloaded{[](const A&) {…}, [](const B&) {…}}, v). A missing alternative does not compile.
#pragma once

namespace admitgen {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace admitgen
