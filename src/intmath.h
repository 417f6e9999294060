/* intmath.h (internal) — integer helpers the core shares that are not part of the API:
 * bit lengths for normalising before a division or a square root, and the two square
 * root implementations exposed for the unit test. */
#ifndef POGON_SRC_INTMATH_H
#define POGON_SRC_INTMATH_H
#include "pogon/fixed.h"

/* Number of significant bits of v (0 for v == 0). The builtin and the portable loop
 * agree exactly. */
static inline int pg__bit_length64(uint64_t v)
{
#if defined(__GNUC__) || defined(__clang__)
    return v == 0 ? 0 : 64 - __builtin_clzll(v);
#else
    int n = 0;
    while (v >= 256u) { n += 8; v >>= 8; }
    while (v != 0) { ++n; v >>= 1; }
    return n;
#endif
}

/* The digit-by-digit implementation behind pg_isqrt64 when PG_FAST_DIV64 is 0, built
 * whatever the setting so that the unit test checks it against the other one. */
uint32_t pg__isqrt64_digits(uint64_t v);
/* The seed table of the Newton implementation (entry i is round(sqrt(64 + i) 2^27)), or
 * NULL and *count = 0 when PG_FAST_DIV64 is 0. Its values decide only how fast
 * pg_isqrt64 is, never what it returns; the unit test checks them. */
const uint32_t *pg__isqrt64_seed_nodes(uint32_t *count);
#endif
