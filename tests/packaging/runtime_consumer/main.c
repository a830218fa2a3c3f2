/* SPDX-License-Identifier: MIT */
/* Links the installed runtime and calls into it: exits 0 when the library answers for two result codes
 * with two different non-empty descriptions. */
#include <admitgen_rt.h>

#include <stdio.h>
#include <string.h>

#ifndef ADMITGEN_RT_ABI_VERSION
#error "admitgen_rt.h does not define ADMITGEN_RT_ABI_VERSION"
#endif

int main(void) {
  const char *ok = admitgen_rt_result_description(ADMITGEN_RT_SUCCESS);
  const char *abi = admitgen_rt_result_description(ADMITGEN_RT_ABI_MISMATCH);
  if (ok == NULL || abi == NULL || ok[0] == '\0' || abi[0] == '\0' || strcmp(ok, abi) == 0) {
    fprintf(stderr, "FAIL: result descriptions '%s' / '%s'\n", ok ? ok : "(null)", abi ? abi : "(null)");
    return 1;
  }
  printf("admitgen runtime ABI %d: '%s', '%s'\n", ADMITGEN_RT_ABI_VERSION, ok, abi);
  return 0;
}
