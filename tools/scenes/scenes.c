/* scenes.c — pyramid, stack, rain and heap. Geometry matches the peers' harnesses: 1 m boxes,
 * density 1, friction 0.6, a static ground whose top is at y = 0. */
#include "scenes.h"
#include <string.h>

static uint32_t default_count(const char *name)
{
    if (strcmp(name, "rain") == 0) return 1000;
    if (strcmp(name, "heap") == 0) return 4000;
    return 20;
}

static uint32_t bodies_for(const char *name, uint32_t count)
{
    if (strcmp(name, "pyramid") == 0) return count * (count + 1u) / 2u + 1u;
    if (strcmp(name, "rain") == 0) return count + 11u;
    if (strcmp(name, "heap") == 0) return count + 5u;
    return count + 1u;
}

pg_world_def pg_scene_world_def(const char *name, uint32_t count)
{
    pg_world_def d = pg_default_world_def();
    uint32_t n;
    if (count == 0) count = default_count(name);
    n = bodies_for(name, count);
    d.max_bodies = n;
    d.max_shapes = n;
    d.max_contacts = n * 4u + 64u;
    return d;
}

static pg_world_def effective_def(const char *name, uint32_t count, const pg_world_def *def)
{
    pg_world_def need = pg_scene_world_def(name, count), d = def != NULL ? *def : need;
    if (d.max_bodies < need.max_bodies) d.max_bodies = need.max_bodies;
    if (d.max_shapes < need.max_shapes) d.max_shapes = need.max_shapes;
    if (d.max_contacts < need.max_contacts) d.max_contacts = need.max_contacts;
    return d;
}

size_t pg_scene_memory_size(const char *name, uint32_t count, const pg_world_def *def)
{
    pg_world_def d = effective_def(name, count, def);
    return pg_world_memory_size(&d);
}

/* A deterministic generator for rain's positions (xorshift32). */
static uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

pg_result pg_scene_build(const char *name, uint32_t count, const pg_world_def *def, void *memory, size_t memory_size, pg_scene *out)
{
    pg_world_def d;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    pg_result r;
    uint32_t i, row;
    if (name == NULL || out == NULL) return PG_ERR_NULL;
    if (count == 0) count = default_count(name);
    d = effective_def(name, count, def);
    memset(out, 0, sizeof *out);
    r = pg_world_create(&d, memory, memory_size, &out->world);
    if (r != PG_OK) return r;
    if (strcmp(name, "pyramid") == 0 || strcmp(name, "stack") == 0) {
        bd.position = pg_v2(0, PG_FIX_C(-1));
        r = pg_make_wall(out->world, &bd, &sd, PG_FIX_C(100), PG_FIX_C(2), &id);
        if (r != PG_OK) return r;
        bd.type = PG_BODY_DYNAMIC;
        for (row = 0; row < (strcmp(name, "pyramid") == 0 ? count : 1u); ++row) {
            uint32_t n = strcmp(name, "pyramid") == 0 ? count - row : count;
            for (i = 0; i < n; ++i) {
                if (strcmp(name, "pyramid") == 0) {
                    /* row `row` has count - row boxes centred on x = 0 */
                    bd.position = pg_v2((pg_fix)((int32_t)(2 * i + 1) * 32768 - (int32_t)n * 32768), PG_FIX_HALF + PG_FIX_C((int32_t)row));
                } else {
                    bd.position = pg_v2(0, PG_FIX_HALF + PG_FIX_C((int32_t)i));
                }
                r = pg_make_box(out->world, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &id);
                if (r != PG_OK) return r;
                out->top = id;
                out->body_count += 1u;
            }
        }
    } else if (strcmp(name, "rain") == 0) {
        uint32_t seed = 12345u;
        /* a container 40 m wide (inside), walls 0.5 m thick; circles in a field above it */
        bd.position = pg_v2(0, PG_FIX_C(-1));
        r = pg_make_wall(out->world, &bd, &sd, PG_FIX_C(42), PG_FIX_C(2), &id);
        /* side walls in 100 m pieces, tall enough for the largest pile (16 000 circles
         * stand about 180 m high) */
        for (i = 0; r == PG_OK && i < 10u; ++i) {
            bd.position = pg_v2((i & 1u) ? PG_FIX_C(20) + PG_FIX_C(1) / 4 : PG_FIX_C(-20) - PG_FIX_C(1) / 4, PG_FIX_C(50 + 100 * (int32_t)(i / 2u)));
            r = pg_make_wall(out->world, &bd, &sd, PG_FIX_HALF, PG_FIX_C(100), &id);
        }
        if (r != PG_OK) return r;
        bd.type = PG_BODY_DYNAMIC;
        for (i = 0; i < count; ++i) {
            /* 39 columns 1 m apart, rows 1 m apart: circles start apart */
            pg_fix radius = (pg_fix)(16384 + (int32_t)(next_random(&seed) % 16385u)); /* 0.25 .. 0.5 m */
            uint32_t column = i % 39u, layer = i / 39u;
            pg_fix jitter = (pg_fix)((int32_t)(next_random(&seed) % 8193u) - 4096); /* +-1/16 m */
            bd.position = pg_v2(PG_FIX_C((int32_t)column) - PG_FIX_C(19) + jitter, PG_FIX_C(2) + PG_FIX_C((int32_t)layer));
            r = pg_make_ball(out->world, &bd, &sd, radius, &id);
            if (r != PG_OK) return r;
            out->top = id;
            out->body_count += 1u;
        }
    } else if (strcmp(name, "heap") == 0) {
        uint32_t seed = 2929u;
        /* a box 30 m wide inside, walls 0.5 m thick and 200 m tall, in 100 m pieces */
        bd.position = pg_v2(0, PG_FIX_C(-1));
        r = pg_make_wall(out->world, &bd, &sd, PG_FIX_C(32), PG_FIX_C(2), &id);
        for (i = 0; r == PG_OK && i < 4u; ++i) {
            bd.position = pg_v2((i & 1u) ? PG_FIX_C(15) + PG_FIX_C(1) / 4 : PG_FIX_C(-15) - PG_FIX_C(1) / 4, PG_FIX_C(50 + 100 * (int32_t)(i / 2u)));
            r = pg_make_wall(out->world, &bd, &sd, PG_FIX_HALF, PG_FIX_C(100), &id);
        }
        if (r != PG_OK) return r;
        bd.type = PG_BODY_DYNAMIC;
        for (i = 0; i < count; ++i) {
            /* every third body a box: circles of radius and boxes of half side 0.25 .. 0.5 m,
             * on 28 columns and rows 1.05 m apart (at most 1 m wide each: they start apart) */
            pg_fix size = (pg_fix)(16384 + (int32_t)(next_random(&seed) % 16385u));
            uint32_t column = i % 28u, layer = i / 28u;
            pg_fix jitter = (pg_fix)((int32_t)(next_random(&seed) % 1025u) - 512); /* +-1/128 m */
            const pg_fix spacing = (pg_fix)68813;                                   /* 1.05 m */
            bd.position = pg_v2((pg_fix)((int32_t)column * spacing - 27 * spacing / 2 + jitter), PG_FIX_C(1) + (pg_fix)((int32_t)layer * spacing));
            r = next_random(&seed) % 3u == 0u ? pg_make_box(out->world, &bd, &sd, 2 * size, 2 * size, &id) : pg_make_ball(out->world, &bd, &sd, size, &id);
            if (r != PG_OK) return r;
            out->top = id;
            out->body_count += 1u;
        }
    } else {
        return PG_ERR_INVALID_ARGUMENT;
    }
    out->top_start = pg_body_position(out->world, out->top);
    return PG_OK;
}
