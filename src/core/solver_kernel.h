/* solver_kernel.h (internal) — what every constraint kind's stages share: the solver's
 * view of a body, the step's context, and the row kernel that loads two bodies'
 * velocities, changes them along a row and stores them (docs/solver-design.md). */
#ifndef POGON_SRC_SOLVER_KERNEL_H
#define POGON_SRC_SOLVER_KERNEL_H
#include "envelope.h"
#include "geom.h"
#include "wide.h"
#include "world_types.h"

/* The rows are forced inline where a pass calls them, and each pass into the stage loop
 * that runs it, so every pass is specialised (use_bias, the cached separation) and keeps
 * the two velocities in registers; the rare, large paths stay out of line. Built for
 * size (-Os, __OPTIMIZE_SIZE__), the compiler decides instead: a copy of every row in
 * every pass is most of the contact solver's flash on a microcontroller (docs/embedded.md).
 * Inlining changes no result: the arithmetic is the same integer expressions. */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE_SIZE__)
#define PG__INLINE_ROW static inline __attribute__((always_inline))
#define PG__NOINLINE static __attribute__((noinline))
#elif defined(__GNUC__) || defined(__clang__)
#define PG__INLINE_ROW static inline
#define PG__NOINLINE static __attribute__((noinline))
#else
#define PG__INLINE_ROW static inline
#define PG__NOINLINE static
#endif
#define PG__INLINE_PASS PG__INLINE_ROW

/* The rows' rounding (ROUNDING): round(x / 2^n), ties toward +infinity, 1 <= n <= 62.
 * Arithmetic right shift of a negative value is pinned by fixed.h's compile-time check. */
static inline int64_t row_round(int64_t x, int n) { return (x + ((int64_t)1 << (n - 1))) >> n; }

/* Ordered so that the int64 fields need no padding (128 bytes): one per body slot in the
 * world's scratch. */
typedef struct solver_body {
    pg_vec2 v;
    pg_fix w;
    pg_vec2 c0, c;        /* centre at the start of the step, and now */
    pg_vec2 dp;           /* c - c0: |.| <= VELOCITY_MAX / step_hz + 9 <= 2^29 + 9 (a step
                             lasts at most 1 s), fits */
    pg_angle a0, a;
    pg_rot dq;            /* rotation from a0 to a; kept only when turns_anchors */
    uint32_t saturated;   /* nonzero when a velocity of this body was clamped to the
                             kernel's bounds in this step: counted once in stats.saturations
                             at the write-back */
    int64_t turn;         /* radians turned since the step's start, Q32 (|w| <= 2^29 Q16 and
                             h <= 2^32 Q32 s, so each substep's w h fits; 16 of them too) */
    int32_t turns_anchors;/* some contact anchor on this body turns with it (not a centred
                             circle): only then is dq needed */
    pg_vec2 accel;        /* from gravity and force, m/s^2 */
    pg_fix alpha;         /* from torque, rad/s^2 */
    pg_vec2 pv;           /* pseudo velocity: the deep push-out of this step, which moves
                             the centre but is never momentum (DEEP PUSH) */
    uint32_t pushed;      /* 1 + the substep in which a deep constraint holds this body */
    int32_t lin_damp, ang_damp; /* Q2.30 factor per substep; PG_ROT_ONE: none */
    pg_vec2 v_pre;        /* v and w just before this substep's warm start */
    pg_fix w_pre;
    int32_t dv_x, dv_y;   /* what the constraints changed over the last substep: v and w */
    int64_t dw;           /* at the end of its relax stage less v_pre, w_pre, which the
                             contacts' warm start of later substeps applies again (WARM
                             START). Both ends of v are within the kernel's bounds (2^29),
                             so dv fits int32; w_pre, after an angular integration, within
                             +-2^31, so dw needs int64 */
} solver_body;

/* What the joints changed in a body's v and w since the substep's velocity integration,
 * which dv leaves out (WARM START): one per solver body slot, in the joints' scratch (an
 * array beside the solver bodies, so a solver body stays 128 bytes). */
typedef struct joint_change { int64_t x, y, w; } joint_change;

typedef struct softness {
    pg_fix bias_rate;
    int32_t mass_scale, impulse_scale; /* Q2.30 */
    int32_t hold_rate;                 /* Q16 m/s per lambda: the bias that holds an impulse
                                          at rest, impulse_scale / mass_scale (DEEP PUSH) */
    int64_t floor_depth;               /* from this separation up, |bias| <= the floor of
                                          DEEP PUSH: no point there is deep */
} softness;

typedef struct step_context {
    uint32_t n;              /* substeps per second */
    int64_t h_q32;           /* substep in Q32 seconds */
    int64_t angle_per_w;     /* binary-angle units per (rad/s) per substep, Q8: w angle_per_w
                                is the turn in Q56 (see angle_step) */
    softness soft, soft_static;
    pg_fix push_max;
    pg_fix push_floor;       /* push-out up to this becomes velocity whatever the load
                                (DEEP PUSH): push_max / 32 */
    uint32_t effects;
    int rotation;            /* PG_EFFECT_ROTATION is on */
    uint32_t sub;            /* the substep the passes are in */
    const pg_world *world;   /* for the bodies' masses when a constraint's rows are set late */
    uint32_t dummy;          /* the solver slot of the static side */
    int *deep_seen;          /* set when a point pushes out past its velocity cap or starts the
                                step with a pseudo impulse (DEEP PUSH) */
    pg_vec2 gravity;         /* the acceleration gravity gives a body of gravity scale 1 */
} step_context;

/* Box2D v3's b2MakeSoft in fixed point: omega = 2 pi hz, a1 = 2 zeta + h omega,
 * a2 = h omega a1, a3 = 1 / (1 + a2); bias rate omega / a1, mass scale a2 a3,
 * impulse scale a3. h = 1 / n_per_second. */
static inline softness pg__make_soft(pg_fix hertz, pg_fix zeta, uint32_t n_per_second)
{
    softness s;
    int64_t omega = row_round((int64_t)hertz * PG_FIX_TWO_PI, 16); /* Q16 */
    int64_t h_omega = (omega * 2 + (int64_t)n_per_second) / (2 * (int64_t)n_per_second);
    int64_t a1 = 2 * (int64_t)zeta + h_omega;
    int64_t a2 = row_round(h_omega * a1, 16);
    s.floor_depth = 0; /* the contacts set it from their push floor (pg__contacts_set_softness) */
    s.bias_rate = a1 > 0 ? (pg_fix)((omega * 65536 + a1 / 2) / a1) : 0;
    s.mass_scale = (int32_t)((a2 * (INT64_C(1) << 30) + (65536 + a2) / 2) / (65536 + a2));
    s.impulse_scale = (int32_t)(((INT64_C(1) << 46) + (65536 + a2) / 2) / (65536 + a2));
    {
        /* a soft row at rest (rel = 0) keeps its lambda when mass_scale bias = -impulse_scale
         * lambda; impulse_scale < 2^30, so the product fits */
        int64_t hold = s.mass_scale > 0 ? ((int64_t)s.impulse_scale * (1 << 16) + s.mass_scale / 2) / s.mass_scale : INT32_MAX;
        s.hold_rate = (int32_t)(hold > INT32_MAX ? INT32_MAX : hold);
    }
    return s;
}

/* ---- the row kernel ------------------------------------------------------------------
 * A constraint loads its two bodies' velocities into int64 locals, solves its rows
 * without intermediate saturation, and clamps once when it stores them. That is safe
 * because every quantity is bounded (L = LAMBDA_MAX = 2^29, 8192 m/s: see
 * envelope.h for why):
 *   a normal row's lambda stays in [0, L], a friction row's in [-L, L], so one row
 *   changes lambda by |dl| <= 2^29 (normal, restitution, warm start) or 2^30 (friction),
 *   a linear velocity by at most |dl| (|k n| <= 1, as a vector) and an angular one by
 *   |dl| 2^7 (|g| < 128 / m);
 *   velocities enter within +-VELOCITY_MAX = 2^29 per component (2^29.5 as a vector;
 *   an angular velocity just integrated from a saturated torque within +-2^31);
 *   the rows of a constraint run normal, normal, friction, friction, so the last one
 *   reads |vB - vA| <= 2^30.5 + 2 (2^29 + 2^29 + 2^30) < 2^32.4 and |w| < 2^31 +
 *   2^36 + 2^36 + 2^37 < 2^38.1. Then every product below fits int64: d . (vB - vA)
 *   <= |d| |vB - vA| < 2^30 2^32.4 (Cauchy-Schwarz bounds the sum too), w (r x d) <
 *   2^38.1 2^23.6 (anchors lie within 200 m of a body's centre), the difference of two
 *   such < 2^62.7, dl l < 2^60, dl g < 2^61; but for the soft row's mass scale times
 *   the relative speed, which has the wide path of mass_scale_times. */
#define LAMBDA_MAX ((int64_t)PG_SOLVER_LAMBDA_MAX)
#define VELOCITY_MAX ((int64_t)PG_SOLVER_VELOCITY_MAX)

typedef struct velocity { int64_t x, y, w; } velocity;

static inline velocity load_velocity(const solver_body *b)
{
    velocity v;
    v.x = b->v.x;
    v.y = b->v.y;
    v.w = b->w;
    return v;
}

static inline pg_fix clamp_velocity(int64_t v)
{
    /* one unsigned comparison on the common path: v in [-VELOCITY_MAX, VELOCITY_MAX] */
    if ((uint64_t)(v + VELOCITY_MAX) <= (uint64_t)(2 * VELOCITY_MAX)) return (pg_fix)v;
    return (pg_fix)(v > 0 ? VELOCITY_MAX : -VELOCITY_MAX);
}

static inline void store_velocity(solver_body *b, const velocity *v)
{
    /* v + VELOCITY_MAX is in [0, 2^30) for all three exactly when their OR is: one test
     * on the common path instead of three */
    uint64_t bits = (uint64_t)(v->x + VELOCITY_MAX) | (uint64_t)(v->y + VELOCITY_MAX) | (uint64_t)(v->w + VELOCITY_MAX);
    if (bits < (uint64_t)(2 * VELOCITY_MAX)) {
        b->v.x = (pg_fix)v->x;
        b->v.y = (pg_fix)v->y;
        b->w = (pg_fix)v->w;
        return;
    }
    b->v.x = clamp_velocity(v->x);
    b->v.y = clamp_velocity(v->y);
    b->w = clamp_velocity(v->w);
    /* v == VELOCITY_MAX takes this path too, unclamped */
    b->saturated |= (uint32_t)(b->v.x != v->x || b->v.y != v->y || b->w != v->w);
}

/* The linear part of a row: what apply_row does when gA = gB = 0. */
static inline void apply_linear(velocity *A, velocity *B, int64_t lambda, int32_t lA_x, int32_t lA_y, int32_t lB_x, int32_t lB_y)
{
    A->x -= row_round(lambda * lA_x, 30);
    A->y -= row_round(lambda * lA_y, 30);
    B->x += row_round(lambda * lB_x, 30);
    B->y += row_round(lambda * lB_y, 30);
}

/* The linear part of relative_speed: all of it when cA = cB = 0. */
static inline int64_t linear_speed(const velocity *A, const velocity *B, pg_dir d)
{
    return row_round(d.x * (B->x - A->x) + d.y * (B->y - A->y), 30);
}

/* A whole row. It does not call apply_linear: written body by body (A's x, y, w, then
 * B's), gcc schedules the substep loop better. */
static inline void apply_row(velocity *A, velocity *B, int64_t lambda, int32_t lA_x, int32_t lA_y, int32_t lB_x, int32_t lB_y, int32_t gA, int32_t gB)
{
    A->x -= row_round(lambda * lA_x, 30);
    A->y -= row_round(lambda * lA_y, 30);
    A->w -= row_round(lambda * gA, 24);
    B->x += row_round(lambda * lB_x, 30);
    B->y += row_round(lambda * lB_y, 30);
    B->w += row_round(lambda * gB, 24);
}

/* The angular part of relative_speed (0 when cA = cB = 0), rounded ties away from zero
 * (ROUNDING: lever arms of 0.5 m make ties common here). */
static inline int64_t angular_speed(const velocity *A, const velocity *B, pg_fix cA, pg_fix cB)
{
    return pg__round_shift64(B->w * cB - A->w * cA, 16);
}

/* Relative velocity of B's anchor against A's along direction d (cA, cB: r x d). */
static inline int64_t relative_speed(const velocity *A, const velocity *B, pg_dir d, pg_fix cA, pg_fix cB)
{
    return linear_speed(A, B, d) + angular_speed(A, B, cA, cB);
}

static inline int64_t clamp_lambda(int64_t acc, int64_t lo, int64_t hi) { return acc < lo ? lo : acc > hi ? hi : acc; }

#endif
