/*
 * admitgen_rt_internal.h - private helpers shared by the runtime kernels (not installed).
 * Fixed-point primitives and the per-term node loops used by both the q31 and the q15 kernels.
 */
#ifndef ADMITGEN_RT_INTERNAL_H
#define ADMITGEN_RT_INTERNAL_H

#include "admitgen_rt.h"

/* Pointers into one block of caller memory, each array aligned to ADMITGEN_RT_ALIGN. */
typedef struct admitgen_rt__layout {
  void *x, *xi, *eta, *hist, *u, *acc;
} admitgen_rt__layout;

/* Bytes for the given shape (states of state_size bytes, accumulators of acc_size bytes); 0 if invalid. */
size_t admitgen_rt__bytes(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                          size_t acc_size);
/* Checks the common init arguments, carves mem into the arrays and zeroes it. */
admitgen_rt_result admitgen_rt__bind(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                     int32_t n_pair, int32_t n_nodes, size_t state_size, size_t acc_size, void *mem,
                                     size_t bytes, admitgen_rt__layout *out);
/* Checks that a replacement model is compatible with a bound instance. */
admitgen_rt_result admitgen_rt__check_swap(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                           int32_t n_pair, int32_t old_fir, int32_t old_real, int32_t old_pair);
/* Zeroes n bytes (no libc dependency in the runtime). */
void admitgen_rt__zero(void *p, size_t n);

/* floor(v / 2^s), 1 <= s <= 62, without relying on the implementation-defined >> of negative values. */
static inline int64_t admitgen_rt__floor_shr(int64_t v, int32_t s) {
  return v >= 0 ? (v >> s) : ~((~v) >> s);
}

/* old + prod / 2^s rounded toward zero of the result (magnitude truncation), saturated to int32.
 * Magnitude truncation makes every state contract strictly under zero input (|x'| <= r |x|, r < 1 in
 * exact arithmetic, rounding only shrinks it further), so a state reaches exactly 0: no limit cycle. */
static inline int32_t admitgen_rt__add_tz(int32_t old, int64_t prod, int32_t s) {
  int64_t v = (int64_t)old + admitgen_rt__floor_shr(prod, s);
  const uint64_t mask = ((uint64_t)1 << s) - 1u;
  if (v < 0 && ((uint64_t)prod & mask) != 0u) v += 1;
  if (v > INT32_MAX) v = INT32_MAX;
  if (v < INT32_MIN) v = INT32_MIN;
  return (int32_t)v;
}

/* One real term over all nodes: x += eps (u - x) (Q1.31 states, eps = m * 2^-s), acc += c x. */
static inline void admitgen_rt__real_q(int32_t *ADMITGEN_RT_RESTRICT x, const int32_t *ADMITGEN_RT_RESTRICT u,
                                       int64_t *ADMITGEN_RT_RESTRICT acc, int32_t n, int32_t m, int32_t s, int32_t c) {
  int32_t i;
  for (i = 0; i < n; ++i) {
    const int32_t v = admitgen_rt__add_tz(x[i], (int64_t)m * ((int64_t)u[i] - (int64_t)x[i]), s);
    x[i] = v;
    acc[i] += (int64_t)c * v;
  }
}

/* One pair over all nodes (coupled form, delta coefficients er, pi, g at scale 2^-s). */
static inline void admitgen_rt__pair_q(int32_t *ADMITGEN_RT_RESTRICT xi, int32_t *ADMITGEN_RT_RESTRICT eta,
                                       const int32_t *ADMITGEN_RT_RESTRICT u, int64_t *ADMITGEN_RT_RESTRICT acc,
                                       int32_t n, int32_t er, int32_t pi, int32_t g, int32_t s, int32_t cr,
                                       int32_t ci) {
  int32_t i;
  for (i = 0; i < n; ++i) {
    const int32_t a = xi[i], b = eta[i];
    const int32_t a1 = admitgen_rt__add_tz(a, (int64_t)er * a - (int64_t)pi * b + (int64_t)g * u[i], s);
    const int32_t b1 = admitgen_rt__add_tz(b, (int64_t)er * b + (int64_t)pi * a, s);
    xi[i] = a1;
    eta[i] = b1;
    acc[i] += (int64_t)cr * a1 + (int64_t)ci * b1;
  }
}

/* acc = d0 u + sum_k d_k u^{n-k} over the ring of past inputs (rows of n nodes). */
static inline void admitgen_rt__fir_q(int64_t *ADMITGEN_RT_RESTRICT acc, const int32_t *ADMITGEN_RT_RESTRICT u,
                                      const int32_t *ADMITGEN_RT_RESTRICT hist, int32_t n, int32_t head,
                                      int32_t rows, int32_t k, int32_t d) {
  /* k == 0: the current input initialises the accumulator; k >= 1: row of u^{n-k}. */
  int32_t i;
  if (k == 0) {
    for (i = 0; i < n; ++i) acc[i] = (int64_t)d * u[i];
  } else {
    const int32_t r = head + k - 1 < rows ? head + k - 1 : head + k - 1 - rows; /* no division */
    const int32_t *row = hist + (size_t)r * (size_t)n;
    for (i = 0; i < n; ++i) acc[i] += (int64_t)d * row[i];
  }
}

/* Pushes the current input into the ring (it becomes u^{n-1}); returns the new head. */
static inline int32_t admitgen_rt__push_q(int32_t *hist, const int32_t *u, int32_t n, int32_t head, int32_t rows) {
  int32_t i;
  int32_t *row;
  head = head == 0 ? rows - 1 : head - 1;
  row = hist + (size_t)head * (size_t)n;
  for (i = 0; i < n; ++i) row[i] = u[i];
  return head;
}

/* Rounds the accumulator to the output (round half up) and saturates to [lo, hi]. */
static inline int32_t admitgen_rt__output(int64_t acc, int32_t shift, int32_t lo, int32_t hi) {
  const int64_t v = admitgen_rt__floor_shr(acc + ((int64_t)1 << (shift - 1)), shift);
  return v > hi ? hi : (v < lo ? lo : (int32_t)v);
}

#endif /* ADMITGEN_RT_INTERNAL_H */
