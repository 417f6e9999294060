/* contact.h (internal) — the contact list: what the step and the editing calls ask of it. */
#ifndef POGON_SRC_CONTACT_H
#define POGON_SRC_CONTACT_H
#include "world_types.h"

/* Broadphase, narrowphase and the list's update for this step (begin and end events). */
pg_result pg__update_contacts(pg_world *world);
/* Whether shapes sa and sb may touch: different bodies, one dynamic, filters agree. */
int pg__shapes_should_collide(const pg_world *w, uint32_t sa, uint32_t sb);
void pg__remove_body_contacts(pg_world *world, uint32_t body_index);
void pg__refresh_contact_materials(pg_world *world, uint32_t body_index); /* after a friction/restitution change */

#endif
