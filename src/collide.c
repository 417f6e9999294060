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
 *                        incident edge is the other
 *                        shape's edge most anti-parallel to the reference normal. When the
 *                        cores are apart (rounded shapes, speculative contacts) the closest
 *                        features of the two edges decide: two vertices give one point with
 *                        the vertex-to-vertex normal (a capsule end on a box corner);
 *                        otherwise, and always when the cores touch or overlap, the
 *                        incident edge is clipped to the reference face's side planes,
 *                        giving up to two points. Points farther apart than `speculative`
 *                        are dropped.
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
 * PRECISION AND BOUNDS (see geom.c): coordinates |x|, |y| <= 2^29 raw, radii and the
 * speculative distance <= 2^28 raw. Dot products with Q2.30 normals are kept as int64
 * Q46 sums (< 2^61) and rounded once. Separations against a face are measured from the
 * face's mean offset (v1.n + v2.n) / 2, not from one of its vertices, so reversing a
 * face (as mirroring does) gives the same bits; every formula is symmetric in the two
 * ends of an edge and rounding is symmetric in sign: mirroring a configuration mirrors
 * the manifold exactly.
 *
 * LIMITS: coincident circle centres get the normal (0, 1). Segments and capsules must
 * have distinct end points (their normals must be valid). SAT over face normals only:
 * deep overlaps of rounded shapes use the cores' face normals (as Box2D).
 */
#include "geom.h"

/* 0.1 * linear slop (0.005 m), Q16.16. */
#define PG__REF_TOLERANCE ((int64_t)33)

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
    pg_dir n = d2 == 0 ? pg__dir(0, (int32_t)PG__Q30) : pg_dir_normalize((int64_t)cb.x - ca.x, (int64_t)cb.y - ca.y);
    if (sep > speculative) return;
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
    if (best > 0 || count == 2) {
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

/* Squared distance (Q32.32) from p to the segment a..b whose unit normal is n; *end is
 * 0 or 1 when the closest point is a or b, -1 when it is inside the segment. A point
 * that projects beyond an end by at most PG__REF_TOLERANCE still counts as inside (its
 * perpendicular distance is used): edges that are flush, as in a column of equal boxes,
 * then keep a two-point manifold instead of flickering to a corner contact. */
static int64_t pg__point_segment(pg_vec2 p, pg_vec2 a, pg_vec2 b, pg_dir n, int *end)
{
    pg_dir t = pg__tangent(n);
    int64_t d, slack = -PG__REF_TOLERANCE * PG__Q30;
    if (pg__dot46((int64_t)p.x - a.x, (int64_t)p.y - a.y, t) < slack) { *end = 0; return pg__dist2(p, a); }
    if (pg__dot46((int64_t)b.x - p.x, (int64_t)b.y - p.y, t) < slack) { *end = 1; return pg__dist2(p, b); }
    *end = -1;
    d = pg__round_shift64(pg__dot46((int64_t)p.x - a.x, (int64_t)p.y - a.y, n), 30);
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

static void pg__collide_polygons(const pg_geom *a, const pg_geom *b, pg_fix speculative, pg_manifold *out)
{
    const pg_geom *ref, *inc;
    int32_t ea, eb, i11, i12, i21, i22, j, flip, far, apart;
    int64_t sa = pg__max_separation(a, b, &ea), sb = pg__max_separation(b, a, &eb);
    int64_t radius = (int64_t)a->radius + b->radius, rdiff;
    int64_t limit2 = ((int64_t)speculative + radius) * ((int64_t)1 << 31);
    int64_t off2, s21, s22, dl21, dl22, du21, du22, best_dot;
    pg_dir n, t;
    pg_vec2 v11, v12, v21, v22;
    uint32_t kind;

    if (sa > limit2 || sb > limit2) return;

    /* Cores apart by more than the tolerance: the reference is the face with the larger
     * separation (A on ties), without hysteresis. The closest points of two separated
     * convex cores span a slab that separates them, so when they are a vertex and a
     * face's interior that face's separation is the distance and no other face's is
     * larger: the best face measures the distance. A face kept by the hysteresis may
     * instead see the incident edge clipped at its side plane farther away than the
     * closest points really are (a vertex of A against the interior of a face of B that
     * is tilted against A's face), overstating the gap. Touching or overlapping cores
     * (resting contact) keep A's face unless B's is better by PG__REF_TOLERANCE. */
    far = (sa > sb ? sa : sb) > PG__REF_TOLERANCE * ((int64_t)1 << 31);
    flip = far ? sb > sa : sb > sa + PG__REF_TOLERANCE * ((int64_t)1 << 31);
    ref = flip ? b : a;
    inc = flip ? a : b;
    i11 = flip ? eb : ea;
    i12 = pg__next(i11, ref->count);
    n = ref->normals[i11];
    t = pg__tangent(n);

    /* Incident edge: the most anti-parallel normal (first on ties). */
    j = 0;
    best_dot = INT64_MAX;
    {
        int32_t k;
        for (k = 0; k < inc->count; ++k) {
            int64_t dd = (int64_t)n.x * inc->normals[k].x + (int64_t)n.y * inc->normals[k].y;
            if (dd < best_dot) { best_dot = dd; j = k; }
        }
    }
    i21 = j;
    i22 = pg__next(j, inc->count);
    v11 = ref->vertices[i11];
    v12 = ref->vertices[i12];
    v21 = inc->vertices[i21];
    v22 = inc->vertices[i22];
    rdiff = (int64_t)ref->radius - inc->radius;
    kind = flip ? PG__KIND_FACE_B : PG__KIND_FACE_A;

    /* Cores apart by more than the tolerance: do two vertices hold the closest points?
     * Two segments can also be apart with no face axis showing it (end to end on one
     * line): unless they cross, look at their closest features too. */
    apart = far;
    if (!apart && a->count == 2 && b->count == 2) apart = !pg__segments_cross(v11, v12, v21, v22);
    if (apart) {
        pg_dir n2 = inc->normals[j];
        int64_t d2[4];
        int ends[4], k, best_k = 0, interior = 0;
        d2[0] = pg__point_segment(v21, v11, v12, n, &ends[0]);
        d2[1] = pg__point_segment(v22, v11, v12, n, &ends[1]);
        d2[2] = pg__point_segment(v11, v21, v22, n2, &ends[2]);
        d2[3] = pg__point_segment(v12, v21, v22, n2, &ends[3]);
        for (k = 1; k < 4; ++k)
            if (d2[k] < d2[best_k]) best_k = k;
        for (k = 0; k < 4; ++k)
            if (d2[k] == d2[best_k] && ends[k] < 0) interior = 1;
        if (!interior && d2[best_k] > 0) {
            int32_t ir, ii; /* reference and incident vertex indices */
            pg_vec2 va, vb;
            int32_t ia, ib;
            int64_t dist, sep;
            pg_dir nn;
            if (best_k < 2) { ii = best_k == 0 ? i21 : i22; ir = ends[best_k] == 0 ? i11 : i12; }
            else { ir = best_k == 2 ? i11 : i12; ii = ends[best_k] == 0 ? i21 : i22; }
            ia = flip ? ii : ir;
            ib = flip ? ir : ii;
            va = a->vertices[ia];
            vb = b->vertices[ib];
            dist = (int64_t)pg__sqrt_nearest((uint64_t)pg__dist2(va, vb));
            sep = dist - radius;
            if (sep > speculative) return;
            nn = pg_dir_normalize((int64_t)vb.x - va.x, (int64_t)vb.y - va.y);
            out->normal = nn;
            pg__push(out, pg__mid_half(va, vb, nn, (int64_t)a->radius - b->radius), sep,
                     PG__ID(PG__KIND_POINTS, ia, ib));
            return;
        }
    }

    /* Clip the incident edge v21 -> v22 (it runs against the tangent) to the reference
     * face's side planes: "lower" through v11, "upper" through v12. */
    off2 = pg__face_off2(ref, i11);
    s21 = pg__q16_of2(pg__sep2(v21, n, off2));
    s22 = pg__q16_of2(pg__sep2(v22, n, off2));
    dl21 = pg__round_shift64(pg__dot46((int64_t)v21.x - v11.x, (int64_t)v21.y - v11.y, t), 30);
    dl22 = pg__round_shift64(pg__dot46((int64_t)v22.x - v11.x, (int64_t)v22.y - v11.y, t), 30);
    du21 = pg__round_shift64(pg__dot46((int64_t)v12.x - v21.x, (int64_t)v12.y - v21.y, t), 30);
    du22 = pg__round_shift64(pg__dot46((int64_t)v12.x - v22.x, (int64_t)v12.y - v22.y, t), 30);

    out->normal = flip ? pg__dir(-n.x, -n.y) : n;
    if ((dl21 < 0 && dl22 < 0) || (du21 < 0 && du22 < 0)) {
        /* The incident edge misses the face (only in degenerate overlaps): one point at
         * its deeper vertex. */
        int use21 = s21 <= s22;
        int64_t s = use21 ? s21 : s22;
        int32_t iv = use21 ? i21 : i22;
        pg_vec2 v = use21 ? v21 : v22;
        if (s - radius <= speculative)
            pg__push(out, pg__add_half(v, n, rdiff - s), s - radius, flip ? PG__ID(kind, iv, i11) : PG__ID(kind, i11, iv));
    } else {
        pg_vec2 p[2];
        int64_t sep[2];
        int32_t iv[2], k;
        /* Lower end: v22, or the point of the edge on the plane through v11. */
        if (dl22 >= 0) {
            p[0] = pg__add_half(v22, n, rdiff - s22);
            sep[0] = s22;
        } else {
            int64_t h = pg__div_round(s22 * dl21 - s21 * dl22, dl21 - dl22);
            /* v11 + (h + e) n, e = off2/2 - v11.n: the point lies on the side plane. */
            int64_t e2 = off2 - 2 * pg__vdot46(v11, n); /* 2e, Q46 */
            p[0] = pg__add_half(v11, n, pg__round_shift64(e2, 30) + h + rdiff);
            sep[0] = h;
        }
        iv[0] = i22;
        /* Upper end: v21, or the point on the plane through v12. */
        if (du21 >= 0) {
            p[1] = pg__add_half(v21, n, rdiff - s21);
            sep[1] = s21;
        } else {
            int64_t h = pg__div_round(s21 * du22 - s22 * du21, du22 - du21);
            int64_t e2 = off2 - 2 * pg__vdot46(v12, n);
            p[1] = pg__add_half(v12, n, pg__round_shift64(e2, 30) + h + rdiff);
            sep[1] = h;
        }
        iv[1] = i21;
        for (k = 0; k < 2; ++k) {
            if (sep[k] - radius > speculative) continue;
            if (k == 1 && out->count == 1 && pg_v2_equal(out->points[0].point, p[1])) continue;
            pg__push(out, p[k], sep[k] - radius, flip ? PG__ID(kind, iv[k], i11) : PG__ID(kind, i11, iv[k]));
        }
    }
    if (out->count == 0) out->normal = pg__dir(0, 0);
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
