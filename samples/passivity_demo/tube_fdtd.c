/* SPDX-License-Identifier: MIT */
/*
 * tube_fdtd.c - 1D tube FDTD with an admitgen boundary filter (runtime f32, implicit history/commit
 * coupling): bounded energy with a passive filter, growth with a deliberately non-passive one
 * (docs/physics.md §2.4: a mode decays at sigma = (c/L) Re beta_n(omega_n), grows where Re beta_n < 0).
 *
 * Staggered leapfrog, pressure p at nodes x_i = i dx (i = 0..N), velocity v at x_{i+1/2}; rigid end at
 * x = 0 (v_{-1/2} = -v_{1/2} mirrored, i.e. a half cell with zero flux), admittance wall at x = L:
 *   v^{n+1/2}_{i+1/2} = v^{n-1/2}_{i+1/2} - dt/(rho dx) (p_{i+1} - p_i)
 *   p^{n+1}_i = p^n_i - rho c^2 dt/dx (v_{i+1/2} - v_{i-1/2})
 *   p^{n+1}_N = p^n_N - 2 rho c^2 dt/dx (v_wall^{n+1/2} - v_{N-1/2}),  rho c v_wall^{n+1/2} = (y^{n+1} + y^n)/2,
 *   y^{n+1} = h0 p^{n+1}_N + s^n  (the filter's instantaneous gain + history split)
 * solved implicitly: p^{n+1}_N = (p^n_N + K v_{N-1/2} - K (s^n + y^n)/(2 rho c)) / (1 + K h0/(2 rho c)),
 * K = 2 rho c^2 dt/dx, then admitgen_rt_commit_f32(p^{n+1}_N). The wall work per step is then
 * mean(p) * mean(y) with mean(y) = H(z) mean(p): non-negative in total iff the discrete H is passive. Energy E = sum (dx_i/2) (p^2/(rho c^2) + rho v^2) (half cells at the ends).
 *
 * Usage: tube_fdtd  → prints the energy history of both walls; exit 0 iff the passive wall keeps
 * max E/E0 <= 1.02 and E(2 s)/E0 < 1, and the non-passive wall's energy grows above 1e3 E0.
 */
#include "wall_active.h"
#include "wall_passive.h"

#include <math.h>
#include <stdio.h>

#define FS 48000
#define N_CELLS 120
#define SECONDS 2.0

static double energy(const double *p, const double *v, double dx, double rho, double c) {
  double e = 0.0;
  int i;
  for (i = 0; i <= N_CELLS; ++i) {
    const double w = (i == 0 || i == N_CELLS) ? 0.5 * dx : dx;
    e += 0.5 * w * p[i] * p[i] / (rho * c * c);
  }
  for (i = 0; i < N_CELLS; ++i) e += 0.5 * dx * rho * v[i] * v[i];
  return e;
}

/* Runs the tube with one wall model; writes the energy ratio at the report times, returns max E/E0. */
static double run(const admitgen_rt_model_f32 *model, const char *label, double *final_ratio) {
  static double p[N_CELLS + 1], v[N_CELLS];
  static unsigned char mem[4096] __attribute__((aligned(ADMITGEN_RT_ALIGN)));
  const double c = 343.0, rho = 1.2, dt = 1.0 / FS, dx = c * dt / 0.9; /* Courant 0.9 */
  const double K = 2.0 * rho * c * c * dt / dx;
  const long steps = (long)(SECONDS * FS);
  const double report[] = {0.1, 0.25, 0.5, 1.0, 2.0};
  admitgen_rt_f32 wall;
  double e0, peak = 1.0;
  float y_prev = 0.0f;
  long n;
  int i, r = 0;
  if (admitgen_rt_init_f32(&wall, model, FS, 1, mem, sizeof mem) != ADMITGEN_RT_SUCCESS) return -1.0;
  for (i = 0; i <= N_CELLS; ++i) { /* Gaussian pulse in the middle of the tube */
    const double x = (i - 0.5 * N_CELLS) / 6.0;
    p[i] = exp(-x * x);
  }
  for (i = 0; i < N_CELLS; ++i) v[i] = 0.0;
  e0 = energy(p, v, dx, rho, c);
  printf("%-12s t [s]:", label);
  for (n = 1; n <= steps; ++n) {
    float hist, u, y;
    for (i = 0; i < N_CELLS; ++i) v[i] -= dt / (rho * dx) * (p[i + 1] - p[i]);
    p[0] -= 2.0 * rho * c * c * dt / dx * v[0];
    for (i = 1; i < N_CELLS; ++i) p[i] -= rho * c * c * dt / dx * (v[i] - v[i - 1]);
    admitgen_rt_history_f32(&wall, &hist);
    p[N_CELLS] = (p[N_CELLS] + K * v[N_CELLS - 1] - K * (hist + y_prev) / (2.0 * rho * c)) /
                 (1.0 + K * wall.model->h0 / (2.0 * rho * c));
    u = (float)p[N_CELLS];
    admitgen_rt_commit_f32(&wall, &u, &y);
    y_prev = y;
    {
      const double ratio = energy(p, v, dx, rho, c) / e0;
      if (ratio > peak) peak = ratio;
      if (r < 5 && n == (long)(report[r] * FS)) {
        printf("  %.2f: E/E0 = %.3g", report[r], ratio);
        ++r;
        *final_ratio = ratio;
      }
    }
  }
  printf("  (max %.3g)\n", peak);
  return peak;
}

int main(void) {
  double fin_passive = 0.0, fin_active = 0.0;
  const double peak_passive = run(wall_passive_model(FS), "passive", &fin_passive);
  const double peak_active = run(wall_active_model(FS), "non-passive", &fin_active);
  const int ok = peak_passive > 0.0 && peak_passive <= 1.02 && fin_passive < 1.0 && fin_active > 1e3;
  printf("%s: passive wall max E/E0 = %.4g, E(2 s)/E0 = %.3g; non-passive wall E(2 s)/E0 = %.3g\n",
         ok ? "PASS" : "FAIL", peak_passive, fin_passive, fin_active);
  return ok ? 0 : 1;
}
