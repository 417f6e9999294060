/* distance_joint.c — the distance joint: two anchors held at a length, as a rigid rod
 * or a spring, with optional minimum and maximum lengths (docs/joints.md): its def and
 * setters, and its rows through the solver's stages. */
#include "def_cookie.h"
#include "distance_joint.h"
#include "error.h"
#include "intmath.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

#define LENGTH_MIN ((pg_fix)328)   /* 0.005 m: the linear slop; shorter has no direction */
#define LENGTH_MAX PG_FIX_C(100)

pg_distance_joint_def pg_default_distance_joint_def(void)
{
    pg_distance_joint_def d;
    d.body_a.index = d.body_a.generation = 0;
    d.body_b = d.body_a;
    d.local_anchor_a = d.local_anchor_b = pg_v2_zero();
    d.length = PG_FIX_ONE;
    d.enable_spring = 0;
    d.hertz = 0;
    d.damping_ratio = 0;
    d.enable_limit = 0;
    d.min_length = 0;
    d.max_length = LENGTH_MAX;
    d.collide_connected = 0;
    d.user_data = 0;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

static pg_result check_length(const pg_world *world, pg_fix length)
{
    if (length < LENGTH_MIN || length > LENGTH_MAX) return pg__fail_value(world, PG_ERR_ENVELOPE, "distance joint length", length, "m is outside 0.005..100 m");
    return PG_OK;
}

static pg_result check_limits(const pg_world *world, pg_fix lo, pg_fix hi)
{
    if (lo < 0 || lo > LENGTH_MAX) return pg__fail_value(world, PG_ERR_ENVELOPE, "distance joint min_length", lo, "m is outside 0..100 m");
    if (hi < 0 || hi > LENGTH_MAX) return pg__fail_value(world, PG_ERR_ENVELOPE, "distance joint max_length", hi, "m is outside 0..100 m");
    if (lo > hi) return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "distance joint min_length", lo, "m is above max_length");
    return PG_OK;
}

pg_result pg_distance_joint_create(pg_world *world, const pg_distance_joint_def *def, pg_joint_id *out)
{
    pg_joint j = {0};
    pg_result r;
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    if (def->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the def was not made by pg_default_distance_joint_def(): start from it and change the fields you need");
    r = pg__joint_check_bodies(world, "pg_distance_joint_create", def->body_a, def->body_b, def->local_anchor_a, def->local_anchor_b, &j);
    if (r == PG_OK) r = check_length(world, def->length);
    if (r == PG_OK) r = pg__joint_check_softness(world, def->hertz, def->damping_ratio, 1);
    if (r == PG_OK) r = check_limits(world, def->min_length, def->max_length);
    if (r != PG_OK) return r;
    j.type = PG_JOINT_DISTANCE;
    j.length = def->length;
    j.hertz = def->hertz;
    j.damping = def->damping_ratio;
    j.lower = def->min_length;
    j.upper = def->max_length;
    j.flags = (def->enable_spring ? PG_JOINT_FLAG_SPRING : 0u) | (def->enable_limit ? PG_JOINT_FLAG_LIMIT : 0u) |
              (def->collide_connected ? PG_JOINT_FLAG_COLLIDE : 0u);
    j.user_data = def->user_data;
    return pg__joint_add(world, &j, out);
}

pg_result pg_distance_joint_set_length(pg_world *world, pg_joint_id id, pg_fix length)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_DISTANCE, "pg_distance_joint_set_length", &r);
    if (j == NULL) return r;
    if ((r = check_length(world, length)) != PG_OK) return r;
    j->length = length;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_distance_joint_set_spring(pg_world *world, pg_joint_id id, int enable, pg_fix hertz, pg_fix damping_ratio)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_DISTANCE, "pg_distance_joint_set_spring", &r);
    if (j == NULL) return r;
    if ((r = pg__joint_check_softness(world, hertz, damping_ratio, 1)) != PG_OK) return r;
    j->flags = enable ? j->flags | PG_JOINT_FLAG_SPRING : j->flags & ~(uint32_t)PG_JOINT_FLAG_SPRING;
    j->hertz = hertz;
    j->damping = damping_ratio;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_distance_joint_set_limits(pg_world *world, pg_joint_id id, int enable, pg_fix min_length, pg_fix max_length)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_DISTANCE, "pg_distance_joint_set_limits", &r);
    if (j == NULL) return r;
    if ((r = check_limits(world, min_length, max_length)) != PG_OK) return r;
    j->flags = enable ? j->flags | PG_JOINT_FLAG_LIMIT : j->flags & ~(uint32_t)PG_JOINT_FLAG_LIMIT;
    j->lower = min_length;
    j->upper = max_length;
    if (!enable) j->lower_impulse = j->upper_impulse = 0;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_fix pg_distance_joint_current_length(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_DISTANCE);
    pg_vec2 pa, pb;
    int64_t dx, dy;
    if (j == NULL) return 0;
    pa = pg_v2_add(world->bodies[j->body_a].center, pg__joint_world_lever(world, j->body_a, j->anchor_a));
    pb = pg_v2_add(world->bodies[j->body_b].center, pg__joint_world_lever(world, j->body_b, j->anchor_b));
    dx = pg__sat64((int64_t)pb.x - pa.x); /* beyond 32767 m the length saturates */
    dy = pg__sat64((int64_t)pb.y - pa.y);
    return pg__sat64((int64_t)pg__sqrt_nearest((uint64_t)(dx * dx + dy * dy)));
}

pg_result pg_distance_joint_get_def(const pg_world *world, pg_joint_id id, pg_distance_joint_def *out)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_DISTANCE);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_distance_joint_get_def: not a valid distance joint handle");
    *out = pg_default_distance_joint_def();
    out->body_a = pg__body_handle(world, j->body_a);
    out->body_b = pg__body_handle(world, j->body_b);
    out->local_anchor_a = j->anchor_a;
    out->local_anchor_b = j->anchor_b;
    out->length = j->length;
    out->enable_spring = (j->flags & PG_JOINT_FLAG_SPRING) != 0;
    out->hertz = j->hertz;
    out->damping_ratio = j->damping;
    out->enable_limit = (j->flags & PG_JOINT_FLAG_LIMIT) != 0;
    out->min_length = j->lower;
    out->max_length = j->upper;
    out->collide_connected = (j->flags & PG_JOINT_FLAG_COLLIDE) != 0;
    out->user_data = j->user_data;
    return PG_OK;
}

/* ---- the rows ------------------------------------------------------------------------------ */
/* One row along the rod carries the length (rigid or a spring) and both limits; each
 * pass turns it to where the anchors are now and measures the length there.
 * The spring is a force, not a soft constraint: once per substep (the solve pass) it
 * changes the relative speed along the rod by -h omega^2 C (semi-implicit Euler, which
 * keeps an undamped spring's energy: a soft constraint's implicit step would take
 * 2 pi omega h of it every period), then its damping 2 zeta omega implicitly,
 * v / (1 + 2 zeta omega h), stable for any ratio. omega = 2 pi hertz, capped at a quarter
 * of the substep rate (omega h <= pi / 2 < 2, where the explicit part is stable). In the
 * row's units (relative speed) the pair's effective mass cancels: the spring's frequency
 * is its hertz whatever the masses. */

static int has_spring(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_SPRING) != 0; }
static int has_limit(const pg_joint *j) { return (j->flags & PG_JOINT_FLAG_LIMIT) != 0 && j->lower < j->upper; }

void pg__distance_joint_prepare(joint_constraint *c, const step_context *ctx)
{
    const pg_joint *j = c->src;
    int64_t dx = (int64_t)c->B.fixed_point.x - c->A.fixed_point.x, dy = (int64_t)c->B.fixed_point.y - c->A.fixed_point.y;
    pg_dir d;
    if (dx * dx + dy * dy < (int64_t)LENGTH_MIN * LENGTH_MIN / 4) { /* anchors together: no direction, take x */
        d.x = 1 << 30;
        d.y = 0;
    } else {
        d = pg_dir_normalize(dx, dy);
    }
    pg__joint_row_linear(&c->axial, &c->A, &c->B, d, c->A.lever, c->B.lever);
    c->axial_imp = j->axial_impulse;
    if (has_spring(j)) { /* spring coefficients: h omega^2 (Q16 1/s) and 2 zeta omega h (Q30) */
        int64_t hz = j->hertz < (pg_fix)((int64_t)ctx->n * 16384) ? j->hertz : (pg_fix)((int64_t)ctx->n * 16384);
        int64_t omega = pg__mul64_shr(hz, PG_FIX_TWO_PI, 16); /* Q16 rad/s, <= 2^30 */
        c->spring_k = pg__mul64_shr(pg__mul64_shr(omega, omega, 16), ctx->h_q32, 32);             /* h omega^2, Q16 */
        c->spring_c = pg__mul64_shr(pg__mul64_shr(2 * (int64_t)j->damping, omega, 16), ctx->h_q32, 18); /* 2 zeta omega h, Q30 */
    }
    c->lower_imp = has_limit(j) ? j->lower_impulse : 0;
    c->upper_imp = has_limit(j) ? j->upper_impulse : 0;
}

/* The rod's direction, the levers and the length (c->along) where the bodies are now. */
static void orient(joint_constraint *c, const solver_body *bodies)
{
    int64_t ax, ay, bx, by, dx, dy, len;
    (void)joint_levers_now(c, bodies); /* the direction moves with the centres too: oriented every pass */
    joint_anchor_now(&c->A, bodies, &ax, &ay);
    joint_anchor_now(&c->B, bodies, &bx, &by);
    dx = clamp64(bx - ax, INT32_MAX);
    dy = clamp64(by - ay, INT32_MAX);
    len = (int64_t)pg__sqrt_nearest((uint64_t)(dx * dx + dy * dy));
    pg__joint_row_orient(&c->axial, len * 2 >= LENGTH_MIN ? pg_dir_normalize(dx, dy) : c->axial.d, c->A.lever_now, c->B.lever_now);
    c->along = len;
}

void pg__distance_joint_warm_start(joint_constraint *c, solver_body *bodies)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    if (!c->axial.on) return;
    orient(c, bodies);
    /* a spring's impulse is a force's, made again each substep: not warm started */
    joint_row_apply(&c->axial, &A, &B, (has_spring(c->src) ? 0 : c->axial_imp) + c->lower_imp - c->upper_imp);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__distance_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
    const pg_joint *j = c->src;
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    int64_t len;
    if (!c->axial.on) return;
    if (moved) orient(c, bodies);
    len = c->along;
    if (!has_spring(j)) {
        pg__joint_row_solve(&c->axial, &c->axial_imp, &A, &B, len - j->length, &c->soft, use_bias);
    } else if (use_bias) { /* the spring: once a substep */
        int64_t v = joint_row_speed(&c->axial, &A, &B), C = clamp64(len - j->length, INT32_MAX);
        int64_t v1 = clamp64(v - row_round(c->spring_k * C, 16), LAMBDA_MAX);
        v1 = pg__div64_shl(v1, (INT64_C(1) << 30) + c->spring_c, 30); /* the damping, implicitly */
        c->axial_imp = clamp64(v1 - v, LAMBDA_MAX);
        joint_row_apply(&c->axial, &A, &B, c->axial_imp);
    }
    if (has_limit(j)) {
        pg__joint_limit_solve(&c->axial, &c->lower_imp, &A, &B, len - j->lower, 1, &c->soft, use_bias, ctx->n);
        pg__joint_limit_solve(&c->axial, &c->upper_imp, &A, &B, len - j->upper, -1, &c->soft, use_bias, ctx->n);
    }
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__distance_joint_store(const joint_constraint *c, pg_joint *j)
{
    j->axial_impulse = (pg_fix)c->axial_imp;
    j->lower_impulse = (pg_fix)c->lower_imp;
    j->upper_impulse = (pg_fix)c->upper_imp;
}

void pg__distance_joint_impulse(const joint_constraint *c, int64_t out[3])
{
    int64_t p = pg__joint_row_impulse(&c->axial, c->axial_imp + c->lower_imp - c->upper_imp);
    /* along the rod, from A's anchor to B's: on B */
    out[0] = row_round(p * c->axial.d.x, 30);
    out[1] = row_round(p * c->axial.d.y, 30);
    out[2] = 0;
}
#endif
