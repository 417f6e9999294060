/** @file
 * pogon/replay_file.h — replay files: a scene and the commands of every frame, with
 * state-hash checkpoints, in a versioned little-endian binary format.
 *
 * A replay file proves a run: it holds the initial scene (scene-file text, see
 * scene_file.h), then for every frame the commands applied before that frame's step,
 * a checkpoint (pg_world_hash and the per-section hashes) every N frames, the final
 * hash and checksums. Replaying it with the same engine reproduces every checkpoint
 * bit for bit. The layout is specified in docs/formats.md ("Replay files").
 *
 * WRITING (the caller feeds the run frame by frame, into a caller buffer)
 *     pg_replay_writer w;
 *     pg_replay_writer_begin(&w, buf, cap, scene_text, scene_len, 60);
 *     pg_replay_writer_add_checkpoint_world(&w, world);        // frame 0
 *     for each frame:
 *         pg_replay_writer_add_frame(&w, cmds, n);             // applied before the step
 *         (apply them, pg_world_step)
 *         if (pg_replay_writer_checkpoint_due(&w)) pg_replay_writer_add_checkpoint_world(&w, world);
 *     pg_replay_writer_finish(&w, pg_world_hash(world), &size);
 *   A call that does not fit returns PG_ERR_MEMORY and writes nothing: grow the buffer
 *   (copy the w.size bytes written so far), pg_replay_writer_set_buffer(), call again.
 *
 * READING
 *   pg_replay_read() validates a whole file from (pointer, length): structure, every
 *   command, the per-region hashes and the file checksum. It never reads outside
 *   [data, data + size) and reports the first problem as {offset, field, message}.
 *
 * PLAYING
 *   pg_replay_player_begin() loads the scene into a world in caller memory
 *   (pg_replay_world_memory_size bytes) and checks checkpoint 0; each
 *   pg_replay_player_step() applies one frame's commands, steps the world and compares
 *   the checkpoint that falls on the new frame, if any.
 *
 * Like the rest of the library this code is integer-only and never allocates.
 */
#ifndef POGON_REPLAY_FILE_H
#define POGON_REPLAY_FILE_H

#include "pogon/replay.h"
#include "pogon/scene_file.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PG_REPLAY_MAGIC "PGREPLAY"          /**< 8 bytes, no terminator in the file */
#define PG_REPLAY_FORMAT_VERSION 4u         /**< the format version this build writes and reads
                                                 (pg_replay_upgrade converts older ones) */
#define PG_REPLAY_HEADER_SIZE 44u           /**< fixed header, hash included */
#define PG_REPLAY_TRAILER_SIZE 29u          /**< the end record: tag, frames, final hash, block hash, checksum */
#define PG_REPLAY_MAX_SECTIONS 16u          /**< section hashes a checkpoint may carry */
#define PG_REPLAY_MAX_FRAME_COMMANDS 65535u /**< commands in one frame (u16 count) */

/** Record tags (one byte before each record). */
#define PG_REPLAY_TAG_FRAME 0x46u      /**< 'F' */
#define PG_REPLAY_TAG_CHECKPOINT 0x43u /**< 'C' */
#define PG_REPLAY_TAG_END 0x45u        /**< 'E' */

/* ---- errors ------------------------------------------------------------------------- */
/** Where and why a replay file was refused. */
typedef struct pg_replay_error {
    size_t offset;       /**< byte offset in the file where the problem is */
    const char *region;  /**< "header", "scene", "frame", "checkpoint", "end", "file"; "work" for a
                              caller's work area (the `_in` calls) (static) */
    const char *field;   /**< the field, e.g. "format_version", "command_count", "kind" (static) */
    int64_t frame;       /**< frame record the field belongs to, or -1 */
    int64_t command;     /**< command index within that frame, or -1 */
    char message[200];   /**< what is wrong, with the values involved */
} pg_replay_error;

/* ---- what a valid file holds --------------------------------------------------------- */
/** What a valid replay file holds (pg_replay_read()). */
typedef struct pg_replay_info {
    size_t size;                    /**< file size */
    uint32_t format_version;        /**< PG_REPLAY_FORMAT_VERSION of the writer */
    uint32_t engine_major;          /**< POGON_VERSION_MAJOR of the recorder */
    uint32_t engine_minor;          /**< POGON_VERSION_MINOR of the recorder */
    uint32_t engine_patch;          /**< POGON_VERSION_PATCH of the recorder */
    uint32_t flags;                 /**< 0 in format version 2 */
    uint32_t numeric_config;        /**< pg_numeric_config() of the recorder (config.h) */
    uint32_t checkpoint_interval;   /**< N: a checkpoint at frames 0, N, 2N, ... */
    uint32_t section_count;         /**< section hashes per checkpoint (PG_SECTION_COUNT when written) */
    const char *scene_text;         /**< points into the file; not NUL-terminated */
    size_t scene_size;              /**< bytes of scene text */
    size_t scene_offset;            /**< file offset of the scene text */
    size_t records_offset;          /**< file offset of checkpoint 0 */
    size_t end_offset;              /**< file offset of the end record */
    uint32_t frame_count;           /**< frame records (steps) */
    uint32_t checkpoint_count;      /**< frame_count / N + 1 */
    uint64_t command_count;         /**< commands in all frames */
    uint64_t kind_counts[PG_CMD_KIND_COUNT]; /**< commands per pg_command_kind */
    uint32_t max_frame_commands;    /**< most commands in one frame */
    uint64_t final_hash;            /**< pg_world_hash() after the last frame */
    uint64_t checksum;              /**< the whole file's checksum, as stored */
} pg_replay_info;

/** Validate a whole replay file. PG_OK fills *info; otherwise PG_ERR_INVALID_ARGUMENT
 * (PG_ERR_NULL for NULL pointers) and *error (may be NULL) describes the first problem.
 * The scene text is checked with pg_scene_read_def.
 * PG_ERR_INCOMPATIBLE: the file is not one this build can play, and *error says why:
 *   - another format version (info->format_version and size are set, the rest is 0): an
 *     older one converts with pg_replay_upgrade (`pogon-replay upgrade IN OUT`);
 *   - a sound file recorded with another numeric configuration (config.h; e.g.
 *     "recorded with a 12-bit sine table; this build has an 8-bit sine table"): *info is
 *     filled, so the file can be shown, but pg_replay_player_begin refuses it. */
pg_result pg_replay_read(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error);

/* ---- small stacks: a work area from the caller -------------------------------------- */
/** The calls that read the file's scene (pg_replay_read, pg_replay_world_memory_size,
 * pg_replay_player_begin, pg_replay_upgrade) put a work area of PG_REPLAY_WORK_BYTES on
 * their own stack: the scene reader's (pg_scene_work_size, scene_file.h) and what they
 * keep themselves. Their `_in` forms take it from the caller instead, for small stacks
 * (a microcontroller's): no frame on their path is then larger than a few hundred bytes
 * and the deepest call stays under 4 KiB on a 32-bit target (docs/embedded.md, "Stack").
 * Results, errors and messages are those of the plain calls.
 *
 * `work`: at least pg_replay_work_size() bytes, aligned to 8 (the alignment of uint64_t
 * on the targets pogon supports), whose contents do not matter; it is overwritten, and
 * nothing in it is needed after the call (a player does not keep it). A work area that
 * is NULL, misaligned or too small is refused with PG_ERR_INVALID_ARGUMENT and *error
 * (region "work", field "work_size", offset 0) naming the size needed, before anything
 * else is written; NULL pointers among the other arguments are still PG_ERR_NULL,
 * checked first. */
#define PG_REPLAY_WORK_BYTES (PG_SCENE_WORK_BYTES + 2048u) /**< an upper bound of pg_replay_work_size() */
/** Bytes of the work area the replay `_in` calls need: the scene reader's
 * (pg_scene_work_size) and what the replay calls keep. At most PG_REPLAY_WORK_BYTES. */
size_t pg_replay_work_size(void);
/** pg_replay_read with a work area from the caller (above). */
pg_result pg_replay_read_in(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error, void *work,
                            size_t work_size);

/** A checkpoint of a valid file, by index 0 .. checkpoint_count-1 (frame = index * N).
 * sections receives min(section_count, PG_SECTION_COUNT) hashes; the rest are zeroed. */
pg_result pg_replay_checkpoint(const uint8_t *data, const pg_replay_info *info, uint32_t index,
                               uint64_t *hash, uint64_t sections[PG_SECTION_COUNT]);

/** Convert a replay file of an older format version into this build's, stamping it with
 * `numeric_config` (pass pg_numeric_config(), and prove the stamp by playing the result:
 * pogon-replay upgrade does). The old file is checked first (its header, its checksums,
 * then the whole converted file with pg_replay_read); the records, hashes and engine
 * version are kept, so nothing recorded changes. A file already of this format version
 * is copied as it is. `out` must not overlap `data`. PG_ERR_MEMORY when `capacity` is
 * short: *out_size (may be NULL) then holds the size needed. PG_ERR_INVALID_ARGUMENT
 * and *error for a damaged file; PG_ERR_INCOMPATIBLE for a version this build does not
 * know. Format 1 had no numeric configuration; format 2 adds it after the flags;
 * format 3 adds the joint commands (its header is format 2's). */
pg_result pg_replay_upgrade(const uint8_t *data, size_t size, uint32_t numeric_config, uint8_t *out, size_t capacity,
                            size_t *out_size, pg_replay_error *error);
/** pg_replay_upgrade with a work area from the caller (pg_replay_read_in). */
pg_result pg_replay_upgrade_in(const uint8_t *data, size_t size, uint32_t numeric_config, uint8_t *out, size_t capacity,
                               size_t *out_size, pg_replay_error *error, void *work, size_t work_size);

/* ---- writer ------------------------------------------------------------------------- */
/** A replay file being written into caller memory (pg_replay_writer_begin()). */
typedef struct pg_replay_writer {
    uint8_t *buffer;                /**< the caller's buffer */
    size_t capacity;                /**< its size */
    size_t size;                    /**< bytes written so far */
    size_t block_start;             /**< start of the bytes the next block hash covers */
    uint32_t checkpoint_interval;   /**< N: a checkpoint every N frames */
    uint32_t frame_count;           /**< frame records written */
    uint32_t checkpoint_count;      /**< checkpoints written */
    int finished;                   /**< 1 after pg_replay_writer_finish() */
} pg_replay_writer;

/** Start a file in `buffer`: header and scene. checkpoint_interval >= 1. The next call
 * must add checkpoint 0 (the state after loading the scene). */
pg_result pg_replay_writer_begin(pg_replay_writer *w, uint8_t *buffer, size_t capacity, const char *scene_text,
                                 size_t scene_size, uint32_t checkpoint_interval);
/** Move to a larger buffer that already holds the w->size bytes written so far. */
pg_result pg_replay_writer_set_buffer(pg_replay_writer *w, uint8_t *buffer, size_t capacity);
/** 1 when the next call must be a checkpoint (frame count a multiple of N, not yet checkpointed). */
int pg_replay_writer_checkpoint_due(const pg_replay_writer *w);
/** The commands applied before the next step (count <= PG_REPLAY_MAX_FRAME_COMMANDS; 0 is fine).
 * PG_ERR_INVALID_ARGUMENT when a checkpoint is due or a command does not encode. */
pg_result pg_replay_writer_add_frame(pg_replay_writer *w, const pg_command *commands, uint32_t count);
/** The checkpoint that is due: the whole-state hash and PG_SECTION_COUNT section hashes.
 * PG_ERR_INVALID_ARGUMENT when the hash is not the one pg_world_hash makes of those
 * sections (FNV-1a of them, little-endian), which the reader checks. */
pg_result pg_replay_writer_add_checkpoint(pg_replay_writer *w, uint64_t hash, const uint64_t sections[PG_SECTION_COUNT]);
/** The checkpoint that is due, with the hashes of `world` as it is now. */
pg_result pg_replay_writer_add_checkpoint_world(pg_replay_writer *w, const pg_world *world);
/** The end record and the checksums; *size (may be NULL) receives the file size. */
pg_result pg_replay_writer_finish(pg_replay_writer *w, uint64_t final_hash, size_t *size);

/* ---- player ------------------------------------------------------------------------- */
/** Bytes of world memory the file's scene needs (pg_world_memory_size of its def). */
pg_result pg_replay_world_memory_size(const pg_replay_info *info, size_t *size, pg_replay_error *error);
/** pg_replay_world_memory_size with a work area from the caller (pg_replay_read_in). */
pg_result pg_replay_world_memory_size_in(const pg_replay_info *info, size_t *size, pg_replay_error *error, void *work,
                                         size_t work_size);

/** A replay file being played (pg_replay_player_begin()). */
typedef struct pg_replay_player {
    const uint8_t *data;           /**< the file */
    pg_replay_info info;           /**< what pg_replay_read() found in it */
    pg_world *world;               /**< the world it plays into */
    size_t cursor;                 /**< file offset of the next record */
    uint32_t frame;                /**< frames stepped */
    uint32_t checkpoints_checked;  /**< checkpoints compared so far */
    uint32_t command_failures;     /**< commands whose call failed (as they did when recorded) */
} pg_replay_player;

/** What one pg_replay_player_step did. */
typedef struct pg_replay_frame_result {
    uint32_t frame;               /**< the frame record played (the world is now at frame + 1) */
    size_t record_offset;         /**< its offset in the file (for pg_replay_apply_frame) */
    uint32_t command_count;       /**< commands in the frame */
    uint32_t command_failures;    /**< of them, those whose call failed */
    int checkpoint;               /**< 1 when a checkpoint fell on frame + 1 and was compared */
    uint32_t checkpoint_index;    /**< which checkpoint, when checkpoint is 1 */
    int match;                    /**< 1 when checkpoint is 0 or the checkpoint matched: its
                                     state hash and every section hash it stores */
    uint64_t expected_hash;       /**< the checkpoint's hash in the file */
    uint64_t actual_hash;         /**< the world's hash now */
    uint32_t section_mismatch;    /**< bit s set: section s differs (sections of this build) */
} pg_replay_frame_result;

/** Load the scene of a file validated by pg_replay_read into a new world in `memory`
 * (aligned to 8) and compare checkpoint 0 (*first, may be NULL, reports it; a mismatch
 * is not an error). Scene errors give PG_ERR_INVALID_ARGUMENT and *error; a file of
 * another numeric configuration PG_ERR_INCOMPATIBLE. */
pg_result pg_replay_player_begin(pg_replay_player *p, const uint8_t *data, const pg_replay_info *info, void *memory,
                                 size_t memory_size, pg_replay_frame_result *first, pg_replay_error *error);
/** pg_replay_player_begin with a work area from the caller (pg_replay_read_in); the
 * player does not keep it: pg_replay_player_step needs none. */
pg_result pg_replay_player_begin_in(pg_replay_player *p, const uint8_t *data, const pg_replay_info *info, void *memory,
                                    size_t memory_size, pg_replay_frame_result *first, pg_replay_error *error,
                                    void *work, size_t work_size);
/** 1 when every frame has been played. */
int pg_replay_player_done(const pg_replay_player *p);
/** Apply the next frame's commands, step, compare the checkpoint that falls on the new
 * frame. PG_ERR_INVALID_ARGUMENT when done. */
pg_result pg_replay_player_step(pg_replay_player *p, pg_replay_frame_result *out);
/** Apply the commands of the frame record at `record_offset` (from a frame result) to any
 * world: for re-simulation after a snapshot restore. Does not step. *applied and
 * *failures (each may be NULL) count the commands applied and those that failed (a
 * failing command changes nothing, as in pg_command_queue_apply_due); both are 0 when
 * the call fails. record_offset must be where one of the file's frame records starts
 * (checked, at the cost of reading the checkpoint block around it): any other offset (a
 * checkpoint, a byte inside a command, past the end) returns PG_ERR_INVALID_ARGUMENT
 * and changes nothing. Errors are explained in pg_world_last_error(world). */
pg_result pg_replay_apply_frame(pg_world *world, const uint8_t *data, const pg_replay_info *info, size_t record_offset,
                                uint32_t *applied, uint32_t *failures);

/** Compare a world with checkpoint `index`: returns 1 when the whole hash and every
 * stored section hash match; *section_mismatch (may be NULL) gets a bit per differing
 * section. 0 for a NULL argument or an index past the last checkpoint. */
int pg_replay_compare_checkpoint(const pg_world *world, const uint8_t *data, const pg_replay_info *info, uint32_t index,
                                 uint64_t *expected, uint64_t *actual, uint32_t *section_mismatch);

#ifdef __cplusplus
}
#endif
#endif
