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

/* floor(n / d) for d > 0, exactly as n / d, with 32-bit divisions only (Hacker's
 * Delight's divlu, 16-bit digits, after one 32-bit division of the high word): on a
 * 32-bit core that has a hardware divider (Cortex-M3/M4) these are instructions, where
 * n / d would call libgcc's 64-bit division. The products that test the digits are
 * formed 32 x 32 -> 64, so none can wrap. */
static inline uint64_t pg__udiv64_32(uint64_t n, uint32_t d)
{
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, qh = hi / d, u1 = hi % d; /* u1 < d */
    int s = 32 - pg__bit_length64(d); /* normalise: the divisor's top bit set */
    uint32_t v = d << s, vn1 = v >> 16, vn0 = v & 0xFFFFu;
    uint32_t un32 = s == 0 ? u1 : (u1 << s) | (lo >> (32 - s)), un10 = lo << s;
    uint32_t un1 = un10 >> 16, un0 = un10 & 0xFFFFu, q1, q0, rhat, un21;
    q1 = un32 / vn1;
    rhat = un32 - q1 * vn1;
    while (q1 > 0xFFFFu || (uint64_t)q1 * vn0 > ((uint64_t)rhat << 16) + un1) {
        --q1;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    un21 = (un32 << 16) + un1 - q1 * v; /* the remainder after the first digit, < v */
    q0 = un21 / vn1;
    rhat = un21 - q0 * vn1;
    while (q0 > 0xFFFFu || (uint64_t)q0 * vn0 > ((uint64_t)rhat << 16) + un0) {
        --q0;
        rhat += vn1;
        if (rhat > 0xFFFFu) break;
    }
    return ((uint64_t)qh << 32) | ((uint64_t)q1 << 16 | q0);
}

/* Nearest integer square root of v (no ties exist for integers). */
static inline uint64_t pg__sqrt_nearest(uint64_t v)
{
    uint64_t r = pg_isqrt64(v);
    if (v - r * r > r) ++r;
    return r;
}

#endif
