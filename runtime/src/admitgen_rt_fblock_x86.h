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
      const ADMITGEN_RT_FT v = ADMITGEN_RT_FI(add_ps)(x0, ADMITGEN_RT_FI(mul_ps)(eps, ADMITGEN_RT_FI(sub_ps)(u[h], x0)));
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
      /* xi' = xi + (e_r xi + (g u - p_i eta));  eta' = eta + (e_r eta + p_i xi) */
      const ADMITGEN_RT_FT a1 = ADMITGEN_RT_FI(add_ps)(
          a, ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(mul_ps)(er, a),
                                    ADMITGEN_RT_FI(sub_ps)(ADMITGEN_RT_FI(mul_ps)(g, u[h]), ADMITGEN_RT_FI(mul_ps)(pi, e))));
      const ADMITGEN_RT_FT e1 =
          ADMITGEN_RT_FI(add_ps)(e, ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(mul_ps)(er, e), ADMITGEN_RT_FI(mul_ps)(pi, a)));
      if (commit) {
        ADMITGEN_RT_FI(storeu_ps)(xi + w * (size_t)h, a1);
        ADMITGEN_RT_FI(storeu_ps)(eta + w * (size_t)h, e1);
      }
      acc[h] = ADMITGEN_RT_FI(add_ps)(acc[h],
                                      ADMITGEN_RT_FI(add_ps)(ADMITGEN_RT_FI(mul_ps)(cr, a1), ADMITGEN_RT_FI(mul_ps)(ci, e1)));
    }
  }
  if (out != NULL)
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) ADMITGEN_RT_FI(storeu_ps)(out + b + w * (size_t)h, acc[h]);
  if (commit && rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
    float *row = inst->hist + (size_t)new_head * n + b;
    for (h = 0; h < ADMITGEN_RT_FVH; ++h) ADMITGEN_RT_FI(storeu_ps)(row + w * (size_t)h, u[h]);
  }
}

int32_t ADMITGEN_RT_FN(frame_f32)(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit) {
  const int32_t block = ADMITGEN_RT_FW * ADMITGEN_RT_FVH, rows = inst->model->n_fir - 1;
  const int32_t nv = inst->n_nodes - (inst->n_nodes - i0) % block;
  const int32_t new_head = rows > 0 ? admitgen_rt__ring_advance(inst->head, 1, rows) : 0;
  int32_t b;
  for (b = i0; b < nv; b += block) ADMITGEN_RT_FN(fblock)(inst, in, out, (size_t)b, new_head, commit);
  return nv;
}
#undef ADMITGEN_RT_FVH
