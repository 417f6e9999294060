/* shape.h (internal) — what shape.c gives the other files. */
#ifndef POGON_SRC_SHAPE_H
#define POGON_SRC_SHAPE_H
#include "geom.h"
#include "world_types.h"

pg_shape *pg__shape(const pg_world *world, pg_shape_id id); /* NULL if stale */
void pg__shape_build_local(const pg_geometry *g, pg_geom *out); /* collision form of a geometry */
pg_result pg__validate_geometry(const pg_geometry *g);             /* what pg_shape_create accepts */

#endif
