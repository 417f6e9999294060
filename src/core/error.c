/* error.c — result codes' names and messages, and the last error a world reports. */
#include "error.h"
#include "text.h"
#include "world_types.h"

static const char *const result_names[PG_RESULT_COUNT] = {
    "PG_OK", "PG_ERR_NULL", "PG_ERR_INVALID_ARGUMENT", "PG_ERR_STALE_HANDLE", "PG_ERR_CAPACITY",
    "PG_ERR_MEMORY", "PG_ERR_ENVELOPE", "PG_ERR_DEGENERATE", "PG_ERR_NOT_CONVEX", "PG_ERR_BODY_TYPE",
    "PG_ERR_NOT_FOUND", "PG_ERR_INCOMPATIBLE"};
static const char *const result_messages[PG_RESULT_COUNT] = {
    "success",
    "a required pointer argument is NULL: pass a valid object or output pointer",
    "an argument has a value the function does not accept: see the function's documentation",
    "the handle names a body or shape that was destroyed: drop the handle",
    "a pool is full: create the world with larger max_bodies / max_shapes / max_contacts",
    "the memory block is too small: allocate pg_world_memory_size(&def) bytes, aligned to 8",
    "a value is outside pogon's envelope (README, Envelope): scale the scene into range",
    "degenerate geometry (no area or length, or repeated/collinear points): fix the vertices",
    "polygon vertices do not form a convex polygon: pass the convex hull",
    "the operation does not apply to this body type (e.g. a force on a static body)",
    "nothing was found",
    "the file was made by another numeric configuration, numerics or format version: use a build like its maker's, or upgrade an old format"};

const char *pg_result_name(pg_result r)
{
    return (unsigned)r < PG_RESULT_COUNT ? result_names[r] : "PG_ERR_UNKNOWN";
}

const char *pg_result_message(pg_result r)
{
    return (unsigned)r < PG_RESULT_COUNT ? result_messages[r] : "unknown result code";
}

pg_result pg__fail(const pg_world *world, pg_result r, const char *detail)
{
    if (world != NULL) {
        /* last_error is diagnostic scratch, not simulation state: writing it through a
         * const world is the one exception to "failing calls change nothing". */
        pg_world *w = (pg_world *)(uintptr_t)world;
        pg__text t = pg__text_in(w->last_error, sizeof w->last_error);
        pg__text_put(&t, result_names[r]);
        pg__text_put(&t, ": ");
        pg__text_put(&t, detail);
    }
    return r;
}

/* "before VALUE after" into buf */
static void join_value(char *buf, size_t cap, const char *before, pg_fix value, const char *after)
{
    pg__text t = pg__text_in(buf, cap);
    pg__text_put(&t, before);
    pg__text_put(&t, " ");
    pg__text_fix(&t, value);
    pg__text_put(&t, " ");
    pg__text_put(&t, after);
}

pg_result pg__fail_value(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *bound)
{
    char buf[144];
    join_value(buf, sizeof buf, what, value, bound);
    return pg__fail(world, r, buf);
}

pg_result pg__fail_limit(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *relation, pg_fix limit,
                         const char *unit)
{
    char buf[144];
    join_value(buf, sizeof buf, relation, limit, unit);
    return pg__fail_value(world, r, what, value, buf);
}

const char *pg_world_last_error(const pg_world *world) { return world != NULL ? world->last_error : ""; }
