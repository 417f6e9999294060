/* query.c — picking, box and shape overlap, free-position search, ray casts.
 * Queries read the world and change nothing. They scan the shapes in index order
 * (results are sorted by body index and deduplicated), which is fast enough for user
 * interaction; the step itself never calls them. */
#include "world_internal.h"

static int boxes_overlap(pg_aabb a, pg_aabb b) { return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y; }

/* The world geometry of a shape as it is now (static and sleeping bodies keep theirs). */
static void shape_world_geom(const pg_world *w, uint32_t s, pg_geom *out)
{
    const pg_body *b = &w->bodies[w->shapes[s].body];
    pg_geom_transform(&w->shapes[s].local, b->origin, b->rot, out);
}

typedef int (*shape_test)(const pg_world *w, const pg_geom *g, const void *arg);

static pg_result collect(const pg_world *w, pg_aabb bound, shape_test test, const void *arg, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    uint32_t s, n = 0, last = PG_NULL_INDEX, b;
    if (count != NULL) *count = 0;
    if (w == NULL || count == NULL || (out == NULL && capacity > 0)) return PG_ERR_NULL;
    /* bodies in ascending index: walk bodies, then their shapes */
    for (b = 0; b < w->body_high; ++b) {
        const pg_body *body = &w->bodies[b];
        if ((body->flags & PG_BODY_FLAG_USED) == 0) continue;
        for (s = body->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next) {
            pg_geom g;
            shape_world_geom(w, s, &g);
            if (!boxes_overlap(pg_geom_aabb(&g), bound)) continue;
            if (test != NULL && !test(w, &g, arg)) continue;
            if (last != b) {
                if (n < capacity) {
                    out[n].index = b;
                    out[n].generation = body->generation;
                }
                ++n;
                last = b;
            }
            break;
        }
    }
    *count = n;
    return PG_OK;
}

static int test_point(const pg_world *w, const pg_geom *g, const void *arg) { (void)w; return pg_geom_contains(g, *(const pg_vec2 *)arg); }
static int test_geom(const pg_world *w, const pg_geom *g, const void *arg) { (void)w; return pg_geom_overlap(g, (const pg_geom *)arg); }

pg_result pg_world_query_point(const pg_world *w, pg_vec2 point, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    pg_aabb box;
    box.lo = box.hi = point;
    return collect(w, box, test_point, &point, out, capacity, count);
}

pg_result pg_world_query_aabb(const pg_world *w, pg_aabb box, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    if (box.lo.x > box.hi.x || box.lo.y > box.hi.y) {
        if (count != NULL) *count = 0;
        return w == NULL ? PG_ERR_NULL : pg__fail(w, PG_ERR_INVALID_ARGUMENT, "query box must have lo <= hi");
    }
    return collect(w, box, NULL, NULL, out, capacity, count);
}

static pg_result place_geometry(const pg_world *w, const pg_geometry *geometry, pg_vec2 position, pg_angle angle, pg_geom *out)
{
    pg_geom local;
    if (geometry->count < 1 || geometry->count > PG_MAX_VERTICES) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "geometry count must be 1..8");
    pg__shape_build_local(geometry, &local); /* the same collision form a shape gets */
    pg_geom_transform(&local, position, pg_rot_from_angle(angle), out);
    return PG_OK;
}

pg_result pg_world_query_geometry(const pg_world *w, const pg_geometry *geometry, pg_vec2 position, pg_angle angle, pg_body_id *out, uint32_t capacity, uint32_t *count)
{
    pg_geom g;
    pg_result r;
    if (count != NULL) *count = 0;
    if (w == NULL || geometry == NULL || count == NULL) return PG_ERR_NULL;
    r = place_geometry(w, geometry, position, angle, &g);
    if (r != PG_OK) return r;
    return collect(w, pg_geom_aabb(&g), test_geom, &g, out, capacity, count);
}

pg_result pg_world_find_free_position(const pg_world *w, const pg_geometry *geometry, pg_vec2 position, pg_angle angle, pg_fix max_distance, pg_fix resolution, pg_vec2 *out)
{
    uint32_t count = 0, ring, k;
    pg_result r;
    if (w == NULL || geometry == NULL || out == NULL) return PG_ERR_NULL;
    if (resolution <= 0 || max_distance < 0) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "resolution must be > 0 and max_distance >= 0");
    if (max_distance / resolution > 256) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "max_distance / resolution must be at most 256");
    for (ring = 0; (int64_t)ring * resolution <= max_distance; ++ring) {
        /* 8 ring-steps per ring unit around, starting to the right, counter-clockwise */
        uint32_t samples = ring == 0 ? 1u : 8u * ring;
        for (k = 0; k < samples; ++k) {
            pg_rot dir = pg_rot_from_angle((pg_angle)((UINT64_C(4294967296) * k) / samples));
            pg_fix radius = (pg_fix)((int64_t)ring * resolution);
            pg_vec2 p = pg_v2_add(position, pg_v2(pg__mul_q30(radius, dir.c), pg__mul_q30(radius, dir.s)));
            r = pg_world_query_geometry(w, geometry, p, angle, NULL, 0, &count);
            if (r != PG_OK) return r;
            if (count == 0) {
                *out = p;
                return PG_OK;
            }
        }
    }
    return PG_ERR_NOT_FOUND;
}

pg_result pg_world_raycast(const pg_world *w, pg_vec2 origin, pg_vec2 translation, pg_ray_hit *hit)
{
    uint32_t s;
    int found = 0;
    pg_fix best = PG_FIX_ONE;
    if (w == NULL || hit == NULL) return PG_ERR_NULL;
    if (translation.x == 0 && translation.y == 0) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "ray translation must not be zero");
    for (s = 0; s < w->shape_high; ++s) {
        pg_geom g;
        pg_fix t;
        pg_vec2 point;
        pg_dir normal;
        if (!w->shapes[s].used) continue;
        shape_world_geom(w, s, &g);
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
    return found ? PG_OK : PG_ERR_NOT_FOUND;
}
