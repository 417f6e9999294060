/* small_build.c — the core built for the smallest step-only program (tests/modules/
 * CMakeLists.txt): without joints (PG_CONFIG_JOINTS=0), with circles and boxes only
 * (PG_CONFIG_SHAPES=0x03) and without sleeping and continuous collision
 * (PG_CONFIG_EFFECTS=0x1F). What it leaves out is refused with a message naming its
 * switch, and what it keeps works: a box dropped on a wall comes to rest on it, and a
 * ball dropped on that box comes to rest on the box. Exit 0 when all holds, 1 with a
 * line saying what did not. */
#include "pogon/pogon.h"
#include "pogon/soft_body.h"
#include <stdio.h>
#include <string.h>

static uint64_t memory[1 << 15];

static int fail(const char *what)
{
    printf("small_build: %s\n", what);
    return 1;
}

/* r is PG_ERR_INVALID_ARGUMENT and the world's message names `knob` */
static int refused(pg_world *w, pg_result r, const char *knob)
{
    return r == PG_ERR_INVALID_ARGUMENT && strstr(pg_world_last_error(w), knob) != NULL;
}

static int near(pg_fix got, pg_fix want) { return got >= want - PG_FIX_ONE / 100 && got <= want + PG_FIX_ONE / 100; }

int main(void)
{
    pg_world_def wd = pg_default_world_def(), joints;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_distance_joint_def jd = pg_default_distance_joint_def();
    pg_soft_def soft = pg_default_soft_def();
    pg_world *world;
    pg_body_id ground, box, ball, other;
    pg_joint_id joint;
    pg_geometry g;
    pg_shape_id shape;
    const char *why;
    pg_vec2 square[4], notch[5];
    int i;

    if (wd.max_joints != 0) return fail("the default world has joint slots");
    joints = wd;
    joints.max_joints = 1;
    why = pg_world_def_problem(&joints);
    if (why == NULL || strstr(why, "PG_CONFIG_JOINTS") == NULL) return fail("a def with a joint slot is not refused by name");
    wd.max_bodies = 8;
    wd.max_shapes = 8;
    wd.max_contacts = 16;
    if (pg_world_create(&wd, memory, sizeof memory, &world) != PG_OK) return fail("the default world is not created");
    if (pg_make_wall(world, &bd, &sd, PG_FIX_C(20), PG_FIX_C(1), &ground) != PG_OK) return fail("no wall");

    /* joints and soft bodies */
    jd.body_a = ground;
    jd.body_b = ground;
    if (!refused(world, pg_distance_joint_create(world, &jd, &joint), "PG_CONFIG_JOINTS")) return fail("a joint is not refused by name");
    if (pg_joint_is_valid(world, joint)) return fail("a refused joint's handle is valid");
    if (!refused(world, pg_make_rope(world, &soft, pg_v2(0, PG_FIX_C(5)), pg_v2(PG_FIX_C(2), PG_FIX_C(5)), 4, &other), "PG_CONFIG_JOINTS"))
        return fail("a rope is not refused by name");

    /* shape kinds other than circles and boxes */
    bd.type = PG_BODY_DYNAMIC;
    bd.position = pg_v2(PG_FIX_C(5), PG_FIX_C(5));
    if (!refused(world, pg_make_capsule(world, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE / 4, &other), "PG_CONFIG_SHAPES"))
        return fail("a capsule is not refused by name");
    if (!refused(world, pg_make_triangle(world, &bd, &sd, PG_FIX_ONE, &other), "PG_CONFIG_SHAPES")) return fail("a triangle is not refused by name");
    if (!refused(world, pg_make_star(world, &bd, &sd, PG_FIX_ONE, &other), "PG_CONFIG_SHAPES")) return fail("a star is not refused by name");
    square[0] = pg_v2(0, 0);
    square[1] = pg_v2(PG_FIX_ONE, 0);
    square[2] = pg_v2(PG_FIX_ONE, PG_FIX_ONE);
    square[3] = pg_v2(0, PG_FIX_ONE);
    notch[0] = square[0], notch[1] = square[1], notch[2] = square[2], notch[3] = pg_v2(PG_FIX_ONE / 2, PG_FIX_ONE / 2), notch[4] = square[3];
    if (!refused(world, pg_make_concave(world, &bd, &sd, notch, 5, &other), "PG_CONFIG_SHAPES")) return fail("a concave body is not refused by name");
    if (!refused(world, pg_make_chain(world, &bd, &sd, square, 4, 0, &other), "PG_CONFIG_SHAPES")) return fail("a chain is not refused by name");
    if (pg_geometry_capsule(square[0], square[1], PG_FIX_ONE / 4, &g) != PG_ERR_INVALID_ARGUMENT) return fail("pg_geometry_capsule makes a capsule");
    if (pg_geometry_segment(square[0], square[1], &g) != PG_ERR_INVALID_ARGUMENT) return fail("pg_geometry_segment makes a segment");
    if (pg_geometry_polygon(square, 3, &g) != PG_ERR_INVALID_ARGUMENT) return fail("pg_geometry_polygon makes a triangle");
    if (pg_geometry_polygon(square, 4, &g) != PG_OK) return fail("pg_geometry_polygon refuses a square");
    g.kind = PG_SHAPE_SEGMENT; /* by hand: pg_shape_create must refuse it too */
    g.count = 2;
    if (!refused(world, pg_shape_create(world, ground, &sd, &g, &shape), "PG_CONFIG_SHAPES")) return fail("a segment is not refused by name");
    if (pg_world_get_stats(world).body_count != 1) return fail("a refused call made a body");

    /* what is kept: a 1 m box dropped 1.5 m onto the wall (top at y = 0.5 m), a ball of
     * radius 0.25 m dropped on the box; at rest their centres are at 1.0 m and 1.75 m,
     * within the contacts' slop of a few millimetres */
    bd.position = pg_v2(0, PG_FIX_C(2) + PG_FIX_HALF);
    if (pg_make_box(world, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box) != PG_OK) return fail("no box");
    bd.position = pg_v2(0, PG_FIX_C(4));
    if (pg_make_ball(world, &bd, &sd, PG_FIX_ONE / 4, &ball) != PG_OK) return fail("no ball");
    for (i = 0; i < 300; ++i) /* 5 s */
        if (pg_world_step(world) != PG_OK) return fail("a step failed");
    if (!near(pg_body_position(world, box).y, PG_FIX_ONE)) return fail("the box is not resting on the wall");
    if (!near(pg_body_position(world, ball).y, PG_FIX_ONE + 3 * PG_FIX_ONE / 4)) return fail("the ball is not resting on the box");
    return 0;
}
