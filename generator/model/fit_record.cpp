// SPDX-License-Identifier: MIT
#include "model/fit_record.hpp"

#include "model/order.hpp"

namespace admitgen {

const FitModel* FitRecord::model(const std::string& order) const {
  const Order wanted = Order::parse(order.empty() ? selected_order : order);
  for (const auto& m : models)
    if (Order::parse(m.order) == wanted) return &m;
  return nullptr;
}

}  // namespace admitgen
