/* world_draw.c — a draw list from a world's public queries (see world_draw.h).
 *
 * Bodies are enumerated with one AABB query over the whole fixed-point range, which
 * returns them in ascending slot order; a body with no shape has no proxy and is not
 * drawn anyway. Colours and flags follow pga_draw_list's rules (app_draw.c): the colour
 * in user_data when PGA_COLOR_FLAG is set, else pga__default_color.
 */
#include "world_draw.h"

#include "app_internal.h"

#include <stdlib.h>

uint32_t pga_world_draw_color(const pg_world *world, pg_body_id body, pg_shape_kind kind, uint32_t shape_count)
{
    uint64_t user_data = pg_body_user_data(world, body);
    if ((user_data & PGA_COLOR_FLAG) != 0) return (uint32_t)(user_data >> 32) & 0xffffffu;
    return pga__default_color(pg_body_type_of(world, body), kind, shape_count);
}

uint32_t pga_world_draw_shapes(const pg_world *world, pga_draw_shape *out, uint32_t capacity)
{
    pg_world_def def;
    pg_aabb everything;
    pg_body_id *bodies;
    pg_shape_id shapes[64];
    uint32_t body_count = 0, written = 0, total = 0, b, i;
    int32_t v;
    if (world == NULL) return 0;
    def = pg_world_get_def(world);
    bodies = (pg_body_id *)malloc((size_t)(def.max_bodies != 0 ? def.max_bodies : 1) * sizeof *bodies);
    if (bodies == NULL) return 0;
    everything.lo = pg_v2(PG_FIX_MIN, PG_FIX_MIN);
    everything.hi = pg_v2(PG_FIX_MAX, PG_FIX_MAX);
    if (pg_world_query_aabb(world, everything, bodies, def.max_bodies, &body_count) != PG_OK) body_count = 0;
    if (body_count > def.max_bodies) body_count = def.max_bodies;
    for (b = 0; b < body_count; ++b) {
        pg_body_type type = pg_body_type_of(world, bodies[b]);
        pg_vec2 position = pg_body_position(world, bodies[b]);
        pg_rot rot = pg_rot_from_angle(pg_body_angle(world, bodies[b]));
        uint32_t flags = 0, n = pg_body_shapes(world, bodies[b], shapes, 64u);
        if (n > 64u) n = 64u;
        if (type == PG_BODY_STATIC) flags |= PGA_DRAW_STATIC;
        if (type == PG_BODY_KINEMATIC) flags |= PGA_DRAW_KINEMATIC;
        if (type != PG_BODY_STATIC && !pg_body_is_awake(world, bodies[b])) flags |= PGA_DRAW_ASLEEP;
        uint32_t color = 0;
        for (i = 0; i < n; ++i) {
            pg_geometry g;
            pga_draw_shape *d;
            if (pg_shape_geometry(world, shapes[i], &g) != PG_OK) continue;
            if (i == 0) color = pga_world_draw_color(world, bodies[b], g.kind, n);
            total++;
            if (written >= capacity || out == NULL) continue;
            d = &out[written++];
            d->body = bodies[b];
            d->kind = g.kind == PG_SHAPE_CHAIN_SEGMENT ? PG_SHAPE_SEGMENT : g.kind; /* drawn as its segment */
            d->count = g.count;
            d->radius = g.radius;
            d->flags = flags;
            d->color = color;
            for (v = 0; v < g.count && v < PG_MAX_VERTICES; ++v)
                d->vertices[v] = pg_v2_add(position, pg_rot_apply(rot, g.vertices[v]));
        }
    }
    free(bodies);
    return total;
}
