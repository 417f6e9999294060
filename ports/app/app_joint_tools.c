/* app_joint_tools.c — the pin, rod and spring tools, and deleting a joint.
 *
 * Each tool takes two clicks. The first is kept as a pending point, with the body under it
 * (the one drawn on top) and the point in that body's frame, so the joint attaches where
 * the body was clicked even if it has moved since.
 *   pin     first a body, then the pin: a revolute joint at the second point between the
 *           first body and the body under that point (other than the first), or the world
 *           when there is none there: a click on empty space or on the first body itself
 *           pins it to the background, as an axle.
 *   rod     two points, each on a body or on empty space (at most one): a rigid distance
 *   spring  joint of the distance between them, with the spring of the parameters.
 * The world's end is a shapeless static body (user_data tag PGA_ANCHOR_TAG) made at the
 * point in the same frame; it belongs to its joint: deleting the joint or the joined body
 * deletes it too. Everything is checked at the click, so a refused joint queues nothing
 * and the message says why: no body, both ends on one body, both ends static, a length
 * outside 0.005..100 m or an anchor beyond 50 m of a moving body's origin. */
#include "app_internal.h"
#include "world_draw.h"

#include <stdlib.h>
#include <string.h>

#define PGA_JOINT_PICK (PG_FIX_ONE / 4)           /* the delete tool's reach to a joint, m */
#define PGA_JOINT_MIN_LENGTH pg_fix_from_ratio(5, 1000)
#define PGA_JOINT_MAX_LENGTH PG_FIX_C(100)
#define PGA_JOINT_MAX_LEVER PG_FIX_C(50)          /* pogon/joint.h: anchors of moving bodies */

static pg_body_id none_body(void)
{
    pg_body_id none = {0, 0};
    return none;
}

/* The body drawn on top at `point`, other than `skip`. */
static pg_body_id body_at_except(const pga_app *app, pg_vec2 point, pg_body_id skip)
{
    pg_body_id hits[16];
    uint32_t n = 0, i;
    const pg_world *w = pga__world(app);
    if (pg_world_query_point(w, point, hits, 16, &n) != PG_OK) return none_body();
    if (n > 16) n = 16;
    for (i = n; i > 0; --i)
        if (!pg_body_id_equal(hits[i - 1], skip)) return hits[i - 1];
    return none_body();
}

static pg_vec2 to_local(const pg_world *w, pg_body_id body, pg_vec2 point)
{
    return pg_rot_apply_inv(pg_rot_from_angle(pg_body_angle(w, body)), pg_v2_sub(point, pg_body_position(w, body)));
}

static pg_vec2 to_world(const pg_world *w, pg_body_id body, pg_vec2 local)
{
    return pg_v2_add(pg_body_position(w, body), pg_rot_apply(pg_rot_from_angle(pg_body_angle(w, body)), local));
}

static const char *fmt(pg_fix v, char buf[PG_FIX_FORMAT_MAX])
{
    pg_fix_format(v, buf, PG_FIX_FORMAT_MAX);
    return buf;
}

/* A moving body's anchor must be within 50 m of its origin. */
static int lever_ok(pga_app *app, const char *what, pg_body_id body, pg_vec2 local)
{
    const pg_world *w = pga__world(app);
    char b[PG_FIX_FORMAT_MAX];
    pg_fix lever;
    if (pg_body_type_of(w, body) == PG_BODY_STATIC) return 1;
    lever = pg_v2_length(local);
    if (lever <= PGA_JOINT_MAX_LEVER) return 1;
    pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the %s's end is %s m from body %u's origin; at most 50 m", what, fmt(lever, b),
             body.index);
    return 0;
}

/* Queue the anchor (a shapeless static body at `point`) that the joint queued next takes as body A. */
static pg_result queue_anchor(pga_app *app, pg_vec2 point)
{
    pga_action a;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_CREATE_BODY);
    a.command.body_def.type = PG_BODY_STATIC;
    a.command.body_def.position = point;
    a.command.body_def.user_data = PGA_ANCHOR_TAG;
    if (app->queue_count + 2 > PGA_QUEUE_CAPACITY) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: too many changes are waiting for the next frame");
        return PG_ERR_CAPACITY;
    }
    return pga__queue(app, &a);
}

static void pin(pga_app *app, pg_vec2 point)
{
    const pg_world *w = pga__world(app);
    pg_body_id first = app->pending_body, other;
    pga_action a;
    char bx[PG_FIX_FORMAT_MAX], by[PG_FIX_FORMAT_MAX];
    if (!pg_body_is_valid(w, first)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the body to pin is gone; click a body first");
        return;
    }
    other = body_at_except(app, point, first);
    if (pg_body_type_of(w, first) == PG_BODY_STATIC && (other.generation == 0 || pg_body_type_of(w, other) == PG_BODY_STATIC)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: body %u is static; pin it to a body that moves", first.index);
        return;
    }
    if (!lever_ok(app, "pin", first, to_local(w, first, point)) ||
        (other.generation != 0 && !lever_ok(app, "pin", other, to_local(w, other, point))))
        return;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_CREATE_REVOLUTE_JOINT);
    a.command.joint_def.revolute.body_b = first;
    a.command.joint_def.revolute.local_anchor_b = to_local(w, first, point);
    if (other.generation != 0) {
        a.command.joint_def.revolute.body_a = other;
        a.command.joint_def.revolute.local_anchor_a = to_local(w, other, point);
        a.command.joint_def.revolute.reference_angle = pg_body_angle(w, first) - pg_body_angle(w, other);
    } else {
        if (queue_anchor(app, point) != PG_OK) return;
        a.anchor_is_last_made = 1;
        a.command.joint_def.revolute.reference_angle = pg_body_angle(w, first);
    }
    if (pga__queue(app, &a) != PG_OK) return;
    if (other.generation != 0)
        pga__say(app, PGA_MESSAGE_INFO, "Pinned body %u to body %u at (%s, %s)", first.index, other.index, fmt(point.x, bx), fmt(point.y, by));
    else
        pga__say(app, PGA_MESSAGE_INFO, "Pinned body %u to the world at (%s, %s)", first.index, fmt(point.x, bx), fmt(point.y, by));
}

/* One end of a rod or spring: a body and its local point, or the world at `point`. */
typedef struct joint_end {
    pg_body_id body;
    pg_vec2 local, point;
} joint_end;

static void rod(pga_app *app, pg_vec2 point, int spring)
{
    const pg_world *w = pga__world(app);
    const char *what = spring ? "spring" : "rod";
    joint_end e[2], t;
    pg_fix length;
    pga_action a;
    pg_distance_joint_def *d;
    char bl[PG_FIX_FORMAT_MAX];
    e[0].body = app->pending_body;
    e[0].local = app->pending_local;
    if (e[0].body.generation != 0 && !pg_body_is_valid(w, e[0].body)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: the body of the %s's first end is gone", what);
        return;
    }
    e[0].point = e[0].body.generation != 0 ? to_world(w, e[0].body, e[0].local) : app->pending[0];
    e[1].body = pga__body_at(app, point);
    e[1].point = point;
    if (e[1].body.generation != 0) e[1].local = to_local(w, e[1].body, point);
    if (e[0].body.generation == 0 && e[1].body.generation == 0) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: neither end of the %s is on a body", what);
        return;
    }
    if (pg_body_id_equal(e[0].body, e[1].body)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: both ends of the %s are on body %u; it joins two bodies", what, e[0].body.index);
        return;
    }
    if ((e[0].body.generation == 0 || pg_body_type_of(w, e[0].body) == PG_BODY_STATIC) &&
        (e[1].body.generation == 0 || pg_body_type_of(w, e[1].body) == PG_BODY_STATIC)) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: neither end of the %s is on a body that moves", what);
        return;
    }
    length = pg_v2_length(pg_v2_sub(e[1].point, e[0].point));
    if (length < PGA_JOINT_MIN_LENGTH || length > PGA_JOINT_MAX_LENGTH) {
        pga__say(app, PGA_MESSAGE_REFUSED, "Refused: a %s must be 0.005..100 m long (the ends are %s m apart)", what, fmt(length, bl));
        return;
    }
    if (e[1].body.generation == 0) t = e[0], e[0] = e[1], e[1] = t; /* the world's end is body A */
    if ((e[0].body.generation != 0 && !lever_ok(app, what, e[0].body, e[0].local)) || !lever_ok(app, what, e[1].body, e[1].local))
        return;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_CREATE_DISTANCE_JOINT);
    d = &a.command.joint_def.distance;
    d->body_b = e[1].body;
    d->local_anchor_b = e[1].local;
    d->length = length;
    if (spring) {
        d->enable_spring = 1;
        d->hertz = app->params.spring_hertz;
        d->damping_ratio = app->params.spring_damping;
    }
    if (e[0].body.generation != 0) {
        d->body_a = e[0].body;
        d->local_anchor_a = e[0].local;
    } else {
        if (queue_anchor(app, e[0].point) != PG_OK) return;
        a.anchor_is_last_made = 1;
    }
    if (pga__queue(app, &a) == PG_OK)
        pga__say(app, PGA_MESSAGE_INFO, "Added a %s %s m long between %s", what, fmt(length, bl),
                 e[0].body.generation != 0 ? "two bodies" : "a body and the world");
}

void pga__joint_tool_press(pga_app *app, pg_vec2 point)
{
    const pg_world *w = pga__world(app);
    const char *what = app->tool == PGA_TOOL_PIN ? "Pin" : app->tool == PGA_TOOL_ROD ? "Rod" : "Spring";
    if (app->pending_count == 0) {
        pg_body_id body = pga__body_at(app, point);
        if (body.generation == 0 && app->tool == PGA_TOOL_PIN) {
            pga__say(app, PGA_MESSAGE_REFUSED, "Nothing to pin here: click the body to pin first");
            return;
        }
        app->pending[0] = point;
        app->pending_count = 1;
        app->pending_body = body;
        if (body.generation != 0) app->pending_local = to_local(w, body, point);
        if (app->tool == PGA_TOOL_PIN)
            pga__say(app, PGA_MESSAGE_INFO, "Pin body %u: click where the pin goes (on another body, or anywhere for the world)", body.index);
        else
            pga__say(app, PGA_MESSAGE_INFO, "%s: first end on %s; click the other end", what, body.generation != 0 ? "a body" : "the world");
        return;
    }
    app->pending_count = 0;
    if (app->tool == PGA_TOOL_PIN) pin(app, point);
    else rod(app, point, app->tool == PGA_TOOL_SPRING);
}

/* ---- deleting ---- */

static int is_anchor(const pg_world *w, pg_body_id body)
{
    pg_shape_id s;
    return body.generation != 0 && pg_body_type_of(w, body) == PG_BODY_STATIC &&
           (pg_body_user_data(w, body) & 0xffffffffu) == PGA_ANCHOR_TAG && pg_body_shapes(w, body, &s, 1) == 0;
}

static void destroy_body(pga_app *app, pg_body_id body, int now)
{
    pga_action a;
    memset(&a, 0, sizeof a);
    a.command = pg_command_init(PG_CMD_DESTROY_BODY);
    a.command.body = body;
    if (now) (void)pga__apply(app, &a.command, NULL);
    else (void)pga__queue(app, &a);
}

void pga__remove_anchors_of(pga_app *app, pg_body_id body, int now)
{
    const pg_world *w = pga__world(app);
    pg_joint_id joints[16], theirs[16];
    uint32_t n = pg_body_joints(w, body, joints, 16), i, k, m;
    if (n > 16) n = 16;
    for (i = 0; i < n; ++i) {
        pg_body_id other = pg_joint_body_a(w, joints[i]);
        int only_ours = 1;
        if (pg_body_id_equal(other, body)) other = pg_joint_body_b(w, joints[i]);
        if (!is_anchor(w, other)) continue;
        m = pg_body_joints(w, other, theirs, 16);
        for (k = 0; k < m && k < 16; ++k) {
            pg_body_id x = pg_joint_body_a(w, theirs[k]), y = pg_joint_body_b(w, theirs[k]);
            if (!pg_body_id_equal(x, body) && !pg_body_id_equal(y, body)) only_ours = 0;
        }
        if (only_ours && m <= 16) destroy_body(app, other, now);
    }
}

static uint64_t dist2(int64_t dx, int64_t dy) { return (uint64_t)(dx * dx) + (uint64_t)(dy * dy); }

/* Distance from p to the segment a-b, m (Q16.16), for p within PGA_JOINT_PICK of the
 * segment's box. Points are within the world's +-1000 m (bodies beyond are removed), so
 * differences stay below 2^28 and products below 2^56. */
static pg_fix distance_to_segment(pg_vec2 p, pg_vec2 a, pg_vec2 b)
{
    int64_t ex = (int64_t)b.x - a.x, ey = (int64_t)b.y - a.y, dx = (int64_t)p.x - a.x, dy = (int64_t)p.y - a.y;
    uint64_t ee = dist2(ex, ey);
    int64_t len, along, cross;
    if (ee == 0) return (pg_fix)pg_isqrt64(dist2(dx, dy));
    len = (int64_t)pg_isqrt64(ee);
    along = (dx * ex + dy * ey) / (len == 0 ? 1 : len);
    if (along <= 0) return (pg_fix)pg_isqrt64(dist2(dx, dy));
    if (along >= len) return (pg_fix)pg_isqrt64(dist2((int64_t)p.x - b.x, (int64_t)p.y - b.y));
    cross = (dx * ey - dy * ex) / len;
    return (pg_fix)(cross < 0 ? -cross : cross);
}

static const char *kind_name(const pg_world *w, pg_joint_id j)
{
    pg_distance_joint_def d;
    switch (pg_joint_type_of(w, j)) {
    case PG_JOINT_DISTANCE: return pg_distance_joint_get_def(w, j, &d) == PG_OK && d.enable_spring ? "a spring" : "a rod";
    case PG_JOINT_REVOLUTE: return "a pin";
    case PG_JOINT_WELD: return "a weld";
    case PG_JOINT_PRISMATIC: return "a prismatic joint";
    default: return "a drag";
    }
}

int pga__delete_joint_at(pga_app *app, pg_vec2 point)
{
    const pg_world *w = pga__world(app);
    uint32_t n = pga_world_draw_joints(w, NULL, 0), i, best = UINT32_MAX;
    pg_fix best_d = PGA_JOINT_PICK;
    pga_draw_joint *list;
    pg_body_id a_body, b_body;
    pga_action act;
    if (n == 0) return 0;
    list = (pga_draw_joint *)malloc(sizeof *list * n);
    if (list == NULL) return 0;
    n = pga_world_draw_joints(w, list, n);
    for (i = 0; i < n; ++i) {
        pg_vec2 lo = pg_v2(list[i].a.x < list[i].b.x ? list[i].a.x : list[i].b.x, list[i].a.y < list[i].b.y ? list[i].a.y : list[i].b.y);
        pg_vec2 hi = pg_v2(list[i].a.x > list[i].b.x ? list[i].a.x : list[i].b.x, list[i].a.y > list[i].b.y ? list[i].a.y : list[i].b.y);
        pg_fix d;
        if (point.x < lo.x - PGA_JOINT_PICK || point.x > hi.x + PGA_JOINT_PICK || point.y < lo.y - PGA_JOINT_PICK ||
            point.y > hi.y + PGA_JOINT_PICK)
            continue;
        d = distance_to_segment(point, list[i].a, list[i].b);
        if (d <= best_d) best_d = d, best = i;
    }
    if (best == UINT32_MAX) {
        free(list);
        return 0;
    }
    memset(&act, 0, sizeof act);
    act.command = pg_command_init(PG_CMD_DESTROY_JOINT);
    act.command.joint = list[best].joint;
    a_body = pg_joint_body_a(w, list[best].joint);
    b_body = pg_joint_body_b(w, list[best].joint);
    free(list);
    if (pga__queue(app, &act) != PG_OK) return 1;
    if (is_anchor(w, a_body) && pg_body_joints(w, a_body, NULL, 0) == 1) destroy_body(app, a_body, 0);
    if (is_anchor(w, b_body) && pg_body_joints(w, b_body, NULL, 0) == 1) destroy_body(app, b_body, 0);
    pga__say(app, PGA_MESSAGE_INFO, "Deleted joint %u (%s)", act.command.joint.index, kind_name(w, act.command.joint));
    return 1;
}
