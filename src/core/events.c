/* events.c — the contact begin and end events of the last step. */
#include "events.h"
#include "world_types.h"

static pg_contact_event make_event(const pg_world *world, const pg_contact *c)
{
    pg_contact_event e;
    e.shape_a.index = c->shape_a;
    e.shape_a.generation = world->shapes[c->shape_a].generation;
    e.shape_b.index = c->shape_b;
    e.shape_b.generation = world->shapes[c->shape_b].generation;
    e.body_a.index = c->body_a;
    e.body_a.generation = world->bodies[c->body_a].generation;
    e.body_b.index = c->body_b;
    e.body_b.generation = world->bodies[c->body_b].generation;
    return e;
}

/* Appends to one of the two lists, or counts the event as dropped (saturating). */
static void push(pg_world *world, pg_contact_event *events, uint32_t *count, const pg_contact *c)
{
    if (*count < pg__event_capacity(&world->def)) {
        events[(*count)++] = make_event(world, c);
    } else if (world->stats.events_dropped < UINT32_MAX) {
        world->stats.events_dropped += 1u;
    }
}

void pg__push_end_event(pg_world *world, const pg_contact *c)
{
    push(world, world->end_events, &world->end_count, c);
}

void pg__push_begin_event(pg_world *world, const pg_contact *c)
{
    push(world, world->begin_events, &world->begin_count, c);
}

const pg_contact_event *pg_world_begin_events(const pg_world *world, uint32_t *count)
{
    if (count != NULL) *count = world != NULL ? world->begin_count : 0;
    return world != NULL ? world->begin_events : NULL;
}

const pg_contact_event *pg_world_end_events(const pg_world *world, uint32_t *count)
{
    if (count != NULL) *count = world != NULL ? world->end_count : 0;
    return world != NULL ? world->end_events : NULL;
}
