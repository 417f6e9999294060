/* reach.c — how far a shape may reach from its body's origin, by the body's type. */
#include "envelope.h"
#include "error.h"
#include "reach.h"

pg_fix pg__geometry_reach(const pg_geometry *g)
{
    pg_fix reach = 0;
    int32_t i;
    for (i = 0; i < g->count && i < PG_MAX_VERTICES; ++i) {
        pg_fix x = g->vertices[i].x, y = g->vertices[i].y; /* within the static reach: negating is safe */
        if (x < 0) x = -x;
        if (y < 0) y = -y;
        if (x > reach) reach = x;
        if (y > reach) reach = y;
    }
    return reach;
}

pg_fix pg__body_reach_limit(pg_body_type type) { return type == PG_BODY_STATIC ? PG_ENV_MAX_STATIC_REACH : PG_ENV_MAX_SIZE; }

pg_result pg__fail_reach(const pg_world *world, pg_fix reach, pg_body_type type)
{
    return pg__fail_limit(world, PG_ERR_ENVELOPE, type == PG_BODY_KINEMATIC ? "a kinematic body's shape reaches" : "a dynamic body's shape reaches",
                          reach, "m from its origin, beyond", pg__body_reach_limit(type),
                          "m, its lever arms' limit (a static body's shapes reach 1000 m)");
}
