/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_process_q15.c - q15 entry points: block processing, FDTD history/commit (kernel in
 * admitgen_rt_fixed.c and the vector kernels).
 *
 * @par Scaling and Overflow Behavior
 *   Input and output are Q1.15; the input is promoted exactly to Q1.31 (x 2^16). States are int32 Q1.31
 *   and normalised by the generator so that |state| <= max|u| < 1: they cannot overflow (stores are
 *   saturated anyway). State-update coefficients are 15-bit mantissas with a per-term exponent
 *   (value = m * 2^-(15 + shift)); a term's update sum_j m_j v_j is formed exactly in 64 bits (the
 *   generator keeps sum_j |m_j| < 2^15, so |sum| < 2^46) and rounded toward zero of the new state
 *   (magnitude truncation: zero input decays to exactly 0, no limit cycle). The output table (FIR taps and
 *   output coefficients, one exponent, sum |m| < 2^15) is accumulated in 64 bits without loss
 *   (|acc| < 2^46), then shifted right by acc_shift with round-half-up and saturated to Q1.15. The
 *   output represents y * 2^-out_shift with 2^out_shift >= L1 norm of the impulse response, so a
 *   full-scale input of any sign pattern cannot saturate it.
 * @par Coefficient and State Ordering
 *   fir {d_0..d_{n_fir-1}}; real {eps, shift, c} per pole; pair {e_r, p_i, g, shift, cr, ci} per pair.
 *   State arrays [term][node] as in admitgen_rt_init_q15.c.
 */
#include "admitgen_rt_internal.h"

void admitgen_rt__process_q15_isa(admitgen_rt_q15 *inst, const int16_t *pIn, int16_t *pOut, int32_t n_frames, int32_t stride,
                                  int isa) {
  const admitgen_rt_model_q15 *m = inst->model;
  const admitgen_rt__qtab t = {NULL, NULL, NULL, m->fir, m->real, m->pair, m->n_fir, m->n_real, m->n_pair, 15, m->acc_shift};
  const admitgen_rt__qio io = {NULL, pIn, NULL, pOut, stride};
  admitgen_rt__qcall(&t, inst->x, inst->xi, inst->eta, inst->hist, inst->n_nodes, &inst->head, &io, n_frames, 1, isa);
}

admitgen_rt_result admitgen_rt_process_q15(admitgen_rt_q15 *inst, const int16_t *pIn, int16_t *pOut, int32_t n_frames, int32_t stride) {
  const admitgen_rt_result r =
      inst == NULL ? ADMITGEN_RT_NULL_POINTER : admitgen_rt__check_call(inst->model, inst->n_nodes, pIn, n_frames, stride);
  if (r == ADMITGEN_RT_SUCCESS && n_frames > 0) admitgen_rt__process_q15_isa(inst, pIn, pOut, n_frames, stride, ADMITGEN_RT_ISA_BEST);
  return r;
}

static void admitgen_rt__history_q15(const admitgen_rt_q15 *inst, int16_t *pHist) {
  /* one frame with u = 0 and commit 0: states and ring unchanged */
  const admitgen_rt_model_q15 *m = inst->model;
  const admitgen_rt__qtab t = {NULL, NULL, NULL, m->fir, m->real, m->pair, m->n_fir, m->n_real, m->n_pair, 15, m->acc_shift};
  const admitgen_rt__qio io = {NULL, NULL, NULL, pHist, inst->n_nodes};
  int32_t head = inst->head;
  admitgen_rt__qcall(&t, inst->x, inst->xi, inst->eta, inst->hist, inst->n_nodes, &head, &io, 1, 0, ADMITGEN_RT_ISA_BEST);
}

admitgen_rt_result admitgen_rt_history_q15(const admitgen_rt_q15 *inst, int16_t *pHist) {
  if (inst == NULL || inst->model == NULL || pHist == NULL) return ADMITGEN_RT_NULL_POINTER;
  admitgen_rt__history_q15(inst, pHist);
  return ADMITGEN_RT_SUCCESS;
}

admitgen_rt_result admitgen_rt_commit_q15(admitgen_rt_q15 *inst, const int16_t *pU, int16_t *pY) {
  return inst == NULL ? ADMITGEN_RT_NULL_POINTER : admitgen_rt_process_q15(inst, pU, pY, 1, inst->n_nodes);
}
