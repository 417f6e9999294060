/* test_wide_div.c — pg__div64_shl (src/core/wide.h), the set-up's wide division: for every
 * numerator, denominator and shift it is round(num 2^shift / den), nearest with ties
 * away from zero, saturated to +-INT64_MAX when the quotient reaches 2^63, exactly as
 * an __int128 reference computes it. The cases cover denominators of every bit length
 * (the quotient bits per hardware division depend on it), 2^63's magnitude, shifts 0..64
 * and the saturation edge; test_wide_div_serial builds it with PG_FAST_DIV64=0 (one bit a
 * turn, for targets without a 64-bit divider). */
#include "pg_test.h"

#include "wide.h"

/* The reference: the exact quotient in 128 bits (|num| 2^shift <= 2^127 fits), rounded
 * half away from zero, saturated past INT64_MAX. */
static int64_t reference(int64_t num, int64_t den, int shift)
{
    int negative = (num < 0) != (den < 0);
    pgt_u128 un = num < 0 ? (pgt_u128)(-(pgt_i128)num) : (pgt_u128)num;
    pgt_u128 ud = den < 0 ? (pgt_u128)(-(pgt_i128)den) : (pgt_u128)den, n, q, r;
    if (den == 0) return num > 0 ? INT64_MAX : num < 0 ? -INT64_MAX : 0;
    n = un << shift;
    q = n / ud;
    r = n % ud;
    if (r >= ud - r) ++q;
    if (q > (pgt_u128)INT64_MAX) return negative ? -INT64_MAX : INT64_MAX;
    return negative ? -(int64_t)q : (int64_t)q;
}

static void check(int64_t num, int64_t den, int shift)
{
    int64_t got = pg__div64_shl(num, den, shift), want = reference(num, den, shift);
    if (got != want)
        fail_msg("pg__div64_shl(%lld, %lld, %d) = %lld, exact %lld", (long long)num, (long long)den, shift, (long long)got,
                 (long long)want);
}

static void test_edges(void **state)
{
    static const int64_t values[] = {0, 1, -1, 2, 3, -3, 65536, INT64_C(1) << 30, (INT64_C(1) << 38) + 1, INT32_MAX,
                                     (INT64_C(1) << 62) - 1, INT64_C(1) << 62, INT64_MAX - 1, INT64_MAX, -INT64_MAX, INT64_MIN};
    size_t i, j;
    int s;
    (void)state;
    for (i = 0; i < sizeof values / sizeof values[0]; ++i)
        for (j = 0; j < sizeof values / sizeof values[0]; ++j)
            for (s = 0; s <= 64; ++s) check(values[i], values[j], s);
}

static void test_random_every_length(void **state)
{
    pgt_rng rng = pgt_rng_seed(UINT64_C(0x5eed0d1f));
    int nbits, dbits, k;
    (void)state;
    for (nbits = 1; nbits <= 64; ++nbits)
        for (dbits = 1; dbits <= 64; ++dbits)
            for (k = 0; k < 12; ++k) {
                uint64_t a = pgt_next(&rng), b = pgt_next(&rng), c = pgt_next(&rng);
                int64_t num = (int64_t)(a >> (64 - nbits) >> 1), den = (int64_t)(b >> (64 - dbits) >> 1);
                if (c & 1u) num = -num;
                if (c & 2u) den = -den;
                check(num, den, (int)((c >> 8) % 65u));
            }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_random_every_length),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
