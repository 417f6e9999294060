/* app_input.c — held keys, turned into commands for the frame that steps (the drag is
 * app_drag.c's; while the player is dragged its keys wait).
 *
 * Keys act on the selected body (the player):
 *   kinematic: W/A/S/D set its velocity to PGA_KEY_SPEED in the key's direction, Q/E its
 *              angular velocity to PGA_KEY_SPIN; releasing every key stops it.
 *   dynamic:   a force of mass x PGA_KEY_ACCEL (PGA_KEY_LIFT upward, enough to beat
 *              gravity) while its speed in that direction is below PGA_KEY_SPEED, and a
 *              torque of inertia x PGA_KEY_SPIN_ACCEL while it turns slower than
 *              PGA_KEY_SPIN_MAX. A 1 m box of density 1 on ground of friction 0.6 reaches
 *              PGA_KEY_SPEED in about half a second. */
#include "app_internal.h"

#define PGA_KEY_SPEED PG_FIX_C(6)
#define PGA_KEY_ACCEL PG_FIX_C(20)
#define PGA_KEY_LIFT PG_FIX_C(25)
#define PGA_KEY_SPIN PG_FIX_C(3)
#define PGA_KEY_SPIN_ACCEL PG_FIX_C(30)
#define PGA_KEY_SPIN_MAX PG_FIX_C(10)

void pga_key(pga_app *app, pga_key_code key, int down)
{
    if (app == NULL) return;
    if ((unsigned)key >= PGA_KEY_COUNT) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Unknown key %d", (int)key);
        return;
    }
    app->keys[key] = down != 0;
}

void pga__command_velocity(pga_app *app, pg_body_id body, pg_vec2 v)
{
    pg_command c = pg_command_init(PG_CMD_SET_LINEAR_VELOCITY);
    c.body = body;
    c.vec = v;
    (void)pga__apply(app, &c, NULL);
}

static void command_spin(pga_app *app, pg_body_id body, pg_fix w)
{
    pg_command c = pg_command_init(PG_CMD_SET_ANGULAR_VELOCITY);
    c.body = body;
    c.scalar = w;
    (void)pga__apply(app, &c, NULL);
}


static void push_dynamic(pga_app *app, pg_body_id body, int dx, int dy, int spin)
{
    const pg_world *w = app->live.world;
    pg_vec2 v = pg_body_linear_velocity(w, body);
    pg_fix mass = pg_fix_from_ratio(pg_body_mass(w, body), INT64_C(1) << 32);       /* Q32.32 kg */
    pg_fix inertia = pg_fix_from_ratio(pg_body_inertia(w, body), INT64_C(1) << 36); /* Q28.36 kg m^2 */
    pg_vec2 f = pg_v2_zero();
    if (dx > 0 && v.x < PGA_KEY_SPEED) f.x = pg_fix_mul(mass, PGA_KEY_ACCEL);
    if (dx < 0 && v.x > -PGA_KEY_SPEED) f.x = pg_fix_neg(pg_fix_mul(mass, PGA_KEY_ACCEL));
    if (dy > 0 && v.y < PGA_KEY_SPEED) f.y = pg_fix_mul(mass, PGA_KEY_LIFT);
    if (dy < 0 && v.y > -PGA_KEY_SPEED) f.y = pg_fix_neg(pg_fix_mul(mass, PGA_KEY_ACCEL));
    if (f.x != 0 || f.y != 0) {
        pg_command c = pg_command_init(PG_CMD_APPLY_FORCE);
        c.body = body;
        c.vec = f;
        (void)pga__apply(app, &c, NULL);
    }
    if (spin != 0) {
        pg_fix av = pg_body_angular_velocity(w, body);
        if ((spin > 0 && av < PGA_KEY_SPIN_MAX) || (spin < 0 && av > -PGA_KEY_SPIN_MAX)) {
            pg_command c = pg_command_init(PG_CMD_APPLY_TORQUE);
            c.body = body;
            c.scalar = pg_fix_mul(inertia, spin > 0 ? PGA_KEY_SPIN_ACCEL : pg_fix_neg(PGA_KEY_SPIN_ACCEL));
            if (c.scalar != 0) (void)pga__apply(app, &c, NULL);
        }
    }
}

static void drive_kinematic(pga_app *app, pg_body_id body, int dx, int dy, int spin)
{
    const pg_world *w = app->live.world;
    pg_vec2 v = pg_v2(dx * PGA_KEY_SPEED, dy * PGA_KEY_SPEED);
    pg_fix av = spin * PGA_KEY_SPIN;
    if (!pg_v2_equal(v, pg_body_linear_velocity(w, body))) pga__command_velocity(app, body, v);
    if (av != pg_body_angular_velocity(w, body)) command_spin(app, body, av);
    if (dx != 0 || dy != 0 || spin != 0) app->driven = body;
    else app->driven.index = app->driven.generation = 0;
}

/* A kinematic body keeps its velocity until told otherwise: the one the app set moving
 * stops when it is no longer the one keys or the pointer lead. */
static void stop_left_behind(pga_app *app)
{
    const pg_world *w = app->live.world;
    pg_body_id b = app->driven;
    if (b.generation == 0) return;
    if (pg_body_id_equal(b, app->selected) || (app->dragging && pg_body_id_equal(b, app->drag_body))) return;
    if (pg_body_is_valid(w, b)) drive_kinematic(app, b, 0, 0, 0);
    app->driven.index = app->driven.generation = 0;
}

void pga__control_commands(pga_app *app)
{
    const pg_world *w = app->live.world;
    pg_body_id sel = app->selected;
    pg_body_type type;
    int dx = app->keys[PGA_KEY_RIGHT] - app->keys[PGA_KEY_LEFT];
    int dy = app->keys[PGA_KEY_UP] - app->keys[PGA_KEY_DOWN];
    int spin = app->keys[PGA_KEY_SPIN_CCW] - app->keys[PGA_KEY_SPIN_CW];

    if (app->dragging && !pg_body_is_valid(w, app->drag_body)) app->dragging = 0;
    stop_left_behind(app);
    pga__drag_commands(app);
    if (app->dragging) {
        if (pg_body_type_of(w, app->drag_body) == PG_BODY_KINEMATIC) app->driven = app->drag_body;
        if (pg_body_id_equal(app->drag_body, sel)) return; /* the pointer leads; keys wait */
    }
    if (!pg_body_is_valid(w, sel)) return;
    type = pg_body_type_of(w, sel);
    if (type == PG_BODY_KINEMATIC && (dx != 0 || dy != 0 || spin != 0 || pg_body_id_equal(app->driven, sel)))
        drive_kinematic(app, sel, dx, dy, spin);
    else if (type == PG_BODY_DYNAMIC && (dx != 0 || dy != 0 || spin != 0))
        push_dynamic(app, sel, dx, dy, spin);
}
