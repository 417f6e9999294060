/* test_broadphase.c — the grid broadphase against a brute-force O(n^2) reference. */
#include <stdlib.h>

#include "pg_test.h"
#include "broadphase.h"

/* ---- reference and harness ---------------------------------------------------------- */

static int overlap(const pg_aabb *a, const pg_aabb *b)
{
    return a->lo.x <= b->hi.x && b->lo.x <= a->hi.x && a->lo.y <= b->hi.y && b->lo.y <= a->hi.y;
}

/* All pairs (i < j, at least one active, closed overlap) in (a, b) order. Returns the
 * number of pairs; writes at most cap of them. */
static size_t brute(const pg_aabb *boxes, const uint8_t *flags, uint32_t n, pg_pair *out, size_t cap)
{
    size_t k = 0;
    uint32_t i, j;
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j) {
            if (!((flags[i] | flags[j]) & PG_PROXY_ACTIVE)) continue;
            if (!overlap(&boxes[i], &boxes[j])) continue;
            if (k < cap) {
                out[k].a = i;
                out[k].b = j;
            }
            ++k;
        }
    return k;
}

/* Runs the broadphase with exactly the documented amount of scratch, filled with a
 * pattern that depends on `garbage` (the result must not depend on it). */
static int run(const pg_aabb *boxes, const uint8_t *flags, uint32_t n, pg_pair *pairs, uint32_t cap,
               uint32_t *count, unsigned garbage)
{
    size_t bytes = pg_broadphase_scratch_bytes(n, cap);
    uint64_t *scratch = malloc(bytes + 8);
    int rc;
    assert_non_null(scratch);
    memset(scratch, (int)(garbage * 0x5bu + 0x11u) & 0xff, bytes + 8);
    rc = pg_broadphase_pairs(boxes, flags, n, pairs, cap, count, scratch, bytes);
    free(scratch);
    return rc;
}

/* The broadphase must give exactly the reference list (same order). Runs it twice with
 * different scratch contents; checks the too-small-scratch error on the way. */
static void check_scene(const pg_aabb *boxes, const uint8_t *flags, uint32_t n, const char *what,
                        unsigned long long seed)
{
    size_t cap = 1u << 16, want;
    pg_pair *ref = malloc(cap * sizeof *ref);
    pg_pair *got = malloc(cap * sizeof *got);
    uint32_t count = 12345, k;
    int rc, pass;
    assert_non_null(ref);
    assert_non_null(got);
    want = brute(boxes, flags, n, ref, cap);
    while (want > cap) {
        cap = want;
        free(ref);
        free(got);
        ref = malloc(cap * sizeof *ref);
        got = malloc(cap * sizeof *got);
        assert_non_null(ref);
        assert_non_null(got);
        want = brute(boxes, flags, n, ref, cap);
    }
    for (pass = 0; pass < 2; ++pass) {
        rc = run(boxes, flags, n, got, (uint32_t)cap, &count, (unsigned)pass * 7u + 3u);
        PG_EXPECT_EQ(rc, 0, "%s seed %llu pass %d", what, seed, pass);
        PG_EXPECT_EQ(count, want, "%s seed %llu pass %d", what, seed, pass);
        for (k = 0; k < count; ++k) {
            if (got[k].a != ref[k].a || got[k].b != ref[k].b) {
                print_error("%s seed %llu: pair %u is (%u, %u), want (%u, %u)\n", what, seed, k,
                            got[k].a, got[k].b, ref[k].a, ref[k].b);
                fail();
            }
        }
    }
    if (n > 0) {
        /* one byte short of the documented size: refused, nothing reported */
        size_t bytes = pg_broadphase_scratch_bytes(n, (uint32_t)cap);
        uint64_t *scratch = malloc(bytes);
        assert_non_null(scratch);
        count = 777;
        rc = pg_broadphase_pairs(boxes, flags, n, got, (uint32_t)cap, &count, scratch, bytes - 1);
        PG_EXPECT_EQ(rc, -2, "%s seed %llu", what, seed);
        PG_EXPECT_EQ(count, 0, "%s seed %llu", what, seed);
        free(scratch);
    }
    free(ref);
    free(got);
}

/* ---- scene generators ----------------------------------------------------------------- */

static pg_fix clampfix(double v)
{
    double m = (double)PG_FIX_MAX;
    if (v > m) v = m;
    if (v < -m) v = -m;
    return (pg_fix)(v < 0 ? v - 0.5 : v + 0.5);
}

static pg_aabb box_m(double cx, double cy, double hw, double hh)
{
    pg_aabb b;
    b.lo.x = clampfix((cx - hw) * 65536.0);
    b.lo.y = clampfix((cy - hh) * 65536.0);
    b.hi.x = clampfix((cx + hw) * 65536.0);
    b.hi.y = clampfix((cy + hh) * 65536.0);
    return b;
}

static double snap(double v, double q) { return q > 0 ? q * (double)(long long)(v / q) : v; }

/* 1000 proxies (or n) of mixed sizes, negative coordinates, some active. */
static void random_scene(pgt_rng *r, pg_aabb *boxes, uint8_t *flags, uint32_t n)
{
    static const double world[] = {3.0, 20.0, 60.0, 400.0, 30000.0};
    static const double active_frac[] = {0.01, 0.2, 0.5, 0.8, 1.0};
    static const double quantum[] = {0.0, 0.0, 0.25, 1.0, 1.0 / 16.0};
    double w = world[pgt_below(r, 5)];
    double af = active_frac[pgt_below(r, 5)];
    double q = quantum[pgt_below(r, 5)];
    double ox = (pgt_unit(r) - 0.7) * 2.0 * w, oy = (pgt_unit(r) - 0.7) * 2.0 * w; /* mostly negative */
    uint32_t i;
    for (i = 0; i < n; ++i) {
        double cx = ox + (pgt_unit(r) * 2.0 - 1.0) * w, cy = oy + (pgt_unit(r) * 2.0 - 1.0) * w;
        double u = pgt_unit(r), hw, hh;
        if (u < 0.80) { /* small bodies */
            hw = 0.02 + pgt_unit(r) * 0.5;
            hh = hw * (0.5 + pgt_unit(r));
        } else if (u < 0.93) { /* medium */
            hw = 0.5 + pgt_unit(r) * 4.0;
            hh = 0.5 + pgt_unit(r) * 4.0;
        } else if (u < 0.97) { /* points and slivers */
            hw = pgt_below(r, 2) ? 0.0 : pgt_unit(r) * 3.0;
            hh = pgt_below(r, 2) ? 0.0 : pgt_unit(r) * 0.01;
        } else if (u < 0.995) { /* walls */
            hw = pgt_below(r, 2) ? 50.0 + pgt_unit(r) * 200.0 : 0.1;
            hh = hw > 1.0 ? 0.2 : 50.0 + pgt_unit(r) * 200.0;
        } else { /* huge: up to the whole range */
            hw = pgt_unit(r) * 40000.0;
            hh = pgt_unit(r) * 40000.0;
        }
        if (q > 0) {
            cx = snap(cx, q);
            cy = snap(cy, q);
            hw = snap(hw, q / 2);
            hh = snap(hh, q / 2);
        }
        boxes[i] = box_m(cx, cy, hw, hh);
        flags[i] = (uint8_t)(pgt_unit(r) < af ? PG_PROXY_ACTIVE : 0u);
        if (pgt_below(r, 16) == 0) flags[i] |= 0x80u; /* other flag bits are ignored */
    }
}

/* ---- tests -------------------------------------------------------------------------- */

static void test_random_scenes_match_reference(void **state)
{
    enum { N = 1000 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    unsigned long long seed;
    (void)state;
    for (seed = 1; seed <= 150; ++seed) {
        pgt_rng r = pgt_rng_seed(seed * 0x9E37u + 5u);
        uint32_t n = seed % 10 == 0 ? (uint32_t)pgt_below(&r, 40) : N;
        random_scene(&r, boxes, flags, n);
        check_scene(boxes, flags, n, "random", seed);
    }
}

static void test_touching_boxes_count(void **state)
{
    /* a 20 x 20 grid of 1 m boxes sharing edges and corners, lo on cell boundaries */
    enum { G = 20, N = G * G + 4 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    pg_pair *pairs;
    uint32_t count, i, j, n = 0;
    int rc;
    (void)state;
    for (j = 0; j < G; ++j)
        for (i = 0; i < G; ++i) {
            boxes[n].lo = pg_v2(PG_FIX_C((int32_t)i - 10), PG_FIX_C((int32_t)j - 10));
            boxes[n].hi = pg_v2(PG_FIX_C((int32_t)i - 9), PG_FIX_C((int32_t)j - 9));
            flags[n++] = PG_PROXY_ACTIVE;
        }
    pairs = malloc(sizeof *pairs * 4096);
    assert_non_null(pairs);
    rc = run(boxes, flags, n, pairs, 4096, &count, 1);
    PG_EXPECT_EQ(rc, 0, "%s", "grid");
    /* 8-neighbourhood: horizontal + vertical + 2 diagonals */
    PG_EXPECT_EQ(count, 2 * G * (G - 1) + 2 * (G - 1) * (G - 1), "%s", "grid");
    check_scene(boxes, flags, n, "grid", 0);

    /* single touching contacts: edge, corner, a point on an edge, one LSB apart */
    n = 0;
    boxes[n].lo = pg_v2(-PG_FIX_C(2), -PG_FIX_C(2));
    boxes[n].hi = pg_v2(0, 0);
    flags[n++] = PG_PROXY_ACTIVE;
    boxes[n].lo = pg_v2(0, 0); /* corner touch */
    boxes[n].hi = pg_v2(PG_FIX_C(1), PG_FIX_C(1));
    flags[n++] = 0;
    boxes[n].lo = pg_v2(-PG_FIX_C(1), 0); /* a point on the top edge of box 0 */
    boxes[n].hi = boxes[n].lo;
    flags[n++] = 0;
    boxes[n].lo = pg_v2(1, -PG_FIX_C(1)); /* one LSB right of box 0: no contact */
    boxes[n].hi = pg_v2(PG_FIX_C(1), -1);
    flags[n++] = 0;
    rc = run(boxes, flags, n, pairs, 16, &count, 2);
    PG_EXPECT_EQ(rc, 0, "%s", "touch");
    PG_EXPECT_EQ(count, 2, "%s", "touch");
    PG_EXPECT_EQ(pairs[0].a, 0, "%s", "touch");
    PG_EXPECT_EQ(pairs[0].b, 1, "%s", "touch");
    PG_EXPECT_EQ(pairs[1].a, 0, "%s", "touch");
    PG_EXPECT_EQ(pairs[1].b, 2, "%s", "touch");
    check_scene(boxes, flags, n, "touch", 0);
    free(pairs);
}

static void test_all_passive_gives_nothing(void **state)
{
    enum { N = 1000 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    pg_pair pairs[4];
    uint32_t count = 99, i;
    pgt_rng r = pgt_rng_seed(42);
    int rc;
    (void)state;
    random_scene(&r, boxes, flags, N);
    for (i = 0; i < N; ++i) flags[i] &= (uint8_t)~PG_PROXY_ACTIVE;
    rc = run(boxes, flags, N, pairs, 4, &count, 0);
    PG_EXPECT_EQ(rc, 0, "%s", "passive");
    PG_EXPECT_EQ(count, 0, "%s", "passive");
    rc = run(boxes, flags, N, NULL, 0, &count, 0);
    PG_EXPECT_EQ(rc, 0, "%s", "passive, no capacity");
    PG_EXPECT_EQ(count, 0, "%s", "passive, no capacity");
    rc = run(boxes, flags, 0, NULL, 0, &count, 0);
    PG_EXPECT_EQ(rc, 0, "%s", "empty");
    PG_EXPECT_EQ(count, 0, "%s", "empty");
}

static void test_capacity_overflow_keeps_first_pairs(void **state)
{
    enum { N = 1000 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    unsigned long long seed;
    (void)state;
    for (seed = 1; seed <= 12; ++seed) {
        pgt_rng r = pgt_rng_seed(seed * 31u + 7u);
        size_t total, c;
        pg_pair *ref, *got;
        uint32_t caps[8], count, k;
        random_scene(&r, boxes, flags, N);
        total = brute(boxes, flags, N, NULL, 0);
        if (total < 4) continue;
        ref = malloc(total * sizeof *ref);
        got = malloc((total + 8) * sizeof *got);
        assert_non_null(ref);
        assert_non_null(got);
        brute(boxes, flags, N, ref, total);
        caps[0] = 0;
        caps[1] = 1;
        caps[2] = 2;
        caps[3] = (uint32_t)(total / 7);
        caps[4] = (uint32_t)(total / 2);
        caps[5] = (uint32_t)(total - 1);
        caps[6] = (uint32_t)total;
        caps[7] = (uint32_t)total + 5;
        for (c = 0; c < 8; ++c) {
            int want_rc = caps[c] < total ? -1 : 0;
            uint32_t want_n = caps[c] < total ? caps[c] : (uint32_t)total;
            int rc = run(boxes, flags, N, got, caps[c], &count, (unsigned)c);
            PG_EXPECT_EQ(rc, want_rc, "seed %llu cap %u total %zu", seed, caps[c], total);
            PG_EXPECT_EQ(count, want_n, "seed %llu cap %u total %zu", seed, caps[c], total);
            for (k = 0; k < count; ++k) {
                if (got[k].a != ref[k].a || got[k].b != ref[k].b) {
                    print_error("seed %llu cap %u: pair %u is (%u, %u), want (%u, %u)\n", seed,
                                caps[c], k, got[k].a, got[k].b, ref[k].a, ref[k].b);
                    fail();
                }
            }
        }
        free(ref);
        free(got);
    }
}

/* Bodies much larger than the mean, passive boxes covering many active cells, and
 * actives that fill more than their entry budget: the large-proxy fallbacks. */
static void test_entry_budget_spill(void **state)
{
    enum { N = 2000 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    unsigned long long seed;
    (void)state;
    for (seed = 1; seed <= 6; ++seed) {
        pgt_rng r = pgt_rng_seed(seed + 1000u);
        uint32_t i;
        /* 1000 active points and 100 active boxes of ~7 cells (1/16 m cells), in 4 m x 4 m;
         * 900 passive boxes of ~7 cells over the same area */
        for (i = 0; i < N; ++i) {
            double cx = pgt_unit(&r) * 4.0 - 6.0, cy = pgt_unit(&r) * 4.0 - 1.0;
            double h = i < 1000 ? 0.0 : 3.4 / 16.0 + pgt_unit(&r) * 0.01;
            boxes[i] = box_m(cx, cy, h, h);
            flags[i] = (uint8_t)(i < 1100 ? PG_PROXY_ACTIVE : 0u);
        }
        check_scene(boxes, flags, N, "passive spill", seed);
        /* 300 active boxes of ~7.5 x 64 m: the cell size is capped at 64 m, so each covers
         * 64 cells and the budget (16 per proxy) runs out */
        for (i = 0; i < 300; ++i) {
            double cx = (pgt_unit(&r) * 2.0 - 1.0) * 3000.0, cy = (pgt_unit(&r) * 2.0 - 1.0) * 3000.0;
            boxes[i] = box_m(cx, cy, 3.7 * 64.0, 3.7 * 64.0);
            flags[i] = (uint8_t)(i % 5 == 0 ? 0u : PG_PROXY_ACTIVE);
        }
        check_scene(boxes, flags, 300, "active spill", seed);
    }
}

/* Coordinates at the ends of the range, tiny boxes spread over all of it (the cell size
 * must grow to keep cell keys in 32 bits), a box over the whole range. */
static void test_extreme_coordinates(void **state)
{
    enum { N = 600 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    unsigned long long seed;
    (void)state;
    for (seed = 1; seed <= 20; ++seed) {
        pgt_rng r = pgt_rng_seed(seed * 77u);
        uint32_t i;
        for (i = 0; i < N; ++i) {
            pg_fix x = pgt_fix_any(&r), y = pgt_fix_any(&r);
            pg_fix w = (pg_fix)pgt_below(&r, seed % 2 ? 1u << 12 : 1u << 18);
            if (pgt_below(&r, 4) == 0) x = pgt_below(&r, 2) ? PG_FIX_MAX - w : PG_FIX_MIN;
            if (pgt_below(&r, 4) == 0) y = pgt_below(&r, 2) ? PG_FIX_MAX - w : PG_FIX_MIN;
            if (x > PG_FIX_MAX - w) x = PG_FIX_MAX - w;
            if (y > PG_FIX_MAX - w) y = PG_FIX_MAX - w;
            boxes[i].lo = pg_v2(x, y);
            boxes[i].hi = pg_v2(x + w, y + w);
            flags[i] = (uint8_t)(pgt_below(&r, 3) ? PG_PROXY_ACTIVE : 0u);
            if (i % 40 == 0) { /* clusters so that some pairs exist */
                pg_fix lx = boxes[i].lo.x / 2048 * 2048, ly = boxes[i].lo.y / 2048 * 2048;
                if (lx > PG_FIX_MAX - 4096) lx = PG_FIX_MAX - 4096;
                if (ly > PG_FIX_MAX - 4096) ly = PG_FIX_MAX - 4096;
                boxes[i].lo = pg_v2(lx, ly);
                boxes[i].hi = pg_v2(lx + 4096, ly + 4096);
            }
        }
        boxes[N - 1].lo = pg_v2(PG_FIX_MIN, PG_FIX_MIN);
        boxes[N - 1].hi = pg_v2(PG_FIX_MAX, PG_FIX_MAX);
        flags[N - 1] = (uint8_t)(seed % 3 == 0 ? PG_PROXY_ACTIVE : 0u);
        check_scene(boxes, flags, N, "extreme", seed);
    }
}

/* 16000 circle-sized boxes piled in a 40 m wide container (floor and walls passive). */
static void test_container_16000(void **state)
{
    enum { N = 16003 };
    static pg_aabb boxes[N];
    static uint8_t flags[N];
    unsigned long long pass;
    (void)state;
    for (pass = 0; pass < 2; ++pass) {
        pgt_rng r = pgt_rng_seed(16000u + pass);
        uint32_t i, n = 0;
        boxes[n] = box_m(0.0, -0.5, 21.0, 0.5); /* floor */
        flags[n++] = 0;
        boxes[n] = box_m(-20.5, 20.0, 0.5, 21.0); /* walls */
        flags[n++] = 0;
        boxes[n] = box_m(20.5, 20.0, 0.5, 21.0);
        flags[n++] = 0;
        for (i = 0; i < 16000; ++i) {
            double rad = 0.1 + pgt_unit(&r) * 0.03;
            double cx = -19.8 + (double)(i % 160) * 0.2475 + pgt_unit(&r) * 0.02;
            double cy = 0.12 + (double)(i / 160) * 0.2 + pgt_unit(&r) * 0.02;
            boxes[n] = box_m(cx, cy, rad, rad);
            /* pass 0: everything awake; pass 1: a mostly sleeping pile */
            flags[n++] = (uint8_t)(pass == 0 || pgt_below(&r, 20) == 0 ? PG_PROXY_ACTIVE : 0u);
        }
        check_scene(boxes, flags, n, "container", pass);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_scenes_match_reference),
        cmocka_unit_test(test_touching_boxes_count),
        cmocka_unit_test(test_all_passive_gives_nothing),
        cmocka_unit_test(test_capacity_overflow_keeps_first_pairs),
        cmocka_unit_test(test_entry_budget_spill),
        cmocka_unit_test(test_extreme_coordinates),
        cmocka_unit_test(test_container_16000),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
