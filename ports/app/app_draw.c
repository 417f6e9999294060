/* app_draw.c — what to draw: every shape of every body in world coordinates, with its
 * colour and flags; the joints (listed by world_draw_joints.c); the colours themselves; what an edit panel shows of a body.
 *
 * Colours live in user_data (PGA_COLOR_FLAG, 0xRRGGBB in bits 32..55), set by the command
 * that makes a body, so a replay shows the same colours. Scene bodies without the flag
 * get a fixed colour by type and shape, the same on every front end. */
#include "app_internal.h"
#include "world_draw.h"

#include <stdlib.h>

#define PGA_SHAPES_PER_BODY 64u

uint64_t pga_user_data_with_color(uint64_t user_data, uint32_t color)
{
    return (user_data & UINT64_C(0xffffffff)) | PGA_COLOR_FLAG | ((uint64_t)(color & 0xffffffu) << 32);
}

uint32_t pga__default_color(pg_body_type type, pg_shape_kind kind, uint32_t shape_count)
{
    if (type == PG_BODY_STATIC) return 0x6b7280u;    /* grey */
    if (type == PG_BODY_KINEMATIC) return 0xf59e0bu; /* amber: the player of the demo */
    if (shape_count > 1) return 0xeab308u;           /* a star, or a compound body */
    switch (kind) {
    case PG_SHAPE_CIRCLE: return 0xef4444u;  /* red */
    case PG_SHAPE_CAPSULE: return 0x10b981u; /* green */
    case PG_SHAPE_SEGMENT:
    case PG_SHAPE_CHAIN_SEGMENT: return 0x9ca3afu; /* light grey */
    default: return 0x3b82f6u;               /* blue: boxes and polygons */
    }
}

/* The colour of a body whose first shape is `kind` and that has `shape_count` shapes. */
static uint32_t color_of(const pg_world *w, pg_body_id body, pg_shape_kind kind, uint32_t shape_count)
{
    uint64_t ud = pg_body_user_data(w, body);
    if ((ud & PGA_COLOR_FLAG) != 0) return (uint32_t)(ud >> 32) & 0xffffffu;
    return pga__default_color(pg_body_type_of(w, body), kind, shape_count);
}

static pg_shape_kind first_kind(const pg_world *w, pg_body_id body, uint32_t *shape_count)
{
    pg_shape_id s;
    pg_geometry g;
    *shape_count = pg_body_shapes(w, body, &s, 1);
    if (*shape_count == 0 || pg_shape_geometry(w, s, &g) != PG_OK) return PG_SHAPE_POLYGON;
    return g.kind;
}

uint32_t pga_body_color(const pga_app *app, pg_body_id body)
{
    const pg_world *w = pga__world(app);
    uint32_t n;
    pg_shape_kind kind;
    if (w == NULL || !pg_body_is_valid(w, body)) return 0;
    kind = first_kind(w, body, &n);
    return color_of(w, body, kind, n);
}

static int grow_shapes(pga_scratch *s, uint32_t need)
{
    pga_draw_shape *grown;
    if (s->shape_capacity >= need) return 1;
    grown = (pga_draw_shape *)realloc(s->shapes, sizeof *grown * need);
    if (grown == NULL) return 0;
    s->shapes = grown;
    s->shape_capacity = need;
    return 1;
}

const pga_draw_shape *pga_draw_list(const pga_app *app, uint32_t *count)
{
    const pg_world *w = pga__world(app);
    pga_scratch *s;
    const pg_body_id *ids;
    uint32_t n, i, k, out = 0;
    if (count != NULL) *count = 0;
    if (w == NULL || count == NULL) return NULL;
    s = app->scratch;
    if (!grow_shapes(s, pg_world_get_def(w).max_shapes)) return NULL;
    ids = pga__list_bodies(app, w, &n);
    for (i = 0; i < n; ++i) {
        pg_body_id body = ids[i];
        pg_shape_id shapes[PGA_SHAPES_PER_BODY];
        uint32_t ns = pg_body_shapes(w, body, shapes, PGA_SHAPES_PER_BODY), flags = 0, color = 0;
        pg_body_type type = pg_body_type_of(w, body);
        pg_rot rot = pg_rot_from_angle(pg_body_angle(w, body));
        pg_vec2 pos = pg_body_position(w, body);
        if (ns > PGA_SHAPES_PER_BODY) ns = PGA_SHAPES_PER_BODY;
        if (pg_body_id_equal(body, app->selected)) flags |= PGA_DRAW_SELECTED;
        if (type == PG_BODY_STATIC) flags |= PGA_DRAW_STATIC;
        if (type == PG_BODY_KINEMATIC) flags |= PGA_DRAW_KINEMATIC;
        if (type != PG_BODY_STATIC && !pg_body_is_awake(w, body)) flags |= PGA_DRAW_ASLEEP;
        for (k = 0; k < ns && out < s->shape_capacity; ++k) {
            pga_draw_shape *d = &s->shapes[out];
            pg_geometry g;
            int32_t v;
            if (pg_shape_geometry(w, shapes[k], &g) != PG_OK) continue;
            if (k == 0) color = color_of(w, body, g.kind, ns);
            d->body = body;
            d->kind = g.kind == PG_SHAPE_CHAIN_SEGMENT ? PG_SHAPE_SEGMENT : g.kind; /* drawn as its segment */
            d->count = g.count;
            d->radius = g.radius;
            d->color = color;
            d->flags = flags;
            for (v = 0; v < g.count && v < PG_MAX_VERTICES; ++v) d->vertices[v] = pg_v2_add(pos, pg_rot_apply(rot, g.vertices[v]));
            out++;
        }
    }
    *count = out;
    return s->shapes;
}

pg_result pga_get_body_info(const pga_app *app, pg_body_id body, pga_body_info *out)
{
    const pg_world *w = pga__world(app);
    pga_body_info info;
    if (app == NULL || out == NULL) return PG_ERR_NULL;
    if (w == NULL || !pg_body_is_valid(w, body)) return PG_ERR_STALE_HANDLE;
    info.body = body;
    info.type = pg_body_type_of(w, body);
    info.kind = first_kind(w, body, &info.shape_count);
    info.position = pg_body_position(w, body);
    info.angle = pg_angle_to_radians(pg_body_angle(w, body));
    info.linear_velocity = pg_body_linear_velocity(w, body);
    info.angular_velocity = pg_body_angular_velocity(w, body);
    info.mass = info.type == PG_BODY_DYNAMIC ? pg_fix_from_ratio(pg_body_mass(w, body), INT64_C(1) << 32) : 0;
    info.color = color_of(w, body, info.kind, info.shape_count);
    info.user_data = pg_body_user_data(w, body);
    info.awake = pg_body_is_awake(w, body);
    *out = info;
    return PG_OK;
}

const pga_draw_joint *pga_draw_joints(const pga_app *app, uint32_t *count)
{
    const pg_world *w = pga__world(app);
    pga_scratch *s;
    uint32_t n;
    if (count != NULL) *count = 0;
    if (w == NULL || count == NULL) return NULL;
    s = app->scratch;
    n = pga_world_draw_joints(w, NULL, 0);
    if (n > s->joint_capacity) {
        pga_draw_joint *grown = (pga_draw_joint *)realloc(s->joints, sizeof *grown * n);
        if (grown == NULL) return NULL;
        s->joints = grown;
        s->joint_capacity = n;
    }
    *count = pga_world_draw_joints(w, s->joints, s->joint_capacity);
    if (*count > s->joint_capacity) *count = s->joint_capacity;
    return s->joints;
}

uint32_t pga_joint_count(const pga_app *app)
{
    const pg_world *w = pga__world(app);
    return w == NULL ? 0 : pga_world_draw_joints(w, NULL, 0);
}
