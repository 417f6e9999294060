/** @file
 * pogon/joint.h — joints: constraints between two bodies, solved in the same soft step
 * as contacts (docs/joints.md).
 *
 * HOW TO USE IT
 *     pg_revolute_joint_def jd = pg_default_revolute_joint_def();
 *     jd.body_a = ground;                           // any body; the zero handle is refused
 *     jd.body_b = arm;
 *     jd.local_anchor_a = pg_v2(0, PG_FIX_C(5));   // the pin, in each body's own frame
 *     jd.local_anchor_b = pg_v2(PG_FIX_C(-1), 0);
 *     pg_joint_id pin;
 *     if (pg_revolute_joint_create(world, &jd, &pin) != PG_OK) puts(pg_world_last_error(world));
 *
 * THE KINDS
 *   distance   two anchors kept at a length: a rigid rod, or a spring (hertz, damping
 *              ratio), with an optional minimum and maximum length
 *   revolute   a pin: the anchors meet; optional angle limits and a motor
 *   weld       the anchors meet and the relative angle is kept: rigid or soft
 *   prismatic  body B slides along an axis fixed in body A; optional limits and a motor
 *   mouse      pulls one body's anchor toward a target point, with a maximum force: what
 *              dragging uses
 *
 * CONVENTIONS (as for bodies and shapes)
 *   - Each kind is made from a def that starts from its defaults function; a def that
 *     did not is refused. Anchors are in each body's frame (relative to its origin),
 *     within 50 m of a dynamic or kinematic body's origin (its lever arm, as for
 *     shapes) and 1000 m of a static body's.
 *   - Handles (pg_joint_id) hold an index and a generation: a destroyed joint's handle
 *     is detected (PG_ERR_STALE_HANDLE). Destroying a body destroys its joints.
 *   - Two bodies joined by a joint do not collide with each other unless its
 *     collide_connected is nonzero (default 0 for every kind).
 *   - Rigid rows are soft constraints of 60 Hz (capped at a quarter of the substep rate)
 *     and damping ratio 5, as Box2D v3.1's joints; springs use the def's hertz and ratio.
 *   - A failing call changes nothing. Creating, destroying or changing a joint wakes its
 *     bodies.
 *   - The world's capacity is pg_world_def.max_joints.
 */
#ifndef POGON_JOINT_H
#define POGON_JOINT_H

#include "pogon/pogon.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A handle to a joint: a slot and its generation, as pg_body_id. The zero handle is
 * never valid. */
typedef struct pg_joint_id {
    uint32_t index;      /**< the slot */
    uint32_t generation; /**< the slot's generation when the joint was made */
} pg_joint_id;
/** Nonzero when a and b name the same joint. */
static inline int pg_joint_id_equal(pg_joint_id a, pg_joint_id b) { return a.index == b.index && a.generation == b.generation; }

/** The kind of a joint. */
typedef enum pg_joint_type {
    PG_JOINT_DISTANCE = 0,  /**< pg_distance_joint_def */
    PG_JOINT_REVOLUTE = 1,  /**< pg_revolute_joint_def */
    PG_JOINT_WELD = 2,      /**< pg_weld_joint_def */
    PG_JOINT_PRISMATIC = 3, /**< pg_prismatic_joint_def */
    PG_JOINT_MOUSE = 4,     /**< pg_mouse_joint_def */
    PG_JOINT_TYPE_COUNT     /**< the number of kinds (not a kind) */
} pg_joint_type;

/* ---- distance ------------------------------------------------------------------------- */
/** Two anchors held at `length`: a rod when enable_spring is 0, else a spring. */
typedef struct pg_distance_joint_def {
    pg_body_id body_a;            /**< one body */
    pg_body_id body_b;            /**< another body; not both static */
    pg_vec2 local_anchor_a;       /**< m, in body A's frame; default (0, 0) */
    pg_vec2 local_anchor_b;       /**< m, in body B's frame; default (0, 0) */
    pg_fix length;                /**< rest length, m: 0.005 .. 100, default 1 */
    int enable_spring;            /**< 0 (default): rigid; nonzero: a spring of hertz and damping_ratio */
    pg_fix hertz;                 /**< spring frequency, Hz: 0 .. 1000 (0: no spring force), default 0 */
    pg_fix damping_ratio;         /**< spring damping ratio: 0 .. 1000, default 0 */
    int enable_limit;             /**< nonzero: the length stays within min_length .. max_length */
    pg_fix min_length;            /**< m, default 0 */
    pg_fix max_length;            /**< m, default 100; min_length <= max_length */
    int collide_connected;        /**< nonzero: the two bodies still collide; default 0 */
    uint64_t user_data;           /**< yours; saved in snapshots */
    uint32_t pg__cookie;          /**< internal: set by pg_default_distance_joint_def() */
} pg_distance_joint_def;
/** The default distance joint def (see each field): every distance joint def starts from here. */
pg_distance_joint_def pg_default_distance_joint_def(void);
/** Create a distance joint; *out receives its handle (the zero handle on failure). */
pg_result pg_distance_joint_create(pg_world *world, const pg_distance_joint_def *def, pg_joint_id *out);
/** The rest length, m (0.005 .. 100). */
pg_result pg_distance_joint_set_length(pg_world *world, pg_joint_id joint, pg_fix length);
/** Spring on (hertz, damping ratio) or off (rigid). */
pg_result pg_distance_joint_set_spring(pg_world *world, pg_joint_id joint, int enable, pg_fix hertz, pg_fix damping_ratio);
/** Length limits, m (min <= max). */
pg_result pg_distance_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix min_length, pg_fix max_length);
/** The distance between the anchors now, m (0 for an invalid handle). */
pg_fix pg_distance_joint_current_length(const pg_world *world, pg_joint_id joint);
/** The joint's def as it is now (bodies as handles), e.g. to save it. */
pg_result pg_distance_joint_get_def(const pg_world *world, pg_joint_id joint, pg_distance_joint_def *out);

/* ---- revolute --------------------------------------------------------------------------- */
/** A pin: body B's anchor stays on body A's. The joint angle is angle(B) - angle(A) -
 * reference_angle, in radians within (-pi, pi]. */
typedef struct pg_revolute_joint_def {
    pg_body_id body_a;            /**< one body */
    pg_body_id body_b;            /**< another body; not both static */
    pg_vec2 local_anchor_a;       /**< m, in body A's frame */
    pg_vec2 local_anchor_b;       /**< m, in body B's frame */
    pg_angle reference_angle;     /**< binary angle of B relative to A at joint angle 0; default 0 */
    int enable_limit;             /**< nonzero: lower_angle <= joint angle <= upper_angle */
    pg_fix lower_angle;           /**< rad, -pi .. upper_angle; default 0 */
    pg_fix upper_angle;           /**< rad, lower_angle .. pi; default 0 */
    int enable_motor;             /**< nonzero: drive the relative angular speed to motor_speed */
    pg_fix motor_speed;           /**< rad/s, within +-1000; default 0 */
    pg_fix max_motor_torque;      /**< N m, >= 0; default 0 */
    int collide_connected;        /**< default 0 */
    uint64_t user_data;           /**< yours; saved in snapshots */
    uint32_t pg__cookie;          /**< internal: set by pg_default_revolute_joint_def() */
} pg_revolute_joint_def;
/** The default revolute joint def: every revolute joint def starts from here. */
pg_revolute_joint_def pg_default_revolute_joint_def(void);
/** Create a revolute joint; *out receives its handle. */
pg_result pg_revolute_joint_create(pg_world *world, const pg_revolute_joint_def *def, pg_joint_id *out);
/** Angle limits on or off, rad (-pi <= lower <= upper <= pi). */
pg_result pg_revolute_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix lower_angle, pg_fix upper_angle);
/** The motor on or off: its speed (rad/s, within +-1000) and its largest torque (N m, >= 0). */
pg_result pg_revolute_joint_set_motor(pg_world *world, pg_joint_id joint, int enable, pg_fix motor_speed, pg_fix max_motor_torque);
/** The joint angle now, rad within (-pi, pi] (0 for an invalid handle). */
pg_fix pg_revolute_joint_angle(const pg_world *world, pg_joint_id joint);
/** The joint's def as it is now. */
pg_result pg_revolute_joint_get_def(const pg_world *world, pg_joint_id joint, pg_revolute_joint_def *out);

/* ---- weld -------------------------------------------------------------------------------- */
/** The anchors meet and the relative angle stays reference_angle. Hertz 0: rigid. */
typedef struct pg_weld_joint_def {
    pg_body_id body_a;            /**< one body */
    pg_body_id body_b;            /**< another body; not both static */
    pg_vec2 local_anchor_a;       /**< m, in body A's frame */
    pg_vec2 local_anchor_b;       /**< m, in body B's frame */
    pg_angle reference_angle;     /**< binary angle of B relative to A; default 0 */
    pg_fix linear_hertz;          /**< Hz, 0 .. 1000; 0 (default): rigid */
    pg_fix linear_damping_ratio;  /**< 0 .. 1000, default 0 */
    pg_fix angular_hertz;         /**< Hz, 0 .. 1000; 0 (default): rigid */
    pg_fix angular_damping_ratio; /**< 0 .. 1000, default 0 */
    int collide_connected;        /**< default 0 */
    uint64_t user_data;           /**< yours; saved in snapshots */
    uint32_t pg__cookie;          /**< internal: set by pg_default_weld_joint_def() */
} pg_weld_joint_def;
/** The default weld joint def: every weld joint def starts from here. */
pg_weld_joint_def pg_default_weld_joint_def(void);
/** Create a weld joint; *out receives its handle. */
pg_result pg_weld_joint_create(pg_world *world, const pg_weld_joint_def *def, pg_joint_id *out);
/** Softness of the linear and angular parts (hertz 0: rigid). */
pg_result pg_weld_joint_set_softness(pg_world *world, pg_joint_id joint, pg_fix linear_hertz, pg_fix linear_damping_ratio,
                                     pg_fix angular_hertz, pg_fix angular_damping_ratio);
/** The joint's def as it is now. */
pg_result pg_weld_joint_get_def(const pg_world *world, pg_joint_id joint, pg_weld_joint_def *out);

/* ---- prismatic ---------------------------------------------------------------------------- */
/** Body B's anchor slides along local_axis_a (fixed in body A) through A's anchor; the
 * relative angle stays reference_angle. The translation is along the axis, m. */
typedef struct pg_prismatic_joint_def {
    pg_body_id body_a;            /**< one body: the axis turns with it */
    pg_body_id body_b;            /**< another body; not both static */
    pg_vec2 local_anchor_a;       /**< m, in body A's frame */
    pg_vec2 local_anchor_b;       /**< m, in body B's frame */
    pg_vec2 local_axis_a;         /**< in A's frame, any nonzero length (normalised); default (1, 0) */
    pg_angle reference_angle;     /**< default 0 */
    int enable_limit;             /**< nonzero: lower_translation <= translation <= upper_translation */
    pg_fix lower_translation;     /**< m, default 0 */
    pg_fix upper_translation;     /**< m, default 0 */
    int enable_motor;             /**< nonzero: drive the speed along the axis to motor_speed */
    pg_fix motor_speed;           /**< m/s, within +-1000; default 0 */
    pg_fix max_motor_force;       /**< N, >= 0; default 0 */
    int collide_connected;        /**< default 0 */
    uint64_t user_data;           /**< yours; saved in snapshots */
    uint32_t pg__cookie;          /**< internal: set by pg_default_prismatic_joint_def() */
} pg_prismatic_joint_def;
/** The default prismatic joint def: every prismatic joint def starts from here. */
pg_prismatic_joint_def pg_default_prismatic_joint_def(void);
/** Create a prismatic joint; *out receives its handle. */
pg_result pg_prismatic_joint_create(pg_world *world, const pg_prismatic_joint_def *def, pg_joint_id *out);
/** Translation limits on or off, m (within +-100, lower <= upper). */
pg_result pg_prismatic_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix lower, pg_fix upper);
/** The motor on or off: its speed along the axis (m/s, within +-1000) and its largest force (N, >= 0). */
pg_result pg_prismatic_joint_set_motor(pg_world *world, pg_joint_id joint, int enable, pg_fix motor_speed, pg_fix max_motor_force);
/** The translation along the axis now, m (0 for an invalid handle). */
pg_fix pg_prismatic_joint_translation(const pg_world *world, pg_joint_id joint);
/** The joint's def as it is now (the axis normalised). */
pg_result pg_prismatic_joint_get_def(const pg_world *world, pg_joint_id joint, pg_prismatic_joint_def *out);

/* ---- mouse --------------------------------------------------------------------------------- */
/** Pulls `body`'s anchor (the body point under `target` when the joint is made) toward
 * `target` as a spring of hertz and damping_ratio, with at most max_force. */
typedef struct pg_mouse_joint_def {
    pg_body_id body;              /**< a dynamic body */
    pg_vec2 target;               /**< world point, m, within +-1000 */
    pg_fix hertz;                 /**< Hz, (0, 1000]; default 5 */
    pg_fix damping_ratio;         /**< 0 .. 1000; default 0.7 */
    pg_fix max_force;             /**< N, >= 0; default 1000 */
    uint64_t user_data;           /**< yours; saved in snapshots */
    uint32_t pg__cookie;          /**< internal: set by pg_default_mouse_joint_def() */
} pg_mouse_joint_def;
/** The default mouse joint def: every mouse joint def starts from here. */
pg_mouse_joint_def pg_default_mouse_joint_def(void);
/** Create a mouse joint; *out receives its handle. */
pg_result pg_mouse_joint_create(pg_world *world, const pg_mouse_joint_def *def, pg_joint_id *out);
/** Move the target (world point within +-1000 m); wakes the body. */
pg_result pg_mouse_joint_set_target(pg_world *world, pg_joint_id joint, pg_vec2 target);
/** The spring: hertz in (0, 1000], damping ratio 0 .. 1000. */
pg_result pg_mouse_joint_set_spring(pg_world *world, pg_joint_id joint, pg_fix hertz, pg_fix damping_ratio);
/** The largest force, N (>= 0). */
pg_result pg_mouse_joint_set_max_force(pg_world *world, pg_joint_id joint, pg_fix max_force);
/** The joint's def as it is now (target is the current target). */
pg_result pg_mouse_joint_get_def(const pg_world *world, pg_joint_id joint, pg_mouse_joint_def *out);

/* ---- every kind ------------------------------------------------------------------------------ */
/** Destroy the joint (wakes its bodies). */
pg_result pg_joint_destroy(pg_world *world, pg_joint_id joint);
/** Nonzero when the handle names a joint of this world. */
int pg_joint_is_valid(const pg_world *world, pg_joint_id joint);
/** The joint's kind (PG_JOINT_TYPE_COUNT for an invalid handle). */
pg_joint_type pg_joint_type_of(const pg_world *world, pg_joint_id joint);
/** @{ */
/** The bodies (the zero handle for an invalid joint; a mouse joint's body is body B and
 * its body A the zero handle). */
pg_body_id pg_joint_body_a(const pg_world *world, pg_joint_id joint);
pg_body_id pg_joint_body_b(const pg_world *world, pg_joint_id joint);
/** @} */
/** Whether the joined bodies collide with each other (wakes them). */
pg_result pg_joint_set_collide_connected(pg_world *world, pg_joint_id joint, int collide);
/** Nonzero when the joined bodies collide with each other. */
int pg_joint_collide_connected(const pg_world *world, pg_joint_id joint);
/** Store a value of yours with the joint (saved in snapshots). */
pg_result pg_joint_set_user_data(pg_world *world, pg_joint_id joint, uint64_t user_data);
/** The value stored with the joint (0 for an invalid handle). */
uint64_t pg_joint_user_data(const pg_world *world, pg_joint_id joint);
/** Up to `capacity` joint handles of the body, in slot order; returns its joint count. */
uint32_t pg_body_joints(const pg_world *world, pg_body_id body, pg_joint_id *out, uint32_t capacity);

/** What a joint did in the last step: the force and torque it applied to body B at B's
 * anchor (body A got the opposite), averaged over the step. Q48.16 N and N m, as the
 * force accumulators. A breakable joint is user code: read this, and destroy the joint
 * when it is too large. */
typedef struct pg_joint_reaction {
    int64_t force_x; /**< N, Q48.16 */
    int64_t force_y; /**< N, Q48.16 */
    int64_t torque;           /**< N m, Q48.16 */
} pg_joint_reaction;
/** The joint's reaction now (zeros and PG_ERR_STALE_HANDLE for an invalid handle). */
pg_result pg_joint_get_reaction(const pg_world *world, pg_joint_id joint, pg_joint_reaction *out);

#ifdef __cplusplus
}
#endif
#endif
