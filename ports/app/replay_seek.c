/* replay_seek.c — a replay player with snapshots for jumping (see replay_seek.h).
 *
 * Two ways forward share one world: up to the furthest frame played ("played") the
 * offsets of the frame records are known and pg_replay_apply_frame re-applies them after
 * a snapshot restore; at the furthest frame the pg_replay_player plays on, which also
 * learns the next record's offset and keeps a snapshot every PGA_SEEK_SNAPSHOT_INTERVAL
 * frames. Both compare each checkpoint they pass.
 */
#include "replay_seek.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct seek_snapshot {
    void *data;
    size_t size;
} seek_snapshot;

struct pga_seek {
    uint8_t *file;
    pg_replay_info info;
    void *world_memory;
    pg_replay_player player;          /* its world is the one shown; its cursor is at `played` */
    uint32_t frame;                   /* the world's frame */
    size_t *record_offsets;           /* [frame] offset of that frame's record, known below `played` */
    seek_snapshot *snapshots;         /* [frame / interval], kept up to `played` */
    uint32_t snapshot_slots;
    signed char *checkpoint_match;    /* [checkpoint] -1 not compared, 0 diverged, 1 matched */
    uint32_t *checkpoint_sections;    /* [checkpoint] differing sections */
    pga_seek_status status;
    char error[200];
};

static void note_checkpoint(pga_seek *s, uint32_t index, int match, uint32_t sections)
{
    if (index >= s->info.checkpoint_count) return;
    if (s->checkpoint_match[index] < 0) {
        s->status.checkpoints_checked++;
        if (!match) s->status.checkpoints_failed++;
    } else if (s->checkpoint_match[index] != (match ? 1 : 0)) {
        /* The same checkpoint compared differently on a second pass: re-stepping is not
         * deterministic. Count it as a failure so that it cannot go unseen. */
        if (!match) s->status.checkpoints_failed++;
    }
    if (!match && (s->status.first_failed_frame < 0 ||
                   (int64_t)index * s->info.checkpoint_interval < s->status.first_failed_frame)) {
        s->status.first_failed_frame = (int64_t)index * s->info.checkpoint_interval;
        s->status.first_failed_sections = sections;
    }
    s->checkpoint_match[index] = (signed char)(match ? 1 : 0);
    s->checkpoint_sections[index] = sections;
    s->status.last_match = match ? 1 : 0;
    s->status.last_checkpoint_frame = index * s->info.checkpoint_interval;
    s->status.last_section_mismatch = sections;
}

static int keep_snapshot(pga_seek *s)
{
    uint32_t slot = s->frame / PGA_SEEK_SNAPSHOT_INTERVAL;
    size_t need, written = 0;
    void *buf;
    if (s->frame % PGA_SEEK_SNAPSHOT_INTERVAL != 0u || slot >= s->snapshot_slots || s->snapshots[slot].data != NULL)
        return 1;
    need = pg_world_snapshot_size(s->player.world);
    buf = malloc(need != 0 ? need : 1);
    if (buf == NULL) {
        snprintf(s->error, sizeof s->error, "out of memory keeping a snapshot of %zu bytes at frame %u", need, s->frame);
        return 0;
    }
    if (pg_world_snapshot_save(s->player.world, buf, need, &written) != PG_OK) {
        snprintf(s->error, sizeof s->error, "snapshot at frame %u: %s", s->frame, pg_world_last_error(s->player.world));
        free(buf);
        return 0;
    }
    s->snapshots[slot].data = buf;
    s->snapshots[slot].size = written;
    s->status.snapshots++;
    s->status.snapshot_bytes += written;
    return 1;
}

static void free_all(pga_seek *s)
{
    uint32_t i;
    if (s == NULL) return;
    if (s->snapshots != NULL)
        for (i = 0; i < s->snapshot_slots; ++i) free(s->snapshots[i].data);
    free(s->snapshots);
    free(s->record_offsets);
    free(s->checkpoint_match);
    free(s->checkpoint_sections);
    free(s->world_memory);
    free(s->file);
    free(s);
}

pg_result pga_seek_open(const uint8_t *data, size_t size, pga_seek **out, char *message, size_t message_capacity)
{
    pg_replay_error err;
    pg_replay_frame_result first;
    size_t memory_size = 0;
    pga_seek *s;
    pg_result r;
    uint32_t i;
    char scratch[1];
    if (message == NULL || message_capacity == 0) {
        message = scratch;
        message_capacity = sizeof scratch;
    }
    message[0] = '\0';
    if (out == NULL) return PG_ERR_NULL;
    *out = NULL;
    if (data == NULL && size != 0) return PG_ERR_NULL;
    s = (pga_seek *)calloc(1, sizeof *s);
    if (s == NULL) {
        snprintf(message, message_capacity, "out of memory");
        return PG_ERR_MEMORY;
    }
    s->file = (uint8_t *)malloc(size != 0 ? size : 1);
    if (s->file == NULL) {
        free_all(s);
        snprintf(message, message_capacity, "out of memory copying a file of %zu bytes", size);
        return PG_ERR_MEMORY;
    }
    if (size != 0) memcpy(s->file, data, size);
    r = pg_replay_read(s->file, size, &s->info, &err);
    if (r == PG_OK) r = pg_replay_world_memory_size(&s->info, &memory_size, &err);
    if (r != PG_OK) {
        snprintf(message, message_capacity, "offset %zu (%s, field %s): %s", err.offset, err.region, err.field, err.message);
        free_all(s);
        return r;
    }
    s->world_memory = malloc(memory_size);
    s->record_offsets = (size_t *)calloc((size_t)s->info.frame_count + 1u, sizeof *s->record_offsets);
    s->snapshot_slots = s->info.frame_count / PGA_SEEK_SNAPSHOT_INTERVAL + 1u;
    s->snapshots = (seek_snapshot *)calloc(s->snapshot_slots, sizeof *s->snapshots);
    s->checkpoint_match = (signed char *)malloc((size_t)s->info.checkpoint_count + 1u);
    s->checkpoint_sections = (uint32_t *)calloc((size_t)s->info.checkpoint_count + 1u, sizeof *s->checkpoint_sections);
    if (s->world_memory == NULL || s->record_offsets == NULL || s->snapshots == NULL || s->checkpoint_match == NULL ||
        s->checkpoint_sections == NULL) {
        snprintf(message, message_capacity, "out of memory for a world of %zu bytes and %u frames", memory_size,
                 s->info.frame_count);
        free_all(s);
        return PG_ERR_MEMORY;
    }
    for (i = 0; i <= s->info.checkpoint_count; ++i) s->checkpoint_match[i] = -1;
    r = pg_replay_player_begin(&s->player, s->file, &s->info, s->world_memory, memory_size, &first, &err);
    if (r != PG_OK) {
        snprintf(message, message_capacity, "offset %zu (%s, field %s): %s", err.offset, err.region, err.field, err.message);
        free_all(s);
        return r;
    }
    s->status.frame_count = s->info.frame_count;
    s->status.checkpoint_count = s->info.checkpoint_count;
    s->status.last_match = -1;
    s->status.first_failed_frame = -1;
    note_checkpoint(s, 0, first.match, first.section_mismatch);
    if (!keep_snapshot(s)) {
        snprintf(message, message_capacity, "%s", s->error);
        free_all(s);
        return PG_ERR_MEMORY;
    }
    *out = s;
    return PG_OK;
}

void pga_seek_close(pga_seek *s) { free_all(s); }

const pg_world *pga_seek_world(const pga_seek *s) { return s != NULL ? s->player.world : NULL; }
const pg_replay_info *pga_seek_info(const pga_seek *s) { return s != NULL ? &s->info : NULL; }
const char *pga_seek_error(const pga_seek *s) { return s != NULL ? s->error : ""; }

pga_seek_status pga_seek_get_status(const pga_seek *s)
{
    pga_seek_status st;
    if (s == NULL) {
        memset(&st, 0, sizeof st);
        st.last_match = -1;
        st.first_failed_frame = -1;
        return st;
    }
    st = s->status;
    st.frame = s->frame;
    st.played = s->player.frame;
    return st;
}

/* One frame forward from s->frame, by whichever way applies. 0 on failure or at the end. */
static int forward_one(pga_seek *s)
{
    uint32_t n = s->info.checkpoint_interval;
    if (s->frame >= s->info.frame_count) return 0;
    if (s->frame < s->player.frame) {
        uint32_t sections = 0;
        int match;
        if (pg_replay_apply_frame(s->player.world, s->file, &s->info, s->record_offsets[s->frame], NULL, NULL) != PG_OK) {
            snprintf(s->error, sizeof s->error, "frame %u: %s", s->frame, pg_world_last_error(s->player.world));
            return 0;
        }
        pg_world_step(s->player.world);
        s->frame++;
        if (s->frame % n == 0u) {
            match = pg_replay_compare_checkpoint(s->player.world, s->file, &s->info, s->frame / n, NULL, NULL, &sections);
            note_checkpoint(s, s->frame / n, match, sections);
        }
        return 1;
    } else {
        pg_replay_frame_result fr;
        uint32_t before = s->player.frame;
        s->record_offsets[s->frame] = s->player.cursor;
        /* A step that fails still counts (the recording stepped the same way); only a
         * player that did not move is an error. */
        (void)pg_replay_player_step(&s->player, &fr);
        if (s->player.frame == before) {
            snprintf(s->error, sizeof s->error, "frame %u: the player could not play the next record", s->frame);
            return 0;
        }
        s->frame = s->player.frame;
        if (fr.checkpoint) note_checkpoint(s, fr.checkpoint_index, fr.match, fr.section_mismatch);
        return keep_snapshot(s);
    }
}

int pga_seek_step(pga_seek *s)
{
    if (s == NULL) return 0;
    if (s->status.seeking) {
        while (!pga_seek_advance(s, 100000u)) {
        }
    }
    return forward_one(s);
}

pg_result pga_seek_jump(pga_seek *s, uint32_t target)
{
    uint32_t reachable, slot;
    if (s == NULL) return PG_ERR_NULL;
    if (target > s->info.frame_count) {
        snprintf(s->error, sizeof s->error, "frame %u is past the replay's last frame %u", target, s->info.frame_count);
        return PG_ERR_INVALID_ARGUMENT;
    }
    /* The latest kept snapshot at or before the target (every slot up to `played` is kept). */
    reachable = target < s->player.frame ? target : s->player.frame;
    slot = reachable / PGA_SEEK_SNAPSHOT_INTERVAL;
    if (!(s->frame <= target && s->frame >= slot * PGA_SEEK_SNAPSHOT_INTERVAL)) {
        pg_result r = pg_world_snapshot_restore(s->player.world, s->snapshots[slot].data, s->snapshots[slot].size);
        if (r != PG_OK) {
            snprintf(s->error, sizeof s->error, "restoring the snapshot of frame %u: %s", slot * PGA_SEEK_SNAPSHOT_INTERVAL,
                     pg_world_last_error(s->player.world));
            return r;
        }
        s->frame = slot * PGA_SEEK_SNAPSHOT_INTERVAL;
    }
    s->status.seeking = 1;
    s->status.seek_from = s->frame;
    s->status.seek_target = target;
    return PG_OK;
}

int pga_seek_advance(pga_seek *s, uint32_t max_frames)
{
    uint32_t done = 0;
    if (s == NULL || !s->status.seeking) return 1;
    while (s->frame < s->status.seek_target && done < max_frames) {
        if (!forward_one(s)) {
            s->status.seeking = 0;
            return 1;
        }
        done++;
    }
    if (s->frame >= s->status.seek_target) {
        s->status.seeking = 0;
        return 1;
    }
    return 0;
}
