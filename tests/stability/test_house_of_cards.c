/* test_house_of_cards.c — houses of cards at the defaults (docs/hard-cases.md, "Houses
 * of cards"). Cards 1 m long and 0.02 or 0.05 m thick lean in pairs at 20 or 25 degrees
 * from the vertical, their tops touching, with a flat card across each two neighbouring
 * pairs; each level stands on the flat cards of the one below. Friction 0.6 (the
 * default), ground a static box.
 *
 * Asserted: two-level houses stand for 60 s with sleeping off and on (every card within
 * 5 mm of where it was placed, and none moving by more than 0.5 mm after the first 10 s:
 * no creep); three-level houses stand with sleeping on (2 cm, 1 mm). Three-level houses
 * with sleeping off creep and one of the four falls (the open finding): printed, not
 * asserted, at the defaults and at 6 substeps and 90 Hz. Leaning columns of 1.5 cm
 * shifts: 10 boxes at the defaults, 20 at 8 substeps and 120 Hz and at 6 substeps and
 * 90 Hz stand (largest tilt under 2 degrees). Every run prints what it measured
 * (print_message). */
#include "../unit/pg_test.h"
#define HARD_PROGRAM "test_house_of_cards"
#include "hard_results.h"

#include <math.h>

#include "pogon/pogon.h"
#include "../unit/pg_test_world.h"

#define MAX_CARDS 32

typedef struct house {
    test_world t;
    pg_body_id cards[MAX_CARDS];
    double x0[MAX_CARDS], y0[MAX_CARDS];
    int n;
} house;

/* what a run may change from the defaults (a measurement of the creep's mechanism) */
typedef struct variant {
    uint32_t substeps;
    double hertz, friction;
    int mirrored; /* cards created right to left */
} variant;

static const variant defaults = {4, 30.0, 0.6, 0};

static void add_card(house *h, double cx, double cy, double angle, double thick, double friction)
{
    pg_body_def bd = dynamic_at(cx, cy);
    pg_shape_def sd = pg_default_shape_def();
    sd.friction = fx(friction);
    assert_true(h->n < MAX_CARDS);
    bd.angle = pg_angle_from_radians(fx(angle));
    assert_int_equal(pg_make_box(h->t.w, &bd, &sd, fx(thick), PG_FIX_ONE, &h->cards[h->n]), PG_OK);
    h->x0[h->n] = cx;
    h->y0[h->n] = cy;
    h->n += 1;
}

/* `levels` levels; the bottom one has `levels` pairs. Pairs are 1.002 m apart, so a flat
 * card (1 m) reaches from one apex to the next; each card's lowest corner touches the
 * floor it stands on and the two tops of a pair are 1 mm apart. */
static void build_house(house *h, int levels, double thick, double deg, int sleeping, const variant *v)
{
    pg_world_def d = pg_default_world_def();
    pg_body_def gb = pg_default_body_def();
    pg_shape_def gs = pg_default_shape_def();
    pg_body_id ground;
    const double th = deg * PGT_PI / 180.0, gap = 0.001, spacing = 1.002;
    const double cx = gap / 2 + 0.5 * sin(th) + thick / 2 * cos(th), cy = 0.5 * cos(th) + thick / 2 * sin(th);
    const double apex = cos(th) + thick * sin(th);
    double base = 0;
    int lv, p;
    d.max_bodies = 40;
    d.max_shapes = 40;
    d.max_contacts = 256;
    if (!sleeping) d.effects &= ~PG_EFFECT_SLEEPING;
    d.substeps = v->substeps;
    d.contact_hertz = fx(v->hertz);
    h->t = make_world_def(&d);
    h->n = 0;
    gb.position = pg_v2(0, -fx(0.5));
    gs.friction = fx(v->friction);
    assert_int_equal(pg_make_wall(h->t.w, &gb, &gs, PG_FIX_C(20), PG_FIX_ONE, &ground), PG_OK);
    for (lv = 0; lv < levels; ++lv) {
        int pairs = levels - lv;
        double first = -(pairs - 1) * spacing / 2;
        for (p = 0; p < pairs; ++p) {
            double ax = first + (v->mirrored ? pairs - 1 - p : p) * spacing, side = v->mirrored ? -1.0 : 1.0;
            add_card(h, ax - side * cx, base + cy, -side * th, thick, v->friction);
            add_card(h, ax + side * cx, base + cy, side * th, thick, v->friction);
        }
        for (p = 0; p + 1 < pairs; ++p)
            add_card(h, first + ((v->mirrored ? pairs - 2 - p : p) + 0.5) * spacing, base + apex + thick / 2, PGT_PI / 2, thick, v->friction);
        base += apex + thick;
    }
}

/* Runs 60 s: the largest distance of any card from where it was placed, and from where
 * it was after 10 s; the time a card first moved 0.2 m (0: never), and the cards' mean
 * x offset after 10 s (the side the house settled to). */
static void run_house(house *h, double *moved, double *crept, double *fell_at, double *mean_dx)
{
    double x10[MAX_CARDS], y10[MAX_CARDS];
    int i, k;
    *moved = *crept = *fell_at = *mean_dx = 0;
    for (i = 1; i <= 3600; ++i) {
        assert_int_equal(pg_world_step(h->t.w), PG_OK);
        for (k = 0; k < h->n; ++k) {
            pg_vec2 p = pg_body_position(h->t.w, h->cards[k]);
            double x = fd(p.x), y = fd(p.y), dist = hypot(x - h->x0[k], y - h->y0[k]);
            if (dist > *moved) *moved = dist;
            if (dist > 0.2 && *fell_at == 0) *fell_at = i / 60.0;
            if (i == 600) x10[k] = x, y10[k] = y, *mean_dx += (x - h->x0[k]) / h->n;
            if (i > 600 && hypot(x - x10[k], y - y10[k]) > *crept) *crept = hypot(x - x10[k], y - y10[k]);
        }
    }
}

/* Every house of `levels` levels (0.02 and 0.05 m cards at 20 and 25 degrees) under v:
 * printed, and with assert_it its largest move and creep checked against the bounds. */
static void check_houses_with(const variant *v, int levels, int sleeping, int assert_it, double bound_moved, double bound_crept)
{
    static const double thick[] = {0.02, 0.05}, degs[] = {20.0, 25.0};
    const int at_defaults = v->substeps == defaults.substeps && v->hertz == defaults.hertz;
    int i, j;
    for (i = 0; i < 2; ++i)
        for (j = 0; j < 2; ++j) {
            house h;
            double moved, crept, fell_at, mean_dx;
            char setting[48] = "";
            if (!at_defaults) snprintf(setting, sizeof setting, ", %u substeps at %.0f Hz", v->substeps, v->hertz);
            build_house(&h, levels, thick[i], degs[j], sleeping, v);
            run_house(&h, &moved, &crept, &fell_at, &mean_dx);
            print_message("house of %d levels, cards %.2f m thick at %.0f deg, sleeping %s%s: largest move %.4f m, after 10 s %.4f m%s\n", levels,
                          thick[i], degs[j], sleeping ? "on" : "off", setting, moved, crept, assert_it ? "" : " (not asserted)");
            if (assert_it) {
                PG_EXPECT_LE(moved, bound_moved, "%d levels, %.2f m at %.0f deg, sleeping %d%s: largest move", levels, thick[i], degs[j], sleeping, setting);
                PG_EXPECT_LE(crept, bound_crept, "%d levels, %.2f m at %.0f deg, sleeping %d%s: creep after 10 s", levels, thick[i], degs[j], sleeping,
                             setting);
            }
            free_world(&h.t);
        }
}

static void check_houses(int levels, int sleeping, int assert_it, double bound_moved, double bound_crept)
{
    check_houses_with(&defaults, levels, sleeping, assert_it, bound_moved, bound_crept);
}

static void test_house_of_cards_two_levels(void **state)
{
    (void)state;
    check_houses(2, 0, 1, 0.005, 0.0005);
    check_houses(2, 1, 1, 0.005, 0.0005);
}

/* The creep of the three-level house of 0.05 m cards at 20 degrees with sleeping off,
 * under the variants docs/hard-cases.md compares (printed: the open finding). */
static void print_creep_variants(void)
{
    static const variant vs[] = {{4, 30.0, 0.6, 0}, {4, 30.0, 0.6, 1}, {8, 30.0, 0.6, 0}, {8, 60.0, 0.6, 0}, {16, 30.0, 0.6, 0},
                                 {4, 60.0, 0.6, 0}, {4, 15.0, 0.6, 0}, {4, 30.0, 0.7, 0}, {4, 30.0, 0.8, 0}};
    size_t k;
    for (k = 0; k < sizeof vs / sizeof vs[0]; ++k) {
        house h;
        double moved, crept, fell_at, mean_dx;
        build_house(&h, 3, 0.05, 20.0, 0, &vs[k]);
        run_house(&h, &moved, &crept, &fell_at, &mean_dx);
        print_message("3 levels, 0.05 m at 20 deg, sleeping off, %u substeps, %.0f Hz, friction %.1f%s: mean x after 10 s %+.5f m, largest move "
                      "%.4f m, after 10 s %.4f m, %s%.1f s (not asserted)\n",
                      vs[k].substeps, vs[k].hertz, vs[k].friction, vs[k].mirrored ? ", mirrored order" : "", mean_dx, moved, crept,
                      fell_at > 0 ? "falls at " : "stands ", fell_at > 0 ? fell_at : 60.0);
        free_world(&h.t);
    }
}

/* 6 substeps with the contacts at the softness cap (a quarter of 360 substeps a second,
 * 90 Hz): the cheapest setting measured at which the 20-box column below stands. */
static const variant at_the_cap = {6, 90.0, 0.6, 0};

static void test_house_of_cards_three_levels(void **state)
{
    (void)state;
    check_houses(3, 1, 1, 0.02, 0.001);
    check_houses(3, 0, 0, 0, 0); /* open: creep with sleeping off (docs/hard-cases.md) */
    check_houses_with(&at_the_cap, 3, 0, 0, 0, 0); /* open there too: some creep */
    print_creep_variants();
}

/* Columns of 1 m boxes, each 1.5 cm to the right of the one below, sleeping off, 60 s:
 * the largest tilt of any box, or the time one first tilts past 10 degrees. */
static double column_tilt(int boxes, double shift, uint32_t substeps, double hertz, double *fell_at)
{
    pg_world_def d = pg_default_world_def();
    pg_body_def gb = pg_default_body_def(), bd;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ground, b[32];
    test_world t;
    double tilt = 0;
    int i, k;
    d.effects &= ~PG_EFFECT_SLEEPING;
    d.substeps = substeps;
    d.contact_hertz = fx(hertz);
    d.max_bodies = 40;
    d.max_shapes = 40;
    d.max_contacts = 128;
    t = make_world_def(&d);
    gb.position = pg_v2(0, -fx(0.5));
    assert_int_equal(pg_make_wall(t.w, &gb, &sd, PG_FIX_C(40), PG_FIX_ONE, &ground), PG_OK);
    for (k = 0; k < boxes; ++k) {
        bd = dynamic_at(k * shift, 0.5 + k);
        assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &b[k]), PG_OK);
    }
    *fell_at = 0;
    for (i = 1; i <= 3600; ++i) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        for (k = 0; k < boxes; ++k) {
            double a = fabs((double)(int32_t)pg_body_angle(t.w, b[k]) * (360.0 / 4294967296.0));
            if (a > tilt) tilt = a;
            if (a > 10.0 && *fell_at == 0) *fell_at = i / 60.0;
        }
    }
    free_world(&t);
    return tilt;
}

/* Asserted: what stands (10 boxes at the defaults, 20 at 8 substeps and 120 Hz and at
 * 6 substeps and 90 Hz, within 2 degrees); printed: the heights and stiffnesses
 * docs/hard-cases.md tabulates. */
static void test_leaning_column_fifteen_mm(void **state)
{
    static const int heights[] = {6, 8, 10, 12, 14, 20};
    static const double hertz[] = {30.0, 60.0, 120.0, 90.0};
    static const uint32_t subs[] = {4, 4, 8, 6};
    int i, j;
    (void)state;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 6; ++i) {
            double fell_at, tilt = column_tilt(heights[i], 0.015, subs[j], hertz[j], &fell_at);
            int asserted = (j == 0 && heights[i] == 10) || (j >= 2 && heights[i] == 20);
            print_message("column of %2d boxes each 1.5 cm over the last, %u substeps %.0f Hz, sleeping off: %s%.1f s, largest tilt %.3f deg%s\n",
                          heights[i], subs[j], hertz[j], fell_at > 0 ? "falls at " : "stands ", fell_at > 0 ? fell_at : 60.0,
                          fell_at > 0 ? 90.0 : tilt, asserted ? "" : " (not asserted)");
            if (asserted) PG_EXPECT_LE(tilt, 2.0, "%d boxes at %.0f Hz: largest tilt (deg)", heights[i], hertz[j]);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_house_of_cards_two_levels),
        cmocka_unit_test(test_house_of_cards_three_levels),
        cmocka_unit_test(test_leaning_column_fifteen_mm),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
