/* soft_body.c — soft bodies from ordinary bodies and joints (pogon/soft_body.h,
 * docs/soft-bodies.md): a blob, a rope and a cloth strip of dynamic balls joined by
 * distance springs. Built on the public API; everything a create call could refuse is
 * checked first, with the world's free slots, so a failing call changes nothing. */
#include "pogon/soft_body.h"
#include "def_cookie.h"
#include "envelope.h"
#include "error.h"
#include "world_types.h" /* the joint pool's count: pg_world_stats has none */

#define SOFT_RADIUS_MIN ((pg_fix)3277) /* 0.05 m */
#define SOFT_RADIUS_MAX PG_FIX_C(5)
#define SOFT_LINK_MAX PG_FIX_C(100)    /* a distance joint's longest rest length */

pg_soft_def pg_default_soft_def(void)
{
    pg_soft_def d;
    d.radius = (pg_fix)13107; /* 0.2 */
    d.density = PG_FIX_ONE;
    d.friction = (pg_fix)39322; /* 0.6 */
    d.restitution = 0;
    d.hertz = PG_FIX_C(5);
    d.damping_ratio = (pg_fix)45875; /* 0.7 */
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

/* Soft bodies are bodies held by joints: a build without joints has none. */
#define NO_JOINTS "soft bodies are made of joints, which this build leaves out (PG_CONFIG_JOINTS=0 in pogon/config.h)"

static pg_result check_def(const pg_world *w, const pg_soft_def *d, const char *who)
{
    if (d->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "the soft def was not made by pg_default_soft_def(): start from it and change the fields you need");
    if (d->radius < SOFT_RADIUS_MIN || d->radius > SOFT_RADIUS_MAX) return pg__fail_value(w, PG_ERR_ENVELOPE, who, d->radius, "m: radius outside 0.05..5 m");
    if (d->density < PG_ENV_MIN_DENSITY || d->density > PG_ENV_MAX_DENSITY) return pg__fail_value(w, PG_ERR_ENVELOPE, who, d->density, "kg/m^2: density outside 0.1..100");
    if (d->friction < 0 || d->friction > PG_ENV_MAX_FRICTION) return pg__fail_value(w, PG_ERR_ENVELOPE, who, d->friction, ": friction outside 0..10");
    if (d->restitution < 0 || d->restitution > PG_FIX_ONE) return pg__fail_value(w, PG_ERR_ENVELOPE, who, d->restitution, ": restitution outside 0..1");
    if (d->hertz < 0 || d->hertz > PG_FIX_C(1000)) return pg__fail_value(w, PG_ERR_INVALID_ARGUMENT, who, d->hertz, "Hz: hertz outside 0..1000");
    if (d->damping_ratio < 0 || d->damping_ratio > PG_FIX_C(1000)) return pg__fail_value(w, PG_ERR_INVALID_ARGUMENT, who, d->damping_ratio, ": damping_ratio outside 0..1000");
    return PG_OK;
}

/* Room for `bodies` balls and `joints` links (checked before anything is made). */
static pg_result check_room(const pg_world *w, uint32_t bodies, uint32_t joints)
{
    pg_world_def d = pg_world_get_def(w);
    pg_world_stats st = pg_world_get_stats(w);
    if (d.max_bodies - st.body_count < bodies || d.max_shapes - st.shape_count < bodies)
        return pg__fail(w, PG_ERR_CAPACITY, "soft body: it needs more free body or shape slots than the world has: raise max_bodies and max_shapes");
    if (d.max_joints - w->joint_count < joints)
        return pg__fail(w, PG_ERR_CAPACITY, "soft body: it needs more free joint slots than the world has: raise max_joints");
    return PG_OK;
}

static int in_envelope(pg_vec2 p)
{
    return p.x >= -PG_ENV_MAX_POSITION && p.x <= PG_ENV_MAX_POSITION && p.y >= -PG_ENV_MAX_POSITION && p.y <= PG_ENV_MAX_POSITION;
}

static pg_fix distance(pg_vec2 a, pg_vec2 b) { return pg_v2_length(pg_v2_sub(b, a)); }

/* A link's rest length must keep its circles apart and fit a distance joint. */
static pg_result check_link(const pg_world *w, const pg_soft_def *d, pg_fix length, const char *who)
{
    if (length < 2 * d->radius) return pg__fail_value(w, PG_ERR_INVALID_ARGUMENT, who, length, "m: neighbouring circles would overlap (closer than twice the radius)");
    if (length > SOFT_LINK_MAX) return pg__fail_value(w, PG_ERR_ENVELOPE, who, length, "m: a link longer than 100 m");
    return PG_OK;
}

static pg_result ball(pg_world *w, const pg_soft_def *d, pg_vec2 p, pg_body_id *out)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    bd.type = PG_BODY_DYNAMIC;
    bd.position = p;
    sd.density = d->density;
    sd.friction = d->friction;
    sd.restitution = d->restitution;
    return pg_make_ball(w, &bd, &sd, d->radius, out);
}

static pg_result link(pg_world *w, const pg_soft_def *d, pg_body_id a, pg_body_id b, pg_fix length)
{
    pg_distance_joint_def jd = pg_default_distance_joint_def();
    pg_joint_id id;
    jd.body_a = a;
    jd.body_b = b;
    jd.length = length;
    jd.enable_spring = d->hertz != 0;
    jd.hertz = d->hertz;
    jd.damping_ratio = d->damping_ratio;
    return pg_distance_joint_create(w, &jd, &id);
}

/* The ring's circle i of n around c. */
static pg_vec2 ring_point(pg_vec2 c, pg_fix r, uint32_t i, uint32_t n)
{
    pg_angle a = (pg_angle)(((uint64_t)i << 32) / n);
    return pg_v2_add(c, pg_rot_apply(pg_rot_from_angle(a), pg_v2(r, 0)));
}

pg_result pg_make_soft_blob(pg_world *w, const pg_soft_def *d, pg_vec2 centre, pg_fix ring_radius, uint32_t count, pg_body_id *first)
{
    static const char who[] = "pg_make_soft_blob";
    pg_body_id c, first_ring = {0, 0}, prev = {0, 0}, cur;
    pg_result r;
    uint32_t i;
    if (first != NULL) first->index = first->generation = 0;
    if (w == NULL || d == NULL) return PG_ERR_NULL;
    if (!PG_CONFIG_JOINTS) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, NO_JOINTS);
    if ((r = check_def(w, d, who)) != PG_OK) return r;
    if (count < 3 || count > 64) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "pg_make_soft_blob: count outside 3..64 ring circles");
    if (ring_radius < 2 * d->radius || ring_radius > PG_FIX_C(50))
        return pg__fail_value(w, PG_ERR_INVALID_ARGUMENT, who, ring_radius, "m: ring_radius outside twice the radius .. 50 m");
    if ((r = check_link(w, d, distance(ring_point(centre, ring_radius, 0, count), ring_point(centre, ring_radius, 1, count)), who)) != PG_OK) return r;
    if (!in_envelope(centre) || !in_envelope(pg_v2_add(centre, pg_v2(ring_radius, ring_radius))) ||
        !in_envelope(pg_v2_sub(centre, pg_v2(ring_radius, ring_radius))))
        return pg__fail(w, PG_ERR_ENVELOPE, "pg_make_soft_blob: the blob reaches beyond +-1000 m");
    if ((r = check_room(w, count + 1u, 2u * count)) != PG_OK) return r;
    if ((r = ball(w, d, centre, &c)) != PG_OK) return r;
    if (first != NULL) *first = c;
    for (i = 0; i < count && r == PG_OK; ++i) {
        pg_vec2 p = ring_point(centre, ring_radius, i, count);
        r = ball(w, d, p, &cur);
        if (r == PG_OK) r = link(w, d, c, cur, distance(centre, p));
        if (r == PG_OK && i > 0) r = link(w, d, prev, cur, distance(ring_point(centre, ring_radius, i - 1u, count), p));
        if (i == 0) first_ring = cur;
        prev = cur;
    }
    if (r == PG_OK) r = link(w, d, prev, first_ring, distance(ring_point(centre, ring_radius, count - 1u, count), ring_point(centre, ring_radius, 0, count)));
    return r;
}

/* start + (end - start) i / n, exact in integers (toward zero) */
static pg_vec2 along(pg_vec2 s, pg_vec2 e, uint32_t i, uint32_t n)
{
    int64_t dx = (int64_t)e.x - s.x, dy = (int64_t)e.y - s.y;
    return pg_v2((pg_fix)(s.x + dx * (int64_t)i / (int64_t)n), (pg_fix)(s.y + dy * (int64_t)i / (int64_t)n));
}

pg_result pg_make_rope(pg_world *w, const pg_soft_def *d, pg_vec2 start, pg_vec2 end, uint32_t count, pg_body_id *first)
{
    static const char who[] = "pg_make_rope";
    pg_body_id prev = {0, 0}, cur;
    pg_result r;
    uint32_t i;
    if (first != NULL) first->index = first->generation = 0;
    if (w == NULL || d == NULL) return PG_ERR_NULL;
    if (!PG_CONFIG_JOINTS) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, NO_JOINTS);
    if ((r = check_def(w, d, who)) != PG_OK) return r;
    if (count < 2 || count > 1024) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "pg_make_rope: count outside 2..1024 circles");
    if (!in_envelope(start) || !in_envelope(end)) return pg__fail(w, PG_ERR_ENVELOPE, "pg_make_rope: an end is beyond +-1000 m");
    for (i = 0; i + 1u < count; ++i)
        if ((r = check_link(w, d, distance(along(start, end, i, count - 1u), along(start, end, i + 1u, count - 1u)), who)) != PG_OK) return r;
    if ((r = check_room(w, count, count - 1u)) != PG_OK) return r;
    for (i = 0; i < count && r == PG_OK; ++i) {
        pg_vec2 p = along(start, end, i, count - 1u);
        r = ball(w, d, p, &cur);
        if (r == PG_OK && i == 0 && first != NULL) *first = cur;
        if (r == PG_OK && i > 0) r = link(w, d, prev, cur, distance(along(start, end, i - 1u, count - 1u), p));
        prev = cur;
    }
    return r;
}

pg_result pg_make_cloth_strip(pg_world *w, const pg_soft_def *d, pg_vec2 origin, pg_fix spacing, uint32_t columns, uint32_t rows,
                              pg_body_id *first)
{
    static const char who[] = "pg_make_cloth_strip";
    pg_body_id row[64]; /* the row being made from column 0 up to i - 1, the row below from i on */
    pg_body_id below_left = {0, 0}, below_here = {0, 0};
    pg_result r;
    uint32_t i, j, joints;
    pg_fix diagonal;
    if (first != NULL) first->index = first->generation = 0;
    if (w == NULL || d == NULL) return PG_ERR_NULL;
    if (!PG_CONFIG_JOINTS) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, NO_JOINTS);
    if ((r = check_def(w, d, who)) != PG_OK) return r;
    if (columns < 2 || columns > 64 || rows < 2 || rows > 64) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "pg_make_cloth_strip: columns and rows must be 2..64");
    if (spacing > PG_FIX_C(50)) return pg__fail_value(w, PG_ERR_ENVELOPE, who, spacing, "m: spacing above 50 m");
    if ((r = check_link(w, d, spacing, who)) != PG_OK) return r;
    diagonal = distance(pg_v2_zero(), pg_v2(spacing, spacing));
    if (!in_envelope(origin) || !in_envelope(pg_v2_add(origin, pg_v2(spacing * (pg_fix)(columns - 1u), spacing * (pg_fix)(rows - 1u)))))
        return pg__fail(w, PG_ERR_ENVELOPE, "pg_make_cloth_strip: the strip reaches beyond +-1000 m");
    joints = (columns - 1u) * rows + columns * (rows - 1u) + 2u * (columns - 1u) * (rows - 1u);
    if ((r = check_room(w, columns * rows, joints)) != PG_OK) return r;
    for (j = 0; j < rows && r == PG_OK; ++j) {
        for (i = 0; i < columns && r == PG_OK; ++i) {
            if (j > 0) below_here = row[i]; /* the row below's, before this row's replaces it */
            r = ball(w, d, pg_v2_add(origin, pg_v2(spacing * (pg_fix)i, spacing * (pg_fix)j)), &row[i]);
            if (r == PG_OK && i == 0 && j == 0 && first != NULL) *first = row[0];
            if (r == PG_OK && i > 0) r = link(w, d, row[i - 1u], row[i], spacing);
            if (r == PG_OK && j > 0) r = link(w, d, below_here, row[i], spacing);
            if (r == PG_OK && j > 0 && i > 0) r = link(w, d, below_left, row[i], diagonal);
            if (r == PG_OK && j > 0 && i > 0) r = link(w, d, below_here, row[i - 1u], diagonal);
            below_left = below_here;
        }
    }
    return r;
}
