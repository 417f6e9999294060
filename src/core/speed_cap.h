/* speed_cap.h (internal) — the envelope's speed and spin caps, as the step and the
 * setters keep them: whatever leaves a step is a velocity the API accepts back. Below
 * body.c and the step's stages, which all write velocities. */
#ifndef POGON_SRC_SPEED_CAP_H
#define POGON_SRC_SPEED_CAP_H
#include "envelope.h"
#include "world_types.h"

/* |v|^2 in Q32, unsigned (at most 2^63 for any two int32 components). */
uint64_t pg__speed_squared(pg_vec2 v);
/* |v| in Q16.16, rounded up, as int64 (up to 2^31.5: it need not fit pg_fix). */
int64_t pg__speed_ceil(pg_vec2 v);
/* The documented speed cap: the inline test passes every legal velocity through, the
 * out-of-line part scales a faster one down, counts it in stats.speed_clamps and sets
 * PG_BODY_FLAG_SPEED_CLAMPED in *flags. */
pg_vec2 pg__clamp_speed_slow(pg_world *world, pg_vec2 v, uint32_t *flags);
static inline pg_vec2 pg__clamp_speed(pg_world *world, pg_vec2 v, uint32_t *flags)
{
    int64_t cap = world->def.max_linear_speed;
    /* each square is at most 2^62; their sum (2^63 for INT32_MIN twice) fits unsigned */
    if ((uint64_t)((int64_t)v.x * v.x) + (uint64_t)((int64_t)v.y * v.y) <= (uint64_t)(cap * cap)) return v;
    return pg__clamp_speed_slow(world, v, flags);
}
/* stats.saturations += n, saturating: what the step clamped to its formats' range. A
 * count, never state: it changes no result. */
static inline void pg__count_saturations(pg_world *world, uint32_t n)
{
    uint32_t s = world->stats.saturations;
    world->stats.saturations = n > UINT32_MAX - s ? UINT32_MAX : s + n;
}
/* Within the position envelope (+-PG_ENV_MAX_POSITION on both axes). */
static inline int pg__in_position_envelope(pg_vec2 p)
{
    return p.x >= -PG_ENV_MAX_POSITION && p.x <= PG_ENV_MAX_POSITION && p.y >= -PG_ENV_MAX_POSITION && p.y <= PG_ENV_MAX_POSITION;
}
/* Write the velocities a step leaves in a body, within what the setters accept: the
 * linear one within max_linear_speed, the angular one within +-1000 rad/s (PG_ENV_MAX_SPIN).
 * The contact solve may exceed both (the solver's own bound is PG_SOLVER_VELOCITY_MAX);
 * each clamp is counted in the stats and flagged on the body. */
void pg__body_store_velocity(pg_world *world, pg_body *b, pg_vec2 v, pg_fix w);

#endif
