/* SPDX-License-Identifier: MIT */
/* The tracer of tools/data-walk: with -finstrument-functions every instrumented function calls these on entry
 * and exit; the main thread's calls are written to $WALK_TRACE as "E <address>" and "X <address>". */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

static FILE* trace;
static pthread_t main_thread;

__attribute__((no_instrument_function, constructor)) static void open_trace(void) {
  const char* path = getenv("WALK_TRACE");
  if (path) trace = fopen(path, "w");
  main_thread = pthread_self();
}

__attribute__((no_instrument_function)) void __cyg_profile_func_enter(void* fn, void* site) {
  (void)site;
  if (trace && pthread_equal(pthread_self(), main_thread)) fprintf(trace, "E %p\n", fn);
}

__attribute__((no_instrument_function)) void __cyg_profile_func_exit(void* fn, void* site) {
  (void)site;
  if (trace && pthread_equal(pthread_self(), main_thread)) fprintf(trace, "X %p\n", fn);
}
