/* hard_results.h — the hard-case suite's figures, written to a results file.
 *
 * Every figure a stability test checks against a bound goes through hard_figure(): with
 * POGON_HARD_RESULTS=FILE in the environment it is appended to FILE as one line of
 * tab-separated values
 *     program  function  figure  value  bound
 * (function: the C function that checked it, the test itself or its helper; figure: what
 * was measured, its unit in parentheses at the end when it has one; value and bound with
 * 9 significant digits). Without the variable nothing is written. The library is
 * deterministic, so a run writes the same lines on every machine (but for the order of
 * the programs). scripts/hard-case-figures.sh runs the suite with it and commits the
 * lines to docs/results/hard_cases.tsv, which tools/docs/hard_cases_table.js renders
 * into docs/hard-cases.md (docs/generated.md).
 *
 * A file includes this after pg_test.h, with HARD_PROGRAM defined as its program's name.
 * PG_EXPECT_LE is redefined here to record its figure, named by its message. */
#ifndef POGON_TEST_HARD_RESULTS_H
#define POGON_TEST_HARD_RESULTS_H

#include <stdio.h>
#include <math.h>
#include <stdlib.h>

#ifndef HARD_PROGRAM
#error "define HARD_PROGRAM (the test program's name) before including hard_results.h"
#endif

/* The bound of a figure that is printed, not asserted (written as "-"). */
#define HARD_NOT_ASSERTED ((double)NAN)

/* Append one figure to $POGON_HARD_RESULTS (tabs and line breaks in the text become spaces). */
static void hard_figure(const char *function, const char *figure, double value, double bound)
{
    const char *path = getenv("POGON_HARD_RESULTS");
    FILE *f;
    const char *p;
    if (path == NULL || path[0] == '\0') return;
    f = fopen(path, "a");
    if (f == NULL) {
        print_error("hard_results: cannot append to %s\n", path);
        fail();
        return;
    }
    fprintf(f, "%s\t%s\t", HARD_PROGRAM, function);
    for (p = figure; *p != '\0'; ++p) fputc(*p == '\t' || *p == '\n' ? ' ' : *p, f);
    if (bound == bound) fprintf(f, "\t%.9g\t%.9g\n", value, bound);
    else fprintf(f, "\t%.9g\t-\n", value); /* HARD_NOT_ASSERTED: NaN */
    fclose(f);
}

/* PG_EXPECT_LE (pg_test.h) that also records its figure, named by its message. */
#undef PG_EXPECT_LE
#define PG_EXPECT_LE(got, bound, fmt, ...)                                                  \
    do {                                                                                   \
        double pgt_g_ = (double)(got), pgt_b_ = (double)(bound);                           \
        char pgt_what_[256];                                                               \
        snprintf(pgt_what_, sizeof pgt_what_, fmt, __VA_ARGS__);                           \
        hard_figure(__func__, pgt_what_, pgt_g_, pgt_b_);                                  \
        if (!(pgt_g_ <= pgt_b_)) {                                                         \
            print_error("%s == %.9g, exceeds the bound %.9g (%s); " fmt "\n", #got, pgt_g_, \
                        pgt_b_, #bound, __VA_ARGS__);                                      \
            fail();                                                                        \
        }                                                                                  \
    } while (0)

#endif
