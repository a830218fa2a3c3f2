/* SPDX-License-Identifier: MIT */
/*
 * rt_misuse.c - the runtime at its limits (docs/runtime.md, "Limits and misuse"): every misuse of the API
 * returns its documented result code and writes nothing; float NaN/Inf input propagates into its own node
 * only, until reset. Built with the runtime sources compiled in, under ASan + UBSan when the build has
 * ADMITGEN_SANITIZERS=ON, so that an out-of-bounds access or undefined operation fails the test instead
 * of passing silently. Prints "PASS (0 failures)".
 */
#include "wall_f32.h"
#include "wall_q15.h"
#include "wall_q31.h"
#include "rt_test_util.h"

#include <math.h>
#include <string.h>

#define RT_EXPECT(call, code) RT_CHECK((call) == (code), "expected %s (%d), got %d", #code, (int)(code), (int)(call))

/* Copies of the q31 tables that a test may corrupt (the generated tables are const). */
static int32_t q31_fir[ADMITGEN_RT_MAX_TERMS], q31_real[3 * ADMITGEN_RT_MAX_TERMS], q31_pair[6 * ADMITGEN_RT_MAX_TERMS];

static admitgen_rt_model_q31 q31_copy(void) {
  admitgen_rt_model_q31 m = wall_q31_48000;
  memcpy(q31_fir, m.fir, sizeof(int32_t) * (size_t)m.n_fir);
  memcpy(q31_real, m.real, sizeof(int32_t) * 3u * (size_t)m.n_real);
  memcpy(q31_pair, m.pair, sizeof(int32_t) * 6u * (size_t)m.n_pair);
  m.fir = q31_fir;
  m.real = q31_real;
  m.pair = q31_pair;
  return m;
}

static void check_null_pointers(void) {
  admitgen_rt_f32 inst, zeroed;
  admitgen_rt_q31 q;
  float buf[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const size_t bytes = admitgen_rt_state_bytes_f32(&wall_f32_48000, 2);
  admitgen_rt_model_f32 no_pair = wall_f32_48000;
  memset(&zeroed, 0, sizeof zeroed);
  RT_EXPECT(admitgen_rt_state_bytes_f32(NULL, 2), 0u);
  RT_EXPECT(admitgen_rt_init_f32(NULL, &wall_f32_48000, 48000, 2, rt_aligned(0), bytes), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_init_f32(&inst, NULL, 48000, 2, rt_aligned(0), bytes), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 2, NULL, bytes), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_init_q31(&q, NULL, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_NULL_POINTER);
  no_pair.pair = NULL; /* a count without its table */
  RT_CHECK(wall_f32_48000.n_pair > 0, "the test model has pairs");
  RT_EXPECT(admitgen_rt_init_f32(&inst, &no_pair, 48000, 2, rt_aligned(0), bytes), ADMITGEN_RT_NULL_POINTER);
  /* an instance never initialised (model NULL) */
  RT_EXPECT(admitgen_rt_process_f32(&zeroed, buf, buf, 1, 2), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_history_f32(&zeroed, buf), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_reset_f32(&zeroed), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_reinit_f32(&zeroed, &wall_f32_48000, 48000), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_process_f32(NULL, buf, buf, 1, 2), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_history_f32(NULL, buf), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_commit_f32(NULL, buf, buf), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_reset_f32(NULL), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 2, rt_aligned(0), bytes), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_process_f32(&inst, NULL, buf, 1, 2), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_process_f32(&inst, NULL, NULL, 0, 2), ADMITGEN_RT_SUCCESS); /* no frames: nothing read */
  RT_EXPECT(admitgen_rt_process_f32(&inst, buf, NULL, 2, 2), ADMITGEN_RT_SUCCESS); /* pOut NULL: state only */
  RT_EXPECT(admitgen_rt_history_f32(&inst, NULL), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_commit_f32(&inst, NULL, buf), ADMITGEN_RT_NULL_POINTER);
  RT_EXPECT(admitgen_rt_commit_f32(&inst, buf, NULL), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_reinit_f32(&inst, NULL, 48000), ADMITGEN_RT_NULL_POINTER);
}

static void check_memory(void) {
  admitgen_rt_q15 inst, before;
  const size_t bytes = admitgen_rt_state_bytes_q15(&wall_q15_48000, 3);
  size_t offset;
  RT_CHECK(bytes > 0u && bytes % ADMITGEN_RT_ALIGN == 0u, "state bytes %lu", (unsigned long)bytes);
  memset(&inst, 0x5a, sizeof inst);
  before = inst;
  for (offset = 1; offset < ADMITGEN_RT_ALIGN; offset *= 2)
    RT_EXPECT(admitgen_rt_init_q15(&inst, &wall_q15_48000, 48000, 3, (unsigned char *)rt_aligned(0) + offset, bytes + 64u),
              ADMITGEN_RT_MISALIGNED);
  RT_EXPECT(admitgen_rt_init_q15(&inst, &wall_q15_48000, 48000, 3, rt_aligned(0), bytes - 1u), ADMITGEN_RT_BUFFER_TOO_SMALL);
  RT_EXPECT(admitgen_rt_init_q15(&inst, &wall_q15_48000, 48000, 3, rt_aligned(0), 0u), ADMITGEN_RT_BUFFER_TOO_SMALL);
  RT_CHECK(memcmp(&inst, &before, sizeof inst) == 0, "a failed init changed the instance");
  RT_EXPECT(admitgen_rt_init_q15(&inst, &wall_q15_48000, 48000, 3, rt_aligned(0), bytes), ADMITGEN_RT_SUCCESS);
}

/* State sizes: n_nodes <= 0 invalid, above ADMITGEN_RT_MAX_NODES too large; at the maximum, 64 pairs need
 * 2 x 64 x 2^24 x 4 bytes and more: exactly that on a 64-bit size_t, ADMITGEN_RT_TOO_LARGE where size_t has
 * 32 bits (the sum computed here in 64 bits decides which). */
static void check_node_counts(void) {
  static const float table[6 * ADMITGEN_RT_MAX_TERMS] = {0.0f};
  admitgen_rt_model_f32 big = wall_f32_48000;
  admitgen_rt_f32 inst;
  const uint64_t rows = (uint64_t)ADMITGEN_RT_MAX_NODES;
  const uint64_t exact = 4u * rows * (64u + 2u * 64u + 63u + 1u + 1u); /* x, xi, eta, hist, u, acc: aligned already */
  big.n_fir = big.n_real = big.n_pair = ADMITGEN_RT_MAX_TERMS;
  big.fir = big.real = big.pair = table;
  RT_EXPECT(admitgen_rt_state_bytes_f32(&wall_f32_48000, 0), 0u);
  RT_EXPECT(admitgen_rt_state_bytes_f32(&wall_f32_48000, -1), 0u);
  RT_EXPECT(admitgen_rt_state_bytes_f32(&wall_f32_48000, ADMITGEN_RT_MAX_NODES + 1), 0u);
  RT_EXPECT(admitgen_rt_state_bytes_f32(&wall_f32_48000, INT32_MAX), 0u);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 0, rt_aligned(0), 1u << 16), ADMITGEN_RT_INVALID_ARGS);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, -5, rt_aligned(0), 1u << 16), ADMITGEN_RT_INVALID_ARGS);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, ADMITGEN_RT_MAX_NODES + 1, rt_aligned(0), (size_t)-1),
            ADMITGEN_RT_TOO_LARGE);
  RT_EXPECT(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, INT32_MAX, rt_aligned(0), (size_t)-1), ADMITGEN_RT_TOO_LARGE);
  if (exact <= (uint64_t)SIZE_MAX) {
    RT_CHECK((uint64_t)admitgen_rt_state_bytes_f32(&big, ADMITGEN_RT_MAX_NODES) == exact, "state bytes at the maximum");
    /* the size fits: the memory offered (1 MiB) is then too small */
    RT_EXPECT(admitgen_rt_init_f32(&inst, &big, 48000, ADMITGEN_RT_MAX_NODES, rt_aligned(0), 1u << 19),
              ADMITGEN_RT_BUFFER_TOO_SMALL);
  } else {
    RT_EXPECT(admitgen_rt_state_bytes_f32(&big, ADMITGEN_RT_MAX_NODES), 0u);
    RT_EXPECT(admitgen_rt_init_f32(&inst, &big, 48000, ADMITGEN_RT_MAX_NODES, rt_aligned(0), (size_t)-1), ADMITGEN_RT_TOO_LARGE);
  }
  big.n_pair = ADMITGEN_RT_MAX_TERMS + 1;
  RT_EXPECT(admitgen_rt_init_f32(&inst, &big, 48000, 1, rt_aligned(0), 1u << 19), ADMITGEN_RT_BAD_MODEL);
  big.n_pair = -1;
  RT_EXPECT(admitgen_rt_init_f32(&inst, &big, 48000, 1, rt_aligned(0), 1u << 19), ADMITGEN_RT_BAD_MODEL);
}

/* stride < n_nodes and negative frame counts are refused before anything is read or written. */
static void check_stride(void) {
  admitgen_rt_q31 inst;
  int32_t in[4 * 8], out[4 * 8];
  int i;
  for (i = 0; i < 32; ++i) in[i] = 1 << 28, out[i] = -7;
  RT_EXPECT(admitgen_rt_init_q31(&inst, &wall_q31_48000, 48000, 4, rt_aligned(0), 1u << 16), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_process_q31(&inst, in, out, 8, 3), ADMITGEN_RT_BAD_STRIDE);
  RT_EXPECT(admitgen_rt_process_q31(&inst, in, out, 8, 0), ADMITGEN_RT_BAD_STRIDE);
  RT_EXPECT(admitgen_rt_process_q31(&inst, in, out, 8, -4), ADMITGEN_RT_BAD_STRIDE);
  RT_EXPECT(admitgen_rt_process_q31(&inst, in, out, -1, 4), ADMITGEN_RT_INVALID_ARGS);
  for (i = 0; i < 32; ++i) RT_CHECK(out[i] == -7, "a refused call wrote output %d", i);
  RT_EXPECT(admitgen_rt_process_q31(&inst, in, out, 8, 4), ADMITGEN_RT_SUCCESS);
  RT_CHECK(out[0] != -7, "a valid call wrote no output");
}

static void check_rate_and_abi(void) {
  admitgen_rt_q31 inst;
  admitgen_rt_model_q31 other_abi = wall_q31_48000;
  other_abi.abi_version = ADMITGEN_RT_ABI_VERSION + 1u;
  RT_EXPECT(admitgen_rt_init_q31(&inst, &wall_q31_48000, 44100, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_RATE_MISMATCH);
  RT_EXPECT(admitgen_rt_init_q31(&inst, &wall_q31_48000, 0, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_RATE_MISMATCH);
  RT_EXPECT(admitgen_rt_init_q31(&inst, &other_abi, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_ABI_MISMATCH);
  RT_EXPECT(admitgen_rt_init_q31(&inst, &wall_q31_48000, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_reinit_q31(&inst, &wall_q31_96000, 48000), ADMITGEN_RT_RATE_MISMATCH);
  RT_EXPECT(admitgen_rt_reinit_q31(&inst, &other_abi, 48000), ADMITGEN_RT_ABI_MISMATCH);
  RT_CHECK(inst.model == &wall_q31_48000, "a refused reinit changed the model");
}

/* Fixed-point models whose shifts or mantissa sums would make a shift or a 64-bit sum undefined. */
static void check_bad_fixed_models(void) {
  admitgen_rt_q31 inst;
  admitgen_rt_model_q31 m = q31_copy();
  RT_CHECK(m.n_real > 0 && m.n_pair > 0, "the test model has real poles and pairs");
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_SUCCESS);
  m.acc_shift = 0;
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  m.acc_shift = 63;
  RT_EXPECT(admitgen_rt_reinit_q31(&inst, &m, 48000), ADMITGEN_RT_BAD_MODEL);
  m = q31_copy();
  q31_real[1] = INT32_MAX; /* 31 + shift would overflow before the shift itself is undefined */
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  m = q31_copy();
  q31_pair[3] = -31; /* total shift 0 */
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  m = q31_copy();
  q31_pair[0] = INT32_MIN, q31_pair[1] = INT32_MAX, q31_pair[2] = INT32_MAX; /* sum of three products > 2^63 */
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  m = q31_copy();
  q31_pair[4] = INT32_MAX; /* output table sum |m| > 2^31 */
  RT_EXPECT(admitgen_rt_init_q31(&inst, &m, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  {
    admitgen_rt_q15 q;
    admitgen_rt_model_q15 m15 = wall_q15_48000;
    m15.acc_shift = -1;
    RT_EXPECT(admitgen_rt_init_q15(&q, &m15, 48000, 1, rt_aligned(0), 1u << 16), ADMITGEN_RT_BAD_MODEL);
  }
}

static int finite(float v) { return v - v == 0.0f; } /* false for NaN and +-Inf */

/* NaN/Inf input: node `bad` receives NaN at frame 5 and +Inf at frame 9; every other node's output is
 * bit-identical to a run without them, node `bad`'s output is non-finite from frame 5 on, and after reset
 * the instance gives the fresh instance's output again. n_nodes 3 takes the small-n path, 40 the fused
 * (vector) path. */
static void check_non_finite(int32_t n_nodes, int32_t bad) {
  enum { frames = 64, max_nodes = 40 };
  static float in[frames * max_nodes], clean[frames * max_nodes], dirty[frames * max_nodes], after[frames * max_nodes];
  admitgen_rt_f32 a, b;
  const size_t bytes = admitgen_rt_state_bytes_f32(&wall_f32_48000, n_nodes);
  rt_rng rng;
  int32_t f, i;
  rt_rng_seed(&rng, 5u);
  for (i = 0; i < frames * n_nodes; ++i) in[i] = (float)(rt_rng_uniform(&rng) - 0.5);
  RT_EXPECT(admitgen_rt_init_f32(&a, &wall_f32_48000, 48000, n_nodes, rt_aligned(0), bytes), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_process_f32(&a, in, clean, frames, n_nodes), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_init_f32(&b, &wall_f32_48000, 48000, n_nodes, rt_aligned(bytes + 64u), bytes), ADMITGEN_RT_SUCCESS);
  in[5 * n_nodes + bad] = (float)NAN;
  in[9 * n_nodes + bad] = (float)INFINITY;
  RT_EXPECT(admitgen_rt_process_f32(&b, in, dirty, frames, n_nodes), ADMITGEN_RT_SUCCESS);
  for (f = 0; f < frames; ++f)
    for (i = 0; i < n_nodes; ++i) {
      const float y = dirty[f * n_nodes + i];
      if (i != bad || f < 5)
        RT_CHECK(memcmp(&y, &clean[f * n_nodes + i], sizeof y) == 0, "n %d: node %d frame %d changed", n_nodes, i, f);
      else
        RT_CHECK(!finite(y), "n %d: node %d frame %d is finite after NaN input", n_nodes, i, f);
    }
  in[5 * n_nodes + bad] = in[9 * n_nodes + bad] = 0.25f;
  RT_EXPECT(admitgen_rt_reset_f32(&b), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_reset_f32(&a), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_process_f32(&a, in, clean, frames, n_nodes), ADMITGEN_RT_SUCCESS);
  RT_EXPECT(admitgen_rt_process_f32(&b, in, after, frames, n_nodes), ADMITGEN_RT_SUCCESS);
  RT_CHECK(memcmp(after, clean, sizeof(float) * (size_t)(frames * n_nodes)) == 0, "n %d: reset did not clear NaN", n_nodes);
}

int main(void) {
  check_null_pointers();
  check_memory();
  check_node_counts();
  check_stride();
  check_rate_and_abi();
  check_bad_fixed_models();
  check_non_finite(3, 1);
  check_non_finite(40, 37);
  printf("%s (%d failures)\n", rt_failures == 0 ? "PASS" : "FAIL", rt_failures);
  return rt_failures == 0 ? 0 : 1;
}
