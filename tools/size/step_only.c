/* step_only.c — the smallest useful pogon program: a world of circles and boxes on a
 * static ground, stepped. Its flash is the "step-only circles-and-boxes" budget of
 * docs/embedded.md; the world lives in .bss, which is RAM, not flash. */
#include "pogon/pogon.h"

static uint64_t memory[1 << 15];

int main(void)
{
    pg_world_def wd = pg_default_world_def();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_world *world;
    pg_body_id ground, box, ball;
    int i;
    wd.max_bodies = 32;
    wd.max_shapes = 32;
    wd.max_contacts = 128;
    if (pg_world_create(&wd, memory, sizeof memory, &world) != PG_OK) return 1;
    if (pg_make_wall(world, &bd, &sd, PG_FIX_C(40), PG_FIX_C(1), &ground) != PG_OK) return 1;
    bd.type = PG_BODY_DYNAMIC;
    bd.position = pg_v2(0, PG_FIX_C(4));
    if (pg_make_box(world, &bd, &sd, PG_FIX_C(1), PG_FIX_C(1), &box) != PG_OK) return 1;
    bd.position = pg_v2(0, PG_FIX_C(6));
    if (pg_make_ball(world, &bd, &sd, PG_FIX_ONE / 2, &ball) != PG_OK) return 1;
    for (i = 0; i < 60; ++i) {
        if (pg_world_step(world) != PG_OK) return 1;
    }
    return pg_body_position(world, ball).y > pg_body_position(world, box).y ? 0 : 2;
}
