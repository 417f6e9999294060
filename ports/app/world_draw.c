/* world_draw.c — a draw list from a world's public queries (see world_draw.h).
 *
 * Bodies are enumerated with one AABB query over the whole fixed-point range, which
 * returns them in ascending slot order; a body with no shape has no proxy and is not
 * drawn anyway.
 */
#include "world_draw.h"

#include <stdlib.h>

uint32_t pga_world_draw_color(pg_body_type type, pg_shape_kind kind, int32_t vertex_count)
{
    if (type == PG_BODY_STATIC) return 0x6b7280u;
    if (type == PG_BODY_KINEMATIC) return 0xd97706u;
    switch (kind) {
    case PG_SHAPE_CIRCLE: return 0x2563ebu;
    case PG_SHAPE_CAPSULE: return 0x16a34au;
    case PG_SHAPE_SEGMENT: return 0x374151u;
    case PG_SHAPE_POLYGON:
    default: return vertex_count == 3 ? 0xdb2777u : 0x7c3aedu;
    }
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
    everything.lo.x = everything.lo.y = -0x7fffffff;
    everything.hi.x = everything.hi.y = 0x7fffffff;
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
        if (type == PG_BODY_DYNAMIC && !pg_body_is_awake(world, bodies[b])) flags |= PGA_DRAW_ASLEEP;
        for (i = 0; i < n; ++i) {
            pg_geometry g;
            pga_draw_shape *d;
            if (pg_shape_geometry(world, shapes[i], &g) != PG_OK) continue;
            total++;
            if (written >= capacity || out == NULL) continue;
            d = &out[written++];
            d->body = bodies[b];
            d->kind = g.kind;
            d->count = g.count;
            d->radius = g.radius;
            d->flags = flags;
            d->color = pga_world_draw_color(type, g.kind, g.count);
            for (v = 0; v < g.count && v < PG_MAX_VERTICES; ++v)
                d->vertices[v] = pg_v2_add(position, pg_rot_apply(rot, g.vertices[v]));
        }
    }
    free(bodies);
    return total;
}
