/* hello_world.c — the example at the top of include/pogon/pogon.h ("HOW TO USE IT"),
 * as a program: a box dropped from 4 m onto a static ground comes to rest on it. If the
 * header's example changes, change this file with it: the smoke test keeps it honest. */
#include <stdio.h>

#include "pogon/pogon.h"

int main(void)
{
    pg_world_def wd = pg_default_world_def();          /* gravity, 60 Hz, 4 substeps, ... */
    wd.max_bodies = 256;                               /* capacities are fixed at creation */
    wd.max_shapes = 256;
    wd.max_contacts = 512;
    static uint64_t memory[1 << 17];                   /* the caller owns all memory: */
    pg_world *world;                                   /* pg_world_memory_size(&wd) bytes */
    if (pg_world_create(&wd, memory, sizeof memory, &world) != PG_OK) return 1;

    pg_body_def bd = pg_default_body_def();            /* a static ground */
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ground, box;
    pg_make_wall(world, &bd, &sd, PG_FIX_C(40), PG_FIX_C(1), &ground);
    bd.type = PG_BODY_DYNAMIC;
    bd.position = pg_v2(0, PG_FIX_C(4));
    pg_make_box(world, &bd, &sd, PG_FIX_C(1), PG_FIX_C(1), &box);
    for (int i = 0; i < 60; ++i) pg_world_step(world);
    pg_vec2 p = pg_body_position(world, box);

    /* The ground's top is at y = 0.5, so the 1 m box rests with its centre at 1.0, less
     * the soft contact's overlap (under a millimetre for one box). */
    char y[PG_FIX_FORMAT_MAX];
    pg_fix_format(p.y, y, sizeof y);
    printf("hello_world: %zu of %zu bytes used; after 1 s the box rests at y = %s m\n", pg_world_memory_size(&wd), sizeof memory, y);
    if (p.y < PG_FIX_C(1) - PG_FIX_ONE / 1000 || p.y > PG_FIX_C(1)) {
        printf("hello_world: FAILED, the box is not resting on the ground\n");
        return 1;
    }
    return 0;
}
