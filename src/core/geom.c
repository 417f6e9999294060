/* geom.c — unit directions, placing geometry and bounding boxes for the
 * convex "polygon with radius" primitives of geom.h.
 *
 * FORMATS AND BOUNDS (shared with collide.c)
 *   Coordinates are Q16.16. The arithmetic below assumes world coordinates within
 *   |x|, |y| <= 2^29 raw (8192 m; the envelope is +-1000 m), so a difference of two
 *   coordinates is below 2^30 raw and a squared distance below 2^61 (Q32.32, int64).
 *   Radii are at most 2^28 raw. Unit directions are Q2.30; a dot product of a Q16.16
 *   difference with a Q2.30 direction is an int64 "Q46" value below 2^61 and is
 *   rounded once with pg__round_shift64(.., 30).
 *   Every rounding is to nearest, ties away from zero, so mirrored inputs give
 *   mirrored results.
 */
#include "geom.h"
#include "intmath.h"

/* ---- small helpers ---------------------------------------------------------------- */

static uint64_t pg__umag(int64_t v) { return v < 0 ? (uint64_t)(-(v + 1)) + 1u : (uint64_t)v; }


/* ---- unit directions ------------------------------------------------------------------ */

pg_dir pg_dir_normalize(int64_t x, int64_t y)
{
    /* Work on magnitudes so that the result is exactly symmetric in sign and in the
     * exchange of x and y. The larger magnitude is brought into [2^30, 2^31] (scaling
     * down rounds to nearest), so the squared length fits 63 bits and the length has
     * 30+ significant bits: each component is within about 1 LSB of Q30. */
    uint64_t ax = pg__umag(x), ay = pg__umag(y), big = ax > ay ? ax : ay, len, s;
    pg_dir d;
    int k;
    d.x = 0;
    d.y = 0;
    if (big == 0) return d;
    k = pg__bit_length64(big) - 31; /* big / 2^k in [2^30, 2^31) */
    if (k > 0) {
        /* floor((a + 2^(k-1)) / 2^k) without overflow: nearest, ties away from zero */
        ax = (ax >> k) + ((ax >> (k - 1)) & 1u);
        ay = (ay >> k) + ((ay >> (k - 1)) & 1u);
    } else if (k < 0) {
        ax <<= -k;
        ay <<= -k;
    }
    s = ax * ax + ay * ay; /* <= 2^63 */
    len = pg__sqrt_nearest(s);
    d.x = (int32_t)((ax * (UINT64_C(1) << 30) + len / 2u) / len);
    d.y = (int32_t)((ay * (UINT64_C(1) << 30) + len / 2u) / len);
    if (x < 0) d.x = -d.x;
    if (y < 0) d.y = -d.y;
    return d;
}

/* ---- placing geometry ------------------------------------------------------------------ */

/* R (x, y) in int64, each coordinate rounded once and not yet saturated: the Q16.16
 * coordinates of a vertex or the Q2.30 ones of a normal, in the same format. */
static int64_t pg__rot_x(pg_rot r, int32_t x, int32_t y) { return pg__round_shift64((int64_t)r.c * x - (int64_t)r.s * y, 30); }
static int64_t pg__rot_y(pg_rot r, int32_t x, int32_t y) { return pg__round_shift64((int64_t)r.s * x + (int64_t)r.c * y, 30); }

/* Whether the second half of the vertices and of the normals is the first half negated
 * (a box, a centred capsule or segment, any centrally symmetric polygon about the body's
 * point). Compared in int64: INT32_MIN has no int32 negation. */
static int pg__centrally_symmetric(const pg_geom *g, int32_t half)
{
    int32_t i;
    for (i = 0; i < half; ++i) {
        if ((int64_t)g->vertices[i + half].x != -(int64_t)g->vertices[i].x ||
            (int64_t)g->vertices[i + half].y != -(int64_t)g->vertices[i].y ||
            (int64_t)g->normals[i + half].x != -(int64_t)g->normals[i].x ||
            (int64_t)g->normals[i + half].y != -(int64_t)g->normals[i].y)
            return 0;
    }
    return 1;
}

/* The placed vertices, normals, centroid and radius; the tail beyond `count` is left to
 * the callers below. Every value is pg_v2_add(position, pg_rot_apply(rotation, v)) for a
 * vertex and the Q30 rotation rounded once for a normal, computed with less work where
 * the result is known to be the same bits:
 *   - R (-v) rounds to exactly -(R v) (the products are exact and pg__round_shift64
 *     rounds ties away from zero, symmetric in sign), so a centrally symmetric polygon
 *     rotates only its first half and negates the unsaturated value for the second;
 *   - R 0 is 0, so a vertex or centroid at the body's point lands on `position`
 *     saturated (to PG_FIX_MIN when it is INT32_MIN), and a zero normal stays zero. */
/* The saturating adds here never clamp inside the envelope: |position| <= 1000 m plus
 * a reach of at most 1000 m (a static body's) is far below 32768 m; a shape that flew
 * out of the envelope (stats.envelope_exits) stops at the edge of the range. */
static void place(const pg_geom *local, pg_vec2 position, pg_rot rotation, pg_geom *world)
{
    int32_t i, count = local->count, half = count / 2;
    pg_vec2 at = pg_v2(pg__sat64(position.x), pg__sat64(position.y));
    /* pg_rot_from_angle returns unit rotations (to 1.25 Q30 units), so placed shapes
     * keep their size and their normals stay unit without normalising here. */
    if (count >= 2 && (count & 1) == 0 && pg__centrally_symmetric(local, half)) {
        for (i = 0; i < half; ++i) {
            pg_vec2 v = local->vertices[i];
            pg_dir n = local->normals[i];
            int64_t vx = pg__rot_x(rotation, v.x, v.y), vy = pg__rot_y(rotation, v.x, v.y);
            int64_t nx = pg__rot_x(rotation, n.x, n.y), ny = pg__rot_y(rotation, n.x, n.y);
            world->vertices[i].x = pg__sat64((int64_t)position.x + pg__sat64(vx));
            world->vertices[i].y = pg__sat64((int64_t)position.y + pg__sat64(vy));
            world->vertices[i + half].x = pg__sat64((int64_t)position.x + pg__sat64(-vx));
            world->vertices[i + half].y = pg__sat64((int64_t)position.y + pg__sat64(-vy));
            world->normals[i].x = (int32_t)nx;
            world->normals[i].y = (int32_t)ny;
            world->normals[i + half].x = (int32_t)-nx;
            world->normals[i + half].y = (int32_t)-ny;
        }
    } else {
        for (i = 0; i < count; ++i) {
            pg_vec2 v = local->vertices[i];
            pg_dir n = local->normals[i];
            if (v.x == 0 && v.y == 0) {
                world->vertices[i] = at;
            } else {
                world->vertices[i].x = pg__sat64((int64_t)position.x + pg__sat64(pg__rot_x(rotation, v.x, v.y)));
                world->vertices[i].y = pg__sat64((int64_t)position.y + pg__sat64(pg__rot_y(rotation, v.x, v.y)));
            }
            if (n.x == 0 && n.y == 0) {
                world->normals[i] = n;
            } else {
                world->normals[i].x = (int32_t)pg__rot_x(rotation, n.x, n.y);
                world->normals[i].y = (int32_t)pg__rot_y(rotation, n.x, n.y);
            }
        }
    }
    if (local->centroid.x == 0 && local->centroid.y == 0) world->centroid = at;
    else world->centroid = pg_v2_add(position, pg_rot_apply(rotation, local->centroid));
    world->radius = local->radius;
}

static void clear_tail(pg_geom *g, int32_t from, int32_t to)
{
    int32_t i;
    for (i = from; i < to; ++i) {
        g->vertices[i] = pg_v2_zero();
        g->normals[i].x = 0;
        g->normals[i].y = 0;
    }
}

pg_vec2 pg_geom_place_point(pg_vec2 local, pg_vec2 position, pg_rot rotation)
{
    return pg_v2(pg__sat64((int64_t)position.x + pg__sat64(pg__rot_x(rotation, local.x, local.y))),
                 pg__sat64((int64_t)position.y + pg__sat64(pg__rot_y(rotation, local.x, local.y))));
}

/* How far p lies in front of a segment's face normals[0], Q46 (negative: behind). */
static int64_t segment_offset(const pg_geom *g, pg_vec2 p)
{
    /* differences of Q16.16 values (below 2^32) times a Q2.30 normal: below 2^63 summed */
    int64_t dx = (int64_t)p.x - g->vertices[0].x, dy = (int64_t)p.y - g->vertices[0].y;
    return dx * g->normals[0].x + dy * g->normals[0].y;
}

int pg_geom_behind_segment(const pg_geom *g, pg_vec2 p) { return segment_offset(g, p) < 0; }

int pg_geom_in_front_of_segment(const pg_geom *g, pg_vec2 p) { return segment_offset(g, p) > 0; }

void pg_geom_transform(const pg_geom *local, pg_vec2 position, pg_rot rotation, pg_geom *world)
{
    place(local, position, rotation, world);
    clear_tail(world, local->count, PG_MAX_POLYGON_VERTICES);
    world->count = local->count;
}

void pg__geom_place_slot(const pg_geom *local, pg_vec2 position, pg_rot rotation, pg_geom *slot)
{
    /* The slot's tail is already zero unless it held more vertices before (a reused shape
     * slot): rewriting all 8 entries every step was 4.5 % of a rain step, where a circle
     * uses one. */
    int32_t before = slot->count;
    const pg_vec2 *v = local->vertices;
    if (local->count == 1 && v[0].x == 0 && v[0].y == 0 && local->normals[0].x == 0 && local->normals[0].y == 0 &&
        local->centroid.x == 0 && local->centroid.y == 0) {
        /* a ball centred on its body's point: what place() gives it, without its set-up */
        pg_vec2 at = pg_v2(pg__sat64(position.x), pg__sat64(position.y));
        slot->vertices[0] = at;
        slot->normals[0] = local->normals[0];
        slot->centroid = at;
        slot->radius = local->radius;
    } else {
        place(local, position, rotation, slot);
    }
    if (before > local->count) clear_tail(slot, local->count, before <= PG_MAX_POLYGON_VERTICES ? before : PG_MAX_POLYGON_VERTICES);
    slot->count = local->count;
}

pg_aabb pg_geom_aabb(const pg_geom *g)
{
    pg_aabb box;
    int32_t i;
    box.lo = g->vertices[0];
    box.hi = g->vertices[0];
    for (i = 1; i < g->count; ++i) {
        pg_vec2 v = g->vertices[i];
        box.lo.x = pg_fix_min(box.lo.x, v.x);
        box.lo.y = pg_fix_min(box.lo.y, v.y);
        box.hi.x = pg_fix_max(box.hi.x, v.x);
        box.hi.y = pg_fix_max(box.hi.y, v.y);
    }
    box.lo.x = pg_fix_sub(box.lo.x, g->radius);
    box.lo.y = pg_fix_sub(box.lo.y, g->radius);
    box.hi.x = pg_fix_add(box.hi.x, g->radius);
    box.hi.y = pg_fix_add(box.hi.y, g->radius);
    return box;
}
