/* world_internal.h (internal) — the world's state and the pieces of a step.
 *
 * State that influences the future (and therefore goes into hashes and snapshots):
 * the body and shape pools (slots in use, generations), every body's motion state and
 * sleep timer, the contact list (sorted by shape pair) with its manifolds and
 * accumulated impulses, world settings and the frame counter. Everything else here is
 * scratch recomputed each step.
 */
#ifndef POGON_SRC_WORLD_INTERNAL_H
#define POGON_SRC_WORLD_INTERNAL_H
#include "pogon/pogon.h"
#include "broadphase.h"
#include "geom.h"
#include "mass.h"

#define PG_NULL_INDEX 0xFFFFFFFFu

/* Linear slop and speculative distance: contacts begin this far apart so resting bodies
 * keep their manifold without jitter. Geometry has no skin: boxes placed edge to edge
 * do not start overlapping. */
#define PG_LINEAR_SLOP ((pg_fix)328)           /* 0.005 m */
#define PG_SPECULATIVE_DISTANCE ((pg_fix)1311) /* 0.02 m: 4 slops */

/* Envelope, Q16.16. */
#define PG_ENV_MIN_SIZE ((pg_fix)1638)          /* 0.025 m: smallest radius / half extent */
#define PG_ENV_MAX_SIZE PG_FIX_C(50)
#define PG_ENV_MIN_DENSITY ((pg_fix)6554)       /* 0.1 */
#define PG_ENV_MAX_DENSITY PG_FIX_C(100)
#define PG_ENV_MAX_POSITION PG_FIX_C(1000)
#define PG_ENV_MAX_FRICTION PG_FIX_C(10)
#define PG_ENV_MAX_SPIN PG_FIX_C(1000)          /* rad/s, either way */

/* The contact solver's bounds (solver.c derives its int64 arithmetic from them; state.c
 * refuses a snapshot beyond them). Velocities, m/s and rad/s: every component is clamped
 * to +-PG_SOLVER_VELOCITY_MAX (8192). Accumulated contact "impulses" (lambda: the change
 * of relative velocity along the row, m/s) to +-PG_SOLVER_LAMBDA_MAX (8192): two bodies
 * meeting head-on at the largest max_linear_speed (4096 m/s) close at 8192 m/s, and one
 * row must be able to stop them, or a speculative contact lets them pass through. */
#define PG_SOLVER_VELOCITY_MAX (INT32_C(1) << 29)
#define PG_SOLVER_LAMBDA_MAX (INT32_C(1) << 29)

enum {
    PG_BODY_FLAG_USED = 1u << 0,
    PG_BODY_FLAG_AWAKE = 1u << 1,
    PG_BODY_FLAG_FIXED_ROTATION = 1u << 2,
    PG_BODY_FLAG_ALLOW_SLEEP = 1u << 3,
    PG_BODY_FLAG_GEOMETRY_DIRTY = 1u << 4, /* world geometry must be recomputed */
    /* What the last step (or an impulse since) did to the body, for pg_body_limits. Not
     * state: nothing reads them to decide the future, hashes and snapshots leave them
     * out, and each step clears them before it sets them again. */
    PG_BODY_FLAG_SPEED_CLAMPED = 1u << 5,
    PG_BODY_FLAG_SPIN_CLAMPED = 1u << 6
};

typedef struct pg_body {
    uint32_t generation;
    uint32_t flags;
    pg_body_type type;
    pg_vec2 origin;          /* derived: center - R local_center */
    pg_vec2 center;          /* world centre of mass: the integrated position */
    pg_vec2 local_center;
    pg_angle angle;
    pg_rot rot;              /* derived from angle */
    pg_vec2 v;
    pg_fix w;
    int64_t force_x, force_y, torque; /* Q48.16, cleared after each step */
    pg_fix linear_damping, angular_damping, gravity_scale;
    int64_t mass, inertia;            /* Q32.32 kg, Q28.36 kg m^2 */
    int64_t inv_mass, inv_inertia;    /* Q25.38 (1/kg, 1/(kg m^2)); 0 for infinite */
    pg_fix sleep_time;
    /* derived from the shapes and local_center (pg__body_set_turn_extents), for continuous
     * collision of turning bodies: how far any shape's core reaches from the centre of
     * mass (an L1 bound; 0 when turning moves no surface, as for a centred circle) and the
     * thinnest shape's inner extent */
    pg_fix turn_reach, inner_extent;
    uint32_t island;         /* while asleep: the lowest body index of its island */
    uint32_t first_shape;    /* shapes of the body, a list in creation order */
    uint32_t shape_count;
    uint64_t user_data;
} pg_body;

typedef struct pg_shape {
    uint32_t generation;
    uint32_t used;
    uint32_t body;
    uint32_t next;           /* next shape of the same body */
    pg_geometry geometry;    /* as given, body frame */
    pg_geom local;           /* collision form, body frame */
    pg_fix density, friction, restitution;
    uint32_t category, mask;
    /* derived from `local` (pg__shape_set_extents), for continuous collision of turning
     * bodies: the farthest core vertex from local.centroid (0 for a circle) and the
     * thinnest extent, the centroid's distance to the nearest face plus the radius */
    pg_fix turn_outer, inner_extent;
} pg_shape;

typedef struct pg_contact_point {
    pg_vec2 point;           /* world, at the last narrowphase */
    pg_fix separation;
    uint32_t id;
    pg_fix normal_impulse;   /* accumulated, velocity-space (see solver.c) */
    pg_fix tangent_impulse;
    pg_fix max_normal_impulse;
    pg_fix push_impulse;     /* accumulated, pseudo-velocity space: the push-out that moves
                                positions only (solver.c, DEEP PUSH) */
} pg_contact_point;

typedef struct pg_contact {
    uint32_t shape_a, shape_b; /* shape_a < shape_b: the sort key */
    uint32_t body_a, body_b;
    pg_dir normal;
    int32_t point_count;       /* 0: boxes overlap but shapes do not touch */
    pg_contact_point points[2];
    pg_fix friction, restitution;
} pg_contact;

struct pg_world {
    pg_world_def def;
    uint64_t frame;
    pg_body *bodies;
    pg_shape *shapes;
    pg_contact *contacts, *contacts_next; /* two buffers, swapped each step */
    uint32_t contact_count;
    uint32_t body_high;        /* one past the highest body slot ever used (never shrinks:
                                  the generations of freed slots are state) */
    uint32_t shape_high;
    uint32_t body_count, shape_count;
    pg_world_stats stats;

    /* scratch, recomputed each step */
    pg_geom *world_geoms;      /* per shape slot, world frame */
    pg_aabb *boxes;            /* per shape slot, fattened */
    uint8_t *proxy_flags;      /* per shape slot: PG_PROXY_ACTIVE when its body moves */
    pg_aabb *proxy_boxes;      /* compacted: used shapes in slot order */
    uint8_t *proxy_flags_compact;
    uint32_t *proxy_shape;     /* proxy -> shape slot */
    pg_pair *pairs;
    uint32_t pair_capacity;
    void *broadphase_scratch;
    size_t broadphase_scratch_bytes;
    void *solver_scratch;
    size_t solver_scratch_bytes;
    uint32_t *island_parent;   /* per body slot */

    pg_contact_event *begin_events, *end_events;
    uint32_t begin_count, end_count;

    char last_error[160];
};

/* world.c */
pg_result pg__fail(const pg_world *world, pg_result r, const char *detail);
pg_result pg__fail_value(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *bound);
/* "what VALUE relation LIMIT unit", e.g. "speed 565.6854 m/s exceeds the world's
 * max_linear_speed 400 m/s" from ("speed", v, "m/s exceeds the world's max_linear_speed",
 * cap, "m/s") */
pg_result pg__fail_limit(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *relation, pg_fix limit,
                         const char *unit);
pg_body *pg__body(const pg_world *world, pg_body_id id); /* NULL if stale */
pg_shape *pg__shape(const pg_world *world, pg_shape_id id);
void pg__push_end_event(pg_world *world, const pg_contact *c);

/* body.c */
void pg__body_update_mass(pg_world *world, uint32_t body_index);
/* inv_mass and inv_inertia from mass, inertia, type and fixed rotation: the one rule, for
 * pg__body_update_mass and for restoring a snapshot (which stores only mass and inertia) */
void pg__body_set_inverse_mass(pg_body *b);
/* round(2^(63 + e) / d) for d > 0, 0 <= e <= 31, as pg__div64_shl(2^(25 + e), d, 38) gives it */
int64_t pg__reciprocal_pow2(int e, int64_t d);
/* Why mass data cannot be a dynamic body's (its mass, inertia or their inverses leave
 * their formats), as a message for the user; NULL when it can. `rotates`: the body does
 * not have fixed rotation (only then is its inverse inertia used). */
const char *pg__mass_data_problem(pg_mass_data md, int rotates);
/* The same for body `body_index` with its shapes at `density` (0: each shape's own),
 * without shape slot `skip` (PG_NULL_INDEX: none), plus `extra` at `extra_density`. */
const char *pg__body_mass_problem(const pg_world *world, uint32_t body_index, pg_fix density, uint32_t skip,
                                  const pg_geom *extra, pg_fix extra_density, int rotates);
void pg__body_sync_geometry(pg_world *world, uint32_t body_index); /* world geoms + boxes */
void pg__wake_body(pg_world *world, uint32_t body_index);         /* and its island */
/* awake and movable: takes part in the solver (inline: the step asks per body and per contact) */
static inline int pg__body_is_active(const pg_body *b)
{
    return (b->flags & (PG_BODY_FLAG_USED | PG_BODY_FLAG_AWAKE)) == (PG_BODY_FLAG_USED | PG_BODY_FLAG_AWAKE) &&
           b->type != PG_BODY_STATIC;
}
/* The documented speed cap: the inline test passes every legal velocity through, the
 * out-of-line part scales a faster one down, counts it in stats.speed_clamps and sets
 * PG_BODY_FLAG_SPEED_CLAMPED in *flags. */
pg_vec2 pg__clamp_speed_slow(pg_world *world, pg_vec2 v, uint32_t *flags);
static inline pg_vec2 pg__clamp_speed(pg_world *world, pg_vec2 v, uint32_t *flags)
{
    int64_t cap = world->def.max_linear_speed;
    /* each square is at most 2^62; their sum (2^63 for INT32_MIN twice) fits unsigned */
    if ((uint64_t)((int64_t)v.x * v.x) + (uint64_t)((int64_t)v.y * v.y) <= (uint64_t)(cap * cap)) return v;
    return pg__clamp_speed_slow(world, v, flags);
}
/* Within the position envelope (+-PG_ENV_MAX_POSITION on both axes). */
static inline int pg__in_position_envelope(pg_vec2 p)
{
    return p.x >= -PG_ENV_MAX_POSITION && p.x <= PG_ENV_MAX_POSITION && p.y >= -PG_ENV_MAX_POSITION && p.y <= PG_ENV_MAX_POSITION;
}
/* Write the velocities a step leaves in a body, within what the setters accept: the
 * linear one within max_linear_speed, the angular one within +-1000 rad/s (PG_ENV_MAX_SPIN).
 * The contact solve may exceed both (the solver's own bound is PG_SOLVER_VELOCITY_MAX);
 * each clamp is counted in the stats and flagged on the body. */
void pg__body_store_velocity(pg_world *world, pg_body *b, pg_vec2 v, pg_fix w);

/* shape.c */
void pg__shape_build_local(const pg_geometry *g, pg_geom *out); /* collision form of a geometry */
pg_result pg__validate_geometry(const pg_geometry *g);             /* what pg_shape_create accepts */

/* contact.c */
pg_result pg__update_contacts(pg_world *world);
/* Whether shapes sa and sb may touch: different bodies, one dynamic, filters agree. */
int pg__shapes_should_collide(const pg_world *w, uint32_t sa, uint32_t sb);
void pg__remove_body_contacts(pg_world *world, uint32_t body_index);
void pg__refresh_contact_materials(pg_world *world, uint32_t body_index); /* after a friction/restitution change */

/* solver.c */
size_t pg__solver_scratch_bytes(const pg_world_def *def);
void pg__solve(pg_world *world);

/* continuous.c: time of impact for bodies that turn too far in a step for their
 * speculative contacts (see the file's header) */
typedef struct pg_sweep {
    uint32_t body;
    pg_vec2 c0, c1;     /* centre of mass at the step's start and end */
    pg_angle a0;        /* angle at the start */
    int64_t turn;       /* the step's turn in binary-angle units, unwrapped (pg__turn_of_step) */
    pg_fix fraction;    /* earliest time of impact, Q16.16 of the step; PG_FIX_ONE: none */
    int32_t moved;      /* c1 was moved: a core circle was held at a surface */
} pg_sweep;
void pg__shape_set_extents(pg_shape *s); /* whenever s->local is built */
void pg__body_set_turn_extents(pg_world *w, uint32_t body); /* whenever its shapes or local_center change */
/* Whether body b is fast-turning at its angular velocity now (for its broadphase boxes at
 * the step's start), and then the radius about its centre of mass that shape s sweeps
 * while it turns: the box covers that disc (otherwise the pose's box is enough). */
int pg__turns_fast_now(const pg_world *w, const pg_body *b);
int64_t pg__shape_turn_radius(const pg_body *b, const pg_shape *s);
/* The turn from a0 to a1 in binary-angle units, unwrapped: the whole turns are taken from
 * `radians` (Q32), the solver's sum of w h over the substeps. Beyond 8 turns either way,
 * a value past PG__MAX_TURN: such a body is not swept. */
int64_t pg__turn_of_step(pg_angle a0, pg_angle a1, int64_t radians);
/* Whether the body of sweep s turned too far for its speculative contacts in the step,
 * or would have at w0, its angular velocity at the step's start (a spin its contacts
 * stopped in the first substep: the contacts were made for the features facing at the
 * start, and a turning body's are the wrong ones). */
int pg__sweep_is_fast(const pg_world *w, const pg_sweep *s, pg_fix w0);
/* Put each swept body back at its earliest time of impact with a static shape whose
 * broadphase box its own overlapped in this step (w->pairs, still this step's after the
 * solve). sweep_of_body: scratch of body_high entries. */
void pg__sweep_fast_turns(pg_world *w, pg_sweep *sweeps, uint32_t n, uint32_t *sweep_of_body);

/* island.c */
void pg__update_sleep(pg_world *world);

#endif
