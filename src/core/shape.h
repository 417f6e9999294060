/* shape.h (internal) — what shape.c gives the other files. */
#ifndef POGON_SRC_SHAPE_H
#define POGON_SRC_SHAPE_H
#include "geom.h"
#include "world_types.h"

pg_shape *pg__shape(const pg_world *world, pg_shape_id id); /* NULL if stale */
void pg__shape_build_local(const pg_geometry *g, pg_geom *out); /* collision form of a geometry */
pg_result pg__validate_geometry(const pg_geometry *g);             /* what pg_shape_create accepts */
/* The shape def's checks for a body of `type` (reported in the world's last error). */
pg_result pg__check_shape_def(const pg_world *world, pg_body_type type, const pg_shape_def *d);
/* Put a shape, checked by the caller, into free slot i and onto body `body`'s list. The
 * caller updates the body's mass, geometry and sleep. */
void pg__shape_attach(pg_world *world, uint32_t body, uint32_t i, const pg_shape_def *def, const pg_geometry *geometry);

/* Whether this build keeps g's kind (PG_CONFIG_SHAPES, pogon/config.h; a polygon's kind
 * is its vertex count: 4 a box, else a polygon), and the message of a kind it leaves
 * out (`who` a string literal). */
int pg__shape_kind_kept(const pg_geometry *g);
#define PG__LEFT_OUT_KIND(who) who ": this build leaves this shape kind out (PG_CONFIG_SHAPES in pogon/config.h): build the library with its PG_SHAPES_* bit"

#endif
