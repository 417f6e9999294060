/* raycast.c — ray casts against one convex geometry (the FORMATS AND BOUNDS of geom.c
 * hold here too). */
#include "collide.h"
#include "intmath.h"
#include "raycast.h"

/* Dot product of an int64 vector (Q16.16 differences) with a Q2.30 direction: Q46. */
static int64_t pg__dot46(int64_t x, int64_t y, pg_dir n) { return x * n.x + y * n.y; }

/* Ray p + s u (u unit, s >= 0 a distance in Q16.16) against the circle (c, r) entered from
 * outside. On a hit closer than *best (and <= smax) updates *best, *point and *normal. */
static void pg__ray_circle(pg_vec2 p, pg_dir u, int64_t smax, pg_vec2 c, pg_fix r, int64_t *best,
                           pg_vec2 *point, pg_dir *normal)
{
    int64_t mx = (int64_t)p.x - c.x, my = (int64_t)p.y - c.y;
    int64_t b = pg__round_shift64(pg__dot46(mx, my, u), 30);          /* m . u, Q16 */
    int64_t h = pg__round_shift64(mx * u.y - my * u.x, 30);           /* m x u, Q16 */
    int64_t r2 = (int64_t)r * r, h2 = h * h, s;
    if (b >= 0 || h2 > r2) return; /* moving away, or passing beside */
    s = -b - (int64_t)pg__sqrt_nearest((uint64_t)(r2 - h2));
    if (s < 0 || s > smax || s >= *best) return;
    *best = s;
    point->x = pg__sat64(p.x + pg__round_shift64((int64_t)u.x * s, 30));
    point->y = pg__sat64(p.y + pg__round_shift64((int64_t)u.y * s, 30));
    /* The normal from the unrounded hit point m + s u (Q46): |m| < 2^30, s < 2^31. */
    *normal = pg_dir_normalize(mx * ((int64_t)1 << 30) + (int64_t)u.x * s, my * ((int64_t)1 << 30) + (int64_t)u.y * s);
}

int pg_geom_raycast(const pg_geom *g, pg_vec2 p, pg_vec2 d, pg_fix max_t, pg_fix *t, pg_vec2 *point, pg_dir *normal)
{
    /* Work with the unit direction u and the distance s along it; the fraction is s / |d|.
     * The shape is the union of its faces pushed out by the radius and (radius > 0) the
     * circles around its vertices: the first one entered from outside is the hit. A ray
     * that starts inside the shape does not hit it. */
    pg_dir u = pg_dir_normalize(d.x, d.y);
    uint64_t len = pg__sqrt_nearest((uint64_t)((int64_t)d.x * d.x) + (uint64_t)((int64_t)d.y * d.y));
    int64_t smax, best = INT64_MAX;
    int32_t i, count = g->count;
    pg_vec2 hit = pg_v2_zero();
    pg_dir hn;
    hn.x = 0;
    hn.y = 0;
    if (len == 0 || max_t < 0 || count < 1) return 0;
    if (pg_geom_contains(g, p)) return 0;
    smax = pg__round_shift64((int64_t)max_t * (int64_t)len, 16);
    if (smax > ((int64_t)1 << 32)) smax = (int64_t)1 << 32; /* beyond any shape in range */

    if (count >= 2) {
        for (i = 0; i < count; ++i) {
            pg_dir n = g->normals[i], tn;
            pg_vec2 v1 = g->vertices[i], v2 = g->vertices[i + 1 < count ? i + 1 : 0], q;
            int64_t den = pg__round_shift64(pg__dot46(u.x, u.y, n), 30); /* u . n, Q30 */
            int64_t out, s, along, len46;
            if (den >= 0) continue; /* parallel or leaving through this face */
            /* How far p lies outside the face pushed out by the radius (Q46). */
            out = pg__dot46((int64_t)p.x - v1.x, (int64_t)p.y - v1.y, n) - (int64_t)g->radius * ((int64_t)1 << 30);
            if (out < 0) continue;
            s = (out + (-den) / 2) / (-den); /* Q46 / Q30 = Q16, rounded (both positive) */
            if (s > smax || s >= best) continue;
            q.x = pg__sat64(p.x + pg__round_shift64((int64_t)u.x * s, 30));
            q.y = pg__sat64(p.y + pg__round_shift64((int64_t)u.y * s, 30));
            /* Within the face: tangential coordinate in [0, length], with 2 LSB of slack so
             * that a ray through a sharp corner cannot slip between two faces. */
            tn.x = -n.y;
            tn.y = n.x;
            along = pg__dot46((int64_t)q.x - v1.x, (int64_t)q.y - v1.y, tn);
            len46 = pg__dot46((int64_t)v2.x - v1.x, (int64_t)v2.y - v1.y, tn);
            if (along < -((int64_t)2 << 30) || along > len46 + ((int64_t)2 << 30)) continue;
            best = s;
            hit = q;
            hn = n;
        }
    }
    if (count == 1 || g->radius > 0) {
        for (i = 0; i < count; ++i) pg__ray_circle(p, u, smax, g->vertices[i], g->radius, &best, &hit, &hn);
    }
    if (best == INT64_MAX) return 0;
    {
        int64_t frac = (best * 65536 + (int64_t)(len / 2u)) / (int64_t)len; /* best <= 2^32 */
        if (frac > max_t) frac = max_t;
        *t = (pg_fix)frac;
    }
    *point = hit;
    *normal = hn;
    return 1;
}
