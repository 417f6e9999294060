/* test_heap_sleeps.c — a large settled pile comes to rest and falls asleep.
 *
 * The `heap` scene (tools/scenes/scenes.c): circles of radius and boxes of half side
 * 0.25 .. 0.5 m, one in three a box, dropped from a grid of 28 columns and rows 1.05 m apart
 * into a box 30 m wide inside, at the defaults (60 Hz, 4 substeps, every effect on).
 * HEAP_BODIES of them stand about HEAP_BODIES / 60 m deep once settled; the pile is one
 * island (every body touches its neighbours), so a single body that the sleep test sees
 * moving keeps all of them awake.
 *
 * Asserted, at every step: no centre below the ground (y > 0: the smallest body has
 * radius 0.25 m) or outside the walls (|x| < 15 m), and the total mechanical energy
 * (kinetic, rotational and m g y) never more than 0.1 % above its start (contacts only
 * take energy away; random piles hold the same bound). At the end of HEAP_SECONDS: every
 * body asleep. The pile settles within 10 s and falls asleep at about 21 s (2 000 bodies)
 * or 21-25 s (4 000, test_heap_sleeps_slow); 40 s leaves the margin that chance needs,
 * since any change of the numerics changes every bit of a pile. Before the sleep test
 * measured motion as well as velocity (src/core/island.c) neither pile ever fell asleep
 * (docs/hard-cases.md, "Heap"). */
#include "../unit/pg_test.h"
#define HARD_PROGRAM "test_heap_sleeps"
#include "hard_results.h"

#include <math.h>
#include <stdlib.h>

#include "pogon/pogon.h"
#include "scenes.h"
#include "../unit/pg_test_world.h"

#ifndef HEAP_BODIES
#define HEAP_BODIES 2000 /* test_heap_sleeps_slow: 4000 */
#endif
#define HEAP_SECONDS 40
#define GRAVITY 10.0

static double mechanical_energy(const pg_world *w, const pg_body_id *ids, uint32_t n)
{
    double e = 0.0;
    uint32_t i;
    for (i = 0; i < n; ++i) {
        double m = (double)pg_body_mass(w, ids[i]) / 4294967296.0, inertia = (double)pg_body_inertia(w, ids[i]) / 68719476736.0;
        pg_vec2 v = pg_body_linear_velocity(w, ids[i]), c = pg_body_world_center(w, ids[i]);
        double om = fd(pg_body_angular_velocity(w, ids[i]));
        e += 0.5 * m * (fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y)) + 0.5 * inertia * om * om + m * GRAVITY * fd(c.y);
    }
    return e;
}

/* The dynamic bodies of the world, found by a query over everything. */
static uint32_t dynamic_bodies(const pg_world *w, pg_body_id *ids, uint32_t capacity)
{
    pg_aabb all;
    uint32_t found = 0, i, n = 0;
    all.lo = pg_v2(PG_FIX_C(-1000), PG_FIX_C(-1000));
    all.hi = pg_v2(PG_FIX_C(1000), PG_FIX_C(1000));
    assert_int_equal(pg_world_query_aabb(w, all, ids, capacity, &found), PG_OK);
    for (i = 0; i < found && i < capacity; ++i)
        if (pg_body_type_of(w, ids[i]) == PG_BODY_DYNAMIC) ids[n++] = ids[i];
    return n;
}

static void test_heap_sleeps(void **state)
{
    pg_world_def d = pg_scene_world_def("heap", HEAP_BODIES);
    size_t size = pg_scene_memory_size("heap", HEAP_BODIES, &d);
    void *memory = malloc(size); /* malloc aligns to 8 at least */
    pg_body_id *ids = (pg_body_id *)malloc(sizeof(pg_body_id) * (HEAP_BODIES + 16));
    pg_scene scene;
    double energy0, rise = -1e9, widest = 0.0, lowest = 1e9;
    uint32_t n, i, awake = 0, first_all_asleep = 0;
    int step;
    (void)state;
    assert_non_null(memory);
    assert_non_null(ids);
    d.gravity = pg_v2(0, fx(-GRAVITY));
    assert_int_equal(pg_scene_build("heap", HEAP_BODIES, &d, memory, size, &scene), PG_OK);
    n = dynamic_bodies(scene.world, ids, HEAP_BODIES + 16);
    assert_int_equal(n, HEAP_BODIES);
    energy0 = mechanical_energy(scene.world, ids, n);
    for (step = 1; step <= HEAP_SECONDS * 60; ++step) {
        double e;
        assert_int_equal(pg_world_step(scene.world), PG_OK);
        for (i = 0; i < n; ++i) {
            pg_vec2 c = pg_body_world_center(scene.world, ids[i]);
            if (fabs(fd(c.x)) > widest) widest = fabs(fd(c.x));
            if (fd(c.y) < lowest) lowest = fd(c.y);
        }
        e = mechanical_energy(scene.world, ids, n) - energy0;
        if (e > rise) rise = e;
        awake = pg_world_get_stats(scene.world).awake_body_count;
        if (awake == 0 && first_all_asleep == 0) first_all_asleep = (uint32_t)step;
        if (awake != 0) first_all_asleep = 0;
        if (step % 120 == 0) print_message("%5.1f s: %u of %u bodies awake\n", step / 60.0, awake, n);
    }
    print_message("all asleep from %.2f s (0: not at the end)\n", first_all_asleep / 60.0);
    PG_EXPECT_LE(widest, 15.0, "heap of %d bodies: widest |x| of a centre, walls at 15 m (m)", HEAP_BODIES);
    PG_EXPECT_LE(-lowest, 0.0, "heap of %d bodies: deepest centre below the ground (m)", HEAP_BODIES);
    PG_EXPECT_LE(100.0 * rise / energy0, 0.1, "heap of %d bodies: largest energy rise above the start (%%)", HEAP_BODIES);
    PG_EXPECT_LE((double)awake, 0.0, "heap of %d bodies: bodies awake after 40 s", HEAP_BODIES);
    free(ids);
    free(memory);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_heap_sleeps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
