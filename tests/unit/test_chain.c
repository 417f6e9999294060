/* test_chain.c — chains of segments (src/core/chain.c, collide.c's chain segments): a box
 * sliding across the joints of a chain gets no upward kick and ends at the height it
 * has on one long segment, while the same run on separate segments bumps (so the test
 * can fail); validation, failing calls, and the state that carries the neighbours.
 *
 * BOUNDS
 *   - Upward speed on a flat chain: at most 0.01 m/s. A box resting on one long segment
 *     shows 2e-5 m/s of solver noise; a ghost bump is a collision with the end of the
 *     next segment, and on separate segments it gives 0.29 m/s at 1 m/s up to 10 m/s at
 *     30 m/s (the box snags or flips): 0.01 m/s lifts a box by 5e-6 m in a step, far
 *     below anything a bump does, and far above the noise.
 *   - Height: within 0.001 m of the run on one long segment, a fifth of the linear slop
 *     (0.005 m) within which contacts rest; a bump lifts the box by 0.01 m or more.
 *   - Over a concave joint (the chain turns 1 degree up) the box must rise: its upward
 *     speed is at most v sin(1 degree) times 1.05 plus 0.01 m/s, the slope's own share
 *     and the push-out of the valley corner; a bump adds the speed of hitting a corner.
 */
#include "pg_test.h"
#include "pg_test_world.h"

#include <stdio.h>

#include "pogon/replay.h"

#define SEGMENTS 20
#define DEG (PGT_PI / 180.0)

enum ground { CHAIN, SEPARATE, ONE_SEGMENT };

typedef struct slide {
    double max_up;   /* largest upward velocity while sliding, m/s */
    double end_y;    /* height at the end, m */
    double end_x;
} slide;

static test_world chain_world(void)
{
    pg_world_def wd = pg_default_world_def();
    wd.max_bodies = 64;
    wd.max_shapes = 96;
    wd.max_contacts = 256;
    return make_world_def(&wd);
}

/* Points from x = 10 to x = -10 (free space on the right of the walk: above), y = 0
 * up to x = 0 and sloping by `bend` degrees beyond (positive: down to the right). */
static void terrain(pg_vec2 *pts, double bend)
{
    int i;
    for (i = 0; i <= SEGMENTS; ++i) {
        double x = 10.0 - i;
        pts[i] = pg_v2(fx(x), fx(x > 0 ? -x * tan(bend * DEG) : 0.0));
    }
}

static slide slide_box(enum ground kind, double speed, double bend)
{
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 pts[SEGMENTS + 1];
    pg_body_id ground, box;
    pg_body_def b = dynamic_at(-9.5, 0.5);
    slide r = {-1e9, 0, 0};
    int i, steps = 0;
    sd.friction = 0;
    terrain(pts, bend);
    if (kind == CHAIN) {
        assert_int_equal(pg_make_chain(t.w, &bd, &sd, pts, SEGMENTS + 1, 0, &ground), PG_OK);
    } else {
        pg_geometry g;
        pg_shape_id s;
        assert_int_equal(pg_body_create(t.w, &bd, &ground), PG_OK);
        for (i = 0; i < (kind == SEPARATE ? SEGMENTS : 1); ++i) {
            assert_int_equal(pg_geometry_segment(pts[kind == SEPARATE ? i + 1 : SEGMENTS], pts[i], &g), PG_OK);
            assert_int_equal(pg_shape_create(t.w, ground, &sd, &g, &s), PG_OK);
        }
    }
    assert_int_equal(pg_make_box(t.w, &b, &sd, fx(1), fx(1), &box), PG_OK);
    for (i = 0; i < 60; ++i) pg_world_step(t.w); /* settle */
    assert_int_equal(pg_body_set_linear_velocity(t.w, box, pg_v2(fx(speed), 0)), PG_OK);
    while (fd(pg_body_position(t.w, box).x) < 9.0 && steps < 3000) {
        double vy;
        pg_world_step(t.w);
        ++steps;
        vy = fd(pg_body_linear_velocity(t.w, box).y);
        if (vy > r.max_up) r.max_up = vy;
    }
    r.end_y = fd(pg_body_position(t.w, box).y);
    r.end_x = fd(pg_body_position(t.w, box).x);
    free_world(&t);
    return r;
}

static const double speeds[] = {1.0, 3.0, 10.0, 30.0};

static void test_flat_chain_has_no_bumps(void **state)
{
    size_t k;
    int bumped = 0;
    (void)state;
    for (k = 0; k < sizeof speeds / sizeof speeds[0]; ++k) {
        slide c = slide_box(CHAIN, speeds[k], 0), one = slide_box(ONE_SEGMENT, speeds[k], 0);
        slide sep = slide_box(SEPARATE, speeds[k], 0);
        PG_EXPECT_LE(c.max_up, 0.01, "speed %g", speeds[k]);
        PG_EXPECT_LE(fabs(c.end_y - one.end_y), 0.001, "%s", "");
        PG_EXPECT_LE(9.0, c.end_x, "%s", ""); /* it crossed every joint */
        PG_EXPECT_LE(one.max_up, 0.01, "%s", "");
        /* the same run on separate segments: the joints' ends kick the box */
        if (sep.max_up > 0.01 || fabs(sep.end_y - one.end_y) > 0.001 || sep.end_x < 9.0) ++bumped;
    }
    assert_int_equal(bumped, (int)(sizeof speeds / sizeof speeds[0]));
}

static void test_bent_chain_has_no_bumps(void **state)
{
    size_t k;
    (void)state;
    for (k = 0; k < sizeof speeds / sizeof speeds[0]; ++k) {
        /* convex joint: the chain bends 1 degree down; nothing pushes the box up */
        slide down = slide_box(CHAIN, speeds[k], 1.0);
        /* concave joint: 1 degree up; the box rises with the slope and no faster */
        slide up = slide_box(CHAIN, speeds[k], -1.0);
        PG_EXPECT_LE(down.max_up, 0.01, "speed %g", speeds[k]);
        PG_EXPECT_LE(up.max_up, 1.05 * speeds[k] * sin(1.0 * DEG) + 0.01, "speed %g", speeds[k]);
    }
}

static void test_ball_rolls_across_joints(void **state)
{
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 pts[SEGMENTS + 1];
    pg_body_id ground, ball;
    pg_body_def b = dynamic_at(-9.5, 0.25);
    double max_up = 0;
    int i;
    (void)state;
    terrain(pts, 0);
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, pts, SEGMENTS + 1, 0, &ground), PG_OK);
    assert_int_equal(pg_make_ball(t.w, &b, &sd, fx(0.25), &ball), PG_OK);
    for (i = 0; i < 30; ++i) pg_world_step(t.w);
    assert_int_equal(pg_body_set_linear_velocity(t.w, ball, pg_v2(fx(8), 0)), PG_OK);
    for (i = 0; i < 120 && fd(pg_body_position(t.w, ball).x) < 9.0; ++i) {
        pg_world_step(t.w);
        if (fd(pg_body_linear_velocity(t.w, ball).y) > max_up) max_up = fd(pg_body_linear_velocity(t.w, ball).y);
    }
    PG_EXPECT_LE(max_up, 0.01, "%s", "");
    PG_EXPECT_LE(fabs(fd(pg_body_position(t.w, ball).y) - 0.25), 0.001, "%s", "");
    free_world(&t);
}

/* One-sided: a box below the chain (on its left, solid side) falls through it. */
static void test_chain_is_one_sided(void **state)
{
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 pts[SEGMENTS + 1];
    pg_body_id ground, box;
    pg_body_def b = dynamic_at(0.3, -2.0);
    int i;
    (void)state;
    terrain(pts, 0);
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, pts, SEGMENTS + 1, 0, &ground), PG_OK);
    b.linear_velocity = pg_v2(0, fx(10)); /* thrown up through it from below */
    assert_int_equal(pg_make_box(t.w, &b, &sd, fx(1), fx(1), &box), PG_OK);
    for (i = 0; i < 30; ++i) pg_world_step(t.w);
    /* it passed through (rising at 10 m/s against g it reaches y = -2 + 5 = 3 m) */
    PG_EXPECT_LE(1.0, fd(pg_body_position(t.w, box).y), "%s", "");
    free_world(&t);
}

/* A ray is stopped by a chain segment only from its front (Box2D v3 casts rays at chain
 * segments one-sided too): from above it hits the flat chain with the normal up, from
 * below it passes through and finds nothing, where a plain segment in the same place is
 * hit from below (so the test can fail). Queries by point and box stay two-sided. */
static void test_rays_are_one_sided(void **state)
{
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 pts[SEGMENTS + 1];
    pg_body_id ground, plain, found[4];
    pg_ray_hit hit;
    pg_geometry seg;
    pg_shape_id shape;
    pg_aabb box;
    uint32_t n = 0;
    (void)state;
    terrain(pts, 0);
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, pts, SEGMENTS + 1, 0, &ground), PG_OK);
    assert_int_equal(pg_world_raycast(t.w, pg_v2(fx(0.5), fx(2)), pg_v2(0, fx(-4)), &hit), PG_OK);
    assert_true(hit.body.index == ground.index);
    PG_EXPECT_EQ(hit.point.y, 0, "%s", "the ray from above stops on the chain");
    PG_EXPECT_EQ(hit.normal.y, PG_FIX_ONE, "%s", "with the chain's normal");
    PG_EXPECT_EQ(hit.fraction, PG_FIX_HALF, "%s", "");
    assert_int_equal(pg_world_raycast(t.w, pg_v2(fx(0.5), fx(-2)), pg_v2(0, fx(4)), &hit), PG_ERR_NOT_FOUND);
    /* from below, slanted across two joints: still nothing */
    assert_int_equal(pg_world_raycast(t.w, pg_v2(fx(-3), fx(-1)), pg_v2(fx(6), fx(2)), &hit), PG_ERR_NOT_FOUND);
    /* a two-sided segment 1 m lower is hit from below */
    bd.position = pg_v2(0, fx(-1));
    assert_int_equal(pg_body_create(t.w, &bd, &plain), PG_OK);
    assert_int_equal(pg_geometry_segment(pg_v2(fx(-5), 0), pg_v2(fx(5), 0), &seg), PG_OK);
    assert_int_equal(pg_shape_create(t.w, plain, &sd, &seg, &shape), PG_OK);
    assert_int_equal(pg_world_raycast(t.w, pg_v2(fx(0.5), fx(-2)), pg_v2(0, fx(4)), &hit), PG_OK);
    assert_true(hit.body.index == plain.index);
    PG_EXPECT_EQ(hit.point.y, fx(-1), "%s", "the plain segment is hit from below");
    /* a box across the chain's line finds it from either side */
    box.lo = pg_v2(fx(0.25), fx(-0.5));
    box.hi = pg_v2(fx(0.75), fx(0.01));
    assert_int_equal(pg_world_query_aabb(t.w, box, found, 4, &n), PG_OK);
    PG_EXPECT_EQ(n, 1, "%s", "the chain, found by a box mostly behind it");
    assert_true(found[0].index == ground.index);
    free_world(&t);
}

/* Continuous collision: a thin plank spinning fast enough for the sweep of continuous.c
 * (a 1 m x 0.1 m plank at 200 rad/s moves its ends 100 m/s, far more than half its
 * thickness a step), thrown up at 10 m/s without gravity from 2 m below the chain,
 * passes through it: exactly as with continuous collision off, 5 m up in 0.5 s but for
 * less than 0.03 m that the chain's contacts push it while its centre crosses, its
 * speed and spin kept. (Stopped at the chain's back, where the sweep of a two-sided
 * segment put it, it stayed there.) Thrown down from 2 m above, its centre never gets
 * behind the chain. */
typedef struct plank_run { double end_y, lowest_y, end_vy, end_w; } plank_run;

static plank_run spinning_plank(double y0, double vy, int continuous)
{
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 pts[SEGMENTS + 1];
    pg_body_id ground, plank;
    pg_body_def b = dynamic_at(0.3, y0);
    plank_run r;
    int i;
    terrain(pts, 0);
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, pts, SEGMENTS + 1, 0, &ground), PG_OK);
    if (!continuous) assert_int_equal(pg_world_set_effects(t.w, pg_world_effects(t.w) & ~PG_EFFECT_CONTINUOUS), PG_OK);
    b.linear_velocity = pg_v2(0, fx(vy));
    b.angular_velocity = fx(200);
    b.gravity_scale = 0;
    assert_int_equal(pg_make_box(t.w, &b, &sd, fx(1), fx(0.1), &plank), PG_OK);
    r.lowest_y = y0;
    for (i = 0; i < 30; ++i) {
        double y;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        y = fd(pg_body_position(t.w, plank).y);
        if (y < r.lowest_y) r.lowest_y = y;
    }
    r.end_y = fd(pg_body_position(t.w, plank).y);
    r.end_vy = fd(pg_body_linear_velocity(t.w, plank).y);
    r.end_w = fd(pg_body_angular_velocity(t.w, plank));
    free_world(&t);
    return r;
}

static void test_continuous_passes_from_behind(void **state)
{
    plank_run up, off, down;
    (void)state;
    up = spinning_plank(-2.0, 10.0, 1);
    off = spinning_plank(-2.0, 10.0, 0);
    down = spinning_plank(2.0, -10.0, 1);
    printf("spinning plank from below: ends at y = %.4f m, %.4f m/s, %.3f rad/s; from above: lowest y = %.4f m\n", up.end_y,
           up.end_vy, up.end_w, down.lowest_y);
    PG_EXPECT_LE(fabs(up.end_y - off.end_y), 0.0, "%s", "continuous collision changes nothing from behind");
    PG_EXPECT_LE(fabs(up.end_y - 3.0), 0.03, "%s", "from behind the chain does not stop it");
    PG_EXPECT_LE(fabs(up.end_vy - 10.0), 0.001, "%s", "nor slow it");
    PG_EXPECT_LE(fabs(up.end_w - 200.0), 0.001, "%s", "nor its spin");
    PG_EXPECT_GE(down.lowest_y, 0.0, "%s", "from the front its centre stays in front");
}

static void test_loop_holds_a_ball(void **state)
{
    /* a clockwise square loop (free space inside): a ball dropped inside stays inside */
    test_world t = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 sq[4];
    pg_body_id ground, ball;
    pg_body_def b = dynamic_at(0, 1);
    int i;
    (void)state;
    sq[0] = pg_v2(fx(-2), fx(-2));
    sq[1] = pg_v2(fx(-2), fx(2));
    sq[2] = pg_v2(fx(2), fx(2));
    sq[3] = pg_v2(fx(2), fx(-2));
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, sq, 4, 1, &ground), PG_OK);
    assert_int_equal(pg_body_shapes(t.w, ground, NULL, 0), 4u);
    b.linear_velocity = pg_v2(fx(5), fx(3));
    assert_int_equal(pg_make_ball(t.w, &b, &sd, fx(0.25), &ball), PG_OK);
    for (i = 0; i < 300; ++i) pg_world_step(t.w);
    PG_EXPECT_LE(fabs(fd(pg_body_position(t.w, ball).x)), 1.76, "%s", "");
    PG_EXPECT_LE(-1.76, fd(pg_body_position(t.w, ball).y), "%s", "");
    PG_EXPECT_LE(fd(pg_body_position(t.w, ball).y), 1.76, "%s", "");
    free_world(&t);
}

static void expect_refused(pg_world *w, const pg_vec2 *pts, int32_t n, int loop, pg_result code, const char *words)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id = {7, 7};
    uint64_t before = pg_world_hash(w);
    assert_int_equal(pg_make_chain(w, &bd, &sd, pts, n, loop, &id), code);
    assert_int_equal(id.index, 0);
    assert_int_equal(id.generation, 0);
    assert_true(pg_world_hash(w) == before);
    if (strstr(pg_world_last_error(w), words) == NULL) fail_msg("'%s' does not say '%s'", pg_world_last_error(w), words);
}

static void test_chain_refusals(void **state)
{
    test_world t = chain_world();
    pg_vec2 p[70];
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id, dyn;
    pg_shape_id sid;
    pg_geometry g;
    int i;
    (void)state;
    for (i = 0; i < 70; ++i) p[i] = pg_v2(fx(-i), 0);
    expect_refused(t.w, p, 1, 0, PG_ERR_INVALID_ARGUMENT, "2..65 points");
    expect_refused(t.w, p, 2, 1, PG_ERR_INVALID_ARGUMENT, "2..65 points");
    expect_refused(t.w, p, 66, 0, PG_ERR_INVALID_ARGUMENT, "2..65 points");
    expect_refused(t.w, p, 65, 1, PG_ERR_INVALID_ARGUMENT, "2..65 points");
    p[3] = p[2];
    expect_refused(t.w, p, 5, 0, PG_ERR_DEGENERATE, "segment 2 ");
    p[3] = pg_v2(fx(-3), fx(1001));
    expect_refused(t.w, p, 5, 0, PG_ERR_ENVELOPE, "point 3 ");
    p[3] = pg_v2(fx(-3), 0);
    assert_int_equal(pg_make_chain(t.w, &bd, &sd, p, 65, 0, &id), PG_OK);
    assert_int_equal(pg_body_shapes(t.w, id, NULL, 0), 64u);
    assert_int_equal(pg_body_type_of(t.w, id), PG_BODY_STATIC);
    /* chain segments stay on static bodies */
    assert_int_equal(pg_body_set_type(t.w, id, PG_BODY_DYNAMIC), PG_ERR_BODY_TYPE);
    bd.type = PG_BODY_DYNAMIC;
    assert_int_equal(pg_body_create(t.w, &bd, &dyn), PG_OK);
    assert_int_equal(pg_geometry_chain_segment(p[0], p[1], p[2], p[3], &g), PG_OK);
    assert_int_equal(pg_shape_create(t.w, dyn, &sd, &g, &sid), PG_ERR_BODY_TYPE);
    /* a neighbour is the segment's own end or an edge's length away */
    assert_int_equal(pg_geometry_chain_segment(pg_v2(p[1].x + 1, 0), p[1], p[2], p[3], &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_chain_segment(p[1], p[1], p[2], p[2], &g), PG_OK);
    free_world(&t);
}

/* The neighbours are state: they decide the normals. Two worlds whose chains differ
 * only in a neighbour hash differently, and a snapshot carries them back. */
static void test_neighbours_in_state(void **state)
{
    test_world a = chain_world(), b = chain_world();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ga, gb;
    pg_shape_id sa, sb;
    pg_geometry g, back;
    unsigned char buf[1 << 16];
    size_t written;
    (void)state;
    assert_int_equal(pg_body_create(a.w, &bd, &ga), PG_OK);
    assert_int_equal(pg_body_create(b.w, &bd, &gb), PG_OK);
    assert_int_equal(pg_geometry_chain_segment(pg_v2(fx(2), fx(0)), pg_v2(fx(1), 0), pg_v2(fx(-1), 0), pg_v2(fx(-2), 0), &g), PG_OK);
    assert_int_equal(pg_shape_create(a.w, ga, &sd, &g, &sa), PG_OK);
    g.vertices[2] = pg_v2(fx(2), fx(1));
    assert_int_equal(pg_shape_create(b.w, gb, &sd, &g, &sb), PG_OK);
    assert_true(pg_world_hash(a.w) != pg_world_hash(b.w));
    assert_int_equal(pg_world_snapshot_save(b.w, buf, sizeof buf, &written), PG_OK);
    assert_int_equal(pg_world_snapshot_restore(a.w, buf, written), PG_OK);
    assert_true(pg_world_hash(a.w) == pg_world_hash(b.w));
    assert_int_equal(pg_shape_geometry(a.w, sa, &back), PG_OK);
    assert_int_equal(back.kind, PG_SHAPE_CHAIN_SEGMENT);
    assert_int_equal(back.vertices[2].y, fx(1));
    assert_int_equal(back.vertices[3].x, fx(-2));
    free_world(&a);
    free_world(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat_chain_has_no_bumps),
        cmocka_unit_test(test_bent_chain_has_no_bumps),
        cmocka_unit_test(test_ball_rolls_across_joints),
        cmocka_unit_test(test_chain_is_one_sided),
        cmocka_unit_test(test_rays_are_one_sided),
        cmocka_unit_test(test_continuous_passes_from_behind),
        cmocka_unit_test(test_loop_holds_a_ball),
        cmocka_unit_test(test_chain_refusals),
        cmocka_unit_test(test_neighbours_in_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
