/* world_draw_joints.c — the joints of any world as a draw list (see world_draw.h), and
 * the anchor the app's mouse joints carry in their user_data.
 *
 * The core lists a body's joints (pg_body_joints) but not a world's, so the joints are
 * found through the bodies the AABB query returns (those with a shape), in slot order: a
 * joint is listed from its body B, or from its body A when B has no shape (a pin to a
 * shapeless anchor is listed from the pinned body, which is B). A joint between two
 * shapeless bodies is not seen, nor drawn.
 */
#include "world_draw.h"

#include <stdlib.h>

#define JOINTS_PER_BODY 64u
#define ANCHOR_BITS 24
#define ANCHOR_MASK ((UINT64_C(1) << ANCHOR_BITS) - 1u)
#define ANCHOR_LIMIT ((int32_t)1 << (ANCHOR_BITS - 1))

uint64_t pga_user_data_with_anchor(pg_vec2 local)
{
    uint64_t x = (uint64_t)(uint32_t)local.x & ANCHOR_MASK, y = (uint64_t)(uint32_t)local.y & ANCHOR_MASK;
    if (local.x < -ANCHOR_LIMIT || local.x >= ANCHOR_LIMIT || local.y < -ANCHOR_LIMIT || local.y >= ANCHOR_LIMIT) return 0;
    return PGA_ANCHOR_FLAG | x | (y << ANCHOR_BITS);
}

static pg_fix sign_extend(uint64_t bits)
{
    int32_t v = (int32_t)(uint32_t)(bits & ANCHOR_MASK);
    return v >= ANCHOR_LIMIT ? v - 2 * ANCHOR_LIMIT : v;
}

int pga_anchor_from_user_data(uint64_t user_data, pg_vec2 *local)
{
    if ((user_data & PGA_ANCHOR_FLAG) == 0 || local == NULL) return 0;
    local->x = sign_extend(user_data);
    local->y = sign_extend(user_data >> ANCHOR_BITS);
    return 1;
}

static pg_vec2 to_world(const pg_world *w, pg_body_id body, pg_vec2 local)
{
    return pg_v2_add(pg_body_position(w, body), pg_rot_apply(pg_rot_from_angle(pg_body_angle(w, body)), local));
}

static uint32_t color_of(pg_joint_type type, int spring)
{
    switch (type) {
    case PG_JOINT_DISTANCE: return spring ? 0xdb2777u : 0x374151u; /* spring pink, rod dark grey */
    case PG_JOINT_REVOLUTE: return 0x111827u;                      /* pin: near black */
    case PG_JOINT_MOUSE: return 0x0891b2u;                         /* drag: cyan */
    default: return 0x7c3aedu;                                     /* weld, prismatic: violet */
    }
}

/* The world anchors of one joint; 0 when its def cannot be read. */
static int describe(const pg_world *w, pg_joint_id j, pga_draw_joint *d)
{
    pg_body_id a = pg_joint_body_a(w, j), b = pg_joint_body_b(w, j);
    pg_vec2 la = pg_v2_zero(), lb = pg_v2_zero();
    d->joint = j;
    d->type = pg_joint_type_of(w, j);
    d->spring = 0;
    switch (d->type) {
    case PG_JOINT_DISTANCE: {
        pg_distance_joint_def def;
        if (pg_distance_joint_get_def(w, j, &def) != PG_OK) return 0;
        la = def.local_anchor_a, lb = def.local_anchor_b, d->spring = def.enable_spring != 0;
        break;
    }
    case PG_JOINT_REVOLUTE: {
        pg_revolute_joint_def def;
        if (pg_revolute_joint_get_def(w, j, &def) != PG_OK) return 0;
        la = def.local_anchor_a, lb = def.local_anchor_b;
        break;
    }
    case PG_JOINT_WELD: {
        pg_weld_joint_def def;
        if (pg_weld_joint_get_def(w, j, &def) != PG_OK) return 0;
        la = def.local_anchor_a, lb = def.local_anchor_b;
        break;
    }
    case PG_JOINT_PRISMATIC: {
        pg_prismatic_joint_def def;
        if (pg_prismatic_joint_get_def(w, j, &def) != PG_OK) return 0;
        la = def.local_anchor_a, lb = def.local_anchor_b;
        break;
    }
    case PG_JOINT_MOUSE: {
        pg_mouse_joint_def def;
        if (pg_mouse_joint_get_def(w, j, &def) != PG_OK) return 0;
        d->a = def.target;
        d->origin_a = def.target;
        if (!pga_anchor_from_user_data(def.user_data, &lb)) lb = pg_v2_zero(); /* not the app's: its origin */
        d->b = to_world(w, b, lb);
        d->origin_b = pg_body_position(w, b);
        d->color = color_of(d->type, 0);
        return 1;
    }
    default: return 0;
    }
    d->a = to_world(w, a, la);
    d->b = to_world(w, b, lb);
    d->origin_a = pg_body_position(w, a);
    d->origin_b = pg_body_position(w, b);
    d->color = color_of(d->type, d->spring);
    return 1;
}

static int has_shape(const pg_world *w, pg_body_id body)
{
    pg_shape_id s;
    return pg_body_shapes(w, body, &s, 1) > 0;
}

uint32_t pga_world_draw_joints(const pg_world *world, pga_draw_joint *out, uint32_t capacity)
{
    pg_world_def def;
    pg_aabb everything;
    pg_body_id *bodies;
    pg_joint_id joints[JOINTS_PER_BODY];
    uint32_t body_count = 0, total = 0, i, k, n;
    if (world == NULL) return 0;
    def = pg_world_get_def(world);
    if (def.max_joints == 0) return 0;
    bodies = (pg_body_id *)malloc((size_t)(def.max_bodies != 0 ? def.max_bodies : 1) * sizeof *bodies);
    if (bodies == NULL) return 0;
    everything.lo = pg_v2(PG_FIX_MIN, PG_FIX_MIN);
    everything.hi = pg_v2(PG_FIX_MAX, PG_FIX_MAX);
    if (pg_world_query_aabb(world, everything, bodies, def.max_bodies, &body_count) != PG_OK) body_count = 0;
    if (body_count > def.max_bodies) body_count = def.max_bodies;
    for (i = 0; i < body_count; ++i) {
        n = pg_body_joints(world, bodies[i], joints, JOINTS_PER_BODY);
        if (n > JOINTS_PER_BODY) n = JOINTS_PER_BODY;
        for (k = 0; k < n; ++k) {
            pg_body_id b = pg_joint_body_b(world, joints[k]);
            pga_draw_joint d;
            if (!pg_body_id_equal(b, bodies[i]) && (!pg_body_id_equal(pg_joint_body_a(world, joints[k]), bodies[i]) || has_shape(world, b)))
                continue; /* listed from its other body */
            if (!describe(world, joints[k], &d)) continue;
            if (out != NULL && total < capacity) out[total] = d;
            total++;
        }
    }
    free(bodies);
    return total;
}
