/* wide.h (internal) — 128-bit products and quotients without __int128 (absent on 32-bit
 * targets and not C99), for the int64 formats of masses, inertias and their inverses.
 * Rounding follows fixed.h: nearest, ties away from zero, symmetric in sign. */
#ifndef POGON_SRC_WIDE_H
#define POGON_SRC_WIDE_H
#include "intmath.h"
#include "pogon/config.h" /* PG_FAST_DIV64 */

typedef struct pg_u128 { uint64_t hi, lo; } pg_u128;

/* The signed value of a two's-complement bit pattern, without implementation-defined
 * conversion (for decoding little-endian fields). */
static inline int32_t pg__i32_from_bits(uint32_t u) { return u <= (uint32_t)INT32_MAX ? (int32_t)u : -(int32_t)(~u) - 1; }
static inline int64_t pg__i64_from_bits(uint64_t u) { return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(~u) - 1; }

static inline uint64_t pg__mag64(int64_t v) { return v < 0 ? (uint64_t)(-(v + 1)) + 1u : (uint64_t)v; }

static inline pg_u128 pg__mul_u64(uint64_t a, uint64_t b)
{
    uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    pg_u128 r;
    r.lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

static inline pg_u128 pg__add_u128(pg_u128 a, pg_u128 b)
{
    pg_u128 r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo);
    return r;
}

/* round(a * b / 2^shift), 1 <= shift <= 126, saturated to +-INT64_MAX. */
static inline int64_t pg__mul64_shr(int64_t a, int64_t b, int shift)
{
    int negative = (a < 0) != (b < 0);
    pg_u128 p = pg__mul_u64(pg__mag64(a), pg__mag64(b)), half, q;
    half.hi = shift > 64 ? (uint64_t)1 << (shift - 65) : 0;
    half.lo = shift > 64 ? 0 : (uint64_t)1 << (shift - 1);
    p = pg__add_u128(p, half);
    if (shift >= 64) { q.lo = p.hi >> (shift - 64); q.hi = 0; }
    else { q.lo = (p.lo >> shift) | (p.hi << (64 - shift)); q.hi = p.hi >> shift; }
    if (q.hi != 0 || q.lo > (uint64_t)INT64_MAX) return negative ? -INT64_MAX : INT64_MAX;
    return negative ? -(int64_t)q.lo : (int64_t)q.lo;
}

/* round(num * 2^shift / den) by long division, saturated to +-INT64_MAX (a quotient
 * of 2^63 or more); den == 0 saturates by the sign of num (0 for 0). 0 <= shift <= 64.
 * With a hardware 64-bit divider (PG_FAST_DIV64) it takes as many quotient bits per
 * division as the remainder has room for, 64 less den's bit length (24 for a Q38 mass);
 * for a den within 2^8 of 2^63, or without the divider, one bit a turn by compare and
 * subtract. Both ways give the same bits. */
static inline int64_t pg__div64_shl(int64_t num, int64_t den, int shift)
{
    int negative = (num < 0) != (den < 0), room, k;
    uint64_t un = pg__mag64(num), ud = pg__mag64(den), q, r;
    if (den == 0) return num > 0 ? INT64_MAX : num < 0 ? -INT64_MAX : 0;
    q = un / ud;
    r = un % ud;
    room = 64 - pg__bit_length64(ud); /* r < ud, so r << room fits */
#if !PG_FAST_DIV64
    room = 0;
#endif
    if (room < 8) {
        for (; shift > 0; --shift) {
            if (q >> 62) return negative ? -INT64_MAX : INT64_MAX;
            q <<= 1;
            r <<= 1; /* r < ud <= 2^63 */
            if (r >= ud) { q |= 1u; r -= ud; }
        }
    }
    while (shift > 0) {
        k = shift < room ? shift : room;
        if (q >> (63 - k)) return negative ? -INT64_MAX : INT64_MAX; /* q << k would reach 2^63 */
        r <<= k;
        q = (q << k) | (r / ud);
        r %= ud;
        shift -= k;
    }
    if (r >= ud - r) ++q;
    if (q > (uint64_t)INT64_MAX) return negative ? -INT64_MAX : INT64_MAX;
    return negative ? -(int64_t)q : (int64_t)q;
}
#endif
