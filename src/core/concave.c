/* concave.c — concave polygons: pg_geometry_decompose (the pieces, for the caller) and
 * pg_make_concave (a body of them). The geometry is decompose.c's; this file checks
 * everything a body needs before it makes one, so a failing call changes nothing. */
#include "concave.h"
#include "body.h"
#include "decompose.h"
#include "error.h"
#include "island.h"
#include "mass.h"
#include "reach.h"
#include "shape.h"

pg_result pg_geometry_decompose(const pg_vec2 *vertices, int32_t count, pg_geometry *pieces, int32_t capacity,
                                int32_t *piece_count, char *message, size_t message_capacity)
{
    pg__decomposition d;
    pg__text why = pg__text_in(message, message_capacity);
    pg_result r;
    int32_t k;
    if (piece_count != NULL) *piece_count = 0;
    if (vertices == NULL || pieces == NULL || piece_count == NULL) {
        pg__text_put(&why, vertices == NULL ? "vertices is NULL" : pieces == NULL ? "pieces is NULL" : "piece_count is NULL");
        return PG_ERR_NULL;
    }
    if (!PG_SHAPES_KEPT(PG_SHAPES_POLYGON)) {
        pg__text_put(&why, PG__LEFT_OUT_KIND("pg_geometry_decompose"));
        return PG_ERR_INVALID_ARGUMENT;
    }
    r = pg__decompose(vertices, count, &d, &why);
    if (r != PG_OK) return r;
    if (d.count > capacity) {
        pg__text_put(&why, "the polygon gives ");
        pg__text_i64(&why, d.count);
        pg__text_put(&why, " pieces, capacity is ");
        pg__text_i64(&why, capacity);
        return PG_ERR_CAPACITY;
    }
    for (k = 0; k < d.count; ++k) pg__piece_geometry(vertices, &d.pieces[k], &pieces[k]);
    *piece_count = d.count;
    return PG_OK;
}

/* pg_make_concave's working set (a decomposition is over 500 bytes), kept off the stack
 * (the budget of docs/embedded.md, Stack, when a scene reader makes the body): in the
 * world's scratch, free between steps, after the mass scratch, because the pieces are
 * attached after pg_compound_mass has checked their mass in its work space. */
typedef struct concave_work {
    pg__decomposition decomposition;
    char message[144];
} concave_work;

static size_t concave_work_offset(void) { return (pg__body_mass_scratch_bytes() + 7u) & ~(size_t)7u; }

size_t pg__concave_scratch_bytes(void)
{
    if (!PG_SHAPES_KEPT(PG_SHAPES_POLYGON)) return pg__body_mass_scratch_bytes(); /* no concave bodies */
    return concave_work_offset() + sizeof(concave_work);
}

static concave_work *concave_work_of(const pg_world *w)
{
    return (concave_work *)(void *)((unsigned char *)w->solver_scratch + concave_work_offset());
}

/* The largest |x| or |y| of the vertices, as pg__geometry_reach measures a shape. */
static pg_fix vertices_reach(const pg_vec2 *v, int32_t n)
{
    pg_fix reach = 0;
    int32_t i;
    for (i = 0; i < n; ++i) { /* within 1000 m (pg__decompose checked): negating is safe */
        pg_fix x = v[i].x < 0 ? -v[i].x : v[i].x, y = v[i].y < 0 ? -v[i].y : v[i].y;
        if (x > reach) reach = x;
        if (y > reach) reach = y;
    }
    return reach;
}

/* Why a dynamic body of these pieces would leave the mass formats, or NULL. The pieces'
 * collision forms are built in the free shape slots they are about to take: an unused
 * slot's contents are not state (neither hashed nor saved), and 62 forms on the stack
 * would be 9 KB. Their list is the world's mass list (body.h), which has room for 65. */
static const char *mass_problem(pg_world *w, const pg_vec2 *v, const pg__decomposition *d, pg_fix density, int rotates)
{
    const pg_geom **geoms;
    pg_fix *densities;
    uint32_t slot = 0;
    int32_t k;
    pg__body_mass_lists(w, &geoms, &densities);
    for (k = 0; k < d->count; ++k, ++slot) {
        pg_geometry g;
        while (w->shapes[slot].used) ++slot; /* the caller counted enough free slots */
        pg__piece_geometry(v, &d->pieces[k], &g);
        pg__shape_build_local(&g, &w->shapes[slot].local);
        geoms[k] = &w->shapes[slot].local;
        densities[k] = density;
    }
    return pg__mass_data_problem(pg_compound_mass(geoms, densities, d->count, pg__body_mass_work(w)), rotates);
}

pg_result pg_make_concave(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, const pg_vec2 *vertices, int32_t count,
                          pg_body_id *out)
{
    concave_work *work;
    const pg__decomposition *d;
    pg__text why;
    pg_body_id id;
    pg_result r;
    int32_t k;
    if (w == NULL) return PG_ERR_NULL;
    if (bd == NULL || sd == NULL || vertices == NULL || out == NULL)
        return pg__fail(w, PG_ERR_NULL, bd == NULL ? "pg_make_concave: body def is NULL" : sd == NULL ? "pg_make_concave: shape def is NULL"
                                        : vertices == NULL ? "pg_make_concave: vertices is NULL" : "pg_make_concave: out is NULL");
    out->index = 0;
    out->generation = 0;
    if (!PG_SHAPES_KEPT(PG_SHAPES_POLYGON)) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, PG__LEFT_OUT_KIND("pg_make_concave"));
    work = concave_work_of(w);
    d = &work->decomposition;
    why = pg__text_in(work->message, sizeof work->message);
    pg__text_put(&why, "pg_make_concave: ");
    r = pg__decompose(vertices, count, &work->decomposition, &why);
    if (r != PG_OK) return pg__fail(w, r, work->message);
    r = pg__check_shape_def(w, bd->type, sd);
    if (r != PG_OK) return r;
    if (vertices_reach(vertices, count) > pg__body_reach_limit(bd->type)) return pg__fail_reach(w, vertices_reach(vertices, count), bd->type);
    if (w->body_count >= w->def.max_bodies) return pg__fail(w, PG_ERR_CAPACITY, "max_bodies reached");
    if (w->shape_count + (uint32_t)d->count > w->def.max_shapes) return pg__fail(w, PG_ERR_CAPACITY, "max_shapes reached");
    if (bd->type == PG_BODY_DYNAMIC) {
        const char *problem = mass_problem(w, vertices, d, sd->density, !bd->fixed_rotation);
        if (problem != NULL) return pg__fail(w, PG_ERR_ENVELOPE, problem);
    }
    /* everything is checked; pg_body_create checks its def before it changes anything */
    r = pg_body_create(w, bd, &id);
    if (r != PG_OK) return r;
    for (k = 0; k < d->count; ++k) {
        pg_geometry g;
        uint32_t slot = 0;
        while (w->shapes[slot].used) ++slot;
        pg__piece_geometry(vertices, &d->pieces[k], &g);
        pg__shape_attach(w, id.index, slot, sd, &g);
    }
    pg__body_update_mass(w, id.index);
    pg__body_sync_geometry(w, id.index);
    pg__wake_body(w, id.index);
    *out = id;
    return PG_OK;
}
