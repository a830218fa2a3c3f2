/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_avx2.c - x86-64 vector kernels, compiled for AVX2 (and AVX-512 F+VL) by target pragmas, one
 * section each (the rest of the library stays baseline x86-64), chosen at run time by
 * __builtin_cpu_supports (admitgen_rt_internal.h).
 *
 * Fixed point (block body: admitgen_rt_qblock_x86.h): AVX2 8 nodes per block, two vectors of 4 int64 lanes each holding a sign-extended Q1.31 value,
 * so _mm256_mul_epi32 forms the exact 32x32 -> 64-bit products the scalar kernel forms. AVX2 has no 64-bit
 * arithmetic right shift; floor(v / 2^s) is computed exactly as ((v + 2^63) >>> s) - 2^(63 - s) (the bias
 * makes v non-negative as an unsigned number; 2^63 is divisible by 2^s). Rounding toward zero of the new
 * state, saturation and the round-half-up output then follow the scalar definitions
 * (admitgen_rt__add_tz, admitgen_rt__output) operation for operation: the results are bit-identical.
 * AVX-512: 16 nodes per block with native 64-bit shifts, min/max and masks (same results).
 * Float: the operations of the generic fused frame pass (admitgen_rt_process_f32.c) in the same order, without
 * FMA (which would round differently): bit-identical too.
 */
#include "admitgen_rt_internal.h"

#if ADMITGEN_RT_HAVE_AVX2
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#include <immintrin.h>

/* ---- float: 32 nodes per block (four vectors), the operations of admitgen_rt__frame_f32_generic in its order */

static inline __m256 admitgen_rt__vreal(__m256 x, __m256 u, __m256 eps) {
  return _mm256_add_ps(x, _mm256_mul_ps(eps, _mm256_sub_ps(u, x)));
}

/* Vectors of 8 floats per block: 4 (32 nodes) keeps 8 of the 16 registers for inputs and accumulators and
 * gives the two multiply and two add pipes independent work (measured: 2 vectors 0.52, 4 vectors 0.39
 * ns/node-sample, 6 spill). */
#define ADMITGEN_RT_FVH 4
static void admitgen_rt__fblock_avx2(const admitgen_rt_f32 *inst, const float *in, float *out, size_t b, int32_t new_head,
                                     int commit) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes;
  const int32_t rows = m->n_fir - 1;
  __m256 u[ADMITGEN_RT_FVH], acc[ADMITGEN_RT_FVH];
  int32_t h, k, t;
  for (h = 0; h < ADMITGEN_RT_FVH; ++h) {
    u[h] = in != NULL ? _mm256_loadu_ps(in + b + 8 * h) : _mm256_setzero_ps();
    acc[h] = _mm256_mul_ps(_mm256_set1_ps(m->n_fir > 0 ? m->fir[0] : 0.0f), u[h]);
  }
  for (k = 1; k < m->n_fir; ++k) {
    const __m256 d = _mm256_set1_ps(m->fir[k]);
    const float *row = inst->hist + (size_t)admitgen_rt__ring_row(inst->head, k, rows) * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) acc[h] = _mm256_add_ps(acc[h], _mm256_mul_ps(d, _mm256_loadu_ps(row + 8 * h)));
  }
  for (t = 0; t < m->n_real; ++t) {
    const __m256 eps = _mm256_set1_ps(m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_EPS]);
    const __m256 c = _mm256_set1_ps(m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C]);
    float *x = inst->x + (size_t)t * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) {
      const __m256 v = admitgen_rt__vreal(_mm256_loadu_ps(x + 8 * h), u[h], eps);
      if (commit) _mm256_storeu_ps(x + 8 * h, v);
      acc[h] = _mm256_add_ps(acc[h], _mm256_mul_ps(c, v));
    }
  }
  for (t = 0; t < m->n_pair; ++t) {
    const float *p = m->pair + ADMITGEN_RT_F32_PAIR_WIDTH * t;
    const __m256 er = _mm256_set1_ps(p[ADMITGEN_RT_F32_PAIR_ER]), pi = _mm256_set1_ps(p[ADMITGEN_RT_F32_PAIR_PI]), g = _mm256_set1_ps(p[ADMITGEN_RT_F32_PAIR_G]);
    const __m256 cr = _mm256_set1_ps(p[ADMITGEN_RT_F32_PAIR_CR]), ci = _mm256_set1_ps(p[ADMITGEN_RT_F32_PAIR_CI]);
    float *xi = inst->xi + (size_t)t * n + b, *eta = inst->eta + (size_t)t * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) {
      const __m256 a = _mm256_loadu_ps(xi + 8 * h), e = _mm256_loadu_ps(eta + 8 * h);
      /* xi' = xi + (e_r xi + (g u - p_i eta));  eta' = eta + (e_r eta + p_i xi) */
      const __m256 a1 = _mm256_add_ps(
          a, _mm256_add_ps(_mm256_mul_ps(er, a), _mm256_sub_ps(_mm256_mul_ps(g, u[h]), _mm256_mul_ps(pi, e))));
      const __m256 e1 = _mm256_add_ps(e, _mm256_add_ps(_mm256_mul_ps(er, e), _mm256_mul_ps(pi, a)));
      if (commit) {
        _mm256_storeu_ps(xi + 8 * h, a1);
        _mm256_storeu_ps(eta + 8 * h, e1);
      }
      acc[h] = _mm256_add_ps(acc[h], _mm256_add_ps(_mm256_mul_ps(cr, a1), _mm256_mul_ps(ci, e1)));
    }
  }
  if (out != NULL)
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) _mm256_storeu_ps(out + b + 8 * h, acc[h]);
  if (commit && rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
    float *row = inst->hist + (size_t)new_head * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) _mm256_storeu_ps(row + 8 * h, u[h]);
  }
}

int32_t admitgen_rt__frame_f32_avx2(const admitgen_rt_f32 *inst, const float *in, float *out, int commit) {
  const int32_t nv = inst->n_nodes - inst->n_nodes % (8 * ADMITGEN_RT_FVH), rows = inst->model->n_fir - 1;
  const int32_t new_head = rows > 0 ? admitgen_rt__ring_advance(inst->head, 1, rows) : 0;
  int32_t b;
  for (b = 0; b < nv; b += 8 * ADMITGEN_RT_FVH) admitgen_rt__fblock_avx2(inst, in, out, (size_t)b, new_head, commit);
  return nv;
}

/* ---- fixed point ---- */

/* A shift by s: count, the bias 2^(63 - s) and the mask 2^s - 1 of the discarded bits. */
typedef struct admitgen_rt__vshift {
  __m128i count;
  __m256i bias, mask;
} admitgen_rt__vshift;

static inline admitgen_rt__vshift admitgen_rt__vshift_make(int32_t s) {
  admitgen_rt__vshift k;
  k.count = _mm_cvtsi32_si128(s);
  k.bias = _mm256_set1_epi64x((long long)((uint64_t)1 << (63 - s)));
  k.mask = _mm256_set1_epi64x((long long)(((uint64_t)1 << s) - 1u));
  return k;
}

static inline __m256i admitgen_rt__vload32(const int32_t *p) {
  return _mm256_cvtepi32_epi64(_mm_loadu_si128((const __m128i *)(const void *)p));
}

/* Low 32 bits of the 4 lanes, packed. */
static inline __m128i admitgen_rt__vnarrow(__m256i v) {
  return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));
}

static inline void admitgen_rt__vstore32(int32_t *p, __m256i v) {
  _mm_storeu_si128((__m128i *)(void *)p, admitgen_rt__vnarrow(v));
}

static inline __m256i admitgen_rt__vmul(__m256i a, int32_t c) { return _mm256_mul_epi32(a, _mm256_set1_epi32(c)); }

static inline __m256i admitgen_rt__vinput(const admitgen_rt__qio *io, size_t idx) {
  if (io->in32 != NULL) return admitgen_rt__vload32(io->in32 + idx);
  if (io->in16 != NULL)
    return _mm256_slli_epi64(_mm256_cvtepi16_epi64(_mm_loadl_epi64((const __m128i *)(const void *)(io->in16 + idx))), 16);
  return _mm256_setzero_si256();
}

/* AVX2 primitives. */
static inline __m256i admitgen_rt__vfloor_shr_avx2(__m256i v, const admitgen_rt__vshift *k) {
  const __m256i sign = _mm256_set1_epi64x((long long)INT64_MIN);
  return _mm256_sub_epi64(_mm256_srl_epi64(_mm256_xor_si256(v, sign), k->count), k->bias);
}

static inline __m256i admitgen_rt__vclamp_avx2(__m256i v, __m256i lo, __m256i hi) {
  v = _mm256_blendv_epi8(v, hi, _mm256_cmpgt_epi64(v, hi));
  return _mm256_blendv_epi8(v, lo, _mm256_cmpgt_epi64(lo, v));
}

/* admitgen_rt__add_tz on 4 lanes: trunc(old + prod / 2^s) saturated to int32. */
static inline __m256i admitgen_rt__vadd_tz_avx2(__m256i old, __m256i prod, const admitgen_rt__vshift *k) {
  const __m256i zero = _mm256_setzero_si256();
  __m256i v = _mm256_add_epi64(old, admitgen_rt__vfloor_shr_avx2(prod, k));
  const __m256i exact = _mm256_cmpeq_epi64(_mm256_and_si256(prod, k->mask), zero);
  v = _mm256_sub_epi64(v, _mm256_andnot_si256(exact, _mm256_cmpgt_epi64(zero, v))); /* +1 if v < 0 and inexact */
  return admitgen_rt__vclamp_avx2(v, _mm256_set1_epi64x(INT32_MIN), _mm256_set1_epi64x(INT32_MAX));
}

#define ADMITGEN_RT_V(name) admitgen_rt__##name##_avx2
#define ADMITGEN_RT_VH 2 /* 8 nodes: 16 vector registers */
#include "admitgen_rt_qblock_x86.h"
#undef ADMITGEN_RT_V
#undef ADMITGEN_RT_VH

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

/* AVX-512 (F + VL, on 256-bit vectors): native 64-bit arithmetic shift, 64-bit min/max and mask registers
 * replace the bias trick, the blends and the compare-and-subtract of the AVX2 primitives. Same results. */
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,avx512f,avx512vl"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,avx512f,avx512vl")
#endif
static inline __m256i admitgen_rt__vfloor_shr_avx512(__m256i v, const admitgen_rt__vshift *k) {
  return _mm256_sra_epi64(v, k->count);
}

static inline __m256i admitgen_rt__vclamp_avx512(__m256i v, __m256i lo, __m256i hi) {
  return _mm256_max_epi64(_mm256_min_epi64(v, hi), lo);
}

static inline __m256i admitgen_rt__vadd_tz_avx512(__m256i old, __m256i prod, const admitgen_rt__vshift *k) {
  __m256i v = _mm256_add_epi64(old, _mm256_sra_epi64(prod, k->count));
  const __mmask8 adjust = _mm256_mask_cmplt_epi64_mask(_mm256_test_epi64_mask(prod, k->mask), v, _mm256_setzero_si256());
  v = _mm256_mask_add_epi64(v, adjust, v, _mm256_set1_epi64x(1)); /* +1 if v < 0 and inexact */
  return admitgen_rt__vclamp_avx512(v, _mm256_set1_epi64x(INT32_MIN), _mm256_set1_epi64x(INT32_MAX));
}

#define ADMITGEN_RT_V(name) admitgen_rt__##name##_avx512
#define ADMITGEN_RT_VH 4 /* 16 nodes: 32 vector registers, half the per-block coefficient set-up */
#include "admitgen_rt_qblock_x86.h"
#undef ADMITGEN_RT_V
#undef ADMITGEN_RT_VH
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#else
typedef int admitgen_rt__avx2_not_built; /* ISO C forbids an empty translation unit */
#endif
