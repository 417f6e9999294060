/* mass.c — mass, centre of mass and rotational inertia of geometries and compounds.
 *
 * METHOD
 *   Every shape contributes four exact moments about one reference point O (the rounded
 *   midpoint of the bounding box of all vertices): area, first moment (x, y) and polar
 *   second moment. They are held as integers in multi-word two's complement (pg__big,
 *   384 bits; enough for ANY int32 coordinates, radii and densities, see the bounds
 *   below), scaled by 24 * 2^61 so that every term is an integer:
 *     lengths   in u = 2^-32 m (Q16.16 inputs times 2^16, relative to O)
 *     polygon   triangle fan about O: with c = a x b,
 *               24 area = 12 c, 24 first = 4 c (a + b), 24 second = 2 c (a.a + a.b + b.b)
 *     circle    area = pi r^2,  I_centre = pi r^2 r^2/2
 *     capsule   with L = |q - p|, s = p + q (= 2 centre): the circle at the centre plus
 *               the terms with L (so a capsule of length 0 is that circle, bit for bit)
 *               area = 2 r L + pi r^2,  I_centre = r L^3/6 + 2 r^3 L + pi r^2 (r^2/2 + L^2/4)
 *               (the rectangle L x 2r plus the two half discs moved by the parallel axis
 *               theorem about their centroids at L/2 + 4r/(3 pi); that pi cancels, so
 *               only the disc's own pi r^2 terms remain). A build without capsules
 *               (PG_CONFIG_SHAPES) compiles the circle's formula only.
 *   pi enters as round(pi 2^61) and L as round(L 2^61) (integer square root of the
 *   exact L^2 2^122): both relative errors are below 2^-62, far below every output LSB.
 *   Each output is then rounded ONCE (nearest, ties away from zero) by an exact
 *   multi-word division:
 *     mass     Q32.32  = M0 / (3 2^112)                 (density-weighted moments M)
 *     area     Q32.32  = A0 / (3 2^96)                  (unit-weight moments A)
 *     centre   Q16.16  = O + M1 / (2^16 M0)             (absolute, so mirror-symmetric)
 *     inertia  Q28.36  = (M2 - 2 M1.d + M0 |d|^2) / (3 2^172), d = centre - O
 *   The inertia is about the STORED (rounded) centre, as mass.h says; it differs from
 *   the inertia about the exact centre of mass by mass * |rounding|^2 <= mass * 2^-33 m^2.
 *   Polygons need not be trusted for their `centroid` field, and a clockwise polygon is
 *   accepted (its winding is reversed first).
 *
 * COMPOUNDS: OVERLAPS OF POLYGONS
 *   With density f(x) = rho_min{i : x in P_i}, expanding the indicator
 *   1[x in P_i and in no P_j, j < i] gives
 *       f = sum over nonempty subsets S of (-1)^(|S|-1) rho_max(S) 1[x in intersection S],
 *   so each nonzero intersection is added with that weight (depth-first over subsets in
 *   index order; an empty or zero-area intersection prunes all its supersets). The
 *   intersections are found by Sutherland-Hodgman clipping (integer side tests, exact).
 *   Each vertex of an intersection is an original vertex or the crossing of two
 *   original edge lines; the clipper remembers which line every edge lies on, and a
 *   crossing is computed from the two original lines (exact rational, rounded once to
 *   u = 2^-32 m, not to Q16.16). This is the only inexact step: each such vertex is
 *   within 2^-32.5 m of the true one, which moves an area by less than
 *   perimeter * 2^-32.5 m^2 (0.71 LSB of the Q32.32 area per metre of the intersection's
 *   perimeter; the tests hold the results to that bound). The result does not
 *   depend on the order of clipping, and mirrored inputs give exactly mirrored vertices.
 *
 * LIMITS AND CONVENTIONS (documented choices)
 *   - Only the first PG__MASS_MAX_OVERLAP (8) polygons of a compound (count >= 3, in index
 *     order) take part in the overlap handling; further polygons are added as if they
 *     overlapped nothing. Circles, capsules and segments never do (mass.h).
 *   - Outputs saturate: mass and area to INT64_MAX (2^31 kg / 2^31 m^2), inertia to
 *     INT64_MAX (about 1.34e8 kg m^2 in Q28.36: a 50 m x 50 m box at density 100 kg/m^2,
 *     1.04e8, still fits; a 60 m box at that density saturates), the centre to
 *     +-PG_FIX_MAX.
 *   - Negative densities and negative radii count as 0. The radius of a polygon
 *     (count >= 3) is ignored: the mass is that of the bare polygon. A geometry with
 *     count outside 1..PG_MAX_POLYGON_VERTICES, or a NULL entry, is skipped.
 *   - Cost: set-up time, not for inner loops. A single shape takes microseconds; eight
 *     mutually overlapping octagons (255 nonempty intersections) a few tens of
 *     milliseconds on a desktop x86-64, because the subset search recomputes each
 *     subset's intersection from its polygons: it keeps the subset's indices, not one
 *     clipped polygon per depth, so that its memory is small. Memory: the caller's work
 *     space of pg__mass_work_bytes() (6144 bytes) and a few KB of stack (the stack
 *     table of docs/embedded.md); no recursion, no heap.
 *   - Without mass (density 0) the centre is the centroid of the area; without area too
 *     (segments, points, degenerate polygons) it is the mean of the geometries' vertex
 *     averages (the midpoint of a segment). Mass and inertia are then 0.
 *
 * BOUNDS (why 384 bits suffice for any legal input): |coordinate - O| <= 2^32 LSB =
 *   2^48 u, radius <= 2^47 u, so a fan term's c <= 2^97 and c (a.a + a.b + b.b) < 2^196;
 *   times 2 * 2^61, times density < 2^31, over <= 72 edges of a clipped polygon and
 *   <= 255 subsets: one compound of 8 polygons stays below 2^305 (a capsule below
 *   2^293); M1.d and M0 |d|^2 in the inertia are of the same size, and the largest
 *   divisor shifted for the long division, 2^16 M0 2^63, is below 2^300. Summing over
 *   more geometries adds log2(count) < 31 bits: still below the sign bit, 2^383.
 */
#include "mass.h"
#include "pogon/config.h" /* PG_CONFIG_SHAPES */

/* Kept out of line so that the stages of a compound, which run one after another, do
 * not share one stack frame as large as all of them together. */
#if defined(__GNUC__) || defined(__clang__)
#define PG__OUT_OF_LINE __attribute__((noinline))
#else
#define PG__OUT_OF_LINE
#endif

/* ---- multi-word signed integers --------------------------------------------------- */

#define PG__BIG_LIMBS 12 /* 384 bits */

typedef struct pg__big { uint32_t w[PG__BIG_LIMBS]; } pg__big; /* two's complement, little endian */

static pg__big pg__big_i64(int64_t v)
{
    pg__big r;
    uint64_t u = (uint64_t)v; /* modulo 2^64: well defined */
    uint32_t ext = v < 0 ? 0xFFFFFFFFu : 0u;
    int i;
    r.w[0] = (uint32_t)(u & 0xFFFFFFFFu);
    r.w[1] = (uint32_t)(u >> 32);
    for (i = 2; i < PG__BIG_LIMBS; ++i) r.w[i] = ext;
    return r;
}

static int pg__big_is_neg(const pg__big *a) { return (a->w[PG__BIG_LIMBS - 1] >> 31) != 0; }

static int pg__big_is_zero(const pg__big *a)
{
    int i;
    for (i = 0; i < PG__BIG_LIMBS; ++i)
        if (a->w[i] != 0) return 0;
    return 1;
}

/* Sign: -1, 0 or 1. */
static int pg__big_sign(const pg__big *a) { return pg__big_is_neg(a) ? -1 : pg__big_is_zero(a) ? 0 : 1; }

static pg__big pg__big_add(pg__big a, pg__big b)
{
    pg__big r;
    uint64_t carry = 0;
    int i;
    for (i = 0; i < PG__BIG_LIMBS; ++i) {
        uint64_t s = (uint64_t)a.w[i] + b.w[i] + carry;
        r.w[i] = (uint32_t)(s & 0xFFFFFFFFu);
        carry = s >> 32;
    }
    return r;
}

static pg__big pg__big_neg(pg__big a)
{
    uint64_t carry = 1;
    int i;
    for (i = 0; i < PG__BIG_LIMBS; ++i) {
        uint64_t s = (uint64_t)(uint32_t)~a.w[i] + carry;
        a.w[i] = (uint32_t)(s & 0xFFFFFFFFu);
        carry = s >> 32;
    }
    return a;
}

static pg__big pg__big_sub(pg__big a, pg__big b) { return pg__big_add(a, pg__big_neg(b)); }

/* The product modulo 2^384, which is the signed product whenever that fits (it always
 * does here, see BOUNDS). */
static pg__big pg__big_mul(pg__big a, pg__big b)
{
    pg__big r;
    int i, j;
    for (i = 0; i < PG__BIG_LIMBS; ++i) r.w[i] = 0;
    for (i = 0; i < PG__BIG_LIMBS; ++i) {
        uint64_t carry = 0;
        if (a.w[i] == 0) continue;
        for (j = 0; i + j < PG__BIG_LIMBS; ++j) {
            uint64_t t = (uint64_t)a.w[i] * b.w[j] + r.w[i + j] + carry; /* < 2^64 */
            r.w[i + j] = (uint32_t)(t & 0xFFFFFFFFu);
            carry = t >> 32;
        }
    }
    return r;
}

/* |v| as an unsigned number (INT64_MIN included) */
static uint64_t pg__u64_abs(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

/* a k modulo 2^384, as pg__big_mul(a, pg__big_i64(k)) gives it: a |k| by a 2-limb
 * multiplier, negated when k < 0 (both are the product modulo 2^384). A 2-limb loop
 * instead of a 12-limb one, and no 48-byte copy of k on the stack. */
static pg__big pg__big_mul_i64(pg__big a, int64_t k)
{
    pg__big r;
    uint64_t m = pg__u64_abs(k);
    uint32_t b[2];
    int i, j;
    b[0] = (uint32_t)(m & 0xFFFFFFFFu);
    b[1] = (uint32_t)(m >> 32);
    for (i = 0; i < PG__BIG_LIMBS; ++i) r.w[i] = 0;
    for (j = 0; j < 2; ++j) {
        uint64_t carry = 0;
        if (b[j] == 0) continue;
        for (i = 0; i + j < PG__BIG_LIMBS; ++i) {
            uint64_t t = (uint64_t)a.w[i] * b[j] + r.w[i + j] + carry; /* < 2^64 */
            r.w[i + j] = (uint32_t)(t & 0xFFFFFFFFu);
            carry = t >> 32;
        }
    }
    return k < 0 ? pg__big_neg(r) : r;
}

/* a b exactly (|a b| <= 2^126), sign-extended to 384 bits: the 4-limb product of the
 * magnitudes, negated when the signs differ. */
static pg__big pg__big_mul2(int64_t a, int64_t b)
{
    pg__big r;
    uint64_t ma = pg__u64_abs(a), mb = pg__u64_abs(b);
    uint32_t x[2], y[2];
    int i, j;
    x[0] = (uint32_t)(ma & 0xFFFFFFFFu);
    x[1] = (uint32_t)(ma >> 32);
    y[0] = (uint32_t)(mb & 0xFFFFFFFFu);
    y[1] = (uint32_t)(mb >> 32);
    for (i = 0; i < PG__BIG_LIMBS; ++i) r.w[i] = 0;
    for (i = 0; i < 2; ++i) {
        uint64_t carry = 0;
        for (j = 0; j < 2; ++j) {
            uint64_t t = (uint64_t)x[i] * y[j] + r.w[i + j] + carry; /* < 2^64 */
            r.w[i + j] = (uint32_t)(t & 0xFFFFFFFFu);
            carry = t >> 32;
        }
        r.w[i + 2] = (uint32_t)carry;
    }
    return (a < 0) != (b < 0) ? pg__big_neg(r) : r;
}

/* a * 2^n, 0 <= n < 384 (bits shifted out are lost). */
static pg__big pg__big_shl(pg__big a, int n)
{
    pg__big r;
    int limbs = n / 32, bits = n % 32, i;
    for (i = PG__BIG_LIMBS - 1; i >= 0; --i) {
        uint32_t hi = i - limbs >= 0 ? a.w[i - limbs] : 0u;
        uint32_t lo = i - limbs - 1 >= 0 ? a.w[i - limbs - 1] : 0u;
        r.w[i] = bits == 0 ? hi : (uint32_t)((hi << bits) | (lo >> (32 - bits)));
    }
    return r;
}

/* Logical shift right by one (used on nonnegative values only). */
static pg__big pg__big_shr1(pg__big a)
{
    int i;
    for (i = 0; i < PG__BIG_LIMBS - 1; ++i) a.w[i] = (a.w[i] >> 1) | (a.w[i + 1] << 31);
    a.w[PG__BIG_LIMBS - 1] >>= 1;
    return a;
}

/* Compare as unsigned (equal to the signed order for nonnegative values). */
static int pg__big_ucmp(const pg__big *a, const pg__big *b)
{
    int i;
    for (i = PG__BIG_LIMBS - 1; i >= 0; --i)
        if (a->w[i] != b->w[i]) return a->w[i] < b->w[i] ? -1 : 1;
    return 0;
}

/* Number of significant bits of a nonnegative value. */
static int pg__big_bitlen(const pg__big *a)
{
    int i, b;
    for (i = PG__BIG_LIMBS - 1; i >= 0; --i)
        if (a->w[i] != 0) {
            for (b = 31; !((a->w[i] >> b) & 1u); --b) {}
            return i * 32 + b + 1;
        }
    return 0;
}

/* round(num / den), nearest, ties away from zero, saturated to +-INT64_MAX. den == 0
 * saturates by the sign of num (0 for 0). Requires bitlen(|den|) <= 384 - 65. */
PG__OUT_OF_LINE static int64_t pg__big_div_round(pg__big num, pg__big den)
{
    int negative, k;
    pg__big d;
    uint64_t q = 0;
    if (pg__big_is_neg(&den)) { num = pg__big_neg(num); den = pg__big_neg(den); }
    negative = pg__big_is_neg(&num);
    if (negative) num = pg__big_neg(num);
    if (pg__big_is_zero(&den)) return pg__big_is_zero(&num) ? 0 : negative ? -INT64_MAX : INT64_MAX;
    d = pg__big_shl(den, 63);
    if (pg__big_ucmp(&num, &d) >= 0) return negative ? -INT64_MAX : INT64_MAX;
    for (k = 62; k >= 0; --k) {
        d = pg__big_shr1(d);
        if (pg__big_ucmp(&num, &d) >= 0) {
            num = pg__big_sub(num, d);
            q |= (uint64_t)1 << k;
        }
    }
    /* remainder num < den: round up when 2 num >= den */
    num = pg__big_shl(num, 1);
    if (pg__big_ucmp(&num, &den) >= 0) ++q;
    if (q > (uint64_t)INT64_MAX) return negative ? -INT64_MAX : INT64_MAX;
    return negative ? -(int64_t)q : (int64_t)q;
}

/* round(sqrt(n)) for n >= 0 (there are no ties for integers). */
static pg__big pg__big_isqrt_round(pg__big n)
{
    pg__big res = pg__big_i64(0), bit, t;
    int len = pg__big_bitlen(&n);
    if (len == 0) return res;
    bit = pg__big_shl(pg__big_i64(1), (len - 1) & ~1);
    while (!pg__big_is_zero(&bit)) {
        t = pg__big_add(res, bit);
        if (pg__big_ucmp(&n, &t) >= 0) {
            n = pg__big_sub(n, t);
            res = pg__big_add(pg__big_shr1(res), bit);
        } else {
            res = pg__big_shr1(res);
        }
        bit = pg__big_shr1(pg__big_shr1(bit));
    }
    /* now n = n0 - res^2; round up when n0 > res^2 + res */
    if (pg__big_ucmp(&n, &res) > 0) res = pg__big_add(res, pg__big_i64(1));
    return res;
}

/* ---- moments ---------------------------------------------------------------------- */

/* round(pi 2^61) */
#define PG__PI_Q61 INT64_C(7244019458077122842)
#define PG__MASS_MAX_OVERLAP 8
/* Clipping a convex n-gon by a half-plane gives at most n + 1 vertices; the deepest
 * intersection starts from 8 vertices and is clipped by 7 polygons of 8 edges. */
#define PG__CLIP_MAX (PG_MAX_POLYGON_VERTICES + (PG__MASS_MAX_OVERLAP - 1) * PG_MAX_POLYGON_VERTICES + 8)

/* A point in u = 2^-32 m relative to the reference O. */
typedef struct pg__pt { int64_t x, y; } pg__pt;

/* Area, first moment and polar second moment about O, times 24 * 2^61, in powers of u. */
typedef struct pg__moments { pg__big m0, m1x, m1y, m2; } pg__moments;

static void pg__moments_zero(pg__moments *m)
{
    m->m0 = m->m1x = m->m1y = m->m2 = pg__big_i64(0);
}

/* acc += w * m */
static void pg__moments_add(pg__moments *acc, const pg__moments *m, int64_t w)
{
    pg__big bw = pg__big_i64(w);
    acc->m0 = pg__big_add(acc->m0, pg__big_mul(m->m0, bw));
    acc->m1x = pg__big_add(acc->m1x, pg__big_mul(m->m1x, bw));
    acc->m1y = pg__big_add(acc->m1y, pg__big_mul(m->m1y, bw));
    acc->m2 = pg__big_add(acc->m2, pg__big_mul(m->m2, bw));
}

/* Twice the signed area (sum of the fan's cross products), in u^2. */
PG__OUT_OF_LINE static pg__big pg__poly_cross_sum(const pg__pt *v, int n)
{
    pg__big s = pg__big_i64(0);
    int i;
    for (i = 0; i < n; ++i) {
        const pg__pt *a = &v[i], *b = &v[(i + 1) % n];
        s = pg__big_add(s, pg__big_sub(pg__big_mul2(a->x, b->y), pg__big_mul2(a->y, b->x)));
    }
    return s;
}

/* One fan triangle O, a, b of a polygon: adds its area and moments (not yet shifted by
 * 2^61) to out. Apart from pg__poly_moments, so the temporaries of one edge are on the
 * stack only while it runs. */
PG__OUT_OF_LINE static void pg__fan_add(const pg__pt *a, const pg__pt *b, pg__moments *out)
{
    /* one product per statement: the sums are exact, so their order does not matter,
     * and few temporaries are live at once */
    pg__big c = pg__big_sub(pg__big_mul2(a->x, b->y), pg__big_mul2(a->y, b->x)), q = pg__big_mul2(a->x, a->x);
    q = pg__big_add(q, pg__big_mul2(a->x, b->x));
    q = pg__big_add(q, pg__big_mul2(b->x, b->x));
    q = pg__big_add(q, pg__big_mul2(a->y, a->y));
    q = pg__big_add(q, pg__big_mul2(a->y, b->y));
    q = pg__big_add(q, pg__big_mul2(b->y, b->y));
    out->m0 = pg__big_add(out->m0, pg__big_mul_i64(c, 12));
    out->m1x = pg__big_add(out->m1x, pg__big_mul_i64(c, 4 * (a->x + b->x)));
    out->m1y = pg__big_add(out->m1y, pg__big_mul_i64(c, 4 * (a->y + b->y)));
    q = pg__big_mul(c, q);
    out->m2 = pg__big_add(out->m2, pg__big_shl(q, 1));
}

PG__OUT_OF_LINE static void pg__poly_moments(const pg__pt *v, int n, pg__moments *out)
{
    int i;
    pg__moments_zero(out);
    for (i = 0; i < n; ++i) pg__fan_add(&v[i], &v[(i + 1) % n], out);
    out->m0 = pg__big_shl(out->m0, 61);
    out->m1x = pg__big_shl(out->m1x, 61);
    out->m1y = pg__big_shl(out->m1y, 61);
    out->m2 = pg__big_shl(out->m2, 61);
}

/* Circle of centre c and radius r (u): 24 area = 24 pi r^2, 24 first = 24 area c,
 * 24 second = 24 area (r^2/2 + |c|^2) = pi r^2 (12 r^2 + 24 |c|^2). A capsule is this
 * circle at its midpoint plus the terms of its length (pg__capsule_moments), so a
 * circle's moments are the same integers as a capsule of length 0 gives, and a build
 * without capsules keeps no square root and no length terms. */
PG__OUT_OF_LINE static void pg__circle_moments(pg__pt c, int64_t r, pg__moments *out)
{
    pg__big r2 = pg__big_mul2(r, r);
    pg__big pir2 = pg__big_mul_i64(r2, PG__PI_Q61); /* pi r^2 2^61 */
    pg__big c2 = pg__big_add(pg__big_mul2(c.x, c.x), pg__big_mul2(c.y, c.y));
    pg__big spread = pg__big_add(pg__big_mul_i64(r2, 12), pg__big_mul_i64(c2, 24)); /* 12 r^2 + 24 |c|^2 */
    out->m0 = pg__big_mul_i64(pir2, 24);
    out->m1x = pg__big_mul_i64(pir2, 24 * c.x);
    out->m1y = pg__big_mul_i64(pir2, 24 * c.y);
    out->m2 = pg__big_mul(pir2, spread);
}

/* What a capsule's length adds to the second moment of the circle at its midpoint
 * (times 24 2^61). Of 24 I_centre = 4 r L^3 + 48 r^3 L + pi r^2 (12 r^2 + 6 L^2) and
 * 24 area |centre|^2 = (12 r L + 6 pi r^2) |s|^2 (s = p + q = 2 centre), the terms with
 * L: r L (4 L^2 + 48 r^2 + 12 |s|^2) + 6 pi r^2 L^2. Apart from pg__capsule_moments, so
 * that its temporaries and the square root's are not on the stack at once. */
PG__OUT_OF_LINE static pg__big pg__capsule_second_of_length(const pg__big *rl, const pg__big *l2, int64_t r, int64_t sx,
                                                           int64_t sy)
{
    /* one product per statement (exact sums, any order): few temporaries live at once */
    pg__big r2 = pg__big_mul2(r, r), t = pg__big_mul_i64(*l2, 4), u;
    t = pg__big_add(t, pg__big_mul_i64(r2, 48));
    u = pg__big_add(pg__big_mul2(sx, sx), pg__big_mul2(sy, sy));
    t = pg__big_add(t, pg__big_mul_i64(u, 12));
    t = pg__big_mul(*rl, t);
    u = pg__big_mul(pg__big_mul_i64(r2, PG__PI_Q61), *l2);
    return pg__big_add(t, pg__big_mul_i64(u, 6));
}

/* L 2^61 = round(sqrt(L^2 2^122)) for the capsule's L^2. */
PG__OUT_OF_LINE static pg__big pg__length_q61(const pg__big *l2) { return pg__big_isqrt_round(pg__big_shl(*l2, 122)); }

/* Capsule p..q of radius r (u): the circle at its midpoint, plus the rectangle 2 r x L
 * and what moving the two half discs apart adds. */
PG__OUT_OF_LINE static void pg__capsule_moments(pg__pt p, pg__pt q, int64_t r, pg__moments *out)
{
    int64_t dx = q.x - p.x, dy = q.y - p.y, sx = p.x + q.x, sy = p.y + q.y;
    pg__pt mid;
    pg__moments length;
    pg__big l2 = pg__big_add(pg__big_mul2(dx, dx), pg__big_mul2(dy, dy)); /* L^2 */
    pg__big rl = pg__big_mul_i64(pg__length_q61(&l2), r);                 /* r L 2^61 */
    /* exact: coordinates relative to O are multiples of 2^16 u, so sx and sy are even */
    mid.x = sx / 2;
    mid.y = sy / 2;
    pg__circle_moments(mid, r, out);
    /* the rectangle's 24 area = 48 r L, its first moment 24 area s / 2 */
    length.m0 = pg__big_mul_i64(rl, 48);
    length.m1x = pg__big_mul_i64(rl, 24 * sx);
    length.m1y = pg__big_mul_i64(rl, 24 * sy);
    length.m2 = pg__capsule_second_of_length(&rl, &l2, r, sx, sy);
    pg__moments_add(out, &length, 1);
}

/* ---- convex clipping ---------------------------------------------------------------- */

typedef struct pg__poly { pg__pt v[PG_MAX_POLYGON_VERTICES]; int n; int64_t rho; } pg__poly;

/* A line through two ORIGINAL points: edge k of polygon j, id = j * 8 + k. */
typedef struct pg__line { pg__pt a, b; } pg__line;

static pg__line pg__line_of(const pg__poly *polys, int id)
{
    const pg__poly *p = &polys[id / PG_MAX_POLYGON_VERTICES];
    int k = id % PG_MAX_POLYGON_VERTICES;
    pg__line l;
    l.a = p->v[k];
    l.b = p->v[(k + 1) % p->n];
    return l;
}

/* A vertex of a clipped polygon and the line of its outgoing edge (to the next vertex).
 * Every vertex of an intersection of convex polygons is an original vertex or the
 * crossing of two original edge lines, so new vertices are computed from the two
 * original lines alone: the result does not depend on the clipping order and rounding
 * errors do not accumulate. */
typedef struct pg__cv { pg__pt p; int line; } pg__cv;

/* The exact side of p relative to the directed line l (positive on the left). */
/* a b - c d, exactly. Out of line, like pg__ratio, so that the crossing below holds
 * only its named values on the stack, not every temporary of their products. */
PG__OUT_OF_LINE static pg__big pg__det2(int64_t a, int64_t b, int64_t c, int64_t d)
{
    return pg__big_sub(pg__big_mul2(a, b), pg__big_mul2(c, d));
}

/* round((p x - q y) / d), as pg__big_div_round rounds it. */
PG__OUT_OF_LINE static int64_t pg__ratio(const pg__big *p, int64_t x, const pg__big *q, int64_t y, const pg__big *d)
{
    return pg__big_div_round(pg__big_sub(pg__big_mul_i64(*p, x), pg__big_mul_i64(*q, y)), *d);
}

static pg__big pg__side(const pg__line *l, pg__pt p)
{
    return pg__det2(l->b.x - l->a.x, p.y - l->a.y, l->b.y - l->a.y, p.x - l->a.x);
}

/* Where the edge s..e (on the line es) crosses the line l (s and e strictly on opposite
 * sides). The crossing of the two lines is
 *   P = ((x1 y2 - y1 x2)(p3 - p4) - (p1 - p2)(x3 y4 - y3 x4)) / D,
 *   D = (x1 - x2)(y3 - y4) - (y1 - y2)(x3 - x4),
 * rounded once; the fraction is unchanged by swapping the lines or the two points of a
 * line, and mirrors exactly under x -> -x or y -> -y. Should the lines be (nearly)
 * parallel, so that their crossing is not on the edge, the edge's own crossing
 * (ds e - de s) / (ds - de) (ds, de the exact sides of s and e) is used. */
static pg__pt pg__crossing(const pg__line *es, const pg__line *l, pg__pt s, pg__pt e)
{
    pg__pt r;
    int64_t x12 = es->a.x - es->b.x, y12 = es->a.y - es->b.y, x34 = l->a.x - l->b.x, y34 = l->a.y - l->b.y;
    pg__big d = pg__det2(x12, y34, y12, x34), ds, de;
    if (!pg__big_is_zero(&d)) {
        pg__big c12 = pg__det2(es->a.x, es->b.y, es->a.y, es->b.x);
        pg__big c34 = pg__det2(l->a.x, l->b.y, l->a.y, l->b.x);
        r.x = pg__ratio(&c12, x34, &c34, x12, &d);
        r.y = pg__ratio(&c12, y34, &c34, y12, &d);
        if (r.x >= (s.x < e.x ? s.x : e.x) - 2 && r.x <= (s.x > e.x ? s.x : e.x) + 2 &&
            r.y >= (s.y < e.y ? s.y : e.y) - 2 && r.y <= (s.y > e.y ? s.y : e.y) + 2)
            return r;
    }
    ds = pg__side(l, s);
    de = pg__side(l, e);
    d = pg__big_sub(ds, de);
    r.x = pg__ratio(&ds, e.x, &de, s.x, &d);
    r.y = pg__ratio(&ds, e.y, &de, s.y, &d);
    return r;
}

/* Append a vertex; a repeat of the previous point merges into it (the merged vertex
 * leaves along the new vertex's line). */
static int pg__push(pg__cv *out, int n, pg__pt p, int line)
{
    if (n > 0 && out[n - 1].p.x == p.x && out[n - 1].p.y == p.y) {
        out[n - 1].line = line;
        return n;
    }
    if (n >= PG__CLIP_MAX) return n; /* cannot happen for convex input (see PG__CLIP_MAX) */
    out[n].p = p;
    out[n].line = line;
    return n + 1;
}

/* Sutherland-Hodgman: keep the part of in[0..n) on the left of (or on) the line lid.
 * Points exactly on the line stay as they are, so shared edges and corners stay exact. */
static int pg__clip(const pg__poly *polys, const pg__cv *in, int n, int lid, pg__cv *out)
{
    signed char sg[PG__CLIP_MAX];
    pg__line l = pg__line_of(polys, lid), es;
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        pg__big side = pg__side(&l, in[i].p);
        sg[i] = (signed char)pg__big_sign(&side);
    }
    for (i = 0; i < n; ++i) {
        int si = (i + n - 1) % n, ni = (i + 1) % n;
        const pg__cv *s = &in[si], *e = &in[i];
        if (sg[i] >= 0) {
            if (sg[si] < 0 && sg[i] > 0) {
                es = pg__line_of(polys, s->line);
                m = pg__push(out, m, pg__crossing(&es, &l, s->p, e->p), s->line);
            }
            /* a vertex on the line whose next neighbour is outside leaves along the line */
            m = pg__push(out, m, e->p, sg[i] == 0 && sg[ni] < 0 ? lid : e->line);
        } else if (sg[si] > 0) {
            es = pg__line_of(polys, s->line);
            m = pg__push(out, m, pg__crossing(&es, &l, s->p, e->p), lid);
        }
    }
    while (m > 1 && out[m - 1].p.x == out[0].p.x && out[m - 1].p.y == out[0].p.y) --m;
    return m;
}

/* ---- compound ----------------------------------------------------------------------- */

typedef struct pg__acc { pg__moments mass, area; } pg__acc;

/* The caller's work space (mass.h): the sums of the moments, the first polygons, two
 * clipping buffers and the points of the intersection being measured. */
typedef struct pg__mass_work {
    pg__acc acc;
    pg__poly polys[PG__MASS_MAX_OVERLAP];
    pg__cv buf[2][PG__CLIP_MAX];
    pg__pt pts[PG__CLIP_MAX];
} pg__mass_work;

/* PG__MASS_WORK_BYTES (mass.h) must hold it: a negative array size fails to compile */
typedef char pg__mass_work_fits[sizeof(pg__mass_work) <= PG__MASS_WORK_BYTES ? 1 : -1];

size_t pg__mass_work_bytes(void) { return sizeof(pg__mass_work); }

/* The intersection of the polygons subset[0..n) (ascending indices): polygon subset[0]
 * clipped by every edge line of the others in turn, stopping once fewer than 3 vertices
 * remain. Returns the vertex count and sets *out to the buffer holding them. The same
 * clips in the same order as when the subset was first reached, so the same vertices:
 * the subset search keeps only the indices of its current subset, not one clipped
 * polygon per depth, and recomputes (about 3 KiB of work space instead of 16). */
static int pg__intersect(pg__mass_work *w, const int *subset, int n, const pg__cv **out)
{
    const pg__poly *p0 = &w->polys[subset[0]];
    int i, t, k, m = p0->n, which = 1;
    for (i = 0; i < m; ++i) {
        w->buf[0][i].p = p0->v[i];
        w->buf[0][i].line = subset[0] * PG_MAX_POLYGON_VERTICES + i;
    }
    for (t = 1; t < n && m >= 3; ++t) {
        const pg__poly *pj = &w->polys[subset[t]];
        for (k = 0; k < pj->n && m >= 3; ++k) {
            m = pg__clip(w->polys, w->buf[which ^ 1], m, subset[t] * PG_MAX_POLYGON_VERTICES + k, w->buf[which]);
            which ^= 1;
        }
    }
    *out = w->buf[which ^ 1];
    return m;
}

/* Adds the intersection of every subset of two or more of the np polygons, with weight
 * (-1)^(|S|-1) rho_max(S), depth first in index order: a subset's supersets are visited
 * only when its intersection has area. Iterative, so the stack does not grow with the
 * depth. */
PG__OUT_OF_LINE static void pg__add_overlaps(pg__mass_work *w, int np, pg__acc *acc)
{
    int subset[PG__MASS_MAX_OVERLAP], next[PG__MASS_MAX_OVERLAP], k, i;
    for (k = 0; k < np - 1; ++k) {
        int depth = 0;
        subset[0] = k;
        next[0] = k + 1;
        while (depth >= 0) {
            /* sign = (-1)^(|S|-1) for S = subset[0..depth]; S gains j, so the sign flips */
            int64_t sign = (depth & 1) ? -1 : 1;
            const pg__cv *v;
            pg__moments g;
            pg__big x;
            int j = next[depth]++, m;
            if (j >= np) {
                --depth;
                continue;
            }
            subset[depth + 1] = j;
            m = pg__intersect(w, subset, depth + 2, &v);
            if (m < 3) continue;
            for (i = 0; i < m; ++i) w->pts[i] = v[i].p;
            x = pg__poly_cross_sum(w->pts, m);
            if (pg__big_sign(&x) <= 0) continue; /* zero area: so are all supersets */
            pg__poly_moments(w->pts, m, &g);
            /* j = max(S + j) gives the density */
            pg__moments_add(&acc->mass, &g, -sign * w->polys[j].rho);
            pg__moments_add(&acc->area, &g, -sign);
            if (j + 1 < np) { /* depth + 1 <= j < np <= PG__MASS_MAX_OVERLAP */
                ++depth;
                next[depth] = j + 1;
            }
        }
    }
}

/* The outputs from the accumulated moments about O = (ox, oy), each rounded once; the
 * fallback centre fbx, fby (sums of vertex averages times 840 over `valid` geometries)
 * when there is neither mass nor area. */
PG__OUT_OF_LINE static pg_mass_data pg__mass_result(const pg__acc *acc, int64_t ox, int64_t oy, pg__big fbx, pg__big fby, int valid)
{
    pg_mass_data md;
    md.inertia = 0;
    md.mass = pg__big_div_round(acc->mass.m0, pg__big_shl(pg__big_i64(3), 112));
    md.area = pg__big_div_round(acc->area.m0, pg__big_shl(pg__big_i64(3), 96));
    if (md.mass < 0) md.mass = 0;
    if (md.area < 0) md.area = 0;
    {
        const pg__moments *w = pg__big_sign(&acc->mass.m0) > 0 ? &acc->mass
                             : pg__big_sign(&acc->area.m0) > 0 ? &acc->area : NULL;
        int64_t cx, cy;
        if (w != NULL) {
            pg__big den = pg__big_shl(w->m0, 16);
            cx = pg__big_div_round(pg__big_add(pg__big_mul_i64(den, ox), w->m1x), den);
            cy = pg__big_div_round(pg__big_add(pg__big_mul_i64(den, oy), w->m1y), den);
        } else {
            pg__big den = pg__big_i64(840 * (int64_t)valid);
            cx = pg__big_div_round(fbx, den);
            cy = pg__big_div_round(fby, den);
        }
        md.center = pg_v2(pg__sat64(cx), pg__sat64(cy));
        if (w == &acc->mass) {
            int64_t dx = ((int64_t)md.center.x - ox) * 65536, dy = ((int64_t)md.center.y - oy) * 65536;
            pg__big in = acc->mass.m2;
            pg__big m1d = pg__big_add(pg__big_mul_i64(acc->mass.m1x, dx), pg__big_mul_i64(acc->mass.m1y, dy));
            in = pg__big_sub(in, pg__big_shl(m1d, 1));
            in = pg__big_add(in, pg__big_mul(acc->mass.m0, pg__big_add(pg__big_mul2(dx, dx), pg__big_mul2(dy, dy))));
            md.inertia = pg__big_div_round(in, pg__big_shl(pg__big_i64(3), 172));
            if (md.inertia < 0) md.inertia = 0;
        }
    }
    return md;
}

/* Adds geometry g (1..8 vertices) at density rho >= 0 to acc, its vertices taken
 * relative to O = (ox, oy). A polygon is also copied, counter-clockwise, into *keep when
 * keep is not NULL, for the overlap search; returns 1 for a polygon, else 0. Out of
 * line, so that its vertices and moments are on the stack only while it runs. */
PG__OUT_OF_LINE static int pg__geom_add(const pg_geom *g, int64_t rho, int64_t ox, int64_t oy, pg__poly *keep, pg__acc *acc)
{
    pg__pt v[PG_MAX_POLYGON_VERTICES];
    pg__moments m;
    int i, polygon = g->count >= 3;
    for (i = 0; i < g->count; ++i) {
        v[i].x = ((int64_t)g->vertices[i].x - ox) * 65536;
        v[i].y = ((int64_t)g->vertices[i].y - oy) * 65536;
    }
    if (polygon) {
        pg__big x = pg__poly_cross_sum(v, g->count);
        if (pg__big_is_neg(&x)) { /* clockwise: reverse */
            for (i = 0; i < g->count / 2; ++i) {
                pg__pt t = v[i];
                v[i] = v[g->count - 1 - i];
                v[g->count - 1 - i] = t;
            }
        }
        pg__poly_moments(v, g->count, &m);
        if (keep != NULL) {
            for (i = 0; i < g->count; ++i) keep->v[i] = v[i];
            keep->n = g->count;
            keep->rho = rho;
        }
    } else {
        /* A kind this build leaves out (PG_CONFIG_SHAPES) never reaches here, as shape
         * creation refuses it; its formula is then not compiled in, and such a geometry
         * would count as having no area. */
        int64_t r = g->radius > 0 ? (int64_t)g->radius * 65536 : 0;
        if (r > 0 && g->count == 1 && PG_SHAPES_KEPT(PG_SHAPES_CIRCLE))
            pg__circle_moments(v[0], r, &m);
        else if (r > 0 && g->count == 2 && PG_SHAPES_KEPT(PG_SHAPES_CAPSULE))
            pg__capsule_moments(v[0], v[1], r, &m);
        else
            return 0; /* segment or point: no area */
    }
    pg__moments_add(&acc->mass, &m, rho);
    pg__moments_add(&acc->area, &m, 1);
    return polygon;
}

pg_mass_data pg_compound_mass(const pg_geom *const *geoms, const pg_fix *densities, int count, void *work)
{
    pg_mass_data md;
    pg__mass_work *mw = (pg__mass_work *)work;
    pg__acc *acc = &mw->acc;
    int np = 0, k, i, valid = 0, any = 0;
    int64_t lox = 0, hix = 0, loy = 0, hiy = 0, ox, oy;
    pg__big fbx = pg__big_i64(0), fby = pg__big_i64(0);

    md.mass = 0;
    md.center = pg_v2_zero();
    md.inertia = 0;
    md.area = 0;
    if (geoms == NULL || densities == NULL || count <= 0) return md;

    /* the reference point: the rounded middle of the bounding box of all vertices */
    for (k = 0; k < count; ++k) {
        const pg_geom *g = geoms[k];
        if (g == NULL || g->count < 1 || g->count > PG_MAX_POLYGON_VERTICES) continue;
        for (i = 0; i < g->count; ++i) {
            int64_t x = g->vertices[i].x, y = g->vertices[i].y;
            if (!any) { lox = hix = x; loy = hiy = y; any = 1; }
            lox = x < lox ? x : lox; hix = x > hix ? x : hix;
            loy = y < loy ? y : loy; hiy = y > hiy ? y : hiy;
        }
    }
    if (!any) return md;
    ox = pg__round_shift64(lox + hix, 1);
    oy = pg__round_shift64(loy + hiy, 1);

    pg__moments_zero(&acc->mass);
    pg__moments_zero(&acc->area);
    for (k = 0; k < count; ++k) {
        const pg_geom *g = geoms[k];
        int64_t sx = 0, sy = 0;
        pg__poly *keep = np < PG__MASS_MAX_OVERLAP ? &mw->polys[np] : NULL;
        if (g == NULL || g->count < 1 || g->count > PG_MAX_POLYGON_VERTICES) continue;
        for (i = 0; i < g->count; ++i) {
            sx += g->vertices[i].x;
            sy += g->vertices[i].y;
        }
        /* fallback centre: sum of vertex averages times 840 = lcm(1..8) */
        fbx = pg__big_add(fbx, pg__big_i64(sx * (840 / g->count)));
        fby = pg__big_add(fby, pg__big_i64(sy * (840 / g->count)));
        ++valid;
        if (pg__geom_add(g, densities[k] > 0 ? densities[k] : 0, ox, oy, keep, acc) && keep != NULL) ++np;
    }
    /* overlaps among the first polygons: subsets of two or more */
    if (np > 1) pg__add_overlaps(mw, np, acc);

    return pg__mass_result(acc, ox, oy, fbx, fby, valid);
}

pg_mass_data pg_geom_mass(const pg_geom *g, pg_fix density)
{
    const pg_geom *one[1];
    pg__mass_work work; /* on the stack: for tests and tools, the library does not call this */
    one[0] = g;
    return pg_compound_mass(one, &density, 1, &work);
}
