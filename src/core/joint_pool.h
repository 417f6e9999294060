/* joint_pool.h (internal) — the joint pool and the bodies' joint lists: handles, slots,
 * linking, and what the other stages ask of them (which bodies are joined, destroying a
 * body's joints). The kinds and the solver sit above it (joint.c). */
#ifndef POGON_SRC_JOINT_POOL_H
#define POGON_SRC_JOINT_POOL_H
#include "world_types.h"

/* A handle's joint, or NULL when the handle is stale or out of range. */
pg_joint *pg__joint(const pg_world *world, pg_joint_id id);
/* The lowest free slot (a pure function of the state), or PG_NULL_INDEX when full. */
uint32_t pg__joint_free_slot(const pg_world *world);
/* Put a filled-in joint in slot `slot`: its generation advances, it joins its bodies'
 * lists, the count grows and its bodies wake. Returns its handle. */
pg_joint_id pg__joint_insert(pg_world *world, uint32_t slot, const pg_joint *joint);
/* Remove joint slot j (wakes its bodies). */
void pg__joint_remove(pg_world *world, uint32_t j);
/* Remove every joint of body slot b (pg_body_destroy). */
void pg__joints_remove_of_body(pg_world *world, uint32_t b);
/* The next joint in body b's list after joint j. */
uint32_t pg__joint_next_of_body(const pg_world *world, uint32_t j, uint32_t b);
/* Nonzero when a joint without collide_connected joins body slots a and b. */
int pg__joint_blocks_collision(const pg_world *world, uint32_t a, uint32_t b);
/* Why body slot b may not become `type` (NULL when it may): the joints' creation rules
 * (one body that can move; a mouse joint's body dynamic) hold for as long as they live,
 * so that every world can be written as a scene and read back. */
const char *pg__joint_type_change_problem(const pg_world *world, uint32_t b, pg_body_type type);
/* Rebuild every body's joint list from the pool (after a restore). */
void pg__joint_rebuild_lists(pg_world *world);
/* Wake the joint's bodies (those that are not static). */
void pg__joint_wake(pg_world *world, const pg_joint *joint);

#endif
