/* SPDX-License-Identifier: MIT */
/*
 * admitgen_rt_qblock_x86.h - the x86 fixed-point block (vectors of 4 int64 lanes), included by
 * admitgen_rt_avx2.c once per instruction set. The includer defines ADMITGEN_RT_VH (vectors per block),
 * ADMITGEN_RT_V(name) (name + ISA suffix)
 * and the primitives ADMITGEN_RT_V(vfloor_shr), ADMITGEN_RT_V(vclamp) and ADMITGEN_RT_V(vadd_tz) with the
 * meaning of admitgen_rt__floor_shr, a clamp and admitgen_rt__add_tz. No include guard on purpose.
 */
static inline void ADMITGEN_RT_V(voutput)(const admitgen_rt__qio *io, size_t idx, __m256i acc, const admitgen_rt__vshift *k,
                                        __m256i half) {
  const __m256i v = ADMITGEN_RT_V(vfloor_shr)(_mm256_add_epi64(acc, half), k);
  if (io->out32 != NULL)
    admitgen_rt__vstore32(io->out32 + idx,
                          ADMITGEN_RT_V(vclamp)(v, _mm256_set1_epi64x(INT32_MIN), _mm256_set1_epi64x(INT32_MAX)));
  if (io->out16 != NULL) {
    const __m128i w = admitgen_rt__vnarrow(ADMITGEN_RT_V(vclamp)(v, _mm256_set1_epi64x(INT16_MIN), _mm256_set1_epi64x(INT16_MAX)));
    _mm_storel_epi64((__m128i *)(void *)(io->out16 + idx), _mm_packs_epi32(w, w));
  }
}

/* One block of 4 ADMITGEN_RT_VH nodes starting at b: vectors h of 4 nodes each. */
void ADMITGEN_RT_V(qblock)(const admitgen_rt__qtab *t, const admitgen_rt__qstate *st, const admitgen_rt__qio *io, size_t base,
                           size_t b, int32_t new_head, int commit) {
  const size_t n = (size_t)st->n;
  __m256i u[ADMITGEN_RT_VH], acc[ADMITGEN_RT_VH];
  int32_t h, k, q;
  for (h = 0; h < ADMITGEN_RT_VH; ++h) {
    u[h] = admitgen_rt__vinput(io, base + b + 4u * (size_t)h);
    acc[h] = admitgen_rt__vmul(u[h], t->n_fir > 0 ? admitgen_rt__qfir(t, 0) : 0);
  }
  for (k = 1; k < t->n_fir; ++k) {
    const int32_t d = admitgen_rt__qfir(t, k);
    const int32_t *row = st->hist + (size_t)admitgen_rt__ring_row(st->head, k, st->rows) * n + b;
    for (h = 0; h < ADMITGEN_RT_VH; ++h) acc[h] = _mm256_add_epi64(acc[h], admitgen_rt__vmul(admitgen_rt__vload32(row + 4 * h), d));
  }
  for (q = 0; q < t->n_real; ++q) {
    const admitgen_rt__qreal_coef r = admitgen_rt__qreal(t, q);
    const admitgen_rt__vshift sh = admitgen_rt__vshift_make(r.s);
    int32_t *x = st->x + (size_t)q * n + b;
    for (h = 0; h < ADMITGEN_RT_VH; ++h) {
      const __m256i x0 = admitgen_rt__vload32(x + 4 * h);
      const __m256i v = ADMITGEN_RT_V(vadd_tz)(x0, _mm256_sub_epi64(admitgen_rt__vmul(u[h], r.m), admitgen_rt__vmul(x0, r.m)), &sh);
      if (commit) admitgen_rt__vstore32(x + 4 * h, v);
      acc[h] = _mm256_add_epi64(acc[h], admitgen_rt__vmul(v, r.c));
    }
  }
  for (q = 0; q < t->n_pair; ++q) {
    const admitgen_rt__qpair_coef p = admitgen_rt__qpair(t, q);
    const admitgen_rt__vshift sh = admitgen_rt__vshift_make(p.s);
    int32_t *xi = st->xi + (size_t)q * n + b, *eta = st->eta + (size_t)q * n + b;
    for (h = 0; h < ADMITGEN_RT_VH; ++h) {
      const __m256i a = admitgen_rt__vload32(xi + 4 * h), e = admitgen_rt__vload32(eta + 4 * h);
      const __m256i pa = _mm256_add_epi64(_mm256_sub_epi64(admitgen_rt__vmul(a, p.er), admitgen_rt__vmul(e, p.pi)),
                                          admitgen_rt__vmul(u[h], p.g));
      const __m256i pe = _mm256_add_epi64(admitgen_rt__vmul(e, p.er), admitgen_rt__vmul(a, p.pi));
      const __m256i a1 = ADMITGEN_RT_V(vadd_tz)(a, pa, &sh), e1 = ADMITGEN_RT_V(vadd_tz)(e, pe, &sh);
      if (commit) {
        admitgen_rt__vstore32(xi + 4 * h, a1);
        admitgen_rt__vstore32(eta + 4 * h, e1);
      }
      acc[h] = _mm256_add_epi64(acc[h], _mm256_add_epi64(admitgen_rt__vmul(a1, p.cr), admitgen_rt__vmul(e1, p.ci)));
    }
  }
  {
    const admitgen_rt__vshift sh = admitgen_rt__vshift_make(t->acc_shift);
    const __m256i half = _mm256_set1_epi64x((long long)((int64_t)1 << (t->acc_shift - 1)));
    for (h = 0; h < ADMITGEN_RT_VH; ++h) ADMITGEN_RT_V(voutput)(io, base + b + 4u * (size_t)h, acc[h], &sh, half);
  }
  if (commit && st->rows > 0) { /* u^n overwrites u^{n-rows}, which this block has just read */
    int32_t *row = st->hist + (size_t)new_head * n + b;
    for (h = 0; h < ADMITGEN_RT_VH; ++h) admitgen_rt__vstore32(row + 4 * h, u[h]);
  }
}

