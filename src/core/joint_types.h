/* joint_types.h (internal) — a joint as the world stores it. Everything here but the
 * body lists (next) is state: in the JOINTS section of the hash and in snapshots
 * (state.c). */
#ifndef POGON_SRC_JOINT_TYPES_H
#define POGON_SRC_JOINT_TYPES_H
#include "pogon/joint.h"

enum {
    PG_JOINT_FLAG_USED = 1u << 0,
    PG_JOINT_FLAG_COLLIDE = 1u << 1,  /* collide_connected */
    PG_JOINT_FLAG_LIMIT = 1u << 2,
    PG_JOINT_FLAG_MOTOR = 1u << 3,
    PG_JOINT_FLAG_SPRING = 1u << 4
};
#define PG_JOINT_STATE_FLAGS (PG_JOINT_FLAG_COLLIDE | PG_JOINT_FLAG_LIMIT | PG_JOINT_FLAG_MOTOR | PG_JOINT_FLAG_SPRING)

/* One struct for every kind; each kind reads the fields its def has (docs/joints.md):
 *   distance   length, lower/upper = min/max length, hertz/damping = spring
 *   revolute   reference_angle, lower/upper = angles (rad), motor_speed, max_motor (N m)
 *   weld       reference_angle, hertz/damping = linear, hertz2/damping2 = angular
 *   prismatic  axis, reference_angle, lower/upper = translations, motor_speed, max_motor (N)
 *   mouse      body_a = PG_NULL_INDEX, anchor_b on the body, target, hertz/damping, max_motor
 *              = max force (N) */
typedef struct pg_joint {
    uint32_t generation;
    uint32_t flags;
    pg_joint_type type;
    uint32_t body_a, body_b;     /* body slots; body_a is PG_NULL_INDEX for a mouse joint */
    pg_vec2 anchor_a, anchor_b;  /* in each body's frame, relative to its origin */
    pg_vec2 axis;                /* prismatic: unit axis in A's frame (Q16.16) */
    pg_vec2 target;              /* mouse: world point */
    pg_angle reference_angle;
    pg_fix length;
    pg_fix lower, upper;
    pg_fix motor_speed, max_motor;
    pg_fix hertz, damping, hertz2, damping2;
    uint64_t user_data;
    /* accumulated impulses, as the change of relative velocity they make (m/s or rad/s,
     * docs/joints.md): the next step warm starts with them */
    pg_fix point_impulse[2];     /* revolute, weld, mouse: the point's x and y; prismatic:
                                    [0] the row across the axis */
    pg_fix axial_impulse;        /* distance: along the rod (rigid or spring); weld and
                                    prismatic: the angle row */
    pg_fix lower_impulse, upper_impulse, motor_impulse;
    /* the bodies' joint lists (derived: rebuilt from the pool on a restore) */
    uint32_t next_a, next_b;     /* next joint of body_a's list, of body_b's */
} pg_joint;

#endif
