/* replay_seek.h — play a replay file forward and jump to any frame, for every front end.
 *
 * WHAT IT IS
 *   A replay player that can go back. While it plays it keeps a snapshot of the world
 *   every PGA_SEEK_SNAPSHOT_INTERVAL frames (pg_world_snapshot_save). A jump restores the
 *   nearest snapshot at or before the target and steps forward from there, applying each
 *   frame's commands with pg_replay_apply_frame; a target beyond the frames played so far
 *   is reached by playing on (keeping snapshots on the way). Every checkpoint the world
 *   passes is compared with the file, and the result is kept per checkpoint.
 *
 *   A jump is done in slices (pga_seek_advance) so that a front end can draw a progress
 *   bar between them; nothing here calls back into the caller.
 *
 * HOW TO USE IT
 *     pga_seek *s;
 *     char why[256];
 *     if (pga_seek_open(data, size, &s, why, sizeof why) != PG_OK) { show(why); ... }
 *     per display frame:
 *         if (playing) pga_seek_step(s);
 *         or: pga_seek_jump(s, target); then pga_seek_advance(s, 2000) until it returns 1
 *         draw pga_seek_world(s), show pga_seek_status(s)
 *     pga_seek_close(s);
 *
 * It allocates with malloc (a front end's helper, not the core) and copies the file.
 */
#ifndef PGA_REPLAY_SEEK_H
#define PGA_REPLAY_SEEK_H

#include <stddef.h>
#include <stdint.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pogon/replay_file.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Frames between kept snapshots: 5 s at 60 Hz. A jump re-steps at most this many frames
 * once the target has been played through. */
#define PGA_SEEK_SNAPSHOT_INTERVAL 300u

typedef struct pga_seek pga_seek;

typedef struct pga_seek_status {
    uint32_t frame;                  /* frames stepped: the world is at this frame */
    uint32_t frame_count;            /* frames in the file */
    uint32_t played;                 /* the furthest frame reached so far */
    uint32_t checkpoint_count;       /* checkpoints in the file */
    uint32_t checkpoints_checked;    /* distinct checkpoints compared so far */
    uint32_t checkpoints_failed;     /* of those, how many diverged */
    int last_match;                  /* latest checkpoint the world passed: 1 matched, 0 diverged, -1 none */
    uint32_t last_checkpoint_frame;  /* its frame */
    uint32_t last_section_mismatch;  /* bit s: section s differed at it (pg_section) */
    int64_t first_failed_frame;      /* frame of the earliest diverged checkpoint, or -1 */
    uint32_t first_failed_sections;  /* its differing sections */
    int seeking;                     /* a jump is in progress */
    uint32_t seek_from, seek_target; /* the frame the jump re-steps from, and its target */
    uint32_t snapshots;              /* snapshots kept */
    size_t snapshot_bytes;           /* their total size */
} pga_seek_status;

/* Validate `data` (pg_replay_read), copy it, load its scene and compare checkpoint 0.
 * On failure *out is NULL and `message` (capacity `message_capacity`, may be 0) holds
 * the reader's report: offset, region, field and what is wrong. */
pg_result pga_seek_open(const uint8_t *data, size_t size, pga_seek **out, char *message, size_t message_capacity);
void pga_seek_close(pga_seek *s);

const pg_world *pga_seek_world(const pga_seek *s);
const pg_replay_info *pga_seek_info(const pga_seek *s);
pga_seek_status pga_seek_get_status(const pga_seek *s);

/* One frame forward (ends a jump in progress first). Returns 1 when the world stepped,
 * 0 at the last frame. */
int pga_seek_step(pga_seek *s);
/* Start a jump to frame `target` (0 .. frame_count): restores the nearest kept snapshot
 * when that is closer than the current frame. PG_ERR_INVALID_ARGUMENT beyond the end. */
pg_result pga_seek_jump(pga_seek *s, uint32_t target);
/* Step the jump in progress by up to `max_frames` frames; 1 when the target is reached
 * (or no jump is in progress), 0 when more slices are needed. */
int pga_seek_advance(pga_seek *s, uint32_t max_frames);

/* The first message of a failure inside the engine (a snapshot that did not restore), or "". */
const char *pga_seek_error(const pga_seek *s);

#ifdef __cplusplus
}
#endif
#endif
