/* scenes.h — the named benchmark and test scenes, built in code.
 * Shared by pogon-bench and the stability tests so both measure the same worlds. */
#ifndef POGON_TOOLS_SCENES_H
#define POGON_TOOLS_SCENES_H
#include "pogon/pogon.h"

typedef struct pg_scene {
    pg_world *world;
    pg_body_id top;       /* the body whose displacement says whether the scene stands */
    pg_vec2 top_start;
    uint32_t body_count;
} pg_scene;

/* Capacities a scene of `count` bodies needs. */
pg_world_def pg_scene_world_def(const char *name, uint32_t count);

/* Build scene `name` ("pyramid", "stack", "rain", "heap") with `count` (rows for pyramid,
 * boxes for stack, circles for rain, circles and boxes for heap; 0 = the default: 20, 20,
 * 1000, 4000) into a world created
 * in `memory`. `def` may be NULL for the scene's defaults; its capacities are raised to
 * what the scene needs. Returns PG_OK or the first error. */
pg_result pg_scene_build(const char *name, uint32_t count, const pg_world_def *def, void *memory, size_t memory_size, pg_scene *out);

/* Bytes pg_scene_build needs for that scene. */
size_t pg_scene_memory_size(const char *name, uint32_t count, const pg_world_def *def);

#endif
