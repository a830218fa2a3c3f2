/* SPDX-License-Identifier: MIT */
/*
 * rt_bench.c - runtime benchmark: recursive convolution (admitgen runtime) vs direct convolution of the same
 * impulse response truncated at -100 dB, f32 / q31 / q15, 1 node (mono audio, 64 frames per call) and
 * 1024 nodes (a solver's boundary, one frame per call), in one run. Prints ns per node-sample, ns per state
 * update (per recursive state and sample), the direct/recursive ratio, the vector/scalar ratio, and the
 * goals of docs/runtime.md with whether this machine meets them. Each figure is the fastest of REPEAT
 * timings of the CPU time of this thread (the machine is shared: wall-clock time would include the time other
 * processes hold the core, more of it for the longer baseline timings, flattering the ratio; the minimum is
 * the least disturbed). The direct convolution is compiled for the instruction
 * sets the runtime dispatches to (AVX2, and AVX-512 with FMA where the CPU has it; the faster build counts), so
 * the ratio compares algorithms, not instruction sets. Input: white noise at -6 dBFS (no subnormals). Model: the reference
 * Q1S1 fit at 48 kHz (samples/fits/q1s1_reference.json).
 */
#define _POSIX_C_SOURCE 199309L
#include "admitgen_rt_internal.h"
#include "bench_f32.h"
#include "bench_q15.h"
#include "bench_q31.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_NODES 1024
#define MAX_TAPS 4096
#define TOTAL (1L << 20) /* node-samples per timing */
#define REPEAT 21

static double now_ns(void) { /* CPU time of this thread: see the top of this file */
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static unsigned char arena[(1u << 22) + 64];
static void *aligned(void) { return (void *)(((uintptr_t)arena + 63u) & ~(uintptr_t)63u); }

static float fin[MAX_NODES * 64], fout[MAX_NODES * 64];
static int32_t qin[MAX_NODES * 64], qout[MAX_NODES * 64];
static int16_t hin[MAX_NODES * 64], hout[MAX_NODES * 64];
static float fh[MAX_TAPS], fhist[2 * MAX_TAPS * MAX_NODES];
static int32_t qh[MAX_TAPS], qhist[2 * MAX_TAPS * MAX_NODES];
static volatile double sink;

typedef enum { F32, Q31, Q15 } format;
static const char *const format_name[3] = {"f32", "q31", "q15"};

static int truncated_length(const float *h, int n) {
  float peak = 0.0f;
  int i, len = 1;
  for (i = 0; i < n; ++i)
    if ((h[i] < 0 ? -h[i] : h[i]) > peak) peak = h[i] < 0 ? -h[i] : h[i];
  for (i = 0; i < n; ++i)
    if ((h[i] < 0 ? -h[i] : h[i]) >= 1e-5f * peak) len = i + 1; /* -100 dB */
  return len;
}

/* frames per call: 64 frames of a mono buffer, or one solver step (1 frame) of 1024 nodes */
static int frames_per_call(int nodes) { return nodes == 1 ? 64 : 1; }

/* One timing of the runtime: ns per node-sample. */
static double time_runtime(format fmt, int nodes, int isa) {
  admitgen_rt_f32 f;
  admitgen_rt_q31 q;
  admitgen_rt_q15 h;
  const int fpc = frames_per_call(nodes);
  const long calls = TOTAL / ((long)nodes * fpc);
  const size_t bytes = sizeof arena - 64;
  long c;
  double t0, acc = 0.0;
  admitgen_rt_result r = ADMITGEN_RT_SUCCESS;
  if (fmt == F32) r = admitgen_rt_init_f32(&f, &bench_f32_48000, 48000, nodes, aligned(), bytes);
  if (fmt == Q31) r = admitgen_rt_init_q31(&q, &bench_q31_48000, 48000, nodes, aligned(), bytes);
  if (fmt == Q15) r = admitgen_rt_init_q15(&h, &bench_q15_48000, 48000, nodes, aligned(), bytes);
  if (r != ADMITGEN_RT_SUCCESS) exit(1);
  t0 = now_ns();
  for (c = 0; c < calls; ++c) {
    if (fmt == F32) {
      admitgen_rt__process_f32_isa(&f, fin, fout, fpc, nodes, isa);
      acc += fout[0];
    } else if (fmt == Q31) {
      admitgen_rt__process_q31_isa(&q, qin, qout, fpc, nodes, isa);
      acc += qout[0];
    } else {
      admitgen_rt__process_q15_isa(&h, hin, hout, fpc, nodes, isa);
      acc += hout[0];
    }
  }
  sink = acc;
  return (now_ns() - t0) / (double)TOTAL;
}

/* Direct convolution, a fair baseline: past inputs in a doubled ring (each input written at head and
 * head + taps, so rows head..head+taps-1 are contiguous: no index arithmetic in the MAC loop). One node:
 * a contiguous dot product over the taps (16 partial sums, vectorised); many nodes: SoA hist[k][node], the node loop vectorised. */
#if defined(__GNUC__) || defined(__clang__)
#define BENCH_INLINE __attribute__((always_inline)) inline
#else
#define BENCH_INLINE inline
#endif

static BENCH_INLINE double direct_f32_body(int nodes, int taps, long steps) {
  long s;
  int k, i, head = 0;
  double acc = 0.0;
  for (s = 0; s < steps; ++s) {
    const float *in = fin + (s & 63) * nodes;
    head = head == 0 ? taps - 1 : head - 1;
    memcpy(fhist + (size_t)head * (size_t)nodes, in, sizeof(float) * (size_t)nodes);
    memcpy(fhist + (size_t)(head + taps) * (size_t)nodes, in, sizeof(float) * (size_t)nodes);
    if (nodes == 1) {
      const float *ring = fhist + head;
      float part[16] = {0.0f}, y = 0.0f; /* 16 partial sums: the dot product vectorises */
      for (k = 0; k + 16 <= taps; k += 16)
        for (i = 0; i < 16; ++i) part[i] += fh[k + i] * ring[k + i];
      for (; k < taps; ++k) y += fh[k] * ring[k];
      for (i = 0; i < 16; ++i) y += part[i];
      fout[0] = y;
    } else {
      for (i = 0; i < nodes; ++i) fout[i] = 0.0f;
      for (k = 0; k < taps; ++k) {
        const float hk = fh[k];
        const float *row = fhist + (size_t)(head + k) * (size_t)nodes;
        for (i = 0; i < nodes; ++i) fout[i] += hk * row[i];
      }
    }
    acc += fout[0];
  }
  return acc;
}

static BENCH_INLINE double direct_q31_body(int nodes, int taps, long steps) {
  static int64_t y[MAX_NODES];
  long s;
  int k, i, head = 0;
  double acc = 0.0;
  for (s = 0; s < steps; ++s) {
    const int32_t *in = qin + (s & 63) * nodes;
    head = head == 0 ? taps - 1 : head - 1;
    memcpy(qhist + (size_t)head * (size_t)nodes, in, sizeof(int32_t) * (size_t)nodes);
    memcpy(qhist + (size_t)(head + taps) * (size_t)nodes, in, sizeof(int32_t) * (size_t)nodes);
    if (nodes == 1) {
      const int32_t *ring = qhist + head;
      int64_t v = 0;
      for (k = 0; k < taps; ++k) v += (int64_t)qh[k] * ring[k];
      y[0] = v;
    } else {
      for (i = 0; i < nodes; ++i) y[i] = 0;
      for (k = 0; k < taps; ++k) {
        const int64_t hk = qh[k];
        const int32_t *row = qhist + (size_t)(head + k) * (size_t)nodes;
        for (i = 0; i < nodes; ++i) y[i] += hk * row[i];
      }
    }
    for (i = 0; i < nodes; ++i) qout[i] = (int32_t)(y[i] >> 31);
    acc += qout[0];
  }
  return acc;
}

static double direct_generic(format fmt, int nodes, int taps, long steps) {
  return fmt == F32 ? direct_f32_body(nodes, taps, steps) : direct_q31_body(nodes, taps, steps);
}
#if ADMITGEN_RT_HAVE_AVX2
__attribute__((target("avx2"))) static double direct_avx2(format fmt, int nodes, int taps, long steps) {
  return fmt == F32 ? direct_f32_body(nodes, taps, steps) : direct_q31_body(nodes, taps, steps);
}
/* Where the runtime's kernels use AVX-512, so does the baseline, with 512-bit vectors (GCC's default tuning
 * would keep 256-bit ones) and FMA (which the runtime forgoes to keep its rounding identical on every path). */
__attribute__((target("avx2,fma,avx512f,avx512vl,prefer-vector-width=512"))) static double direct_avx512(format fmt, int nodes,
                                                                                                        int taps, long steps) {
  return fmt == F32 ? direct_f32_body(nodes, taps, steps) : direct_q31_body(nodes, taps, steps);
}
#endif

/* One timing of the direct convolution (q15 data would use the q31 arithmetic: not timed separately). */
static double time_direct_isa(format fmt, int nodes, int taps, int isa) {
  const long steps = TOTAL / nodes / (nodes == 1 ? 16 : 1); /* a mono step is slow: fewer of them */
  double t0;
  memset(fhist, 0, sizeof(float) * 2u * (size_t)taps * (size_t)nodes);
  memset(qhist, 0, sizeof(int32_t) * 2u * (size_t)taps * (size_t)nodes);
  t0 = now_ns();
#if ADMITGEN_RT_HAVE_AVX2
  if (isa == 2)
    sink = direct_avx512(fmt, nodes, taps, steps);
  else if (isa == 1)
    sink = direct_avx2(fmt, nodes, taps, steps);
  else
#endif
    sink = direct_generic(fmt, nodes, taps, steps);
  (void)isa;
  return (now_ns() - t0) / (double)(steps * nodes);
}

/* One timing of the strongest baseline: each build up to the CPU's best instruction set (AVX-512 code is not
 * always the faster one: q31 is), the fastest of them. */
static double time_direct(format fmt, int nodes, int taps) {
  const int top = admitgen_rt__use_simd(ADMITGEN_RT_ISA_BEST); /* 2 AVX-512, 1 AVX2 (or NEON), 0 none */
  double best = 1e30;
  int isa;
  for (isa = top; isa >= (top > 0 ? 1 : 0); --isa) {
    const double t = time_direct_isa(fmt, nodes, taps, isa);
    if (t < best) best = t;
  }
  return best;
}

/* The fastest of REPEAT timings (time_runtime with arg = isa, time_direct with arg = taps). */
static double fastest(double (*timing)(format, int, int), format fmt, int nodes, int arg) {
  double best = 1e30;
  int r;
  for (r = 0; r < REPEAT; ++r) {
    const double t = timing(fmt, nodes, arg);
    if (t < best) best = t;
  }
  return best;
}

static int impulse_response(void) {
  admitgen_rt_f32 inst;
  const float zero = 0.0f, one = 1.0f;
  int i, taps;
  if (admitgen_rt_init_f32(&inst, &bench_f32_48000, 48000, 1, aligned(), sizeof arena - 64) != ADMITGEN_RT_SUCCESS) exit(1);
  admitgen_rt_process_f32(&inst, &one, fh, 1, 1);
  for (i = 1; i < MAX_TAPS; ++i) admitgen_rt_process_f32(&inst, &zero, fh + i, 1, 1);
  taps = truncated_length(fh, MAX_TAPS);
  for (i = 0; i < taps; ++i) qh[i] = (int32_t)((double)fh[i] * 2147483648.0 / (double)(1 << bench_q31_48000.out_shift));
  return taps;
}

static void goal(const char *what, double value, const char *unit, double limit, int at_most) {
  const int met = at_most ? value <= limit : value >= limit;
  printf("goal %-44s %s %6.2f %-14s measured %8.3f  %s\n", what, at_most ? "<=" : ">=", limit, unit, value,
         met ? "MET" : "NOT MET");
}

int main(void) {
  static const int node_counts[2] = {1, 1024};
  const int states = bench_f32_48000.n_real + 2 * bench_f32_48000.n_pair;
  const int simd = admitgen_rt__use_simd(ADMITGEN_RT_ISA_BEST);
  double f32_1 = 0.0, f32_1024 = 0.0, f32_ratio = 0.0, q31_1024 = 0.0;
  int i, taps, n, fmt;
  unsigned x = 12345u;
  for (i = 0; i < MAX_NODES * 64; ++i) {
    x = x * 1103515245u + 12345u;
    fin[i] = (float)((int)(x >> 8) - (1 << 23)) / (float)(1 << 24); /* uniform [-0.5, 0.5) */
    qin[i] = (int32_t)((double)fin[i] * 2147483648.0);
    hin[i] = (int16_t)(qin[i] / 65536);
  }
  taps = impulse_response();
  printf("admitgen runtime benchmark: model %s at 48000 Hz, %d recursive states + %d FIR taps per node; direct\n"
         "convolution baseline: the impulse response truncated at -100 dB = %d taps. Vector kernels: %s.\n"
         "Fastest of %d timings (thread CPU time) of %ld node-samples each.\n",
         BENCH_F32_ORDER, states, (int)bench_f32_48000.n_fir, taps,
         simd == 2 ? "AVX-512 F+VL (runtime and direct baseline)"
                  : simd == 1 ? (ADMITGEN_RT_HAVE_AVX2 ? "AVX2 (runtime and direct baseline)" : "NEON") : "none (scalar)", REPEAT, TOTAL);
  printf("%-5s %6s %14s %16s %14s %8s %14s %12s\n", "fmt", "nodes", "ns/node-sample", "ns/state-update", "direct ns",
         "ratio", "scalar ns", "vec/scalar");
  for (fmt = F32; fmt <= Q15; ++fmt)
    for (n = 0; n < 2; ++n) {
      const int nodes = node_counts[n];
      const double r = fastest(time_runtime, (format)fmt, nodes, ADMITGEN_RT_ISA_BEST);
      const double s = nodes > ADMITGEN_RT_SMALL_N && simd ? fastest(time_runtime, (format)fmt, nodes, ADMITGEN_RT_ISA_SCALAR) : r;
      const double d = fmt == Q15 ? 0.0 : fastest(time_direct, (format)fmt, nodes, taps);
      if (fmt == Q15)
        printf("%-5s %6d %14.3f %16.3f %14s %8s %14.3f %12.1f\n", format_name[fmt], nodes, r, r / states, "-", "-", s, s / r);
      else
        printf("%-5s %6d %14.3f %16.3f %14.3f %8.1f %14.3f %12.1f\n", format_name[fmt], nodes, r, r / states, d, d / r, s,
               s / r);
      if (fmt == F32 && nodes == 1) f32_1 = r;
      if (fmt == F32 && nodes == 1024) {
        f32_1024 = r / states;
        f32_ratio = d / r;
      }
      if (fmt == Q31 && nodes == 1024) q31_1024 = r / states;
    }
  printf("(scalar ns: the same call with the vector kernels disabled; the small-n path of 1 node has none.)\n");
  if (admitgen_rt__use_simd(ADMITGEN_RT_ISA_BEST) == 2) {
    const double a32 = fastest(time_runtime, F32, 1024, ADMITGEN_RT_ISA_AVX2) / states;
    const double a31 = fastest(time_runtime, Q31, 1024, ADMITGEN_RT_ISA_AVX2) / states;
    const double a15 = fastest(time_runtime, Q15, 1024, ADMITGEN_RT_ISA_AVX2) / states;
    printf("1024 nodes, AVX2 kernels only (this CPU also has AVX-512 F+VL, used above): f32 %.3f, q31 %.3f, q15 %.3f "
           "ns/state-update\n", a32, a31, a15);
  }
  goal("f32, 1024 nodes, ns per state update", f32_1024, "ns", 0.25, 1);
  goal("f32, 1024 nodes, speed-up over direct convolution", f32_ratio, "x", 50.0, 0);
  goal("f32, 1 node, ns per sample", f32_1, "ns", 3.0, 1);
  goal("q31, 1024 nodes, ns per state update", q31_1024, "ns", 1.0, 1);
  printf("state memory per node: %.1f bytes f32, %.1f bytes q31 (incl. per-node scratch); persistent state %d x 4 bytes\n"
         "(%d states + %d past inputs).\n",
         (double)admitgen_rt_state_bytes_f32(&bench_f32_48000, 1024) / 1024.0,
         (double)admitgen_rt_state_bytes_q31(&bench_q31_48000, 1024) / 1024.0, states + bench_f32_48000.n_fir - 1, states,
         bench_f32_48000.n_fir - 1);
  return 0;
}
