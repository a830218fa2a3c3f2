// SPDX-License-Identifier: MIT
// The C99 runtime and a generated header of every format compiled as C++ (unity build of the runtime
// sources) with the strict warning set: engines written in C++ include them directly. Built as C++17 (model
// structs filled positionally) and as C++20 (by designated initialisers, so the compiler checks the order).
#include "../../runtime/src/admitgen_rt_avx2.c"
#include "../../runtime/src/admitgen_rt_common.c"
#include "../../runtime/src/admitgen_rt_fixed.c"
#include "../../runtime/src/admitgen_rt_init_f32.c"
#include "../../runtime/src/admitgen_rt_init_q15.c"
#include "../../runtime/src/admitgen_rt_init_q31.c"
#include "../../runtime/src/admitgen_rt_neon.c"
#include "../../runtime/src/admitgen_rt_process_f32.c"
#include "../../runtime/src/admitgen_rt_process_q15.c"
#include "../../runtime/src/admitgen_rt_process_q31.c"
#include "wall_f32.h"
#include "wall_q15.h"
#include "wall_q31.h"

#include <cstdio>
#include <vector>

int main() {
  alignas(64) static unsigned char mem[1 << 16];
  admitgen_rt_f32 f;
  admitgen_rt_q31 q;
  admitgen_rt_q15 h;
  int failures = 0;
  failures += admitgen_rt_init_f32(&f, wall_f32_model(48000), 48000, 1, mem, sizeof mem) != ADMITGEN_RT_SUCCESS;
  float one = 1.0f, y = 0.0f;
  admitgen_rt_process_f32(&f, &one, &y, 1, 1);
  failures += y != wall_f32_48000.h0;  // the first impulse-response sample is the instantaneous gain
  failures += admitgen_rt_init_q31(&q, wall_q31_model(48000), 48000, 1, mem, sizeof mem) != ADMITGEN_RT_SUCCESS;
  failures += admitgen_rt_init_q15(&h, wall_q15_model(48000), 48000, 1, mem, sizeof mem) != ADMITGEN_RT_SUCCESS;
  failures += wall_q31_model(44100) != nullptr;
  std::printf("runtime as C++: %s\n", failures == 0 ? "PASS" : "FAIL");
  return failures == 0 ? 0 : 1;
}
