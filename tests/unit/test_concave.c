/* test_concave.c — concave polygons (src/core/decompose.c, src/core/concave.c): the pieces are
 * convex polygons pg_geometry_polygon accepts, their areas add up to the polygon's
 * exactly (integer coordinates: both are exact integers, twice the area in raw units
 * squared), a body of them has the polygon's mass, centre and inertia, and bad input
 * is refused with the vertex or edge named, changing nothing.
 *
 * Mass references are computed in long double from the exact Q16.16 vertices with the
 * polygon formulas (shoelace moments), so they need no decomposition: mass and area
 * agree to one rounding of their formats (1 LSB), the centre to 1 LSB of Q16.16, the
 * inertia (about the library's rounded centre, as mass.h defines it) to 1 LSB of Q28.36
 * plus 2^-40 relative for the reference's own rounding.
 */
#include "pg_test.h"
#include "pg_test_world.h"

#include "pogon/replay.h"
#include "body.h"
#include "concave.h"
#include "decompose.h"

typedef long double ld;

/* Twice the signed area in raw units squared: exact. */
static int64_t area2(const pg_vec2 *v, int32_t n)
{
    int64_t a = 0;
    int32_t i;
    for (i = 0; i < n; ++i) {
        pg_vec2 p = v[i], q = v[(i + 1) % n];
        a += (int64_t)p.x * q.y - (int64_t)q.x * p.y;
    }
    return a;
}

static int32_t make_circle(pg_vec2 *v, int32_t n, double r)
{
    int32_t i;
    for (i = 0; i < n; ++i) v[i] = pg_v2(fx(r * cos(2 * PGT_PI * i / n)), fx(r * sin(2 * PGT_PI * i / n)));
    return n;
}

/* a star: alternate radii, concave at every other vertex */
static int32_t make_star(pg_vec2 *v, int32_t n, double r1, double r2)
{
    int32_t i;
    for (i = 0; i < n; ++i) {
        double r = (i & 1) ? r2 : r1;
        v[i] = pg_v2(fx(r * cos(2 * PGT_PI * i / n)), fx(r * sin(2 * PGT_PI * i / n)));
    }
    return n;
}

static int32_t make_bowl(pg_vec2 *v)
{
    /* a U: outer 4 x 3, walls 0.5 thick, counter-clockwise */
    static const double p[][2] = {{-2, 0}, {2, 0}, {2, 3}, {1.5, 3}, {1.5, 0.5}, {-1.5, 0.5}, {-1.5, 3}, {-2, 3}};
    int32_t i;
    for (i = 0; i < 8; ++i) v[i] = pg_v2(fx(p[i][0]), fx(p[i][1]));
    return 8;
}

static int32_t make_comb(pg_vec2 *v)
{
    /* a comb of 10 teeth: 42 vertices, clockwise */
    int32_t n = 0, k;
    v[n++] = pg_v2(fx(0), fx(0));
    for (k = 0; k < 10; ++k) {
        v[n++] = pg_v2(fx(k * 1.0), fx(2 + 0.1 * k));
        v[n++] = pg_v2(fx(k * 1.0 + 0.5), fx(2 + 0.1 * k));
        v[n++] = pg_v2(fx(k * 1.0 + 0.5), fx(0.6));
        v[n++] = pg_v2(fx(k * 1.0 + 1.0), fx(0.6));
    }
    v[n - 1] = pg_v2(fx(10), fx(0)); /* the last gap's foot closes the base */
    return n;
}

static void reverse(pg_vec2 *v, int32_t n)
{
    int32_t i;
    for (i = 1; i < n - i; ++i) {
        pg_vec2 t = v[i];
        v[i] = v[n - i];
        v[n - i] = t;
    }
}

static void check_pieces(const pg_vec2 *v, int32_t n);

/* Random star-shaped polygons (vertices at increasing angles, so always simple): each
 * is split into valid pieces whose areas add up, or refused only for thinness (or, by
 * chance, a collinear vertex). Seeded: a failure reproduces. */
static void test_random_polygons(void **state)
{
    pgt_rng rng = pgt_rng_seed(28);
    int round, split = 0;
    (void)state;
    for (round = 0; round < 400; ++round) {
        pg_vec2 v[PG_CONCAVE_MAX_VERTICES];
        pg_geometry pieces[PG_CONCAVE_MAX_PIECES];
        int32_t n = 3 + (int32_t)pgt_below(&rng, PG_CONCAVE_MAX_VERTICES - 2), i, count;
        double scale = 0.05 + 10.0 * pgt_unit(&rng);
        char msg[160];
        pg_result r;
        for (i = 0; i < n; ++i) {
            double a = 2 * PGT_PI * (i + 0.8 * pgt_unit(&rng)) / n, rad = scale * (0.2 + pgt_unit(&rng));
            v[i] = pg_v2(fx(rad * cos(a)), fx(rad * sin(a)));
        }
        r = pg_geometry_decompose(v, n, pieces, PG_CONCAVE_MAX_PIECES, &count, msg, sizeof msg);
        if (r == PG_OK) {
            check_pieces(v, n);
            ++split;
        } else if (r != PG_ERR_ENVELOPE && r != PG_ERR_DEGENERATE) {
            fail_msg("round %d, %d vertices: %s %s", round, n, pg_result_name(r), msg);
        }
    }
    /* most are thick enough: the test is not passing by refusing everything */
    PG_EXPECT_LE(200, split, "%s", "polygons split");
}

static void check_pieces(const pg_vec2 *v, int32_t n)
{
    pg_geometry pieces[PG_CONCAVE_MAX_PIECES];
    int32_t count, k, i, j;
    int64_t sum = 0, want = area2(v, n);
    char msg[160];
    pg_result r = pg_geometry_decompose(v, n, pieces, PG_CONCAVE_MAX_PIECES, &count, msg, sizeof msg);
    if (r != PG_OK) fail_msg("decompose refused %d vertices: %s", n, msg);
    assert_true(count >= 1 && count <= n - 2);
    for (k = 0; k < count; ++k) {
        pg_geometry again;
        assert_int_equal(pieces[k].kind, PG_SHAPE_POLYGON);
        assert_true(pieces[k].count >= 3 && pieces[k].count <= PG_MAX_VERTICES);
        /* convex, counter-clockwise, thick enough: exactly what a hand-made geometry needs */
        assert_int_equal(pg_geometry_polygon(pieces[k].vertices, pieces[k].count, &again), PG_OK);
        assert_memory_equal(again.vertices, pieces[k].vertices, sizeof again.vertices);
        for (i = 0; i < pieces[k].count; ++i) { /* every piece vertex is a polygon vertex */
            int found = 0;
            for (j = 0; j < n; ++j) found |= pg_v2_equal(v[j], pieces[k].vertices[i]);
            assert_true(found);
        }
        sum += area2(pieces[k].vertices, pieces[k].count);
    }
    PG_EXPECT_EQ(sum, want < 0 ? -want : want, "%d vertices", n);
}

static void test_pieces_convex_and_areas_add_up(void **state)
{
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES];
    int32_t n;
    (void)state;
    n = make_bowl(v);
    check_pieces(v, n);
    reverse(v, n);
    check_pieces(v, n);
    n = make_comb(v);
    check_pieces(v, n);
    n = make_circle(v, 64, 1.0);
    check_pieces(v, n);
    n = make_circle(v, 64, 20.0);
    check_pieces(v, n);
    n = make_star(v, 64, 3.0, 1.5);
    check_pieces(v, n);
    n = make_star(v, 10, 1.0, 0.4);
    check_pieces(v, n);
    reverse(v, n);
    check_pieces(v, n);
}

/* The pieces are a pure function of the input: either winding gives the same pieces
 * (the clipping walks counter-clockwise from vertex 0 in both). */
static void test_winding_gives_same_pieces(void **state)
{
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES];
    pg_geometry a[PG_CONCAVE_MAX_PIECES], b[PG_CONCAVE_MAX_PIECES];
    int32_t n = make_star(v, 24, 2.0, 1.0), ca, cb;
    (void)state;
    assert_int_equal(pg_geometry_decompose(v, n, a, PG_CONCAVE_MAX_PIECES, &ca, NULL, 0), PG_OK);
    reverse(v, n);
    assert_int_equal(pg_geometry_decompose(v, n, b, PG_CONCAVE_MAX_PIECES, &cb, NULL, 0), PG_OK);
    assert_int_equal(ca, cb);
    assert_memory_equal(a, b, (size_t)ca * sizeof a[0]);
}

static void expect_refused(const pg_vec2 *v, int32_t n, pg_result code, const char *words)
{
    pg_geometry pieces[PG_CONCAVE_MAX_PIECES];
    int32_t count = 99;
    char msg[160];
    assert_int_equal(pg_geometry_decompose(v, n, pieces, PG_CONCAVE_MAX_PIECES, &count, msg, sizeof msg), code);
    assert_int_equal(count, 0);
    if (strstr(msg, words) == NULL) fail_msg("'%s' does not say '%s'", msg, words);
}

static void test_refusals(void **state)
{
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES + 2];
    pg_geometry one[1];
    int32_t n, count;
    (void)state;
    n = make_bowl(v);
    expect_refused(v, 2, PG_ERR_INVALID_ARGUMENT, "3..64 vertices, got 2");
    make_circle(v, 65, 5.0);
    expect_refused(v, 65, PG_ERR_INVALID_ARGUMENT, "3..64 vertices, got 65");
    n = make_bowl(v);
    v[5] = v[2]; /* a repeated point */
    expect_refused(v, n, PG_ERR_DEGENERATE, "vertex 5 (2, 3) repeats vertex 2");
    n = make_bowl(v);
    v[1] = pg_v2(fx(2), 0);
    v[2] = pg_v2(fx(2), fx(1.5));
    v[3] = pg_v2(fx(2), fx(3)); /* vertex 2 lies on the line from 1 to 3 */
    expect_refused(v, n, PG_ERR_DEGENERATE, "vertex 2 (2, 1.5) lies on the line through its neighbours");
    /* a bow tie: edges 0 and 2 cross */
    v[0] = pg_v2(0, 0);
    v[1] = pg_v2(fx(1), fx(1));
    v[2] = pg_v2(fx(1), 0);
    v[3] = pg_v2(0, fx(1));
    expect_refused(v, 4, PG_ERR_INVALID_ARGUMENT, "edges 0 (vertex 0 to 1) and 2 (vertex 2 to 3) cross or touch");
    /* a vertex touching a non-adjacent edge */
    v[0] = pg_v2(0, 0);
    v[1] = pg_v2(fx(4), 0);
    v[2] = pg_v2(fx(4), fx(2));
    v[3] = pg_v2(fx(2), 0); /* on edge 0 */
    v[4] = pg_v2(0, fx(2));
    expect_refused(v, 5, PG_ERR_INVALID_ARGUMENT, "cross or touch");
    /* beyond the envelope */
    n = make_bowl(v);
    v[4].x = fx(1000.5);
    expect_refused(v, n, PG_ERR_ENVELOPE, "vertex 4 ");
    /* a part thinner than 0.01 m: a U whose bottom is 0.008 m thick */
    n = make_bowl(v);
    v[4].y = fx(0.008);
    v[5].y = fx(0.008);
    expect_refused(v, n, PG_ERR_ENVELOPE, "thinner than 0.01 m");
    /* too short an edge */
    n = make_bowl(v);
    v[3] = pg_v2(fx(1.997), fx(3));
    expect_refused(v, n, PG_ERR_DEGENERATE, "edge 2 (vertex 2 to 3) is shorter than 0.005 m");
    /* capacity */
    n = make_bowl(v);
    assert_int_equal(pg_geometry_decompose(v, n, one, 1, &count, NULL, 0), PG_ERR_CAPACITY);
    assert_int_equal(pg_geometry_decompose(NULL, n, one, 1, &count, NULL, 0), PG_ERR_NULL);
}

/* Reference mass properties of a simple polygon (either winding) in long double. */
static void polygon_reference(const pg_vec2 *v, int32_t n, ld *area, ld *cx, ld *cy, ld *inertia_unit)
{
    ld a = 0, sx = 0, sy = 0, ixx = 0;
    int32_t i;
    for (i = 0; i < n; ++i) {
        ld x0 = v[i].x / 65536.0L, y0 = v[i].y / 65536.0L, x1 = v[(i + 1) % n].x / 65536.0L, y1 = v[(i + 1) % n].y / 65536.0L;
        ld c = x0 * y1 - x1 * y0;
        a += c;
        sx += (x0 + x1) * c;
        sy += (y0 + y1) * c;
        ixx += (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1) * c;
    }
    a /= 2;
    *cx = sx / (6 * a);
    *cy = sy / (6 * a);
    *area = a < 0 ? -a : a;
    /* polar moment about the origin per unit density, then about the centre */
    *inertia_unit = (a < 0 ? -ixx : ixx) / 12 - *area * (*cx * *cx + *cy * *cy);
}

static void check_body(const pg_vec2 *v, int32_t n, double density)
{
    test_world t;
    pg_world_def wd = pg_default_world_def();
    pg_body_def bd = dynamic_at(1, 2);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    ld area, cx, cy, iu, mass, inertia;
    pg_vec2 c;
    wd.max_shapes = 128;
    t = make_world_def(&wd);
    sd.density = fx(density);
    if (pg_make_concave(t.w, &bd, &sd, v, n, &id) != PG_OK) fail_msg("%s", pg_world_last_error(t.w));
    polygon_reference(v, n, &area, &cx, &cy, &iu);
    mass = area * (ld)sd.density / 65536.0L;
    inertia = iu * (ld)sd.density / 65536.0L;
    PG_EXPECT_LE(fabsl((ld)pg_body_mass(t.w, id) - mass * 4294967296.0L), 1.0, "mass of %d vertices", n);
    c = pg_body_world_center(t.w, id);
    PG_EXPECT_LE(fabsl((ld)c.x - (cx + 1) * 65536.0L), 1.0, "centre x of %d vertices", n);
    PG_EXPECT_LE(fabsl((ld)c.y - (cy + 2) * 65536.0L), 1.0, "centre y of %d vertices", n);
    /* the library's inertia is about its rounded centre: move the reference there */
    inertia += mass * ((c.x / 65536.0L - 1 - cx) * (c.x / 65536.0L - 1 - cx) + (c.y / 65536.0L - 2 - cy) * (c.y / 65536.0L - 2 - cy));
    PG_EXPECT_LE(fabsl((ld)pg_body_inertia(t.w, id) - inertia * 68719476736.0L), 1.0 + 0x1p-40L * inertia * 68719476736.0L,
                 "inertia of %d vertices", n);
    free_world(&t);
}

static void test_body_mass_is_the_polygons(void **state)
{
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES];
    int32_t n;
    (void)state;
    n = make_bowl(v);
    check_body(v, n, 1.0);
    n = make_star(v, 64, 3.0, 1.5);
    check_body(v, n, 2.5);
    n = make_comb(v);
    check_body(v, n, 0.5);
    n = make_circle(v, 64, 1.0);
    check_body(v, n, 1.0);
}

static void test_failing_make_changes_nothing(void **state)
{
    test_world t;
    pg_world_def wd = pg_default_world_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id = {3, 3}, ok;
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES];
    int32_t n = make_bowl(v);
    uint64_t before;
    (void)state;
    wd.max_shapes = 4;
    t = make_world_def(&wd);
    assert_int_equal(pg_make_box(t.w, &bd, &sd, fx(1), fx(1), &ok), PG_OK);
    before = pg_world_hash(t.w);
    /* a self-intersecting polygon: the vertex swap crosses two edges */
    {
        pg_vec2 s = v[1];
        v[1] = v[2];
        v[2] = s;
    }
    assert_int_equal(pg_make_concave(t.w, &bd, &sd, v, n, &id), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_make_concave: edges"));
    assert_int_equal(id.index, 0);
    assert_true(pg_world_hash(t.w) == before);
    n = make_comb(v); /* more pieces than the 3 free shape slots */
    {
        pg_geometry pieces[PG_CONCAVE_MAX_PIECES];
        int32_t count;
        assert_int_equal(pg_geometry_decompose(v, n, pieces, PG_CONCAVE_MAX_PIECES, &count, NULL, 0), PG_OK);
        assert_true(count > 3);
    }
    assert_int_equal(pg_make_concave(t.w, &bd, &sd, v, n, &id), PG_ERR_CAPACITY);
    assert_true(pg_world_hash(t.w) == before);
    /* a dynamic body reaches 50 m at most */
    v[0] = pg_v2(0, fx(-60));
    assert_int_equal(pg_make_concave(t.w, &bd, &sd, v, n, &id), PG_ERR_ENVELOPE);
    assert_true(pg_world_hash(t.w) == before);
    free_world(&t);
}

/* pg_make_concave works in the world's scratch (src/core/concave.c): in the smallest
 * worlds (one body, one contact, no joints), whose scratch is sized by the mass work and
 * the decomposition alone, the scratch holds the working set, the body is the same bit
 * for bit as in a default world, and a refusal names the edges at fault as there. */
static void test_smallest_world_makes_the_same_body(void **state)
{
    test_world big, small;
    pg_world_def wd = pg_default_world_def();
    pg_body_def bd = dynamic_at(1, 2);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id a, b;
    pg_vec2 v[PG_CONCAVE_MAX_VERTICES], ca, cb;
    int32_t n = make_star(v, 64, 3.0, 1.5);
    (void)state;
    sd.density = fx(2.5);
    big = make_world_def(&wd);
    wd.max_bodies = 1;
    wd.max_contacts = 1;
    wd.max_joints = 0;
    wd.max_shapes = PG_CONCAVE_MAX_PIECES;
    small = make_world_def(&wd);
    /* the working set follows the mass scratch in the world's scratch */
    assert_true(pg__concave_scratch_bytes() >= pg__body_mass_scratch_bytes() + sizeof(pg__decomposition));
    assert_true(small.w->solver_scratch_bytes >= pg__concave_scratch_bytes());
    if (pg_make_concave(big.w, &bd, &sd, v, n, &a) != PG_OK) fail_msg("%s", pg_world_last_error(big.w));
    if (pg_make_concave(small.w, &bd, &sd, v, n, &b) != PG_OK) fail_msg("%s", pg_world_last_error(small.w));
    assert_int_equal(pg_world_get_stats(big.w).shape_count, pg_world_get_stats(small.w).shape_count);
    assert_true(pg_body_mass(big.w, a) == pg_body_mass(small.w, b));
    assert_true(pg_body_inertia(big.w, a) == pg_body_inertia(small.w, b));
    ca = pg_body_world_center(big.w, a);
    cb = pg_body_world_center(small.w, b);
    assert_int_equal(ca.x, cb.x);
    assert_int_equal(ca.y, cb.y);
    free_world(&small);
    wd.max_shapes = 1;
    small = make_world_def(&wd);
    assert_true(small.w->solver_scratch_bytes >= pg__concave_scratch_bytes());
    n = make_bowl(v);
    {
        pg_vec2 s = v[1]; /* the swap crosses two edges */
        v[1] = v[2];
        v[2] = s;
    }
    assert_int_equal(pg_make_concave(small.w, &bd, &sd, v, n, &b), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_make_concave(big.w, &bd, &sd, v, n, &a), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(small.w), "pg_make_concave: edges 0 (vertex 0 to 1) and 2 (vertex 2 to 3) cross"));
    assert_string_equal(pg_world_last_error(small.w), pg_world_last_error(big.w));
    free_world(&small);
    free_world(&big);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pieces_convex_and_areas_add_up),
        cmocka_unit_test(test_winding_gives_same_pieces),
        cmocka_unit_test(test_random_polygons),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_body_mass_is_the_polygons),
        cmocka_unit_test(test_failing_make_changes_nothing),
        cmocka_unit_test(test_smallest_world_makes_the_same_body),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
