/* pg_test.h — small helpers shared by pogon's CMocka tests.
 *
 *   - includes CMocka in the order it needs;
 *   - a deterministic PRNG (splitmix64; every test seeds its own, so a failure
 *     reproduces exactly) and generators of values at every scale;
 *   - __int128 reference types (tests only: the library never uses them);
 *   - PG_EXPECT_EQ / PG_EXPECT_LE: compare as long long / double and print the
 *     operands on failure (cmocka 1.1's assert_int_equal prints negatives as hex).
 */
#ifndef POGON_TEST_PG_TEST_H
#define POGON_TEST_PG_TEST_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/config.h"
#include "pogon/fixed.h"

__extension__ typedef __int128 pgt_i128;
__extension__ typedef unsigned __int128 pgt_u128;

/* Pi to double precision (M_PI is not C99). */
#define PGT_PI 3.14159265358979323846

/* What the sine table's size leaves in a rotation (relative), for bounds that hold at
 * every PG_TRIG_TABLE_BITS (8..12). With h = 2 pi / 2^bits, the table's interpolated
 * (c, s) lies on a chord up to h^2/8 inside the unit circle; pg_rot_from_angle scales it
 * by one Newton step for 1/sqrt(c^2 + s^2), which leaves 3/2 (h^2/8)^2 of it:
 * 1.3e-13 at 12 bits (0.0001 Q2.30 units), 8.5e-9 at 8 bits (9.1 units). The rounding
 * to Q2.30 comes on top. */
static inline double pgt_rot_norm_error(void)
{
    double h = 2.0 * PGT_PI / (double)(1 << PG_TRIG_TABLE_BITS), chord = h * h / 8.0;
    return 1.5 * chord * chord;
}

/* The angle by which a rotation from the table can miss its angle: a point on the chord
 * between two entries points up to h^3 / (36 sqrt 3) away from where the arc would
 * (the factor 1 + h^2 covers the next term): 5.8e-11 rad at 12 bits, 2.4e-7 at 8 (255
 * Q2.30 units in a rotated unit vector's components). */
static inline double pgt_rot_angle_error(void)
{
    double h = 2.0 * PGT_PI / (double)(1 << PG_TRIG_TABLE_BITS);
    return h * h * h / (36.0 * 1.7320508075688772) * (1.0 + h * h);
}

/* Fail with a formatted message that names the inputs. Always give at least one
 * argument after the format. */
#define PG_EXPECT_EQ(got, want, fmt, ...)                                                   \
    do {                                                                                   \
        long long pgt_g_ = (long long)(got), pgt_w_ = (long long)(want);                   \
        if (pgt_g_ != pgt_w_) {                                                            \
            print_error("%s == %lld, want %lld (%s); " fmt "\n", #got, pgt_g_, pgt_w_,     \
                        #want, __VA_ARGS__);                                               \
            fail();                                                                        \
        }                                                                                  \
    } while (0)

#define PG_EXPECT_LE(got, bound, fmt, ...)                                                  \
    do {                                                                                   \
        double pgt_g_ = (double)(got), pgt_b_ = (double)(bound);                           \
        if (!(pgt_g_ <= pgt_b_)) {                                                         \
            print_error("%s == %.9g, exceeds the bound %.9g (%s); " fmt "\n", #got, pgt_g_, \
                        pgt_b_, #bound, __VA_ARGS__);                                      \
            fail();                                                                        \
        }                                                                                  \
    } while (0)

#define PG_EXPECT_GE(got, bound, fmt, ...)                                                  \
    do {                                                                                   \
        double pgt_g_ = (double)(got), pgt_b_ = (double)(bound);                           \
        if (!(pgt_g_ >= pgt_b_)) {                                                         \
            print_error("%s == %.9g, below the bound %.9g (%s); " fmt "\n", #got, pgt_g_,  \
                        pgt_b_, #bound, __VA_ARGS__);                                      \
            fail();                                                                        \
        }                                                                                  \
    } while (0)

/* ---- deterministic PRNG ------------------------------------------------------------ */
typedef struct pgt_rng { uint64_t s; } pgt_rng;

static inline pgt_rng pgt_rng_seed(uint64_t seed) { pgt_rng r; r.s = seed; return r; }

static inline uint64_t pgt_next(pgt_rng *r)
{
    uint64_t z = (r->s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* Uniform in [0, n), n > 0 (the bias of % is irrelevant for tests). */
static inline uint64_t pgt_below(pgt_rng *r, uint64_t n) { return pgt_next(r) % n; }

/* A uniformly random double in [0, 1). */
static inline double pgt_unit(pgt_rng *r) { return (double)(pgt_next(r) >> 11) * (1.0 / 9007199254740992.0); }

/* A legal pg_fix at a random scale: the magnitude has a random number of bits (0..31),
 * so tiny, ordinary and huge values are all common. Never INT32_MIN. */
static inline pg_fix pgt_fix_any(pgt_rng *r)
{
    uint64_t x = pgt_next(r);
    uint32_t mag = (uint32_t)(x >> 33) >> (x & 31u); /* < 2^31 */
    return (x >> 5) & 1u ? -(pg_fix)mag : (pg_fix)mag;
}

/* A legal pg_fix with |v| < 2^bits. */
static inline pg_fix pgt_fix_bits(pgt_rng *r, int bits)
{
    uint64_t x = pgt_next(r);
    uint32_t mag = (uint32_t)((x >> 1) & ((UINT64_C(1) << bits) - 1u));
    if (mag > (uint32_t)INT32_MAX) mag = (uint32_t)INT32_MAX;
    return x & 1u ? -(pg_fix)mag : (pg_fix)mag;
}

/* An int64 at a random scale, occasionally INT64_MIN / INT64_MAX. */
static inline int64_t pgt_i64_any(pgt_rng *r)
{
    uint64_t x = pgt_next(r), sel = pgt_next(r);
    if ((sel & 255u) == 0) return INT64_MIN;
    if ((sel & 255u) == 1) return INT64_MAX;
    x >>= (sel >> 8) % 64u;
    x >>= 1; /* < 2^63 */
    return (sel >> 16) & 1u ? -(int64_t)x : (int64_t)x;
}

/* ---- exact references -------------------------------------------------------------- */

/* num / den rounded to nearest, ties away from zero, den != 0. */
static inline pgt_i128 pgt_div_round(pgt_i128 num, pgt_i128 den)
{
    int negative = (num < 0) != (den < 0);
    pgt_u128 n = (pgt_u128)(num < 0 ? -num : num), d = (pgt_u128)(den < 0 ? -den : den);
    pgt_u128 q = n / d, rem = n % d;
    if (rem >= d - rem) ++q; /* 2 rem >= d */
    return negative ? -(pgt_i128)q : (pgt_i128)q;
}

/* Clamp to the legal pg_fix range, reporting whether it had to. */
static inline pg_fix pgt_sat(pgt_i128 v, int *overflow)
{
    if (v > (pgt_i128)PG_FIX_MAX) { if (overflow) *overflow = 1; return PG_FIX_MAX; }
    if (v < (pgt_i128)PG_FIX_MIN) { if (overflow) *overflow = 1; return PG_FIX_MIN; }
    if (overflow) *overflow = 0;
    return (pg_fix)v;
}

/* A file read whole into memory that the caller frees: exactly its bytes, no NUL after
 * them (the scene reader must take a buffer that is not a C string). Fails the test when
 * the file cannot be read. */
static inline char *pgt_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    char *text;
    long n;
    if (f == NULL) {
        print_error("cannot open %s\n", path);
        fail();
    }
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    n = ftell(f);
    assert_true(n > 0);
    assert_int_equal(fseek(f, 0, SEEK_SET), 0);
    text = malloc((size_t)n);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    *size = (size_t)n;
    return text;
}

#endif
