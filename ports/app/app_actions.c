/* app_actions.c — UI actions that change the world: gravity, effects, the selected body's
 * material and colour. Each is queued as commands for the next frame. */
#include "app_internal.h"

#include <string.h>

static pg_result live_only(pga_app *app, const char *what)
{
    if (app->mode == PGA_MODE_LIVE) return PG_OK;
    pga__say(app, PGA_MESSAGE_REFUSED, "%s: %s", what, app->mode == PGA_MODE_EMPTY ? "load a scene first" : "stop the playback first");
    return PG_ERR_INVALID_ARGUMENT;
}

static pg_result queue_command(pga_app *app, const pg_command *c)
{
    pga_action a;
    memset(&a, 0, sizeof a);
    a.command = *c;
    return pga__queue(app, &a);
}

/* Gravity does not wake sleeping bodies by itself: the toggle wakes them so it shows. */
pg_result pga_toggle_gravity(pga_app *app)
{
    pg_command c;
    const pg_body_id *ids;
    uint32_t n, i;
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if ((r = live_only(app, "Gravity not changed")) != PG_OK) return r;
    c = pg_command_init(PG_CMD_SET_GRAVITY);
    c.vec = app->gravity_enabled ? pg_v2_zero() : app->gravity_on;
    if ((r = queue_command(app, &c)) != PG_OK) return r;
    app->gravity_enabled = !app->gravity_enabled;
    ids = pga__list_bodies(app, app->live.world, &n);
    for (i = 0; i < n; ++i) {
        if (pg_body_type_of(app->live.world, ids[i]) != PG_BODY_DYNAMIC || pg_body_is_awake(app->live.world, ids[i])) continue;
        c = pg_command_init(PG_CMD_SET_AWAKE);
        c.body = ids[i];
        c.value = 1;
        if (queue_command(app, &c) != PG_OK) break;
    }
    pga__say(app, PGA_MESSAGE_INFO, "Gravity %s", app->gravity_enabled ? "on" : "off");
    return PG_OK;
}

pg_result pga_set_effects(pga_app *app, uint32_t effects)
{
    pg_command c;
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if ((effects & ~PG_EFFECTS_ALL) != 0) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Effects not changed: 0x%x has bits that are not PG_EFFECT_* (0x%x)", effects, PG_EFFECTS_ALL);
        return PG_ERR_INVALID_ARGUMENT;
    }
    if ((r = live_only(app, "Effects not changed")) != PG_OK) return r;
    c = pg_command_init(PG_CMD_SET_EFFECTS);
    c.value = effects;
    if ((r = queue_command(app, &c)) != PG_OK) return r;
    app->effects = effects;
    pga__say(app, PGA_MESSAGE_INFO, "Effects set to 0x%02x", effects);
    return PG_OK;
}

static pg_result selected_body(pga_app *app, const char *what, pg_body_id *out)
{
    pg_result r = live_only(app, what);
    if (r != PG_OK) return r;
    if (!pg_body_is_valid(app->live.world, app->selected)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s: no body is selected", what);
        return PG_ERR_STALE_HANDLE;
    }
    *out = app->selected;
    return PG_OK;
}

pg_result pga_set_selected_material(pga_app *app, pg_fix density, pg_fix friction, pg_fix restitution)
{
    static const char what[] = "Material not changed";
    pg_body_id body;
    pg_command c[3];
    pg_result r;
    int i;
    if (app == NULL) return PG_ERR_NULL;
    if ((r = selected_body(app, what, &body)) != PG_OK) return r;
    if (density < pg_fix_from_ratio(1, 10) || density > PG_FIX_C(100) || friction < 0 || friction > PG_FIX_C(10) ||
        restitution < 0 || restitution > PG_FIX_ONE) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s: density must be 0.1..100 kg/m^2, friction 0..10, restitution 0..1", what);
        return PG_ERR_ENVELOPE;
    }
    if (app->queue_count + 3 > PGA_QUEUE_CAPACITY) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s: too many changes are waiting for the next frame", what);
        return PG_ERR_CAPACITY;
    }
    c[0] = pg_command_init(PG_CMD_SET_DENSITY);
    c[0].scalar = density;
    c[1] = pg_command_init(PG_CMD_SET_FRICTION);
    c[1].scalar = friction;
    c[2] = pg_command_init(PG_CMD_SET_RESTITUTION);
    c[2].scalar = restitution;
    for (i = 0; i < 3; ++i) {
        /* a static body keeps density 0 (it has no mass to change) */
        if (i == 0 && pg_body_type_of(app->live.world, body) != PG_BODY_DYNAMIC) continue;
        c[i].body = body;
        (void)queue_command(app, &c[i]);
    }
    pga__say(app, PGA_MESSAGE_INFO, "Material of body %u changed", body.index);
    return PG_OK;
}

pg_result pga_set_selected_color(pga_app *app, uint32_t color)
{
    static const char what[] = "Colour not changed";
    pg_body_id body;
    pg_command c;
    pg_result r;
    if (app == NULL) return PG_ERR_NULL;
    if ((r = selected_body(app, what, &body)) != PG_OK) return r;
    if (color > 0xffffffu) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s: 0x%x is not 0xRRGGBB", what, color);
        return PG_ERR_ENVELOPE;
    }
    c = pg_command_init(PG_CMD_SET_USER_DATA);
    c.body = body;
    c.user_data = pga_user_data_with_color(pg_body_user_data(app->live.world, body), color);
    if ((r = queue_command(app, &c)) != PG_OK) return r;
    pga__say(app, PGA_MESSAGE_INFO, "Colour of body %u changed to #%06x", body.index, color);
    return PG_OK;
}
