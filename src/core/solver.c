/* solver.c — the soft step (Box2D v3's) as named stages, which every constraint kind
 * passes through:
 *   prepare                  each kind's constraints from the state at the step's start
 *   per substep:
 *     integrate velocities   gravity, forces, damping (per body)
 *     warm start             each kind applies its accumulated impulses
 *     solve                  each kind's rows with a soft bias
 *     integrate positions    (per body)
 *     relax                  each kind's rows without bias
 *   restitution              once after the substeps
 *   store                    impulses back into the world for the next step's warm start
 * then the bodies are written back and fast-turning ones swept (continuous.c).
 * The kinds: joints (joint_solver.c, one file per joint kind) and contacts
 * (contact_solver.c), in that order in every stage. docs/solver-design.md gives the
 * reasons. */
#include "body.h"
#include "contact_solver.h"
#include "continuous.h"
#include "joint_solver.h"
#include "solver.h"
#include "solver_kernel.h"

/* Byte offset of the constraints in the scratch: after the solver bodies, rounded up to
 * 8 because a constraint holds int64 fields and a solver body's size need not be a
 * multiple of 8. */
static size_t constraints_offset(uint32_t max_bodies)
{
    return (sizeof(solver_body) * ((size_t)max_bodies + 1u) + 7u) & ~(size_t)7u;
}

/* Bytes of the constraint area. The sweeps of fast-turning bodies (continuous.c) and
 * their index by body reuse it once the impulses are stored: the write-back that fills
 * them still reads the list of active bodies after it, never the constraints. It is
 * rounded up to 8, so the list after it stays aligned as the constraints are. */
static size_t constraint_area_bytes(const pg_world_def *def)
{
    size_t cons = pg__contact_constraint_bytes(def->max_contacts), sweeps = (sizeof(pg_sweep) + sizeof(uint32_t)) * def->max_bodies;
    return ((cons > sweeps ? cons : sweeps) + 7u) & ~(size_t)7u;
}

/* The joints' constraints go last, after the deep push's list, aligned to 8. */
#define joints_offset_pad 8u

size_t pg__solver_scratch_bytes(const pg_world_def *def)
{
    /* ... the active bodies, and the constraints of the pseudo pass (DEEP PUSH) */
    return constraints_offset(def->max_bodies) + constraint_area_bytes(def) + sizeof(uint32_t) * def->max_bodies +
           sizeof(uint32_t) * def->max_contacts + joints_offset_pad + pg__joint_scratch_bytes(def->max_joints, def->max_bodies) + 64u;
}

/* The gravity term g (a pg_fix) plus the force term f = round(F invm), which
 * pg__mul64_shr may have saturated to +-INT64_MAX: the exact sum when |f| <= 2^62, else
 * g + sign(f) 2^62. Either way pg__sat64 of the result is the exact sum saturated to
 * +-PG_FIX_MAX (beyond 2^62 - 2^31 both are past PG_FIX_MAX on the same side). */
static int64_t add_force_term(int64_t g, int64_t f)
{
    const int64_t lim = INT64_C(1) << 62;
    return g + (f > lim ? lim : f < -lim ? -lim : f);
}

/* The binary angle a substep at angular velocity w turns: round(w angle_per_w / 2^24)
 * modulo 2^32 (a full turn), rounded as pg__round_shift64 does (nearest, ties away from
 * zero). w angle_per_w reaches 2^31 * 2^37.4 at step_hz * substeps = 1, past int64 once
 * |w| > 2^63 / angle_per_w (about 789 n rad/s, n = step_hz * substeps). But a full turn is
 * 2^56 in the product, so only the product modulo 2^56 matters: the unsigned product
 * (modulo 2^64) and the rounding offset added modulo 2^64 give exactly the low 32 bits of
 * the rounded quotient, for every w, and the same bits as the int64 formula wherever that
 * did not overflow. angle_per_w > 0, so the product has w's sign. */
static inline pg_angle angle_step(pg_fix w, int64_t angle_per_w)
{
    uint64_t p = (uint64_t)(int64_t)w * (uint64_t)angle_per_w;
    return (pg_angle)((p + (w < 0 ? UINT64_C(0x7FFFFF) : UINT64_C(0x800000))) >> 24);
}

/* Integrate velocities in substep sub. The velocity change of substep k is
 * round(a t_(k+1)) - round(a t_k), t_k = k h: the rounding errors do not add up over the
 * substeps, a step changes velocity by round(a dt) exactly.
 * a is a pg_fix and t_k stays below 2^32 Q32 s but at the end of a 1 Hz step, where
 * h = round(2^32 / substeps) rounds up for 6, 7, 10 and 13 substeps and t_n reaches
 * 2^32 + 8: a t_n and its rounding then leave int64 for |a| near PG_FIX_MAX. For
 * t = 2^32 + r, round(a t / 2^32) = a + round(a r / 2^32), exactly and rounded the same
 * way (a 2^32 and a r have a's sign); a r stays below (2^31 - 1)(2^32 - 1).
 * Out of line: it runs once per substep, and keeps pg__solve small. */
#define TIME_ONE (INT64_C(1) << 32)
PG__NOINLINE void integrate_velocities(pg_world *w, solver_body *bodies, const uint32_t *active, uint32_t n_active,
                                       const step_context *ctx, uint32_t sub, int rotation, joint_change *joints)
{
    int64_t t0 = ctx->h_q32 * (int64_t)sub, t1 = ctx->h_q32 * (int64_t)(sub + 1u); /* <= 2^32 / step_hz + 8 */
    int64_t whole = 0; /* 1 when t1 >= 2^32 (see TIME_ONE); t0 < 2^32 always */
    int64_t gx, gy;    /* the change the shared acceleration g makes: most bodies have it */
    pg_vec2 g = ctx->gravity;
    uint32_t i;
    if (t1 >= TIME_ONE) {
        t1 -= TIME_ONE;
        whole = 1;
    }
    gx = whole * g.x + pg__round_shift64(g.x * t1, 32) - pg__round_shift64(g.x * t0, 32);
    gy = whole * g.y + pg__round_shift64(g.y * t1, 32) - pg__round_shift64(g.y * t0, 32);
    for (i = 0; i < n_active; ++i) {
        solver_body *sb = &bodies[active[i]];
        /* what the constraints did to this body in the last substep: from just before its
         * warm start to the end of its relax stage (solver_body's dv) */
        sb->dv_x = (int32_t)((int64_t)sb->v.x - sb->v_pre.x);
        sb->dv_y = (int32_t)((int64_t)sb->v.y - sb->v_pre.y);
        sb->dw = (int64_t)sb->w - sb->w_pre;
        if (joints != NULL) { /* the joints warm start their own rows: leave their change out */
            joint_change *j = &joints[active[i]];
            sb->dv_x = pg__sat64((int64_t)sb->dv_x - j->x);
            sb->dv_y = pg__sat64((int64_t)sb->dv_y - j->y);
            sb->dw -= j->w;
            j->x = j->y = j->w = 0;
        }
        if (sb->accel.x != 0 || sb->accel.y != 0) {
            int64_t vx, vy;
            if (sb->accel.x == g.x && sb->accel.y == g.y) { /* the same formula, computed once */
                vx = (int64_t)sb->v.x + gx;
                vy = (int64_t)sb->v.y + gy;
            } else {
                vx = (int64_t)sb->v.x + whole * sb->accel.x + pg__round_shift64(sb->accel.x * t1, 32) - pg__round_shift64(sb->accel.x * t0, 32);
                vy = (int64_t)sb->v.y + whole * sb->accel.y + pg__round_shift64(sb->accel.y * t1, 32) - pg__round_shift64(sb->accel.y * t0, 32);
            }
            /* |v| <= 2^29 and the change within +-2^31 (|a| <= PG_FIX_MAX, t <= 1 s): out of
             * Q16.16 only for an acceleration beyond the envelope, counted */
            sb->saturated |= (uint32_t)(vx != pg__sat64(vx) || vy != pg__sat64(vy));
            sb->v = pg__clamp_speed(w, pg_v2(pg__sat64(vx), pg__sat64(vy)), &w->bodies[active[i]].flags);
        }
        if (sb->lin_damp != PG_ROT_ONE) {
            sb->v.x = pg__mul_q30(sb->v.x, sb->lin_damp);
            sb->v.y = pg__mul_q30(sb->v.y, sb->lin_damp);
        }
        if (rotation) {
            if (sb->alpha != 0) {
                int64_t spun = (int64_t)sb->w + whole * sb->alpha + pg__round_shift64(sb->alpha * t1, 32) - pg__round_shift64(sb->alpha * t0, 32);
                sb->saturated |= (uint32_t)(spun != pg__sat64(spun)); /* as v above */
                sb->w = pg__sat64(spun);
            }
            if (sb->ang_damp != PG_ROT_ONE) sb->w = pg__mul_q30(sb->w, sb->ang_damp);
        }
        sb->v_pre = sb->v;
        sb->w_pre = sb->w;
    }
}

/* Integrate positions in the current substep: centres by v (and by the deep push's pseudo
 * velocity, which moves them but is never momentum), angles by w. */
static void integrate_positions(solver_body *bodies, const uint32_t *active, uint32_t n_active, const step_context *ctx, int pseudo)
{
    const int rotation = ctx->rotation;
    uint32_t i;
    for (i = 0; i < n_active; ++i) {
        solver_body *sb = &bodies[active[i]];
        int64_t vx = sb->v.x, vy = sb->v.y;
        if (pseudo) {
            vx += sb->pv.x;
            vy += sb->pv.y;
        }
        /* saturating only for a body already out of the envelope: from |c| <= 1000 m, at
         * most VELOCITY_MAX (8192 m/s, plus as much pseudo velocity) for at most 1 s
         * reaches 17384 m < 32768 m within a step (envelope_exits counts the way out) */
        sb->c.x = pg__sat64((int64_t)sb->c.x + pg__round_shift64(vx * ctx->h_q32, 32));
        sb->c.y = pg__sat64((int64_t)sb->c.y + pg__round_shift64(vy * ctx->h_q32, 32));
        sb->dp = pg_v2((pg_fix)((int64_t)sb->c.x - sb->c0.x), (pg_fix)((int64_t)sb->c.y - sb->c0.y));
        if (rotation && sb->w != 0) {
            sb->a += angle_step(sb->w, ctx->angle_per_w);
            sb->turn += ((int64_t)sb->w * ctx->h_q32) >> 16; /* for continuous.c's sweep */
            if (sb->turns_anchors) sb->dq = pg_rot_from_angle(sb->a - sb->a0); /* a ball's is never read */
        }
    }
}

void pg__solve(pg_world *w)
{
    unsigned char *scratch = (unsigned char *)w->solver_scratch;
    solver_body *bodies = (solver_body *)(void *)scratch;
    uint32_t dummy = w->def.max_bodies; /* the static side of a contact */
    unsigned char *area = scratch + constraints_offset(w->def.max_bodies); /* the constraints */
    uint32_t *active = (uint32_t *)(void *)(area + constraint_area_bytes(&w->def));
    uint32_t *deep_list = active + w->def.max_bodies;
    void *joint_area = (void *)(((uintptr_t)(deep_list + w->def.max_contacts) + 7u) & ~(uintptr_t)7u);
    pg_sweep *sweeps = (pg_sweep *)(void *)area; /* after the store stage (constraint_area_bytes) */
    uint32_t n_active = 0, n_fast = 0, i, sub;
    int sweeping;
    step_context ctx;
    pg_contact_stage contacts;
    pg_joint_stage joints;
    int have_joints;
    const uint32_t effects = w->def.effects;
    const int rotation = (effects & PG__EFFECT(PG_EFFECT_ROTATION)) != 0;

    ctx.n = w->def.step_hz * w->def.substeps;
    ctx.h_q32 = (int64_t)(((UINT64_C(1) << 32) + ctx.n / 2u) / ctx.n);
    ctx.angle_per_w = (INT64_C(174992710548) + (int64_t)ctx.n / 2) / (int64_t)ctx.n; /* 2^40 / (2 pi) / n */
    pg__contacts_set_softness(&ctx, &w->def);
    ctx.effects = effects;
    ctx.rotation = rotation;
    ctx.world = w;
    ctx.dummy = dummy;
    ctx.sub = 0;
    ctx.deep_seen = NULL; /* the contacts' prepare stage points it at their flag */
    /* a body of gravity scale 1 and no force gets exactly this (pg_fix_mul by 1 is exact) */
    ctx.gravity = (effects & PG__EFFECT(PG_EFFECT_GRAVITY)) != 0 ? w->def.gravity : pg_v2_zero();

    /* the dummy static body */
    {
        solver_body *d = &bodies[dummy];
        d->v = pg_v2_zero();
        d->w = 0;
        d->c0 = d->c = d->dp = pg_v2_zero();
        d->a0 = d->a = 0;
        d->dq = pg_rot_identity();
        d->turn = 0;
        d->turns_anchors = 0;
        d->accel = pg_v2_zero(); /* read for the approach speed (APPROACH) */
        d->alpha = 0;
        d->pv = pg_v2_zero();
        d->saturated = 0;
        d->pushed = 0;
        d->lin_damp = d->ang_damp = PG_ROT_ONE;
        d->v_pre = pg_v2_zero();
        d->w_pre = 0;
    }

    /* bodies */
    for (i = 0; i < w->body_high; ++i) {
        pg_body *b = &w->bodies[i];
        solver_body *sb;
        if (!pg__body_is_active(b)) continue;
        active[n_active++] = i;
        sb = &bodies[i];
        /* the kernel's bounds: a body's velocities are within max_linear_speed (at most
         * 4096 m/s) and +-1000 rad/s (the caps every write keeps), so these never clamp */
        sb->v = pg_v2(clamp_velocity(b->v.x), clamp_velocity(b->v.y));
        sb->w = rotation ? clamp_velocity(b->w) : 0;
        sb->saturated = 0;
        sb->c0 = sb->c = b->center;
        sb->dp = pg_v2_zero();
        sb->a0 = sb->a = b->angle;
        sb->dq = pg_rot_identity();
        sb->turn = 0;
        sb->turns_anchors = 0;
        sb->accel = pg_v2_zero();
        sb->alpha = 0;
        sb->pv = pg_v2_zero();
        sb->pushed = 0;
        sb->lin_damp = PG_ROT_ONE;
        sb->ang_damp = PG_ROT_ONE;
        sb->v_pre = sb->v; /* the first substep warm starts from the constraints */
        sb->w_pre = sb->w;
        if (b->type != PG_BODY_DYNAMIC) continue;
        {
            int64_t ax = 0, ay = 0, alpha = 0;
            if ((effects & PG__EFFECT(PG_EFFECT_GRAVITY)) != 0 && b->gravity_scale != 0) {
                ax = pg_fix_mul(w->def.gravity.x, b->gravity_scale);
                ay = pg_fix_mul(w->def.gravity.y, b->gravity_scale);
            }
            if (b->force_x != 0 || b->force_y != 0) {
                /* the force term saturates (to +-INT64_MAX) for an accumulated force far
                 * beyond the envelope on a light body: add it saturating */
                ax = add_force_term(ax, pg__mul64_shr(b->force_x, b->inv_mass, 38));
                ay = add_force_term(ay, pg__mul64_shr(b->force_y, b->inv_mass, 38));
            }
            if (rotation && b->torque != 0) alpha = pg__mul64_shr(b->torque, b->inv_inertia, 38);
            /* gravity is within +-1000 m/s^2; a force or torque beyond the envelope on a
             * light body may leave Q16.16: counted */
            sb->saturated = (uint32_t)(ax != pg__sat64(ax) || ay != pg__sat64(ay) || alpha != pg__sat64(alpha));
            sb->accel = pg_v2(pg__sat64(ax), pg__sat64(ay));
            sb->alpha = pg__sat64(alpha);
        }
        if ((effects & PG__EFFECT(PG_EFFECT_DAMPING)) != 0) {
            /* v *= 1 / (1 + h c) per substep */
            int64_t N = (int64_t)ctx.n * 65536;
            if (b->linear_damping > 0) sb->lin_damp = (int32_t)(((INT64_C(1) << 30) * N + (N + b->linear_damping) / 2) / (N + b->linear_damping));
            if (b->angular_damping > 0) sb->ang_damp = (int32_t)(((INT64_C(1) << 30) * N + (N + b->angular_damping) / 2) / (N + b->angular_damping));
        }
    }

    /* The stages: each constraint kind takes part in each through a call of its own. */
    joints.count = 0;
    if (w->joint_count > 0) pg__joints_prepare(&joints, &ctx, bodies, joint_area, active, n_active);
    have_joints = joints.count > 0;
    pg__contacts_prepare(&contacts, &ctx, bodies, area, deep_list);
    for (sub = 0; sub < w->def.substeps; ++sub) {
        ctx.sub = sub;
        integrate_velocities(w, bodies, active, n_active, &ctx, sub, rotation, have_joints ? joints.change : NULL);
        if (have_joints) pg__joints_warm_start(&joints, bodies);
        pg__contacts_warm_start(&contacts, &ctx, bodies, active, n_active);
        if (have_joints) pg__joints_solve(&joints, &ctx, bodies);
        pg__contacts_solve(&contacts, &ctx, bodies);
        integrate_positions(bodies, active, n_active, &ctx, contacts.deep);
        if (have_joints) pg__joints_relax(&joints, &ctx, bodies);
        pg__contacts_relax(&contacts, &ctx, bodies);
    }
    pg__contacts_restitution(&contacts, &ctx, bodies);
    if (have_joints) pg__joints_store(&joints, w);
    pg__contacts_store(&contacts, w);

    /* write back, and the sweeps of bodies that turned too far for their speculative
     * contacts (continuous.c) */
    sweeping = rotation && (effects & PG__EFFECT(PG_EFFECT_CONTINUOUS)) != 0;
    for (i = 0; i < n_active; ++i) {
        pg_body *b = &w->bodies[active[i]];
        const solver_body *sb = &bodies[active[i]];
        pg_fix w0 = b->w;
        int was_inside = pg__in_position_envelope(b->origin);
        if (sb->saturated) pg__count_saturations(w, 1u);
        /* the contact solve may have left a velocity past the caps: clamp it (counted) */
        pg__body_store_velocity(w, b, sb->v, rotation ? sb->w : b->w); /* rotation off pauses spin */
        b->center = sb->c;
        if (b->angle != sb->a) {
            b->angle = sb->a;
            b->rot = pg_rot_from_angle(sb->a);
        }
        b->origin = pg_v2_sub(b->center, pg_rot_apply(b->rot, b->local_center));
        if (was_inside && !pg__in_position_envelope(b->origin)) w->stats.envelope_exits += 1u;
        b->force_x = b->force_y = b->torque = 0;
        if (sweeping && b->turn_reach != 0 && (sb->turn != 0 || w0 != 0) && b->type == PG_BODY_DYNAMIC) {
            pg_sweep *s = &sweeps[n_fast];
            s->body = active[i];
            s->c0 = sb->c0;
            s->c1 = sb->c;
            s->a0 = sb->a0;
            s->turn = pg__turn_of_step(sb->a0, sb->a, sb->turn);
            if (pg__sweep_is_fast(w, s, w0)) ++n_fast;
        }
    }
    if (n_fast > 0) pg__sweep_fast_turns(w, sweeps, n_fast, (uint32_t *)(void *)(sweeps + w->def.max_bodies));
}
