// SPDX-License-Identifier: MIT
/// @file
/// The runtime's model structs built from emitted coefficients, and one-node instances that run the
/// runtime's own kernels (runtime/include/admitgen_rt.h). Wherever the generator needs the arithmetic it
/// ships — golden vectors, limit cycles, the simulated tube — it runs these, never a copy of the recursion.
/// The table layout is the runtime's ADMITGEN_RT_*_WIDTH / index macros; this is its only writer here.
#pragma once

#include "admitgen_rt.h"
#include "codegen/coefficients.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace admitgen::codegen {

/// The runtime's types of one format, by sample type: float (f32), int32_t (q31), int16_t (q15).
template <typename Sample>
struct RuntimeTypes;
template <>
struct RuntimeTypes<float> {
  using Model = admitgen_rt_model_f32;
  using Instance = admitgen_rt_f32;
  using Coefficients = FloatCoefficients;
  using State = float;
};
template <>
struct RuntimeTypes<std::int32_t> {
  using Model = admitgen_rt_model_q31;
  using Instance = admitgen_rt_q31;
  using Coefficients = FixedCoefficients;
  using State = std::int32_t;  ///< Q1.31
};
template <>
struct RuntimeTypes<std::int16_t> {
  using Model = admitgen_rt_model_q15;
  using Instance = admitgen_rt_q15;
  using Coefficients = FixedCoefficients;
  using State = std::int32_t;  ///< Q1.31 (wider than the data)
};

/// The tables of `c` in the runtime's layout (f32: ADMITGEN_RT_F32_*, q31/q15: ADMITGEN_RT_Q_* rows) and the
/// runtime's model struct over them, valid while this lives (not copyable: the struct points into the
/// tables). Throws InternalError if an entry does not fit the format's table type.
template <typename Sample>
class RuntimeModel {
 public:
  using Model = typename RuntimeTypes<Sample>::Model;
  RuntimeModel(const typename RuntimeTypes<Sample>::Coefficients& c, int fs_hz);
  RuntimeModel(const RuntimeModel&) = delete;
  RuntimeModel& operator=(const RuntimeModel&) = delete;
  const Model& model() const { return model_; }
  const std::vector<Sample>& fir() const { return fir_; }
  const std::vector<Sample>& real() const { return real_; }  ///< one row per real pole
  const std::vector<Sample>& pair() const { return pair_; }  ///< one row per pair

 private:
  std::vector<Sample> fir_, real_, pair_;
  std::vector<std::int32_t> fir32_, real32_, pair32_;  ///< q15 with 32-bit coefficients (FixedCoefficients::wide)
  Model model_{};
};
using RuntimeModelF32 = RuntimeModel<float>;
using RuntimeModelQ31 = RuntimeModel<std::int32_t>;
using RuntimeModelQ15 = RuntimeModel<std::int16_t>;

/// Caller-owned, ADMITGEN_RT_ALIGN-aligned state memory for one runtime instance.
class RuntimeStateMemory {
 public:
  explicit RuntimeStateMemory(std::size_t bytes);
  void* data() const { return data_; }
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_;
  std::unique_ptr<std::byte[]> raw_;
  void* data_ = nullptr;
};

/// One node of the runtime (n_nodes = 1) running `c`'s tables at fs_hz with the runtime's kernels, from zero
/// state. Sample: float (f32), int32_t (q31: Q1.31) or int16_t (q15: Q1.15). States are in the runtime's
/// units (f32: values; fixed point: Q1.31 integers) and may be set before a run (e.g. full scale).
/// Throws InputError, naming the runtime's reason, if the runtime refuses the tables.
template <typename Sample>
class RuntimeNode {
 public:
  using Coefficients = typename RuntimeTypes<Sample>::Coefficients;
  using State = typename RuntimeTypes<Sample>::State;
  RuntimeNode(const Coefficients& c, int fs_hz);
  ~RuntimeNode();
  RuntimeNode(const RuntimeNode&) = delete;
  RuntimeNode& operator=(const RuntimeNode&) = delete;

  /// admitgen_rt_process_*: in.size() frames; out may be nullptr (state only).
  void process(const Sample* in, Sample* out, std::size_t n);
  std::vector<Sample> process(const std::vector<Sample>& in);
  /// n frames of zero input, outputs discarded.
  void run_zero_input(long n);
  /// admitgen_rt_history_*: the output the next frame gives for u = 0 (state untouched).
  Sample history() const;
  /// admitgen_rt_commit_*: one frame u; returns its output.
  Sample commit(Sample u);

  std::size_t n_real() const;
  std::size_t n_pair() const;
  State& x(std::size_t q);    ///< real pole q
  State& xi(std::size_t s);   ///< pair s, in-phase
  State& eta(std::size_t s);  ///< pair s, quadrature

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
using RuntimeNodeF32 = RuntimeNode<float>;
using RuntimeNodeQ31 = RuntimeNode<std::int32_t>;
using RuntimeNodeQ15 = RuntimeNode<std::int16_t>;

/// The runtime's output for input `in` from zero state, for q31 (Q1.31 values) or q15 (Q1.15 values, which
/// must fit int16), both held in int32: the bit-exact shipped arithmetic (golden vectors).
std::vector<std::int32_t> run_runtime(const FixedCoefficients& c, int fs_hz, const std::vector<std::int32_t>& in);

}  // namespace admitgen::codegen
