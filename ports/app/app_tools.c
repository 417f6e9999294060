/* app_tools.c — what a pointer press does with each tool: select (and start a drag),
 * delete (a joint near the point, else the body under it), hand the joint tools their
 * clicks (app_joint_tools.c), or add a body: one click for a ball, capsule, box or star, three for a
 * triangle (its vertices), two for a wall (its ends).
 *
 * An add is checked against the world as it is now: a body that would overlap another is
 * refused with a message, or with the nudge switch placed at the nearest free spot
 * (pg_world_find_free_position, within PGA_NUDGE_RANGE). A wall is static, so it may
 * cross other static bodies; it is refused only where it would overlap one that moves.
 * Adds queued in the same frame are not yet in the world and are not checked against
 * each other. */
#include "app_internal.h"

#include <string.h>

#define PGA_NUDGE_RANGE PG_FIX_C(8)
#define PGA_NUDGE_STEP (PG_FIX_ONE / 8)
#define PGA_WORLD_LIMIT PG_FIX_C(1000)

/* The shapes a tool makes, in the body frame, and one convex outline for the nudge. */
typedef struct tool_shapes {
    pg_geometry parts[2];
    uint32_t count;
    pg_geometry outline;
} tool_shapes;

static const char *fmt(pg_fix v, char buf[PG_FIX_FORMAT_MAX])
{
    pg_fix_format(v, buf, PG_FIX_FORMAT_MAX);
    return buf;
}

static pg_result shapes_for(pga_tool tool, const pga_params *p, tool_shapes *s)
{
    pg_result r = PG_ERR_INVALID_ARGUMENT;
    memset(s, 0, sizeof *s);
    s->count = 1;
    switch (tool) {
    case PGA_TOOL_BALL: r = pg_geometry_circle(pg_v2_zero(), p->radius, &s->parts[0]); break;
    case PGA_TOOL_CAPSULE:
        r = pg_geometry_capsule(pg_v2(-p->width / 2, 0), pg_v2(p->width - p->width / 2, 0), p->radius, &s->parts[0]);
        break;
    case PGA_TOOL_BOX: r = pg_geometry_box(p->width / 2, p->height / 2, pg_v2_zero(), 0, &s->parts[0]); break;
    case PGA_TOOL_STAR: {
        /* two triangles as pg_make_star makes them; their hull is a regular hexagon */
        pg_vec2 hex[6];
        int i;
        r = pg_geometry_triangle(pg_v2_zero(), p->radius, PG_ANGLE_QUARTER, &s->parts[0]);
        if (r == PG_OK) r = pg_geometry_triangle(pg_v2_zero(), p->radius, PG_ANGLE_QUARTER + PG_ANGLE_HALF, &s->parts[1]);
        s->count = 2;
        for (i = 0; i < 6; ++i) {
            pg_rot rot = pg_rot_from_angle((pg_angle)(PG_ANGLE_QUARTER / 3u + (uint32_t)i * (PG_ANGLE_QUARTER / 3u * 2u)));
            hex[i] = pg_rot_apply(rot, pg_v2(p->radius, 0));
        }
        if (r == PG_OK) r = pg_geometry_polygon(hex, 6, &s->outline);
        return r;
    }
    default: break;
    }
    s->outline = s->parts[0];
    return r;
}

/* Bodies the shapes would overlap at (position, angle); statics count unless `moving_only`. */
static uint32_t overlaps(const pg_world *w, const tool_shapes *s, pg_vec2 position, pg_angle angle, int moving_only)
{
    pg_body_id ids[64];
    uint32_t total = 0, i, k, n;
    for (i = 0; i < s->count; ++i) {
        if (pg_world_query_geometry(w, &s->parts[i], position, angle, ids, 64, &n) != PG_OK) return 1;
        for (k = 0; k < n && k < 64; ++k)
            if (!moving_only || pg_body_type_of(w, ids[k]) != PG_BODY_STATIC) total++;
        if (n > 64 && !moving_only) total += n - 64;
    }
    return total;
}

static int point_ok(pga_app *app, pg_vec2 p)
{
    if (p.x < -PGA_WORLD_LIMIT || p.x > PGA_WORLD_LIMIT || p.y < -PGA_WORLD_LIMIT || p.y > PGA_WORLD_LIMIT) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the point is outside the world's +-1000 m");
        return 0;
    }
    return 1;
}

/* Where the body goes: the click, or the nearest free spot with nudge; 0 when refused. */
static int place(pga_app *app, const char *what, const tool_shapes *s, pg_vec2 click, pg_angle angle, int moving_only,
                 pg_vec2 *at)
{
    const pg_world *w = pga__world(app);
    char bx[PG_FIX_FORMAT_MAX], by[PG_FIX_FORMAT_MAX];
    *at = click;
    if (overlaps(w, s, click, angle, moving_only) == 0) return 1;
    if (!app->params.nudge || moving_only) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the %s would overlap another body at (%s, %s)", what,
                 fmt(click.x, bx), fmt(click.y, by));
        return 0;
    }
    if (pg_world_find_free_position(w, &s->outline, click, angle, PGA_NUDGE_RANGE, PGA_NUDGE_STEP, at) != PG_OK ||
        overlaps(w, s, *at, angle, 0) != 0) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: no free spot for the %s within 8 m of (%s, %s)", what,
                 fmt(click.x, bx), fmt(click.y, by));
        return 0;
    }
    return 1;
}

static pg_body_def new_body_def(const pga_app *app, pg_body_type type, pg_vec2 at, pg_angle angle)
{
    pg_body_def bd = pg_default_body_def();
    bd.type = type;
    bd.position = at;
    bd.angle = angle;
    bd.user_data = pga_user_data_with_color(0, app->params.color);
    return bd;
}

static pg_shape_def new_shape_def(const pga_app *app)
{
    pg_shape_def sd = pg_default_shape_def();
    sd.density = app->params.density;
    sd.friction = app->params.friction;
    sd.restitution = app->params.restitution;
    return sd;
}

static void added(pga_app *app, const char *what, pg_vec2 click, pg_vec2 at)
{
    char bx[PG_FIX_FORMAT_MAX], by[PG_FIX_FORMAT_MAX];
    if (pg_v2_equal(click, at)) pga__say(app, PGA_MESSAGE_INFO, "Added a %s at (%s, %s)", what, fmt(at.x, bx), fmt(at.y, by));
    else pga__say(app, PGA_MESSAGE_INFO, "Added a %s at (%s, %s), the nearest free spot", what, fmt(at.x, bx), fmt(at.y, by));
}

static void add_one_click(pga_app *app, pga_tool tool, pg_vec2 click)
{
    static const pg_make_kind kinds[PGA_TOOL_COUNT] = {PG_MAKE_BALL, PG_MAKE_BALL, PG_MAKE_BALL, PG_MAKE_CAPSULE,
                                                       PG_MAKE_BOX, PG_MAKE_TRIANGLE, PG_MAKE_STAR, PG_MAKE_WALL};
    const pga_params *p = &app->params;
    const char *what = pga_tool_name(tool);
    tool_shapes s;
    pga_action a;
    pg_vec2 at;
    if (shapes_for(tool, p, &s) != PG_OK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the %s's size is outside the envelope", what);
        return;
    }
    if (!place(app, what, &s, click, 0, 0, &at)) return;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_MAKE);
    a.command.make_kind = kinds[tool];
    a.command.body_def = new_body_def(app, PG_BODY_DYNAMIC, at, 0);
    a.command.shape_def = new_shape_def(app);
    switch (tool) {
    case PGA_TOOL_CAPSULE: a.command.size0 = p->width; a.command.size1 = p->radius; break;
    case PGA_TOOL_BOX: a.command.size0 = p->width; a.command.size1 = p->height; break;
    default: a.command.size0 = p->radius; break;
    }
    if (pga__queue(app, &a) == PG_OK) added(app, what, click, at);
}

/* Three points: a dynamic body at their centroid with one polygon. */
static void add_triangle(pga_app *app)
{
    const pg_vec2 *v = app->pending;
    pg_vec2 c, centroid, local[3];
    tool_shapes s;
    pga_action a;
    int i;
    pg_result r;
    c = pg_v2(pg_fix_from_ratio((int64_t)v[0].x + v[1].x + v[2].x, 3 * 65536),
              pg_fix_from_ratio((int64_t)v[0].y + v[1].y + v[2].y, 3 * 65536));
    for (i = 0; i < 3; ++i) local[i] = pg_v2_sub(v[i], c);
    memset(&s, 0, sizeof s);
    r = pg_geometry_polygon(local, 3, &s.parts[0]);
    if (r != PG_OK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the three points make no triangle (%s: %s)", pg_result_name(r),
                 r == PG_ERR_DEGENERATE ? "they are on one line or too close" : "sides must be 0.005..100 m");
        return;
    }
    s.count = 1;
    s.outline = s.parts[0];
    centroid = c;
    if (!place(app, "triangle", &s, centroid, 0, 0, &c)) return;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_CREATE_BODY);
    a.command.body_def = new_body_def(app, PG_BODY_DYNAMIC, c, 0);
    if (app->queue_count + 2 > PGA_QUEUE_CAPACITY || pga__queue(app, &a) != PG_OK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: too many changes are waiting for the next frame");
        return;
    }
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_ADD_SHAPE);
    a.command.shape_def = new_shape_def(app);
    a.command.geometry = s.parts[0];
    a.body_is_last_made = 1;
    (void)pga__queue(app, &a);
    added(app, "triangle", centroid, c);
}

/* Two points: a static box from one to the other, `height` thick. */
static void add_wall(pga_app *app)
{
    pg_vec2 a0 = app->pending[0], a1 = app->pending[1];
    pg_vec2 d = pg_v2_sub(a1, a0);
    pg_fix length = pg_v2_length(d);
    pg_angle angle = pg_angle_atan2(d.y, d.x);
    pg_vec2 mid = pg_v2(pg_fix_from_ratio((int64_t)a0.x + a1.x, 2 * 65536), pg_fix_from_ratio((int64_t)a0.y + a1.y, 2 * 65536));
    tool_shapes s;
    pga_action a;
    char bl[PG_FIX_FORMAT_MAX];
    memset(&s, 0, sizeof s);
    if (length < pg_fix_from_ratio(5, 100) || length > PG_FIX_C(100) ||
        pg_geometry_box(length / 2, app->params.height / 2, pg_v2_zero(), 0, &s.parts[0]) != PG_OK) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: a wall must be 0.05..100 m long (the points are %s m apart)", fmt(length, bl));
        return;
    }
    s.count = 1;
    s.outline = s.parts[0];
    if (!place(app, "wall", &s, mid, angle, 1, &mid)) return;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_MAKE);
    a.command.make_kind = PG_MAKE_WALL;
    a.command.body_def = new_body_def(app, PG_BODY_STATIC, mid, angle);
    a.command.shape_def = new_shape_def(app);
    a.command.size0 = length;
    a.command.size1 = app->params.height;
    if (pga__queue(app, &a) == PG_OK) pga__say(app, PGA_MESSAGE_INFO, "Added a wall %s m long", fmt(length, bl));
}

static void collect(pga_app *app, pg_vec2 point, uint32_t needed, const char *what)
{
    app->pending[app->pending_count++] = point;
    if (app->pending_count < needed) {
        pga__say(app, PGA_MESSAGE_INFO, "%s: point %u of %u", what, app->pending_count, needed);
        return;
    }
    if (needed == 3) add_triangle(app);
    else add_wall(app);
    app->pending_count = 0;
}

static void select_and_grab(pga_app *app, pg_vec2 point)
{
    const pg_world *w = pga__world(app);
    pg_body_id body = pga__body_at(app, point);
    if (body.generation == 0) {
        app->selected = body;
        pga__say(app, PGA_MESSAGE_INFO, "Nothing here: no body selected");
        return;
    }
    (void)pga_select(app, body);
    if (pg_body_type_of(w, body) != PG_BODY_STATIC) pga__drag_start(app, body, point);
    pga__say(app, PGA_MESSAGE_INFO, "Selected body %u", body.index);
}

/* A joint drawn near the point goes first (joints are drawn over bodies), else the body
 * under it, with the anchors of its joints to the world. */
static void delete_at(pga_app *app, pg_vec2 point)
{
    pg_body_id body;
    pga_action a;
    if (pga__delete_joint_at(app, point)) return;
    body = pga__body_at(app, point);
    if (body.generation == 0) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Nothing to delete here");
        return;
    }
    pga__remove_anchors_of(app, body, 0);
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_DESTROY_BODY);
    a.command.body = body;
    if (pga__queue(app, &a) == PG_OK) pga__say(app, PGA_MESSAGE_INFO, "Deleted body %u", body.index);
}

void pga_pointer_down(pga_app *app, pg_vec2 point)
{
    if (app == NULL) return;
    if (app->mode != PGA_MODE_LIVE) {
        pga__say(app, PGA_MESSAGE_REFUSED, "%s", app->mode == PGA_MODE_EMPTY ? "Load a scene first" : "Stop the playback to change the world");
        return;
    }
    if (!point_ok(app, point)) return;
    switch (app->tool) {
    case PGA_TOOL_MOVE: select_and_grab(app, point); break;
    case PGA_TOOL_DELETE: delete_at(app, point); break;
    case PGA_TOOL_TRIANGLE: collect(app, point, 3, "Triangle"); break;
    case PGA_TOOL_WALL: collect(app, point, 2, "Wall"); break;
    case PGA_TOOL_PIN:
    case PGA_TOOL_ROD:
    case PGA_TOOL_SPRING: pga__joint_tool_press(app, point); break;
    default: add_one_click(app, app->tool, point); break;
    }
}

const pg_vec2 *pga_pending_points(const pga_app *app, uint32_t *count)
{
    if (count != NULL) *count = app == NULL ? 0 : app->pending_count;
    return app == NULL ? NULL : app->pending;
}
