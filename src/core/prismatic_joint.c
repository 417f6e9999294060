/* prismatic_joint.c — the prismatic joint: body B slides along an axis fixed in body A,
 * with optional limits and a motor (docs/joints.md): its def and setters, and its rows
 * through the solver's stages. */
#include "def_cookie.h"
#include "prismatic_joint.h"
#include "error.h"
#include "intmath.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

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
    /* an axis already of unit length (as stored, then written and read back) is kept: made
     * unit again it could move by an LSB, and a world written as a scene would not load
     * to the same joint */
    if (len >= 65535 && len <= 65537) {
        *out = axis;
        return PG_OK;
    }
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
    pg__joint_store_limits(world, j, enable, lower, upper);
    return PG_OK;
}

pg_result pg_prismatic_joint_set_motor(pg_world *world, pg_joint_id id, int enable, pg_fix speed, pg_fix max_force)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_PRISMATIC, "pg_prismatic_joint_set_motor", &r);
    if (j == NULL) return r;
    if ((r = check_motor(world, speed, max_force)) != PG_OK) return r;
    pg__joint_store_motor(world, j, enable, speed, max_force);
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

/* ---- the rows ------------------------------------------------------------------------------ */
/* Box2D v3's rows, one after the other: the motor and the limits along the axis, then
 * the row across the axis and the angle. A's lever arm of the linear rows reaches B's
 * anchor (rA + d), so the rows turn A as a force at B's anchor would. */

static int has_limit(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_LIMIT) != 0; }
static int has_motor(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_MOTOR) != 0; }

void pg__prismatic_joint_prepare(joint_constraint *c, const step_context *ctx)
{
    const pg_joint *j = c->src;
    pg_rot rA = pg_rot_from_angle(c->A.fixed_angle);
    pg_vec2 axis = pg_rot_apply(rA, j->axis);
    pg_dir d = pg_dir_normalize(axis.x, axis.y), n;
    pg_vec2 gap = pg_v2(pg__sat64((int64_t)c->B.fixed_point.x - c->A.fixed_point.x), pg__sat64((int64_t)c->B.fixed_point.y - c->A.fixed_point.y));
    pg_vec2 reach = pg_v2_add(c->A.lever, gap);
    n.x = -d.y;
    n.y = d.x;
    c->axis0 = axis;
    pg__joint_row_linear(&c->axial, &c->A, &c->B, d, reach, c->B.lever);
    pg__joint_row_linear(&c->perp, &c->A, &c->B, n, reach, c->B.lever);
    pg__joint_row_angular(&c->angular, &c->A, &c->B);
    c->imp[0] = j->point_impulse[0];
    c->axial_imp = j->axial_impulse;
    c->motor_imp = has_motor(j) ? j->motor_impulse : 0;
    c->lower_imp = has_limit(j) ? j->lower_impulse : 0;
    c->upper_imp = has_limit(j) ? j->upper_impulse : 0;
    c->motor_max = pg__joint_row_cap(c->axial.K, j->max_motor, ctx->h_q32);
    if (c->motor_imp > c->motor_max) c->motor_imp = c->motor_max;
    if (c->motor_imp < -c->motor_max) c->motor_imp = -c->motor_max;
}

/* The axis (turned with A) and the levers where the bodies are now: the translation
 * along the axis and the offset across it (c->along, c->across), m. */
static void orient(joint_constraint *c, const solver_body *bodies)
{
    int64_t ax, ay, bx, by, dx, dy;
    pg_vec2 axis, reach;
    pg_dir d, n;
    (void)joint_levers_now(c, bodies); /* the direction moves with the centres too: oriented every pass */
    axis = c->A.active ? pg_rot_apply(bodies[c->A.slot].dq, c->axis0) : c->axis0; /* Q16.16 unit */
    d = pg_dir_normalize(axis.x, axis.y);
    n.x = -d.y;
    n.y = d.x;
    joint_anchor_now(&c->A, bodies, &ax, &ay);
    joint_anchor_now(&c->B, bodies, &bx, &by);
    dx = clamp64(bx - ax, INT32_MAX);
    dy = clamp64(by - ay, INT32_MAX);
    reach = pg_v2(pg__sat64((int64_t)c->A.lever_now.x + dx), pg__sat64((int64_t)c->A.lever_now.y + dy));
    pg__joint_row_orient(&c->axial, d, reach, c->B.lever_now);
    pg__joint_row_orient(&c->perp, n, reach, c->B.lever_now);
    c->along = pg__round_shift64(dx * axis.x + dy * axis.y, 16);
    c->across = pg__round_shift64(dy * axis.x - dx * axis.y, 16);
}

void pg__prismatic_joint_warm_start(joint_constraint *c, solver_body *bodies)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    if (!c->axial.on) return;
    orient(c, bodies);
    joint_row_apply(&c->axial, &A, &B, c->motor_imp + c->lower_imp - c->upper_imp);
    joint_row_apply(&c->perp, &A, &B, c->imp[0]);
    if (c->angular.on) joint_row_apply(&c->angular, &A, &B, c->axial_imp);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__prismatic_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
    const pg_joint *j = c->src;
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    int64_t along, across;
    pg_angle aA;
    if (!c->axial.on) return;
    aA = joint_angle_now(&c->A, bodies);
    if (moved) orient(c, bodies);
    along = c->along;
    across = c->across;
    if (has_motor(j)) pg__joint_motor_solve(&c->axial, &c->motor_imp, &A, &B, j->motor_speed, c->motor_max);
    if (has_limit(j)) {
        pg__joint_limit_solve(&c->axial, &c->lower_imp, &A, &B, along - j->lower, 1, &c->soft, use_bias, ctx->n);
        pg__joint_limit_solve(&c->axial, &c->upper_imp, &A, &B, along - j->upper, -1, &c->soft, use_bias, ctx->n);
    }
    pg__joint_row_solve(&c->perp, &c->imp[0], &A, &B, across, &c->soft, use_bias);
    pg__joint_row_solve(&c->angular, &c->axial_imp, &A, &B, pg_angle_to_radians(joint_angle_now(&c->B, bodies) - aA - j->reference_angle),
                    &c->soft, use_bias);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__prismatic_joint_store(const joint_constraint *c, pg_joint *j)
{
    j->point_impulse[0] = (pg_fix)c->imp[0];
    j->axial_impulse = (pg_fix)c->axial_imp;
    j->motor_impulse = (pg_fix)c->motor_imp;
    j->lower_impulse = (pg_fix)c->lower_imp;
    j->upper_impulse = (pg_fix)c->upper_imp;
}

void pg__prismatic_joint_impulse(const joint_constraint *c, int64_t out[3])
{
    int64_t pa = pg__joint_row_impulse(&c->axial, c->motor_imp + c->lower_imp - c->upper_imp);
    int64_t pp = pg__joint_row_impulse(&c->perp, c->imp[0]);
    out[0] = row_round(pa * c->axial.d.x + pp * c->perp.d.x, 30);
    out[1] = row_round(pa * c->axial.d.y + pp * c->perp.d.y, 30);
    out[2] = pg__joint_row_impulse(&c->angular, c->axial_imp);
}
#endif
