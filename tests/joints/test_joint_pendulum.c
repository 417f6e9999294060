/* test_joint_pendulum.c — pendulums swing with their analytic periods, and a rigid rod
 * keeps its length (docs/joints.md, "Tolerances").
 *
 * A ball on a distance joint (a rod to its centre, which leaves the ball free to turn,
 * so it swings as a point mass) has the period 2 pi sqrt(L / g) for small amplitudes; a
 * ball pinned by a revolute joint at a point L from its centre turns with the swing, a
 * physical pendulum of period 2 pi sqrt((L^2 + k^2) / (g L)), k^2 = r^2 / 2 its radius
 * of gyration squared. Both are measured over 20 periods from the times the bob crosses
 * the vertical (interpolated between steps), starting 5 degrees out, where the finite
 * amplitude lengthens the period by 1 + theta^2 / 16 = 1.0005 (included). */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"

#define ROD_LENGTH_TOLERANCE 0.001 /* m: docs/joints.md */

/* The mean period of 20 swings of `bob` about x = pivot_x, from the crossings of the
 * vertical, and the largest deviation of the anchor distance from `length` (when
 * `rod_error` is not NULL). */
static double measure_period(pg_world *w, pg_body_id bob, double pivot_x, double pivot_y, double length, double *rod_error)
{
    double prev = body_x(w, bob) - pivot_x, t = 0.0, first = -1.0, last = -1.0, dt = 1.0 / 60.0, worst = 0.0;
    int crossings = 0, step;
    for (step = 0; step < 60 * 60 && crossings < 41; ++step) {
        double x, dx, dy, err;
        assert_int_equal(pg_world_step(w), PG_OK);
        t += dt;
        x = body_x(w, bob) - pivot_x;
        dx = x;
        dy = body_y(w, bob) - pivot_y;
        err = fabs(sqrt(dx * dx + dy * dy) - length);
        if (err > worst) worst = err;
        if ((prev < 0.0) != (x < 0.0)) {
            double at = t - dt + dt * prev / (prev - x); /* linear between the two steps */
            if (first < 0.0) first = at;
            last = at;
            ++crossings;
        }
        prev = x;
    }
    if (rod_error != NULL) *rod_error = worst;
    assert_int_equal(crossings, 41);
    return (last - first) / 20.0; /* 40 half periods */
}

static void test_rod_pendulum_period_and_length(void **state)
{
    const double L = 1.0, g = 10.0, theta = 5.0 * PGT_PI / 180.0;
    test_world t = joint_world(8, 4);
    pg_body_id pivot = static_anchor(t.w, 0.0, 10.0);
    pg_body_id bob = ball_at(t.w, L * sin(theta), 10.0 - L * cos(theta), 0.05, 10.0);
    pg_distance_joint_def jd = pg_default_distance_joint_def();
    pg_joint_id rod;
    double period, expected = 2.0 * PGT_PI * sqrt(L / g) * (1.0 + theta * theta / 16.0), rod_error;
    (void)state;
    jd.body_a = pivot;
    jd.body_b = bob;
    jd.length = fx(L);
    assert_int_equal(pg_distance_joint_create(t.w, &jd, &rod), PG_OK);
    period = measure_period(t.w, bob, 0.0, 10.0, L, &rod_error);
    printf("rod pendulum: period %.5f s, analytic %.5f s (%+.3f %%), rod length error up to %.6f m\n", period, expected,
           100.0 * (period / expected - 1.0), rod_error);
    JT_LE(fabs(period / expected - 1.0), 0.01);
    JT_LE(rod_error, ROD_LENGTH_TOLERANCE);
    free_world(&t);
}

static void test_revolute_pendulum_period(void **state)
{
    const double L = 2.0, g = 10.0, r = 0.2, theta = 5.0 * PGT_PI / 180.0;
    test_world t = joint_world(8, 4);
    pg_body_id pivot = static_anchor(t.w, 0.0, 10.0);
    pg_body_id bob = ball_at(t.w, L * sin(theta), 10.0 - L * cos(theta), r, 1.0);
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_joint_id pin;
    double k2 = r * r / 2.0, period, expected = 2.0 * PGT_PI * sqrt((L * L + k2) / (g * L)) * (1.0 + theta * theta / 16.0);
    (void)state;
    jd.body_a = pivot;
    jd.body_b = bob;
    jd.local_anchor_b = pg_v2(fx(-L * sin(theta)), fx(L * cos(theta))); /* the pivot, in the ball's frame */
    assert_int_equal(pg_revolute_joint_create(t.w, &jd, &pin), PG_OK);
    period = measure_period(t.w, bob, 0.0, 10.0, L, NULL);
    printf("revolute pendulum: period %.5f s, analytic %.5f s (%+.3f %%)\n", period, expected, 100.0 * (period / expected - 1.0));
    JT_LE(fabs(period / expected - 1.0), 0.01);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rod_pendulum_period_and_length),
        cmocka_unit_test(test_revolute_pendulum_period),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
