/* joint_def.h (internal) — the checks every joint kind's create and setters share: the
 * bodies, the anchors, the softness, and taking a slot. Each check reports through
 * pg__fail (a failing call changes nothing). */
#ifndef POGON_SRC_JOINT_DEF_H
#define POGON_SRC_JOINT_DEF_H
#include "world_types.h"

/* Check two bodies and their anchors for a joint and fill j's bodies and anchors. `who`
 * names the function for messages ("pg_revolute_joint_create"). */
pg_result pg__joint_check_bodies(const pg_world *world, const char *who, pg_body_id a, pg_body_id b, pg_vec2 anchor_a,
                                 pg_vec2 anchor_b, pg_joint *j);
/* hertz 0 .. 1000 (zero allowed when allow_zero) and damping ratio 0 .. 1000 */
pg_result pg__joint_check_softness(const pg_world *world, pg_fix hertz, pg_fix damping_ratio, int allow_zero);
/* The joint a setter acts on, checked to be of `type`: NULL (and the failure in *r)
 * when the handle is stale or the kind differs. */
pg_joint *pg__joint_of_type(pg_world *world, pg_joint_id id, pg_joint_type type, const char *who, pg_result *r);
const pg_joint *pg__joint_of_type_const(const pg_world *world, pg_joint_id id, pg_joint_type type);
/* Set a joint's limit range or its motor, once its kind has checked the values (a
 * revolute's in radians, a prismatic's in metres): the flag, the values, the impulse of
 * a turned-off part back to 0, and its bodies woken. */
void pg__joint_store_limits(pg_world *world, pg_joint *j, int enable, pg_fix lower, pg_fix upper);
void pg__joint_store_motor(pg_world *world, pg_joint *j, int enable, pg_fix speed, pg_fix max_motor);
/* Take the lowest free slot for j (PG_ERR_CAPACITY when full) and write its handle. */
pg_result pg__joint_add(pg_world *world, const pg_joint *j, pg_joint_id *out);
/* A body slot's handle (the zero handle for PG_NULL_INDEX). */
pg_body_id pg__body_handle(const pg_world *world, uint32_t body);
/* The anchor's body-frame point relative to the body's centre of mass, turned to the
 * world frame by the body's rotation now. */
pg_vec2 pg__joint_world_lever(const pg_world *world, uint32_t body, pg_vec2 anchor);

#endif
