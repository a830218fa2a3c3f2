/* SPDX-License-Identifier: MIT */
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

/* Bytes for the given shape (states of state_size bytes, accumulators of acc_size bytes) in *bytes, or the
 * reason there is no such size (BAD_MODEL, INVALID_ARGS, TOO_LARGE; *bytes = 0). */
admitgen_rt_result admitgen_rt__size(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                                     size_t acc_size, size_t *bytes);
/* admitgen_rt__size, 0 if there is none. */
size_t admitgen_rt__bytes(int32_t n_fir, int32_t n_real, int32_t n_pair, int32_t n_nodes, size_t state_size,
                          size_t acc_size);
/* Checks the common init arguments, carves mem into the arrays and zeroes it. */
admitgen_rt_result admitgen_rt__bind(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                     int32_t n_pair, int32_t n_nodes, size_t state_size, size_t acc_size, void *mem,
                                     size_t bytes, admitgen_rt__layout *out);
/* Checks that a replacement model is compatible with a bound instance. */
admitgen_rt_result admitgen_rt__check_swap(uint32_t abi, int32_t model_fs, int32_t fs_hz, int32_t n_fir, int32_t n_real,
                                           int32_t n_pair, int32_t old_fir, int32_t old_real, int32_t old_pair);
/* A model's counts in 0..ADMITGEN_RT_MAX_TERMS (BAD_MODEL) and a table behind every non-zero count
 * (NULL_POINTER). */
admitgen_rt_result admitgen_rt__check_tables(int32_t n_fir, int32_t n_real, int32_t n_pair, const void *fir,
                                             const void *real, const void *pair);
/* The checks of a process/commit call before any memory is touched (docs/runtime.md, "Limits and misuse"):
 * model is the instance's model (NULL: never initialised), in the input (NULL allowed only for 0 frames). */
admitgen_rt_result admitgen_rt__check_call(const void *model, int32_t n_nodes, const void *in, int32_t n_frames,
                                           int32_t stride);
/* Zeroes n bytes (no libc dependency in the runtime). */
void admitgen_rt__zero(void *p, size_t n);

/* floor(v / 2^s), 1 <= s <= 62, without relying on the implementation-defined >> of negative values. */
static inline int64_t admitgen_rt__floor_shr(int64_t v, int32_t s) {
  return v >= 0 ? (v >> s) : ~((~v) >> s);
}

/* v saturated to int32. The range test is one 64-bit add and a test of the high word, so a 32-bit core keeps
 * the result in one register (and multiplies it with SMLAL). */
static inline int32_t admitgen_rt__sat32(int64_t v) {
  if (((uint64_t)v + 0x80000000u) >> 32 != 0u) return v < 0 ? INT32_MIN : INT32_MAX;
  return (int32_t)v;
}

/* old + prod / 2^s rounded toward zero of the result (magnitude truncation), saturated to int32.
 * Magnitude truncation makes every state contract strictly under zero input (|x'| <= r |x|, r < 1 in
 * exact arithmetic, rounding only shrinks it further), so a state reaches exactly 0: no limit cycle. */
static inline int32_t admitgen_rt__add_tz(int32_t old, int64_t prod, int32_t s) {
  int64_t v = (int64_t)old + admitgen_rt__floor_shr(prod, s);
  const uint64_t mask = ((uint64_t)1 << s) - 1u;
  if (v < 0 && ((uint64_t)prod & mask) != 0u) v += 1;
  return admitgen_rt__sat32(v);
}

/* Rounds the accumulator to the output (round half up) and saturates to [lo, hi]. */
static inline int32_t admitgen_rt__output(int64_t acc, int32_t shift, int32_t lo, int32_t hi) {
  const int32_t v = admitgen_rt__sat32(admitgen_rt__floor_shr(acc + ((int64_t)1 << (shift - 1)), shift));
  return v > hi ? hi : (v < lo ? lo : v);
}

/* Ring of past inputs, rows [rows][n_nodes]: u^{n-k} (k = 1..rows) is in row head + k - 1 (mod rows). */
static inline int32_t admitgen_rt__ring_row(int32_t head, int32_t k, int32_t rows) {
  const int32_t r = head + k - 1;
  return r < rows ? r : r - rows; /* no division: head < rows and k <= rows */
}
/* The ring position after advancing n frames (u^n becomes u^{n-1}: head moves back by one per frame). */
static inline int32_t admitgen_rt__ring_advance(int32_t head, int32_t frames, int32_t rows) {
  int32_t h = head - frames;
  while (h < 0) h += rows;
  return h;
}

/* Float state updates, in the one evaluation order every float path uses (docs/runtime.md, "f32 evaluation
 * order and bound"). Delta form: with zero input each new state is the old one plus one rounded increment
 * (full precision for slow poles, whose increments are small); the pair's xi adds g u to xi first, off the
 * recursion's dependency chain, so that every state reaches the next one through one multiply and two adds
 * (the mono path is bound by the latency of that chain: 8 instead of 9 cycles per sample on a Zen 5):
 *   x' = x + eps (u - x);  xi' = (xi + g u) + (e_r xi - p_i eta);  eta' = eta + (e_r eta + p_i xi). */
static inline float admitgen_rt__real_f32(float x, float u, float eps) { return x + eps * (u - x); }
static inline float admitgen_rt__xi_f32(float a, float e, float u, float er, float pi, float g) {
  return (a + g * u) + (er * a - pi * e);
}
static inline float admitgen_rt__eta_f32(float a, float e, float er, float pi) { return e + (er * e + pi * a); }

/* ------------------------------------------------------------------------------------------------ */
/* Kernel organisation (docs/runtime.md):
 *  - small-n path (n_nodes <= ADMITGEN_RT_SMALL_N): per node, frames inside each term (CMSIS-DSP biquad
 *    style): a term's state stays in a register across a chunk of frames whose accumulators (f32 on vector
 *    targets: state trajectories) sit in a stack array;
 *  - block path: per frame, one fused pass over a block of nodes updates every term with the block's
 *    accumulators in registers; SIMD kernels (AVX2 on x86-64, selected at run time; NEON on aarch64)
 *    process whole vector blocks and the scalar kernel the remainder.
 * Integer arithmetic is exact in 64 bits whatever the order, so every path is bit-identical; the float
 * kernels use one evaluation order on every path (and ISO C forbids contracting it into FMAs unless
 * FP_CONTRACT is on, which C99 mode leaves off in GCC), so they are bit-identical too. */
#define ADMITGEN_RT_SMALL_N 8
/* Frames per chunk of the small-n path; its stack arrays hold 64 + CHUNK inputs and CHUNK accumulators
 * (about 0.8 KiB for the fixed formats at 32 on Cortex-M4): define smaller for a tight MCU stack. (The f32
 * path on vector targets has its own, ADMITGEN_RT_FCHUNK: admitgen_rt_process_f32.c.) */
#ifndef ADMITGEN_RT_CHUNK
#define ADMITGEN_RT_CHUNK 32
#endif

#if !defined(ADMITGEN_RT_NO_SIMD) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ADMITGEN_RT_HAVE_AVX2 1
#else
#define ADMITGEN_RT_HAVE_AVX2 0
#endif
#if !defined(ADMITGEN_RT_NO_SIMD) && defined(__aarch64__) && defined(__ARM_NEON)
#define ADMITGEN_RT_HAVE_NEON 1
#else
#define ADMITGEN_RT_HAVE_NEON 0
#endif

/* Instruction set of a call: ADMITGEN_RT_ISA_BEST picks the fastest the CPU has; the tests force SCALAR (and
 * AVX2, below AVX-512) to prove every vector kernel bit-identical to the reference. admitgen_rt__use_simd
 * returns 0 (scalar), 1 (AVX2 or NEON) or 2 (AVX-512 F+VL, for the fixed-point kernels). */
#define ADMITGEN_RT_ISA_SCALAR 0
#define ADMITGEN_RT_ISA_BEST 1
#define ADMITGEN_RT_ISA_AVX2 2
static inline int admitgen_rt__use_simd(int isa) {
#if ADMITGEN_RT_HAVE_AVX2
  if (isa == ADMITGEN_RT_ISA_SCALAR || !__builtin_cpu_supports("avx2")) return 0;
  return isa != ADMITGEN_RT_ISA_AVX2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") ? 2 : 1;
#elif ADMITGEN_RT_HAVE_NEON
  return isa != ADMITGEN_RT_ISA_SCALAR;
#else
  (void)isa;
  return 0;
#endif
}

/* Fixed-point coefficients of either format: q31 tables (int32) or q15 tables (int16), one set NULL. */
typedef struct admitgen_rt__qtab {
  const int32_t *fir32, *real32, *pair32;
  const int16_t *fir16, *real16, *pair16;
  int32_t n_fir, n_real, n_pair;
  int32_t bits;      /* 31 or 15: state-update coefficients are m * 2^-(bits + shift) */
  int32_t acc_shift; /* accumulator -> output */
} admitgen_rt__qtab;

/* The tables of a q15 model: 16-bit coefficients (B = 15), or 32-bit ones (B = 31) when fir32 is set. */
static inline admitgen_rt__qtab admitgen_rt__q15_tab(const admitgen_rt_model_q15 *m) {
  admitgen_rt__qtab t = {NULL, NULL, NULL, m->fir, m->real, m->pair, m->n_fir, m->n_real, m->n_pair, 15, m->acc_shift};
  if (m->fir32 != NULL) {
    t.fir32 = m->fir32, t.real32 = m->real32, t.pair32 = m->pair32;
    t.fir16 = NULL, t.real16 = NULL, t.pair16 = NULL;
    t.bits = 31;
  }
  return t;
}

static inline int32_t admitgen_rt__qfir(const admitgen_rt__qtab *t, int32_t k) {
  return t->fir32 != NULL ? t->fir32[k] : (int32_t)t->fir16[k];
}
/* A term's coefficients, total shifts s = bits + shift. */
typedef struct admitgen_rt__qreal_coef {
  int32_t m, s, c;
} admitgen_rt__qreal_coef;
typedef struct admitgen_rt__qpair_coef {
  int32_t er, pi, g, s, cr, ci;
} admitgen_rt__qpair_coef;
/* Entry j (an ADMITGEN_RT_Q_* index) of real pole / pair q's row, from either table type. */
static inline int32_t admitgen_rt__qreal_entry(const admitgen_rt__qtab *t, int32_t q, int32_t j) {
  const int32_t at = ADMITGEN_RT_Q_REAL_WIDTH * q + j;
  return t->real32 != NULL ? t->real32[at] : (int32_t)t->real16[at];
}
static inline int32_t admitgen_rt__qpair_entry(const admitgen_rt__qtab *t, int32_t q, int32_t j) {
  const int32_t at = ADMITGEN_RT_Q_PAIR_WIDTH * q + j;
  return t->pair32 != NULL ? t->pair32[at] : (int32_t)t->pair16[at];
}
static inline admitgen_rt__qreal_coef admitgen_rt__qreal(const admitgen_rt__qtab *t, int32_t q) {
  admitgen_rt__qreal_coef r;
  r.m = admitgen_rt__qreal_entry(t, q, ADMITGEN_RT_Q_REAL_EPS);
  r.s = t->bits + admitgen_rt__qreal_entry(t, q, ADMITGEN_RT_Q_REAL_SHIFT);
  r.c = admitgen_rt__qreal_entry(t, q, ADMITGEN_RT_Q_REAL_C);
  return r;
}
static inline admitgen_rt__qpair_coef admitgen_rt__qpair(const admitgen_rt__qtab *t, int32_t q) {
  admitgen_rt__qpair_coef p;
  p.er = admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_ER);
  p.pi = admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_PI);
  p.g = admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_G);
  p.s = t->bits + admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_SHIFT);
  p.cr = admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_CR);
  p.ci = admitgen_rt__qpair_entry(t, q, ADMITGEN_RT_Q_PAIR_CI);
  return p;
}

/* States of a q31 or q15 instance (identical layouts: Q1.31 states, [term][node]). */
typedef struct admitgen_rt__qstate {
  int32_t *x, *xi, *eta, *hist;
  int32_t n, head, rows; /* rows = n_fir - 1 ring rows (0: no ring) */
} admitgen_rt__qstate;

/* Data of one call: Q1.31 or Q1.15 input (both NULL: u = 0), output (both NULL: none); frame f of node i
 * at [f * stride + i]. */
typedef struct admitgen_rt__qio {
  const int32_t *in32;
  const int16_t *in16;
  int32_t *out32;
  int16_t *out16;
  int32_t stride;
} admitgen_rt__qio;

/* A fixed-point model's shifts and mantissa sums within the bounds that keep every 64-bit product sum and
 * shift defined (BAD_MODEL otherwise; docs/runtime.md, "Limits and misuse"). Tables already checked non-NULL. */
admitgen_rt_result admitgen_rt__check_qmodel(const admitgen_rt__qtab *t);
/* Runs a call of either fixed format on an instance's states (head updated); commit 0 computes the outputs
 * of one frame without changing the state (history). */
void admitgen_rt__qcall(const admitgen_rt__qtab *t, int32_t *x, int32_t *xi, int32_t *eta, int32_t *hist, int32_t n,
                        int32_t *head, const admitgen_rt__qio *io, int32_t n_frames, int commit, int isa);
/* Vector fused pass of frame f over ADMITGEN_RT_QVEC nodes from b (AVX2: 8, AVX-512: 16, NEON: 4); new_head:
 * the ring row u^n goes to. The scalar pass does the remaining nodes. */
#if ADMITGEN_RT_HAVE_AVX2
#define ADMITGEN_RT_QVEC 8
void admitgen_rt__qblock_avx2(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io,
                              size_t base, size_t b, int32_t new_head, int commit);
#define ADMITGEN_RT_QVEC_AVX512 16
void admitgen_rt__qblock_avx512(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io,
                                size_t base, size_t b, int32_t new_head, int commit);
/* Float fused pass of one frame over nodes [i0, n - (n - i0) % 32) (same operations as the generic pass);
 * returns the end. AVX-512: blocks of 64 instead of 32. */
int32_t admitgen_rt__frame_f32_avx2(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit);
int32_t admitgen_rt__frame_f32_avx512(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit);
#endif
#if ADMITGEN_RT_HAVE_NEON
#define ADMITGEN_RT_QVEC 4
void admitgen_rt__qblock_neon(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io,
                              size_t base, size_t b, int32_t new_head, int commit);
#endif
/* Float fused pass of one frame over nodes [i0, n) (in NULL: u = 0; out may be NULL; commit 0: history). */
void admitgen_rt__frame_f32_generic(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit);
/* Fixed-point calls with a forced instruction set (tests). */
void admitgen_rt__process_q31_isa(admitgen_rt_q31 *inst, const int32_t *pIn, int32_t *pOut, int32_t n_frames,
                                  int32_t stride, int isa);
void admitgen_rt__process_q15_isa(admitgen_rt_q15 *inst, const int16_t *pIn, int16_t *pOut, int32_t n_frames,
                                  int32_t stride, int isa);
/* Float call with a forced instruction set (tests). */
void admitgen_rt__process_f32_isa(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames,
                                  int32_t stride, int isa);

#endif /* ADMITGEN_RT_INTERNAL_H */
