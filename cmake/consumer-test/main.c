/* A user of pogon: checks a few exact results through the public API. */
#ifndef PG_TRIG_TABLE_BITS
#error "PG_TRIG_TABLE_BITS should come from the package (pogon::pogon or pkg-config)"
#endif
#include <pogon/fixed.h>
#include <stdio.h>
#include <string.h>

static int failures;

static void expect_fix(const char *what, pg_fix got, pg_fix want)
{
    char g[PG_FIX_FORMAT_MAX], w[PG_FIX_FORMAT_MAX];
    pg_fix_format(got, g, sizeof g);
    pg_fix_format(want, w, sizeof w);
    printf("%-22s %s%s\n", what, g, got == want ? "" : " MISMATCH");
    if (got != want) {
        printf("  expected %s (raw %ld, got raw %ld)\n", w, (long)want, (long)got);
        failures++;
    }
}

int main(void)
{
    char buf[PG_FIX_FORMAT_MAX];
    pg_fix x = 0;

    /* pg_fix_mul is inline (header only); the rest live in the library. */
    expect_fix("3 * 0.5", pg_fix_mul(PG_FIX_C(3), PG_FIX_HALF), 98304);   /* 1.5 */
    expect_fix("sqrt(2)", pg_fix_sqrt(PG_FIX_C(2)), 92682);               /* round(1.41421356 * 65536) */
    expect_fix("1 / 3", pg_fix_div(PG_FIX_ONE, PG_FIX_C(3)), 21845);
    if (pg_fix_parse("-12.375", 7, &x) != PG_FIX_OK) failures++;
    expect_fix("parse -12.375", x, -811008);
    pg_fix_format(pg_fix_mul(PG_FIX_C(3), PG_FIX_HALF), buf, sizeof buf);
    if (strcmp(buf, "1.5") != 0) {
        printf("format gave '%s', expected '1.5'\n", buf);
        failures++;
    }
    printf("PG_TRIG_TABLE_BITS=%d\n", PG_TRIG_TABLE_BITS);
    printf("consumer: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
