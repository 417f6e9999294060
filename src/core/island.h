/* island.h (internal) — sleeping and waking. */
#ifndef POGON_SRC_ISLAND_H
#define POGON_SRC_ISLAND_H
#include "world_types.h"

/* Before the solve: where each active body starts the step, from which the sleep test
 * measures how far it moves. */
void pg__note_step_start(pg_world *world);
/* After the solve: bodies at rest long enough fall asleep, island by island. */
void pg__update_sleep(pg_world *world);
/* Before a step: wake a dynamic body joined to an awake one (a joint made while one
 * slept, a body put to sleep by hand), so no joint pulls on a sleeping body. */
void pg__wake_joined_bodies(pg_world *world);
/* Wake body_index and the island it sleeps in. */
void pg__wake_body(pg_world *world, uint32_t body_index);

#endif
