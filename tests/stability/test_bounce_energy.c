/* test_bounce_energy.c — bounces that keep their energy (docs/hard-cases.md, "Bounce
 * energy"). A body of restitution 1 on ground of restitution 1 keeps its energy from one
 * bounce to the next to within 0.1 %, over 10 000 steps, and its energy at the top of a
 * bounce never rises more than 1 % above where it started; restitution e keeps e^2 of it.
 *
 * Energy per unit mass E = g h + v^2 / 2 (h: height of the bottom above the ground) is
 * compared at the same phase of every bounce, its top (the step at which vy turns from +
 * to -): within a bounce semi-implicit Euler swings it by about g v h (GUIDE.md).
 * Every test prints what it measured (print_message). */
#include "../unit/pg_test.h"
#define HARD_PROGRAM "test_bounce_energy"
#include "hard_results.h"

#include <math.h>

#include "pogon/pogon.h"
#include "../unit/pg_test_world.h"

static const double G = 10.0;

typedef struct bounce_run {
    int apexes, checked;
    double e0, max_e, worst_loss, last_e; /* worst_loss: largest fraction lost from one apex to the next */
    double worst_ratio_err;               /* restitution e: largest |E_k / E_(k-1) - e^2| */
} bounce_run;

/* A body dropped so that its bottom starts h0 above the ground (top at y = 0), run for
 * `steps` steps at `substeps`; kind 0 a ball of radius `size`, 1 a box of side `size`
 * landing flat. Apexes whose approach speed sqrt(2 E) is above 1.5 m/s (clear of the
 * restitution threshold, 1 m/s) are checked. */
static bounce_run drop(int kind, double size, double h0, double e, uint32_t substeps, int steps)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_body_def st = pg_default_body_def(), bd;
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id g, body;
    bounce_run r = {0, 0, 0, 0, 0, 0, 0};
    double prev_vy = 0, prev_e, half = kind == 0 ? size : size / 2;
    int i;
    d.max_bodies = 4;
    d.max_shapes = 4;
    d.max_contacts = 16;
    d.substeps = substeps;
    t = make_world_def(&d);
    st.position = pg_v2(0, -fx(0.5));
    sd.restitution = fx(e);
    assert_int_equal(pg_make_wall(t.w, &st, &sd, PG_FIX_C(40), PG_FIX_ONE, &g), PG_OK);
    bd = dynamic_at(0, h0 + half);
    if (kind == 0) assert_int_equal(pg_make_ball(t.w, &bd, &sd, fx(size), &body), PG_OK);
    else assert_int_equal(pg_make_box(t.w, &bd, &sd, fx(size), fx(size), &body), PG_OK);
    r.e0 = prev_e = G * (fd(bd.position.y) - half);
    r.max_e = 0;
    for (i = 0; i < steps; ++i) {
        pg_vec2 v, p;
        double vy;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        v = pg_body_linear_velocity(t.w, body);
        p = pg_body_position(t.w, body);
        vy = fd(v.y);
        if (prev_vy > 0 && vy <= 0) {
            double en = G * (fd(p.y) - half) + 0.5 * (fd(v.x) * fd(v.x) + vy * vy);
            ++r.apexes;
            if (en > r.max_e) r.max_e = en;
            if (sqrt(2.0 * prev_e) > 1.5 && sqrt(2.0 * en) > 1.5) {
                double loss = 1.0 - en / prev_e, err = fabs(en / prev_e - e * e);
                ++r.checked;
                if (loss > r.worst_loss) r.worst_loss = loss;
                if (err > r.worst_ratio_err) r.worst_ratio_err = err;
            }
            prev_e = en;
            r.last_e = en;
        }
        prev_vy = vy;
    }
    free_world(&t);
    return r;
}

/* A ball of restitution 1 dropped from 2 m at the defaults, and at 1, 2 and 8 substeps:
 * under 0.1 % lost per bounce, never 1 % above the start, for 10 000 steps. */
static void test_superball_keeps_bouncing(void **state)
{
    static const uint32_t subs[] = {4, 1, 2, 8};
    int k;
    (void)state;
    for (k = 0; k < 4; ++k) {
        bounce_run r = drop(0, 0.25, 2.0, 1.0, subs[k], 10000);
        print_message("ball R 0.25 m from 2 m, restitution 1, %u substeps: %d apexes (%d checked), worst loss per bounce %.4f %%, "
                      "highest apex %+.4f %% of the start, last %+.3f %%\n",
                      subs[k], r.apexes, r.checked, 100 * r.worst_loss, 100 * (r.max_e / r.e0 - 1), 100 * (r.last_e / r.e0 - 1));
        assert_true(r.checked >= 100); /* it kept bouncing: 131 bounces of about 1.27 s in 10 000 steps */
        PG_EXPECT_LE(r.worst_loss, 0.001, "%u substeps: energy lost in one bounce", subs[k]);
        PG_EXPECT_LE(r.max_e, 1.01 * r.e0, "%u substeps: energy at an apex", subs[k]);
    }
}

/* Balls of several sizes dropped from several heights, and a box landing flat. */
static void test_bounce_energy_across_sizes_and_heights(void **state)
{
    static const double sizes[] = {0.05, 0.25, 2.0}, heights[] = {0.5, 2.0, 20.0};
    int i, j, kind;
    (void)state;
    for (kind = 0; kind < 2; ++kind)
        for (i = 0; i < 3; ++i)
            for (j = 0; j < 3; ++j) {
                bounce_run r = drop(kind, sizes[i], heights[j], 1.0, 4, 3000);
                print_message("%s %.2f m from %4.1f m: %d apexes (%d checked), worst loss per bounce %.4f %%, highest apex %+.4f %%\n",
                              kind == 0 ? "ball R" : "box", sizes[i], heights[j], r.apexes, r.checked, 100 * r.worst_loss,
                              100 * (r.max_e / r.e0 - 1));
                assert_true(r.checked >= 1);
                PG_EXPECT_LE(r.worst_loss, 0.001, "%s %.2f from %.1f: energy lost in one bounce", kind == 0 ? "ball" : "box", sizes[i],
                             heights[j]);
                PG_EXPECT_LE(r.max_e, 1.01 * r.e0, "%s %.2f from %.1f: energy at an apex", kind == 0 ? "ball" : "box", sizes[i], heights[j]);
            }
}

/* Restitution e keeps e^2 of the energy from one apex to the next. */
static void test_bounce_keeps_e_squared(void **state)
{
    static const double es[] = {0.5, 0.8, 0.95};
    int k;
    (void)state;
    for (k = 0; k < 3; ++k) {
        bounce_run r = drop(0, 0.25, 5.0, es[k], 4, 3000);
        print_message("ball, restitution %.2f from 5 m: %d apexes checked, apex energy ratio within %.4f of e^2 = %.4f\n", es[k], r.checked,
                      r.worst_ratio_err, es[k] * es[k]);
        assert_true(r.checked >= 2);
        PG_EXPECT_LE(r.worst_ratio_err, 0.002, "restitution %.2f: apex energy ratio against e^2", es[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_superball_keeps_bouncing),
        cmocka_unit_test(test_bounce_energy_across_sizes_and_heights),
        cmocka_unit_test(test_bounce_keeps_e_squared),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
