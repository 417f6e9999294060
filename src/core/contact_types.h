/* contact_types.h (internal) — a contact as the world stores it between steps: its
 * manifold and the accumulated impulses the next step warm starts with. */
#ifndef POGON_SRC_CONTACT_TYPES_H
#define POGON_SRC_CONTACT_TYPES_H
#include "pogon/fixed.h"
#include "geom.h"

typedef struct pg_contact_point {
    pg_vec2 point;           /* world, at the last narrowphase */
    pg_fix separation;
    uint32_t id;
    pg_fix normal_impulse;   /* accumulated, velocity-space (docs/solver-design.md) */
    pg_fix tangent_impulse;
    pg_fix max_normal_impulse;
    pg_fix push_impulse;     /* accumulated, pseudo-velocity space: the push-out that moves
                                positions only (docs/solver-design.md, deep push) */
} pg_contact_point;

typedef struct pg_contact {
    uint32_t shape_a, shape_b; /* shape_a < shape_b: the sort key */
    uint32_t body_a, body_b;
    pg_dir normal;
    int32_t point_count;       /* 0: boxes overlap but shapes do not touch */
    pg_contact_point points[2];
    pg_fix friction, restitution;
} pg_contact;

#endif
