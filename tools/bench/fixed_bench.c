/* pogon-fixbench — what do pogon's scalar and trig operations cost, next to double?
 *
 * Usage: pogon-fixbench [--json] [--quick] [--reps N]
 *   default   a markdown table: operation, implementation, table size, ns per operation,
 *             and the largest error measured against double on the benchmark's inputs
 *             (for sine and cosine: over a dense sweep of all angles, so the rows of the
 *             table sizes 8..12 form an accuracy-versus-time table).
 *   --json    one JSON object per line per operation instead.
 *   --quick   tiny iteration counts (a smoke test; timings are meaningless).
 *   --reps N  repetitions per operation (median reported; default 9).
 *
 * Method: each operation runs over arrays of N precomputed pseudo-random inputs (fixed
 * seed) and stores its results in an array; a pass over the arrays is called through a
 * function pointer so the compiler cannot merge passes, and every result array is
 * folded into a volatile sink. A repetition repeats the pass until it lasts about 2 ms;
 * ns/op is the median repetition's time divided by the operations it ran, measured with
 * clock_gettime(CLOCK_MONOTONIC). This is throughput over independent inputs, loop
 * included (see the "loop baseline" row); the compiler may vectorise either side.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PG_TRIG_ALL_TABLES 1
#include "pogon/config.h"
#include "pogon/fixed.h"
#include "trig.h"
#include "trig_table.inc"

#define N 4096
#define PI 3.14159265358979323846
#define TURN 4294967296.0
#define LSB 65536.0
#define Q30 1073741824.0

static pg_fix fa[N], fb[N], fpos[N], frad[N];
static pg_angle ang[N];
static double da[N], db[N], dpos[N], drad[N];
static int32_t out_i[N];
static double out_d[N];
static volatile uint64_t sink;

/* ---- inputs ------------------------------------------------------------------------- */
static uint64_t rng_state = UINT64_C(0x706F676F6E);
static uint64_t rng(void)
{
    uint64_t z = (rng_state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}
static double unit(void) { return (double)(rng() >> 11) * (1.0 / 9007199254740992.0); }

static void make_inputs(void)
{
    for (int i = 0; i < N; ++i) {
        /* operands in [-100, 100] with |b| >= 1/64, so products and quotients are mostly
         * in range: the common case, not the saturation path */
        double a = (unit() * 2.0 - 1.0) * 100.0, b = (unit() * 2.0 - 1.0) * 100.0;
        if (fabs(b) < 1.0 / 64) b = 1.0 / 64;
        fa[i] = (pg_fix)lround(a * LSB);
        fb[i] = (pg_fix)lround(b * LSB);
        fpos[i] = (pg_fix)(rng() >> 33);                       /* [0, 32768) */
        ang[i] = (pg_angle)rng();
        frad[i] = pg_angle_to_radians(ang[i]);                  /* [-pi, pi] */
        da[i] = fa[i] / LSB;
        db[i] = fb[i] / LSB;
        dpos[i] = fpos[i] / LSB;
        drad[i] = frad[i] / LSB;
    }
}

/* ---- the operations, one pass each -------------------------------------------------- */
static void run_baseline(void) { for (int i = 0; i < N; ++i) out_i[i] = fa[i] ^ fb[i]; }
static void run_mul(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_mul(fa[i], fb[i]); }
static void run_div(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_div(fa[i], fb[i]); }
static void run_sqrt(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_sqrt(fpos[i]); }
static void run_atan2(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_atan2(fa[i], fb[i]); }
static void run_lib_sin(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_sin(frad[i]); }
static void run_lib_cos(void) { for (int i = 0; i < N; ++i) out_i[i] = pg_fix_cos(frad[i]); }

#define TABLE_RUNS(bits)                                                                      \
    static void run_sin_##bits(void)                                                         \
    {                                                                                        \
        for (int i = 0; i < N; ++i) out_i[i] = pg__table_sin_q30(pg_sin_table_##bits, bits, ang[i]); \
    }                                                                                        \
    static void run_cos_##bits(void)                                                         \
    {                                                                                        \
        for (int i = 0; i < N; ++i)                                                          \
            out_i[i] = pg__table_sin_q30(pg_sin_table_##bits, bits, ang[i] + PG_ANGLE_QUARTER); \
    }
TABLE_RUNS(8)
TABLE_RUNS(9)
TABLE_RUNS(10)
TABLE_RUNS(11)
TABLE_RUNS(12)

static void run_dbaseline(void) { for (int i = 0; i < N; ++i) out_d[i] = da[i] + db[i]; }
static void run_dmul(void) { for (int i = 0; i < N; ++i) out_d[i] = da[i] * db[i]; }
static void run_ddiv(void) { for (int i = 0; i < N; ++i) out_d[i] = da[i] / db[i]; }
static void run_dsqrt(void) { for (int i = 0; i < N; ++i) out_d[i] = sqrt(dpos[i]); }
static void run_dsin(void) { for (int i = 0; i < N; ++i) out_d[i] = sin(drad[i]); }
static void run_dcos(void) { for (int i = 0; i < N; ++i) out_d[i] = cos(drad[i]); }
static void run_datan2(void) { for (int i = 0; i < N; ++i) out_d[i] = atan2(da[i], db[i]); }

/* ---- errors against double, in real units ------------------------------------------- */
static double err_mul(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) w = fmax(w, fabs(pg_fix_mul(fa[i], fb[i]) / LSB - da[i] * db[i]));
    return w;
}
static double err_div(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) {
        double q = da[i] / db[i];
        if (fabs(q) < 32767.0) w = fmax(w, fabs(pg_fix_div(fa[i], fb[i]) / LSB - q));
    }
    return w;
}
static double err_sqrt(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) w = fmax(w, fabs(pg_fix_sqrt(fpos[i]) / LSB - sqrt(dpos[i])));
    return w;
}
static double err_atan2(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) {
        double d = fabs(pg_fix_atan2(fa[i], fb[i]) / LSB - atan2(da[i], db[i]));
        if (d > PI) d = fabs(d - 2 * PI);
        w = fmax(w, d);
    }
    return w;
}
static double err_lib_sin(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) w = fmax(w, fabs(pg_fix_sin(frad[i]) / LSB - sin(drad[i])));
    return w;
}
static double err_lib_cos(void)
{
    double w = 0;
    for (int i = 0; i < N; ++i) w = fmax(w, fabs(pg_fix_cos(frad[i]) / LSB - cos(drad[i])));
    return w;
}

static int quick;

/* Max |sin - table sin| and |cos - table cos| over every node, interval midpoint and
 * quarter point, plus (unless --quick) a stride-4093 sweep of all 2^32 angles. */
static double table_error(const int32_t *tab, int bits)
{
    int k = 32 - bits;
    double w = 0;
    for (uint32_t i = 0; i < (1u << bits); ++i) {
        for (uint32_t f = 0; f < 4; ++f) {
            pg_angle a = (i << k) + (f << (k - 2));
            double x = a * (2 * PI / TURN);
            w = fmax(w, fabs(pg__table_sin_q30(tab, bits, a) / Q30 - sin(x)));
            w = fmax(w, fabs(pg__table_sin_q30(tab, bits, a + PG_ANGLE_QUARTER) / Q30 - cos(x)));
        }
    }
    if (!quick) {
        for (uint64_t a64 = 12345; a64 < (UINT64_C(1) << 32); a64 += 4093) {
            pg_angle a = (pg_angle)a64;
            double x = a * (2 * PI / TURN);
            w = fmax(w, fabs(pg__table_sin_q30(tab, bits, a) / Q30 - sin(x)));
            w = fmax(w, fabs(pg__table_sin_q30(tab, bits, a + PG_ANGLE_QUARTER) / Q30 - cos(x)));
        }
    }
    return w;
}

/* ---- timing ------------------------------------------------------------------------- */
static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static void fold_outputs(void)
{
    uint64_t h = sink;
    for (int i = 0; i < N; ++i) {
        uint64_t bits;
        memcpy(&bits, &out_d[i], sizeof bits);
        h = (h ^ (uint32_t)out_i[i] ^ bits) * UINT64_C(0x100000001B3);
    }
    sink = h;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Median ns per operation of `reps` repetitions. */
static double time_op(void (*volatile run)(void), int reps)
{
    double t[64], t0, one;
    long passes = 1, p;
    run(); /* warm the caches and the branch predictors */
    t0 = now_ns();
    run();
    one = now_ns() - t0;
    if (!quick && one > 0) passes = (long)(2e6 / one) + 1; /* about 2 ms per repetition */
    for (int r = 0; r < reps; ++r) {
        t0 = now_ns();
        for (p = 0; p < passes; ++p) run();
        t[r] = (now_ns() - t0) / ((double)passes * N);
        fold_outputs();
    }
    qsort(t, (size_t)reps, sizeof t[0], cmp_double);
    return t[reps / 2];
}

/* ---- the table of operations -------------------------------------------------------- */
typedef struct {
    const char *op, *impl;
    int bits;             /* table size, 0 when not a table operation */
    void (*run)(void);
    double (*err)(void);  /* NULL: the double reference itself */
    const int32_t *table; /* sine table whose sweep error to report */
} bench;

static const bench benches[] = {
    {"loop baseline (a^b)", "int32", 0, run_baseline, NULL, NULL},
    {"loop baseline (a+b)", "double", 0, run_dbaseline, NULL, NULL},
    {"mul", "pg_fix_mul", 0, run_mul, err_mul, NULL},
    {"mul", "double a*b", 0, run_dmul, NULL, NULL},
    {"div", "pg_fix_div", 0, run_div, err_div, NULL},
    {"div", "double a/b", 0, run_ddiv, NULL, NULL},
    {"sqrt", "pg_fix_sqrt", 0, run_sqrt, err_sqrt, NULL},
    {"sqrt", "double sqrt", 0, run_dsqrt, NULL, NULL},
    {"sin", "table Q2.30", 8, run_sin_8, NULL, pg_sin_table_8},
    {"sin", "table Q2.30", 9, run_sin_9, NULL, pg_sin_table_9},
    {"sin", "table Q2.30", 10, run_sin_10, NULL, pg_sin_table_10},
    {"sin", "table Q2.30", 11, run_sin_11, NULL, pg_sin_table_11},
    {"sin", "table Q2.30", 12, run_sin_12, NULL, pg_sin_table_12},
    {"sin", "pg_fix_sin (radians)", PG_TRIG_TABLE_BITS, run_lib_sin, err_lib_sin, NULL},
    {"sin", "double sin", 0, run_dsin, NULL, NULL},
    {"cos", "table Q2.30", 8, run_cos_8, NULL, pg_sin_table_8},
    {"cos", "table Q2.30", 9, run_cos_9, NULL, pg_sin_table_9},
    {"cos", "table Q2.30", 10, run_cos_10, NULL, pg_sin_table_10},
    {"cos", "table Q2.30", 11, run_cos_11, NULL, pg_sin_table_11},
    {"cos", "table Q2.30", 12, run_cos_12, NULL, pg_sin_table_12},
    {"cos", "pg_fix_cos (radians)", PG_TRIG_TABLE_BITS, run_lib_cos, err_lib_cos, NULL},
    {"cos", "double cos", 0, run_dcos, NULL, NULL},
    {"atan2", "pg_fix_atan2 (CORDIC)", 0, run_atan2, err_atan2, NULL},
    {"atan2", "double atan2", 0, run_datan2, NULL, NULL},
};
#define NBENCH (sizeof benches / sizeof benches[0])

static void usage(FILE *f)
{
    fprintf(f, "usage: pogon-fixbench [--json] [--quick] [--reps N]\n"
               "  ns per operation of pogon's Q16.16 scalar and trig operations next to double,\n"
               "  and their largest error measured against double.\n");
}

int main(int argc, char **argv)
{
    int json = 0, reps = 9;
    double table_err[13] = {0};
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--json") == 0) json = 1;
        else if (strcmp(argv[i], "--quick") == 0) quick = 1;
        else if (strcmp(argv[i], "--reps") == 0 && i + 1 < argc) {
            reps = atoi(argv[++i]);
            if (reps < 1 || reps > 64) { fprintf(stderr, "pogon-fixbench: --reps must be 1..64\n"); return 2; }
        } else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "pogon-fixbench: unknown argument '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }
    if (quick && reps > 3) reps = 3;
    make_inputs();
    table_err[8] = table_error(pg_sin_table_8, 8);
    table_err[9] = table_error(pg_sin_table_9, 9);
    table_err[10] = table_error(pg_sin_table_10, 10);
    table_err[11] = table_error(pg_sin_table_11, 11);
    table_err[12] = table_error(pg_sin_table_12, 12);

    if (!json) {
        printf("pogon-fixbench: %d inputs per pass, median of %d repetitions%s; library table size %d bits\n\n", N, reps,
               quick ? " (--quick: timings meaningless)" : "", PG_TRIG_TABLE_BITS);
        printf("| operation | implementation | table bits | ns/op | max abs error vs double |\n");
        printf("|---|---|---:|---:|---:|\n");
    }
    for (size_t i = 0; i < NBENCH; ++i) {
        const bench *b = &benches[i];
        double ns = time_op(b->run, reps);
        double err = b->table ? table_err[b->bits] : b->err ? b->err() : -1.0;
        if (json) {
            printf("{\"op\":\"%s\",\"impl\":\"%s\",", b->op, b->impl);
            if (b->bits) printf("\"table_bits\":%d,", b->bits);
            else printf("\"table_bits\":null,");
            printf("\"ns_per_op\":%.4f,", ns);
            if (err >= 0) printf("\"max_abs_error\":%.6e,", err);
            else printf("\"max_abs_error\":null,");
            printf("\"inputs\":%d,\"reps\":%d,\"quick\":%s}\n", N, reps, quick ? "true" : "false");
        } else {
            char bits[8] = "", errs[48] = "reference";
            if (b->bits) snprintf(bits, sizeof bits, "%d", b->bits);
            if (err >= 0) snprintf(errs, sizeof errs, "%.3e (%.3f LSB)", err, err * LSB);
            else if (strstr(b->op, "baseline")) snprintf(errs, sizeof errs, "-");
            printf("| %s | %s | %s | %.2f | %s |\n", b->op, b->impl, bits, ns, errs);
        }
    }
    if (!json) {
        printf("\nErrors: mul/div/sqrt/atan2/pg_fix_sin/cos over the benchmark inputs; table rows over every node,\n"
               "midpoint and quarter point%s. LSB = 2^-16. Sink: %llu\n",
               quick ? "" : " and a stride-4093 sweep of all 2^32 angles", (unsigned long long)(sink & 0xFFFF));
    }
    return 0;
}
