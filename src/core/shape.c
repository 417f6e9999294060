/* shape.c — geometry validation, shapes on bodies, and the six ready-made kinds. */
#include "body.h"
#include "contact.h"
#include "continuous.h"
#include "def_cookie.h"
#include "envelope.h"
#include "error.h"
#include "island.h"
#include "mass.h"
#include "reach.h"
#include "shape.h"
#include "wide.h"

#define MIN_EDGE PG_LINEAR_SLOP       /* shorter edges are degenerate */

/* A handle's shape, or NULL when the handle is stale or out of range. */
pg_shape *pg__shape(const pg_world *world, pg_shape_id id)
{
    pg_shape *s;
    if (world == NULL || id.index >= world->def.max_shapes || id.generation == 0) return NULL;
    s = &world->shapes[id.index];
    return (s->used && s->generation == id.generation) ? s : NULL;
}

/* A geometry on its own may reach as far as a static body allows; a moving body's
 * shapes are held to PG_ENV_MAX_SIZE when they join it (pg__body_reach_limit). */
static int offset_ok(pg_vec2 p)
{
    return p.x >= -PG_ENV_MAX_STATIC_REACH && p.x <= PG_ENV_MAX_STATIC_REACH && p.y >= -PG_ENV_MAX_STATIC_REACH &&
           p.y <= PG_ENV_MAX_STATIC_REACH;
}
static int radius_ok(pg_fix r) { return r >= PG_ENV_MIN_HALF_THICKNESS && r <= PG_ENV_MAX_SIZE; }

/* Whether a width cross / sqrt(e2) is at least PG_ENV_MIN_THICKNESS, compared exactly as
 * cross^2 >= T^2 e2 in 128 bits (cross, e2 < 2^56 for vertices within the reach). */
static int wide_enough(int64_t cross, int64_t e2)
{
    const uint64_t t = (uint64_t)PG_ENV_MIN_THICKNESS;
    pg_u128 lhs, rhs;
    if (cross <= 0) return 0;
    lhs = pg__mul_u64((uint64_t)cross, (uint64_t)cross);
    rhs = pg__mul_u64(t * t, (uint64_t)e2);
    return lhs.hi > rhs.hi || (lhs.hi == rhs.hi && lhs.lo >= rhs.lo);
}

static void clear_geometry(pg_geometry *g)
{
    int i;
    g->kind = PG_SHAPE_CIRCLE;
    g->count = 0;
    g->radius = 0;
    for (i = 0; i < PG_MAX_VERTICES; ++i) g->vertices[i] = pg_v2_zero();
}

pg_result pg_geometry_circle(pg_vec2 center, pg_fix radius, pg_geometry *out)
{
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (!radius_ok(radius)) return radius <= 0 ? PG_ERR_DEGENERATE : PG_ERR_ENVELOPE;
    if (!offset_ok(center)) return PG_ERR_ENVELOPE;
    out->kind = PG_SHAPE_CIRCLE;
    out->count = 1;
    out->vertices[0] = center;
    out->radius = radius;
    return PG_OK;
}

static pg_result two_points(pg_vec2 a, pg_vec2 b, pg_fix min_length)
{
    int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y;
    if (!offset_ok(a) || !offset_ok(b)) return PG_ERR_ENVELOPE;
    if (dx * dx + dy * dy < (int64_t)min_length * min_length) return PG_ERR_DEGENERATE;
    return PG_OK;
}

pg_result pg_geometry_segment(pg_vec2 a, pg_vec2 b, pg_geometry *out)
{
    pg_result r;
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (!PG_SHAPES_KEPT(PG_SHAPES_SEGMENT)) return PG_ERR_INVALID_ARGUMENT;
    r = two_points(a, b, PG_ENV_MIN_THICKNESS);
    if (r != PG_OK) return r;
    out->kind = PG_SHAPE_SEGMENT;
    out->count = 2;
    out->vertices[0] = a;
    out->vertices[1] = b;
    return PG_OK;
}

/* A neighbour is the segment's own end (none: the chain ends there) or a point at least
 * an edge's length away from it. */
static int ghost_ok(pg_vec2 ghost, pg_vec2 end)
{
    int64_t dx = (int64_t)ghost.x - end.x, dy = (int64_t)ghost.y - end.y;
    if (!offset_ok(ghost)) return 0;
    return (dx == 0 && dy == 0) || dx * dx + dy * dy >= (int64_t)MIN_EDGE * MIN_EDGE;
}

pg_result pg_geometry_chain_segment(pg_vec2 before, pg_vec2 a, pg_vec2 b, pg_vec2 after, pg_geometry *out)
{
    pg_result r;
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (!PG_SHAPES_KEPT(PG_SHAPES_CHAIN)) return PG_ERR_INVALID_ARGUMENT;
    r = two_points(a, b, PG_ENV_MIN_THICKNESS);
    if (r != PG_OK) return r;
    if (!offset_ok(before) || !offset_ok(after)) return PG_ERR_ENVELOPE;
    if (!ghost_ok(before, a) || !ghost_ok(after, b)) return PG_ERR_DEGENERATE;
    out->kind = PG_SHAPE_CHAIN_SEGMENT;
    out->count = 2;
    out->vertices[0] = a;
    out->vertices[1] = b;
    out->vertices[2] = before;
    out->vertices[3] = after;
    return PG_OK;
}

pg_result pg_geometry_capsule(pg_vec2 a, pg_vec2 b, pg_fix radius, pg_geometry *out)
{
    pg_result r;
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (!PG_SHAPES_KEPT(PG_SHAPES_CAPSULE)) return PG_ERR_INVALID_ARGUMENT;
    if (!radius_ok(radius)) return radius <= 0 ? PG_ERR_DEGENERATE : PG_ERR_ENVELOPE;
    r = two_points(a, b, MIN_EDGE);
    if (r != PG_OK) return r;
    out->kind = PG_SHAPE_CAPSULE;
    out->count = 2;
    out->vertices[0] = a;
    out->vertices[1] = b;
    out->radius = radius;
    return PG_OK;
}

pg_result pg_geometry_polygon(const pg_vec2 *vertices, int32_t count, pg_geometry *out)
{
    int32_t i;
    int64_t area2 = 0;
    if (out == NULL || vertices == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (count < 3 || count > PG_MAX_VERTICES) return PG_ERR_INVALID_ARGUMENT;
    if (!PG_SHAPES_KEPT(count == 4 ? PG_SHAPES_BOX : PG_SHAPES_POLYGON)) return PG_ERR_INVALID_ARGUMENT;
    for (i = 0; i < count; ++i)
        if (!offset_ok(vertices[i])) return PG_ERR_ENVELOPE;
    for (i = 0; i < count; ++i) { /* twice the signed area, relative to vertex 0 (|v| <= 2^22) */
        pg_vec2 a = vertices[i], b = vertices[(i + 1) % count];
        area2 += ((int64_t)a.x - vertices[0].x) * ((int64_t)b.y - vertices[0].y) -
                 ((int64_t)a.y - vertices[0].y) * ((int64_t)b.x - vertices[0].x);
    }
    if (area2 == 0) return PG_ERR_DEGENERATE;
    for (i = 0; i < count; ++i) out->vertices[i] = area2 > 0 ? vertices[i] : vertices[count - 1 - i];
    for (i = 0; i < count; ++i) {
        pg_vec2 a = out->vertices[i], b = out->vertices[(i + 1) % count], c = out->vertices[(i + 2) % count];
        int64_t ex = (int64_t)b.x - a.x, ey = (int64_t)b.y - a.y, fx = (int64_t)c.x - b.x, fy = (int64_t)c.y - b.y;
        int64_t cross = ex * fy - ey * fx;
        if (ex * ex + ey * ey < (int64_t)MIN_EDGE * MIN_EDGE) return PG_ERR_DEGENERATE;
        if (cross == 0) return PG_ERR_DEGENERATE;
        if (cross < 0) return PG_ERR_NOT_CONVEX;
    }
    /* A winding that turns twice (a pentagram) passes the local test above; every
     * vertex must also lie left of the fan lines from vertex 0. */
    for (i = 1; i + 1 < count; ++i) {
        pg_vec2 a = out->vertices[0], b = out->vertices[i], c = out->vertices[i + 1];
        int64_t cross = ((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
        if (cross <= 0) return PG_ERR_NOT_CONVEX;
    }
    /* Thickness, the one rule of every shape: against each edge's line the farthest
     * vertex lies at least PG_ENV_MIN_THICKNESS away (a box's shorter side, a thin
     * polygon's narrowest width). */
    for (i = 0; i < count; ++i) {
        pg_vec2 a = out->vertices[i], b = out->vertices[(i + 1) % count];
        int64_t ex = (int64_t)b.x - a.x, ey = (int64_t)b.y - a.y, widest = 0;
        int32_t j;
        for (j = 0; j < count; ++j) {
            int64_t c = ex * ((int64_t)out->vertices[j].y - a.y) - ey * ((int64_t)out->vertices[j].x - a.x);
            if (c > widest) widest = c;
        }
        if (!wide_enough(widest, ex * ex + ey * ey)) return PG_ERR_ENVELOPE;
    }
    out->kind = PG_SHAPE_POLYGON;
    out->count = count;
    return PG_OK;
}

pg_result pg_geometry_box(pg_fix hw, pg_fix hh, pg_vec2 center, pg_angle angle, pg_geometry *out)
{
    pg_vec2 v[4];
    pg_rot r = pg_rot_from_angle(angle);
    int i;
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (hw <= 0 || hh <= 0) return PG_ERR_DEGENERATE;
    if (hw < PG_ENV_MIN_HALF_THICKNESS || hh < PG_ENV_MIN_HALF_THICKNESS || hw > PG_ENV_MAX_STATIC_REACH || hh > PG_ENV_MAX_STATIC_REACH)
        return PG_ERR_ENVELOPE;
    if (!offset_ok(center)) return PG_ERR_ENVELOPE;
    v[0] = pg_v2(-hw, -hh);
    v[1] = pg_v2(hw, -hh);
    v[2] = pg_v2(hw, hh);
    v[3] = pg_v2(-hw, hh);
    for (i = 0; i < 4; ++i) v[i] = pg_v2_add(center, angle == 0 ? v[i] : pg_rot_apply(r, v[i]));
    return pg_geometry_polygon(v, 4, out);
}

pg_result pg_geometry_triangle(pg_vec2 center, pg_fix circumradius, pg_angle angle, pg_geometry *out)
{
    pg_vec2 v[3];
    int i;
    if (out == NULL) return PG_ERR_NULL;
    clear_geometry(out);
    if (!PG_SHAPES_KEPT(PG_SHAPES_POLYGON)) return PG_ERR_INVALID_ARGUMENT;
    if (circumradius <= 0) return PG_ERR_DEGENERATE;
    if (circumradius > PG_ENV_MAX_STATIC_REACH) return PG_ERR_ENVELOPE; /* then the polygon's own rules */
    for (i = 0; i < 3; ++i) {
        pg_rot r = pg_rot_from_angle(angle + (pg_angle)((uint32_t)i * 1431655765u)); /* i/3 turn */
        v[i] = pg_v2_add(center, pg_v2(pg__mul_q30(circumradius, r.c), pg__mul_q30(circumradius, r.s)));
    }
    return pg_geometry_polygon(v, 3, out);
}

/* ---- shapes ---------------------------------------------------------------------------------- */
pg_shape_def pg_default_shape_def(void)
{
    pg_shape_def d;
    d.density = PG_FIX_ONE;
    d.friction = (pg_fix)39322; /* 0.6 */
    d.restitution = 0;
    d.category = 1u;
    d.mask = 0xFFFFFFFFu;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

void pg__shape_build_local(const pg_geometry *g, pg_geom *out)
{
    int32_t i, n = g->count;
    int64_t cx = 0, cy = 0;
    for (i = 0; i < PG_MAX_POLYGON_VERTICES; ++i) {
        out->vertices[i] = i < n ? g->vertices[i] : pg_v2_zero();
        out->normals[i].x = 0;
        out->normals[i].y = 0;
    }
    out->count = n;
    out->radius = g->radius;
    if (n >= 2) {
        for (i = 0; i < n; ++i) {
            pg_vec2 a = g->vertices[i], b = g->vertices[(i + 1) % n];
            out->normals[i] = pg_dir_normalize((int64_t)b.y - a.y, -((int64_t)b.x - a.x));
        }
        if (n == 2) {
            out->normals[1].x = -out->normals[0].x;
            out->normals[1].y = -out->normals[0].y;
        }
    }
    for (i = 0; i < n; ++i) cx += g->vertices[i].x, cy += g->vertices[i].y;
    /* the vertex average: a point inside, used by narrowphase for orientation only */
    out->centroid = pg_v2((pg_fix)(cx / n), (pg_fix)(cy / n));
}

static pg_result check_shape_def(const pg_world *world, const pg_body *b, const pg_shape_def *d)
{
    return pg__check_shape_def(world, b->type, d);
}

pg_result pg__check_shape_def(const pg_world *world, pg_body_type type, const pg_shape_def *d)
{
    if (d->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the shape def was not made by pg_default_shape_def(): start from pg_default_shape_def() and change the fields you need");
    if (type == PG_BODY_DYNAMIC && (d->density < PG_ENV_MIN_DENSITY || d->density > PG_ENV_MAX_DENSITY))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "density", d->density, "kg/m^2 is outside 0.1..100 for a dynamic body");
    if (d->density < 0 || d->density > PG_ENV_MAX_DENSITY)
        return pg__fail_value(world, PG_ERR_ENVELOPE, "density", d->density, "kg/m^2 is outside 0..100");
    if (d->friction < 0 || d->friction > PG_ENV_MAX_FRICTION)
        return pg__fail_value(world, PG_ERR_ENVELOPE, "friction", d->friction, "is outside 0..10");
    if (d->restitution < 0 || d->restitution > PG_FIX_ONE)
        return pg__fail_value(world, PG_ERR_ENVELOPE, "restitution", d->restitution, "is outside 0..1");
    return PG_OK;
}

/* Whether this build keeps g's kind (a polygon's by its vertex count). */
int pg__shape_kind_kept(const pg_geometry *g)
{
    switch (g->kind) {
    case PG_SHAPE_CIRCLE: return PG_SHAPES_KEPT(PG_SHAPES_CIRCLE);
    case PG_SHAPE_SEGMENT: return PG_SHAPES_KEPT(PG_SHAPES_SEGMENT);
    case PG_SHAPE_CAPSULE: return PG_SHAPES_KEPT(PG_SHAPES_CAPSULE);
    case PG_SHAPE_CHAIN_SEGMENT: return PG_SHAPES_KEPT(PG_SHAPES_CHAIN);
    case PG_SHAPE_POLYGON: return PG_SHAPES_KEPT(g->count == 4 ? PG_SHAPES_BOX : PG_SHAPES_POLYGON);
    default: return 1; /* not a kind: pg__validate_geometry refuses it */
    }
}

/* What pg__validate_geometry's result means for a geometry the caller filled in. */
static pg_result check_geometry(const pg_world *world, const pg_geometry *g)
{
    pg_result r;
    if (!pg__shape_kind_kept(g)) return pg__fail(world, PG_ERR_INVALID_ARGUMENT, PG__LEFT_OUT_KIND("geometry"));
    r = pg__validate_geometry(g);
    switch (r) {
    case PG_OK: return PG_OK;
    case PG_ERR_NOT_CONVEX:
        return pg__fail(world, r, "polygon vertices must be convex and counter-clockwise (pg_geometry_polygon puts clockwise ones in order)");
    case PG_ERR_DEGENERATE:
        return pg__fail(world, r, "geometry is degenerate: zero or negative radius, zero area, collinear vertices or an edge under 0.005 m");
    case PG_ERR_ENVELOPE:
        return pg__fail(world, r, "geometry is outside the envelope: radius 0.005..50 m, at least 0.01 m thick (a box's sides, a polygon's narrowest width, a segment's length), vertices within 1000 m of the body origin");
    default:
        return pg__fail(world, r, "geometry kind, count or radius do not match: circle 1 vertex, segment and chain segment 2 and radius 0, capsule 2, polygon 3..8 and radius 0 (use the pg_geometry_* functions)");
    }
}

pg_result pg__validate_geometry(const pg_geometry *g)
{
    pg_geometry copy;
    pg_result r;
    switch (g->kind) {
    case PG_SHAPE_CIRCLE:
        r = PG_SHAPES_KEPT(PG_SHAPES_CIRCLE) && g->count == 1 ? pg_geometry_circle(g->vertices[0], g->radius, &copy) : PG_ERR_INVALID_ARGUMENT;
        break;
    case PG_SHAPE_SEGMENT:
        r = PG_SHAPES_KEPT(PG_SHAPES_SEGMENT) && g->count == 2 && g->radius == 0 ? pg_geometry_segment(g->vertices[0], g->vertices[1], &copy) : PG_ERR_INVALID_ARGUMENT;
        break;
    case PG_SHAPE_CAPSULE:
        r = PG_SHAPES_KEPT(PG_SHAPES_CAPSULE) && g->count == 2 ? pg_geometry_capsule(g->vertices[0], g->vertices[1], g->radius, &copy) : PG_ERR_INVALID_ARGUMENT;
        break;
    case PG_SHAPE_CHAIN_SEGMENT:
        r = PG_SHAPES_KEPT(PG_SHAPES_CHAIN) && g->count == 2 && g->radius == 0 ? pg_geometry_chain_segment(g->vertices[2], g->vertices[0], g->vertices[1], g->vertices[3], &copy)
                                            : PG_ERR_INVALID_ARGUMENT;
        break;
    case PG_SHAPE_POLYGON:
        r = g->radius == 0 ? pg_geometry_polygon(g->vertices, g->count, &copy) : PG_ERR_INVALID_ARGUMENT;
        if (r == PG_OK) { /* must already be counter-clockwise: pg_geometry_polygon reverses a clockwise one */
            int32_t i;
            for (i = 0; i < g->count; ++i)
                if (copy.vertices[i].x != g->vertices[i].x || copy.vertices[i].y != g->vertices[i].y) r = PG_ERR_NOT_CONVEX;
        }
        break;
    default:
        r = PG_ERR_INVALID_ARGUMENT;
        break;
    }
    return r;
}

void pg__shape_attach(pg_world *world, uint32_t body, uint32_t i, const pg_shape_def *def, const pg_geometry *geometry)
{
    pg_body *b = &world->bodies[body];
    pg_shape *s;
    uint32_t *link;
    s = &world->shapes[i];
    {
        uint32_t generation = s->generation + 1u;
        s->generation = generation == 0 ? 1u : generation;
    }
    s->used = 1;
    s->body = body;
    s->next = PG_NULL_INDEX;
    s->geometry = *geometry;
    {
        /* unused vertex slots are not state: stored as zero (a chain segment's two
         * neighbours follow its two vertices) */
        int32_t k = geometry->kind == PG_SHAPE_CHAIN_SEGMENT ? 4 : geometry->count;
        for (; k < PG_MAX_POLYGON_VERTICES; ++k) s->geometry.vertices[k] = pg_v2_zero();
    }
    pg__shape_build_local(geometry, &s->local);
    pg__shape_set_extents(s);
    s->density = def->density;
    s->friction = def->friction;
    s->restitution = def->restitution;
    s->category = def->category;
    s->mask = def->mask;
    /* append: shapes stay in creation order */
    for (link = &b->first_shape; *link != PG_NULL_INDEX; link = &world->shapes[*link].next) {}
    *link = i;
    b->shape_count += 1u;
    b->flags |= PG_BODY_FLAG_GEOMETRY_DIRTY;
    if (i >= world->shape_high) world->shape_high = i + 1u;
    world->shape_count += 1u;
}

pg_result pg_shape_create(pg_world *world, pg_body_id body, const pg_shape_def *def, const pg_geometry *geometry, pg_shape_id *out)
{
    pg_body *b = pg__body(world, body);
    pg_shape *s;
    uint32_t i;
    pg_result r;
    const char *why;
    if (out != NULL) out->index = 0, out->generation = 0;
    if (world == NULL) return PG_ERR_NULL;
    if (def == NULL || geometry == NULL || out == NULL)
        return pg__fail(world, PG_ERR_NULL, def == NULL ? "pg_shape_create: def is NULL" : geometry == NULL ? "pg_shape_create: geometry is NULL" : "pg_shape_create: out is NULL");
    if (b == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_shape_create: body handle is stale or invalid");
    r = check_shape_def(world, b, def);
    if (r != PG_OK) return r;
    r = check_geometry(world, geometry);
    if (r != PG_OK) return r;
    if (geometry->kind == PG_SHAPE_CHAIN_SEGMENT && b->type != PG_BODY_STATIC)
        return pg__fail(world, PG_ERR_BODY_TYPE, "chain segments go on static bodies only (terrain)");
    if (pg__geometry_reach(geometry) > pg__body_reach_limit(b->type)) return pg__fail_reach(world, pg__geometry_reach(geometry), b->type);
    if (b->shape_count >= 64) return pg__fail(world, PG_ERR_CAPACITY, "a body has at most 64 shapes");
    if (b->type == PG_BODY_DYNAMIC) {
        pg_geom local;
        pg__shape_build_local(geometry, &local);
        why = pg__body_mass_problem(world, body.index, 0, PG_NULL_INDEX, &local, def->density, (b->flags & PG_BODY_FLAG_FIXED_ROTATION) == 0);
        if (why != NULL) return pg__fail(world, PG_ERR_ENVELOPE, why);
    }
    for (i = 0; i < world->def.max_shapes; ++i)
        if (!world->shapes[i].used) break;
    if (i == world->def.max_shapes) return pg__fail(world, PG_ERR_CAPACITY, "max_shapes reached");
    pg__shape_attach(world, body.index, i, def, geometry);
    s = &world->shapes[i];
    pg__body_update_mass(world, body.index);
    pg__body_sync_geometry(world, body.index);
    pg__wake_body(world, body.index);
    out->index = i;
    out->generation = s->generation;
    return PG_OK;
}

pg_result pg_shape_destroy(pg_world *world, pg_shape_id id)
{
    pg_shape *s = pg__shape(world, id);
    pg_body *b;
    uint32_t *link;
    if (world == NULL) return PG_ERR_NULL;
    if (s == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_shape_destroy: shape handle is stale or invalid");
    b = &world->bodies[s->body];
    if (b->type == PG_BODY_DYNAMIC) {
        /* what remains must still fit (removing a shape only lowers the inertia, so only
         * the lower limit can be crossed: a large shape holding a tiny one) */
        const char *why = pg__body_mass_problem(world, s->body, 0, id.index, NULL, 0, (b->flags & PG_BODY_FLAG_FIXED_ROTATION) == 0);
        if (why != NULL) return pg__fail(world, PG_ERR_ENVELOPE, why);
    }
    pg__remove_body_contacts(world, s->body); /* simplest correct: the body's pairs are found again */
    for (link = &b->first_shape; *link != id.index; link = &world->shapes[*link].next) {}
    *link = s->next;
    s->used = 0;
    b->shape_count -= 1u;
    world->shape_count -= 1u;
    pg__body_update_mass(world, s->body);
    b->flags |= PG_BODY_FLAG_GEOMETRY_DIRTY;
    pg__wake_body(world, s->body);
    return PG_OK;
}

pg_body_id pg_shape_body(const pg_world *world, pg_shape_id id)
{
    const pg_shape *s = pg__shape(world, id);
    pg_body_id b = {0, 0};
    if (s != NULL) {
        b.index = s->body;
        b.generation = world->bodies[s->body].generation;
    }
    return b;
}

pg_result pg_shape_geometry(const pg_world *world, pg_shape_id id, pg_geometry *out)
{
    const pg_shape *s = pg__shape(world, id);
    if (world == NULL) return PG_ERR_NULL;
    if (out == NULL) return pg__fail(world, PG_ERR_NULL, "pg_shape_geometry: out is NULL");
    if (s == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_shape_geometry: shape handle is stale or invalid");
    *out = s->geometry;
    return PG_OK;
}

/* ---- the six kinds ------------------------------------------------------------------------------ */
/* What pg__mass_data_problem finds in a new dynamic body of the first n (<= 2) shapes
 * g. Out of line: its two geometries would otherwise sit in make_body's frame below
 * everything it calls (docs/embedded.md, stack). */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static const char *first_shapes_mass_problem(pg_world *w, const pg_geometry *g, int n, pg_fix density, int rotates)
{
    pg_geom locals[2];
    const pg_geom *ptrs[2];
    pg_fix dens[2];
    int i;
    for (i = 0; i < n; ++i) {
        pg__shape_build_local(&g[i], &locals[i]);
        ptrs[i] = &locals[i];
        dens[i] = density;
    }
    return pg__mass_data_problem(pg_compound_mass(ptrs, dens, n, pg__body_mass_work(w)), rotates);
}

static pg_result make_body(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, const pg_geometry *g, int n, pg_body_id *out)
{
    pg_body_id id;
    pg_result r;
    const char *why;
    int i;
    if (w == NULL) return PG_ERR_NULL;
    if (bd == NULL || sd == NULL || out == NULL)
        return pg__fail(w, PG_ERR_NULL, bd == NULL ? "pg_make_*: body def is NULL" : sd == NULL ? "pg_make_*: shape def is NULL" : "pg_make_*: out is NULL");
    out->index = 0;
    out->generation = 0;
    if (w->body_count >= w->def.max_bodies) return pg__fail(w, PG_ERR_CAPACITY, "max_bodies reached");
    if (w->shape_count + (uint32_t)n > w->def.max_shapes) return pg__fail(w, PG_ERR_CAPACITY, "max_shapes reached");
    { /* validate everything first: a failing call must leave the pools untouched */
        pg_body probe;
        probe.type = bd->type;
        r = check_shape_def(w, &probe, sd);
        for (i = 0; r == PG_OK && i < n; ++i) r = check_geometry(w, &g[i]);
        if (r != PG_OK) return r;
        for (i = 0; i < n; ++i)
            if (pg__geometry_reach(&g[i]) > pg__body_reach_limit(bd->type)) return pg__fail_reach(w, pg__geometry_reach(&g[i]), bd->type);
        if (bd->type == PG_BODY_DYNAMIC) {
            why = first_shapes_mass_problem(w, g, n < 2 ? n : 2, sd->density, !bd->fixed_rotation);
            if (why != NULL) return pg__fail(w, PG_ERR_ENVELOPE, why);
        }
    }
    /* Everything is checked: the body and its shapes are made without further checks.
     * (Made shape by shape through pg_shape_create, a star whose first triangle alone is
     * below the inertia limit failed after its body was made, and undoing that left the
     * pools' generations moved on.) pg_body_create checks the body def before it changes
     * anything; the free slots were counted above. */
    r = pg_body_create(w, bd, &id);
    if (r != PG_OK) return r;
    for (i = 0; i < n; ++i) {
        uint32_t slot = 0;
        while (w->shapes[slot].used) ++slot;
        pg__shape_attach(w, id.index, slot, sd, &g[i]);
    }
    pg__body_update_mass(w, id.index);
    pg__body_sync_geometry(w, id.index);
    pg__wake_body(w, id.index);
    *out = id;
    return PG_OK;
}

static pg_result geometry_failed(pg_world *w, pg_result r, const char *what)
{
    return pg__fail(w, r, what);
}

pg_result pg_make_ball(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix radius, pg_body_id *out)
{
    pg_geometry g;
    pg_result r = pg_geometry_circle(pg_v2_zero(), radius, &g);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_CIRCLE) ? "ball radius must be 0.005..50 m" : PG__LEFT_OUT_KIND("pg_make_ball"));
    return make_body(w, bd, sd, &g, 1, out);
}

pg_result pg_make_capsule(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix length, pg_fix radius, pg_body_id *out)
{
    pg_geometry g;
    pg_result r = length < 0 ? PG_ERR_DEGENERATE : pg_geometry_capsule(pg_v2(-length / 2, 0), pg_v2(length - length / 2, 0), radius, &g);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_CAPSULE) ? "capsule length must be 0.005..2000 m and radius 0.005..50 m (a dynamic or kinematic capsule reaches at most 50 m from its centre)" : PG__LEFT_OUT_KIND("pg_make_capsule"));
    return make_body(w, bd, sd, &g, 1, out);
}

pg_result pg_make_box(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix width, pg_fix height, pg_body_id *out)
{
    pg_geometry g;
    pg_result r = pg_geometry_box(width / 2, height / 2, pg_v2_zero(), 0, &g);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_BOX) ? "box sides must be 0.01..2000 m (0.01..100 m on a dynamic or kinematic body)" : PG__LEFT_OUT_KIND("pg_make_box"));
    return make_body(w, bd, sd, &g, 1, out);
}

pg_result pg_make_triangle(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix circumradius, pg_body_id *out)
{
    pg_geometry g;
    pg_result r = pg_geometry_triangle(pg_v2_zero(), circumradius, PG_ANGLE_QUARTER, &g);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_POLYGON) ? "triangle circumradius must be 0.0067..1000 m (at least 0.01 m thick; up to 50 m on a dynamic or kinematic body)" : PG__LEFT_OUT_KIND("pg_make_triangle"));
    return make_body(w, bd, sd, &g, 1, out);
}

pg_result pg_make_star(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix circumradius, pg_body_id *out)
{
    pg_geometry g[2];
    pg_result r = pg_geometry_triangle(pg_v2_zero(), circumradius, PG_ANGLE_QUARTER, &g[0]);
    if (r == PG_OK) r = pg_geometry_triangle(pg_v2_zero(), circumradius, PG_ANGLE_QUARTER + PG_ANGLE_HALF, &g[1]);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_POLYGON) ? "star circumradius must be 0.0067..1000 m (at least 0.01 m thick; up to 50 m on a dynamic or kinematic body)" : PG__LEFT_OUT_KIND("pg_make_star"));
    return make_body(w, bd, sd, g, 2, out);
}

pg_result pg_make_wall(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix width, pg_fix height, pg_body_id *out)
{
    pg_body_def def;
    pg_geometry g;
    pg_result r;
    if (w == NULL) return PG_ERR_NULL;
    if (bd == NULL) return pg__fail(w, PG_ERR_NULL, "pg_make_wall: body def is NULL");
    def = *bd;
    def.type = PG_BODY_STATIC; /* whatever bd says: a wall does not move */
    def.linear_velocity = pg_v2_zero();
    def.angular_velocity = 0;
    r = pg_geometry_box(width / 2, height / 2, pg_v2_zero(), 0, &g);
    if (r != PG_OK) return w == NULL ? PG_ERR_NULL : geometry_failed(w, r, PG_SHAPES_KEPT(PG_SHAPES_BOX) ? "wall sides must be 0.01..2000 m" : PG__LEFT_OUT_KIND("pg_make_wall"));
    return make_body(w, &def, sd, &g, 1, out);
}
