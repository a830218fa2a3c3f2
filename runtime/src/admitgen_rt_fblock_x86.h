/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_fblock_x86.h - the x86 float fused frame pass (the operations of admitgen_rt__frame_f32_generic in
 * its order, lane by lane, no FMA: the same bits), included by admitgen_rt_avx2.c once per instruction set. The
 * includer defines ADMITGEN_RT_FT (the vector type), ADMITGEN_RT_FW (floats per vector), ADMITGEN_RT_FI(op)
 * (the intrinsic _mm256_op or _mm512_op) and ADMITGEN_RT_FN(name) (name + ISA suffix). Blocks of 4 vectors:
 * with 8 floats, 4 (32 nodes) keep 8 of the 16 registers for inputs and accumulators and give the two multiply
 * and two add pipes independent work (measured: 2 vectors 0.52, 4 vectors 0.39 ns/node-sample, 6 spill).
 * No include guard on purpose.
 */
#define ADMITGEN_RT_FVH 4
/* The state updates of admitgen_rt_internal.h (admitgen_rt__real_f32, admitgen_rt__xi_f32, admitgen_rt__eta_f32),
 * lane by lane. */
static inline ADMITGEN_RT_FT ADMITGEN_RT_FN(vreal)(ADMITGEN_RT_FT x, ADMITGEN_RT_FT u, ADMITGEN_RT_FT eps) {
  return ADMITGEN_RT_FI(add_ps)(x, ADMITGEN_RT_FI(mul_ps)(eps, ADMITGEN_RT_FI(sub_ps)(u, x)));
}
static inline ADMITGEN_RT_FT ADMITGEN_RT_FN(vxi)(ADMITGEN_RT_FT a, ADMITGEN_RT_FT e, ADMITGEN_RT_FT u, ADMITGEN_RT_FT er,
                                                 ADMITGEN_RT_FT pi, ADMITGEN_RT_FT g) {
  return ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(add_ps)(a, ADMITGEN_RT_FI(mul_ps)(g, u)),
                                ADMITGEN_RT_FI(sub_ps)(ADMITGEN_RT_FI(mul_ps)(er, a), ADMITGEN_RT_FI(mul_ps)(pi, e)));
}
static inline ADMITGEN_RT_FT ADMITGEN_RT_FN(veta)(ADMITGEN_RT_FT a, ADMITGEN_RT_FT e, ADMITGEN_RT_FT er, ADMITGEN_RT_FT pi) {
  return ADMITGEN_RT_FI(add_ps)(e, ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(mul_ps)(er, e), ADMITGEN_RT_FI(mul_ps)(pi, a)));
}
/* acc + (cr a + ci e) */
static inline ADMITGEN_RT_FT ADMITGEN_RT_FN(vpair_out)(ADMITGEN_RT_FT acc, ADMITGEN_RT_FT a, ADMITGEN_RT_FT e, ADMITGEN_RT_FT cr,
                                                       ADMITGEN_RT_FT ci) {
  return ADMITGEN_RT_FI(add_ps)(acc, ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(mul_ps)(cr, a), ADMITGEN_RT_FI(mul_ps)(ci, e)));
}
static void ADMITGEN_RT_FN(fblock)(const admitgen_rt_f32 *inst, const float *in, float *out, size_t b, int32_t new_head,
                                   int commit) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes, w = ADMITGEN_RT_FW;
  const int32_t rows = m->n_fir - 1;
  ADMITGEN_RT_FT u[ADMITGEN_RT_FVH], acc[ADMITGEN_RT_FVH];
  int32_t h, k, t;
  for (h = 0; h < ADMITGEN_RT_FVH; ++h) {
    u[h] = in != NULL ? ADMITGEN_RT_FI(loadu_ps)(in + b + w * (size_t)h) : ADMITGEN_RT_FI(setzero_ps)();
    acc[h] = ADMITGEN_RT_FI(mul_ps)(ADMITGEN_RT_FI(set1_ps)(m->n_fir > 0 ? m->fir[0] : 0.0f), u[h]);
  }
  for (k = 1; k < m->n_fir; ++k) {
    const ADMITGEN_RT_FT d = ADMITGEN_RT_FI(set1_ps)(m->fir[k]);
    const float *row = inst->hist + (size_t)admitgen_rt__ring_row(inst->head, k, rows) * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h)
      acc[h] = ADMITGEN_RT_FI(add_ps)(acc[h], ADMITGEN_RT_FI(mul_ps)(d, ADMITGEN_RT_FI(loadu_ps)(row + w * (size_t)h)));
  }
  for (t = 0; t < m->n_real; ++t) {
    const ADMITGEN_RT_FT eps = ADMITGEN_RT_FI(set1_ps)(m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_EPS]), c = ADMITGEN_RT_FI(set1_ps)(m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C]);
    float *x = inst->x + (size_t)t * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) { /* x' = x + eps (u - x) */
      const ADMITGEN_RT_FT x0 = ADMITGEN_RT_FI(loadu_ps)(x + w * (size_t)h);
      const ADMITGEN_RT_FT v = ADMITGEN_RT_FN(vreal)(x0, u[h], eps);
      if (commit) ADMITGEN_RT_FI(storeu_ps)(x + w * (size_t)h, v);
      acc[h] = ADMITGEN_RT_FI(add_ps)(acc[h], ADMITGEN_RT_FI(mul_ps)(c, v));
    }
  }
  for (t = 0; t < m->n_pair; ++t) {
    const float *p = m->pair + ADMITGEN_RT_F32_PAIR_WIDTH * t;
    const ADMITGEN_RT_FT er = ADMITGEN_RT_FI(set1_ps)(p[ADMITGEN_RT_F32_PAIR_ER]), pi = ADMITGEN_RT_FI(set1_ps)(p[ADMITGEN_RT_F32_PAIR_PI]), g = ADMITGEN_RT_FI(set1_ps)(p[ADMITGEN_RT_F32_PAIR_G]);
    const ADMITGEN_RT_FT cr = ADMITGEN_RT_FI(set1_ps)(p[ADMITGEN_RT_F32_PAIR_CR]), ci = ADMITGEN_RT_FI(set1_ps)(p[ADMITGEN_RT_F32_PAIR_CI]);
    float *xi = inst->xi + (size_t)t * n + b, *eta = inst->eta + (size_t)t * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) {
      const ADMITGEN_RT_FT a = ADMITGEN_RT_FI(loadu_ps)(xi + w * (size_t)h), e = ADMITGEN_RT_FI(loadu_ps)(eta + w * (size_t)h);
      const ADMITGEN_RT_FT a1 = ADMITGEN_RT_FN(vxi)(a, e, u[h], er, pi, g), e1 = ADMITGEN_RT_FN(veta)(a, e, er, pi);
      if (commit) {
        ADMITGEN_RT_FI(storeu_ps)(xi + w * (size_t)h, a1);
        ADMITGEN_RT_FI(storeu_ps)(eta + w * (size_t)h, e1);
      }
      acc[h] = ADMITGEN_RT_FN(vpair_out)(acc[h], a1, e1, cr, ci);
    }
  }
  if (out != NULL)
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) ADMITGEN_RT_FI(storeu_ps)(out + b + w * (size_t)h, acc[h]);
  if (commit && rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
    float *row = inst->hist + (size_t)new_head * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) ADMITGEN_RT_FI(storeu_ps)(row + w * (size_t)h, u[h]);
  }
}

/* ---- small models: node vectors outermost, every coefficient in a register (docs/runtime.md, "Kernels") ----
 * A model of at most ADMITGEN_RT_FFIR FIR taps, 2 real poles and 2 pairs (Q0S0 to Q2S2 with any FIR path: what
 * the fit grid emits but its largest orders), in process and commit, runs one pass over the nodes,
 * ADMITGEN_RT_FVS vectors at a time, each step's whole output (FIR, then the terms in order) formed before the
 * next: nothing is re-read but the states and the past inputs, the coefficients are broadcast and the ring
 * rows' addresses computed once per frame, and the loop carries no loop over terms (their counts are constants
 * of one of 9 copies, the FIR length a predictable branch per tap). The multiply pipes then bind it: 15
 * multiplies per node-sample for Q1S1, two vectors per cycle on a Zen 5 (measured 0.17 against 0.38 ns per
 * node-sample for the per-term block form above, which history and larger models keep). Same operations in
 * the same order as every other path. */
#define ADMITGEN_RT_FFIR 8
#define ADMITGEN_RT_FVS 2 /* vectors per step (AVX2: 4 spill, measured 0.39 against 0.30 ns; AVX-512: 2 = 4) */
#if defined(__GNUC__) || defined(__clang__)
#define ADMITGEN_RT_FALWAYS static inline __attribute__((always_inline))
#else
#define ADMITGEN_RT_FALWAYS static inline
#endif
ADMITGEN_RT_FALWAYS void ADMITGEN_RT_FN(fsmall)(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int32_t nv,
                                                int32_t new_head, const int nr, const int np) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes, w = ADMITGEN_RT_FW;
  const int32_t nf = m->n_fir, rows = nf - 1;
  const float *row[ADMITGEN_RT_FFIR];
  /* u^n goes to the ring row of u^{n-rows} (read above it), or to the scratch row when there is no ring; the
   * outputs to the scratch accumulators when the caller wants none: no branch in the loop */
  float *x[2], *xi[2], *eta[2], *ring = rows > 0 ? inst->hist + (size_t)new_head * n : inst->u;
  float *y = out != NULL ? out : inst->acc;
  ADMITGEN_RT_FT d[ADMITGEN_RT_FFIR], eps[2], c[2], er[2], pi[2], g[2], cr[2], ci[2];
  size_t b;
  int32_t k, t, h;
  for (k = 0; k < ADMITGEN_RT_FFIR; ++k) {
    d[k] = ADMITGEN_RT_FI(set1_ps)(k < nf ? m->fir[k] : 0.0f);
    row[k] = k >= 1 && k < nf ? inst->hist + (size_t)admitgen_rt__ring_row(inst->head, k, rows) * n : NULL;
  }
  for (t = 0; t < 2; ++t) {
    const float *r = m->real + ADMITGEN_RT_F32_REAL_WIDTH * t, *p = m->pair + ADMITGEN_RT_F32_PAIR_WIDTH * t;
    x[t] = t < nr ? inst->x + (size_t)t * n : NULL;
    xi[t] = t < np ? inst->xi + (size_t)t * n : NULL;
    eta[t] = t < np ? inst->eta + (size_t)t * n : NULL;
    eps[t] = ADMITGEN_RT_FI(set1_ps)(t < nr ? r[ADMITGEN_RT_F32_REAL_EPS] : 0.0f);
    c[t] = ADMITGEN_RT_FI(set1_ps)(t < nr ? r[ADMITGEN_RT_F32_REAL_C] : 0.0f);
    er[t] = ADMITGEN_RT_FI(set1_ps)(t < np ? p[ADMITGEN_RT_F32_PAIR_ER] : 0.0f);
    pi[t] = ADMITGEN_RT_FI(set1_ps)(t < np ? p[ADMITGEN_RT_F32_PAIR_PI] : 0.0f);
    g[t] = ADMITGEN_RT_FI(set1_ps)(t < np ? p[ADMITGEN_RT_F32_PAIR_G] : 0.0f);
    cr[t] = ADMITGEN_RT_FI(set1_ps)(t < np ? p[ADMITGEN_RT_F32_PAIR_CR] : 0.0f);
    ci[t] = ADMITGEN_RT_FI(set1_ps)(t < np ? p[ADMITGEN_RT_F32_PAIR_CI] : 0.0f);
  }
  for (b = (size_t)i0; b < (size_t)nv; b += w * ADMITGEN_RT_FVS) {
    ADMITGEN_RT_FT u[ADMITGEN_RT_FVS], acc[ADMITGEN_RT_FVS];
    for (h = 0; h < ADMITGEN_RT_FVS; ++h) {
      u[h] = ADMITGEN_RT_FI(loadu_ps)(in + b + w * (size_t)h);
      acc[h] = ADMITGEN_RT_FI(mul_ps)(d[0], u[h]);
    }
    for (k = 1; k < ADMITGEN_RT_FFIR; ++k) /* unrolled: one branch per tap and vector block */
      if (k < nf)
        for (h = 0; h < ADMITGEN_RT_FVS; ++h)
          acc[h] = ADMITGEN_RT_FI(add_ps)(acc[h], ADMITGEN_RT_FI(mul_ps)(d[k], ADMITGEN_RT_FI(loadu_ps)(row[k] + b + w * (size_t)h)));
    for (t = 0; t < nr; ++t)
      for (h = 0; h < ADMITGEN_RT_FVS; ++h) {
        float *p = x[t] + b + w * (size_t)h;
        const ADMITGEN_RT_FT v = ADMITGEN_RT_FN(vreal)(ADMITGEN_RT_FI(loadu_ps)(p), u[h], eps[t]);
        ADMITGEN_RT_FI(storeu_ps)(p, v);
        acc[h] = ADMITGEN_RT_FI(add_ps)(acc[h], ADMITGEN_RT_FI(mul_ps)(c[t], v));
      }
    for (t = 0; t < np; ++t)
      for (h = 0; h < ADMITGEN_RT_FVS; ++h) {
        float *pa = xi[t] + b + w * (size_t)h, *pe = eta[t] + b + w * (size_t)h;
        const ADMITGEN_RT_FT a = ADMITGEN_RT_FI(loadu_ps)(pa), e = ADMITGEN_RT_FI(loadu_ps)(pe);
        const ADMITGEN_RT_FT a1 = ADMITGEN_RT_FN(vxi)(a, e, u[h], er[t], pi[t], g[t]), e1 = ADMITGEN_RT_FN(veta)(a, e, er[t], pi[t]);
        ADMITGEN_RT_FI(storeu_ps)(pa, a1);
        ADMITGEN_RT_FI(storeu_ps)(pe, e1);
        acc[h] = ADMITGEN_RT_FN(vpair_out)(acc[h], a1, e1, cr[t], ci[t]);
      }
    for (h = 0; h < ADMITGEN_RT_FVS; ++h) {
      ADMITGEN_RT_FI(storeu_ps)(y + b + w * (size_t)h, acc[h]);
      ADMITGEN_RT_FI(storeu_ps)(ring + b + w * (size_t)h, u[h]);
    }
  }
}

int32_t ADMITGEN_RT_FN(frame_f32)(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit) {
  const admitgen_rt_model_f32 *m = inst->model;
  const int small = commit && in != NULL && m->n_fir <= ADMITGEN_RT_FFIR && m->n_real <= 2 && m->n_pair <= 2;
  const int32_t block = ADMITGEN_RT_FW * (small ? ADMITGEN_RT_FVS : ADMITGEN_RT_FVH), rows = m->n_fir - 1;
  const int32_t nv = inst->n_nodes - (inst->n_nodes - i0) % block;
  const int32_t new_head = rows > 0 ? admitgen_rt__ring_advance(inst->head, 1, rows) : 0;
  int32_t b;
  if (nv <= i0) return i0; /* no whole block: no set-up */
  if (small) {
    switch (3 * m->n_real + m->n_pair) { /* constant term counts: the loops over terms unroll */
      case 0: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 0, 0); break;
      case 1: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 0, 1); break;
      case 2: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 0, 2); break;
      case 3: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 1, 0); break;
      case 4: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 1, 1); break;
      case 5: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 1, 2); break;
      case 6: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 2, 0); break;
      case 7: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 2, 1); break;
      default: ADMITGEN_RT_FN(fsmall)(inst, in, out, i0, nv, new_head, 2, 2); break;
    }
  } else {
    for (b = i0; b < nv; b += block) ADMITGEN_RT_FN(fblock)(inst, in, out, (size_t)b, new_head, commit);
  }
  return nv;
}
#undef ADMITGEN_RT_FVH
#undef ADMITGEN_RT_FFIR
#undef ADMITGEN_RT_FVS
#undef ADMITGEN_RT_FALWAYS
