/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_process_q15.c - q15 entry points: block processing, FDTD history/commit (kernel in
 * admitgen_rt_fixed.c and the vector kernels).
 *
 * @par Scaling and Overflow Behavior
 *   Q1.15 data (promoted exactly to Q1.31), Q1.31 states, every product and sum exact in 64 bits, state updates rounded
 *   toward zero, output rounded half up and saturated: stated once in docs/runtime.md, "Q formats and
 *   rounding"; the bounds the kernel relies on are checked at init (admitgen_rt__check_qmodel).
 * @par Coefficient and State Ordering
 *   Tables: the ADMITGEN_RT_Q_* layout of admitgen_rt.h. State arrays [term][node] as in
 *   admitgen_rt_init_q15.c.
 */
#include "admitgen_rt_internal.h"

void admitgen_rt__process_q15_isa(admitgen_rt_q15 *inst, const int16_t *pIn, int16_t *pOut, int32_t n_frames, int32_t stride,
                                  int isa) {
  const admitgen_rt_model_q15 *m = inst->model;
  const admitgen_rt__qtab t = admitgen_rt__q15_tab(m);
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
  const admitgen_rt__qtab t = admitgen_rt__q15_tab(m);
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
