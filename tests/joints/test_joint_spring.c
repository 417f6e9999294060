/* test_joint_spring.c — a distance joint with a spring oscillates at its hertz, and
 * decays at its damping ratio (docs/joints.md).
 *
 * The spring's stiffness is set from its hertz and the pair's effective mass (1/K
 * along the rod: the reduced mass m1 m2 / (m1 + m2) of two balls joined at their
 * centres), so the pair's separation oscillates at exactly that frequency. Gravity is
 * off; the frequency comes from the times the length crosses its rest length over 10
 * periods, interpolated between steps. */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"

typedef struct spring_run {
    double frequency;      /* measured, Hz */
    double first_peak, last_peak; /* |stretch| at the start and at the extreme 10 periods later */
    double first_speed, last_speed; /* |relative speed| at the first and the last crossing of the rest length */
    double momentum_drift; /* |sum m v| at the end, kg m/s */
} spring_run;

/* The relative speed of b from a along the line between them, m/s. */
static double separation_speed(pg_world *w, pg_body_id a, pg_body_id b)
{
    double dx = body_x(w, b) - body_x(w, a), dy = body_y(w, b) - body_y(w, a), len = sqrt(dx * dx + dy * dy);
    pg_vec2 va = pg_body_linear_velocity(w, a), vb = pg_body_linear_velocity(w, b);
    return ((fd(vb.x) - fd(va.x)) * dx + (fd(vb.y) - fd(va.y)) * dy) / len;
}

static spring_run run_pair(double hertz, double zeta, double m1_density, double m2_density)
{
    test_world t = joint_world(8, 4);
    pg_body_id a = ball_at(t.w, 0.0, 5.0, 0.25, m1_density), b = ball_at(t.w, 2.2, 5.0, 0.25, m2_density);
    pg_distance_joint_def jd = pg_default_distance_joint_def();
    pg_joint_id spring;
    spring_run r = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double prev, prev_speed = 0.0, t_now = 0.0, first = -1.0, last = -1.0, dt = 1.0 / 60.0, peak = 0.0;
    int crossings = 0, peaks = 0, step;
    assert_int_equal(pg_world_set_gravity(t.w, pg_v2_zero()), PG_OK);
    assert_int_equal(pg_world_set_effects(t.w, PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING), PG_OK); /* slow swings are not rest */
    jd.body_a = a;
    jd.body_b = b;
    jd.length = fx(2.0);
    jd.enable_spring = 1;
    jd.hertz = fx(hertz);
    jd.damping_ratio = fx(zeta);
    assert_int_equal(pg_distance_joint_create(t.w, &jd, &spring), PG_OK);
    prev = fd(pg_distance_joint_current_length(t.w, spring)) - 2.0;
    for (step = 0; step < 6000 && crossings < 21; ++step) {
        double x, speed;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        t_now += dt;
        x = fd(pg_distance_joint_current_length(t.w, spring)) - 2.0;
        speed = separation_speed(t.w, a, b);
        if (fabs(x) > peak) peak = fabs(x);
        if ((prev < 0.0) != (x < 0.0)) {
            double f = prev / (prev - x), at = t_now - dt + dt * f, v = fabs(prev_speed + f * (speed - prev_speed));
            if (first < 0.0) r.first_speed = v;
            r.last_speed = v;
            if (first < 0.0) first = at;
            last = at;
            ++crossings;
            if (peaks == 0) r.first_peak = peak;
            ++peaks;
            r.last_peak = peak;
            peak = 0.0;
        }
        prev = x;
        prev_speed = speed;
    }
    assert_int_equal(crossings, 21);
    r.frequency = 10.0 / (last - first);
    {
        pg_vec2 va = pg_body_linear_velocity(t.w, a), vb = pg_body_linear_velocity(t.w, b);
        double px = body_mass(t.w, a) * fd(va.x) + body_mass(t.w, b) * fd(vb.x);
        double py = body_mass(t.w, a) * fd(va.y) + body_mass(t.w, b) * fd(vb.y);
        r.momentum_drift = sqrt(px * px + py * py);
    }
    free_world(&t);
    return r;
}

static void test_spring_pair_oscillates_at_its_hertz(void **state)
{
    const double hz[] = {0.5, 2.0, 5.0};
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        spring_run r = run_pair(hz[i], 0.0, 1.0, 4.0); /* masses 1:4 */
        printf("spring %.1f Hz, undamped: measured %.4f Hz (%+.3f %%), speed through the rest length %.5f then %.5f m/s, momentum %.2e kg m/s\n",
               hz[i], r.frequency, 100.0 * (r.frequency / hz[i] - 1.0), r.first_speed, r.last_speed, r.momentum_drift);
        JT_LE(fabs(r.frequency / hz[i] - 1.0), 0.02);
        /* undamped: it keeps its energy, all kinetic where it passes its rest length:
         * the speed there 10 periods on is the first one's within 1 % */
        JT_LE(fabs(r.last_speed / r.first_speed - 1.0), 0.01);
        /* the joint's impulses are equal and opposite: no net momentum */
        JT_LE(r.momentum_drift, 1e-3);
    }
}

static void test_spring_damping_ratio(void **state)
{
    /* a damped oscillator's swing shrinks as exp(-zeta omega t): from the start (an
     * extreme) to the extreme 10 periods of the damped frequency omega sqrt(1 - zeta^2)
     * later, by exp(-zeta 2 pi 10 / sqrt(1 - zeta^2)) */
    const double zeta = 0.05, hz = 2.0;
    spring_run r = run_pair(hz, zeta, 1.0, 1.0);
    double expected = exp(-zeta * 2.0 * PGT_PI * 10.0 / sqrt(1.0 - zeta * zeta)), got = r.last_peak / r.first_peak;
    (void)state;
    printf("spring %.1f Hz, damping ratio %.2f: swing ratio %.4f, analytic %.4f\n", hz, zeta, got, expected);
    JT_LE(fabs(got / expected - 1.0), 0.05);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spring_pair_oscillates_at_its_hertz),
        cmocka_unit_test(test_spring_damping_ratio),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
