/* test_limits.c — the envelope's caps are kept by the step and reported.
 *
 * Whatever leaves a step is something the API accepts back: no body's speed exceeds
 * max_linear_speed and no angular velocity 1000 rad/s, each clamp is counted
 * (stats.speed_clamps, spin_clamps) and flagged (pg_body_limits), every getter's value
 * is accepted by its setter, and a scene written mid-flight loads. A body carried past
 * +-1000 m is counted (stats.envelope_exits) and flagged. Dropped contacts are counted
 * one by one (stats.capacity_misses), and so are the values a step clamps to the range of
 * its formats (stats.saturations). */
#include "pg_test.h"
#include "pg_test_world.h"

#include "pogon/replay.h"
#include "pogon/scene_file.h"

/* |v|^2 <= cap^2, exactly (Q32). */
static int within_cap(pg_vec2 v, pg_fix cap)
{
    uint64_t x = (uint64_t)llabs((long long)v.x), y = (uint64_t)llabs((long long)v.y), c = (uint64_t)cap;
    return x * x + y * y <= c * c;
}

/* Every body's velocities are within the caps and accepted back by their setters. */
static void expect_motion_accepted(pg_world *w, const pg_body_id *bodies, int n, int step)
{
    pg_fix cap = pg_world_get_def(w).max_linear_speed;
    int i;
    for (i = 0; i < n; ++i) {
        pg_vec2 v = pg_body_linear_velocity(w, bodies[i]);
        pg_fix av = pg_body_angular_velocity(w, bodies[i]);
        if (!within_cap(v, cap)) {
            print_error("step %d body %d: velocity (%.5f, %.5f) m/s, speed %.5f above the cap %.5f\n", step, i, fd(v.x), fd(v.y),
                        sqrt(fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y)), fd(cap));
            fail();
        }
        PG_EXPECT_LE(fabs(fd(av)), 1000.0, "step %d body %d angular velocity", step, i);
        if (pg_body_type_of(w, bodies[i]) == PG_BODY_STATIC) continue;
        PG_EXPECT_EQ(pg_body_set_linear_velocity(w, bodies[i], v), PG_OK, "step %d body %d: setter refuses the getter's value", step, i);
        PG_EXPECT_EQ(pg_body_set_angular_velocity(w, bodies[i], av), PG_OK, "step %d body %d: setter refuses the getter's value", step, i);
    }
}

/* A scene written now loads into a fresh world (its settings, every body). */
static void expect_scene_loads(pg_world *w)
{
    size_t n = pg_scene_write(w, NULL, 0);
    char *text = malloc(n + 1);
    pg_world_def d;
    pg_scene_error err;
    test_world t;
    assert_non_null(text);
    assert_int_equal(pg_scene_write(w, text, n + 1), n);
    if (pg_scene_read_def(text, n, &d, &err) != PG_OK) {
        print_error("a scene written mid-flight does not read: %s\n", err.message);
        fail();
    }
    t = make_world_def(&d);
    if (pg_scene_load(t.w, text, n, &err) != PG_OK) {
        print_error("a scene written mid-flight does not load: %s\n", err.message);
        fail();
    }
    free_world(&t);
    free(text);
}

/* The case: a heavy box (density 100) at +400 m/s meets a light plank and a
 * light box (density 0.1) at -400 m/s, no gravity. The contact solve throws the light
 * box back at more than the cap (407.6 m/s before the fix, for 10 000 steps). */
static void test_heavy_meets_light_at_the_cap(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def heavy = pg_default_shape_def(), light = pg_default_shape_def();
    pg_body_def bd;
    pg_body_id b[3];
    int i, flagged = 0;
    (void)state;
    d.gravity = pg_v2_zero();
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 32;
    t = make_world_def(&d);
    heavy.density = PG_FIX_C(100);
    light.density = fx(0.1);
    bd = dynamic_at(-10, 0);
    bd.linear_velocity = pg_v2(PG_FIX_C(400), 0);
    assert_int_equal(pg_make_box(t.w, &bd, &heavy, PG_FIX_C(1), PG_FIX_C(1), &b[0]), PG_OK);
    bd = dynamic_at(10, 0);
    bd.linear_velocity = pg_v2(-PG_FIX_C(400), 0);
    assert_int_equal(pg_make_box(t.w, &bd, &light, fx(0.2), PG_FIX_C(2), &b[1]), PG_OK);
    bd = dynamic_at(10.6, 0);
    bd.linear_velocity = pg_v2(-PG_FIX_C(400), 0);
    assert_int_equal(pg_make_box(t.w, &bd, &light, PG_FIX_C(1), PG_FIX_C(1), &b[2]), PG_OK);
    for (i = 1; i <= 600; ++i) {
        int k;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        for (k = 0; k < 3; ++k) flagged |= (pg_body_limits(t.w, b[k]) & PG_BODY_LIMIT_SPEED_CLAMPED) != 0;
        expect_motion_accepted(t.w, b, 3, i);
        if (i == 3) expect_scene_loads(t.w);
    }
    print_message("heavy meets light: %u speed clamps\n", (unsigned)pg_world_get_stats(t.w).speed_clamps);
    assert_true(pg_world_get_stats(t.w).speed_clamps > 0); /* the collision did exceed the cap */
    assert_true(flagged);
    free_world(&t);
}

/* Three boxes on one spot with a small cap (0.1875 m/s): the push-out alone would throw
 * them at several times the cap in the first step (6.2 times before the fix). */
static void test_overlapping_bodies_with_a_small_cap(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id b[3];
    int i;
    (void)state;
    d.max_linear_speed = fx(0.1875);
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 32;
    t = make_world_def(&d);
    for (i = 0; i < 3; ++i) {
        pg_body_def bd = dynamic_at(0.1 * i, 1 + 0.05 * i);
        assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_C(1), PG_FIX_C(1), &b[i]), PG_OK);
    }
    for (i = 1; i <= 120; ++i) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        expect_motion_accepted(t.w, b, 3, i);
        if (i == 1) expect_scene_loads(t.w);
    }
    assert_true(pg_world_get_stats(t.w).speed_clamps > 0);
    free_world(&t);
}

/* A heavy box at 400 m/s strikes a small light box (0.05 m, density 0.1) off its centre:
 * the contact throws it into a spin far beyond 1000 rad/s, which the step clamps and
 * counts (1 656 rad/s were seen before the fix). */
static void test_spin_stays_within_its_limit(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def heavy = pg_default_shape_def(), light = pg_default_shape_def();
    pg_body_def bd;
    pg_body_id b[2];
    int i, flagged = 0;
    (void)state;
    d.gravity = pg_v2_zero();
    d.max_bodies = 4;
    d.max_shapes = 4;
    d.max_contacts = 16;
    t = make_world_def(&d);
    heavy.density = PG_FIX_C(100);
    light.density = fx(0.1);
    bd = dynamic_at(0, 0);
    assert_int_equal(pg_make_box(t.w, &bd, &light, fx(0.05), fx(0.05), &b[0]), PG_OK);
    bd = dynamic_at(-5, 0.51);
    bd.linear_velocity = pg_v2(PG_FIX_C(400), 0);
    assert_int_equal(pg_make_box(t.w, &bd, &heavy, PG_FIX_C(1), PG_FIX_C(1), &b[1]), PG_OK);
    for (i = 1; i <= 60; ++i) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        flagged |= (pg_body_limits(t.w, b[0]) & PG_BODY_LIMIT_SPIN_CLAMPED) != 0;
        expect_motion_accepted(t.w, b, 2, i);
    }
    print_message("spin: %u spin clamps\n", (unsigned)pg_world_get_stats(t.w).spin_clamps);
    assert_true(pg_world_get_stats(t.w).spin_clamps > 0);
    assert_true(flagged);
    free_world(&t);
}

/* An angular impulse past the limit is clamped, counted and flagged; the next step
 * that does not clamp clears the flag. */
static void test_angular_impulse_clamp_is_reported(void **state)
{
    test_world t;
    pg_world_def d = pg_default_world_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id b;
    (void)state;
    d.gravity = pg_v2_zero();
    t = make_world_def(&d);
    assert_int_equal(pg_make_box(t.w, &bd, &sd, PG_FIX_C(1), PG_FIX_C(1), &b), PG_OK);
    assert_int_equal(pg_body_limits(t.w, b), 0);
    assert_int_equal(pg_body_apply_angular_impulse(t.w, b, PG_FIX_C(1000)), PG_OK);
    assert_int_equal(pg_body_angular_velocity(t.w, b), PG_FIX_C(1000));
    assert_int_equal(pg_world_get_stats(t.w).spin_clamps, 1);
    assert_int_equal(pg_body_limits(t.w, b), PG_BODY_LIMIT_SPIN_CLAMPED);
    assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_body_limits(t.w, b), 0);
    assert_int_equal(pg_world_get_stats(t.w).spin_clamps, 1);
    free_world(&t);
}

/* A body flung out of the envelope (400 m/s from 990 m) is counted once as it leaves and
 * flagged for as long as it is out; before, it flew on silently and pinned at 32768 m. */
static void test_leaving_the_envelope_is_reported(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(990, 0);
    pg_body_id b, still;
    int i, left_at = 0;
    (void)state;
    d.gravity = pg_v2_zero();
    t = make_world_def(&d);
    bd.linear_velocity = pg_v2(PG_FIX_C(400), 0);
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, PG_FIX_HALF, &b), PG_OK);
    bd = dynamic_at(0, 0);
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, PG_FIX_HALF, &still), PG_OK);
    for (i = 1; i <= 6000; ++i) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        if (left_at == 0 && (pg_body_limits(t.w, b) & PG_BODY_LIMIT_OUTSIDE) != 0) left_at = i;
        assert_int_equal(pg_body_limits(t.w, still), 0);
    }
    /* 10 m at 400 m/s: 1.5 steps at 60 Hz; it leaves in step 2 */
    assert_int_equal(left_at, 2);
    assert_int_equal(pg_world_get_stats(t.w).envelope_exits, 1);
    assert_int_equal(pg_body_limits(t.w, b), PG_BODY_LIMIT_OUTSIDE);
    assert_true(pg_body_position(t.w, b).x > PG_FIX_C(1000));
    free_world(&t);
}

/* capacity_misses counts the contacts dropped, not the steps that dropped some: 40 balls
 * resting in one overlapping heap want hundreds of contacts, a world holds 8. */
static void test_capacity_misses_counts_each_dropped_contact(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def sd = pg_default_shape_def();
    int i;
    pg_world_stats st;
    (void)state;
    d.gravity = pg_v2_zero();
    d.max_bodies = 64;
    d.max_shapes = 64;
    d.max_contacts = 8;
    t = make_world_def(&d);
    for (i = 0; i < 40; ++i) {
        pg_body_def bd = dynamic_at(0.01 * i, 0);
        pg_body_id b;
        assert_int_equal(pg_make_ball(t.w, &bd, &sd, PG_FIX_C(2), &b), PG_OK);
    }
    assert_int_equal(pg_world_step(t.w), PG_OK);
    st = pg_world_get_stats(t.w);
    print_message("one step: %u pairs, %u contacts kept, %u misses\n", (unsigned)st.pair_count, (unsigned)st.contact_count,
                  (unsigned)st.capacity_misses);
    /* every pair of the 40 overlapping balls (780) is a contact the world could not keep,
     * but for the 8 it kept */
    assert_int_equal(st.contact_count, 8);
    assert_int_equal(st.capacity_misses, 40 * 39 / 2 - 8);
    free_world(&t);
}

/* A force far beyond the envelope on a light ball (32767 N on 7.9e-4 kg) gives an
 * acceleration past Q16.16: one saturation for that body in that step, none once the
 * force is spent, and none in an ordinary step. */
static void test_force_past_the_format_is_counted(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id b;
    (void)state;
    d.gravity = pg_v2_zero();
    t = make_world_def(&d);
    sd.density = fx(0.1);
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, fx(0.05), &b), PG_OK);
    assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_world_get_stats(t.w).saturations, 0);
    assert_int_equal(pg_body_apply_force(t.w, b, pg_v2(PG_FIX_C(1), 0)), PG_OK); /* 1270 m/s^2: fits */
    assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_world_get_stats(t.w).saturations, 0);
    assert_int_equal(pg_body_apply_force(t.w, b, pg_v2(PG_FIX_MAX, 0)), PG_OK);
    assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_world_get_stats(t.w).saturations, 1);
    assert_true(pg_world_get_stats(t.w).speed_clamps > 0); /* and the speed cap then holds it */
    assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_world_get_stats(t.w).saturations, 1);
    free_world(&t);
}

/* A heavy box and a light ball meet head-on, bouncing (restitution 1), no gravity. At the
 * largest max_linear_speed (4096 m/s each way) the bounce wants a change of relative
 * velocity of 16384 m/s, twice the solver's bound on a contact impulse (8192 m/s): the
 * impulse is held there, and counted. At the default 400 m/s nothing is. */
static void test_impulse_at_the_solver_bound_is_counted(void **state)
{
    int fast;
    (void)state;
    for (fast = 0; fast < 2; ++fast) {
        pg_world_def d = pg_default_world_def();
        test_world t;
        pg_shape_def heavy = pg_default_shape_def(), light = pg_default_shape_def();
        pg_fix speed = fast ? PG_FIX_C(4096) : PG_FIX_C(400);
        pg_body_def bd;
        pg_body_id box, ball;
        int i;
        d.gravity = pg_v2_zero();
        d.max_linear_speed = PG_FIX_C(4096);
        d.max_bodies = 8;
        d.max_shapes = 8;
        d.max_contacts = 32;
        t = make_world_def(&d);
        heavy.density = PG_FIX_C(100);
        light.density = fx(0.1);
        heavy.restitution = light.restitution = PG_FIX_ONE;
        bd = dynamic_at(-200, 0);
        bd.linear_velocity = pg_v2(speed, 0);
        assert_int_equal(pg_make_box(t.w, &bd, &heavy, PG_FIX_C(10), PG_FIX_C(10), &box), PG_OK);
        bd = dynamic_at(200, 0);
        bd.linear_velocity = pg_v2(-speed, 0);
        assert_int_equal(pg_make_ball(t.w, &bd, &light, PG_FIX_HALF, &ball), PG_OK);
        for (i = 0; i < 60; ++i) assert_int_equal(pg_world_step(t.w), PG_OK);
        /* they met: the ball flies away ahead of the box */
        assert_true(pg_body_linear_velocity(t.w, ball).x > 0);
        print_message("head-on at %d m/s: %u saturations\n", fast ? 4096 : 400, (unsigned)pg_world_get_stats(t.w).saturations);
        if (fast) assert_true(pg_world_get_stats(t.w).saturations > 0);
        else assert_int_equal(pg_world_get_stats(t.w).saturations, 0);
        free_world(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_heavy_meets_light_at_the_cap),
        cmocka_unit_test(test_overlapping_bodies_with_a_small_cap),
        cmocka_unit_test(test_spin_stays_within_its_limit),
        cmocka_unit_test(test_angular_impulse_clamp_is_reported),
        cmocka_unit_test(test_leaving_the_envelope_is_reported),
        cmocka_unit_test(test_capacity_misses_counts_each_dropped_contact),
        cmocka_unit_test(test_force_past_the_format_is_counted),
        cmocka_unit_test(test_impulse_at_the_solver_bound_is_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
