/* test_hostile_input.c — what an audit's hostile client found in the body and shape API,
 * each a case that crashed (UBSan), accepted what it should refuse, or refused without
 * saying what to change. Every refused call must leave the world as it was (same state
 * hash) and leave a message that starts with the code's name and names the value or the
 * parameter at fault. The sanitizer preset (debug-asan) runs this file with
 * -fsanitize=undefined: the overflow cases fail there, not by an assertion. */
#include "pg_test.h"

#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pg_test_world.h"

static test_world world_without_gravity(void)
{
    pg_world_def d = pg_default_world_def();
    d.gravity = pg_v2(0, 0);
    d.max_bodies = 16;
    d.max_shapes = 32;
    d.max_contacts = 64;
    return make_world_def(&d);
}

/* r is `want`, the world's hash is `hash`, and the message starts with the code's name
 * and contains `needle`. */
static void expect_refused(const test_world *t, pg_result r, pg_result want, uint64_t hash, const char *needle, const char *what)
{
    const char *msg = pg_world_last_error(t->w);
    if (r != want) fail_msg("%s: got %s, want %s (\"%s\")", what, pg_result_name(r), pg_result_name(want), msg);
    if (strncmp(msg, pg_result_name(want), strlen(pg_result_name(want))) != 0) fail_msg("%s: message \"%s\"", what, msg);
    if (strstr(msg, needle) == NULL) fail_msg("%s: message \"%s\" does not say \"%s\"", what, msg, needle);
    if (pg_world_hash(t->w) != hash) fail_msg("%s: the world changed", what);
    print_message("%s: %s\n", what, msg);
}

/* |v|^2 <= cap^2, exactly, in integers */
static int within_cap(pg_vec2 v, pg_fix cap)
{
    int64_t x = v.x, y = v.y, c = cap;
    return (uint64_t)(x * x) + (uint64_t)(y * y) <= (uint64_t)(c * c);
}

/* A velocity of INT32_MIN components: its squared length, 2^63, overflowed int64. */
static void test_most_negative_velocity_is_refused(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id box, refused;
    uint64_t hash;
    (void)state;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK);
    hash = pg_world_hash(t.w);
    bd.linear_velocity = pg_v2(INT32_MIN, INT32_MIN);
    expect_refused(&t, pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &refused), PG_ERR_ENVELOPE, hash, "max_linear_speed 400 m/s",
                   "body def with velocity (INT32_MIN, INT32_MIN)");
    expect_refused(&t, pg_body_set_linear_velocity(t.w, box, pg_v2(INT32_MIN, INT32_MIN)), PG_ERR_ENVELOPE, hash, "max_linear_speed",
                   "pg_body_set_linear_velocity (INT32_MIN, INT32_MIN)");
    free_world(&t);
}

/* An impulse far beyond the cap leaves the body at the cap, never above it (the clamp
 * rounds toward zero), so its own velocity can be set again. Before, the length used to
 * scale was saturated at 32768 m/s and (PG_FIX_MAX, PG_FIX_MIN) came out at 565.7 m/s. */
static void test_clamped_velocity_is_within_the_cap(void **state)
{
    test_world t = world_without_gravity();
    pg_world_def d = pg_world_get_def(t.w);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id box;
    pg_vec2 v;
    static const pg_vec2 impulses[] = {{PG_FIX_MAX, PG_FIX_MIN}, {PG_FIX_C(3000), PG_FIX_C(1)}, {-PG_FIX_C(777), PG_FIX_C(999)}};
    size_t k;
    (void)state;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK); /* 1 kg */
    for (k = 0; k < sizeof impulses / sizeof impulses[0]; ++k) {
        double want_x, want_y, len = hypot(fd(impulses[k].x), fd(impulses[k].y));
        assert_int_equal(pg_body_set_linear_velocity(t.w, box, pg_v2(0, 0)), PG_OK);
        assert_int_equal(pg_body_apply_linear_impulse(t.w, box, impulses[k], pg_body_position(t.w, box)), PG_OK);
        v = pg_body_linear_velocity(t.w, box);
        want_x = fd(impulses[k].x) / len * fd(d.max_linear_speed);
        want_y = fd(impulses[k].y) / len * fd(d.max_linear_speed);
        print_message("impulse (%.1f, %.1f) on 1 kg: v = (%.5f, %.5f), |v| = %.6f m/s (cap %.0f)\n", fd(impulses[k].x), fd(impulses[k].y), fd(v.x),
                      fd(v.y), hypot(fd(v.x), fd(v.y)), fd(d.max_linear_speed));
        assert_true(within_cap(v, d.max_linear_speed));
        /* the direction is kept: each component within 2 LSB of the exact scaled one */
        assert_true(fabs(fd(v.x) - want_x) <= 2.0 / 65536.0 && fabs(fd(v.y) - want_y) <= 2.0 / 65536.0);
        assert_int_equal(pg_body_set_linear_velocity(t.w, box, v), PG_OK);
    }
    assert_true(pg_world_get_stats(t.w).speed_clamps >= 3u);
    free_world(&t);
}

/* A body that flew out to the saturated edge (+-32768 m) and a force at a point inside
 * the envelope: the lever arm reaches 2^32 in Q16.16 and r x F overflowed int64. */
static void test_force_at_a_point_on_a_body_far_outside(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(999, 999);
    pg_body_id box;
    int i;
    (void)state;
    bd.linear_velocity = pg_v2(PG_FIX_C(280), PG_FIX_C(280));
    bd.allow_sleep = 0;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK);
    for (i = 0; i < 7200 && pg_body_position(t.w, box).x < PG_FIX_C(32700); ++i) assert_int_equal(pg_world_step(t.w), PG_OK);
    print_message("the box reached (%.1f, %.1f) m after %d steps\n", fd(pg_body_position(t.w, box).x), fd(pg_body_position(t.w, box).y), i);
    assert_true(pg_body_position(t.w, box).x >= PG_FIX_C(32700));
    assert_int_equal(pg_body_apply_force_at(t.w, box, pg_v2(PG_FIX_MAX, PG_FIX_MIN), pg_v2(-PG_FIX_C(1000), -PG_FIX_C(1000))), PG_OK);
    assert_int_equal(pg_body_apply_linear_impulse(t.w, box, pg_v2(PG_FIX_MAX, PG_FIX_MIN), pg_v2(-PG_FIX_C(1000), -PG_FIX_C(1000))), PG_OK);
    /* the torque of the impulse, far beyond what the envelope allows, is clamped */
    assert_true(pg_body_angular_velocity(t.w, box) == PG_FIX_C(1000) || pg_body_angular_velocity(t.w, box) == -PG_FIX_C(1000));
    assert_int_equal(pg_world_step(t.w), PG_OK);
    free_world(&t);
}

/* The widest speculative window the envelope allows: step_hz 1, max_linear_speed 4096 m/s,
 * continuous collision on. Two bodies meeting head-on at full speed close at 8192 m/s
 * and get a window of 8192 m, past the 2^28 raw (4096 m) that collide.c's bounds were
 * first written for; stopping them takes a row's lambda of 8192 m/s, four times the
 * solver's old LAMBDA_MAX (they passed through each other untouched). Every pair of
 * shape kinds must collide without overflow (UBSan in the debug-asan preset) and
 * exchange an impulse in the step they meet, and a ball must stay on its side of a ball
 * or a box face it hits square on (a triangle or a star turns a slanted face to it, so
 * it glances off and flies on). Two boxes do not stay apart at this corner of the
 * envelope: the two points of their face contact are solved together and each row's
 * lambda is its point's share of the blow times its own row's K, 1.25 times the closing
 * speed for two 1 m boxes, past LAMBDA_MAX; up to 2048 m/s each at 1 Hz, and at 4096 m/s
 * each at 60 Hz, they stop touching (docs/hard-cases.md, "Head-on boxes"). */
static void test_widest_speculative_window(void **state)
{
    typedef pg_result (*maker)(pg_world *, const pg_body_def *, const pg_shape_def *, pg_fix, pg_body_id *);
    static const char *const names[] = {"ball", "box", "triangle", "star"};
    int ka, kb;
    (void)state;
    for (ka = 0; ka < 4; ++ka)
        for (kb = 0; kb < 4; ++kb) {
            pg_world_def d = pg_default_world_def();
            test_world t;
            pg_shape_def sd = pg_default_shape_def();
            pg_body_def bd;
            pg_body_id body[2];
            const pg_fix speed = PG_FIX_C(4096);
            int i;
            d.gravity = pg_v2(0, 0);
            d.step_hz = 1;
            d.max_linear_speed = speed;
            d.max_bodies = 4;
            d.max_shapes = 4;
            d.max_contacts = 8;
            t = make_world_def(&d);
            for (i = 0; i < 2; ++i) {
                int kind = i == 0 ? ka : kb;
                pg_result r;
                bd = dynamic_at(i == 0 ? -700.0 : 700.0, 0);
                bd.linear_velocity = pg_v2(i == 0 ? speed : -speed, 0);
                bd.allow_sleep = 0;
                if (kind == 1) r = pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &body[i]);
                else {
                    maker m = kind == 0 ? pg_make_ball : kind == 2 ? pg_make_triangle : pg_make_star;
                    r = m(t.w, &bd, &sd, PG_FIX_ONE / 2, &body[i]);
                }
                assert_int_equal(r, PG_OK);
            }
            for (i = 0; i < 4; ++i) {
                pg_vec2 pa, pb, va;
                assert_int_equal(pg_world_step(t.w), PG_OK);
                pa = pg_body_position(t.w, body[0]);
                pb = pg_body_position(t.w, body[1]);
                va = pg_body_linear_velocity(t.w, body[0]);
                print_message("%s against %s, step %d: a at (%.1f, %.1f) moving (%.1f, %.1f); b at (%.1f, %.1f)\n", names[ka], names[kb], i + 1,
                              fd(pa.x), fd(pa.y), fd(va.x), fd(va.y), fd(pb.x), fd(pb.y));
                if (i == 0 && va.x > PG_FIX_C(3000)) fail_msg("%s against %s: no impulse in the step they met", names[ka], names[kb]);
                if (ka < 2 && kb < 2 && (ka == 0 || kb == 0) && pa.x >= pb.x) fail_msg("%s against %s: passed through at step %d", names[ka], names[kb], i + 1);
            }
            free_world(&t);
        }
}

/* A static body becoming dynamic: its shapes' densities must be a dynamic body's. Before,
 * a density-0 wall became a 1 kg point that never turned. */
static void test_set_type_checks_the_densities(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = pg_default_body_def();
    pg_body_id wall;
    uint64_t hash;
    (void)state;
    sd.density = 0;
    assert_int_equal(pg_make_wall(t.w, &bd, &sd, PG_FIX_C(4), PG_FIX_ONE, &wall), PG_OK);
    hash = pg_world_hash(t.w);
    expect_refused(&t, pg_body_set_type(t.w, wall, PG_BODY_DYNAMIC), PG_ERR_ENVELOPE, hash, "pg_body_set_density",
                   "a density-0 wall made dynamic");
    assert_int_equal(pg_body_type_of(t.w, wall), PG_BODY_STATIC);
    assert_int_equal(pg_body_set_density(t.w, wall, PG_FIX_ONE), PG_OK);
    assert_int_equal(pg_body_set_type(t.w, wall, PG_BODY_DYNAMIC), PG_OK);
    assert_true(pg_body_mass(t.w, wall) == (int64_t)4 << 32); /* 4 m x 1 m at 1 kg/m^2 */
    free_world(&t);
}

/* A static body cannot move: a def with a velocity is refused, as the scene reader
 * refuses it; pg_make_wall, static by name, ignores the velocity of the def it is given. */
static void test_static_body_with_velocity_is_refused(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = pg_default_body_def();
    pg_body_id id;
    uint64_t hash = pg_world_hash(t.w);
    (void)state;
    bd.linear_velocity = pg_v2(PG_FIX_ONE, 0);
    expect_refused(&t, pg_body_create(t.w, &bd, &id), PG_ERR_BODY_TYPE, hash, "kinematic", "static body def with a velocity");
    bd.linear_velocity = pg_v2(0, 0);
    bd.angular_velocity = PG_FIX_ONE;
    expect_refused(&t, pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_ERR_BODY_TYPE, hash, "angular_velocity",
                   "static box with an angular velocity");
    bd = dynamic_at(0, 0);
    bd.linear_velocity = pg_v2(PG_FIX_ONE, 0);
    assert_int_equal(pg_make_wall(t.w, &bd, &sd, PG_FIX_C(2), PG_FIX_ONE, &id), PG_OK);
    assert_int_equal(pg_body_type_of(t.w, id), PG_BODY_STATIC);
    assert_true(pg_v2_equal(pg_body_linear_velocity(t.w, id), pg_v2(0, 0)));
    free_world(&t);
}

/* A geometry filled in by hand: a clockwise polygon whose first and last vertices share
 * their x passed the old check, which compared only vertex 0's x with the reordered
 * copy, and the body fell through the ground. Unused vertex slots are not state: they
 * are stored as zero whatever the caller left there. */
static void test_hand_built_geometry(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id body;
    pg_shape_id shape;
    pg_geometry g, back;
    uint64_t hash;
    int i;
    (void)state;
    assert_int_equal(pg_body_create(t.w, &bd, &body), PG_OK);
    hash = pg_world_hash(t.w);
    memset(&g, 0, sizeof g);
    g.kind = PG_SHAPE_POLYGON;
    g.count = 3;
    g.vertices[0] = pg_v2(0, 0);
    g.vertices[1] = pg_v2(PG_FIX_ONE, -PG_FIX_ONE);
    g.vertices[2] = pg_v2(0, -PG_FIX_C(2));
    expect_refused(&t, pg_shape_create(t.w, body, &sd, &g, &shape), PG_ERR_NOT_CONVEX, hash, "counter-clockwise",
                   "clockwise triangle (0,0) (1,-1) (0,-2)");
    g.kind = PG_SHAPE_CIRCLE;
    g.count = 2;
    g.radius = PG_FIX_HALF;
    expect_refused(&t, pg_shape_create(t.w, body, &sd, &g, &shape), PG_ERR_INVALID_ARGUMENT, hash, "circle 1 vertex", "circle with 2 vertices");
    g.count = 1;
    g.radius = 0;
    expect_refused(&t, pg_shape_create(t.w, body, &sd, &g, &shape), PG_ERR_DEGENERATE, hash, "radius", "circle of radius 0");
    g.radius = PG_FIX_HALF;
    for (i = 1; i < 8; ++i) g.vertices[i] = pg_v2(PG_FIX_C(7) * i, -PG_FIX_C(3) * i); /* garbage in the unused slots */
    assert_int_equal(pg_shape_create(t.w, body, &sd, &g, &shape), PG_OK);
    assert_int_equal(pg_shape_geometry(t.w, shape, &back), PG_OK);
    assert_int_equal(back.count, 1);
    assert_true(pg_v2_equal(back.vertices[0], pg_v2(0, 0)));
    for (i = 1; i < 8; ++i) assert_true(pg_v2_equal(back.vertices[i], pg_v2(0, 0)));
    free_world(&t);
}

/* PG_ERR_NULL with a world at hand says which parameter was NULL, and the messages of
 * envelope refusals carry the value at fault. */
static void test_messages_name_the_fault(void **state)
{
    test_world t = world_without_gravity();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id box, refused;
    pg_shape_id shape, refused_shape;
    pg_geometry g;
    uint64_t hash;
    (void)state;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), PG_OK);
    assert_int_equal(pg_body_shapes(t.w, box, &shape, 1), 1);
    assert_int_equal(pg_geometry_circle(pg_v2(0, 0), PG_FIX_HALF, &g), PG_OK);
    hash = pg_world_hash(t.w);
    expect_refused(&t, pg_body_create(t.w, NULL, &refused), PG_ERR_NULL, hash, "def is NULL", "pg_body_create without a def");
    expect_refused(&t, pg_body_create(t.w, &bd, NULL), PG_ERR_NULL, hash, "out is NULL", "pg_body_create without out");
    expect_refused(&t, pg_shape_create(t.w, box, &sd, NULL, &refused_shape), PG_ERR_NULL, hash, "geometry is NULL", "pg_shape_create without a geometry");
    expect_refused(&t, pg_make_ball(t.w, &bd, NULL, PG_FIX_ONE, &refused), PG_ERR_NULL, hash, "shape def is NULL", "pg_make_ball without a shape def");
    expect_refused(&t, pg_make_wall(t.w, NULL, &sd, PG_FIX_ONE, PG_FIX_ONE, &refused), PG_ERR_NULL, hash, "body def is NULL", "pg_make_wall without a body def");
    expect_refused(&t, pg_shape_geometry(t.w, shape, NULL), PG_ERR_NULL, hash, "out is NULL", "pg_shape_geometry without out");
    expect_refused(&t, pg_body_set_damping(t.w, box, 0, PG_FIX_C(2000)), PG_ERR_ENVELOPE, hash, "angular damping 2000", "angular damping 2000");
    expect_refused(&t, pg_body_set_transform(t.w, box, pg_v2(0, PG_FIX_C(1001)), 0), PG_ERR_ENVELOPE, hash, "1001", "transform to y = 1001");
    expect_refused(&t, pg_world_set_gravity(t.w, pg_v2(0, -PG_FIX_C(1500))), PG_ERR_ENVELOPE, hash, "-1500", "gravity y -1500");
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_most_negative_velocity_is_refused),
        cmocka_unit_test(test_clamped_velocity_is_within_the_cap),
        cmocka_unit_test(test_force_at_a_point_on_a_body_far_outside),
        cmocka_unit_test(test_widest_speculative_window),
        cmocka_unit_test(test_set_type_checks_the_densities),
        cmocka_unit_test(test_static_body_with_velocity_is_refused),
        cmocka_unit_test(test_hand_built_geometry),
        cmocka_unit_test(test_messages_name_the_fault),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
