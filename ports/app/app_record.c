/* app_record.c — the session's recording: a pogon-replay file written as frames go by.
 *
 * The file's scene is the live world's canonical text (app_world.c); checkpoint 0 is the
 * world as loaded; every stepped frame adds the commands applied before its step, and a
 * checkpoint every PGA_CHECKPOINT_INTERVAL frames. pga_recording finishes a copy (the end
 * record needs the final hash: the hash after the last logged step), so recording goes
 * on. That hash is the world's, unless commands applied while paused wait for the next
 * step: then it is the hash taken before the first of them. */
#include "app_internal.h"

#include <stdlib.h>
#include <string.h>

void pga__recorder_free(pga_recorder *rec)
{
    free(rec->data);
    free(rec->copy);
    memset(rec, 0, sizeof *rec);
}

/* Grow the buffer to at least `need` bytes (doubling), keeping what was written. */
static pg_result grow(pga_recorder *rec, size_t need)
{
    size_t cap = rec->capacity ? rec->capacity : 65536;
    uint8_t *data;
    while (cap < need) cap *= 2;
    if (cap == rec->capacity) cap *= 2;
    data = (uint8_t *)realloc(rec->data, cap);
    if (data == NULL) return PG_ERR_MEMORY;
    rec->data = data;
    rec->capacity = cap;
    return PG_OK;
}

pg_result pga__recorder_start(pga_app *app)
{
    pga_recorder *rec = &app->recorder;
    pg_result r;
    rec->active = 0;
    if (rec->capacity < app->live.text_size + 65536 && grow(rec, app->live.text_size + 65536) != PG_OK)
        return PG_ERR_MEMORY;
    while ((r = pg_replay_writer_begin(&rec->writer, rec->data, rec->capacity, app->live.text, app->live.text_size,
                                       PGA_CHECKPOINT_INTERVAL)) == PG_ERR_MEMORY) {
        if (grow(rec, rec->capacity * 2) != PG_OK) return PG_ERR_MEMORY;
    }
    if (r != PG_OK) return r;
    while ((r = pg_replay_writer_add_checkpoint_world(&rec->writer, app->live.world)) == PG_ERR_MEMORY) {
        if (grow(rec, rec->capacity * 2) != PG_OK) return PG_ERR_MEMORY;
        pg_replay_writer_set_buffer(&rec->writer, rec->data, rec->capacity);
    }
    if (r != PG_OK) return r;
    rec->active = 1;
    return PG_OK;
}

void pga__recorder_before_changes(pga_app *app)
{
    if (app->recorder.active && app->frame_command_count == 0) app->recorder.logged_hash = pg_world_hash(app->live.world);
}

pg_result pga__recorder_frame(pga_app *app, const pg_command *commands, uint32_t count)
{
    pga_recorder *rec = &app->recorder;
    pg_result r;
    if (!rec->active) return PG_OK;
    while ((r = pg_replay_writer_add_frame(&rec->writer, commands, count)) == PG_ERR_MEMORY) {
        if (grow(rec, rec->capacity * 2) != PG_OK) return PG_ERR_MEMORY;
        pg_replay_writer_set_buffer(&rec->writer, rec->data, rec->capacity);
    }
    return r;
}

pg_result pga__recorder_after_step(pga_app *app)
{
    pga_recorder *rec = &app->recorder;
    pg_result r = PG_OK;
    if (!rec->active) return PG_OK;
    if (!pg_replay_writer_checkpoint_due(&rec->writer)) return PG_OK;
    while ((r = pg_replay_writer_add_checkpoint_world(&rec->writer, app->live.world)) == PG_ERR_MEMORY) {
        if (grow(rec, rec->capacity * 2) != PG_OK) return PG_ERR_MEMORY;
        pg_replay_writer_set_buffer(&rec->writer, rec->data, rec->capacity);
    }
    return r;
}

pg_result pga_recording(pga_app *app, const uint8_t **data, size_t *size)
{
    pga_recorder *rec;
    pg_replay_writer copy;
    size_t need, written = 0;
    pg_result r;
    if (app == NULL || data == NULL || size == NULL) {
        if (app != NULL) pga__say(app, PGA_MESSAGE_REFUSED, "No recording: a NULL argument");
        return PG_ERR_NULL;
    }
    rec = &app->recorder;
    if (app->mode != PGA_MODE_LIVE || !rec->active) {
        pga__say(app, PGA_MESSAGE_REFUSED, "No recording: %s",
                 app->mode == PGA_MODE_PLAYBACK ? "a replay is playing (stop it to record)"
                 : app->mode == PGA_MODE_EMPTY ? "no scene is loaded" : "recording stopped (out of memory)");
        return PG_ERR_INVALID_ARGUMENT;
    }
    need = rec->writer.size + PG_REPLAY_TRAILER_SIZE + 64;
    if (rec->copy_capacity < need) {
        uint8_t *grown = (uint8_t *)realloc(rec->copy, need);
        if (grown == NULL) {
            pga__say(app, PGA_MESSAGE_ERROR, "No recording: out of memory");
            return PG_ERR_MEMORY;
        }
        rec->copy = grown;
        rec->copy_capacity = need;
    }
    memcpy(rec->copy, rec->data, rec->writer.size);
    copy = rec->writer;
    r = pg_replay_writer_set_buffer(&copy, rec->copy, rec->copy_capacity);
    if (r == PG_OK)
        r = pg_replay_writer_finish(&copy, app->frame_command_count > 0 ? rec->logged_hash : pg_world_hash(app->live.world),
                                    &written);
    if (r != PG_OK) {
        pga__say(app, PGA_MESSAGE_ERROR, "No recording: the replay writer says %s", pg_result_name(r));
        return r;
    }
    *data = rec->copy;
    *size = written;
    return PG_OK;
}
