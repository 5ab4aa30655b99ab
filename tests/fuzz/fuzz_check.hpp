// The invariant checks of the fuzz targets: each target defines its own
// [[noreturn]] fail(what, line[, detail...]) that prints its context and
// aborts (so libFuzzer records the input); these macros call it.
#pragma once

// FUZZ_CHECK(condition): abort with the condition and the context on stderr.
// FUZZ_CHECK_AT(condition, extra...): also passes `extra` to fail().
#define FUZZ_CHECK(condition)                     \
  do {                                            \
    if (!(condition)) fail(#condition, __LINE__); \
  } while (0)
#define FUZZ_CHECK_AT(condition, ...)                          \
  do {                                                         \
    if (!(condition)) fail(#condition, __LINE__, __VA_ARGS__); \
  } while (0)
