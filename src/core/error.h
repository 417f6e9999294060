/* error.h (internal) — how a failing call reports: the result code it returns and a
 * message in pg_world_last_error naming what was wrong. */
#ifndef POGON_SRC_ERROR_H
#define POGON_SRC_ERROR_H
#include "pogon/pogon.h"

pg_result pg__fail(const pg_world *world, pg_result r, const char *detail);
pg_result pg__fail_value(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *bound);
/* "what VALUE relation LIMIT unit", e.g. "speed 565.6854 m/s exceeds the world's
 * max_linear_speed 400 m/s" from ("speed", v, "m/s exceeds the world's max_linear_speed",
 * cap, "m/s") */
pg_result pg__fail_limit(const pg_world *world, pg_result r, const char *what, pg_fix value, const char *relation, pg_fix limit,
                         const char *unit);

#endif
