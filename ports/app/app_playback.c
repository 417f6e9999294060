/* app_playback.c — playing a replay file: the file is validated whole (pg_replay_read)
 * before anything changes, its scene replaces the world, and each pga_frame plays one
 * frame record with the core's player, comparing the checkpoints that fall on it. Pause
 * and single step work as in live mode. Stopping goes live from the state reached, with
 * a new recording (pga__restart_from). */
#include "app_internal.h"

#include <stdlib.h>
#include <string.h>

void pga__player_free(pga_player *p)
{
    free(p->data);
    free(p->memory);
    memset(p, 0, sizeof *p);
}

static void refuse(pga_app *app, const pg_replay_error *e)
{
    pga__say(app, PGA_MESSAGE_ERROR, "Replay refused: offset %lu, %s field %s: %s", (unsigned long)e->offset,
             e->region != NULL ? e->region : "file", e->field != NULL ? e->field : "?", e->message);
}

pg_result pga_play_replay(pga_app *app, const uint8_t *data, size_t size)
{
    pga_player p;
    pg_replay_error e;
    pg_replay_frame_result first;
    size_t need = 0;
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if (data == NULL) {
        pga__say(app, PGA_MESSAGE_ERROR, "Replay refused: no data given");
        return PG_ERR_NULL;
    }
    memset(&p, 0, sizeof p);
    memset(&e, 0, sizeof e);
    r = pg_replay_read(data, size, &p.player.info, &e);
    if (r != PG_OK) {
        refuse(app, &e);
        return r;
    }
    r = pg_replay_world_memory_size(&p.player.info, &need, &e);
    if (r != PG_OK) {
        refuse(app, &e);
        return r;
    }
    if (need > PGA_MAX_WORLD_BYTES) {
        pga__say(app, PGA_MESSAGE_ERROR, "Replay refused: offset %lu, scene: its capacities need %lu MiB of world memory; the app allows at most %lu MiB",
                 (unsigned long)p.player.info.scene_offset, (unsigned long)(need >> 20), (unsigned long)(PGA_MAX_WORLD_BYTES >> 20));
        return PG_ERR_CAPACITY;
    }
    p.data = (uint8_t *)malloc(size);
    p.memory = malloc(need);
    if (p.data == NULL || p.memory == NULL) {
        pga__player_free(&p);
        pga__say(app, PGA_MESSAGE_ERROR, "Replay refused: out of memory (%lu bytes of world)", (unsigned long)need);
        return PG_ERR_MEMORY;
    }
    memcpy(p.data, data, size);
    p.size = size;
    /* read again from the app's copy: the info points into the file */
    r = pg_replay_read(p.data, size, &p.player.info, &e);
    if (r == PG_OK) r = pg_replay_player_begin(&p.player, p.data, &p.player.info, p.memory, need, &first, &e);
    if (r != PG_OK) {
        pga__player_free(&p);
        refuse(app, &e);
        return r;
    }
    pga__player_free(&app->playback);
    pga__world_free(&app->live);
    app->playback = p;
    app->mode = PGA_MODE_PLAYBACK;
    pga__reset_input(app);
    app->selected.index = app->selected.generation = 0;
    memset(&app->playback.state, 0, sizeof app->playback.state);
    app->playback.state.active = 1;
    app->playback.state.frame_count = p.player.info.frame_count;
    app->playback.state.checkpoints_checked = 1;
    app->playback.state.checkpoints_failed = first.match ? 0u : 1u;
    app->playback.state.last_match = first.match ? 1 : 0;
    app->playback.state.section_mismatch = first.section_mismatch;
    pga__say(app, PGA_MESSAGE_INFO, "Playing a replay: %u frames, %u checkpoints", p.player.info.frame_count,
             p.player.info.checkpoint_count);
    return PG_OK;
}

int pga__playback_frame(pga_app *app)
{
    pga_player *p = &app->playback;
    pg_replay_frame_result fr;
    if (pg_replay_player_done(&p->player)) return 0;
    if (app->paused && !app->step_requested) return 0;
    app->step_requested = 0;
    if (pg_replay_player_step(&p->player, &fr) != PG_OK) return 0;
    p->state.frame = p->player.frame;
    if (fr.checkpoint) {
        p->state.checkpoints_checked++;
        if (!fr.match) {
            p->state.checkpoints_failed++;
            p->state.section_mismatch = fr.section_mismatch;
        }
        p->state.last_match = fr.match ? 1 : 0;
    }
    if (pg_replay_player_done(&p->player))
        pga__say(app, p->state.checkpoints_failed == 0 ? PGA_MESSAGE_INFO : PGA_MESSAGE_ERROR,
                 "Replay finished: %u frames, %u of %u checkpoints matched", p->state.frame,
                 p->state.checkpoints_checked - p->state.checkpoints_failed, p->state.checkpoints_checked);
    return 1;
}

pga_playback pga_playback_state(const pga_app *app)
{
    pga_playback none;
    if (app != NULL && app->mode == PGA_MODE_PLAYBACK) return app->playback.state;
    memset(&none, 0, sizeof none);
    none.last_match = -1;
    return none;
}

pg_result pga_stop_playback(pga_app *app)
{
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if (app->mode != PGA_MODE_PLAYBACK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "No replay is playing");
        return PG_ERR_INVALID_ARGUMENT;
    }
    r = pga__restart_from(app, app->playback.player.world, 0, "Going live");
    if (r == PG_OK) {
        app->selected = pga__find_player(app);
        pga__say(app, PGA_MESSAGE_INFO, "Live from the replay's frame: a new recording starts here");
    }
    return r;
}
