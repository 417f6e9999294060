/* prismatic_joint.c — the prismatic joint: body B slides along an axis fixed in body A,
 * with optional limits and a motor (docs/joints.md). Its def and setters here; its rows
 * in prismatic_joint_solver.c. */
#include "def_cookie.h"
#include "error.h"
#include "intmath.h"
#include "joint_def.h"
#include "joint_pool.h"

#define TRANSLATION_MAX PG_FIX_C(100)

pg_prismatic_joint_def pg_default_prismatic_joint_def(void)
{
    pg_prismatic_joint_def d;
    d.body_a.index = d.body_a.generation = 0;
    d.body_b = d.body_a;
    d.local_anchor_a = d.local_anchor_b = pg_v2_zero();
    d.local_axis_a = pg_v2(PG_FIX_ONE, 0);
    d.reference_angle = 0;
    d.enable_limit = 0;
    d.lower_translation = d.upper_translation = 0;
    d.enable_motor = 0;
    d.motor_speed = 0;
    d.max_motor_force = 0;
    d.collide_connected = 0;
    d.user_data = 0;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

static pg_result check_limits(const pg_world *world, pg_fix lo, pg_fix hi)
{
    if (lo < -TRANSLATION_MAX || lo > TRANSLATION_MAX) return pg__fail_value(world, PG_ERR_ENVELOPE, "prismatic lower_translation", lo, "m is outside +-100 m");
    if (hi < -TRANSLATION_MAX || hi > TRANSLATION_MAX) return pg__fail_value(world, PG_ERR_ENVELOPE, "prismatic upper_translation", hi, "m is outside +-100 m");
    if (lo > hi) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "prismatic lower_translation", lo, "m is above upper_translation");
    return PG_OK;
}

static pg_result check_motor(const pg_world *world, pg_fix speed, pg_fix force)
{
    if (speed < -PG_FIX_C(1000) || speed > PG_FIX_C(1000)) return pg__fail_value(world, PG_ERR_ENVELOPE, "prismatic motor_speed", speed, "m/s is outside +-1000");
    if (force < 0) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "prismatic max_motor_force", force, "N is negative");
    return PG_OK;
}

/* The axis as a unit vector in Q16.16; refused when shorter than 0.001 m (no direction). */
static pg_result unit_axis(const pg_world *world, pg_vec2 axis, pg_vec2 *out)
{
    int64_t x = axis.x, y = axis.y, len;
    if (axis.x < PG_FIX_MIN || axis.y < PG_FIX_MIN) x = y = 0;
    len = (int64_t)pg__sqrt_nearest((uint64_t)(x * x + y * y));
    if (len < 66) return pg__fail(world, PG_ERR_DEGENERATE, "prismatic local_axis_a has no direction: give a nonzero vector (any length)");
    *out = pg_v2((pg_fix)((x * 65536 + (x < 0 ? -len / 2 : len / 2)) / len), (pg_fix)((y * 65536 + (y < 0 ? -len / 2 : len / 2)) / len));
    return PG_OK;
}

pg_result pg_prismatic_joint_create(pg_world *world, const pg_prismatic_joint_def *def, pg_joint_id *out)
{
    pg_joint j = {0};
    pg_result r;
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    if (def->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the def was not made by pg_default_prismatic_joint_def(): start from it and change the fields you need");
    r = pg__joint_check_bodies(world, "pg_prismatic_joint_create", def->body_a, def->body_b, def->local_anchor_a, def->local_anchor_b, &j);
    if (r == PG_OK) r = unit_axis(world, def->local_axis_a, &j.axis);
    if (r == PG_OK) r = check_limits(world, def->lower_translation, def->upper_translation);
    if (r == PG_OK) r = check_motor(world, def->motor_speed, def->max_motor_force);
    if (r != PG_OK) return r;
    j.type = PG_JOINT_PRISMATIC;
    j.reference_angle = def->reference_angle;
    j.lower = def->lower_translation;
    j.upper = def->upper_translation;
    j.motor_speed = def->motor_speed;
    j.max_motor = def->max_motor_force;
    j.flags = (def->enable_limit ? PG_JOINT_FLAG_LIMIT : 0u) | (def->enable_motor ? PG_JOINT_FLAG_MOTOR : 0u) |
              (def->collide_connected ? PG_JOINT_FLAG_COLLIDE : 0u);
    j.user_data = def->user_data;
    return pg__joint_add(world, &j, out);
}

pg_result pg_prismatic_joint_set_limits(pg_world *world, pg_joint_id id, int enable, pg_fix lower, pg_fix upper)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_PRISMATIC, "pg_prismatic_joint_set_limits", &r);
    if (j == NULL) return r;
    if ((r = check_limits(world, lower, upper)) != PG_OK) return r;
    j->flags = enable ? j->flags | PG_JOINT_FLAG_LIMIT : j->flags & ~(uint32_t)PG_JOINT_FLAG_LIMIT;
    j->lower = lower;
    j->upper = upper;
    if (!enable) j->lower_impulse = j->upper_impulse = 0;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_prismatic_joint_set_motor(pg_world *world, pg_joint_id id, int enable, pg_fix speed, pg_fix max_force)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_PRISMATIC, "pg_prismatic_joint_set_motor", &r);
    if (j == NULL) return r;
    if ((r = check_motor(world, speed, max_force)) != PG_OK) return r;
    j->flags = enable ? j->flags | PG_JOINT_FLAG_MOTOR : j->flags & ~(uint32_t)PG_JOINT_FLAG_MOTOR;
    j->motor_speed = speed;
    j->max_motor = max_force;
    if (!enable) j->motor_impulse = 0;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_fix pg_prismatic_joint_translation(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_PRISMATIC);
    const pg_body *a;
    pg_vec2 pa, pb, axis;
    int64_t dx, dy;
    if (j == NULL) return 0;
    a = &world->bodies[j->body_a];
    pa = pg_v2_add(a->center, pg__joint_world_lever(world, j->body_a, j->anchor_a));
    pb = pg_v2_add(world->bodies[j->body_b].center, pg__joint_world_lever(world, j->body_b, j->anchor_b));
    axis = pg_rot_apply(a->rot, j->axis);
    dx = pg__sat64((int64_t)pb.x - pa.x);
    dy = pg__sat64((int64_t)pb.y - pa.y);
    return pg__sat64(pg__round_shift64(dx * axis.x + dy * axis.y, 16));
}

pg_result pg_prismatic_joint_get_def(const pg_world *world, pg_joint_id id, pg_prismatic_joint_def *out)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_PRISMATIC);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_prismatic_joint_get_def: not a valid prismatic joint handle");
    *out = pg_default_prismatic_joint_def();
    out->body_a = pg__body_handle(world, j->body_a);
    out->body_b = pg__body_handle(world, j->body_b);
    out->local_anchor_a = j->anchor_a;
    out->local_anchor_b = j->anchor_b;
    out->local_axis_a = j->axis;
    out->reference_angle = j->reference_angle;
    out->enable_limit = (j->flags & PG_JOINT_FLAG_LIMIT) != 0;
    out->lower_translation = j->lower;
    out->upper_translation = j->upper;
    out->enable_motor = (j->flags & PG_JOINT_FLAG_MOTOR) != 0;
    out->motor_speed = j->motor_speed;
    out->max_motor_force = j->max_motor;
    out->collide_connected = (j->flags & PG_JOINT_FLAG_COLLIDE) != 0;
    out->user_data = j->user_data;
    return PG_OK;
}
