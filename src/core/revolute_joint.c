/* revolute_joint.c — the revolute joint: a pin, with optional angle limits and a motor
 * (docs/joints.md): its def and setters, and its rows through the solver's stages. */
#include "def_cookie.h"
#include "revolute_joint.h"
#include "error.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

pg_revolute_joint_def pg_default_revolute_joint_def(void)
{
    pg_revolute_joint_def d;
    d.body_a.index = d.body_a.generation = 0;
    d.body_b = d.body_a;
    d.local_anchor_a = d.local_anchor_b = pg_v2_zero();
    d.reference_angle = 0;
    d.enable_limit = 0;
    d.lower_angle = d.upper_angle = 0;
    d.enable_motor = 0;
    d.motor_speed = 0;
    d.max_motor_torque = 0;
    d.collide_connected = 0;
    d.user_data = 0;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

static pg_result check_limits(const pg_world *world, pg_fix lo, pg_fix hi)
{
    if (lo < -PG_FIX_PI || lo > PG_FIX_PI) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "revolute lower_angle", lo, "rad is outside -pi..pi");
    if (hi < -PG_FIX_PI || hi > PG_FIX_PI) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "revolute upper_angle", hi, "rad is outside -pi..pi");
    if (lo > hi) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "revolute lower_angle", lo, "rad is above upper_angle");
    return PG_OK;
}

static pg_result check_motor(const pg_world *world, pg_fix speed, pg_fix torque)
{
    if (speed < -PG_FIX_C(1000) || speed > PG_FIX_C(1000)) return pg__fail_value(world, PG_ERR_ENVELOPE, "revolute motor_speed", speed, "rad/s is outside +-1000");
    if (torque < 0) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "revolute max_motor_torque", torque, "N m is negative");
    return PG_OK;
}

pg_result pg_revolute_joint_create(pg_world *world, const pg_revolute_joint_def *def, pg_joint_id *out)
{
    pg_joint j = {0};
    pg_result r;
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    if (def->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the def was not made by pg_default_revolute_joint_def(): start from it and change the fields you need");
    r = pg__joint_check_bodies(world, "pg_revolute_joint_create", def->body_a, def->body_b, def->local_anchor_a, def->local_anchor_b, &j);
    if (r == PG_OK) r = check_limits(world, def->lower_angle, def->upper_angle);
    if (r == PG_OK) r = check_motor(world, def->motor_speed, def->max_motor_torque);
    if (r != PG_OK) return r;
    j.type = PG_JOINT_REVOLUTE;
    j.reference_angle = def->reference_angle;
    j.lower = def->lower_angle;
    j.upper = def->upper_angle;
    j.motor_speed = def->motor_speed;
    j.max_motor = def->max_motor_torque;
    j.flags = (def->enable_limit ? PG_JOINT_FLAG_LIMIT : 0u) | (def->enable_motor ? PG_JOINT_FLAG_MOTOR : 0u) |
              (def->collide_connected ? PG_JOINT_FLAG_COLLIDE : 0u);
    j.user_data = def->user_data;
    return pg__joint_add(world, &j, out);
}

pg_result pg_revolute_joint_set_limits(pg_world *world, pg_joint_id id, int enable, pg_fix lower, pg_fix upper)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_REVOLUTE, "pg_revolute_joint_set_limits", &r);
    if (j == NULL) return r;
    if ((r = check_limits(world, lower, upper)) != PG_OK) return r;
    pg__joint_store_limits(world, j, enable, lower, upper);
    return PG_OK;
}

pg_result pg_revolute_joint_set_motor(pg_world *world, pg_joint_id id, int enable, pg_fix speed, pg_fix max_torque)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_REVOLUTE, "pg_revolute_joint_set_motor", &r);
    if (j == NULL) return r;
    if ((r = check_motor(world, speed, max_torque)) != PG_OK) return r;
    pg__joint_store_motor(world, j, enable, speed, max_torque);
    return PG_OK;
}

pg_fix pg_revolute_joint_angle(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_REVOLUTE);
    if (j == NULL) return 0;
    return pg_angle_to_radians(world->bodies[j->body_b].angle - world->bodies[j->body_a].angle - j->reference_angle);
}

pg_result pg_revolute_joint_get_def(const pg_world *world, pg_joint_id id, pg_revolute_joint_def *out)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_REVOLUTE);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_revolute_joint_get_def: not a valid revolute joint handle");
    *out = pg_default_revolute_joint_def();
    out->body_a = pg__body_handle(world, j->body_a);
    out->body_b = pg__body_handle(world, j->body_b);
    out->local_anchor_a = j->anchor_a;
    out->local_anchor_b = j->anchor_b;
    out->reference_angle = j->reference_angle;
    out->enable_limit = (j->flags & PG_JOINT_FLAG_LIMIT) != 0;
    out->lower_angle = j->lower;
    out->upper_angle = j->upper;
    out->enable_motor = (j->flags & PG_JOINT_FLAG_MOTOR) != 0;
    out->motor_speed = j->motor_speed;
    out->max_motor_torque = j->max_motor;
    out->collide_connected = (j->flags & PG_JOINT_FLAG_COLLIDE) != 0;
    out->user_data = j->user_data;
    return PG_OK;
}

/* ---- the rows ------------------------------------------------------------------------------ */
/* gcc's -Os (the Cortex-M builds) keeps one copy of the pass and calls the point block's
 * shared out-of-line kernels; other builds inline them into each form of the pass. The
 * same arithmetic either way, so the same bits. */
#if defined(__OPTIMIZE_SIZE__)
#define revolute_point_solve pg__joint_point_solve
#define revolute_point_apply pg__joint_point_apply
#else
#define revolute_point_solve joint_point_solve
#define revolute_point_apply joint_point_apply
#endif
/* The pin is a 2x2 point block; the motor and the two limits share one angular row
 * (wB - wA). Order in a pass, as Box2D v3's: motor, limits, then the point, so the point
 * has the last word. */

static int has_limit(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_LIMIT) != 0; }
static int has_motor(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_MOTOR) != 0; }

void pg__revolute_joint_prepare(joint_constraint *c, const step_context *ctx)
{
    const pg_joint *j = c->src;
    pg__joint_point_init(&c->point, &c->A, &c->B);
    c->imp[0] = j->point_impulse[0];
    c->imp[1] = j->point_impulse[1];
    c->motor_imp = c->lower_imp = c->upper_imp = c->motor_max = 0;
    if (!has_motor(j) && !has_limit(j)) { /* a bare pin: the angular row is never read */
        c->angular.on = 0;
        c->angular.K = 0;
        return;
    }
    pg__joint_row_angular(&c->angular, &c->A, &c->B);
    if (has_limit(j)) {
        c->lower_imp = j->lower_impulse;
        c->upper_imp = j->upper_impulse;
    }
    if (has_motor(j)) {
        c->motor_max = pg__joint_row_cap(c->angular.K, j->max_motor, ctx->h_q32);
        c->motor_imp = clamp64(j->motor_impulse, c->motor_max);
    }
}

void pg__revolute_joint_warm_start(joint_constraint *c, solver_body *bodies)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    /* the levers are current: a body turns only when positions are integrated, and the
     * first relax sweep after that (joint_solver.c) turned them and made the angular
     * coefficients again; in the first substep the set-up's hold (no turn yet) */
    if (c->point.S == 0) return;
    revolute_point_apply(&c->point, &A, &B, c->imp[0], c->imp[1]);
    if (c->angular.on && (c->motor_imp | c->lower_imp | c->upper_imp) != 0) /* a row of lambda 0 changes nothing */
        joint_row_apply(&c->angular, &A, &B, c->motor_imp + c->lower_imp - c->upper_imp);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

/* A pass, inline in the two forms the stages call (the solve pass, with bias; a relax
 * sweep, without), so each is specialised. */
PG__INLINE_PASS void revolute_pass(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
    const pg_joint *j = c->src;
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    int64_t ax = 0, ay = 0, bx = 0, by = 0;
    if (c->point.S == 0) return;
    if (moved && joint_levers_now(c, bodies)) pg__joint_point_orient(&c->point, c->A.lever_now, c->B.lever_now);
    if ((j->flags & (PG_JOINT_FLAG_MOTOR | PG_JOINT_FLAG_LIMIT)) != 0) {
        if (has_motor(j)) pg__joint_motor_solve(&c->angular, &c->motor_imp, &A, &B, j->motor_speed, c->motor_max);
        if (has_limit(j)) {
            pg_angle rel = joint_angle_now(&c->B, bodies) - joint_angle_now(&c->A, bodies) - j->reference_angle;
            int64_t angle = pg_angle_to_radians(rel);
            pg__joint_limit_solve(&c->angular, &c->lower_imp, &A, &B, angle - j->lower, 1, &c->soft, use_bias, ctx->n);
            pg__joint_limit_solve(&c->angular, &c->upper_imp, &A, &B, angle - j->upper, -1, &c->soft, use_bias, ctx->n);
        }
    }
    if (use_bias) { /* a relax sweep has no bias: the point's position error is not read */
        joint_anchor_now(&c->A, bodies, &ax, &ay);
        joint_anchor_now(&c->B, bodies, &bx, &by);
    }
    revolute_point_solve(c, &A, &B, bx - ax, by - ay, &c->soft, use_bias);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__revolute_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
#if defined(__OPTIMIZE_SIZE__)
    revolute_pass(c, bodies, ctx, use_bias, moved);
#else
    if (use_bias) revolute_pass(c, bodies, ctx, 1, moved);
    else revolute_pass(c, bodies, ctx, 0, moved);
#endif
}

void pg__revolute_joint_store(const joint_constraint *c, pg_joint *j)
{
    j->point_impulse[0] = (pg_fix)c->imp[0];
    j->point_impulse[1] = (pg_fix)c->imp[1];
    j->motor_impulse = (pg_fix)c->motor_imp;
    j->lower_impulse = (pg_fix)c->lower_imp;
    j->upper_impulse = (pg_fix)c->upper_imp;
}

void pg__revolute_joint_impulse(const joint_constraint *c, int64_t out[3])
{
    pg__joint_point_impulse(&c->point, c->imp, out);
    out[2] = pg__joint_row_impulse(&c->angular, c->motor_imp + c->lower_imp - c->upper_imp);
}
#endif
