/* SPDX-License-Identifier: MIT */
/*
 * rt_check.h - the check macro of the C runtime tests: counts failures and prints where and why.
 */
#ifndef RT_CHECK_H
#define RT_CHECK_H

#include <stdio.h>

static int rt_failures = 0;

#define RT_CHECK(cond, ...)                                          \
  do {                                                               \
    if (!(cond)) {                                                   \
      ++rt_failures;                                                 \
      printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);       \
      printf(__VA_ARGS__);                                           \
      printf("\n");                                                  \
    }                                                                \
  } while (0)

#endif
