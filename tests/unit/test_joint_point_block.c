/* test_joint_point_block.c — the point block's shares (src/core/joint_rows.c,
 * pg__joint_point_init): mA and mB are (1/mA) / S and (1/mB) / S in Q2.30, S = 1/mA + 1/mB
 * saturated, each rounded to nearest with ties away from zero, then times K'^-1; ia and ib
 * are (1/IA) / S and (1/IB) / S. The set-up skips divisions where an identity gives the
 * same number (B's share as 2^30 less A's, a half for equal masses, one quotient for equal
 * inertias, 0 for a side that does not move); these cases hold it to an __int128
 * reference where the identities do not apply: both shares ties (S a multiple of 2^31),
 * a saturated S, and random masses, inertias and levers, equal and not. */
#include "pg_test.h"

#include "joint_rows.h"

/* round(inv 2^30 / S), as the set-up rounds a share */
static int64_t share(int64_t inv, int64_t S) { return (int64_t)pgt_div_round((pgt_i128)inv << 30, S); }

/* the inertia terms' (1/I) / S, which saturates to INT64_MAX past 2^63 */
static int64_t share_sat(int64_t inv, int64_t S)
{
    pgt_i128 q = pgt_div_round((pgt_i128)inv << 30, S);
    return q > (pgt_i128)INT64_MAX ? INT64_MAX : (int64_t)q;
}

static int64_t sum_sat(int64_t a, int64_t b) { return a > INT64_MAX - b ? INT64_MAX : a + b; }

static joint_side side(int64_t inv_mass, int64_t inv_inertia, pg_fix lx, pg_fix ly)
{
    joint_side s;
    memset(&s, 0, sizeof s);
    s.active = inv_mass > 0;
    s.inv_mass = inv_mass;
    s.inv_inertia = inv_inertia;
    s.lever = s.lever_now = pg_v2(lx, ly);
    return s;
}

static void check(const joint_side *A, const joint_side *B)
{
    joint_point p;
    int64_t S = sum_sat(A->inv_mass, B->inv_mass), a, b;
    int k;
    pg__joint_point_init(&p, A, B);
    assert_true(p.S == S);
    assert_true(p.ia == share_sat(A->inv_inertia, S));
    assert_true(p.ib == share_sat(B->inv_inertia, S));
    a = share(A->inv_mass, S);
    b = share(B->inv_mass, S);
    for (k = 0; k < 3; ++k) {
        if (p.mA[k] != (int32_t)row_round(a * p.kinv[k], 30) || p.mB[k] != (int32_t)row_round(b * p.kinv[k], 30))
            fail_msg("1/mA %lld, 1/mB %lld: entry %d is (%d, %d), exact shares %lld, %lld give (%d, %d)", (long long)A->inv_mass,
                     (long long)B->inv_mass, k, p.mA[k], p.mB[k], (long long)a, (long long)b, (int)row_round(a * p.kinv[k], 30),
                     (int)row_round(b * p.kinv[k], 30));
    }
}

/* Without inertia K'^-1 = I, so mA[0] and mB[0] are the shares themselves. */
static void test_ties(void **state)
{
    /* 1/mA = (2 n + 1) c, S = c 2^31: (1/mA) 2^30 / S = n + 1/2, and so is B's share */
    static const int64_t odd[] = {1, 3, 12345, 999999, (INT64_C(1) << 31) - 1};
    static const int64_t scale[] = {1, 128, INT64_C(1) << 20, INT64_C(1) << 31};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof odd / sizeof odd[0]; ++i)
        for (j = 0; j < sizeof scale / sizeof scale[0]; ++j) {
            int64_t a = odd[i] * scale[j], S = scale[j] << 31;
            joint_side A = side(a, 0, 0, 0), B = side(S - a, 0, 0, 0);
            joint_point p;
            check(&A, &B);
            pg__joint_point_init(&p, &A, &B);
            assert_int_equal(p.mA[0] + p.mB[0], (INT64_C(1) << 30) + 1); /* both rounded up */
        }
}

static void test_saturated_and_static(void **state)
{
    static const int64_t inv[] = {0, 1, 3, INT64_C(1) << 38, (INT64_C(1) << 62) + 5, INT64_MAX - 1, INT64_MAX};
    size_t i, j;
    (void)state;
    for (i = 0; i < sizeof inv / sizeof inv[0]; ++i)
        for (j = 0; j < sizeof inv / sizeof inv[0]; ++j) {
            joint_side A = side(inv[i], 0, 0, 0), B = side(inv[j], 0, 0, 0);
            if (inv[i] == 0 && inv[j] == 0) continue; /* S = 0: no block */
            check(&A, &B);
        }
}

static void test_random(void **state)
{
    pgt_rng rng = pgt_rng_seed(UINT64_C(0x70b10c4));
    int k;
    (void)state;
    for (k = 0; k < 20000; ++k) {
        uint64_t r = pgt_next(&rng), s = pgt_next(&rng), t = pgt_next(&rng);
        int64_t ma = (int64_t)(r >> (24 + (t & 15u))), mb = (int64_t)(s >> (24 + ((t >> 4) & 15u)));
        joint_side A = side(ma, (int64_t)(t >> 26), (pg_fix)(int16_t)(r >> 8) * 4, (pg_fix)(int16_t)(s >> 8) * 4);
        joint_side B = side(mb, (int64_t)(r >> 27), (pg_fix)(int16_t)(t >> 40) * 4, (pg_fix)(int16_t)(t >> 20) * 4);
        if (ma == 0 && mb == 0) continue;
        check(&A, &B);
    }
}

/* Identical bodies: equal masses make each share exactly a half, equal inertias one
 * quotient for both sides. */
static void test_identical_bodies(void **state)
{
    pgt_rng rng = pgt_rng_seed(UINT64_C(0x1de471ca1));
    int k;
    (void)state;
    for (k = 0; k < 20000; ++k) {
        uint64_t r = pgt_next(&rng), t = pgt_next(&rng);
        int64_t m = (int64_t)(r >> (1 + t % 62u)), i = (int64_t)(t >> (1 + (r >> 8) % 62u));
        joint_side A = side(m, i, (pg_fix)(int16_t)(r >> 16) * 4, (pg_fix)(int16_t)(t >> 16) * 4);
        joint_side B = side(m, i, (pg_fix)(int16_t)(r >> 32) * 4, (pg_fix)(int16_t)(t >> 32) * 4);
        if (m == 0) continue;
        check(&A, &B);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ties),
        cmocka_unit_test(test_saturated_and_static),
        cmocka_unit_test(test_random),
        cmocka_unit_test(test_identical_bodies),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
