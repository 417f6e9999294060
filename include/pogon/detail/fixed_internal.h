/* pogon/detail/fixed_internal.h — internals of pogon/fixed.h: not part of the API.
 *
 * The platform checks and the rounding primitives that fixed.h's static inline functions
 * call. They are installed with the public headers because those inline functions are
 * compiled in the user's code, but their names (pg__*, PG__*) may change in any version:
 * do not call them. Include pogon/fixed.h, never this file; the API reference leaves it
 * out. src/ uses these primitives too, so the rounding rule is written once, here.
 */
#ifndef POGON_DETAIL_FIXED_INTERNAL_H
#define POGON_DETAIL_FIXED_INTERNAL_H

#ifndef POGON_FIXED_H
#error "include pogon/fixed.h, not pogon/detail/fixed_internal.h"
#endif

/* ---- compile-time checks on the platform ---------------------------------- */
#define PG__STATIC_ASSERT(cond, name) typedef char pg__static_assert_##name[(cond) ? 1 : -1]
PG__STATIC_ASSERT((-1 >> 1) == -1, arithmetic_shift_int);
PG__STATIC_ASSERT((((int64_t)-1) >> 1) == -1, arithmetic_shift_int64);
PG__STATIC_ASSERT(((int64_t)-7) / 2 == -3, division_truncates_toward_zero);
PG__STATIC_ASSERT(sizeof(pg_fix) == 4 && sizeof(pg_angle) == 4, widths);

/* ---- rounding primitives (the rounding rule, written once) ---------------- */

/* x / 2^n rounded to nearest, ties away from zero. 1 <= n <= 62.
 * Requires |x| + 2^(n-1) <= INT64_MAX, true for every caller in pogon. */
static inline int64_t pg__round_shift64(int64_t x, int n)
{
    /* x >> 63 is -1 for a negative x and 0 otherwise (arithmetic shift, pinned above):
     * the same as subtracting (x < 0) in fewer instructions (in wasm a comparison yields
     * an i32 that must be widened) */
    int64_t half = (int64_t)1 << (n - 1);
    /* cppcheck-suppress shiftTooManyBitsSigned ; implementation-defined, pinned to arithmetic by fixed.h's check */
    return (x + half + (x >> 63)) >> n;
}

/* Clamp an int64 to the legal pg_fix range. */
static inline pg_fix pg__sat64(int64_t x)
{
    return x > (int64_t)PG_FIX_MAX ? PG_FIX_MAX : x < (int64_t)PG_FIX_MIN ? PG_FIX_MIN : (pg_fix)x;
}

/* Multiply a Q16.16 component by a Q2.30 factor, rounded. */
static inline pg_fix pg__mul_q30(pg_fix a, int32_t q30) { return (pg_fix)pg__round_shift64((int64_t)a * q30, 30); }

#endif /* POGON_DETAIL_FIXED_INTERNAL_H */
