/* chain.c — pg_make_chain: a static body of chain segments (terrain), each knowing its
 * neighbours so that collide.c can keep normals within the chain's own (no ghost bumps
 * at the joints). Everything is checked before the body is made. */
#include "body.h"
#include "chain.h"
#include "error.h"
#include "island.h"
#include "shape.h"

/* The chain segment from point i to the next, with its neighbours (a missing neighbour
 * at an open chain's end is the segment's own end). */
static pg_result segment_of(const pg_vec2 *p, int32_t n, int loop, int32_t i, pg_geometry *g)
{
    pg_vec2 a = p[i], b = p[(i + 1) % n];
    pg_vec2 before = (i > 0 || loop) ? p[(i + n - 1) % n] : a;
    pg_vec2 after = (i + 2 < n || loop) ? p[(i + 2) % n] : b;
    return pg_geometry_chain_segment(before, a, b, after, g);
}

pg_result pg__chain_problem(const pg_vec2 *points, int32_t count, int loop, pg__text *why)
{
    int32_t i, segments;
    if (loop ? (count < 3 || count > PG_CHAIN_MAX_POINTS - 1) : (count < 2 || count > PG_CHAIN_MAX_POINTS)) {
        pg__text_put(why, "a chain has 2..65 points (a loop 3..64), got ");
        pg__text_i64(why, count);
        return PG_ERR_INVALID_ARGUMENT;
    }
    for (i = 0; i < count; ++i)
        if (points[i].x < -PG_FIX_C(1000) || points[i].x > PG_FIX_C(1000) || points[i].y < -PG_FIX_C(1000) || points[i].y > PG_FIX_C(1000)) {
            pg__text_put(why, "point ");
            pg__text_i64(why, i);
            pg__text_put(why, " lies beyond 1000 m of the body origin");
            return PG_ERR_ENVELOPE;
        }
    segments = loop ? count : count - 1;
    for (i = 0; i < segments; ++i) {
        pg_geometry g;
        if (segment_of(points, count, loop, i, &g) != PG_OK) {
            pg__text_put(why, "segment ");
            pg__text_i64(why, i);
            pg__text_put(why, " (from point ");
            pg__text_i64(why, i);
            pg__text_put(why, " to the next) is shorter than 0.01 m");
            return PG_ERR_DEGENERATE;
        }
    }
    return PG_OK;
}

void pg__chain_segment(const pg_vec2 *points, int32_t count, int loop, int32_t i, pg_geometry *out)
{
    (void)segment_of(points, count, loop, i, out);
}

pg_result pg_make_chain(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, const pg_vec2 *points, int32_t count, int loop,
                        pg_body_id *out)
{
    pg_body_def def;
    pg_body_id id;
    pg_result r;
    int32_t i, segments;
    if (w == NULL) return PG_ERR_NULL;
    if (bd == NULL || sd == NULL || points == NULL || out == NULL)
        return pg__fail(w, PG_ERR_NULL, bd == NULL ? "pg_make_chain: body def is NULL" : sd == NULL ? "pg_make_chain: shape def is NULL"
                                        : points == NULL ? "pg_make_chain: points is NULL" : "pg_make_chain: out is NULL");
    out->index = 0;
    out->generation = 0;
    if (!PG_SHAPES_KEPT(PG_SHAPES_CHAIN)) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, PG__LEFT_OUT_KIND("pg_make_chain"));
    {
        char buf[144];
        pg__text why = pg__text_in(buf, sizeof buf);
        pg__text_put(&why, "pg_make_chain: ");
        r = pg__chain_problem(points, count, loop, &why);
        if (r != PG_OK) return pg__fail(w, r, buf);
    }
    segments = loop ? count : count - 1;
    def = *bd;
    def.type = PG_BODY_STATIC; /* terrain: whatever bd says */
    def.linear_velocity = pg_v2_zero();
    def.angular_velocity = 0;
    r = pg__check_shape_def(w, PG_BODY_STATIC, sd);
    if (r != PG_OK) return r;
    if (w->body_count >= w->def.max_bodies) return pg__fail(w, PG_ERR_CAPACITY, "max_bodies reached");
    if (w->shape_count + (uint32_t)segments > w->def.max_shapes) return pg__fail(w, PG_ERR_CAPACITY, "max_shapes reached");
    r = pg_body_create(w, &def, &id);
    if (r != PG_OK) return r;
    for (i = 0; i < segments; ++i) {
        pg_geometry g;
        uint32_t slot = 0;
        while (w->shapes[slot].used) ++slot;
        (void)segment_of(points, count, loop, i, &g);
        pg__shape_attach(w, id.index, slot, sd, &g);
    }
    pg__body_update_mass(w, id.index);
    pg__body_sync_geometry(w, id.index);
    pg__wake_body(w, id.index);
    *out = id;
    return PG_OK;
}
