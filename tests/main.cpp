// SPDX-License-Identifier: MIT
// doctest entry point for the admitgen test suite.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
