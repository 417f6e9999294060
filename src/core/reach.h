/* reach.h (internal) — what reach.c gives the other files: the envelope's reach of a
 * shape, which depends on the type of the body it is on (docs/envelope.md). */
#ifndef POGON_SRC_REACH_H
#define POGON_SRC_REACH_H
#include "pogon/pogon.h"

/* How far geometry g reaches from its body's origin: the largest |x| or |y| of its
 * vertices (a circle's centre). A body of type `type` takes shapes that reach at most
 * pg__body_reach_limit(type): PG_ENV_MAX_SIZE for a dynamic or kinematic body,
 * PG_ENV_MAX_STATIC_REACH for a static one. pg__fail_reach reports a shape past it. */
pg_fix pg__geometry_reach(const pg_geometry *g);
pg_fix pg__body_reach_limit(pg_body_type type);
pg_result pg__fail_reach(const pg_world *world, pg_fix reach, pg_body_type type);

#endif
