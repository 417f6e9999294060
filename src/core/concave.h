/* concave.h (internal) — what concave.c gives world.c: the scratch a concave body needs. */
#ifndef POGON_SRC_CONCAVE_H
#define POGON_SRC_CONCAVE_H
#include <stddef.h>

/* Scratch bytes pg_make_concave needs between steps: the mass scratch
 * (pg__body_mass_scratch_bytes), then the polygon's decomposition and the refusal's text,
 * which outlive the mass computations. The world's solver scratch is never smaller
 * (world.c). A build without polygons needs the mass scratch only. */
size_t pg__concave_scratch_bytes(void);

#endif
