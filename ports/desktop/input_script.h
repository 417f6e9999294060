/* input_script.h — app-level input events by frame, for recording without a window.
 *
 * FORMAT (one event a line; '#' starts a comment; blank lines are ignored)
 *     TICK EVENT ARGS...
 *   TICK counts pga_frame() calls from 0: the events of tick T happen, in file order,
 *   just before call T (while the app runs unpaused, tick T is world frame T). Ticks
 *   never go down from one line to the next. Coordinates are world metres (y up),
 *   numbers exact decimals ("1.25", "-.5") as in scene files. EVENT is one of
 *     tool move|delete|ball|capsule|box|triangle|star|wall
 *     down X Y | move X Y | up X Y      the pointer (press, move, release)
 *     click X Y                          down and up at one point
 *     key left|right|up|down|ccw|cw down|up
 *     gravity                            toggle gravity
 *     effect NAME                        toggle one effect: gravity rotation friction
 *                                        restitution damping sleeping continuous
 *     effects LIST                       set them all: names joined by '+', or all, none
 *     pause | resume | step              step: one frame while paused
 *     preset fast|balanced|accurate
 *     nudge on|off                       place overlapping adds at the nearest free spot
 *     param NAME VALUE                   radius width height density friction restitution
 *                                        (metres, kg/m^2); color 0xRRGGBB
 *     select none                        drop the selection
 */
#ifndef DESKTOP_INPUT_SCRIPT_H
#define DESKTOP_INPUT_SCRIPT_H

#include <stddef.h>
#include <stdint.h>

#include "pogon_app.h"

typedef enum desktop_event_kind {
    DESKTOP_EV_TOOL, DESKTOP_EV_DOWN, DESKTOP_EV_MOVE, DESKTOP_EV_UP, DESKTOP_EV_CLICK, DESKTOP_EV_KEY,
    DESKTOP_EV_GRAVITY, DESKTOP_EV_EFFECT, DESKTOP_EV_EFFECTS, DESKTOP_EV_PAUSE, DESKTOP_EV_RESUME, DESKTOP_EV_STEP,
    DESKTOP_EV_PRESET, DESKTOP_EV_NUDGE, DESKTOP_EV_PARAM, DESKTOP_EV_SELECT_NONE
} desktop_event_kind;

typedef enum desktop_param { DESKTOP_PARAM_RADIUS, DESKTOP_PARAM_WIDTH, DESKTOP_PARAM_HEIGHT, DESKTOP_PARAM_DENSITY,
                             DESKTOP_PARAM_FRICTION, DESKTOP_PARAM_RESTITUTION, DESKTOP_PARAM_COLOR,
                             DESKTOP_PARAM_SPRING_HERTZ, DESKTOP_PARAM_SPRING_DAMPING } desktop_param;

typedef struct desktop_event {
    uint32_t tick;
    desktop_event_kind kind;
    pg_vec2 point;       /* DOWN MOVE UP CLICK */
    uint32_t value;      /* TOOL (pga_tool), KEY (pga_key), EFFECT(S) (bits), PRESET, NUDGE, PARAM (desktop_param), COLOR */
    int down;            /* KEY */
    pg_fix number;       /* PARAM */
    int line;            /* in the script, for messages */
} desktop_event;

typedef struct desktop_script {
    desktop_event *events;
    size_t count;
} desktop_script;

/* Parse a whole script. Returns 0 with "LINE:COLUMN: what is wrong" in `error`. */
int desktop_script_parse(const char *text, size_t length, desktop_script *out, char *error, size_t error_capacity);
void desktop_script_free(desktop_script *s);

/* Hand one event to the app (the same calls the window makes for its input). */
void desktop_event_apply(pga_app *app, const desktop_event *e);

#endif
