/* joint_pool.c — the joint pool and the bodies' joint lists. A slot is taken lowest
 * first, so which slot a new joint gets is a function of the state; the lists only
 * answer "which joints has this body", never decide an order. */
#include "island.h"
#include "joint_pool.h"
#include "reach.h"

pg_joint *pg__joint(const pg_world *world, pg_joint_id id)
{
    pg_joint *j;
    if (world == NULL || id.index >= world->def.max_joints || id.generation == 0) return NULL;
    j = &world->joints[id.index];
    return ((j->flags & PG_JOINT_FLAG_USED) != 0 && j->generation == id.generation) ? j : NULL;
}

uint32_t pg__joint_free_slot(const pg_world *world)
{
    uint32_t i;
    for (i = 0; i < world->joint_high; ++i)
        if ((world->joints[i].flags & PG_JOINT_FLAG_USED) == 0) return i;
    return world->joint_high < world->def.max_joints ? world->joint_high : PG_NULL_INDEX;
}

uint32_t pg__joint_next_of_body(const pg_world *world, uint32_t j, uint32_t b)
{
    const pg_joint *jt = &world->joints[j];
    return jt->body_a == b ? jt->next_a : jt->next_b;
}

static void link(pg_world *world, uint32_t j)
{
    pg_joint *jt = &world->joints[j];
    jt->next_a = jt->next_b = PG_NULL_INDEX;
    if (jt->body_a != PG_NULL_INDEX) {
        jt->next_a = world->bodies[jt->body_a].first_joint;
        world->bodies[jt->body_a].first_joint = j;
    }
    jt->next_b = world->bodies[jt->body_b].first_joint;
    world->bodies[jt->body_b].first_joint = j;
}

static void unlink_from(pg_world *world, uint32_t j, uint32_t b)
{
    uint32_t *at = &world->bodies[b].first_joint;
    while (*at != PG_NULL_INDEX) {
        if (*at == j) {
            *at = pg__joint_next_of_body(world, j, b);
            return;
        }
        {
            pg_joint *o = &world->joints[*at];
            at = o->body_a == b ? &o->next_a : &o->next_b;
        }
    }
}

void pg__joint_wake(pg_world *world, const pg_joint *joint)
{
    if (joint->body_a != PG_NULL_INDEX && world->bodies[joint->body_a].type != PG_BODY_STATIC) pg__wake_body(world, joint->body_a);
    if (world->bodies[joint->body_b].type != PG_BODY_STATIC) pg__wake_body(world, joint->body_b);
}

pg_joint_id pg__joint_insert(pg_world *world, uint32_t slot, const pg_joint *joint)
{
    pg_joint *jt = &world->joints[slot];
    uint32_t generation = jt->generation + 1u;
    pg_joint_id id;
    if (generation == 0) generation = 1u; /* the zero handle is never valid */
    *jt = *joint;
    jt->generation = generation;
    jt->flags |= PG_JOINT_FLAG_USED;
    link(world, slot);
    if (slot >= world->joint_high) world->joint_high = slot + 1u;
    world->joint_count += 1u;
    pg__joint_wake(world, jt);
    id.index = slot;
    id.generation = generation;
    return id;
}

void pg__joint_remove(pg_world *world, uint32_t j)
{
    pg_joint *jt = &world->joints[j];
    uint32_t generation = jt->generation;
    pg__joint_wake(world, jt);
    if (jt->body_a != PG_NULL_INDEX) unlink_from(world, j, jt->body_a);
    unlink_from(world, j, jt->body_b);
    {
        /* every field but the generation back to zero: a free slot hashes as one */
        pg_joint zero = {0};
        *jt = zero;
    }
    jt->generation = generation;
    jt->next_a = jt->next_b = PG_NULL_INDEX;
    world->joint_count -= 1u;
}

void pg__joints_remove_of_body(pg_world *world, uint32_t b)
{
    while (world->bodies[b].first_joint != PG_NULL_INDEX) pg__joint_remove(world, world->bodies[b].first_joint);
}

int pg__joint_blocks_collision(const pg_world *world, uint32_t a, uint32_t b)
{
    uint32_t j;
    for (j = world->bodies[a].first_joint; j != PG_NULL_INDEX; j = pg__joint_next_of_body(world, j, a)) {
        const pg_joint *jt = &world->joints[j];
        if ((jt->body_a == b || jt->body_b == b) && (jt->flags & PG_JOINT_FLAG_COLLIDE) == 0) return 1;
    }
    return 0;
}

const char *pg__joint_type_change_problem(const pg_world *world, uint32_t b, pg_body_type type)
{
    uint32_t j;
    for (j = world->bodies[b].first_joint; j != PG_NULL_INDEX; j = pg__joint_next_of_body(world, j, b)) {
        const pg_joint *jt = &world->joints[j];
        uint32_t other = jt->body_a == b ? jt->body_b : jt->body_a;
        pg_vec2 anchor = jt->body_a == b ? jt->anchor_a : jt->anchor_b;
        pg_fix ax = pg_fix_abs(anchor.x), ay = pg_fix_abs(anchor.y);
        if ((ax > ay ? ax : ay) > pg__body_reach_limit(type))
            return "a joint's anchor on this body is beyond 50 m of its origin, farther than a moving body's anchor may be: destroy the joint first";
        if (jt->type == PG_JOINT_MOUSE) {
            if (type != PG_BODY_DYNAMIC)
                return "a mouse joint pulls this body, and it pulls only a dynamic body: destroy the mouse joint first";
        } else if (type == PG_BODY_STATIC && other != PG_NULL_INDEX && world->bodies[other].type == PG_BODY_STATIC) {
            return "a joint joins this body to a static body, and a joint needs a body that can move: destroy the joint first";
        }
    }
    return NULL;
}

void pg__joint_rebuild_lists(pg_world *world)
{
    uint32_t i, j;
    for (i = 0; i < world->def.max_bodies; ++i) world->bodies[i].first_joint = PG_NULL_INDEX;
    /* highest slot first, so each list runs in slot order */
    for (j = world->joint_high; j-- > 0;)
        if ((world->joints[j].flags & PG_JOINT_FLAG_USED) != 0) link(world, j);
}
