/* test_soft_body.c — the soft-body helpers (pogon/soft_body.h, docs/soft-bodies.md): a
 * blob at rest under gravity keeps its area within the documented bound; a rope of rigid
 * links hangs with its length; a cloth strip has the documented links; every failing
 * call changes nothing (the state hash) and says why. */
#include "pg_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pg_test_world.h"
#include "pogon/soft_body.h"
#include "pogon/replay.h"

/* |got - want| <= tol, printing both on failure */
#define NEAR(got, want, tol, what) PG_EXPECT_LE(fabs((got) - (want)), (tol), "%s", what)

static test_world ground_world(uint32_t bodies, uint32_t joints)
{
    pg_world_def d = pg_default_world_def();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id g;
    test_world t;
    d.max_bodies = d.max_shapes = bodies;
    d.max_contacts = 8 * bodies;
    d.max_joints = joints;
    t = make_world_def(&d);
    assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(40), fx(1), &g), PG_OK); /* top at y = 0.5 */
    return t;
}

static pg_vec2 centre_of(pg_world *w, uint32_t slot)
{
    pg_body_id id = {slot, 1};
    return pg_body_position(w, id);
}

/* Shoelace area of the ring circles' centres (slots first .. first + n - 1, in order). */
static double ring_area(pg_world *w, uint32_t first, uint32_t n)
{
    double a = 0;
    uint32_t i;
    for (i = 0; i < n; ++i) {
        pg_vec2 p = centre_of(w, first + i), q = centre_of(w, first + (i + 1) % n);
        a += fd(p.x) * fd(q.y) - fd(q.x) * fd(p.y);
    }
    return 0.5 * a;
}

/* A blob of 12 circles (default def: radius 0.2, 5 Hz, ratio 0.7) on a ring of 1 m,
 * dropped from 1 m onto the ground: after 5 s at rest its ring encloses at least 85 % of
 * its area at rest in the air (a regular 12-gon of radius 1 m: 3 m^2), and at most 100 %
 * plus rounding (springs do not inflate it). */
static void blob_keeps_its_area(void **state)
{
    test_world t = ground_world(16, 32);
    pg_soft_def sd = pg_default_soft_def();
    pg_body_id c;
    double a0, a;
    int f;
    (void)state;
    assert_int_equal(pg_make_soft_blob(t.w, &sd, pg_v2(0, fx(2.75)), fx(1), 12, &c), PG_OK);
    assert_int_equal(c.index, 1);
    a0 = ring_area(t.w, 2, 12);
    NEAR(a0, 3.0, 1e-3, "the ring's area as made");
    for (f = 0; f < 300; ++f) assert_int_equal(pg_world_step(t.w), PG_OK);
    a = ring_area(t.w, 2, 12);
    printf("blob at rest: area %.4f m^2 of %.4f (%.1f %%), centre at y = %.3f m\n", a, a0, 100.0 * a / a0, fd(centre_of(t.w, 1).y));
    PG_EXPECT_LE(0.85 * a0, a, "%s", "the blob's area at rest against 85 % of its area");
    PG_EXPECT_LE(a, a0 * 1.001, "%s", "the blob's area at rest against its area");
    PG_EXPECT_LE(fabs(fd(pg_body_linear_velocity(t.w, c).y)), 0.01, "%s", "the blob is at rest");
    free_world(&t);
}

/* A rope of 20 circles with rigid links (hertz 0) 0.25 m apart, hanging straight down
 * from a pin: after 5 s its bottom circle is 19 x 0.25 = 4.75 m below the pin, to 1 %. */
static void rope_hangs_with_its_length(void **state)
{
    test_world t = ground_world(24, 24);
    pg_soft_def sd = pg_default_soft_def();
    pg_body_def bd = pg_default_body_def();
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_body_id pin, first;
    pg_joint_id j;
    double drop;
    int f;
    (void)state;
    sd.radius = fx(0.1);
    sd.hertz = 0;
    bd.position = pg_v2(0, fx(10));
    assert_int_equal(pg_body_create(t.w, &bd, &pin), PG_OK);
    assert_int_equal(pg_make_rope(t.w, &sd, pg_v2(0, fx(10)), pg_v2(0, fx(10 - 4.75)), 20, &first), PG_OK);
    jd.body_a = pin;
    jd.body_b = first;
    assert_int_equal(pg_revolute_joint_create(t.w, &jd, &j), PG_OK);
    for (f = 0; f < 300; ++f) assert_int_equal(pg_world_step(t.w), PG_OK);
    drop = 10.0 - fd(centre_of(t.w, first.index + 19).y);
    printf("rope of 20 rigid links: bottom %.4f m below the pin (4.75 expected)\n", drop);
    NEAR(drop, 4.75, 0.0475, "the rope's hanging length");
    free_world(&t);
}

/* A 4 x 3 cloth strip: 12 circles, each joined as documented; its corner has 3 links
 * (right, up, diagonal), an inner circle 8. */
static void cloth_has_its_links(void **state)
{
    test_world t = ground_world(16, 64);
    pg_soft_def sd = pg_default_soft_def();
    pg_body_id first, inner = {1 + 5, 1};
    pg_joint_id js[16];
    pg_world_stats st;
    (void)state;
    assert_int_equal(pg_make_cloth_strip(t.w, &sd, pg_v2(fx(-1), fx(3)), fx(0.5), 4, 3, &first), PG_OK);
    st = pg_world_get_stats(t.w);
    assert_int_equal(st.body_count, 13);
    assert_int_equal(pg_body_joints(t.w, first, js, 16), 3);
    assert_int_equal(pg_body_joints(t.w, inner, js, 16), 8);
    {
        pg_joint_id last = {3 * 3 + 4 * 2 + 2 * 3 * 2 - 1, 1}, none = {3 * 3 + 4 * 2 + 2 * 3 * 2, 1};
        assert_true(pg_joint_is_valid(t.w, last));
        assert_false(pg_joint_is_valid(t.w, none));
    }
    assert_int_equal(pg_world_step(t.w), PG_OK);
    free_world(&t);
}

static void failing_calls_change_nothing(void **state)
{
    test_world t = ground_world(8, 8);
    pg_soft_def sd = pg_default_soft_def(), bad;
    pg_body_id first = {5, 5};
    uint64_t h = pg_world_hash(t.w);
    (void)state;
    /* 13 bodies do not fit 7 free slots */
    assert_int_equal(pg_make_soft_blob(t.w, &sd, pg_v2(0, fx(3)), fx(1), 12, &first), PG_ERR_CAPACITY);
    assert_non_null(strstr(pg_world_last_error(t.w), "max_bodies"));
    assert_int_equal(first.index, 0);
    /* a rope of 8 circles needs 8 body slots: 7 are free */
    assert_int_equal(pg_make_rope(t.w, &sd, pg_v2(0, fx(3)), pg_v2(fx(4), fx(3)), 8, &first), PG_ERR_CAPACITY);
    bad = sd;
    bad.radius = fx(0.01);
    assert_int_equal(pg_make_rope(t.w, &bad, pg_v2(0, fx(3)), pg_v2(fx(1), fx(3)), 3, &first), PG_ERR_ENVELOPE);
    bad = sd;
    bad.hertz = fx(-1);
    assert_int_equal(pg_make_rope(t.w, &bad, pg_v2(0, fx(3)), pg_v2(fx(1), fx(3)), 3, &first), PG_ERR_INVALID_ARGUMENT);
    bad = sd;
    bad.pg__cookie = 0;
    assert_int_equal(pg_make_rope(t.w, &bad, pg_v2(0, fx(3)), pg_v2(fx(1), fx(3)), 3, &first), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_default_soft_def"));
    /* circles that would overlap: 3 circles on 0.5 m with radius 0.2 */
    assert_int_equal(pg_make_rope(t.w, &sd, pg_v2(0, fx(3)), pg_v2(fx(0.5), fx(3)), 3, &first), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "overlap"));
    assert_int_equal(pg_make_soft_blob(t.w, &sd, pg_v2(0, fx(3)), fx(0.3), 3, &first), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_make_soft_blob(t.w, &sd, pg_v2(0, fx(3)), fx(1), 2, &first), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_make_cloth_strip(t.w, &sd, pg_v2(0, fx(3)), fx(0.5), 1, 3, &first), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_make_cloth_strip(t.w, &sd, pg_v2(fx(999), fx(3)), fx(0.5), 4, 2, &first), PG_ERR_ENVELOPE);
    assert_int_equal(pg_make_rope(NULL, &sd, pg_v2(0, 0), pg_v2(fx(1), 0), 2, &first), PG_ERR_NULL);
    assert_true(pg_world_hash(t.w) == h);
    /* and one that fits */
    assert_int_equal(pg_make_rope(t.w, &sd, pg_v2(0, fx(3)), pg_v2(fx(2), fx(3)), 5, &first), PG_OK);
    assert_true(pg_world_hash(t.w) != h);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(blob_keeps_its_area),
        cmocka_unit_test(rope_hangs_with_its_length),
        cmocka_unit_test(cloth_has_its_links),
        cmocka_unit_test(failing_calls_change_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
