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
 * recursions overlap: the mono path is bound by their latency; two forms, below); more nodes, one fused pass
 * per frame over blocks of nodes (AVX2 or AVX-512 intrinsics when the CPU has them: admitgen_rt_avx2.c).
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

/* ---- small-n path: per node, a chunk of frames at a time ----
 * A term's recursion is latency-bound (the pair's xi -> eta -> xi cycle; docs/runtime.md, "Desktop
 * figures"), so a recursion pass runs two terms side by side (their chains overlap). Two forms, the same
 * results (every output is d_0 u, + d_k u^{n-k}, + c x' per real pole, + (cr xi' + ci eta') per pair, in this
 * order):
 *  - trajectories (ADMITGEN_RT_SMALLN_TRAJ 1: targets with a vector unit): the recursion pass holds nothing but
 *    the recursions and writes the new state of every frame to a trajectory; one output pass then forms the
 *    outputs ADMITGEN_RT_FV frames at a time in vector registers. With the output products inside the
 *    recursion loop a Zen 5 took 15 cycles per sample instead of about 10: they compete with the recursion for
 *    the multiply and add pipes.
 *  - accumulators (0: 32-bit MCUs and other scalar cores): the FIR over the chunk into acc[f], then each
 *    recursion pass adds its terms to acc[f]; no trajectory is stored and read back (Cortex-M4F: 86 instead of
 *    115 instructions per sample). */
#ifndef ADMITGEN_RT_SMALLN_TRAJ
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_NEON))
#define ADMITGEN_RT_SMALLN_TRAJ 1
#else
#define ADMITGEN_RT_SMALLN_TRAJ 0
#endif
#endif

/* Inlined into each caller (the last pass is instantiated once per kind: admitgen_rt__last_pass_out). */
#if defined(__GNUC__) || defined(__clang__)
#define ADMITGEN_RT_INLINE static inline __attribute__((always_inline))
#else
#define ADMITGEN_RT_INLINE static inline
#endif

/* Frames per chunk of the small-n path: ADMITGEN_RT_CHUNK on scalar cores (MCU stack); 64 in the trajectory form
 * (desktop: halves the per-chunk work of 32, measured 3.05 -> 2.76 ns per sample on a Zen 5). */
#if ADMITGEN_RT_SMALLN_TRAJ
#ifndef ADMITGEN_RT_FCHUNK
#define ADMITGEN_RT_FCHUNK 64
#endif
#else
#define ADMITGEN_RT_FCHUNK ADMITGEN_RT_CHUNK
#endif
/* Trajectory floats per chunk (stack, 1 KiB): a chunk has ADMITGEN_RT_FCHUNK frames while the model has at most
 * 4 states (Q1S1, Q0S2, ...), half as many up to 8 states, and so on; a model of more states than this (at
 * most 3 ADMITGEN_RT_MAX_TERMS) runs on the block path. */
#define ADMITGEN_RT_TRAJ (4 * ADMITGEN_RT_FCHUNK)
/* Frames per step of the output pass (two 4-float vectors). */
#define ADMITGEN_RT_FV 8

/* An empty asm that the value passes through: GCC's SLP vectoriser would otherwise pack two recursions'
 * updates (x and xi, or xi and eta) into one vector register, adding shuffles to the latency-bound chain
 * (measured 4.2 instead of 2.9 ns per sample); the value and its rounding are untouched. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define ADMITGEN_RT_SCALAR(v) __asm__("" : "+x"(v))
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
#define ADMITGEN_RT_SCALAR(v) __asm__("" : "+w"(v))
#else
#define ADMITGEN_RT_SCALAR(v) ((void)0)
#endif

#if ADMITGEN_RT_SMALLN_TRAJ /* the new state of term j, frame f: to its trajectory t */
#define ADMITGEN_RT_EMIT_R(acc, f, t, x, c) ((t)[f] = (x))
#define ADMITGEN_RT_EMIT_P(acc, f, ta, te, a, e, cr, ci) ((ta)[f] = (a), (te)[f] = (e))
#else /* ... or its contribution to the output */
#define ADMITGEN_RT_EMIT_R(acc, f, t, x, c) ((acc)[f] += (c) * (x))
#define ADMITGEN_RT_EMIT_P(acc, f, ta, te, a, e, cr, ci) ((acc)[f] += (cr) * (a) + (ci) * (e))
#endif

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

/* Recursion passes over nf frames (trajectories tx of a real pole, ta and te of a pair's xi and eta; or the
 * accumulators acc: ADMITGEN_RT_EMIT_*), terms emitted in the canonical order. */
static void admitgen_rt__pass_r(float *acc, float *tx, const float *u, int32_t nf, admitgen_rt__rterm r) {
  float x = *r.x;
  int32_t f;
  (void)acc;
  (void)tx;
  for (f = 0; f < nf; ++f) {
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    ADMITGEN_RT_SCALAR(x);
    ADMITGEN_RT_EMIT_R(acc, f, tx, x, r.c);
  }
  *r.x = x;
}

static void admitgen_rt__pass_p(float *acc, float *ta, float *te, const float *u, int32_t nf, admitgen_rt__pterm p) {
  float a = *p.xi, e = *p.eta;
  int32_t f;
  (void)acc;
  (void)ta;
  (void)te;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    a = a1;
    ADMITGEN_RT_SCALAR(a);
    ADMITGEN_RT_SCALAR(e);
    ADMITGEN_RT_EMIT_P(acc, f, ta, te, a, e, p.cr, p.ci);
  }
  *p.xi = a;
  *p.eta = e;
}

static void admitgen_rt__pass_rr(float *acc, float *tx, float *ty, const float *u, int32_t nf, admitgen_rt__rterm r,
                                 admitgen_rt__rterm s) {
  float x = *r.x, y = *s.x;
  int32_t f;
  (void)acc;
  (void)tx;
  (void)ty;
  for (f = 0; f < nf; ++f) {
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    y = admitgen_rt__real_f32(y, u[f], s.eps);
    ADMITGEN_RT_SCALAR(x);
    ADMITGEN_RT_SCALAR(y);
    ADMITGEN_RT_EMIT_R(acc, f, tx, x, r.c);
    ADMITGEN_RT_EMIT_R(acc, f, ty, y, s.c);
  }
  *r.x = x;
  *s.x = y;
}

static void admitgen_rt__pass_rp(float *acc, float *tx, float *ta, float *te, const float *u, int32_t nf,
                                 admitgen_rt__rterm r, admitgen_rt__pterm p) {
  float x = *r.x, a = *p.xi, e = *p.eta;
  int32_t f;
  (void)acc;
  (void)tx;
  (void)ta;
  (void)te;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    a = a1;
    x = admitgen_rt__real_f32(x, u[f], r.eps);
    ADMITGEN_RT_SCALAR(x);
    ADMITGEN_RT_SCALAR(a);
    ADMITGEN_RT_SCALAR(e);
    ADMITGEN_RT_EMIT_R(acc, f, tx, x, r.c);
    ADMITGEN_RT_EMIT_P(acc, f, ta, te, a, e, p.cr, p.ci);
  }
  *r.x = x;
  *p.xi = a;
  *p.eta = e;
}

static void admitgen_rt__pass_pp(float *acc, float *ta, float *te, float *tb, float *th, const float *u, int32_t nf,
                                 admitgen_rt__pterm p, admitgen_rt__pterm q) {
  float a = *p.xi, e = *p.eta, b = *q.xi, h = *q.eta;
  int32_t f;
  (void)acc;
  (void)ta;
  (void)te;
  (void)tb;
  (void)th;
  for (f = 0; f < nf; ++f) {
    const float a1 = admitgen_rt__xi_f32(a, e, u[f], p.er, p.pi, p.g);
    const float b1 = admitgen_rt__xi_f32(b, h, u[f], q.er, q.pi, q.g);
    e = admitgen_rt__eta_f32(a, e, p.er, p.pi);
    h = admitgen_rt__eta_f32(b, h, q.er, q.pi);
    a = a1;
    b = b1;
    ADMITGEN_RT_SCALAR(a);
    ADMITGEN_RT_SCALAR(e);
    ADMITGEN_RT_SCALAR(b);
    ADMITGEN_RT_SCALAR(h);
    ADMITGEN_RT_EMIT_P(acc, f, ta, te, a, e, p.cr, p.ci);
    ADMITGEN_RT_EMIT_P(acc, f, tb, th, b, h, q.cr, q.ci);
  }
  *p.xi = a;
  *p.eta = e;
  *q.xi = b;
  *q.eta = h;
}

/* The recursions of terms [0, nt) over nf frames, two terms per pass, in the canonical order; trajectory j (reals
 * in order, then xi and eta of each pair) at tr + j * len (accumulator form: len 0, tr unused). */
ADMITGEN_RT_INLINE void admitgen_rt__chunk_terms(const admitgen_rt_f32 *inst, float *acc, float *tr, int32_t len,
                                                 const float *u, int32_t i, int32_t nf, int32_t nt) {
  const int32_t nr = inst->model->n_real;
  int32_t t = 0;
  for (; t + 1 < nt; t += 2) {
    float *at = tr + (size_t)(t < nr ? t : 2 * t - nr) * (size_t)len; /* trajectory of term t */
    if (t + 1 < nr)
      admitgen_rt__pass_rr(acc, at, at + len, u, nf, admitgen_rt__rterm_at(inst, t, i), admitgen_rt__rterm_at(inst, t + 1, i));
    else if (t < nr)
      admitgen_rt__pass_rp(acc, at, at + len, at + 2 * len, u, nf, admitgen_rt__rterm_at(inst, t, i),
                           admitgen_rt__pterm_at(inst, t + 1 - nr, i));
    else
      admitgen_rt__pass_pp(acc, at, at + len, at + 2 * len, at + 3 * len, u, nf, admitgen_rt__pterm_at(inst, t - nr, i),
                           admitgen_rt__pterm_at(inst, t + 1 - nr, i));
  }
  if (t < nt) {
    float *at = tr + (size_t)(t < nr ? t : 2 * t - nr) * (size_t)len;
    if (t < nr)
      admitgen_rt__pass_r(acc, at, u, nf, admitgen_rt__rterm_at(inst, t, i));
    else
      admitgen_rt__pass_p(acc, at, at + len, u, nf, admitgen_rt__pterm_at(inst, t - nr, i));
  }
}

#if ADMITGEN_RT_SMALLN_TRAJ
/* Outputs of frames [f, f + w) in the canonical order, into y[f..]: one frame at a time. */
static void admitgen_rt__out_frames(const admitgen_rt_model_f32 *m, const float *u, const float *tr, int32_t len,
                                    int32_t f, int32_t w, float *y) {
  int32_t j, k, t;
  for (j = f; j < f + w; ++j) {
    float v = (m->n_fir > 0 ? m->fir[0] : 0.0f) * u[j];
    for (k = 1; k < m->n_fir; ++k) v += m->fir[k] * u[j - k];
    for (t = 0; t < m->n_real; ++t) v += m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C] * tr[(size_t)t * (size_t)len + (size_t)j];
    for (t = 0; t < m->n_pair; ++t) {
      const float *a = tr + (size_t)(m->n_real + 2 * t) * (size_t)len + (size_t)j;
      v += m->pair[ADMITGEN_RT_F32_PAIR_WIDTH * t + ADMITGEN_RT_F32_PAIR_CR] * a[0] + m->pair[ADMITGEN_RT_F32_PAIR_WIDTH * t + ADMITGEN_RT_F32_PAIR_CI] * a[len];
    }
    y[j] = v;
  }
}

/* The same, ADMITGEN_RT_FV = 8 frames in two 4-float vectors (GCC/Clang vector extension: SSE on x86-64, NEON
 * on aarch64); the same operations lane by lane. Vectors are moved with memcpy (no alignment or aliasing
 * assumption) and never passed by value (no ABI question). */
typedef float admitgen_rt__v4 __attribute__((vector_size(16)));
#define ADMITGEN_RT_V4_LOAD2(lo, hi, p) (__builtin_memcpy(&(lo), (p), 16), __builtin_memcpy(&(hi), (p) + 4, 16))
ADMITGEN_RT_INLINE void admitgen_rt__out_vec(const admitgen_rt_model_f32 *m, const float *u, const float *tr, int32_t len, int32_t f,
                                 float *y) {
  admitgen_rt__v4 v0, v1, a0, a1, b0, b1;
  int32_t k, t;
  float c = m->n_fir > 0 ? m->fir[0] : 0.0f;
  ADMITGEN_RT_V4_LOAD2(a0, a1, u + f);
  v0 = c * a0;
  v1 = c * a1;
  for (k = 1; k < m->n_fir; ++k) {
    c = m->fir[k];
    ADMITGEN_RT_V4_LOAD2(a0, a1, u + f - k);
    v0 += c * a0;
    v1 += c * a1;
  }
  for (t = 0; t < m->n_real; ++t) {
    c = m->real[ADMITGEN_RT_F32_REAL_WIDTH * t + ADMITGEN_RT_F32_REAL_C];
    ADMITGEN_RT_V4_LOAD2(a0, a1, tr + (size_t)t * (size_t)len + (size_t)f);
    v0 += c * a0;
    v1 += c * a1;
  }
  for (t = 0; t < m->n_pair; ++t) {
    const float *a = tr + (size_t)(m->n_real + 2 * t) * (size_t)len + (size_t)f;
    const float cr = m->pair[ADMITGEN_RT_F32_PAIR_WIDTH * t + ADMITGEN_RT_F32_PAIR_CR], ci = m->pair[ADMITGEN_RT_F32_PAIR_WIDTH * t + ADMITGEN_RT_F32_PAIR_CI];
    ADMITGEN_RT_V4_LOAD2(a0, a1, a);
    ADMITGEN_RT_V4_LOAD2(b0, b1, a + len);
    v0 += cr * a0 + ci * b0;
    v1 += cr * a1 + ci * b1;
  }
  __builtin_memcpy(y + f, &v0, 16);
  __builtin_memcpy(y + f + 4, &v1, 16);
}
#endif

#if ADMITGEN_RT_SMALLN_TRAJ
/* Frames [f, f + w) of the last recursion pass (kind: see admitgen_rt__last_pass_out). */
ADMITGEN_RT_INLINE void admitgen_rt__last_pass_block(int kind, float *at, int32_t len, const float *u, int32_t f, int32_t w,
                                                     admitgen_rt__rterm r0, admitgen_rt__rterm r1, admitgen_rt__pterm p0,
                                                     admitgen_rt__pterm p1) {
  switch (kind) {
    case 1: admitgen_rt__pass_r(NULL, at + f, u + f, w, r0); break;
    case 2: admitgen_rt__pass_p(NULL, at + f, at + len + f, u + f, w, p0); break;
    case 3: admitgen_rt__pass_rr(NULL, at + f, at + len + f, u + f, w, r0, r1); break;
    case 4: admitgen_rt__pass_rp(NULL, at + f, at + len + f, at + 2 * len + f, u + f, w, r0, p0); break;
    case 5: admitgen_rt__pass_pp(NULL, at + f, at + len + f, at + 2 * len + f, at + 3 * len + f, u + f, w, p0, p1); break;
    default: break;
  }
}

/* The last recursion pass of a chunk (terms t.. to the end: one or two), software-pipelined with the output pass:
 * ADMITGEN_RT_FV frames of recursion, then the outputs of the previous ADMITGEN_RT_FV frames (whose trajectories
 * are complete), so that the out-of-order core runs the independent output work beside the latency-bound
 * recursion (measured 3.29 -> 3.08 ns per sample on a Zen 5). The pass's states stay in locals across blocks. */
ADMITGEN_RT_INLINE void admitgen_rt__last_pass_kind(const int kind, const admitgen_rt_f32 *inst, float *tr, int32_t len,
                                                    const float *u, int32_t i, int32_t nf, int32_t t, float *y) {
  const admitgen_rt_model_f32 *m = inst->model;
  const int32_t nr = m->n_real;
  float *at = tr + (size_t)(t < nr ? t : 2 * t - nr) * (size_t)len; /* trajectory of term t */
  float *home[4] = {NULL, NULL, NULL, NULL}, st[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  admitgen_rt__rterm r0, r1;
  admitgen_rt__pterm p0, p1;
  int32_t f, w = 0, j;
  r0 = r1 = admitgen_rt__rterm_at(inst, 0, i);
  p0 = p1 = admitgen_rt__pterm_at(inst, 0, i);
  if (kind == 1 || kind == 3 || kind == 4) {
    r0 = admitgen_rt__rterm_at(inst, t, i);
    home[0] = r0.x;
    r0.x = &st[0];
  }
  if (kind == 3) {
    r1 = admitgen_rt__rterm_at(inst, t + 1, i);
    home[1] = r1.x;
    r1.x = &st[1];
  }
  if (kind == 2 || kind == 5 || kind == 4) {
    p0 = admitgen_rt__pterm_at(inst, kind == 4 ? t + 1 - nr : t - nr, i);
    home[0 + (kind == 4)] = p0.xi; /* rp: the real pole's state is st[0] */
    home[2] = p0.eta;
    p0.xi = &st[0 + (kind == 4)];
    p0.eta = &st[2];
  }
  if (kind == 5) {
    p1 = admitgen_rt__pterm_at(inst, t + 1 - nr, i);
    home[1] = p1.xi;
    home[3] = p1.eta;
    p1.xi = &st[1];
    p1.eta = &st[3];
  }
  for (j = 0; j < 4; ++j)
    if (home[j] != NULL) st[j] = *home[j];
  for (f = 0; f + ADMITGEN_RT_FV <= nf; f += ADMITGEN_RT_FV) { /* full blocks: a constant trip count */
    admitgen_rt__last_pass_block(kind, at, len, u, f, ADMITGEN_RT_FV, r0, r1, p0, p1);
    if (f > 0) admitgen_rt__out_vec(m, u, tr, len, f - ADMITGEN_RT_FV, y);
  }
  w = nf - f;
  if (w > 0) admitgen_rt__last_pass_block(kind, at, len, u, f, w, r0, r1, p0, p1);
  if (f > 0) admitgen_rt__out_vec(m, u, tr, len, f - ADMITGEN_RT_FV, y);
  if (w > 0) admitgen_rt__out_frames(m, u, tr, len, f, w, y);
  for (j = 0; j < 4; ++j)
    if (home[j] != NULL) *home[j] = st[j];
}

/* kind: the terms of the last pass, 0 none, 1 r, 2 p, 3 rr, 4 rp, 5 pp; one copy of the pipelined loop per kind
 * (a constant kind lets the compiler keep the pass's states in registers across blocks). */
ADMITGEN_RT_INLINE void admitgen_rt__last_pass_out(const admitgen_rt_f32 *inst, float *tr, int32_t len, const float *u,
                                                   int32_t i, int32_t nf, int32_t t, float *y) {
  const int32_t nr = inst->model->n_real, nt = nr + inst->model->n_pair;
  const int kind = t >= nt ? 0 : t + 1 == nt ? (t < nr ? 1 : 2) : t + 1 < nr ? 3 : t < nr ? 4 : 5;
  switch (kind) {
    case 1: admitgen_rt__last_pass_kind(1, inst, tr, len, u, i, nf, t, y); break;
    case 2: admitgen_rt__last_pass_kind(2, inst, tr, len, u, i, nf, t, y); break;
    case 3: admitgen_rt__last_pass_kind(3, inst, tr, len, u, i, nf, t, y); break;
    case 4: admitgen_rt__last_pass_kind(4, inst, tr, len, u, i, nf, t, y); break;
    case 5: admitgen_rt__last_pass_kind(5, inst, tr, len, u, i, nf, t, y); break;
    default: admitgen_rt__last_pass_kind(0, inst, tr, len, u, i, nf, t, y); break;
  }
}
#endif

/* Node i, frames [f0, f0 + nf), nf <= len (the chunk length); ub = past inputs (oldest first), then the
 * chunk's. */
ADMITGEN_RT_INLINE void admitgen_rt__chunk_body(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t stride,
                                                int32_t i, int32_t f0, int32_t nf, int32_t len) {
  const admitgen_rt_model_f32 *m = inst->model;
  const size_t n = (size_t)inst->n_nodes;
  const int32_t rows = m->n_fir > 1 ? m->n_fir - 1 : 0;
  float ub[ADMITGEN_RT_MAX_TERMS + ADMITGEN_RT_FCHUNK];
#if ADMITGEN_RT_SMALLN_TRAJ
  float tr[ADMITGEN_RT_TRAJ];
  /* mono: straight into the output; else into the first trajectory (tr has room for len frames), whose frame f
   * the output pass reads before it writes output frame f */
  float *y = pOut != NULL && stride == 1 ? pOut + f0 : tr;
#else
  float y[ADMITGEN_RT_FCHUNK];
  const float d0 = m->n_fir > 0 ? m->fir[0] : 0.0f;
#endif
  const float *u = ub + rows;
  int32_t f, k;
  for (k = 1; k <= rows; ++k) ub[rows - k] = inst->hist[(size_t)admitgen_rt__ring_row(inst->head, k, rows) * n + (size_t)i];
  if (stride == 1)
    for (f = 0; f < nf; ++f) ub[rows + f] = pIn[f0 + f];
  else
    for (f = 0; f < nf; ++f) ub[rows + f] = pIn[(size_t)(f0 + f) * (size_t)stride + (size_t)i];
#if ADMITGEN_RT_SMALLN_TRAJ
  {
    const int32_t nt = m->n_real + m->n_pair, last = nt > 0 ? (nt - 1) / 2 * 2 : 0; /* first term of the last pass */
    admitgen_rt__chunk_terms(inst, NULL, tr, len, u, i, nf, last);
    admitgen_rt__last_pass_out(inst, tr, len, u, i, nf, last, y);
  }
  if (pOut != NULL && y == tr)
#else
  (void)len;
  for (f = 0; f < nf; ++f) y[f] = d0 * u[f];
  for (k = 1; k < m->n_fir; ++k) {
    const float d = m->fir[k];
    for (f = 0; f < nf; ++f) y[f] += d * u[f - k];
  }
  admitgen_rt__chunk_terms(inst, y, y, 0, u, i, nf, m->n_real + m->n_pair);
  if (pOut != NULL)
#endif
    for (f = 0; f < nf; ++f) pOut[(size_t)(f0 + f) * (size_t)stride + (size_t)i] = y[f];
  if (rows > 0) {
    const int32_t new_head = admitgen_rt__ring_advance(inst->head, nf, rows);
    for (k = 1; k <= rows; ++k) inst->hist[(size_t)admitgen_rt__ring_row(new_head, k, rows) * n + (size_t)i] = u[nf - k];
  }
}

static void admitgen_rt__chunk_f32(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t stride, int32_t i,
                                   int32_t f0, int32_t nf, int32_t len) {
  admitgen_rt__chunk_body(inst, pIn, pOut, stride, i, f0, nf, len);
}

/* One frame over every node: AVX-512 and AVX2 blocks first when the CPU has them, the generic pass for the rest. */
static void admitgen_rt__frame_f32(const admitgen_rt_f32 *inst, const float *in, float *out, int commit, int simd) {
  int32_t done = 0;
#if ADMITGEN_RT_HAVE_AVX2
  if (simd == 2) done = admitgen_rt__frame_f32_avx512(inst, in, out, 0, commit);
  if (simd) done = admitgen_rt__frame_f32_avx2(inst, in, out, done, commit);
#else
  (void)simd;
#endif
  if (done < inst->n_nodes) admitgen_rt__frame_f32_generic(inst, in, out, done, commit);
}

void admitgen_rt__process_f32_isa(admitgen_rt_f32 *inst, const float *pIn, float *pOut, int32_t n_frames,
                                  int32_t stride, int isa) {
  const int32_t rows = inst->model->n_fir - 1;
  int32_t f;
  const int32_t states = ADMITGEN_RT_SMALLN_TRAJ ? inst->model->n_real + 2 * inst->model->n_pair : 0;
  if (inst->n_nodes <= ADMITGEN_RT_SMALL_N && states <= ADMITGEN_RT_TRAJ) { /* (beyond: the block path) */
    int32_t len = ADMITGEN_RT_FCHUNK; /* frames per chunk: as many as the trajectories have room for */
    while (len * states > ADMITGEN_RT_TRAJ) len /= 2;
    for (f = 0; f < n_frames; f += len) {
      const int32_t nf = n_frames - f < len ? n_frames - f : len;
      int32_t i;
      for (i = 0; i < inst->n_nodes; ++i) admitgen_rt__chunk_f32(inst, pIn, pOut, stride, i, f, nf, len);
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
