/* chain.h (internal) — what chain.c gives the other files: the checks and segments of a
 * chain of points, for pg_make_chain and the scene reader. */
#ifndef POGON_SRC_CHAIN_H
#define POGON_SRC_CHAIN_H
#include "pogon/pogon.h"
#include "text.h"

/* Why pg_make_chain refuses these points (PG_OK: it does not), the reason, naming the
 * point or segment at fault, appended to *why. */
pg_result pg__chain_problem(const pg_vec2 *points, int32_t count, int loop, pg__text *why);
/* Chain segment i (from point i to the next) with its neighbours; the points passed
 * pg__chain_problem. */
void pg__chain_segment(const pg_vec2 *points, int32_t count, int loop, int32_t i, pg_geometry *out);

#endif
