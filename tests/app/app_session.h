/* app_session.h — a scripted playground session that uses every kind of world change
 * the app makes (adds of each kind, triangle and wall by clicks, keys, drag, gravity,
 * effects, nudge, delete, changes while paused, single step, material, pin, rod, spring,
 * the mouse-joint drag, deleting a joint). Run on the demo scene for 240 frames by test_app_replay and by app_record_session (whose file the
 * native pogon-replay verifies). */
#ifndef POGON_APP_SESSION_H
#define POGON_APP_SESSION_H

#include "pogon_app.h"

static pg_vec2 session_at(double x, double y)
{
    return pg_v2((pg_fix)(x * 65536.0 + (x < 0 ? -0.5 : 0.5)), (pg_fix)(y * 65536.0 + (y < 0 ? -0.5 : 0.5)));
}

/* A session that uses every kind of world change the app makes. */
static void app_session_run(pga_app *app)
{
    pga_params p = pga_default_params();
    int f;
    for (f = 0; f < 240; ++f) {
        switch (f) {
        case 2: pga_set_tool(app, PGA_TOOL_BOX); pga_pointer_down(app, session_at(-8, 6)); break;
        case 4: pga_set_tool(app, PGA_TOOL_BALL); pga_pointer_down(app, session_at(-4, 7)); break;
        case 6: pga_set_tool(app, PGA_TOOL_CAPSULE); pga_pointer_down(app, session_at(0, 8)); break;
        case 8: pga_set_tool(app, PGA_TOOL_STAR); pga_pointer_down(app, session_at(4, 9)); break;
        case 10:
            pga_set_tool(app, PGA_TOOL_TRIANGLE);
            pga_pointer_down(app, session_at(8, 6));
            pga_pointer_down(app, session_at(10, 6));
            pga_pointer_down(app, session_at(9, 8));
            break;
        case 12:
            pga_set_tool(app, PGA_TOOL_WALL);
            pga_pointer_down(app, session_at(-18, 12));
            pga_pointer_down(app, session_at(-12, 10));
            break;
        case 20: pga_key(app, PGA_KEY_LEFT, 1); break;
        case 50: pga_key(app, PGA_KEY_LEFT, 0); pga_key(app, PGA_KEY_UP, 1); break;
        case 60: pga_key(app, PGA_KEY_UP, 0); break;
        case 70: pga_toggle_gravity(app); break;
        case 80:
            pga_set_tool(app, PGA_TOOL_MOVE);
            pga_pointer_down(app, session_at(-2, 0.5)); /* the demo's box */
            pga_pointer_move(app, session_at(0, 5));
            break;
        case 100: pga_pointer_up(app, session_at(0, 5)); pga_toggle_gravity(app); break;
        case 110: pga_set_effects(app, PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING); break;
        case 120: /* changes while paused are logged with the next step */
            pga_set_paused(app, 1);
            p.nudge = 1;
            pga_set_params(app, &p);
            pga_set_tool(app, PGA_TOOL_BOX);
            pga_pointer_down(app, session_at(0, 5));
            break;
        case 125: pga_set_tool(app, PGA_TOOL_DELETE); pga_pointer_down(app, session_at(-10, 0.5)); break;
        case 130: pga_step_once(app); break;
        case 140: pga_set_paused(app, 0); break;
        case 150: pga_set_selected_material(app, PG_FIX_C(2), PG_FIX_ONE / 4, PG_FIX_ONE / 2); break;
        case 160: /* joints, made while paused so the clicks find the bodies where they were made */
            pga_set_paused(app, 1);
            pga_set_tool(app, PGA_TOOL_BALL);
            pga_pointer_down(app, session_at(-14, 16));
            pga_set_tool(app, PGA_TOOL_BOX);
            pga_pointer_down(app, session_at(-10, 16));
            break;
        case 161:
            pga_set_tool(app, PGA_TOOL_PIN); /* a pendulum about a point of the world */
            pga_pointer_down(app, session_at(-14, 16));
            pga_pointer_down(app, session_at(-14, 18));
            pga_set_tool(app, PGA_TOOL_ROD);
            pga_pointer_down(app, session_at(-14, 16));
            pga_pointer_down(app, session_at(-10, 16));
            pga_set_tool(app, PGA_TOOL_SPRING);
            pga_pointer_down(app, session_at(-10, 16));
            pga_pointer_down(app, session_at(-10, 19));
            break;
        case 162:
            pga_set_tool(app, PGA_TOOL_MOVE); /* a mouse-joint drag of the box */
            pga_pointer_down(app, session_at(-10, 16));
            pga_pointer_move(app, session_at(-7, 14));
            break;
        case 163: pga_set_paused(app, 0); break;
        case 190: pga_pointer_move(app, session_at(-8, 12)); break;
        case 200: pga_pointer_up(app, session_at(-8, 12)); break;
        case 215: pga_set_tool(app, PGA_TOOL_DELETE); pga_pointer_down(app, session_at(-14, 18)); break; /* the pin */
        default: break;
        }
        pga_frame(app);
    }
}

#endif
