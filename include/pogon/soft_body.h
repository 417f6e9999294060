/** @file
 * pogon/soft_body.h — soft bodies made of ordinary bodies and joints: small circles
 * joined by distance springs (docs/soft-bodies.md). They need nothing from the solver
 * that other bodies and joints do not: every circle is a dynamic ball, every link a
 * pg_distance_joint, so they step, hash, snapshot and replay like anything else.
 *
 * HOW TO USE IT
 *     pg_soft_def sd = pg_default_soft_def();      // circles of 0.2 m, springs of 5 Hz
 *     pg_body_id centre;
 *     if (pg_make_soft_blob(world, &sd, pg_v2(0, PG_FIX_C(5)), PG_FIX_C(1), 12, &centre) != PG_OK)
 *         puts(pg_world_last_error(world));
 *
 * THE SHAPES
 *   blob         a centre circle and `count` circles on a ring around it; each ring
 *                circle is joined to the centre and to its two neighbours
 *   rope         `count` circles on a line, each joined to the next
 *   cloth strip  a grid of columns x rows circles, each joined to its right and upper
 *                neighbours and across both diagonals of each cell (shear)
 *
 * STIFFNESS AND DAMPING
 *   Each link is a distance joint of rest length its initial length, with the def's
 *   hertz and damping_ratio as a spring (pogon/joint.h): hertz is the frequency at which
 *   a link would oscillate with the masses it joins, damping_ratio 1 is critical. Hertz 0
 *   makes the links rigid rods. A blob of 12 circles with the defaults (5 Hz, ratio 0.7)
 *   keeps its area within the bound docs/soft-bodies.md gives.
 *
 * CONVENTIONS
 *   The bodies are made in order (the blob's centre first, then the ring from angle 0
 *   counter-clockwise; a rope from `start`; a cloth row by row from `origin`), taking
 *   the lowest free slots, then the joints. Everything is checked before anything is
 *   made (the def, the counts, the sizes, the positions, and the world's free body,
 *   shape and joint slots), so a failing call changes nothing. The first body made is
 *   written to *first (may be NULL); the rest follow it in creation order.
 */
#ifndef POGON_SOFT_BODY_H
#define POGON_SOFT_BODY_H

#include "pogon/joint.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What every circle and link of a soft body is made of. */
typedef struct pg_soft_def {
    pg_fix radius;         /**< each circle's radius, m: 0.05 .. 5; default 0.2 */
    pg_fix density;        /**< kg/m^2: 0.1 .. 100; default 1 */
    pg_fix friction;       /**< 0 .. 10; default 0.6 */
    pg_fix restitution;    /**< 0 .. 1; default 0 */
    pg_fix hertz;          /**< the links' spring frequency, Hz: 0 (rigid rods) .. 1000; default 5 */
    pg_fix damping_ratio;  /**< the links' damping ratio: 0 .. 1000; default 0.7 */
    uint32_t pg__cookie;   /**< internal: set by pg_default_soft_def() */
} pg_soft_def;
/** The defaults: circles of 0.2 m, density 1, friction 0.6, restitution 0; springs of
 * 5 Hz, damping ratio 0.7. Every soft def starts here. */
pg_soft_def pg_default_soft_def(void);

/** A blob: a centre circle at `centre` and `count` circles (3 .. 64) on a ring of
 * `ring_radius` m around it. The ring's neighbours must not overlap (their distance at
 * least twice the radius) nor the centre (ring_radius at least twice the radius).
 * Makes count + 1 bodies and shapes and 2 count joints; *first is the centre. */
pg_result pg_make_soft_blob(pg_world *world, const pg_soft_def *def, pg_vec2 centre, pg_fix ring_radius, uint32_t count,
                            pg_body_id *first);

/** A rope of `count` circles (2 .. 1024) from `start` to `end`, evenly spaced (the
 * spacing at least twice the radius, at most 100 m). Makes count bodies and shapes and
 * count - 1 joints; *first is the circle at `start` (pin it with a joint of your own). */
pg_result pg_make_rope(pg_world *world, const pg_soft_def *def, pg_vec2 start, pg_vec2 end, uint32_t count, pg_body_id *first);

/** A cloth strip of columns x rows circles (each 2 .. 64) from `origin` (its lower left
 * circle), `spacing` m apart (at least twice the radius, at most 50 m). Makes
 * columns x rows bodies and shapes and (columns - 1) rows + columns (rows - 1) +
 * 2 (columns - 1)(rows - 1) joints; *first is the circle at `origin`. */
pg_result pg_make_cloth_strip(pg_world *world, const pg_soft_def *def, pg_vec2 origin, pg_fix spacing, uint32_t columns,
                              uint32_t rows, pg_body_id *first);

#ifdef __cplusplus
}
#endif
#endif
