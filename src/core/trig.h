/* trig.h (internal) — table interpolation shared by the library, its tests and the
 * micro-benchmark, which compare every table size in one run. */
#ifndef POGON_SRC_TRIG_H
#define POGON_SRC_TRIG_H
#include "pogon/fixed.h"

/* sin(a) in Q2.30 from a full-turn table of 2^bits entries, interpolated linearly with
 * all the fraction bits the angle has below the table index.
 *
 * The exact interpolant s0 + (s1 - s0) * frac / 2^k is rounded ONCE (k = 32 - bits).
 * Rounding only the increment, s0 + round((s1 - s0) * frac / 2^k), is not symmetric
 * under reflection: at a tie, interpolating from the other end (as sin(-a) does) rounds
 * the other way, and sin(-a) == -sin(a) failed by 1 for a few angles. With one rounding
 * of the exact value the table's symmetries carry over to every angle, bit for bit:
 * sin(-a) == -sin(a), sin(a + half) == -sin(a), sin(half - a) == sin(a), cos(-a) == cos(a).
 * Magnitudes: |s0| * 2^k <= 2^54 and |s1 - s0| * frac < 2^25 * 2^24, so int64 suffices. */
static inline int32_t pg__interp_sin_q30(int64_t s0, int64_t s1, int k, int64_t frac)
{
    return (int32_t)pg__round_shift64(s0 * ((int64_t)1 << k) + (s1 - s0) * frac, k);
}

static inline int32_t pg__table_sin_q30(const int32_t *table, int bits, pg_angle a)
{
    int k = 32 - bits;
    uint32_t index = a >> k;
    uint32_t mask = ((uint32_t)1 << bits) - 1u;
    int64_t frac = (int64_t)(a & ((UINT32_C(1) << k) - 1u));
    return pg__interp_sin_q30(table[index], table[(index + 1u) & mask], k, frac);
}

/* Entry `index` (mod 2^bits) of the full-turn table, read from its first quarter
 * (2^(bits-2) + 1 entries): the generator mirrors that quarter to make the full table
 * (tools/tablegen.c), so full[q + j] = quarter[q - j], full[2q + j] = -quarter[j] and
 * full[3q + j] = -quarter[q - j], exactly. A quarter of the flash for a few operations
 * per read; test_trig compares every entry at every size with the full table. */
static inline int32_t pg__quarter_entry(const int32_t *quarter, int bits, uint32_t index)
{
    uint32_t q = (uint32_t)1 << (bits - 2);
    uint32_t j = index & (q - 1u), quadrant = (index >> (bits - 2)) & 3u;
    int32_t v = quarter[(quadrant & 1u) ? q - j : j];
    return (quadrant & 2u) ? -v : v;
}

/* pg__table_sin_q30 of the full table that `quarter` is the first quarter of: the same
 * entries and the same interpolation, so the same value for every angle. */
static inline int32_t pg__quarter_sin_q30(const int32_t *quarter, int bits, pg_angle a)
{
    int k = 32 - bits;
    uint32_t index = a >> k;
    int64_t frac = (int64_t)(a & ((UINT32_C(1) << k) - 1u));
    return pg__interp_sin_q30(pg__quarter_entry(quarter, bits, index), pg__quarter_entry(quarter, bits, index + 1u), k, frac);
}
#endif
