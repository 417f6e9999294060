/* test_mass.c — mass, centre of mass, inertia and area of geometries and compounds
 * (src/core/mass.c).
 *
 * References are computed here in long double (64-bit mantissa on x86-64; at least
 * double elsewhere) from the EXACT values of the Q16.16 inputs, about the centre the
 * library returned (mass.h: the inertia is about the stored `center`), so they need no
 * cancellation-prone parallel-axis step.
 *
 * TOLERANCES, from the formats (LSB = one unit of the output format):
 *   - Every result is one rounding (nearest) of an exact value when no overlap has to be
 *     clipped: tolerance 0.5 LSB, plus REF_REL * |reference| for the reference's own
 *     floating-point error (REF_REL = 2^-50 is far above the long double error of these
 *     short sums, and below one LSB for every value tested). Circles and capsules use
 *     pi and the capsule length to 61 fraction bits: relative 2^-62, inside that margin.
 *   - Overlaps of polygons are clipped; each crossing vertex is rounded to 2^-32 m, i.e.
 *     moved by at most 2^-32.5 m. That moves an area by at most perimeter * 2^-32.5 m^2,
 *     which is perimeter * 2^-0.5 LSB of the Q32.32 area; mass scales by the density, and
 *     a second moment by the squared distance of the moved vertices from the centre.
 *     Those bounds are computed per case from the intersection's own perimeter.
 *   - The Q16.16 INPUTS are rounded too: an equilateral triangle's x coordinates
 *     r sqrt(3)/2 are not representable. Comparisons with closed forms of the ideal shape
 *     (r^2 sqrt(3) for the star) therefore carry the input quantisation bound
 *     2^-17 / (r sqrt(3)/2) (relative), which is ~3e-6 for r = 0.5, above a 1e-6 figure.
 */
#include "pg_test.h"

#include <math.h>
#include <stdlib.h>

#include "mass.h"
#include "wide.h"
#include "world_internal.h"

typedef long double ld;

#define LPI 3.14159265358979323846264338327950288L
#define REF_REL 8.8817841970012523e-16 /* 2^-50 */
#define Q32 4294967296.0L
#define Q36 68719476736.0L
#define Q16 65536.0L

/* pg_compound_mass's work space (mass.h), which a world lends from its scratch */
static uint64_t mass_work[PG__MASS_WORK_BYTES / 8u];

static pg_fix fx(double v) { return (pg_fix)llround(v * 65536.0); }
static ld fd(pg_fix v) { return (ld)v / Q16; }

/* ---- building geometries ------------------------------------------------------------ */

static pg_geom geom_raw(const pg_vec2 *v, int n, pg_fix radius)
{
    pg_geom g;
    memset(&g, 0, sizeof g);
    for (int i = 0; i < n; ++i) g.vertices[i] = v[i];
    g.count = n;
    g.radius = radius;
    g.centroid = pg_v2(fx(123.0), fx(-77.0)); /* deliberately wrong: must not be trusted */
    return g;
}

static pg_geom poly(const double *xy, int n)
{
    pg_vec2 v[PG_MAX_POLYGON_VERTICES];
    for (int i = 0; i < n; ++i) v[i] = pg_v2(fx(xy[2 * i]), fx(xy[2 * i + 1]));
    return geom_raw(v, n, 0);
}

static pg_geom box(double x0, double y0, double x1, double y1)
{
    double xy[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    return poly(xy, 4);
}

static pg_geom circle(double x, double y, double r)
{
    pg_vec2 v = pg_v2(fx(x), fx(y));
    return geom_raw(&v, 1, fx(r));
}

static pg_geom capsule(double x0, double y0, double x1, double y1, double r)
{
    pg_vec2 v[2] = {pg_v2(fx(x0), fx(y0)), pg_v2(fx(x1), fx(y1))};
    return geom_raw(v, 2, fx(r));
}

/* ---- long double references ------------------------------------------------------------ */

/* Area, first moment and polar second moment about a point R. */
typedef struct ref { ld a, sx, sy, j; } ref;

static ref ref_zero(void) { ref r = {0, 0, 0, 0}; return r; }

static void ref_add(ref *acc, ref m, ld w)
{
    acc->a += w * m.a;
    acc->sx += w * m.sx;
    acc->sy += w * m.sy;
    acc->j += w * m.j;
}

/* Simple polygon (any winding is taken as given: CCW positive) about (rx, ry). */
static ref ref_pts(const ld *x, const ld *y, int n, ld rx, ld ry)
{
    ref r = ref_zero();
    for (int i = 0; i < n; ++i) {
        int k = (i + 1) % n;
        ld ax = x[i] - rx, ay = y[i] - ry, bx = x[k] - rx, by = y[k] - ry;
        ld c = ax * by - ay * bx;
        r.a += c / 2;
        r.sx += c * (ax + bx) / 6;
        r.sy += c * (ay + by) / 6;
        r.j += c * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by) / 12;
    }
    return r;
}

static ref ref_geom(const pg_geom *g, ld rx, ld ry)
{
    ld x[PG_MAX_POLYGON_VERTICES], y[PG_MAX_POLYGON_VERTICES];
    ref r = ref_zero();
    for (int i = 0; i < g->count; ++i) { x[i] = fd(g->vertices[i].x); y[i] = fd(g->vertices[i].y); }
    if (g->count >= 3) {
        r = ref_pts(x, y, g->count, rx, ry);
        if (r.a < 0) { r.a = -r.a; r.sx = -r.sx; r.sy = -r.sy; r.j = -r.j; }
    } else if (g->radius > 0) {
        /* Box2D's form: a rectangle 2r x L plus a disc whose halves sit at the ends,
         * their centroids 4r/(3 pi) beyond them. */
        ld rad = fd(g->radius), x1 = x[g->count - 1], y1 = y[g->count - 1];
        ld len = sqrtl((x1 - x[0]) * (x1 - x[0]) + (y1 - y[0]) * (y1 - y[0]));
        ld h = len / 2, lc = 4 * rad / (3 * LPI);
        ld disc = LPI * rad * rad, rect = 2 * rad * len;
        ld ic = disc * (rad * rad / 2 + h * h + 2 * h * lc) + rect * (4 * rad * rad + len * len) / 12;
        ld mx = (x[0] + x1) / 2 - rx, my = (y[0] + y1) / 2 - ry;
        r.a = disc + rect;
        r.sx = r.a * mx;
        r.sy = r.a * my;
        r.j = ic + r.a * (mx * mx + my * my);
    }
    return r;
}

/* ---- comparison ------------------------------------------------------------------------- */

typedef struct tol { ld area, mass, center, inertia; } tol; /* extra LSB beyond 0.5 */

static const tol EXACT = {0, 0, 0, 0};

static void expect_lsb(long long got, ld want_raw, ld extra, const char *what, const char *field)
{
    ld err = fabsl((ld)got - want_raw), bound = 0.5L + extra + REF_REL * fabsl(want_raw);
    if (!(err <= bound)) {
        print_error("%s: %s = %lld, reference %.6Lf, error %.4Lg LSB > bound %.4Lg\n", what, field, got,
                    want_raw, err, bound);
        fail();
    }
}

/* mass_m: density-weighted moments, area_m: unit-weight moments, both about md->center. */
static void expect_md(const pg_mass_data *md, ref mass_m, ref area_m, tol t, const char *what)
{
    ld cx = fd(md->center.x), cy = fd(md->center.y);
    expect_lsb(md->area, area_m.a * Q32, t.area, what, "area");
    expect_lsb(md->mass, mass_m.a * Q32, t.mass, what, "mass");
    if (mass_m.a > 0) {
        expect_lsb(md->center.x, (cx + mass_m.sx / mass_m.a) * Q16, t.center, what, "center.x");
        expect_lsb(md->center.y, (cy + mass_m.sy / mass_m.a) * Q16, t.center, what, "center.y");
    }
    expect_lsb(md->inertia, mass_m.j * Q36, t.inertia, what, "inertia");
}

/* One geometry at a density: everything about the returned centre. */
static pg_mass_data check_single(const pg_geom *g, pg_fix density, const char *what)
{
    pg_mass_data md = pg_geom_mass(g, density);
    ref a = ref_geom(g, fd(md.center.x), fd(md.center.y)), m = ref_zero();
    ref_add(&m, a, fd(density));
    expect_md(&md, m, a, EXACT, what);
    return md;
}

static void expect_same(const pg_mass_data *a, const pg_mass_data *b, const char *what)
{
    PG_EXPECT_EQ(a->mass, b->mass, "%s", what);
    PG_EXPECT_EQ(a->inertia, b->inertia, "%s", what);
    PG_EXPECT_EQ(a->area, b->area, "%s", what);
    PG_EXPECT_EQ(a->center.x, b->center.x, "%s", what);
    PG_EXPECT_EQ(a->center.y, b->center.y, "%s", what);
}

/* ---- single shapes ------------------------------------------------------------------------ */

static void test_circle(void **state)
{
    (void)state;
    pg_geom c = circle(2.0, -3.0, 1.5);
    pg_mass_data md = check_single(&c, fx(2.0), "circle r=1.5 rho=2");
    PG_EXPECT_EQ(md.center.x, fx(2.0), "%s", "circle centre");
    PG_EXPECT_EQ(md.center.y, fx(-3.0), "%s", "circle centre");
    /* closed forms, written out: m = rho pi r^2, I = m r^2 / 2 */
    expect_lsb(md.mass, 2.0L * LPI * 2.25L * Q32, 0, "circle", "mass closed form");
    expect_lsb(md.inertia, 2.0L * LPI * 2.25L * 2.25L / 2 * Q36, 0, "circle", "inertia closed form");
    expect_lsb(md.area, LPI * 2.25L * Q32, 0, "circle", "area closed form");
    c = circle(-0.3, 0.7, 0.01);
    check_single(&c, fx(1000.0), "small circle");
    c = circle(10.0, 20.0, 30.0);
    check_single(&c, fx(0.5), "large circle");
    /* a point (radius 0) has no area */
    c = circle(1.25, -2.5, 0.0);
    md = pg_geom_mass(&c, fx(5.0));
    PG_EXPECT_EQ(md.mass, 0, "%s", "point");
    PG_EXPECT_EQ(md.area, 0, "%s", "point");
    PG_EXPECT_EQ(md.inertia, 0, "%s", "point");
    PG_EXPECT_EQ(md.center.x, fx(1.25), "%s", "point");
    PG_EXPECT_EQ(md.center.y, fx(-2.5), "%s", "point");
}

static void test_box(void **state)
{
    (void)state;
    pg_geom b = box(-1.0, -0.5, 1.0, 0.5);
    pg_mass_data md = check_single(&b, fx(1.5), "box 2x1");
    /* all exact: area 2, mass 3, I = m (w^2 + h^2) / 12 = 1.25 */
    PG_EXPECT_EQ(md.area, INT64_C(2) << 32, "%s", "box area");
    PG_EXPECT_EQ(md.mass, INT64_C(3) << 32, "%s", "box mass");
    PG_EXPECT_EQ(md.inertia, INT64_C(5) << 34, "%s", "box inertia");
    PG_EXPECT_EQ(md.center.x, 0, "%s", "box centre");
    PG_EXPECT_EQ(md.center.y, 0, "%s", "box centre");
}

static void test_off_centre_box(void **state)
{
    (void)state;
    pg_geom b = box(3.0, -1.0, 5.0, 2.0);
    pg_mass_data md = check_single(&b, fx(0.75), "off-centre box");
    PG_EXPECT_EQ(md.center.x, fx(4.0), "%s", "centre");
    PG_EXPECT_EQ(md.center.y, fx(0.5), "%s", "centre");
    /* I = m (4 + 9) / 12 with m = 4.5: exact in Q28.36 */
    PG_EXPECT_EQ(md.inertia, (INT64_C(45) * 13 << 36) / 120, "%s", "inertia");
}

static void test_triangles(void **state)
{
    (void)state;
    double right[6] = {0, 0, 3, 0, 0, 4};
    pg_geom t = poly(right, 3);
    pg_mass_data md = check_single(&t, fx(1.0), "right triangle 3-4-5");
    PG_EXPECT_EQ(md.area, INT64_C(6) << 32, "%s", "area");
    PG_EXPECT_EQ(md.center.x, fx(1.0), "%s", "centroid x");
    PG_EXPECT_EQ(md.center.y, 87381, "%s", "centroid y = round(4/3 * 2^16)");
    /* I about the centroid = m (a^2 + b^2) / 18 = 6 * 25 / 18; the stored centre is off by
     * d = 87381/65536 - 4/3, adding m d^2 */
    {
        ld d = 87381.0L / Q16 - 4.0L / 3.0L;
        expect_lsb(md.inertia, (6.0L * 25.0L / 18.0L + 6.0L * d * d) * Q36, 0, "right triangle", "closed form");
    }
    {
        double h = sqrt(3.0);
        double eq[6] = {-1, 0, 1, 0, 0, h};
        t = poly(eq, 3);
        check_single(&t, fx(2.5), "equilateral triangle side 2");
        /* vs the ideal closed form m s^2 / 12 (s = 2): within the input quantisation */
        md = pg_geom_mass(&t, fx(2.5));
        {
            ld ideal = 2.5L * sqrtl(3.0L) * 4.0L / 12.0L, rel = fabsl((ld)md.inertia / Q36 / ideal - 1);
            PG_EXPECT_LE((double)rel, 2.0 * (0.5 / 65536.0) / h + 1e-12, "%s", "equilateral vs ideal");
        }
    }
    /* clockwise input is accepted and gives the same bits */
    {
        double cw[6] = {0, 0, 0, 4, 3, 0};
        pg_geom t2 = poly(cw, 3), t1 = poly(right, 3);
        pg_mass_data a = pg_geom_mass(&t1, fx(1.0)), b = pg_geom_mass(&t2, fx(1.0));
        expect_same(&a, &b, "clockwise triangle");
    }
}

static void test_capsule(void **state)
{
    (void)state;
    pg_geom c = capsule(-1.0, 0.5, 2.0, 1.5, 0.4);
    pg_mass_data md = check_single(&c, fx(3.0), "capsule oblique");
    PG_EXPECT_EQ(md.center.x, fx(0.5), "%s", "capsule centre = midpoint");
    PG_EXPECT_EQ(md.center.y, fx(1.0), "%s", "capsule centre = midpoint");
    /* horizontal capsule against the closed form built independently here:
     * rectangle m_r (L^2 + 4 r^2)/12, two half discs with centroids at L/2 + 4r/(3 pi) */
    c = capsule(-1.0, 0.0, 1.0, 0.0, 0.5);
    md = check_single(&c, fx(1.0), "capsule horizontal");
    {
        ld L = 2, r = 0.5L, mr = 2 * r * L, mh = LPI * r * r / 2, d = 4 * r / (3 * LPI);
        ld ih = mh * r * r / 2 - mh * d * d; /* half disc about its own centroid */
        ld off = L / 2 + d;
        ld inertia = mr * (L * L + 4 * r * r) / 12 + 2 * (ih + mh * off * off);
        expect_lsb(md.inertia, inertia * Q36, 0, "capsule", "closed form inertia");
        expect_lsb(md.area, (mr + 2 * mh) * Q32, 0, "capsule", "closed form area");
    }
    check_single(&c, fx(7.25), "capsule density 7.25");
    c = capsule(-20.0, -30.0, 25.0, 10.0, 3.0);
    check_single(&c, fx(10.0), "long capsule");
    /* a capsule of length 0 is a circle, bit for bit */
    {
        pg_geom a = capsule(1.5, -2.0, 1.5, -2.0, 0.75), b = circle(1.5, -2.0, 0.75);
        pg_mass_data ma = pg_geom_mass(&a, fx(2.0)), mb = pg_geom_mass(&b, fx(2.0));
        expect_same(&ma, &mb, "zero-length capsule == circle");
    }
}

/* A circle has its own formula (mass.c, pg__circle_moments), so that a build without
 * capsules keeps no capsule code; it must give the bits of the capsule of length 0 it
 * replaced, for every input. Returns 1 when the circle has mass, so the callers can show
 * that their sweeps were not all trivial. */
static int expect_circle_as_capsule(pg_vec2 c, pg_fix r, pg_fix density, const char *what)
{
    pg_vec2 ends[2] = {c, c};
    pg_geom circ = geom_raw(&c, 1, r), caps = geom_raw(ends, 2, r);
    pg_mass_data a = pg_geom_mass(&circ, density), b = pg_geom_mass(&caps, density);
    expect_same(&a, &b, what);
    return a.mass > 0;
}

/* In a compound the circle's centre is away from the reference point, so its first
 * moment and the parallel-axis term of its second moment are not zero. */
static int expect_circle_as_capsule_in_compound(pg_vec2 c, pg_fix r, const pg_geom *other, pg_fix rho_circle,
                                                pg_fix rho_other, const char *what)
{
    pg_vec2 ends[2] = {c, c};
    pg_geom circ = geom_raw(&c, 1, r), caps = geom_raw(ends, 2, r);
    const pg_geom *with_circle[2] = {other, &circ}, *with_capsule[2] = {other, &caps};
    pg_fix rho[2] = {rho_other, rho_circle};
    pg_mass_data a = pg_compound_mass(with_circle, rho, 2, mass_work);
    pg_mass_data b = pg_compound_mass(with_capsule, rho, 2, mass_work);
    expect_same(&a, &b, what);
    return a.inertia > 0 && a.inertia < INT64_MAX;
}

static void test_circle_matches_zero_length_capsule(void **state)
{
    (void)state;
    /* the envelope's edges (radius 0.005..50 m, positions +-1000 m, density
     * 0.1..100 kg/m^2), one LSB either side, and every int32 extreme */
    static const pg_fix radii[] = {INT32_MIN, -1, 0, 1, 2, 327, 328, 655, 3277, 65536, 65537, 50 << 16, (50 << 16) + 1,
                                   1000 << 16, PG_FIX_MAX};
    static const pg_fix coords[] = {INT32_MIN, -(1000 << 16), -65537, -1, 0, 1, 32768, 1000 << 16, PG_FIX_MAX};
    static const pg_fix densities[] = {INT32_MIN, -1, 0, 1, 6554, 65536, 100 << 16, PG_FIX_MAX};
    const size_t nr = sizeof radii / sizeof radii[0], nc = sizeof coords / sizeof coords[0];
    const size_t nd = sizeof densities / sizeof densities[0];
    pgt_rng rng = pgt_rng_seed(30);
    long with_mass = 0, cases = 0;
    char what[96];
    for (size_t i = 0; i < nr; ++i)
        for (size_t x = 0; x < nc; ++x)
            for (size_t y = 0; y < nc; ++y)
                for (size_t d = 0; d < nd; ++d) {
                    snprintf(what, sizeof what, "edge r=%ld c=(%ld,%ld) rho=%ld", (long)radii[i], (long)coords[x],
                             (long)coords[y], (long)densities[d]);
                    with_mass += expect_circle_as_capsule(pg_v2(coords[x], coords[y]), radii[i], densities[d], what);
                    ++cases;
                }
    /* the edges with mass: 12 positive radii x 5 positive densities x 81 centres, less the
     * 3 x 81 below half an LSB of mass (radius 1 or 2 LSB at density 1 LSB, radius 1 LSB
     * at 0.1 kg/m^2) */
    PG_EXPECT_EQ(with_mass, (12 * 5 - 3) * 81, "%s", "edge cases with mass");
    PG_EXPECT_EQ(cases, (long)(nr * nc * nc * nd), "%s", "edge cases");

    /* seeded sweep: radii and densities log-spread over the envelope (any int32 one case in
     * eight), centres within +-1000 m (any int32 one case in eight) */
    with_mass = 0;
    long expected_with_mass = 0;
    for (long it = 0; it < 100000; ++it) {
        uint64_t pick = pgt_next(&rng);
        pg_fix r = (pick & 7u) == 0 ? pgt_fix_any(&rng) : (pg_fix)(327 + pgt_below(&rng, (50 << 16) - 326) / (1u + pgt_below(&rng, 64)));
        pg_fix rho = (pick & 56u) == 0 ? pgt_fix_any(&rng) : (pg_fix)(6554 + pgt_below(&rng, (100 << 16) - 6553) / (1u + pgt_below(&rng, 64)));
        pg_fix cx = (pick & 448u) == 0 ? pgt_fix_any(&rng) : pgt_fix_bits(&rng, 26);
        pg_fix cy = (pick & 448u) == 0 ? pgt_fix_any(&rng) : pgt_fix_bits(&rng, 26);
        snprintf(what, sizeof what, "sweep %ld: r=%ld c=(%ld,%ld) rho=%ld", it, (long)r, (long)cx, (long)cy, (long)rho);
        with_mass += expect_circle_as_capsule(pg_v2(cx, cy), r, rho, what);
        /* the mass in Q32.32 LSB is pi r^2 rho 2^-16 (r, rho in Q16.16): at least half an LSB */
        expected_with_mass += r > 0 && rho > 0 && LPI * (ld)r * (ld)r * (ld)rho >= 32768.0L;
    }
    PG_EXPECT_EQ(with_mass, expected_with_mass, "%s", "sweep cases with mass");
    PG_EXPECT_LE(100000 - with_mass, 13000, "%s", "the sweep's cases without mass (12.1 %, 1 - (15/16)^2, draw a negative radius or density)");

    /* beside a box: the circle away from the reference point, within 32 m of the origin
     * and up to 5 m in size, so that few inertias saturate */
    with_mass = 0;
    for (long it = 0; it < 2000; ++it) {
        pg_fix half = (pg_fix)(655 + pgt_below(&rng, 5 << 16));
        pg_fix bx = pgt_fix_bits(&rng, 21), by = pgt_fix_bits(&rng, 21);
        pg_vec2 corners[4] = {pg_v2(bx - half, by - half), pg_v2(bx + half, by - half), pg_v2(bx + half, by + half),
                              pg_v2(bx - half, by + half)};
        pg_geom b = geom_raw(corners, 4, 0);
        pg_fix r = (pg_fix)(327 + pgt_below(&rng, (5 << 16) - 326));
        pg_vec2 c = pg_v2(pgt_fix_bits(&rng, 21), pgt_fix_bits(&rng, 21));
        pg_fix rho_c = (pg_fix)(6554 + pgt_below(&rng, 100 << 16)), rho_b = (pg_fix)(6554 + pgt_below(&rng, 100 << 16));
        snprintf(what, sizeof what, "beside a box %ld: r=%ld c=(%ld,%ld)", it, (long)r, (long)c.x, (long)c.y);
        with_mass += expect_circle_as_capsule_in_compound(c, r, &b, rho_c, rho_b, what);
    }
    PG_EXPECT_LE(2000 - with_mass, 20, "%s", "compounds whose inertia saturates");
}

static void test_segment(void **state)
{
    (void)state;
    pg_geom s = capsule(1.0, -2.0, 2.0, -2.5, 0.0);
    pg_mass_data md = pg_geom_mass(&s, fx(5.0));
    PG_EXPECT_EQ(md.mass, 0, "%s", "segment mass");
    PG_EXPECT_EQ(md.area, 0, "%s", "segment area");
    PG_EXPECT_EQ(md.inertia, 0, "%s", "segment inertia");
    PG_EXPECT_EQ(md.center.x, fx(1.5), "%s", "segment midpoint");
    PG_EXPECT_EQ(md.center.y, fx(-2.25), "%s", "segment midpoint");
    /* half-LSB midpoints round away from zero, symmetrically */
    {
        pg_vec2 v[2] = {pg_v2(0, 0), pg_v2(1, -1)};
        pg_geom g = geom_raw(v, 2, 0);
        md = pg_geom_mass(&g, fx(1.0));
        PG_EXPECT_EQ(md.center.x, 1, "%s", "0.5 LSB -> 1");
        PG_EXPECT_EQ(md.center.y, -1, "%s", "-0.5 LSB -> -1");
    }
}

static void test_octagon(void **state)
{
    (void)state;
    double xy[16];
    for (int i = 0; i < 8; ++i) {
        double a = 0.3 + 2 * PGT_PI * i / 8;
        xy[2 * i] = 0.3 + 2.0 * cos(a);
        xy[2 * i + 1] = -0.7 + 2.0 * sin(a);
    }
    pg_geom g = poly(xy, 8);
    pg_mass_data md = check_single(&g, fx(1.25), "regular octagon");
    /* ideal regular octagon of circumradius R: A = 2 sqrt(2) R^2, I = m R^2 (1 + 2 cos^2(pi/8)) / 6 */
    {
        ld A = 2 * sqrtl(2.0L) * 4, c = cosl(LPI / 8), I = 1.25L * A * 4 * (1 + 2 * c * c) / 6;
        PG_EXPECT_LE(fabs((double)((ld)md.area / Q32 / A - 1)), 1e-5, "%s", "octagon area vs ideal (input quantisation)");
        PG_EXPECT_LE(fabs((double)((ld)md.inertia / Q36 / I - 1)), 1e-5, "%s", "octagon inertia vs ideal");
    }
    {
        double irr[16] = {0, 0, 2, -0.5, 3.5, 0.25, 4, 1.5, 3.75, 3, 2.5, 3.9, 0.75, 3.5, -0.4, 1.8};
        g = poly(irr, 8);
        check_single(&g, fx(3.0), "irregular octagon");
    }
}

/* ---- compounds ------------------------------------------------------------------------------ */

static void test_compound_separate(void **state)
{
    (void)state;
    pg_geom a = box(0, 0, 1, 1), b = box(3, 0, 5, 2), c = circle(-2, 1, 0.5), s = capsule(0, 3, 2, 4, 0.25);
    const pg_geom *gs[4] = {&a, &b, &c, &s};
    pg_fix rho[4] = {fx(1.0), fx(2.0), fx(0.5), fx(4.0)};
    pg_mass_data md = pg_compound_mass(gs, rho, 4, mass_work);
    ref m = ref_zero(), ar = ref_zero();
    for (int i = 0; i < 4; ++i) {
        ref r = ref_geom(gs[i], fd(md.center.x), fd(md.center.y));
        ref_add(&m, r, fd(rho[i]));
        ref_add(&ar, r, 1);
    }
    expect_md(&md, m, ar, EXACT, "four separate shapes");
    /* the parallel axis theorem spelled out for the two boxes alone */
    md = pg_compound_mass(gs, rho, 2, mass_work);
    {
        ld ma = 1, mb = 8, cx = (0.5L * ma + 4 * mb) / (ma + mb), cy = (0.5L * ma + 1 * mb) / (ma + mb);
        ld ia = ma * 2 / 12, ib = mb * 8 / 12;
        ld sx = fd(md.center.x) - cx, sy = fd(md.center.y) - cy; /* stored vs exact centre */
        ld inertia = ia + ma * ((0.5L - cx) * (0.5L - cx) + (0.5L - cy) * (0.5L - cy)) + ib +
                     mb * ((4 - cx) * (4 - cx) + (1 - cy) * (1 - cy)) + (ma + mb) * (sx * sx + sy * sy);
        expect_lsb(md.mass, 9 * Q32, 0, "two boxes", "mass");
        expect_lsb(md.center.x, cx * Q16, 0, "two boxes", "centre x");
        expect_lsb(md.center.y, cy * Q16, 0, "two boxes", "centre y");
        expect_lsb(md.inertia, inertia * Q36, 0, "two boxes", "parallel axis inertia");
    }
}

static void test_compound_overlap_l_shape(void **state)
{
    (void)state;
    pg_geom a = box(0, 0, 2, 1), b = box(0, 0, 1, 2), top = box(0, 1, 1, 2), right = box(1, 0, 2, 1);
    pg_fix r1 = fx(1.0), r2 = fx(3.0);
    /* a first: the overlap [0,1]^2 has a's density */
    {
        const pg_geom *gs[2] = {&a, &b};
        pg_fix rho[2] = {r1, r2};
        pg_mass_data md = pg_compound_mass(gs, rho, 2, mass_work);
        ld cx = fd(md.center.x), cy = fd(md.center.y);
        ref m = ref_zero(), ar = ref_zero();
        ref_add(&m, ref_geom(&a, cx, cy), fd(r1));
        ref_add(&m, ref_geom(&top, cx, cy), fd(r2));
        ref_add(&ar, ref_geom(&a, cx, cy), 1);
        ref_add(&ar, ref_geom(&top, cx, cy), 1);
        expect_md(&md, m, ar, EXACT, "L shape, a first");
        PG_EXPECT_EQ(md.area, INT64_C(3) << 32, "%s", "union area 3, not 4");
        PG_EXPECT_EQ(md.mass, INT64_C(5) << 32, "%s", "2 * 1 + 1 * 3");
    }
    /* b first: the overlap has b's density */
    {
        const pg_geom *gs[2] = {&b, &a};
        pg_fix rho[2] = {r2, r1};
        pg_mass_data md = pg_compound_mass(gs, rho, 2, mass_work);
        ld cx = fd(md.center.x), cy = fd(md.center.y);
        ref m = ref_zero(), ar = ref_zero();
        ref_add(&m, ref_geom(&b, cx, cy), fd(r2));
        ref_add(&m, ref_geom(&right, cx, cy), fd(r1));
        ref_add(&ar, ref_geom(&b, cx, cy), 1);
        ref_add(&ar, ref_geom(&right, cx, cy), 1);
        expect_md(&md, m, ar, EXACT, "L shape, b first");
        PG_EXPECT_EQ(md.mass, INT64_C(7) << 32, "%s", "2 * 3 + 1 * 1");
    }
    /* equal densities: the union is the same either way, bit for bit */
    {
        const pg_geom *ab[2] = {&a, &b}, *ba[2] = {&b, &a}, *lt[2] = {&a, &top};
        pg_fix rho[2] = {r2, r2};
        pg_mass_data x = pg_compound_mass(ab, rho, 2, mass_work), y = pg_compound_mass(ba, rho, 2, mass_work), z = pg_compound_mass(lt, rho, 2, mass_work);
        expect_same(&x, &y, "L shape order");
        expect_same(&x, &z, "L shape vs its disjoint decomposition");
    }
}

static void test_compound_identical(void **state)
{
    (void)state;
    pg_geom b = box(-0.75, 0.5, 1.25, 1.75);
    const pg_geom *gs[9] = {&b, &b, &b, &b, &b, &b, &b, &b, &b};
    pg_fix rho[9] = {fx(2.0), fx(5.0), fx(0.5), fx(1.0), fx(3.0), fx(7.0), fx(0.25), fx(9.0), fx(4.0)};
    pg_mass_data one = pg_geom_mass(&b, rho[0]);
    for (int n = 2; n <= 8; ++n) {
        pg_mass_data md = pg_compound_mass(gs, rho, n, mass_work);
        char what[64];
        snprintf(what, sizeof what, "%d identical boxes", n);
        expect_same(&md, &one, what); /* 2^n - 1 subsets, all the same box */
    }
    /* documented limit: only the first 8 polygons are overlap-checked; a ninth is added
     * as if it overlapped nothing */
    {
        pg_mass_data md = pg_compound_mass(gs, rho, 9, mass_work), ninth = pg_geom_mass(&b, rho[8]);
        PG_EXPECT_EQ(md.mass, one.mass + ninth.mass, "%s", "ninth polygon counted separately");
        PG_EXPECT_EQ(md.area, 2 * one.area, "%s", "ninth polygon counted separately");
        PG_EXPECT_EQ(md.center.x, one.center.x, "%s", "same centre");
    }
}

/* Nested boxes A > B > C: listed outer first, everything has A's density; listed inner
 * first, each ring has its own. Three-level inclusion-exclusion with exact vertices. */
static void test_compound_nested(void **state)
{
    (void)state;
    pg_geom a = box(-4, -3, 4, 3), b = box(-1, -1, 3, 2), c = box(0, 0, 1, 1);
    pg_fix ra = fx(1.0), rb = fx(2.0), rc = fx(8.0);
    {
        const pg_geom *gs[3] = {&a, &b, &c};
        pg_fix rho[3] = {ra, rb, rc};
        pg_mass_data md = pg_compound_mass(gs, rho, 3, mass_work), just_a = pg_geom_mass(&a, ra);
        expect_same(&md, &just_a, "outer first");
    }
    {
        const pg_geom *gs[3] = {&c, &b, &a};
        pg_fix rho[3] = {rc, rb, ra};
        pg_mass_data md = pg_compound_mass(gs, rho, 3, mass_work);
        ld cx = fd(md.center.x), cy = fd(md.center.y);
        ref ma = ref_geom(&a, cx, cy), mb = ref_geom(&b, cx, cy), mc = ref_geom(&c, cx, cy), m = ref_zero();
        ref_add(&m, mc, fd(rc));
        ref_add(&m, mb, fd(rb));
        ref_add(&m, mc, -fd(rb));
        ref_add(&m, ma, fd(ra));
        ref_add(&m, mb, -fd(ra));
        expect_md(&md, m, ma, EXACT, "inner first");
    }
}

/* ---- the hexagram ------------------------------------------------------------------------------ */

/* Crossing of segments p0p1 and q0q1 in long double, if proper. */
static int seg_cross(ld p0x, ld p0y, ld p1x, ld p1y, ld q0x, ld q0y, ld q1x, ld q1y, ld *x, ld *y)
{
    ld rx = p1x - p0x, ry = p1y - p0y, sx = q1x - q0x, sy = q1y - q0y, d = rx * sy - ry * sx;
    if (d == 0) return 0;
    ld t = ((q0x - p0x) * sy - (q0y - p0y) * sx) / d, u = ((q0x - p0x) * ry - (q0y - p0y) * rx) / d;
    if (t <= 0 || t >= 1 || u <= 0 || u >= 1) return 0;
    *x = p0x + t * rx;
    *y = p0y + t * ry;
    return 1;
}

typedef struct pa { ld x, y, ang; } pa;

static int pa_cmp(const void *a, const void *b)
{
    ld x = ((const pa *)a)->ang, y = ((const pa *)b)->ang;
    return x < y ? -1 : x > y;
}

/* The star's outline as one 12-vertex (non-convex) polygon about (rx, ry); also the
 * perimeter of the inner hexagon and its largest squared distance from the centre. */
static ref hexagram_ref(const pg_geom *up, const pg_geom *down, ld ccx, ld ccy, ld rx, ld ry, ld *hex_perim,
                        ld *hex_r2)
{
    pa p[12];
    ld inner[6][2];
    int n = 0, ni = 0;
    for (int i = 0; i < 3; ++i) {
        p[n].x = fd(up->vertices[i].x); p[n].y = fd(up->vertices[i].y); ++n;
        p[n].x = fd(down->vertices[i].x); p[n].y = fd(down->vertices[i].y); ++n;
    }
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            ld x, y;
            if (seg_cross(fd(up->vertices[i].x), fd(up->vertices[i].y), fd(up->vertices[(i + 1) % 3].x),
                          fd(up->vertices[(i + 1) % 3].y), fd(down->vertices[k].x), fd(down->vertices[k].y),
                          fd(down->vertices[(k + 1) % 3].x), fd(down->vertices[(k + 1) % 3].y), &x, &y)) {
                p[n].x = x; p[n].y = y; ++n;
                inner[ni][0] = x; inner[ni][1] = y; ++ni;
            }
        }
    assert_int_equal(n, 12);
    for (int i = 0; i < 12; ++i) p[i].ang = atan2l(p[i].y - ccy, p[i].x - ccx);
    qsort(p, 12, sizeof p[0], pa_cmp);
    {
        ld xs[12], ys[12];
        for (int i = 0; i < 12; ++i) { xs[i] = p[i].x; ys[i] = p[i].y; }
        *hex_perim = 0;
        *hex_r2 = 0;
        /* inner points, in angular order too */
        for (int i = 0, k = 0; i < 12; ++i) {
            int is_inner = 0;
            for (int j = 0; j < 6; ++j) is_inner |= (inner[j][0] == xs[i] && inner[j][1] == ys[i]);
            if (is_inner) {
                inner[k][0] = xs[i]; inner[k][1] = ys[i]; ++k;
            }
        }
        for (int j = 0; j < 6; ++j) {
            ld dx = inner[(j + 1) % 6][0] - inner[j][0], dy = inner[(j + 1) % 6][1] - inner[j][1];
            ld ex = inner[j][0] - ccx, ey = inner[j][1] - ccy;
            *hex_perim += sqrtl(dx * dx + dy * dy);
            if (ex * ex + ey * ey > *hex_r2) *hex_r2 = ex * ex + ey * ey;
        }
        return ref_pts(xs, ys, 12, rx, ry);
    }
}

static void star(double r, double cx, double cy, pg_geom *up, pg_geom *down)
{
    double h = r * sqrt(3.0) / 2;
    double u[6] = {cx - h, cy - r / 2, cx + h, cy - r / 2, cx, cy + r};
    double d[6] = {cx + h, cy + r / 2, cx - h, cy + r / 2, cx, cy - r};
    *up = poly(u, 3);
    *down = poly(d, 3);
}

static void check_star(double r, double cx, double cy, pg_fix density)
{
    pg_geom up, down;
    char what[96];
    snprintf(what, sizeof what, "star r=%g at (%g, %g)", r, cx, cy);
    star(r, cx, cy, &up, &down);
    const pg_geom *gs[2] = {&up, &down};
    pg_fix rho[2] = {density, density};
    pg_mass_data md = pg_compound_mass(gs, rho, 2, mass_work);
    ld perim, r2, rhol = fd(density);
    ref a = hexagram_ref(&up, &down, fd(fx(cx)), fd(fx(cy)), fd(md.center.x), fd(md.center.y), &perim, &r2), m = ref_zero();
    ref_add(&m, a, rhol);
    /* crossing vertices are within 2^-32.5 m of exact (see the top of the file) */
    {
        ld move = perim * 0.70710678118654752L / Q32; /* area moved, m^2 */
        tol t;
        t.area = move * Q32;
        t.mass = rhol * move * Q32;
        t.center = rhol * move * sqrtl(r2) / (m.a) * Q16;
        t.inertia = rhol * move * r2 * Q36;
        expect_md(&md, m, a, t, what);
    }
    /* the centre is the common centre exactly: the inputs are symmetric about it and the
     * crossings are rounded symmetrically, so the error is far below half an LSB */
    PG_EXPECT_EQ(md.center.x, fx(cx), "%s", what);
    PG_EXPECT_EQ(md.center.y, fx(cy), "%s", what);
    /* against the ideal star r^2 sqrt(3) (not twice a triangle, 3 sqrt(3)/2 r^2): the only
     * difference allowed is the input quantisation of x = r sqrt(3)/2; the quantised star
     * is the ideal one stretched in x by xq / x */
    {
        ld ideal = (ld)r * r * sqrtl(3.0L), x = (ld)r * sqrtl(3.0L) / 2, xq = fd(fx(cx + (double)x)) - fd(fx(cx));
        ld rel = fabsl((ld)md.area / Q32 / ideal - 1);
        PG_EXPECT_LE((double)rel, (double)(0.5L / 65536.0L / x + 1e-9L), "%s: vs r^2 sqrt(3), quantisation bound", what);
        PG_EXPECT_LE((double)fabsl((ld)md.area / Q32 / (ideal * xq / x) - 1), 1e-9, "%s: vs the stretched ideal star", what);
        PG_EXPECT_LE((double)fabsl(((ld)md.inertia / Q36) / (m.j) - 1), 1e-5, "%s: inertia vs reference (1e-5)", what);
    }
}

static void test_star(void **state)
{
    (void)state;
    check_star(1.0, 0.0, 0.0, fx(1.0));
    check_star(0.5, 0.0, 0.0, fx(1.0));
    check_star(3.0, 0.0, 0.0, fx(1.0));
    check_star(1.0, 7.5, -2.25, fx(2.5));
    check_star(3.0, -120.0, 64.5, fx(10.0));
    check_star(0.5, 999.0, -999.0, fx(0.75));
}

/* ---- scaling, extremes, symmetry ------------------------------------------------------------------- */

/* A convex polygon: points on a rotated ellipse at jittered angles. */
static pg_geom random_convex(pgt_rng *rng, double cx, double cy, double scale)
{
    int n = 3 + (int)pgt_below(rng, 6);
    double a = scale * (0.5 + pgt_unit(rng)), b = scale * (0.5 + pgt_unit(rng)), rot = 2 * PGT_PI * pgt_unit(rng);
    double xy[16];
    for (int i = 0; i < n; ++i) {
        double t = 2 * PGT_PI * (i + 0.35 * pgt_unit(rng)) / n;
        double ex = a * cos(t), ey = b * sin(t);
        xy[2 * i] = cx + ex * cos(rot) - ey * sin(rot);
        xy[2 * i + 1] = cy + ex * sin(rot) + ey * cos(rot);
    }
    return poly(xy, n);
}

static void test_density_linear(void **state)
{
    (void)state;
    pgt_rng rng = pgt_rng_seed(42);
    for (int it = 0; it < 200; ++it) {
        pg_geom g = random_convex(&rng, 10 * pgt_unit(&rng) - 5, 10 * pgt_unit(&rng) - 5, 0.1 + 5 * pgt_unit(&rng));
        pg_fix rho = (pg_fix)(1 + pgt_below(&rng, 20 << 16));
        int k = 2 + (int)pgt_below(&rng, 9);
        pg_mass_data m1 = pg_geom_mass(&g, rho), mk = pg_geom_mass(&g, rho * k);
        /* the exact values scale by k; each side is rounded once */
        PG_EXPECT_LE(llabs((long long)(mk.mass - (int64_t)k * m1.mass)), 0.5 + 0.5 * k, "it=%d", it);
        PG_EXPECT_LE(llabs((long long)(mk.inertia - (int64_t)k * m1.inertia)), 0.5 + 0.5 * k, "it=%d", it);
        PG_EXPECT_EQ(mk.area, m1.area, "it=%d", it);
        PG_EXPECT_EQ(mk.center.x, m1.center.x, "it=%d", it);
        PG_EXPECT_EQ(mk.center.y, m1.center.y, "it=%d", it);
        check_single(&g, rho, "random convex");
    }
    /* an exactly representable case scales exactly */
    {
        pg_geom b = box(0, 0, 2, 3);
        pg_mass_data m1 = pg_geom_mass(&b, fx(1.0)), m3 = pg_geom_mass(&b, fx(3.0));
        PG_EXPECT_EQ(m3.mass, 3 * m1.mass, "%s", "box x3");
        PG_EXPECT_EQ(m3.inertia, 3 * m1.inertia, "%s", "box x3");
    }
}

static void test_extremes(void **state)
{
    (void)state;
    {
        pg_geom b = box(-0.025, -0.025, 0.025, 0.025);
        pg_mass_data md = check_single(&b, fx(0.1), "0.05 m box, density 0.1");
        /* vs double from the representable inputs (0.025 m and 0.1 kg/m^2 are not: the
         * quantised box is 0.04999 m at 0.100006 kg/m^2, 4e-4 lighter than the ideal) */
        double s = 2 * (double)fd(fx(0.025)), m = (double)fd(fx(0.1)) * s * s, i = m * 2 * s * s / 12;
        PG_EXPECT_LE(fabs((double)md.mass / 4294967296.0 / m - 1), 1e-4, "%s", "small box mass");
        PG_EXPECT_LE(fabs((double)md.inertia / 68719476736.0 / i - 1), 1e-4, "%s", "small box inertia");
        assert_true(md.inertia > 0);
    }
    {
        pg_geom b = box(-25, -25, 25, 25);
        pg_mass_data md = check_single(&b, fx(100.0), "50 m box, density 100");
        double m = 100.0 * 2500, i = m * 5000 / 12; /* 1.04e8 kg m^2 */
        PG_EXPECT_LE(fabs((double)md.mass / 4294967296.0 / m - 1), 1e-4, "%s", "large box mass");
        PG_EXPECT_LE(fabs((double)md.inertia / 68719476736.0 / i - 1), 1e-4, "%s", "large box inertia");
        assert_true(md.inertia < INT64_MAX);
    }
    /* beyond Q28.36: the inertia saturates (documented), the rest is exact */
    {
        pg_geom b = box(-30, -30, 30, 30);
        pg_mass_data md = pg_geom_mass(&b, fx(100.0));
        PG_EXPECT_EQ(md.inertia, INT64_MAX, "%s", "60 m box inertia saturates");
        PG_EXPECT_EQ(md.mass, INT64_C(360000) << 32, "%s", "60 m box mass");
        PG_EXPECT_EQ(md.area, INT64_C(3600) << 32, "%s", "60 m box area");
    }
    /* the largest legal inputs: no overflow inside, saturated outputs */
    {
        pg_geom b = poly((const double[]){-32767, -32767, 32767, -32767, 32767, 32767, -32767, 32767}, 4);
        pg_geom c = circle(32767, -32767, 32767);
        pg_mass_data md = pg_geom_mass(&b, PG_FIX_MAX);
        PG_EXPECT_EQ(md.mass, INT64_MAX, "%s", "huge box");
        PG_EXPECT_EQ(md.area, INT64_MAX, "%s", "huge box");
        PG_EXPECT_EQ(md.inertia, INT64_MAX, "%s", "huge box");
        PG_EXPECT_EQ(md.center.x, 0, "%s", "huge box");
        md = pg_geom_mass(&c, PG_FIX_MAX);
        PG_EXPECT_EQ(md.mass, INT64_MAX, "%s", "huge circle");
        PG_EXPECT_EQ(md.center.x, fx(32767), "%s", "huge circle");
        {
            const pg_geom *gs[3] = {&b, &b, &c};
            pg_fix rho[3] = {PG_FIX_MAX, 1, PG_FIX_MAX};
            md = pg_compound_mass(gs, rho, 3, mass_work);
            PG_EXPECT_EQ(md.inertia, INT64_MAX, "%s", "huge compound");
        }
    }
    /* degenerate calls */
    {
        pg_mass_data md = pg_compound_mass(NULL, NULL, 0, mass_work);
        PG_EXPECT_EQ(md.mass, 0, "%s", "empty");
        pg_geom b = box(0, 0, 1, 1);
        md = pg_geom_mass(&b, fx(-2.0));
        PG_EXPECT_EQ(md.mass, 0, "%s", "negative density counts as 0");
        PG_EXPECT_EQ(md.inertia, 0, "%s", "negative density counts as 0");
        PG_EXPECT_EQ(md.area, INT64_C(1) << 32, "%s", "area still there");
        PG_EXPECT_EQ(md.center.x, fx(0.5), "%s", "centre of the area without mass");
    }
}

/* mirrored in x = a (a an exact Q16.16 value), winding restored */
static pg_geom mirror_x(const pg_geom *g, pg_fix a)
{
    pg_vec2 v[PG_MAX_POLYGON_VERTICES];
    for (int i = 0; i < g->count; ++i) {
        pg_vec2 p = g->vertices[g->count - 1 - i];
        v[i] = pg_v2(2 * a - p.x, p.y);
    }
    return geom_raw(v, g->count, g->radius);
}

static pg_geom mirror_y(const pg_geom *g)
{
    pg_vec2 v[PG_MAX_POLYGON_VERTICES];
    for (int i = 0; i < g->count; ++i) {
        pg_vec2 p = g->vertices[g->count - 1 - i];
        v[i] = pg_v2(p.x, -p.y);
    }
    return geom_raw(v, g->count, g->radius);
}

static void test_mirror_symmetry(void **state)
{
    (void)state;
    pgt_rng rng = pgt_rng_seed(7);
    for (int it = 0; it < 300; ++it) {
        pg_geom g = random_convex(&rng, 40 * pgt_unit(&rng) - 20, 40 * pgt_unit(&rng) - 20, 0.05 + 10 * pgt_unit(&rng));
        pg_fix a = (pg_fix)pgt_below(&rng, 1 << 20) - (1 << 19);
        pg_fix rho = (pg_fix)(1 + pgt_below(&rng, 50 << 16));
        pg_geom mx = mirror_x(&g, a), my = mirror_y(&g);
        pg_mass_data m = pg_geom_mass(&g, rho), ma = pg_geom_mass(&mx, rho), mb = pg_geom_mass(&my, rho);
        PG_EXPECT_EQ(ma.mass, m.mass, "it=%d", it);
        PG_EXPECT_EQ(ma.inertia, m.inertia, "it=%d", it);
        PG_EXPECT_EQ(ma.area, m.area, "it=%d", it);
        PG_EXPECT_EQ(ma.center.x, 2 * a - m.center.x, "it=%d", it);
        PG_EXPECT_EQ(ma.center.y, m.center.y, "it=%d", it);
        PG_EXPECT_EQ(mb.mass, m.mass, "it=%d", it);
        PG_EXPECT_EQ(mb.inertia, m.inertia, "it=%d", it);
        PG_EXPECT_EQ(mb.center.x, m.center.x, "it=%d", it);
        PG_EXPECT_EQ(mb.center.y, -m.center.y, "it=%d", it);
    }
    /* overlapping compounds too: crossings are computed from the original edge lines, so
     * they mirror exactly */
    for (int it = 0; it < 200; ++it) {
        pg_geom g[3], mg[3];
        const pg_geom *gs[3], *ms[3];
        pg_fix rho[3];
        for (int i = 0; i < 3; ++i) {
            g[i] = random_convex(&rng, 2 * pgt_unit(&rng), 2 * pgt_unit(&rng), 0.5 + 2 * pgt_unit(&rng));
            mg[i] = mirror_x(&g[i], 0);
            gs[i] = &g[i];
            ms[i] = &mg[i];
            rho[i] = (pg_fix)(1 + pgt_below(&rng, 10 << 16));
        }
        pg_mass_data m = pg_compound_mass(gs, rho, 3, mass_work), mm = pg_compound_mass(ms, rho, 3, mass_work);
        PG_EXPECT_EQ(mm.mass, m.mass, "compound it=%d", it);
        PG_EXPECT_EQ(mm.inertia, m.inertia, "compound it=%d", it);
        PG_EXPECT_EQ(mm.area, m.area, "compound it=%d", it);
        PG_EXPECT_EQ(mm.center.x, -m.center.x, "compound it=%d", it);
        PG_EXPECT_EQ(mm.center.y, m.center.y, "compound it=%d", it);
    }
}

static void test_translation(void **state)
{
    (void)state;
    pgt_rng rng = pgt_rng_seed(99);
    for (int it = 0; it < 200; ++it) {
        pg_geom g = random_convex(&rng, 0, 0, 0.05 + 25 * pgt_unit(&rng)), t;
        pg_fix dx = (pg_fix)pgt_below(&rng, 2000u << 16) - (1000 << 16), dy = (pg_fix)pgt_below(&rng, 2000u << 16) - (1000 << 16);
        pg_fix rho = (pg_fix)(1 + pgt_below(&rng, 100 << 16));
        t = g;
        for (int i = 0; i < t.count; ++i) t.vertices[i] = pg_v2(g.vertices[i].x + dx, g.vertices[i].y + dy);
        pg_mass_data m = pg_geom_mass(&g, rho), mt = pg_geom_mass(&t, rho);
        PG_EXPECT_EQ(mt.mass, m.mass, "it=%d", it);
        PG_EXPECT_EQ(mt.inertia, m.inertia, "it=%d", it);
        PG_EXPECT_EQ(mt.area, m.area, "it=%d", it);
        PG_EXPECT_EQ(mt.center.x, m.center.x + dx, "it=%d", it);
        PG_EXPECT_EQ(mt.center.y, m.center.y + dy, "it=%d", it);
        check_single(&t, rho, "far polygon");
    }
}

/* ---- random overlaps against an independent long double clipper ----------------------------------- */

typedef struct lpoly { ld x[80], y[80]; int n; } lpoly;

static lpoly lpoly_of(const pg_geom *g)
{
    lpoly p;
    p.n = g->count;
    for (int i = 0; i < g->count; ++i) { p.x[i] = fd(g->vertices[i].x); p.y[i] = fd(g->vertices[i].y); }
    return p;
}

/* Intersection of convex CCW polygons in long double (textbook Sutherland-Hodgman). */
static lpoly lclip(lpoly s, const lpoly *c)
{
    for (int k = 0; k < c->n && s.n > 0; ++k) {
        ld ax = c->x[k], ay = c->y[k], bx = c->x[(k + 1) % c->n], by = c->y[(k + 1) % c->n];
        lpoly o;
        o.n = 0;
        for (int i = 0; i < s.n; ++i) {
            ld px = s.x[(i + s.n - 1) % s.n], py = s.y[(i + s.n - 1) % s.n], qx = s.x[i], qy = s.y[i];
            ld dp = (bx - ax) * (py - ay) - (by - ay) * (px - ax), dq = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
            if (dq >= 0) {
                if (dp < 0) { ld t = dp / (dp - dq); o.x[o.n] = px + t * (qx - px); o.y[o.n] = py + t * (qy - py); ++o.n; }
                o.x[o.n] = qx; o.y[o.n] = qy; ++o.n;
            } else if (dp >= 0) {
                ld t = dp / (dp - dq);
                o.x[o.n] = px + t * (qx - px); o.y[o.n] = py + t * (qy - py); ++o.n;
            }
        }
        s = o;
    }
    return s;
}

/* A compound against inclusion-exclusion over long double intersections, with the
 * tolerance of the 2^-32 m rounding of every clipped vertex; and, with equal densities,
 * the union must not depend on the order of the polygons, bit for bit. */
static void check_compound_ref(const pg_geom *g, const pg_fix *rho, int n, const char *what)
{
    const pg_geom *gs[4];
    for (int i = 0; i < n; ++i) gs[i] = &g[i];
    pg_mass_data md = pg_compound_mass(gs, rho, n, mass_work);
    ld cx = fd(md.center.x), cy = fd(md.center.y);
    ref m = ref_zero(), ar = ref_zero();
    ld move_area = 0, move_mass = 0, move_j = 0;
    /* weight (-1)^(|S|-1) rho_max(S) */
    for (unsigned s = 1; s < (1u << n); ++s) {
        int top = 0, size = 0;
        lpoly p;
        p.n = 0;
        for (int i = 0; i < n; ++i)
            if (s >> i & 1u) {
                lpoly gi = lpoly_of(&g[i]);
                p = size == 0 ? gi : lclip(p, &gi);
                top = i;
                ++size;
            }
        if (p.n < 3) continue;
        ref r = ref_pts(p.x, p.y, p.n, cx, cy);
        ld sign = size % 2 ? 1 : -1;
        ref_add(&m, r, sign * fd(rho[top]));
        ref_add(&ar, r, sign);
        if (size >= 2) { /* a clipped polygon: its vertices are rounded to 2^-32 m */
            ld per = 0, r2 = 0;
            for (int i = 0; i < p.n; ++i) {
                int k = (i + 1) % p.n;
                ld ex = p.x[i] - cx, ey = p.y[i] - cy;
                per += sqrtl((p.x[k] - p.x[i]) * (p.x[k] - p.x[i]) + (p.y[k] - p.y[i]) * (p.y[k] - p.y[i]));
                if (ex * ex + ey * ey > r2) r2 = ex * ex + ey * ey;
            }
            ld mv = per * 0.70710678118654752L / Q32;
            move_area += mv;
            move_mass += mv * fd(rho[top]);
            move_j += mv * fd(rho[top]) * r2;
        }
    }
    {
        tol t;
        t.area = move_area * Q32;
        t.mass = move_mass * Q32;
        t.center = m.a > 0 ? move_mass * 8 / m.a * Q16 : 0; /* |c - x| < 8 m for these */
        t.inertia = move_j * Q36;
        expect_md(&md, m, ar, t, what);
    }
    {
        const pg_geom *rev[4];
        pg_fix same[4];
        for (int i = 0; i < n; ++i) { rev[i] = gs[n - 1 - i]; same[i] = rho[0]; }
        pg_mass_data x = pg_compound_mass(gs, same, n, mass_work), y = pg_compound_mass(rev, same, n, mass_work);
        expect_same(&x, &y, what);
    }
}

static void test_random_overlaps(void **state)
{
    (void)state;
    pgt_rng rng = pgt_rng_seed(2024);
    for (int it = 0; it < 300; ++it) {
        int n = 2 + (int)pgt_below(&rng, 3); /* 2..4 polygons */
        pg_geom g[4];
        pg_fix rho[4];
        char what[48];
        for (int i = 0; i < n; ++i) {
            g[i] = random_convex(&rng, 3 * pgt_unit(&rng), 3 * pgt_unit(&rng), 0.3 + 2 * pgt_unit(&rng));
            rho[i] = (pg_fix)(1 + pgt_below(&rng, 10 << 16));
        }
        snprintf(what, sizeof what, "random overlap it=%d n=%d", it, n);
        check_compound_ref(g, rho, n, what);
    }
}

/* Clip lines through vertices: B's edge passes exactly through two corners of A, so A∩B
 * has vertices ON that line whose outgoing edge runs along it; C then cuts that edge
 * obliquely, and the crossing must be taken with B's line, not A's. */
static void test_overlap_through_vertices(void **state)
{
    (void)state;
    double tri[6] = {2, 0, 0, 2, -3, -3}, cut[6] = {-1, -0.2, 4, -3, 4, 1.3};
    pg_geom g[3];
    pg_fix rho[3] = {fx(1.0), fx(2.0), fx(4.0)};
    g[0] = box(0, 0, 2, 2);
    g[1] = poly(tri, 3);
    g[2] = poly(cut, 3);
    check_compound_ref(g, rho, 3, "through vertices A,B,C");
    {
        pg_geom h[3] = {g[1], g[0], g[2]};
        check_compound_ref(h, rho, 3, "through vertices B,A,C");
    }
    {
        pg_geom h[3] = {g[2], g[0], g[1]};
        check_compound_ref(h, rho, 3, "through vertices C,A,B");
    }
}

static void test_zero_mass_centres(void **state)
{
    (void)state;
    pg_geom s1 = capsule(0, 0, 2, 0, 0), s2 = capsule(4, 2, 4, 4, 0), b = box(10, 10, 12, 14);
    const pg_geom *gs[3] = {&s1, &s2, &b};
    pg_fix rho[3] = {fx(1.0), fx(1.0), 0};
    /* only segments: the mean of their midpoints (1, 0) and (4, 3) */
    pg_mass_data md = pg_compound_mass(gs, rho, 2, mass_work);
    PG_EXPECT_EQ(md.center.x, fx(2.5), "%s", "segments only");
    PG_EXPECT_EQ(md.center.y, fx(1.5), "%s", "segments only");
    PG_EXPECT_EQ(md.mass, 0, "%s", "segments only");
    /* a massless box: the centroid of its area */
    md = pg_compound_mass(gs, rho, 3, mass_work);
    PG_EXPECT_EQ(md.mass, 0, "%s", "massless box");
    PG_EXPECT_EQ(md.inertia, 0, "%s", "massless box");
    PG_EXPECT_EQ(md.area, INT64_C(8) << 32, "%s", "massless box");
    PG_EXPECT_EQ(md.center.x, fx(11.0), "%s", "massless box");
    PG_EXPECT_EQ(md.center.y, fx(12.0), "%s", "massless box");
}

/* Inverse mass and inertia: the two-division path agrees with the long division
 * (pg__div64_shl) everywhere, including the edges of its range and the fallback. */
static void test_reciprocal_matches_long_division(void **state)
{
    uint64_t x = UINT64_C(88172645463325252);
    int e, k, j;
    long i;
    (void)state;
    for (e = 7; e <= 11; e += 4) {
        for (i = 0; i < 200000; ++i) {
            int64_t d;
            int bits;
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            bits = 1 + (int)(x % 63u);
            d = (int64_t)(x >> (64 - bits));
            if (d <= 0) continue;
            if (pg__reciprocal_pow2(e, d) != pg__div64_shl(INT64_C(1) << (25 + e), d, 38))
                fail_msg("e %d, d %lld: the two-division reciprocal differs from the long division", e, (long long)d);
        }
        for (k = 0; k < 63; ++k)
            for (j = -3; j <= 3; ++j) {
                int64_t d = ((int64_t)1 << k) + j;
                if (d <= 0) continue;
                if (pg__reciprocal_pow2(e, d) != pg__div64_shl(INT64_C(1) << (25 + e), d, 38))
                    fail_msg("e %d, d %lld (near 2^%d): the two-division reciprocal differs", e, (long long)d, k);
            }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle),
        cmocka_unit_test(test_box),
        cmocka_unit_test(test_off_centre_box),
        cmocka_unit_test(test_triangles),
        cmocka_unit_test(test_capsule),
        cmocka_unit_test(test_circle_matches_zero_length_capsule),
        cmocka_unit_test(test_segment),
        cmocka_unit_test(test_octagon),
        cmocka_unit_test(test_compound_separate),
        cmocka_unit_test(test_compound_overlap_l_shape),
        cmocka_unit_test(test_compound_identical),
        cmocka_unit_test(test_compound_nested),
        cmocka_unit_test(test_star),
        cmocka_unit_test(test_density_linear),
        cmocka_unit_test(test_extremes),
        cmocka_unit_test(test_mirror_symmetry),
        cmocka_unit_test(test_translation),
        cmocka_unit_test(test_random_overlaps),
        cmocka_unit_test(test_overlap_through_vertices),
        cmocka_unit_test(test_zero_mass_centres),
        cmocka_unit_test(test_reciprocal_matches_long_division),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
