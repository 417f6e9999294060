/* solver.h (internal) — the step's solve: forces, constraints, integration. */
#ifndef POGON_SRC_SOLVER_H
#define POGON_SRC_SOLVER_H
#include "world_types.h"

size_t pg__solver_scratch_bytes(const pg_world_def *def);
void pg__solve(pg_world *world);

#endif
