/* speed_cap.c — the step's and the setters' speed and spin caps (see speed_cap.h). */
#include "speed_cap.h"
#include "wide.h"

/* |v|^2 in Q32, unsigned: for any two int32 components (INT32_MIN too) it is at most
 * 2^63, which a signed sum would overflow. */
uint64_t pg__speed_squared(pg_vec2 v)
{
    return pg__mag64(v.x) * pg__mag64(v.x) + pg__mag64(v.y) * pg__mag64(v.y);
}

/* |v| in Q16.16, rounded up, as int64 (up to 2^31.5: it need not fit pg_fix). */
int64_t pg__speed_ceil(pg_vec2 v)
{
    uint64_t ss = pg__speed_squared(v), r = pg_isqrt64(ss);
    return (int64_t)(r * r < ss ? r + 1u : r);
}

/* The speed cap acts on the magnitude: a faster velocity is scaled down to the cap,
 * keeping its direction, and the event is counted in stats.speed_clamps. Each component
 * becomes v cap / |v| with |v| rounded up and the quotient rounded toward zero (the
 * rounding rule for this one place, symmetric in sign): the result never exceeds the
 * cap, so a clamped velocity can be set again, saved in a scene file and read back. */
pg_vec2 pg__clamp_speed_slow(pg_world *world, pg_vec2 v, uint32_t *flags)
{
    uint64_t cap = (uint64_t)world->def.max_linear_speed, len;
    if (pg__speed_squared(v) <= cap * cap) return v;
    world->stats.speed_clamps += 1u;
    *flags |= PG_BODY_FLAG_SPEED_CLAMPED;
    len = (uint64_t)pg__speed_ceil(v); /* > cap >= 1 */
    /* |v.x| cap < 2^31 2^28: no overflow; the quotient is at most cap */
    return pg_v2((pg_fix)(v.x < 0 ? -(int64_t)(pg__mag64(v.x) * cap / len) : (int64_t)(pg__mag64(v.x) * cap / len)),
                 (pg_fix)(v.y < 0 ? -(int64_t)(pg__mag64(v.y) * cap / len) : (int64_t)(pg__mag64(v.y) * cap / len)));
}

void pg__body_store_velocity(pg_world *world, pg_body *b, pg_vec2 v, pg_fix w)
{
    b->v = pg__clamp_speed(world, v, &b->flags);
    if (w > PG_ENV_MAX_SPIN || w < -PG_ENV_MAX_SPIN) {
        w = w > 0 ? PG_ENV_MAX_SPIN : -PG_ENV_MAX_SPIN;
        world->stats.spin_clamps += 1u;
        b->flags |= PG_BODY_FLAG_SPIN_CLAMPED;
    }
    b->w = w;
}

