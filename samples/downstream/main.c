/* SPDX-License-Identifier: MIT */
/* Downstream use of a generated boundary filter: instantaneous gain, impulse response, band table. */
#define WALL_REQUIRE_FS_HZ 48000 /* compile error if wall.h has no 48 kHz coefficients */
#include "wall.h"

#include <stdio.h>

static unsigned char memory[4096 + ADMITGEN_RT_ALIGN];

int main(void) {
  admitgen_rt_f32 wall_filter;
  void *mem = (void *)(((uintptr_t)memory + ADMITGEN_RT_ALIGN - 1u) & ~(uintptr_t)(ADMITGEN_RT_ALIGN - 1));
  float u[8] = {1.0f, 0, 0, 0, 0, 0, 0, 0}, y[8];
  int i;
  const admitgen_rt_result r = admitgen_rt_init_f32(&wall_filter, wall_model(48000), 48000, 1, mem, 4096);
  if (r != ADMITGEN_RT_SUCCESS) {
    printf("init failed: %s\n", admitgen_rt_result_description(r));
    return 1;
  }
  admitgen_rt_process_f32(&wall_filter, u, y, 8, 1);
  printf("wall.h: model %s, h0 = %.6f, first impulse-response samples:", WALL_ORDER, (double)wall_48000.h0);
  for (i = 0; i < 8; ++i) printf(" %.5f", (double)y[i]);
  printf("\noctave band absorption (normal / random incidence):\n");
  for (i = 0; i < WALL_N_OCTAVE; ++i)
    printf("  %7.0f Hz  %.3f  %.3f\n", (double)wall_octave[i][0], (double)wall_octave[i][1], (double)wall_octave[i][2]);
  /* the first output sample of an impulse is the instantaneous gain */
  return y[0] == wall_48000.h0 ? 0 : 1;
}
