/* test_envelope_shapes.c — the envelope users meet first (docs/envelope.md): long static
 * shapes (grounds, ramps and walls up to 2 000 m) and thin shapes (cards and planks down
 * to 0.01 m), accepted by one rule whatever function makes them, refused past it with
 * PG_ERR_ENVELOPE and a message, and behaving as well as ordinary ones.
 *
 * Every test prints what it measured (print_message). */
#include "../unit/pg_test.h"
#define HARD_PROGRAM "test_envelope_shapes"
#include "hard_results.h"

#include <math.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "../unit/pg_test_world.h"

#define Q32 4294967296.0
#define Q36 68719476736.0

static test_world world_with(uint32_t effects)
{
    pg_world_def d = pg_default_world_def();
    d.effects = effects;
    d.max_bodies = 32;
    d.max_shapes = 64;
    d.max_contacts = 256;
    return make_world_def(&d);
}

static void step_n(pg_world *w, int n)
{
    int i;
    for (i = 0; i < n; ++i) assert_int_equal(pg_world_step(w), PG_OK);
}

static double angle_deg(pg_angle a) { return (double)(int32_t)a * (360.0 / 4294967296.0); }

/* r must be PG_ERR_ENVELOPE and the world's last error must mention `word`. */
static void expect_envelope(pg_world *w, pg_result r, const char *word, const char *what)
{
    const char *e = pg_world_last_error(w);
    print_message("%s: %s, \"%s\"\n", what, pg_result_name(r), e);
    if (r != PG_ERR_ENVELOPE || strstr(e, word) == NULL) {
        print_error("%s: got %s (\"%s\"), want PG_ERR_ENVELOPE naming \"%s\"\n", what, pg_result_name(r), e, word);
        fail();
    }
}

static uint32_t body_count(pg_world *w) { return pg_world_get_stats(w).body_count; }

/* ---- long static shapes -------------------------------------------------------------- */

/* Static boxes, walls, polygons, segments and capsules are accepted as long as their
 * vertices stay within 1000 m of the body's origin (a 2 000 m ground from -1000 to 1000 m);
 * moving bodies keep 50 m; past either, PG_ERR_ENVELOPE with a message, world unchanged. */
static void test_long_static_shapes_accepted(void **state)
{
    test_world t = world_with(PG_EFFECTS_ALL);
    pg_world *w = t.w;
    pg_body_def st = pg_default_body_def(), dyn = dynamic_at(0, 5), kin = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id, holder, big;
    pg_shape_id sid;
    pg_geometry g;
    pg_vec2 ramp[4];
    uint32_t n;
    (void)state;
    kin.type = PG_BODY_KINEMATIC;

    assert_int_equal(pg_make_wall(w, &st, &sd, PG_FIX_C(120), PG_FIX_ONE, &id), PG_OK);
    assert_int_equal(pg_make_wall(w, &st, &sd, PG_FIX_ONE, PG_FIX_C(600), &id), PG_OK);
    assert_int_equal(pg_make_wall(w, &st, &sd, PG_FIX_C(2000), PG_FIX_ONE, &id), PG_OK);
    st.type = PG_BODY_STATIC;
    assert_int_equal(pg_make_box(w, &st, &sd, PG_FIX_C(2000), PG_FIX_C(2), &id), PG_OK);
    /* a 120 m ramp at 30 degrees as a rotated box and as a polygon, on one static body */
    assert_int_equal(pg_body_create(w, &st, &holder), PG_OK);
    assert_int_equal(pg_geometry_box(PG_FIX_C(60), fx(0.5), pg_v2(0, 0), pg_angle_from_radians(fx(PGT_PI / 6)), &g), PG_OK);
    assert_int_equal(pg_shape_create(w, holder, &sd, &g, &sid), PG_OK);
    ramp[0] = pg_v2(-PG_FIX_C(1000), -PG_FIX_C(10));
    ramp[1] = pg_v2(PG_FIX_C(1000), -PG_FIX_C(10));
    ramp[2] = pg_v2(PG_FIX_C(1000), PG_FIX_C(50));
    ramp[3] = pg_v2(-PG_FIX_C(1000), -PG_FIX_C(9));
    assert_int_equal(pg_geometry_polygon(ramp, 4, &g), PG_OK);
    assert_int_equal(pg_shape_create(w, holder, &sd, &g, &sid), PG_OK);
    assert_int_equal(pg_geometry_segment(pg_v2(-PG_FIX_C(1000), 0), pg_v2(PG_FIX_C(1000), 0), &g), PG_OK);
    assert_int_equal(pg_shape_create(w, holder, &sd, &g, &sid), PG_OK);
    assert_int_equal(pg_geometry_capsule(pg_v2(-PG_FIX_C(999), 0), pg_v2(PG_FIX_C(999), 0), PG_FIX_ONE, &g), PG_OK);
    assert_int_equal(pg_shape_create(w, holder, &sd, &g, &sid), PG_OK);
    n = body_count(w);

    /* past the static reach */
    expect_envelope(w, pg_make_wall(w, &st, &sd, fx(2000.1), PG_FIX_ONE, &id), "wall sides", "wall 2000.1 m");
    assert_int_equal(pg_geometry_segment(pg_v2(-PG_FIX_C(1000), 0), pg_v2(fx(1000.01), 0), &g), PG_ERR_ENVELOPE);
    /* moving bodies keep 50 m: their lever arms */
    expect_envelope(w, pg_make_box(w, &dyn, &sd, fx(100.5), PG_FIX_ONE, &id), "50 m", "dynamic 100.5 m box");
    expect_envelope(w, pg_make_box(w, &kin, &sd, PG_FIX_C(120), PG_FIX_ONE, &id), "kinematic", "kinematic 120 m box");
    assert_int_equal(pg_make_box(w, &dyn, &sd, PG_FIX_C(100), PG_FIX_ONE, &big), PG_OK); /* the edge itself */
    n += 1u;
    expect_envelope(w, pg_make_capsule(w, &dyn, &sd, PG_FIX_C(120), fx(0.5), &id), "50 m", "dynamic 120 m capsule");
    assert_int_equal(pg_geometry_box(PG_FIX_C(60), fx(0.5), pg_v2(0, 0), 0, &g), PG_OK);
    expect_envelope(w, pg_shape_create(w, big, &sd, &g, &sid), "reaches 60", "120 m box onto a dynamic body");
    /* a long static body cannot become a moving one */
    expect_envelope(w, pg_body_set_type(w, holder, PG_BODY_DYNAMIC), "dynamic body's shape reaches", "long static body made dynamic");
    expect_envelope(w, pg_body_set_type(w, holder, PG_BODY_KINEMATIC), "kinematic", "long static body made kinematic");
    assert_int_equal(pg_body_type_of(w, holder), PG_BODY_STATIC);
    assert_int_equal(body_count(w), n);
    free_world(&t);
}

/* A snapshot of a world with a 2 000 m ground restores to the same hash, and a snapshot
 * whose dynamic body holds such a shape is refused as corrupt. */
static void test_long_static_shape_snapshot(void **state)
{
    test_world t = world_with(PG_EFFECTS_ALL), u = world_with(PG_EFFECTS_ALL);
    pg_body_def st = pg_default_body_def(), dyn = dynamic_at(900, 1);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id g, box;
    static unsigned char buf[1 << 16];
    size_t size = 0;
    (void)state;
    st.position = pg_v2(0, -fx(0.5));
    assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(2000), PG_FIX_ONE, &g), PG_OK);
    assert_int_equal(pg_make_box(t.w, &dyn, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK);
    step_n(t.w, 30);
    assert_int_equal(pg_world_snapshot_save(t.w, buf, sizeof buf, &size), PG_OK);
    assert_int_equal(pg_world_snapshot_restore(u.w, buf, size), PG_OK);
    PG_EXPECT_EQ(pg_world_hash(u.w), pg_world_hash(t.w), "%s", "restored hash");
    step_n(t.w, 30);
    step_n(u.w, 30);
    PG_EXPECT_EQ(pg_world_hash(u.w), pg_world_hash(t.w), "%s", "hash 30 steps after restoring");
    free_world(&t);
    free_world(&u);
}

/* One body on a 2 000 m ground: `x0` its start, `vx` its initial speed. Returns the
 * trajectory's samples relative to x0 (every 10 steps, 60 samples: x - x0, y, angle,
 * vx, vy, w as raw values). */
static void run_on_long_ground(double x0, double vx, int32_t out[60][6], int tilted)
{
    test_world t = world_with(PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING);
    pg_body_def st = pg_default_body_def(), bd = dynamic_at(x0, tilted ? 0.8 : 0.25);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id g, box;
    int i;
    st.position = pg_v2(0, -PG_FIX_C(1));
    assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(2000), PG_FIX_C(2), &g), PG_OK);
    bd.linear_velocity = pg_v2(fx(vx), 0);
    if (tilted) bd.angle = pg_angle_from_radians(fx(0.3));
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, fx(0.5), &box), PG_OK);
    for (i = 0; i < 60; ++i) {
        pg_vec2 p, v;
        step_n(t.w, 10);
        p = pg_body_position(t.w, box);
        v = pg_body_linear_velocity(t.w, box);
        out[i][0] = (int32_t)(p.x - fx(x0));
        out[i][1] = p.y;
        out[i][2] = (int32_t)pg_body_angle(t.w, box);
        out[i][3] = v.x;
        out[i][4] = v.y;
        out[i][5] = pg_body_angular_velocity(t.w, box);
    }
    free_world(&t);
}

/* A box resting, sliding, or landing tilted at x = +-900 m on a 2 000 m ground moves
 * exactly as at x = 0: the same bits, shifted by 900 m (fixed point has the same
 * resolution everywhere, and every product in the narrowphase and solver is exact in
 * int64 at these distances). */
static void test_far_along_long_ground_as_at_origin(void **state)
{
    static const double speeds[] = {0.0, 3.0, -3.0};
    static const double places[] = {900.0, -900.0, 990.0};
    int32_t ref[60][6], far[60][6];
    int s, p, tilted;
    (void)state;
    for (tilted = 0; tilted < 2; ++tilted)
        for (s = 0; s < 3; ++s) {
            run_on_long_ground(0.0, speeds[s], ref, tilted);
            for (p = 0; p < 3; ++p) {
                int i, k, differ = 0;
                run_on_long_ground(places[p], speeds[s], far, tilted);
                for (i = 0; i < 60; ++i)
                    for (k = 0; k < 6; ++k) differ += far[i][k] != ref[i][k];
                print_message("box %s at x = %.0f m, %+.0f m/s: %d of 360 samples differ from x = 0 (end: x %+.5f m, y %.5f m, %.4f deg)\n",
                              tilted ? "landing tilted" : "flat", places[p], speeds[s], differ, fd(far[59][0]), fd(far[59][1]),
                              angle_deg((pg_angle)(uint32_t)far[59][2]));
                PG_EXPECT_EQ(differ, 0, "x0 %.0f, speed %.0f, tilted %d", places[p], speeds[s], tilted);
            }
        }
    /* and the physics is right: the sliding box stops after v^2 / (2 mu g) = 0.75 m */
    run_on_long_ground(900.0, 3.0, far, 0);
    print_message("sliding at 3 m/s with friction 0.6: stopped after %.4f m (v^2/(2 mu g) = 0.75 m)\n", fd(far[59][0]));
    PG_EXPECT_LE(fabs(fd(far[59][0]) - 0.75), 0.01, "%s", "stopping distance");
}

/* A box slides down a 120 m static ramp at 30 degrees with friction 0.2: after 2 s it has
 * gone g (sin a - mu cos a) t^2 / 2 along it, as on a short ramp. */
static void test_box_slides_down_long_ramp(void **state)
{
    test_world t = world_with(PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING);
    pg_body_def st = pg_default_body_def(), bd;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ramp, box;
    const double a = PGT_PI / 6, mu = 0.2;
    double along0, along, want;
    pg_vec2 p0, p;
    (void)state;
    sd.friction = fx(mu);
    st.angle = pg_angle_from_radians(fx(a));
    assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(120), PG_FIX_ONE, &ramp), PG_OK);
    /* the box on the ramp's top face, 40 m up the slope from its centre */
    bd = dynamic_at(40 * cos(a) - 1.0 * sin(a), 40 * sin(a) + 1.0 * cos(a));
    bd.angle = st.angle;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK);
    step_n(t.w, 10);
    p0 = pg_body_position(t.w, box);
    along0 = fd(p0.x) * cos(a) + fd(p0.y) * sin(a);
    step_n(t.w, 120);
    p = pg_body_position(t.w, box);
    along = fd(p.x) * cos(a) + fd(p.y) * sin(a);
    {
        double v0 = 10.0 * (sin(a) - mu * cos(a)) * 10.0 / 60.0; /* speed after the first 10 steps */
        want = -(v0 * 2.0 + 0.5 * 10.0 * (sin(a) - mu * cos(a)) * 4.0);
    }
    print_message("120 m ramp at 30 deg, friction 0.2: slid %.4f m in 2 s (want %.4f m), %.4f deg off the slope\n", along - along0, want,
                  angle_deg(pg_body_angle(t.w, box)) - 30.0);
    PG_EXPECT_LE(fabs((along - along0) - want), 0.01 * fabs(want), "%s", "distance down the ramp");
    PG_EXPECT_LE(fabs(angle_deg(pg_body_angle(t.w, box)) - 30.0), 0.05, "%s", "box stays flat on the ramp");
    free_world(&t);
}

/* ---- thin shapes ----------------------------------------------------------------------- */

/* One rule for every way of making a shape: at least 0.01 m across in every direction. A
 * box and the same rectangle as a polygon are accepted or refused alike. */
static void test_thin_shapes_one_rule(void **state)
{
    test_world t = world_with(PG_EFFECTS_ALL);
    pg_body_def bd = dynamic_at(0, 1);
    pg_shape_def sd = pg_default_shape_def();
    pg_geometry g;
    pg_body_id id;
    pg_shape_id sid;
    static const double thick[] = {0.01, 0.0099, 0.008, 0.02, 0.05};
    int i;
    (void)state;
    for (i = 0; i < 5; ++i) {
        double h = thick[i];
        pg_vec2 v[4];
        pg_result rb = pg_geometry_box(PG_FIX_C(1) / 2, fx(h) / 2, pg_v2(0, 0), 0, &g), rp, rr, rt;
        v[0] = pg_v2(-fx(0.5), -fx(h) / 2);
        v[1] = pg_v2(fx(0.5), -fx(h) / 2);
        v[2] = pg_v2(fx(0.5), fx(h) / 2);
        v[3] = pg_v2(-fx(0.5), fx(h) / 2);
        rp = pg_geometry_polygon(v, 4, &g);
        /* the same card turned 45 degrees (its vertices rounded: a width within 1e-4 m) */
        {
            pg_vec2 r[4];
            int k;
            for (k = 0; k < 4; ++k) {
                double x = fd(v[k].x), y = fd(v[k].y), c = cos(PGT_PI / 4), s = sin(PGT_PI / 4);
                r[k] = pg_v2(fx(c * x - s * y), fx(s * x + c * y));
            }
            rr = pg_geometry_polygon(r, 4, &g);
        }
        rt = pg_geometry_capsule(pg_v2(-fx(0.5), 0), pg_v2(fx(0.5), 0), fx(h) / 2, &g);
        print_message("1 m x %.4f m: box %s, polygon %s, polygon at 45 deg %s, capsule %s\n", h, pg_result_name(rb), pg_result_name(rp),
                      pg_result_name(rr), pg_result_name(rt));
        {
            pg_result want = h >= 0.01 ? PG_OK : PG_ERR_ENVELOPE;
            PG_EXPECT_EQ(rb, want, "box %.4f", h);
            PG_EXPECT_EQ(rp, want, "polygon %.4f", h);
            PG_EXPECT_EQ(rt, want, "capsule %.4f", h);
            if (h >= 0.0101 || h <= 0.0099) PG_EXPECT_EQ(rr, want, "turned polygon %.4f", h);
        }
    }
    /* a thin sliver filled in by hand is refused at pg_shape_create with a message */
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_OK);
    memset(&g, 0, sizeof g);
    g.kind = PG_SHAPE_POLYGON;
    g.count = 3;
    g.vertices[0] = pg_v2(-fx(0.5), 0);
    g.vertices[1] = pg_v2(fx(0.5), 0);
    g.vertices[2] = pg_v2(0, fx(0.005));
    expect_envelope(t.w, pg_shape_create(t.w, id, &sd, &g, &sid), "thick", "a 0.005 m sliver of a triangle");
    /* the smallest ball and the thinnest card are made by pg_make_* */
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, fx(0.005), &id), PG_ERR_ENVELOPE); /* inertia 9.8e-10: its own limit */
    bd.fixed_rotation = 1;
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, fx(0.005), &id), PG_OK);
    bd.fixed_rotation = 0;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, fx(0.01), &id), PG_OK);
    expect_envelope(t.w, pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, fx(0.009), &id), "0.01", "1 m x 0.009 m box");
    expect_envelope(t.w, pg_make_ball(t.w, &bd, &sd, fx(0.0045), &id), "0.005", "ball of radius 0.0045 m");
    free_world(&t);
}

/* Cards 1 m long and 0.01 to 0.05 m thick keep exact mass and inertia, land flat from
 * 0.5 m and rest where the soft contact puts them, at every density of the envelope. */
static void test_thin_cards_rest_flat(void **state)
{
    static const double thick[] = {0.01, 0.02, 0.05}, dens[] = {0.1, 1.0, 100.0};
    int i, j;
    (void)state;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            test_world t = world_with(PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING);
            pg_body_def st = pg_default_body_def(), bd = dynamic_at(0.3, 0.5);
            pg_shape_def sd = pg_default_shape_def();
            pg_body_id g, card;
            double h = fd(fx(thick[i]) / 2 * 2), m, inertia, want_m, want_i, y, drift = 0, turn = 0, x0;
            int k;
            st.position = pg_v2(0, -fx(0.5));
            assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(20), PG_FIX_ONE, &g), PG_OK);
            sd.density = fx(dens[j]);
            assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, fx(thick[i]), &card), PG_OK);
            m = (double)pg_body_mass(t.w, card) / Q32;
            inertia = (double)pg_body_inertia(t.w, card) / Q36;
            want_m = fd(sd.density) * 1.0 * h;
            want_i = want_m * (1.0 + h * h) / 12.0;
            PG_EXPECT_LE(fabs(m - want_m), 1.0 / Q32, "card %.2f density %.1f: mass", thick[i], dens[j]);
            PG_EXPECT_LE(fabs(inertia - want_i), 1.0 / Q36 + 1e-12 * want_i, "card %.2f density %.1f: inertia", thick[i], dens[j]);
            step_n(t.w, 120);
            x0 = fd(pg_body_position(t.w, card).x);
            for (k = 0; k < 240; ++k) {
                double dx;
                step_n(t.w, 1);
                dx = fabs(fd(pg_body_position(t.w, card).x) - x0);
                if (dx > drift) drift = dx;
                if (fabs(angle_deg(pg_body_angle(t.w, card))) > turn) turn = fabs(angle_deg(pg_body_angle(t.w, card)));
            }
            y = fd(pg_body_position(t.w, card).y);
            print_message("card 1 x %.2f m, density %5.1f: mass %.6g kg, inertia %.6g kg m^2 (exact %.6g); rests at y %.5f (half thickness %.3f), drift %.2e m, tilt %.4f deg\n",
                          thick[i], dens[j], m, inertia, want_i, y, h / 2, drift, turn);
            PG_EXPECT_LE(fabs(y - h / 2), 0.005, "card %.2f density %.1f: resting height", thick[i], dens[j]);
            PG_EXPECT_LE(drift, 1e-4, "card %.2f density %.1f: drift at rest", thick[i], dens[j]);
            PG_EXPECT_LE(turn, 0.01, "card %.2f density %.1f: tilt at rest", thick[i], dens[j]);
            free_world(&t);
        }
}

/* A 0.01 m card thrown flat at the ground at 30 m/s, or edge-on at 10 m/s, stops on it:
 * its speculative contacts hold although it moves many times its thickness in a step. */
static void test_thin_card_thrown_at_ground(void **state)
{
    int edge;
    (void)state;
    for (edge = 0; edge < 2; ++edge) {
        test_world t = world_with(PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING);
        pg_body_def st = pg_default_body_def(), bd = dynamic_at(0, 2);
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id g, card;
        double lowest = 10;
        int k;
        st.position = pg_v2(0, -fx(0.5));
        assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(20), PG_FIX_ONE, &g), PG_OK);
        bd.linear_velocity = pg_v2(0, edge ? -PG_FIX_C(10) : -PG_FIX_C(30));
        if (edge) bd.angle = pg_angle_from_radians(fx(PGT_PI / 2 - 0.1));
        assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, fx(0.01), &card), PG_OK);
        for (k = 0; k < 180; ++k) {
            double y;
            step_n(t.w, 1);
            y = fd(pg_body_position(t.w, card).y);
            if (y < lowest) lowest = y;
        }
        print_message("0.01 m card thrown %s: lowest centre %.4f m, ends at y %.4f m\n", edge ? "edge-on at 10 m/s" : "flat at 30 m/s", lowest,
                      fd(pg_body_position(t.w, card).y));
        PG_EXPECT_LE(-lowest, 0.0, "card thrown %s: its centre stays above the ground", edge ? "edge-on" : "flat");
        PG_EXPECT_LE(fabs(fd(pg_body_position(t.w, card).y) - 0.005), 0.005, "card thrown %s: rests on the ground", edge ? "edge-on" : "flat");
        free_world(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_long_static_shapes_accepted),
        cmocka_unit_test(test_long_static_shape_snapshot),
        cmocka_unit_test(test_far_along_long_ground_as_at_origin),
        cmocka_unit_test(test_box_slides_down_long_ramp),
        cmocka_unit_test(test_thin_shapes_one_rule),
        cmocka_unit_test(test_thin_cards_rest_flat),
        cmocka_unit_test(test_thin_card_thrown_at_ground),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
