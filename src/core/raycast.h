/* raycast.h (internal) — a ray against one convex geometry. */
#ifndef POGON_SRC_RAYCAST_H
#define POGON_SRC_RAYCAST_H
#include "geom.h"

/* Ray cast against one geometry: origin p, direction d (any length, not zero),
 * maximum fraction max_t of d (Q16.16, e.g. PG_FIX_ONE for the segment p..p+d).
 * Returns nonzero on a hit with the fraction *t, the point and the outward normal. */
int pg_geom_raycast(const pg_geom *g, pg_vec2 p, pg_vec2 d, pg_fix max_t, pg_fix *t, pg_vec2 *point, pg_dir *normal);

#endif
