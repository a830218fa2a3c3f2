/* SPDX-License-Identifier: MIT */
/*
 * engine_example.c - an audio engine's view of a wall filter. A 1 s interleaved stereo buffer of a
 * 1 kHz tone (left) and white noise (right) at 48 kHz is pushed through the wall admittance in blocks of
 * 256 frames, as an audio callback would, in float and in Q31; the example reports the output level per
 * channel, the float/Q31 agreement, and that the 44.1 kHz model is refused at 48 kHz.
 */
#include "wall_f32.h"
#include "wall_q31.h"

#include <math.h>
#include <stdio.h>

#define FS 48000
#define FRAMES FS
#define CHANNELS 2
#define BLOCK 256

static float buffer[FRAMES * CHANNELS], out_f32[FRAMES * CHANNELS];
static int32_t buffer_q31[FRAMES * CHANNELS], out_q31[FRAMES * CHANNELS];
static unsigned char heap_f32[8192], heap_q31[8192]; /* "engine-owned" memory for the filter state */

static void *align(unsigned char *p) {
  return (void *)(((uintptr_t)p + ADMITGEN_RT_ALIGN - 1u) & ~(uintptr_t)(ADMITGEN_RT_ALIGN - 1));
}

int main(void) {
  admitgen_rt_f32 wall;
  admitgen_rt_q31 wall_fixed;
  unsigned seed = 1u;
  double rms_in[CHANNELS] = {0}, rms_out[CHANNELS] = {0}, err = 0.0, ref = 0.0;
  int f, c;
  const double scale = ldexp(1.0, -WALL_Q31_48000_OUT_SHIFT);
  for (f = 0; f < FRAMES; ++f) {
    seed = seed * 1103515245u + 12345u;
    buffer[CHANNELS * f] = 0.25f * (float)sin(2.0 * 3.14159265358979 * 1000.0 * f / FS);
    buffer[CHANNELS * f + 1] = 0.25f * ((float)(seed >> 8) / 16777216.0f - 0.5f);
    for (c = 0; c < CHANNELS; ++c) buffer_q31[CHANNELS * f + c] = (int32_t)(buffer[CHANNELS * f + c] * 2147483648.0);
  }
  /* A 44.1 kHz model at a 48 kHz engine rate is refused: coefficients are only valid at their own rate. */
  if (admitgen_rt_init_f32(&wall, wall_f32_model(44100), FS, CHANNELS, align(heap_f32), 4096) != ADMITGEN_RT_RATE_MISMATCH)
    return 1;
  if (admitgen_rt_state_bytes_f32(wall_f32_model(FS), CHANNELS) > 4096 ||
      admitgen_rt_init_f32(&wall, wall_f32_model(FS), FS, CHANNELS, align(heap_f32), 4096) != ADMITGEN_RT_SUCCESS ||
      admitgen_rt_init_q31(&wall_fixed, wall_q31_model(FS), FS, CHANNELS, align(heap_q31), 4096) != ADMITGEN_RT_SUCCESS)
    return 1;
  /* the "audio callback": one block at a time, both channels at once (stride = channels) */
  for (f = 0; f < FRAMES; f += BLOCK) {
    admitgen_rt_process_f32(&wall, buffer + CHANNELS * f, out_f32 + CHANNELS * f, BLOCK, CHANNELS);
    admitgen_rt_process_q31(&wall_fixed, buffer_q31 + CHANNELS * f, out_q31 + CHANNELS * f, BLOCK, CHANNELS);
  }
  for (f = FS / 10; f < FRAMES; ++f) /* skip the onset */
    for (c = 0; c < CHANNELS; ++c) {
      const double y = out_f32[CHANNELS * f + c], yq = ldexp((double)out_q31[CHANNELS * f + c], -31) / scale;
      rms_in[c] += (double)buffer[CHANNELS * f + c] * buffer[CHANNELS * f + c];
      rms_out[c] += y * y;
      ref += y * y;
      err += (yq - y) * (yq - y);
    }
  printf("wall filter %s at %d Hz, blocks of %d frames, %d channels\n", WALL_F32_ORDER, FS, BLOCK, CHANNELS);
  printf("  1 kHz tone: |G| = %.4f (output rms / input rms)\n", sqrt(rms_out[0] / rms_in[0]));
  printf("  noise:      rms gain %.4f\n", sqrt(rms_out[1] / rms_in[1]));
  printf("  q31 vs f32: %.1f dB SNR\n", 10.0 * log10(ref / err));
  return 10.0 * log10(ref / err) > 90.0 ? 0 : 1; /* the float path limits this comparison (~2^-24) */
}
