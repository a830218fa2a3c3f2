/* SPDX-License-Identifier: MIT */
/*
 * rt_count.c - a fixed workload for counting instructions under QEMU (cross_figures.cmake): RT_FRAMES
 * frames of RT_NODES nodes of the emitted 48 kHz model in format RT_FORMAT (1 f32, 2 q31, 3 q15), the golden
 * input (the first 32 frames, repeated) as signal; one node is processed 32 frames per call (audio), more nodes one frame per call (a
 * solver's boundary). Two builds differing only in RT_FRAMES give, by difference, the instructions per
 * node-sample without start-up and I/O.
 */
#include "admitgen_rt.h"
#include "rt_golden.h"

#if RT_FORMAT == 1
#include "wall_f32.h"
typedef float sample_t;
#define INIT(i, mem, bytes) admitgen_rt_init_f32(i, &wall_f32_48000, 48000, RT_NODES, mem, bytes)
#define PROCESS admitgen_rt_process_f32
#define INPUT(k) ((float)rt_golden_q31_in[k] * (1.0f / 2147483648.0f))
static admitgen_rt_f32 inst;
#elif RT_FORMAT == 2
#include "wall_q31.h"
typedef int32_t sample_t;
#define INIT(i, mem, bytes) admitgen_rt_init_q31(i, &wall_q31_48000, 48000, RT_NODES, mem, bytes)
#define PROCESS admitgen_rt_process_q31
#define INPUT(k) rt_golden_q31_in[k]
static admitgen_rt_q31 inst;
#else
#include "wall_q15.h"
typedef int16_t sample_t;
#define INIT(i, mem, bytes) admitgen_rt_init_q15(i, &wall_q15_48000, 48000, RT_NODES, mem, bytes)
#define PROCESS admitgen_rt_process_q15
#define INPUT(k) rt_golden_q15_in[k]
static admitgen_rt_q15 inst;
#endif

#define PER_CALL (RT_NODES == 1 ? 32 : 1)
static sample_t in[RT_NODES * 32], out[RT_NODES * 32];
static unsigned char memory[(RT_NODES * 64 + 1024) * 4 + 64];

int main(void) {
  void *mem = (void *)(((uintptr_t)memory + 63u) & ~(uintptr_t)63u);
  int32_t f, i;
  if (INIT(&inst, mem, sizeof memory - 64) != ADMITGEN_RT_SUCCESS) return 1;
  for (i = 0; i < RT_NODES * 32; ++i) in[i] = INPUT(i % RT_GOLDEN_q31_COUNT); /* outside the counted difference */
  for (f = 0; f < RT_FRAMES; f += PER_CALL) PROCESS(&inst, in + (f % 32) * RT_NODES, out, PER_CALL, RT_NODES);
  return out[0] == (sample_t)12345 ? 2 : 0; /* keeps the output live */
}
