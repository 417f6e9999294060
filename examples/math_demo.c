/* math_demo — pogon's fixed-point math without a world.
 *
 * Parses decimal text, multiplies, divides, takes square roots, sines and cosines of
 * binary angles, atan2, rotates and normalises vectors, and prints every result as
 * exact decimal text with pg_fix_format. There is no float or double anywhere in this
 * program (on x86-64 it is even compiled with -mgeneral-regs-only): the library needs
 * none, neither to compute nor to read or print numbers.
 *
 * Results whose exact value the API promises (correct rounding) are checked; the
 * program prints "MISMATCH" and exits 1 if one differs, and ends with
 * "math_demo: all N checks passed" otherwise. CTest runs it as the test math_demo.
 */
#include <pogon/fixed.h>
#include <stdio.h>
#include <string.h>

static int checks, failures;

/* Format into one of a few rotating buffers, so several values fit in one printf. */
static const char *fx(pg_fix a)
{
    static char bufs[8][PG_FIX_FORMAT_MAX];
    static unsigned next;
    char *b = bufs[next++ % 8u];
    pg_fix_format(a, b, PG_FIX_FORMAT_MAX);
    return b;
}

/* The exact value of a Q16.16 number: k / 2^16 = k * 5^16 / 10^16, so 16 fraction
 * digits always suffice. pg_fix_format gives the shortest text that reads back to the
 * same value; this shows every digit. */
static const char *exact(pg_fix a)
{
    static char bufs[4][32];
    static unsigned next;
    char *b = bufs[next++ % 4u];
    uint32_t mag = a < 0 ? (uint32_t)0 - (uint32_t)a : (uint32_t)a;
    uint64_t frac = (uint64_t)(mag & 0xFFFFu) * UINT64_C(152587890625); /* 5^16 */
    int len = snprintf(b, 32, "%s%lu.%016llu", a < 0 ? "-" : "", (unsigned long)(mag >> 16),
                       (unsigned long long)frac);
    while (len > 2 && b[len - 1] == '0' && b[len - 2] != '.') b[--len] = '\0';
    return b;
}

static pg_fix parse(const char *text)
{
    pg_fix v = 0;
    pg_fix_status st = pg_fix_parse(text, strlen(text), &v);
    if (st != PG_FIX_OK) {
        printf("cannot parse \"%s\": %s\n", text, pg_fix_status_message(st));
        failures++;
    }
    return v;
}

/* Compare with the exactly expected raw value; a mismatch is reported on the line. */
static const char *check(pg_fix got, pg_fix want)
{
    checks++;
    if (got == want) return "";
    failures++;
    return "  MISMATCH";
}

/* Within `tol` LSB of the expected value (for table-based trigonometry). */
static const char *check_near(pg_fix got, pg_fix want, pg_fix tol)
{
    checks++;
    if (got >= want - tol && got <= want + tol) return "";
    failures++;
    return "  MISMATCH";
}

/* Tolerance in LSB for a table-based sine, cosine or rotation of a value of magnitude
 * up to `mag`: linear interpolation errs by up to (2 pi / 2^bits)^2 / 8 (config.h),
 * which is 323413 / 4^bits LSB per unit, plus one LSB of rounding. */
static pg_fix trig_tol(int32_t mag)
{
    int64_t per_unit_scaled = INT64_C(323413) * mag;
    int64_t denom = (int64_t)1 << (2 * PG_TRIG_TABLE_BITS);
    return (pg_fix)((per_unit_scaled + denom - 1) / denom + 1);
}

/* Whole degrees to a binary angle (a full turn is 2^32), rounded to nearest. */
static pg_angle angle_from_degrees(int32_t deg)
{
    int64_t d = deg % 360;
    if (d < 0) d += 360;
    return (pg_angle)((((uint64_t)d << 32) + 180u) / 360u);
}

/* A binary angle to degrees in [-180, 180), Q16.16, rounded. */
static pg_fix degrees_from_angle(pg_angle a)
{
    int64_t s = a >= PG_ANGLE_HALF ? (int64_t)a - INT64_C(4294967296) : (int64_t)a;
    return pg_fix_from_ratio(s * 360, INT64_C(4294967296));
}

int main(void)
{
    static const char *texts[] = {"3.14159", "0.1", "-2.5", "0.000007", "32767.99998"};
    static const pg_fix raws[] = {205887, 6554, -163840, 0, 2147483647};
    pg_fix a, b, r;
    pg_fix_status st;
    size_t i;

    printf("pogon math demo: Q16.16 fixed point, integer arithmetic only\n");

    printf("\nparse and format (raw = value * 65536, rounded to nearest)\n");
    for (i = 0; i < sizeof texts / sizeof texts[0]; ++i) {
        a = parse(texts[i]);
        printf("  %-13s -> %-11s raw %-10ld exactly %s%s\n", texts[i], fx(a), (long)a, exact(a),
               check(a, raws[i]));
    }

    printf("\narithmetic (round to nearest, ties away from zero, symmetric in sign)\n");
    a = parse("1.5");
    b = parse("2.25");
    r = pg_fix_mul(a, b);
    printf("  %s * %s = %s%s\n", fx(a), fx(b), fx(r), check(r, parse("3.375")));
    r = pg_fix_mul(pg_fix_neg(a), b);
    printf("  %s * %s = %s%s\n", fx(pg_fix_neg(a)), fx(b), fx(r), check(r, parse("-3.375")));
    r = pg_fix_div(PG_FIX_ONE, PG_FIX_C(3));
    printf("  1 / 3 = %s (exactly %s)%s\n", fx(r), exact(r), check(r, 21845));
    r = pg_fix_div(PG_FIX_C(-1), PG_FIX_C(3));
    printf("  -1 / 3 = %s%s\n", fx(r), check(r, -21845));
    r = pg_fix_div(PG_FIX_C(2), PG_FIX_C(3));
    printf("  2 / 3 = %s%s\n", fx(r), check(r, 43691));
    st = pg_fix_mul_checked(PG_FIX_C(30000), PG_FIX_C(2), &r);
    printf("  30000 * 2 = %s (%s)%s\n", fx(r), pg_fix_status_message(st), check(r, PG_FIX_MAX));
    st = pg_fix_div_checked(PG_FIX_C(-10), 0, &r);
    printf("  -10 / 0 = %s (%s)%s\n", fx(r), pg_fix_status_message(st), check(r, PG_FIX_MIN));
    r = pg_fix_sqrt(PG_FIX_C(2));
    printf("  sqrt(2) = %s (exactly %s; sqrt(2) = 1.41421356...)%s\n", fx(r), exact(r), check(r, 92682));
    r = pg_fix_sqrt(parse("0.25"));
    printf("  sqrt(0.25) = %s%s\n", fx(r), check(r, PG_FIX_HALF));
    r = pg_fix_sqrt(PG_FIX_C(10000));
    printf("  sqrt(10000) = %s%s\n", fx(r), check(r, PG_FIX_C(100)));

    printf("\nangles and trigonometry (binary angles, sine table of 2^%d entries)\n", PG_TRIG_TABLE_BITS);
    r = pg_fix_sin(pg_fix_div(PG_FIX_PI, PG_FIX_C(6)));
    printf("  sin(pi/6) = %s%s\n", fx(r), check_near(r, PG_FIX_HALF, trig_tol(1)));
    r = (pg_fix)pg__round_shift64(pg_angle_cos_q30(angle_from_degrees(60)), 14);
    printf("  cos(60 deg) = %s%s\n", fx(r), check_near(r, PG_FIX_HALF, trig_tol(1)));
    r = (pg_fix)pg__round_shift64(pg_angle_sin_q30(PG_ANGLE_QUARTER), 14);
    printf("  sin(90 deg) = %s%s\n", fx(r), check(r, PG_FIX_ONE));
    r = pg_fix_cos(PG_FIX_PI);
    printf("  cos(pi) = %s%s\n", fx(r), check(r, -PG_FIX_ONE));
    r = pg_fix_atan2(PG_FIX_ONE, PG_FIX_ONE);
    printf("  atan2(1, 1) = %s rad = %s deg%s\n", fx(r),
           fx(degrees_from_angle(pg_angle_atan2(PG_FIX_ONE, PG_FIX_ONE))), check_near(r, 51472, 1));
    r = degrees_from_angle(pg_angle_atan2(PG_FIX_C(-1), PG_FIX_C(-1)));
    printf("  atan2(-1, -1) = %s deg%s\n", fx(r), check_near(r, PG_FIX_C(-135), 2));
    r = pg_fix_wrap_angle(PG_FIX_C(7));
    printf("  wrap(7 rad) = %s rad (7 - 2 pi)%s\n", fx(r), check_near(r, 46977, 1));

    printf("\nvectors and rotations (rotations hold cos and sin in Q2.30)\n");
    {
        pg_vec2 v = pg_v2(PG_FIX_C(3), PG_FIX_C(4)), u, w;
        pg_rot q = pg_rot_from_angle(PG_ANGLE_QUARTER);
        w = pg_rot_apply(q, pg_v2(PG_FIX_ONE, 0));
        printf("  rotate (1, 0) by 90 deg = (%s, %s)%s%s\n", fx(w.x), fx(w.y),
               check(w.x, 0), check(w.y, PG_FIX_ONE));
        q = pg_rot_from_angle(angle_from_degrees(30));
        w = pg_rot_apply(q, v);
        printf("  rotate (3, 4) by 30 deg = (%s, %s), length %s%s\n", fx(w.x), fx(w.y),
               fx(pg_v2_length(w)), check_near(pg_v2_length(w), PG_FIX_C(5), trig_tol(5)));
        u = pg_rot_apply_inv(q, w);
        printf("  and back = (%s, %s)%s%s\n", fx(u.x), fx(u.y),
               check_near(u.x, v.x, 2 * trig_tol(5)), check_near(u.y, v.y, 2 * trig_tol(5)));
        r = pg_v2_length(v);
        printf("  length (3, 4) = %s%s\n", fx(r), check(r, PG_FIX_C(5)));
        u = pg_v2_normalize(v);
        printf("  normalize (3, 4) = (%s, %s)%s%s\n", fx(u.x), fx(u.y),
               check_near(u.x, parse("0.6"), 1), check_near(u.y, parse("0.8"), 1));
        r = pg_v2_dot(v, pg_v2(PG_FIX_C(-4), PG_FIX_C(3)));
        printf("  dot((3, 4), (-4, 3)) = %s%s\n", fx(r), check(r, 0));
        r = pg_v2_cross(v, pg_v2(PG_FIX_C(-4), PG_FIX_C(3)));
        printf("  cross((3, 4), (-4, 3)) = %s%s\n", fx(r), check(r, PG_FIX_C(25)));
    }

    printf("\n");
    if (failures) {
        printf("math_demo: %d of %d checks FAILED\n", failures, checks);
        return 1;
    }
    printf("math_demo: all %d checks passed\n", checks);
    return 0;
}
