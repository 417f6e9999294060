/* decompose.c — a simple polygon split into convex pieces of at most PG_MAX_VERTICES
 * vertices (docs/concave.md).
 *
 * 1. Validation: 3..PG_CONCAVE_MAX_VERTICES vertices within 1000 m, no repeated point,
 *    no edge under 0.005 m, no vertex on the line through its neighbours, no two
 *    non-adjacent edges touching (so the polygon is simple and has area).
 * 2. Ear clipping on the counter-clockwise order from input vertex 0: each round clips
 *    the ear (strictly convex, no other vertex in or on its triangle) whose triangle is
 *    thickest, the first counted from vertex 0 on ties.
 * 3. Hertel-Mehlhorn: two pieces that share an edge are merged while their union is
 *    strictly convex with at most PG_MAX_VERTICES vertices, pieces in creation order.
 * 4. A piece that pg_geometry_polygon refuses (thinner than 0.01 m: ear clipping leaves
 *    slivers where vertices lie close to a line) is merged with a neighbour, or the
 *    union re-split along another diagonal, while that gives two valid pieces.
 * Coordinates are within 2^26 raw, differences 2^27, cross products 2^55: every test is
 * exact in int64, so the pieces are a pure function of the input and their areas add up
 * to the polygon's exactly.
 */
#include "decompose.h"
#include "envelope.h"

#define MIN_EDGE PG_LINEAR_SLOP /* as pg_geometry_polygon: shorter edges are degenerate */

/* (b - a) x (c - a), exact: |.| < 2^56 for coordinates within 2^26 raw. */
static int64_t cross3(pg_vec2 a, pg_vec2 b, pg_vec2 c)
{
    return ((int64_t)b.x - a.x) * ((int64_t)c.y - a.y) - ((int64_t)b.y - a.y) * ((int64_t)c.x - a.x);
}

static int sign64(int64_t v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

/* p, on the line through a and b, lies within their bounding box. */
static int within(pg_vec2 a, pg_vec2 b, pg_vec2 p)
{
    return p.x >= (a.x < b.x ? a.x : b.x) && p.x <= (a.x > b.x ? a.x : b.x) && p.y >= (a.y < b.y ? a.y : b.y) &&
           p.y <= (a.y > b.y ? a.y : b.y);
}

/* Do the closed segments a1-a2 and b1-b2 share a point? */
static int segments_touch(pg_vec2 a1, pg_vec2 a2, pg_vec2 b1, pg_vec2 b2)
{
    int o1 = sign64(cross3(a1, a2, b1)), o2 = sign64(cross3(a1, a2, b2));
    int o3 = sign64(cross3(b1, b2, a1)), o4 = sign64(cross3(b1, b2, a2));
    if (o1 * o2 < 0 && o3 * o4 < 0) return 1;
    return (o1 == 0 && within(a1, a2, b1)) || (o2 == 0 && within(a1, a2, b2)) || (o3 == 0 && within(b1, b2, a1)) ||
           (o4 == 0 && within(b1, b2, a2));
}

static void say_vertex(pg__text *t, const char *before, int32_t i, const pg_vec2 *v)
{
    pg__text_put(t, before);
    pg__text_i64(t, i);
    pg__text_put(t, " (");
    pg__text_fix(t, v[i].x);
    pg__text_put(t, ", ");
    pg__text_fix(t, v[i].y);
    pg__text_put(t, ")");
}

static void say_edge(pg__text *t, const char *before, int32_t i, int32_t n)
{
    pg__text_put(t, before);
    pg__text_i64(t, i);
    pg__text_put(t, " (vertex ");
    pg__text_i64(t, i);
    pg__text_put(t, " to ");
    pg__text_i64(t, (i + 1) % n);
    pg__text_put(t, ")");
}

static pg_result validate(const pg_vec2 *v, int32_t n, int64_t *area2, pg__text *why)
{
    int32_t i, j;
    if (n < 3 || n > PG_CONCAVE_MAX_VERTICES) {
        pg__text_put(why, "a concave polygon has 3..64 vertices, got ");
        pg__text_i64(why, n);
        return PG_ERR_INVALID_ARGUMENT;
    }
    for (i = 0; i < n; ++i) {
        if (v[i].x < -PG_ENV_MAX_STATIC_REACH || v[i].x > PG_ENV_MAX_STATIC_REACH || v[i].y < -PG_ENV_MAX_STATIC_REACH ||
            v[i].y > PG_ENV_MAX_STATIC_REACH) {
            say_vertex(why, "vertex ", i, v);
            pg__text_put(why, " lies beyond 1000 m of the origin");
            return PG_ERR_ENVELOPE;
        }
    }
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (v[i].x == v[j].x && v[i].y == v[j].y) {
                say_vertex(why, "vertex ", j, v);
                pg__text_put(why, " repeats vertex ");
                pg__text_i64(why, i);
                pg__text_put(why, ": remove one");
                return PG_ERR_DEGENERATE;
            }
    for (i = 0; i < n; ++i) {
        pg_vec2 a = v[i], b = v[(i + 1) % n];
        int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y;
        if (dx * dx + dy * dy < (int64_t)MIN_EDGE * MIN_EDGE) {
            say_edge(why, "edge ", i, n);
            pg__text_put(why, " is shorter than 0.005 m");
            return PG_ERR_DEGENERATE;
        }
    }
    for (i = 0; i < n; ++i)
        if (cross3(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == 0) {
            say_vertex(why, "vertex ", i, v);
            pg__text_put(why, " lies on the line through its neighbours (collinear): remove it");
            return PG_ERR_DEGENERATE;
        }
    for (i = 0; i < n; ++i)
        for (j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue; /* adjacent through vertex 0 */
            if (segments_touch(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) {
                say_edge(why, "edges ", i, n);
                say_edge(why, " and ", j, n);
                pg__text_put(why, " cross or touch: the polygon must be simple (self-intersecting)");
                return PG_ERR_INVALID_ARGUMENT;
            }
        }
    *area2 = 0;
    for (i = 1; i + 1 < n; ++i) *area2 += cross3(v[0], v[i], v[i + 1]); /* |.| < 64 * 2^56 */
    if (*area2 == 0) {
        pg__text_put(why, "the polygon has zero area");
        return PG_ERR_DEGENERATE;
    }
    return PG_OK;
}

/* ---- ear clipping ---------------------------------------------------------------------- */

/* Is position k of the remaining cycle an ear? ord maps positions to input indices. */
static int is_ear(const pg_vec2 *v, const uint8_t *ord, const uint8_t *prv, const uint8_t *nxt, int k)
{
    int p = prv[k], q = nxt[k], r;
    pg_vec2 a = v[ord[p]], b = v[ord[k]], c = v[ord[q]];
    for (r = nxt[q]; r != p; r = nxt[r]) {
        pg_vec2 x = v[ord[r]];
        if (cross3(a, b, x) >= 0 && cross3(b, c, x) >= 0 && cross3(c, a, x) >= 0) return 0;
    }
    return 1;
}

static int64_t dist2(pg_vec2 a, pg_vec2 b)
{
    int64_t dx = (int64_t)b.x - a.x, dy = (int64_t)b.y - a.y;
    return dx * dx + dy * dy; /* < 2^57 */
}

/* The triangle's smallest height (raw units, rounded down): twice its area over its
 * longest side; -1 when it is not strictly convex at b. */
static int64_t thickness(pg_vec2 a, pg_vec2 b, pg_vec2 c)
{
    int64_t twice = cross3(a, b, c), l2 = dist2(a, b), m;
    if (twice <= 0) return -1;
    m = dist2(b, c);
    l2 = m > l2 ? m : l2;
    m = dist2(c, a);
    l2 = m > l2 ? m : l2;
    return twice / (int64_t)pg_isqrt64((uint64_t)l2); /* the longest side is >= 1 raw unit */
}

static void put_triangle(pg__decomposition *out, uint8_t a, uint8_t b, uint8_t c)
{
    pg__piece *p = &out->pieces[out->count++];
    p->count = 3;
    p->index[0] = a;
    p->index[1] = b;
    p->index[2] = c;
}

/* Each round clips the thickest ear (the ear whose triangle has the largest smallest
 * height; on ties the first from position 0, counter-clockwise): thin ears, which a
 * first-found rule takes along a gently curved edge, are left for last, when merging
 * absorbs them. */
static pg_result clip_ears(const pg_vec2 *v, int32_t n, int64_t area2, pg__decomposition *out, pg__text *why)
{
    uint8_t ord[PG_CONCAVE_MAX_VERTICES], prv[PG_CONCAVE_MAX_VERTICES], nxt[PG_CONCAVE_MAX_VERTICES];
    int32_t k, remaining = n, first = 0;
    if (n < 3 || n > PG_CONCAVE_MAX_VERTICES) { /* checked by the caller; kept so every index below is set */
        pg__text_put(why, "a polygon needs 3 to 64 vertices");
        return PG_ERR_INVALID_ARGUMENT;
    }
    for (k = 0; k < n; ++k) {
        ord[k] = (uint8_t)(area2 > 0 ? k : (n - k) % n); /* counter-clockwise from vertex 0 */
        prv[k] = (uint8_t)((k + n - 1) % n);
        nxt[k] = (uint8_t)((k + 1) % n);
    }
    out->count = 0;
    while (remaining > 3) {
        int32_t best = -1, i;
        int64_t best_t = -1;
        for (i = 0, k = first; i < remaining; ++i, k = nxt[k]) {
            int64_t t = thickness(v[ord[prv[k]]], v[ord[k]], v[ord[nxt[k]]]);
            if (t > best_t && is_ear(v, ord, prv, nxt, k)) {
                best_t = t;
                best = k;
            }
        }
        if (best < 0) { /* a simple polygon always has an ear */
            pg__text_put(why, "no ear found (the polygon is not simple)");
            return PG_ERR_INVALID_ARGUMENT;
        }
        {
            int p = prv[best], q = nxt[best];
            put_triangle(out, ord[p], ord[best], ord[q]);
            nxt[p] = (uint8_t)q;
            prv[q] = (uint8_t)p;
            if (best == first) first = q;
            --remaining;
        }
    }
    put_triangle(out, ord[prv[first]], ord[first], ord[nxt[first]]);
    return PG_OK;
}

/* ---- merging ------------------------------------------------------------------------------ */

/* The union of pieces a and b if they share an edge, as a vertex cycle in u (up to
 * 2 PG_MAX_VERTICES - 2); returns its count, 0 when they share none. */
static int unite(const pg__piece *a, const pg__piece *b, uint8_t *u)
{
    int i, j, k, m = 0;
    for (i = 0; i < a->count; ++i) {
        uint8_t x = a->index[i], y = a->index[(i + 1) % a->count];
        for (j = 0; j < b->count; ++j) {
            if (b->index[j] != y || b->index[(j + 1) % b->count] != x) continue;
            for (k = 1; k <= a->count; ++k) u[m++] = a->index[(i + k) % a->count]; /* y .. x */
            for (k = 2; k < b->count; ++k) u[m++] = b->index[(j + k) % b->count];  /* after x .. before y */
            return m;
        }
    }
    return 0;
}

static int strictly_convex(const pg_vec2 *v, const uint8_t *u, int m)
{
    int k;
    for (k = 0; k < m; ++k)
        if (cross3(v[u[(k + m - 1) % m]], v[u[k]], v[u[(k + 1) % m]]) <= 0) return 0;
    return 1;
}

static void set_piece(pg__piece *p, const uint8_t *u, int from, int count, int m)
{
    int k;
    p->count = (uint8_t)count;
    for (k = 0; k < PG_MAX_VERTICES; ++k) p->index[k] = (uint8_t)(k < count ? u[(from + k) % m] : 0u);
}

static void drop_piece(pg__decomposition *d, int b)
{
    int k;
    for (k = b; k + 1 < d->count; ++k) d->pieces[k] = d->pieces[k + 1];
    --d->count;
}

/* Hertel-Mehlhorn: merge pieces while a union stays convex and small enough. */
static void merge_pieces(const pg_vec2 *v, pg__decomposition *d)
{
    int a = 0, b;
    uint8_t u[2 * PG_MAX_VERTICES];
    while (a < d->count) {
        int merged = 0;
        for (b = a + 1; b < d->count && !merged; ++b) {
            int m = unite(&d->pieces[a], &d->pieces[b], u);
            if (m == 0 || m > PG_MAX_VERTICES || !strictly_convex(v, u, m)) continue;
            set_piece(&d->pieces[a], u, 0, m, m);
            drop_piece(d, b);
            merged = 1;
        }
        if (!merged) ++a; /* else try a again with its new edges */
    }
}

/* A piece pg_geometry_polygon accepts as it is: counter-clockwise (it would turn a
 * clockwise one round), convex, edges of 0.005 m, 0.01 m thick. */
static int piece_ok(const pg_vec2 *v, const pg__piece *p)
{
    pg_geometry g;
    pg_vec2 w[PG_MAX_VERTICES];
    int64_t twice = 0;
    int k;
    for (k = 0; k < p->count; ++k) w[k] = v[p->index[k]];
    for (k = 1; k + 1 < p->count; ++k) twice += cross3(w[0], w[k], w[k + 1]);
    return twice > 0 && pg_geometry_polygon(w, p->count, &g) == PG_OK;
}

/* Piece a is refused (a sliver): merge it into a neighbour, or split their union (which
 * need not be convex) again along another diagonal where both parts are valid: two
 * convex counter-clockwise parts of the union's cycle tile it, their diagonal inside.
 * Returns whether it did. */
static int repair(const pg_vec2 *v, pg__decomposition *d, int a)
{
    uint8_t u[2 * PG_MAX_VERTICES];
    int b, i, len;
    for (b = 0; b < d->count; ++b) {
        int m = b == a ? 0 : unite(&d->pieces[a], &d->pieces[b], u);
        if (m == 0) continue;
        if (m <= PG_MAX_VERTICES && strictly_convex(v, u, m)) {
            pg__piece whole;
            set_piece(&whole, u, 0, m, m);
            if (!piece_ok(v, &whole)) continue;
            d->pieces[a] = whole;
            drop_piece(d, b);
            return 1;
        }
        /* two parts u[i .. i+len] and u[i+len .. i+m], sharing the diagonal */
        for (i = 0; i < m; ++i)
            for (len = 2; len <= m - 2; ++len) {
                pg__piece p1, p2;
                if (len + 1 > PG_MAX_VERTICES || m - len + 1 > PG_MAX_VERTICES) continue;
                set_piece(&p1, u, i, len + 1, m);
                set_piece(&p2, u, i + len, m - len + 1, m);
                if (!piece_ok(v, &p1) || !piece_ok(v, &p2)) continue;
                d->pieces[a] = p1;
                d->pieces[b] = p2;
                return 1;
            }
    }
    return 0;
}

pg_result pg__decompose(const pg_vec2 *v, int32_t n, pg__decomposition *out, pg__text *why)
{
    int64_t area2 = 0;
    int a, k;
    pg_result r;
    out->count = 0;
    if (v == NULL) {
        pg__text_put(why, "vertices is NULL");
        return PG_ERR_NULL;
    }
    r = validate(v, n, &area2, why);
    if (r == PG_OK) r = clip_ears(v, n, area2, out, why);
    if (r != PG_OK) {
        out->count = 0;
        return r;
    }
    merge_pieces(v, out);
    /* each repair makes one refused piece valid and no valid piece invalid: it ends */
    for (a = 0; a < out->count;) {
        if (piece_ok(v, &out->pieces[a]) || !repair(v, out, a)) ++a;
        else a = 0;
    }
    for (a = 0; a < out->count; ++a) {
        const pg__piece *p = &out->pieces[a];
        if (piece_ok(v, p)) continue;
        pg__text_put(why, "the polygon is thinner than 0.01 m (or has two vertices closer than 0.005 m) in the piece between vertices");
        for (k = 0; k < p->count; ++k) {
            pg__text_put(why, k == 0 ? " " : ", ");
            pg__text_i64(why, p->index[k]);
        }
        pg__text_put(why, ": widen it or remove a vertex");
        out->count = 0;
        return PG_ERR_ENVELOPE;
    }
    return PG_OK;
}

void pg__piece_geometry(const pg_vec2 *v, const pg__piece *p, pg_geometry *out)
{
    pg_vec2 w[PG_MAX_VERTICES];
    int k;
    for (k = 0; k < p->count; ++k) w[k] = v[p->index[k]];
    (void)pg_geometry_polygon(w, p->count, out);
}
