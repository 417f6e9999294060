/* continuous.c — time of impact for bodies that turn too far in a step for their
 * speculative contacts (part of PG_EFFECT_CONTINUOUS).
 *
 * WHY: speculative contacts (contact.c widens each pair's window by how far the pair can
 * close in a step) stop a fast body at a surface, but their points are the features
 * that face each other at the step's start. A body that turns a large part of a turn in
 * one step brings other corners round to the surface, which no contact point tracks: a
 * box of 0.15-1.5 m thrown at 10-100 m/s and spinning at 160-300 rad/s passed through a
 * static wall 0.1 m thick in 40 of 2625 throws, and corners went up to a body's size
 * deep into a 1 m wall (without this sweep; test_spinning_box_meets_a_thin_wall).
 *
 * WHAT (Box2D v3's continuous step, for turning bodies): after the solve, a dynamic body
 * whose turn in the step, or the turn its angular velocity at the step's start would have
 * made, moves its farthest point more than half its thinnest extent (|turn| reach >
 * inner / 2, the extents below) is "fast-turning". (The start's rate counts too: a
 * contact made for the wrong features can stop the spin in the first substep and let the
 * body go on into the wall.) For each static shape its broadphase box overlaps (the box
 * of a body turning that fast covers every orientation, pg__shape_turn_radius; the pair
 * need not have a contact), the earliest fraction of the step at which the shape, moved
 * along the step's path, comes within PG_LINEAR_SLOP of the static shape is found by
 * conservative advancement. The body is put back at the earliest fraction over its pairs
 * and keeps its velocities, so the next step's contacts, made from the features that
 * really meet, stop it.
 *
 * TOUCHING: a shape that starts as close as a hit would end (within the slop and a
 * quarter), or so close that the advances could not cover the step (closer than
 * bound / PG__TOI_ITERATIONS: each moves t by gap / bound, and a body turning past a
 * surface would stop a little further each advance and pause, step after step), is swept
 * again as a small circle at the shape's centre, a quarter of its thinnest extent (as v3
 * does). A body rolling or tumbling along a wall then goes on, and its core still cannot
 * cross the wall: for a square that leaves a corner at most sqrt(2)/2 - 1/8 of its side
 * deep. A circle at the centre of mass does not turn, so it only translates, and its
 * distance from a convex shape is convex in t: its advances use the approach speed along
 * the normal (Newton's method from the left, which never passes the root), so it needs
 * no such margin. A core circle that touches already (its shape then overlaps the
 * surface by three quarters of its thinnest extent, and the contacts, made for other
 * features, have not stopped it) and moves in along the normal is held at the surface:
 * the step's path and the body's velocity lose their parts along the normal (an
 * inelastic impact of the core on the static surface), and it slides and turns on. Put
 * back at its start pose instead, a body whose contacts do not push (a spinning plank
 * whose ends turn away from the wall) stayed there step after step.
 *
 * THE PATH: the centre of mass moves on a straight line from c0 to c1 and the angle
 * turns uniformly by `turn` (binary-angle units, unwrapped): the end pose is the solver's
 * exactly, and the whole turns are taken from the solver's sum of w h over the substeps
 * (pg__turn_of_step), so a spin that a contact stopped or reversed in mid-step counts as
 * far as it went.
 *
 * CONSERVATIVE ADVANCEMENT: no point of a shape moves faster along the path than
 * bound = |dc|_1 + |turn| reach per step (reach: the farthest the shape's core reaches
 * from the centre of mass, an L1 bound), so from a fraction t at distance d > target the
 * shape cannot touch before t + (d - target) / bound. The distance is pg_collide's
 * smallest separation, which for separated shapes is the distance between the surfaces
 * to within 2.21 LSB (collide.c). At most PG__TOI_ITERATIONS advances; a pair still
 * closing after that stops where it got to (early, never late).
 *
 * Everything is integer and a pure function of the state: pairs in broadphase order (a
 * held core changes the path that the body's later pairs see), the earliest fraction per
 * body (a minimum), bodies in index order.
 */
#include "collide.h"
#include "contact.h"
#include "continuous.h"
#include "envelope.h"
#include "wide.h"
#include "speed_cap.h"
#include "world_types.h"

#define PG__TOI_TARGET PG_LINEAR_SLOP
#define PG__TOI_TOLERANCE (PG_LINEAR_SLOP / 4)
#define PG__TOI_ITERATIONS 20
/* 2 pi 2^16, rounded up: radians per binary-angle unit times 2^48 (see turn_radians) */
#define PG__TWO_PI_Q16_UP INT64_C(411775)
/* 2^32 / (2 pi): binary-angle units per radian */
#define PG__UNITS_PER_RADIAN INT64_C(683565276)
/* A body turning more than 8 turns in a step is not swept: its path means nothing. */
#define PG__MAX_TURN (INT64_C(1) << 35)

static int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

void pg__shape_set_extents(pg_shape *s)
{
    const pg_geom *g = &s->local;
    int64_t outer = 0, inner = INT64_MAX;
    int32_t k;
    if (!PG__EFFECT(PG_EFFECT_CONTINUOUS)) { /* nothing reads them: a build without the effect drops this code */
        s->turn_outer = 0;
        s->inner_extent = 0;
        return;
    }
    for (k = 0; k < g->count; ++k) {
        /* body-frame coordinates within the envelope: |d| < 2^24, d^2 < 2^49 */
        int64_t dx = (int64_t)g->vertices[k].x - g->centroid.x, dy = (int64_t)g->vertices[k].y - g->centroid.y;
        int64_t e = (int64_t)pg_isqrt64((uint64_t)(dx * dx + dy * dy)) + 1;
        if (e > outer) outer = e;
    }
    if (g->count >= 3) {
        for (k = 0; k < g->count; ++k) {
            /* the centroid lies inside: its distance to every face's line is positive */
            int64_t dx = (int64_t)g->vertices[k].x - g->centroid.x, dy = (int64_t)g->vertices[k].y - g->centroid.y;
            int64_t d = pg__round_shift64(dx * g->normals[k].x + dy * g->normals[k].y, 30);
            if (d < inner) inner = d;
        }
        if (inner < 0) inner = 0;
    } else {
        inner = 0; /* a circle, segment or capsule: its thickness is its radius */
    }
    s->turn_outer = g->count == 1 ? 0 : (pg_fix)outer;
    s->inner_extent = (pg_fix)(inner + g->radius);
}

/* How far the core of shape s reaches from its body's centre of mass (L1, Q16.16): every
 * point of the shape moves by at most |turn| times this when the body turns (a circle's
 * surface moves with its centre). */
static int64_t shape_reach(const pg_shape *s, pg_vec2 local_center)
{
    return abs64((int64_t)s->local.centroid.x - local_center.x) + abs64((int64_t)s->local.centroid.y - local_center.y) + s->turn_outer;
}

/* |turn| in Q16.16 radians, rounded up. */
static int64_t turn_radians(int64_t turn) { return (abs64(turn) * PG__TWO_PI_Q16_UP + (INT64_C(1) << 32) - 1) >> 32; }

void pg__body_set_turn_extents(pg_world *w, uint32_t body)
{
    pg_body *b = &w->bodies[body];
    int64_t reach = 0, inner = 0;
    uint32_t s;
    if (!PG__EFFECT(PG_EFFECT_CONTINUOUS)) { /* as in pg__shape_set_extents */
        b->turn_reach = 0;
        b->inner_extent = 0;
        return;
    }
    for (s = b->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next) {
        int64_t r = shape_reach(&w->shapes[s], b->local_center);
        if (r > reach) reach = r;
        if (s == b->first_shape || w->shapes[s].inner_extent < inner) inner = w->shapes[s].inner_extent;
    }
    /* vertices and the centre of mass lie within 50 m of the body's origin (the envelope):
     * reach < 2 * 100 m + 71 m < 2^24.2 */
    b->turn_reach = pg__sat64(reach);
    b->inner_extent = (pg_fix)inner;
}

/* The turn a body at angular velocity w makes in one step, Q16.16 rad rounded up, or -1
 * beyond PG__MAX_TURN (such a body is not swept). */
static int64_t turn_at_rate(pg_fix w, uint32_t step_hz)
{
    int64_t turn = (abs64(w) + (int64_t)step_hz - 1) / (int64_t)step_hz;
    return turn > (PG__MAX_TURN * PG__TWO_PI_Q16_UP >> 32) ? -1 : turn;
}

/* Whether body b, turning by turn_rad (Q16.16 rad, >= 0) in a step, is fast-turning:
 * some shape's farthest point moves more than half the body's smallest extent. */
static int turns_fast(const pg_body *b, int64_t turn_rad)
{
    /* reach < 2^24.2 (shapes and the centre of mass within 50 m of the origin) and
     * turn_rad <= 2^21.7 (8 turns): the product is below 2^46 */
    return b->turn_reach > 0 && turn_rad * b->turn_reach > (int64_t)b->inner_extent * 32768;
}

int pg__turns_fast_now(const pg_world *w, const pg_body *b)
{
    int64_t turn_rad;
    if (b->type != PG_BODY_DYNAMIC || b->w == 0 || b->turn_reach == 0 || (b->flags & PG_BODY_FLAG_FIXED_ROTATION) != 0) return 0;
    if ((w->def.effects & PG__EFFECT(PG_EFFECT_CONTINUOUS)) == 0 || (w->def.effects & PG__EFFECT(PG_EFFECT_ROTATION)) == 0) return 0;
    turn_rad = turn_at_rate(b->w, w->def.step_hz);
    return turn_rad >= 0 && turns_fast(b, turn_rad);
}

int64_t pg__shape_turn_radius(const pg_body *b, const pg_shape *s) { return shape_reach(s, b->local_center) + s->local.radius; }

int64_t pg__turn_of_step(pg_angle a0, pg_angle a1, int64_t radians)
{
    int64_t d0 = (int64_t)(uint32_t)(a1 - a0), est, k;
    /* 8 turns: 50.27 rad, Q32 */
    if (radians > INT64_C(215902344906) || radians < -INT64_C(215902344906)) return PG__MAX_TURN + 1;
    if (d0 >= (INT64_C(1) << 31)) d0 -= INT64_C(1) << 32; /* the short way round, in [-2^31, 2^31) */
    /* |radians| < 2^37.7 Q32, so < 2^21.7 in Q16, times 2^29.4 < 2^52 */
    est = pg__round_shift64((radians >> 16) * PG__UNITS_PER_RADIAN, 16);
    k = (est - d0 + (INT64_C(1) << 31)) >> 32; /* whole turns: the nearest to the estimate */
    return d0 + k * (INT64_C(1) << 32);
}

/* Body b's shape `local` placed at fraction t (Q16.16 in [0, 1]) of sweep s. */
static void place_at(const pg_sweep *s, const pg_body *b, const pg_geom *local, int64_t t, pg_geom *out)
{
    pg_vec2 c;
    pg_rot q;
    pg_angle a = s->a0 + (pg_angle)(uint64_t)pg__round_shift64(s->turn * t, 16);
    /* never clamps: t in [0, 1], the point lies between c0 and c1 (both Q16.16) */
    c.x = pg__sat64((int64_t)s->c0.x + pg__round_shift64(((int64_t)s->c1.x - s->c0.x) * t, 16));
    c.y = pg__sat64((int64_t)s->c0.y + pg__round_shift64(((int64_t)s->c1.y - s->c0.y) * t, 16));
    q = pg_rot_from_angle(a);
    pg_geom_transform(local, pg_v2_sub(c, pg_rot_apply(q, b->local_center)), q, out);
}

/* The smallest separation of the placed shape from the target, or INT64_MAX when they are
 * farther apart than the window; *n: the manifold's normal, from the shape to the target. */
static int64_t distance(const pg_geom *g, const pg_geom *target, int64_t window, pg_dir *n)
{
    pg_manifold m;
    /* window: the reach of a step (a bound of at most 2 x 16384 m plus the target), below
     * 2^31 inside the envelope; beyond, a clamped window only finds fewer contacts */
    pg_collide(g, target, pg__sat64(window), &m);
    if (m.count == 0) return INT64_MAX;
    *n = m.normal;
    return m.count == 2 && m.points[1].separation < m.points[0].separation ? m.points[1].separation : m.points[0].separation;
}

enum { TOI_NONE, TOI_HIT, TOI_TOUCHING, TOI_HOLD };

/* How far dc (a path, Q16.16 m per step, or a velocity) goes along n towards the target:
 * |dc| < 2^32.5 and |n| = 2^30, so the dot product fits (Cauchy-Schwarz). */
static int64_t approach(int64_t dcx, int64_t dcy, pg_dir n) { return pg__round_shift64(dcx * n.x + dcy * n.y, 30); }

/* Conservative advancement of `local` (body frame) along s against the static target;
 * reach is the shape's turn reach. On a hit *t is the fraction.
 * A shape that does not turn with its body (reach 0: the core circle at the centre of
 * mass) only translates along a line, and its distance from a convex shape is a convex
 * function of t: the tangent at t is below the curve, so t + (d - target) / (approach
 * speed along the normal) never passes the root, and it reaches it in a few advances
 * (Newton's method from the left). Moving away (approach <= 0) it can only get farther. */
static int time_of_impact(const pg_sweep *s, const pg_body *b, const pg_geom *local, int64_t reach, const pg_geom *target,
                          int64_t *t_out, pg_dir *hold)
{
    /* |dc| < 2^32 per component; |turn| reach < 2^21.7 * 2^24.2 before the shift */
    int64_t dcx = (int64_t)s->c1.x - s->c0.x, dcy = (int64_t)s->c1.y - s->c0.y;
    int64_t bound = abs64(dcx) + abs64(dcy) + pg__round_shift64(turn_radians(s->turn) * reach, 16) + 1;
    int64_t t = 0, d;
    pg_geom g;
    pg_dir n;
    int i;
    place_at(s, b, local, 0, &g);
    d = distance(&g, target, bound + PG__TOI_TARGET, &n);
    if (d == INT64_MAX) return TOI_NONE;
    /* Touching; or, for a turning shape, too close for the advances to cover the step:
     * from a gap g they move t by g / bound, and a body turning past a surface at that
     * gap (the next corner coming round) would stop a little further each advance and
     * pause (see the header) */
    if (reach == 0 && d - PG__TOI_TARGET <= PG__TOI_TOLERANCE) {
        /* the core circle touches already: it may leave, or slide along, but not go in */
        if (approach(dcx, dcy, n) <= 0) return TOI_NONE;
        *hold = n;
        return TOI_HOLD;
    }
    if (d - PG__TOI_TARGET <= PG__TOI_TOLERANCE || (reach != 0 && d - PG__TOI_TARGET <= bound / PG__TOI_ITERATIONS)) return TOI_TOUCHING;
    for (i = 0; i < PG__TOI_ITERATIONS; ++i) {
        /* d - target < 2^32 here (within the window), times 2^16 */
        int64_t speed = bound, dt;
        if (reach == 0) {
            speed = approach(dcx, dcy, n); /* along the normal */
            if (speed <= 0) return TOI_NONE;
        }
        dt = ((d - PG__TOI_TARGET) * 65536) / speed;
        t += dt > 0 ? dt : 1;
        if (t >= PG_FIX_ONE) return TOI_NONE;
        place_at(s, b, local, t, &g);
        d = distance(&g, target, pg__round_shift64(bound * (PG_FIX_ONE - t), 16) + PG__TOI_TARGET + 1, &n);
        if (d == INT64_MAX) return TOI_NONE;
        if (d <= PG__TOI_TARGET + PG__TOI_TOLERANCE) break;
    }
    *t_out = t;
    return TOI_HIT;
}

/* The earliest fraction at which shape `shape` of the swept body comes within the slop of
 * the static geometry `target`, or PG_FIX_ONE. *held: its core circle touches and moves
 * in, along *hold (see the header). */
static int64_t shape_against_static(const pg_world *w, const pg_sweep *s, uint32_t shape, const pg_geom *target, int *held,
                                    pg_dir *hold)
{
    const pg_shape *sh = &w->shapes[shape];
    const pg_body *b = &w->bodies[s->body];
    int64_t t = PG_FIX_ONE;
    int r = time_of_impact(s, b, &sh->local, shape_reach(sh, b->local_center), target, &t, hold);
    if (r == TOI_TOUCHING) {
        /* touching at the start: sweep the shape's core circle instead (see the header) */
        pg_geom core;
        int32_t k;
        for (k = 0; k < PG_MAX_POLYGON_VERTICES; ++k) {
            core.vertices[k] = pg_v2_zero();
            core.normals[k].x = core.normals[k].y = 0;
        }
        core.count = 1;
        core.vertices[0] = sh->local.centroid;
        core.centroid = sh->local.centroid;
        core.radius = sh->inner_extent / 4;
        r = time_of_impact(s, b, &core,
                           abs64((int64_t)core.centroid.x - b->local_center.x) + abs64((int64_t)core.centroid.y - b->local_center.y),
                           target, &t, hold);
    }
    *held = r == TOI_HOLD;
    return r == TOI_HIT ? t : PG_FIX_ONE;
}

/* Take from v its part along n when that moves in: v - max(0, v.n) n. */
static pg_vec2 without_approach(pg_vec2 v, pg_dir n)
{
    int64_t vn = approach(v.x, v.y, n);
    if (vn <= 0) return v;
    /* v less a part of itself along n: no longer than v, so within Q16.16 but for a v
     * near the corner of the range (|v| > 32768), far outside the envelope */
    return pg_v2(pg__sat64((int64_t)v.x - pg__round_shift64(vn * n.x, 30)), pg__sat64((int64_t)v.y - pg__round_shift64(vn * n.y, 30)));
}

int pg__sweep_is_fast(const pg_world *w, const pg_sweep *s, pg_fix w0)
{
    const pg_body *b = &w->bodies[s->body];
    int64_t turn, start = turn_at_rate(w0, w->def.step_hz);
    if (s->turn > PG__MAX_TURN || s->turn < -PG__MAX_TURN || start < 0) return 0;
    turn = turn_radians(s->turn);
    return turns_fast(b, turn > start ? turn : start);
}

void pg__sweep_fast_turns(pg_world *w, pg_sweep *sweeps, uint32_t n, uint32_t *sweep_of_body)
{
    uint32_t i;
    for (i = 0; i < w->body_high; ++i) sweep_of_body[i] = PG_NULL_INDEX;
    for (i = 0; i < n; ++i) {
        sweeps[i].fraction = PG_FIX_ONE;
        sweeps[i].moved = 0;
        sweep_of_body[sweeps[i].body] = i;
    }
    for (i = 0; i < w->stats.pair_count; ++i) {
        uint32_t sa = w->proxy_shape[w->pairs[i].a], sb = w->proxy_shape[w->pairs[i].b];
        uint32_t ba = w->shapes[sa].body, bb = w->shapes[sb].body;
        uint32_t ka = sweep_of_body[ba], kb = sweep_of_body[bb];
        uint32_t k, shape, other_shape;
        int64_t t;
        int held;
        pg_dir hold;
        if (ka != PG_NULL_INDEX && w->bodies[bb].type == PG_BODY_STATIC) {
            k = ka;
            shape = sa;
            other_shape = sb;
        } else if (kb != PG_NULL_INDEX && w->bodies[ba].type == PG_BODY_STATIC) {
            k = kb;
            shape = sb;
            other_shape = sa;
        } else {
            continue;
        }
        if (!pg__shapes_should_collide(w, sa, sb)) continue;
        /* a chain segment is solid on its front only, and its own contacts push out a
         * body whose centre of mass stays in front: only a centre that crosses it from
         * the front needs the sweep (Box2D v3's rule). A body coming from behind passes
         * through, and one stopped mid-crossing would be thrown out by those contacts. */
        if (w->shapes[other_shape].geometry.kind == PG_SHAPE_CHAIN_SEGMENT &&
            (pg_geom_behind_segment(&w->world_geoms[other_shape], sweeps[k].c0) ||
             pg_geom_in_front_of_segment(&w->world_geoms[other_shape], sweeps[k].c1)))
            continue;
        t = shape_against_static(w, &sweeps[k], shape, &w->world_geoms[other_shape], &held, &hold);
        if (held) {
            /* the core may not go in: the step's path loses its part along the normal (the
             * pairs after this one see the new path), and so does the velocity, as in an
             * inelastic impact of the core on the static surface */
            pg_sweep *sw = &sweeps[k];
            pg_body *b = &w->bodies[sw->body];
            pg_vec2 dc = pg_v2((pg_fix)((int64_t)sw->c1.x - sw->c0.x), (pg_fix)((int64_t)sw->c1.y - sw->c0.y));
            dc = without_approach(dc, hold);
            /* never clamps inside the envelope: |c0| <= 1000 m, |dc| <= one step's path */
            sw->c1 = pg_v2(pg__sat64((int64_t)sw->c0.x + dc.x), pg__sat64((int64_t)sw->c0.y + dc.y));
            sw->moved = 1;
            /* a projection cannot lengthen v, but its rounding might by a step: keep the cap */
            b->v = pg__clamp_speed(w, without_approach(b->v, hold), &b->flags);
        } else if (t < sweeps[k].fraction) {
            sweeps[k].fraction = (pg_fix)t;
        }
    }
    for (i = 0; i < n; ++i) {
        const pg_sweep *s = &sweeps[i];
        pg_body *b = &w->bodies[s->body];
        int64_t t = s->fraction;
        if (t >= PG_FIX_ONE && !s->moved) continue;
        /* between c0 and c1, as in the sweep's placement: never clamps */
        b->center.x = pg__sat64((int64_t)s->c0.x + pg__round_shift64(((int64_t)s->c1.x - s->c0.x) * t, 16));
        b->center.y = pg__sat64((int64_t)s->c0.y + pg__round_shift64(((int64_t)s->c1.y - s->c0.y) * t, 16));
        b->angle = s->a0 + (pg_angle)(uint64_t)pg__round_shift64(s->turn * t, 16);
        b->rot = pg_rot_from_angle(b->angle);
        b->origin = pg_v2_sub(b->center, pg_rot_apply(b->rot, b->local_center));
    }
}
