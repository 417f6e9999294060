/* fixed_internal.h (internal) — fixed.c's square root internals, exposed for the unit
 * test that checks them. */
#ifndef POGON_SRC_FIXED_INTERNAL_H
#define POGON_SRC_FIXED_INTERNAL_H
#include <stdint.h>

/* The digit-by-digit implementation behind pg_isqrt64 when PG_FAST_DIV64 is 0, built
 * whatever the setting so that the unit test checks it against the other one. */
uint32_t pg__isqrt64_digits(uint64_t v);
/* The seed table of the Newton implementation (entry i is round(sqrt(64 + i) 2^27)), or
 * NULL and *count = 0 when PG_FAST_DIV64 is 0. Its values decide only how fast
 * pg_isqrt64 is, never what it returns; the unit test checks them. */
const uint32_t *pg__isqrt64_seed_nodes(uint32_t *count);

#endif
