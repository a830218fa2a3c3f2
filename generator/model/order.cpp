// SPDX-License-Identifier: MIT
#include "model/order.hpp"

#include "core/errors.hpp"

#include <cctype>

namespace admitgen {

Order::Order(int q, int s) : q_(q), s_(s) {
  if (q < 0 || s < 0 || q > kMaxPoles || s > kMaxPoles)
    throw InputError(fmt::format("model order Q{}S{}: Q and S must lie in [0, {}]", q, s, kMaxPoles));
}

Order Order::parse(const std::string& text) {
  std::string t;
  for (char ch : text) t += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  int q = -1, s = -1;
  char tail = 0;
  if (std::sscanf(t.c_str(), "Q%dS%d%c", &q, &s, &tail) != 2 || t.find_first_of("+-") != std::string::npos)
    throw InputError(fmt::format("model order '{}': expected the form QxSy, e.g. Q1S1", text));
  return Order(q, s);
}

std::string Order::name() const { return fmt::format("Q{}S{}", q_, s_); }

std::vector<std::string> Order::parameter_names() const {
  std::vector<std::string> names{"G_inf"};
  for (int i = 1; i <= q_; ++i) {
    names.push_back(fmt::format("A_{}", i));
    names.push_back(fmt::format("lambda_{}", i));
  }
  for (int i = 1; i <= s_; ++i)
    for (const char* base : {"B", "C", "alpha", "beta"}) names.push_back(fmt::format("{}_{}", base, i));
  return names;
}

std::vector<Family> Order::families() const {
  std::vector<Family> f{Family::g_inf};
  for (int i = 0; i < q_; ++i) f.insert(f.end(), {Family::a, Family::lambda});
  for (int i = 0; i < s_; ++i) f.insert(f.end(), {Family::b, Family::c, Family::alpha, Family::beta});
  return f;
}

std::vector<Order> order_grid(int qmax, int smax) {
  if (qmax < 0 || smax < 0)
    throw InputError(fmt::format("{} {} / {} {}: both must be 0 or more", setting("qmax"), qmax, setting("smax"), smax));
  std::vector<Order> grid;
  for (int q = 0; q <= qmax; ++q)
    for (int s = 0; s <= smax; ++s) grid.emplace_back(q, s);
  return grid;
}

}  // namespace admitgen
