/* world_internal.h (internal) — every internal header at once, for the files that sit
 * on top of the step (state.c, replay_file.c, scene_file.c, command.c) and for tests.
 * A file the step runs must include only the headers it uses: including this one from
 * such a file makes a cycle, which scripts/check-layers.sh reports
 * (docs/architecture.md). */
#ifndef POGON_SRC_WORLD_INTERNAL_H
#define POGON_SRC_WORLD_INTERNAL_H
#include "body.h"
#include "collide.h"
#include "contact.h"
#include "continuous.h"
#include "def_cookie.h"
#include "envelope.h"
#include "error.h"
#include "events.h"
#include "geom.h"
#include "island.h"
#include "joint_def.h"
#include "joint_pool.h"
#include "mass.h"
#include "raycast.h"
#include "reach.h"
#include "shape.h"
#include "solver.h"
#include "world_types.h"

/* The parts of a world's memory block for `def` (world.c): the name of part i and, in
 * *bytes, its size with alignment; NULL (and 0) past the last part or for a def
 * pg_world_memory_size refuses. For tools/size (docs/embedded.md's RAM table). */
const char *pg__world_memory_part(const pg_world_def *def, unsigned i, size_t *bytes);
#endif
