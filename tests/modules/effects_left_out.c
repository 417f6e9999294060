/* effects_left_out.c — the core built without sleeping and continuous collision
 * (PG_CONFIG_EFFECTS=0x1F, tests/modules/CMakeLists.txt): the default world leaves them
 * out, turning either on is refused with a message naming the switch, and the effects
 * that remain still work: a ball dropped 2.5 m onto a wall comes to rest on it and, with
 * no sleeping, stays awake. Exit 0 when all holds, 1 with a line saying what did not. */
#include "pogon/pogon.h"
#include <stdio.h>
#include <string.h>

static uint64_t memory[1 << 15];

static int fail(const char *what)
{
    printf("effects_left_out: %s\n", what);
    return 1;
}

int main(void)
{
    pg_world_def wd = pg_default_world_def(), all;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_world *world;
    pg_body_id ground, ball;
    const char *why;
    pg_fix y;
    int i;
    if (wd.effects != 0x1Fu) return fail("the default world's effects are not 0x1F");
    all = wd;
    all.effects = PG_EFFECTS_ALL;
    why = pg_world_def_problem(&all);
    if (why == NULL || strstr(why, "PG_CONFIG_EFFECTS") == NULL) return fail("a def with every effect is not refused by name");
    if (pg_world_memory_size(&all) != 0) return fail("a def with every effect has a memory size");
    wd.max_bodies = 8;
    wd.max_shapes = 8;
    wd.max_contacts = 16;
    if (pg_world_create(&wd, memory, sizeof memory, &world) != PG_OK) return fail("the default world is not created");
    if (pg_world_set_effects(world, 0x1Fu | PG_EFFECT_CONTINUOUS) != PG_ERR_INVALID_ARGUMENT ||
        strstr(pg_world_last_error(world), "PG_CONFIG_EFFECTS") == NULL)
        return fail("turning continuous collision on is not refused by name");
    if (pg_world_set_effects(world, 0x1Fu | PG_EFFECT_SLEEPING) != PG_ERR_INVALID_ARGUMENT)
        return fail("turning sleeping on is not refused");
    if (pg_world_effects(world) != 0x1Fu) return fail("a refused call changed the effects");
    if (pg_make_wall(world, &bd, &sd, PG_FIX_C(20), PG_FIX_C(1), &ground) != PG_OK) return fail("no wall");
    bd.type = PG_BODY_DYNAMIC;
    /* radius 0.75 m, its lowest point 2.5 m above the wall's top (y = 0.5 m) */
    bd.position = pg_v2(0, PG_FIX_C(3) + 3 * PG_FIX_ONE / 4);
    if (pg_make_ball(world, &bd, &sd, 3 * PG_FIX_ONE / 4, &ball) != PG_OK) return fail("no ball");
    for (i = 0; i < 300; ++i) /* 5 s */
        if (pg_world_step(world) != PG_OK) return fail("a step failed");
    /* the wall's top is at y = 0.5, the ball's radius 0.75: at rest its centre is at 1.25 m,
     * within the contact's slop of a few millimetres */
    y = pg_body_position(world, ball).y;
    if (y < PG_FIX_C(1) + PG_FIX_HALF / 2 - PG_FIX_ONE / 100 || y > PG_FIX_C(1) + PG_FIX_HALF / 2 + PG_FIX_ONE / 100)
        return fail("the ball is not resting on the wall");
    if (!pg_body_is_awake(world, ball)) return fail("the ball fell asleep in a build without sleeping");
    return 0;
}
