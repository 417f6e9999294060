/* test_trig.c — binary angles, the sine tables at every size, CORDIC atan2, rotations,
 * vector length and normalisation, 2x2 solve, dot and cross products.
 *
 * Every table size 8..12 is tested in one run: trig_table.inc is included with
 * PG_TRIG_ALL_TABLES and interpolated with the library's own pg__table_sin_q30.
 *
 * THE SINE ERROR BOUND (per table size, N = 2^bits entries, h = 2 pi / N)
 *   Linear interpolation between exact nodes errs by at most h^2/8 * max|sin''| = h^2/8.
 *   Each entry is sin rounded to Q2.30 (error <= 1/2 unit of 2^-30); interpolating
 *   those errors is a convex combination, so it adds <= 1/2 unit; the interpolated value
 *   is rounded once, another <= 1/2 unit. So
 *       |table_sin(a) - sin(a)| <= h^2/8 + 2^-30              (B(bits) below)
 *   bits:   8        9        10       11       12
 *   h^2/8:  7.53e-5  1.88e-5  4.71e-6  1.18e-6  2.94e-7
 *   The bound is nearly attained at the midpoints of the intervals next to the peaks
 *   (error cos(h/2) (1 - cos(h/2)) ~ h^2/8 - h^4/64), so the test also checks that the
 *   sweep found an error close to it: a sweep that missed the worst points would pass
 *   any table.
 */
#define PG_TRIG_ALL_TABLES 1
#include "pg_test.h"

#include <math.h>

#include "pogon/config.h"
#include "trig.h"
#include "trig_table.inc"

typedef struct { int bits; const int32_t *table, *quarter; } table_info;
static const table_info tables[] = {
    {8, pg_sin_table_8, pg_sin_quarter_8}, {9, pg_sin_table_9, pg_sin_quarter_9}, {10, pg_sin_table_10, pg_sin_quarter_10},
    {11, pg_sin_table_11, pg_sin_quarter_11}, {12, pg_sin_table_12, pg_sin_quarter_12},
};
#define NTABLES (sizeof tables / sizeof tables[0])

#define TURN 4294967296.0
#define Q30 1073741824.0
#define LSB 65536.0

static double turn_to_rad(double units) { return units * (2.0 * PGT_PI / TURN); }

/* B(bits) of the header comment, in real units. */
static double sin_bound(int bits)
{
    double h = 2.0 * PGT_PI / (double)(1 << bits);
    return h * h / 8.0 + 1.0 / Q30;
}

static const int32_t *configured_table(void)
{
    for (size_t i = 0; i < NTABLES; ++i)
        if (tables[i].bits == PG_TRIG_TABLE_BITS) return tables[i].table;
    fail_msg("PG_TRIG_TABLE_BITS=%d has no table in trig_table.inc", PG_TRIG_TABLE_BITS);
    return NULL;
}

/* Signed difference got - want of two angles in turn units, wrapped to [-2^31, 2^31). */
static double angle_diff(double got, double want)
{
    double d = fmod(got - want, TURN);
    if (d >= TURN / 2) d -= TURN;
    if (d < -TURN / 2) d += TURN;
    return d;
}

/* ---- the tables ------------------------------------------------------------------------ */

static void test_table_entries(void **state)
{
    (void)state;
    for (size_t t = 0; t < NTABLES; ++t) {
        int bits = tables[t].bits, n = 1 << bits;
        const int32_t *tab = tables[t].table;
        for (int i = 0; i < n; ++i) {
            double exact = sin(2.0 * PGT_PI * i / n) * Q30;
            /* each entry is sin rounded to nearest Q2.30 */
            PG_EXPECT_LE(fabs(tab[i] - exact), 0.5 + 1e-6, "bits=%d i=%d", bits, i);
            /* mirrored exactly: sin(-x) = -sin(x), sin(pi - x) = sin(x) */
            PG_EXPECT_EQ(tab[(n - i) & (n - 1)], -tab[i], "bits=%d i=%d", bits, i);
            PG_EXPECT_EQ(tab[(n / 2 - i) & (n - 1)], tab[i], "bits=%d i=%d", bits, i);
        }
        PG_EXPECT_EQ(tab[0], 0, "bits=%d", bits);
        PG_EXPECT_EQ(tab[n / 4], PG_ROT_ONE, "bits=%d", bits);
        PG_EXPECT_EQ(tab[n / 2], 0, "bits=%d", bits);
        PG_EXPECT_EQ(tab[3 * n / 4], -PG_ROT_ONE, "bits=%d", bits);
    }
    for (int i = 0; i < 32; ++i) {
        double exact = atan(ldexp(1.0, -i)) / (2.0 * PGT_PI) * TURN;
        PG_EXPECT_LE(fabs(pg_cordic_atan_table[i] - exact), 0.5 + 1e-6, "cordic i=%d", i);
    }
}

/* Max |table_sin - sin| and |table_cos - cos| over a dense sweep, in real units. */
static double sweep_error(const int32_t *tab, int bits)
{
    int k = 32 - bits;
    double worst = 0.0;
    /* every node, the midpoint and quarter points of every interval ... */
    for (uint32_t i = 0; i < (1u << bits); ++i) {
        for (uint32_t f = 0; f < 4; ++f) {
            pg_angle a = (i << k) + (f << (k - 2));
            double x = turn_to_rad((double)a);
            double es = fabs(pg__table_sin_q30(tab, bits, a) / Q30 - sin(x));
            double ec = fabs(pg__table_sin_q30(tab, bits, a + PG_ANGLE_QUARTER) / Q30 - cos(x));
            if (f == 0) PG_EXPECT_EQ(pg__table_sin_q30(tab, bits, a), tab[i], "node bits=%d i=%u", bits, i);
            if (es > worst) worst = es;
            if (ec > worst) worst = ec;
        }
    }
    /* ... and a strided sweep of all angles (stride prime, so every offset within an
     * interval is visited at some point) */
    for (uint64_t a64 = 12345; a64 < (UINT64_C(1) << 32); a64 += 4093) {
        pg_angle a = (pg_angle)a64;
        double x = turn_to_rad((double)a);
        double es = fabs(pg__table_sin_q30(tab, bits, a) / Q30 - sin(x));
        double ec = fabs(pg__table_sin_q30(tab, bits, a + PG_ANGLE_QUARTER) / Q30 - cos(x));
        if (es > worst) worst = es;
        if (ec > worst) worst = ec;
    }
    return worst;
}

static void test_table_error_bound(void **state)
{
    (void)state;
    for (size_t t = 0; t < NTABLES; ++t) {
        int bits = tables[t].bits;
        double h = 2.0 * PGT_PI / (double)(1 << bits);
        double worst = sweep_error(tables[t].table, bits), bound = sin_bound(bits);
        double attained = cos(h / 2) * (1.0 - cos(h / 2)) - 1.0 / Q30; /* see header */
        print_message("sin/cos table %2d bits: max error %.4e (%.1f Q2.30 units, %.3f Q16.16 LSB), bound h^2/8 + 2^-30 = %.4e\n",
                      bits, worst, worst * Q30, worst * LSB, bound);
        PG_EXPECT_LE(worst, bound + 1e-12, "table bits=%d", bits);
        PG_EXPECT_LE(attained, worst, "the sweep must reach the worst case, bits=%d", bits);
    }
}

static void test_table_symmetries(void **state)
{
    pgt_rng r = pgt_rng_seed(21);
    (void)state;
    for (size_t t = 0; t < NTABLES; ++t) {
        int bits = tables[t].bits;
        const int32_t *tab = tables[t].table;
        for (int i = 0; i < 400000; ++i) {
            pg_angle a = (pg_angle)pgt_next(&r);
            int32_t s, c;
            if (i < 4096) a = ((pg_angle)i << (32 - bits)) + ((pg_angle)1 << (31 - bits)); /* midpoints */
            if (i >= 4096 && i < 8192) a = (pg_angle)(i - 4096) << (32 - bits) | (pg_angle)(i & 7); /* near nodes */
            s = pg__table_sin_q30(tab, bits, a);
            c = pg__table_sin_q30(tab, bits, a + PG_ANGLE_QUARTER);
            PG_EXPECT_EQ(pg__table_sin_q30(tab, bits, 0u - a), -s, "sin(-a) bits=%d a=%u", bits, a);
            PG_EXPECT_EQ(pg__table_sin_q30(tab, bits, a + PG_ANGLE_HALF), -s, "sin(a+half) bits=%d a=%u", bits, a);
            PG_EXPECT_EQ(pg__table_sin_q30(tab, bits, PG_ANGLE_HALF - a), s, "sin(half-a) bits=%d a=%u", bits, a);
            PG_EXPECT_EQ(pg__table_sin_q30(tab, bits, PG_ANGLE_QUARTER - a), c, "cos(-a) bits=%d a=%u", bits, a);
            if (s < -PG_ROT_ONE || s > PG_ROT_ONE) fail_msg("|sin| > 1: bits=%d a=%u s=%d", bits, a, s);
        }
    }
}

/* The library stores only the first quarter of each table and mirrors it on reading
 * (pg__quarter_entry). Every entry of the full turn, and the wrap past its end, must be
 * the full table's: the interpolation (pg__interp_sin_q30) is then fed the same two
 * entries for every angle, so pg__quarter_sin_q30 equals pg__table_sin_q30 for all 2^32
 * angles. The sweep checks that on the functions themselves: every angle within 3 of a
 * table node (the quadrant boundaries among them) and a dense stride in between. */
static void test_quarter_tables(void **state)
{
    (void)state;
    for (size_t t = 0; t < NTABLES; ++t) {
        int bits = tables[t].bits;
        uint32_t n = (uint32_t)1 << bits, k = 32u - (uint32_t)bits;
        for (uint32_t i = 0; i <= n; ++i)
            PG_EXPECT_EQ(pg__quarter_entry(tables[t].quarter, bits, i), tables[t].table[i & (n - 1u)], "bits=%d i=%u", bits, i);
        for (uint32_t i = 0; i < n; ++i) {
            for (int d = -3; d <= 3; ++d) {
                pg_angle a = (i << k) + (uint32_t)d;
                PG_EXPECT_EQ(pg__quarter_sin_q30(tables[t].quarter, bits, a), pg__table_sin_q30(tables[t].table, bits, a),
                             "bits=%d a=%u", bits, a);
            }
        }
        for (uint64_t a = 0; a < (UINT64_C(1) << 32); a += 65521u)
            PG_EXPECT_EQ(pg__quarter_sin_q30(tables[t].quarter, bits, (pg_angle)a), pg__table_sin_q30(tables[t].table, bits, (pg_angle)a),
                         "bits=%d a=%u", bits, (pg_angle)a);
    }
}

static void test_library_tables(void **state)
{
    const int32_t *tab = configured_table();
    pgt_rng r = pgt_rng_seed(22);
    (void)state;
    PG_EXPECT_EQ(pg_angle_sin_q30(0), 0, "%s", "sin 0");
    PG_EXPECT_EQ(pg_angle_sin_q30(PG_ANGLE_QUARTER), PG_ROT_ONE, "%s", "sin quarter");
    PG_EXPECT_EQ(pg_angle_sin_q30(PG_ANGLE_HALF), 0, "%s", "sin half");
    PG_EXPECT_EQ(pg_angle_sin_q30(3u * PG_ANGLE_QUARTER), -PG_ROT_ONE, "%s", "sin 3/4");
    PG_EXPECT_EQ(pg_angle_cos_q30(0), PG_ROT_ONE, "%s", "cos 0");
    PG_EXPECT_EQ(pg_angle_cos_q30(PG_ANGLE_HALF), -PG_ROT_ONE, "%s", "cos half");
    PG_EXPECT_EQ(pg_fix_sin(0), 0, "%s", "");
    PG_EXPECT_EQ(pg_fix_cos(0), PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_fix_sin(PG_FIX_HALF_PI), PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_fix_sin(-PG_FIX_HALF_PI), -PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_fix_cos(PG_FIX_PI), -PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_fix_sin(PG_FIX_PI), 0, "%s", "sin(205887 / 2^16) = 6.35e-6 = 0.42 LSB");
    for (int i = 0; i < 200000; ++i) {
        pg_angle a = (pg_angle)pgt_next(&r);
        pg_rot rot = pg_rot_from_angle(a);
        PG_EXPECT_EQ(pg_angle_sin_q30(a), pg__table_sin_q30(tab, PG_TRIG_TABLE_BITS, a), "a=%u", a);
        PG_EXPECT_EQ(pg_angle_cos_q30(a), pg__table_sin_q30(tab, PG_TRIG_TABLE_BITS, a + PG_ANGLE_QUARTER), "a=%u", a);
        /* pg_rot_from_angle is the table's (cos, sin) brought back to unit length: the
         * same direction (the Newton factor scales both components alike, so the angle
         * moves by at most the rounding of one component, 2^-31 rad) */
        PG_EXPECT_LE(fabs(atan2((double)rot.s, (double)rot.c) -
                          atan2((double)pg_angle_sin_q30(a), (double)pg_angle_cos_q30(a))), 1.5 / Q30, "a=%u", a);
    }
}

/* pg_fix_sin / pg_fix_cos on radians: table error, the final rounding to Q16.16 (1/2 LSB)
 * and the radians -> binary angle conversion (1/2 unit plus the error of its rounded
 * constant, |r| * |C - 2^32/(2 pi)| / 2^16 units; sin is 1-Lipschitz). */
static double conversion_error_units(pg_fix radians)
{
    const double c_exact = TURN / (2.0 * PGT_PI), c_used = 683565276.0;
    return 0.5 + fabs((double)radians) * fabs(c_used - c_exact) / LSB;
}

static void check_fix_sin_cos(pg_fix x, double *worst)
{
    double xr = x / LSB;
    double bound = sin_bound(PG_TRIG_TABLE_BITS) + 0.5 / LSB + turn_to_rad(conversion_error_units(x)) + 1e-12;
    double es = fabs(pg_fix_sin(x) / LSB - sin(xr)), ec = fabs(pg_fix_cos(x) / LSB - cos(xr));
    PG_EXPECT_LE(es, bound, "sin x=%d", x);
    PG_EXPECT_LE(ec, bound, "cos x=%d", x);
    if (es > *worst) *worst = es;
    if (ec > *worst) *worst = ec;
}

static void test_fix_sin_cos(void **state)
{
    pgt_rng r = pgt_rng_seed(23);
    double worst = 0.0;
    (void)state;
    double worst_small;
    for (pg_fix x = -8 * PG_FIX_ONE; x <= 8 * PG_FIX_ONE; x += 7) check_fix_sin_cos(x, &worst);
    worst_small = worst;
    for (int i = 0; i < 200000; ++i) check_fix_sin_cos(pgt_fix_any(&r), &worst);
    check_fix_sin_cos(PG_FIX_MAX, &worst);
    check_fix_sin_cos(PG_FIX_MIN, &worst);
    print_message("pg_fix_sin/cos (table %d bits): max error %.3f LSB for |x| <= 8, %.3f LSB over all x "
                  "(large |x| adds the radians->angle constant's error)\n",
                  PG_TRIG_TABLE_BITS, worst_small * LSB, worst * LSB);
    /* exact symmetries of the library functions */
    for (int i = 0; i < 200000; ++i) {
        pg_fix x = pgt_fix_any(&r);
        PG_EXPECT_EQ(pg_fix_sin(-x), -pg_fix_sin(x), "x=%d", x);
        PG_EXPECT_EQ(pg_fix_cos(-x), pg_fix_cos(x), "x=%d", x);
    }
}

/* ---- atan2 ------------------------------------------------------------------------------ */

#define ATAN2_BOUND (TURN / 1048576.0) /* 2^-20 turn, documented in fixed.h */

static double check_atan2(pg_fix y, pg_fix x)
{
    pg_angle got = pg_angle_atan2(y, x);
    double want = (x == 0 && y == 0) ? 0.0 : atan2((double)y, (double)x) / (2.0 * PGT_PI) * TURN;
    double err = fabs(angle_diff((double)got, want));
    pg_fix rad = pg_fix_atan2(y, x);
    PG_EXPECT_LE(err, ATAN2_BOUND, "atan2(%d, %d) = %u, want %.1f", y, x, got, want);
    /* exact symmetries: quadrants are restored by exact integer operations */
    PG_EXPECT_EQ(pg_angle_atan2(-y, x), (pg_angle)(0u - got), "atan2(-y, x): y=%d x=%d", y, x);
    if (x != 0) PG_EXPECT_EQ(pg_angle_atan2(y, -x), (pg_angle)(PG_ANGLE_HALF - got), "atan2(y, -x): y=%d x=%d", y, x);
    /* radians: the angle error plus the final rounding */
    if (rad < -PG_FIX_PI || rad > PG_FIX_PI) fail_msg("pg_fix_atan2(%d, %d) = %d out of [-pi, pi]", y, x, rad);
    {
        double wr = (x == 0 && y == 0) ? 0.0 : atan2((double)y, (double)x) * LSB;
        double d = fabs(rad - wr);
        if (d > PGT_PI * LSB) d = fabs(d - 2.0 * PGT_PI * LSB); /* -pi and pi are the same angle */
        PG_EXPECT_LE(d, 0.5 + turn_to_rad(ATAN2_BOUND) * LSB + 1e-6, "pg_fix_atan2(%d, %d) = %d", y, x, rad);
    }
    return err;
}

static void test_atan2(void **state)
{
    static const pg_fix mags[] = {1, 2, 3, 7, 100, 32767, PG_FIX_ONE, PG_FIX_ONE + 1, 1 << 29, (1 << 30) - 1,
                                  1 << 30, PG_FIX_MAX - 1, PG_FIX_MAX};
    pgt_rng r = pgt_rng_seed(24);
    double worst = 0.0, e;
    (void)state;
    PG_EXPECT_EQ(pg_angle_atan2(0, 0), 0, "%s", "(0, 0) -> 0");
    PG_EXPECT_EQ(pg_fix_atan2(0, 0), 0, "%s", "(0, 0) -> 0");
    for (size_t i = 0; i < sizeof mags / sizeof mags[0]; ++i) {
        pg_fix m = mags[i];
        /* the positive and negative x axes are exact */
        PG_EXPECT_EQ(pg_angle_atan2(0, m), 0, "x axis m=%d", m);
        PG_EXPECT_EQ(pg_angle_atan2(0, -m), PG_ANGLE_HALF, "negative x axis m=%d", m);
        PG_EXPECT_EQ(pg_fix_atan2(0, -m), -PG_FIX_PI, "negative x axis in radians is -pi, m=%d", m);
        e = check_atan2(m, 0); if (e > worst) worst = e;      /* y axis */
        e = check_atan2(-m, 0); if (e > worst) worst = e;
        for (size_t j = 0; j < sizeof mags / sizeof mags[0]; ++j) {
            e = check_atan2(m, mags[j]); if (e > worst) worst = e;
            e = check_atan2(-m, -mags[j]); if (e > worst) worst = e;
            e = check_atan2(mags[j], -m); if (e > worst) worst = e;
        }
    }
    for (pg_fix y = -60; y <= 60; ++y)
        for (pg_fix x = -60; x <= 60; ++x) { e = check_atan2(y, x); if (e > worst) worst = e; }
    for (int i = 0; i < 300000; ++i) {
        e = check_atan2(pgt_fix_any(&r), pgt_fix_any(&r));
        if (e > worst) worst = e;
    }
    print_message("atan2: max error %.1f turn units (%.3g turn; bound 2^-20 = %.3g)\n", worst, worst / TURN, ATAN2_BOUND / TURN);
}

/* ---- angles and radians ------------------------------------------------------------------ */

static void test_angle_radians(void **state)
{
    /* half a Q16.16 radian step in turn units: the resolution of angle -> radians */
    const double half_step_units = TURN / (2.0 * PGT_PI) / LSB / 2.0;
    pgt_rng r = pgt_rng_seed(25);
    (void)state;
    PG_EXPECT_EQ(pg_angle_to_radians(0), 0, "%s", "");
    PG_EXPECT_EQ(pg_angle_to_radians(PG_ANGLE_QUARTER), PG_FIX_HALF_PI, "%s", "");
    PG_EXPECT_EQ(pg_angle_to_radians(0u - PG_ANGLE_QUARTER), -PG_FIX_HALF_PI, "%s", "");
    PG_EXPECT_EQ(pg_angle_to_radians(PG_ANGLE_HALF), -PG_FIX_PI, "%s", "half a turn is -pi: range [-pi, pi)");
    PG_EXPECT_EQ(pg_angle_to_radians(PG_ANGLE_HALF - 1), PG_FIX_PI, "%s", "");
    PG_EXPECT_EQ(pg_angle_to_radians(1u << 29), 51472, "%s", "pi/4 = 51471.85 LSB");
    PG_EXPECT_EQ(pg_angle_from_radians(0), 0, "%s", "");
    PG_EXPECT_EQ(pg_angle_from_radians(PG_FIX_TWO_PI), 1752, "%s", "round(411775 * 683565276 / 2^16) mod 2^32: 2 pi + 0.17 LSB");

    /* to_radians: correctly rounded (its constant errs by 2e-5 LSB at most), symmetric */
    for (uint64_t a64 = 0; a64 < (UINT64_C(1) << 32); a64 += 65521) {
        pg_angle a = (pg_angle)(a64 ^ (a64 >> 7));
        pg_fix got = pg_angle_to_radians(a);
        double want = turn_to_rad((double)(int32_t)a) * LSB;
        PG_EXPECT_LE(fabs(got - want), 0.5 + 1e-4, "to_radians(%u) = %d, want %.4f", a, got, want);
        if (a != PG_ANGLE_HALF) PG_EXPECT_EQ(pg_angle_to_radians(0u - a), -got, "a=%u", a);
    }
    /* from_radians: within 1/2 unit plus the error of the rounded constant, mod 2^32 */
    for (int i = 0; i < 300000; ++i) {
        pg_fix x = i < 1000 ? (pg_fix)(i - 500) : pgt_fix_any(&r);
        double want = (double)x / LSB / (2.0 * PGT_PI) * TURN;
        double err = fabs(angle_diff((double)pg_angle_from_radians(x), want));
        /* + 0.01: the double reference ~2^44 units carries 2^-8-unit steps */
        PG_EXPECT_LE(err, conversion_error_units(x) + 0.01, "from_radians(%d)", x);
        PG_EXPECT_EQ(pg_angle_from_radians(-x), (pg_angle)(0u - pg_angle_from_radians(x)), "x=%d", x);
    }
    /* round trip radians -> angle -> radians is exact on all of [-pi, pi] */
    for (pg_fix x = -PG_FIX_PI; x <= PG_FIX_PI; ++x) {
        PG_EXPECT_EQ(pg_angle_to_radians(pg_angle_from_radians(x)), x, "x=%d", x);
        PG_EXPECT_EQ(pg_fix_wrap_angle(x), x, "wrap is the identity on [-pi, pi]: x=%d", x);
    }
    /* round trip angle -> radians -> angle: within half a radian step (5215.2 units) */
    for (int i = 0; i < 300000; ++i) {
        pg_angle a = (pg_angle)pgt_next(&r);
        double err = fabs(angle_diff((double)pg_angle_from_radians(pg_angle_to_radians(a)), (double)a));
        PG_EXPECT_LE(err, half_step_units + 1.0, "a=%u", a);
    }
    /* wrapping: any radians to [-pi, pi], within 1/2 LSB plus the conversion error */
    for (int i = 0; i < 300000; ++i) {
        pg_fix x = pgt_fix_any(&r), w = pg_fix_wrap_angle(x);
        double exact = remainder((double)x / LSB, 2.0 * PGT_PI) * LSB, d;
        if (w < -PG_FIX_PI || w > PG_FIX_PI) fail_msg("wrap(%d) = %d out of [-pi, pi]", x, w);
        d = fabs(w - exact);
        if (d > PGT_PI * LSB) d = fabs(d - 2.0 * PGT_PI * LSB);
        PG_EXPECT_LE(d, 0.5 + turn_to_rad(conversion_error_units(x)) * LSB + 1e-6, "wrap(%d) = %d, exact %.3f", x, w, exact);
    }
    /* adding a whole turn (PG_FIX_TWO_PI = 2 pi + 0.17 LSB) moves the result by <= 1 LSB */
    for (pg_fix x = -PG_FIX_PI; x <= PG_FIX_PI; x += 3) {
        pg_fix w = pg_fix_wrap_angle(x + PG_FIX_TWO_PI), d = w - x;
        if (d > PG_FIX_PI) d -= PG_FIX_TWO_PI;
        if (d < -PG_FIX_PI) d += PG_FIX_TWO_PI;
        if (d < -1 || d > 1) fail_msg("wrap(%d + 2 pi) = %d", x, w);
    }
}

/* ---- rotations ----------------------------------------------------------------------------- */

static pg_fix ref_round_sat(pgt_i128 num, int shift)
{
    return pgt_sat(pgt_div_round(num, (pgt_i128)1 << shift), NULL);
}

static void test_rotations(void **state)
{
    const double b = sin_bound(PG_TRIG_TABLE_BITS), h = 2.0 * PGT_PI / (double)(1 << PG_TRIG_TABLE_BITS);
    const double hchord = h * h / 8.0;
    pgt_rng r = pgt_rng_seed(26);
    double worst_rt_small = 0.0, worst_rt_1000 = 0.0, worst_norm = 0.0;
    (void)state;
    /* exact rotations */
    for (int i = 0; i < 10000; ++i) {
        pg_vec2 v = pg_v2(pgt_fix_any(&r), pgt_fix_any(&r));
        pg_rot q = pg_rot_from_angle(PG_ANGLE_QUARTER), h = pg_rot_from_angle(PG_ANGLE_HALF);
        assert_true(pg_v2_equal(pg_rot_apply(pg_rot_identity(), v), v));
        assert_true(pg_v2_equal(pg_rot_apply_inv(pg_rot_identity(), v), v));
        assert_true(pg_v2_equal(pg_rot_apply(pg_rot_from_angle(0), v), v));
        assert_true(pg_v2_equal(pg_rot_apply(q, v), pg_v2_perp(v)));
        assert_true(pg_v2_equal(pg_rot_apply_inv(q, v), pg_v2_rperp(v)));
        assert_true(pg_v2_equal(pg_rot_apply(h, v), pg_v2_neg(v)));
    }
    for (int i = 0; i < 300000; ++i) {
        pg_angle a = (pg_angle)pgt_next(&r);
        pg_rot rot = pg_rot_from_angle(a);
        int bits = i % 3 == 0 ? 16 : i % 3 == 1 ? 26 : 30; /* |v_i| < 1, < 1024, < 16384 */
        pg_vec2 v = pg_v2(pgt_fix_bits(&r, bits), pgt_fix_bits(&r, bits)), w, u;
        double nr = hypot((double)rot.c, (double)rot.s) / Q30, lv = hypot(v.x, v.y), lw, ex, ey, dev;
        /* The table's (c, s) lies on a chord, |(c, s)| in [cos(h/2), 1] (h^2/8 short at
         * most); pg_rot_from_angle scales it by one Newton step for 1/sqrt(q), which
         * leaves a relative error of 3/2 (h^2/8)^2 (pgt_rot_norm_error: 1.3e-13 at 12
         * bits, 8.5e-9 at 8), then rounds: the factor to Q30 (1/2 unit relative) and
         * each component (1/2 unit, sqrt(2)/2 together). Hence
         * | |R| - 1 | <= 3/2 (h^2/8)^2 + (0.5 + 0.71) 2^-30 (hchord, the unnormalised
         * bound, is kept for comparison). */
        (void)hchord;
        PG_EXPECT_LE(fabs(nr - 1.0), pgt_rot_norm_error() + 1.25 / Q30, "a=%u", a);
        if (fabs(nr - 1.0) > worst_norm) worst_norm = fabs(nr - 1.0);
        /* R v and R^T v are the exact products rounded once (and saturated) */
        w = pg_rot_apply(rot, v);
        PG_EXPECT_EQ(w.x, ref_round_sat((pgt_i128)rot.c * v.x - (pgt_i128)rot.s * v.y, 30), "a=%u", a);
        PG_EXPECT_EQ(w.y, ref_round_sat((pgt_i128)rot.s * v.x + (pgt_i128)rot.c * v.y, 30), "a=%u", a);
        u = pg_rot_apply_inv(rot, v);
        PG_EXPECT_EQ(u.x, ref_round_sat((pgt_i128)rot.c * v.x + (pgt_i128)rot.s * v.y, 30), "a=%u", a);
        PG_EXPECT_EQ(u.y, ref_round_sat((pgt_i128)rot.c * v.y - (pgt_i128)rot.s * v.x, 30), "a=%u", a);
        if (bits == 30 && (lv * nr > PG_FIX_MAX * 0.999)) continue; /* may saturate */
        /* length: |R v| = |v| |R| up to the rounding of the two components (sqrt(2)/2 LSB),
         * so |v| is preserved within |v| sqrt(2) B + sqrt(2)/2 LSB */
        lw = hypot(w.x, w.y);
        PG_EXPECT_LE(fabs(lw - lv * nr), 0.70711, "a=%u v=(%d,%d)", a, v.x, v.y);
        PG_EXPECT_LE(fabs(lw - lv), lv * sqrt(2.0) * b + 0.70711, "a=%u v=(%d,%d)", a, v.x, v.y);
        PG_EXPECT_LE(fabs(hypot(u.x, u.y) - lv), lv * sqrt(2.0) * b + 0.70711, "a=%u v=(%d,%d)", a, v.x, v.y);
        /* round trip R^T (R v) = |R|^2 v + R^T e1 + e2 with |e1| <= sqrt(2)/2, |e2_i| <= 1/2:
         * each component within |R| sqrt(2)/2 + 1/2 LSB of |R|^2 v */
        u = pg_rot_apply_inv(rot, w);
        ex = fabs(u.x - nr * nr * v.x);
        ey = fabs(u.y - nr * nr * v.y);
        PG_EXPECT_LE(ex, nr * 0.70711 + 0.5, "round trip a=%u v=(%d,%d)", a, v.x, v.y);
        PG_EXPECT_LE(ey, nr * 0.70711 + 0.5, "round trip a=%u v=(%d,%d)", a, v.x, v.y);
        dev = fmax(fabs((double)u.x - v.x), fabs((double)u.y - v.y));
        if (bits == 16 && dev > worst_rt_small) worst_rt_small = dev;
        if (bits == 26 && dev > worst_rt_1000) worst_rt_1000 = dev;
        /* So rotating there and back is NOT exact beyond small vectors: |R|^2 != 1 scales v
         * by up to 2 sqrt(2) B (1.3e-5 with 10 bits: 0.87 LSB per unit of length). For
         * components below 1 and a table of >= 10 bits the bound above is
         * 0.71 + 0.5 + 0.87 < 3, so the result is back within 2 LSB. */
        if (bits == 16 && PG_TRIG_TABLE_BITS >= 10)
            PG_EXPECT_LE(dev, 2.0, "round trip of a vector with components below 1: a=%u v=(%d,%d)", a, v.x, v.y);
    }
    print_message("rotations (table %d bits): max | |R| - 1 | = %.3g; rotate+inverse max deviation %.2f LSB "
                  "for |v_i| < 1, %.2f LSB for |v_i| < 1024\n",
                  PG_TRIG_TABLE_BITS, worst_norm, worst_rt_small, worst_rt_1000);
}

/* ---- vectors ------------------------------------------------------------------------------- */

static void check_length(pg_vec2 v)
{
    pg_fix got = pg_v2_length(v);
    pgt_u128 s4 = 4 * ((pgt_u128)((pgt_i128)v.x * v.x) + (pgt_u128)((pgt_i128)v.y * v.y));
    pgt_u128 lo = (pgt_u128)(2 * (pgt_i128)got - 1) * (pgt_u128)(2 * (pgt_i128)got - 1);
    pgt_u128 hi = (pgt_u128)(2 * (pgt_i128)got + 1) * (pgt_u128)(2 * (pgt_i128)got + 1);
    if (got < 0) fail_msg("length(%d, %d) = %d", v.x, v.y, got);
    if (got == PG_FIX_MAX) {
        if (!(got == 0 || lo < s4)) fail_msg("length(%d, %d) saturated too early", v.x, v.y);
        return;
    }
    /* correctly rounded: (2r - 1)^2 < 4 |v|^2 < (2r + 1)^2 (no ties: odd squares) */
    if (!((got == 0 || lo < s4) && s4 < hi)) fail_msg("length(%d, %d) = %d is not correctly rounded", v.x, v.y, got);
}

static void test_length(void **state)
{
    pgt_rng r = pgt_rng_seed(27);
    (void)state;
    PG_EXPECT_EQ(pg_v2_length(pg_v2(0, 0)), 0, "%s", "");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(3 * PG_FIX_ONE, -4 * PG_FIX_ONE)), 5 * PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(-PG_FIX_ONE, 0)), PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(1, 1)), 1, "%s", "sqrt 2 LSB");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(1, 2)), 2, "%s", "sqrt 5 = 2.236 LSB");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(2, 2)), 3, "%s", "sqrt 8 = 2.83 LSB");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(PG_FIX_MAX, 0)), PG_FIX_MAX, "%s", "");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(PG_FIX_MIN, 0)), PG_FIX_MAX, "%s", "");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(PG_FIX_MAX, PG_FIX_MAX)), PG_FIX_MAX, "%s", "saturates");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(PG_FIX_MIN, PG_FIX_MIN)), PG_FIX_MAX, "%s", "saturates");
    PG_EXPECT_EQ(pg_v2_length(pg_v2(PG_FIX_MAX, 1)), PG_FIX_MAX, "%s", "");
    check_length(pg_v2(PG_FIX_MAX, PG_FIX_MAX));
    check_length(pg_v2(1518500250, 1518500250)); /* |v| just below 2^31 - 1 */
    check_length(pg_v2(1518500249, 1518500250));
    for (pg_fix x = -300; x <= 300; ++x)
        for (pg_fix y = -300; y <= 300; ++y) check_length(pg_v2(x, y));
    for (int i = 0; i < 1000000; ++i) check_length(pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)));
}

static void test_normalize(void **state)
{
    pgt_rng r = pgt_rng_seed(28);
    double worst = 0.0;
    pg_vec2 n;
    (void)state;
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2_zero()), pg_v2_zero()));
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(5, 0)), pg_v2(PG_FIX_ONE, 0)));
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(0, PG_FIX_MIN)), pg_v2(0, -PG_FIX_ONE)));
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(PG_FIX_MAX, 0)), pg_v2(PG_FIX_ONE, 0)));
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(1, 1)), pg_v2(46341, 46341)));   /* 46340.95 */
    assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(-1, 1)), pg_v2(-46341, 46341)));
    n = pg_v2_normalize(pg_v2(3 * PG_FIX_ONE, 4 * PG_FIX_ONE));
    assert_true(pg_v2_equal(n, pg_v2(39322, 52429))); /* 39321.6, 52428.8 */
    for (int i = 0; i < 600000; ++i) {
        pg_vec2 v = i % 2 ? pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)) : pg_v2(pgt_fix_bits(&r, 8), pgt_fix_bits(&r, 8));
        double l = hypot(v.x, v.y), ex, ey;
        if (v.x == 0 && v.y == 0) continue;
        n = pg_v2_normalize(v);
        ex = fabs(n.x - v.x / l * LSB);
        ey = fabs(n.y - v.y / l * LSB);
        PG_EXPECT_LE(ex, 1.0, "normalize(%d, %d).x = %d", v.x, v.y, n.x);
        PG_EXPECT_LE(ey, 1.0, "normalize(%d, %d).y = %d", v.x, v.y, n.y);
        if (ex > worst) worst = ex;
        if (ey > worst) worst = ey;
        /* exact symmetries */
        assert_true(pg_v2_equal(pg_v2_normalize(pg_v2_neg(v)), pg_v2_neg(n)));
        assert_true(pg_v2_equal(pg_v2_normalize(pg_v2(v.y, v.x)), pg_v2(n.y, n.x)));
    }
    print_message("normalize: max component error %.4f LSB (documented bound 1)\n", worst);
}

/* ---- dot, cross, 2x2 matrices ----------------------------------------------------------- */

static void test_dot_cross_mul(void **state)
{
    pgt_rng r = pgt_rng_seed(29);
    (void)state;
    PG_EXPECT_EQ(pg_v2_dot(pg_v2(1, 0), pg_v2(PG_FIX_HALF, 0)), 1, "%s", "half an LSB -> away");
    PG_EXPECT_EQ(pg_v2_dot(pg_v2(-1, 0), pg_v2(PG_FIX_HALF, 0)), -1, "%s", "");
    PG_EXPECT_EQ(pg_v2_cross(pg_v2(PG_FIX_ONE, 0), pg_v2(0, PG_FIX_ONE)), PG_FIX_ONE, "%s", "");
    PG_EXPECT_EQ(pg_v2_dot(pg_v2(PG_FIX_MAX, PG_FIX_MAX), pg_v2(PG_FIX_MAX, PG_FIX_MAX)), PG_FIX_MAX, "%s", "saturates");
    PG_EXPECT_EQ(pg_v2_cross(pg_v2(PG_FIX_MAX, PG_FIX_MIN), pg_v2(PG_FIX_MAX, PG_FIX_MAX)), PG_FIX_MAX, "%s", "saturates");
    for (int i = 0; i < 500000; ++i) {
        pg_vec2 a = pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)), b = pg_v2(pgt_fix_any(&r), pgt_fix_any(&r));
        pg_mat22 m = pg_mat22_make(pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)), pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)));
        pg_vec2 mv = pg_mat22_mul(m, a);
        pg_fix d = pg_v2_dot(a, b), c = pg_v2_cross(a, b);
        PG_EXPECT_EQ(d, ref_round_sat((pgt_i128)a.x * b.x + (pgt_i128)a.y * b.y, 16), "i=%d", i);
        PG_EXPECT_EQ(c, ref_round_sat((pgt_i128)a.x * b.y - (pgt_i128)a.y * b.x, 16), "i=%d", i);
        PG_EXPECT_EQ(pg_v2_dot(pg_v2_neg(a), b), -d, "symmetric rounding i=%d", i);
        PG_EXPECT_EQ(pg_v2_cross(b, a), -c, "antisymmetric i=%d", i);
        PG_EXPECT_EQ(mv.x, ref_round_sat((pgt_i128)m.col1.x * a.x + (pgt_i128)m.col2.x * a.y, 16), "i=%d", i);
        PG_EXPECT_EQ(mv.y, ref_round_sat((pgt_i128)m.col1.y * a.x + (pgt_i128)m.col2.y * a.y, 16), "i=%d", i);
    }
}

static void test_mat22_solve(void **state)
{
    pgt_rng r = pgt_rng_seed(30);
    int compared = 0;
    (void)state;
    /* singular matrices give the zero vector */
    assert_true(pg_v2_equal(pg_mat22_solve(pg_mat22_make(pg_v2(0, 0), pg_v2(0, 0)), pg_v2(PG_FIX_ONE, 2)), pg_v2_zero()));
    assert_true(pg_v2_equal(pg_mat22_solve(pg_mat22_make(pg_v2(PG_FIX_ONE, 2 * PG_FIX_ONE),
                                                         pg_v2(2 * PG_FIX_ONE, 4 * PG_FIX_ONE)),
                                           pg_v2(PG_FIX_ONE, PG_FIX_ONE)),
                            pg_v2_zero()));
    /* identity and diagonal */
    {
        pg_mat22 id = pg_mat22_make(pg_v2(PG_FIX_ONE, 0), pg_v2(0, PG_FIX_ONE));
        pg_mat22 two = pg_mat22_make(pg_v2(2 * PG_FIX_ONE, 0), pg_v2(0, -2 * PG_FIX_ONE));
        for (int i = 0; i < 10000; ++i) {
            pg_vec2 b = pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)), x = pg_mat22_solve(two, b);
            assert_true(pg_v2_equal(pg_mat22_solve(id, b), b));
            PG_EXPECT_EQ(x.x, pgt_div_round(b.x, 2), "b.x=%d", b.x);
            PG_EXPECT_EQ(x.y, -pgt_div_round(b.y, 2), "b.y=%d", b.y);
        }
    }
    for (int i = 0; i < 500000; ++i) {
        int full = i % 2;
        pg_mat22 m = full ? pg_mat22_make(pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)), pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)))
                          : pg_mat22_make(pg_v2(pgt_fix_bits(&r, 20), pgt_fix_bits(&r, 20)),
                                          pg_v2(pgt_fix_bits(&r, 20), pgt_fix_bits(&r, 20)));
        pg_vec2 b = full ? pg_v2(pgt_fix_any(&r), pgt_fix_any(&r)) : pg_v2(pgt_fix_bits(&r, 20), pgt_fix_bits(&r, 20));
        pg_vec2 x = pg_mat22_solve(m, b);
        pgt_i128 det = (pgt_i128)m.col1.x * m.col2.y - (pgt_i128)m.col2.x * m.col1.y;
        pgt_i128 nx = (pgt_i128)m.col2.y * b.x - (pgt_i128)m.col2.x * b.y;
        pgt_i128 ny = (pgt_i128)m.col1.x * b.y - (pgt_i128)m.col1.y * b.x;
        if (det == 0) {
            assert_true(pg_v2_equal(x, pg_v2_zero()));
            continue;
        }
        /* Cramer's rule, exactly, rounded once */
        PG_EXPECT_EQ(x.x, pgt_sat(pgt_div_round(nx * 65536, det), NULL), "i=%d", i);
        PG_EXPECT_EQ(x.y, pgt_sat(pgt_div_round(ny * 65536, det), NULL), "i=%d", i);
        /* against a double solve: with 20-bit entries every product and sum is exact in
         * double, so only the final division rounds */
        if (!full) {
            double dd = (double)det, xd = (double)nx / dd * LSB, yd = (double)ny / dd * LSB;
            if (fabs(xd) < PG_FIX_MAX && fabs(yd) < PG_FIX_MAX) {
                PG_EXPECT_LE(fabs(x.x - xd), 0.5 + 1e-6, "i=%d", i);
                PG_EXPECT_LE(fabs(x.y - yd), 0.5 + 1e-6, "i=%d", i);
                ++compared;
            }
        }
    }
    if (compared < 100000) fail_msg("only %d solves were compared with double", compared);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_entries),
        cmocka_unit_test(test_table_error_bound),
        cmocka_unit_test(test_table_symmetries),
        cmocka_unit_test(test_quarter_tables),
        cmocka_unit_test(test_library_tables),
        cmocka_unit_test(test_fix_sin_cos),
        cmocka_unit_test(test_atan2),
        cmocka_unit_test(test_angle_radians),
        cmocka_unit_test(test_rotations),
        cmocka_unit_test(test_length),
        cmocka_unit_test(test_normalize),
        cmocka_unit_test(test_dot_cross_mul),
        cmocka_unit_test(test_mat22_solve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
