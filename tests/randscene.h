/* randscene: random scene files for the oracle (tests/oracle.c). A seed
 * gives one scene as text, which the caller parses with scene_parse, so
 * every random scene is also a parser test. The same seed gives the same
 * text on every host. */
#ifndef FXRT_TESTS_RANDSCENE_H
#define FXRT_TESTS_RANDSCENE_H

#include <stddef.h>
#include <stdint.h>

/* Largest text randscene_text writes, NUL included. */
#define RANDSCENE_MAX_TEXT 8192

/* Write the scene of this seed into buf (len >= RANDSCENE_MAX_TEXT).
 * Returns the text's length. */
size_t randscene_text(uint64_t seed, char *buf, size_t len);

#endif
