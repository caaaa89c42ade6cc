/* The C tests' check: report a failed condition with its place and count it, and go on. */
#ifndef HSTMON_C_CHECK_H
#define HSTMON_C_CHECK_H

#include <stdio.h>

/* Checks failed so far in this test program (defined by each test). */
extern int failures;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                              \
    }                                                                          \
  } while (0)

#endif
