/*
 * rt_bench.c - runtime benchmark: recursive convolution (admitgen runtime) vs direct convolution with the
 * same impulse response truncated at -100 dB, for f32 and q31, 1 node and 1024 nodes, in one run.
 * Prints ns per node-sample, ns per state update (per recursive state and sample), the direct/recursive
 * ratio, and the state memory per node. Input: white noise (no subnormals). Model: the reference Q1S1 fit at
 * 48 kHz (samples/fits/q1s1_reference.json).
 */
#define _POSIX_C_SOURCE 199309L
#include "bench_f32.h"
#include "bench_q31.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_NODES 1024
#define MAX_TAPS 4096
#define TOTAL (1L << 23) /* node-samples per measurement */

static double now_ns(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static unsigned char arena[(1u << 22) + 64];
static void *aligned(void) { return (void *)(((uintptr_t)arena + 63u) & ~(uintptr_t)63u); }

static float fin[MAX_NODES * 64], fout[MAX_NODES * 64];
static int32_t qin[MAX_NODES * 64], qout[MAX_NODES * 64];
static float fh[MAX_TAPS], fhist[2 * MAX_TAPS * MAX_NODES];
static int32_t qh[MAX_TAPS], qhist[2 * MAX_TAPS * MAX_NODES];
static volatile double sink;

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

static double bench_f32(int nodes) {
  admitgen_rt_f32 inst;
  const int fpc = frames_per_call(nodes);
  const long calls = TOTAL / ((long)nodes * fpc);
  long c;
  double t0, acc = 0.0;
  if (admitgen_rt_init_f32(&inst, &bench_f32_48000, 48000, nodes, aligned(), sizeof arena - 64) != ADMITGEN_RT_SUCCESS) exit(1);
  t0 = now_ns();
  for (c = 0; c < calls; ++c) {
    admitgen_rt_process_f32(&inst, fin, fout, fpc, nodes);
    acc += fout[0];
  }
  sink = acc;
  return (now_ns() - t0) / (double)TOTAL;
}

static double bench_q31(int nodes) {
  admitgen_rt_q31 inst;
  const int fpc = frames_per_call(nodes);
  const long calls = TOTAL / ((long)nodes * fpc);
  long c;
  double t0, acc = 0.0;
  if (admitgen_rt_init_q31(&inst, &bench_q31_48000, 48000, nodes, aligned(), sizeof arena - 64) != ADMITGEN_RT_SUCCESS) exit(1);
  t0 = now_ns();
  for (c = 0; c < calls; ++c) {
    admitgen_rt_process_q31(&inst, qin, qout, fpc, nodes);
    acc += qout[0];
  }
  sink = acc;
  return (now_ns() - t0) / (double)TOTAL;
}

/* Direct convolution, a fair baseline: past inputs in a doubled ring (each input written at head and
 * head + taps, so rows head..head+taps-1 are contiguous: no index arithmetic in the MAC loop), SoA
 * hist[k][node] so the node loop vectorises; for one node the tap loop is a contiguous dot product. */
static double direct_f32(int nodes, int taps) {
  const long steps = TOTAL / nodes;
  long s;
  int k, i, head = 0;
  double t0, acc = 0.0;
  memset(fhist, 0, sizeof(float) * 2u * (size_t)taps * (size_t)nodes);
  t0 = now_ns();
  for (s = 0; s < steps; ++s) {
    const float *in = fin + (s & 63) * nodes;
    float *y = fout;
    head = head == 0 ? taps - 1 : head - 1;
    memcpy(fhist + (size_t)head * (size_t)nodes, in, sizeof(float) * (size_t)nodes);
    memcpy(fhist + (size_t)(head + taps) * (size_t)nodes, in, sizeof(float) * (size_t)nodes);
    for (i = 0; i < nodes; ++i) y[i] = 0.0f;
    for (k = 0; k < taps; ++k) {
      const float hk = fh[k];
      const float *row = fhist + (size_t)(head + k) * (size_t)nodes;
      for (i = 0; i < nodes; ++i) y[i] += hk * row[i];
    }
    acc += y[0];
  }
  sink = acc;
  return (now_ns() - t0) / (double)TOTAL;
}

static double direct_q31(int nodes, int taps) {
  static int64_t y[MAX_NODES];
  const long steps = TOTAL / nodes;
  long s;
  int k, i, head = 0;
  double t0, acc = 0.0;
  memset(qhist, 0, sizeof(int32_t) * 2u * (size_t)taps * (size_t)nodes);
  t0 = now_ns();
  for (s = 0; s < steps; ++s) {
    const int32_t *in = qin + (s & 63) * nodes;
    head = head == 0 ? taps - 1 : head - 1;
    memcpy(qhist + (size_t)head * (size_t)nodes, in, sizeof(int32_t) * (size_t)nodes);
    memcpy(qhist + (size_t)(head + taps) * (size_t)nodes, in, sizeof(int32_t) * (size_t)nodes);
    for (i = 0; i < nodes; ++i) y[i] = 0;
    for (k = 0; k < taps; ++k) {
      const int64_t hk = qh[k];
      const int32_t *row = qhist + (size_t)(head + k) * (size_t)nodes;
      for (i = 0; i < nodes; ++i) y[i] += hk * row[i];
    }
    for (i = 0; i < nodes; ++i) qout[i] = (int32_t)(y[i] >> 31);
    acc += qout[0];
  }
  sink = acc;
  return (now_ns() - t0) / (double)TOTAL;
}

int main(void) {
  static const int node_counts[2] = {1, 1024};
  const int states = bench_f32_48000.n_real + 2 * bench_f32_48000.n_pair;
  admitgen_rt_f32 inst;
  float one = 1.0f;
  int i, taps, n;
  unsigned x = 12345u;
  for (i = 0; i < MAX_NODES * 64; ++i) {
    x = x * 1103515245u + 12345u;
    fin[i] = (float)((int)(x >> 8) - (1 << 23)) / (float)(1 << 24); /* uniform [-0.5, 0.5) */
    qin[i] = (int32_t)((double)fin[i] * 2147483648.0);
  }
  /* impulse response of the f32 model, truncated at -100 dB; the q31 one in output units (2^-out_shift) */
  if (admitgen_rt_init_f32(&inst, &bench_f32_48000, 48000, 1, aligned(), sizeof arena - 64) != ADMITGEN_RT_SUCCESS) return 1;
  admitgen_rt_process_f32(&inst, &one, fh, 1, 1);
  for (i = 1; i < MAX_TAPS; ++i) {
    const float zero = 0.0f;
    admitgen_rt_process_f32(&inst, &zero, fh + i, 1, 1);
  }
  taps = truncated_length(fh, MAX_TAPS);
  for (i = 0; i < taps; ++i) qh[i] = (int32_t)((double)fh[i] * 2147483648.0 / (double)(1 << bench_q31_48000.out_shift));
  printf("admitgen runtime benchmark: model %s at 48000 Hz, %d recursive states + %d FIR taps per node; direct\n"
         "convolution baseline: the impulse response truncated at -100 dB = %d taps. %ld node-samples per figure.\n",
         BENCH_F32_ORDER, states, (int)bench_f32_48000.n_fir, taps, TOTAL);
  printf("%-5s %6s %14s %16s %14s %8s %14s\n", "fmt", "nodes", "ns/node-sample", "ns/state-update", "direct ns/ns",
         "ratio", "state B/node");
  for (n = 0; n < 2; ++n) {
    const int nodes = node_counts[n];
    const double r = bench_f32(nodes), d = direct_f32(nodes, taps);
    const double bytes = (double)admitgen_rt_state_bytes_f32(&bench_f32_48000, nodes) / nodes;
    printf("%-5s %6d %14.3f %16.3f %14.3f %8.1f %14.1f\n", "f32", nodes, r, r / states, d, d / r, bytes);
  }
  for (n = 0; n < 2; ++n) {
    const int nodes = node_counts[n];
    const double r = bench_q31(nodes), d = direct_q31(nodes, taps);
    const double bytes = (double)admitgen_rt_state_bytes_q31(&bench_q31_48000, nodes) / nodes;
    printf("%-5s %6d %14.3f %16.3f %14.3f %8.1f %14.1f\n", "q31", nodes, r, r / states, d, d / r, bytes);
  }
  printf("state bytes per node include the per-node scratch (input copy, accumulator); the persistent state is\n"
         "%d x 4 bytes (%d states + %d past inputs).\n", states + bench_f32_48000.n_fir - 1, states,
         bench_f32_48000.n_fir - 1);
  return 0;
}
