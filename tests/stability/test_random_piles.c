/* test_random_piles.c — piles the tree does not hold: random mixes of every shape kind.
 *
 * The named hard cases (test_hard_cases.c) each isolate one difficulty. Users build
 * scenes nobody wrote down, so this test builds 100 piles from a seeded generator and
 * holds each to what any pile must do. A pile: a container 29 m wide inside (a static
 * ground whose top is at y = 0, walls 200 m tall), 60 bodies dropped from a grid of
 * 3.2 m cells 1.6 .. 20.8 m up (no two overlap at the start), each a ball, capsule, box,
 * triangle or star 0.15 .. 1.5 m across, density 0.3 .. 3 (1:10), friction 0 .. 1, a
 * quarter of them with restitution up to 0.8, thrown at up to 5 m/s and spun at up to
 * 3 rad/s. Every pile runs 20 s at the defaults (60 Hz, 4 substeps, every effect on).
 *
 * test_random_piles asserts, for every pile:
 *   - nothing passes through a wall or the ground: at every step every centre stays
 *     within |x| < 14.5 m and above y = -0.5 m, and after 20 s above y = 0. (A light
 *     body pinched under a heavy one landing at 20 m/s is pressed into the ground for a
 *     few steps, its centre 0.28 m below the surface at worst in 400 piles, 0.043 m in
 *     500 with the solver's current order: the light body cannot stop the heavy one in
 *     one pass of the solver, docs/hard-cases.md. A body that passed through would end
 *     below the surface or fall on.)
 *   - the total mechanical energy (kinetic, rotational, and m g y) never exceeds its
 *     value at the start by more than 0.1 % (measured: it never exceeds it at all; the
 *     first steps of free fall lose about 0.003 % to the integrator): contacts can only
 *     dissipate, so a pile that gains energy has a solver fault;
 *   - no contact is dropped for capacity and no speed reaches the cap.
 * And over the 100 piles: at least 75 are entirely asleep after 20 s. The others hold
 * bodies that keep moving: a triangle rocking on a ball without slipping (a conservative
 * oscillator: nothing in pogon resists rolling), a ball still rolling, part of a heap
 * still creeping at a few cm/s. How many is a matter of chance, since any change of the
 * numerics changes every bit of a pile: four other sets of 100 seeds gave 83 to 90, and
 * these seeds between 81 and 92 with the rounding and solver orders they have had, so the bound sits three standard deviations below them. It still
 * catches what it was written for: before a body's surface speed counted for sleep (island.c) 67 of these
 * 100 slept, small balls rolling at a few mm/s turning faster than 2 degrees/s.
 *
 * test_bouncy_piles: 40 of the same piles with every restitution 1, where the energy
 * must still never rise above its start. (A rebound that ignores this rose by up to 194 %: a
 * point that first pushed in a later substep rebounded from an approach speed that
 * other contacts' pushes had made in this step; docs/solver-design.md, APPROACH.) With nothing lost
 * at impacts the energy may gather in a light body and throw it over a wall, so
 * containment is not asserted there.
 *
 * test_thrown_spinning_piles: 20 of the piles thrown at up to 60 m/s and spun at up to
 * 200 rad/s inside a closed box of 0.1 m thick static walls, where sweeping fast-turning
 * bodies must neither add energy nor pause a body (details above that test). */
#include "../unit/pg_test.h"
#define HARD_PROGRAM "test_random_piles"
#include "hard_results.h"

#include <math.h>
#include <stdlib.h>

#include "pogon/pogon.h"
#include "../unit/pg_test_world.h"

#define PILES 100
#define BOUNCY_PILES 40
#define BODIES 60
#define SECONDS 20
#define GRAVITY 10.0

static uint32_t next_random(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

/* uniform in [a, b] in steps of (b - a) / 100000: exact decimal inputs, the same everywhere */
static double uniform(uint32_t *s, double a, double b) { return a + (b - a) * (double)(next_random(s) % 100001u) / 100000.0; }

/* The pile's 60 bodies, thrown at up to `throw_speed` per axis and spun at up to `spin`. */
static void add_bodies(pg_world *w, uint32_t seed, pg_body_id *ids, int bouncy, double throw_speed, double spin)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    int i;
    bd.type = PG_BODY_DYNAMIC;
    for (i = 0; i < BODIES; ++i) {
        uint32_t kind = next_random(&seed) % 5u;
        double size = uniform(&seed, 0.15, 1.5);
        sd.density = fx(pow(10.0, uniform(&seed, -0.5, 0.5)));
        sd.friction = fx(uniform(&seed, 0.0, 1.0));
        sd.restitution = next_random(&seed) % 4u == 0 ? fx(uniform(&seed, 0.0, 0.8)) : 0;
        if (bouncy) sd.restitution = PG_FIX_ONE;
        bd.position = pg_v2(fx(-13.0 + (i % 9) * 3.2 + uniform(&seed, -0.2, 0.2)), fx(1.6 + (i / 9) * 3.2));
        bd.angle = next_random(&seed);
        {   /* one draw per statement: the order in which a call's arguments are evaluated is
             * unspecified (gcc took the second first, clang the first), and with two draws in
             * one call the piles differed between the compilers; vy first keeps gcc's piles */
            double vy = uniform(&seed, -throw_speed, throw_speed), vx = uniform(&seed, -throw_speed, throw_speed);
            bd.linear_velocity = pg_v2(fx(vx), fx(vy));
        }
        bd.angular_velocity = fx(uniform(&seed, -spin, spin));
        switch (kind) {
        case 0: assert_int_equal(pg_make_ball(w, &bd, &sd, fx(size / 2), &ids[i]), PG_OK); break;
        case 1: assert_int_equal(pg_make_capsule(w, &bd, &sd, fx(size), fx(size / 4), &ids[i]), PG_OK); break;
        case 2: assert_int_equal(pg_make_box(w, &bd, &sd, fx(size), fx(uniform(&seed, 0.15, 1.5)), &ids[i]), PG_OK); break;
        case 3: assert_int_equal(pg_make_triangle(w, &bd, &sd, fx(size / 1.5), &ids[i]), PG_OK); break;
        default: assert_int_equal(pg_make_star(w, &bd, &sd, fx(size / 1.5), &ids[i]), PG_OK); break;
        }
    }
}

static void build_pile(pg_world *w, uint32_t seed, pg_body_id *ids, int bouncy)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    int i;
    bd.position = pg_v2(0, PG_FIX_C(-1));
    assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_C(30), PG_FIX_C(2), &id), PG_OK);
    for (i = 0; i < 4; ++i) { /* walls in 100 m pieces (vertices lie within 50 m of a body) */
        bd.position = pg_v2(i & 1 ? PG_FIX_C(15) : PG_FIX_C(-15), PG_FIX_C(50 + 100 * (i / 2)));
        assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_ONE, PG_FIX_C(100), &id), PG_OK);
    }
    add_bodies(w, seed, ids, bouncy, 5.0, 3.0);
}

typedef struct pile_result {
    double worst_x, lowest_y;  /* largest |x| and lowest y of any centre, at any step */
    double lowest_end;         /* lowest y of any centre after the last step */
    double energy0, energy_rise; /* at the start, and the largest E(t) - E(0) */
    uint32_t awake_at_end, speed_clamps, capacity_misses;
} pile_result;

static double mechanical_energy(const pg_world *w, const pg_body_id *ids, int n)
{
    double e = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        double m = (double)pg_body_mass(w, ids[i]) / 4294967296.0, inertia = (double)pg_body_inertia(w, ids[i]) / 68719476736.0;
        pg_vec2 v = pg_body_linear_velocity(w, ids[i]), c = pg_body_world_center(w, ids[i]);
        double om = fd(pg_body_angular_velocity(w, ids[i]));
        e += 0.5 * m * (fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y)) + 0.5 * inertia * om * om + m * GRAVITY * fd(c.y);
    }
    return e;
}

static pile_result run_pile(uint32_t seed, int bouncy)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_body_id ids[BODIES];
    pile_result r;
    int i, step;
    d.gravity = pg_v2(0, fx(-GRAVITY));
    d.max_bodies = BODIES + 5;
    d.max_shapes = 2 * BODIES + 5; /* a star is two triangles */
    d.max_contacts = 8 * BODIES + 64;
    t = make_world_def(&d);
    build_pile(t.w, seed, ids, bouncy);
    r.worst_x = 0.0;
    r.lowest_y = 1e9;
    r.energy0 = mechanical_energy(t.w, ids, BODIES);
    r.energy_rise = -1e9;
    for (step = 1; step <= SECONDS * 60; ++step) {
        double e;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        for (i = 0; i < BODIES; ++i) {
            pg_vec2 c = pg_body_world_center(t.w, ids[i]);
            if (fabs(fd(c.x)) > r.worst_x) r.worst_x = fabs(fd(c.x));
            if (fd(c.y) < r.lowest_y) r.lowest_y = fd(c.y);
        }
        e = mechanical_energy(t.w, ids, BODIES) - r.energy0;
        if (e > r.energy_rise) r.energy_rise = e;
    }
    r.lowest_end = 1e9;
    for (i = 0; i < BODIES; ++i)
        if (fd(pg_body_world_center(t.w, ids[i]).y) < r.lowest_end) r.lowest_end = fd(pg_body_world_center(t.w, ids[i]).y);
    r.awake_at_end = pg_world_get_stats(t.w).awake_body_count;
    r.speed_clamps = pg_world_get_stats(t.w).speed_clamps;
    r.capacity_misses = pg_world_get_stats(t.w).capacity_misses;
    free_world(&t);
    return r;
}

static void test_random_piles(void **state)
{
    int k, asleep = 0, ok = 1;
    double widest = 0.0, deepest = -1e9, deepest_end = -1e9, rise = -1e9;
    unsigned clamps = 0;
    (void)state;
    for (k = 0; k < PILES; ++k) {
        pile_result r = run_pile(0x9E3779B9u ^ (uint32_t)(k * 7919 + 1), 0);
        print_message("pile %2d: widest |x| %.3f m, lowest y %.4f m (%.4f m at the end), energy %.1f J at the start, largest "
                      "rise %+.4f %%, awake after %d s: %u, clamps %u, capacity misses %u\n",
                      k, r.worst_x, r.lowest_y, r.lowest_end, r.energy0, 100.0 * r.energy_rise / r.energy0, SECONDS,
                      r.awake_at_end, r.speed_clamps, r.capacity_misses);
        if (r.awake_at_end == 0) ++asleep;
        if (r.worst_x > widest) widest = r.worst_x;
        if (-r.lowest_y > deepest) deepest = -r.lowest_y;
        if (-r.lowest_end > deepest_end) deepest_end = -r.lowest_end;
        if (100.0 * r.energy_rise / r.energy0 > rise) rise = 100.0 * r.energy_rise / r.energy0;
        clamps += r.speed_clamps + r.capacity_misses;
        if (!(r.worst_x < 14.5 && r.lowest_y > -0.5 && r.lowest_end > 0.0)) {
            print_error("pile %d: a body passed a wall or the ground (widest |x| %.4f m, lowest y %.4f m, %.4f m at the end)\n", k,
                        r.worst_x, r.lowest_y, r.lowest_end);
            ok = 0;
        }
        if (!(r.energy_rise <= 0.001 * r.energy0)) {
            print_error("pile %d: the energy rose %.3f J (%.4f %%) above its start\n", k, r.energy_rise, 100.0 * r.energy_rise / r.energy0);
            ok = 0;
        }
        if (r.speed_clamps != 0 || r.capacity_misses != 0) {
            print_error("pile %d: %u speed clamps, %u capacity misses\n", k, r.speed_clamps, r.capacity_misses);
            ok = 0;
        }
    }
    print_message("%d of %d piles asleep after %d s\n", asleep, PILES, SECONDS);
    hard_figure(__func__, "100 piles: widest |x| of a body, walls at 15 m (m)", widest, 14.5);
    hard_figure(__func__, "100 piles: deepest centre below the ground (m)", deepest, 0.5);
    hard_figure(__func__, "100 piles: deepest centre below the ground at the end (m)", deepest_end, 0.0);
    hard_figure(__func__, "100 piles: largest energy rise above the start (%)", rise, 0.1);
    hard_figure(__func__, "100 piles: speed clamps and capacity misses", clamps, 0.0);
    hard_figure(__func__, "100 piles: piles still awake after 20 s", PILES - asleep, PILES - 75);
    if (asleep < 75) {
        print_error("only %d of %d piles are asleep after %d s (at least 75)\n", asleep, PILES, SECONDS);
        ok = 0;
    }
    if (!ok) fail();
}

static void test_bouncy_piles(void **state)
{
    int k, ok = 1;
    double rise = -1e9;
    (void)state;
    for (k = 0; k < BOUNCY_PILES; ++k) {
        pile_result r = run_pile(0x9E3779B9u ^ (uint32_t)(k * 7919 + 1), 1);
        print_message("bouncy pile %2d: energy %.1f J at the start, largest rise %+.4f %%\n", k, r.energy0,
                      100.0 * r.energy_rise / r.energy0);
        if (100.0 * r.energy_rise / r.energy0 > rise) rise = 100.0 * r.energy_rise / r.energy0;
        if (!(r.energy_rise <= 0.001 * r.energy0)) {
            print_error("bouncy pile %d: the energy rose %.3f J (%.4f %%) above its start\n", k, r.energy_rise,
                        100.0 * r.energy_rise / r.energy0);
            ok = 0;
        }
    }
    hard_figure(__func__, "40 piles with restitution 1: largest energy rise above the start (%)", rise, 0.1);
    if (!ok) fail();
}

/* test_thrown_spinning_piles: 20 of the piles thrown hard, at up to 60 m/s per axis and
 * spun at up to 200 rad/s, inside a closed box whose floor, walls and ceiling are static
 * and only 0.1 m thick (30 m x 30 m inside), for 10 s. Many bodies turn a large part of a
 * turn per step, so continuous.c sweeps them and puts them back at their times of impact,
 * which must neither add energy nor hold a body still. Asserted for every pile: the
 * energy never rises more than 0.1 % above its start (measured over 200 such piles, ten
 * seed sets: at most 0.003 %); no body pauses (three steps in a row faster than 2 m/s
 * moving less than a twentieth of that in a step; holding a touching core circle at its
 * start pose instead of sliding it along the surface paused one); no speed clamps, no
 * capacity misses. Printed, not asserted: bodies that end outside the box. Over the ten
 * seed sets 42 of 12 000 bodies did (85 before the sweep), nearly all small bodies that
 * the pile squeezed or rammed through a wall, which the sweep of turning bodies against
 * static shapes does not cover (docs/hard-cases.md). DEEP PUSH (push-out past
 * a contact's hold moves positions only) did not change that rate: over these seeds and
 * nine more sets (seed + set * 104729), 31 bodies before it and 30 after; these seeds lose
 * 2 (none before). */
#define THROWN_PILES 20

static void test_thrown_spinning_piles(void **state)
{
    int k, ok = 1, all_out = 0, all_paused = 0;
    double worst_rise = -1e9;
    unsigned clamps = 0;
    (void)state;
    for (k = 0; k < THROWN_PILES; ++k) {
        pg_world_def d = pg_default_world_def();
        test_world t;
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id ids[BODIES], id;
        pg_vec2 last[BODIES];
        int still[BODIES], i, step, paused = 0, strayed = 0, out = 0;
        double e0, rise = -1e9;
        d.gravity = pg_v2(0, fx(-GRAVITY));
        d.max_bodies = BODIES + 5;
        d.max_shapes = 2 * BODIES + 5;
        d.max_contacts = 8 * BODIES + 64;
        t = make_world_def(&d);
        bd.position = pg_v2(0, fx(-0.05)); /* floor, top at y = 0 */
        assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(30.2), fx(0.1), &id), PG_OK);
        bd.position = pg_v2(0, fx(30.05)); /* ceiling, bottom at y = 30 */
        assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(30.2), fx(0.1), &id), PG_OK);
        for (i = 0; i < 2; ++i) { /* walls, inner faces at x = -15 and 15 */
            bd.position = pg_v2(fx(i ? 15.05 : -15.05), fx(15.0));
            assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(0.1), fx(30.2), &id), PG_OK);
        }
        add_bodies(t.w, 0x9E3779B9u ^ (uint32_t)(k * 7919 + 1), ids, 0, 60.0, 200.0);
        e0 = mechanical_energy(t.w, ids, BODIES);
        for (i = 0; i < BODIES; ++i) {
            last[i] = pg_body_world_center(t.w, ids[i]);
            still[i] = 0;
        }
        for (step = 1; step <= 600; ++step) {
            double e;
            assert_int_equal(pg_world_step(t.w), PG_OK);
            for (i = 0; i < BODIES; ++i) {
                pg_vec2 c = pg_body_world_center(t.w, ids[i]), v = pg_body_linear_velocity(t.w, ids[i]);
                double sp = sqrt(fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y));
                double moved = sqrt((fd(c.x) - fd(last[i].x)) * (fd(c.x) - fd(last[i].x)) + (fd(c.y) - fd(last[i].y)) * (fd(c.y) - fd(last[i].y)));
                if (fabs(fd(c.x)) > 15.0 || fd(c.y) < 0.0 || fd(c.y) > 30.0) ++strayed;
                still[i] = sp > 2.0 && moved < 0.05 * sp / 60.0 ? still[i] + 1 : 0;
                if (still[i] == 3) ++paused;
                last[i] = c;
            }
            e = mechanical_energy(t.w, ids, BODIES) - e0;
            if (e > rise) rise = e;
        }
        for (i = 0; i < BODIES; ++i) {
            pg_vec2 c = pg_body_world_center(t.w, ids[i]);
            if (fabs(fd(c.x)) > 15.0 || fd(c.y) < 0.0 || fd(c.y) > 30.0) ++out;
        }
        print_message("thrown pile %2d: %d bodies outside after 10 s, %d body-steps with a centre outside, %d pauses, largest energy rise "
                      "%+.4f %%, clamps %u, capacity misses %u\n",
                      k, out, strayed, paused, 100.0 * rise / e0, pg_world_get_stats(t.w).speed_clamps,
                      pg_world_get_stats(t.w).capacity_misses);
        all_out += out;
        all_paused += paused;
        if (100.0 * rise / e0 > worst_rise) worst_rise = 100.0 * rise / e0;
        clamps += pg_world_get_stats(t.w).speed_clamps + pg_world_get_stats(t.w).capacity_misses;
        if (paused != 0 || !(rise <= 0.001 * e0) || pg_world_get_stats(t.w).speed_clamps != 0 ||
            pg_world_get_stats(t.w).capacity_misses != 0) {
            print_error("thrown pile %d: %d pauses, energy rise %.4f %%, %u clamps, %u capacity misses\n", k, paused, 100.0 * rise / e0,
                        pg_world_get_stats(t.w).speed_clamps, pg_world_get_stats(t.w).capacity_misses);
            ok = 0;
        }
        free_world(&t);
    }
    hard_figure(__func__, "20 thrown piles: largest energy rise above the start (%)", worst_rise, 0.1);
    hard_figure(__func__, "20 thrown piles: pauses", all_paused, 0.0);
    hard_figure(__func__, "20 thrown piles: speed clamps and capacity misses", clamps, 0.0);
    hard_figure(__func__, "20 thrown piles: bodies outside the box after 10 s (of 1200)", all_out, HARD_NOT_ASSERTED);
    if (!ok) fail();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_piles),
        cmocka_unit_test(test_bouncy_piles),
        cmocka_unit_test(test_thrown_spinning_piles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
