/* SPDX-License-Identifier: MIT */
/*
 * rt_response_f32.c - the emitted f32 header + runtime, compiled by the C compiler and run:
 *  1. frequency response measured from the running filter's impulse response (DTFT) against the
 *     continuous model G at the data frequencies, per f/fs band and per sample rate (bounds below);
 *  2. the same against the double-precision discrete reference (isolates float arithmetic error);
 *  3. block-size invariance (1, 7, 64, 1024) and node/stride layout: bit-identical outputs;
 *  4. the FDTD split y^n = h0 u^n + s^{n-1}.
 */
#define WALL_F32_WITH_REFERENCE
#include "wall_f32.h"
#include "rt_test_util.h"

#include <math.h>
#include <string.h>

#define N_IR 8192
#define N_F 200
#define N_BANDS 5
static const double band_edge[N_BANDS + 1] = {0.0, 0.02, 0.05, 0.1, 0.2, 0.5};

/* Bound on max |H - G|/|G| per rate and f/fs band (-1: no data there). What limits it is the refit: the
 * generator computes, in double, the error of the emitted model at the data frequencies and states it in the
 * header (48 kHz: 9.1e-6, 96 kHz: 6.9e-6, 32 kHz: 3.9e-5, 24 kHz: 3.9e-4, 16 kHz: 8.3e-3 with the
 * 9.3 kHz real pole folded, above 16 kHz's Nyquist). It grows with f/fs (the FIR taps approximate a
 * polynomial in jwT), so the bounds are per band: the measured value (run of this commit) times 2,
 * which also covers the float arithmetic (item 2). */
typedef struct rate_bound {
  int32_t fs;
  double bound[N_BANDS];
} rate_bound;
static const rate_bound bounds[] = {
    {96000, {5e-6, 1.5e-5, -1, -1, -1}},
    {48000, {3e-6, 5e-6, 2e-5, -1, -1}},
    {32000, {1.5e-5, 1.5e-5, 3e-5, 8e-5, -1}},
    /* 24 kHz: emit prefers the refit candidate whose response stays passive up to Nyquist; the most
     * accurate one was not (Re H < 0 over 8.2-8.7 kHz), and the passive one costs accuracy: measured
     * 8.6e-5, 2.0e-4, 2.2e-4, 9.7e-4 per band, asserted at 2x. */
    {24000, {1.8e-4, 4e-4, 4.5e-4, 2e-3, -1}},
    {16000, {2e-3, 2.5e-3, 3.5e-3, 7e-3, 1.7e-2}},
};
/* float arithmetic: |H_f32 - H_double| / |G|. States are O(1) and each update adds <= 2^-24 relative error;
 * the noise gain of the slowest pair at 96 kHz is 1/(1 - r^2) = 31, |G| >= 0.01 at the data: about
 * 6e-8 * sqrt(31) * (sum|c| ~ 3) / 0.01 = 1e-4 worst case; measured 1e-6. Asserted: 2e-5. */
#define FLOAT_BOUND 2e-5

static void continuous(double f, double *re, double *im) {
  const double w = 2.0 * 3.14159265358979323846 * f;
  int q, s;
  double gr = wall_f32_theta[0], gi = 0.0;
  for (q = 0; q < WALL_F32_Q; ++q) {
    const double a = wall_f32_theta[1 + 2 * q], l = wall_f32_theta[2 + 2 * q], d = l * l + w * w;
    gr += a * l / d;
    gi -= a * w / d;
  }
  for (s = 0; s < WALL_F32_S; ++s) {
    const double *p = wall_f32_theta + 1 + 2 * WALL_F32_Q + 4 * s;
    const double b = p[0], c = p[1], al = p[2], be = p[3];
    const double wp = w + be, wm = w - be, ip = 1.0 / (al * al + wp * wp), im_ = 1.0 / (al * al + wm * wm);
    gr += (b * al + c * wp) * ip + (b * al - c * wm) * im_;
    gi += (c * al - b * wp) * ip - (c * al + b * wm) * im_;
  }
  *re = gr;
  *im = gi;
}

/* DTFT of h at f (phasor recursion; renormalised every 256 samples). */
static void dtft(const double *h, int n, double f, double fs, double *re, double *im) {
  const double th = -2.0 * 3.14159265358979323846 * f / fs;
  const double cr = cos(th), ci = sin(th);
  double zr = 1.0, zi = 0.0, sr = 0.0, si = 0.0;
  int k;
  for (k = 0; k < n; ++k) {
    double t;
    sr += h[k] * zr;
    si += h[k] * zi;
    t = zr * cr - zi * ci;
    zi = zr * ci + zi * cr;
    zr = t;
    if ((k & 255) == 255) {
      zr = cos(th * (k + 1));
      zi = sin(th * (k + 1));
    }
  }
  *re = sr;
  *im = si;
}

/* Double-precision impulse response of the reference tables (same recursion as the runtime). */
static void reference_ir(const double *fir, int nf, const double *real, int nr, const double *pair, int np, double *h,
                         int n) {
  double x[8] = {0}, xi[8] = {0}, eta[8] = {0};
  int i, k;
  for (i = 0; i < n; ++i) {
    const double u = i == 0 ? 1.0 : 0.0;
    double acc = i < nf ? fir[i] : 0.0;
    for (k = 0; k < nr; ++k) {
      x[k] += real[2 * k] * (u - x[k]);
      acc += real[2 * k + 1] * x[k];
    }
    for (k = 0; k < np; ++k) {
      const double *p = pair + 5 * k, a = xi[k], b = eta[k];
      xi[k] = a + (p[0] * a - p[1] * b + p[2] * u);
      eta[k] = b + (p[0] * b + p[1] * a);
      acc += p[3] * xi[k] + p[4] * eta[k];
    }
    h[i] = acc;
  }
}

static float in_buf[4 * N_IR], out_a[4 * N_IR], out_b[4 * N_IR];
static double h32[N_IR], href[N_IR];

static void check_rate(int32_t fs, const double *ref_fir, const double *ref_real, const double *ref_pair,
                       const rate_bound *b) {
  const admitgen_rt_model_f32 *m = wall_f32_model(fs);
  admitgen_rt_f32 inst;
  double worst[N_BANDS] = {0}, worst_float = 0.0;
  int counts[N_BANDS] = {0};
  int i, j;
  RT_CHECK(m != NULL, "no model for %ld Hz", (long)fs);
  if (m == NULL) return;
  RT_CHECK(admitgen_rt_init_f32(&inst, m, fs, 1, rt_aligned(0), 1u << 19) == ADMITGEN_RT_SUCCESS, "init");
  memset(in_buf, 0, sizeof in_buf);
  in_buf[0] = 1.0f;
  admitgen_rt_process_f32(&inst, in_buf, out_a, N_IR, 1);
  for (i = 0; i < N_IR; ++i) h32[i] = out_a[i];
  reference_ir(ref_fir, m->n_fir, ref_real, m->n_real, ref_pair, m->n_pair, href, N_IR);
  for (i = 0; i < N_F; ++i) {
    const double f = WALL_F32_DATA_F_MIN_HZ * pow((double)WALL_F32_DATA_F_MAX_HZ / WALL_F32_DATA_F_MIN_HZ, i / (N_F - 1.0));
    double gr, gi, hr, hi, rr, ri, g, e1, e2;
    continuous(f, &gr, &gi);
    dtft(h32, N_IR, f, fs, &hr, &hi);
    dtft(href, N_IR, f, fs, &rr, &ri);
    g = sqrt(gr * gr + gi * gi);
    e1 = sqrt((hr - gr) * (hr - gr) + (hi - gi) * (hi - gi)) / g;
    e2 = sqrt((hr - rr) * (hr - rr) + (hi - ri) * (hi - ri)) / g;
    for (j = 0; j < N_BANDS; ++j)
      if (f / fs >= band_edge[j] && f / fs < band_edge[j + 1]) {
        if (e1 > worst[j]) worst[j] = e1;
        ++counts[j];
      }
    if (e2 > worst_float) worst_float = e2;
  }
  printf("fs %6ld Hz: max |H-G|/|G| per f/fs band:", (long)fs);
  for (j = 0; j < N_BANDS; ++j) {
    if (counts[j] == 0) {
      printf("  [%.2f,%.2f) -      ", band_edge[j], band_edge[j + 1]);
      continue;
    }
    printf("  [%.2f,%.2f) %.2e", band_edge[j], band_edge[j + 1], worst[j]);
    RT_CHECK(b->bound[j] > 0.0 && worst[j] <= b->bound[j], "fs %ld band %d: %.3e > bound %.1e", (long)fs, j, worst[j],
             b->bound[j]);
  }
  printf("; float vs double %.2e\n", worst_float);
  RT_CHECK(worst_float <= FLOAT_BOUND, "float arithmetic error %.3e", worst_float);
}

static void check_blocks_and_nodes(void) {
  const admitgen_rt_model_f32 *m = &wall_f32_48000;
  static const int32_t sizes[4] = {1, 7, 64, 1024};
  admitgen_rt_f32 inst;
  rt_rng rng;
  int i, s, k;
  const int n = 3000;
  rt_rng_seed(&rng, 7u);
  for (i = 0; i < 4 * n; ++i) in_buf[i] = (float)(rt_rng_uniform(&rng) - 0.5);
  /* reference: one call, node 0 of a 1-node instance */
  RT_CHECK(admitgen_rt_init_f32(&inst, m, 48000, 1, rt_aligned(0), 1u << 19) == 0, "init");
  admitgen_rt_process_f32(&inst, in_buf, out_a, n, 1);
  for (s = 0; s < 4; ++s) {
    int pos = 0;
    admitgen_rt_reset_f32(&inst);
    while (pos < n) {
      const int len = pos + sizes[s] > n ? n - pos : sizes[s];
      admitgen_rt_process_f32(&inst, in_buf + pos, out_b + pos, len, 1);
      pos += len;
    }
    RT_CHECK(memcmp(out_a, out_b, (size_t)n * sizeof(float)) == 0, "block size %ld changes the output", (long)sizes[s]);
  }
  /* 3 nodes interleaved with stride 4 (a 4-channel buffer, 3 walls): node k equals a 1-node run on channel k */
  RT_CHECK(admitgen_rt_init_f32(&inst, m, 48000, 3, rt_aligned(0), 1u << 19) == 0, "init 3 nodes");
  admitgen_rt_process_f32(&inst, in_buf, out_b, n / 4, 4);
  for (k = 0; k < 3; ++k) {
    admitgen_rt_f32 one;
    static float chan_in[1000], chan_out[1000];
    for (i = 0; i < n / 4; ++i) chan_in[i] = in_buf[4 * i + k];
    RT_CHECK(admitgen_rt_init_f32(&one, m, 48000, 1, rt_aligned(1u << 19), 1u << 18) == 0, "init one");
    admitgen_rt_process_f32(&one, chan_in, chan_out, n / 4, 1);
    for (i = 0; i < n / 4; ++i)
      if (chan_out[i] != out_b[4 * i + k]) break;
    RT_CHECK(i == n / 4, "node %d differs from its single-node run at frame %d", k, i);
  }
}

static void check_split(void) {
  /* y^n = h0 u^n + s^{n-1}: relative error bounded by float rounding of the two sums (~1e-6). */
  const admitgen_rt_model_f32 *m = &wall_f32_48000;
  admitgen_rt_f32 inst;
  rt_rng rng;
  float s[2], u[2], y[2];
  double worst = 0.0;
  int i, k;
  rt_rng_seed(&rng, 11u);
  RT_CHECK(admitgen_rt_init_f32(&inst, m, 48000, 2, rt_aligned(0), 1u << 19) == 0, "init");
  for (i = 0; i < 2000; ++i) {
    admitgen_rt_history_f32(&inst, s);
    for (k = 0; k < 2; ++k) u[k] = (float)(rt_rng_uniform(&rng) - 0.5);
    admitgen_rt_commit_f32(&inst, u, y);
    for (k = 0; k < 2; ++k) {
      const double e = fabs((double)y[k] - ((double)m->h0 * u[k] + s[k]));
      if (e > worst) worst = e;
    }
  }
  printf("split y = h0 u + s: max abs error %.2e (h0 = %.6f)\n", worst, (double)m->h0);
  RT_CHECK(worst <= 1e-5, "split error %.3e", worst);
}

static void check_errors(void) {
  admitgen_rt_f32 inst;
  RT_CHECK(admitgen_rt_init_f32(&inst, &wall_f32_48000, 44100, 1, rt_aligned(0), 1u << 19) == ADMITGEN_RT_RATE_MISMATCH,
           "rate mismatch accepted");
  RT_CHECK(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 1, (unsigned char *)rt_aligned(0) + 4, 1u << 19) ==
               ADMITGEN_RT_MISALIGNED,
           "misaligned memory accepted");
  RT_CHECK(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 1, rt_aligned(0), 16) == ADMITGEN_RT_BUFFER_TOO_SMALL,
           "small buffer accepted");
  RT_CHECK(admitgen_rt_init_f32(&inst, &wall_f32_48000, 48000, 1, rt_aligned(0), 1u << 19) == ADMITGEN_RT_SUCCESS, "init");
  RT_CHECK(admitgen_rt_reinit_f32(&inst, &wall_f32_96000, 96000) == ADMITGEN_RT_SHAPE_MISMATCH ||
               wall_f32_96000.n_fir == wall_f32_48000.n_fir,
           "shape mismatch accepted");
  RT_CHECK(admitgen_rt_reinit_f32(&inst, &wall_f32_48000, 96000) == ADMITGEN_RT_RATE_MISMATCH, "reinit rate");
}

int main(void) {
  check_rate(96000, wall_f32_96000_ref_fir, wall_f32_96000_ref_real, wall_f32_96000_ref_pair, &bounds[0]);
  check_rate(48000, wall_f32_48000_ref_fir, wall_f32_48000_ref_real, wall_f32_48000_ref_pair, &bounds[1]);
  check_rate(32000, wall_f32_32000_ref_fir, wall_f32_32000_ref_real, wall_f32_32000_ref_pair, &bounds[2]);
  check_rate(24000, wall_f32_24000_ref_fir, wall_f32_24000_ref_real, wall_f32_24000_ref_pair, &bounds[3]);
  check_rate(16000, wall_f32_16000_ref_fir, wall_f32_16000_ref_real, wall_f32_16000_ref_pair, &bounds[4]);
  check_blocks_and_nodes();
  check_split();
  check_errors();
  printf("%s (%d failures)\n", rt_failures == 0 ? "PASS" : "FAIL", rt_failures);
  return rt_failures == 0 ? 0 : 1;
}
