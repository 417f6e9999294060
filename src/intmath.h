/* intmath.h (internal) — integer helpers the core shares that are not part of the API:
 * bit lengths for normalising before a division or a square root (fixed_internal.h has
 * the square root's internals). */
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

/* Nearest integer square root of v (no ties exist for integers). */
static inline uint64_t pg__sqrt_nearest(uint64_t v)
{
    uint64_t r = pg_isqrt64(v);
    if (v - r * r > r) ++r;
    return r;
}

#endif
