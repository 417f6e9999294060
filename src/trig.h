/* trig.h (internal) — table interpolation shared by the library, its tests and the
 * micro-benchmark, which compare every table size in one run. */
#ifndef POGON_SRC_TRIG_H
#define POGON_SRC_TRIG_H
#include "pogon/fixed.h"

/* sin(a) in Q2.30 from a full-turn table of 2^bits entries, interpolated linearly with
 * all the fraction bits the angle has below the table index. */
static inline int32_t pg__table_sin_q30(const int32_t *table, int bits, pg_angle a)
{
    uint32_t index = a >> (32 - bits);
    uint32_t mask = ((uint32_t)1 << bits) - 1u;
    int64_t frac = (int64_t)(a & ((UINT32_C(1) << (32 - bits)) - 1u));
    int32_t s0 = table[index], s1 = table[(index + 1u) & mask];
    return s0 + (int32_t)pg__round_shift64((int64_t)(s1 - s0) * frac, 32 - bits);
}
#endif
