/* test_collide.c — narrowphase geometry: unit directions, manifolds for every pair of
 * primitive kinds, feature ids, symmetry (argument swap, mirroring), ray casts,
 * containment, overlap and bounding boxes.
 *
 * Doubles are used only to build inputs and as references for inexact results.
 */
#include "pg_test.h"

#include <math.h>
#include <stdlib.h>

#include "collide.h"
#include "raycast.h"

#define Q30 1073741824.0
#define SPEC ((pg_fix)1311) /* 0.02 m */

static pg_fix fx(double v) { return (pg_fix)llround(v * 65536.0); }
static double dbl(pg_fix v) { return (double)v / 65536.0; }
static pg_vec2 vv(double x, double y) { return pg_v2(fx(x), fx(y)); }

static pg_geom blank(void)
{
    pg_geom g;
    memset(&g, 0, sizeof g);
    return g;
}

static pg_geom make_circle(double x, double y, double r)
{
    pg_geom g = blank();
    g.count = 1;
    g.vertices[0] = vv(x, y);
    g.centroid = g.vertices[0];
    g.radius = fx(r);
    return g;
}

/* Normals from the vertices (counter-clockwise). */
static void set_normals(pg_geom *g)
{
    int32_t i;
    int64_t sx = 0, sy = 0;
    for (i = 0; i < g->count; ++i) {
        pg_vec2 a = g->vertices[i], b = g->vertices[(i + 1) % g->count];
        g->normals[i] = pg_dir_normalize((int64_t)b.y - a.y, -((int64_t)b.x - a.x));
        sx += a.x;
        sy += a.y;
    }
    g->centroid = pg_v2((pg_fix)(sx / g->count), (pg_fix)(sy / g->count));
}

static pg_geom make_poly(const double *xy, int count, double r)
{
    pg_geom g = blank();
    int i;
    g.count = count;
    for (i = 0; i < count; ++i) g.vertices[i] = vv(xy[2 * i], xy[2 * i + 1]);
    set_normals(&g);
    g.radius = fx(r);
    return g;
}

static pg_geom make_capsule(double x1, double y1, double x2, double y2, double r)
{
    double xy[4];
    xy[0] = x1; xy[1] = y1; xy[2] = x2; xy[3] = y2;
    return make_poly(xy, 2, r);
}

static pg_angle angle_of(double radians)
{
    double turns = radians / (2.0 * PGT_PI);
    turns -= floor(turns);
    return (pg_angle)(uint32_t)llround(turns * 4294967296.0);
}

/* A box with half extents (hw, hh), centred at (x, y), rotated by `radians`: built in
 * its local frame with exact axis normals and placed with pg_geom_transform. */
static pg_geom make_box(double hw, double hh, double x, double y, double radians)
{
    pg_geom local = blank(), world;
    local.count = 4;
    local.vertices[0] = vv(-hw, -hh);
    local.vertices[1] = vv(hw, -hh);
    local.vertices[2] = vv(hw, hh);
    local.vertices[3] = vv(-hw, hh);
    local.normals[0].x = 0; local.normals[0].y = -(1 << 30);
    local.normals[1].x = 1 << 30; local.normals[1].y = 0;
    local.normals[2].x = 0; local.normals[2].y = 1 << 30;
    local.normals[3].x = -(1 << 30); local.normals[3].y = 0;
    pg_geom_transform(&local, vv(x, y), radians == 0.0 ? pg_rot_identity() : pg_rot_from_angle(angle_of(radians)), &world);
    return world;
}

/* Mirror in x (x -> -x) and rewind counter-clockwise. */
static pg_geom mirror(const pg_geom *g)
{
    pg_geom m = *g;
    int32_t c = g->count, k;
    for (k = 0; k < c; ++k) {
        pg_vec2 v = g->vertices[c - 1 - k];
        pg_dir n = g->normals[((c - 2 - k) % c + c) % c];
        m.vertices[k] = pg_v2(-v.x, v.y);
        m.normals[k].x = -n.x;
        m.normals[k].y = n.y;
    }
    m.centroid.x = -g->centroid.x;
    return m;
}

static pg_manifold collide(const pg_geom *a, const pg_geom *b, pg_fix spec)
{
    pg_manifold m;
    memset(&m, 0xA5, sizeof m); /* pg_collide must fill everything */
    pg_collide(a, b, spec, &m);
    return m;
}

static double ndx(pg_dir n) { return n.x / Q30; }
static double ndy(pg_dir n) { return n.y / Q30; }

static void expect_near(double got, double want, double tol, const char *what)
{
    if (!(fabs(got - want) <= tol)) {
        print_error("%s: got %.9f want %.9f (tol %.3g)\n", what, got, want, tol);
        fail();
    }
}

/* n is the unit vector along (dx, dy) (computed from the Q16.16 inputs) within 2 LSB. */
static void expect_dir(pg_dir n, double dx, double dy, const char *what)
{
    double l = sqrt(dx * dx + dy * dy);
    expect_near(n.x, dx / l * Q30, 2.0, what);
    expect_near(n.y, dy / l * Q30, 2.0, what);
}

static double gx(const pg_geom *g, int i) { return dbl(g->vertices[i].x); }
static double gy(const pg_geom *g, int i) { return dbl(g->vertices[i].y); }

/* Unit length within a few LSB, plus what the sine table's size leaves in the rotation
 * that turned the normal (pgt_rot_norm_error: nothing at 12 bits, 9 units at 8). */
static void expect_unit(pg_dir n)
{
    double l = sqrt((double)n.x * n.x + (double)n.y * n.y);
    expect_near(l, Q30, 4.0 + pgt_rot_norm_error() * Q30, "normal length (Q30 units)");
}

/* ---- pg_dir_normalize --------------------------------------------------------------- */

static void test_dir_normalize(void **state)
{
    pgt_rng rng = pgt_rng_seed(12345);
    double worst = 0.0;
    int i;
    (void)state;
    {
        pg_dir z = pg_dir_normalize(0, 0);
        assert_int_equal(z.x, 0);
        assert_int_equal(z.y, 0);
    }
    {
        pg_dir a = pg_dir_normalize(5, 0), b = pg_dir_normalize(0, -7), c = pg_dir_normalize(INT64_MAX, INT64_MAX);
        PG_EXPECT_EQ(a.x, 1 << 30, "%s", "x axis");
        PG_EXPECT_EQ(a.y, 0, "%s", "x axis");
        PG_EXPECT_EQ(b.x, 0, "%s", "-y axis");
        PG_EXPECT_EQ(b.y, -(1 << 30), "%s", "-y axis");
        PG_EXPECT_EQ(c.x, c.y, "%s", "diagonal");
        expect_near(c.x, Q30 / sqrt(2.0), 1.0, "huge diagonal");
    }
    for (i = 0; i < 200000; ++i) {
        int bits = 1 + (int)pgt_below(&rng, 62);
        int64_t x = (int64_t)(pgt_next(&rng) >> (64 - bits)), y = (int64_t)(pgt_next(&rng) >> (64 - bits));
        pg_dir d, e, f;
        double l;
        if (pgt_next(&rng) & 1) x = -x;
        if (pgt_next(&rng) & 1) y = -y;
        if (pgt_below(&rng, 4) == 0) y >>= pgt_below(&rng, 40); /* very unequal magnitudes */
        if (x == 0 && y == 0) continue;
        d = pg_dir_normalize(x, y);
        l = sqrt((double)x * x + (double)y * y);
        {
            double ex = fabs(d.x - (double)x / l * Q30), ey = fabs(d.y - (double)y / l * Q30);
            if (ex > worst) worst = ex;
            if (ey > worst) worst = ey;
        }
        e = pg_dir_normalize(-x, -y);
        f = pg_dir_normalize(y, x);
        PG_EXPECT_EQ(e.x, -d.x, "sign symmetry x=%lld y=%lld", (long long)x, (long long)y);
        PG_EXPECT_EQ(e.y, -d.y, "sign symmetry x=%lld y=%lld", (long long)x, (long long)y);
        PG_EXPECT_EQ(f.x, d.y, "swap symmetry x=%lld y=%lld", (long long)x, (long long)y);
        PG_EXPECT_EQ(f.y, d.x, "swap symmetry x=%lld y=%lld", (long long)x, (long long)y);
    }
    PG_EXPECT_LE(worst, 1.5, "%s", "max error in Q30 LSB");
}

/* ---- circles -------------------------------------------------------------------------- */

static void test_circle_circle(void **state)
{
    /* touching exactly: reported with separation 0 (<= speculative 0) */
    pg_geom a = make_circle(2, 2, 0.5), b = make_circle(3, 2, 0.5);
    pg_manifold m;
    (void)state;
    m = collide(&a, &b, 0);
    PG_EXPECT_EQ(m.count, 1, "%s", "touching");
    PG_EXPECT_EQ(m.points[0].separation, 0, "%s", "touching");
    PG_EXPECT_EQ(m.points[0].point.x, fx(2.5), "%s", "contact between");
    PG_EXPECT_EQ(m.normal.x, 1 << 30, "%s", "+x");
}

static void test_circle_circle_cases(void **state)
{
    pg_manifold m;
    (void)state;
    {   /* overlap by 0.2 along (0.6, 0.8) */
        pg_geom a = make_circle(1, 2, 0.5), b = make_circle(1.36, 2.48, 0.3);
        m = collide(&a, &b, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "overlap");
        expect_dir(m.normal, gx(&b, 0) - gx(&a, 0), gy(&b, 0) - gy(&a, 0), "normal");
        expect_near(dbl(m.points[0].separation), -0.2, 2.0 / 65536, "separation");
        /* midway: A's surface at 1 + 0.5 n, B's at 1.48 - 0.3 n: midpoint = A + 0.4 n */
        expect_near(dbl(m.points[0].point.x), 1 + 0.4 * 0.6, 2.0 / 65536, "px");
        expect_near(dbl(m.points[0].point.y), 2 + 0.4 * 0.8, 2.0 / 65536, "py");
        PG_EXPECT_EQ(m.points[0].id, 0x20000u, "%s", "circle id");
        /* swapped: normal reversed, same separation */
        m = collide(&b, &a, 0);
        expect_dir(m.normal, gx(&a, 0) - gx(&b, 0), gy(&a, 0) - gy(&b, 0), "swapped normal");
        expect_near(dbl(m.points[0].separation), -0.2, 2.0 / 65536, "swap separation");
    }
    {   /* separated by 0.05: reported only within the speculative window */
        pg_geom a = make_circle(0, 0, 0.5), b = make_circle(1.05, 0, 0.5);
        m = collide(&a, &b, 0);
        PG_EXPECT_EQ(m.count, 0, "%s", "separated, no speculation");
        m = collide(&a, &b, fx(0.04));
        PG_EXPECT_EQ(m.count, 0, "%s", "window too small");
        m = collide(&a, &b, fx(0.06));
        PG_EXPECT_EQ(m.count, 1, "%s", "inside the window");
        PG_EXPECT_EQ(m.normal.x, 1 << 30, "%s", "normal +x");
        PG_EXPECT_EQ(m.normal.y, 0, "%s", "normal +x");
        PG_EXPECT_EQ(m.points[0].separation, fx(1.05) - fx(1.0), "%s", "exact separation");
        PG_EXPECT_EQ(m.points[0].point.x, (fx(1.05) + 1) / 2, "%s", "midway (rounded, ties away)");
    }
}

static void test_circle_box(void **state)
{
    pg_geom box = make_box(1, 0.5, 0, 0, 0);
    pg_manifold m;
    (void)state;
    {   /* above the top face, overlapping by 0.1 */
        pg_geom c = make_circle(0.3, 0.8, 0.4);
        m = collide(&box, &c, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "face");
        PG_EXPECT_EQ(m.normal.x, 0, "%s", "face normal");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "face normal");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.8) - fx(0.5) - fx(0.4), "%s", "separation");
        expect_near(dbl(m.points[0].point.y), 0.45, 1.0 / 65536, "midway y");
        PG_EXPECT_EQ(m.points[0].point.x, fx(0.3), "%s", "x");
        PG_EXPECT_EQ(m.points[0].id, 0x00000200u, "%s", "face 2 of A (top), circle 0");
        /* circle as A */
        m = collide(&c, &box, 0);
        PG_EXPECT_EQ(m.normal.y, -(1 << 30), "%s", "reversed");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.8) - fx(0.5) - fx(0.4), "%s", "same separation");
        PG_EXPECT_EQ(m.points[0].id, 0x00010002u, "%s", "B's face 2");
    }
    {   /* side face, deep: centre inside the box */
        pg_geom c = make_circle(0.9, 0.1, 0.3);
        m = collide(&box, &c, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "deep");
        PG_EXPECT_EQ(m.normal.x, 1 << 30, "%s", "right face");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.9) - fx(1.0) - fx(0.3), "%s", "separation");
    }
    {   /* corner region: normal along corner -> centre */
        pg_geom c = make_circle(1.3, 0.9, 0.6); /* offset (0.3, 0.4): distance 0.5 */
        m = collide(&box, &c, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "corner");
        expect_dir(m.normal, gx(&c, 0) - 1, gy(&c, 0) - 0.5, "corner normal");
        expect_near(dbl(m.points[0].separation), -0.1, 1.0 / 65536, "corner separation");
        expect_near(dbl(m.points[0].point.x), 1 + 0.6 * -0.05, 2.0 / 65536, "corner px");
        expect_near(dbl(m.points[0].point.y), 0.5 + 0.8 * -0.05, 2.0 / 65536, "corner py");
        PG_EXPECT_EQ(m.points[0].id, 0x20200u, "%s", "vertex 2 of A");
        /* out of reach */
        c = make_circle(1.3, 0.9, 0.45);
        m = collide(&box, &c, 0);
        PG_EXPECT_EQ(m.count, 0, "%s", "corner apart by 0.05");
        m = collide(&box, &c, fx(0.06));
        PG_EXPECT_EQ(m.count, 1, "%s", "corner speculative");
    }
}

static void test_segment_circle(void **state)
{
    pg_geom seg = make_capsule(-1, 0, 1, 0, 0);
    pg_manifold m;
    (void)state;
    {   /* above the middle */
        pg_geom c = make_circle(0.25, 0.3, 0.4);
        m = collide(&seg, &c, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "middle");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.3) - fx(0.4), "%s", "separation");
        /* below */
        c = make_circle(0.25, -0.3, 0.4);
        m = collide(&seg, &c, 0);
        PG_EXPECT_EQ(m.normal.y, -(1 << 30), "%s", "down");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.3) - fx(0.4), "%s", "separation below");
    }
    {   /* beyond the end on the segment's line: the end point's region */
        pg_geom c = make_circle(1.2, 0, 0.3);
        m = collide(&seg, &c, 0);
        PG_EXPECT_EQ(m.count, 1, "%s", "end");
        PG_EXPECT_EQ(m.normal.x, 1 << 30, "%s", "+x");
        PG_EXPECT_EQ(m.normal.y, 0, "%s", "+x");
        PG_EXPECT_EQ(m.points[0].separation, fx(1.2) - fx(1.0) - fx(0.3), "%s", "separation");
        /* capsule radius adds */
        seg.radius = fx(0.05);
        m = collide(&c, &seg, 0);
        PG_EXPECT_EQ(m.normal.x, -(1 << 30), "%s", "circle as A");
        PG_EXPECT_EQ(m.points[0].separation, fx(1.2) - fx(1.0) - fx(0.3) - fx(0.05), "%s", "with radius");
        seg.radius = 0;
    }
    {   /* off the end diagonally */
        pg_geom c = make_circle(-1.3, -0.4, 0.6);
        m = collide(&seg, &c, 0);
        expect_dir(m.normal, gx(&c, 0) + 1, gy(&c, 0), "end normal");
        expect_near(dbl(m.points[0].separation), -0.1, 1.0 / 65536, "sep");
    }
}

/* ---- boxes ------------------------------------------------------------------------------- */

static void test_box_box_resting(void **state)
{
    pg_geom ground = make_box(5, 0.5, 0, -0.5, 0);
    pg_geom box = make_box(0.5, 0.5, 0, 0.49, 0); /* 0.01 deep */
    pg_manifold m;
    int i;
    (void)state;
    m = collide(&ground, &box, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "two points");
    PG_EXPECT_EQ(m.normal.x, 0, "%s", "exact normal");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "exact normal");
    PG_EXPECT_EQ(m.points[0].separation, m.points[1].separation, "%s", "equal separations");
    PG_EXPECT_EQ(m.points[0].separation, fx(0.49) - fx(0.5), "%s", "depth");
    PG_EXPECT_EQ(m.points[0].point.x, -m.points[1].point.x, "%s", "symmetric points");
    PG_EXPECT_EQ(labs((long)m.points[0].point.x), fx(0.5), "%s", "x = +-half width");
    for (i = 0; i < 2; ++i) {
        /* midway between y = 0 (ground) and y = -0.01 (box bottom) */
        expect_near(dbl(m.points[i].point.y), -0.005, 1.0 / 65536, "midway");
        PG_EXPECT_EQ(m.points[i].id >> 16, 0, "%s", "A's face is the reference");
        PG_EXPECT_EQ((m.points[i].id >> 8) & 0xFF, 2, "%s", "A's top face");
    }
    assert_true(m.points[0].id != m.points[1].id);
    /* incident edge: the box's bottom 0 -> 1; the first point comes from its end 1 */
    PG_EXPECT_EQ(m.points[0].id, 0x00000201u, "%s", "A's face 2, B's vertex 1");
    PG_EXPECT_EQ(m.points[1].id, 0x00000200u, "%s", "A's face 2, B's vertex 0");

    /* Two equal boxes stacked exactly: tie between A's top and B's bottom -> A. */
    {
        pg_geom lower = make_box(0.5, 0.5, 3, 0.5, 0), upper = make_box(0.5, 0.5, 3, 1.5, 0);
        m = collide(&lower, &upper, SPEC);
        PG_EXPECT_EQ(m.count, 2, "%s", "stacked");
        PG_EXPECT_EQ(m.normal.x, 0, "%s", "stacked normal");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "stacked normal");
        PG_EXPECT_EQ(m.points[0].separation, 0, "%s", "touching");
        PG_EXPECT_EQ(m.points[1].separation, 0, "%s", "touching");
        PG_EXPECT_EQ(m.points[0].id >> 16, 0, "%s", "A reference");
        PG_EXPECT_EQ(m.points[0].point.y, fx(1.0), "%s", "on the interface");
        PG_EXPECT_EQ(m.points[0].point.x + m.points[1].point.x, 2 * fx(3), "%s", "symmetric about x = 3");
        /* swapped: B (now the lower box) keeps the reference when it is A */
        m = collide(&upper, &lower, SPEC);
        PG_EXPECT_EQ(m.normal.y, -(1 << 30), "%s", "swapped stacked normal");
        PG_EXPECT_EQ(m.points[0].id >> 16, 0, "%s", "A (upper) reference");
        PG_EXPECT_EQ(m.points[0].separation, 0, "%s", "swapped touching");
    }
    /* Hovering within the speculative distance, and beyond it. */
    {
        pg_geom hover = make_box(0.5, 0.5, 0, 0.51, 0);
        m = collide(&ground, &hover, SPEC);
        PG_EXPECT_EQ(m.count, 2, "%s", "speculative pair");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.01), "%s", "gap");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "speculative normal");
        /* equal boxes, flush edges, apart: still two points with the face normal */
        {
            pg_geom lower = make_box(0.5, 0.5, 3, 0.5, 0), upper = make_box(0.5, 0.5, 3, 1.51, 0);
            m = collide(&lower, &upper, SPEC);
            PG_EXPECT_EQ(m.count, 2, "%s", "flush speculative pair");
            PG_EXPECT_EQ(m.normal.x, 0, "%s", "flush normal");
            PG_EXPECT_EQ(m.points[0].separation, fx(0.01), "%s", "flush gap");
            upper = make_box(0.5, 0.5, 3.0002, 1.51, 0); /* 0.0002 m sideways: still flush */
            m = collide(&lower, &upper, SPEC);
            PG_EXPECT_EQ(m.count, 2, "%s", "nearly flush speculative pair");
            PG_EXPECT_EQ(m.normal.x, 0, "%s", "nearly flush normal");
        }
        hover = make_box(0.5, 0.5, 0, 0.53, 0);
        m = collide(&ground, &hover, SPEC);
        PG_EXPECT_EQ(m.count, 0, "%s", "beyond speculative");
    }
}

static void test_box_offset_sideways(void **state)
{
    pg_geom ground = make_box(5, 0.5, 0, -0.5, 0);
    pg_geom box = make_box(0.5, 0.5, 4.8, 0.48, 0); /* overhangs the right edge */
    pg_manifold m;
    pg_fix xs[2];
    (void)state;
    m = collide(&ground, &box, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "two points");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
    xs[0] = m.points[0].point.x < m.points[1].point.x ? m.points[0].point.x : m.points[1].point.x;
    xs[1] = m.points[0].point.x < m.points[1].point.x ? m.points[1].point.x : m.points[0].point.x;
    PG_EXPECT_EQ(xs[0], fx(4.8) - fx(0.5), "%s", "box corner");
    PG_EXPECT_EQ(xs[1], fx(5.0), "%s", "clipped at the ground's edge");
    PG_EXPECT_EQ(m.points[0].separation, fx(0.48) - fx(0.5), "%s", "depth");
    PG_EXPECT_EQ(m.points[1].separation, fx(0.48) - fx(0.5), "%s", "depth");
    expect_near(dbl(m.points[0].point.y), -0.01, 1.0 / 65536, "midway");

    /* box wider than its support: both points clipped, at the support's corners */
    {
        pg_geom post = make_box(0.2, 1, 0, 0, 0), plank = make_box(2, 0.1, 0.3, 1.095, 0);
        m = collide(&post, &plank, SPEC);
        PG_EXPECT_EQ(m.count, 2, "%s", "plank");
        PG_EXPECT_EQ(m.points[0].point.x + m.points[1].point.x, 0, "%s", "at +-0.2");
        PG_EXPECT_EQ(labs((long)m.points[0].point.x), fx(0.2), "%s", "at +-0.2");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.995) - fx(1.0), "%s", "depth");
        PG_EXPECT_EQ(m.points[1].separation, fx(0.995) - fx(1.0), "%s", "depth");
    }
}

/* Double reference: separation of b from a along the unit axis n (support functions). */
static double ref_separation(const pg_geom *a, const pg_geom *b, pg_dir nd)
{
    double nx = ndx(nd), ny = ndy(nd), l = sqrt(nx * nx + ny * ny), maxa = -1e300, minb = 1e300;
    int i;
    nx /= l;
    ny /= l;
    for (i = 0; i < a->count; ++i) {
        double p = dbl(a->vertices[i].x) * nx + dbl(a->vertices[i].y) * ny;
        if (p > maxa) maxa = p;
    }
    for (i = 0; i < b->count; ++i) {
        double p = dbl(b->vertices[i].x) * nx + dbl(b->vertices[i].y) * ny;
        if (p < minb) minb = p;
    }
    return minb - maxa - dbl(a->radius) - dbl(b->radius);
}

static void test_box_box_rotated(void **state)
{
    int deg, dir;
    (void)state;
    for (deg = 0; deg < 360; deg += 7) {
        for (dir = 0; dir < 2; ++dir) {
            double ang = deg * PGT_PI / 180.0, c = cos(ang), s = sin(ang);
            /* lowest point of the rotated box 0.03 below the ground's top */
            double low = 0.6 * fabs(s) + 0.4 * fabs(c);
            pg_geom ground = make_box(4, 0.5, 0.1, -0.5, 0.02 * dir);
            pg_geom box = make_box(0.6, 0.4, 0.3, low - 0.03, ang);
            pg_manifold m = dir ? collide(&box, &ground, SPEC) : collide(&ground, &box, SPEC);
            double want, got = 1e300;
            int i;
            assert_true(m.count >= 1);
            expect_unit(m.normal);
            want = dir ? ref_separation(&box, &ground, m.normal) : ref_separation(&ground, &box, m.normal);
            for (i = 0; i < m.count; ++i)
                if (dbl(m.points[i].separation) < got) got = dbl(m.points[i].separation);
            if (fabs(got - want) > 3.0 / 65536) {
                print_error("deg %d dir %d: separation %.8f, reference %.8f\n", deg, dir, got, want);
                fail();
            }
            /* the normal points from A to B */
            if (dir) assert_true(m.normal.y < 0);
            else assert_true(m.normal.y > 0);
        }
    }
    /* two rotated boxes in the air, corner into face */
    {
        pg_geom a = make_box(0.5, 0.5, 0, 0, 0.3), b = make_box(0.5, 0.5, 0.95, 0.3, 1.0);
        pg_manifold m = collide(&a, &b, SPEC);
        double want;
        int i;
        assert_true(m.count >= 1);
        want = ref_separation(&a, &b, m.normal);
        if (m.points[0].id >> 16 == 1) { /* B's face is the reference: measure along it */
            pg_dir nb;
            nb.x = -m.normal.x;
            nb.y = -m.normal.y;
            want = ref_separation(&b, &a, nb);
        }
        for (i = 0; i < m.count; ++i) assert_true(dbl(m.points[i].separation) >= want - 3.0 / 65536);
        expect_near(dbl(m.points[0].separation < (m.count > 1 ? m.points[1].separation : INT32_MAX) ? m.points[0].separation : m.points[1].separation),
                    want, 3.0 / 65536, "rotated pair depth");
    }
}

static void test_feature_ids_stable(void **state)
{
    pg_geom ground = make_box(5, 0.5, 0, -0.5, 0);
    pg_manifold first, m;
    int k;
    (void)state;
    {
        pg_geom box = make_box(0.5, 0.5, 0, 0.495, 0.01);
        first = collide(&ground, &box, SPEC);
    }
    assert_int_equal(first.count, 2);
    for (k = 1; k <= 20; ++k) {
        pg_geom box = make_box(0.5, 0.5, 0.005 * k, 0.495 + 0.0002 * (k % 3), 0.01 - 0.0005 * k);
        m = collide(&ground, &box, SPEC);
        assert_int_equal(m.count, 2);
        PG_EXPECT_EQ(m.points[0].id, first.points[0].id, "step %d", k);
        PG_EXPECT_EQ(m.points[1].id, first.points[1].id, "step %d", k);
    }
}

/* ---- capsules and segments ---------------------------------------------------------- */

static void test_capsule_on_box(void **state)
{
    pg_geom box = make_box(2, 0.5, 0, 0, 0);
    pg_geom cap = make_capsule(-1, 0.74, 1, 0.74, 0.25); /* 0.01 deep */
    pg_manifold m;
    (void)state;
    m = collide(&box, &cap, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "lying flat");
    PG_EXPECT_EQ(m.normal.x, 0, "%s", "up");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
    PG_EXPECT_EQ(m.points[0].separation, fx(0.74) - fx(0.5) - fx(0.25), "%s", "depth");
    PG_EXPECT_EQ(m.points[1].separation, fx(0.74) - fx(0.5) - fx(0.25), "%s", "depth");
    PG_EXPECT_EQ(m.points[0].point.x + m.points[1].point.x, 0, "%s", "points under the ends");
    PG_EXPECT_EQ(labs((long)m.points[0].point.x), fx(1), "%s", "points under the ends");
    expect_near(dbl(m.points[0].point.y), 0.495, 1.0 / 65536, "midway");
    /* the capsule as A */
    m = collide(&cap, &box, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "swapped");
    PG_EXPECT_EQ(m.normal.y, -(1 << 30), "%s", "down");
    PG_EXPECT_EQ(m.points[0].separation, fx(0.74) - fx(0.5) - fx(0.25), "%s", "depth");
    PG_EXPECT_EQ(labs((long)m.points[0].point.x), fx(1), "%s", "points under the ends");
    /* tilted slightly: still two points, different depths */
    cap = make_capsule(-1, 0.74, 1, 0.76, 0.25);
    m = collide(&box, &cap, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "tilted");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "tilted normal");
    assert_true(m.points[0].separation != m.points[1].separation);
}

static void test_capsule_corner(void **state)
{
    pg_geom box = make_box(1, 1, 0, 0, 0);
    pg_geom cap = make_capsule(1.2, 1.3, 3.2, 1.3, 0.25);
    pg_manifold m;
    double d = sqrt(0.2 * 0.2 + 0.3 * 0.3);
    (void)state;
    m = collide(&box, &cap, fx(0.2));
    PG_EXPECT_EQ(m.count, 1, "%s", "one point");
    expect_dir(m.normal, gx(&cap, 0) - 1, gy(&cap, 0) - 1, "corner normal");
    expect_near(dbl(m.points[0].separation), d - 0.25, 1.0 / 65536, "separation");
    expect_near(dbl(m.points[0].point.x), 1 + 0.2 / d * (d - 0.25) / 2, 2.0 / 65536, "midway x");
    expect_near(dbl(m.points[0].point.y), 1 + 0.3 / d * (d - 0.25) / 2, 2.0 / 65536, "midway y");
    PG_EXPECT_EQ(m.points[0].id >> 16, 2, "%s", "vertex-vertex");
    PG_EXPECT_EQ((m.points[0].id >> 8) & 0xFF, 2, "%s", "box corner 2");
    PG_EXPECT_EQ(m.points[0].id & 0xFF, 0, "%s", "capsule end 0");
    m = collide(&box, &cap, fx(0.1));
    PG_EXPECT_EQ(m.count, 0, "%s", "out of speculative reach");
    /* overlapping corner (the cores apart, the rounded end into the corner) */
    cap = make_capsule(1.1, 1.15, 3.1, 1.15, 0.25);
    m = collide(&cap, &box, 0);
    PG_EXPECT_EQ(m.count, 1, "%s", "overlapping end");
    d = sqrt(0.1 * 0.1 + 0.15 * 0.15);
    expect_dir(m.normal, 1 - gx(&cap, 0), 1 - gy(&cap, 0), "reversed corner normal");
    expect_near(dbl(m.points[0].separation), d - 0.25, 1.0 / 65536, "separation");
}

static void test_capsule_capsule(void **state)
{
    pg_manifold m;
    (void)state;
    {   /* parallel, overlapping in x over [-0.5, 1] */
        pg_geom a = make_capsule(-1, 0, 1, 0, 0.25), b = make_capsule(-0.5, 0.45, 1.5, 0.45, 0.25);
        m = collide(&a, &b, SPEC);
        PG_EXPECT_EQ(m.count, 2, "%s", "parallel");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.45) - fx(0.5), "%s", "depth");
        PG_EXPECT_EQ(m.points[1].separation, fx(0.45) - fx(0.5), "%s", "depth");
        {
            pg_fix lo = m.points[0].point.x < m.points[1].point.x ? m.points[0].point.x : m.points[1].point.x;
            pg_fix hi = m.points[0].point.x < m.points[1].point.x ? m.points[1].point.x : m.points[0].point.x;
            PG_EXPECT_EQ(lo, fx(-0.5), "%s", "overlap start");
            PG_EXPECT_EQ(hi, fx(1), "%s", "overlap end");
        }
        expect_near(dbl(m.points[0].point.y), 0.225, 1.0 / 65536, "midway");
    }
    {   /* end to end on one line: vertex-vertex */
        pg_geom a = make_capsule(-1, 0, 1, 0, 0.25), b = make_capsule(1.4, 0, 3, 0, 0.25);
        m = collide(&a, &b, SPEC);
        PG_EXPECT_EQ(m.count, 1, "%s", "end to end");
        PG_EXPECT_EQ(m.normal.x, 1 << 30, "%s", "+x");
        PG_EXPECT_EQ(m.normal.y, 0, "%s", "+x");
        PG_EXPECT_EQ(m.points[0].separation, fx(1.4) - fx(1) - fx(0.5), "%s", "separation");
        PG_EXPECT_EQ(m.points[0].point.x, (fx(1.4) + fx(1)) / 2, "%s", "midway");
    }
    {   /* crossed: B stands on A's middle, cores apart by 0.45 */
        pg_geom a = make_capsule(-1, 0, 1, 0, 0.25), b = make_capsule(0, 0.45, 0, 2.45, 0.25);
        m = collide(&a, &b, SPEC);
        PG_EXPECT_EQ(m.count, 1, "%s", "crossed");
        PG_EXPECT_EQ(m.normal.x, 0, "%s", "up");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.45) - fx(0.5), "%s", "depth");
        PG_EXPECT_EQ(m.points[0].point.x, 0, "%s", "x");
        expect_near(dbl(m.points[0].point.y), 0.225, 1.0 / 65536, "midway");
    }
    {   /* crossed as an X: the cores intersect */
        pg_geom a = make_capsule(-1, 0, 1, 0, 0.1), b = make_capsule(0.2, -0.6, 0.2, 1.4, 0.1);
        int i;
        m = collide(&a, &b, SPEC);
        assert_true(m.count >= 1);
        expect_unit(m.normal);
        for (i = 0; i < m.count; ++i) assert_true(m.points[i].separation < 0);
        /* the cheapest way apart: move B up by 0.6 (+ radii) */
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
        PG_EXPECT_EQ(m.points[0].separation, -fx(0.6) - 2 * fx(0.1), "%s", "depth");
    }
    {   /* slightly skewed, apart: 1 or 2 points, normal from the closest features */
        pg_geom a = make_capsule(-1, 0, 1, 0, 0.25), b = make_capsule(-1, 0.6, 1, 0.52, 0.25);
        m = collide(&a, &b, fx(0.2));
        PG_EXPECT_EQ(m.count, 2, "%s", "almost parallel");
        PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "A's face normal");
    }
}

static void test_triangle_box(void **state)
{
    static const double tri[6] = {0.1, -0.1, 1, 1, -1, 1.2};
    pg_geom box = make_box(2, 0.5, 0, -0.5, 0);
    pg_geom t = make_poly(tri, 3, 0);
    pg_manifold m;
    (void)state;
    m = collide(&box, &t, SPEC);
    PG_EXPECT_EQ(m.count, 1, "%s", "tip");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "up");
    PG_EXPECT_EQ(m.points[0].separation, -fx(0.1), "%s", "depth");
    PG_EXPECT_EQ(m.points[0].point.x, fx(0.1), "%s", "tip x");
    expect_near(dbl(m.points[0].point.y), -0.05, 1.0 / 65536, "midway");
    PG_EXPECT_EQ(m.points[0].id & 0xFF, 0, "%s", "vertex 0 of the triangle");
    m = collide(&t, &box, SPEC);
    PG_EXPECT_EQ(m.count, 1, "%s", "swapped");
    PG_EXPECT_EQ(m.normal.y, -(1 << 30), "%s", "down");
    PG_EXPECT_EQ(m.points[0].separation, -fx(0.1), "%s", "depth");
    PG_EXPECT_EQ(m.points[0].point.x, fx(0.1), "%s", "tip x");
    /* lying on its long side: two points */
    {
        static const double flat[6] = {-1, 0.01, 1, 0.01, 0, 1};
        pg_geom f = make_poly(flat, 3, 0);
        m = collide(&box, &f, SPEC);
        PG_EXPECT_EQ(m.count, 2, "%s", "flat");
        PG_EXPECT_EQ(m.points[0].separation, fx(0.01), "%s", "speculative gap");
        PG_EXPECT_EQ(m.points[0].point.x + m.points[1].point.x, 0, "%s", "symmetric");
    }
}

/* ---- symmetry ----------------------------------------------------------------------------- */

static int same_point(const pg_manifold_point *p, const pg_manifold_point *q, int mirror_x, int tol)
{
    pg_fix qx = mirror_x ? -q->point.x : q->point.x;
    return abs(p->point.x - qx) <= tol && abs(p->point.y - q->point.y) <= tol && abs(p->separation - q->separation) <= tol;
}

static void expect_matching(const pg_manifold *m, const pg_manifold *w, int mirror_x, int tol, const char *what)
{
    int i, j;
    PG_EXPECT_EQ(m->count, w->count, "%s", what);
    for (i = 0; i < m->count; ++i) {
        int found = 0;
        for (j = 0; j < w->count; ++j) found |= same_point(&m->points[i], &w->points[j], mirror_x, tol);
        if (!found) {
            print_error("%s: point %d (%d, %d) sep %d has no match\n", what, i, m->points[i].point.x, m->points[i].point.y,
                        m->points[i].separation);
            fail();
        }
    }
}

typedef struct pair_case { pg_geom a, b; pg_fix spec; const char *name; } pair_case;

static int make_cases(pair_case *c)
{
    static const double tri[6] = {0.13, -0.07, 1, 1, -1, 1.2};
    int n = 0;
    c[n].a = make_box(4, 0.5, 0.1, -0.5, 0); c[n].b = make_box(0.6, 0.4, 0.3, 0.4, 0.4); c[n].spec = SPEC; c[n++].name = "rotated box on ground";
    c[n].a = make_box(5, 0.5, 0, -0.5, 0); c[n].b = make_box(0.5, 0.5, 4.8, 0.48, 0); c[n].spec = SPEC; c[n++].name = "overhanging box";
    c[n].a = make_box(0.5, 0.5, 0, 0, 0.3); c[n].b = make_box(0.5, 0.5, 0.95, 0.3, 1.0); c[n].spec = SPEC; c[n++].name = "two rotated boxes";
    c[n].a = make_box(1, 1, 0, 0, 0); c[n].b = make_capsule(1.2, 1.3, 3.2, 1.3, 0.25); c[n].spec = fx(0.2); c[n++].name = "capsule corner";
    c[n].a = make_box(2, 0.5, 0, -0.5, 0.05); c[n].b = make_poly(tri, 3, 0); c[n].spec = SPEC; c[n++].name = "triangle";
    c[n].a = make_box(1, 0.5, 0.2, 0, 0.7); c[n].b = make_circle(1.3, 0.9, 0.6); c[n].spec = SPEC; c[n++].name = "circle corner";
    c[n].a = make_capsule(-1, 0.1, 1, -0.05, 0.25); c[n].b = make_capsule(-0.5, 0.45, 1.5, 0.52, 0.25); c[n].spec = SPEC; c[n++].name = "capsules";
    c[n].a = make_circle(0.3, 0.1, 0.5); c[n].b = make_circle(1.1, 0.7, 0.55); c[n].spec = SPEC; c[n++].name = "circles";
    c[n].a = make_capsule(-1, 0, 1, 0.3, 0); c[n].b = make_circle(0.4, 0.5, 0.4); c[n].spec = SPEC; c[n++].name = "segment circle";
    c[n].a = make_box(0.5, 0.5, 3, 0.5, 0); c[n].b = make_box(0.5, 0.5, 3, 1.5, 0); c[n].spec = SPEC; c[n++].name = "stacked";
    return n;
}

static void test_mirror_symmetry(void **state)
{
    pair_case cases[16];
    int n = make_cases(cases), k;
    (void)state;
    for (k = 0; k < n; ++k) {
        pg_geom ma = mirror(&cases[k].a), mb = mirror(&cases[k].b);
        pg_manifold m = collide(&cases[k].a, &cases[k].b, cases[k].spec), w = collide(&ma, &mb, cases[k].spec);
        assert_true(m.count >= 1);
        PG_EXPECT_EQ(w.normal.x, -m.normal.x, "%s", cases[k].name);
        PG_EXPECT_EQ(w.normal.y, m.normal.y, "%s", cases[k].name);
        expect_matching(&m, &w, 1, 0, cases[k].name);
    }
}

static void test_swap_arguments(void **state)
{
    pair_case cases[16];
    int n = make_cases(cases), k;
    (void)state;
    for (k = 0; k < n; ++k) {
        pg_manifold m = collide(&cases[k].a, &cases[k].b, cases[k].spec), w = collide(&cases[k].b, &cases[k].a, cases[k].spec);
        double dot = ((double)m.normal.x * w.normal.x + (double)m.normal.y * w.normal.y) / (Q30 * Q30);
        assert_true(m.count >= 1);
        if (dot > -0.999999) {
            print_error("%s: normals not opposite (%d %d) (%d %d)\n", cases[k].name, m.normal.x, m.normal.y, w.normal.x, w.normal.y);
            fail();
        }
        expect_matching(&m, &w, 0, 2, cases[k].name);
    }
}

/* ---- queries -------------------------------------------------------------------------------- */

static void test_raycast(void **state)
{
    pg_fix t;
    pg_vec2 p;
    pg_dir n;
    (void)state;
    {   /* circle */
        pg_geom c = make_circle(0, 0, 1);
        double hx = -sqrt(1 - 0.25);
        assert_true(pg_geom_raycast(&c, vv(-5, 0.5), vv(10, 0), PG_FIX_ONE, &t, &p, &n));
        expect_near(dbl(t), (hx + 5) / 10, 2.0 / 65536, "circle t");
        expect_near(dbl(p.x), hx, 2.0 / 65536, "circle x");
        expect_near(dbl(p.y), 0.5, 1.0 / 65536, "circle y");
        expect_near(ndx(n), hx, 1e-5, "circle nx");
        expect_near(ndy(n), 0.5, 1e-5, "circle ny");
        assert_false(pg_geom_raycast(&c, vv(-5, 0.5), vv(10, 0), fx(0.4), &t, &p, &n)); /* too short */
        assert_false(pg_geom_raycast(&c, vv(-5, 1.1), vv(10, 0), PG_FIX_ONE, &t, &p, &n)); /* beside */
        assert_false(pg_geom_raycast(&c, vv(5, 0.5), vv(10, 0), PG_FIX_ONE, &t, &p, &n));  /* away */
        assert_false(pg_geom_raycast(&c, vv(0.2, 0.1), vv(10, 0), PG_FIX_ONE, &t, &p, &n)); /* inside */
    }
    {   /* box */
        pg_geom b = make_box(1, 0.5, 0, 0, 0);
        assert_true(pg_geom_raycast(&b, vv(-5, 0.2), vv(10, 0), PG_FIX_ONE, &t, &p, &n));
        PG_EXPECT_EQ(t, fx(0.4), "%s", "box t");
        PG_EXPECT_EQ(p.x, fx(-1), "%s", "box x");
        PG_EXPECT_EQ(n.x, -(1 << 30), "%s", "box normal");
        PG_EXPECT_EQ(n.y, 0, "%s", "box normal");
        /* diagonal from above-right into the top face */
        assert_true(pg_geom_raycast(&b, vv(1.5, 2.5), vv(-1, -2), fx(2), &t, &p, &n));
        expect_near(dbl(t), 1.0, 2.0 / 65536, "diagonal t");
        expect_near(dbl(p.x), 0.5, 2.0 / 65536, "diagonal x");
        PG_EXPECT_EQ(n.y, 1 << 30, "%s", "top normal");
        /* through a corner exactly */
        assert_true(pg_geom_raycast(&b, vv(2, 1.5), vv(-2, -2), PG_FIX_ONE, &t, &p, &n));
        expect_near(dbl(t), 0.5, 2.0 / 65536, "corner t");
        assert_false(pg_geom_raycast(&b, vv(-5, 0.6), vv(10, 0), PG_FIX_ONE, &t, &p, &n)); /* above */
        /* rotated box: compare with a double computation */
        {
            pg_geom r = make_box(1, 0.5, 0.3, -0.2, 0.6);
            double best = 1e300;
            int i;
            assert_true(pg_geom_raycast(&r, vv(-4, 0.1), vv(8, 0.5), PG_FIX_ONE, &t, &p, &n));
            for (i = 0; i < 4; ++i) { /* intersect with each edge line */
                double ax = dbl(r.vertices[i].x), ay = dbl(r.vertices[i].y);
                double bx = dbl(r.vertices[(i + 1) % 4].x), by = dbl(r.vertices[(i + 1) % 4].y);
                double ex = bx - ax, ey = by - ay, den = 8 * ey - 0.5 * ex;
                double tt, uu;
                if (den == 0) continue;
                tt = ((ax + 4) * ey - (ay - 0.1) * ex) / den;
                uu = ((ax + 4) * 0.5 - (ay - 0.1) * 8) / den;
                if (uu >= 0 && uu <= 1 && tt < best) best = tt;
            }
            expect_near(dbl(t), best, 2.0 / 65536, "rotated box t");
        }
    }
    {   /* capsule: side and end */
        pg_geom cap = make_capsule(-1, 0, 1, 0, 0.5);
        assert_true(pg_geom_raycast(&cap, vv(0.3, 3), vv(0, -4), PG_FIX_ONE, &t, &p, &n));
        expect_near(dbl(t), 2.5 / 4, 1.0 / 65536, "side t");
        PG_EXPECT_EQ(n.y, 1 << 30, "%s", "side normal");
        PG_EXPECT_EQ(p.y, fx(0.5), "%s", "side y");
        assert_true(pg_geom_raycast(&cap, vv(4, 0.3), vv(-4, 0), PG_FIX_ONE, &t, &p, &n));
        expect_near(dbl(p.x), 1 + 0.4, 2.0 / 65536, "end x");
        expect_near(ndx(n), 0.8, 1e-5, "end nx");
        expect_near(ndy(n), 0.6, 1e-5, "end ny");
        expect_near(dbl(t), (4 - 1.4) / 4, 2.0 / 65536, "end t");
        assert_false(pg_geom_raycast(&cap, vv(4, 0.6), vv(-8, 0), PG_FIX_ONE, &t, &p, &n));
    }
    {   /* segment (radius 0) from below */
        pg_geom seg = make_capsule(-1, 1, 1, 1, 0);
        assert_true(pg_geom_raycast(&seg, vv(0.5, 0), vv(0, 2), PG_FIX_ONE, &t, &p, &n));
        PG_EXPECT_EQ(t, PG_FIX_HALF, "%s", "segment t");
        PG_EXPECT_EQ(n.y, -(1 << 30), "%s", "segment normal faces the ray");
    }
}

static void test_contains(void **state)
{
    pg_geom c = make_circle(1, 1, 0.5), b = make_box(1, 0.5, 0, 0, 0.3), cap = make_capsule(-1, 0, 1, 0, 0.5);
    (void)state;
    assert_true(pg_geom_contains(&c, vv(1.3, 1.3)));
    assert_true(pg_geom_contains(&c, vv(1.5, 1)));   /* boundary */
    assert_false(pg_geom_contains(&c, vv(1.36, 1.36)));
    assert_true(pg_geom_contains(&b, vv(0, 0)));
    assert_true(pg_geom_contains(&b, vv(0.9 * cos(0.3), 0.9 * sin(0.3))));
    assert_false(pg_geom_contains(&b, vv(1.1 * cos(0.3), 1.1 * sin(0.3))));
    assert_true(pg_geom_contains(&cap, vv(1.3, 0.3)));  /* in the rounded end */
    assert_false(pg_geom_contains(&cap, vv(1.4, 0.4))); /* beyond it, inside the bounding box */
    assert_true(pg_geom_contains(&cap, vv(0, -0.49)));
    assert_false(pg_geom_contains(&cap, vv(0, -0.51)));
}

static void test_overlap(void **state)
{
    pg_geom a = make_box(0.5, 0.5, 0, 0, 0), b = make_box(0.5, 0.5, 0.99, 0, 0), touching = make_box(0.5, 0.5, 1, 0, 0);
    pg_geom far = make_box(0.5, 0.5, 1.01, 0, 0), c = make_circle(0.8, 0, 0.31), cap = make_capsule(0, 0.8, 2, 0.8, 0.29);
    (void)state;
    assert_true(pg_geom_overlap(&a, &b));
    assert_false(pg_geom_overlap(&a, &touching));
    assert_false(pg_geom_overlap(&a, &far));
    assert_true(pg_geom_overlap(&a, &c));
    assert_true(pg_geom_overlap(&c, &a));
    assert_false(pg_geom_overlap(&a, &cap));
    cap.radius = fx(0.31);
    assert_true(pg_geom_overlap(&cap, &a));
}

static void test_aabb(void **state)
{
    pg_geom cap = make_capsule(-1, 0.5, 2, -0.25, 0.25), c = make_circle(3, 4, 1.5), b = make_box(1, 0.5, 0, 0, PGT_PI / 2);
    pg_aabb box;
    (void)state;
    box = pg_geom_aabb(&cap);
    PG_EXPECT_EQ(box.lo.x, fx(-1.25), "%s", "capsule lo x");
    PG_EXPECT_EQ(box.lo.y, fx(-0.5), "%s", "capsule lo y");
    PG_EXPECT_EQ(box.hi.x, fx(2.25), "%s", "capsule hi x");
    PG_EXPECT_EQ(box.hi.y, fx(0.75), "%s", "capsule hi y");
    box = pg_geom_aabb(&c);
    PG_EXPECT_EQ(box.lo.x, fx(1.5), "%s", "circle");
    PG_EXPECT_EQ(box.hi.y, fx(5.5), "%s", "circle");
    box = pg_geom_aabb(&b);
    expect_near(dbl(box.hi.x), 0.5, 2.0 / 65536, "rotated box");
    expect_near(dbl(box.hi.y), 1.0, 2.0 / 65536, "rotated box");
}

static void test_transform(void **state)
{
    pg_geom b = make_box(1, 0.5, 2, 3, PGT_PI / 6);
    int i;
    (void)state;
    PG_EXPECT_EQ(b.count, 4, "%s", "count");
    for (i = 0; i < 4; ++i) expect_unit(b.normals[i]);
    expect_near(ndx(b.normals[1]), cos(PGT_PI / 6), 4e-9 + pgt_rot_angle_error(), "rotated normal");
    expect_near(dbl(b.vertices[2].x), 2 + cos(PGT_PI / 6) - 0.5 * sin(PGT_PI / 6), 2.0 / 65536, "vertex");
    expect_near(dbl(b.centroid.x), 2, 1.0 / 65536, "centroid");
}

/* Large coordinates (near the +-1000 m envelope) behave like small ones. */
static void test_far_from_origin(void **state)
{
    pg_geom ground = make_box(5, 0.5, 990, -995.5, 0), box = make_box(0.5, 0.5, 990.2, -994.51, 0);
    pg_manifold m;
    (void)state;
    m = collide(&ground, &box, SPEC);
    PG_EXPECT_EQ(m.count, 2, "%s", "far");
    PG_EXPECT_EQ(m.normal.y, 1 << 30, "%s", "far normal");
    PG_EXPECT_EQ(m.points[0].separation, fx(-994.51) - fx(-995) - fx(0.5), "%s", "far depth");
    {
        pg_geom c1 = make_circle(-999, 999, 1), c2 = make_circle(-997.2, 999.6, 1);
        m = collide(&c1, &c2, SPEC);
        PG_EXPECT_EQ(m.count, 1, "%s", "far circles");
        expect_near(dbl(m.points[0].separation), sqrt(1.8 * 1.8 + 0.6 * 0.6) - 2, 1.0 / 65536, "far circles sep");
    }
}


/* ---- randomised checks against a double reference ------------------------------------- */

static double rnd(pgt_rng *r, double lo, double hi) { return lo + (hi - lo) * pgt_unit(r); }

static pg_geom random_shape(pgt_rng *r, double x, double y)
{
    int kind = (int)pgt_below(r, 6);
    double ang = rnd(r, 0, 2 * PGT_PI);
    if (kind == 0) return make_circle(x, y, rnd(r, 0.05, 1.0));
    if (kind == 1) {
        /* one draw per statement: argument evaluation order is unspecified in C */
        double hw = rnd(r, 0.1, 1.5);
        double hh = rnd(r, 0.1, 1.5);
        return make_box(hw, hh, x, y, ang);
    }
    if (kind == 2 || kind == 3) {
        double h = rnd(r, 0.1, 1.2);
        double radius = kind == 2 ? rnd(r, 0.05, 0.5) : 0;
        return make_capsule(x - h * cos(ang), y - h * sin(ang), x + h * cos(ang), y + h * sin(ang), radius);
    }
    {   /* a regular-ish polygon of 3..8 vertices */
        double xy[16], rad = rnd(r, 0.2, 1.2);
        int n = 3 + (int)pgt_below(r, 6), i;
        for (i = 0; i < n; ++i) {
            double jitter = rnd(r, -0.2, 0.2);
            double a = ang + 2 * PGT_PI * (i + jitter) / n;
            xy[2 * i] = x + rad * cos(a);
            xy[2 * i + 1] = y + rad * sin(a);
        }
        /* kinds 4 and 5 are both polygons, radius 0: pogon has no rounded polygons
         * (pg_geometry in pogon.h: "a polygon is 3..8 vertices, ..., radius 0", and
         * pg__validate_geometry rejects a polygon with a radius), so none is drawn. */
        return make_poly(xy, n, 0);
    }
}

static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
    double ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey, t = l2 > 0 ? ((px - ax) * ex + (py - ay) * ey) / l2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    return hypot(px - ax - t * ex, py - ay - t * ey);
}

static double orient2(double ax, double ay, double bx, double by, double cx, double cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int inside_poly(const pg_geom *g, double px, double py)
{
    int i;
    if (g->count < 3) return 0;
    for (i = 0; i < g->count; ++i) {
        int k = (i + 1) % g->count;
        if (orient2(gx(g, i), gy(g, i), gx(g, k), gy(g, k), px, py) < 0) return 0;
    }
    return 1;
}

/* Distance between the cores (0 when they touch or overlap). */
static double core_distance(const pg_geom *a, const pg_geom *b)
{
    double best = 1e300;
    int i, j, ea = a->count == 1 ? 1 : a->count == 2 ? 1 : a->count, eb = b->count == 1 ? 1 : b->count == 2 ? 1 : b->count;
    for (i = 0; i < a->count; ++i)
        if (inside_poly(b, gx(a, i), gy(a, i))) return 0;
    for (i = 0; i < b->count; ++i)
        if (inside_poly(a, gx(b, i), gy(b, i))) return 0;
    for (i = 0; i < ea; ++i) {
        int i2 = (i + 1) % a->count;
        for (j = 0; j < eb; ++j) {
            int j2 = (j + 1) % b->count;
            double d;
            if (a->count >= 2 && b->count >= 2) {
                double o1 = orient2(gx(a, i), gy(a, i), gx(a, i2), gy(a, i2), gx(b, j), gy(b, j));
                double o2 = orient2(gx(a, i), gy(a, i), gx(a, i2), gy(a, i2), gx(b, j2), gy(b, j2));
                double o3 = orient2(gx(b, j), gy(b, j), gx(b, j2), gy(b, j2), gx(a, i), gy(a, i));
                double o4 = orient2(gx(b, j), gy(b, j), gx(b, j2), gy(b, j2), gx(a, i2), gy(a, i2));
                if (o1 * o2 < 0 && o3 * o4 < 0) return 0;
            }
            d = seg_dist(gx(a, i), gy(a, i), gx(b, j), gy(b, j), gx(b, j2), gy(b, j2));
            if (d < best) best = d;
            d = seg_dist(gx(a, i2), gy(a, i2), gx(b, j), gy(b, j), gx(b, j2), gy(b, j2));
            if (d < best) best = d;
            d = seg_dist(gx(b, j), gy(b, j), gx(a, i), gy(a, i), gx(a, i2), gy(a, i2));
            if (d < best) best = d;
            d = seg_dist(gx(b, j2), gy(b, j2), gx(a, i), gy(a, i), gx(a, i2), gy(a, i2));
            if (d < best) best = d;
        }
    }
    return best;
}

/* Largest separation over the face normals of both cores (for overlapping cores). */
static double sat_depth(const pg_geom *a, const pg_geom *b)
{
    double best = -1e300;
    int pass, i, j;
    for (pass = 0; pass < 2; ++pass) {
        const pg_geom *p = pass ? b : a, *q = pass ? a : b;
        if (p->count < 2) continue;
        for (i = 0; i < p->count; ++i) {
            int k = (i + 1) % p->count;
            double ex = gx(p, k) - gx(p, i), ey = gy(p, k) - gy(p, i), l = hypot(ex, ey), nx = ey / l, ny = -ex / l, s = 1e300;
            for (j = 0; j < q->count; ++j) {
                double d = (gx(q, j) - gx(p, i)) * nx + (gy(q, j) - gy(p, i)) * ny;
                if (d < s) s = d;
            }
            if (s > best) best = s;
        }
    }
    if (a->count == 1 && b->count == 1) best = 0;
    return best;
}

static pg_geom shifted(const pg_geom *g, pg_fix dx, pg_fix dy)
{
    pg_geom h = *g;
    int i;
    for (i = 0; i < g->count; ++i) {
        h.vertices[i].x += dx;
        h.vertices[i].y += dy;
    }
    h.centroid.x += dx;
    h.centroid.y += dy;
    return h;
}

/* ---- what collide.c promises, for the randomised checks (distances in LSB = 2^-16 m) ---- */

#define REF_TOL 33                          /* PG__REF_TOLERANCE in collide.c, LSB */
#define HALF_SQRT2 0.70710678118654752440   /* a point rounded per component moves <= this */

/* Bounds on rounding, derived from collide.c (every rounding is to nearest, <= 1/2 LSB):
 *
 * VERTEX_POINT  a vertex-to-vertex point (and circle-circle, and a circle in a vertex's
 *   region) is va + ((vb - va) + (rA - rB) n) / 2, rounded per component (<= HALF_SQRT2);
 *   its separation uses dist = the nearest integer to |vb - va| (<= 1/2) and n, within
 *   2 Q30 LSB of the unit vector (test_dir_normalize) times |vb - va| < 2^18 LSB (< 1e-3).
 *   So p - (s/2 + rA) n = va + (|vb - va| u - dist n) / 2 + rounding lies within
 *   1/4 + HALF_SQRT2 + 1e-3 of va, and the same for vb.
 * FACE_ETA  a face of a box placed by pg_geom_transform has exact rotated normals but
 *   vertices rounded per component, so (v2 - v1) . n, exactly 0 before rounding, is at
 *   most sqrt(2): the face's line and collide.c's face plane (stored normal, mean offset
 *   (v1 + v2) . n / 2) cross at the face's middle and are at most HALF_SQRT2 apart within
 *   the face. (Faces of make_poly take their normals from the edge: about 1e-4 LSB.)
 * REF_POINT  the point of the reference core under a manifold point is, per collide.c,
 *   either the incident vertex's core point minus its separation along n (separation
 *   rounded, 1/2; the vertex is kept only when its rounded tangential offset is >= 0, so
 *   it is at most 1/2 beyond the face's end: sqrt(1/4 + FACE_ETA^2) from the face), or
 *   v11 + round(2 eta) / 2 n on a side plane (FACE_ETA + 1/4); then the point itself is
 *   rounded (HALF_SQRT2): at most 1/2 + sqrt(3/4) + HALF_SQRT2 from the face segment.
 * INC_POINT  the point of the incident core: the vertex itself plus the point's rounding
 *   (HALF_SQRT2), or the incident edge cut at a side plane: the cut is interpolated
 *   between the two incident vertices' rounded (tangential, normal) coordinates, a point
 *   of the segment between them and so within HALF_SQRT2 of the true edge, rounded by the
 *   division (1/2), offset by round(2 eta) / 2 - eta (1/4), and the point is rounded
 *   (HALF_SQRT2).
 * SEPARATION_LOW  a reported separation is never below the distance by more than: the
 *   face path, the incident vertices' separations rounded (1/2) and the cut interpolated
 *   between them and rounded (1/2), measured from the face plane, which is within
 *   FACE_ETA of the face's line where the closest point is; vertex to vertex, 1/2. This
 *   needs the distance to be what collide.c measures (see the apart check in
 *   test_random_pairs for where its tolerances make it measure less). */
#define VERTEX_POINT_TOL (0.25 + HALF_SQRT2 + 1e-3)
#define REF_POINT_TOL (0.5 + 0.86602540378443864676 + HALF_SQRT2 + 1e-3)
#define INC_POINT_TOL (0.75 + 2 * HALF_SQRT2 + 1e-3)
#define SEPARATION_LOW_TOL (1.0 + HALF_SQRT2 + 1e-3)

/* OVERSTATEMENT  how far a reported separation of separated cores can exceed the
 *   distance (collide.c, SEPARATED CORES). The reference face's incident edge holds the
 *   incident core's vertex deepest along the face normal, whose separation from the face's
 *   mean plane is the face's SAT separation s, at most the distance + FACE_ETA. collide.c
 *   keeps that vertex as a point (rounded: s + 1/2), or cuts the edge at the side plane
 *   it lies beyond, and keeps the cut only while its separation exceeds the vertex's
 *   rounded one by at most PG__DIP_TOLERANCE (1 LSB: s + 1/2 + 1), or the exact distance
 *   from the face's vertex on that plane to the edge beyond it by at most that (+ the
 *   edge's FACE_ETA, when measured to the edge's line). Otherwise (and when the edge misses
 *   the face) the closest features decide, vertex to vertex (the distance to 1/2) or a
 *   vertex against a face's interior (s + 1/2 of that face). So the bound is
 *   DIP_TOL + 1/2 + FACE_ETA: 2.21 LSB for boxes placed by pg_geom_transform, 1.5 for
 *   faces whose normals are exact to far below 1 LSB over their length (make_poly). */
#define DIP_TOL 1.0 /* PG__DIP_TOLERANCE in collide.c, LSB */
#define OVERSTATE_TOL (DIP_TOL + 0.5 + HALF_SQRT2 + 1e-3)
#define OVERSTATE_TOL_EXACT_NORMALS (DIP_TOL + 0.5 + 1e-3)

/* Twice the separation of q's vertices from p's face i as collide.c measures it (stored
 * normal, from the face's mean offset), exactly: Q46 x 2 (|coordinates| < 2^20 raw here). */
static int64_t face_sep2(const pg_geom *p, int32_t i, const pg_geom *q)
{
    pg_dir n = p->normals[i];
    pg_vec2 v1 = p->vertices[i], v2 = p->vertices[(i + 1) % p->count];
    int64_t lo = INT64_MAX, off2 = (int64_t)v1.x * n.x + (int64_t)v1.y * n.y + (int64_t)v2.x * n.x + (int64_t)v2.y * n.y;
    int32_t j;
    for (j = 0; j < q->count; ++j) {
        int64_t d = (int64_t)q->vertices[j].x * n.x + (int64_t)q->vertices[j].y * n.y;
        if (d < lo) lo = d;
    }
    return 2 * lo - off2;
}

static int64_t best_face_sep2(const pg_geom *p, const pg_geom *q)
{
    int64_t best = INT64_MIN;
    int32_t i;
    for (i = 0; i < p->count; ++i) {
        int64_t s = face_sep2(p, i, q);
        if (s > best) best = s;
    }
    return best;
}

/* Distances (LSB) from (x, y) (raw units) to g's core features. */
static double dist_to_vertex(const pg_geom *g, int32_t i, double x, double y)
{
    return hypot(x - g->vertices[i].x, y - g->vertices[i].y);
}

static double dist_to_edge(const pg_geom *g, int32_t i, double x, double y)
{
    int32_t k = (i + 1) % g->count;
    return seg_dist(x, y, g->vertices[i].x, g->vertices[i].y, g->vertices[k].x, g->vertices[k].y);
}

static double dist_to_edge_line(const pg_geom *g, int32_t i, double x, double y)
{
    int32_t k = (i + 1) % g->count;
    double ex = (double)g->vertices[k].x - g->vertices[i].x, ey = (double)g->vertices[k].y - g->vertices[i].y;
    return fabs(orient2(g->vertices[i].x, g->vertices[i].y, g->vertices[k].x, g->vertices[k].y, x, y)) / hypot(ex, ey);
}

/* From a point of the incident core to the edges at vertex iv (the point is that vertex
 * or lies on the incident edge, which runs into or out of iv). */
static double dist_to_incident(const pg_geom *g, int32_t iv, double x, double y)
{
    double d1, d2;
    if (g->count == 1) return dist_to_vertex(g, 0, x, y);
    d1 = dist_to_edge(g, iv, x, y);
    d2 = dist_to_edge(g, (iv + g->count - 1) % g->count, x, y);
    return d1 < d2 ? d1 : d2;
}

/* Rounded tangential offsets (LSB) of w past the start of p's face i and before its end,
 * along the face's stored direction, as collide.c clips with them. */
static int64_t past_start(const pg_geom *p, int32_t i, pg_vec2 w)
{
    pg_dir n = p->normals[i];
    pg_vec2 e = p->vertices[i];
    return pg__round_shift64(((int64_t)w.x - e.x) * -(int64_t)n.y + ((int64_t)w.y - e.y) * n.x, 30);
}

static int64_t before_end(const pg_geom *p, int32_t i, pg_vec2 w)
{
    pg_dir n = p->normals[i];
    pg_vec2 e = p->vertices[(i + 1) % p->count];
    return pg__round_shift64(((int64_t)e.x - w.x) * -(int64_t)n.y + ((int64_t)e.y - w.y) * n.x, 30);
}

/* Does the edge w1 w2 miss p's face i, both ends beyond the same side plane? */
static int misses_face(const pg_geom *p, int32_t i, pg_vec2 w1, pg_vec2 w2)
{
    return (past_start(p, i, w1) < 0 && past_start(p, i, w2) < 0) || (before_end(p, i, w1) < 0 && before_end(p, i, w2) < 0);
}

/* Each point of m lies midway between the two surfaces (geom.h, collide.c): collide.c
 * places it halfway between a point of A's surface and a point of B's, which are the
 * separation apart along the normal and are core points pushed out by the radii along n:
 *     qa = p - (s/2 + rA) n  is a point of A's core,   qb = p + (s/2 + rB) n  of B's,
 * at the features the id names: on the reference face (kinds 0, 1), at the incident
 * vertex or on the incident edge cut next to it, or at the two vertices (kind 2), within
 * the rounding derived above. (Checking instead that p is within |s|/2 of both surfaces
 * would be wrong for a tilted capsule: collide.c takes its surface point as the core
 * point - r n, which is inside the capsule.) One case is designed to leave the face: when
 * the incident edge misses the face (both ends beyond one side plane; collide.c keeps
 * "one point at its deeper vertex"), the point is over the face's LINE beyond its end. */
static unsigned long long midway_seed; /* named in expect_midway's messages */

static void expect_midway(const pg_geom *a, const pg_geom *b, const pg_manifold *m, int iter)
{
    double nx = m->normal.x / Q30, ny = m->normal.y / Q30;
    int32_t i;
    for (i = 0; i < m->count; ++i) {
        const pg_manifold_point *mp = &m->points[i];
        double s = mp->separation, ka = s / 2 + a->radius, kb = s / 2 + b->radius;
        double q[2][2];
        uint32_t kind = mp->id >> 16;
        int32_t fa = (int32_t)((mp->id >> 8) & 0xFFu), fb = (int32_t)(mp->id & 0xFFu);
        q[0][0] = mp->point.x - ka * nx;
        q[0][1] = mp->point.y - ka * ny;
        q[1][0] = mp->point.x + kb * nx;
        q[1][1] = mp->point.y + kb * ny;
        if (kind == 2) {
            PG_EXPECT_LE(dist_to_vertex(a, fa, q[0][0], q[0][1]), VERTEX_POINT_TOL, "seed %llu iter %d point %d: A's vertex %d", midway_seed, iter, i, fa);
            PG_EXPECT_LE(dist_to_vertex(b, fb, q[1][0], q[1][1]), VERTEX_POINT_TOL, "seed %llu iter %d point %d: B's vertex %d", midway_seed, iter, i, fb);
        } else {
            /* kind 0: A's face fa is the reference, B's vertex fb incident; kind 1 the other way */
            const pg_geom *ref = kind == 0 ? a : b, *inc = kind == 0 ? b : a;
            const double *qr = q[kind == 0 ? 0 : 1], *qi = q[kind == 0 ? 1 : 0];
            int32_t f = kind == 0 ? fa : fb, iv = kind == 0 ? fb : fa, c = inc->count;
            int miss = m->count == 1 && c >= 2 && dist_to_vertex(inc, iv, qi[0], qi[1]) <= HALF_SQRT2 + 1e-3 &&
                       (misses_face(ref, f, inc->vertices[iv], inc->vertices[(iv + 1) % c]) ||
                        misses_face(ref, f, inc->vertices[iv], inc->vertices[(iv + c - 1) % c]));
            PG_EXPECT_LE(kind, 1, "seed %llu iter %d point %d: id %x", midway_seed, iter, i, mp->id);
            PG_EXPECT_LE(dist_to_edge_line(ref, f, qr[0], qr[1]), REF_POINT_TOL, "seed %llu iter %d point %d id %x: off the reference face's line",
                         midway_seed, iter, i, mp->id);
            if (!miss)
                PG_EXPECT_LE(dist_to_edge(ref, f, qr[0], qr[1]), REF_POINT_TOL, "seed %llu iter %d point %d id %x: beyond the reference face", midway_seed, iter, i, mp->id);
            PG_EXPECT_LE(dist_to_incident(inc, iv, qi[0], qi[1]), INC_POINT_TOL, "seed %llu iter %d point %d id %x: off the incident feature", midway_seed, iter, i, mp->id);
        }
    }
}

/* The id of the same point with the arguments swapped: kinds 0 and 1 trade places, the
 * two feature bytes too. */
static uint32_t swapped_id(uint32_t id)
{
    uint32_t kind = id >> 16;
    return (kind < 2 ? kind ^ 1u : kind) << 16 | (id & 0xFFu) << 8 | ((id >> 8) & 0xFFu);
}

/* Regression (random pair 6854 of test_random_pairs): a rotated box A and an octagon B,
 * apart by 354 LSB. The closest points are A's vertex 1 and the interior of B's face 6,
 * which is tilted by about 9 degrees against A's face 0. B's face separates them by
 * 354 LSB, A's by 347: within the reference hysteresis, so A's face used to stay the
 * reference and B's incident edge was clipped at the side plane through A's vertex 1,
 * 358 LSB from A: more than the distance. Apart cores now take the better face. */
static void test_apart_tilted_faces(void **state)
{
    static const int32_t av[4][2] = {{88644, -43694}, {-73446, 66126}, {-88644, 43694}, {73446, -66126}};
    static const int32_t an[4][2] = {{602266598, 888929946}, {-888929946, 602266598}, {-602266598, -888929946}, {888929946, -602266598}};
    static const int32_t bv[8][2] = {{43243, 73882}, {55289, 116108}, {25554, 173031}, {-16123, 187269},
                                     {-75086, 159675}, {-90975, 115490}, {-73310, 66453}, {-19737, 41011}};
    pg_geom a = blank(), b = blank();
    pg_manifold m, w;
    double ref, got = 1e300, got2 = 1e300;
    int i;
    (void)state;
    a.count = 4;
    for (i = 0; i < 4; ++i) {
        a.vertices[i] = pg_v2(av[i][0], av[i][1]);
        a.normals[i].x = an[i][0];
        a.normals[i].y = an[i][1];
    }
    b.count = 8;
    for (i = 0; i < 8; ++i) b.vertices[i] = pg_v2(bv[i][0], bv[i][1]);
    /* A is a box placed by pg_geom_transform (centroid 0): its own normals, as given */
    set_normals(&b);
    ref = core_distance(&a, &b);
    expect_near(ref, 0.005397413, 1e-8, "reference distance");
    m = collide(&a, &b, fx(0.1));
    PG_EXPECT_LE(1, m.count, "%s", "contact");
    expect_unit(m.normal);
    for (i = 0; i < m.count; ++i)
        if (dbl(m.points[i].separation) < got) got = dbl(m.points[i].separation);
    /* a vertex against a face's interior, cores apart by more than PG__REF_TOLERANCE:
     * the separation is the distance within rounding */
    PG_EXPECT_LE(got - ref, 3.0 / 65536, "separation %.6f reference %.6f", got, ref);
    PG_EXPECT_LE(-SEPARATION_LOW_TOL / 65536, got - ref, "separation %.9f reference %.9f", got, ref);
    /* B's face 6 is the reference: the normal points from A to B along -n6 */
    PG_EXPECT_EQ(m.normal.x, -b.normals[6].x, "%s", "normal x");
    PG_EXPECT_EQ(m.normal.y, -b.normals[6].y, "%s", "normal y");
    w = collide(&b, &a, fx(0.1));
    PG_EXPECT_LE(1, w.count, "%s", "swapped contact");
    for (i = 0; i < w.count; ++i)
        if (dbl(w.points[i].separation) < got2) got2 = dbl(w.points[i].separation);
    PG_EXPECT_LE(got2 - ref, 3.0 / 65536, "swapped separation %.6f reference %.6f", got2, ref);
    PG_EXPECT_LE(-SEPARATION_LOW_TOL / 65536, got2 - ref, "swapped separation %.9f reference %.9f", got2, ref);
}

static pg_geom geom_of(int32_t count, const int32_t (*v)[2], const int32_t (*n)[2], pg_fix radius)
{
    pg_geom g = blank();
    int32_t i;
    g.count = count;
    for (i = 0; i < count; ++i) {
        g.vertices[i] = pg_v2(v[i][0], v[i][1]);
        g.normals[i].x = n[i][0];
        g.normals[i].y = n[i][1];
    }
    g.radius = radius;
    return g;
}

/* The smallest separation of a manifold, m. */
static double min_separation(const pg_manifold *m)
{
    double got = 1e300;
    int i;
    for (i = 0; i < m->count; ++i)
        if (dbl(m->points[i].separation) < got) got = dbl(m->points[i].separation);
    return got;
}

/* Regression (seed 11, pair 974022 of test_random_pairs): a triangle A and a box B,
 * 6163.7 LSB apart, the closest points A's vertex 0 and B's vertex 0. B's face 0 is the
 * reference; A's incident edge 0 -> 1 ends at vertex 0, a few LSB beyond the face's end,
 * and rises steeply from there over the face: clipped at the side plane it reported 6210
 * (the mirrored pair, 6164). */
static void test_vertex_beyond_face_polygons(void **state)
{
    static const int32_t av[3][2] = {{49436, 38831}, {-62582, -5942}, {41545, -47178}};
    static const int32_t an[3][2] = {{-398515268, 997049189}, {-395347014, -998309693}, {1069251114, -98099740}};
    static const int32_t bv[4][2] = {{-41530, 105135}, {52761, 44021}, {71596, 73081}, {-22695, 134195}};
    static const int32_t bn[4][2] = {{-584007579, -901030882}, {901030882, -584007579}, {584007579, 901030882}, {-901030882, 584007579}};
    pg_geom a = geom_of(3, av, an, 0), b = geom_of(4, bv, bn, 0), ma = mirror(&a), mb = mirror(&b);
    pg_manifold m = collide(&a, &b, fx(0.1)), w = collide(&b, &a, fx(0.1)), r = collide(&ma, &mb, fx(0.1));
    double ref = core_distance(&a, &b);
    (void)state;
    expect_near(ref * 65536, 6163.7, 0.05, "reference distance (LSB)");
    PG_EXPECT_LE(1, m.count, "%s", "contact");
    PG_EXPECT_LE((min_separation(&m) - ref) * 65536, OVERSTATE_TOL, "%s", "overstated (LSB)");
    PG_EXPECT_LE((ref - min_separation(&m)) * 65536, SEPARATION_LOW_TOL, "%s", "understated (LSB)");
    PG_EXPECT_LE((min_separation(&w) - ref) * 65536, OVERSTATE_TOL, "%s", "swapped: overstated (LSB)");
    PG_EXPECT_LE((ref - min_separation(&w)) * 65536, SEPARATION_LOW_TOL, "%s", "swapped: understated (LSB)");
    PG_EXPECT_EQ(r.normal.x, -m.normal.x, "%s", "mirror");
    PG_EXPECT_EQ(r.normal.y, m.normal.y, "%s", "mirror");
    expect_matching(&m, &r, 1, 0, "mirror");
    expect_midway(&a, &b, &m, -1);
}

/* Regression (seed 11, pair 28851 of test_random_pairs): a box A and a capsule B whose
 * cores are apart; the capsule's end and the box's vertex 0 are nearly as close as the
 * end and the interior of the box's face 0. pg__point_segment measured the perpendicular
 * distance from the face's first vertex, which mirroring changes (the face is reversed):
 * 28142 against 28141 (squared distances, rounded), so one side chose vertex to vertex
 * (one point, separation 2208) and the mirror image the face (two points, another
 * normal). Distances to a face's interior are now measured from its mean plane. */
static void test_mirror_near_tie(void **state)
{
    static const int32_t av[4][2] = {{117301, -34030}, {59605, 106605}, {-117301, 34030}, {-59605, -106605}};
    static const int32_t an[4][2] = {{993394023, 407541186}, {-407541186, 993394023}, {-993394023, -407541186}, {407541186, -993394023}};
    static const int32_t bv[2][2] = {{127895, -60101}, {15859, -109184}};
    static const int32_t bn[2][2] = {{-430871397, 983499539}, {430871397, -983499539}};
    pg_geom a = geom_of(4, av, an, 0), b = geom_of(2, bv, bn, 25933), ma = mirror(&a), mb = mirror(&b);
    pg_manifold m = collide(&a, &b, fx(0.1)), r = collide(&ma, &mb, fx(0.1));
    double ref = core_distance(&a, &b) - dbl(b.radius);
    (void)state;
    PG_EXPECT_LE(1, m.count, "%s", "contact");
    PG_EXPECT_LE((min_separation(&m) - ref) * 65536, OVERSTATE_TOL, "%s", "overstated (LSB)");
    PG_EXPECT_LE((ref - min_separation(&m)) * 65536, SEPARATION_LOW_TOL, "%s", "understated (LSB)");
    PG_EXPECT_EQ(r.normal.x, -m.normal.x, "%s", "mirror");
    PG_EXPECT_EQ(r.normal.y, m.normal.y, "%s", "mirror");
    expect_matching(&m, &r, 1, 0, "mirror");
    expect_midway(&a, &b, &m, -1);
}

/* Regression (near pairs, seed 3, pair 175266): a hexagon A and a capsule B whose end lies
 * 77 LSB from A's vertex 4, 0.6 LSB inside A's face 4. The capsule's edge leaves the face
 * right there, so the clip's two ends (the end itself, and the cut at the side plane
 * through vertex 4) round to the same point. The second one used to be dropped: the cut
 * (separation -27390) here, the end (-27392) in the mirror image, where the two ends
 * trade places. The deeper one is kept now. */
static void test_mirror_coincident_ends(void **state)
{
    static const int32_t av[6][2] = {{47009, -24922}, {45296, 27915}, {-12965, 51603}, {-48158, 22622}, {-49534, -19427}, {12710, -51666}};
    static const int32_t an[6][2] = {{1073177971, 34792927}, {404417058, 994669969}, {-682564827, 828870775},
                                     {-1073167381, 35118036}, {-493831170, -953442332}, {660243837, -846758277}};
    static const int32_t bv[2][2] = {{-49569, -19496}, {-115871, -68278}};
    static const int32_t bn[2][2] = {{-636332860, 864871086}, {636332860, -864871086}};
    pg_geom a = geom_of(6, av, an, 0), b = geom_of(2, bv, bn, 27469), ma = mirror(&a), mb = mirror(&b);
    pg_manifold m = collide(&a, &b, fx(0.1)), r = collide(&ma, &mb, fx(0.1));
    double ref = core_distance(&a, &b) - dbl(b.radius);
    (void)state;
    PG_EXPECT_EQ(m.count, 1, "%s", "one point");
    PG_EXPECT_EQ(m.points[0].separation, -27392, "%s", "the deeper end");
    PG_EXPECT_EQ(m.points[0].id, 0x400u, "%s", "A's face 4, B's vertex 0 (the end itself)");
    PG_EXPECT_LE((min_separation(&m) - ref) * 65536, OVERSTATE_TOL, "%s", "overstated (LSB)");
    PG_EXPECT_LE((ref - min_separation(&m)) * 65536, SEPARATION_LOW_TOL, "%s", "understated (LSB)");
    PG_EXPECT_EQ(r.normal.x, -m.normal.x, "%s", "mirror");
    PG_EXPECT_EQ(r.normal.y, m.normal.y, "%s", "mirror");
    expect_matching(&m, &r, 1, 0, "mirror");
    expect_midway(&a, &b, &m, -1);
}

/* A plank lying across the edge of a box, tilted down towards its overhang by tau and
 * apart by g at the box's corner. The plank's bottom edge, clipped at the side plane
 * through the corner, is cut g above it, while the plank's overhanging corner lies
 * 0.6 tan(tau) lower, beyond the box: the cut "dips" (collide.c) by far more than
 * PG__DIP_TOLERANCE, but the edge runs on past the corner rather than towards it, so the
 * corner is as far from the edge as the cut (to g (1 - cos tau), far below 1 LSB) and the
 * face contact stays: A's face, kept by the hysteresis (B's is better by less than
 * PG__REF_TOLERANCE), two points, no switch of reference between resting and hovering.
 * (With the arguments swapped the plank's face is A's, and the better one anyway.) */
static void test_overhang_keeps_face(void **state)
{
    static const double taus[] = {0.0001, 0.0003, 0.0005}, gaps[] = {2, 10, 30};
    int t, k, order;
    (void)state;
    for (t = 0; t < 3; ++t)
        for (k = 0; k < 3; ++k) {
            double tau = taus[t], g = gaps[k] / 65536, xc = 0.6;
            double yc = g + 0.1 * cos(tau) + (0.5 - xc - 0.1 * sin(tau)) * tan(tau);
            pg_geom a = make_box(0.5, 0.5, 0, -0.5, 0), b = make_box(0.5, 0.1, xc, yc, -tau);
            double ref = core_distance(&a, &b);
            for (order = 0; order < 2; ++order) {
                pg_manifold m = order ? collide(&b, &a, SPEC) : collide(&a, &b, SPEC);
                int i;
                PG_EXPECT_EQ(m.count, 2, "tau %.4f gap %.0f LSB order %d: two points", tau, gaps[k], order);
                /* A's face: the box's top, or (arguments swapped) the plank's bottom */
                PG_EXPECT_EQ(m.normal.x, order ? b.normals[0].x : 0, "tau %.4f gap %.0f LSB order %d: A's face normal", tau, gaps[k], order);
                PG_EXPECT_EQ(m.normal.y, order ? b.normals[0].y : 1 << 30, "tau %.4f gap %.0f LSB order %d: A's face normal", tau, gaps[k],
                             order);
                for (i = 0; i < m.count; ++i)
                    PG_EXPECT_EQ(m.points[i].id >> 16, 0, "tau %.4f gap %.0f LSB order %d: A's face is the reference", tau, gaps[k], order);
                PG_EXPECT_LE((min_separation(&m) - ref) * 65536, OVERSTATE_TOL, "tau %.4f gap %.0f LSB order %d: overstated (LSB)", tau,
                             gaps[k], order);
                PG_EXPECT_LE((ref - min_separation(&m)) * 65536, SEPARATION_LOW_TOL, "tau %.4f gap %.0f LSB order %d: understated (LSB)",
                             tau, gaps[k], order);
                expect_midway(order ? &b : &a, order ? &a : &b, &m, -1);
            }
        }
}

/* A segment or capsule end just beyond the end of another one's face (README, "what is
 * left", used to say the gap could be overstated by up to ~30 LSB there; it was not
 * bounded). A runs from (0, 0) to (1, 0) and B's end w lies delta beyond A's end at the
 * height h, B leaning back over A at the tilt theta. Clipping B's edge at A's side plane
 * x = 1 gives a point at the height h + delta tan(theta), while the distance is
 * sqrt(h^2 + delta^2) (or, when B's edge passes closer to A's end than w does, that
 * distance). collide.c used to count a vertex up to PG__REF_TOLERANCE (33 LSB) beyond a
 * face's end as over the face and report that cut: 57 LSB too much at 60 degrees, 1890 at
 * 89, and at 89.8 degrees with delta = 33 LSB no contact at all although the gap is
 * 0.03 m, inside the 0.1 m speculative distance. Now a cut is kept only while it lies at
 * most PG__DIP_TOLERANCE above the vertex beyond it, or at most that farther from A's end
 * than the rest of B's edge (then the separation is at most the distance +
 * OVERSTATE_TOL_EXACT_NORMALS: 1.5 LSB for these faces, whose normals come from the
 * edges); otherwise the closest features decide and the separation is the distance to
 * 1/2 LSB (the nearest integer square root, or a rounded separation from a face whose
 * plane passes through its vertices to 1e-4 LSB; the double reference is exact to far
 * below that). Heights 0.03 m (cores apart by more than PG__REF_TOLERANCE, the better
 * face is the reference) and 20 LSB (within it: A's face stays the reference under the
 * hysteresis unless B's is better by more than 33 LSB). */
static void check_vertex_gap(const double *tilts, int ntilts, double *worst)
{
    static const int32_t deltas[] = {0, 1, 10, REF_TOL, REF_TOL + 1, 2 * REF_TOL};
    static const double radii[] = {0, 0.01}, heights[] = {0.03, 20.0 / 65536};
    int t, k, r, o, order;
    midway_seed = 0;
    for (t = 0; t < ntilts; ++t)
        for (k = 0; k < (int)(sizeof deltas / sizeof deltas[0]); ++k)
            for (r = 0; r < 2; ++r)
                for (o = 0; o < 2; ++o) {
                    double th = tilts[t] * PGT_PI / 180.0, h = heights[o], wx = 1 + deltas[k] / 65536.0;
                    pg_geom a = make_capsule(0, 0, 1, 0, radii[r]), b = make_capsule(wx, h, wx - cos(th), h + sin(th), radii[r]);
                    double ref = core_distance(&a, &b) - dbl(a.radius) - dbl(b.radius);
                    /* The cut lies delta tan(theta) above w: past 2.5 LSB the rounded dip
                     * exceeds PG__DIP_TOLERANCE for sure, and B leaning away (theta >= 90
                     * degrees) misses A's face. With the cores apart by more than
                     * PG__REF_TOLERANCE A's face is the better one, so the closest features
                     * decide: exact to 1/2 LSB. (Within it, B's face, the better one, is
                     * tried first, and its clip may dip by up to PG__DIP_TOLERANCE.) */
                    int exact = o == 0 && deltas[k] > 0 && (th >= PGT_PI / 2 || deltas[k] * tan(th) > 2.5);
                    PG_EXPECT_EQ(b.vertices[0].x, fx(1) + deltas[k], "%s", "w lies delta beyond A's end");
                    for (order = 0; order < 2; ++order) {
                        pg_manifold m = order ? collide(&b, &a, fx(0.1)) : collide(&a, &b, fx(0.1));
                        double got = 1e300, err;
                        int i;
                        PG_EXPECT_LE(1, m.count, "tilt %.1f deg, delta %d LSB, height %.6f, radius %.2f, order %d: no contact, gap %.6f",
                                     tilts[t], deltas[k], h, radii[r], order, ref);
                        for (i = 0; i < m.count; ++i)
                            if (dbl(m.points[i].separation) < got) got = dbl(m.points[i].separation);
                        err = (got - ref) * 65536.0;
                        if (m.count > 0 && err > *worst) *worst = err;
                        PG_EXPECT_LE(err, exact ? 0.5 + 1e-3 : OVERSTATE_TOL_EXACT_NORMALS,
                                     "tilt %.1f deg, delta %d LSB, height %.6f, radius %.2f, order %d: overstated gap (LSB)", tilts[t],
                                     deltas[k], h, radii[r], order);
                        PG_EXPECT_LE(-err, exact ? 0.5 + 1e-3 : SEPARATION_LOW_TOL,
                                     "tilt %.1f deg, delta %d LSB, height %.6f, radius %.2f, order %d: understated gap (LSB)", tilts[t],
                                     deltas[k], h, radii[r], order);
                        expect_midway(order ? &b : &a, order ? &a : &b, &m, -1);
                    }
                }
}

static void test_segment_vertex_gap(void **state)
{
    static const double tilts[] = {10, 20, 30, 40};
    double worst = 0;
    (void)state;
    check_vertex_gap(tilts, 4, &worst);
    print_message("segment vertex gap: worst overstatement %.2f LSB (bound %.2f)\n", worst, OVERSTATE_TOL_EXACT_NORMALS);
}

static void test_segment_vertex_gap_steep(void **state)
{
    static const double tilts[] = {45, 60, 80, 89, 89.8, 90, 90.2, 100, 135, 170};
    double worst = 0;
    (void)state;
    check_vertex_gap(tilts, 10, &worst);
    print_message("segment vertex gap, steep: worst overstatement %.2f LSB (bound %.2f)\n", worst, OVERSTATE_TOL_EXACT_NORMALS);
}

/* Pairs per seed in test_random_pairs and test_random_near_pairs: about 3 s in all in a
 * release build, a quarter as many without NDEBUG (debug and sanitizer builds are some 10
 * times slower). Build with -DPGT_RANDOM_PAIRS=N -DPGT_NEAR_PAIRS=M to search longer. */
#ifndef PGT_RANDOM_PAIRS
#ifdef NDEBUG
#define PGT_RANDOM_PAIRS 250000
#else
#define PGT_RANDOM_PAIRS 62500
#endif
#endif
#ifndef PGT_NEAR_PAIRS
#ifdef NDEBUG
#define PGT_NEAR_PAIRS 25000
#else
#define PGT_NEAR_PAIRS 6250
#endif
#endif

typedef struct pair_stats {
    int checked, touching, tolerant, exact_swaps;
    double worst_apart, worst_over, worst_deep; /* m */
} pair_stats;

/* Every check of one pair against the double reference, its mirror image, a translated
 * copy (the shift drawn from rng) and the swapped pair. */
static void check_pair(const pg_geom *a, const pg_geom *b, pgt_rng *rng, unsigned long long seed, int iter, pair_stats *st)
{
    pg_fix spec = fx(0.1);
    pg_manifold m = collide(a, b, spec), w;
    double radii = dbl(a->radius) + dbl(b->radius), d = core_distance(a, b), ref, got = 1e300;
    /* collide.c's own quantities, only to tell which of its tolerances can act: two
     * polygons (segments and capsules included) have SAT face separations, and the
     * reference is the better face outright ("far") once the better one exceeds
     * PG__REF_TOLERANCE */
    int poly_pair = a->count >= 2 && b->count >= 2, far;
    int64_t sa2 = poly_pair ? best_face_sep2(a, b) : 0, sb2 = poly_pair ? best_face_sep2(b, a) : 0;
    double sat = (double)(sa2 > sb2 ? sa2 : sb2) / 2147483648.0 / 65536.0; /* m */
    int i;
    far = poly_pair && (sa2 > sb2 ? sa2 : sb2) > ((int64_t)REF_TOL << 31);
    ref = d > 0 ? d - radii : sat_depth(a, b) - radii;
    /* reported separations lie within [distance - SEPARATION_LOW_TOL, distance +
     * OVERSTATE_TOL] when the cores are apart (below), so a contact is never dropped
     * within the speculative distance less OVERSTATE_TOL */
    if (ref > 0.1 + SEPARATION_LOW_TOL / 65536) {
        PG_EXPECT_EQ(m.count, 0, "seed %llu iter %d: reference separation %.9f", seed, iter, ref);
        return;
    }
    if (ref <= 0.1 - OVERSTATE_TOL / 65536) PG_EXPECT_LE(1, m.count, "seed %llu iter %d: no contact, reference %.9f", seed, iter, ref);
    if (m.count == 0) return;
    ++st->checked;
    expect_unit(m.normal);
    for (i = 0; i < m.count; ++i)
        if (dbl(m.points[i].separation) < got) got = dbl(m.points[i].separation);
    if (d > 0) {
        /* apart: the separation is the distance, at most SEPARATION_LOW_TOL below it
         * (rounding, derived above) and at most OVERSTATE_TOL above it, unless
         * collide.c's reference hysteresis acts: cores within PG__REF_TOLERANCE keep
         * A's face while B's is better by up to that, and of a segment's face (which
         * has no inside) an incident vertex can then lie on the far side of the line
         * although the cores are apart. Then the separation is still at least the
         * reference face's, less 1 (two roundings), and the reference face separates
         * by at least sat - PG__REF_TOLERANCE. */
        double err = got - ref, low = ref;
        if (poly_pair && !far) {
            low = sat - REF_TOL / 65536.0 - radii;
            if (low > ref) low = ref;
            ++st->tolerant;
        }
        if (fabs(err) > st->worst_apart) st->worst_apart = fabs(err);
        if (err > st->worst_over) st->worst_over = err;
        if (err > OVERSTATE_TOL / 65536 || got < low - SEPARATION_LOW_TOL / 65536) {
            print_error("seed %llu iter %d: apart, separation %.9f reference %.9f lower bound %.9f (counts %d %d)\n", seed, iter, got, ref, low,
                        a->count, b->count);
            fail();
        }
    } else {
        /* overlapping: the depth along the best face axis, A preferred within 33 LSB */
        double err = got - ref;
        ++st->touching;
        if (fabs(err) > st->worst_deep) st->worst_deep = fabs(err);
        if (err > 3.0 / 65536 || err < -40.0 / 65536) {
            print_error("seed %llu iter %d: overlap, separation %.6f reference %.6f (counts %d %d)\n", seed, iter, got, ref, a->count, b->count);
            fail();
        }
    }
    expect_midway(a, b, &m, iter);
    /* exact mirror symmetry */
    {
        pg_geom ma = mirror(a), mb = mirror(b);
        char what[64];
        snprintf(what, sizeof what, "mirror seed %llu iter %d", seed, iter);
        w = collide(&ma, &mb, spec);
        PG_EXPECT_EQ(w.normal.x, -m.normal.x, "%s", what);
        PG_EXPECT_EQ(w.normal.y, m.normal.y, "%s", what);
        expect_matching(&m, &w, 1, 0, what);
    }
    /* exact translation invariance */
    {
        pg_fix dx = (pg_fix)(pgt_below(rng, 2 * 900 * 65536u) - 900 * 65536), dy = (pg_fix)(pgt_below(rng, 2 * 900 * 65536u) - 900 * 65536);
        pg_geom ta = shifted(a, dx, dy), tb = shifted(b, dx, dy);
        w = collide(&ta, &tb, spec);
        PG_EXPECT_EQ(w.count, m.count, "translate seed %llu iter %d", seed, iter);
        PG_EXPECT_EQ(w.normal.x, m.normal.x, "translate seed %llu iter %d", seed, iter);
        PG_EXPECT_EQ(w.normal.y, m.normal.y, "translate seed %llu iter %d", seed, iter);
        for (i = 0; i < m.count; ++i) {
            PG_EXPECT_EQ(w.points[i].point.x, m.points[i].point.x + dx, "translate seed %llu iter %d", seed, iter);
            PG_EXPECT_EQ(w.points[i].point.y, m.points[i].point.y + dy, "translate seed %llu iter %d counts %d %d id %x n %d %d", seed, iter, a->count, b->count, m.points[i].id, m.normal.x, m.normal.y);
            PG_EXPECT_EQ(w.points[i].separation, m.points[i].separation, "translate seed %llu iter %d", seed, iter);
            PG_EXPECT_EQ(w.points[i].id, m.points[i].id, "translate seed %llu iter %d", seed, iter);
        }
    }
    /* swapped arguments. collide.c's choices do not depend on the order when a
     * circle is involved, or when the cores are apart by more than PG__REF_TOLERANCE
     * on the better face axis and the two faces do not tie ("A on ties"): the same
     * reference face and incident edge, the same arithmetic, the normal reported
     * negated and the ids naming A and B the other way round. Exactly, but for the
     * midpoint of two vertices (kind 2): va + round((vb - va + k n) / 2) and
     * vb + round((va - vb + k n) / 2) differ by 1 LSB in a component where the half
     * is a tie (rounding ties away from zero is not translation invariant). Otherwise
     * A's face stays the reference while B's is better by up to PG__REF_TOLERANCE:
     * the depths differ by up to that plus rounding. */
    {
        double got2 = 1e300;
        w = collide(b, a, spec);
        PG_EXPECT_LE(1, w.count, "swap seed %llu iter %d", seed, iter);
        if (!poly_pair || (far && sa2 != sb2)) {
            ++st->exact_swaps;
            PG_EXPECT_EQ(w.count, m.count, "swap seed %llu iter %d", seed, iter);
            PG_EXPECT_EQ(w.normal.x, -m.normal.x, "swap seed %llu iter %d", seed, iter);
            PG_EXPECT_EQ(w.normal.y, -m.normal.y, "swap seed %llu iter %d", seed, iter);
            for (i = 0; i < m.count && i < w.count; ++i) {
                int tol = m.points[i].id >> 16 == 2 ? 1 : 0;
                PG_EXPECT_EQ(w.points[i].id, swapped_id(m.points[i].id), "swap seed %llu iter %d point %d", seed, iter, i);
                PG_EXPECT_EQ(w.points[i].separation, m.points[i].separation, "swap seed %llu iter %d point %d", seed, iter, i);
                PG_EXPECT_LE(abs(w.points[i].point.x - m.points[i].point.x), tol, "swap seed %llu iter %d point %d", seed, iter, i);
                PG_EXPECT_LE(abs(w.points[i].point.y - m.points[i].point.y), tol, "swap seed %llu iter %d point %d", seed, iter, i);
            }
        } else {
            for (i = 0; i < w.count; ++i)
                if (dbl(w.points[i].separation) < got2) got2 = dbl(w.points[i].separation);
            PG_EXPECT_LE(fabs(got2 - got), 40.0 / 65536, "swap seed %llu iter %d", seed, iter);
        }
    }
}

static void print_stats(const char *what, unsigned long long seed, int pairs, const pair_stats *st)
{
    print_message("%s, seed %llu: %d of %d with contacts (%d overlapping, %d apart within the hysteresis, %d swapped exactly); "
                  "worst |error| apart %.3g LSB (overstated %.3g, bound %.3g), overlapping %.3g LSB\n",
                  what, seed, st->checked, pairs, st->touching, st->tolerant, st->exact_swaps, st->worst_apart * 65536,
                  st->worst_over * 65536, OVERSTATE_TOL, st->worst_deep * 65536);
}

static void random_pairs(unsigned long long seed, int pairs)
{
    pgt_rng rng = pgt_rng_seed(seed);
    pair_stats st;
    int iter;
    memset(&st, 0, sizeof st);
    midway_seed = seed;
    for (iter = 0; iter < pairs; ++iter) {
        /* One random draw per statement, in this order: the order in which a call's
         * arguments are evaluated is unspecified, and gcc and clang differ. */
        pg_geom a = random_shape(&rng, 0, 0), b;
        double bx = rnd(&rng, -2.5, 2.5);
        double by = rnd(&rng, -2.5, 2.5);
        b = random_shape(&rng, bx, by);
        check_pair(&a, &b, &rng, seed, iter, &st);
    }
    print_stats("random pairs", seed, pairs, &st);
}

/* Pairs whose cores are apart by 0 to 80 LSB, where most of collide.c's decisions are
 * close: B is moved from A's centre along a random direction until the distance reaches
 * the target (bisection over whole LSB steps). */
static void near_pairs(unsigned long long seed, int pairs)
{
    pgt_rng rng = pgt_rng_seed(seed);
    pair_stats st;
    int iter;
    memset(&st, 0, sizeof st);
    midway_seed = seed;
    for (iter = 0; iter < pairs; ++iter) {
        pg_geom a = random_shape(&rng, 0, 0), b = random_shape(&rng, 0, 0), c;
        double ang = rnd(&rng, 0, 2 * PGT_PI);
        double target = rnd(&rng, 0, 80) / 65536;
        int32_t lo = 0, hi = 1 << 19;
        while (hi - lo > 1) {
            int32_t mid = lo + (hi - lo) / 2;
            c = shifted(&b, (pg_fix)lround(mid * cos(ang)), (pg_fix)lround(mid * sin(ang)));
            if (core_distance(&a, &c) < target) lo = mid;
            else hi = mid;
        }
        c = shifted(&b, (pg_fix)lround(hi * cos(ang)), (pg_fix)lround(hi * sin(ang)));
        check_pair(&a, &c, &rng, seed, iter, &st);
    }
    print_stats("near pairs", seed, pairs, &st);
}

/* Seeds 7, 11 and 99 found the mirror asymmetry (pg__point_segment measured from an
 * edge's first vertex) in 2 million pairs each; seed 11 the overstated gap of a polygon
 * pair (test_vertex_beyond_face_polygons). */
static void test_random_pairs(void **state)
{
    static const unsigned long long seeds[] = {7, 11, 99, 2024};
    int k;
    (void)state;
    for (k = 0; k < (int)(sizeof seeds / sizeof seeds[0]); ++k) random_pairs(seeds[k], PGT_RANDOM_PAIRS);
}

static void test_random_near_pairs(void **state)
{
    static const unsigned long long seeds[] = {7, 11, 99, 2024};
    int k;
    (void)state;
    for (k = 0; k < (int)(sizeof seeds / sizeof seeds[0]); ++k) near_pairs(seeds[k], PGT_NEAR_PAIRS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dir_normalize),
        cmocka_unit_test(test_circle_circle),
        cmocka_unit_test(test_circle_circle_cases),
        cmocka_unit_test(test_circle_box),
        cmocka_unit_test(test_segment_circle),
        cmocka_unit_test(test_box_box_resting),
        cmocka_unit_test(test_box_offset_sideways),
        cmocka_unit_test(test_box_box_rotated),
        cmocka_unit_test(test_feature_ids_stable),
        cmocka_unit_test(test_capsule_on_box),
        cmocka_unit_test(test_capsule_corner),
        cmocka_unit_test(test_capsule_capsule),
        cmocka_unit_test(test_triangle_box),
        cmocka_unit_test(test_mirror_symmetry),
        cmocka_unit_test(test_swap_arguments),
        cmocka_unit_test(test_raycast),
        cmocka_unit_test(test_contains),
        cmocka_unit_test(test_overlap),
        cmocka_unit_test(test_aabb),
        cmocka_unit_test(test_transform),
        cmocka_unit_test(test_far_from_origin),
        cmocka_unit_test(test_apart_tilted_faces),
        cmocka_unit_test(test_vertex_beyond_face_polygons),
        cmocka_unit_test(test_mirror_near_tie),
        cmocka_unit_test(test_mirror_coincident_ends),
        cmocka_unit_test(test_overhang_keeps_face),
        cmocka_unit_test(test_segment_vertex_gap),
        cmocka_unit_test(test_segment_vertex_gap_steep),
        cmocka_unit_test(test_random_pairs),
        cmocka_unit_test(test_random_near_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
