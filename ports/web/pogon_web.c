/* pogon_web.c — the browser demo's binding: ports/app (pogon_app.h) as flat functions
 * that JavaScript can call through the WebAssembly exports.
 *
 * Why a binding at all: JavaScript can pass and receive only numbers and pointers, so
 * every pga_* call that takes or returns a struct is flattened here into scalar
 * arguments (Q16.16 values as int32, handles as index + generation, 64-bit hashes as
 * hex text). The page holds one app; this file holds its pointer. No interaction logic
 * lives here: each function forwards to one pga_* call or reads one value.
 *
 * Struct layouts the page reads straight from wasm memory (the draw list) are described
 * by pgw_draw_layout(), so the JavaScript never hard-codes an offset.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <emscripten/emscripten.h>

#include "pogon_app.h"

static pga_app *g_app;
/* The replay being played: the app may read it until the next replay is loaded. */
static uint8_t *g_replay;
static char g_recorded_with[160];
static size_t g_recording_size;
static char g_hash_text[17];

#define EXPORT EMSCRIPTEN_KEEPALIVE

/* ---- life ------------------------------------------------------------------------------ */
EXPORT int pgw_create(void)
{
    if (!g_app) g_app = pga_create();
    return g_app != NULL;
}

EXPORT int pgw_load_scene(const char *name, const char *text, int length)
{
    if (!g_app || length < 0) return PG_ERR_NULL;
    return (int)pga_load_scene(g_app, name, text, (size_t)length);
}

EXPORT const char *pgw_scene_name(void) { return g_app ? pga_scene_name(g_app) : ""; }

/* ---- tools and parameters ----------------------------------------------------------------- */
EXPORT int pgw_set_tool(int tool) { return g_app ? (int)pga_set_tool(g_app, (pga_tool)tool) : PG_ERR_NULL; }
EXPORT int pgw_get_tool(void) { return g_app ? (int)pga_get_tool(g_app) : 0; }
EXPORT const char *pgw_tool_name(int tool) { return pga_tool_name((pga_tool)tool); }
EXPORT int pgw_tool_count(void) { return PGA_TOOL_COUNT; }

/* All parameters at once, as pga_set_params validates them together. */
EXPORT int pgw_set_params(pg_fix radius, pg_fix width, pg_fix height, pg_fix density, pg_fix friction,
                          pg_fix restitution, uint32_t color, int nudge)
{
    pga_params p;
    if (!g_app) return PG_ERR_NULL;
    p = pga_get_params(g_app);
    p.radius = radius;
    p.width = width;
    p.height = height;
    p.density = density;
    p.friction = friction;
    p.restitution = restitution;
    p.color = color & 0xFFFFFFu;
    p.nudge = nudge;
    return (int)pga_set_params(g_app, &p);
}

/* The spring tool's frequency (Hz) and damping ratio, Q16.16, validated with the rest. */
EXPORT int pgw_set_spring(pg_fix hertz, pg_fix damping_ratio)
{
    pga_params p;
    if (!g_app) return PG_ERR_NULL;
    p = pga_get_params(g_app);
    p.spring_hertz = hertz;
    p.spring_damping = damping_ratio;
    return (int)pga_set_params(g_app, &p);
}

/* One parameter of the app's current set: 0 radius, 1 width, 2 height, 3 density,
 * 4 friction, 5 restitution, 6 colour, 7 nudge, 8 spring hertz, 9 spring damping ratio;
 * of the defaults when `defaults`. */
EXPORT int32_t pgw_param(int which, int defaults)
{
    pga_params p;
    if (defaults || !g_app) p = pga_default_params();
    else p = pga_get_params(g_app);
    switch (which) {
    case 0: return p.radius;
    case 1: return p.width;
    case 2: return p.height;
    case 3: return p.density;
    case 4: return p.friction;
    case 5: return p.restitution;
    case 6: return (int32_t)p.color;
    case 7: return p.nudge;
    case 8: return p.spring_hertz;
    case 9: return p.spring_damping;
    default: return 0;
    }
}

/* ---- input ------------------------------------------------------------------------------- */
/* phase: 0 down, 1 move, 2 up; x, y in Q16.16 metres (y up). */
EXPORT void pgw_pointer(int phase, pg_fix x, pg_fix y)
{
    pg_vec2 p = pg_v2(x, y);
    if (!g_app) return;
    if (phase == 0) pga_pointer_down(g_app, p);
    else if (phase == 1) pga_pointer_move(g_app, p);
    else pga_pointer_up(g_app, p);
}

EXPORT void pgw_key(int key, int down)
{
    if (g_app && key >= 0 && key < PGA_KEY_COUNT) pga_key(g_app, (pga_key_code)key, down != 0);
}

/* ---- actions ------------------------------------------------------------------------------ */
EXPORT int pgw_toggle_gravity(void) { return g_app ? (int)pga_toggle_gravity(g_app) : PG_ERR_NULL; }
EXPORT int pgw_set_effects(uint32_t effects) { return g_app ? (int)pga_set_effects(g_app, effects) : PG_ERR_NULL; }
EXPORT void pgw_set_paused(int paused) { if (g_app) pga_set_paused(g_app, paused != 0); }
EXPORT int pgw_paused(void) { return g_app ? pga_paused(g_app) : 1; }
EXPORT void pgw_step_once(void) { if (g_app) pga_step_once(g_app); }
EXPORT int pgw_set_preset(int preset) { return g_app ? (int)pga_set_preset(g_app, (pga_preset)preset) : PG_ERR_NULL; }
EXPORT int pgw_get_preset(void) { return g_app ? (int)pga_get_preset(g_app) : 0; }

EXPORT uint32_t pgw_selected_index(void) { return g_app ? pga_selected(g_app).index : 0; }
EXPORT uint32_t pgw_selected_generation(void) { return g_app ? pga_selected(g_app).generation : 0; }
EXPORT int pgw_select(uint32_t index, uint32_t generation)
{
    pg_body_id id;
    if (!g_app) return PG_ERR_NULL;
    id.index = index;
    id.generation = generation;
    return (int)pga_select(g_app, id);
}
EXPORT int pgw_set_selected_material(pg_fix density, pg_fix friction, pg_fix restitution)
{
    return g_app ? (int)pga_set_selected_material(g_app, density, friction, restitution) : PG_ERR_NULL;
}

/* ---- time --------------------------------------------------------------------------------- */
EXPORT int pgw_frame(void) { return g_app ? pga_frame(g_app) : 0; }
/* Frame numbers stay below 2^32 in any session a page can hold (2 years at 60 Hz). */
EXPORT uint32_t pgw_frame_number(void) { return g_app ? (uint32_t)pga_frame_number(g_app) : 0; }

/* ---- the world, read only ----------------------------------------------------------------- */
static const pg_world *world_of_app(void) { return g_app ? pga_world(g_app) : NULL; }

EXPORT uint32_t pgw_step_hz(void)
{
    const pg_world *w = world_of_app();
    return w ? pg_world_get_def(w).step_hz : 60u;
}
/* The effect switches as queued (what the next frame applies), for the checkboxes. */
EXPORT uint32_t pgw_effects(void) { return g_app ? pga_effects(g_app) : 0u; }
EXPORT int pgw_gravity_enabled(void) { return g_app ? pga_gravity_enabled(g_app) : 0; }
EXPORT pg_fix pgw_gravity(int axis)
{
    const pg_world *w = world_of_app();
    pg_vec2 g;
    if (!w) return 0;
    g = pg_world_gravity(w);
    return axis ? g.y : g.x;
}
EXPORT uint32_t pgw_awake_count(void)
{
    const pg_world *w = world_of_app();
    return w ? pg_world_get_stats(w).awake_body_count : 0u;
}

/* A body's centre of mass (component 0, 1), origin (2, 3), linear velocity (4, 5) in
 * Q16.16, angle as a binary angle (6), angular velocity (7), type (8), awake (9). */
EXPORT int32_t pgw_body(uint32_t index, uint32_t generation, int what)
{
    const pg_world *w = world_of_app();
    pg_body_id id;
    id.index = index;
    id.generation = generation;
    if (!w || !pg_body_is_valid(w, id)) return 0;
    switch (what) {
    case 0: return pg_body_world_center(w, id).x;
    case 1: return pg_body_world_center(w, id).y;
    case 2: return pg_body_position(w, id).x;
    case 3: return pg_body_position(w, id).y;
    case 4: return pg_body_linear_velocity(w, id).x;
    case 5: return pg_body_linear_velocity(w, id).y;
    case 6: return (int32_t)pg_body_angle(w, id);
    case 7: return pg_body_angular_velocity(w, id);
    case 8: return (int32_t)pg_body_type_of(w, id);
    case 9: return pg_body_is_awake(w, id);
    default: return 0;
    }
}
/* A body's mass (Q16.16 kg, 0 for static and kinematic bodies) and colour as drawn,
 * from the app's body info: 0 mass, 1 colour. */
EXPORT int32_t pgw_body_info(uint32_t index, uint32_t generation, int what)
{
    pga_body_info info;
    pg_body_id id;
    id.index = index;
    id.generation = generation;
    if (!g_app || pga_get_body_info(g_app, id, &info) != PG_OK) return 0;
    return what == 0 ? info.mass : (int32_t)info.color;
}
EXPORT int pgw_set_selected_color(uint32_t color) { return g_app ? (int)pga_set_selected_color(g_app, color) : PG_ERR_NULL; }

/* ---- drawing ------------------------------------------------------------------------------- */
static uint32_t g_draw_count;

EXPORT const pga_draw_shape *pgw_draw_list(void)
{
    g_draw_count = 0;
    return g_app ? pga_draw_list(g_app, &g_draw_count) : NULL;
}
EXPORT uint32_t pgw_draw_count(void) { return g_draw_count; }

/* Byte offsets of pga_draw_shape's fields: 0 size, 1 body.index, 2 body.generation,
 * 3 kind, 4 count, 5 vertices, 6 radius, 7 color, 8 flags; 9 sizeof(pg_vec2). */
EXPORT int pgw_draw_layout(int which)
{
    switch (which) {
    case 0: return (int)sizeof(pga_draw_shape);
    case 1: return (int)(offsetof(pga_draw_shape, body) + offsetof(pg_body_id, index));
    case 2: return (int)(offsetof(pga_draw_shape, body) + offsetof(pg_body_id, generation));
    case 3: return (int)offsetof(pga_draw_shape, kind);
    case 4: return (int)offsetof(pga_draw_shape, count);
    case 5: return (int)offsetof(pga_draw_shape, vertices);
    case 6: return (int)offsetof(pga_draw_shape, radius);
    case 7: return (int)offsetof(pga_draw_shape, color);
    case 8: return (int)offsetof(pga_draw_shape, flags);
    case 9: return (int)sizeof(pg_vec2);
    default: return -1;
    }
}

static uint32_t g_joint_draw_count;

EXPORT const pga_draw_joint *pgw_draw_joints(void)
{
    g_joint_draw_count = 0;
    return g_app ? pga_draw_joints(g_app, &g_joint_draw_count) : NULL;
}
EXPORT uint32_t pgw_joint_draw_count(void) { return g_joint_draw_count; }
EXPORT uint32_t pgw_joint_count(void) { return g_app ? pga_joint_count(g_app) : 0u; }

/* Byte offsets of pga_draw_joint's fields: 0 size, 1 type, 2 spring, 3 a, 4 b,
 * 5 origin_a, 6 origin_b, 7 color (a pg_vec2 is x then y, int32 each). */
EXPORT int pgw_joint_layout(int which)
{
    switch (which) {
    case 0: return (int)sizeof(pga_draw_joint);
    case 1: return (int)offsetof(pga_draw_joint, type);
    case 2: return (int)offsetof(pga_draw_joint, spring);
    case 3: return (int)offsetof(pga_draw_joint, a);
    case 4: return (int)offsetof(pga_draw_joint, b);
    case 5: return (int)offsetof(pga_draw_joint, origin_a);
    case 6: return (int)offsetof(pga_draw_joint, origin_b);
    case 7: return (int)offsetof(pga_draw_joint, color);
    default: return -1;
    }
}

static uint32_t g_pending_count;
EXPORT const pg_vec2 *pgw_pending_points(void)
{
    g_pending_count = 0;
    return g_app ? pga_pending_points(g_app, &g_pending_count) : NULL;
}
EXPORT uint32_t pgw_pending_count(void) { return g_pending_count; }

EXPORT const char *pgw_message(void) { return g_app ? pga_message(g_app) : ""; }
EXPORT uint32_t pgw_message_serial(void) { return g_app ? pga_message_serial(g_app) : 0u; }
/* 0 info, 1 refused, 2 error (pga_message_level). */
EXPORT int pgw_message_level(void) { return g_app ? (int)pga_message_level_of(g_app) : 0; }

/* ---- recording and playback ---------------------------------------------------------------- */
/* Pointer to the finished replay of the session (size in pgw_recording_size), or 0. */
EXPORT const uint8_t *pgw_recording(void)
{
    const uint8_t *data = NULL;
    g_recording_size = 0;
    if (!g_app || pga_recording(g_app, &data, &g_recording_size) != PG_OK) {
        g_recording_size = 0;
        return NULL;
    }
    return data;
}
EXPORT uint32_t pgw_recording_size(void) { return (uint32_t)g_recording_size; }

/* `data` comes from malloc in the page. On success the binding keeps it (the app plays
 * from it) and frees the replay played before; on failure it is freed at once. */
EXPORT int pgw_play_replay(uint8_t *data, int size)
{
    pg_result r;
    if (!g_app || size < 0) {
        free(data);
        return PG_ERR_NULL;
    }
    r = pga_play_replay(g_app, data, (size_t)size);
    if (r != PG_OK) {
        free(data);
        return (int)r;
    }
    free(g_replay);
    g_replay = data;
    g_recorded_with[0] = '\0';
    {
        pg_replay_info info;
        char config[96];
        if (pg_replay_read(data, (size_t)size, &info, NULL) == PG_OK) {
            pg_numeric_config_describe(info.numeric_config, config, sizeof config);
            snprintf(g_recorded_with, sizeof g_recorded_with, "pogon %u.%u.%u, %s", info.engine_major,
                     info.engine_minor, info.engine_patch, config);
        }
    }
    return PG_OK;
}

/* What recorded the replay being played: "pogon 0.2.0, a 12-bit sine table" (its engine
 * version and numeric configuration, from its header, read when it was loaded), or "". */
EXPORT const char *pgw_replay_recorded_with(void) { return g_recorded_with; }

/* 0 active, 1 frame, 2 frame_count, 3 checkpoints_checked, 4 checkpoints_failed,
 * 5 last_match, 6 section_mismatch. */
EXPORT int32_t pgw_playback(int which)
{
    pga_playback s;
    if (!g_app) return 0;
    s = pga_playback_state(g_app);
    switch (which) {
    case 0: return s.active;
    case 1: return (int32_t)s.frame;
    case 2: return (int32_t)s.frame_count;
    case 3: return (int32_t)s.checkpoints_checked;
    case 4: return (int32_t)s.checkpoints_failed;
    case 5: return s.last_match;
    case 6: return (int32_t)s.section_mismatch;
    default: return 0;
    }
}
EXPORT int pgw_stop_playback(void) { return g_app ? (int)pga_stop_playback(g_app) : PG_ERR_NULL; }

/* ---- numbers for the UI ---------------------------------------------------------------------- */
EXPORT const char *pgw_state_hash(void)
{
    uint64_t h = g_app ? pga_state_hash(g_app) : 0u;
    snprintf(g_hash_text, sizeof g_hash_text, "%08x%08x", (unsigned)(h >> 32), (unsigned)(h & 0xFFFFFFFFu));
    return g_hash_text;
}
EXPORT uint32_t pgw_body_count(void) { return g_app ? pga_body_count(g_app) : 0u; }
EXPORT const char *pgw_result_name(int r) { return pg_result_name((pg_result)r); }
