/* events.h (internal) — the contact begin and end events a step reports. */
#ifndef POGON_SRC_EVENTS_H
#define POGON_SRC_EVENTS_H
#include "contact_types.h"
#include "pogon/pogon.h"

/* How many begin events, and apart end events, a world with this def keeps per step
 * (pg_world_def.max_contact_events; PG_EVENTS_AS_CONTACTS is max_contacts). */
static inline uint32_t pg__event_capacity(const pg_world_def *def)
{
    return def->max_contact_events == PG_EVENTS_AS_CONTACTS ? def->max_contacts : def->max_contact_events;
}

/* Append an event for contact c; past the capacity in a step, the rest are counted in
 * stats.events_dropped. */
void pg__push_begin_event(pg_world *world, const pg_contact *c);
void pg__push_end_event(pg_world *world, const pg_contact *c);

#endif
