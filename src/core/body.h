/* body.h (internal) — what body.c gives the other files: handles, mass, geometry sync
 * and the speed cap. */
#ifndef POGON_SRC_BODY_H
#define POGON_SRC_BODY_H
#include "geom.h"
#include "mass.h"
#include "speed_cap.h"
#include "world_types.h"

pg_body *pg__body(const pg_world *world, pg_body_id id); /* NULL if stale */
void pg__body_update_mass(pg_world *world, uint32_t body_index);
/* Scratch bytes the mass of a body needs between steps (pg_compound_mass's work space and
 * the list of a body's up to 65 geometries and densities): the world's solver scratch is
 * never smaller (world.c), so shape and body calls keep them off the stack. */
size_t pg__body_mass_scratch_bytes(void);
/* That work space for pg_compound_mass, in the world's scratch: valid between steps only */
void *pg__body_mass_work(const pg_world *world);
/* The list of up to 65 geometries and densities for pg_compound_mass, in the world's
 * scratch before the work space, for a caller that builds a compound of its own (a
 * concave body's pieces): valid between steps only */
void pg__body_mass_lists(const pg_world *world, const pg_geom ***geoms, pg_fix **densities);
/* inv_mass and inv_inertia from mass, inertia, type and fixed rotation: the one rule, for
 * pg__body_update_mass and for restoring a snapshot (which stores only mass and inertia) */
void pg__body_set_inverse_mass(pg_body *b);
/* round(2^(63 + e) / d) for d > 0, 0 <= e <= 31, as pg__div64_shl(2^(25 + e), d, 38) gives it */
int64_t pg__reciprocal_pow2(int e, int64_t d);
/* Why mass data cannot be a dynamic body's (its mass, inertia or their inverses leave
 * their formats), as a message for the user; NULL when it can. `rotates`: the body does
 * not have fixed rotation (only then is its inverse inertia used). */
const char *pg__mass_data_problem(pg_mass_data md, int rotates);
/* The same for body `body_index` with its shapes at `density` (0: each shape's own),
 * without shape slot `skip` (PG_NULL_INDEX: none), plus `extra` at `extra_density`. */
const char *pg__body_mass_problem(const pg_world *world, uint32_t body_index, pg_fix density, uint32_t skip,
                                  const pg_geom *extra, pg_fix extra_density, int rotates);
void pg__body_sync_geometry(pg_world *world, uint32_t body_index); /* world geoms + boxes */

#endif
