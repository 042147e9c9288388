// core/assert.h: JELLO_ASSERT(condition), the check of an invariant: a fact the code relies on
// that no input can break (an input that could is refused with a message instead).
//
// It is compiled in debug builds and in every sanitizer build (CMake defines JELLO_ASSERTS
// there), and out of release builds, where the hot loops run. A failure names the file, the line
// and the condition on stderr, then aborts, so that a test or a fuzzer reports it.
#pragma once

#include <cstdio>
#include <cstdlib>

#if !defined(NDEBUG) || defined(JELLO_ASSERTS)
#define JELLO_ASSERT(condition)                                                              \
  do {                                                                                       \
    if (!(condition)) {                                                                      \
      std::fprintf(stderr, "%s:%d: invariant broken: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                          \
    }                                                                                        \
  } while (0)
#else
#define JELLO_ASSERT(condition) static_cast<void>(sizeof(condition))
#endif
