/* app_drag.c — the drag of the move tool, turned into commands for the frame that steps.
 *
 * A dynamic body is dragged by a mouse joint, as in Box2D's testbed: at the first step
 * after the press a create_mouse_joint command puts its anchor at the pressed point (the
 * target is that point, so the body point under it is the anchor), with at most
 * PGA_DRAG_FORCE_PER_KG x mass (Box2D's testbed's 1000 x mass; saturated at the Q16.16
 * force limit, 32767 N) and the core's default spring (5 Hz, ratio 0.7). Every stepped
 * frame in which the pointer has moved gives a set_mouse_target command; the frame after
 * the release a destroy_joint. A press and release between two steps make no joint; a
 * new press before a step replaces the joint there.
 * A kinematic body has no mass for a joint to pull: its velocity is set toward the
 * pointer (PGA_DRAG_GAIN per second of distance, at most PGA_DRAG_SPEED), and it stops
 * when released (app_input.c). */
#include "app_internal.h"

#define PGA_DRAG_GAIN PG_FIX_C(10)
#define PGA_DRAG_SPEED PG_FIX_C(30)
#define PGA_DRAG_FORCE_PER_KG 1000

void pga__drag_start(pga_app *app, pg_body_id body, pg_vec2 point)
{
    const pg_world *w = pga__world(app);
    app->dragging = 1;
    app->drag_body = body;
    app->drag_offset = pg_v2_sub(pg_body_position(w, body), point);
    app->drag_point = point;
    app->drag_target = point;
    app->drag_pressed = 1;
}

void pga_pointer_move(pga_app *app, pg_vec2 point)
{
    if (app == NULL || !app->dragging) return;
    app->drag_target = point;
}

void pga_pointer_up(pga_app *app, pg_vec2 point)
{
    if (app == NULL || !app->dragging) return;
    app->drag_target = point;
    app->dragging = 0;
}

/* 1000 N per kg of the body (Q32.32 mass), saturated at the largest pg_fix. */
static pg_fix max_force_for(const pg_world *w, pg_body_id body)
{
    int64_t mass = pg_body_mass(w, body); /* Q32.32 kg */
    if (mass <= 0) return 0;
    if (mass >= ((int64_t)PG_FIX_MAX << 16) / PGA_DRAG_FORCE_PER_KG) return PG_FIX_MAX;
    return (pg_fix)((mass * PGA_DRAG_FORCE_PER_KG) >> 16);
}

/* The anchor the core will take (the body point under `point`), in the body frame. */
static pg_vec2 local_point(const pg_world *w, pg_body_id body, pg_vec2 point)
{
    return pg_rot_apply_inv(pg_rot_from_angle(pg_body_angle(w, body)), pg_v2_sub(point, pg_body_position(w, body)));
}

static void make_joint(pga_app *app)
{
    const pg_world *w = app->live.world;
    pg_command c = pg_command_init(PG_CMD_CREATE_MOUSE_JOINT);
    pg_joint_id made = {0, 0};
    pg_result r;
    c.joint_def.mouse.body = app->drag_body;
    c.joint_def.mouse.target = app->drag_point;
    c.joint_def.mouse.max_force = max_force_for(w, app->drag_body);
    c.joint_def.mouse.user_data = pga_user_data_with_anchor(local_point(w, app->drag_body, app->drag_point));
    r = pga__apply_made(app, &c, NULL, &made);
    if (r != PG_OK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Drag not started: %s", pg_world_last_error(app->live.world));
        app->dragging = 0;
        return;
    }
    app->drag_joint = made;
    app->drag_sent_target = app->drag_point;
}

void pga__drag_drop_joint(pga_app *app)
{
    pg_command c;
    if (app->drag_joint.generation != 0 && app->mode == PGA_MODE_LIVE && pg_joint_is_valid(app->live.world, app->drag_joint)) {
        c = pg_command_init(PG_CMD_DESTROY_JOINT);
        c.joint = app->drag_joint;
        (void)pga__apply(app, &c, NULL);
    }
    app->drag_joint.index = app->drag_joint.generation = 0;
}

/* Velocity toward the pointer, capped. */
static void drag_kinematic(pga_app *app)
{
    const pg_world *w = app->live.world;
    pg_vec2 target = pg_v2_add(app->drag_target, app->drag_offset);
    pg_vec2 v = pg_v2_scale(pg_v2_sub(target, pg_body_position(w, app->drag_body)), PGA_DRAG_GAIN);
    pg_fix speed = pg_v2_length(v);
    if (speed > PGA_DRAG_SPEED) v = pg_v2_scale(pg_v2_normalize(v), PGA_DRAG_SPEED);
    pga__command_velocity(app, app->drag_body, v);
}

void pga__drag_commands(pga_app *app)
{
    const pg_world *w = app->live.world;
    /* a joint destroyed with its body (deleted, or gone beyond the world) */
    if (app->drag_joint.generation != 0 && !pg_joint_is_valid(w, app->drag_joint))
        app->drag_joint.index = app->drag_joint.generation = 0;
    /* a press since the last step (a release and a new press while paused) starts anew */
    if (app->drag_pressed) pga__drag_drop_joint(app);
    app->drag_pressed = 0;
    if (!app->dragging || !pg_body_is_valid(w, app->drag_body)) {
        app->dragging = 0;
        pga__drag_drop_joint(app);
        return;
    }
    if (pg_body_type_of(w, app->drag_body) != PG_BODY_DYNAMIC) {
        pga__drag_drop_joint(app);
        drag_kinematic(app);
        return;
    }
    if (app->drag_joint.generation == 0) make_joint(app);
    if (app->drag_joint.generation != 0 && !pg_v2_equal(app->drag_target, app->drag_sent_target)) {
        pg_command c = pg_command_init(PG_CMD_SET_MOUSE_TARGET);
        c.joint = app->drag_joint;
        c.vec = app->drag_target;
        if (pga__apply(app, &c, NULL) == PG_OK) app->drag_sent_target = app->drag_target;
    }
}
