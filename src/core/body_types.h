/* body_types.h (internal) — a body as the world stores it. Everything here that
 * influences the future is in the state hash and snapshots (state.c). */
#ifndef POGON_SRC_BODY_TYPES_H
#define POGON_SRC_BODY_TYPES_H
#include "pogon/pogon.h"

#define PG_NULL_INDEX 0xFFFFFFFFu

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

/* The fields are ordered so that every int64 lands on a multiple of 8 without padding
 * (168 bytes, the sum of the fields rounded up to 8): a world holds one per body slot. */
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
    pg_fix sleep_time;
    int64_t force_x, force_y, torque; /* Q48.16, cleared after each step */
    pg_fix linear_damping, angular_damping;
    int64_t mass, inertia;            /* Q32.32 kg, Q28.36 kg m^2 */
    int64_t inv_mass, inv_inertia;    /* Q25.38 (1/kg, 1/(kg m^2)); 0 for infinite */
    uint64_t user_data;
    pg_fix gravity_scale;
    /* derived from the shapes and local_center (pg__body_set_turn_extents), for continuous
     * collision of turning bodies: how far any shape's core reaches from the centre of
     * mass (an L1 bound; 0 when turning moves no surface, as for a centred circle) and the
     * thinnest shape's inner extent; 0 in a build without continuous collision */
    pg_fix turn_reach, inner_extent;
    uint32_t island;         /* while asleep: the lowest body index of its island */
    uint32_t first_shape;    /* shapes of the body, a list in creation order */
    uint32_t shape_count;
    uint32_t first_joint;    /* the body's joints, a list through pg_joint next_a / next_b
                                (derived from the joint pool: rebuilt on a restore) */
} pg_body;

/* awake and movable: takes part in the solver (inline: the step asks per body and per contact) */
static inline int pg__body_is_active(const pg_body *b)
{
    return (b->flags & (PG_BODY_FLAG_USED | PG_BODY_FLAG_AWAKE)) == (PG_BODY_FLAG_USED | PG_BODY_FLAG_AWAKE) &&
           b->type != PG_BODY_STATIC;
}

#endif
