/* replay_file_internal.h — what replay_file.c shares with replay_upgrade.c: the work
 * area of the replay calls that read a scene (pg_replay_work_size, pogon/replay_file.h).
 *
 * These calls sit above the scene reader's deepest chain (a body made in a world, by
 * pg_shape_create or pg_make_concave, and its mass), so what they keep lives in the
 * caller's work area, not in their frames (docs/embedded.md, "Stack"). */
#ifndef POGON_SRC_REPLAY_FILE_INTERNAL_H
#define POGON_SRC_REPLAY_FILE_INTERNAL_H
#include "pogon/replay_file.h"
#include "pogon/scene_file.h"

/* The replay calls' own part of the work area; the scene reader's work area
 * (pg_scene_work_size() bytes) follows it, at its size rounded up to 8. */
typedef struct pg__replay_work {
    pg_replay_info upgrade_info;   /* pg_replay_upgrade: what the reader found in the converted file */
    pg_replay_error upgrade_error; /* pg_replay_upgrade: the reader's error, before its offset is mapped back */
    pg_replay_info info;           /* pg_replay_read: the file's description until the scene is checked */
    pg_scene_error scene_error;    /* the scene reader's error, before it names a file offset */
    pg_world_def def;              /* the scene's world settings */
    size_t upgrade_size;           /* pg_replay_upgrade: the converted file's size */
    uint32_t upgrade_version;      /* pg_replay_upgrade: the old file's format version */
} pg__replay_work;

/* The replay part of `work`, or NULL after *error (may be NULL) names the size and
 * alignment needed (region "work"). */
pg__replay_work *pg__replay_work_in(void *work, size_t work_size, pg_replay_error *error);

/* pg_replay_read_in on a work area pg__replay_work_in accepted. */
pg_result pg__replay_read(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error,
                          pg__replay_work *w);

#endif
