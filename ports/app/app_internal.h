/* app_internal.h — the state behind pga_app, shared by the files of ports/app.
 *
 * Who owns what:
 *   app.c          life, messages, tools and parameters, selection, small accessors
 *   app_world.c    building a world from scene text (capacities, substeps), listing bodies
 *   app_tools.c    what a pointer press does: select, delete, add (overlap check, nudge)
 *   app_joint_tools.c  the pin, rod and spring tools, and deleting joints and their anchors
 *   app_input.c    held keys: the commands they give each frame
 *   app_drag.c     the drag: a mouse joint (dynamic) or a velocity (kinematic) each frame
 *   app_frame.c    the queue of actions and pga_frame in live mode (apply, log, step)
 *   app_record.c   the replay writer in a growing buffer, pga_recording
 *   app_playback.c playing a replay file
 *   app_draw.c     the draw list and colours
 *   world_draw_joints.c  the joints of a world as a draw list (also for replay views)
 * Data flows one way: input and actions fill the queue, pga_frame turns it into commands
 * on the world and the log, drawing only reads.
 */
#ifndef POGON_APP_INTERNAL_H
#define POGON_APP_INTERNAL_H

#include "pogon_app.h"
#include "pogon/scene_file.h"

#include <stddef.h>
#include <stdint.h>

/* Capacities every live world has at least, so a visitor can add bodies to any scene. */
#define PGA_MIN_BODIES 512u
#define PGA_MIN_SHAPES 1024u
#define PGA_MIN_CONTACTS 4096u
#define PGA_MIN_JOINTS 256u
/* The user_data tag (low 32 bits) of the shapeless static bodies the joint tools make as
 * the world's end of a pin, rod or spring on empty space: "anch". */
#define PGA_ANCHOR_TAG 0x616e6368u
/* The most memory one world may take: a scene or replay asking for more (its capacities)
 * is refused with a message instead of failing an allocation (in wasm, aborting). */
#define PGA_MAX_WORLD_BYTES ((size_t)256 << 20)
/* Checkpoint interval of recordings (frames). */
#define PGA_CHECKPOINT_INTERVAL 60u
/* Actions queued between two frames (a front end gives a few per display frame). */
#define PGA_QUEUE_CAPACITY 1024u

/* A world in memory the app allocated, with the scene text it was built from. */
typedef struct pga_world_box {
    pg_world *world;
    void *memory;
    char *text;          /* canonical scene text (pg_scene_write of the fresh world) */
    size_t text_size;
} pga_world_box;

/* One queued world change: a command, and whether its `body` is the body made by the
 * previous command of the queue (a triangle: create_body, then add_shape to it; a joint
 * to the world: the anchor, then the joint whose body A it is). */
typedef struct pga_action {
    pg_command command;
    int body_is_last_made;
    int anchor_is_last_made;   /* a CREATE_*_JOINT whose body_a is the body made just before */
    int select_made;     /* select the body this command makes */
} pga_action;

/* The recording: a replay writer in a buffer that grows. */
typedef struct pga_recorder {
    pg_replay_writer writer;
    uint8_t *data;
    size_t capacity;
    int active;
    uint64_t logged_hash;   /* while commands wait unlogged (paused): the hash before them */
    uint8_t *copy;          /* pga_recording's finished copy */
    size_t copy_capacity;
} pga_recorder;

/* Playback of a replay file. */
typedef struct pga_player {
    uint8_t *data;          /* the app's copy of the file */
    size_t size;
    void *memory;
    pg_replay_player player;
    pga_playback state;
} pga_player;

/* What the front end reads and the app writes from const functions. */
typedef struct pga_scratch {
    pga_draw_shape *shapes;
    uint32_t shape_capacity;
    pg_body_id *bodies;
    uint32_t body_capacity;
    pga_draw_joint *joints;
    uint32_t joint_capacity;
} pga_scratch;

enum { PGA_MODE_EMPTY = 0, PGA_MODE_LIVE, PGA_MODE_PLAYBACK };

struct pga_app {
    int mode;
    pga_world_box live;             /* the world in live mode */
    pga_player playback;            /* the player in playback mode */
    char scene_name[64];

    pga_tool tool;
    pga_params params;
    pga_preset preset;
    pg_vec2 pending[3];
    uint32_t pending_count;
    pg_body_id pending_body;        /* a joint tool's first click: the body under it (or zero) */
    pg_vec2 pending_local;          /* and the point in that body's frame */

    pg_body_id selected;
    int keys[PGA_KEY_COUNT];
    pg_body_id driven;              /* the kinematic body keys or the drag set moving (stopped when let go) */

    int dragging;                   /* a body picked with the move tool is held */
    pg_body_id drag_body;
    pg_vec2 drag_offset;            /* body origin minus the grab point */
    pg_vec2 drag_target;            /* where the pointer is */
    pg_vec2 drag_point;             /* where the body was pressed */
    pg_joint_id drag_joint;         /* the mouse joint of a dynamic body's drag, once made */
    int drag_pressed;               /* a press since the last stepped frame: its joint replaces any other */
    pg_vec2 drag_sent_target;       /* the target last given to it */

    int paused, step_requested;
    pg_vec2 gravity_on;             /* the gravity the toggle restores */
    int gravity_enabled;            /* the state after every queued toggle */
    uint32_t effects;               /* the state after every queued set_effects */

    pga_action *queue;
    uint32_t queue_count;
    pg_command *frame_commands;     /* applied since the last step, logged with the next frame */
    uint32_t frame_command_count, frame_command_capacity;

    pga_recorder recorder;

    char message[256];
    pga_message_level message_level;
    uint32_t message_serial;

    pga_scratch *scratch;
};

/* ---- app.c ---- */
void pga__say(pga_app *app, pga_message_level level, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The world the app shows (live or playback), NULL when none. */
pg_world *pga__world(const pga_app *app);
/* Drop pending clicks, keys, drag and queue (after a world change of identity). */
void pga__reset_input(pga_app *app);
/* Make a built world the live one: the old world and any playback go, recording restarts. */
pg_result pga__go_live(pga_app *app, pga_world_box *box);
/* Rebuild the live world from `world`'s current state written as a scene, with `substeps`
 * (0: as it is); the selection follows by rank. `why` starts the message on failure. */
pg_result pga__restart_from(pga_app *app, const pg_world *world, uint32_t substeps, const char *why);

/* ---- app_world.c ---- */
/* Build a world from scene text: its settings, capacities raised to the PGA_MIN_* floor,
 * substeps replaced when `substeps` is nonzero. The world is built from its own canonical
 * text (box->text), so a replay of that text starts from the same bits. On failure
 * returns the reader's result and writes its message to `error` (size `error_size`). */
pg_result pga__world_build(pga_world_box *box, const char *text, size_t length, uint32_t substeps, char *error,
                           size_t error_size);
void pga__world_free(pga_world_box *box);
/* Scene text of a world's current state (malloc'd, NUL-terminated), NULL when out of memory. */
char *pga__world_text(const pg_world *world, size_t *size);
/* Every body with a shape, in ascending slot order, into the app's scratch list. */
const pg_body_id *pga__list_bodies(const pga_app *app, const pg_world *world, uint32_t *count);
/* The body under a point (the one with the highest slot: it is drawn on top), or zero. */
pg_body_id pga__body_at(const pga_app *app, pg_vec2 point);
/* The body with user_data tag (low 32 bits) 1, or the zero handle. */
pg_body_id pga__find_player(const pga_app *app);

/* ---- app_frame.c ---- */
/* Queue a world change for the next frame. PG_ERR_CAPACITY (with a message) when full. */
pg_result pga__queue(pga_app *app, const pga_action *action);
/* Apply every queued action now (their commands join the next frame record). */
void pga__flush_queue(pga_app *app);
/* Apply one command now and remember it for the next frame record. */
pg_result pga__apply(pga_app *app, const pg_command *command, pg_body_id *made);
/* pga__apply, and `made_joint` (may be NULL) receives a created joint. */
pg_result pga__apply_made(pga_app *app, const pg_command *command, pg_body_id *made, pg_joint_id *made_joint);

/* ---- app_input.c ---- */
/* The key and drag commands of the frame that is about to step. */
void pga__control_commands(pga_app *app);
/* Apply a set_linear_velocity command now. */
void pga__command_velocity(pga_app *app, pg_body_id body, pg_vec2 v);

/* ---- app_drag.c ---- */
/* Start holding `body` pressed at `point` (not static). */
void pga__drag_start(pga_app *app, pg_body_id body, pg_vec2 point);
/* The drag's commands of the frame about to step: make, move or destroy the mouse joint,
 * or set a kinematic body's velocity. */
void pga__drag_commands(pga_app *app);
/* Destroy the drag's mouse joint now (before the world is written for a restart). */
void pga__drag_drop_joint(pga_app *app);

/* ---- app_joint_tools.c ---- */
/* A press with the pin, rod or spring tool. */
void pga__joint_tool_press(pga_app *app, pg_vec2 point);
/* With the delete tool: queue the destruction of the joint drawn nearest `point` (within
 * PGA_JOINT_PICK) and of its anchor; 1 when one was found. */
int pga__delete_joint_at(pga_app *app, pg_vec2 point);
/* Before `body` is destroyed: destroy the anchors (PGA_ANCHOR_TAG) whose joints all join
 * them to `body`, which would be left joined to nothing. `now`: apply the commands now,
 * else queue them. */
void pga__remove_anchors_of(pga_app *app, pg_body_id body, int now);

/* ---- app_record.c ---- */
pg_result pga__recorder_start(pga_app *app);
/* Called before the first command of a frame is applied: keeps the hash the file ends
 * with while that frame is not yet logged. */
void pga__recorder_before_changes(pga_app *app);
/* Log the frame's commands (before the step). */
pg_result pga__recorder_frame(pga_app *app, const pg_command *commands, uint32_t count);
/* After the step: the hash and a checkpoint when due. */
pg_result pga__recorder_after_step(pga_app *app);
void pga__recorder_free(pga_recorder *rec);

/* ---- app_playback.c ---- */
void pga__player_free(pga_player *p);
int pga__playback_frame(pga_app *app);

/* ---- app_draw.c ---- */
uint32_t pga__default_color(pg_body_type type, pg_shape_kind kind, uint32_t shape_count);

#endif
