/* SPDX-License-Identifier: MIT */
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
    case ADMITGEN_RT_NULL_POINTER: return "a required pointer is NULL (or the instance was never initialised)";
    case ADMITGEN_RT_TOO_LARGE: return "more than ADMITGEN_RT_MAX_NODES nodes, or a size that does not fit in size_t";
    case ADMITGEN_RT_BAD_STRIDE: return "stride is smaller than the node count";
    case ADMITGEN_RT_BAD_MODEL: return "model counts, shifts or mantissas are out of range";
    default: return "unknown result code";
  }
}

static size_t admitgen_rt__round_up(size_t n) {
  return (n + (size_t)ADMITGEN_RT_ALIGN - 1u) & ~((size_t)ADMITGEN_RT_ALIGN - 1u);
}

/* total += n rounded up to ADMITGEN_RT_ALIGN, n = count * rows * size; 0 if any step overflows size_t. */
static int admitgen_rt__add_array(size_t *total, size_t count, size_t rows, size_t size) {
  size_t n;
  if (count != 0u && rows > SIZE_MAX / count) return 0;
  n = count * rows;
  if (n != 0u && size > SIZE_MAX / n) return 0;
  n *= size;
  if (n > SIZE_MAX - ((size_t)ADMITGEN_RT_ALIGN - 1u)) return 0;
  n = admitgen_rt__round_up(n);
  if (n > SIZE_MAX - *total) return 0;
  *total += n;
  return 1;
}

static int admitgen_rt__valid_count(int32_t n) { return n >= 0 && n <= ADMITGEN_RT_MAX_TERMS; }

admitgen_rt_result admitgen_rt__size(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                                     size_t acc_size, size_t *bytes) {
  size_t rows, total = 0u;
  *bytes = 0u;
  if (!admitgen_rt__valid_count(n_fir) || !admitgen_rt__valid_count(n_real) || !admitgen_rt__valid_count(n_pair))
    return ADMITGEN_RT_BAD_MODEL;
  if (n_nodes <= 0) return ADMITGEN_RT_INVALID_ARGS;
  if (n_nodes > ADMITGEN_RT_MAX_NODES) return ADMITGEN_RT_TOO_LARGE;
  rows = (size_t)n_nodes;
  if (!admitgen_rt__add_array(&total, (size_t)n_real, rows, state_size) ||
      !admitgen_rt__add_array(&total, (size_t)n_pair, rows, state_size) ||
      !admitgen_rt__add_array(&total, (size_t)n_pair, rows, state_size) ||
      !admitgen_rt__add_array(&total, (size_t)(n_fir > 1 ? n_fir - 1 : 0), rows, state_size) ||
      !admitgen_rt__add_array(&total, 1u, rows, state_size) || !admitgen_rt__add_array(&total, 1u, rows, acc_size))
    return ADMITGEN_RT_TOO_LARGE; /* 32-bit size_t: 64 pairs x 2^24 nodes x 4 bytes is 2^32 per array */
  *bytes = total;
  return ADMITGEN_RT_SUCCESS;
}

size_t admitgen_rt__bytes(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                          size_t acc_size) {
  size_t bytes;
  return admitgen_rt__size(n_fir, n_real, n_pair, n_nodes, state_size, acc_size, &bytes) == ADMITGEN_RT_SUCCESS ? bytes : 0u;
}

admitgen_rt_result admitgen_rt__check_tables(int32_t n_fir, int32_t n_real, int32_t n_pair, const void *fir,
                                             const void *real, const void *pair) {
  if (!admitgen_rt__valid_count(n_fir) || !admitgen_rt__valid_count(n_real) || !admitgen_rt__valid_count(n_pair))
    return ADMITGEN_RT_BAD_MODEL;
  if ((n_fir > 0 && fir == NULL) || (n_real > 0 && real == NULL) || (n_pair > 0 && pair == NULL))
    return ADMITGEN_RT_NULL_POINTER;
  return ADMITGEN_RT_SUCCESS;
}

admitgen_rt_result admitgen_rt__check_call(const void *model, int32_t n_nodes, const void *in, int32_t n_frames,
                                           int32_t stride) {
  if (model == NULL) return ADMITGEN_RT_NULL_POINTER;
  if (n_frames < 0) return ADMITGEN_RT_INVALID_ARGS;
  if (n_frames == 0) return ADMITGEN_RT_SUCCESS;
  if (in == NULL) return ADMITGEN_RT_NULL_POINTER;
  if (stride < n_nodes) return ADMITGEN_RT_BAD_STRIDE;
  /* the last index (n_frames - 1) * stride + n_nodes - 1 must fit in size_t (32-bit targets; below 2^63 for
   * int32_t operands, so a 64-bit size_t needs no test and the call no division) */
#if SIZE_MAX < 0xFFFFFFFFFFFFFFFFu
  if ((size_t)(n_frames - 1) > (SIZE_MAX - (size_t)n_nodes) / (size_t)stride) return ADMITGEN_RT_TOO_LARGE;
#endif
  return ADMITGEN_RT_SUCCESS;
}

void admitgen_rt__zero(void *p, size_t n) {
  unsigned char *b = (unsigned char *)p;
  size_t i;
  for (i = 0; i < n; ++i) b[i] = 0u;
}

admitgen_rt_result admitgen_rt__bind(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                     int32_t n_pair, int32_t n_nodes, size_t state_size, size_t acc_size, void *mem,
                                     size_t bytes, admitgen_rt__layout *out) {
  size_t need;
  unsigned char *p = (unsigned char *)mem;
  const size_t rows = (size_t)n_nodes;
  admitgen_rt_result r;
  if (abi != (uint32_t)ADMITGEN_RT_ABI_VERSION) return ADMITGEN_RT_ABI_MISMATCH;
  if (model_fs != fs_hz) return ADMITGEN_RT_RATE_MISMATCH;
  r = admitgen_rt__size(n_fir, n_real, n_pair, n_nodes, state_size, acc_size, &need);
  if (r != ADMITGEN_RT_SUCCESS) return r;
  if (mem == NULL) return ADMITGEN_RT_NULL_POINTER;
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
