// SPDX-License-Identifier: MIT
#include "selection/order_marginals.hpp"

namespace admitgen {

OrderMarginals::OrderMarginals(const Measurement& data, DataCount count, double admittance_scale)
    : data_(data), count_(count), scale_(admittance_scale) {}

OrderMarginals::Entry& OrderMarginals::entry(const Order& order) {
  Entry& e = entries_[{order.q(), order.s()}];
  if (!e.evidence) e.evidence = std::make_unique<ResidueEvidence>(data_, order, count_, scale_);
  return e;
}

const ResidueEvidence& OrderMarginals::of(const Order& order) { return *entry(order).evidence; }

const MarginalPeak& OrderMarginals::peak(const ModelResult& model) {
  Entry& e = entry(model.order);
  const long calls = model.run.calls;
  if (e.calls != calls || e.live != model.live || e.log_z != model.run.log_z) {
    e.peak = marginal_peak(*e.evidence, model.order, model.run, model.live);
    e.calls = calls;
    e.live = model.live;
    e.log_z = model.run.log_z;
  }
  return e.peak;
}

}  // namespace admitgen
