/* collide.c — contact manifolds between convex "polygons with radius" (geom.h).
 *
 * METHOD (the ideas of Box2D v3's manifold code, written for integers)
 *   circle  - circle     centre to centre.
 *   polygon - circle     (polygon = count 2..8, so segments and capsules too) the face of
 *                        the polygon core with the largest separation from the centre; if
 *                        the centre lies outside that face's side planes, the vertex's
 *                        Voronoi region: the normal runs from the vertex to the centre.
 *   polygon - polygon    (anything with count >= 2) separating axes over the face normals
 *                        of both cores. The reference face is A's best face unless B's is
 *                        better by more than PG__REF_TOLERANCE (0.1 linear slop), so
 *                        stacked boxes keep one reference; cores apart by more than that
 *                        take the better face outright (it measures the distance). The
 *                        incident edge is the other shape's edge most anti-parallel to the
 *                        reference normal; it is clipped to the reference face's side
 *                        planes, giving up to two points. When the cores are apart (rounded
 *                        shapes, speculative contacts) and the edge runs on beyond a side
 *                        plane towards the face's line (a "dip": the vertex beyond is
 *                        nearer the line than the cut), the cut can lie farther from the
 *                        face's vertex than the edge beyond it does (a capsule leaning back
 *                        over a face with its end just past the face's end). The face
 *                        contact is kept while the cut is at most PG__DIP_TOLERANCE farther
 *                        from that vertex than the edge beyond the plane (compared exactly),
 *                        so nearly flush edges (a column of equal boxes) and a plank tilted
 *                        over an edge keep their two points and their reference. Otherwise,
 *                        and when the edge misses the face, the better face is taken
 *                        outright, and if its clip too overstates or misses, the closest
 *                        features of that face and its incident edge decide: two vertices
 *                        give one point with the vertex-to-vertex normal (a capsule end on a
 *                        box corner); a vertex of the face against the edge's interior makes
 *                        the edge's face the reference. Points farther apart than
 *                        `speculative` are dropped.
 *
 * CONTACT POINTS lie midway between the two surfaces; separations are signed distances
 * along the normal between the surfaces (radii included).
 *
 * FEATURE IDS  id = kind << 16 | (feature on A) << 8 | (feature on B)
 *   kind 0 (PG__KIND_FACE_A): A's face is the reference; the A byte is the reference
 *          face index, the B byte the incident vertex of B the point comes from (the
 *          vertex itself or the end of the incident edge that was clipped).
 *   kind 1 (PG__KIND_FACE_B): B's face is the reference; the B byte is B's face, the A
 *          byte A's incident vertex.
 *   kind 2 (PG__KIND_POINTS): vertex to vertex; the bytes are the vertex indices (0 for
 *          a circle's centre). Circle-circle is 0x20000.
 *   For a polygon against a circle the circle's byte is 0.
 *
 * PRECISION AND BOUNDS (see geom.c): coordinates |x|, |y| <= 2^29 raw, radii <= 2^28 raw
 * (the envelope's 50 m is 2^21.6), the speculative distance any pg_fix >= 0: contact.c
 * widens it to the distance a pair can close in one step, which reaches 11 585 m
 * (2^29.5 raw) at step_hz 1 and 4096 m/s, and the one product it enters,
 * (speculative + radii) 2^31, stays below 2^63. Dot products with Q2.30 normals are kept
 * as int64 Q46 sums (< 2^61) and rounded once. Separations against a face are measured from the
 * face's mean offset (v1.n + v2.n) / 2, not from one of its vertices, so reversing a
 * face (as mirroring does) gives the same bits; so are distances to a segment's interior
 * in the closest-feature test. Every formula is symmetric in the two ends of an edge and
 * rounding is symmetric in sign: mirroring a configuration mirrors the manifold exactly
 * (short of exact ties between two faces, two incident edges or two vertex pairs, which
 * go to the first in index order).
 *
 * SEPARATED CORES: the smallest reported separation exceeds the distance between the
 * cores (radii aside) by at most PG__DIP_TOLERANCE + 1/2 + eta LSB, eta the largest offset
 * of a face's mean plane from its own vertices, |(v2 - v1) . n| / 2: at most
 * sqrt(2)/2 + 1e-3 for shapes placed by pg_geom_transform (vertices rounded per
 * component, normals rotated), so 2.21 LSB. Derivation: the incident edge holds the
 * incident core's vertex w deepest along n (it is the most anti-parallel edge), and w's
 * separation from the face's mean plane is the face's SAT separation s <= distance + eta
 * (the separation along any axis is at most the distance; the mean plane lies within
 * eta of the face's vertices). Kept as a point, w reports round(s) <= s + 1/2. Beyond a
 * side plane through the face's vertex v, the cut there (separation h) is kept if its dip
 * is at most 1 (h <= round(s) + 1 <= s + 3/2), or else if h is at most 1 + the exact
 * distance from v to the edge beyond the plane (to w, or to the edge's line measured from
 * its mean plane: + eta). v is the reference core's point nearest that part of the edge:
 * the face's own region ends at the side plane, and the next face turns away from an
 * edge that dips towards the face's line unless the cores meet. The fallbacks are exact
 * to rounding: vertex to vertex the nearest integer distance (1/2), a face whose interior
 * holds the closest point its separation (s + 1/2). So no contact is dropped while the
 * distance less the radii is at most speculative - 2.21 LSB. Each clipped point is its
 * own distance from the reference core, rounded, so no separation lies below the distance
 * by more than 1 + eta, except while the hysteresis keeps a face whose separation is
 * below the better one's: a segment has no inside, and an incident vertex past its line
 * can still be apart from it (down to that face's separation less 1).
 *
 * LIMITS: coincident circle centres get the normal (0, 1). Segments and capsules must
 * have distinct end points (their normals must be valid). SAT over face normals only:
 * deep overlaps of rounded shapes use the cores' face normals (as Box2D).
 */
#include "collide.h"
#include "pogon/config.h" /* PG_CONFIG_SHAPES */

/* Whether this build keeps a kind of two vertices (capsules, segments, chain segments):
 * without one, shape creation makes no such geometry and the tests for count 2 fold to
 * false, so their code drops out of a circles-and-boxes build. */
#define PG__TWO_VERTEX_KEPT PG_SHAPES_KEPT(PG_SHAPES_CAPSULE | PG_SHAPES_SEGMENT | PG_SHAPES_CHAIN)

/* 0.1 * linear slop (0.005 m), Q16.16. */
#define PG__REF_TOLERANCE ((int64_t)33)

/* Separated cores: how much farther from the face's vertex a cut at a side plane may lie
 * than the incident edge beyond that plane, Q16.16 (see pg__clip, pg__cut_overstates). */
#define PG__DIP_TOLERANCE ((int64_t)1)

#define PG__KIND_FACE_A 0u
#define PG__KIND_FACE_B 1u
#define PG__KIND_POINTS 2u
#define PG__ID(kind, ia, ib) (((uint32_t)(kind) << 16) | ((uint32_t)(ia) << 8) | (uint32_t)(ib))

#define PG__Q30 ((int64_t)1 << 30)

/* ---- helpers ------------------------------------------------------------------------ */

static uint64_t pg__sqrt_nearest(uint64_t v)
{
    uint64_t r = pg_isqrt64(v);
    if (v - r * r > r) ++r;
    return r;
}

/* (x, y) . n for Q16.16 components and a Q2.30 direction: Q46, |.| < 2^61. */
static int64_t pg__dot46(int64_t x, int64_t y, pg_dir n) { return x * n.x + y * n.y; }

static int64_t pg__vdot46(pg_vec2 v, pg_dir n) { return pg__dot46(v.x, v.y, n); }

static int64_t pg__dist2(pg_vec2 a, pg_vec2 b)
{
    int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y;
    return dx * dx + dy * dy; /* < 2^61 */
}

/* n / d rounded to nearest, ties away from zero; d > 0, |n| + d/2 < 2^63. */
static int64_t pg__div_round(int64_t n, int64_t d)
{
    return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

static pg_dir pg__dir(int32_t x, int32_t y)
{
    pg_dir d;
    d.x = x;
    d.y = y;
    return d;
}

static pg_dir pg__tangent(pg_dir n) { return pg__dir(-n.y, n.x); } /* along v[i] -> v[i+1] */

static int32_t pg__next(int32_t i, int32_t count) { return i + 1 < count ? i + 1 : 0; }

/* Twice the offset of face i along its normal, (v_i + v_i+1) . n_i, Q46. */
static int64_t pg__face_off2(const pg_geom *g, int32_t i)
{
    pg_dir n = g->normals[i];
    return pg__vdot46(g->vertices[i], n) + pg__vdot46(g->vertices[pg__next(i, g->count)], n);
}

/* Twice the separation of p from face i (Q46 x 2): 2 p.n - off2, |.| < 2^62. */
static int64_t pg__sep2(pg_vec2 p, pg_dir n, int64_t off2) { return 2 * pg__vdot46(p, n) - off2; }

/* SATURATION here, in pg__add_half, pg__mid_half and pg__push: never inside the
 * envelope. Shapes are placed within 1000 m + 1000 m (a static body's reach) of the
 * origin, so every point and manifold point lies within 2000 m and every separation
 * within the speculative window (at most 4 x 4096 m/s over one step, contact.c) plus
 * 4000 m, below 32768 m; only shapes flown out of the envelope (stats.envelope_exits)
 * reach the edge of Q16.16, where these keep the results defined. */
/* The Q16.16 value of a "Q46 x 2" quantity. */
static pg_fix pg__q16_of2(int64_t v2) { return pg__sat64(pg__round_shift64(v2, 31)); }

/* p + n * (k / 2), k in Q16.16: one rounding per component. */
static pg_vec2 pg__add_half(pg_vec2 p, pg_dir n, int64_t k)
{
    return pg_v2(pg__sat64(p.x + pg__round_shift64(k * n.x, 31)), pg__sat64(p.y + pg__round_shift64(k * n.y, 31)));
}

/* (a + b) / 2 + n * (k / 2), k in Q16.16, rounded once per component. Written as
 * a + ((b - a) + k n) / 2 so that only a difference is rounded: the result is exactly
 * translation invariant as well as mirror symmetric (rounding (a + b) / 2 directly would
 * round ties by the sign of a + b, which a translation can change). */
static pg_vec2 pg__mid_half(pg_vec2 a, pg_vec2 b, pg_dir n, int64_t k)
{
    return pg_v2(pg__sat64(a.x + pg__round_shift64(((int64_t)b.x - a.x) * PG__Q30 + k * n.x, 31)),
                 pg__sat64(a.y + pg__round_shift64(((int64_t)b.y - a.y) * PG__Q30 + k * n.y, 31)));
}

static void pg__clear(pg_manifold *m)
{
    int i;
    m->normal = pg__dir(0, 0);
    m->count = 0;
    for (i = 0; i < 2; ++i) {
        m->points[i].point = pg_v2_zero();
        m->points[i].separation = 0;
        m->points[i].id = 0;
    }
}

static void pg__push(pg_manifold *m, pg_vec2 point, int64_t separation, uint32_t id)
{
    pg_manifold_point *mp = &m->points[m->count++];
    mp->point = point;
    mp->separation = pg__sat64(separation);
    mp->id = id;
}

/* ---- circle - circle ------------------------------------------------------------------ */

static void pg__collide_circles(const pg_geom *a, const pg_geom *b, pg_fix speculative, pg_manifold *out)
{
    pg_vec2 ca = a->vertices[0], cb = b->vertices[0];
    int64_t d2 = pg__dist2(ca, cb), dist = (int64_t)pg__sqrt_nearest((uint64_t)d2);
    int64_t sep = dist - a->radius - b->radius;
    pg_dir n;
    if (sep > speculative) return; /* before the normal: a pair left out needs no unit vector */
    n = d2 == 0 ? pg__dir(0, (int32_t)PG__Q30) : pg_dir_normalize((int64_t)cb.x - ca.x, (int64_t)cb.y - ca.y);
    out->normal = n;
    pg__push(out, pg__mid_half(ca, cb, n, (int64_t)a->radius - b->radius), sep, PG__ID(PG__KIND_POINTS, 0, 0));
}

/* ---- polygon - circle ------------------------------------------------------------------ */

/* poly has count >= 2, circ count 1. circle_is_a: the circle is shape A (the normal is
 * then reversed and the ids name the circle as A). */
static void pg__collide_poly_circle(const pg_geom *poly, const pg_geom *circ, int circle_is_a, pg_fix speculative,
                                    pg_manifold *out)
{
    pg_vec2 c = circ->vertices[0];
    int32_t i, face = 0, count = poly->count, vertex = -1;
    int64_t best = INT64_MIN, radius = (int64_t)poly->radius + circ->radius;
    int64_t rdiff = (int64_t)poly->radius - circ->radius;
    pg_dir n;
    pg_vec2 point;
    int64_t sep;
    uint32_t id;

    for (i = 0; i < count; ++i) {
        int64_t s = pg__sep2(c, poly->normals[i], pg__face_off2(poly, i));
        if (s > best) { best = s; face = i; }
    }
    if (best > ((int64_t)speculative + radius) * ((int64_t)1 << 31)) return;

    /* Outside the core (always possible for a segment, which has no inside): Voronoi
     * regions of the face's two vertices. */
    if (best > 0 || (PG__TWO_VERTEX_KEPT && count == 2)) {
        int32_t i2 = pg__next(face, count);
        pg_vec2 v1 = poly->vertices[face], v2 = poly->vertices[i2];
        pg_dir t = pg__tangent(poly->normals[face]);
        if (pg__dot46((int64_t)c.x - v1.x, (int64_t)c.y - v1.y, t) < 0) vertex = face;
        else if (pg__dot46((int64_t)v2.x - c.x, (int64_t)v2.y - c.y, t) < 0) vertex = i2;
    }
    if (vertex >= 0 && pg__dist2(poly->vertices[vertex], c) != 0) {
        pg_vec2 v = poly->vertices[vertex];
        int64_t dist = (int64_t)pg__sqrt_nearest((uint64_t)pg__dist2(v, c));
        sep = dist - radius;
        if (sep > speculative) return;
        n = pg_dir_normalize((int64_t)c.x - v.x, (int64_t)c.y - v.y);
        point = pg__mid_half(v, c, n, rdiff);
        id = circle_is_a ? PG__ID(PG__KIND_POINTS, 0, vertex) : PG__ID(PG__KIND_POINTS, vertex, 0);
    } else {
        pg_fix s16 = pg__q16_of2(best);
        n = poly->normals[face];
        sep = (int64_t)s16 - radius;
        if (sep > speculative) return;
        /* Core point c - s n; midway between the surfaces: c + n (rp - rc - s) / 2. */
        point = pg__add_half(c, n, rdiff - s16);
        id = circle_is_a ? PG__ID(PG__KIND_FACE_B, 0, face) : PG__ID(PG__KIND_FACE_A, face, 0);
    }
    out->normal = circle_is_a ? pg__dir(-n.x, -n.y) : n;
    pg__push(out, point, sep, id);
}

/* ---- polygon - polygon (including segments and capsules) ------------------------------- */

/* The largest separation ("Q46 x 2") of b's vertices from a's faces, and that face. */
static int64_t pg__max_separation(const pg_geom *a, const pg_geom *b, int32_t *edge)
{
    int64_t best = INT64_MIN;
    int32_t i, j;
    *edge = 0;
    if (a->count == 4 && a->normals[2].x == -a->normals[0].x && a->normals[2].y == -a->normals[0].y &&
        a->normals[3].x == -a->normals[1].x && a->normals[3].y == -a->normals[1].y) {
        /* A box (opposite faces have opposite normals, exactly: rounding is symmetric):
         * the deepest vertex of b along -n is the farthest along n, so one pass over b's
         * vertices per pair of faces finds both. Same values and ties as the loop below. */
        int64_t si[4];
        for (i = 0; i < 2; ++i) {
            pg_dir n = a->normals[i];
            int64_t lo = INT64_MAX, hi = INT64_MIN;
            for (j = 0; j < b->count; ++j) {
                int64_t d = pg__vdot46(b->vertices[j], n);
                if (d < lo) lo = d;
                if (d > hi) hi = d;
            }
            si[i] = 2 * lo - pg__face_off2(a, i);
            si[i + 2] = -2 * hi - pg__face_off2(a, i + 2);
        }
        for (i = 0; i < 4; ++i)
            if (si[i] > best) { best = si[i]; *edge = i; }
        return best;
    }
    for (i = 0; i < a->count; ++i) {
        pg_dir n = a->normals[i];
        int64_t lo = INT64_MAX, si;
        /* the deepest vertex of b along n; sep2 = 2 (v . n) - off2 is increasing in v . n */
        for (j = 0; j < b->count; ++j) {
            int64_t d = pg__vdot46(b->vertices[j], n);
            if (d < lo) lo = d;
        }
        si = 2 * lo - pg__face_off2(a, i);
        if (si > best) { best = si; *edge = i; }
    }
    return best;
}

/* A box: four vertices whose opposite faces have opposite normals (exactly: rounding is
 * symmetric, so every placed rectangle or parallelogram qualifies). */
static int pg__is_box(const pg_geom *g)
{
    return g->count == 4 && g->normals[2].x == -g->normals[0].x && g->normals[2].y == -g->normals[0].y &&
           g->normals[3].x == -g->normals[1].x && g->normals[3].y == -g->normals[1].y;
}

/* pg__max_separation of the box g against the box o, written out: the same values and
 * ties. One pass over o's vertices gives, per pair of opposite faces, the deepest along n
 * and along -n (Q46 products < 2^60, as pg__vdot46); face i's doubled offset
 * (v_i + v_i+1) . n_i is one product of the summed vertices (components < 2^30: < 2^61,
 * the same integer as the two products), face i + 2's the negation of (v_i+2 + v_i+3) . n_i
 * (n_i+2 = -n_i). The separations stay below 2^62, as pg__sep2's. */
static int64_t pg__box_separation(const pg_geom *g, const pg_geom *o, int32_t *edge)
{
    const pg_vec2 *v = g->vertices, *w = o->vertices;
    int64_t nx0 = g->normals[0].x, ny0 = g->normals[0].y, nx1 = g->normals[1].x, ny1 = g->normals[1].y;
    int64_t lo0 = INT64_MAX, hi0 = INT64_MIN, lo1 = INT64_MAX, hi1 = INT64_MIN, si[4], best;
    int32_t j;
    for (j = 0; j < 4; ++j) {
        int64_t x = w[j].x, y = w[j].y, d0 = x * nx0 + y * ny0, d1 = x * nx1 + y * ny1;
        if (d0 < lo0) lo0 = d0;
        if (d0 > hi0) hi0 = d0;
        if (d1 < lo1) lo1 = d1;
        if (d1 > hi1) hi1 = d1;
    }
    si[0] = 2 * lo0 - (((int64_t)v[0].x + v[1].x) * nx0 + ((int64_t)v[0].y + v[1].y) * ny0);
    si[1] = 2 * lo1 - (((int64_t)v[1].x + v[2].x) * nx1 + ((int64_t)v[1].y + v[2].y) * ny1);
    si[2] = -2 * hi0 + (((int64_t)v[2].x + v[3].x) * nx0 + ((int64_t)v[2].y + v[3].y) * ny0);
    si[3] = -2 * hi1 + (((int64_t)v[3].x + v[0].x) * nx1 + ((int64_t)v[3].y + v[0].y) * ny1);
    best = si[0];
    *edge = 0;
    for (j = 1; j < 4; ++j)
        if (si[j] > best) { best = si[j]; *edge = j; }
    return best;
}

/* pg__incident_edge of a box: its normals 2 and 3 are the negations of 0 and 1, and so
 * are their products with n (the same order, the same ties). */
static int32_t pg__box_incident_edge(const pg_geom *g, pg_dir n)
{
    int64_t d0 = (int64_t)n.x * g->normals[0].x + (int64_t)n.y * g->normals[0].y;
    int64_t d1 = (int64_t)n.x * g->normals[1].x + (int64_t)n.y * g->normals[1].y, best = d0;
    int32_t j = 0;
    if (d1 < best) { best = d1; j = 1; }
    if (-d0 < best) { best = -d0; j = 2; }
    if (-d1 < best) j = 3;
    return j;
}

/* Squared distance (Q32.32) from p to the segment a..b whose unit normal is n; *end is
 * 0 or 1 when the closest point is a or b (p projects beyond that end; decided exactly),
 * -1 when it is inside the segment. Inside, the distance is p's separation from the
 * segment's mean plane (v1 + v2) . n / 2, rounded, as for faces: reversing the segment
 * (as mirroring does) gives the same bits. */
static int64_t pg__point_segment(pg_vec2 p, pg_vec2 a, pg_vec2 b, pg_dir n, int *end)
{
    pg_dir t = pg__tangent(n);
    int64_t d;
    if (pg__dot46((int64_t)p.x - a.x, (int64_t)p.y - a.y, t) < 0) { *end = 0; return pg__dist2(p, a); }
    if (pg__dot46((int64_t)b.x - p.x, (int64_t)b.y - p.y, t) < 0) { *end = 1; return pg__dist2(p, b); }
    *end = -1;
    d = pg__q16_of2(pg__sep2(p, n, pg__vdot46(a, n) + pg__vdot46(b, n)));
    return d * d;
}

/* Sign of (q - p) x (r - p). */
static int pg__orient(pg_vec2 p, pg_vec2 q, pg_vec2 r)
{
    int64_t c = ((int64_t)q.x - p.x) * ((int64_t)r.y - p.y) - ((int64_t)q.y - p.y) * ((int64_t)r.x - p.x);
    return (c > 0) - (c < 0);
}

/* Do the segments a1..a2 and b1..b2 cross at a point inside both (strictly)? */
static int pg__segments_cross(pg_vec2 a1, pg_vec2 a2, pg_vec2 b1, pg_vec2 b2)
{
    return pg__orient(a1, a2, b1) * pg__orient(a1, a2, b2) < 0 && pg__orient(b1, b2, a1) * pg__orient(b1, b2, a2) < 0;
}

/* The edge of g whose normal is the most anti-parallel to n (the first on ties). */
static int32_t pg__incident_edge(const pg_geom *g, pg_dir n)
{
    int32_t k, j = 0;
    int64_t best = INT64_MAX;
    for (k = 0; k < g->count; ++k) {
        int64_t dd = (int64_t)n.x * g->normals[k].x + (int64_t)n.y * g->normals[k].y;
        if (dd < best) { best = dd; j = k; }
    }
    return j;
}

/* The incident edge i21 -> i22 of inc clipped to the side planes of ref's face i11:
 * the candidate points before the speculative filter, with their core separations. */
typedef struct pg__clip {
    pg_vec2 p[2];
    int64_t sep[2]; /* Q16.16, between the cores (radii not subtracted) */
    int32_t iv[2];  /* the incident vertex each point comes from */
    int32_t count;  /* 1 when the edge misses the face (both ends beyond one side plane), else 2 */
    int32_t miss;
    /* Per end (0: at the lower side plane, through v11; 1: at the upper one, through v12),
     * when the edge was cut there: the cut's "dip", its separation less that of the
     * incident vertex beyond the plane (Q16.16); INT64_MIN when that end is the vertex. */
    int64_t dip[2];
} pg__clip;

static void pg__clip_edge(const pg_geom *ref, int32_t i11, const pg_geom *inc, int32_t i21, int64_t rdiff, pg__clip *c)
{
    int32_t i12 = pg__next(i11, ref->count), i22 = pg__next(i21, inc->count);
    pg_dir n = ref->normals[i11], t = pg__tangent(n);
    pg_vec2 v11 = ref->vertices[i11], v12 = ref->vertices[i12], v21 = inc->vertices[i21], v22 = inc->vertices[i22];
    /* The four vertices' projections on n and on t (Q46, < 2^60): every quantity below is
     * a sum of them, the same integer as the product of the corresponding difference. */
    int64_t n11 = pg__vdot46(v11, n), n12 = pg__vdot46(v12, n), n21 = pg__vdot46(v21, n), n22 = pg__vdot46(v22, n);
    int64_t t11 = pg__vdot46(v11, t), t12 = pg__vdot46(v12, t), t21 = pg__vdot46(v21, t), t22 = pg__vdot46(v22, t);
    int64_t off2 = n11 + n12; /* pg__face_off2 */
    int64_t s21 = pg__q16_of2(2 * n21 - off2), s22 = pg__q16_of2(2 * n22 - off2);
    /* The incident edge runs against the tangent: "lower" side plane through v11,
     * "upper" through v12; dl = rounded offset past the lower plane, du before the upper
     * ((v21 - v11) . t = t21 - t11, ...: differences < 2^61). */
    int64_t dl21 = pg__round_shift64(t21 - t11, 30);
    int64_t dl22 = pg__round_shift64(t22 - t11, 30);
    int64_t du21 = pg__round_shift64(t12 - t21, 30);
    int64_t du22 = pg__round_shift64(t12 - t22, 30);

    c->dip[0] = c->dip[1] = INT64_MIN;
    c->miss = (dl21 < 0 && dl22 < 0) || (du21 < 0 && du22 < 0);
    if (c->miss) {
        /* One point at the deeper vertex. */
        int use21 = s21 <= s22;
        int64_t s = use21 ? s21 : s22;
        c->count = 1;
        c->iv[0] = use21 ? i21 : i22;
        c->p[0] = pg__add_half(use21 ? v21 : v22, n, rdiff - s);
        c->sep[0] = s;
        return;
    }
    c->count = 2;
    /* Lower end: v22, or the point of the edge on the plane through v11. */
    if (dl22 >= 0) {
        c->p[0] = pg__add_half(v22, n, rdiff - s22);
        c->sep[0] = s22;
    } else {
        int64_t h = pg__div_round(s22 * dl21 - s21 * dl22, dl21 - dl22);
        /* v11 + (h + e) n, e = off2/2 - v11.n: the point lies on the side plane. */
        int64_t e2 = n12 - n11; /* 2e = off2 - 2 v11.n, Q46 */
        c->p[0] = pg__add_half(v11, n, pg__round_shift64(e2, 30) + h + rdiff);
        c->sep[0] = h;
        c->dip[0] = h - s22;
    }
    c->iv[0] = i22;
    /* Upper end: v21, or the point on the plane through v12. */
    if (du21 >= 0) {
        c->p[1] = pg__add_half(v21, n, rdiff - s21);
        c->sep[1] = s21;
    } else {
        int64_t h = pg__div_round(s21 * du22 - s22 * du21, du22 - du21);
        int64_t e2 = n11 - n12; /* off2 - 2 v12.n */
        c->p[1] = pg__add_half(v12, n, pg__round_shift64(e2, 30) + h + rdiff);
        c->sep[1] = h;
        c->dip[1] = h - s21;
    }
    c->iv[1] = i21;
}

/* A cut at the side plane through the face vertex v, separation h (Q16.16): is it
 * farther from v, by more than PG__DIP_TOLERANCE, than the part of the incident edge
 * beyond that plane is? That part ends at the incident vertex w, d points along the edge
 * towards w, n2 and off2 are the incident face's normal and doubled offset. The edge
 * dips, so its point nearest v lies beyond the plane: w when v projects onto the edge's
 * line beyond w, else the foot of the perpendicular, v's separation from the edge's mean
 * plane; both compared exactly. (Counting an incident vertex up to PG__REF_TOLERANCE
 * beyond a face's end as over the face, as collide.c did once, reported the cut: the
 * gap overstated by that offset times the tangent of the edge's tilt, without bound.) */
static int pg__cut_overstates(int64_t h, pg_vec2 v, pg_vec2 w, pg_dir d, pg_dir n2, int64_t off2)
{
    int64_t k = h - PG__DIP_TOLERANCE, s;
    if (k <= 0) return 0;
    if (pg__dot46((int64_t)v.x - w.x, (int64_t)v.y - w.y, d) >= 0) return k * k > pg__dist2(v, w);
    s = pg__sep2(v, n2, off2);
    return k * ((int64_t)1 << 31) > (s < 0 ? -s : s);
}

/* Does the clip of the incident edge i21 of inc against ref's face i11 miss the face, or
 * overstate the gap at a side plane by more than PG__DIP_TOLERANCE? */
static int pg__clip_overstates(const pg_geom *ref, int32_t i11, const pg_geom *inc, int32_t i21, const pg__clip *c)
{
    int32_t i22 = pg__next(i21, inc->count);
    pg_dir n2 = inc->normals[i21], t2 = pg__tangent(n2);
    int64_t off2 = pg__face_off2(inc, i21);
    if (c->miss) return 1;
    if (c->dip[0] > PG__DIP_TOLERANCE &&
        pg__cut_overstates(c->sep[0], ref->vertices[i11], inc->vertices[i22], t2, n2, off2))
        return 1;
    return c->dip[1] > PG__DIP_TOLERANCE &&
           pg__cut_overstates(c->sep[1], ref->vertices[pg__next(i11, ref->count)], inc->vertices[i21], pg__dir(-t2.x, -t2.y), n2, off2);
}

static void pg__collide_polygons(const pg_geom *a, const pg_geom *b, pg_fix speculative, pg_manifold *out)
{
    const pg_geom *ref, *inc;
    int32_t ea, eb, i11, j, flip, far, k;
    int64_t sa, sb;
    int64_t radius = (int64_t)a->radius + b->radius;
    int64_t limit2 = ((int64_t)speculative + radius) * ((int64_t)1 << 31);
    pg_dir n;
    uint32_t kind;
    pg__clip c;
    int boxes = pg__is_box(a) && pg__is_box(b);

    /* (B's faces need not be measured once A's show the shapes apart: nothing is reported) */
    sa = boxes ? pg__box_separation(a, b, &ea) : pg__max_separation(a, b, &ea);
    if (sa > limit2) return;
    sb = boxes ? pg__box_separation(b, a, &eb) : pg__max_separation(b, a, &eb);
    if (sb > limit2) return;

    /* Cores apart by more than the tolerance: the reference is the face with the larger
     * separation (A on ties), without hysteresis. The closest points of two separated
     * convex cores span a slab that separates them, so when they are a vertex and a
     * face's interior that face's separation is the distance and no other face's is
     * larger: the best face measures the distance. Touching, overlapping or nearly
     * touching cores (resting contact) keep A's face unless B's is better by
     * PG__REF_TOLERANCE. */
    far = (sa > sb ? sa : sb) > PG__REF_TOLERANCE * ((int64_t)1 << 31);
    flip = far ? sb > sa : sb > sa + PG__REF_TOLERANCE * ((int64_t)1 << 31);
    ref = flip ? b : a;
    inc = flip ? a : b;
    i11 = flip ? eb : ea;
    j = boxes ? pg__box_incident_edge(inc, ref->normals[i11]) : pg__incident_edge(inc, ref->normals[i11]);
    pg__clip_edge(ref, i11, inc, j, (int64_t)ref->radius - inc->radius, &c);

    /* Cores apart (a face axis separates them, or two segments that do not cross: end to
     * end on one line no face axis shows it) whose clip misses the face or overstates the
     * gap at a side plane: take the better face outright, and if its clip does too, the
     * closest features of that face and its incident edge decide. */
    if ((sa > 0 || sb > 0 || (PG__TWO_VERTEX_KEPT && a->count == 2 && b->count == 2)) &&
        (c.miss || c.dip[0] > PG__DIP_TOLERANCE || c.dip[1] > PG__DIP_TOLERANCE) &&
        (sa > 0 || sb > 0 || !pg__segments_cross(a->vertices[0], a->vertices[1], b->vertices[0], b->vertices[1])) &&
        pg__clip_overstates(ref, i11, inc, j, &c)) {
        if (flip != (sb > sa)) {
            flip = sb > sa;
            ref = flip ? b : a;
            inc = flip ? a : b;
            i11 = flip ? eb : ea;
            j = pg__incident_edge(inc, ref->normals[i11]);
            pg__clip_edge(ref, i11, inc, j, (int64_t)ref->radius - inc->radius, &c);
        }
        if (pg__clip_overstates(ref, i11, inc, j, &c)) {
            int32_t i12 = pg__next(i11, ref->count), i22 = pg__next(j, inc->count);
            pg_vec2 v11 = ref->vertices[i11], v12 = ref->vertices[i12], v21 = inc->vertices[j], v22 = inc->vertices[i22];
            int64_t d2[4];
            int ends[4], best_k = 0, face_vertex = 0, ref_vertex = -1;
            d2[0] = pg__point_segment(v21, v11, v12, ref->normals[i11], &ends[0]);
            d2[1] = pg__point_segment(v22, v11, v12, ref->normals[i11], &ends[1]);
            d2[2] = pg__point_segment(v11, v21, v22, inc->normals[j], &ends[2]);
            d2[3] = pg__point_segment(v12, v21, v22, inc->normals[j], &ends[3]);
            for (k = 1; k < 4; ++k)
                if (d2[k] < d2[best_k]) best_k = k;
            for (k = 0; k < 4; ++k)
                if (d2[k] == d2[best_k] && ends[k] < 0) {
                    if (k < 2) face_vertex = 1;
                    else ref_vertex = k;
                }
            /* An incident vertex over the face's interior (or touching cores): the clip
             * holds it. */
            if (d2[best_k] > 0 && !face_vertex) {
                if (ref_vertex < 0) {
                    /* Two vertices: one point, the normal from A's vertex to B's. */
                    int32_t ir, ii, ia, ib;
                    pg_vec2 va, vb;
                    int64_t dist, sep;
                    pg_dir nn;
                    if (best_k < 2) { ii = best_k == 0 ? j : i22; ir = ends[best_k] == 0 ? i11 : i12; }
                    else { ir = best_k == 2 ? i11 : i12; ii = ends[best_k] == 0 ? j : i22; }
                    ia = flip ? ii : ir;
                    ib = flip ? ir : ii;
                    va = a->vertices[ia];
                    vb = b->vertices[ib];
                    dist = (int64_t)pg__sqrt_nearest((uint64_t)pg__dist2(va, vb));
                    sep = dist - radius;
                    if (sep > speculative) return;
                    nn = pg_dir_normalize((int64_t)vb.x - va.x, (int64_t)vb.y - va.y);
                    out->normal = nn;
                    pg__push(out, pg__mid_half(va, vb, nn, (int64_t)a->radius - b->radius), sep, PG__ID(PG__KIND_POINTS, ia, ib));
                    return;
                } else {
                    /* A vertex of the reference face against the incident edge's interior
                     * (the better face ties with that edge's, or rounding): that edge's
                     * face is the reference, of a segment the side facing the vertex. */
                    const pg_geom *g = ref;
                    pg_vec2 v = ref_vertex == 2 ? v11 : v12;
                    ref = inc;
                    inc = g;
                    flip = !flip;
                    i11 = j;
                    if (PG__TWO_VERTEX_KEPT && ref->count == 2 && pg__sep2(v, ref->normals[i11], pg__face_off2(ref, i11)) < 0)
                        i11 = 1 - i11;
                    j = pg__incident_edge(inc, ref->normals[i11]);
                    pg__clip_edge(ref, i11, inc, j, (int64_t)ref->radius - inc->radius, &c);
                }
            }
        }
    }

    /* Two ends that round to the same point (the edge crosses a side plane right next to
     * its vertex) are one point: the deeper, on ties the vertex rather than the cut, so
     * that the choice does not depend on which end is the "lower" one (mirroring swaps
     * them). */
    if (c.count == 2 && pg_v2_equal(c.p[0], c.p[1])) {
        k = c.sep[0] != c.sep[1] ? c.sep[1] < c.sep[0] : c.dip[0] != INT64_MIN;
        c.p[0] = c.p[k];
        c.sep[0] = c.sep[k];
        c.iv[0] = c.iv[k];
        c.count = 1;
    }
    n = ref->normals[i11];
    kind = flip ? PG__KIND_FACE_B : PG__KIND_FACE_A;
    out->normal = flip ? pg__dir(-n.x, -n.y) : n;
    for (k = 0; k < c.count; ++k) {
        if (c.sep[k] - radius > speculative) continue;
        pg__push(out, c.p[k], c.sep[k] - radius, flip ? PG__ID(kind, c.iv[k], i11) : PG__ID(kind, i11, c.iv[k]));
    }
    if (out->count == 0) out->normal = pg__dir(0, 0);
}

/* ---- chain segment ------------------------------------------------------------------------
 * The ideas of Box2D v3's chain segments ("smooth segments"), for integers. A chain
 * segment v0 -> v1 is one-sided: it collides on the side of its face normal n1
 * (normals[0]). At each joint the neighbour decides which normals the segment may give:
 * at a convex joint (the chain turns towards n1 by more than CHAIN_FLAT) the cone
 * between the neighbour's normal and n1; at a flat or concave joint none but n1. The
 * plain segment's manifold is computed first; a normal outside the cone on the
 * neighbour's side beyond its normal is left to the neighbour (skip), any other normal
 * outside the cone is replaced by n1 ("snap": the other shape's incident edge clipped to
 * the segment's side planes, or a circle's centre between them). A box sliding over a
 * flat joint thus meets two faces with the same normal and never the end of the next
 * segment. An end with no neighbour is an ordinary rounded end. */

/* Joints whose turn has a sine below 2^-7 (0.45 degrees) count as flat: Q60. */
#define PG__CHAIN_FLAT ((int64_t)1 << 53)

static int64_t pg__cross60(pg_dir a, pg_dir b) { return (int64_t)a.x * b.y - (int64_t)a.y * b.x; }
static int64_t pg__dot60(pg_dir a, pg_dir b) { return (int64_t)a.x * b.x + (int64_t)a.y * b.y; }

/* The right-hand unit normal of the edge from a to b. */
static pg_dir pg__edge_normal(pg_vec2 a, pg_vec2 b) { return pg_dir_normalize((int64_t)b.y - a.y, -((int64_t)b.x - a.x)); }

/* The manifold against the face normal n1 of seg alone (see above). */
static void pg__chain_snap(const pg_geom *seg, const pg_geom *other, pg_fix speculative, pg_manifold *out)
{
    pg_dir n1 = seg->normals[0], t1 = pg__tangent(n1);
    int64_t radius = (int64_t)seg->radius + other->radius, rdiff = (int64_t)seg->radius - other->radius;
    int32_t k;
    pg__clear(out);
    if (other->count == 1) {
        pg_vec2 c = other->vertices[0], v0 = seg->vertices[0], v1 = seg->vertices[1];
        pg_fix s16;
        if (pg__dot46((int64_t)c.x - v0.x, (int64_t)c.y - v0.y, t1) < 0 || pg__dot46((int64_t)v1.x - c.x, (int64_t)v1.y - c.y, t1) < 0)
            return; /* beyond a side plane: the neighbour's */
        s16 = pg__q16_of2(pg__sep2(c, n1, pg__face_off2(seg, 0)));
        if ((int64_t)s16 - radius > speculative) return;
        out->normal = n1;
        pg__push(out, pg__add_half(c, n1, rdiff - s16), (int64_t)s16 - radius, PG__ID(PG__KIND_FACE_A, 0, 0));
    } else {
        pg__clip c;
        pg__clip_edge(seg, 0, other, pg__incident_edge(other, n1), rdiff, &c);
        if (c.miss) return;
        if (c.count == 2 && pg_v2_equal(c.p[0], c.p[1])) c.count = 1;
        out->normal = n1;
        for (k = 0; k < c.count; ++k)
            if (c.sep[k] - radius <= speculative) pg__push(out, c.p[k], c.sep[k] - radius, PG__ID(PG__KIND_FACE_A, 0, c.iv[k]));
    }
    if (out->count == 0) out->normal = pg__dir(0, 0);
}

void pg_collide_chain(const pg_geom *seg, const pg_vec2 *before, const pg_vec2 *after, const pg_geom *other, pg_fix speculative,
                      pg_manifold *out)
{
    pg_vec2 v0 = seg->vertices[0], v1 = seg->vertices[1], c = other->centroid;
    pg_dir n1 = seg->normals[0], t1 = pg__tangent(n1), n0 = n1, n2 = n1, nrm;
    int convex0 = 0, convex2 = 0, tail;
    pg__clear(out);
    if (seg->count != 2 || other->count < 1 || other->count > PG_MAX_POLYGON_VERTICES) return;
    if (speculative < 0) speculative = 0;
    if (before != NULL) {
        n0 = pg__edge_normal(*before, v0);
        convex0 = pg__cross60(pg__tangent(n0), t1) > PG__CHAIN_FLAT;
    }
    if (after != NULL) {
        n2 = pg__edge_normal(v1, *after);
        convex2 = pg__cross60(t1, pg__tangent(n2)) > PG__CHAIN_FLAT;
    }
    /* one-sided: nothing for a shape whose centre is behind every face the joint has */
    if (pg__dot46((int64_t)c.x - v0.x, (int64_t)c.y - v0.y, n1) < 0 &&
        !(convex0 && pg__dot46((int64_t)c.x - v0.x, (int64_t)c.y - v0.y, n0) >= 0) &&
        !(convex2 && pg__dot46((int64_t)c.x - v1.x, (int64_t)c.y - v1.y, n2) >= 0))
        return;
    pg_collide(seg, other, speculative, out);
    if (out->count == 0) return;
    nrm = out->normal;
    if (nrm.x == n1.x && nrm.y == n1.y) return; /* the face itself */
    tail = pg__dot60(nrm, t1) <= 0;
    if (tail ? before == NULL : after == NULL) return; /* the chain's rounded end */
    if (tail ? convex0 : convex2) {
        int64_t beyond = tail ? pg__cross60(nrm, n0) : pg__cross60(n2, nrm);
        if (beyond > PG__CHAIN_FLAT) pg__clear(out); /* the neighbour's */
        return;                                         /* else within the joint's cone */
    }
    pg__chain_snap(seg, other, speculative, out);
}

/* ---- entry points ------------------------------------------------------------------------ */

void pg_collide(const pg_geom *a, const pg_geom *b, pg_fix speculative, pg_manifold *out)
{
    pg__clear(out);
    if (a->count < 1 || b->count < 1 || a->count > PG_MAX_POLYGON_VERTICES || b->count > PG_MAX_POLYGON_VERTICES)
        return;
    if (speculative < 0) speculative = 0;
    if (a->count == 1 && b->count == 1) pg__collide_circles(a, b, speculative, out);
    else if (b->count == 1) pg__collide_poly_circle(a, b, 0, speculative, out);
    else if (a->count == 1) pg__collide_poly_circle(b, a, 1, speculative, out);
    else pg__collide_polygons(a, b, speculative, out);
}

int pg_geom_overlap(const pg_geom *a, const pg_geom *b)
{
    pg_manifold m;
    int32_t i;
    pg_collide(a, b, 0, &m);
    for (i = 0; i < m.count; ++i)
        if (m.points[i].separation < 0) return 1;
    return 0;
}

int pg_geom_contains(const pg_geom *g, pg_vec2 p)
{
    /* The same decision as pg_collide against a circle of radius 0 at p: separation <= 0. */
    pg_geom point;
    pg_manifold m;
    int32_t i;
    for (i = 0; i < PG_MAX_POLYGON_VERTICES; ++i) {
        point.vertices[i] = pg_v2_zero();
        point.normals[i].x = 0;
        point.normals[i].y = 0;
    }
    point.vertices[0] = p;
    point.centroid = p;
    point.radius = 0;
    point.count = 1;
    pg_collide(g, &point, 0, &m);
    return m.count > 0 && m.points[0].separation <= 0;
}
