/* Shared helpers of the C API tests (tests/api): reading a deck file, counting failed checks. */
#ifndef API_TEST_UTIL_H
#define API_TEST_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int n_failed = 0;

#define CHECK(cond, what)                                                                  \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      fprintf(stderr, "FAIL %s:%d: %s\n", __FILE__, __LINE__, what);                       \
      n_failed++;                                                                          \
    }                                                                                      \
  } while (0)

/* The whole text of a file, NUL-terminated (malloc'ed), or NULL. */
static char *read_text(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *text = malloc((size_t)n + 1);
  if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    text = NULL;
  }
  if (text) text[n] = '\0';
  fclose(f);
  return text;
}

/* deck text followed by extra groups (malloc'ed). */
static char *concat(const char *a, const char *b) {
  size_t na = strlen(a), nb = strlen(b);
  char *s = malloc(na + nb + 2);
  memcpy(s, a, na);
  s[na] = '\n';
  memcpy(s + na + 1, b, nb + 1);
  return s;
}

#endif
