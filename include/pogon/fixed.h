/** @file
 * pogon/fixed.h — Q16.16 fixed-point scalars, 2D vectors and rotations.
 *
 * Everything here is integer arithmetic with fully defined behaviour, so a
 * computation gives the same bits on every compiler, optimisation level and CPU.
 *
 * NUMBER FORMATS
 *   pg_fix    Q16.16 in an int32_t: 16 integer bits (with sign), 16 fraction bits.
 *             Legal range is SYMMETRIC: [-PG_FIX_MAX, PG_FIX_MAX], about ±32767.99998,
 *             resolution 2^-16 ≈ 1.5e-5. INT32_MIN is never produced by any function
 *             here; it is not a pg_fix value (negating it would overflow).
 *   pg_angle  a binary angle in a uint32_t: a full turn is 2^32, so angles wrap for
 *             free (unsigned overflow is defined in C) and never drift.
 *   pg_rot    a rotation as cosine and sine in Q2.30 (int32_t, 1.0 = 2^30), so applying
 *             it adds no rounding of its own beyond the final one. pg_rot_from_angle
 *             takes (c, s) from the sine table, which lies on a chord of the unit circle
 *             (up to (2 pi / 2^bits)^2 / 8 short), and scales it back to unit length
 *             with one Newton step: | |R| - 1 | < 1.25 * 2^-30 for every table size, so
 *             rotated shapes keep their size and R^T (R v) returns v within rounding
 *             (tests/unit/test_trig.c).
 *
 * THE ROUNDING RULE (of every function here, and of pogon but for one place)
 *   Every operation that drops bits rounds to nearest, ties away from zero.
 *   The rule is symmetric in sign: f(-x) == -f(x). A bias that always pushes one way
 *   makes resting bodies creep, so pogon never truncates toward -infinity on values
 *   that can be negative. The rule is written once, in pg__round_shift64()
 *   (pogon/detail/fixed_internal.h).
 *   The one other rule: the contact solver's rows (docs/solver-design.md, ROUNDING) round to
 *   nearest with ties toward +infinity, (x + 2^(n-1)) >> n, which differs from this
 *   rule only at an exact tie of a negative value, by one unit, and costs half the
 *   operations in the step's hottest loop. Where ties are common, the angular speed
 *   at a lever arm that is a power of two, the solver keeps this rule; elsewhere a tie
 *   needs the n bits shifted out to be exactly one half, and a symmetric 20-box column
 *   keeps every box at x = 0 exactly for 60 s (tests/stability/test_stacking.c).
 *
 * OVERFLOW
 *   Scalar operations SATURATE: a result that does not fit becomes ±PG_FIX_MAX.
 *   The *_checked variants return 0 when the exact (rounded) result fits and a nonzero
 *   PG_FIX_* status when it saturated, so callers that must know can find out.
 *   Vector helpers assume components in the legal range (they never see INT32_MIN).
 *
 * PLATFORM REQUIREMENTS, pinned by compile-time checks below
 *   two's complement int32_t/int64_t (C99 guarantees it for exact-width types) and
 *   arithmetic right shift of negative signed values (implementation-defined in C99;
 *   every compiler pogon supports does it, and the check refuses to build otherwise).
 */
#ifndef POGON_FIXED_H
#define POGON_FIXED_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A Q16.16 fixed-point number: 16 integer bits with sign, 16 fraction bits; the legal
 * range is [-PG_FIX_MAX, PG_FIX_MAX]. */
typedef int32_t pg_fix;
/** A binary angle: a full turn is 2^32, so angles wrap by unsigned overflow. */
typedef uint32_t pg_angle;
/** A 2D vector of Q16.16 components. */
typedef struct pg_vec2 {
    pg_fix x; /**< x component */
    pg_fix y; /**< y component */
} pg_vec2;
/** A rotation as its cosine and sine in Q2.30 (1.0 = 2^30). */
typedef struct pg_rot {
    int32_t c; /**< cosine, Q2.30 */
    int32_t s; /**< sine, Q2.30 */
} pg_rot;
/** A 2x2 matrix by columns. */
typedef struct pg_mat22 {
    pg_vec2 col1; /**< first column */
    pg_vec2 col2; /**< second column */
} pg_mat22;
/** An axis-aligned box, lo <= hi in both components. */
typedef struct pg_aabb {
    pg_vec2 lo; /**< lower corner */
    pg_vec2 hi; /**< upper corner */
} pg_aabb;

#define PG_FIX_SHIFT 16                   /**< fraction bits of a pg_fix */
#define PG_FIX_ONE ((pg_fix)0x10000)      /**< 1.0 */
#define PG_FIX_HALF ((pg_fix)0x8000)      /**< 0.5 */
#define PG_FIX_MAX ((pg_fix)INT32_MAX)    /**< largest pg_fix, about 32767.99998 */
#define PG_FIX_MIN ((pg_fix)(-INT32_MAX)) /**< symmetric: -PG_FIX_MAX */
#define PG_FIX_EPS ((pg_fix)1)            /**< one LSB, 2^-16 */
#define PG_FIX_PI ((pg_fix)205887)        /**< round(pi * 2^16) */
#define PG_FIX_TWO_PI ((pg_fix)411775)    /**< round(2 pi * 2^16) */
#define PG_FIX_HALF_PI ((pg_fix)102944)   /**< round(pi/2 * 2^16) */
#define PG_ROT_ONE ((int32_t)0x40000000)  /**< 1.0 in Q2.30 */
#define PG_ANGLE_QUARTER ((pg_angle)0x40000000u) /**< a quarter turn as a pg_angle */
#define PG_ANGLE_HALF ((pg_angle)0x80000000u)    /**< half a turn as a pg_angle */

/** Integer literal helper: PG_FIX_C(3) is 3.0. For fractions use pg_fix_from_ratio or
 * pg_fix_parse; there is deliberately no float conversion in the library. */
#define PG_FIX_C(i) ((pg_fix)((i) * 65536))

/** Status of the *_checked functions and of parsing. */
typedef enum pg_fix_status {
    PG_FIX_OK = 0,
    PG_FIX_OVERFLOW = 1,   /**< result saturated to +-PG_FIX_MAX */
    PG_FIX_DIV_ZERO = 2,   /**< division by zero; result saturated (0/0 gives 0) */
    PG_FIX_DOMAIN = 3,     /**< e.g. sqrt of a negative number; result is 0 */
    PG_FIX_SYNTAX = 4      /**< malformed decimal text */
} pg_fix_status;

/** A name and an actionable message for a status value. */
const char *pg_fix_status_message(pg_fix_status status);



/* The platform checks and the rounding primitives the inline functions below use. */
#include "pogon/detail/fixed_internal.h"

/* ---- conversion ------------------------------------------------------------ */
/** The integer i as Q16.16, saturating. */
static inline pg_fix pg_fix_from_int(int32_t i) { return pg__sat64((int64_t)i * 65536); }

/** i rounded to the nearest integer (ties away from zero). */
static inline int32_t pg_fix_to_int(pg_fix a) { return (int32_t)pg__round_shift64(a, 16); }

/** num/den as Q16.16, rounded; saturates; den == 0 saturates by the sign of num. */
pg_fix pg_fix_from_ratio(int64_t num, int64_t den);

/** Parse exact decimal text: [+|-]digits[.digits], [+|-].digits or [+|-]digits. (so
 * ".5" and "5." are accepted), nothing else (no spaces, no exponent, no "." alone). Any number of digits; the result is the correctly rounded
 * Q16.16 value (ties away from zero). `len` bytes are read; the text need not be
 * NUL-terminated. Returns PG_FIX_SYNTAX for malformed text or text == NULL (and
 * *out = 0), PG_FIX_OVERFLOW when the value is beyond +-PG_FIX_MAX (and *out saturated).
 * out may be NULL: the text is checked and the status returned, the value is dropped. */
pg_fix_status pg_fix_parse(const char *text, size_t len, pg_fix *out);

/** Shortest decimal text that pg_fix_parse turns back into `a` (at most 5 fraction
 * digits, e.g. "-12.375", "0.1", "3"). Writes at most `size` bytes including the
 * terminating NUL; returns the length it needs without the NUL (snprintf-style).
 * PG_FIX_FORMAT_MAX bytes are always enough. */
size_t pg_fix_format(pg_fix a, char *buf, size_t size);
#define PG_FIX_FORMAT_MAX 16 /**< bytes pg_fix_format() needs at most, with the NUL */

/* ---- scalar arithmetic (all saturating) ------------------------------------ */
/** a + b, saturating. */
static inline pg_fix pg_fix_add(pg_fix a, pg_fix b) { return pg__sat64((int64_t)a + b); }
/** a - b, saturating. */
static inline pg_fix pg_fix_sub(pg_fix a, pg_fix b) { return pg__sat64((int64_t)a - b); }
/** -a (never overflows: the range is symmetric). */
static inline pg_fix pg_fix_neg(pg_fix a) { return pg__sat64(-(int64_t)a); }
/** |a|. */
static inline pg_fix pg_fix_abs(pg_fix a) { return pg__sat64(a < 0 ? -(int64_t)a : (int64_t)a); }
/** The smaller of a and b. */
static inline pg_fix pg_fix_min(pg_fix a, pg_fix b) { return a < b ? a : b; }
/** The larger of a and b. */
static inline pg_fix pg_fix_max(pg_fix a, pg_fix b) { return a > b ? a : b; }
/** a limited to [lo, hi]. */
static inline pg_fix pg_fix_clamp(pg_fix a, pg_fix lo, pg_fix hi) { return a < lo ? lo : a > hi ? hi : a; }

/** a*b with a 64-bit product, rounded once. */
static inline pg_fix pg_fix_mul(pg_fix a, pg_fix b)
{
    return pg__sat64(pg__round_shift64((int64_t)a * b, 16));
}

/** a/b rounded; b == 0 gives +PG_FIX_MAX for a > 0, PG_FIX_MIN for a < 0, 0 for a == 0. */
pg_fix pg_fix_div(pg_fix a, pg_fix b);

/** @{ */
/** The saturating result in *out and its status. out may be NULL: the status alone is
 * returned ("would a + b overflow?"); it is never an error. */
pg_fix_status pg_fix_add_checked(pg_fix a, pg_fix b, pg_fix *out);
pg_fix_status pg_fix_sub_checked(pg_fix a, pg_fix b, pg_fix *out);
pg_fix_status pg_fix_mul_checked(pg_fix a, pg_fix b, pg_fix *out);
pg_fix_status pg_fix_div_checked(pg_fix a, pg_fix b, pg_fix *out);
/** @} */

/** @{ */
/** Correctly rounded square root (nearest; there are no ties). sqrt of a negative
 * value is 0 (pg_fix_sqrt_checked reports PG_FIX_DOMAIN; its out may be NULL, as for
 * the other *_checked functions). */
pg_fix pg_fix_sqrt(pg_fix a);
pg_fix_status pg_fix_sqrt_checked(pg_fix a, pg_fix *out);
/** @} */

/** 1/a, rounded, saturating (pg_fix_div(PG_FIX_ONE, a)). */
pg_fix pg_fix_recip(pg_fix a);

/** Integer square root of a 64-bit value, floor. Used for lengths of int64 sums. How it
 * is computed depends on PG_FAST_DIV64 (config.h); what it returns does not. */
uint32_t pg_isqrt64(uint64_t v);

/* ---- angles and trigonometry ------------------------------------------------ */

/** Radians (Q16.16) to a binary angle, modulo a full turn. Error at most 1/2 unit plus
 * 6.5e-6 unit per LSB of |radians| (the rounded constant 2^32 / 2 pi): 1.9 units
 * (2.8e-9 rad) on [-pi, pi], 2e-5 rad (1.3 LSB) at the ends of the range. On [-PG_FIX_PI, PG_FIX_PI],
 * pg_angle_to_radians(pg_angle_from_radians(r)) == r exactly; the other way round returns
 * within half a radian LSB (5216 units) of the angle. */
pg_angle pg_angle_from_radians(pg_fix radians);
/** A binary angle to radians in [-pi, pi): in Q16.16 that is [-PG_FIX_PI, PG_FIX_PI]
 * (PG_FIX_PI < pi), half a turn giving -PG_FIX_PI. */
pg_fix pg_angle_to_radians(pg_angle a);
/** Wrap radians into [-pi, pi). */
pg_fix pg_fix_wrap_angle(pg_fix radians);

/** @{ */
/** Sine and cosine in Q2.30 from the lookup table with linear interpolation. The table
 * size is PG_TRIG_TABLE_BITS (config.h). */
int32_t pg_angle_sin_q30(pg_angle a);
int32_t pg_angle_cos_q30(pg_angle a);
pg_fix pg_fix_sin(pg_fix radians);
pg_fix pg_fix_cos(pg_fix radians);
/** @} */

/** atan2 by integer CORDIC: the binary angle of the vector (x, y); (0, 0) gives 0.
 * Error below 2^-20 turn for any inputs. */
pg_angle pg_angle_atan2(pg_fix y, pg_fix x);
/** The same in radians, in [-pi, pi). */
pg_fix pg_fix_atan2(pg_fix y, pg_fix x);

/* ---- 2D vectors -------------------------------------------------------------- */
/** The vector (x, y). */
static inline pg_vec2 pg_v2(pg_fix x, pg_fix y) { pg_vec2 v; v.x = x; v.y = y; return v; }
/** The vector (0, 0). */
static inline pg_vec2 pg_v2_zero(void) { return pg_v2(0, 0); }
/** a + b, each component saturating. */
static inline pg_vec2 pg_v2_add(pg_vec2 a, pg_vec2 b) { return pg_v2(pg_fix_add(a.x, b.x), pg_fix_add(a.y, b.y)); }
/** a - b, each component saturating. */
static inline pg_vec2 pg_v2_sub(pg_vec2 a, pg_vec2 b) { return pg_v2(pg_fix_sub(a.x, b.x), pg_fix_sub(a.y, b.y)); }
/** -a. */
static inline pg_vec2 pg_v2_neg(pg_vec2 a) { return pg_v2(pg_fix_neg(a.x), pg_fix_neg(a.y)); }
/** v times the scalar s, each component rounded once. */
static inline pg_vec2 pg_v2_scale(pg_vec2 v, pg_fix s) { return pg_v2(pg_fix_mul(v.x, s), pg_fix_mul(v.y, s)); }
/** Nonzero when a and b are the same vector. */
static inline int pg_v2_equal(pg_vec2 a, pg_vec2 b) { return a.x == b.x && a.y == b.y; }

/** The dot product a . b: the 64-bit sum of products is rounded once. */
static inline pg_fix pg_v2_dot(pg_vec2 a, pg_vec2 b)
{
    return pg__sat64(pg__round_shift64((int64_t)a.x * b.x + (int64_t)a.y * b.y, 16));
}
/** The cross product a x b (a scalar in 2D): the 64-bit sum of products is rounded once. */
static inline pg_fix pg_v2_cross(pg_vec2 a, pg_vec2 b)
{
    return pg__sat64(pg__round_shift64((int64_t)a.x * b.y - (int64_t)a.y * b.x, 16));
}
/** s x v = (-s*v.y, s*v.x): angular velocity times a lever arm. */
static inline pg_vec2 pg_v2_cross_sv(pg_fix s, pg_vec2 v) { return pg_v2(pg_fix_neg(pg_fix_mul(s, v.y)), pg_fix_mul(s, v.x)); }
/** v x s = (s*v.y, -s*v.x) */
static inline pg_vec2 pg_v2_cross_vs(pg_vec2 v, pg_fix s) { return pg_v2(pg_fix_mul(s, v.y), pg_fix_neg(pg_fix_mul(s, v.x))); }
/** @{ */
/** Counter-clockwise perpendicular (-y, x) and clockwise (y, -x). */
static inline pg_vec2 pg_v2_perp(pg_vec2 v) { return pg_v2(pg_fix_neg(v.y), v.x); }
static inline pg_vec2 pg_v2_rperp(pg_vec2 v) { return pg_v2(v.y, pg_fix_neg(v.x)); }
/** @} */

/** Length, correctly rounded, saturating. */
pg_fix pg_v2_length(pg_vec2 v);
/** Unit vector in the direction of v, each component within 1 LSB of exact.
 * The zero vector normalises to the zero vector (check with pg_v2_equal). */
pg_vec2 pg_v2_normalize(pg_vec2 v);

/* ---- rotations ---------------------------------------------------------------- */
/** The rotation by 0. */
static inline pg_rot pg_rot_identity(void) { pg_rot r; r.c = PG_ROT_ONE; r.s = 0; return r; }
/** The rotation by the binary angle a, from the sine table, scaled back to unit length
 * (see the top of this file). */
pg_rot pg_rot_from_angle(pg_angle a);

/** R v, each component the exact sum rounded once; saturates only when |v| itself
 * exceeds PG_FIX_MAX (e.g. (PG_FIX_MAX, PG_FIX_MAX) turned by 45 degrees). */
static inline pg_vec2 pg_rot_apply(pg_rot r, pg_vec2 v)
{
    return pg_v2(pg__sat64(pg__round_shift64((int64_t)r.c * v.x - (int64_t)r.s * v.y, 30)),
                 pg__sat64(pg__round_shift64((int64_t)r.s * v.x + (int64_t)r.c * v.y, 30)));
}
/** R^T v (the inverse rotation), rounded and saturating as pg_rot_apply(). */
static inline pg_vec2 pg_rot_apply_inv(pg_rot r, pg_vec2 v)
{
    return pg_v2(pg__sat64(pg__round_shift64((int64_t)r.c * v.x + (int64_t)r.s * v.y, 30)),
                 pg__sat64(pg__round_shift64((int64_t)r.c * v.y - (int64_t)r.s * v.x, 30)));
}

/* ---- 2x2 matrices ----------------------------------------------------------------- */
/** The matrix with columns col1 and col2. */
static inline pg_mat22 pg_mat22_make(pg_vec2 col1, pg_vec2 col2) { pg_mat22 m; m.col1 = col1; m.col2 = col2; return m; }
/** m v, each component the 64-bit sum rounded once, saturating. */
static inline pg_vec2 pg_mat22_mul(pg_mat22 m, pg_vec2 v)
{
    return pg_v2(pg__sat64(pg__round_shift64((int64_t)m.col1.x * v.x + (int64_t)m.col2.x * v.y, 16)),
                 pg__sat64(pg__round_shift64((int64_t)m.col1.y * v.x + (int64_t)m.col2.y * v.y, 16)));
}
/** Solve m x = b (Cramer's rule, 64-bit); a singular matrix gives the zero vector. */
pg_vec2 pg_mat22_solve(pg_mat22 m, pg_vec2 b);

#ifdef __cplusplus
}
#endif
#endif
