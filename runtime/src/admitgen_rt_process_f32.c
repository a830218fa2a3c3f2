/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_process_f32.c - float kernel: small-n path, dispatch of the fused frame pass, FDTD
 * history/commit.
 *
 * Per frame and node (see admitgen_rt.h for the recursion; the state updates in admitgen_rt_internal.h):
 *   acc = d_0 u, acc += d_k u^{n-k} (k = 1..), acc += c x' per real pole, acc += (cr xi' + ci eta') per
 *   pair, in this order on every path, so all paths give identical bits.
 * The delta form keeps eps = 1 - e^{-lambda T} at full float precision for slow poles (a float
 * p = e^{-lambda T} would carry only 2^-24/(lambda T) relative precision in 1 - p).
 *
 * Paths: up to ADMITGEN_RT_SMALL_N nodes, frames inside each term (terms two at a time, so that their
 * recursions overlap: the mono path is bound by their latency); more nodes, one fused pass per frame over
 * blocks of nodes (AVX2 intrinsics when the CPU has them: admitgen_rt_avx2.c).
 */
#include "admitgen_rt_internal.h"

#define ADMITGEN_RT_FBLOCK 16

void admitgen_rt__frame_f32_generic(const admitgen_rt_f32 *inst, const float *in, float *out, int32_t i0, int commit) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes;
  const int32_t rows = m->n_fir - 1, new_head = rows > 0 ? admitgen_rt__ring_advance(inst->head, 1, rows) : 0;
  const float d0 = m->n_fir > 0 ? m->fir[0] : 0.0f;
  int32_t b;
  for (b = i0; b < inst->n_nodes; b += ADMITGEN_RT_FBLOCK) {
    const int32_t nb = inst->n_nodes - b < ADMITGEN_RT_FBLOCK ? inst->n_nodes - b : ADMITGEN_RT_FBLOCK;
    float u[ADMITGEN_RT_FBLOCK], acc[ADMITGEN_RT_FBLOCK];
    int32_t j, k, t;
    for (j = 0; j < nb; ++j) {
      u[j] = in != NULL ? in[b + j] : 0.0f;
      acc[j] = d0 * u[j];
    }
    for (k = 1; k < m->n_fir; ++k) {
      const float d = m->fir[k];
      const float *row = inst->hist + (size_t)admitgen_rt__ring_row(inst->head, k, rows) * n + (size_t)b;
      for (j = 0; j < nb; ++j) acc[j] += d * row[j];
    }
    for (t = 0; t < m->n_real; ++t) {
      const float eps = m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_EPS], c = m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C];
      float *x = inst->x + (size_t)t * n + (size_t)b;
      for (j = 0; j < nb; ++j) {
        const float v = admitgen_rt__real_f32(x[j], u[j], eps);
        if (commit) x[j] = v;
        acc[j] += c * v;
      }
    }
    for (t = 0; t < m->n_pair; ++t) {
      const float *p = m->pair + ADMITGEN_RT_F32_PAIR_WIDTH * t;
      float *xi = inst->xi + (size_t)t * n + (size_t)b, *eta = inst->eta + (size_t)t * n + (size_t)b;
      for (j = 0; j < nb; ++j) {
        const float a1 = admitgen_rt__xi_f32(xi[j], eta[j], u[j], p[ADMITGEN_RT_F32_PAIR_ER], p[ADMITGEN_RT_F32_PAIR_PI], p[ADMITGEN_RT_F32_PAIR_G]);
        const float e1 = admitgen_rt__eta_f32(xi[j], eta[j], p[ADMITGEN_RT_F32_PAIR_ER], p[ADMITGEN_RT_F32_PAIR_PI]);
        if (commit) {
          xi[j] = a1;
          eta[j] = e1;
        }
        acc[j] += p[ADMITGEN_RT_F32_PAIR_CR] * a1 + p[ADMITGEN_RT_F32_PAIR_CI] * e1;
      }
    }
    if (out != NULL)
      for (j = 0; j < nb; ++j) out[b + j] = acc[j];
    if (commit && rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
      float *row = inst->hist + (size_t)new_head * n + (size_t)b;
      for (j = 0; j < nb; ++j) row[j] = u[j];
    }
  }
}

/* ---- small-n path: one node, a chunk of nf frames; acc[f] collects the terms in the canonical order ---- */

typedef struct admitgen_rt__rterm {
  float *x;
  float eps, c;
} admitgen_rt__rterm;

typedef struct admitgen_rt__pterm {
  float *xi, *eta;
  float er, pi, g, cr, ci;
} admitgen_rt__pterm;

static admitgen_rt__rterm admitgen_rt__rterm_at(const admitgen_rt_f32 *inst, int32_t t, int32_t i) {
  admitgen_rt__rterm r;
  r.x = inst->x + (size_t)t * (size_t)inst->n_nodes + (size_t)i;
  r.eps = inst->model->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_EPS];
  r.c = inst->model->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C];
  return r;
}

static admitgen_rt__pterm admitgen_rt__pterm_at(const admitgen_rt_f32 *inst, int32_t t, int32_t i) {
  const float *p = inst->model->pair + ADMITGEN_RT_F32_PAIR_WIDTH * t;
  admitgen_rt__pterm q;
  q.xi = inst->xi + (size_t)t * (size_t)inst->n_nodes + (size_t)i;
  q.eta = inst->eta + (size_t)t * (size_t)inst->n_nodes + (size_t)i;
  q.er = p[ADMITGEN_RT_F32_PAIR_ER];
  q.pi = p[ADMITGEN_RT_F32_PAIR_PI];
  q.g = p[ADMITGEN_RT_F32_PAIR_G];
  q.cr = p[ADMITGEN_RT_F32_PAIR_CR];
  q.ci = p[ADMITGEN_RT_F32_PAIR_CI];
  return q;
}

static void admitgen_rt__chunk_r(float *acc, const float *u, int32_t nf, admitgen_rt__rterm r) {
  float x = *r.x;
  int32_t f;
  for (f = 0; f < nf; ++f) {
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    acc[f] += r.c * x;
  }
  *r.x = x;
}

static void admitgen_rt__chunk_p(float *acc, const float *u, int32_t nf, admitgen_rt__pterm p) {
  float a = *p.xi, e = *p.eta;
  int32_t f;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    a = a1;
    acc[f] += p.cr * a + p.ci * e;
  }
  *p.xi = a;
  *p.eta = e;
}

static void admitgen_rt__chunk_rr(float *acc, const float *u, int32_t nf, admitgen_rt__rterm r, admitgen_rt__rterm s) {
  float x = *r.x, y = *s.x;
  int32_t f;
  for (f = 0; f < nf; ++f) {
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    y = admitgen_rt__real_f32(y, u[f], s.eps);
    acc[f] += r.c * x;
    acc[f] += s.c * y;
  }
  *r.x = x;
  *s.x = y;
}

static void admitgen_rt__chunk_rp(float *acc, const float *u, int32_t nf, admitgen_rt__rterm r, admitgen_rt__pterm p) {
  float x = *r.x, a = *p.xi, e = *p.eta;
  int32_t f;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    a = a1;
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    acc[f] += r.c * x;
    acc[f] += p.cr * a + p.ci * e;
  }
  *r.x = x;
  *p.xi = a;
  *p.eta = e;
}

static void admitgen_rt__chunk_pp(float *acc, const float *u, int32_t nf, admitgen_rt__pterm p, admitgen_rt__pterm q) {
  float a = *p.xi, e = *p.eta, b = *q.xi, h = *q.eta;
  int32_t f;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    const float b1 = admitgen_rt__xi_f32(b, h, u[f], q.er, q.pi, q.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    h = admitgen_rt__eta_f32(b, h, q.er, q.pi);
    a = a1;
    b = b1;
    acc[f] += p.cr * a + p.ci * e;
    acc[f] += q.cr * b + q.ci * h;
  }
  *p.xi = a;
  *p.eta = e;
  *q.xi = b;
  *q.eta = h;
}

/* Terms in the canonical order (reals, then pairs), two per pass over the chunk. */
static void admitgen_rt__chunk_terms(const admitgen_rt_f32 *inst, float *acc, const float *u, int32_t i, int32_t nf) {
  const int32_t nr = inst->model->n_real, nt = nr + inst->model->n_pair;
  int32_t t = 0;
  for (; t + 1 < nt; t += 2) {
    if (t + 1 < nr)
      admitgen_rt__chunk_rr(acc, u, nf, admitgen_rt__rterm_at(inst, t, i), admitgen_rt__rterm_at(inst, t + 1, i));
    else if (t < nr)
      admitgen_rt__chunk_rp(acc, u, nf, admitgen_rt__rterm_at(inst, t, i), admitgen_rt__pterm_at(inst, t + 1 - nr, i));
    else
      admitgen_rt__chunk_pp(acc, u, nf, admitgen_rt__pterm_at(inst, t - nr, i), admitgen_rt__pterm_at(inst, t + 1 - nr, i));
  }
  if (t < nt) {
    if (t < nr)
      admitgen_rt__chunk_r(acc, u, nf, admitgen_rt__rterm_at(inst, t, i));
    else
      admitgen_rt__chunk_p(acc, u, nf, admitgen_rt__pterm_at(inst, t - nr, i));
  }
}

/* Node i, frames [f0, f0 + nf), nf <= ADMITGEN_RT_CHUNK; ub = past inputs (oldest first), then the chunk's. */
static void admitgen_rt__chunk_f32(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t stride, int32_t i,
                                   int32_t f0, int32_t nf) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes;
  const int32_t rows = m->n_fir > 1 ? m->n_fir - 1 : 0;
  float ub[64 + ADMITGEN_RT_CHUNK], acc[ADMITGEN_RT_CHUNK];
  const float *u = ub + rows;
  const float d0 = m->n_fir > 0 ? m->fir[0] : 0.0f;
  int32_t f, k;
  for (k = 1; k <= rows; ++k) ub[rows - k] = inst->hist[(size_t)admitgen_rt__ring_row(inst->head, k, rows) * n + (size_t)i];
  for (f = 0; f < nf; ++f) {
    ub[rows + f] = pIn[(size_t)(f0 + f) * (size_t)stride + (size_t)i];
    acc[f] = d0 * u[f];
  }
  for (k = 1; k < m->n_fir; ++k) {
    const float d = m->fir[k];
    for (f = 0; f < nf; ++f) acc[f] += d * u[f - k];
  }
  admitgen_rt__chunk_terms(inst, acc, u, i, nf);
  if (pOut != NULL)
    for (f = 0; f < nf; ++f) pOut[(size_t)(f0 + f) * (size_t)stride + (size_t)i] = acc[f];
  if (rows > 0) {
    const int32_t new_head = admitgen_rt__ring_advance(inst->head, nf, rows);
    for (k = 1; k <= rows; ++k) inst->hist[(size_t)admitgen_rt__ring_row(new_head, k, rows) * n + (size_t)i] = u[nf - k];
  }
}

/* One frame over every node: AVX2 blocks first when the CPU has them, the generic pass for the rest. */
static void admitgen_rt__frame_f32(const admitgen_rt_f32 *inst, const float *in, float *out, int commit, int simd) {
  int32_t done = 0;
#if ADMITGEN_RT_HAVE_AVX2
  if (simd) done = admitgen_rt__frame_f32_avx2(inst, in, out, commit);
#else
  (void)simd;
#endif
  if (done < inst->n_nodes) admitgen_rt__frame_f32_generic(inst, in, out, done, commit);
}

void admitgen_rt__process_f32_isa(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames,
                                  int32_t stride, int isa) {
  const int32_t rows = inst->model->n_fir - 1;
  int32_t f;
  if (inst->n_nodes <= ADMITGEN_RT_SMALL_N) {
    for (f = 0; f < n_frames; f += ADMITGEN_RT_CHUNK) {
      const int32_t nf = n_frames - f < ADMITGEN_RT_CHUNK ? n_frames - f : ADMITGEN_RT_CHUNK;
      int32_t i;
      for (i = 0; i < inst->n_nodes; ++i) admitgen_rt__chunk_f32(inst, pIn, pOut, stride, i, f, nf);
      if (rows > 0) inst->head = admitgen_rt__ring_advance(inst->head, nf, rows);
    }
  } else {
    const int simd = admitgen_rt__use_simd(isa);
    for (f = 0; f < n_frames; ++f) {
      admitgen_rt__frame_f32(inst, pIn + (size_t)f * (size_t)stride, pOut != NULL ? pOut + (size_t)f * (size_t)stride : NULL,
                             1, simd);
      if (rows > 0) inst->head = admitgen_rt__ring_advance(inst->head, 1, rows);
    }
  }
}

admitgen_rt_result admitgen_rt_process_f32(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames, int32_t stride) {
  const admitgen_rt_result r =
      inst == NULL ? ADMITGEN_RT_NULL_POINTER : admitgen_rt__check_call(inst->model, inst->n_nodes, pIn, n_frames, stride);
  if (r == ADMITGEN_RT_SUCCESS && n_frames > 0) admitgen_rt__process_f32_isa(inst, pIn, pOut, n_frames, stride, ADMITGEN_RT_ISA_BEST);
  return r;
}

admitgen_rt_result admitgen_rt_history_f32(const admitgen_rt_f32 *inst, float *pHist) {
  /* s^{n-1}: the frame pass with u = 0, states and ring left unchanged */
  if (inst == NULL || inst->model == NULL || pHist == NULL) return ADMITGEN_RT_NULL_POINTER;
  admitgen_rt__frame_f32(inst, NULL, pHist, 0, admitgen_rt__use_simd(ADMITGEN_RT_ISA_BEST));
  return ADMITGEN_RT_SUCCESS;
}

admitgen_rt_result admitgen_rt_commit_f32(admitgen_rt_f32 *inst, const float *pU, float *pY) {
  return inst == NULL ? ADMITGEN_RT_NULL_POINTER : admitgen_rt_process_f32(inst, pU, pY, 1, inst->n_nodes);
}
