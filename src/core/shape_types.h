/* shape_types.h (internal) — a shape as the world stores it. */
#ifndef POGON_SRC_SHAPE_TYPES_H
#define POGON_SRC_SHAPE_TYPES_H
#include "pogon/pogon.h"
#include "geom.h"

typedef struct pg_shape {
    uint32_t generation;
    uint32_t used;
    uint32_t body;
    uint32_t next;           /* next shape of the same body */
    pg_geometry geometry;    /* as given, body frame */
    pg_geom local;           /* collision form, body frame */
    pg_fix density, friction, restitution;
    uint32_t category, mask;
    /* derived from `local` (pg__shape_set_extents), for continuous collision of turning
     * bodies: the farthest core vertex from local.centroid (0 for a circle) and the
     * thinnest extent, the centroid's distance to the nearest face plus the radius; 0 in
     * a build without continuous collision (PG_CONFIG_EFFECTS) */
    pg_fix turn_outer, inner_extent;
} pg_shape;

#endif
