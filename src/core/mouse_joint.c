/* mouse_joint.c — the mouse (target) joint: pulls a body's anchor toward a world point
 * as a spring with a maximum force, what dragging uses (docs/joints.md): its def and
 * setters, and its rows through the solver's stages. */
#include "body.h"
#include "intmath.h"
#include "mouse_joint.h"
#include "def_cookie.h"
#include "error.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

pg_mouse_joint_def pg_default_mouse_joint_def(void)
{
    pg_mouse_joint_def d;
    d.body.index = d.body.generation = 0;
    d.target = pg_v2_zero();
    d.hertz = PG_FIX_C(5);
    d.damping_ratio = (pg_fix)45875; /* 0.7 */
    d.max_force = PG_FIX_C(1000);
    d.user_data = 0;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

static pg_result check_target(const pg_world *world, pg_vec2 target)
{
    if (!pg__in_position_envelope(target))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "mouse joint target component", target.x < -PG_FIX_C(1000) || target.x > PG_FIX_C(1000) ? target.x : target.y,
                              "m is outside +-1000 m");
    return PG_OK;
}

static pg_result check_force(const pg_world *world, pg_fix f)
{
    return f < 0 ? pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "mouse joint max_force", f, "N is negative") : PG_OK;
}

pg_result pg_mouse_joint_create(pg_world *world, const pg_mouse_joint_def *def, pg_joint_id *out)
{
    pg_joint j = {0};
    pg_result r;
    const pg_body *b;
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    if (def->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the def was not made by pg_default_mouse_joint_def(): start from it and change the fields you need");
    b = pg__body(world, def->body);
    if (b == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_mouse_joint_create: body is stale or invalid");
    if (b->type != PG_BODY_DYNAMIC) return pg__fail(world, PG_ERR_BODY_TYPE, "pg_mouse_joint_create: the body must be dynamic");
    if ((r = check_target(world, def->target)) != PG_OK) return r;
    if ((r = pg__joint_check_softness(world, def->hertz, def->damping_ratio, 0)) != PG_OK) return r;
    if ((r = check_force(world, def->max_force)) != PG_OK) return r;
    {
        /* the anchor: the body point under the target, in the body's frame */
        pg_vec2 d = pg_v2(pg__sat64((int64_t)def->target.x - b->origin.x), pg__sat64((int64_t)def->target.y - b->origin.y));
        pg_rot inv = b->rot;
        inv.s = -inv.s;
        j.anchor_b = pg_rot_apply(inv, d);
        if (pg_fix_abs(j.anchor_b.x) > PG_FIX_C(50) || pg_fix_abs(j.anchor_b.y) > PG_FIX_C(50))
            return pg__fail(world, PG_ERR_ENVELOPE, "pg_mouse_joint_create: the target is more than 50 m from the body's origin");
    }
    j.type = PG_JOINT_MOUSE;
    j.body_a = PG_NULL_INDEX;
    j.body_b = def->body.index;
    j.target = def->target;
    j.hertz = def->hertz;
    j.damping = def->damping_ratio;
    j.max_motor = def->max_force;
    j.flags = PG_JOINT_FLAG_COLLIDE; /* one body: nothing to filter */
    j.user_data = def->user_data;
    return pg__joint_add(world, &j, out);
}

pg_result pg_mouse_joint_set_target(pg_world *world, pg_joint_id id, pg_vec2 target)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_MOUSE, "pg_mouse_joint_set_target", &r);
    if (j == NULL) return r;
    if ((r = check_target(world, target)) != PG_OK) return r;
    j->target = target;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_mouse_joint_set_spring(pg_world *world, pg_joint_id id, pg_fix hertz, pg_fix damping_ratio)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_MOUSE, "pg_mouse_joint_set_spring", &r);
    if (j == NULL) return r;
    if ((r = pg__joint_check_softness(world, hertz, damping_ratio, 0)) != PG_OK) return r;
    j->hertz = hertz;
    j->damping = damping_ratio;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_mouse_joint_set_max_force(pg_world *world, pg_joint_id id, pg_fix max_force)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_MOUSE, "pg_mouse_joint_set_max_force", &r);
    if (j == NULL) return r;
    if ((r = check_force(world, max_force)) != PG_OK) return r;
    j->max_motor = max_force;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_mouse_joint_get_def(const pg_world *world, pg_joint_id id, pg_mouse_joint_def *out)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_MOUSE);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_mouse_joint_get_def: not a valid mouse joint handle");
    *out = pg_default_mouse_joint_def();
    out->body = pg__body_handle(world, j->body_b);
    out->target = j->target;
    out->hertz = j->hertz;
    out->damping_ratio = j->damping;
    out->max_force = j->max_motor;
    out->user_data = j->user_data;
    return PG_OK;
}

/* ---- the rows ------------------------------------------------------------------------------ */
/* A point block whose side A is the target (a point that does not move), soft, in the
 * solve pass only, with the impulse's magnitude capped at max_force h: in lambda units the cap is
 * on |K'^-1 L| <= max_force h S (joint_rows.h). */

void pg__mouse_joint_prepare(joint_constraint *c, const step_context *ctx)
{
    const pg_joint *j = c->src;
    int64_t fh = pg__mul64_shr(j->max_motor, ctx->h_q32, 32); /* Q16 N s */
    c->A.fixed_point = j->target;
    pg__joint_point_init(&c->point, &c->A, &c->B);
    c->soft = pg__joint_spring_softness(j->hertz, j->damping, ctx->n);
    c->imp[0] = j->point_impulse[0];
    c->imp[1] = j->point_impulse[1];
    c->motor_max = clamp64(pg__mul64_shr(c->point.S, fh, 38), LAMBDA_MAX);
}

void pg__mouse_joint_warm_start(joint_constraint *c, solver_body *bodies)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    if (c->point.S == 0) return;
    if (joint_levers_now(c, bodies)) pg__joint_point_orient(&c->point, c->A.lever_now, c->B.lever_now);
    pg__joint_point_apply(&c->point, &A, &B, c->imp[0], c->imp[1]);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__mouse_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    int64_t bx, by, vx, vy, nx, ny, qx, qy, q;
    (void)ctx;
    if (c->point.S == 0 || !use_bias) return; /* a spring: the solve pass only */
    if (moved && joint_levers_now(c, bodies)) pg__joint_point_orient(&c->point, c->A.lever_now, c->B.lever_now);
    joint_anchor_now(&c->B, bodies, &bx, &by);
    pg__joint_point_speed(&A, &B, c->A.lever_now, c->B.lever_now, &vx, &vy);
    nx = c->imp[0] + pg__joint_soft_delta(vx, row_round(c->soft.bias_rate * clamp64(bx - c->A.fixed_point.x, INT32_MAX), 16), c->imp[0], &c->soft, 1);
    ny = c->imp[1] + pg__joint_soft_delta(vy, row_round(c->soft.bias_rate * clamp64(by - c->A.fixed_point.y, INT32_MAX), 16), c->imp[1], &c->soft, 1);
    nx = clamp64(nx, LAMBDA_MAX);
    ny = clamp64(ny, LAMBDA_MAX);
    qx = row_round(c->point.kinv[0] * nx + c->point.kinv[1] * ny, 30);
    qy = row_round(c->point.kinv[1] * nx + c->point.kinv[2] * ny, 30);
    q = (int64_t)pg__sqrt_nearest((uint64_t)(qx * qx + qy * qy)); /* |q| <= 2^30: the squares fit */
    if (q > c->motor_max) { /* scale back to the cap, rounding toward zero */
        nx = nx * c->motor_max / q;
        ny = ny * c->motor_max / q;
    }
    pg__joint_point_apply(&c->point, &A, &B, nx - c->imp[0], ny - c->imp[1]);
    c->imp[0] = nx;
    c->imp[1] = ny;
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__mouse_joint_store(const joint_constraint *c, pg_joint *j)
{
    j->point_impulse[0] = (pg_fix)c->imp[0];
    j->point_impulse[1] = (pg_fix)c->imp[1];
}

void pg__mouse_joint_impulse(const joint_constraint *c, int64_t out[3])
{
    pg__joint_point_impulse(&c->point, c->imp, out);
    out[2] = 0;
}
#endif
