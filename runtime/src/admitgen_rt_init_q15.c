/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_init_q15.c - state size, init, reinit (coefficient swap) and reset of the q15 instance.
 *
 * State memory (caller-owned, ADMITGEN_RT_ALIGN-aligned), each array starting on an aligned boundary:
 *   x[n_real][n_nodes], xi[n_pair][n_nodes], eta[n_pair][n_nodes], hist[n_fir-1][n_nodes],
 *   u[n_nodes] (scratch), acc[n_nodes] (scratch, int64_t)
 * States are int32_t in Q1.31. No allocation; init zeroes the memory.
 */
#include "admitgen_rt_internal.h"

size_t admitgen_rt_state_bytes_q15(const admitgen_rt_model_q15 *model, int32_t n_nodes) {
  if (model == NULL) return 0;
  return admitgen_rt__bytes(model->n_fir, model->n_real, model->n_pair, n_nodes, sizeof(int32_t), sizeof(int64_t));
}

/* The model's own consistency (docs/runtime.md, "Limits and misuse"), before anything reads its tables. */
static admitgen_rt_result admitgen_rt__check_model_q15(const admitgen_rt_model_q15 *m) {
  const admitgen_rt_result r =
      m->fir32 != NULL ? admitgen_rt__check_tables(m->n_fir, m->n_real, m->n_pair, m->fir32, m->real32, m->pair32)
                       : admitgen_rt__check_tables(m->n_fir, m->n_real, m->n_pair, m->fir, m->real, m->pair);
  if (r != ADMITGEN_RT_SUCCESS) return r;
  {
    const admitgen_rt__qtab t = admitgen_rt__q15_tab(m);
    return admitgen_rt__check_qmodel(&t);
  }
}

admitgen_rt_result admitgen_rt_init_q15(admitgen_rt_q15 *inst, const admitgen_rt_model_q15 *model, int32_t fs_hz,
                                        int32_t n_nodes, void *mem, size_t bytes) {
  admitgen_rt__layout l;
  admitgen_rt_result r;
  if (inst == NULL || model == NULL) return ADMITGEN_RT_NULL_POINTER;
  if (model->abi_version != (uint32_t)ADMITGEN_RT_ABI_VERSION) return ADMITGEN_RT_ABI_MISMATCH;
  r = admitgen_rt__check_model_q15(model);
  if (r != ADMITGEN_RT_SUCCESS) return r;
  r = admitgen_rt__bind(model->abi_version, model->fs_hz, fs_hz, model->n_fir, model->n_real, model->n_pair, n_nodes,
                        sizeof(int32_t), sizeof(int64_t), mem, bytes, &l);
  if (r != ADMITGEN_RT_SUCCESS) return r;
  inst->model = model;
  inst->n_nodes = n_nodes;
  inst->head = 0;
  inst->x = (int32_t *)l.x;
  inst->xi = (int32_t *)l.xi;
  inst->eta = (int32_t *)l.eta;
  inst->hist = (int32_t *)l.hist;
  inst->u = (int32_t *)l.u;
  inst->acc = (int64_t *)l.acc;
  return ADMITGEN_RT_SUCCESS;
}

admitgen_rt_result admitgen_rt_reinit_q15(admitgen_rt_q15 *inst, const admitgen_rt_model_q15 *model, int32_t fs_hz) {
  admitgen_rt_result r;
  if (inst == NULL || model == NULL || inst->model == NULL) return ADMITGEN_RT_NULL_POINTER;
  if (model->abi_version != (uint32_t)ADMITGEN_RT_ABI_VERSION) return ADMITGEN_RT_ABI_MISMATCH;
  r = admitgen_rt__check_model_q15(model);
  if (r != ADMITGEN_RT_SUCCESS) return r;
  r = admitgen_rt__check_swap(model->abi_version, model->fs_hz, fs_hz, model->n_fir, model->n_real, model->n_pair,
                              inst->model->n_fir, inst->model->n_real, inst->model->n_pair);
  if (r == ADMITGEN_RT_SUCCESS) inst->model = model;
  return r;
}

admitgen_rt_result admitgen_rt_reset_q15(admitgen_rt_q15 *inst) {
  if (inst == NULL || inst->model == NULL) return ADMITGEN_RT_NULL_POINTER;
  admitgen_rt__zero(inst->x, admitgen_rt_state_bytes_q15(inst->model, inst->n_nodes));
  inst->head = 0;
  return ADMITGEN_RT_SUCCESS;
}
