/*
 * admitgen_rt_common.c - result descriptions and the state-memory layout shared by every format.
 */
#include "admitgen_rt_internal.h"

const char *admitgen_rt_result_description(admitgen_rt_result result) {
  switch (result) {
    case ADMITGEN_RT_SUCCESS: return "success";
    case ADMITGEN_RT_INVALID_ARGS: return "invalid arguments";
    case ADMITGEN_RT_ABI_MISMATCH: return "model was generated for another runtime ABI version; regenerate it";
    case ADMITGEN_RT_RATE_MISMATCH: return "model coefficients are for another sample rate";
    case ADMITGEN_RT_SHAPE_MISMATCH: return "replacement model has a different number of terms";
    case ADMITGEN_RT_BUFFER_TOO_SMALL: return "state memory is smaller than *_state_bytes()";
    case ADMITGEN_RT_MISALIGNED: return "state memory is not aligned to ADMITGEN_RT_ALIGN";
    default: return "unknown result code";
  }
}

static size_t admitgen_rt__round_up(size_t n) {
  return (n + (size_t)ADMITGEN_RT_ALIGN - 1u) & ~((size_t)ADMITGEN_RT_ALIGN - 1u);
}

static int admitgen_rt__valid_shape(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes) {
  return n_fir >= 0 && n_real >= 0 && n_pair >= 0 && n_nodes > 0 && n_fir <= 64 && n_real <= 64 && n_pair <= 64 &&
         n_nodes <= (1 << 24);
}

size_t admitgen_rt__bytes(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                          size_t acc_size) {
  size_t rows;
  if (!admitgen_rt__valid_shape(n_fir, n_real, n_pair, n_nodes)) return 0;
  rows = (size_t)n_nodes;
  return admitgen_rt__round_up((size_t)n_real * rows * state_size) +
         2u * admitgen_rt__round_up((size_t)n_pair * rows * state_size) +
         admitgen_rt__round_up((size_t)(n_fir > 1 ? n_fir - 1 : 0) * rows * state_size) +
         admitgen_rt__round_up(rows * state_size) + admitgen_rt__round_up(rows * acc_size);
}

void admitgen_rt__zero(void *p, size_t n) {
  unsigned char *b = (unsigned char *)p;
  size_t i;
  for (i = 0; i < n; ++i) b[i] = 0u;
}

admitgen_rt_result admitgen_rt__bind(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                     int32_t n_pair, int32_t n_nodes, size_t state_size, size_t acc_size, void *mem,
                                     size_t bytes, admitgen_rt__layout *out) {
  const size_t need = admitgen_rt__bytes(n_fir, n_real, n_pair, n_nodes, state_size, acc_size);
  unsigned char *p = (unsigned char *)mem;
  const size_t rows = (size_t)n_nodes;
  if (abi != (uint32_t)ADMITGEN_RT_ABI_VERSION) return ADMITGEN_RT_ABI_MISMATCH;
  if (model_fs != fs_hz) return ADMITGEN_RT_RATE_MISMATCH;
  if (need == 0u || mem == NULL) return ADMITGEN_RT_INVALID_ARGS;
  if (bytes < need) return ADMITGEN_RT_BUFFER_TOO_SMALL;
  if (((uintptr_t)mem % (uintptr_t)ADMITGEN_RT_ALIGN) != 0u) return ADMITGEN_RT_MISALIGNED;
  admitgen_rt__zero(mem, need);
  out->x = p;
  p += admitgen_rt__round_up((size_t)n_real * rows * state_size);
  out->xi = p;
  p += admitgen_rt__round_up((size_t)n_pair * rows * state_size);
  out->eta = p;
  p += admitgen_rt__round_up((size_t)n_pair * rows * state_size);
  out->hist = p;
  p += admitgen_rt__round_up((size_t)(n_fir > 1 ? n_fir - 1 : 0) * rows * state_size);
  out->u = p;
  p += admitgen_rt__round_up(rows * state_size);
  out->acc = p;
  return ADMITGEN_RT_SUCCESS;
}

admitgen_rt_result admitgen_rt__check_swap(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                           int32_t n_pair, int32_t old_fir, int32_t old_real, int32_t old_pair) {
  if (abi != (uint32_t)ADMITGEN_RT_ABI_VERSION) return ADMITGEN_RT_ABI_MISMATCH;
  if (model_fs != fs_hz) return ADMITGEN_RT_RATE_MISMATCH;
  if (n_fir != old_fir || n_real != old_real || n_pair != old_pair) return ADMITGEN_RT_SHAPE_MISMATCH;
  return ADMITGEN_RT_SUCCESS;
}
