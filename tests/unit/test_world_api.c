/* test_world_api.c — the public world API (include/pogon/pogon.h): every error path,
 * handles, the envelope, geometry validation, masses of the ready-made kinds, events
 * and queries.
 *
 * Expectations come from pogon.h's documentation and from closed-form geometry
 * (areas, second moments); nothing here is a value copied from a run.
 */
#include "pg_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pg_test_world.h"

#define Q32 4294967296.0
#define Q36 68719476736.0


/* ---- a world in malloc'd memory -------------------------------------------------------- */
static test_world make_world(uint32_t bodies, uint32_t shapes, uint32_t contacts)
{
    pg_world_def d = pg_default_world_def();
    d.max_bodies = bodies;
    d.max_shapes = shapes;
    d.max_contacts = contacts;
    return make_world_def(&d);
}

static uint32_t body_count(const pg_world *w) { return pg_world_get_stats(w).body_count; }
static uint32_t shape_count(const pg_world *w) { return pg_world_get_stats(w).shape_count; }

/* ---- results ------------------------------------------------------------------------------ */
static void test_result_names_and_messages(void **state)
{
    static const char *const expected_names[PG_RESULT_COUNT] = {
        "PG_OK", "PG_ERR_NULL", "PG_ERR_INVALID_ARGUMENT", "PG_ERR_STALE_HANDLE", "PG_ERR_CAPACITY", "PG_ERR_MEMORY",
        "PG_ERR_ENVELOPE", "PG_ERR_DEGENERATE", "PG_ERR_NOT_CONVEX", "PG_ERR_BODY_TYPE", "PG_ERR_NOT_FOUND",
        "PG_ERR_INCOMPATIBLE"};
    int i, j;
    (void)state;
    for (i = 0; i < PG_RESULT_COUNT; ++i) {
        const char *n = pg_result_name((pg_result)i), *m = pg_result_message((pg_result)i);
        assert_non_null(n);
        assert_non_null(m);
        assert_true(strlen(n) > 0);
        assert_true(strlen(m) > 0);
        assert_string_equal(n, expected_names[i]);
        for (j = 0; j < i; ++j) {
            assert_string_not_equal(n, pg_result_name((pg_result)j));
            assert_string_not_equal(m, pg_result_message((pg_result)j));
        }
    }
}

/* ---- world definition and memory ------------------------------------------------------- */
static void test_memory_size_of_invalid_defs(void **state)
{
    pg_world_def d0 = pg_default_world_def(), d;
    (void)state;
    assert_true(pg_world_memory_size(&d0) > 0);
    assert_int_equal(pg_world_memory_size(NULL), 0);
    d = d0; d.substeps = 0; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.substeps = 17; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.step_hz = 0; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.step_hz = 1001; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.effects = PG_EFFECTS_ALL | 0x80u; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.effects = 1u << 31; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.max_bodies = 0; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.max_shapes = 0; assert_int_equal(pg_world_memory_size(&d), 0);
    d = d0; d.max_contacts = 0; assert_int_equal(pg_world_memory_size(&d), 0);
    /* the documented ends of the ranges are valid */
    d = d0; d.substeps = 1; assert_true(pg_world_memory_size(&d) > 0);
    d = d0; d.substeps = 16; assert_true(pg_world_memory_size(&d) > 0);
    d = d0; d.step_hz = 1; assert_true(pg_world_memory_size(&d) > 0);
    d = d0; d.step_hz = 1000; assert_true(pg_world_memory_size(&d) > 0);
    d = d0; d.effects = 0; assert_true(pg_world_memory_size(&d) > 0);
}

/* pg_world_def_problem names the field at fault, and only for invalid defs. */
static void test_def_problem_names_the_field(void **state)
{
    pg_world_def d0 = pg_default_world_def(), d;
    (void)state;
    assert_null(pg_world_def_problem(&d0));
    assert_non_null(pg_world_def_problem(NULL));
    d = d0; d.substeps = 17; assert_string_equal(pg_world_def_problem(&d), "substeps must be 1..16");
    d = d0; d.step_hz = 0; assert_string_equal(pg_world_def_problem(&d), "step_hz must be 1..1000");
    d = d0; d.contact_hertz = 0; assert_string_equal(pg_world_def_problem(&d), "contact_hertz must be in (0, 1000]");
    d = d0; d.max_contacts = 0; assert_string_equal(pg_world_def_problem(&d), "max_contacts must be 1..2^24");
    d = d0; d.substeps = 16; assert_null(pg_world_def_problem(&d));
}

/* A def that did not start from its defaults function (here a zeroed one, whose
 * gravity_scale 0 or capacities 0 would otherwise be taken at face value) is refused,
 * and the message names the function to call. A def from the function with every field
 * copied by hand into a zeroed struct is refused too: the fields are not the whole def. */
static void test_defs_not_from_their_defaults_are_refused(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world_def wd, copy, ok = pg_default_world_def();
    pg_body_def bd, good_bd = pg_default_body_def();
    pg_shape_def sd, good_sd = pg_default_shape_def();
    pg_body_id id;
    pg_shape_id sid;
    pg_geometry g;
    uint64_t mem[64];
    pg_world *w = NULL;
    (void)state;
    memset(&wd, 0, sizeof wd);
    memset(&bd, 0, sizeof bd);
    memset(&sd, 0, sizeof sd);

    assert_non_null(strstr(pg_world_def_problem(&wd), "pg_default_world_def()"));
    assert_int_equal(pg_world_memory_size(&wd), 0);
    assert_int_equal(pg_world_create(&wd, mem, sizeof mem, &w), PG_ERR_INVALID_ARGUMENT);
    assert_null(w);
    memset(&copy, 0, sizeof copy);
    copy.gravity = ok.gravity; copy.step_hz = ok.step_hz; copy.substeps = ok.substeps; copy.effects = ok.effects;
    copy.contact_hertz = ok.contact_hertz; copy.contact_damping_ratio = ok.contact_damping_ratio;
    copy.contact_push_max = ok.contact_push_max; copy.restitution_threshold = ok.restitution_threshold;
    copy.max_linear_speed = ok.max_linear_speed; copy.sleep_linear_tolerance = ok.sleep_linear_tolerance;
    copy.sleep_angular_tolerance = ok.sleep_angular_tolerance; copy.time_to_sleep = ok.time_to_sleep;
    copy.max_bodies = ok.max_bodies; copy.max_shapes = ok.max_shapes; copy.max_contacts = ok.max_contacts;
    assert_non_null(strstr(pg_world_def_problem(&copy), "pg_default_world_def()"));
    assert_null(pg_world_def_problem(&ok));

    assert_int_equal(pg_body_create(t.w, &bd, &id), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_default_body_def()"));
    assert_int_equal(pg_make_ball(t.w, &bd, &good_sd, PG_FIX_ONE, &id), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_default_body_def()"));
    assert_int_equal(pg_make_ball(t.w, &good_bd, &sd, PG_FIX_ONE, &id), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_default_shape_def()"));
    assert_int_equal(pg_world_get_stats(t.w).body_count, 0); /* nothing was made */

    assert_int_equal(pg_body_create(t.w, &good_bd, &id), PG_OK);
    assert_int_equal(pg_geometry_circle(pg_v2_zero(), PG_FIX_ONE, &g), PG_OK);
    assert_int_equal(pg_shape_create(t.w, id, &sd, &g, &sid), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "pg_default_shape_def()"));
    free_world(&t);
}

static void test_world_create_errors(void **state)
{
    pg_world_def d = pg_default_world_def(), bad;
    size_t need;
    uint64_t *mem;
    pg_world *w = NULL;
    (void)state;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 16;
    need = pg_world_memory_size(&d);
    assert_true(need > 0);
    mem = (uint64_t *)malloc(need + 16);
    assert_non_null(mem);

    assert_int_equal(pg_world_create(NULL, mem, need, &w), PG_ERR_NULL);
    assert_int_equal(pg_world_create(&d, NULL, need, &w), PG_ERR_NULL);
    assert_int_equal(pg_world_create(&d, mem, need, NULL), PG_ERR_NULL);

    assert_int_equal(pg_world_create(&d, mem, need - 1, &w), PG_ERR_MEMORY);
    assert_int_equal(pg_world_create(&d, mem, 0, &w), PG_ERR_MEMORY);
    /* misaligned (4 bytes off an 8-aligned block), with enough bytes */
    assert_int_equal(pg_world_create(&d, (unsigned char *)mem + 4, need, &w), PG_ERR_MEMORY);
    assert_int_equal(pg_world_create(&d, (unsigned char *)mem + 1, need, &w), PG_ERR_MEMORY);

    bad = d; bad.substeps = 0;
    assert_int_equal(pg_world_create(&bad, mem, need + 16, &w), PG_ERR_INVALID_ARGUMENT);
    bad = d; bad.step_hz = 0;
    assert_int_equal(pg_world_create(&bad, mem, need + 16, &w), PG_ERR_INVALID_ARGUMENT);
    bad = d; bad.effects = 0x80u;
    assert_int_equal(pg_world_create(&bad, mem, need + 16, &w), PG_ERR_INVALID_ARGUMENT);
    bad = d; bad.max_bodies = 0;
    assert_int_equal(pg_world_create(&bad, mem, need + 16, &w), PG_ERR_INVALID_ARGUMENT);

    /* exactly the size asked for is enough */
    assert_int_equal(pg_world_create(&d, mem, need, &w), PG_OK);
    assert_non_null(w);
    assert_int_equal(body_count(w), 0);
    assert_int_equal(pg_world_frame(w), 0);
    assert_string_equal(pg_world_last_error(w), "");
    free(mem);
}

static void test_null_pointers(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id, ground;
    pg_shape_id sid;
    pg_geometry g;
    pg_vec2 v[3] = {{0, 0}, {PG_FIX_ONE, 0}, {0, PG_FIX_ONE}};
    pg_body_id out[4];
    uint32_t count;
    pg_aabb box;
    pg_ray_hit hit;
    pg_vec2 p;
    (void)state;

    assert_int_equal(pg_world_step(NULL), PG_ERR_NULL);
    assert_int_equal(pg_world_set_gravity(NULL, pg_v2_zero()), PG_ERR_NULL);
    assert_int_equal(pg_world_set_effects(NULL, 0), PG_ERR_NULL);
    assert_string_equal(pg_world_last_error(NULL), "");

    assert_int_equal(pg_body_create(NULL, &bd, &id), PG_ERR_NULL);
    assert_int_equal(pg_body_create(w, NULL, &id), PG_ERR_NULL);
    assert_int_equal(pg_body_create(w, &bd, NULL), PG_ERR_NULL);
    assert_int_equal(body_count(w), 0);

    assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_C(10), PG_FIX_ONE, &ground), PG_OK);
    assert_int_equal(pg_body_destroy(NULL, ground), PG_ERR_NULL);
    assert_int_equal(pg_body_set_transform(NULL, ground, pg_v2_zero(), 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_linear_velocity(NULL, ground, pg_v2_zero()), PG_ERR_NULL);
    assert_int_equal(pg_body_set_angular_velocity(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_type(NULL, ground, PG_BODY_STATIC), PG_ERR_NULL);
    assert_int_equal(pg_body_set_awake(NULL, ground, 1), PG_ERR_NULL);
    assert_int_equal(pg_body_set_gravity_scale(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_damping(NULL, ground, 0, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_fixed_rotation(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_user_data(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_friction(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_restitution(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_set_density(NULL, ground, PG_FIX_ONE), PG_ERR_NULL);
    assert_int_equal(pg_body_set_filter(NULL, ground, 1, 1), PG_ERR_NULL);
    assert_int_equal(pg_body_apply_force(NULL, ground, pg_v2_zero()), PG_ERR_NULL);
    assert_int_equal(pg_body_apply_force_at(NULL, ground, pg_v2_zero(), pg_v2_zero()), PG_ERR_NULL);
    assert_int_equal(pg_body_apply_torque(NULL, ground, 0), PG_ERR_NULL);
    assert_int_equal(pg_body_apply_linear_impulse(NULL, ground, pg_v2_zero(), pg_v2_zero()), PG_ERR_NULL);
    assert_int_equal(pg_body_apply_angular_impulse(NULL, ground, 0), PG_ERR_NULL);

    assert_int_equal(pg_geometry_circle(pg_v2_zero(), PG_FIX_ONE, NULL), PG_ERR_NULL);
    assert_int_equal(pg_geometry_segment(pg_v2_zero(), pg_v2(PG_FIX_ONE, 0), NULL), PG_ERR_NULL);
    assert_int_equal(pg_geometry_capsule(pg_v2_zero(), pg_v2(PG_FIX_ONE, 0), PG_FIX_HALF, NULL), PG_ERR_NULL);
    assert_int_equal(pg_geometry_box(PG_FIX_ONE, PG_FIX_ONE, pg_v2_zero(), 0, NULL), PG_ERR_NULL);
    assert_int_equal(pg_geometry_polygon(v, 3, NULL), PG_ERR_NULL);
    assert_int_equal(pg_geometry_polygon(NULL, 3, &g), PG_ERR_NULL);
    assert_int_equal(pg_geometry_triangle(pg_v2_zero(), PG_FIX_ONE, 0, NULL), PG_ERR_NULL);

    assert_int_equal(pg_geometry_circle(pg_v2_zero(), PG_FIX_ONE, &g), PG_OK);
    bd = dynamic_at(0, 5);
    assert_int_equal(pg_body_create(w, &bd, &id), PG_OK);
    assert_int_equal(pg_shape_create(NULL, id, &sd, &g, &sid), PG_ERR_NULL);
    assert_int_equal(pg_shape_create(w, id, NULL, &g, &sid), PG_ERR_NULL);
    assert_int_equal(pg_shape_create(w, id, &sd, NULL, &sid), PG_ERR_NULL);
    assert_int_equal(pg_shape_create(w, id, &sd, &g, NULL), PG_ERR_NULL);
    assert_int_equal(pg_body_shapes(w, id, NULL, 0), 0);
    assert_int_equal(shape_count(w), 1);
    assert_int_equal(pg_shape_create(w, id, &sd, &g, &sid), PG_OK);
    assert_int_equal(pg_shape_destroy(NULL, sid), PG_ERR_NULL);
    assert_int_equal(pg_shape_geometry(w, sid, NULL), PG_ERR_NULL);
    assert_int_equal(pg_shape_geometry(NULL, sid, &g), PG_ERR_NULL);

    assert_int_equal(pg_make_ball(NULL, &bd, &sd, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_ball(w, NULL, &sd, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_ball(w, &bd, NULL, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, NULL), PG_ERR_NULL);
    assert_int_equal(pg_make_box(NULL, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_box(w, NULL, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_capsule(w, &bd, NULL, PG_FIX_ONE, PG_FIX_HALF, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_triangle(w, &bd, &sd, PG_FIX_ONE, NULL), PG_ERR_NULL);
    assert_int_equal(pg_make_star(w, NULL, &sd, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_wall(w, NULL, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(pg_make_wall(NULL, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &id), PG_ERR_NULL);
    assert_int_equal(body_count(w), 2);
    assert_int_equal(shape_count(w), 2);

    assert_int_equal(pg_world_query_point(NULL, pg_v2_zero(), out, 4, &count), PG_ERR_NULL);
    assert_int_equal(pg_world_query_point(w, pg_v2_zero(), out, 4, NULL), PG_ERR_NULL);
    assert_int_equal(pg_world_query_point(w, pg_v2_zero(), NULL, 4, &count), PG_ERR_NULL);
    box.lo = pg_v2(-PG_FIX_ONE, -PG_FIX_ONE);
    box.hi = pg_v2(PG_FIX_ONE, PG_FIX_ONE);
    assert_int_equal(pg_world_query_aabb(NULL, box, out, 4, &count), PG_ERR_NULL);
    assert_int_equal(pg_world_query_aabb(w, box, out, 4, NULL), PG_ERR_NULL);
    assert_int_equal(pg_world_query_geometry(NULL, &g, pg_v2_zero(), 0, out, 4, &count), PG_ERR_NULL);
    assert_int_equal(pg_world_query_geometry(w, NULL, pg_v2_zero(), 0, out, 4, &count), PG_ERR_NULL);
    assert_int_equal(pg_world_query_geometry(w, &g, pg_v2_zero(), 0, out, 4, NULL), PG_ERR_NULL);
    assert_int_equal(pg_world_find_free_position(NULL, &g, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, &p), PG_ERR_NULL);
    assert_int_equal(pg_world_find_free_position(w, NULL, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, &p), PG_ERR_NULL);
    assert_int_equal(pg_world_find_free_position(w, &g, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, NULL), PG_ERR_NULL);
    assert_int_equal(pg_world_raycast(NULL, pg_v2_zero(), pg_v2(PG_FIX_ONE, 0), &hit), PG_ERR_NULL);
    assert_int_equal(pg_world_raycast(w, pg_v2_zero(), pg_v2(PG_FIX_ONE, 0), NULL), PG_ERR_NULL);

    /* getters of a NULL world return zero values */
    assert_int_equal(pg_world_frame(NULL), 0);
    assert_int_equal(pg_world_effects(NULL), 0);
    assert_int_equal(pg_world_get_stats(NULL).body_count, 0);
    assert_int_equal(pg_body_is_valid(NULL, ground), 0);
    assert_int_equal(pg_body_mass(NULL, id), 0);
    free_world(&t);
}

/* ---- capacity ------------------------------------------------------------------------------------ */
static void test_capacity_bodies(void **state)
{
    test_world t = make_world(2, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id a, b, c = {77, 77};
    (void)state;
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &a), PG_OK);
    bd.position = pg_v2(PG_FIX_C(5), 0);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &b), PG_OK);
    bd.position = pg_v2(PG_FIX_C(10), 0);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &c), PG_ERR_CAPACITY);
    assert_true(strlen(pg_world_last_error(w)) > 0);
    assert_int_equal(pg_body_create(w, &bd, &c), PG_ERR_CAPACITY);
    assert_int_equal(body_count(w), 2);
    assert_int_equal(shape_count(w), 2);
    assert_true(pg_body_is_valid(w, a));
    assert_true(pg_body_is_valid(w, b));
    assert_false(pg_body_is_valid(w, c));
    /* after freeing a slot it works again */
    assert_int_equal(pg_body_destroy(w, a), PG_OK);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &c), PG_OK);
    assert_int_equal(body_count(w), 2);
    free_world(&t);
}

static void test_capacity_shapes(void **state)
{
    test_world t = make_world(8, 2, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id a, b, c;
    pg_shape_id s;
    pg_geometry g;
    (void)state;
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &a), PG_OK);
    bd.position = pg_v2(PG_FIX_C(5), 0);
    /* a star needs two shapes, one is left: all or nothing */
    assert_int_equal(pg_make_star(w, &bd, &sd, PG_FIX_ONE, &b), PG_ERR_CAPACITY);
    assert_int_equal(body_count(w), 1);
    assert_int_equal(shape_count(w), 1);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &b), PG_OK);
    assert_int_equal(shape_count(w), 2);
    bd.position = pg_v2(PG_FIX_C(10), 0);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &c), PG_ERR_CAPACITY);
    assert_int_equal(pg_geometry_circle(pg_v2(PG_FIX_ONE, 0), PG_FIX_HALF, &g), PG_OK);
    assert_int_equal(pg_shape_create(w, a, &sd, &g, &s), PG_ERR_CAPACITY);
    assert_int_equal(body_count(w), 2);
    assert_int_equal(shape_count(w), 2);
    assert_int_equal(pg_body_shapes(w, a, NULL, 0), 1);
    free_world(&t);
}

/* "A failing call leaves the world unchanged": a make_* call that fails on its shape
 * definition must not leave a trace in the body pool either. Compare the handle the
 * next successful call gets with the handle it gets in a world without the failure. */
static void test_failed_make_leaves_pool_unchanged(void **state)
{
    test_world t1 = make_world(8, 8, 16), t2 = make_world(8, 8, 16);
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def(), bad = sd;
    pg_body_id h1, h2, x;
    (void)state;
    bad.density = fx(0.05);
    assert_int_equal(pg_make_box(t1.w, &bd, &bad, PG_FIX_ONE, PG_FIX_ONE, &x), PG_ERR_ENVELOPE);
    assert_int_equal(body_count(t1.w), 0);
    assert_int_equal(shape_count(t1.w), 0);
    assert_int_equal(pg_make_box(t1.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &h1), PG_OK);
    assert_int_equal(pg_make_box(t2.w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &h2), PG_OK);
    free_world(&t1);
    free_world(&t2);
    PG_EXPECT_EQ(h1.index, h2.index, "%s", "slot after a failed pg_make_box");
    PG_EXPECT_EQ(h1.generation, h2.generation, "%s", "generation after a failed pg_make_box (a failing call must leave the pool unchanged)");
}

/* ---- handles ------------------------------------------------------------------------------------- */
static void check_all_stale(pg_world *w, pg_body_id id)
{
    pg_shape_id s;
    pg_geometry g;
    assert_false(pg_body_is_valid(w, id));
    assert_int_equal(pg_body_type_of(w, id), 0);
    assert_true(pg_v2_equal(pg_body_position(w, id), pg_v2_zero()));
    assert_true(pg_v2_equal(pg_body_world_center(w, id), pg_v2_zero()));
    assert_int_equal(pg_body_angle(w, id), 0);
    assert_true(pg_v2_equal(pg_body_linear_velocity(w, id), pg_v2_zero()));
    assert_int_equal(pg_body_angular_velocity(w, id), 0);
    assert_true(pg_body_mass(w, id) == 0);
    assert_true(pg_body_inertia(w, id) == 0);
    assert_int_equal(pg_body_is_awake(w, id), 0);
    assert_true(pg_body_user_data(w, id) == 0);
    assert_int_equal(pg_body_shapes(w, id, &s, 1), 0);

    assert_int_equal(pg_body_destroy(w, id), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_transform(w, id, pg_v2_zero(), 0), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_linear_velocity(w, id, pg_v2(PG_FIX_ONE, 0)), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_angular_velocity(w, id, PG_FIX_ONE), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_type(w, id, PG_BODY_DYNAMIC), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_awake(w, id, 1), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_gravity_scale(w, id, PG_FIX_ONE), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_damping(w, id, 0, 0), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_fixed_rotation(w, id, 1), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_user_data(w, id, 5), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_friction(w, id, PG_FIX_HALF), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_restitution(w, id, PG_FIX_HALF), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_density(w, id, PG_FIX_ONE), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_set_filter(w, id, 1, 1), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_apply_force(w, id, pg_v2(PG_FIX_ONE, 0)), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_apply_force_at(w, id, pg_v2(PG_FIX_ONE, 0), pg_v2_zero()), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_apply_torque(w, id, PG_FIX_ONE), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_apply_linear_impulse(w, id, pg_v2(PG_FIX_ONE, 0), pg_v2_zero()), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_body_apply_angular_impulse(w, id, PG_FIX_ONE), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_geometry_circle(pg_v2_zero(), PG_FIX_ONE, &g), PG_OK);
    {
        pg_shape_def sd = pg_default_shape_def();
        assert_int_equal(pg_shape_create(w, id, &sd, &g, &s), PG_ERR_STALE_HANDLE);
    }
}

static void test_stale_handles(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(1, 2);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id a, other, reuse;
    pg_shape_id shapes[2];
    pg_geometry g;
    pg_body_id zero = {0, 0};
    pg_shape_id zero_shape = {0, 0};
    (void)state;
    bd.user_data = 99;
    assert_int_equal(pg_make_star(w, &bd, &sd, PG_FIX_ONE, &a), PG_OK);
    bd.position = pg_v2(PG_FIX_C(5), 0);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &other), PG_OK);
    assert_int_equal(pg_body_shapes(w, a, shapes, 2), 2);
    assert_true(pg_body_id_equal(pg_shape_body(w, shapes[0]), a));
    assert_int_equal(pg_body_user_data(w, a), 99);

    assert_int_equal(pg_body_destroy(w, a), PG_OK);
    assert_int_equal(body_count(w), 1);
    assert_int_equal(shape_count(w), 1);
    check_all_stale(w, a);
    /* its shapes are gone too */
    assert_int_equal(pg_shape_geometry(w, shapes[0], &g), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_shape_destroy(w, shapes[1]), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_shape_body(w, shapes[0]).generation, 0);
    assert_int_equal(pg_shape_body(w, shapes[0]).index, 0);
    /* a failed call on a stale handle changed nothing */
    assert_int_equal(body_count(w), 1);
    assert_int_equal(shape_count(w), 1);

    /* the slot is reused with another generation: the old handle stays stale */
    bd.position = pg_v2(PG_FIX_C(-5), 0);
    assert_int_equal(pg_make_star(w, &bd, &sd, PG_FIX_ONE, &reuse), PG_OK);
    assert_int_equal(reuse.index, a.index);
    assert_true(reuse.generation != a.generation);
    assert_true(pg_body_is_valid(w, reuse));
    check_all_stale(w, a);
    assert_true(pg_body_is_valid(w, reuse)); /* calls on the stale handle did not touch it */
    assert_int_equal(pg_body_shapes(w, reuse, NULL, 0), 2);
    {
        pg_shape_id ns[2];
        assert_int_equal(pg_body_shapes(w, reuse, ns, 2), 2);
        assert_true(ns[0].index != shapes[0].index || ns[0].generation != shapes[0].generation);
        assert_int_equal(pg_shape_geometry(w, shapes[0], &g), PG_ERR_STALE_HANDLE);
        assert_int_equal(pg_shape_geometry(w, ns[0], &g), PG_OK);
    }

    /* the zero handle is never valid */
    check_all_stale(w, zero);
    assert_int_equal(pg_shape_geometry(w, zero_shape, &g), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_shape_destroy(w, zero_shape), PG_ERR_STALE_HANDLE);
    /* an index beyond the pool */
    {
        pg_body_id far = {1000000u, 1u};
        check_all_stale(w, far);
    }
    assert_true(pg_body_is_valid(w, other));
    assert_int_equal(body_count(w), 2);
    free_world(&t);
}

/* ---- envelope ----------------------------------------------------------------------------------- */
static void expect_envelope(pg_world *w, pg_result r, const char *field)
{
    const char *e = pg_world_last_error(w);
    if (r != PG_ERR_ENVELOPE) {
        print_error("got %s, want PG_ERR_ENVELOPE for %s (last error \"%s\")\n", pg_result_name(r), field, e);
        fail();
    }
    if (strlen(e) == 0 || strstr(e, field) == NULL) {
        print_error("last error \"%s\" does not mention \"%s\"\n", e, field);
        fail();
    }
}

static void test_envelope(void **state)
{
    test_world t = make_world(16, 16, 32);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0), b2;
    pg_shape_def sd = pg_default_shape_def(), s2;
    pg_body_id id, ok;
    pg_world_def d = pg_world_get_def(w);
    (void)state;
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &ok), PG_OK);

    s2 = sd; s2.density = fx(0.05);
    expect_envelope(w, pg_make_ball(w, &bd, &s2, PG_FIX_ONE, &id), "density");
    s2 = sd; s2.density = PG_FIX_C(200);
    expect_envelope(w, pg_make_box(w, &bd, &s2, PG_FIX_ONE, PG_FIX_ONE, &id), "density");
    s2 = sd; s2.friction = -PG_FIX_ONE;
    expect_envelope(w, pg_make_ball(w, &bd, &s2, PG_FIX_ONE, &id), "friction");
    s2 = sd; s2.friction = PG_FIX_C(11);
    expect_envelope(w, pg_make_ball(w, &bd, &s2, PG_FIX_ONE, &id), "friction");
    s2 = sd; s2.restitution = fx(1.5);
    expect_envelope(w, pg_make_ball(w, &bd, &s2, PG_FIX_ONE, &id), "restitution");
    b2 = bd; b2.position = pg_v2(PG_FIX_C(2000), 0);
    expect_envelope(w, pg_make_ball(w, &b2, &sd, PG_FIX_ONE, &id), "position");
    b2 = bd; b2.position = pg_v2(0, -PG_FIX_C(2000));
    expect_envelope(w, pg_body_create(w, &b2, &id), "position");
    b2 = bd; b2.linear_velocity = pg_v2(pg_fix_add(d.max_linear_speed, PG_FIX_ONE), 0);
    expect_envelope(w, pg_make_ball(w, &b2, &sd, PG_FIX_ONE, &id), "velocity");
    expect_envelope(w, pg_make_ball(w, &bd, &sd, fx(0.004), &id), "radius"); /* below 0.005 m: thinner than 0.01 m */
    expect_envelope(w, pg_make_ball(w, &bd, &sd, PG_FIX_C(60), &id), "radius");
    assert_int_equal(body_count(w), 1);
    assert_int_equal(shape_count(w), 1);

    /* setters on an existing body: same envelope, body unchanged */
    expect_envelope(w, pg_body_set_density(w, ok, fx(0.05)), "density");
    expect_envelope(w, pg_body_set_density(w, ok, PG_FIX_C(200)), "density");
    expect_envelope(w, pg_body_set_friction(w, ok, -PG_FIX_ONE), "friction");
    expect_envelope(w, pg_body_set_friction(w, ok, PG_FIX_C(11)), "friction");
    expect_envelope(w, pg_body_set_restitution(w, ok, fx(1.5)), "restitution");
    expect_envelope(w, pg_body_set_transform(w, ok, pg_v2(PG_FIX_C(2000), 0), 0), "position");
    expect_envelope(w, pg_body_set_linear_velocity(w, ok, pg_v2(0, -pg_fix_add(d.max_linear_speed, PG_FIX_ONE))), "velocity");
    {
        double m = (double)pg_body_mass(w, ok) / Q32;
        assert_true(fabs(m - PGT_PI) < 1e-3); /* radius 1, density 1: still pi kg */
        assert_true(pg_v2_equal(pg_body_position(w, ok), pg_v2_zero()));
        assert_true(pg_v2_equal(pg_body_linear_velocity(w, ok), pg_v2_zero()));
    }

    /* the edges of the envelope are inside it */
    s2 = sd; s2.density = fx(0.1); s2.friction = PG_FIX_C(10); s2.restitution = PG_FIX_ONE;
    b2 = bd; b2.position = pg_v2(PG_FIX_C(1000), -PG_FIX_C(1000));
    assert_int_equal(pg_make_ball(w, &b2, &s2, PG_FIX_C(50), &id), PG_OK);
    s2.density = PG_FIX_C(100);
    b2.position = pg_v2(-PG_FIX_C(1000), PG_FIX_C(1000));
    b2.linear_velocity = pg_v2(d.max_linear_speed, 0);
    assert_int_equal(pg_make_box(w, &b2, &s2, fx(0.1), fx(0.1), &id), PG_OK);
    /* density 0 is allowed on a static body */
    b2 = pg_default_body_def();
    b2.position = pg_v2(0, -PG_FIX_C(10));
    s2 = sd; s2.density = 0;
    assert_int_equal(pg_make_wall(w, &b2, &s2, PG_FIX_C(10), PG_FIX_ONE, &id), PG_OK);
    free_world(&t);
}

/* "speeds up to max_linear_speed": a speed is the length of the velocity, so a velocity
 * of (300, 300) m/s (speed 424 m/s) is outside the default 400 m/s envelope even though
 * each component is below it. */
static void test_envelope_speed_is_magnitude(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id, ok;
    pg_fix cap = pg_world_get_def(w).max_linear_speed;
    pg_fix comp = fx(fd(cap) * 0.75); /* |(c, c)| = 1.06 cap */
    (void)state;
    pg_result r1, r2;
    char e1[200], e2[200];
    uint32_t n;
    pg_vec2 v;
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &ok), PG_OK);
    bd.position = pg_v2(PG_FIX_C(10), 0);
    bd.linear_velocity = pg_v2(comp, comp);
    r1 = pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &id);
    snprintf(e1, sizeof e1, "%s", pg_world_last_error(w));
    r2 = pg_body_set_linear_velocity(w, ok, pg_v2(comp, -comp));
    snprintf(e2, sizeof e2, "%s", pg_world_last_error(w));
    n = body_count(w);
    v = pg_body_linear_velocity(w, ok);
    free_world(&t); /* before any assertion, so a failure leaks nothing */
    if (r1 != PG_ERR_ENVELOPE || r2 != PG_ERR_ENVELOPE) {
        print_error("velocity (%g, %g) m/s, speed %g m/s > max_linear_speed %g: pg_make_ball gave %s (\"%s\"), "
                    "pg_body_set_linear_velocity gave %s (\"%s\"); want PG_ERR_ENVELOPE\n",
                    fd(comp), fd(comp), fd(comp) * sqrt(2.0), fd(cap), pg_result_name(r1), e1, pg_result_name(r2), e2);
        fail();
    }
    assert_non_null(strstr(e1, "velocity"));
    assert_non_null(strstr(e2, "velocity"));
    assert_int_equal(n, 1);
    assert_true(pg_v2_equal(v, pg_v2_zero()));
}

/* ---- geometry ----------------------------------------------------------------------------------- */
static void test_degenerate_and_convexity(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_geometry g;
    pg_body_id id;
    const pg_fix O = PG_FIX_ONE;
    (void)state;
    assert_int_equal(pg_geometry_circle(pg_v2_zero(), 0, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_box(0, O, pg_v2_zero(), 0, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_box(O, 0, pg_v2_zero(), 0, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_box(0, 0, pg_v2_zero(), 0, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_segment(pg_v2(O, O), pg_v2(O, O), &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_capsule(pg_v2(O, O), pg_v2(O, O), O / 2, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_capsule(pg_v2(0, 0), pg_v2(O, 0), 0, &g), PG_ERR_DEGENERATE);
    assert_int_equal(pg_geometry_triangle(pg_v2_zero(), 0, 0, &g), PG_ERR_DEGENERATE);
    {
        pg_vec2 collinear[3] = {{0, 0}, {O, O}, {2 * O, 2 * O}};
        pg_vec2 collinear4[4] = {{0, 0}, {O, 0}, {2 * O, 0}, {3 * O, 0}};
        pg_vec2 dup_tri[3] = {{0, 0}, {O, 0}, {O, 0}};
        pg_vec2 dup_quad[4] = {{0, 0}, {O, 0}, {O, 0}, {0, O}};
        pg_vec2 dup_first[4] = {{0, 0}, {O, 0}, {0, O}, {0, 0}};
        pg_vec2 mid_on_edge[4] = {{0, 0}, {O, 0}, {2 * O, 0}, {O, O}}; /* a straight angle */
        assert_int_equal(pg_geometry_polygon(collinear, 3, &g), PG_ERR_DEGENERATE);
        assert_int_equal(pg_geometry_polygon(collinear4, 4, &g), PG_ERR_DEGENERATE);
        assert_int_equal(pg_geometry_polygon(dup_tri, 3, &g), PG_ERR_DEGENERATE);
        assert_int_equal(pg_geometry_polygon(dup_quad, 4, &g), PG_ERR_DEGENERATE);
        assert_int_equal(pg_geometry_polygon(dup_first, 4, &g), PG_ERR_DEGENERATE);
        assert_int_equal(pg_geometry_polygon(mid_on_edge, 4, &g), PG_ERR_DEGENERATE);
    }
    {
        /* a dart: (1, 0.5) is a reflex vertex; counter-clockwise */
        pg_vec2 dart[5] = {{0, 0}, {2 * O, 0}, {2 * O, 2 * O}, {O, O / 2}, {0, 2 * O}};
        pg_vec2 dart_cw[5] = {{0, 2 * O}, {O, O / 2}, {2 * O, 2 * O}, {2 * O, 0}, {0, 0}};
        /* a self-intersecting pentagram: every turn is the same way */
        pg_vec2 star[5];
        int i;
        for (i = 0; i < 5; ++i) {
            double a = PGT_PI / 2 + 2.0 * PGT_PI * (double)(2 * i % 5) / 5.0;
            star[i] = pg_v2(fx(cos(a)), fx(sin(a)));
        }
        assert_int_equal(pg_geometry_polygon(dart, 5, &g), PG_ERR_NOT_CONVEX);
        assert_int_equal(pg_geometry_polygon(dart_cw, 5, &g), PG_ERR_NOT_CONVEX);
        assert_int_equal(pg_geometry_polygon(star, 5, &g), PG_ERR_NOT_CONVEX);
    }
    {
        pg_vec2 nine[9];
        int i;
        for (i = 0; i < 9; ++i) {
            double a = 2.0 * PGT_PI * i / 9.0;
            nine[i] = pg_v2(fx(cos(a)), fx(sin(a)));
        }
        assert_int_equal(pg_geometry_polygon(nine, 9, &g), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(pg_geometry_polygon(nine, 2, &g), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(pg_geometry_polygon(nine, 0, &g), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(pg_geometry_polygon(nine, 8, &g), PG_OK); /* 8 of them are fine */
        assert_int_equal(g.count, 8);
    }
    /* clockwise input is accepted and stored counter-clockwise */
    {
        pg_vec2 cw[4] = {{0, 0}, {0, O}, {O, O}, {O, 0}};
        int i;
        int64_t area2 = 0;
        assert_int_equal(pg_geometry_polygon(cw, 4, &g), PG_OK);
        for (i = 0; i < 4; ++i) {
            pg_vec2 a = g.vertices[i], b = g.vertices[(i + 1) % 4];
            area2 += (int64_t)a.x * b.y - (int64_t)a.y * b.x;
        }
        assert_true(area2 > 0);
    }
    /* the ready-made kinds report the same codes and leave nothing behind */
    assert_int_equal(pg_make_ball(w, &bd, &sd, 0, &id), PG_ERR_DEGENERATE);
    assert_true(strlen(pg_world_last_error(w)) > 0);
    assert_int_equal(pg_make_box(w, &bd, &sd, 0, PG_FIX_ONE, &id), PG_ERR_DEGENERATE);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, 0, &id), PG_ERR_DEGENERATE);
    assert_int_equal(pg_make_triangle(w, &bd, &sd, 0, &id), PG_ERR_DEGENERATE);
    assert_int_equal(pg_make_star(w, &bd, &sd, 0, &id), PG_ERR_DEGENERATE);
    assert_int_equal(pg_make_wall(w, &bd, &sd, 0, PG_FIX_ONE, &id), PG_ERR_DEGENERATE);
    assert_int_equal(pg_make_capsule(w, &bd, &sd, PG_FIX_ONE, 0, &id), PG_ERR_DEGENERATE);
    assert_int_equal(body_count(w), 0);
    assert_int_equal(shape_count(w), 0);
    free_world(&t);
}

/* pg_shape_create re-validates a hand-made geometry. */
static void test_shape_create_validates_geometry(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_geometry g;
    pg_body_id b;
    pg_shape_id s;
    (void)state;
    assert_int_equal(pg_body_create(w, &bd, &b), PG_OK);
    memset(&g, 0, sizeof g);
    g.kind = PG_SHAPE_CIRCLE;
    g.count = 1;
    g.radius = 0;
    assert_int_equal(pg_shape_create(w, b, &sd, &g, &s), PG_ERR_DEGENERATE);
    memset(&g, 0, sizeof g);
    g.kind = PG_SHAPE_POLYGON;
    g.count = 4;
    g.vertices[0] = pg_v2(0, 0);
    g.vertices[1] = pg_v2(PG_FIX_C(2), 0);
    g.vertices[2] = pg_v2(PG_FIX_ONE, PG_FIX_HALF); /* reflex */
    g.vertices[3] = pg_v2(PG_FIX_ONE, PG_FIX_C(2));
    assert_int_equal(pg_shape_create(w, b, &sd, &g, &s), PG_ERR_NOT_CONVEX);
    g.count = 9;
    assert_int_equal(pg_shape_create(w, b, &sd, &g, &s), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(shape_count(w), 0);
    assert_int_equal(pg_body_shapes(w, b, NULL, 0), 0);
    free_world(&t);
}

/* ---- body types ----------------------------------------------------------------------------------- */
static void test_forces_need_dynamic_body(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id st, kin;
    pg_vec2 f = pg_v2(PG_FIX_ONE, 0);
    int i;
    (void)state;
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &st), PG_OK); /* default: static */
    bd.type = PG_BODY_KINEMATIC;
    bd.position = pg_v2(PG_FIX_C(5), 0);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &kin), PG_OK);
    for (i = 0; i < 2; ++i) {
        pg_body_id b = i == 0 ? st : kin;
        assert_int_equal(pg_body_apply_force(w, b, f), PG_ERR_BODY_TYPE);
        assert_int_equal(pg_body_apply_force_at(w, b, f, pg_v2(0, PG_FIX_HALF)), PG_ERR_BODY_TYPE);
        assert_int_equal(pg_body_apply_torque(w, b, PG_FIX_ONE), PG_ERR_BODY_TYPE);
        assert_int_equal(pg_body_apply_linear_impulse(w, b, f, pg_v2_zero()), PG_ERR_BODY_TYPE);
        assert_int_equal(pg_body_apply_angular_impulse(w, b, PG_FIX_ONE), PG_ERR_BODY_TYPE);
        assert_true(strlen(pg_world_last_error(w)) > 0);
    }
    for (i = 0; i < 10; ++i) assert_int_equal(pg_world_step(w), PG_OK);
    assert_true(pg_v2_equal(pg_body_position(w, st), pg_v2_zero()));
    assert_true(pg_v2_equal(pg_body_position(w, kin), pg_v2(PG_FIX_C(5), 0)));
    assert_int_equal(pg_body_angle(w, st), 0);
    assert_int_equal(pg_body_angle(w, kin), 0);
    free_world(&t);
}

/* ---- masses of the ready-made kinds ---------------------------------------------------------------- */
static void expect_rel(double got, double want, double rel, const char *what)
{
    if (!(fabs(got - want) <= rel * fabs(want))) {
        print_error("%s: got %.9g, want %.9g (relative error %.3g > %.3g)\n", what, got, want, fabs(got - want) / fabs(want), rel);
        fail();
    }
}

static void test_masses(void **state)
{
    test_world t = make_world(32, 64, 64);
    pg_world *w = t.w;
    pg_body_def bd = dynamic_at(0, 0);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    static const double radii[] = {0.5, 1.0, 2.0, 7.25};
    static const double densities[] = {1.0, 2.5, 0.3, 10.0};
    int i;
    (void)state;
    for (i = 0; i < 4; ++i) {
        double r = radii[i], rho = densities[i];
        char what[96];
        sd.density = fx(rho);
        bd.position = pg_v2(PG_FIX_C(20 * i), 0);
        rho = fd(sd.density);

        /* star: two triangles of circumradius r overlap in a hexagon; the union has area
         * r^2 sqrt(3) (the overlap is counted once: the sum would be 2 * 3 sqrt(3)/4 r^2). */
        assert_int_equal(pg_make_star(w, &bd, &sd, fx(r), &id), PG_OK);
        snprintf(what, sizeof what, "star r=%g density=%g", r, rho);
        expect_rel((double)pg_body_mass(w, id) / Q32, rho * r * r * sqrt(3.0), 1e-4, what);
        /* symmetric about its centre */
        assert_true(fabs(fd(pg_body_world_center(w, id).x) - fd(bd.position.x)) < 1e-4 * r);
        assert_true(fabs(fd(pg_body_world_center(w, id).y) - fd(bd.position.y)) < 1e-4 * r);

        /* ball: pi r^2 density, inertia m r^2 / 2 */
        bd.position.y = PG_FIX_C(30);
        assert_int_equal(pg_make_ball(w, &bd, &sd, fx(r), &id), PG_OK);
        snprintf(what, sizeof what, "ball r=%g density=%g", r, rho);
        expect_rel((double)pg_body_mass(w, id) / Q32, PGT_PI * r * r * rho, 1e-4, what);
        expect_rel((double)pg_body_inertia(w, id) / Q36, PGT_PI * r * r * rho * r * r / 2.0, 1e-4, what);

        /* capsule: a rectangle 2r x L plus a disc */
        {
            double L = 1.5 * r;
            bd.position.y = PG_FIX_C(60);
            assert_int_equal(pg_make_capsule(w, &bd, &sd, fx(L), fx(r), &id), PG_OK);
            snprintf(what, sizeof what, "capsule L=%g r=%g density=%g", L, r, rho);
            expect_rel((double)pg_body_mass(w, id) / Q32, (2.0 * r * L + PGT_PI * r * r) * rho, 1e-4, what);
        }
        bd.position.y = 0;
    }
    /* box: m = w h density, I = m (w^2 + h^2) / 12 about the centre */
    {
        static const double dims[][3] = {{1, 1, 1}, {2, 1, 3}, {0.5, 4, 0.7}, {10, 0.25, 2}};
        for (i = 0; i < 4; ++i) {
            double bw = dims[i][0], bh = dims[i][1], rho, m;
            char what[96];
            sd.density = fx(dims[i][2]);
            rho = fd(sd.density);
            bd.position = pg_v2(PG_FIX_C(20 * i), -PG_FIX_C(30));
            assert_int_equal(pg_make_box(w, &bd, &sd, fx(bw), fx(bh), &id), PG_OK);
            m = bw * bh * rho;
            snprintf(what, sizeof what, "box %gx%g density=%g mass", bw, bh, rho);
            expect_rel((double)pg_body_mass(w, id) / Q32, m, 1e-6, what);
            snprintf(what, sizeof what, "box %gx%g density=%g inertia", bw, bh, rho);
            expect_rel((double)pg_body_inertia(w, id) / Q36, m * (bw * bw + bh * bh) / 12.0, 1e-6, what);
            assert_true(pg_v2_equal(pg_body_world_center(w, id), bd.position));
        }
    }
    /* static bodies have no mass */
    {
        pg_body_def sb = pg_default_body_def();
        sb.position = pg_v2(0, -PG_FIX_C(100));
        sd.density = PG_FIX_ONE;
        assert_int_equal(pg_make_wall(w, &sb, &sd, PG_FIX_C(4), PG_FIX_ONE, &id), PG_OK);
        assert_true(pg_body_mass(w, id) == 0);
        assert_int_equal(pg_body_type_of(w, id), PG_BODY_STATIC);
    }
    free_world(&t);
}

/* ---- events --------------------------------------------------------------------------------------- */
static int event_is(const pg_contact_event *e, pg_body_id x, pg_body_id y)
{
    return (pg_body_id_equal(e->body_a, x) && pg_body_id_equal(e->body_b, y)) ||
           (pg_body_id_equal(e->body_a, y) && pg_body_id_equal(e->body_b, x));
}

static int event_shapes_are(const pg_world *w, const pg_contact_event *e, pg_body_id x, pg_body_id y)
{
    pg_shape_id sx, sy;
    pg_shape_id ea = e->shape_a, eb = e->shape_b;
    if (pg_body_shapes(w, x, &sx, 1) != 1 || pg_body_shapes(w, y, &sy, 1) != 1) return 0;
    return (ea.index == sx.index && ea.generation == sx.generation && eb.index == sy.index && eb.generation == sy.generation) ||
           (ea.index == sy.index && ea.generation == sy.generation && eb.index == sx.index && eb.generation == sx.generation);
}

/* Ground: a wall 20 x 1 centred at y = -0.5 (top at 0). Ball r = 0.25 dropped from
 * y = 2. `leave`: 0 destroy the ball after it rests, 1 launch it upward. */
static void run_event_scene(int leave)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ground, ball;
    const double r = 0.25;
    uint32_t n, begins = 0, ends = 0;
    int step, begin_step = -1;
    double prev_gap = 1e9;
    const pg_contact_event *ev;
    bd.position = pg_v2(0, -PG_FIX_HALF);
    assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_C(20), PG_FIX_ONE, &ground), PG_OK);
    bd = dynamic_at(0, 2.0);
    assert_int_equal(pg_make_ball(w, &bd, &sd, fx(r), &ball), PG_OK);
    for (step = 0; step < 180; ++step) { /* 3 s: lands at ~0.6 s, rests, sleeps */
        double gap;
        assert_int_equal(pg_world_step(w), PG_OK);
        gap = fd(pg_body_position(w, ball).y) - r;
        ev = pg_world_begin_events(w, &n);
        if (n > 0) assert_non_null(ev);
        if (n > 0) {
            assert_int_equal(n, 1);
            assert_true(event_is(&ev[0], ground, ball));
            assert_true(event_shapes_are(w, &ev[0], ground, ball));
            begin_step = step;
            /* it begins when the ball lands: touching (within a contact margin of 2.5 cm)
             * by the end of this step, and not yet touching before it */
            if (!(gap < 0.025 && prev_gap > 0.0)) {
                print_error("begin event at step %d with gap %.6f m (before the step: %.6f m)\n", step, gap, prev_gap);
                fail();
            }
        }
        begins += n;
        (void)pg_world_end_events(w, &n);
        ends += n;
        prev_gap = gap;
    }
    PG_EXPECT_EQ(begins, 1, "%s", "begin events while a ball falls, lands, rests and sleeps");
    PG_EXPECT_EQ(ends, 0, "%s", "end events while the ball rests");
    assert_true(begin_step > 0);
    if (leave == 0) {
        assert_int_equal(pg_body_destroy(w, ball), PG_OK);
        ev = pg_world_end_events(w, &n);
        PG_EXPECT_EQ(n, 1, "%s", "end events after destroying the resting ball");
        assert_true(event_is(&ev[0], ground, ball)); /* the handle as it was */
        assert_int_equal(pg_world_step(w), PG_OK);
        (void)pg_world_end_events(w, &n);
        PG_EXPECT_EQ(n, 0, "%s", "end events in the step after the destruction (reported once)");
        (void)pg_world_begin_events(w, &n);
        assert_int_equal(n, 0);
    } else {
        int end_step = -1;
        ends = 0;
        assert_int_equal(pg_body_set_linear_velocity(w, ball, pg_v2(0, PG_FIX_C(5))), PG_OK);
        for (step = 0; step < 30; ++step) { /* rises 1.25 m in 0.5 s */
            assert_int_equal(pg_world_step(w), PG_OK);
            ev = pg_world_end_events(w, &n);
            if (n > 0) {
                assert_int_equal(n, 1);
                assert_true(event_is(&ev[0], ground, ball));
                assert_true(fd(pg_body_position(w, ball).y) - r > 0.0); /* it has left */
                end_step = step;
            }
            ends += n;
            (void)pg_world_begin_events(w, &n);
            assert_int_equal(n, 0);
        }
        PG_EXPECT_EQ(ends, 1, "%s", "end events when the ball is launched off the ground");
        assert_true(end_step >= 0 && end_step < 5);
    }
    free_world(&t);
}

static void test_events_destroy(void **state) { (void)state; run_event_scene(0); }

/* Five balls side by side land in the same step on one ground: five begin events in
 * that step, and five end events when they are destroyed. Three worlds differ only in
 * max_contact_events: as many as contacts (the default), 2, and 0. */
#define EVENT_BALLS 5
typedef struct event_world {
    test_world t;
    pg_body_id balls[EVENT_BALLS];
    uint32_t begins, ends;
} event_world;

static void make_event_world(event_world *e, uint32_t max_events)
{
    pg_world_def d = pg_default_world_def();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ground;
    int i;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 16;
    d.max_contact_events = max_events;
    e->t = make_world_def(&d);
    e->begins = e->ends = 0;
    bd.position = pg_v2(0, -PG_FIX_HALF);
    assert_int_equal(pg_make_wall(e->t.w, &bd, &sd, PG_FIX_C(20), PG_FIX_ONE, &ground), PG_OK);
    for (i = 0; i < EVENT_BALLS; ++i) {
        bd = dynamic_at(-4.0 + 2.0 * i, 2.0);
        assert_int_equal(pg_make_ball(e->t.w, &bd, &sd, fx(0.25), &e->balls[i]), PG_OK);
    }
}

static void count_events(event_world *e, uint32_t capacity)
{
    uint32_t n;
    (void)pg_world_begin_events(e->t.w, &n);
    assert_true(n <= capacity);
    e->begins += n;
    (void)pg_world_end_events(e->t.w, &n);
    assert_true(n <= capacity);
    e->ends += n;
}

static void test_events_capacity(void **state)
{
    static const uint32_t capacity[3] = {PG_EVENTS_AS_CONTACTS, 2, 0};
    static const uint32_t kept[3] = {EVENT_BALLS, 2, 0};
    event_world e[3];
    pg_world_def d = pg_default_world_def();
    size_t full, two, none;
    int k, step, i;
    (void)state;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 16;
    full = pg_world_memory_size(&d);
    d.max_contact_events = 2;
    two = pg_world_memory_size(&d);
    d.max_contact_events = 0;
    none = pg_world_memory_size(&d);
    /* one begin and one end list, each of the capacity's events */
    assert_int_equal(full - two, 2 * sizeof(pg_contact_event) * (16 - 2));
    assert_int_equal(full - none, 2 * sizeof(pg_contact_event) * 16);
    d.max_contact_events = 1u << 24;
    assert_null(pg_world_def_problem(&d));
    d.max_contact_events = (1u << 24) + 1u;
    assert_non_null(pg_world_def_problem(&d));
    assert_non_null(strstr(pg_world_def_problem(&d), "max_contact_events"));
    assert_int_equal(pg_world_memory_size(&d), 0);

    for (k = 0; k < 3; ++k) make_event_world(&e[k], capacity[k]);
    for (step = 0; step < 120; ++step) { /* 2 s: they land at about 0.6 s */
        for (k = 0; k < 3; ++k) {
            assert_int_equal(pg_world_step(e[k].t.w), PG_OK);
            count_events(&e[k], kept[k]);
        }
        /* events are outputs: what a world keeps of them never changes its future */
        assert_true(pg_world_hash(e[0].t.w) == pg_world_hash(e[1].t.w));
        assert_true(pg_world_hash(e[0].t.w) == pg_world_hash(e[2].t.w));
    }
    for (k = 0; k < 3; ++k) {
        PG_EXPECT_EQ(e[k].begins, kept[k], "begin events kept of %d landings", EVENT_BALLS);
        PG_EXPECT_EQ(pg_world_get_stats(e[k].t.w).events_dropped, EVENT_BALLS - kept[k], "%s", "begin events dropped");
        for (i = 0; i < EVENT_BALLS; ++i) assert_int_equal(pg_body_destroy(e[k].t.w, e[k].balls[i]), PG_OK);
        count_events(&e[k], kept[k]);
        PG_EXPECT_EQ(e[k].ends, kept[k], "end events kept of %d destructions", EVENT_BALLS);
        PG_EXPECT_EQ(pg_world_get_stats(e[k].t.w).events_dropped, 2 * (EVENT_BALLS - kept[k]), "%s", "events dropped in all");
        free_world(&e[k].t);
    }
}
static void test_events_leave(void **state) { (void)state; run_event_scene(1); }

/* ---- queries -------------------------------------------------------------------------------------- */
static void test_query_point_and_aabb(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id box, ball, out[4];
    uint32_t count;
    pg_aabb q;
    (void)state;
    bd.position = pg_v2(PG_FIX_C(2), PG_FIX_C(3));
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_C(2), PG_FIX_ONE, &box), PG_OK); /* x 1..3, y 2.5..3.5 */
    bd = dynamic_at(10, 0);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &ball), PG_OK);

    assert_int_equal(pg_world_query_point(w, pg_v2(PG_FIX_C(2), PG_FIX_C(3)), out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box));
    assert_int_equal(pg_world_query_point(w, pg_v2(fx(2.9), fx(2.6)), out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box));
    /* outside, near each side */
    assert_int_equal(pg_world_query_point(w, pg_v2(fx(3.05), PG_FIX_C(3)), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    assert_int_equal(pg_world_query_point(w, pg_v2(fx(0.95), PG_FIX_C(3)), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    assert_int_equal(pg_world_query_point(w, pg_v2(PG_FIX_C(2), fx(3.55)), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    assert_int_equal(pg_world_query_point(w, pg_v2(PG_FIX_C(2), fx(2.45)), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    /* the ball: inside its circle, not in its bounding box's corner */
    assert_int_equal(pg_world_query_point(w, pg_v2(fx(10.75), fx(0.75)), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    assert_int_equal(pg_world_query_point(w, pg_v2(fx(10.6), fx(0.6)), out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], ball));

    q.lo = pg_v2(0, 0);
    q.hi = pg_v2(PG_FIX_C(12), PG_FIX_C(4));
    assert_int_equal(pg_world_query_aabb(w, q, out, 4, &count), PG_OK);
    assert_int_equal(count, 2);
    assert_true(out[0].index < out[1].index); /* ascending index order */
    assert_true((pg_body_id_equal(out[0], box) && pg_body_id_equal(out[1], ball)) ||
                (pg_body_id_equal(out[1], box) && pg_body_id_equal(out[0], ball)));
    /* capacity 1: the count still says 2 */
    assert_int_equal(pg_world_query_aabb(w, q, out, 1, &count), PG_OK);
    assert_int_equal(count, 2);
    assert_int_equal(pg_world_query_aabb(w, q, NULL, 0, &count), PG_OK);
    assert_int_equal(count, 2);
    q.lo = pg_v2(fx(3.1), 0);
    q.hi = pg_v2(fx(8.9), PG_FIX_C(4));
    assert_int_equal(pg_world_query_aabb(w, q, out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    q.lo = pg_v2(fx(2.9), fx(3.4));
    q.hi = pg_v2(fx(3.2), fx(5));
    assert_int_equal(pg_world_query_aabb(w, q, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box));
    /* lo > hi is not a box */
    q.lo = pg_v2(PG_FIX_C(5), 0);
    q.hi = pg_v2(PG_FIX_C(4), PG_FIX_C(4));
    assert_int_equal(pg_world_query_aabb(w, q, out, 4, &count), PG_ERR_INVALID_ARGUMENT);
    free_world(&t);
}

static void test_query_geometry_and_free_position(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id box, out[4];
    pg_geometry probe;
    uint32_t count;
    pg_vec2 p, free_p;
    (void)state;
    bd.position = pg_v2(0, 0);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_C(2), PG_FIX_C(2), &box), PG_OK); /* -1..1 */
    assert_int_equal(pg_geometry_box(PG_FIX_HALF, PG_FIX_HALF, pg_v2_zero(), 0, &probe), PG_OK);

    /* overlapping by 0.25 m */
    assert_int_equal(pg_world_query_geometry(w, &probe, pg_v2(fx(1.25), 0), 0, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box));
    /* 0.1 m away on each side */
    assert_int_equal(pg_world_query_geometry(w, &probe, pg_v2(fx(1.6), 0), 0, out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    assert_int_equal(pg_world_query_geometry(w, &probe, pg_v2(0, fx(-1.6)), 0, out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    /* turned 45 degrees, its corner reaches 0.707 m: at 1.6 m it overlaps, at 1.8 m not */
    assert_int_equal(pg_world_query_geometry(w, &probe, pg_v2(fx(1.6), 0), PG_ANGLE_QUARTER / 2, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_int_equal(pg_world_query_geometry(w, &probe, pg_v2(fx(1.8), 0), PG_ANGLE_QUARTER / 2, out, 4, &count), PG_OK);
    assert_int_equal(count, 0);

    /* a free position: returned as is */
    p = pg_v2(PG_FIX_C(3), PG_FIX_C(3));
    assert_int_equal(pg_world_find_free_position(w, &probe, p, 0, PG_FIX_C(4), fx(0.25), &free_p), PG_OK);
    assert_true(pg_v2_equal(free_p, p));
    /* an occupied one: the answer is free, and no farther than max_distance */
    p = pg_v2(fx(0.5), fx(0.25));
    assert_int_equal(pg_world_find_free_position(w, &probe, p, 0, PG_FIX_C(4), fx(0.25), &free_p), PG_OK);
    assert_int_equal(pg_world_query_geometry(w, &probe, free_p, 0, out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    {
        double dx = fd(free_p.x) - 0.5, dy = fd(free_p.y) - 0.25, dist = sqrt(dx * dx + dy * dy);
        assert_true(dist <= 4.0 + 1e-4);
        /* the probe needs its centre 1.5 m out of the box on some axis: the nearest free
         * point of the search is at least that far, measured from the box's face */
        assert_true(fabs(fd(free_p.x)) >= 1.5 || fabs(fd(free_p.y)) >= 1.5);
    }
    /* nowhere free within reach */
    assert_int_equal(pg_world_find_free_position(w, &probe, pg_v2_zero(), 0, fx(0.5), fx(0.25), &free_p), PG_ERR_NOT_FOUND);
    free_world(&t);
}

static void test_raycast(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id near_box, far_box;
    pg_ray_hit hit;
    (void)state;
    bd.position = pg_v2(PG_FIX_C(10), 0); /* the far one first, so creation order is not the answer */
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_C(2), PG_FIX_C(2), &far_box), PG_OK); /* x 9..11 */
    bd.position = pg_v2(PG_FIX_C(5), fx(0.5));
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_C(2), &near_box), PG_OK); /* x 4.5..5.5 */

    assert_int_equal(pg_world_raycast(w, pg_v2(0, 0), pg_v2(PG_FIX_C(20), 0), &hit), PG_OK);
    assert_true(pg_body_id_equal(hit.body, near_box));
    assert_true(fabs(fd(hit.fraction) - 4.5 / 20.0) < 1e-3);
    assert_true(fabs(fd(hit.normal.x) + 1.0) < 1e-3);
    assert_true(fabs(fd(hit.normal.y)) < 1e-3);
    assert_true(fabs(fd(hit.point.x) - 4.5) < 1e-3 * 20);
    assert_true(fabs(fd(hit.point.y)) < 1e-3 * 20);
    {
        pg_body_id b = pg_shape_body(w, hit.shape);
        assert_true(pg_body_id_equal(b, near_box));
    }
    /* from the other side: the far box is now the nearest; normal +x */
    assert_int_equal(pg_world_raycast(w, pg_v2(PG_FIX_C(20), 0), pg_v2(-PG_FIX_C(20), 0), &hit), PG_OK);
    assert_true(pg_body_id_equal(hit.body, far_box));
    assert_true(fabs(fd(hit.fraction) - 9.0 / 20.0) < 1e-3);
    assert_true(fabs(fd(hit.normal.x) - 1.0) < 1e-3);
    assert_true(fabs(fd(hit.normal.y)) < 1e-3);
    /* above the near box (its top is at 1.5): the far box (top at 1) is missed too */
    assert_int_equal(pg_world_raycast(w, pg_v2(0, fx(1.75)), pg_v2(PG_FIX_C(20), 0), &hit), PG_ERR_NOT_FOUND);
    /* diagonal down onto the near box's top: hits (5, 1.5) at fraction 0.5 of (0,3)->(10,0) */
    assert_int_equal(pg_world_raycast(w, pg_v2(0, PG_FIX_C(3)), pg_v2(PG_FIX_C(10), -PG_FIX_C(3)), &hit), PG_OK);
    assert_true(pg_body_id_equal(hit.body, near_box));
    assert_true(fabs(fd(hit.fraction) - 0.5) < 1e-3);
    assert_true(fabs(fd(hit.normal.y) - 1.0) < 1e-3);
    /* too short to reach */
    assert_int_equal(pg_world_raycast(w, pg_v2(0, 0), pg_v2(PG_FIX_C(4), 0), &hit), PG_ERR_NOT_FOUND);
    /* a zero translation is not a ray */
    assert_int_equal(pg_world_raycast(w, pg_v2(0, 0), pg_v2_zero(), &hit), PG_ERR_INVALID_ARGUMENT);
    free_world(&t);
}

/* ---- queries: validation, messages, far bodies ------------------------------------------------------ */
/* r is `code`, and pg_world_last_error starts with the code's name and mentions each of
 * the (up to two) texts: the function and what is wrong. */
static void expect_error(const pg_world *w, pg_result r, pg_result code, const char *text1, const char *text2, int line)
{
    const char *e = pg_world_last_error(w);
    const char *name = pg_result_name(code);
    if (r != code) {
        print_error("line %d: got %s, want %s (last error \"%s\")\n", line, pg_result_name(r), name, e);
        fail();
    }
    if (strncmp(e, name, strlen(name)) != 0 || strstr(e, text1) == NULL || (text2 != NULL && strstr(e, text2) == NULL)) {
        print_error("line %d: last error \"%s\" does not start with %s and mention \"%s\" and \"%s\"\n", line, e, name,
                    text1, text2 != NULL ? text2 : "");
        fail();
    }
}
#define EXPECT_ERROR(w, call, code, text1, text2) expect_error((w), (call), (code), (text1), (text2), __LINE__)

/* A NULL argument names the function and the parameter (pg_world_last_error); a NULL
 * world has nowhere to keep a message and only returns PG_ERR_NULL. */
static void test_query_null_messages(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id, out[4];
    pg_geometry g;
    pg_aabb box;
    pg_vec2 p = pg_v2(PG_FIX_C(7), PG_FIX_C(7));
    uint32_t count = 5;
    (void)state;
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &id), PG_OK);
    assert_int_equal(pg_geometry_box(PG_FIX_HALF, PG_FIX_HALF, pg_v2_zero(), 0, &g), PG_OK);
    box.lo = pg_v2(-PG_FIX_ONE, -PG_FIX_ONE);
    box.hi = pg_v2(PG_FIX_ONE, PG_FIX_ONE);
    EXPECT_ERROR(w, pg_world_query_point(w, pg_v2_zero(), out, 4, NULL), PG_ERR_NULL, "pg_world_query_point", "count is NULL");
    EXPECT_ERROR(w, pg_world_query_point(w, pg_v2_zero(), NULL, 4, &count), PG_ERR_NULL, "pg_world_query_point", "out is NULL");
    assert_int_equal(count, 0);
    EXPECT_ERROR(w, pg_world_query_aabb(w, box, out, 4, NULL), PG_ERR_NULL, "pg_world_query_aabb", "count is NULL");
    EXPECT_ERROR(w, pg_world_query_aabb(w, box, NULL, 3, &count), PG_ERR_NULL, "pg_world_query_aabb", "out is NULL");
    EXPECT_ERROR(w, pg_world_query_geometry(w, NULL, pg_v2_zero(), 0, out, 4, &count), PG_ERR_NULL, "pg_world_query_geometry", "geometry is NULL");
    EXPECT_ERROR(w, pg_world_query_geometry(w, &g, pg_v2_zero(), 0, out, 4, NULL), PG_ERR_NULL, "pg_world_query_geometry", "count is NULL");
    EXPECT_ERROR(w, pg_world_query_geometry(w, &g, pg_v2_zero(), 0, NULL, 4, &count), PG_ERR_NULL, "pg_world_query_geometry", "out is NULL");
    EXPECT_ERROR(w, pg_world_find_free_position(w, NULL, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, &p), PG_ERR_NULL, "pg_world_find_free_position", "geometry is NULL");
    EXPECT_ERROR(w, pg_world_find_free_position(w, &g, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, NULL), PG_ERR_NULL, "pg_world_find_free_position", "out is NULL");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2_zero(), pg_v2(PG_FIX_ONE, 0), NULL), PG_ERR_NULL, "pg_world_raycast", "hit is NULL");
    /* capacity 0 with a NULL array is the way to only count */
    assert_int_equal(pg_world_query_point(w, pg_v2_zero(), NULL, 0, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_v2_equal(p, pg_v2(PG_FIX_C(7), PG_FIX_C(7)))); /* untouched by the failures */
    free_world(&t);
}

/* PG_ERR_NOT_FOUND is an answer, but like every result other than PG_OK it sets
 * pg_world_last_error (a message left over from an earlier call would mislead). */
static void test_not_found_messages(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    pg_geometry big;
    pg_ray_hit hit;
    pg_vec2 p = pg_v2(PG_FIX_C(7), PG_FIX_C(7));
    (void)state;
    assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_C(20), PG_FIX_C(2), &id), PG_OK);
    assert_int_equal(pg_geometry_box(PG_FIX_C(30), PG_FIX_C(30), pg_v2_zero(), 0, &big), PG_OK);
    /* an earlier failure, whose message must not survive */
    assert_int_equal(pg_world_raycast(w, pg_v2_zero(), pg_v2_zero(), &hit), PG_ERR_INVALID_ARGUMENT);
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(0, PG_FIX_C(100)), pg_v2(0, PG_FIX_ONE), &hit), PG_ERR_NOT_FOUND, "pg_world_raycast", "no shape");
    EXPECT_ERROR(w, pg_world_find_free_position(w, &big, pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, &p), PG_ERR_NOT_FOUND,
                 "pg_world_find_free_position", "max_distance 1 m");
    assert_true(pg_v2_equal(p, pg_v2(PG_FIX_C(7), PG_FIX_C(7)))); /* *out is left alone */
    free_world(&t);
}

/* The query geometry passes the checks pg_shape_create makes, with the same result. */
static void test_query_geometry_validates(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ground, out[4];
    pg_shape_id sid;
    pg_geometry g[6];
    pg_vec2 p = pg_v2(PG_FIX_C(7), PG_FIX_C(7));
    uint32_t count;
    int i, k;
    (void)state;
    assert_int_equal(pg_make_wall(w, &bd, &sd, PG_FIX_C(20), PG_FIX_C(2), &ground), PG_OK); /* y -1..1 */
    memset(g, 0, sizeof g);
    g[0].kind = (pg_shape_kind)42; /* no such kind */
    g[0].count = 8;
    for (i = 0; i < 8; ++i) g[0].vertices[i] = pg_v2(i & 1 ? PG_FIX_MAX : PG_FIX_MIN, i & 2 ? PG_FIX_MAX : PG_FIX_MIN);
    g[0].radius = PG_FIX_MAX;
    g[1].kind = PG_SHAPE_CIRCLE; /* negative radius */
    g[1].count = 1;
    g[1].radius = -PG_FIX_C(5);
    g[2].kind = PG_SHAPE_POLYGON; /* self-crossing (a bow tie) */
    g[2].count = 4;
    g[2].vertices[0] = pg_v2(0, 0);
    g[2].vertices[1] = pg_v2(PG_FIX_ONE, PG_FIX_ONE);
    g[2].vertices[2] = pg_v2(PG_FIX_ONE, 0);
    g[2].vertices[3] = pg_v2(0, PG_FIX_ONE);
    g[3].kind = PG_SHAPE_POLYGON; /* clockwise */
    g[3].count = 3;
    g[3].vertices[0] = pg_v2(0, 0);
    g[3].vertices[1] = pg_v2(0, PG_FIX_ONE);
    g[3].vertices[2] = pg_v2(PG_FIX_ONE, 0);
    g[4].kind = PG_SHAPE_CIRCLE; /* a circle of 100 m: beyond the envelope */
    g[4].count = 1;
    g[4].radius = PG_FIX_C(100);
    g[5].kind = PG_SHAPE_POLYGON; /* count 9 */
    g[5].count = 9;
    for (k = 0; k < 6; ++k) {
        pg_body_def dyn = dynamic_at(0, 5);
        pg_body_id b;
        pg_result want;
        assert_int_equal(pg_body_create(w, &dyn, &b), PG_OK);
        want = pg_shape_create(w, b, &sd, &g[k], &sid);
        assert_int_not_equal(want, PG_OK);
        assert_int_equal(pg_body_destroy(w, b), PG_OK);
        count = 77;
        out[0].index = 99;
        EXPECT_ERROR(w, pg_world_query_geometry(w, &g[k], pg_v2_zero(), 0, out, 4, &count), want, "pg_world_query_geometry", "geometry");
        PG_EXPECT_EQ(count, 0, "geometry %d", k);
        PG_EXPECT_EQ(out[0].index, 99, "geometry %d", k);
        EXPECT_ERROR(w, pg_world_find_free_position(w, &g[k], pg_v2_zero(), 0, PG_FIX_ONE, PG_FIX_HALF, &p), want,
                     "pg_world_find_free_position", "geometry");
        assert_true(pg_v2_equal(p, pg_v2(PG_FIX_C(7), PG_FIX_C(7))));
    }
    /* a valid one still works */
    assert_int_equal(pg_geometry_circle(pg_v2_zero(), PG_FIX_HALF, &g[0]), PG_OK);
    assert_int_equal(pg_world_query_geometry(w, &g[0], pg_v2_zero(), 0, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], ground));
    free_world(&t);
}

/* Rays are checked against the envelope: both ends within +-1000 m. */
static void test_raycast_envelope(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id ball;
    pg_ray_hit hit;
    const pg_fix e = PG_FIX_C(1000);
    (void)state;
    bd.position = pg_v2(e, e);
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &ball), PG_OK);
    /* the audit's ray: origin at the corner of the plane (UBSan: collide.c pg__dist2 before) */
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(PG_FIX_MIN, PG_FIX_MIN), pg_v2(PG_FIX_MAX, PG_FIX_MIN), &hit), PG_ERR_ENVELOPE,
                 "pg_world_raycast", "1000 m");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(PG_FIX_MAX, PG_FIX_MAX), pg_v2(PG_FIX_MIN, PG_FIX_MIN), &hit), PG_ERR_ENVELOPE,
                 "pg_world_raycast", "origin");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(INT32_MIN, 0), pg_v2(PG_FIX_ONE, 0), &hit), PG_ERR_ENVELOPE, "pg_world_raycast", "origin");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(e + 1, 0), pg_v2(-PG_FIX_ONE, 0), &hit), PG_ERR_ENVELOPE, "pg_world_raycast", "origin");
    /* the end too */
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(0, 0), pg_v2(e + 1, 0), &hit), PG_ERR_ENVELOPE, "pg_world_raycast", "end");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(-e, -e), pg_v2(PG_FIX_MAX, PG_FIX_MAX), &hit), PG_ERR_ENVELOPE, "pg_world_raycast", "end");
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(0, 0), pg_v2(0, INT32_MIN), &hit), PG_ERR_ENVELOPE, "pg_world_raycast", "end");
    /* corner to corner is legal and hits the ball at (1000, 1000) */
    assert_int_equal(pg_world_raycast(w, pg_v2(-e, -e), pg_v2(2 * e, 2 * e), &hit), PG_OK);
    assert_true(pg_body_id_equal(hit.body, ball));
    assert_true(fabs(fd(hit.fraction) - (1.0 - 1.0 / (2000.0 * sqrt(2.0)))) < 1e-4);
    assert_true(fabs(fd(hit.point.x) - (1000.0 - sqrt(0.5))) < 1e-3);
    assert_true(fabs(fd(hit.normal.x) + sqrt(0.5)) < 1e-3);
    /* and along the edge of the envelope, missing it */
    EXPECT_ERROR(w, pg_world_raycast(w, pg_v2(-e, -e), pg_v2(2 * e, 0), &hit), PG_ERR_NOT_FOUND, "pg_world_raycast", NULL);
    free_world(&t);
}

/* Bodies may fly out of the envelope (their positions saturate at +-32768 m): queries
 * near them and legal rays elsewhere stay defined (UBSan: collide.c pg__dist2 before). */
static void test_queries_with_far_body(void **state)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_world *w;
    pg_body_def bd = dynamic_at(1000, 1000);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id flyer, mid, other, box_flyer, out[4];
    pg_ray_hit hit;
    pg_geometry g;
    pg_vec2 c, cb;
    uint32_t count;
    int i;
    (void)state;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_contacts = 16;
    d.gravity = pg_v2_zero();
    d.max_linear_speed = PG_FIX_C(4096);
    t = make_world_def(&d);
    w = t.w;
    bd.linear_velocity = pg_v2(PG_FIX_C(2800), PG_FIX_C(2800));
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &flyer), PG_OK);
    bd = dynamic_at(-1000, 1000);
    bd.linear_velocity = pg_v2(-PG_FIX_C(2000), 0); /* 12 s later: x = -25000 m */
    bd.angular_velocity = PG_FIX_C(3);
    assert_int_equal(pg_make_box(w, &bd, &sd, PG_FIX_C(4), PG_FIX_C(2), &box_flyer), PG_OK);
    bd = dynamic_at(-900, -1000);
    bd.linear_velocity = pg_v2(PG_FIX_C(2400), 0); /* 12 s later: x = 27900 m */
    assert_int_equal(pg_make_capsule(w, &bd, &sd, PG_FIX_C(4), PG_FIX_ONE, &mid), PG_OK);
    bd = pg_default_body_def();
    bd.position = pg_v2(PG_FIX_C(-990), PG_FIX_C(-1000));
    assert_int_equal(pg_make_ball(w, &bd, &sd, PG_FIX_ONE, &other), PG_OK);
    for (i = 0; i < 720; ++i) assert_int_equal(pg_world_step(w), PG_OK);
    c = pg_body_position(w, flyer);
    assert_true(c.x == PG_FIX_MAX && c.y == PG_FIX_MAX); /* saturated: 1000 + 12 * 2800 m */
    cb = pg_body_position(w, box_flyer);
    assert_true(cb.x < -PG_FIX_C(16000) && cb.x > PG_FIX_MIN && fabs(fd(cb.y) - 1000.0) < 1.0);
    assert_true(pg_body_position(w, mid).x > PG_FIX_C(20000));

    /* the audit's ray: from (-1000, -1000), 10 m along x: reaches the static ball at -990 */
    assert_int_equal(pg_world_raycast(w, pg_v2(PG_FIX_C(-1000), PG_FIX_C(-1000)), pg_v2(PG_FIX_C(10), 0), &hit), PG_OK);
    assert_true(pg_body_id_equal(hit.body, other));
    assert_true(fabs(fd(hit.fraction) - 0.9) < 1e-3);
    /* rays over the whole envelope, every direction: the far bodies are never hit */
    for (i = 0; i < 64; ++i) {
        double a = 2.0 * PGT_PI * i / 64.0;
        pg_result r = pg_world_raycast(w, pg_v2(fx(999.0 * cos(a)), fx(999.0 * sin(a))), pg_v2(fx(-1998.0 * cos(a)), fx(-1998.0 * sin(a))), &hit);
        assert_true(r == PG_OK || r == PG_ERR_NOT_FOUND);
        if (r == PG_OK) assert_true(pg_body_id_equal(hit.body, other));
    }
    /* queries at the far bodies find them (and nothing overflows); the saturated one has
     * lost its shape, so only "not something else" is certain about it */
    assert_int_equal(pg_world_query_point(w, c, out, 4, &count), PG_OK);
    assert_true(count == 0 || (count == 1 && pg_body_id_equal(out[0], flyer)));
    assert_int_equal(pg_world_query_point(w, cb, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box_flyer));
    assert_int_equal(pg_world_query_point(w, pg_body_position(w, mid), out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], mid));
    assert_int_equal(pg_geometry_box(PG_FIX_C(50), PG_FIX_C(50), pg_v2_zero(), 0, &g), PG_OK);
    assert_int_equal(pg_world_query_geometry(w, &g, pg_v2(PG_FIX_MAX, PG_FIX_MAX), PG_ANGLE_QUARTER / 2, out, 4, &count), PG_OK);
    assert_true(count == 0 || (count == 1 && pg_body_id_equal(out[0], flyer)));
    assert_int_equal(pg_world_query_geometry(w, &g, pg_body_position(w, mid), 777u, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], mid));
    assert_int_equal(pg_world_query_geometry(w, &g, cb, 12345u, out, 4, &count), PG_OK);
    assert_int_equal(count, 1);
    assert_true(pg_body_id_equal(out[0], box_flyer));
    assert_int_equal(pg_world_query_point(w, pg_v2(PG_FIX_MIN, PG_FIX_MAX), out, 4, &count), PG_OK);
    assert_int_equal(count, 0);
    free_world(&t);
}

/* ---- world settings ----------------------------------------------------------------------------------- */
static void test_world_settings(void **state)
{
    test_world t = make_world(8, 8, 16);
    pg_world *w = t.w;
    (void)state;
    assert_int_equal(pg_world_effects(w), PG_EFFECTS_ALL);
    assert_int_equal(pg_world_set_effects(w, PG_EFFECTS_ALL | 0x100u), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_world_effects(w), PG_EFFECTS_ALL);
    assert_int_equal(pg_world_set_effects(w, PG_EFFECT_GRAVITY), PG_OK);
    assert_int_equal(pg_world_effects(w), PG_EFFECT_GRAVITY);
    assert_int_equal(pg_world_set_gravity(w, pg_v2(PG_FIX_ONE, -PG_FIX_C(3))), PG_OK);
    assert_true(pg_v2_equal(pg_world_gravity(w), pg_v2(PG_FIX_ONE, -PG_FIX_C(3))));
    assert_true(pg_v2_equal(pg_world_get_def(w).gravity, pg_v2(PG_FIX_ONE, -PG_FIX_C(3))));
    assert_int_equal(pg_world_step(w), PG_OK);
    assert_int_equal(pg_world_step(w), PG_OK);
    assert_int_equal(pg_world_frame(w), 2);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_result_names_and_messages),
        cmocka_unit_test(test_memory_size_of_invalid_defs),
        cmocka_unit_test(test_events_capacity),
        cmocka_unit_test(test_def_problem_names_the_field),
        cmocka_unit_test(test_defs_not_from_their_defaults_are_refused),
        cmocka_unit_test(test_world_create_errors),
        cmocka_unit_test(test_null_pointers),
        cmocka_unit_test(test_capacity_bodies),
        cmocka_unit_test(test_capacity_shapes),
        cmocka_unit_test(test_failed_make_leaves_pool_unchanged),
        cmocka_unit_test(test_stale_handles),
        cmocka_unit_test(test_envelope),
        cmocka_unit_test(test_envelope_speed_is_magnitude),
        cmocka_unit_test(test_degenerate_and_convexity),
        cmocka_unit_test(test_shape_create_validates_geometry),
        cmocka_unit_test(test_forces_need_dynamic_body),
        cmocka_unit_test(test_masses),
        cmocka_unit_test(test_events_destroy),
        cmocka_unit_test(test_events_leave),
        cmocka_unit_test(test_query_point_and_aabb),
        cmocka_unit_test(test_query_geometry_and_free_position),
        cmocka_unit_test(test_raycast),
        cmocka_unit_test(test_query_null_messages),
        cmocka_unit_test(test_not_found_messages),
        cmocka_unit_test(test_query_geometry_validates),
        cmocka_unit_test(test_raycast_envelope),
        cmocka_unit_test(test_queries_with_far_body),
        cmocka_unit_test(test_world_settings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
