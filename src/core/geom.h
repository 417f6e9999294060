/* geom.h (internal) — convex geometry as the narrowphase sees it: placing, bounding
 * boxes (collide.h: manifolds and overlap tests; raycast.h: ray casts).
 *
 * Every primitive is a convex polygon of 1 to PG_MAX_POLYGON_VERTICES vertices with a
 * radius (the Minkowski sum of the polygon and a disc):
 *   circle   count 1, radius r           segment  count 2, radius 0
 *   capsule  count 2, radius r           polygon  count 3..8 (box, triangle, ...), radius 0
 * Vertices wind counter-clockwise. normals[i] is the outward unit normal of the edge
 * vertices[i] -> vertices[(i+1) % count]; for count 2 that gives normals[1] == -normals[0];
 * for count 1 the normals are unused.
 */
#ifndef POGON_SRC_GEOM_H
#define POGON_SRC_GEOM_H
#include "pogon/fixed.h"

#define PG_MAX_POLYGON_VERTICES 8

/* A unit direction in Q2.30 (1.0 == 2^30). */
typedef struct pg_dir { int32_t x, y; } pg_dir;

typedef struct pg_geom {
    pg_vec2 vertices[PG_MAX_POLYGON_VERTICES];
    pg_dir normals[PG_MAX_POLYGON_VERTICES];
    pg_vec2 centroid; /* of the polygon's area (or of the vertices for count < 3) */
    pg_fix radius;
    int32_t count;
} pg_geom;

/* Unit vector along (x, y) in Q2.30, exact to about 1 LSB of Q30; zero gives zero. */
pg_dir pg_dir_normalize(int64_t x, int64_t y);

/* Place one point as pg_geom_transform places a vertex (a chain segment's neighbours). */
pg_vec2 pg_geom_place_point(pg_vec2 local, pg_vec2 position, pg_rot rotation);

/* Place a local geometry with a body's transform: world = position + R local. */
void pg_geom_transform(const pg_geom *local, pg_vec2 position, pg_rot rotation, pg_geom *world);
/* The same into a world's per-shape slot, which is always initialised (zero at world
 * creation, then placed): entries beyond the count are cleared only where the slot
 * held more vertices before. */
void pg__geom_place_slot(const pg_geom *local, pg_vec2 position, pg_rot rotation, pg_geom *slot);

/* The bounding box of a placed geometry, radius included. */
pg_aabb pg_geom_aabb(const pg_geom *g);

/* Whether p lies strictly behind the face normals[0] of a segment (two vertices, as a
 * chain segment is placed): its back side, where a one-sided chain segment is not
 * solid. A point on the segment's line is not behind. */
int pg_geom_behind_segment(const pg_geom *g, pg_vec2 p);
/* Whether p lies strictly in front of it (a point on the line is neither). */
int pg_geom_in_front_of_segment(const pg_geom *g, pg_vec2 p);

#endif
