/* collide.h (internal) — contact manifolds between two convex geometries (geom.h), and
 * the overlap and containment tests that are decided by them. */
#ifndef POGON_SRC_COLLIDE_H
#define POGON_SRC_COLLIDE_H
#include "geom.h"

typedef struct pg_manifold_point {
    pg_vec2 point;       /* world position, midway between the two surfaces */
    pg_fix separation;   /* signed distance along the normal; negative means overlap */
    uint32_t id;         /* feature key: the same while the same features touch */
} pg_manifold_point;

typedef struct pg_manifold {
    pg_dir normal;       /* unit, Q2.30, pointing from shape A to shape B */
    pg_manifold_point points[2];
    int32_t count;       /* 0, 1 or 2 */
} pg_manifold;

/* The contact manifold of a and b: the points whose separation is at most
 * `speculative` (>= 0) are reported. count == 0 when they are farther apart. */
void pg_collide(const pg_geom *a, const pg_geom *b, pg_fix speculative, pg_manifold *out);

/* The manifold of a chain segment against another geometry (not a chain segment): seg
 * is the placed segment (count 2; it collides on the side of normals[0], the right of
 * vertices[0] -> vertices[1]), before and after its neighbours in the same frame (NULL
 * where the chain ends). Normals outside the cone the neighbours allow at a joint are
 * left to the neighbour or replaced by the face normal, so a body sliding across a
 * joint meets no corner. The normal points from the segment to `other`. */
void pg_collide_chain(const pg_geom *seg, const pg_vec2 *before, const pg_vec2 *after, const pg_geom *other, pg_fix speculative,
                      pg_manifold *out);

/* Signed distance-style overlap test used by queries: nonzero when a and b overlap
 * (separation < 0). */
int pg_geom_overlap(const pg_geom *a, const pg_geom *b);

/* Does the geometry contain the point (radius included)? */
int pg_geom_contains(const pg_geom *g, pg_vec2 p);

#endif
