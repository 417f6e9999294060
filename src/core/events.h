/* events.h (internal) — the contact begin and end events a step reports. */
#ifndef POGON_SRC_EVENTS_H
#define POGON_SRC_EVENTS_H
#include "contact_types.h"
#include "pogon/pogon.h"

/* Append an event for contact c; beyond max_contacts events in a step, the rest are dropped. */
void pg__push_begin_event(pg_world *world, const pg_contact *c);
void pg__push_end_event(pg_world *world, const pg_contact *c);

#endif
