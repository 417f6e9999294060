/* world_types.h (internal) — the world as it sits in the caller's memory.
 *
 * State that influences the future (and therefore goes into hashes and snapshots):
 * the body, shape and joint pools (slots in use, generations), the joints' parameters
 * and accumulated impulses, every body's motion state and
 * sleep timer, the contact list (sorted by shape pair) with its manifolds and
 * accumulated impulses, world settings and the frame counter. Everything else here is
 * scratch recomputed each step. Every stage of the step includes this; none includes
 * world.c's header, because world.c is the orchestrator on top (docs/architecture.md).
 */
#ifndef POGON_SRC_WORLD_TYPES_H
#define POGON_SRC_WORLD_TYPES_H
#include "pogon/pogon.h"
#include "body_types.h"
#include "broadphase.h"
#include "contact_types.h"
#include "geom.h"
#include "joint_types.h"
#include "shape_types.h"

/* An effect bit as the step tests it: 0 when the build leaves the effect out
 * (PG_CONFIG_EFFECTS, pogon/config.h), so the test folds to a constant and the effect's
 * code drops out of the program. A world's effects never hold such a bit (world.c
 * refuses it), so in a build that keeps the effect nothing changes. */
#define PG__EFFECT(bit) ((uint32_t)(bit) & (uint32_t)(PG_CONFIG_EFFECTS))

/* A body's centre of mass and angle at the start of a step, and whether after the solve
 * one of its contacts holds a deep-push impulse (island.c). */
typedef struct pg_step_start {
    pg_vec2 center;
    pg_angle angle;
    uint32_t pushed;
} pg_step_start;

struct pg_world {
    pg_world_def def;
    uint64_t frame;
    pg_body *bodies;
    pg_shape *shapes;
    pg_contact *contacts;      /* the contact update builds the next list in the scratch and
                                  copies it back (contact.c) */
    uint32_t contact_count;
    uint32_t body_high;        /* one past the highest body slot ever used (never shrinks:
                                  the generations of freed slots are state) */
    uint32_t shape_high;
    uint32_t body_count, shape_count;
    pg_joint *joints;
    uint32_t joint_high;       /* one past the highest joint slot ever used */
    uint32_t joint_count;
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
    void *broadphase_scratch;  /* the broadphase's and the solver's scratch are one */
    size_t broadphase_scratch_bytes; /* area (world.c compute_layout): never live at once */
    void *solver_scratch;
    size_t solver_scratch_bytes;
    uint32_t *island_parent;   /* per body slot */
    pg_step_start *step_start; /* per body slot: where an active body was when the step began
                                  (island.c: rest is measured by how far a body moved) */

    pg_contact_event *begin_events, *end_events;
    uint32_t begin_count, end_count;

    char last_error[160];
};

#endif
