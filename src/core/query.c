/* query.c — picking, box and shape overlap, free-position search, ray casts.
 * Queries read the world and change nothing (but pg_world_last_error, which every
 * result other than PG_OK sets, PG_ERR_NOT_FOUND included). They scan the shapes in
 * index order (results are sorted by body index and deduplicated), which is fast
 * enough for user interaction; the step itself never calls them.
 *
 * RANGE. Every exact test (pg_geom_contains, pg_geom_overlap, pg_geom_raycast) runs only
 * on a shape whose bounding box meets the query's box, so the two geometries it compares
 * lie within one box of each other. That is what keeps collide.c's and geom.c's int64
 * products in range: they take differences of coordinates, and a far-off shape (a body
 * that flew out of the envelope; positions saturate at +-32768 m) against a point on the
 * other side of the plane would overflow them (pg__dist2, pg__ray_circle). Absolute
 * coordinates up to +-2^31 raw are fine where the two geometries are close: their dot
 * products with Q2.30 normals stay below 2^62.5 and only their differences are
 * combined. A ray additionally has both ends within the envelope (checked), so every
 * shape it is tested against lies within a shape's size of +-1000 m. */
#include "body.h"
#include "collide.h"
#include "envelope.h"
#include "error.h"
#include "raycast.h"
#include "shape.h"
#include "text.h"
#include "world_types.h"

static int boxes_overlap(pg_aabb a, pg_aabb b) { return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y; }

/* ---- messages --------------------------------------------------------------------------- */
static pg_result fail2(const pg_world *w, pg_result r, const char *fn, const char *detail)
{
    char buf[144];
    pg__text t = pg__text_in(buf, sizeof buf);
    pg__text_put(&t, fn);
    pg__text_put(&t, ": ");
    pg__text_put(&t, detail);
    return pg__fail(w, r, buf);
}

/* What a geometry refused by pg__validate_geometry (the checks of pg_shape_create) has wrong. */
static const char *geometry_problem(pg_result r)
{
    switch (r) {
    case PG_ERR_NOT_CONVEX: return "geometry: polygon vertices must be convex and counter-clockwise (use pg_geometry_polygon)";
    case PG_ERR_DEGENERATE: return "geometry is degenerate: radius <= 0, no area, collinear vertices or an edge under 0.005 m";
    case PG_ERR_ENVELOPE: return "geometry is outside the envelope: radius 0.005..50 m, at least 0.01 m thick, vertices within 1000 m of its origin";
    default: return "geometry kind, count or radius do not fit together (build it with the pg_geometry_* functions)";
    }
}

/* The collision form of a query geometry, refused as pg_shape_create would refuse it. */
static pg_result query_local(const pg_world *w, const char *fn, const pg_geometry *geometry, pg_geom *local)
{
    pg_result r = pg__validate_geometry(geometry);
    if (r != PG_OK) return fail2(w, r, fn, geometry_problem(r));
    pg__shape_build_local(geometry, local); /* the same collision form a shape gets */
    return PG_OK;
}

/* ---- scanning ------------------------------------------------------------------------------ */
/* The world geometry of a shape as it is now (static and sleeping bodies keep theirs). */
static void shape_world_geom(const pg_world *w, uint32_t s, pg_geom *out)
{
    const pg_body *b = &w->bodies[w->shapes[s].body];
    pg_geom_transform(&w->shapes[s].local, b->origin, b->rot, out);
}

typedef int (*shape_test)(const pg_geom *g, const void *arg);

/* The number of bodies with a shape whose box meets `bound` and that passes `test`
 * (NULL: the box is enough); the first `capacity` of them go to out. any: stop at the
 * first (the count is then 0 or 1). */
static uint32_t scan(const pg_world *w, pg_aabb bound, shape_test test, const void *arg, pg_body_id *out, uint32_t capacity,
                     int any)
{
    uint32_t s, n = 0, b;
    /* bodies in ascending index: walk bodies, then their shapes */
    for (b = 0; b < w->body_high; ++b) {
        const pg_body *body = &w->bodies[b];
        if ((body->flags & PG_BODY_FLAG_USED) == 0) continue;
        for (s = body->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next) {
            pg_geom g;
            shape_world_geom(w, s, &g);
            if (!boxes_overlap(pg_geom_aabb(&g), bound)) continue; /* see RANGE above */
            if (test != NULL && !test(&g, arg)) continue;
            if (n < capacity) {
                out[n].index = b;
                out[n].generation = body->generation;
            }
            ++n;
            break;
        }
        if (any && n > 0) break;
    }
    return n;
}

/* The output checks every listing query makes; *count is 0 until the answer is known. */
static pg_result check_output(const pg_world *w, const char *fn, const pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    if (count != NULL) *count = 0;
    if (w == NULL) return PG_ERR_NULL;
    if (count == NULL) return fail2(w, PG_ERR_NULL, fn, "count is NULL");
    if (out == NULL && capacity > 0) return fail2(w, PG_ERR_NULL, fn, "out is NULL but capacity is not 0 (pass capacity 0 to only count)");
    return PG_OK;
}

static int test_point(const pg_geom *g, const void *arg) { return pg_geom_contains(g, *(const pg_vec2 *)arg); }
static int test_geom(const pg_geom *g, const void *arg) { return pg_geom_overlap(g, (const pg_geom *)arg); }

pg_result pg_world_query_point(const pg_world *w, pg_vec2 point, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    pg_aabb box;
    pg_result r = check_output(w, "pg_world_query_point", out, capacity, count);
    if (r != PG_OK) return r;
    box.lo = box.hi = point;
    *count = scan(w, box, test_point, &point, out, capacity, 0);
    return PG_OK;
}

pg_result pg_world_query_aabb(const pg_world *w, pg_aabb box, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    pg_result r = check_output(w, "pg_world_query_aabb", out, capacity, count);
    if (r != PG_OK) return r;
    if (box.lo.x > box.hi.x || box.lo.y > box.hi.y) return fail2(w, PG_ERR_INVALID_ARGUMENT, "pg_world_query_aabb", "query box must have lo <= hi");
    *count = scan(w, box, NULL, NULL, out, capacity, 0);
    return PG_OK;
}

pg_result pg_world_query_geometry(const pg_world *w, const pg_geometry *geometry, pg_vec2 position, pg_angle angle, pg_body_id *out,
                                  uint32_t capacity, uint32_t *count)
{
    static const char fn[] = "pg_world_query_geometry";
    pg_geom local, g;
    pg_result r = check_output(w, fn, out, capacity, count);
    if (r != PG_OK) return r;
    if (geometry == NULL) return fail2(w, PG_ERR_NULL, fn, "geometry is NULL");
    r = query_local(w, fn, geometry, &local);
    if (r != PG_OK) return r;
    pg_geom_transform(&local, position, pg_rot_from_angle(angle), &g);
    *count = scan(w, pg_geom_aabb(&g), test_geom, &g, out, capacity, 0);
    return PG_OK;
}

pg_result pg_world_find_free_position(const pg_world *w, const pg_geometry *geometry, pg_vec2 position, pg_angle angle, pg_fix max_distance,
                                      pg_fix resolution, pg_vec2 *out)
{
    static const char fn[] = "pg_world_find_free_position";
    uint32_t ring, k;
    pg_geom local;
    pg_rot rot;
    pg_result r;
    char buf[144];
    pg__text t;
    if (w == NULL) return PG_ERR_NULL;
    if (geometry == NULL) return fail2(w, PG_ERR_NULL, fn, "geometry is NULL");
    if (out == NULL) return fail2(w, PG_ERR_NULL, fn, "out is NULL");
    if (resolution <= 0 || max_distance < 0) return fail2(w, PG_ERR_INVALID_ARGUMENT, fn, "resolution must be > 0 and max_distance >= 0");
    if (max_distance / resolution > 256) return fail2(w, PG_ERR_INVALID_ARGUMENT, fn, "max_distance / resolution must be at most 256");
    r = query_local(w, fn, geometry, &local);
    if (r != PG_OK) return r;
    rot = pg_rot_from_angle(angle);
    for (ring = 0; (int64_t)ring * resolution <= max_distance; ++ring) {
        /* 8 ring-steps per ring unit around, starting to the right, counter-clockwise */
        uint32_t samples = ring == 0 ? 1u : 8u * ring;
        for (k = 0; k < samples; ++k) {
            pg_rot dir = pg_rot_from_angle((pg_angle)((UINT64_C(4294967296) * k) / samples));
            pg_fix radius = (pg_fix)((int64_t)ring * resolution);
            pg_vec2 p = pg_v2_add(position, pg_v2(pg__mul_q30(radius, dir.c), pg__mul_q30(radius, dir.s)));
            pg_geom g;
            pg_geom_transform(&local, p, rot, &g);
            if (scan(w, pg_geom_aabb(&g), test_geom, &g, NULL, 0, 1) == 0) {
                *out = p;
                return PG_OK;
            }
        }
    }
    t = pg__text_in(buf, sizeof buf);
    pg__text_put(&t, "no free position within max_distance ");
    pg__text_fix(&t, max_distance);
    pg__text_put(&t, " m (step ");
    pg__text_fix(&t, resolution);
    pg__text_put(&t, " m): search farther or place it elsewhere");
    return fail2(w, PG_ERR_NOT_FOUND, fn, buf);
}

/* ---- ray casts -------------------------------------------------------------------------------- */
static int within_envelope(int64_t v) { return v >= -(int64_t)PG_ENV_MAX_POSITION && v <= (int64_t)PG_ENV_MAX_POSITION; }

/* "origin x -1500 m is outside the envelope: ..." for the first coordinate of (x, y) out of it. */
static pg_result ray_outside(const pg_world *w, const char *what, int64_t x, int64_t y)
{
    int64_t v = within_envelope(x) ? y : x;
    char buf[144];
    pg__text t = pg__text_in(buf, sizeof buf);
    pg__text_put(&t, what);
    pg__text_put(&t, within_envelope(x) ? " y " : " x ");
    if (v > PG_FIX_MAX || v < PG_FIX_MIN) pg__text_put(&t, v > 0 ? "beyond 32768" : "beyond -32768");
    else pg__text_fix(&t, (pg_fix)v);
    pg__text_put(&t, " m is outside the envelope: both ends of a ray must lie within +-1000 m");
    return fail2(w, PG_ERR_ENVELOPE, "pg_world_raycast", buf);
}

/* The ray's box is widened by this much (Q16.16, about 1 mm) so that a hit a few LSB off the
 * exact segment, from rounding in pg_geom_raycast, is never lost to the box test. */
#define RAY_BOX_MARGIN ((pg_fix)64)

pg_result pg_world_raycast(const pg_world *w, pg_vec2 origin, pg_vec2 translation, pg_ray_hit *hit)
{
    uint32_t s;
    int found = 0;
    pg_fix best = PG_FIX_ONE;
    int64_t end_x, end_y;
    pg_aabb ray_box;
    if (w == NULL) return PG_ERR_NULL;
    if (hit == NULL) return fail2(w, PG_ERR_NULL, "pg_world_raycast", "hit is NULL");
    if (translation.x == 0 && translation.y == 0)
        return fail2(w, PG_ERR_INVALID_ARGUMENT, "pg_world_raycast", "ray translation must not be zero");
    end_x = (int64_t)origin.x + translation.x;
    end_y = (int64_t)origin.y + translation.y;
    if (!within_envelope(origin.x) || !within_envelope(origin.y)) return ray_outside(w, "origin", origin.x, origin.y);
    if (!within_envelope(end_x) || !within_envelope(end_y)) return ray_outside(w, "end (origin + translation)", end_x, end_y);
    /* both ends within +-1000 m: the box and its margin fit a pg_fix */
    ray_box.lo = pg_v2((pg_fix)((origin.x < end_x ? origin.x : end_x) - RAY_BOX_MARGIN),
                       (pg_fix)((origin.y < end_y ? origin.y : end_y) - RAY_BOX_MARGIN));
    ray_box.hi = pg_v2((pg_fix)((origin.x > end_x ? origin.x : end_x) + RAY_BOX_MARGIN),
                       (pg_fix)((origin.y > end_y ? origin.y : end_y) + RAY_BOX_MARGIN));
    for (s = 0; s < w->shape_high; ++s) {
        pg_geom g;
        pg_fix t;
        pg_vec2 point;
        pg_dir normal;
        if (!w->shapes[s].used) continue;
        shape_world_geom(w, s, &g);
        if (!boxes_overlap(pg_geom_aabb(&g), ray_box)) continue; /* see RANGE above */
        /* a chain segment is one-sided for rays as for contacts (as in Box2D v3): a ray
         * from behind it passes through */
        if (w->shapes[s].geometry.kind == PG_SHAPE_CHAIN_SEGMENT && pg_geom_behind_segment(&g, origin)) continue;
        if (pg_geom_raycast(&g, origin, translation, best, &t, &point, &normal) && (!found || t < best)) {
            const pg_shape *sh = &w->shapes[s];
            found = 1;
            best = t;
            hit->shape.index = s;
            hit->shape.generation = sh->generation;
            hit->body.index = sh->body;
            hit->body.generation = w->bodies[sh->body].generation;
            hit->point = point;
            hit->normal = pg_v2((pg_fix)pg__round_shift64(normal.x, 14), (pg_fix)pg__round_shift64(normal.y, 14));
            hit->fraction = t;
        }
    }
    if (!found) return fail2(w, PG_ERR_NOT_FOUND, "pg_world_raycast", "the ray hits no shape (an answer, not a failure: *hit is unchanged)");
    return PG_OK;
}
