/* app_frame.c — the queue of world changes and one live frame.
 *
 * Input between frames only queues actions. pga_frame applies the queue in arrival
 * order, then (when it steps) the commands of held keys and the drag, logs all of them
 * as the frame's record, steps, and checkpoints. While paused the queue is still applied
 * at each pga_frame so the user sees what was added; those commands wait in
 * frame_commands and are logged with the next step. Applying them then or before the
 * step makes no difference to the state, since nothing else happens in between. */
#include "app_internal.h"

#include <stdlib.h>
#include <string.h>

pg_result pga__queue(pga_app *app, const pga_action *action)
{
    if (app->mode != PGA_MODE_LIVE) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s", app->mode == PGA_MODE_EMPTY ? "Load a scene first" : "Stop the playback to change the world");
        return PG_ERR_INVALID_ARGUMENT;
    }
    if (app->queue_count >= PGA_QUEUE_CAPACITY) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: %u changes are already waiting for the next frame", PGA_QUEUE_CAPACITY);
        return PG_ERR_CAPACITY;
    }
    app->queue[app->queue_count++] = *action;
    return PG_OK;
}

pg_result pga__apply(pga_app *app, const pg_command *command, pg_body_id *made)
{
    return pga__apply_made(app, command, made, NULL);
}

pg_result pga__apply_made(pga_app *app, const pg_command *command, pg_body_id *made, pg_joint_id *made_joint)
{
    pg_result r;
    if (app->frame_command_count >= PG_REPLAY_MAX_FRAME_COMMANDS) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: a frame holds at most %u changes; step first", PG_REPLAY_MAX_FRAME_COMMANDS);
        return PG_ERR_CAPACITY;
    }
    if (app->frame_command_count == app->frame_command_capacity) {
        uint32_t cap = app->frame_command_capacity ? app->frame_command_capacity * 2 : 64;
        pg_command *grown = (pg_command *)realloc(app->frame_commands, sizeof *grown * cap);
        if (grown == NULL) {
            pga__say(app, PGA_MESSAGE_ERROR, "Refused: out of memory");
            return PG_ERR_MEMORY;
        }
        app->frame_commands = grown;
        app->frame_command_capacity = cap;
    }
    r = pg_command_apply_made(app->live.world, command, made, made_joint);
    /* A failing command changes nothing, so it is left out of the log. */
    if (r == PG_OK) app->frame_commands[app->frame_command_count++] = *command;
    return r;
}

/* A joint command's body A (the anchor made just before it). */
static void set_joint_body_a(pg_command *c, pg_body_id body)
{
    if (c->kind == PG_CMD_CREATE_DISTANCE_JOINT) c->joint_def.distance.body_a = body;
    else if (c->kind == PG_CMD_CREATE_REVOLUTE_JOINT) c->joint_def.revolute.body_a = body;
}

void pga__flush_queue(pga_app *app)
{
    pg_body_id made = {0, 0}, none = {0, 0};
    uint32_t i;
    if (app->queue_count > 0) pga__recorder_before_changes(app);
    for (i = 0; i < app->queue_count; ++i) {
        pga_action *a = &app->queue[i];
        pg_body_id created = {0, 0};
        pg_result r;
        if (a->body_is_last_made) {
            if (made.generation == 0) continue; /* the body it belongs to was not made */
            a->command.body = made;
        }
        if (a->anchor_is_last_made) {
            if (made.generation == 0) continue; /* its anchor was not made */
            set_joint_body_a(&a->command, made);
        }
        r = pga__apply(app, &a->command, &created);
        if (r != PG_OK) {
            pga__say(app, PGA_MESSAGE_REFUSED, "Not done (%s): %s", pg_command_kind_name(a->command.kind),
                     pg_world_last_error(app->live.world));
            if (a->command.kind == PG_CMD_CREATE_BODY || a->command.kind == PG_CMD_MAKE) made = none;
            /* a shape that could not be added leaves an empty body, a joint its anchor: remove it */
            if ((a->body_is_last_made || a->anchor_is_last_made) && made.generation != 0) {
                pg_command d = pg_command_init(PG_CMD_DESTROY_BODY);
                d.body = made;
                (void)pga__apply(app, &d, NULL);
                made = none;
            }
            continue;
        }
        if (a->command.kind == PG_CMD_CREATE_BODY || a->command.kind == PG_CMD_MAKE) {
            made = created;
            if (a->select_made) app->selected = created;
        } else if (a->command.kind == PG_CMD_DESTROY_BODY) {
            if (pg_body_id_equal(a->command.body, app->selected)) app->selected = none;
            if (pg_body_id_equal(a->command.body, app->drag_body)) app->dragging = 0;
        }
    }
    app->queue_count = 0;
}

/* A body beyond +-1000 m (the envelope's positions) has left the world: it is removed by
 * a command, so the world can always be written and loaded again as a scene (presets). */
static void remove_escaped(pga_app *app)
{
    const pg_world *w = app->live.world;
    const pg_fix limit = PG_FIX_C(1000);
    const pg_body_id *ids;
    uint32_t n, i, removed = 0;
    ids = pga__list_bodies(app, w, &n);
    for (i = 0; i < n; ++i) {
        pg_vec2 p = pg_body_position(w, ids[i]);
        if (p.x >= -limit && p.x <= limit && p.y >= -limit && p.y <= limit) continue;
        {
            pg_command c = pg_command_init(PG_CMD_DESTROY_BODY);
            pg_body_id gone = ids[i];
            c.body = gone;
            pga__remove_anchors_of(app, gone, 1); /* its pins' anchors, which would be left with nothing */
            if (pga__apply(app, &c, NULL) != PG_OK) continue;
            removed++;
            if (pg_body_id_equal(gone, app->selected)) app->selected.index = app->selected.generation = 0;
            if (app->dragging && pg_body_id_equal(gone, app->drag_body)) app->dragging = 0;
        }
    }
    if (removed > 0) pga__say(app, PGA_MESSAGE_INFO, "Removed %u bod%s that left the world (beyond +-1000 m)", removed, removed == 1 ? "y" : "ies");
}

int pga_frame(pga_app *app)
{
    pg_result r;
    if (app == NULL) return 0;
    if (app->mode == PGA_MODE_PLAYBACK) return pga__playback_frame(app);
    if (app->mode != PGA_MODE_LIVE) return 0;
    pga__flush_queue(app);
    if (!pg_body_is_valid(app->live.world, app->selected)) app->selected.index = app->selected.generation = 0;
    if (app->paused && !app->step_requested) return 0;
    app->step_requested = 0;
    remove_escaped(app);
    pga__control_commands(app);
    r = pga__recorder_frame(app, app->frame_commands, app->frame_command_count);
    app->frame_command_count = 0;
    if (pg_world_step(app->live.world) != PG_OK) {
        pga__say(app, PGA_MESSAGE_ERROR, "Step failed: %s", pg_world_last_error(app->live.world));
        return 0;
    }
    if (r == PG_OK) r = pga__recorder_after_step(app);
    if (r != PG_OK && app->recorder.active) {
        app->recorder.active = 0;
        pga__say(app, PGA_MESSAGE_ERROR, "Recording stopped: %s", pg_result_message(r));
    }
    return 1;
}
