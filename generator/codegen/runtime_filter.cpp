// SPDX-License-Identifier: MIT
#include "codegen/runtime_filter.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <type_traits>

namespace admitgen::codegen {
namespace {

/// Appends one term's row: entry j of `row` at the index the runtime reads it from.
template <typename T, std::size_t W>
void append_row(std::vector<T>& table, const std::array<T, W>& row) {
  table.insert(table.end(), row.begin(), row.end());
}

template <typename T>
T narrow(std::int32_t v) {
  ADMITGEN_ENSURE(v >= std::numeric_limits<T>::min() && v <= std::numeric_limits<T>::max(),
                  "table entry {} does not fit the format", v);
  return static_cast<T>(v);
}

void require(admitgen_rt_result r, const char* what) {
  if (r != ADMITGEN_RT_SUCCESS)
    throw InputError(fmt::format("the runtime refuses the emitted tables ({}): {}", what, admitgen_rt_result_description(r)));
}

/// The runtime's entry points of one format.
template <typename Sample>
struct Api;
#define ADMITGEN_RUNTIME_API(SAMPLE, FORMAT)                          \
  template <>                                                         \
  struct Api<SAMPLE> {                                                \
    static constexpr const char* name = #FORMAT;                      \
    static constexpr auto bytes = admitgen_rt_state_bytes_##FORMAT;   \
    static constexpr auto init = admitgen_rt_init_##FORMAT;           \
    static constexpr auto process = admitgen_rt_process_##FORMAT;     \
    static constexpr auto history = admitgen_rt_history_##FORMAT;     \
  };
ADMITGEN_RUNTIME_API(float, f32)
ADMITGEN_RUNTIME_API(std::int32_t, q31)
ADMITGEN_RUNTIME_API(std::int16_t, q15)
#undef ADMITGEN_RUNTIME_API

/// The f32 rows (ADMITGEN_RT_F32_*).
void fill_tables(const FloatCoefficients& c, std::vector<float>& fir, std::vector<float>& real, std::vector<float>& pair) {
  fir = c.fir;
  for (const auto& t : c.real) {
    std::array<float, ADMITGEN_RT_F32_REAL_WIDTH> row{};
    row[ADMITGEN_RT_F32_REAL_EPS] = t[0];
    row[ADMITGEN_RT_F32_REAL_C] = t[1];
    append_row(real, row);
  }
  for (const auto& t : c.pair) {
    std::array<float, ADMITGEN_RT_F32_PAIR_WIDTH> row{};
    row[ADMITGEN_RT_F32_PAIR_ER] = t[0];
    row[ADMITGEN_RT_F32_PAIR_PI] = t[1];
    row[ADMITGEN_RT_F32_PAIR_G] = t[2];
    row[ADMITGEN_RT_F32_PAIR_CR] = t[3];
    row[ADMITGEN_RT_F32_PAIR_CI] = t[4];
    append_row(pair, row);
  }
}

/// The q31 / q15 rows (ADMITGEN_RT_Q_*), int32 or int16 entries.
template <typename T>
void fill_tables(const FixedCoefficients& c, std::vector<T>& fir, std::vector<T>& real, std::vector<T>& pair) {
  for (const auto d : c.fir) fir.push_back(narrow<T>(d));
  for (const auto& t : c.real) {
    std::array<T, ADMITGEN_RT_Q_REAL_WIDTH> row{};
    row[ADMITGEN_RT_Q_REAL_EPS] = narrow<T>(t.eps);
    row[ADMITGEN_RT_Q_REAL_SHIFT] = narrow<T>(t.shift);
    row[ADMITGEN_RT_Q_REAL_C] = narrow<T>(t.c);
    append_row(real, row);
  }
  for (const auto& t : c.pair) {
    std::array<T, ADMITGEN_RT_Q_PAIR_WIDTH> row{};
    row[ADMITGEN_RT_Q_PAIR_ER] = narrow<T>(t.e_r);
    row[ADMITGEN_RT_Q_PAIR_PI] = narrow<T>(t.p_i);
    row[ADMITGEN_RT_Q_PAIR_G] = narrow<T>(t.g);
    row[ADMITGEN_RT_Q_PAIR_SHIFT] = narrow<T>(t.shift);
    row[ADMITGEN_RT_Q_PAIR_CR] = narrow<T>(t.c_r);
    row[ADMITGEN_RT_Q_PAIR_CI] = narrow<T>(t.c_i);
    append_row(pair, row);
  }
}

/// The format's own scalars: f32 the instantaneous gain, q31/q15 the output scaling.
void set_scalars(admitgen_rt_model_f32& m, const FloatCoefficients& c) { m.h0 = c.h0; }
template <typename Model>
void set_scalars(Model& m, const FixedCoefficients& c) {
  m.out_shift = c.out_shift;
  m.acc_shift = c.acc_shift;
}

/// The table pointers of the model struct: q15 with 32-bit coefficients uses fir32/real32/pair32.
template <typename Model, typename T>
void set_tables(Model& m, const std::vector<T>& fir, const std::vector<T>& real, const std::vector<T>& pair) {
  m.fir = fir.data();
  m.real = real.data();
  m.pair = pair.data();
}
void set_tables(admitgen_rt_model_q15& m, const std::vector<std::int32_t>& fir, const std::vector<std::int32_t>& real,
                const std::vector<std::int32_t>& pair) {
  m.fir = nullptr, m.real = nullptr, m.pair = nullptr;
  m.fir32 = fir.data();
  m.real32 = real.data();
  m.pair32 = pair.data();
}

bool wide_tables(const FloatCoefficients&) { return false; }
bool wide_tables(const FixedCoefficients& c) { return c.wide(); }

}  // namespace

template <typename Sample>
RuntimeModel<Sample>::RuntimeModel(const typename RuntimeTypes<Sample>::Coefficients& c, int fs_hz) {
  const bool wide = std::is_same_v<Sample, std::int16_t> && wide_tables(c);  // q31 rows are int32 anyway
  if (wide) {
    if constexpr (std::is_same_v<Sample, std::int16_t>) fill_tables(c, fir32_, real32_, pair32_);
  } else {
    fill_tables(c, fir_, real_, pair_);
  }
  model_.abi_version = ADMITGEN_RT_ABI_VERSION;
  model_.fs_hz = fs_hz;
  model_.method = ADMITGEN_RT_METHOD_MATCHED_EXP;
  model_.n_fir = static_cast<std::int32_t>(fir_.size());
  model_.n_real = static_cast<std::int32_t>(c.real.size());
  model_.n_pair = static_cast<std::int32_t>(c.pair.size());
  set_scalars(model_, c);
  if constexpr (std::is_same_v<Sample, std::int16_t>) {
    if (wide) {
      model_.n_fir = static_cast<std::int32_t>(fir32_.size());
      set_tables(model_, fir32_, real32_, pair32_);
      return;
    }
  }
  set_tables(model_, fir_, real_, pair_);
}
template class RuntimeModel<float>;
template class RuntimeModel<std::int32_t>;
template class RuntimeModel<std::int16_t>;

RuntimeStateMemory::RuntimeStateMemory(std::size_t bytes)
    : bytes_(bytes), raw_(new std::byte[bytes + ADMITGEN_RT_ALIGN]) {
  void* p = raw_.get();
  std::size_t space = bytes + ADMITGEN_RT_ALIGN;
  data_ = std::align(ADMITGEN_RT_ALIGN, bytes, p, space);
}

template <typename Sample>
struct RuntimeNode<Sample>::Impl {
  using A = Api<Sample>;
  Impl(const Coefficients& c, int fs_hz)
      : model(c, fs_hz), memory(std::max<std::size_t>(1, A::bytes(&model.model(), 1))) {
    require(A::init(&inst, &model.model(), fs_hz, 1, memory.data(), memory.bytes()), A::name);
  }
  RuntimeModel<Sample> model;
  RuntimeStateMemory memory;
  typename RuntimeTypes<Sample>::Instance inst{};
};

template <typename Sample>
RuntimeNode<Sample>::RuntimeNode(const Coefficients& c, int fs_hz) : impl_(std::make_unique<Impl>(c, fs_hz)) {}
template <typename Sample>
RuntimeNode<Sample>::~RuntimeNode() = default;

template <typename Sample>
void RuntimeNode<Sample>::process(const Sample* in, Sample* out, std::size_t n) {
  // The runtime takes int32 frame counts: long inputs go in blocks (the state carries over exactly).
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  for (std::size_t done = 0; done < n; done += kBlock) {
    const auto frames = static_cast<std::int32_t>(std::min(kBlock, n - done));
    require(Impl::A::process(&impl_->inst, in + done, out != nullptr ? out + done : nullptr, frames, 1), Impl::A::name);
  }
}

template <typename Sample>
std::vector<Sample> RuntimeNode<Sample>::process(const std::vector<Sample>& in) {
  std::vector<Sample> out(in.size());
  process(in.data(), out.data(), in.size());
  return out;
}

template <typename Sample>
void RuntimeNode<Sample>::run_zero_input(long n) {
  const std::vector<Sample> zeros(4096, Sample{0});
  for (long done = 0; done < n; done += static_cast<long>(zeros.size()))
    process(zeros.data(), nullptr, static_cast<std::size_t>(std::min<long>(n - done, static_cast<long>(zeros.size()))));
}

template <typename Sample>
Sample RuntimeNode<Sample>::history() const {
  Sample s{};
  require(Impl::A::history(&impl_->inst, &s), Impl::A::name);
  return s;
}

template <typename Sample>
Sample RuntimeNode<Sample>::commit(Sample u) {
  Sample y{};
  process(&u, &y, 1);  // admitgen_rt_commit_* is process of one frame
  return y;
}

template <typename Sample>
std::size_t RuntimeNode<Sample>::n_real() const {
  return static_cast<std::size_t>(impl_->model.model().n_real);
}
template <typename Sample>
std::size_t RuntimeNode<Sample>::n_pair() const {
  return static_cast<std::size_t>(impl_->model.model().n_pair);
}
// One node: the state arrays [term][node] hold term t at index t.
template <typename Sample>
typename RuntimeNode<Sample>::State& RuntimeNode<Sample>::x(std::size_t q) {
  ADMITGEN_ENSURE(q < n_real(), "real pole {} of {}", q, n_real());
  return impl_->inst.x[q];
}
template <typename Sample>
typename RuntimeNode<Sample>::State& RuntimeNode<Sample>::xi(std::size_t s) {
  ADMITGEN_ENSURE(s < n_pair(), "pair {} of {}", s, n_pair());
  return impl_->inst.xi[s];
}
template <typename Sample>
typename RuntimeNode<Sample>::State& RuntimeNode<Sample>::eta(std::size_t s) {
  ADMITGEN_ENSURE(s < n_pair(), "pair {} of {}", s, n_pair());
  return impl_->inst.eta[s];
}

template class RuntimeNode<float>;
template class RuntimeNode<std::int32_t>;
template class RuntimeNode<std::int16_t>;

std::vector<std::int32_t> run_runtime(const FixedCoefficients& c, int fs_hz, const std::vector<std::int32_t>& in) {
  if (c.format == Format::q31) return RuntimeNodeQ31(c, fs_hz).process(in);
  ADMITGEN_ENSURE(c.format == Format::q15, "run_runtime() is for q31/q15");
  std::vector<std::int16_t> in16;
  in16.reserve(in.size());
  for (const auto v : in) in16.push_back(narrow<std::int16_t>(v));
  const auto out16 = RuntimeNodeQ15(c, fs_hz).process(in16);
  return {out16.begin(), out16.end()};
}

}  // namespace admitgen::codegen
