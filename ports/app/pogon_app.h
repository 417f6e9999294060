/* pogon_app.h — the playground's interaction logic, shared by every front end.
 *
 * WHAT IT IS
 *   A physics playground in C99 that knows nothing of browsers or windows. It owns a
 *   pg_world made from a scene file, takes platform-neutral input (pointer and keys in
 *   world coordinates, UI actions), and says what to draw. A front end (ports/web,
 *   ports/desktop) only turns its events into these calls and draws pga_draw_list().
 *
 * DETERMINISM
 *   Every change the app makes to the world is a pg_command applied at the start of a
 *   frame and logged with that frame, so the session's log is a replay file in the
 *   pogon-replay format (pga_recording) that reproduces the session bit for bit on any
 *   target. Input that arrives between frames is queued and applied before the next
 *   step, in arrival order. Things that are not commands (the accuracy preset, loading
 *   a scene) restart the world and the recording from a scene text.
 *
 * HOW TO USE IT
 *     pga_app *app = pga_create();
 *     pga_load_scene(app, "demo", text, length);       // world + a new recording
 *     per display frame:
 *         (input) pga_pointer_down/move/up(app, world_point), pga_key(app, key, down), ...
 *         while (accumulator >= 1/60 s) { pga_frame(app); accumulator -= 1/60 s; }
 *         draw pga_draw_list(app), pga_pending_points(app), pga_message(app)
 *     pga_destroy(app);
 *
 * CONVENTIONS
 *   - Functions that can fail return pg_result and leave the app unchanged on failure;
 *     pga_message() then holds a sentence for the user ("Refused: the box would overlap
 *     another body").
 *   - The app allocates with malloc (it is a front end's helper, not the core).
 *   - Quantities are pg_fix (Q16.16) metres, kg/m^2, rad/s; colours are 0xRRGGBB.
 */
#ifndef POGON_APP_H
#define POGON_APP_H

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pogon/replay_file.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pga_app pga_app;

/* ---- life ------------------------------------------------------------------------------ */
pga_app *pga_create(void);            /* NULL when out of memory; no world until a scene loads */
void pga_destroy(pga_app *app);

/* Replace the world with the scene `text` (pogon scene file) and start a new recording
 * from it. `name` is kept for the UI (pga_scene_name). On failure the app keeps its
 * world and pga_message() holds the scene reader's error (line and column). */
pg_result pga_load_scene(pga_app *app, const char *name, const char *text, size_t length);
const char *pga_scene_name(const pga_app *app);
const pg_world *pga_world(const pga_app *app);   /* read-only: change it through the app */

/* ---- tools and parameters ----------------------------------------------------------------- */
typedef enum pga_tool {
    PGA_TOOL_MOVE = 0,     /* click selects the body under the pointer as the player; press and move drags it */
    PGA_TOOL_DELETE,       /* click removes the body under the pointer (static walls too) */
    PGA_TOOL_BALL,         /* one click: a ball of `radius` */
    PGA_TOOL_CAPSULE,      /* one click: a capsule `width` long (between cap centres) of `radius` */
    PGA_TOOL_BOX,          /* one click: a box `width` x `height` */
    PGA_TOOL_TRIANGLE,     /* three clicks: its vertices (either winding) */
    PGA_TOOL_STAR,         /* one click: a star of circumradius `radius` */
    PGA_TOOL_WALL,         /* two clicks: a static thin box from the first point to the second, `height` thick */
    PGA_TOOL_PIN,          /* two clicks: the body to pin, then the pin: a revolute joint there to the body under
                              it, or to the world (a shapeless static anchor) on empty space or on the first body */
    PGA_TOOL_ROD,          /* two clicks: a rigid distance joint between the two points (bodies, or one body and
                              empty space = the world) */
    PGA_TOOL_SPRING,       /* as the rod, with a spring of `spring_hertz` and `spring_damping` */
    PGA_TOOL_COUNT
} pga_tool;
const char *pga_tool_name(pga_tool tool);          /* "move", "delete", "ball", ... */

typedef struct pga_params {
    pg_fix radius;         /* ball, capsule, star; default 0.5 m */
    pg_fix width, height;  /* box; capsule length = width; wall thickness = height; default 1 x 1 m */
    pg_fix density, friction, restitution;  /* defaults 1, 0.6, 0 */
    uint32_t color;        /* 0xRRGGBB of new bodies */
    int nudge;             /* nonzero: an add that would overlap is placed at the nearest free spot
                              (pg_world_find_free_position) instead of being refused */
    pg_fix spring_hertz;   /* spring tool: frequency, Hz, (0, 1000]; default 4 (the core caps it at a quarter
                              of the substep rate) */
    pg_fix spring_damping; /* spring tool: damping ratio, 0..1000; default 0.3 */
} pga_params;
pga_params pga_default_params(void);

/* Changing the tool drops pending clicks. Parameters are validated (the envelope of
 * pogon.h); PG_ERR_ENVELOPE with a message leaves them unchanged. */
pg_result pga_set_tool(pga_app *app, pga_tool tool);
pga_tool pga_get_tool(const pga_app *app);
pg_result pga_set_params(pga_app *app, const pga_params *params);
pga_params pga_get_params(const pga_app *app);

/* ---- input (world coordinates, metres, y up) ----------------------------------------------- */
typedef enum pga_key_code {
    PGA_KEY_LEFT = 0, PGA_KEY_RIGHT, PGA_KEY_UP, PGA_KEY_DOWN,  /* W A S D and the arrows */
    PGA_KEY_SPIN_CCW, PGA_KEY_SPIN_CW,                          /* Q and E */
    PGA_KEY_COUNT
} pga_key_code;

/* A press: acts according to the tool (select, delete, add, collect a triangle's or a
 * wall's or a joint's point). The outcome is reported in pga_message(). */
void pga_pointer_down(pga_app *app, pg_vec2 point);
/* While a body picked with the move tool is held, each stepped frame drags it: a dynamic
 * body by a mouse joint at the pressed point whose target follows the pointer (a command
 * each frame the target changes), a kinematic body by a velocity toward the pointer.
 * Releasing ends the drag (the mouse joint is destroyed at the next step). */
void pga_pointer_move(pga_app *app, pg_vec2 point);
void pga_pointer_up(pga_app *app, pg_vec2 point);
/* Held keys push (force) or spin (torque) the selected body, as commands each frame. */
void pga_key(pga_app *app, pga_key_code key, int down);

/* ---- actions ---------------------------------------------------------------------------------- */
pg_result pga_toggle_gravity(pga_app *app);               /* a set_gravity command */
pg_result pga_set_effects(pga_app *app, uint32_t effects); /* PG_EFFECT_* bits, a set_effects command */
void pga_set_paused(pga_app *app, int paused);
int pga_paused(const pga_app *app);
/* While paused: the next pga_frame() steps once. */
void pga_step_once(pga_app *app);

typedef enum pga_preset { PGA_PRESET_FAST = 0, PGA_PRESET_BALANCED, PGA_PRESET_ACCURATE, PGA_PRESET_COUNT } pga_preset;
/* Substeps 2, 4 or 8 (the sine table is fixed at build time). Not a command: the world
 * and the recording restart from the current state written as a scene. */
pg_result pga_set_preset(pga_app *app, pga_preset preset);
pga_preset pga_get_preset(const pga_app *app);

/* The selected body (the player), or the zero handle. */
pg_body_id pga_selected(const pga_app *app);
pg_result pga_select(pga_app *app, pg_body_id body);
/* Edit the selected body's material (commands). */
pg_result pga_set_selected_material(pga_app *app, pg_fix density, pg_fix friction, pg_fix restitution);

/* ---- time ------------------------------------------------------------------------------------- */
/* One fixed step (1/step_hz s): apply the queued and key/drag commands (and remove bodies
 * beyond +-1000 m), log them, step, checkpoint. Does nothing while paused unless pga_step_once was called. In playback,
 * plays the next frame of the replay instead. Returns 1 when the world stepped. */
int pga_frame(pga_app *app);
uint64_t pga_frame_number(const pga_app *app);

/* ---- drawing ------------------------------------------------------------------------------- */
enum { PGA_DRAW_SELECTED = 1u << 0, PGA_DRAW_STATIC = 1u << 1, PGA_DRAW_ASLEEP = 1u << 2, PGA_DRAW_KINEMATIC = 1u << 3 };
typedef struct pga_draw_shape {
    pg_body_id body;
    pg_shape_kind kind;
    int32_t count;                       /* vertices used */
    pg_vec2 vertices[PG_MAX_VERTICES];   /* world frame */
    pg_fix radius;
    uint32_t color;                      /* 0xRRGGBB */
    uint32_t flags;                      /* PGA_DRAW_* */
} pga_draw_shape;
/* Every shape of every body, in slot order; valid until the next call into the app. */
const pga_draw_shape *pga_draw_list(const pga_app *app, uint32_t *count);
/* Every joint whose body B (or, when B has no shape, body A) has a shape, in that body's
 * slot order: what to draw, with world anchors. A pin (revolute) is a dot at `b` with
 * thin arms from the bodies' origins (a pendulum shows its arm), a rod a line, a spring a
 * zigzag, a mouse joint a thin line from the body's anchor `b` to its target `a`. Valid
 * until the next call into the app. */
typedef struct pga_draw_joint {
    pg_joint_id joint;
    pg_joint_type type;
    int spring;                          /* a distance joint with its spring on */
    pg_vec2 a, b;                        /* world anchors on body A and body B; mouse: a = target */
    pg_vec2 origin_a, origin_b;          /* the bodies' origins; mouse: origin_a = target */
    uint32_t color;                      /* 0xRRGGBB by kind, the same on every front end */
} pga_draw_joint;
const pga_draw_joint *pga_draw_joints(const pga_app *app, uint32_t *count);
uint32_t pga_joint_count(const pga_app *app);    /* the joints pga_draw_joints lists */
/* Points collected so far for a triangle, a wall or a joint's first click. */
const pg_vec2 *pga_pending_points(const pga_app *app, uint32_t *count);
/* The latest message for the user and a counter that grows with each new one. */
const char *pga_message(const pga_app *app);
uint32_t pga_message_serial(const pga_app *app);
/* How the front end should show the latest message. */
typedef enum pga_message_level {
    PGA_MESSAGE_INFO = 0,    /* what happened ("Added a box", "Selected body 7") */
    PGA_MESSAGE_REFUSED,     /* an action the app did not do, and why (overlap, bad parameter) */
    PGA_MESSAGE_ERROR        /* a file or scene that could not be read, with where and why */
} pga_message_level;
pga_message_level pga_message_level_of(const pga_app *app);

/* ---- colours --------------------------------------------------------------------------------- */
/* A body's colour travels in its user_data, so a replay shows the same colours: bit 56
 * (PGA_COLOR_FLAG) says bits 32..55 hold 0xRRGGBB; the low 32 bits stay the scene's tag
 * (the demo's player is tag 1). Bodies without the flag get a colour by type and shape. */
#define PGA_COLOR_FLAG (UINT64_C(1) << 56)
uint64_t pga_user_data_with_color(uint64_t user_data, uint32_t color);
uint32_t pga_body_color(const pga_app *app, pg_body_id body);   /* 0 for an invalid handle */
/* The core's mouse joint def gives its target but not its anchor on the body, so the
 * app's mouse joints carry the anchor (body frame, within +-128 m) in their user_data, and
 * a replay draws the drag as it was: bit 57 (PGA_ANCHOR_FLAG), x in bits 0..23 and y in
 * bits 24..47 as signed Q16.16. */
#define PGA_ANCHOR_FLAG (UINT64_C(1) << 57)
uint64_t pga_user_data_with_anchor(pg_vec2 local_anchor);
/* 1 and *local_anchor when user_data holds an anchor, else 0. */
int pga_anchor_from_user_data(uint64_t user_data, pg_vec2 *local_anchor);

/* ---- what an edit panel shows ------------------------------------------------------------------ */
typedef struct pga_body_info {
    pg_body_id body;
    pg_body_type type;
    pg_shape_kind kind;          /* of its first shape */
    uint32_t shape_count;
    pg_vec2 position;            /* body origin, m */
    pg_fix angle;                /* radians in [-pi, pi) */
    pg_vec2 linear_velocity;     /* m/s */
    pg_fix angular_velocity;     /* rad/s */
    pg_fix mass;                 /* kg (Q16.16, saturated; 0 for static and kinematic) */
    uint32_t color;              /* 0xRRGGBB as drawn */
    uint64_t user_data;
    int awake;
} pga_body_info;
/* PG_ERR_STALE_HANDLE for a body that is not in the world shown. */
pg_result pga_get_body_info(const pga_app *app, pg_body_id body, pga_body_info *out);
/* Recolour the selected body (a set_user_data command keeping its tag). */
pg_result pga_set_selected_color(pga_app *app, uint32_t color);

/* ---- lists for menus --------------------------------------------------------------------------- */
/* The PG_EFFECT_* switches in bit order: index 0 .. pga_effect_count()-1. */
uint32_t pga_effect_count(void);
uint32_t pga_effect_bit(uint32_t index);          /* 0 past the end */
const char *pga_effect_name(uint32_t index);      /* "gravity", "rotation", ...; "" past the end */
uint32_t pga_effects(const pga_app *app);         /* the switches as queued */
const char *pga_preset_name(pga_preset preset);   /* "fast", "balanced", "accurate" */
int pga_gravity_enabled(const pga_app *app);      /* as queued */

/* ---- recording and playback ----------------------------------------------------------------- */
/* A finished replay file of the session so far (since the last scene load, preset
 * change or end of playback), in a buffer owned by the app, valid until the next call.
 * Recording never stops while the app is in live mode. The file's scene is the live
 * world's own text, capacities raised so added bodies fit (docs/app.md). */
pg_result pga_recording(pga_app *app, const uint8_t **data, size_t *size);

/* Leave live mode and play a replay file: its scene replaces the world, and pga_frame
 * plays one frame. A corrupt file changes nothing and pga_message() holds the reader's
 * error (offset, region, field). */
pg_result pga_play_replay(pga_app *app, const uint8_t *data, size_t size);
typedef struct pga_playback {
    int active;                 /* 1 in playback mode */
    uint32_t frame, frame_count;
    uint32_t checkpoints_checked, checkpoints_failed;
    int last_match;             /* the latest checkpoint compared: 1 matched, 0 diverged, -1 none yet */
    uint32_t section_mismatch;  /* of the latest diverged checkpoint */
} pga_playback;
pga_playback pga_playback_state(const pga_app *app);
/* Back to live mode from the replay's current state, with a new recording. */
pg_result pga_stop_playback(pga_app *app);

/* ---- numbers for the UI ------------------------------------------------------------------------ */
uint64_t pga_state_hash(const pga_app *app);     /* pg_world_hash */
uint32_t pga_body_count(const pga_app *app);

#ifdef __cplusplus
}
#endif
#endif
