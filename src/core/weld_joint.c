/* weld_joint.c — the weld joint: two bodies held together, rigid or soft
 * (docs/joints.md): its def and setters, and its rows through the solver's stages. */
#include "def_cookie.h"
#include "weld_joint.h"
#include "error.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

pg_weld_joint_def pg_default_weld_joint_def(void)
{
    pg_weld_joint_def d;
    d.body_a.index = d.body_a.generation = 0;
    d.body_b = d.body_a;
    d.local_anchor_a = d.local_anchor_b = pg_v2_zero();
    d.reference_angle = 0;
    d.linear_hertz = d.linear_damping_ratio = 0;
    d.angular_hertz = d.angular_damping_ratio = 0;
    d.collide_connected = 0;
    d.user_data = 0;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

static pg_result check_softness(const pg_world *world, pg_fix lh, pg_fix lz, pg_fix ah, pg_fix az)
{
    pg_result r = pg__joint_check_softness(world, lh, lz, 1);
    return r != PG_OK ? r : pg__joint_check_softness(world, ah, az, 1);
}

pg_result pg_weld_joint_create(pg_world *world, const pg_weld_joint_def *def, pg_joint_id *out)
{
    pg_joint j = {0};
    pg_result r;
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    if (def->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the def was not made by pg_default_weld_joint_def(): start from it and change the fields you need");
    r = pg__joint_check_bodies(world, "pg_weld_joint_create", def->body_a, def->body_b, def->local_anchor_a, def->local_anchor_b, &j);
    if (r == PG_OK) r = check_softness(world, def->linear_hertz, def->linear_damping_ratio, def->angular_hertz, def->angular_damping_ratio);
    if (r != PG_OK) return r;
    j.type = PG_JOINT_WELD;
    j.reference_angle = def->reference_angle;
    j.hertz = def->linear_hertz;
    j.damping = def->linear_damping_ratio;
    j.hertz2 = def->angular_hertz;
    j.damping2 = def->angular_damping_ratio;
    j.flags = def->collide_connected ? PG_JOINT_FLAG_COLLIDE : 0u;
    j.user_data = def->user_data;
    return pg__joint_add(world, &j, out);
}

pg_result pg_weld_joint_set_softness(pg_world *world, pg_joint_id id, pg_fix linear_hertz, pg_fix linear_damping_ratio,
                                     pg_fix angular_hertz, pg_fix angular_damping_ratio)
{
    pg_result r;
    pg_joint *j = pg__joint_of_type(world, id, PG_JOINT_WELD, "pg_weld_joint_set_softness", &r);
    if (j == NULL) return r;
    if ((r = check_softness(world, linear_hertz, linear_damping_ratio, angular_hertz, angular_damping_ratio)) != PG_OK) return r;
    j->hertz = linear_hertz;
    j->damping = linear_damping_ratio;
    j->hertz2 = angular_hertz;
    j->damping2 = angular_damping_ratio;
    pg__joint_wake(world, j);
    return PG_OK;
}

pg_result pg_weld_joint_get_def(const pg_world *world, pg_joint_id id, pg_weld_joint_def *out)
{
    const pg_joint *j = pg__joint_of_type_const(world, id, PG_JOINT_WELD);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_weld_joint_get_def: not a valid weld joint handle");
    *out = pg_default_weld_joint_def();
    out->body_a = pg__body_handle(world, j->body_a);
    out->body_b = pg__body_handle(world, j->body_b);
    out->local_anchor_a = j->anchor_a;
    out->local_anchor_b = j->anchor_b;
    out->reference_angle = j->reference_angle;
    out->linear_hertz = j->hertz;
    out->linear_damping_ratio = j->damping;
    out->angular_hertz = j->hertz2;
    out->angular_damping_ratio = j->damping2;
    out->collide_connected = (j->flags & PG_JOINT_FLAG_COLLIDE) != 0;
    out->user_data = j->user_data;
    return PG_OK;
}

/* ---- the rows ------------------------------------------------------------------------------ */
/* Box2D v3's split: the angle as one angular row, then the anchors as a 2x2 point block.
 * A part of hertz 0 is rigid (the joints' softness in the solve pass, none in the relax
 * passes); a part with hertz is a soft spring in the solve pass only. */

void pg__weld_joint_prepare(joint_constraint *c, const step_context *ctx)
{
    const pg_joint *j = c->src;
    pg__joint_point_init(&c->point, &c->A, &c->B);
    pg__joint_row_angular(&c->angular, &c->A, &c->B);
    if (j->hertz > 0) c->soft = pg__joint_spring_softness(j->hertz, j->damping, ctx->n); /* else the rigid one */
    if (j->hertz2 > 0) c->soft2 = pg__joint_spring_softness(j->hertz2, j->damping2, ctx->n);
    c->imp[0] = j->point_impulse[0];
    c->imp[1] = j->point_impulse[1];
    c->axial_imp = j->axial_impulse;
}

void pg__weld_joint_warm_start(joint_constraint *c, solver_body *bodies)
{
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    if (c->point.S == 0) return;
    if (joint_levers_now(c, bodies)) pg__joint_point_orient(&c->point, c->A.lever_now, c->B.lever_now);
    pg__joint_point_apply(&c->point, &A, &B, c->imp[0], c->imp[1]);
    if (c->angular.on) joint_row_apply(&c->angular, &A, &B, c->axial_imp);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__weld_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved)
{
    const pg_joint *j = c->src;
    const velocity A0 = load_velocity(&bodies[c->A.slot]), B0 = load_velocity(&bodies[c->B.slot]);
    velocity A = A0, B = B0;
    int64_t ax = 0, ay = 0, bx = 0, by = 0;
    pg_angle rel;
    (void)ctx;
    if (c->point.S == 0) return;
    if (moved && joint_levers_now(c, bodies)) pg__joint_point_orient(&c->point, c->A.lever_now, c->B.lever_now);
    rel = joint_angle_now(&c->B, bodies) - joint_angle_now(&c->A, bodies) - j->reference_angle;
    if (use_bias || j->hertz2 == 0) pg__joint_row_solve(&c->angular, &c->axial_imp, &A, &B, pg_angle_to_radians(rel), &c->soft2, use_bias);
    if (use_bias) { /* a relax sweep has no bias: the point's position error is not read */
        joint_anchor_now(&c->A, bodies, &ax, &ay);
        joint_anchor_now(&c->B, bodies, &bx, &by);
    }
    if (use_bias || j->hertz == 0) pg__joint_point_solve(c, &A, &B, bx - ax, by - ay, &c->soft, use_bias);
    joint_store(bodies, &c->A, &A, &A0);
    joint_store(bodies, &c->B, &B, &B0);
}

void pg__weld_joint_store(const joint_constraint *c, pg_joint *j)
{
    j->point_impulse[0] = (pg_fix)c->imp[0];
    j->point_impulse[1] = (pg_fix)c->imp[1];
    j->axial_impulse = (pg_fix)c->axial_imp;
}

void pg__weld_joint_impulse(const joint_constraint *c, int64_t out[3])
{
    pg__joint_point_impulse(&c->point, c->imp, out);
    out[2] = pg__joint_row_impulse(&c->angular, c->axial_imp);
}
#endif
