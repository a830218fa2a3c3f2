/*
 * admitgen_rt_process_q31.c - q31 kernel.
 *
 * @par Scaling and Overflow Behavior
 *   Input and output are Q1.31. States are int32 Q1.31
 *   and normalised by the generator so that |state| <= max|u| < 1: they cannot overflow (stores are
 *   saturated anyway). State-update coefficients are 31-bit mantissas with a per-term exponent
 *   (value = m * 2^-(31 + shift)); a term's update sum_j m_j v_j is formed exactly in 64 bits (the
 *   generator keeps sum_j |m_j| < 2^31, so |sum| < 2^62) and rounded toward zero of the new state
 *   (magnitude truncation: zero input decays to exactly 0, no limit cycle). The output table (FIR taps and
 *   output coefficients, one exponent, sum |m| < 2^31) is accumulated in 64 bits without loss
 *   (|acc| < 2^62), then shifted right by acc_shift with round-half-up and saturated to Q1.31. The
 *   output represents y * 2^-out_shift with 2^out_shift >= L1 norm of the impulse response, so a
 *   full-scale input of any sign pattern cannot saturate it.
 * @par Coefficient and State Ordering
 *   fir {d_0..d_{n_fir-1}}; real {eps, shift, c} per pole; pair {e_r, p_i, g, shift, cr, ci} per pair.
 *   State arrays [term][node] as in admitgen_rt_init_q31.c.
 */
#include "admitgen_rt_internal.h"

void admitgen_rt_process_q31(admitgen_rt_q31 *inst, const int32_t *pIn, int32_t *pOut, int32_t n_frames, int32_t stride) {
  const admitgen_rt_model_q31 *m = inst->model;
  const int32_t n = inst->n_nodes, rows = m->n_fir - 1;
  int32_t f, i, k, t;
  for (f = 0; f < n_frames; ++f) {
    const int32_t *src = pIn + (size_t)f * (size_t)stride;
    for (i = 0; i < n; ++i) inst->u[i] = src[i];
    if (m->n_fir == 0)
      for (i = 0; i < n; ++i) inst->acc[i] = 0;
    for (k = 0; k < m->n_fir; ++k)
      admitgen_rt__fir_q(inst->acc, inst->u, inst->hist, n, inst->head, rows, k, m->fir[k]);
    for (t = 0; t < m->n_real; ++t) {
      const int32_t *r = m->real + 3 * t;
      admitgen_rt__real_q(inst->x + (size_t)t * (size_t)n, inst->u, inst->acc, n, r[0], 31 + r[1], r[2]);
    }
    for (t = 0; t < m->n_pair; ++t) {
      const int32_t *p = m->pair + 6 * t;
      admitgen_rt__pair_q(inst->xi + (size_t)t * (size_t)n, inst->eta + (size_t)t * (size_t)n, inst->u, inst->acc, n,
                          p[0], p[1], p[2], 31 + p[3], p[4], p[5]);
    }
    if (rows > 0) inst->head = admitgen_rt__push_q(inst->hist, inst->u, n, inst->head, rows);
    if (pOut != NULL) {
      int32_t *dst = pOut + (size_t)f * (size_t)stride;
      for (i = 0; i < n; ++i) dst[i] = (int32_t) admitgen_rt__output(inst->acc[i], m->acc_shift, INT32_MIN, INT32_MAX);
    }
  }
}
