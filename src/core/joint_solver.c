/* joint_solver.c — the joints through the solver's stages: builds each joint's
 * constraint from the state at the step's start, and dispatches every stage to its
 * kind's rows (<kind>_joint.c), joints in slot order. */
#include "distance_joint.h"
#include "error.h"
#include "joint_pool.h"
#include "joint_solver.h"
#include "mouse_joint.h"
#include "prismatic_joint.h"
#include "revolute_joint.h"
#include "weld_joint.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

size_t pg__joint_scratch_bytes(uint32_t max_joints, uint32_t max_bodies)
{
    /* a world made without joints never prepares them (pg__solve: joint_count > 0) */
    if (max_joints == 0) return 0;
    return sizeof(joint_change) * ((size_t)max_bodies + 1u) + sizeof(joint_constraint) * (size_t)max_joints;
}

void pg__joints_prepare(pg_joint_stage *s, const step_context *ctx, solver_body *bodies, void *area, const uint32_t *active,
                        uint32_t n_active)
{
    const pg_world *w = ctx->world;
    const softness rigid = pg__joint_rigid_softness(ctx->n); /* the same for every joint of the step */
    uint32_t i;
    s->change = (joint_change *)area;
    s->cons = (joint_constraint *)(void *)(s->change + w->def.max_bodies + 1u);
    s->count = s->weld_count = 0;
    for (i = 0; i < n_active; ++i) s->change[active[i]].x = s->change[active[i]].y = s->change[active[i]].w = 0;
    for (i = 0; i < w->joint_high; ++i) {
        const pg_joint *j = &w->joints[i];
        joint_constraint *c;
        int activeA, activeB;
        if ((j->flags & PG_JOINT_FLAG_USED) == 0) continue;
        activeA = j->body_a != PG_NULL_INDEX && pg__body_is_active(&w->bodies[j->body_a]);
        activeB = pg__body_is_active(&w->bodies[j->body_b]);
        if (!activeA && !activeB) continue;
        c = &s->cons[s->count++];
        c->joint = i;
        c->src = j;
        if (j->body_a != PG_NULL_INDEX) {
            pg__joint_side_init(&c->A, w, j->body_a, j->anchor_a, activeA, activeA ? j->body_a : ctx->dummy, ctx->rotation);
        } else { /* a mouse joint: side A is its target (mouse_joint.c) */
            c->A.slot = ctx->dummy;
            c->A.active = 0;
            c->A.inv_mass = c->A.inv_inertia = 0;
            c->A.local = c->A.lever = c->A.lever_now = c->A.fixed_point = pg_v2_zero();
            c->A.dq_seen = pg_rot_identity();
            c->A.fixed_angle = 0;
        }
        pg__joint_side_init(&c->B, w, j->body_b, j->anchor_b, activeB, activeB ? j->body_b : ctx->dummy, ctx->rotation);
        /* the integration keeps these bodies' turn since the step's start (dq): the levers follow it */
        if (activeA) {
            bodies[c->A.slot].turns_anchors = 1;
            c->A.change = &s->change[c->A.slot];
        }
        if (activeB) {
            bodies[c->B.slot].turns_anchors = 1;
            c->B.change = &s->change[c->B.slot];
        }
        c->imp[0] = c->imp[1] = c->axial_imp = c->lower_imp = c->upper_imp = c->motor_imp = c->motor_max = 0;
        c->soft = c->soft2 = rigid; /* a kind with a spring sets its own */
        switch (j->type) {
        case PG_JOINT_DISTANCE: pg__distance_joint_prepare(c, ctx); break;
        case PG_JOINT_REVOLUTE: pg__revolute_joint_prepare(c, ctx); break;
        case PG_JOINT_WELD: pg__weld_joint_prepare(c, ctx); s->weld_count++; break;
        case PG_JOINT_PRISMATIC: pg__prismatic_joint_prepare(c, ctx); break;
        default: pg__mouse_joint_prepare(c, ctx); break;
        }
    }
}

void pg__joints_warm_start(const pg_joint_stage *s, solver_body *bodies)
{
    uint32_t i;
    for (i = 0; i < s->count; ++i) {
        joint_constraint *c = &s->cons[i];
        switch (c->src->type) {
        case PG_JOINT_DISTANCE: pg__distance_joint_warm_start(c, bodies); break;
        case PG_JOINT_REVOLUTE: pg__revolute_joint_warm_start(c, bodies); break;
        case PG_JOINT_WELD: pg__weld_joint_warm_start(c, bodies); break;
        case PG_JOINT_PRISMATIC: pg__prismatic_joint_warm_start(c, bodies); break;
        default: pg__mouse_joint_warm_start(c, bodies); break;
        }
    }
}

/* A pass over the joints. `moved`: the bodies may have moved since the joints' last
 * visit, so the rows that follow them (levers, directions, position errors) are made
 * again; positions change only when they are integrated, between the solve pass and the
 * first relax sweep, and the warm start before the solve pass orients every joint (a
 * pin's warm start finds its levers made by that first relax sweep, or by the set-up). */
static void pass(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies, int use_bias, int moved)
{
    uint32_t i;
    for (i = 0; i < s->count; ++i) {
        joint_constraint *c = &s->cons[i];
        switch (c->src->type) {
        case PG_JOINT_DISTANCE: pg__distance_joint_solve(c, bodies, ctx, use_bias, moved); break;
        case PG_JOINT_REVOLUTE: pg__revolute_joint_solve(c, bodies, ctx, use_bias, moved); break;
        case PG_JOINT_WELD: pg__weld_joint_solve(c, bodies, ctx, use_bias, moved); break;
        case PG_JOINT_PRISMATIC: pg__prismatic_joint_solve(c, bodies, ctx, use_bias, moved); break;
        default: pg__mouse_joint_solve(c, bodies, ctx, use_bias, moved); break;
        }
    }
}

void pg__joints_solve(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies) { pass(s, ctx, bodies, 1, 0); }
/* The relax stage: one sweep over every joint's rigid rows, as Box2D v3's one relax
 * iteration (springs and soft parts act in the solve pass only; without bias a sweep adds
 * no energy), then more sweeps over the welds alone. Gauss-Seidel carries a change one
 * joint a sweep against the slot order; a pin hands on a force, but a weld also a
 * bending moment, which grows along a welded cantilever with every box beyond the joint:
 * with one sweep the moments at the wall lag the load and a cantilever of welds swings
 * on its soft joints for long (test_joint_weld asserts that it comes to rest). Chains of
 * pins and grids of them hold with the one sweep (test_joint_chain, pogon-bench's
 * joint_grid and chain and their sanity figures, docs/joints.md). */
#define JOINT_RELAX_SWEEPS 1 /* at least 1: the first sweep turns the levers for the next warm start */
#define WELD_RELAX_SWEEPS 8 /* the welds' sweeps, the first of them with every joint */

void pg__joints_relax(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies)
{
    int k;
    uint32_t i;
    for (k = 0; k < JOINT_RELAX_SWEEPS; ++k) pass(s, ctx, bodies, 0, k == 0);
    for (; k < WELD_RELAX_SWEEPS && s->weld_count > 0; ++k)
        for (i = 0; i < s->count; ++i)
            if (s->cons[i].src->type == PG_JOINT_WELD) pg__weld_joint_solve(&s->cons[i], bodies, ctx, 0, 0);
}

void pg__joints_store(const pg_joint_stage *s, pg_world *w)
{
    uint32_t i;
    for (i = 0; i < s->count; ++i) {
        const joint_constraint *c = &s->cons[i];
        pg_joint *j = &w->joints[c->joint];
        switch (j->type) {
        case PG_JOINT_DISTANCE: pg__distance_joint_store(c, j); break;
        case PG_JOINT_REVOLUTE: pg__revolute_joint_store(c, j); break;
        case PG_JOINT_WELD: pg__weld_joint_store(c, j); break;
        case PG_JOINT_PRISMATIC: pg__prismatic_joint_store(c, j); break;
        default: pg__mouse_joint_store(c, j); break;
        }
    }
}

/* The reaction from the stored lambdas and the bodies as they are now (the step's own
 * coefficients are gone with its scratch): the impulse each substep applies in full,
 * times the substep rate. */
pg_result pg_joint_get_reaction(const pg_world *world, pg_joint_id id, pg_joint_reaction *out)
{
    const pg_joint *j = pg__joint(world, id);
    joint_constraint c;
    step_context ctx;
    int64_t p[3] = {0, 0, 0};
    if (out != NULL) out->force_x = out->force_y = out->torque = 0;
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_joint_get_reaction: joint handle is stale or invalid");
    ctx.n = world->def.step_hz * world->def.substeps;
    ctx.h_q32 = (int64_t)(((UINT64_C(1) << 32) + ctx.n / 2u) / ctx.n);
    ctx.rotation = (world->def.effects & PG_EFFECT_ROTATION) != 0;
    ctx.world = world;
    ctx.dummy = world->def.max_bodies;
    c.joint = id.index;
    c.src = j;
    /* every side as if it moved, so the coefficients are the bodies' own */
    if (j->body_a != PG_NULL_INDEX) {
        pg__joint_side_init(&c.A, world, j->body_a, j->anchor_a, world->bodies[j->body_a].type == PG_BODY_DYNAMIC, j->body_a, ctx.rotation);
    } else {
        c.A.slot = ctx.dummy;
        c.A.active = 0;
        c.A.inv_mass = c.A.inv_inertia = 0;
        c.A.local = c.A.lever = c.A.lever_now = c.A.fixed_point = pg_v2_zero();
        c.A.dq_seen = pg_rot_identity();
        c.A.fixed_angle = 0;
    }
    pg__joint_side_init(&c.B, world, j->body_b, j->anchor_b, world->bodies[j->body_b].type == PG_BODY_DYNAMIC, j->body_b, ctx.rotation);
    c.soft = c.soft2 = pg__joint_rigid_softness(ctx.n);
    switch (j->type) {
    case PG_JOINT_DISTANCE: pg__distance_joint_prepare(&c, &ctx); pg__distance_joint_impulse(&c, p); break;
    case PG_JOINT_REVOLUTE: pg__revolute_joint_prepare(&c, &ctx); pg__revolute_joint_impulse(&c, p); break;
    case PG_JOINT_WELD: pg__weld_joint_prepare(&c, &ctx); pg__weld_joint_impulse(&c, p); break;
    case PG_JOINT_PRISMATIC: pg__prismatic_joint_prepare(&c, &ctx); pg__prismatic_joint_impulse(&c, p); break;
    default: pg__mouse_joint_prepare(&c, &ctx); pg__mouse_joint_impulse(&c, p); break;
    }
    /* |P| < 2^63 / n: saturate the product rather than wrap */
    out->force_x = pg__mul64_shr(p[0], (int64_t)ctx.n << 1, 1);
    out->force_y = pg__mul64_shr(p[1], (int64_t)ctx.n << 1, 1);
    out->torque = pg__mul64_shr(p[2], (int64_t)ctx.n << 1, 1);
    return PG_OK;
}
#endif
