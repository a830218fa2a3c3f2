/* SPDX-License-Identifier: MIT */
/*
 * rt_test_util.h - helpers of the C runtime tests: the check macro (rt_check.h), the same
 * xoshiro256** generator as generator/core/rng.hpp (seeded by splitmix64), aligned static memory.
 */
#ifndef RT_TEST_UTIL_H
#define RT_TEST_UTIL_H

#include "rt_check.h"

#include <stdint.h>

typedef struct rt_rng {
  uint64_t s[4];
} rt_rng;

static uint64_t rt_splitmix64(uint64_t *x) {
  uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static void rt_rng_seed(rt_rng *r, uint64_t seed) {
  int i;
  for (i = 0; i < 4; ++i) r->s[i] = rt_splitmix64(&seed);
}

static uint64_t rt_rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t rt_rng_next(rt_rng *r) {
  const uint64_t result = rt_rotl(r->s[1] * 5u, 7) * 9u;
  const uint64_t t = r->s[1] << 17;
  r->s[2] ^= r->s[0];
  r->s[3] ^= r->s[1];
  r->s[1] ^= r->s[2];
  r->s[0] ^= r->s[3];
  r->s[2] ^= t;
  r->s[3] = rt_rotl(r->s[3], 45);
  return result;
}

/* Uniform on [0, 1) with 53 bits (as admitgen::Rng::uniform). */
static double rt_rng_uniform(rt_rng *r) { return (double)(rt_rng_next(r) >> 11) * (1.0 / 9007199254740992.0); }

/* State memory for the tests: static, aligned by a union with a 64-byte type is not portable C99, so
 * over-allocate and align the pointer by hand. */
static unsigned char rt_arena[1u << 20];
static void *rt_aligned(size_t offset) {
  uintptr_t p = (uintptr_t)(rt_arena + offset);
  p = (p + 63u) & ~(uintptr_t)63u;
  return (void *)p;
}

#endif
