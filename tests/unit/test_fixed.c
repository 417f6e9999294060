/* test_fixed.c — the Q16.16 scalar: rounding rule, saturation, status codes, division,
 * ratios, square roots, decimal parsing and formatting.
 *
 * Every expectation is exact. References are computed here with __int128 (or with exact
 * integer reasoning written out in the test); doubles are not used for exact results.
 */
#include "pg_test.h"
#include "fixed_internal.h" /* the square roots' internals */
#include "intmath.h"

#include <limits.h>

#define MAX PG_FIX_MAX
#define MIN PG_FIX_MIN
#define ONE PG_FIX_ONE

/* ---- the rounding primitive --------------------------------------------------------- */

static void test_round_shift_rule(void **state)
{
    (void)state;
    /* Small values at every shift: x / 2^n, nearest, ties away from zero. */
    for (int n = 1; n <= 20; ++n) {
        for (int64_t x = -5000; x <= 5000; ++x) {
            int64_t want = (int64_t)pgt_div_round(x, (pgt_i128)1 << n);
            PG_EXPECT_EQ(pg__round_shift64(x, n), want, "x=%lld n=%d", (long long)x, n);
            PG_EXPECT_EQ(pg__round_shift64(-x, n), -want, "symmetry x=%lld n=%d", (long long)x, n);
        }
    }
    /* Exact halves in both signs go away from zero. */
    PG_EXPECT_EQ(pg__round_shift64(1, 1), 1, "%s", "0.5");
    PG_EXPECT_EQ(pg__round_shift64(-1, 1), -1, "%s", "-0.5");
    PG_EXPECT_EQ(pg__round_shift64(3, 1), 2, "%s", "1.5");
    PG_EXPECT_EQ(pg__round_shift64(-3, 1), -2, "%s", "-1.5");
    PG_EXPECT_EQ(pg__round_shift64(5, 1), 3, "%s", "2.5 (ties to even would give 2)");
    PG_EXPECT_EQ(pg__round_shift64(-5, 1), -3, "%s", "-2.5");
    PG_EXPECT_EQ(pg__round_shift64(0x8000, 16), 1, "%s", "half an LSB");
    PG_EXPECT_EQ(pg__round_shift64(-0x8000, 16), -1, "%s", "minus half an LSB");
    PG_EXPECT_EQ(pg__round_shift64(0x7FFF, 16), 0, "%s", "just below half");
    PG_EXPECT_EQ(pg__round_shift64(-0x7FFF, 16), 0, "%s", "just above minus half");
    /* Large values near the documented limit |x| + 2^(n-1) <= INT64_MAX. */
    {
        pgt_rng r = pgt_rng_seed(11);
        for (int i = 0; i < 200000; ++i) {
            int n = 1 + (int)pgt_below(&r, 62);
            int64_t lim = INT64_MAX - (((int64_t)1 << (n - 1)) - 1);
            int64_t x = (int64_t)(pgt_next(&r) >> 1) % lim;
            if (pgt_next(&r) & 1u) x = -x;
            PG_EXPECT_EQ(pg__round_shift64(x, n), (int64_t)pgt_div_round(x, (pgt_i128)1 << n),
                         "x=%lld n=%d", (long long)x, n);
        }
    }
}

/* ---- conversions, add, sub, neg, abs -------------------------------------------------- */

static void test_int_conversion_and_sat(void **state)
{
    (void)state;
    PG_EXPECT_EQ(pg_fix_from_int(0), 0, "%d", 0);
    PG_EXPECT_EQ(pg_fix_from_int(1), ONE, "%d", 1);
    PG_EXPECT_EQ(pg_fix_from_int(-1), -ONE, "%d", -1);
    PG_EXPECT_EQ(pg_fix_from_int(32767), 32767 * 65536, "%d", 32767);
    PG_EXPECT_EQ(pg_fix_from_int(-32767), -32767 * 65536, "%d", -32767);
    PG_EXPECT_EQ(pg_fix_from_int(32768), MAX, "%s", "saturates");
    PG_EXPECT_EQ(pg_fix_from_int(-32768), MIN, "%s", "saturates: -2^31 is not a pg_fix");
    PG_EXPECT_EQ(pg_fix_from_int(INT32_MAX), MAX, "%s", "saturates");
    PG_EXPECT_EQ(pg_fix_from_int(INT32_MIN), MIN, "%s", "saturates");

    PG_EXPECT_EQ(pg_fix_to_int(0x8000), 1, "%s", "0.5 -> 1");
    PG_EXPECT_EQ(pg_fix_to_int(-0x8000), -1, "%s", "-0.5 -> -1");
    PG_EXPECT_EQ(pg_fix_to_int(0x7FFF), 0, "%s", "0.49998 -> 0");
    PG_EXPECT_EQ(pg_fix_to_int(-0x7FFF), 0, "%s", "-0.49998 -> 0");
    PG_EXPECT_EQ(pg_fix_to_int(ONE + 0x8000), 2, "%s", "1.5 -> 2");
    PG_EXPECT_EQ(pg_fix_to_int(-ONE - 0x8000), -2, "%s", "-1.5 -> -2");
    PG_EXPECT_EQ(pg_fix_to_int(MAX), 32768, "%s", "32767.99998 -> 32768");
    PG_EXPECT_EQ(pg_fix_to_int(MIN), -32768, "%s", "-32767.99998 -> -32768");

    PG_EXPECT_EQ(PG_FIX_MIN, -PG_FIX_MAX, "%s", "the range is symmetric");
    PG_EXPECT_EQ(pg_fix_neg(MIN), MAX, "%s", "");
    PG_EXPECT_EQ(pg_fix_neg(MAX), MIN, "%s", "");
    PG_EXPECT_EQ(pg_fix_abs(MIN), MAX, "%s", "");
    PG_EXPECT_EQ(pg_fix_abs(-1), 1, "%s", "");
    PG_EXPECT_EQ(pg_fix_neg(INT32_MIN), MAX, "%s", "even the illegal INT32_MIN saturates");
    PG_EXPECT_EQ(pg_fix_abs(INT32_MIN), MAX, "%s", "even the illegal INT32_MIN saturates");
    PG_EXPECT_EQ(pg_fix_clamp(5, -3, 3), 3, "%s", "");
    PG_EXPECT_EQ(pg_fix_clamp(-5, -3, 3), -3, "%s", "");
    PG_EXPECT_EQ(pg_fix_clamp(2, -3, 3), 2, "%s", "");
    PG_EXPECT_EQ(pg_fix_min(-2, 1), -2, "%s", "");
    PG_EXPECT_EQ(pg_fix_max(-2, 1), 1, "%s", "");
}

static void test_add_sub_checked(void **state)
{
    static const struct { pg_fix a, b, sum, diff; int sum_st, diff_st; } cases[] = {
        {0, 0, 0, 0, PG_FIX_OK, PG_FIX_OK},
        {MAX, 0, MAX, MAX, PG_FIX_OK, PG_FIX_OK},
        {MAX, 1, MAX, MAX - 1, PG_FIX_OVERFLOW, PG_FIX_OK},
        {MAX, -1, MAX - 1, MAX, PG_FIX_OK, PG_FIX_OVERFLOW},
        {MIN, -1, MIN, MIN + 1, PG_FIX_OVERFLOW, PG_FIX_OK},
        {MIN, 1, MIN + 1, MIN, PG_FIX_OK, PG_FIX_OVERFLOW},
        {MIN, MAX, 0, MIN, PG_FIX_OK, PG_FIX_OVERFLOW},
        {MAX, MAX, MAX, 0, PG_FIX_OVERFLOW, PG_FIX_OK},
        {MIN, MIN, MIN, 0, PG_FIX_OVERFLOW, PG_FIX_OK},
        {ONE, -ONE, 0, 2 * ONE, PG_FIX_OK, PG_FIX_OK},
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        pg_fix out = 12345;
        PG_EXPECT_EQ(pg_fix_add_checked(cases[i].a, cases[i].b, &out), cases[i].sum_st, "case %zu", i);
        PG_EXPECT_EQ(out, cases[i].sum, "add case %zu", i);
        PG_EXPECT_EQ(pg_fix_add(cases[i].a, cases[i].b), cases[i].sum, "add case %zu", i);
        out = 12345;
        PG_EXPECT_EQ(pg_fix_sub_checked(cases[i].a, cases[i].b, &out), cases[i].diff_st, "case %zu", i);
        PG_EXPECT_EQ(out, cases[i].diff, "sub case %zu", i);
        PG_EXPECT_EQ(pg_fix_sub(cases[i].a, cases[i].b), cases[i].diff, "sub case %zu", i);
    }
    {
        pgt_rng r = pgt_rng_seed(12);
        for (int i = 0; i < 300000; ++i) {
            pg_fix a = pgt_fix_any(&r), b = pgt_fix_any(&r), out;
            int ov;
            pg_fix want = pgt_sat((pgt_i128)a + b, &ov);
            PG_EXPECT_EQ(pg_fix_add_checked(a, b, &out), ov ? PG_FIX_OVERFLOW : PG_FIX_OK, "a=%d b=%d", a, b);
            PG_EXPECT_EQ(out, want, "a=%d b=%d", a, b);
            want = pgt_sat((pgt_i128)a - b, &ov);
            PG_EXPECT_EQ(pg_fix_sub_checked(a, b, &out), ov ? PG_FIX_OVERFLOW : PG_FIX_OK, "a=%d b=%d", a, b);
            PG_EXPECT_EQ(out, want, "a=%d b=%d", a, b);
        }
    }
}

/* ---- multiplication ------------------------------------------------------------------ */

typedef struct { pg_fix a, b, want; int status; } binop_case;

static const binop_case mul_cases[] = {
    {0, 0, 0, PG_FIX_OK},
    {1, 1, 0, PG_FIX_OK},              /* 2^-32 -> 0 */
    {1, -1, 0, PG_FIX_OK},             /* -2^-32 -> 0, not -1 */
    {1, 32768, 1, PG_FIX_OK},          /* exactly half an LSB -> away from zero */
    {-1, 32768, -1, PG_FIX_OK},
    {1, -32768, -1, PG_FIX_OK},
    {-1, -32768, 1, PG_FIX_OK},
    {1, 32767, 0, PG_FIX_OK},          /* just below half */
    {-1, 32767, 0, PG_FIX_OK},
    {3, 32768, 2, PG_FIX_OK},          /* 1.5 -> 2 */
    {-3, 32768, -2, PG_FIX_OK},
    {5, 32768, 3, PG_FIX_OK},          /* 2.5 -> 3 (ties to even would give 2) */
    {-5, 32768, -3, PG_FIX_OK},
    {ONE, ONE, ONE, PG_FIX_OK},
    {-ONE, ONE, -ONE, PG_FIX_OK},
    {-ONE, -ONE, ONE, PG_FIX_OK},
    {PG_FIX_HALF, PG_FIX_HALF, 16384, PG_FIX_OK},
    {-PG_FIX_HALF, PG_FIX_HALF, -16384, PG_FIX_OK},
    {2 * ONE, 3 * ONE, 6 * ONE, PG_FIX_OK},
    {MAX, ONE, MAX, PG_FIX_OK},
    {MIN, ONE, MIN, PG_FIX_OK},
    {MAX, -ONE, MIN, PG_FIX_OK},
    {MIN, -ONE, MAX, PG_FIX_OK},
    {MAX, PG_FIX_HALF, 1073741824, PG_FIX_OK},   /* 1073741823.5 -> away */
    {MIN, PG_FIX_HALF, -1073741824, PG_FIX_OK},
    {MAX, 1, 32768, PG_FIX_OK},                  /* (2^31 - 1) 2^-16 = 32767.99998 LSB */
    {181 * ONE, 181 * ONE, 32761 * ONE, PG_FIX_OK},
    {182 * ONE, 182 * ONE, MAX, PG_FIX_OVERFLOW},
    {-182 * ONE, 182 * ONE, MIN, PG_FIX_OVERFLOW},
    {MAX, ONE + 1, MAX, PG_FIX_OVERFLOW},
    {MAX, MAX, MAX, PG_FIX_OVERFLOW},
    {MIN, MIN, MAX, PG_FIX_OVERFLOW},
    {MAX, MIN, MIN, PG_FIX_OVERFLOW},
    {MIN, MAX, MIN, PG_FIX_OVERFLOW},
    {0, MIN, 0, PG_FIX_OK},
};

static pg_fix ref_mul(pg_fix a, pg_fix b, int *overflow)
{
    return pgt_sat(pgt_div_round((pgt_i128)a * b, 65536), overflow);
}

static void test_mul_edges(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof mul_cases / sizeof mul_cases[0]; ++i) {
        const binop_case *c = &mul_cases[i];
        pg_fix out = 12345;
        int ov;
        PG_EXPECT_EQ(pg_fix_mul(c->a, c->b), c->want, "mul case %zu: %d * %d", i, c->a, c->b);
        PG_EXPECT_EQ(pg_fix_mul(c->b, c->a), c->want, "commuted case %zu", i);
        PG_EXPECT_EQ(pg_fix_mul_checked(c->a, c->b, &out), c->status, "case %zu", i);
        PG_EXPECT_EQ(out, c->want, "checked case %zu", i);
        PG_EXPECT_EQ(ref_mul(c->a, c->b, &ov), c->want, "the reference agrees, case %zu", i);
    }
    /* The overflow boundary: products that round to at most MAX are OK, the next one
     * overflows. For b > 1, a0 = the largest a with a b / 2^16 < MAX + 1/2, that is
     * a b <= (2 MAX + 1) 2^15 - 1. */
    for (int64_t b = ONE + 1; b < ONE + 3000; ++b) {
        int64_t a0 = ((2 * (int64_t)MAX + 1) * 32768 - 1) / b;
        for (int64_t a = a0 - 2; a <= a0 + 2; ++a) {
            pg_fix out, want = a <= a0 ? ref_mul((pg_fix)a, (pg_fix)b, NULL) : MAX;
            int st = a <= a0 ? PG_FIX_OK : PG_FIX_OVERFLOW;
            PG_EXPECT_EQ(pg_fix_mul_checked((pg_fix)a, (pg_fix)b, &out), st, "a=%lld b=%lld", (long long)a, (long long)b);
            PG_EXPECT_EQ(out, want, "a=%lld b=%lld", (long long)a, (long long)b);
            PG_EXPECT_EQ(pg_fix_mul_checked((pg_fix)-a, (pg_fix)b, &out), st, "a=%lld b=%lld", (long long)-a, (long long)b);
            PG_EXPECT_EQ(out, -want, "a=%lld b=%lld", (long long)-a, (long long)b);
        }
        PG_EXPECT_EQ(pg_fix_mul((pg_fix)a0, (pg_fix)b) >= MAX - (pg_fix)(b >> 16), 1, "a0=%lld b=%lld is near MAX",
                     (long long)a0, (long long)b);
    }
}

static void test_mul_random(void **state)
{
    pgt_rng r = pgt_rng_seed(1);
    (void)state;
    for (int i = 0; i < 1000000; ++i) {
        pg_fix a = pgt_fix_any(&r), b = pgt_fix_any(&r), out;
        int ov;
        pg_fix want = ref_mul(a, b, &ov);
        PG_EXPECT_EQ(pg_fix_mul(a, b), want, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(pg_fix_mul_checked(a, b, &out), ov ? PG_FIX_OVERFLOW : PG_FIX_OK, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(out, want, "a=%d b=%d", a, b);
        /* symmetric in sign, commutative */
        PG_EXPECT_EQ(pg_fix_mul(-a, b), -want, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(pg_fix_mul(a, -b), -want, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(pg_fix_mul(b, a), want, "a=%d b=%d", a, b);
    }
    /* Small operands, where the rounding of every product is visible. */
    for (pg_fix a = -300; a <= 300; ++a) {
        for (pg_fix b = -40000; b <= 40000; b += 37) {
            PG_EXPECT_EQ(pg_fix_mul(a, b), ref_mul(a, b, NULL), "a=%d b=%d", a, b);
        }
    }
}

/* ---- division ------------------------------------------------------------------------ */

static const binop_case div_cases[] = {
    {0, 5, 0, PG_FIX_OK},
    {0, MIN, 0, PG_FIX_OK},
    {1, 2 * ONE, 1, PG_FIX_OK},         /* half an LSB -> away from zero */
    {-1, 2 * ONE, -1, PG_FIX_OK},
    {1, -2 * ONE, -1, PG_FIX_OK},
    {-1, -2 * ONE, 1, PG_FIX_OK},
    {1, 3 * ONE, 0, PG_FIX_OK},         /* 1/3 LSB */
    {2, 3 * ONE, 1, PG_FIX_OK},         /* 2/3 LSB */
    {-2, 3 * ONE, -1, PG_FIX_OK},
    {3, 2 * ONE, 2, PG_FIX_OK},         /* 1.5 -> 2 */
    {5, 2 * ONE, 3, PG_FIX_OK},         /* 2.5 -> 3 (ties to even would give 2) */
    {-5, 2 * ONE, -3, PG_FIX_OK},
    {5, -2 * ONE, -3, PG_FIX_OK},
    {ONE, 3 * ONE, 21845, PG_FIX_OK},   /* 21845.33 */
    {2 * ONE, 3 * ONE, 43691, PG_FIX_OK}, /* 43690.67 */
    {-2 * ONE, 3 * ONE, -43691, PG_FIX_OK},
    {MAX, ONE, MAX, PG_FIX_OK},
    {MIN, ONE, MIN, PG_FIX_OK},
    {MAX, -ONE, MIN, PG_FIX_OK},
    {MIN, -ONE, MAX, PG_FIX_OK},
    {MAX, MAX, ONE, PG_FIX_OK},
    {MIN, MAX, -ONE, PG_FIX_OK},
    {MIN, MIN, ONE, PG_FIX_OK},
    {MAX, 2 * ONE, 1073741824, PG_FIX_OK}, /* 1073741823.5 -> away */
    {MIN, 2 * ONE, -1073741824, PG_FIX_OK},
    {1, MAX, 0, PG_FIX_OK},
    {1, 1, ONE, PG_FIX_OK},
    {-1, 1, -ONE, PG_FIX_OK},
    {MAX, ONE + 1, 2147450880, PG_FIX_OK}, /* (2^31-1) * 65536/65537 = 2147450879.99.. */
    {MAX, 1, MAX, PG_FIX_OVERFLOW},
    {MIN, 1, MIN, PG_FIX_OVERFLOW},
    {MAX, -1, MIN, PG_FIX_OVERFLOW},
    {16384 * ONE, PG_FIX_HALF, MAX, PG_FIX_OVERFLOW},
    {-16384 * ONE, PG_FIX_HALF, MIN, PG_FIX_OVERFLOW},
    {MAX, ONE - 1, MAX, PG_FIX_OVERFLOW},
    /* 32767 / (1 - 2^-16) = 2147450879.49999 LSB: just below a tie */
    {32767 * ONE, ONE - 1, 2147450879, PG_FIX_OK},
    {-32767 * ONE, ONE - 1, -2147450879, PG_FIX_OK},
    /* 2147450880 / (1 - 2^-16) = 2^31 LSB exactly: the first quotient past MAX. (No a/b
     * lies strictly between MAX and MAX + 1 LSB: a 2^16 = MAX b + r needs r = b mod 2^16,
     * which is not below b, so rounding alone never crosses the limit.) */
    {2147450880, ONE - 1, MAX, PG_FIX_OVERFLOW},
    {2147450879, ONE - 1, MAX, PG_FIX_OK}, /* MAX - 1/65535 LSB -> MAX */
    /* division by zero: saturated by the sign of the dividend, 0/0 gives 0 */
    {1, 0, MAX, PG_FIX_DIV_ZERO},
    {ONE, 0, MAX, PG_FIX_DIV_ZERO},
    {MAX, 0, MAX, PG_FIX_DIV_ZERO},
    {-1, 0, MIN, PG_FIX_DIV_ZERO},
    {MIN, 0, MIN, PG_FIX_DIV_ZERO},
    {0, 0, 0, PG_FIX_DIV_ZERO},
};

static pg_fix ref_div(pg_fix a, pg_fix b, int *status)
{
    int ov;
    pg_fix v;
    if (b == 0) {
        *status = PG_FIX_DIV_ZERO;
        return a > 0 ? MAX : a < 0 ? MIN : 0;
    }
    v = pgt_sat(pgt_div_round((pgt_i128)a * 65536, b), &ov);
    *status = ov ? PG_FIX_OVERFLOW : PG_FIX_OK;
    return v;
}

static void test_div_edges(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof div_cases / sizeof div_cases[0]; ++i) {
        const binop_case *c = &div_cases[i];
        pg_fix out = 12345;
        int st;
        PG_EXPECT_EQ(pg_fix_div(c->a, c->b), c->want, "div case %zu: %d / %d", i, c->a, c->b);
        PG_EXPECT_EQ(pg_fix_div_checked(c->a, c->b, &out), c->status, "case %zu", i);
        PG_EXPECT_EQ(out, c->want, "checked case %zu", i);
        PG_EXPECT_EQ(ref_div(c->a, c->b, &st), c->want, "the reference agrees, case %zu", i);
        PG_EXPECT_EQ(st, c->status, "the reference agrees, case %zu", i);
    }
    PG_EXPECT_EQ(pg_fix_recip(0), MAX, "%s", "1/0");
    PG_EXPECT_EQ(pg_fix_recip(ONE), ONE, "%s", "1/1");
    PG_EXPECT_EQ(pg_fix_recip(-ONE), -ONE, "%s", "1/-1");
    PG_EXPECT_EQ(pg_fix_recip(2 * ONE), PG_FIX_HALF, "%s", "1/2");
    PG_EXPECT_EQ(pg_fix_recip(3 * ONE), 21845, "%s", "1/3");
    PG_EXPECT_EQ(pg_fix_recip(-3 * ONE), -21845, "%s", "-1/3");
    PG_EXPECT_EQ(pg_fix_recip(1), MAX, "%s", "1/2^-16 = 65536 saturates");
    PG_EXPECT_EQ(pg_fix_recip(-1), MIN, "%s", "");
    PG_EXPECT_EQ(pg_fix_recip(2), MAX, "%s", "32768 saturates");
    PG_EXPECT_EQ(pg_fix_recip(3), 21845 * ONE + 21845, "%s", "21845.333.. -> 21845.33333 (1431655765)");
    PG_EXPECT_EQ(pg_fix_recip(MAX), 2, "%s", "3.0518e-5 = 2.00000000093 LSB");
}

static void test_div_random(void **state)
{
    pgt_rng r = pgt_rng_seed(2);
    (void)state;
    for (int i = 0; i < 1000000; ++i) {
        pg_fix a = pgt_fix_any(&r), b = pgt_fix_any(&r), out;
        int st;
        pg_fix want = ref_div(a, b, &st);
        PG_EXPECT_EQ(pg_fix_div(a, b), want, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(pg_fix_div_checked(a, b, &out), st, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(out, want, "a=%d b=%d", a, b);
        PG_EXPECT_EQ(pg_fix_div(-a, b), -want, "a=%d b=%d", a, b);
        if (b != 0) PG_EXPECT_EQ(pg_fix_div(a, -b), -want, "a=%d b=%d", a, b);
    }
    /* Quotients near ties: a = (2k+1) * b / 2 exactly when b is even, for small k. */
    for (int i = 0; i < 200000; ++i) {
        pg_fix b = 2 * (pg_fix)(1 + pgt_below(&r, 1u << 20));
        int64_t k = (int64_t)pgt_below(&r, 4096);
        int64_t num = (2 * k + 1) * (b / 2); /* = (k + 1/2) * b: a * 2^16 must equal it */
        if (num % 65536 != 0) continue;
        {
            pg_fix a = (pg_fix)(num / 65536), out;
            int st;
            PG_EXPECT_EQ(pg_fix_div_checked(a, b, &out), PG_FIX_OK, "a=%d b=%d", a, b);
            PG_EXPECT_EQ(out, (pg_fix)(k + 1), "tie a=%d b=%d", a, b);
            PG_EXPECT_EQ(pg_fix_div(-a, b), -(pg_fix)(k + 1), "tie a=%d b=%d", -a, b);
            PG_EXPECT_EQ(ref_div(a, b, &st), (pg_fix)(k + 1), "reference a=%d b=%d", a, b);
        }
    }
}

/* ---- ratios of int64 ------------------------------------------------------------------ */

static pg_fix ref_ratio(int64_t num, int64_t den)
{
    if (den == 0) return num > 0 ? MAX : num < 0 ? MIN : 0;
    return pgt_sat(pgt_div_round((pgt_i128)num * 65536, den), NULL);
}

static void test_from_ratio(void **state)
{
    static const struct { int64_t num, den; pg_fix want; } cases[] = {
        {0, 1, 0},
        {0, -7, 0},
        {1, 2, PG_FIX_HALF},
        {1, 3, 21845},
        {2, 3, 43691},
        {-2, 3, -43691},
        {2, -3, -43691},
        {-2, -3, 43691},
        {1, 131072, 1},            /* half an LSB -> away */
        {-1, 131072, -1},
        {1, -131072, -1},
        {1, 131073, 0},
        {3, 262144, 1},            /* 0.75 LSB */
        {5, 131072 * 2, 1},        /* 1.25 LSB */
        {INT64_MAX, INT64_MAX, ONE},
        {INT64_MIN, INT64_MIN, ONE},
        {INT64_MIN, INT64_MAX, -ONE}, /* -1.0000000000000000001 */
        {INT64_MAX, INT64_MIN, -ONE}, /* -0.99999999999999999989 */
        {(INT64_C(1) << 62), INT64_MAX, PG_FIX_HALF}, /* 0.5000000000000000001 */
        {INT64_MIN / 2, INT64_MAX, -PG_FIX_HALF},
        {1, INT64_MAX, 0},
        {-1, INT64_MIN, 0},
        {INT64_MIN, 1, MIN},
        {INT64_MAX, 1, MAX},
        {INT64_MAX, -1, MIN},
        {INT64_MIN, -1, MAX},
        {32767, 1, 32767 * ONE},
        {32768, 1, MAX},
        {-32768, 1, MIN},
        /* (2^47 - 2^15 - 1) / 2^32 = (2^31 - 1/2 - 2^-16) LSB -> MAX, no overflow */
        {(INT64_C(1) << 47) - 32768 - 1, INT64_C(1) << 32, MAX},
        /* (2^47 - 2^15) / 2^32 = exactly 2^31 - 1/2 LSB: the tie rounds to 2^31, saturated */
        {(INT64_C(1) << 47) - 32768, INT64_C(1) << 32, MAX},
        {-((INT64_C(1) << 47) - 32768 - 1), INT64_C(1) << 32, MIN},
        /* Q32.32 cross products as in pg_mat22_solve */
        {INT64_C(3) << 32, INT64_C(2) << 32, 98304},
        {INT64_C(1000000007) * 1000000009, INT64_C(999999937) * 1000000007, 65536},
        /* division by zero saturates by the sign of num */
        {5, 0, MAX},
        {-5, 0, MIN},
        {INT64_MIN, 0, MIN},
        {0, 0, 0},
    };
    pgt_rng r = pgt_rng_seed(3);
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        PG_EXPECT_EQ(pg_fix_from_ratio(cases[i].num, cases[i].den), cases[i].want,
                     "case %zu: %lld / %lld", i, (long long)cases[i].num, (long long)cases[i].den);
        PG_EXPECT_EQ(ref_ratio(cases[i].num, cases[i].den), cases[i].want, "the reference agrees, case %zu", i);
    }
    /* Large random operands at every scale, against the 128-bit reference. */
    for (int i = 0; i < 1000000; ++i) {
        int64_t num = pgt_i64_any(&r), den = pgt_i64_any(&r);
        if (i % 4 == 1) den = (int64_t)((pgt_next(&r) >> 40) + 1) * ((i & 8) ? -1 : 1); /* small dens */
        if (i % 4 == 2) { /* results in range, often close to the limits */
            den = (int64_t)(pgt_next(&r) >> 2) + 1;
            num = (int64_t)(((pgt_i128)den * (int64_t)pgt_fix_any(&r)) >> 16);
        }
        PG_EXPECT_EQ(pg_fix_from_ratio(num, den), ref_ratio(num, den), "%lld / %lld", (long long)num, (long long)den);
    }
    /* Exact ties with huge operands: num / den = (2k + 1) / 2^17 with den = 2^17 * m. */
    for (int i = 0; i < 100000; ++i) {
        int64_t m = (int64_t)(pgt_next(&r) >> 35) + 1; /* < 2^29 */
        int64_t k = (int64_t)pgt_below(&r, 1u << 16);
        int64_t num = (2 * k + 1) * m, den = m << 17;
        PG_EXPECT_EQ(pg_fix_from_ratio(num, den), (pg_fix)(k + 1), "tie %lld / %lld", (long long)num, (long long)den);
        PG_EXPECT_EQ(pg_fix_from_ratio(-num, den), -(pg_fix)(k + 1), "tie %lld / %lld", (long long)-num, (long long)den);
        PG_EXPECT_EQ(pg_fix_from_ratio(num - 1, den), (pg_fix)k, "below tie %lld / %lld", (long long)num - 1, (long long)den);
        PG_EXPECT_EQ(pg_fix_from_ratio(1 - num, den), -(pg_fix)k, "below tie %lld / %lld", (long long)(1 - num), (long long)den);
    }
}

/* ---- square roots ----------------------------------------------------------------------- */

/* r is sqrt(a) correctly rounded iff (r - 1/2)^2 < a * 2^16 < (r + 1/2)^2, that is
 * (2r - 1)^2 < 4 a 2^16 < (2r + 1)^2 (both sides of a square of an odd number; 4 a 2^16 is
 * even, so there are no ties). This is the definition, not a re-implementation. */
static void check_sqrt(pg_fix a)
{
    pg_fix r = pg_fix_sqrt(a), out = 12345;
    uint64_t v4 = (uint64_t)a << 18, lo, hi;
    PG_EXPECT_EQ(pg_fix_sqrt_checked(a, &out), PG_FIX_OK, "a=%d", a);
    PG_EXPECT_EQ(out, r, "a=%d", a);
    if (r < 0) fail_msg("sqrt(%d) = %d is negative", a, r);
    lo = r > 0 ? (uint64_t)(2 * (int64_t)r - 1) * (uint64_t)(2 * (int64_t)r - 1) : 0;
    hi = (uint64_t)(2 * (int64_t)r + 1) * (uint64_t)(2 * (int64_t)r + 1);
    if (!((r == 0 || lo < v4) && v4 < hi)) fail_msg("sqrt(%d) = %d is not correctly rounded", a, r);
}

static void test_sqrt(void **state)
{
    static const struct { pg_fix a, want; } cases[] = {
        {0, 0},
        {1, 256},                  /* sqrt(2^-16) = 2^-8 */
        {2, 362},                  /* 2^-8 * sqrt 2 * 2^16 = 362.04 */
        {4, 512},
        {ONE, ONE},
        {4 * ONE, 2 * ONE},
        {2 * ONE, 92682},          /* 92681.900 */
        {PG_FIX_HALF, 46341},      /* 46340.950 */
        {32761 * ONE, 181 * ONE},
        {MAX, 11863283},           /* sqrt(2^47 - 2^16) = 11863283.200 */
    };
    pgt_rng r = pgt_rng_seed(4);
    pg_fix out;
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        PG_EXPECT_EQ(pg_fix_sqrt(cases[i].a), cases[i].want, "sqrt(%d)", cases[i].a);
        check_sqrt(cases[i].a);
    }
    /* negative arguments: 0 and PG_FIX_DOMAIN */
    out = 12345;
    PG_EXPECT_EQ(pg_fix_sqrt_checked(-1, &out), PG_FIX_DOMAIN, "%s", "sqrt(-1 LSB)");
    PG_EXPECT_EQ(out, 0, "%s", "sqrt(-1 LSB)");
    out = 12345;
    PG_EXPECT_EQ(pg_fix_sqrt_checked(MIN, &out), PG_FIX_DOMAIN, "%s", "sqrt(MIN)");
    PG_EXPECT_EQ(out, 0, "%s", "sqrt(MIN)");
    PG_EXPECT_EQ(pg_fix_sqrt(-ONE), 0, "%s", "sqrt(-1)");

    /* every value below 2^21, a strided sweep of the whole range, random values */
    for (pg_fix a = 0; a < (1 << 21); ++a) check_sqrt(a);
    for (int64_t a = MAX; a >= 0; a -= 1021) check_sqrt((pg_fix)a);
    for (int i = 0; i < 1000000; ++i) check_sqrt(pgt_fix_any(&r) & INT32_MAX);
    /* the values on both sides of every rounding boundary (r + 1/2)^2 for random r */
    for (int i = 0; i < 300000; ++i) {
        uint64_t rr = pgt_below(&r, 11863283u) + 1u, edge = rr * rr + rr; /* (r + 1/2)^2 - 1/4 */
        pg_fix a = (pg_fix)(edge >> 16);
        check_sqrt(a);
        if (a < MAX) check_sqrt(a + 1);
    }
    /* exact squares k^2 (in LSB^2 units) give exactly k, and monotonicity near them */
    for (int64_t k = 1; k < 11863283; k += 97) {
        uint64_t v = (uint64_t)(k * k);
        if ((v & 0xFFFFu) == 0) PG_EXPECT_EQ(pg_fix_sqrt((pg_fix)(v >> 16)), k, "k=%lld", (long long)k);
    }
}

/* pg_isqrt64 (whichever implementation PG_FAST_DIV64 picked) and the digit-by-digit one
 * (pg__isqrt64_digits, used when PG_FAST_DIV64 is 0) must both return the floor. */
static void check_isqrt64(uint64_t v)
{
    uint32_t r = pg_isqrt64(v), d = pg__isqrt64_digits(v);
    pgt_u128 r2 = (pgt_u128)r * r, r12 = (pgt_u128)((uint64_t)r + 1) * ((uint64_t)r + 1);
    if (!(r2 <= v && v < r12)) fail_msg("pg_isqrt64(%llu) = %u is not the floor", (unsigned long long)v, r);
    if (d != r) fail_msg("pg__isqrt64_digits(%llu) = %u, pg_isqrt64 = %u", (unsigned long long)v, d, r);
}

/* The Newton implementation's seed nodes are round(sqrt(64 + i) 2^27): checked exactly,
 * as the generator's output is for the sine table. r = floor(sqrt(x)) for x = (64 + i) 2^54,
 * and the nearest integer is r + 1 when x - r^2 > r (no ties for integers). */
static void test_isqrt64_seed_nodes(void **state)
{
    uint32_t count = 0, i;
    const uint32_t *nodes = pg__isqrt64_seed_nodes(&count);
    (void)state;
    if (nodes == NULL) skip();
    assert_int_equal(count, 193);
    for (i = 0; i < count; ++i) {
        uint64_t x = (uint64_t)(64u + i) << 54;
        uint64_t r = pg__isqrt64_digits(x);
        if (x - r * r > r) ++r;
        if (nodes[i] != r) fail_msg("isqrt seed node %u is %u, round(sqrt(%u) 2^27) is %llu", i, nodes[i], 64u + i, (unsigned long long)r);
    }
}

static void test_isqrt64(void **state)
{
    static const uint64_t edges[] = {
        0, 1, 2, 3, 4, 5, 8, 9, 10, 15, 16, 17, UINT64_C(4294967295), UINT64_C(4294967296),
        UINT64_C(4294967297), (UINT64_C(1) << 62) - 1, UINT64_C(1) << 62, (UINT64_C(1) << 62) + 1,
        (UINT64_C(1) << 63) - 1, UINT64_C(1) << 63, UINT64_C(0xFFFFFFFE00000001) - 1,
        UINT64_C(0xFFFFFFFE00000001) /* (2^32-1)^2 */, UINT64_C(0xFFFFFFFE00000001) + 1,
        UINT64_MAX - 1, UINT64_MAX,
    };
    pgt_rng r = pgt_rng_seed(5);
    (void)state;
    for (size_t i = 0; i < sizeof edges / sizeof edges[0]; ++i) check_isqrt64(edges[i]);
    PG_EXPECT_EQ(pg_isqrt64(UINT64_MAX), 4294967295u, "%s", "floor sqrt(2^64 - 1)");
    PG_EXPECT_EQ(pg_isqrt64(UINT64_C(0xFFFFFFFE00000001)), 4294967295u, "%s", "(2^32-1)^2");
    PG_EXPECT_EQ(pg_isqrt64(UINT64_C(0xFFFFFFFE00000000)), 4294967294u, "%s", "(2^32-1)^2 - 1");
    for (uint64_t v = 0; v < 100000; ++v) check_isqrt64(v);
    for (int i = 0; i < 300000; ++i) {
        uint64_t k = pgt_next(&r) >> (32 + pgt_below(&r, 32)); /* k < 2^32 */
        check_isqrt64(k * k);
        if (k > 0) check_isqrt64(k * k - 1);
        check_isqrt64(k * k + 1);
        check_isqrt64(pgt_next(&r) >> pgt_below(&r, 64));
    }
    /* Every bit length, 65536 values each (4.2 million): the top bit set, the rest random,
     * and the smallest and largest values of that length. */
    for (int bits = 1; bits <= 64; ++bits) {
        uint64_t top = UINT64_C(1) << (bits - 1), rest = top - 1u;
        check_isqrt64(top);
        check_isqrt64(top | rest);
        for (int i = 0; i < 65536; ++i) check_isqrt64(top | (pgt_next(&r) & rest));
    }
    /* Squares and their neighbours, k^2 - 1, k^2, k^2 + 1, for k near every power of two
     * up to 2^32 - 1 (the floor changes at k^2; the Newton step lands one above the
     * floor just below it). */
    for (int j = 0; j <= 32; ++j) {
        uint64_t c = UINT64_C(1) << j;
        for (uint64_t k = c > 64u ? c - 64u : 0u; k <= c + 64u && k <= UINT64_C(0xFFFFFFFF); ++k) {
            check_isqrt64(k * k);
            if (k > 0) check_isqrt64(k * k - 1u);
            check_isqrt64(k * k + 1u);
        }
    }
    for (uint64_t k = UINT64_C(0xFFFFFFFF) - 4096u; k <= UINT64_C(0xFFFFFFFF); ++k) {
        check_isqrt64(k * k);
        check_isqrt64(k * k - 1u);
        check_isqrt64(k * k + 1u);
    }
}

/* ---- status messages --------------------------------------------------------------------- */

/* pg__udiv64_32 (intmath.h) is floor(n / d) exactly: at the edges of both operands and
 * for random operands of every bit length (the solver's reciprocals use it in place of
 * a 64-bit division, which must not change a bit). */
static void check_udiv64_32(uint64_t n, uint32_t d)
{
    uint64_t q = pg__udiv64_32(n, d);
    if (q != n / d) fail_msg("pg__udiv64_32(%llu, %lu) = %llu, want %llu", (unsigned long long)n, (unsigned long)d,
                             (unsigned long long)q, (unsigned long long)(n / d));
}

static void test_udiv64_32(void **state)
{
    static const uint64_t ns[] = {0, 1, 2, 0xFFFFu, 0x10000u, 0xFFFFFFFFu, UINT64_C(0x100000000), UINT64_C(0x7FFFFFFFFFFFFFFF),
                                  UINT64_C(0x8000000000000000), UINT64_C(0xFFFFFFFFFFFFFFFF), UINT64_C(0xFFFFFFFF00000000),
                                  UINT64_C(0x4000000020000000), UINT64_C(0x00007FFFFFFF8000)};
    static const uint32_t ds[] = {1, 2, 3, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u,
                                  0xFFFFFFFFu, 0x40000000u, 0x7FFF8001u};
    pgt_rng r = pgt_rng_seed(21);
    size_t i, j;
    int k;
    (void)state;
    for (i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (j = 0; j < sizeof ds / sizeof ds[0]; ++j) {
            check_udiv64_32(ns[i], ds[j]);
            check_udiv64_32(ns[i] - (ns[i] > 0), ds[j]);
            check_udiv64_32((uint64_t)ds[j] * (ns[i] & 0xFFFFFFFFu), ds[j]); /* exact multiples */
            check_udiv64_32((uint64_t)ds[j] * (ns[i] & 0xFFFFFFFFu) + ds[j] - 1u, ds[j]);
        }
    for (k = 0; k < 2000000; ++k) {
        uint64_t n = pgt_next(&r) >> pgt_below(&r, 64);
        uint32_t d = (uint32_t)(pgt_next(&r) >> (32 + pgt_below(&r, 32)));
        if (d == 0) d = 1;
        check_udiv64_32(n, d);
    }
}

static void test_status_messages(void **state)
{
    static const struct { pg_fix_status st; const char *name; } names[] = {
        {PG_FIX_OK, "PG_FIX_OK"},           {PG_FIX_OVERFLOW, "PG_FIX_OVERFLOW"},
        {PG_FIX_DIV_ZERO, "PG_FIX_DIV_ZERO"}, {PG_FIX_DOMAIN, "PG_FIX_DOMAIN"},
        {PG_FIX_SYNTAX, "PG_FIX_SYNTAX"},
    };
    (void)state;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        const char *m = pg_fix_status_message(names[i].st);
        size_t n = strlen(names[i].name);
        assert_non_null(m);
        if (strncmp(m, names[i].name, n) != 0 || m[n] != ':' || strlen(m) < n + 10)
            fail_msg("message for %s is \"%s\"; want \"%s: <explanation>\"", names[i].name, m, names[i].name);
    }
    assert_string_equal(pg_fix_status_message((pg_fix_status)99), "unknown pg_fix_status");
}

/* ---- decimal formatting ------------------------------------------------------------------ */

/* The value a p-fraction-digit decimal T / 10^p parses to (magnitudes only). */
static int64_t parse_value_of(uint64_t t, int p)
{
    pgt_i128 pow = 1;
    for (int i = 0; i < p; ++i) pow *= 10;
    return (int64_t)pgt_div_round((pgt_i128)t * 65536, pow);
}

/* Check that `text` is the shortest decimal that parses back to a, in canonical form:
 * -?(0|[1-9][0-9]*)(.[0-9]*[1-9])? */
static void check_format(pg_fix a)
{
    char buf[PG_FIX_FORMAT_MAX];
    size_t n = pg_fix_format(a, buf, sizeof buf), i = 0, dot = 0;
    pg_fix back = 12345;
    int p = 0;
    uint64_t mag = (uint64_t)(a < 0 ? -(int64_t)a : a), t = 0;
    if (n >= sizeof buf || strlen(buf) != n) fail_msg("format(%d): length %zu, text \"%s\"", a, n, buf);
    PG_EXPECT_EQ(pg_fix_parse(buf, n, &back), PG_FIX_OK, "format(%d) = \"%s\"", a, buf);
    PG_EXPECT_EQ(back, a, "round trip of format(%d) = \"%s\"", a, buf);
    /* canonical form */
    if (buf[0] == '-') {
        if (a >= 0) fail_msg("format(%d) = \"%s\" has a sign", a, buf);
        ++i;
    } else if (a < 0) {
        fail_msg("format(%d) = \"%s\" lost its sign", a, buf);
    }
    if (buf[i] == '0' && buf[i + 1] != '\0' && buf[i + 1] != '.') fail_msg("format(%d) = \"%s\": leading zero", a, buf);
    for (; i < n; ++i) {
        if (buf[i] == '.') {
            if (dot) fail_msg("format(%d) = \"%s\": two dots", a, buf);
            dot = i;
        } else if (buf[i] >= '0' && buf[i] <= '9') {
            t = t * 10u + (uint64_t)(buf[i] - '0');
            if (dot) ++p;
        } else {
            fail_msg("format(%d) = \"%s\": bad character", a, buf);
        }
    }
    if (dot && (p == 0 || buf[n - 1] == '0')) fail_msg("format(%d) = \"%s\": trailing dot or zero", a, buf);
    if (p > 5) fail_msg("format(%d) = \"%s\": more than 5 fraction digits", a, buf);
    if (strcmp(buf, "-0") == 0) fail_msg("format(%d) = \"-0\"", a);
    /* shortest: no decimal with p - 1 fraction digits parses to |a|. The two candidates
     * nearest to |a| are floor and ceil of |a| 10^(p-1) / 2^16. */
    if (p > 0) {
        uint64_t pow = 1, c;
        for (int k = 0; k < p - 1; ++k) pow *= 10u;
        c = mag * pow / 65536u;
        if ((uint64_t)parse_value_of(c, p - 1) == mag || (uint64_t)parse_value_of(c + 1, p - 1) == mag)
            fail_msg("format(%d) = \"%s\" is not the shortest: %d fraction digits would do", a, buf, p - 1);
    }
    /* with that length, the nearest: |T/10^p - |a|/2^16| <= 1/2 * 10^-p */
    {
        pgt_i128 pow = 1, diff;
        for (int k = 0; k < p; ++k) pow *= 10;
        diff = (pgt_i128)t * 65536 - (pgt_i128)mag * pow; /* in units of 1/(10^p 2^16) */
        if (diff < 0) diff = -diff;
        if (2 * diff > 65536) fail_msg("format(%d) = \"%s\" is not the nearest %d-digit decimal", a, buf, p);
    }
}

static void test_format_exact(void **state)
{
    static const struct { pg_fix a; const char *text; } cases[] = {
        {0, "0"},
        {ONE, "1"},
        {-ONE, "-1"},
        {PG_FIX_HALF, "0.5"},
        {-PG_FIX_HALF, "-0.5"},
        {-(12 * ONE + 24576), "-12.375"},
        {6554, "0.1"},            /* parse("0.1") == 6554 */
        {6553, "0.09999"},        /* 0.0999908..: nothing shorter parses back */
        {-6554, "-0.1"},
        {16384, "0.25"},
        {1024, "0.01563"},        /* 0.015625: 5 digits needed; 1562.5 rounds away */
        {1, "0.00002"},           /* 1.52588e-5 */
        {-1, "-0.00002"},
        {2, "0.00003"},
        {PG_FIX_PI, "3.14159"},
        {-PG_FIX_PI, "-3.14159"},
        {32767 * ONE, "32767"},
        {MAX, "32767.99998"},
        {MIN, "-32767.99998"},
        {10 * ONE, "10"},
        {100 * ONE + 32768, "100.5"},
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char buf[PG_FIX_FORMAT_MAX];
        size_t n = pg_fix_format(cases[i].a, buf, sizeof buf);
        if (strcmp(buf, cases[i].text) != 0) fail_msg("format(%d) = \"%s\", want \"%s\"", cases[i].a, buf, cases[i].text);
        PG_EXPECT_EQ(n, strlen(cases[i].text), "format(%d)", cases[i].a);
        check_format(cases[i].a);
    }
}

static void test_format_roundtrip(void **state)
{
    static const pg_fix int_parts[] = {0, 1, 9, 10, 99, 12345, 32767};
    pgt_rng r = pgt_rng_seed(6);
    (void)state;
    /* every fraction with a few integer parts, both signs */
    for (size_t k = 0; k < sizeof int_parts / sizeof int_parts[0]; ++k) {
        for (pg_fix f = 0; f < 65536; ++f) {
            pg_fix a = int_parts[k] * 65536 + f;
            check_format(a);
            check_format(-a);
        }
    }
    /* a strided sweep of the whole range */
    for (int64_t a = MIN; a <= MAX; a += 4099) check_format((pg_fix)a);
    check_format(MAX);
    /* random values */
    for (int i = 0; i < 300000; ++i) check_format(pgt_fix_any(&r));
}

static void test_format_truncation(void **state)
{
    char buf[PG_FIX_FORMAT_MAX];
    pg_fix a = -(12 * ONE + 24576); /* "-12.375", 7 characters */
    (void)state;
    /* snprintf semantics: the needed length without the NUL is returned, at most
     * size - 1 characters are written, always followed by a NUL when size > 0. */
    PG_EXPECT_EQ(pg_fix_format(a, NULL, 0), 7, "%s", "length query with NULL");
    memset(buf, 'x', sizeof buf);
    PG_EXPECT_EQ(pg_fix_format(a, buf, 0), 7, "%s", "size 0");
    PG_EXPECT_EQ(buf[0], 'x', "%s", "size 0 writes nothing");
    PG_EXPECT_EQ(pg_fix_format(a, buf, 1), 7, "%s", "size 1");
    assert_string_equal(buf, "");
    PG_EXPECT_EQ(buf[1], 'x', "%s", "size 1 writes only the NUL");
    memset(buf, 'x', sizeof buf);
    PG_EXPECT_EQ(pg_fix_format(a, buf, 3), 7, "%s", "size 3");
    assert_string_equal(buf, "-1");
    PG_EXPECT_EQ(buf[3], 'x', "%s", "no write past size");
    memset(buf, 'x', sizeof buf);
    PG_EXPECT_EQ(pg_fix_format(a, buf, 7), 7, "%s", "size 7: one short");
    assert_string_equal(buf, "-12.37");
    PG_EXPECT_EQ(buf[7], 'x', "%s", "no write past size");
    memset(buf, 'x', sizeof buf);
    PG_EXPECT_EQ(pg_fix_format(a, buf, 8), 7, "%s", "size 8: exact fit");
    assert_string_equal(buf, "-12.375");
    PG_EXPECT_EQ(buf[8], 'x', "%s", "no write past size");
    /* the longest outputs fit PG_FIX_FORMAT_MAX */
    PG_EXPECT_EQ(pg_fix_format(MIN, buf, sizeof buf), 12, "%s", "-32767.99998");
    assert_string_equal(buf, "-32767.99998");
    PG_EXPECT_EQ(pg_fix_format(-(32767 * ONE + 1), NULL, 0), 12, "%s", "-32767.00002");
    PG_EXPECT_EQ(pg_fix_format(0, buf, 2), 1, "%s", "zero");
    assert_string_equal(buf, "0");
}

/* ---- decimal parsing ----------------------------------------------------------------------- */

static void expect_parse(const char *text, size_t len, pg_fix_status status, pg_fix want)
{
    pg_fix out = 12345;
    pg_fix_status st = pg_fix_parse(text, len, &out);
    if (st != status || out != want)
        fail_msg("parse(\"%.*s\", %zu) = %d, status %d; want %d, status %d", (int)len, text ? text : "(null)", len, out,
                 (int)st, want, (int)status);
}
#define PARSE_OK(text, want) expect_parse(text, sizeof(text) - 1, PG_FIX_OK, want)
#define PARSE_OVERFLOW(text, want) expect_parse(text, sizeof(text) - 1, PG_FIX_OVERFLOW, want)
#define PARSE_SYNTAX(text) expect_parse(text, sizeof(text) - 1, PG_FIX_SYNTAX, 0)

static void test_parse_exact(void **state)
{
    (void)state;
    PARSE_OK("0", 0);
    PARSE_OK("-0", 0);
    PARSE_OK("+0", 0);
    PARSE_OK("0.0", 0);
    PARSE_OK("1", ONE);
    PARSE_OK("+1", ONE);
    PARSE_OK("-1", -ONE);
    PARSE_OK(".5", PG_FIX_HALF);
    PARSE_OK("+.5", PG_FIX_HALF);
    PARSE_OK("-.5", -PG_FIX_HALF);
    PARSE_OK("5.", 5 * ONE);   /* a trailing dot is accepted (documented) */
    PARSE_OK("-5.", -5 * ONE);
    PARSE_OK("1.5", 98304);
    PARSE_OK("0.1", 6554);     /* 6553.6 */
    PARSE_OK("-0.1", -6554);
    PARSE_OK("3.14159", 205887); /* 205887.242 */
    PARSE_OK("-12.375", -(12 * ONE + 24576));
    PARSE_OK("0.00001", 1);    /* 0.655 LSB */
    PARSE_OK("0.000007", 0);   /* 0.459 LSB */
    PARSE_OK("0.0000077", 1);  /* 0.505 LSB */
    PARSE_OK("-0.000007", 0);  /* rounds to zero, no negative zero */
    PARSE_OK("32767", 32767 * ONE);
    PARSE_OK("32767.99998", MAX);   /* 65534.69 */
    PARSE_OK("32767.99999", MAX);   /* 65535.34 */
    PARSE_OK("-32767.99999", MIN);
    PARSE_OK("-32767.99998", MIN);
    PARSE_OK("000000000000000000000000000000000000000012.5", 12 * ONE + PG_FIX_HALF);
    PARSE_OK("12.50000000000000000000000000000000000000000000", 12 * ONE + PG_FIX_HALF);
    PARSE_OK("0.99999999999999999999999999999999999999999", ONE);
    /* `len` bytes are read; no NUL terminator needed */
    expect_parse("12.5xyz", 4, PG_FIX_OK, 12 * ONE + PG_FIX_HALF);
    expect_parse("1.25", 3, PG_FIX_OK, 78643); /* "1.2": 78643.2 */
    expect_parse("-7", 1, PG_FIX_SYNTAX, 0);   /* "-" */
}

static void test_parse_ties_and_long_digits(void **state)
{
    (void)state;
    /* 2^-17 = 0.00000762939453125 exactly (17 digits): half an LSB -> away from zero */
    PARSE_OK("0.00000762939453125", 1);
    PARSE_OK("-0.00000762939453125", -1);
    PARSE_OK("0.0000076293945312", 0);   /* 16 digits: just below */
    PARSE_OK("0.0000076293945313", 1);   /* 16 digits: just above */
    /* 45 digits: the tie followed by zeros is still the tie; anything after lifts it */
    PARSE_OK("0.000007629394531250000000000000000000000000000", 1);
    PARSE_OK("-0.000007629394531250000000000000000000000000000", -1);
    PARSE_OK("0.000007629394531250000000000000000000000000001", 1);
    /* just below the tie, with 45 digits: must not round up */
    PARSE_OK("0.000007629394531249999999999999999999999999999", 0);
    PARSE_OK("-0.000007629394531249999999999999999999999999999", 0);
    /* 1.5 and 2.5 LSB: ties away from zero (to-even would give 2 and 2) */
    PARSE_OK("0.00002288818359375", 2);
    PARSE_OK("0.00003814697265625", 3);
    PARSE_OK("-0.00003814697265625", -3);
    PARSE_OK("0.00003814697265624999999999999999999999999999999999", 2);
    /* 12345 + 12345.5 LSB */
    PARSE_OK("12345.18837738037109375", 12345 * ONE + 12346); /* 12345.5 / 65536 exactly */
    PARSE_OK("12345.188377380371093749", 12345 * ONE + 12345);
    /* the last tie below the limit: MAX - 1/2 LSB rounds up to MAX (fits) */
    PARSE_OK("32767.99997711181640625", MAX);                 /* 65534.5 / 65536 */
    PARSE_OK("32767.9999771118164062499999999999999999999", MAX - 1);
    /* the tie above MAX: 32767 + 65535.5/65536 rounds to 2^31: overflow */
    PARSE_OVERFLOW("32767.99999237060546875", MAX);
    PARSE_OVERFLOW("-32767.99999237060546875", MIN);
    PARSE_OK("32767.99999237060546874999999999999999999999", MAX);
    PARSE_OK("-32767.99999237060546874999999999999999999999", MIN);
}

static void test_parse_overflow(void **state)
{
    pgt_rng r = pgt_rng_seed(7);
    (void)state;
    PARSE_OVERFLOW("32768", MAX);
    PARSE_OVERFLOW("-32768", MIN);
    PARSE_OVERFLOW("+32768.0", MAX);
    PARSE_OVERFLOW("32767.999995", MAX);  /* 65535.67 LSB rounds to 2^31 */
    PARSE_OVERFLOW("32767.9999999999999999999999999999999999999", MAX);
    PARSE_OVERFLOW("99999999999999999999999999999999999999999", MAX);
    PARSE_OVERFLOW("-99999999999999999999999999999999999999999.5", MIN);
    PARSE_OVERFLOW("18446744073709551616", MAX); /* 2^64: must not wrap */
    PARSE_OVERFLOW("-18446744073709551617", MIN);
    PARSE_OVERFLOW("4294967296", MAX);
    PARSE_OVERFLOW("65536", MAX);
    for (int i = 0; i < 100000; ++i) {
        char buf[64];
        uint64_t ip = 32768u + (pgt_next(&r) >> pgt_below(&r, 49));
        int neg = (int)(pgt_next(&r) & 1u);
        int n = snprintf(buf, sizeof buf, "%s%llu.%llu", neg ? "-" : "", (unsigned long long)ip,
                         (unsigned long long)pgt_below(&r, 1000000));
        expect_parse(buf, (size_t)n, PG_FIX_OVERFLOW, neg ? MIN : MAX);
    }
}

static void test_parse_malformed(void **state)
{
    (void)state;
    PARSE_SYNTAX("");
    PARSE_SYNTAX("-");
    PARSE_SYNTAX("+");
    PARSE_SYNTAX(".");
    PARSE_SYNTAX("-.");
    PARSE_SYNTAX("+.");
    PARSE_SYNTAX("..5");
    PARSE_SYNTAX("5..");
    PARSE_SYNTAX("1e3");
    PARSE_SYNTAX("1E3");
    PARSE_SYNTAX("1.5e-3");
    PARSE_SYNTAX(" 1");
    PARSE_SYNTAX("1 ");
    PARSE_SYNTAX("\t1");
    PARSE_SYNTAX("1\n");
    PARSE_SYNTAX("1.2.3");
    PARSE_SYNTAX("--1");
    PARSE_SYNTAX("+-1");
    PARSE_SYNTAX("-+1");
    PARSE_SYNTAX("++1");
    PARSE_SYNTAX("1-");
    PARSE_SYNTAX("1+");
    PARSE_SYNTAX("0x10");
    PARSE_SYNTAX("1,5");
    PARSE_SYNTAX("1_000");
    PARSE_SYNTAX("abc");
    PARSE_SYNTAX("inf");
    PARSE_SYNTAX("nan");
    PARSE_SYNTAX("-inf");
    PARSE_SYNTAX("\xc2\xbd");       /* a non-ASCII "1/2" */
    PARSE_SYNTAX("1\xd9\xa1");      /* non-ASCII digit */
    PARSE_SYNTAX("99999999999999999999999x"); /* syntax beats overflow */
    PARSE_SYNTAX("-32768 ");
    expect_parse("1\0", 2, PG_FIX_SYNTAX, 0); /* an embedded NUL is a character */
    expect_parse("\0", 1, PG_FIX_SYNTAX, 0);
    expect_parse("12", 0, PG_FIX_SYNTAX, 0);  /* zero bytes read: empty */
    expect_parse(NULL, 0, PG_FIX_SYNTAX, 0);
    expect_parse(NULL, 5, PG_FIX_SYNTAX, 0);
}

/* Reference parser: exact, by a different route from the library. The value of
 * [sign] I.F as a multiple of 10^-25 is P = I 10^25 + F25 (the first 25 fraction digits)
 * plus a tail t in [0, 1). Every rounding boundary (2k + 1) 2^-17 is a whole multiple of
 * 10^-25 (it has 17 fraction digits), so the value reaches a boundary iff P does: the tail
 * never decides, and round(P 2^16 / 10^25) with ties away is the exact answer. */
static pg_fix_status ref_parse(const char *s, size_t len, pg_fix *out)
{
    size_t i = 0;
    int neg = 0, digits = 0, fd = 0;
    pgt_i128 ip = 0, fr = 0, pow25 = 1, q;
    *out = 0;
    for (int k = 0; k < 25; ++k) pow25 *= 10;
    if (i < len && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    for (; i < len && s[i] >= '0' && s[i] <= '9'; ++i, ++digits) {
        ip = ip * 10 + (s[i] - '0');
        if (ip > 1000000) ip = 1000000; /* clearly out of range; keep it from growing */
    }
    if (i < len && s[i] == '.') {
        for (++i; i < len && s[i] >= '0' && s[i] <= '9'; ++i, ++digits) {
            if (fd < 25) { fr = fr * 10 + (s[i] - '0'); ++fd; }
        }
    }
    if (digits == 0 || i != len) return PG_FIX_SYNTAX;
    for (; fd < 25; ++fd) fr *= 10;
    q = pgt_div_round((ip * pow25 + fr) * 65536, pow25);
    if (q > (pgt_i128)MAX) {
        *out = neg ? MIN : MAX;
        return PG_FIX_OVERFLOW;
    }
    *out = neg ? -(pg_fix)q : (pg_fix)q;
    return PG_FIX_OK;
}

static void test_parse_random(void **state)
{
    pgt_rng r = pgt_rng_seed(8);
    (void)state;
    for (int i = 0; i < 400000; ++i) {
        char buf[128];
        size_t n = 0;
        uint64_t kind = pgt_below(&r, 8);
        uint64_t sign = pgt_below(&r, 3);
        pg_fix got, want;
        pg_fix_status st, wst;
        if (sign == 1) buf[n++] = '-';
        if (sign == 2) buf[n++] = '+';
        if (kind == 0) { /* exact halfway points (2k + 1) / 2^17, 17 digits, plus a tail */
            uint64_t ip = pgt_below(&r, 32768u), k = pgt_below(&r, 65536u);
            uint64_t frac = (2u * k + 1u) * UINT64_C(762939453125); /* * 5^17: 17 digits */
            n += (size_t)snprintf(buf + n, sizeof buf - n, "%llu.%017llu", (unsigned long long)ip, (unsigned long long)frac);
            switch (pgt_below(&r, 4)) {
            case 0: break;
            case 1: n += (size_t)snprintf(buf + n, sizeof buf - n, "0000000000000000000000000"); break;
            case 2: n += (size_t)snprintf(buf + n, sizeof buf - n, "00000000000000000000000001"); break;
            default: /* just below: subtract one unit in the 17th place, append 9s */
                n -= 1;
                if (buf[n] == '0') { n += 1; break; } /* frac is odd * 5^17, ends in 5 */
                buf[n] = (char)(buf[n] - 1);
                n += 1;
                n += (size_t)snprintf(buf + n, sizeof buf - n, "99999999999999999999999999");
                break;
            }
        } else {
            uint64_t ip_digits = pgt_below(&r, 7), frac_digits = pgt_below(&r, kind == 1 ? 46 : 22);
            int dot = frac_digits > 0 || pgt_below(&r, 4) == 0;
            if (ip_digits == 0 && !dot) ip_digits = 1;
            for (uint64_t k = 0; k < ip_digits; ++k) buf[n++] = (char)('0' + pgt_below(&r, k == 0 && ip_digits > 1 && kind != 2 ? 4 : 10));
            if (dot) {
                buf[n++] = '.';
                for (uint64_t k = 0; k < frac_digits; ++k) buf[n++] = (char)('0' + pgt_below(&r, 10));
            }
            if (ip_digits == 0 && frac_digits == 0) buf[n++] = '7'; /* "." alone is malformed */
            buf[n] = '\0';
        }
        st = pg_fix_parse(buf, n, &got);
        wst = ref_parse(buf, n, &want);
        if (st != wst || got != want)
            fail_msg("parse(\"%s\") = %d status %d; reference %d status %d", buf, got, (int)st, want, (int)wst);
        if (wst == PG_FIX_SYNTAX) fail_msg("generator made malformed text \"%s\"", buf);
    }
}

/* A NULL result pointer is allowed (fixed.h): the status is still computed and returned,
 * the value is discarded. Before: a store through NULL (fixed.c). */
static void test_null_out(void **state)
{
    pgt_rng r = pgt_rng_seed(21);
    (void)state;
    assert_int_equal(pg_fix_parse("1.5", 3, NULL), PG_FIX_OK);
    assert_int_equal(pg_fix_parse("-32768", 6, NULL), PG_FIX_OVERFLOW);
    assert_int_equal(pg_fix_parse("1.5x", 4, NULL), PG_FIX_SYNTAX);
    assert_int_equal(pg_fix_parse(NULL, 3, NULL), PG_FIX_SYNTAX);
    assert_int_equal(pg_fix_parse("", 0, NULL), PG_FIX_SYNTAX);
    assert_int_equal(pg_fix_add_checked(PG_FIX_MAX, 1, NULL), PG_FIX_OVERFLOW);
    assert_int_equal(pg_fix_sub_checked(PG_FIX_MIN, 1, NULL), PG_FIX_OVERFLOW);
    assert_int_equal(pg_fix_mul_checked(PG_FIX_C(200), PG_FIX_C(200), NULL), PG_FIX_OVERFLOW);
    assert_int_equal(pg_fix_div_checked(PG_FIX_ONE, 0, NULL), PG_FIX_DIV_ZERO);
    assert_int_equal(pg_fix_div_checked(0, 0, NULL), PG_FIX_DIV_ZERO);
    assert_int_equal(pg_fix_div_checked(PG_FIX_C(30000), 1, NULL), PG_FIX_OVERFLOW);
    assert_int_equal(pg_fix_sqrt_checked(-1, NULL), PG_FIX_DOMAIN);
    assert_int_equal(pg_fix_sqrt_checked(PG_FIX_C(4), NULL), PG_FIX_OK);
    /* the same status as with a result pointer, for values at every scale */
    for (int i = 0; i < 20000; ++i) {
        pg_fix a = pgt_fix_any(&r), b = pgt_fix_any(&r), v;
        char text[PG_FIX_FORMAT_MAX];
        size_t n = pg_fix_format(a, text, sizeof text);
        PG_EXPECT_EQ(pg_fix_add_checked(a, b, NULL), pg_fix_add_checked(a, b, &v), "add %d %d", a, b);
        PG_EXPECT_EQ(pg_fix_sub_checked(a, b, NULL), pg_fix_sub_checked(a, b, &v), "sub %d %d", a, b);
        PG_EXPECT_EQ(pg_fix_mul_checked(a, b, NULL), pg_fix_mul_checked(a, b, &v), "mul %d %d", a, b);
        PG_EXPECT_EQ(pg_fix_div_checked(a, b, NULL), pg_fix_div_checked(a, b, &v), "div %d %d", a, b);
        PG_EXPECT_EQ(pg_fix_div_checked(a, 0, NULL), pg_fix_div_checked(a, 0, &v), "div %d 0", a);
        PG_EXPECT_EQ(pg_fix_sqrt_checked(a, NULL), pg_fix_sqrt_checked(a, &v), "sqrt %d", a);
        PG_EXPECT_EQ(pg_fix_parse(text, n, NULL), pg_fix_parse(text, n, &v), "parse %s", text);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_shift_rule),
        cmocka_unit_test(test_int_conversion_and_sat),
        cmocka_unit_test(test_add_sub_checked),
        cmocka_unit_test(test_mul_edges),
        cmocka_unit_test(test_mul_random),
        cmocka_unit_test(test_div_edges),
        cmocka_unit_test(test_div_random),
        cmocka_unit_test(test_from_ratio),
        cmocka_unit_test(test_sqrt),
        cmocka_unit_test(test_isqrt64_seed_nodes),
        cmocka_unit_test(test_isqrt64),
        cmocka_unit_test(test_udiv64_32),
        cmocka_unit_test(test_status_messages),
        cmocka_unit_test(test_format_exact),
        cmocka_unit_test(test_format_roundtrip),
        cmocka_unit_test(test_format_truncation),
        cmocka_unit_test(test_parse_exact),
        cmocka_unit_test(test_parse_ties_and_long_digits),
        cmocka_unit_test(test_parse_overflow),
        cmocka_unit_test(test_parse_malformed),
        cmocka_unit_test(test_parse_random),
        cmocka_unit_test(test_null_out),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
