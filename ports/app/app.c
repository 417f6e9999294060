/* app.c — the app's life, messages, tools and parameters, selection and small accessors. */
#include "app_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const tool_names[PGA_TOOL_COUNT] = {"move", "delete", "ball", "capsule", "box",
                                                       "triangle", "star", "wall", "pin", "rod", "spring"};
static const char *const preset_names[PGA_PRESET_COUNT] = {"fast", "balanced", "accurate"};
static const uint32_t preset_substeps[PGA_PRESET_COUNT] = {2, 4, 8};

pga_app *pga_create(void)
{
    pga_app *app = (pga_app *)calloc(1, sizeof *app);
    if (app == NULL) return NULL;
    app->scratch = (pga_scratch *)calloc(1, sizeof *app->scratch);
    app->queue = (pga_action *)calloc(PGA_QUEUE_CAPACITY, sizeof *app->queue);
    if (app->scratch == NULL || app->queue == NULL) {
        pga_destroy(app);
        return NULL;
    }
    app->mode = PGA_MODE_EMPTY;
    app->tool = PGA_TOOL_MOVE;
    app->params = pga_default_params();
    app->preset = PGA_PRESET_BALANCED;
    app->gravity_on = pg_v2(0, PG_FIX_C(-10));
    app->effects = PG_EFFECTS_ALL;
    pga__say(app, PGA_MESSAGE_INFO, "Load a scene to start");
    return app;
}

void pga_destroy(pga_app *app)
{
    if (app == NULL) return;
    pga__world_free(&app->live);
    pga__player_free(&app->playback);
    pga__recorder_free(&app->recorder);
    if (app->scratch != NULL) {
        free(app->scratch->shapes);
        free(app->scratch->bodies);
        free(app->scratch->joints);
        free(app->scratch);
    }
    free(app->queue);
    free(app->frame_commands);
    free(app);
}

void pga__say(pga_app *app, pga_message_level level, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    vsnprintf(app->message, sizeof app->message, format, ap);
    va_end(ap);
    app->message_level = level;
    app->message_serial++;
}

const char *pga_message(const pga_app *app) { return app == NULL ? "" : app->message; }
uint32_t pga_message_serial(const pga_app *app) { return app == NULL ? 0 : app->message_serial; }
pga_message_level pga_message_level_of(const pga_app *app) { return app == NULL ? PGA_MESSAGE_INFO : app->message_level; }

pg_world *pga__world(const pga_app *app)
{
    if (app == NULL) return NULL;
    if (app->mode == PGA_MODE_LIVE) return app->live.world;
    if (app->mode == PGA_MODE_PLAYBACK) return app->playback.player.world;
    return NULL;
}

const pg_world *pga_world(const pga_app *app) { return pga__world(app); }
const char *pga_scene_name(const pga_app *app) { return app == NULL ? "" : app->scene_name; }

void pga__reset_input(pga_app *app)
{
    memset(app->keys, 0, sizeof app->keys);
    app->pending_count = 0;
    app->dragging = 0;
    app->drag_joint.index = app->drag_joint.generation = 0;
    app->driven.index = app->driven.generation = 0;
    app->queue_count = 0;
    app->frame_command_count = 0;
    app->step_requested = 0;
}

/* The world's gravity and effects become the toggles' state. */
static void adopt_world_settings(pga_app *app)
{
    const pg_world *w = pga__world(app);
    pg_world_def def = pg_world_get_def(w);
    pg_vec2 g = pg_world_gravity(w);
    uint32_t i;
    app->gravity_enabled = g.x != 0 || g.y != 0;
    if (app->gravity_enabled) app->gravity_on = g;
    app->effects = pg_world_effects(w);
    for (i = 0; i < PGA_PRESET_COUNT; ++i)
        if (preset_substeps[i] == def.substeps) app->preset = (pga_preset)i;
}

static void set_name(pga_app *app, const char *name)
{
    size_t n = name == NULL ? 0 : strlen(name);
    if (n >= sizeof app->scene_name) n = sizeof app->scene_name - 1;
    if (n > 0) memcpy(app->scene_name, name, n);
    app->scene_name[n] = '\0';
}

/* Make `box` the live world: drop the old one (and any playback), restart recording. */
pg_result pga__go_live(pga_app *app, pga_world_box *box)
{
    pg_result r;
    pga__world_free(&app->live);
    pga__player_free(&app->playback);
    app->live = *box;
    app->mode = PGA_MODE_LIVE;
    pga__reset_input(app);
    adopt_world_settings(app);
    r = pga__recorder_start(app);
    if (r != PG_OK) pga__say(app, PGA_MESSAGE_ERROR, "Recording stopped: out of memory for the replay buffer");
    return r;
}

pg_result pga_load_scene(pga_app *app, const char *name, const char *text, size_t length)
{
    pga_world_box box;
    char error[200];
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if (text == NULL) {
        pga__say(app, PGA_MESSAGE_ERROR, "Scene not loaded: no text given");
        return PG_ERR_NULL;
    }
    r = pga__world_build(&box, text, length, 0, error, sizeof error);
    if (r != PG_OK) {
        pga__say(app, PGA_MESSAGE_ERROR, "Scene %s not loaded: %s", name != NULL ? name : "", error);
        return r;
    }
    r = pga__go_live(app, &box);
    set_name(app, name);
    app->selected = pga__find_player(app);
    if (r == PG_OK)
        pga__say(app, PGA_MESSAGE_INFO, "Loaded scene %s: %u bodies", app->scene_name, pga_body_count(app));
    return r;
}

/* ---- tools and parameters ---- */
const char *pga_tool_name(pga_tool tool) { return (unsigned)tool < PGA_TOOL_COUNT ? tool_names[tool] : ""; }
const char *pga_preset_name(pga_preset preset) { return (unsigned)preset < PGA_PRESET_COUNT ? preset_names[preset] : ""; }

pga_params pga_default_params(void)
{
    pga_params p;
    memset(&p, 0, sizeof p);
    p.radius = PG_FIX_HALF;
    p.width = PG_FIX_ONE;
    p.height = PG_FIX_ONE;
    p.density = PG_FIX_ONE;
    p.friction = pg_fix_from_ratio(6, 10);
    p.restitution = 0;
    p.color = 0x3b82f6u;
    p.nudge = 0;
    p.spring_hertz = PG_FIX_C(4);
    p.spring_damping = pg_fix_from_ratio(3, 10);
    return p;
}

pg_result pga_set_tool(pga_app *app, pga_tool tool)
{
    if (app == NULL) return PG_ERR_NULL;
    if ((unsigned)tool >= PGA_TOOL_COUNT) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Unknown tool %d (0..%d)", (int)tool, PGA_TOOL_COUNT - 1);
        return PG_ERR_INVALID_ARGUMENT;
    }
    app->tool = tool;
    app->pending_count = 0;
    return PG_OK;
}

pga_tool pga_get_tool(const pga_app *app) { return app == NULL ? PGA_TOOL_MOVE : app->tool; }

static int in_range(pg_fix v, pg_fix lo, pg_fix hi) { return v >= lo && v <= hi; }

pg_result pga_set_params(pga_app *app, const pga_params *p)
{
    const char *what = NULL;
    if (app == NULL) return PG_ERR_NULL;
    if (p == NULL) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Parameters not changed: none given");
        return PG_ERR_NULL;
    }
    /* The envelope of pogon.h for the ready-made kinds (sizes as pg_make_* take them). */
    if (!in_range(p->radius, pg_fix_from_ratio(25, 1000), PG_FIX_C(50))) what = "radius must be 0.025..50 m";
    else if (!in_range(p->width, pg_fix_from_ratio(5, 100), PG_FIX_C(100))) what = "width must be 0.05..100 m";
    else if (!in_range(p->height, pg_fix_from_ratio(5, 100), PG_FIX_C(100))) what = "height must be 0.05..100 m";
    else if (!in_range(p->density, pg_fix_from_ratio(1, 10), PG_FIX_C(100))) what = "density must be 0.1..100 kg/m^2";
    else if (!in_range(p->friction, 0, PG_FIX_C(10))) what = "friction must be 0..10";
    else if (!in_range(p->restitution, 0, PG_FIX_ONE)) what = "restitution must be 0..1";
    else if (p->color > 0xffffffu) what = "colour must be 0xRRGGBB (at most 0xffffff)";
    /* the core's ranges for a distance joint's spring; hertz 0 would be no spring at all */
    else if (!in_range(p->spring_hertz, 1, PG_FIX_C(1000))) what = "spring frequency must be above 0 and at most 1000 Hz";
    else if (!in_range(p->spring_damping, 0, PG_FIX_C(1000))) what = "spring damping ratio must be 0..1000";
    if (what != NULL) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Parameters not changed: %s", what);
        return PG_ERR_ENVELOPE;
    }
    app->params = *p;
    app->params.nudge = p->nudge != 0;
    return PG_OK;
}

pga_params pga_get_params(const pga_app *app) { return app == NULL ? pga_default_params() : app->params; }

/* ---- selection ---- */
pg_body_id pga_selected(const pga_app *app)
{
    pg_body_id none = {0, 0};
    if (app == NULL || !pg_body_is_valid(pga__world(app), app->selected)) return none;
    return app->selected;
}

pg_result pga_select(pga_app *app, pg_body_id body)
{
    pg_body_id none = {0, 0};
    if (app == NULL) return PG_ERR_NULL;
    if (body.index == 0 && body.generation == 0) {
        app->selected = none;
        return PG_OK;
    }
    if (!pg_body_is_valid(pga__world(app), body)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Not selected: body %u/%u is not in the world", body.index, body.generation);
        return PG_ERR_STALE_HANDLE;
    }
    app->selected = body;
    return PG_OK;
}

/* ---- numbers for the UI ---- */
uint64_t pga_frame_number(const pga_app *app)
{
    const pg_world *w = pga__world(app);
    return w == NULL ? 0 : pg_world_frame(w);
}

uint64_t pga_state_hash(const pga_app *app)
{
    const pg_world *w = pga__world(app);
    return w == NULL ? 0 : pg_world_hash(w);
}

uint32_t pga_body_count(const pga_app *app)
{
    uint32_t n = 0;
    const pg_world *w = pga__world(app);
    if (w != NULL) (void)pga__list_bodies(app, w, &n);
    return n;
}

/* ---- lists for menus ---- */
static const char *const effect_names[] = {"gravity", "rotation", "friction", "restitution",
                                           "damping", "sleeping", "continuous"};
uint32_t pga_effect_count(void) { return (uint32_t)(sizeof effect_names / sizeof effect_names[0]); }
uint32_t pga_effect_bit(uint32_t index) { return index < pga_effect_count() ? 1u << index : 0u; }
const char *pga_effect_name(uint32_t index) { return index < pga_effect_count() ? effect_names[index] : ""; }
uint32_t pga_effects(const pga_app *app) { return app == NULL ? 0 : app->effects; }
int pga_gravity_enabled(const pga_app *app) { return app == NULL ? 0 : app->gravity_enabled; }

/* ---- paused, presets ---- */
void pga_set_paused(pga_app *app, int paused)
{
    if (app == NULL) return;
    app->paused = paused != 0;
    app->step_requested = 0;
}

int pga_paused(const pga_app *app) { return app == NULL ? 0 : app->paused; }

void pga_step_once(pga_app *app)
{
    if (app == NULL || !app->paused) return;
    app->step_requested = 1;
}

pga_preset pga_get_preset(const pga_app *app) { return app == NULL ? PGA_PRESET_BALANCED : app->preset; }

/* Rebuild the live world from its current state written as a scene, with `substeps`.
 * Handles change (bodies load compacted in slot order): the selection follows by rank. */
pg_result pga__restart_from(pga_app *app, const pg_world *world, uint32_t substeps, const char *why)
{
    pga_world_box box;
    char error[200];
    char *text;
    size_t size;
    uint32_t rank = UINT32_MAX, count = 0, i;
    const pg_body_id *ids;
    pg_result r;

    ids = pga__list_bodies(app, world, &count);
    for (i = 0; i < count; ++i)
        if (pg_body_id_equal(ids[i], app->selected)) rank = i;
    text = pga__world_text(world, &size);
    if (text == NULL) {
        pga__say(app, PGA_MESSAGE_ERROR, "%s failed: out of memory", why);
        return PG_ERR_MEMORY;
    }
    r = pga__world_build(&box, text, size, substeps, error, sizeof error);
    free(text);
    if (r != PG_OK) {
        /* e.g. a body that flew beyond the envelope cannot be loaded again */
        pga__say(app, PGA_MESSAGE_ERROR, "%s failed: %s", why, error);
        return r;
    }
    r = pga__go_live(app, &box);
    app->selected.index = 0;
    app->selected.generation = 0;
    ids = pga__list_bodies(app, app->live.world, &count);
    if (rank < count) app->selected = ids[rank];
    return r;
}

pg_result pga_set_preset(pga_app *app, pga_preset preset)
{
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if ((unsigned)preset >= PGA_PRESET_COUNT) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Unknown preset %d (0 fast, 1 balanced, 2 accurate)", (int)preset);
        return PG_ERR_INVALID_ARGUMENT;
    }
    if (app->mode != PGA_MODE_LIVE) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Preset not changed: %s", app->mode == PGA_MODE_EMPTY ? "no scene is loaded" : "stop the playback first");
        return PG_ERR_INVALID_ARGUMENT;
    }
    /* queued changes name handles of the old world: they go in before it is written; a
     * drag does not survive the restart, so its mouse joint goes too */
    pga__flush_queue(app);
    pga__drag_drop_joint(app);
    r = pga__restart_from(app, app->live.world, preset_substeps[preset], "Preset change");
    if (r != PG_OK) return r;
    app->preset = preset;
    pga__say(app, PGA_MESSAGE_INFO, "Accuracy %s (%u substeps): the world and the recording restart here",
             preset_names[preset], preset_substeps[preset]);
    return PG_OK;
}
