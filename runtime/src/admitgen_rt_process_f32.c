/*
 * admitgen_rt_process_f32.c - float kernel: block processing, FDTD history/commit.
 *
 * Per frame and node (see admitgen_rt.h for the recursion):
 *   acc = d_0 u + sum_{k>=1} d_k u^{n-k};  x += eps (u - x), acc += c x;
 *   xi' = xi + (e_r xi - p_i eta + g u), eta' = eta + (e_r eta + p_i xi), acc += cr xi' + ci eta'.
 * The delta form keeps eps = 1 - e^{-lambda T} at full float precision for slow poles (a float
 * p = e^{-lambda T} would carry only 2^-24/(lambda T) relative precision in 1 - p).
 *
 * Loop order: frames outer, terms middle, nodes inner (structure-of-arrays: one vectorisable loop per term).
 */
#include "admitgen_rt_internal.h"

static void admitgen_rt__frame_f32(admitgen_rt_f32 *inst) {
  const admitgen_rt_model_f32 *m = inst->model;
  const int32_t n = inst->n_nodes, rows = m->n_fir - 1;
  float *ADMITGEN_RT_RESTRICT acc = inst->acc;
  const float *ADMITGEN_RT_RESTRICT u = inst->u;
  int32_t i, k, t;
  const float d0 = m->n_fir > 0 ? m->fir[0] : 0.0f;
  for (i = 0; i < n; ++i) acc[i] = d0 * u[i];
  for (k = 1; k < m->n_fir; ++k) {
    const float d = m->fir[k];
    const int32_t r = inst->head + k - 1 < rows ? inst->head + k - 1 : inst->head + k - 1 - rows; /* no division */
    const float *ADMITGEN_RT_RESTRICT row = inst->hist + (size_t)r * (size_t)n;
    for (i = 0; i < n; ++i) acc[i] += d * row[i];
  }
  for (t = 0; t < m->n_real; ++t) {
    const float eps = m->real[2 * t], c = m->real[2 * t + 1];
    float *ADMITGEN_RT_RESTRICT x = inst->x + (size_t)t * (size_t)n;
    for (i = 0; i < n; ++i) {
      const float v = x[i] + eps * (u[i] - x[i]);
      x[i] = v;
      acc[i] += c * v;
    }
  }
  for (t = 0; t < m->n_pair; ++t) {
    const float *p = m->pair + 5 * t;
    const float er = p[0], pi = p[1], g = p[2], cr = p[3], ci = p[4];
    float *ADMITGEN_RT_RESTRICT xi = inst->xi + (size_t)t * (size_t)n;
    float *ADMITGEN_RT_RESTRICT eta = inst->eta + (size_t)t * (size_t)n;
    for (i = 0; i < n; ++i) {
      const float a = xi[i], b = eta[i];
      const float a1 = a + (er * a - pi * b + g * u[i]);
      const float b1 = b + (er * b + pi * a);
      xi[i] = a1;
      eta[i] = b1;
      acc[i] += cr * a1 + ci * b1;
    }
  }
  if (rows > 0) {
    float *row;
    inst->head = inst->head == 0 ? rows - 1 : inst->head - 1;
    row = inst->hist + (size_t)inst->head * (size_t)n;
    for (i = 0; i < n; ++i) row[i] = u[i];
  }
}

void admitgen_rt_process_f32(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames, int32_t stride) {
  const int32_t n = inst->n_nodes;
  int32_t f, i;
  for (f = 0; f < n_frames; ++f) {
    const float *src = pIn + (size_t)f * (size_t)stride;
    for (i = 0; i < n; ++i) inst->u[i] = src[i];
    admitgen_rt__frame_f32(inst);
    if (pOut != NULL) {
      float *dst = pOut + (size_t)f * (size_t)stride;
      for (i = 0; i < n; ++i) dst[i] = inst->acc[i];
    }
  }
}

void admitgen_rt_history_f32(const admitgen_rt_f32 *inst, float *pHist) {
  /* s^{n-1} = sum_{k>=1} d_k u^{n-k} + sum_q c (1 - eps) x + sum_s [cr (xi + e_r xi - p_i eta) + ci (eta + e_r eta + p_i xi)] */
  const admitgen_rt_model_f32 *m = inst->model;
  const int32_t n = inst->n_nodes, rows = m->n_fir - 1;
  int32_t i, k, t;
  for (i = 0; i < n; ++i) pHist[i] = 0.0f;
  for (k = 1; k < m->n_fir; ++k) {
    const float d = m->fir[k];
    const float *row = inst->hist + (size_t)((inst->head + k - 1) % rows) * (size_t)n;
    for (i = 0; i < n; ++i) pHist[i] += d * row[i];
  }
  for (t = 0; t < m->n_real; ++t) {
    const float eps = m->real[2 * t], c = m->real[2 * t + 1];
    const float *x = inst->x + (size_t)t * (size_t)n;
    for (i = 0; i < n; ++i) pHist[i] += c * (x[i] - eps * x[i]);
  }
  for (t = 0; t < m->n_pair; ++t) {
    const float *p = m->pair + 5 * t;
    const float *xi = inst->xi + (size_t)t * (size_t)n, *eta = inst->eta + (size_t)t * (size_t)n;
    for (i = 0; i < n; ++i) {
      const float a = xi[i], b = eta[i];
      pHist[i] += p[3] * (a + (p[0] * a - p[1] * b)) + p[4] * (b + (p[0] * b + p[1] * a));
    }
  }
}

void admitgen_rt_commit_f32(admitgen_rt_f32 *inst, const float *pU, float *pY) {
  admitgen_rt_process_f32(inst, pU, pY, 1, inst->n_nodes);
}
