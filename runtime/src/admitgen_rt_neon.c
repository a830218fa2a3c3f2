/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_neon.c - aarch64 NEON fixed-point kernel (NEON is mandatory on aarch64: no dispatch).
 *
 * 4 nodes per block as two int64x2 vectors; vmull_s32/vmlal_s32/vmlsl_s32 form the exact 32x32 -> 64-bit
 * products of the scalar kernel; vshlq_s64 by -s is the arithmetic (floor) right shift; vqmovn_s64 is the
 * saturating narrowing to int32 (and vqmovn_s32 on to int16), i.e. the clamps of admitgen_rt__add_tz and
 * admitgen_rt__output. Bit-identical to admitgen_rt_fixed.c, which drives the blocks and handles the n % 4
 * remaining nodes.
 */
#include "admitgen_rt_internal.h"

#if ADMITGEN_RT_HAVE_NEON
#include <arm_neon.h>

/* trunc(old + prod / 2^s) on 2 lanes (before saturation): floor, then +1 where negative and inexact. */
static inline int64x2_t admitgen_rt__nadd_tz(int32x2_t old, int64x2_t prod, int64x2_t neg_s, int64x2_t mask) {
  int64x2_t v = vaddw_s32(vshlq_s64(prod, neg_s), old);
  const uint64x2_t adj = vandq_u64(vtstq_s64(prod, mask), vcltzq_s64(v));
  return vsubq_s64(v, vreinterpretq_s64_u64(adj)); /* adj lanes are all ones = -1 */
}

static inline int32x4_t admitgen_rt__ninput(const admitgen_rt__qio *io, size_t idx) {
  if (io->in32 != NULL) return vld1q_s32(io->in32 + idx);
  if (io->in16 != NULL) return vshll_n_s16(vld1_s16(io->in16 + idx), 16);
  return vdupq_n_s32(0);
}

void admitgen_rt__qblock_neon(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io,
                              size_t base, size_t b, int32_t new_head, int commit) {
  const size_t n = (size_t)st->n;
  const int32x4_t u = admitgen_rt__ninput(io, base + b);
  const int32x2_t ul = vget_low_s32(u), uh = vget_high_s32(u);
  const int32_t d0 = t->n_fir > 0 ? admitgen_rt__qfir(t, 0) : 0;
  int64x2_t al = vmull_n_s32(ul, d0), ah = vmull_n_s32(uh, d0);
  int32_t k, q;
  for (k = 1; k < t->n_fir; ++k) {
    const int32_t d = admitgen_rt__qfir(t, k);
    const int32x4_t r = vld1q_s32(st->hist + (size_t)admitgen_rt__ring_row(st->head, k, st->rows) * n + b);
    al = vmlal_n_s32(al, vget_low_s32(r), d);
    ah = vmlal_n_s32(ah, vget_high_s32(r), d);
  }
  for (q = 0; q < t->n_real; ++q) {
    const admitgen_rt__qreal_coef rc = admitgen_rt__qreal(t, q);
    const int32_t m = rc.m, c = rc.c;
    const int64x2_t neg_s = vdupq_n_s64(-(int64_t)rc.s), mask = vdupq_n_s64((int64_t)(((uint64_t)1 << rc.s) - 1u));
    int32_t *px = st->x + (size_t)q * n + b;
    const int32x4_t x = vld1q_s32(px);
    const int32x2_t xl = vget_low_s32(x), xh = vget_high_s32(x);
    const int32x2_t vl = vqmovn_s64(admitgen_rt__nadd_tz(xl, vmlsl_n_s32(vmull_n_s32(ul, m), xl, m), neg_s, mask));
    const int32x2_t vh = vqmovn_s64(admitgen_rt__nadd_tz(xh, vmlsl_n_s32(vmull_n_s32(uh, m), xh, m), neg_s, mask));
    if (commit) vst1q_s32(px, vcombine_s32(vl, vh));
    al = vmlal_n_s32(al, vl, c);
    ah = vmlal_n_s32(ah, vh, c);
  }
  for (q = 0; q < t->n_pair; ++q) {
    const admitgen_rt__qpair_coef pc = admitgen_rt__qpair(t, q);
    const int32_t er = pc.er, pi = pc.pi, g = pc.g, cr = pc.cr, ci = pc.ci;
    const int64x2_t neg_s = vdupq_n_s64(-(int64_t)pc.s), mask = vdupq_n_s64((int64_t)(((uint64_t)1 << pc.s) - 1u));
    int32_t *pxi = st->xi + (size_t)q * n + b, *peta = st->eta + (size_t)q * n + b;
    const int32x4_t a = vld1q_s32(pxi), e = vld1q_s32(peta);
    const int32x2_t a_l = vget_low_s32(a), a_h = vget_high_s32(a), e_l = vget_low_s32(e), e_h = vget_high_s32(e);
    const int64x2_t pal = vmlal_n_s32(vmlsl_n_s32(vmull_n_s32(a_l, er), e_l, pi), ul, g);
    const int64x2_t pah = vmlal_n_s32(vmlsl_n_s32(vmull_n_s32(a_h, er), e_h, pi), uh, g);
    const int64x2_t pel = vmlal_n_s32(vmull_n_s32(e_l, er), a_l, pi), peh = vmlal_n_s32(vmull_n_s32(e_h, er), a_h, pi);
    const int32x2_t a1l = vqmovn_s64(admitgen_rt__nadd_tz(a_l, pal, neg_s, mask));
    const int32x2_t a1h = vqmovn_s64(admitgen_rt__nadd_tz(a_h, pah, neg_s, mask));
    const int32x2_t e1l = vqmovn_s64(admitgen_rt__nadd_tz(e_l, pel, neg_s, mask));
    const int32x2_t e1h = vqmovn_s64(admitgen_rt__nadd_tz(e_h, peh, neg_s, mask));
    if (commit) {
      vst1q_s32(pxi, vcombine_s32(a1l, a1h));
      vst1q_s32(peta, vcombine_s32(e1l, e1h));
    }
    al = vmlal_n_s32(vmlal_n_s32(al, a1l, cr), e1l, ci);
    ah = vmlal_n_s32(vmlal_n_s32(ah, a1h, cr), e1h, ci);
  }
  {
    const int64x2_t half = vdupq_n_s64((int64_t)1 << (t->acc_shift - 1)), neg_s = vdupq_n_s64(-(int64_t)t->acc_shift);
    const int32x4_t y = vcombine_s32(vqmovn_s64(vshlq_s64(vaddq_s64(al, half), neg_s)),
                                     vqmovn_s64(vshlq_s64(vaddq_s64(ah, half), neg_s)));
    if (io->out32 != NULL) vst1q_s32(io->out32 + base + b, y);
    if (io->out16 != NULL) vst1_s16(io->out16 + base + b, vqmovn_s32(y));
  }
  if (commit && st->rows > 0) vst1q_s32(st->hist + (size_t)new_head * n + b, u); /* overwrites u^{n-rows}, read above */
}

#else
typedef int admitgen_rt__neon_not_built; /* ISO C forbids an empty translation unit */
#endif
