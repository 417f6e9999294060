/* test_joint_limits.c — revolute and prismatic limits hold their bounds, and motors
 * reach their target speed at their maximum torque or force (docs/joints.md).
 *
 * Limits are soft like every joint row: an overlap is pushed out over a few substeps,
 * so a bound is held within a documented tolerance (LIMIT_ANGLE_TOLERANCE,
 * LIMIT_TRANSLATION_TOLERANCE), measured here at every step. */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"

#define LIMIT_ANGLE_TOLERANCE 0.02       /* rad: docs/joints.md */
#define LIMIT_TRANSLATION_TOLERANCE 0.01 /* m: docs/joints.md */

/* A 2 m bar pinned at its left end to a static body, horizontal at angle 0. */
static pg_joint_id pinned_bar(test_world *t, pg_body_id *bar, double lower, double upper)
{
    pg_body_id pin = static_anchor(t->w, 0.0, 10.0);
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_joint_id j;
    *bar = box_at(t->w, 1.0, 10.0, 2.0, 0.2, 1.0);
    jd.body_a = pin;
    jd.body_b = *bar;
    jd.local_anchor_b = pg_v2(fx(-1.0), 0);
    jd.enable_limit = 1;
    jd.lower_angle = fx(lower);
    jd.upper_angle = fx(upper);
    assert_int_equal(pg_revolute_joint_create(t->w, &jd, &j), PG_OK);
    return j;
}

static void test_revolute_limits_hold(void **state)
{
    test_world t = joint_world(8, 4);
    pg_body_id bar;
    pg_joint_id j = pinned_bar(&t, &bar, -0.5, 0.25);
    double lowest = 10.0, highest = -10.0;
    int step;
    (void)state;
    /* gravity swings it down onto the lower limit, where it rests */
    for (step = 0; step < 180; ++step) {
        double a;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        a = fd(pg_revolute_joint_angle(t.w, j));
        if (a < lowest) lowest = a;
    }
    printf("revolute lower limit -0.5 rad: lowest %.5f rad, at rest %.5f rad\n", lowest, fd(pg_revolute_joint_angle(t.w, j)));
    JT_LE(-0.5 - lowest, LIMIT_ANGLE_TOLERANCE);
    JT_LE(fabs(fd(pg_revolute_joint_angle(t.w, j)) + 0.5), LIMIT_ANGLE_TOLERANCE);
    /* a motor at 5 rad/s and 10 N m (gravity's torque on the bar is 4 N m) drives it up
     * onto the upper limit and keeps pushing */
    assert_int_equal(pg_revolute_joint_set_motor(t.w, j, 1, fx(5.0), fx(10.0)), PG_OK);
    for (step = 0; step < 180; ++step) {
        double a;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        a = fd(pg_revolute_joint_angle(t.w, j));
        if (a > highest) highest = a;
        if (a < lowest) lowest = a;
    }
    printf("revolute upper limit 0.25 rad under a motor: highest %.5f rad, at rest %.5f rad\n", highest, fd(pg_revolute_joint_angle(t.w, j)));
    JT_LE(highest - 0.25, LIMIT_ANGLE_TOLERANCE);
    JT_LE(fabs(fd(pg_revolute_joint_angle(t.w, j)) - 0.25), LIMIT_ANGLE_TOLERANCE);
    JT_LE(-0.5 - lowest, LIMIT_ANGLE_TOLERANCE);
    free_world(&t);
}

static void test_revolute_motor_reaches_its_speed_at_its_torque(void **state)
{
    /* a wheel pinned at its centre: the motor accelerates it at T / I until it turns at
     * the target speed, then holds it there */
    const double target = 10.0, torque = 0.5;
    test_world t = joint_world(8, 4);
    pg_body_id axle = static_anchor(t.w, 0.0, 5.0), wheel = ball_at(t.w, 0.0, 5.0, 0.5, 1.0);
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_joint_id j;
    double inertia = body_inertia(t.w, wheel), expected_time = inertia * target / torque, reached = -1.0, w = 0.0;
    pg_joint_reaction reaction;
    int step;
    (void)state;
    jd.body_a = axle;
    jd.body_b = wheel;
    jd.enable_motor = 1;
    jd.motor_speed = fx(target);
    jd.max_motor_torque = fx(torque);
    assert_int_equal(pg_revolute_joint_create(t.w, &jd, &j), PG_OK);
    for (step = 1; step <= 600; ++step) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        w = fd(pg_body_angular_velocity(t.w, wheel));
        if (reached < 0.0 && w >= target * 0.999) reached = step / 60.0;
        if (step == 30) { /* accelerating: the motor gives all its torque, and the wheel T / I */
            assert_int_equal(pg_joint_get_reaction(t.w, j, &reaction), PG_OK);
            printf("motor torque while accelerating %.4f N m (max %.1f), angular speed %.4f rad/s, analytic %.4f\n",
                   (double)reaction.torque / 65536.0, torque, w, torque / inertia * 0.5);
            JT_LE(fabs((double)reaction.torque / 65536.0 / torque - 1.0), 0.01);
            JT_LE(fabs(w / (torque / inertia * 0.5) - 1.0), 0.01);
        }
    }
    printf("motor: %.4f rad/s after 10 s (target %.1f), reached at %.4f s, analytic %.4f s\n", w, target, reached, expected_time);
    JT_LE(fabs(w - target), 0.001 * target);
    JT_LE(0.0, reached);
    JT_LE(fabs(reached - expected_time), 2.0 / 60.0);
    free_world(&t);
}

/* A box on a prismatic joint along an axis tilted 30 degrees down from +x */
static void test_prismatic_limits_and_motor(void **state)
{
    test_world t = joint_world(8, 4);
    pg_body_id base = static_anchor(t.w, 0.0, 10.0), box = box_at(t.w, 0.0, 10.0, 0.5, 0.5, 1.0);
    pg_prismatic_joint_def jd = pg_default_prismatic_joint_def();
    pg_joint_id j;
    double c = cos(-PGT_PI / 6.0), s = sin(-PGT_PI / 6.0), lowest = 10.0, highest = -10.0, worst_off_axis = 0.0, worst_turn = 0.0;
    int step;
    (void)state;
    jd.body_a = base;
    jd.body_b = box;
    jd.local_axis_a = pg_v2(fx(c * 3.0), fx(s * 3.0)); /* any length */
    jd.enable_limit = 1;
    jd.lower_translation = fx(-1.0);
    jd.upper_translation = fx(1.5);
    assert_int_equal(pg_prismatic_joint_create(t.w, &jd, &j), PG_OK);
    for (step = 0; step < 600; ++step) {
        double tr, dx, dy, off;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        if (step == 120) assert_int_equal(pg_prismatic_joint_set_motor(t.w, j, 1, fx(-2.0), fx(100.0)), PG_OK); /* up the slope */
        tr = fd(pg_prismatic_joint_translation(t.w, j));
        if (tr < lowest) lowest = tr;
        if (tr > highest) highest = tr;
        dx = body_x(t.w, box);
        dy = body_y(t.w, box) - 10.0;
        off = fabs(-s * dx + c * dy); /* distance from the axis line */
        if (off > worst_off_axis) worst_off_axis = off;
        if (fabs(fd(pg_angle_to_radians(pg_body_angle(t.w, box)))) > worst_turn) worst_turn = fabs(fd(pg_angle_to_radians(pg_body_angle(t.w, box))));
        if (step == 119) {
            printf("prismatic: slid down to %.5f m (upper limit 1.5)\n", tr);
            JT_LE(fabs(tr - 1.5), LIMIT_TRANSLATION_TOLERANCE);
        }
        if (step == 150) { /* the motor pulls it up the slope at 2 m/s */
            pg_vec2 v = pg_body_linear_velocity(t.w, box);
            double along = fd(v.x) * c + fd(v.y) * s;
            printf("prismatic motor: %.5f m/s along the axis (target -2)\n", along);
            JT_LE(fabs(along + 2.0), 0.002);
        }
    }
    printf("prismatic: translation within [%.5f, %.5f] (limits -1, 1.5), off the axis up to %.6f m, turned up to %.6f rad, at %.5f m\n", lowest,
           highest, worst_off_axis, worst_turn, fd(pg_prismatic_joint_translation(t.w, j)));
    JT_LE(-1.0 - lowest, LIMIT_TRANSLATION_TOLERANCE);
    JT_LE(highest - 1.5, LIMIT_TRANSLATION_TOLERANCE);
    JT_LE(fabs(fd(pg_prismatic_joint_translation(t.w, j)) + 1.0), LIMIT_TRANSLATION_TOLERANCE);
    JT_LE(worst_off_axis, LIMIT_TRANSLATION_TOLERANCE);
    JT_LE(worst_turn, LIMIT_ANGLE_TOLERANCE);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_revolute_limits_hold),
        cmocka_unit_test(test_revolute_motor_reaches_its_speed_at_its_torque),
        cmocka_unit_test(test_prismatic_limits_and_motor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
