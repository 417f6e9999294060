/* joint_scenes.h — the joint benchmark scenes, joint_grid and chain, built in code.
 * The peers' harnesses (tools/bench/box2d_harness.cpp, chipmunk_harness.c) rebuild them
 * from the same integers; docs/performance.md says what each measures.
 *
 *   joint_grid N  (default 40) N x N circles of radius 0.4 m (26214 / 65536), 1 m apart:
 *                 column c, row k at (c, -k) m. Row 0 is static (the pins); every body
 *                 below it is dynamic, density 1, joined by a revolute joint to the body
 *                 above it (anchors (0, -0.5) and (0, 0.5)) and, from column 1 on, to the
 *                 body on its left (anchors (0.5, 0) and (-0.5, 0)): N (N - 1) bodies and
 *                 (2N - 1)(N - 1) joints. The grid starts at rest in its hanging shape, so
 *                 a rigid solver keeps it there; the sanity figure is the sag, how far the
 *                 bottom row came down.
 *   chain N       (default 20) N chains of 40 links. A link is a capsule, 1 m between its
 *                 cap centres, radius 0.125 m, density 1. Chain j starts horizontal:
 *                 link i centred at (2 j + i + 0.5, 2 j) m, joined to the next link at the
 *                 cap centres ((0.5, 0) and (-0.5, 0)); link 0 is pinned by a revolute
 *                 joint to a static body without shapes at (2 j, 2 j): the pins step up
 *                 and across, so the chains start 2 m apart and hang 2 m apart. The
 *                 chains fall and swing, undamped, for the whole run. The sanity figure is the stretch: the sum over a
 *                 chain's 40 joints of the distance between the two anchors (0 for a
 *                 rigid chain), the largest over the chains.
 * In both, every shape has category 2 and mask ~2, so nothing collides: the broadphase
 * still finds the pairs whose boxes overlap and the filter drops them, as in the peers,
 * but the scenes time joints, not contacts. Gravity 10 m/s^2
 * down, 1/60 s steps, 4 substeps, and sleeping off (the scenes time awake joints).
 */
#ifndef POGON_TOOLS_JOINT_SCENES_H
#define POGON_TOOLS_JOINT_SCENES_H
#include "pogon/pogon.h"

/* Kept apart from scenes.c, which the cross-compiled targets build without floating
 * point: the sanity figures here are reported in double. */
typedef struct pg_joint_scene {
    pg_world *world;
    pg_body_id first;     /* the first body of the grid or of the first chain; the others
                             follow it in consecutive slots (checked when they are made) */
    uint32_t body_count;  /* dynamic bodies */
    uint32_t joint_count;
} pg_joint_scene;

/* Nonzero for "joint_grid" and "chain". */
int pg_is_joint_scene(const char *name);

/* The scene's default count (joint_grid: 40 columns and rows; chain: 20 chains). */
uint32_t pg_joint_scene_default_count(const char *name);

/* Capacities for the scene and its settings: sleeping off, the rest pogon's defaults. */
pg_world_def pg_joint_scene_world_def(const char *name, uint32_t count);

/* Bytes pg_joint_scene_build needs. */
size_t pg_joint_scene_memory_size(const char *name, uint32_t count, const pg_world_def *def);

/* Build scene `name` with `count` (0: the default) into a world created in `memory`; `def`
 * may be NULL for pg_joint_scene_world_def, and its capacities are raised to what the
 * scene needs. Returns PG_OK or the first error. */
pg_result pg_joint_scene_build(const char *name, uint32_t count, const pg_world_def *def, void *memory, size_t memory_size,
                               pg_joint_scene *out);

/* The scene's sanity figure now, m (the grid's sag, the chains' stretch) and the largest
 * single anchor gap, m. Returns 0 when `sc` is not a built joint scene. */
typedef struct pg_joint_sanity {
    const char *figure;  /* "sag" or "stretch" */
    double value_m;      /* the figure */
    double worst_gap_m;  /* the largest distance between a joint's two anchors */
} pg_joint_sanity;
int pg_joint_scene_sanity(const char *name, uint32_t count, const pg_joint_scene *sc, pg_joint_sanity *out);

#endif
