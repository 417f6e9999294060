/* joint_rows.h (internal) — what every joint kind's rows share (docs/joints.md,
 * "Fixed point"): a joint's constraint in the step's scratch, its two sides, the 2x2
 * point block and the scalar row, each with lambda stored as the change of relative
 * velocity it makes (m/s or rad/s), as the contacts' rows do (docs/solver-design.md).
 *
 * A point block of inverse mass matrix K (1/kg) is solved in units of
 * S = 1/mA + 1/mB: K' = K / S >= I, so K'^-1 has entries within [-1, 1] (Q2.30), and a
 * lambda L = K P changes the velocities by -(1/mA / S) K'^-1 L (A's linear part), by
 * -(1/IA / S) (rA_perp . K'^-1 L) (A's angular part), and so on: coefficients of
 * bounded range (|g| <= 1 / (2 k) for a radius of gyration k >= 2^-8 m, as the
 * contacts' lever-arm coefficients). The soft step's update needs no K at all:
 * dL = -mass_scale (v + bias) - impulse_scale L, rigid: dL = -v. */
#ifndef POGON_SRC_JOINT_ROWS_H
#define POGON_SRC_JOINT_ROWS_H
#include "solver_kernel.h"

/* One side of a joint in this step. */
typedef struct joint_side {
    uint32_t slot;         /* solver body slot (the dummy when the body does not move in this step) */
    joint_change *change;  /* the body's joint change (NULL for a side that does not move) */
    int active;
    int64_t inv_mass, inv_inertia; /* Q25.38; 0 for a side that does not move */
    pg_vec2 local;         /* anchor less the local centre of mass, body frame */
    pg_vec2 lever;         /* local turned by the angle at the step's start: world frame */
    pg_vec2 lever_now;     /* lever turned by what the body turned since (joint_levers_now) */
    pg_rot dq_seen;        /* the body's turn lever_now was made for (identity at the step's start) */
    pg_vec2 fixed_point;   /* a side that does not move: its anchor's world point */
    pg_angle fixed_angle;  /* and its angle */
} joint_side;

/* A scalar row (a contact row's form): linear part along d, angular parts cA, cB. */
typedef struct joint_row {
    pg_dir d;                        /* Q2.30 unit direction; (0, 0) for an angular row */
    pg_fix cA, cB;                   /* r x d (m), or 1 for an angular row */
    int32_t lA_x, lA_y, lB_x, lB_y;  /* Q2.30: (1/m) / K times d */
    int32_t gA, gB;                  /* Q8.24: (1/I) c / K */
    int64_t kA, kB;                  /* Q2.30: (1/m) / K, kept for the passes' new directions */
    int64_t qA, qB;                  /* Q2.30: (1/I) / K in units of S (joint_row_orient) */
    int64_t K;                       /* Q25.38: K (1/kg, or 1/(kg m^2)), for forces and caps */
    int on;                          /* 0: neither side can respond (K = 0) */
} joint_row;

/* The 2x2 point block: B's anchor onto A's. */
typedef struct joint_point {
    int32_t mA[3], mB[3];  /* Q2.30: (1/m / S) K'^-1, as xx, xy, yy */
    int32_t gA[2], gB[2];  /* Q8.24: (1/I / S) r_perp . K'^-1 */
    int32_t kinv[3];       /* Q2.30: K'^-1 */
    int64_t S;             /* Q25.38 */
    int64_t ia, ib;        /* Q2.30: (1/I) / S, for the g of the levers now */
} joint_point;

typedef struct joint_constraint {
    uint32_t joint;        /* the joint's slot */
    const pg_joint *src;   /* its parameters (not changed during the step) */
    joint_side A, B;
    joint_point point;     /* revolute, weld, mouse */
    joint_row axial;       /* distance: along the rod; prismatic: along the axis */
    joint_row perp;        /* prismatic: across the axis */
    joint_row angular;     /* revolute limits and motor, weld, prismatic */
    softness soft;         /* rigid rows (the step's joint softness, set once by joint_solver.c), or a spring's */
    softness soft2;        /* weld: the angular part's */
    int64_t imp[2];        /* the point's lambdas, or imp[0] for prismatic's perp row */
    int64_t axial_imp, lower_imp, upper_imp, motor_imp;
    int64_t motor_max;     /* the motor's (mouse: the force's) cap, as lambda */
    int64_t spring_k;      /* distance spring: h omega^2, Q16 1/s */
    int64_t spring_c;      /* distance spring: 2 zeta omega h, Q2.30 */
    pg_vec2 axis0;         /* prismatic: the axis in A's frame at the step's start (world) */
    int64_t along, across; /* distance: the length now (along); prismatic: the translation
                              along the axis and the offset across it; made where the rows are
                              oriented, when the bodies moved */
} joint_constraint;

/* ---- set-up (joint_rows.c) ---- */
/* Fill a side from its body (`active`: it moves in this step; rotation: PG_EFFECT_ROTATION). */
void pg__joint_side_init(joint_side *s, const pg_world *w, uint32_t body, pg_vec2 anchor, int active, uint32_t slot, int rotation);
/* The point block for levers A.lever and B.lever. */
void pg__joint_point_init(joint_point *p, const joint_side *A, const joint_side *B);
/* A linear row along unit direction d with levers rA, rB (world frame). */
void pg__joint_row_linear(joint_row *r, const joint_side *A, const joint_side *B, pg_dir d, pg_vec2 rA, pg_vec2 rB);
/* An angular row (wB - wA). */
void pg__joint_row_angular(joint_row *r, const joint_side *A, const joint_side *B);
/* The joints' rigid softness for the step: a quarter of the substep rate (60 Hz at 60
 * steps of 4 substeps; the stiffest the soft step keeps stable, and a joint's give under
 * load goes as 1 / hertz^2), damping ratio 5. */
softness pg__joint_rigid_softness(uint32_t n_per_second);
/* A spring's softness, its hertz capped at a quarter of the substep rate as the contacts'. */
softness pg__joint_spring_softness(pg_fix hertz, pg_fix zeta, uint32_t n_per_second);
/* The lambda cap for a force or torque cap f (N or N m) over one substep: K f h, at most LAMBDA_MAX. */
int64_t pg__joint_row_cap(int64_t K, pg_fix f, int64_t h_q32);
/* The impulse (Q16 N s or N m s) of a row's lambda, and a point's (x, y). */
int64_t pg__joint_row_impulse(const joint_row *r, int64_t lambda);
void pg__joint_point_impulse(const joint_point *p, const int64_t L[2], int64_t out[2]);

/* Turn a linear row to direction d with levers rA, rB (the set-up's K kept): the rows
 * follow the bodies through the substeps, as Box2D v3's joints do. */
void pg__joint_row_orient(joint_row *r, pg_dir d, pg_vec2 rA, pg_vec2 rB);
/* The point block's angular coefficients for the levers now (K'^-1 kept). */
void pg__joint_point_orient(joint_point *p, pg_vec2 rA, pg_vec2 rB);

/* ---- the substeps (inline) ---- */
/* A side's lever now: the step's lever turned by the body's turn since (its dq, kept
 * because prepare set turns_anchors). A body turns only when positions are integrated,
 * once a substep, while the passes visit a joint three times (warm start, solve, relax;
 * a weld ten): the lever is turned again only when dq is not the one it was made for.
 * Returns 1 when it changed. */
static inline int joint_side_turn(joint_side *s, const solver_body *bodies)
{
    pg_rot dq;
    if (!s->active) return 0; /* lever_now stays lever */
    dq = bodies[s->slot].dq;
    if (dq.c == s->dq_seen.c && dq.s == s->dq_seen.s) return 0;
    s->dq_seen = dq;
    s->lever_now = pg_rot_apply(dq, s->lever);
    return 1;
}

/* Both sides' levers now; 1 when either changed (what depends on the levers alone, the
 * point block's angular coefficients, is then made again). */
static inline int joint_levers_now(joint_constraint *c, const solver_body *bodies)
{
    int a = joint_side_turn(&c->A, bodies);
    return joint_side_turn(&c->B, bodies) | a;
}

/* Store a joint's velocities into a side's body, adding the change to the body's joint
 * change (joint_change: the contacts' warm start leaves it out, WARM START). v0 is the
 * velocity the pass loaded, which nothing has written since (a joint's two sides are two
 * bodies, or one is the dummy): taken from the pass, not read again from the body, which
 * after the other side's store the compiler would have to. */
static inline void joint_store(solver_body *bodies, const joint_side *s, const velocity *v, const velocity *v0)
{
    solver_body *b = &bodies[s->slot];
    if (!s->active) return; /* the dummy side: its coefficients are 0 */
    store_velocity(b, v);
    s->change->x += (int64_t)b->v.x - v0->x;
    s->change->y += (int64_t)b->v.y - v0->y;
    s->change->w += (int64_t)b->w - v0->w;
}

/* The anchor's world point now: a moving side's centre plus its lever now. */
static inline void joint_anchor_now(const joint_side *s, const solver_body *bodies, int64_t *x, int64_t *y)
{
    if (!s->active) {
        *x = s->fixed_point.x;
        *y = s->fixed_point.y;
    } else {
        const solver_body *b = &bodies[s->slot];
        *x = (int64_t)b->c.x + s->lever_now.x;
        *y = (int64_t)b->c.y + s->lever_now.y;
    }
}

static inline pg_angle joint_angle_now(const joint_side *s, const solver_body *bodies)
{
    return s->active ? bodies[s->slot].a : s->fixed_angle;
}

static inline int64_t clamp64(int64_t v, int64_t limit) { return v < -limit ? -limit : v > limit ? limit : v; }

/* The point block's kernels, inline so that a kind's pass specialises them (use_soft a
 * constant) and keeps the velocities in registers; the pg__ forms below are the same
 * out of line for the kinds whose passes are rare. Plain inline, not forced: an -Os
 * build (Cortex-M) keeps one copy, an -O3 build inlines them where they are called. */
/* The soft step's new lambda change from v (the row's relative speed) and bias: with
 * bias (soft) -ms (v + bias) - is l, without it (rigid) -v. v + bias is held within
 * +-2^32 (beyond any speed the kernel keeps) so the products fit int64. */
static inline int64_t joint_soft_delta(int64_t v, int64_t bias, int64_t acc, const softness *s, int use_soft)
{
    if (!use_soft) return -clamp64(v, INT64_C(1) << 32);
    return -row_round(s->mass_scale * clamp64(v + bias, INT64_C(1) << 32), 30) - row_round((int64_t)s->impulse_scale * acc, 30);
}

/* The relative velocity of B's anchor against A's: (vB + wB x rB) - (vA + wA x rA). */
static inline void joint_point_speed(const velocity *A, const velocity *B, pg_vec2 rA, pg_vec2 rB, int64_t *cx, int64_t *cy)
{
    *cx = B->x - A->x + pg__round_shift64(A->w * rA.y - B->w * rB.y, 16);
    *cy = B->y - A->y + pg__round_shift64(B->w * rB.x - A->w * rA.x, 16);
}

/* Apply a point block's lambda change (dx, dy). */
static inline void joint_point_apply(const joint_point *p, velocity *A, velocity *B, int64_t dx, int64_t dy)
{
    A->x -= row_round(p->mA[0] * dx + p->mA[1] * dy, 30);
    A->y -= row_round(p->mA[1] * dx + p->mA[2] * dy, 30);
    A->w -= row_round(p->gA[0] * dx + p->gA[1] * dy, 24);
    B->x += row_round(p->mB[0] * dx + p->mB[1] * dy, 30);
    B->y += row_round(p->mB[1] * dx + p->mB[2] * dy, 30);
    B->w += row_round(p->gB[0] * dx + p->gB[1] * dy, 24);
}

/* A point block's pass: C (m) is B's anchor less A's now; soft or rigid (C unread). */
static inline void joint_point_solve(joint_constraint *c, velocity *A, velocity *B, int64_t Cx, int64_t Cy, const softness *s, int use_soft)
{
    int64_t vx, vy, bx = 0, by = 0, nx, ny;
    joint_point_speed(A, B, c->A.lever_now, c->B.lever_now, &vx, &vy);
    if (use_soft) {
        bx = row_round(s->bias_rate * clamp64(Cx, INT32_MAX), 16);
        by = row_round(s->bias_rate * clamp64(Cy, INT32_MAX), 16);
    }
    nx = clamp64(c->imp[0] + joint_soft_delta(vx, bx, c->imp[0], s, use_soft), LAMBDA_MAX);
    ny = clamp64(c->imp[1] + joint_soft_delta(vy, by, c->imp[1], s, use_soft), LAMBDA_MAX);
    joint_point_apply(&c->point, A, B, nx - c->imp[0], ny - c->imp[1]);
    c->imp[0] = nx;
    c->imp[1] = ny;
}

int64_t pg__joint_soft_delta(int64_t v, int64_t bias, int64_t acc, const softness *s, int use_soft);
void pg__joint_point_speed(const velocity *A, const velocity *B, pg_vec2 rA, pg_vec2 rB, int64_t *cx, int64_t *cy);
void pg__joint_point_apply(const joint_point *p, velocity *A, velocity *B, int64_t dx, int64_t dy);
void pg__joint_point_solve(joint_constraint *c, velocity *A, velocity *B, int64_t Cx, int64_t Cy, const softness *s, int use_soft);
/* An equality row's pass (C: its position error). */
void pg__joint_row_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t C, const softness *s, int use_soft);
/* A one-sided row: keeps C >= 0 (sign 1) or C <= 0 (sign -1). Box2D v3's limit: a gap
 * closes at most by C / h (speculative), an overlap is pushed out softly in the solve
 * pass and only stopped in the relax passes. */
void pg__joint_limit_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t C, int sign, const softness *s,
                           int use_soft, uint32_t n_per_second);
/* A motor row: drives the row's speed to `speed`, its lambda within +-cap. */
void pg__joint_motor_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t speed, int64_t cap);

static inline void joint_row_apply(const joint_row *r, velocity *A, velocity *B, int64_t dl)
{
    apply_row(A, B, dl, r->lA_x, r->lA_y, r->lB_x, r->lB_y, r->gA, r->gB);
}

static inline int64_t joint_row_speed(const joint_row *r, const velocity *A, const velocity *B)
{
    return relative_speed(A, B, r->d, r->cA, r->cB);
}

#endif
