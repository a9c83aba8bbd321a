#pragma once
// A property a fuzz target asserts: on violation it prints what and aborts, which libFuzzer
// reports as a crash with the input saved (and the replay tests as a failure).

#include <cstdio>
#include <cstdlib>

#define CYBER_FUZZ_CHECK(condition)                                                           \
  do {                                                                                        \
    if (!(condition)) {                                                                       \
      std::fprintf(stderr, "%s:%d: property violated: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                           \
    }                                                                                         \
  } while (false)
