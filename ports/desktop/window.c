/* window.c — the SDL2 window (keys and mouse in docs/desktop.md).
 *
 * Live mode: SDL events become pga_* calls, pga_frame() runs at the world's step rate
 * from a time accumulator, the app's draw list is drawn, and the recorder writes the
 * session once a second. Playback mode: a replay_seek player, its world drawn through
 * world_draw, with pause, step, speed and jumps (a jump runs in slices under a progress
 * bar). The interaction logic is the app's; this file only routes input and draws.
 */
#define _POSIX_C_SOURCE 200809L
#include "window.h"

#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file_io.h"
#include "input_script.h"
#include "overlay.h"
#include "recorder.h"
#include "render.h"
#include "replay_seek.h"
#include "scene_list.h"
#include "scene_name.h"
#include "view.h"
#include "world_draw.h"

#ifndef POGON_SCENES_DIR
#define POGON_SCENES_DIR "scenes"
#endif

#define SLICE_SECONDS 0.05       /* time a drawn frame may spend re-stepping a jump or fast playback */
#define SLICE_FRAMES 8u          /* frames between two looks at the clock */
#define MAX_STEPS_PER_DRAW 8     /* live mode catches up at most this many steps a frame */

typedef struct desktop_window {
    const desktop_options *o;
    SDL_Window *window;
    SDL_Renderer *renderer;
    char renderer_name[64];
    desktop_view view;
    pga_app *app;
    desktop_recorder recorder;
    desktop_scene_list scenes;
    int scene_index;
    pga_seek *seek;              /* non-NULL: playback mode */
    char replay_name[256];
    int replay_paused;
    double speed, play_accumulator, accumulator, now;
    pga_draw_shape *shapes;
    uint32_t shape_capacity;
    char notice[300];            /* the port's own message (files); shown when newer than the app's */
    uint32_t notice_app_serial;
    uint32_t echoed_serial;      /* the app message last printed */
    int step_requested;          /* N while paused: step in this drawn frame, whatever the clock */
    int screenshot_due;
    int quit;
    uint64_t frames_drawn;
} desktop_window;

static double seconds(void) { return (double)SDL_GetPerformanceCounter() / (double)SDL_GetPerformanceFrequency(); }

static void notice(desktop_window *w, const char *text)
{
    snprintf(w->notice, sizeof w->notice, "%s", text);
    w->notice_app_serial = w->app != NULL ? pga_message_serial(w->app) : 0;
    if (!w->o->quiet) printf("pogon-desktop: %s\n", text);
    fflush(stdout);
}

/* ---- files ------------------------------------------------------------------------------ */
static int load_scene_file(desktop_window *w, const char *path)
{
    uint8_t *text;
    size_t size;
    char why[400], name[128];
    if (!desktop_read_file(path, &text, &size, why, sizeof why)) {
        notice(w, why);
        return 0;
    }
    /* Loading restarts the app's recording: write the one that ends here first. */
    if (w->recorder.path[0] != '\0') desktop_recorder_tick(&w->recorder, w->app, w->now, 1);
    desktop_scene_name(path, name, sizeof name);
    if (pga_load_scene(w->app, name, (const char *)text, size) != PG_OK) {
        snprintf(why, sizeof why, "%s: %s", path, pga_message(w->app));
        notice(w, why);
        free(text);
        return 0;
    }
    free(text);
    return 1;
}

static int open_replay(desktop_window *w, const char *path)
{
    uint8_t *data;
    size_t size;
    char why[600];
    pga_seek *s;
    if (!desktop_read_file(path, &data, &size, why, sizeof why)) {
        notice(w, why);
        return 0;
    }
    if (pga_seek_open(data, size, &s, why, sizeof why) != PG_OK) {
        char line[700];
        snprintf(line, sizeof line, "%s is not a replay that can be played: %s", path, why);
        notice(w, line);
        free(data);
        return 0;
    }
    free(data);
    pga_seek_close(w->seek);
    w->seek = s;
    snprintf(w->replay_name, sizeof w->replay_name, "%s", path);
    w->replay_paused = 0;
    w->speed = 1.0;
    w->play_accumulator = 0.0;
    snprintf(why, sizeof why, "playing %s (%u frames)", path, pga_seek_info(s)->frame_count);
    notice(w, why);
    return 1;
}

static void open_dropped(desktop_window *w, const char *path)
{
    size_t n = strlen(path);
    if (n > 6 && strcmp(path + n - 6, ".scene") == 0) {
        pga_seek_close(w->seek);
        w->seek = NULL;
        load_scene_file(w, path);
    } else {
        open_replay(w, path);
    }
}

static void take_screenshot(desktop_window *w, uint64_t frame)
{
    SDL_Surface *s = SDL_CreateRGBSurfaceWithFormat(0, w->view.width, w->view.height, 32, SDL_PIXELFORMAT_ARGB8888);
    char path[1100], line[1200];
    if (s == NULL) return;
    snprintf(path, sizeof path, "%s-%llu.bmp", w->o->screenshot_path != NULL ? w->o->screenshot_path : "pogon-shot",
             (unsigned long long)frame);
    if (SDL_RenderReadPixels(w->renderer, NULL, SDL_PIXELFORMAT_ARGB8888, s->pixels, s->pitch) != 0 ||
        SDL_SaveBMP(s, path) != 0) {
        snprintf(line, sizeof line, "screenshot not written: %s", SDL_GetError());
    } else {
        snprintf(line, sizeof line, "screenshot of frame %llu written to %s", (unsigned long long)frame, path);
    }
    SDL_FreeSurface(s);
    notice(w, line);
}

/* ---- input ------------------------------------------------------------------------------- */
static int app_key_of(SDL_Keycode k, pga_key_code *out)
{
    switch (k) {
    case SDLK_LEFT: case SDLK_a: *out = PGA_KEY_LEFT; return 1;
    case SDLK_RIGHT: case SDLK_d: *out = PGA_KEY_RIGHT; return 1;
    case SDLK_UP: case SDLK_w: *out = PGA_KEY_UP; return 1;
    case SDLK_DOWN: case SDLK_s: *out = PGA_KEY_DOWN; return 1;
    case SDLK_q: *out = PGA_KEY_SPIN_CCW; return 1;
    case SDLK_e: *out = PGA_KEY_SPIN_CW; return 1;
    default: return 0;
    }
}

static void scale_sizes(desktop_window *w, int larger)
{
    pga_params p = pga_get_params(w->app);
    pg_fix num = larger ? 5 : 4, den = larger ? 4 : 5;
    p.radius = (pg_fix)((int64_t)p.radius * num / den);
    p.width = (pg_fix)((int64_t)p.width * num / den);
    p.height = (pg_fix)((int64_t)p.height * num / den);
    pga_set_params(w->app, &p);
}

/* 1..8 the body tools in pga_tool order, 9 pin, 0 rod, - spring; -1 for other keys. */
static int tool_of_key(SDL_Keycode c)
{
    if (c >= SDLK_1 && c <= SDLK_9) return (int)(c - SDLK_1);
    if (c == SDLK_0) return PGA_TOOL_ROD;
    if (c == SDLK_MINUS) return PGA_TOOL_SPRING;
    return -1;
}

static const char *key_of_tool(pga_tool t)
{
    static const char *const keys[PGA_TOOL_COUNT] = {"1", "2", "3", "4", "5", "6", "7", "8", "9", "0", "-"};
    return (unsigned)t < PGA_TOOL_COUNT ? keys[t] : "?";
}

/* The spring tool's frequency by 4/5 or 5/4 (`,` and `.`), within what the app takes. */
static void scale_spring(desktop_window *w, int stiffer)
{
    pga_params p = pga_get_params(w->app);
    char line[96], hz[PG_FIX_FORMAT_MAX], ratio[PG_FIX_FORMAT_MAX];
    p.spring_hertz = (pg_fix)((int64_t)p.spring_hertz * (stiffer ? 5 : 4) / (stiffer ? 4 : 5));
    if (pga_set_params(w->app, &p) != PG_OK) return;
    pg_fix_format(p.spring_hertz, hz, sizeof hz);
    pg_fix_format(p.spring_damping, ratio, sizeof ratio);
    snprintf(line, sizeof line, "spring %s Hz, damping ratio %s", hz, ratio);
    notice(w, line);
}

static void live_key(desktop_window *w, const SDL_KeyboardEvent *k)
{
    SDL_Keycode c = k->keysym.sym;
    pga_key_code key;
    if (app_key_of(c, &key)) {
        if (!k->repeat) pga_key(w->app, key, k->type == SDL_KEYDOWN);
        return;
    }
    if (k->type != SDL_KEYDOWN || k->repeat) return;
    if (tool_of_key(c) >= 0) {
        char line[64];
        pga_set_tool(w->app, (pga_tool)tool_of_key(c));
        snprintf(line, sizeof line, "tool %s", pga_tool_name(pga_get_tool(w->app)));
        notice(w, line);
    } else if (c == SDLK_COMMA || c == SDLK_PERIOD) {
        scale_spring(w, c == SDLK_PERIOD);
    } else if (c >= SDLK_F1 && c <= SDLK_F7) {
        pga_set_effects(w->app, pga_effects(w->app) ^ pga_effect_bit((uint32_t)(c - SDLK_F1)));
    } else if (c == SDLK_F9 || c == SDLK_F10 || c == SDLK_F11) {
        desktop_recorder_tick(&w->recorder, w->app, w->now, 1); /* a preset restarts the recording */
        pga_set_preset(w->app, (pga_preset)(c - SDLK_F9));
    } else if (c == SDLK_g) {
        pga_toggle_gravity(w->app);
    } else if (c == SDLK_p || c == SDLK_SPACE) {
        pga_set_paused(w->app, !pga_paused(w->app));
    } else if (c == SDLK_n) {
        if (!pga_paused(w->app)) pga_set_paused(w->app, 1);
        pga_step_once(w->app);
        w->step_requested = 1;
    } else if (c == SDLK_u) {
        pga_params p = pga_get_params(w->app);
        p.nudge = !p.nudge;
        pga_set_params(w->app, &p);
    } else if (c == SDLK_LEFTBRACKET || c == SDLK_RIGHTBRACKET) {
        scale_sizes(w, c == SDLK_RIGHTBRACKET);
    } else if (c == SDLK_TAB && w->scenes.count > 0) {
        int step = (k->keysym.mod & KMOD_SHIFT) ? w->scenes.count - 1 : 1;
        w->scene_index = (w->scene_index + step) % w->scenes.count;
        load_scene_file(w, w->scenes.paths[w->scene_index]);
    }
}

static void playback_jump(desktop_window *w, int64_t target)
{
    uint32_t last = pga_seek_info(w->seek)->frame_count;
    if (target < 0) target = 0;
    if (target > (int64_t)last) target = last;
    if (pga_seek_jump(w->seek, (uint32_t)target) != PG_OK) notice(w, pga_seek_error(w->seek));
}

static void playback_key(desktop_window *w, const SDL_KeyboardEvent *k)
{
    pga_seek_status st = pga_seek_get_status(w->seek);
    SDL_Keycode c = k->keysym.sym;
    if (k->type != SDL_KEYDOWN) return;
    if (c == SDLK_SPACE || c == SDLK_p) {
        w->replay_paused = !w->replay_paused;
    } else if (c == SDLK_n || c == SDLK_RIGHT) {
        w->replay_paused = 1;
        playback_jump(w, (int64_t)st.frame + 1);
    } else if (c == SDLK_LEFT) {
        w->replay_paused = 1;
        playback_jump(w, (int64_t)st.frame - 1);
    } else if (c == SDLK_PLUS || c == SDLK_EQUALS || c == SDLK_KP_PLUS) {
        if (w->speed < 64.0) w->speed *= 2.0;
    } else if (c == SDLK_MINUS || c == SDLK_KP_MINUS) {
        if (w->speed > 1.0 / 16.0) w->speed *= 0.5;
    } else if (c == SDLK_HOME) {
        playback_jump(w, 0);
    } else if (c == SDLK_END) {
        playback_jump(w, st.frame_count);
    } else if (c == SDLK_PAGEUP) {
        playback_jump(w, (int64_t)st.frame - 600);
    } else if (c == SDLK_PAGEDOWN) {
        playback_jump(w, (int64_t)st.frame + 600);
    } else if (c == SDLK_l) {
        pga_seek_close(w->seek);
        w->seek = NULL;
        notice(w, "back to live mode");
    }
}

static void handle_event(desktop_window *w, const SDL_Event *e)
{
    switch (e->type) {
    case SDL_QUIT: w->quit = 1; break;
    case SDL_DROPFILE:
        open_dropped(w, e->drop.file);
        SDL_free(e->drop.file);
        break;
    case SDL_KEYDOWN:
    case SDL_KEYUP:
        if (e->key.keysym.sym == SDLK_ESCAPE && e->type == SDL_KEYDOWN) w->quit = 1;
        else if (e->key.keysym.sym == SDLK_F12 && e->type == SDL_KEYDOWN) w->screenshot_due = 1;
        else if (w->seek != NULL) playback_key(w, &e->key);
        else live_key(w, &e->key);
        break;
    case SDL_MOUSEBUTTONDOWN:
        if (e->button.button != SDL_BUTTON_LEFT) break;
        if (w->seek != NULL) {
            if (e->button.y >= w->view.height - DESKTOP_TIMELINE_HEIGHT)
                playback_jump(w, (int64_t)((double)e->button.x / (w->view.width - 1) * pga_seek_info(w->seek)->frame_count + 0.5));
        } else {
            pga_pointer_down(w->app, desktop_view_to_world(&w->view, e->button.x, e->button.y));
        }
        break;
    case SDL_MOUSEMOTION:
        if (w->seek == NULL) pga_pointer_move(w->app, desktop_view_to_world(&w->view, e->motion.x, e->motion.y));
        break;
    case SDL_MOUSEBUTTONUP:
        if (e->button.button == SDL_BUTTON_LEFT && w->seek == NULL)
            pga_pointer_up(w->app, desktop_view_to_world(&w->view, e->button.x, e->button.y));
        break;
    default: break;
    }
}

/* ---- time --------------------------------------------------------------------------------- */
static void advance_live(desktop_window *w, double dt)
{
    uint32_t hz = pg_world_get_def(pga_world(w->app)).step_hz;
    double step = 1.0 / (double)(hz != 0 ? hz : 60u);
    int n = 0;
    if (w->step_requested) {
        w->step_requested = 0;
        pga_frame(w->app); /* paused: the requested single step */
        return;
    }
    if (w->o->bench_seconds > 0.0) {
        pga_frame(w->app); /* one step a drawn frame: frames per second are steps per second */
        return;
    }
    w->accumulator += dt;
    while (w->accumulator >= step && n < MAX_STEPS_PER_DRAW) {
        pga_frame(w->app);
        w->accumulator -= step;
        n++;
    }
    if (n == MAX_STEPS_PER_DRAW) w->accumulator = 0.0; /* too slow to keep up: slow down instead of spiralling */
}

static void advance_playback(desktop_window *w, double dt)
{
    pga_seek_status st = pga_seek_get_status(w->seek);
    uint32_t hz = pg_world_get_def(pga_seek_world(w->seek)).step_hz, n = 0;
    double until = seconds() + SLICE_SECONDS;
    if (st.seeking) {
        /* A slice of the jump, then a drawn frame with the progress bar. */
        int arrived;
        while (!(arrived = pga_seek_advance(w->seek, SLICE_FRAMES)) && seconds() < until) {
        }
        if (arrived) {
            char line[64];
            snprintf(line, sizeof line, "jumped to frame %u", pga_seek_get_status(w->seek).frame);
            notice(w, line);
        }
        return;
    }
    if (w->replay_paused) return;
    w->play_accumulator += dt * w->speed * (double)(hz != 0 ? hz : 60u);
    while (w->play_accumulator >= 1.0) {
        if (!pga_seek_step(w->seek)) {
            w->replay_paused = 1;
            w->play_accumulator = 0.0;
            return;
        }
        w->play_accumulator -= 1.0;
        if (++n % SLICE_FRAMES == 0u && seconds() >= until) {
            w->play_accumulator = 0.0; /* faster than this machine can play: drop the backlog */
            break;
        }
    }
}

/* ---- drawing ------------------------------------------------------------------------------- */
static void section_names(uint32_t mask, char *out, size_t capacity)
{
    int s;
    size_t len = 0;
    out[0] = '\0';
    for (s = 0; s < PG_SECTION_COUNT; ++s)
        if (mask & (1u << s)) len += (size_t)snprintf(out + len, len < capacity ? capacity - len : 0, "%s%s", len ? "," : "", pg_section_name((pg_section)s));
}

static void draw_live(desktop_window *w)
{
    uint32_t count = 0, pending_count = 0, i;
    const pga_draw_shape *shapes = pga_draw_list(w->app, &count);
    const pg_vec2 *pending = pga_pending_points(w->app, &pending_count);
    uint32_t joint_count = 0;
    const pga_draw_joint *joints = pga_draw_joints(w->app, &joint_count);
    pga_params p = pga_get_params(w->app);
    char l1[256], l2[256], l3[320], effects[96];
    const char *lines[3];
    size_t len = 0;
    desktop_render_shapes(w->renderer, &w->view, shapes, count);
    desktop_render_joints(w->renderer, &w->view, joints, joint_count);
    desktop_render_pending(w->renderer, &w->view, pending, pending_count);
    for (i = 0; i < pga_effect_count(); ++i)
        len += (size_t)snprintf(effects + len, len < sizeof effects ? sizeof effects - len : 0, "F%u %s%s ", i + 1,
                                pga_effect_name(i), (pga_effects(w->app) & pga_effect_bit(i)) ? "+" : "-");
    snprintf(l1, sizeof l1, "LIVE %s | tool %s %s | frame %llu | bodies %u | joints %u | %s | preset %s | gravity %s | nudge %s",
             pga_scene_name(w->app), key_of_tool(pga_get_tool(w->app)), pga_tool_name(pga_get_tool(w->app)),
             (unsigned long long)pga_frame_number(w->app), pga_body_count(w->app), joint_count, pga_paused(w->app) ? "PAUSED" : "running",
             pga_preset_name(pga_get_preset(w->app)), pga_gravity_enabled(w->app) ? "on" : "off", p.nudge ? "on" : "off");
    snprintf(l2, sizeof l2, "%s| rec %s", effects, w->recorder.path);
    if (w->notice[0] != '\0' && w->notice_app_serial == pga_message_serial(w->app)) snprintf(l3, sizeof l3, "%s", w->notice);
    else snprintf(l3, sizeof l3, "%s", pga_message(w->app));
    lines[0] = l1;
    lines[1] = l2;
    lines[2] = l3;
    desktop_overlay_text(w->renderer, w->view.width, lines, 3);
}

/* The joints of the replay's world, over its bodies as in live mode. */
static void draw_replay_joints(desktop_window *w)
{
    uint32_t n = pga_world_draw_joints(pga_seek_world(w->seek), NULL, 0);
    pga_draw_joint *joints;
    if (n == 0) return;
    joints = (pga_draw_joint *)malloc((size_t)n * sizeof *joints);
    if (joints == NULL) return;
    n = pga_world_draw_joints(pga_seek_world(w->seek), joints, n);
    desktop_render_joints(w->renderer, &w->view, joints, n);
    free(joints);
}

static void draw_playback(desktop_window *w)
{
    pga_seek_status st = pga_seek_get_status(w->seek);
    uint32_t count = pga_world_draw_shapes(pga_seek_world(w->seek), NULL, 0);
    char l1[320], l2[320], l3[320], sections[96];
    const char *lines[3];
    if (count > w->shape_capacity) {
        pga_draw_shape *n = (pga_draw_shape *)realloc(w->shapes, (size_t)count * sizeof *n);
        if (n != NULL) {
            w->shapes = n;
            w->shape_capacity = count;
        }
    }
    count = pga_world_draw_shapes(pga_seek_world(w->seek), w->shapes, w->shape_capacity);
    if (count > w->shape_capacity) count = w->shape_capacity;
    desktop_render_shapes(w->renderer, &w->view, w->shapes, count);
    draw_replay_joints(w);
    if (st.seeking)
        snprintf(l1, sizeof l1, "PLAY %s | JUMPING to frame %u: %u of %u frames re-stepped", w->replay_name, st.seek_target,
                 st.frame - st.seek_from, st.seek_target - st.seek_from);
    else
        snprintf(l1, sizeof l1, "PLAY %s | frame %u / %u | speed %gx | %s", w->replay_name, st.frame, st.frame_count,
                 w->speed, w->replay_paused ? "PAUSED" : "playing");
    section_names(st.last_section_mismatch, sections, sizeof sections);
    if (st.last_match < 0)
        snprintf(l2, sizeof l2, "no checkpoint compared yet | %u checkpoints in the file", st.checkpoint_count);
    else
        snprintf(l2, sizeof l2, "checkpoint at frame %u: %s%s | %u of %u compared, %u diverged", st.last_checkpoint_frame,
                 st.last_match ? "hash matches" : "DIVERGED in ", st.last_match ? "" : sections, st.checkpoints_checked,
                 st.checkpoint_count, st.checkpoints_failed);
    if (w->notice[0] != '\0' && strncmp(w->notice, "playing ", 8) != 0) snprintf(l3, sizeof l3, "%s", w->notice);
    else snprintf(l3, sizeof l3, "Space pause  N/Right step  Left back  +/- speed  Home/End PgUp/PgDn jump  click the bar  L live");
    lines[0] = l1;
    lines[1] = l2;
    lines[2] = l3;
    desktop_overlay_text(w->renderer, w->view.width, lines, 3);
    desktop_overlay_timeline(w->renderer, w->view.width, w->view.height,
                             st.frame_count ? (double)st.frame / st.frame_count : 1.0,
                             st.seeking && st.frame_count ? (double)st.seek_target / st.frame_count : -1.0,
                             st.checkpoints_failed ? 0xdc2626u : 0x16a34au);
}

static void draw(desktop_window *w)
{
    uint64_t frame = w->seek != NULL ? pga_seek_get_status(w->seek).frame : pga_frame_number(w->app);
    desktop_render_clear(w->renderer);
    if (w->seek != NULL) draw_playback(w);
    else draw_live(w);
    if (w->screenshot_due) {
        w->screenshot_due = 0;
        take_screenshot(w, frame);
    }
    SDL_RenderPresent(w->renderer);
    w->frames_drawn++;
}

/* ---- life ----------------------------------------------------------------------------------- */
static int open_window(desktop_window *w)
{
    SDL_RendererInfo info;
    Uint32 flags = w->o->bench_seconds > 0.0 ? 0u : SDL_RENDERER_PRESENTVSYNC;
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
        fprintf(stderr, "pogon-desktop: no window (SDL: %s); use --headless without a display\n", SDL_GetError());
        return 0;
    }
    SDL_EventState(SDL_DROPFILE, SDL_ENABLE);
    w->window = SDL_CreateWindow("pogon", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w->view.width, w->view.height, 0);
    if (w->window == NULL) {
        fprintf(stderr, "pogon-desktop: SDL_CreateWindow: %s\n", SDL_GetError());
        return 0;
    }
    w->renderer = SDL_CreateRenderer(w->window, -1, flags);
    if (w->renderer == NULL) w->renderer = SDL_CreateRenderer(w->window, -1, SDL_RENDERER_SOFTWARE);
    if (w->renderer == NULL) {
        fprintf(stderr, "pogon-desktop: SDL_CreateRenderer: %s\n", SDL_GetError());
        return 0;
    }
    if (SDL_GetRendererInfo(w->renderer, &info) == 0) snprintf(w->renderer_name, sizeof w->renderer_name, "%s", info.name);
    return 1;
}

static int start_app(desktop_window *w)
{
    const char *scene = w->o->scene_path;
    char folder[1024];
    const char *slash;
    w->app = pga_create();
    if (w->app == NULL) {
        fprintf(stderr, "pogon-desktop: out of memory\n");
        return 0;
    }
    if (scene == NULL) scene = POGON_SCENES_DIR "/demo.scene";
    slash = strrchr(scene, '/');
    if (slash != NULL) snprintf(folder, sizeof folder, "%.*s", (int)(slash - scene), scene);
    else snprintf(folder, sizeof folder, ".");
    desktop_scene_list_read(&w->scenes, folder);
    w->scene_index = desktop_scene_list_find(&w->scenes, scene);
    if (w->scene_index < 0) w->scene_index = 0;
    if (!load_scene_file(w, scene)) {
        fprintf(stderr, "pogon-desktop: %s\n", w->notice);
        return 0;
    }
    if (w->o->effects != NULL) {
        desktop_script one;
        char line[200], why[300];
        snprintf(line, sizeof line, "0 effects %s\n", w->o->effects);
        if (!desktop_script_parse(line, strlen(line), &one, why, sizeof why) || one.count != 1) {
            fprintf(stderr, "pogon-desktop: --effects %s: %s\n", w->o->effects, why);
            return 0;
        }
        desktop_event_apply(w->app, &one.events[0]);
        desktop_script_free(&one);
    }
    desktop_recorder_start(&w->recorder, w->o->output_path, w->o->quiet);
    return 1;
}

int desktop_window_run(const desktop_options *o)
{
    desktop_window w;
    double start, last, bench_start = 0.0;
    uint64_t bench_frames0 = 0, bench_steps0 = 0;
    int status = 0;
    memset(&w, 0, sizeof w);
    w.o = o;
    w.speed = 1.0;
    w.view.center_x = o->view_x;
    w.view.center_y = o->view_y;
    w.view.scale = o->view_scale;
    w.view.width = o->width;
    w.view.height = o->height;
    if (!open_window(&w) || !start_app(&w)) {
        status = 2;
        goto done;
    }
    if (o->play_path != NULL && !open_replay(&w, o->play_path)) {
        fprintf(stderr, "pogon-desktop: %s\n", w.notice);
        status = 2;
        goto done;
    }
    if (!o->quiet) printf("pogon-desktop: renderer %s, %dx%d\n", w.renderer_name, w.view.width, w.view.height);
    fflush(stdout);
    start = last = seconds();
    w.now = 0.0;
    while (!w.quit) {
        SDL_Event e;
        double now, dt;
        now = seconds();
        w.now = now - start;
        while (SDL_PollEvent(&e)) handle_event(&w, &e);
        dt = now - last;
        last = now;
        if (dt > 0.25) dt = 0.25;
        if (w.seek != NULL) advance_playback(&w, dt);
        else advance_live(&w, dt);
        if (w.seek == NULL) desktop_recorder_tick(&w.recorder, w.app, now - start, 0);
        if (pga_message_serial(w.app) != w.echoed_serial) {
            /* The app's messages on the terminal too: a log of what the session did. */
            w.echoed_serial = pga_message_serial(w.app);
            if (!o->quiet) printf("pogon-desktop: frame %llu: %s\n", (unsigned long long)pga_frame_number(w.app), pga_message(w.app));
            fflush(stdout);
        }
        draw(&w);
        if (o->bench_seconds > 0.0) {
            /* The first second warms up; frames are counted after it. */
            if (bench_start == 0.0 && now - start >= 1.0) {
                bench_start = now;
                bench_frames0 = w.frames_drawn;
                bench_steps0 = pga_frame_number(w.app);
            } else if (bench_start != 0.0 && now - bench_start >= o->bench_seconds) {
                double secs = now - bench_start;
                printf("bench: %.1f frames per second (%llu frames drawn and %llu steps in %.2f s; scene %s, %u bodies, "
                       "%u awake, renderer %s, %dx%d)\n",
                       (double)(w.frames_drawn - bench_frames0) / secs,
                       (unsigned long long)(w.frames_drawn - bench_frames0),
                       (unsigned long long)(pga_frame_number(w.app) - bench_steps0), secs, pga_scene_name(w.app),
                       pga_body_count(w.app), pg_world_get_stats(pga_world(w.app)).awake_body_count, w.renderer_name,
                       w.view.width, w.view.height);
                w.quit = 1;
            }
        }
    }
    if (!desktop_recorder_finish(&w.recorder, w.app, seconds() - start)) status = 2;
done:
    pga_seek_close(w.seek);
    free(w.shapes);
    desktop_scene_list_free(&w.scenes);
    if (w.app != NULL) pga_destroy(w.app);
    if (w.renderer != NULL) SDL_DestroyRenderer(w.renderer);
    if (w.window != NULL) SDL_DestroyWindow(w.window);
    SDL_Quit();
    return status;
}
