/* mass.h (internal) — mass, centre of mass and rotational inertia from geometry.
 *
 * Formats (also documented in pogon.h):
 *   mass      int64, Q32.32 kilograms
 *   inertia   int64, Q28.36 kg m^2, about the centre of mass
 *   area      int64, Q32.32 m^2
 * Densities are Q16.16 kg/m^2 (pogon is 2D: mass per area).
 * All arithmetic is exact integer arithmetic with 128-bit intermediates (wide.h) and
 * one rounding at the end, so results are the same bits on every platform.
 */
#ifndef POGON_SRC_MASS_H
#define POGON_SRC_MASS_H
#include "geom.h"

typedef struct pg_mass_data {
    int64_t mass;     /* Q32.32 kg */
    pg_vec2 center;   /* centre of mass in the geometry's frame, Q16.16 m */
    int64_t inertia;  /* Q28.36 kg m^2 about `center` */
    int64_t area;     /* Q32.32 m^2 */
} pg_mass_data;

/* Mass data of one convex geometry (circle, capsule, segment (zero area), polygon)
 * at a density. Exact for every kind: a capsule is a rectangle plus one full disc.
 * Its work space is on the stack (about 6 KiB): for tests and tools. */
pg_mass_data pg_geom_mass(const pg_geom *g, pg_fix density);

/* Bytes of the work space pg_compound_mass needs (the polygons whose overlaps it
 * measures, and clipping buffers): a few KiB, which a caller takes from memory it owns
 * (the world's scratch) rather than from the stack. */
size_t pg__mass_work_bytes(void);
/* An upper bound of pg__mass_work_bytes() for a buffer declared at compile time (mass.c
 * checks it). */
#define PG__MASS_WORK_BYTES 6144u

/* Mass data of a compound of `count` geometries (in one frame) with their densities,
 * combined with the parallel axis theorem. Regions where polygons (count >= 3)
 * overlap are counted once, with the density of the lowest-indexed polygon covering
 * them (inclusion-exclusion over the convex intersections). Circles, capsules and
 * segments are assumed not to overlap other shapes. `work`: pg__mass_work_bytes() bytes
 * aligned to 8, whose contents do not matter. */
pg_mass_data pg_compound_mass(const pg_geom *const *geoms, const pg_fix *densities, int count, void *work);

#endif
