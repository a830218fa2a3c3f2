/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_fixed.c - the scalar fixed-point kernel shared by q31 and q15 (the reference every vector
 * kernel must match bit for bit, and the path for 32-bit MCUs), and the dispatch between paths.
 *
 * Per frame and node, with Q1.31 states and 64-bit accumulators (scaling in admitgen_rt_process_q31.c):
 *   acc = sum_k d_k u^{n-k};  x += eps (u - x), acc += c x;
 *   xi' = xi + (e_r xi - p_i eta + g u), eta' = eta + (e_r eta + p_i xi), acc += cr xi' + ci eta';
 *   y = round(acc / 2^acc_shift), saturated.
 * Every product and sum is exact in 64 bits (the generator bounds the tables), so the order of the
 * accumulation is free: the small-n path and the block path give identical bits.
 */
#include "admitgen_rt_internal.h"

/* Nodes per block of the scalar frame pass: 4 accumulators fit the registers of a 32-bit core. */
#define ADMITGEN_RT_QBLOCK 4

/* Inputs idx0 + k step (k < count) as Q1.31 (u = 0 without input). */
static void admitgen_rt__qload(const admitgen_rt__qio *io, size_t idx0, size_t step, int32_t *u, int32_t count) {
  int32_t k;
  if (io->in32 != NULL) {
    for (k = 0; k < count; ++k) u[k] = io->in32[idx0 + (size_t)k * step];
  } else if (io->in16 != NULL) {
    for (k = 0; k < count; ++k) u[k] = (int32_t)io->in16[idx0 + (size_t)k * step] * 65536; /* Q1.15 -> Q1.31, exact */
  } else {
    for (k = 0; k < count; ++k) u[k] = 0;
  }
}

/* Outputs idx0 + k step (k < count) from the accumulators (nothing without output). */
static void admitgen_rt__qstore(const admitgen_rt__qio *io, int32_t acc_shift, size_t idx0, size_t step,
                                const int64_t *acc, int32_t count) {
  int32_t k;
  if (io->out32 != NULL)
    for (k = 0; k < count; ++k) io->out32[idx0 + (size_t)k * step] = admitgen_rt__output(acc[k], acc_shift, INT32_MIN, INT32_MAX);
  if (io->out16 != NULL)
    for (k = 0; k < count; ++k)
      io->out16[idx0 + (size_t)k * step] = (int16_t)admitgen_rt__output(acc[k], acc_shift, INT16_MIN, INT16_MAX);
}

/* Scalar fused pass of frame f over nodes [i0, i1). */
static void admitgen_rt__qframe_scalar(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st,
                                       const admitgen_rt__qio *io, int32_t f, int32_t i0, int32_t i1, int commit) {
  const size_t n = (size_t)st->n, base = (size_t)f * (size_t)io->stride;
  const int32_t rows = st->rows, d0 = t->n_fir > 0 ? admitgen_rt__qfir(t, 0) : 0;
  const int32_t new_head = rows > 0 ? admitgen_rt__ring_advance(st->head, 1, rows) : 0;
  int32_t b;
  for (b = i0; b < i1; b += ADMITGEN_RT_QBLOCK) {
    const int32_t nb = i1 - b < ADMITGEN_RT_QBLOCK ? i1 - b : ADMITGEN_RT_QBLOCK;
    int32_t u[ADMITGEN_RT_QBLOCK];
    int64_t acc[ADMITGEN_RT_QBLOCK];
    int32_t j, k, q;
    admitgen_rt__qload(io, base + (size_t)b, 1u, u, nb);
    for (j = 0; j < nb; ++j) acc[j] = (int64_t)d0 * u[j];
    for (k = 1; k < t->n_fir; ++k) {
      const int32_t d = admitgen_rt__qfir(t, k);
      const int32_t *row = st->hist + (size_t)admitgen_rt__ring_row(st->head, k, rows) * n + (size_t)b;
      for (j = 0; j < nb; ++j) acc[j] += (int64_t)d * row[j];
    }
    for (q = 0; q < t->n_real; ++q) {
      const admitgen_rt__qreal_coef r = admitgen_rt__qreal(t, q);
      int32_t *x = st->x + (size_t)q * n + (size_t)b;
      for (j = 0; j < nb; ++j) {
        const int32_t v = admitgen_rt__add_tz(x[j], (int64_t)r.m * u[j] - (int64_t)r.m * x[j], r.s);
        if (commit) x[j] = v;
        acc[j] += (int64_t)r.c * v;
      }
    }
    for (q = 0; q < t->n_pair; ++q) {
      const admitgen_rt__qpair_coef p = admitgen_rt__qpair(t, q);
      int32_t *xi = st->xi + (size_t)q * n + (size_t)b, *eta = st->eta + (size_t)q * n + (size_t)b;
      for (j = 0; j < nb; ++j) {
        const int32_t a1 = admitgen_rt__add_tz(xi[j], (int64_t)p.er * xi[j] - (int64_t)p.pi * eta[j] + (int64_t)p.g * u[j], p.s);
        const int32_t e1 = admitgen_rt__add_tz(eta[j], (int64_t)p.er * eta[j] + (int64_t)p.pi * xi[j], p.s);
        acc[j] += (int64_t)p.cr * a1 + (int64_t)p.ci * e1;
        if (commit) {
          xi[j] = a1;
          eta[j] = e1;
        }
      }
    }
    admitgen_rt__qstore(io, t->acc_shift, base + (size_t)b, 1u, acc, nb);
    if (commit && rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
      int32_t *row = st->hist + (size_t)new_head * n + (size_t)b;
      for (j = 0; j < nb; ++j) row[j] = u[j];
    }
  }
}

/* Small-n path: node i, frames [f0, f0 + nf) with nf <= ADMITGEN_RT_CHUNK; each term runs over the frames
 * with its state in a register. ub holds the node's past inputs (oldest first) then the chunk's inputs. */
static void admitgen_rt__qchunk(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st,
                                const admitgen_rt__qio *io, int32_t i, int32_t f0, int32_t nf) {
  const size_t n = (size_t)st->n;
  const int32_t rows = st->rows;
  int32_t ub[64 + ADMITGEN_RT_CHUNK];
  int64_t acc[ADMITGEN_RT_CHUNK];
  const int32_t *u = ub + rows;
  int32_t f, k, q;
  for (k = 1; k <= rows; ++k) ub[rows - k] = st->hist[(size_t)admitgen_rt__ring_row(st->head, k, rows) * n + (size_t)i];
  admitgen_rt__qload(io, (size_t)f0 * (size_t)io->stride + (size_t)i, (size_t)io->stride, ub + rows, nf);
  {
    const int32_t d0 = t->n_fir > 0 ? admitgen_rt__qfir(t, 0) : 0;
    for (f = 0; f < nf; ++f) acc[f] = (int64_t)d0 * u[f];
  }
  for (k = 1; k < t->n_fir; ++k) {
    const int32_t d = admitgen_rt__qfir(t, k);
    for (f = 0; f < nf; ++f) acc[f] += (int64_t)d * u[f - k];
  }
  for (q = 0; q < t->n_real; ++q) {
    const admitgen_rt__qreal_coef r = admitgen_rt__qreal(t, q);
    int32_t *px = st->x + (size_t)q * n + (size_t)i;
    int32_t x = *px;
    for (f = 0; f < nf; ++f) {
      x = admitgen_rt__add_tz(x, (int64_t)r.m * u[f] - (int64_t)r.m * x, r.s);
      acc[f] += (int64_t)r.c * x;
    }
    *px = x;
  }
  for (q = 0; q < t->n_pair; ++q) {
    const admitgen_rt__qpair_coef p = admitgen_rt__qpair(t, q);
    int32_t *pxi = st->xi + (size_t)q * n + (size_t)i, *peta = st->eta + (size_t)q * n + (size_t)i;
    int32_t a = *pxi, e = *peta;
    for (f = 0; f < nf; ++f) {
      const int32_t a1 = admitgen_rt__add_tz(a, (int64_t)p.er * a - (int64_t)p.pi * e + (int64_t)p.g * u[f], p.s);
      e = admitgen_rt__add_tz(e, (int64_t)p.er * e + (int64_t)p.pi * a, p.s);
      a = a1;
      acc[f] += (int64_t)p.cr * a + (int64_t)p.ci * e;
    }
    *pxi = a;
    *peta = e;
  }
  admitgen_rt__qstore(io, t->acc_shift, (size_t)f0 * (size_t)io->stride + (size_t)i, (size_t)io->stride, acc, nf);
  if (rows > 0) {
    const int32_t new_head = admitgen_rt__ring_advance(st->head, nf, rows);
    for (k = 1; k <= rows; ++k)
      st->hist[(size_t)admitgen_rt__ring_row(new_head, k, rows) * n + (size_t)i] = u[nf - k];
  }
}

/* One frame over every node: vector blocks first (when the CPU has them), the scalar pass for the rest. */
static void admitgen_rt__qframe(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io,
                                int32_t f, int commit, int simd) {
  int32_t done = 0;
#if ADMITGEN_RT_HAVE_AVX2 || ADMITGEN_RT_HAVE_NEON
  if (simd) {
    const int32_t new_head = st->rows > 0 ? admitgen_rt__ring_advance(st->head, 1, st->rows) : 0;
    const size_t base = (size_t)f * (size_t)io->stride;
#if ADMITGEN_RT_HAVE_AVX2
    if (simd == 2)
      for (; done + ADMITGEN_RT_QVEC_AVX512 <= st->n; done += ADMITGEN_RT_QVEC_AVX512)
        admitgen_rt__qblock_avx512(t, st, io, base, (size_t)done, new_head, commit);
    for (; done + ADMITGEN_RT_QVEC <= st->n; done += ADMITGEN_RT_QVEC)
      admitgen_rt__qblock_avx2(t, st, io, base, (size_t)done, new_head, commit);
#else
    for (; done + ADMITGEN_RT_QVEC <= st->n; done += ADMITGEN_RT_QVEC)
      admitgen_rt__qblock_neon(t, st, io, base, (size_t)done, new_head, commit);
#endif
  }
#else
  (void)simd;
#endif
  if (done < st->n) admitgen_rt__qframe_scalar(t, st, io, f, done, st->n, commit);
}

void admitgen_rt__qcall(const admitgen_rt__qtab *t, int32_t *x, int32_t *xi, int32_t *eta, int32_t *hist, int32_t n,
                        int32_t *head, const admitgen_rt__qio *io, int32_t n_frames, int commit, int isa) {
  admitgen_rt__qstate st;
  int32_t f;
  st.x = x;
  st.xi = xi;
  st.eta = eta;
  st.hist = hist;
  st.n = n;
  st.head = *head;
  st.rows = t->n_fir > 1 ? t->n_fir - 1 : 0;
  if (!commit) {
    admitgen_rt__qframe(t, &st, io, 0, 0, admitgen_rt__use_simd(isa));
  } else if (n <= ADMITGEN_RT_SMALL_N) {
    for (f = 0; f < n_frames; f += ADMITGEN_RT_CHUNK) {
      const int32_t nf = n_frames - f < ADMITGEN_RT_CHUNK ? n_frames - f : ADMITGEN_RT_CHUNK;
      int32_t i;
      for (i = 0; i < n; ++i) admitgen_rt__qchunk(t, &st, io, i, f, nf);
      if (st.rows > 0) st.head = admitgen_rt__ring_advance(st.head, nf, st.rows);
    }
  } else {
    const int simd = admitgen_rt__use_simd(isa);
    for (f = 0; f < n_frames; ++f) {
      admitgen_rt__qframe(t, &st, io, f, 1, simd);
      if (st.rows > 0) st.head = admitgen_rt__ring_advance(st.head, 1, st.rows);
    }
  }
  *head = st.head;
}

/* |v| as an unsigned 64-bit value (defined for INT32_MIN). */
static uint64_t admitgen_rt__abs64(int32_t v) { return v < 0 ? (uint64_t)(-(int64_t)v) : (uint64_t)v; }


/* A term's total shift bits + shift within 1..62 (tested before the sum is formed: no overflow). */
static int admitgen_rt__valid_term_shift(int32_t bits, int32_t shift) { return shift >= 1 - bits && shift <= 62 - bits; }

admitgen_rt_result admitgen_rt__check_qmodel(const admitgen_rt__qtab *t) {
  /* Bounds (docs/runtime.md): states and inputs |v| <= 2^31, so a sum of products sum_j m_j v_j stays below
   * 2^62 in magnitude when sum_j |m_j| <= 2^31; the real pole's m (u - x) is below 2^63 for any int32 m. */
  const uint64_t limit = (uint64_t)1 << 31;
  uint64_t out = 0u;
  int32_t k;
  if (t->acc_shift < 1 || t->acc_shift > 62) return ADMITGEN_RT_BAD_MODEL;
  for (k = 0; k < t->n_fir; ++k) out += admitgen_rt__abs64(admitgen_rt__qfir(t, k));
  for (k = 0; k < t->n_real; ++k) {
    if (!admitgen_rt__valid_term_shift(t->bits, admitgen_rt__qreal_entry(t, k, ADMITGEN_RT_Q_REAL_SHIFT))) return ADMITGEN_RT_BAD_MODEL;
    out += admitgen_rt__abs64(admitgen_rt__qreal_entry(t, k, ADMITGEN_RT_Q_REAL_C));
  }
  for (k = 0; k < t->n_pair; ++k) {
    uint64_t update = 0u;
    if (!admitgen_rt__valid_term_shift(t->bits, admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_SHIFT))) return ADMITGEN_RT_BAD_MODEL;
    update += admitgen_rt__abs64(admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_ER));
    update += admitgen_rt__abs64(admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_PI));
    update += admitgen_rt__abs64(admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_G));
    if (update > limit) return ADMITGEN_RT_BAD_MODEL;
    out += admitgen_rt__abs64(admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_CR)) +
           admitgen_rt__abs64(admitgen_rt__qpair_entry(t, k, ADMITGEN_RT_Q_PAIR_CI));
  }
  return out > limit ? ADMITGEN_RT_BAD_MODEL : ADMITGEN_RT_SUCCESS;
}
