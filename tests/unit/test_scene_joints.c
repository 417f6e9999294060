/* test_scene_joints.c — joints in scene files (docs/formats.md, "Joints"): a world with a
 * joint of every kind, every def field away from its default, is written and read back
 * to the same state hash and the same text, and steps the same afterwards; malformed
 * joint lines give the documented result at the right line and column; a failing load
 * leaves the world as it was.
 */
#include "pg_test.h"

#include <stdlib.h>
#include <string.h>

#include "pg_test_world.h"
#include "pogon/joint.h"
#include "pogon/replay.h"
#include "pogon/scene_file.h"

static pg_body_id body(pg_world *w, pg_body_type type, double x, double y)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    bd.type = type;
    bd.position = pg_v2(fx(x), fx(y));
    assert_int_equal(pg_make_box(w, &bd, &sd, fx(0.5), fx(0.5), &id), PG_OK);
    return id;
}

/* A ground, six boxes and one joint of each kind, every field away from its default. */
static test_world every_kind(void)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_world *w;
    pg_body_id g, b[6];
    pg_joint_id j;
    int i;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_joints = 8;
    t = make_world_def(&d);
    w = t.w;
    g = body(w, PG_BODY_STATIC, 0, 0);
    for (i = 0; i < 6; ++i) b[i] = body(w, PG_BODY_DYNAMIC, -5.0 + 2.0 * i, 3);
    {
        pg_distance_joint_def jd = pg_default_distance_joint_def();
        jd.body_a = g, jd.body_b = b[0];
        jd.local_anchor_a = pg_v2(fx(-5), fx(6)), jd.local_anchor_b = pg_v2(fx(0.25), fx(0.1));
        jd.length = fx(2.75), jd.enable_spring = 1, jd.hertz = fx(4), jd.damping_ratio = fx(0.3);
        jd.enable_limit = 1, jd.min_length = fx(1), jd.max_length = fx(3.5), jd.collide_connected = 1, jd.user_data = 11;
        assert_int_equal(pg_distance_joint_create(w, &jd, &j), PG_OK);
    }
    {
        pg_revolute_joint_def jd = pg_default_revolute_joint_def();
        jd.body_a = b[0], jd.body_b = b[1];
        jd.local_anchor_a = pg_v2(fx(1), 0), jd.local_anchor_b = pg_v2(fx(-1), 0);
        jd.reference_angle = 0x12345679u, jd.enable_limit = 1, jd.lower_angle = fx(-0.5), jd.upper_angle = fx(0.75);
        jd.enable_motor = 1, jd.motor_speed = fx(-2), jd.max_motor_torque = fx(30), jd.user_data = 12;
        assert_int_equal(pg_revolute_joint_create(w, &jd, &j), PG_OK);
    }
    {
        pg_weld_joint_def jd = pg_default_weld_joint_def();
        jd.body_a = b[1], jd.body_b = b[2];
        jd.local_anchor_a = pg_v2(fx(1), fx(0.2)), jd.local_anchor_b = pg_v2(fx(-1), fx(0.2));
        jd.reference_angle = PG_ANGLE_QUARTER, jd.linear_hertz = fx(8), jd.linear_damping_ratio = fx(0.5);
        jd.angular_hertz = fx(3), jd.angular_damping_ratio = fx(1.5), jd.collide_connected = 1, jd.user_data = 13;
        assert_int_equal(pg_weld_joint_create(w, &jd, &j), PG_OK);
    }
    {
        pg_prismatic_joint_def jd = pg_default_prismatic_joint_def();
        jd.body_a = g, jd.body_b = b[3];
        jd.local_anchor_a = pg_v2(fx(1), fx(3)), jd.local_anchor_b = pg_v2(0, fx(-0.25));
        jd.local_axis_a = pg_v2(fx(3), fx(4)), jd.reference_angle = 0x01000000u;
        jd.enable_limit = 1, jd.lower_translation = fx(-1), jd.upper_translation = fx(2);
        jd.enable_motor = 1, jd.motor_speed = fx(0.5), jd.max_motor_force = fx(50), jd.user_data = 14;
        assert_int_equal(pg_prismatic_joint_create(w, &jd, &j), PG_OK);
    }
    {
        pg_mouse_joint_def jd = pg_default_mouse_joint_def();
        jd.body = b[4];
        jd.target = pg_v2(fx(3.2), fx(3.3));
        jd.hertz = fx(7), jd.damping_ratio = fx(0.9), jd.max_force = fx(250), jd.user_data = 15;
        assert_int_equal(pg_mouse_joint_create(w, &jd, &j), PG_OK);
        assert_int_equal(pg_mouse_joint_set_target(w, j, pg_v2(fx(4), fx(5))), PG_OK); /* anchor and target now differ */
    }
    {
        pg_revolute_joint_def jd = pg_default_revolute_joint_def(); /* every field at its default */
        jd.body_a = b[4], jd.body_b = b[5];
        assert_int_equal(pg_revolute_joint_create(w, &jd, &j), PG_OK);
    }
    return t;
}

static char *write_text(const pg_world *w, size_t *size)
{
    size_t n = pg_scene_write(w, NULL, 0);
    char *text = malloc(n + 1);
    assert_non_null(text);
    assert_int_equal(pg_scene_write(w, text, n + 1), n);
    *size = n;
    return text;
}

static test_world load(const char *text, size_t size)
{
    pg_world_def d;
    pg_scene_error e;
    test_world t;
    pg_result r = pg_scene_read_def(text, size, &d, &e);
    if (r != PG_OK) {
        print_error("read_def: %s\n%s\n", e.message, text);
        fail();
    }
    t = make_world_def(&d);
    r = pg_scene_load(t.w, text, size, &e);
    if (r != PG_OK) {
        print_error("load: %s\n", e.message);
        fail();
    }
    return t;
}

static void round_trip(void **state)
{
    test_world a = every_kind(), b;
    size_t n1, n2;
    char *t1 = write_text(a.w, &n1), *t2;
    int i;
    (void)state;
    b = load(t1, n1);
    {
        pg_joint_id last = {5, 1}, none = {6, 1};
        assert_true(pg_joint_is_valid(b.w, last));
        assert_false(pg_joint_is_valid(b.w, none));
    }
    t2 = write_text(b.w, &n2);
    assert_int_equal(n1, n2);
    assert_memory_equal(t1, t2, n1);
    {
        uint64_t sa[PG_SECTION_COUNT], sb[PG_SECTION_COUNT];
        pg_world_section_hashes(a.w, sa);
        pg_world_section_hashes(b.w, sb);
        for (i = 0; i < PG_SECTION_COUNT; ++i)
            if (sa[i] != sb[i]) {
                print_error("section %s differs after the round trip\n%s", pg_section_name((pg_section)i), t1);
                fail();
            }
    }
    for (i = 0; i < 120; ++i) {
        assert_int_equal(pg_world_step(a.w), PG_OK);
        assert_int_equal(pg_world_step(b.w), PG_OK);
        assert_true(pg_world_hash(a.w) == pg_world_hash(b.w));
    }
    free(t1);
    free(t2);
    free_world(&a);
    free_world(&b);
}

/* The file form, as written: the shortest decimals, defaults left out. */
static void written_form(void **state)
{
    test_world a = every_kind();
    size_t n;
    char *t = write_text(a.w, &n);
    (void)state;
    assert_non_null(strstr(t, "\njoint distance 0 1 local_anchor_a -5 6 local_anchor_b 0.25 0.1 length 2.75 enable_spring 1 hertz 4"));
    assert_non_null(strstr(t, "\njoint weld 2 3 local_anchor_a 1 0.2 local_anchor_b -1 0.2 reference_angle 90 linear_hertz 8"));
    assert_non_null(strstr(t, "\njoint mouse 5 local_anchor_b "));
    assert_non_null(strstr(t, " target 4 5 hertz 7 damping_ratio 0.9 max_force 250 user_data 15\n"));
    assert_non_null(strstr(t, "\njoint revolute 5 6\n"));
    assert_non_null(strstr(t, "\nmax_joints 8\n"));
    free(t);
    free_world(&a);
}

typedef struct bad_case {
    const char *joint_line; /* appended to BASE */
    pg_result result;
    uint32_t line, column;
    const char *message; /* the start of the message after "line L, column C: " */
} bad_case;

/* bodies 0 (static), 1 and 2 (dynamic) */
#define BASE "pogon-scene 1\nwall 10 1\nbox 1 1 position 0 3\nbody dynamic\n  position 2 3\n  shape circle 0.5\nend\n"

static const bad_case bad_cases[] = {
    {"joint hinge 0 1\n", PG_ERR_INVALID_ARGUMENT, 8, 7, "expected a joint kind"},
    {"joint revolute 0 3\n", PG_ERR_INVALID_ARGUMENT, 8, 18, "there is no body 3 above this line"},
    {"joint revolute 0\n", PG_ERR_INVALID_ARGUMENT, 8, 17, "expected an integer for 'body_b'"},
    {"joint revolute 1 1\n", PG_ERR_INVALID_ARGUMENT, 8, 18, "a joint joins two different bodies"},
    {"joint revolute 0 1 length 2\n", PG_ERR_INVALID_ARGUMENT, 8, 20, "expected a property of a revolute joint, got 'length'"},
    {"joint distance 0 1 length 2 length 3\n", PG_ERR_INVALID_ARGUMENT, 8, 29, "'length' is given twice for a joint"},
    {"joint distance 0 1 length 200\n", PG_ERR_ENVELOPE, 8, 27, "'length' is 200"},
    {"joint distance 0 1 enable_limit 1 min_length 3 max_length 2\n", PG_ERR_INVALID_ARGUMENT, 8, 46, "'min_length' is above 'max_length'"},
    {"joint revolute 1 2 local_anchor_b 60 0\n", PG_ERR_ENVELOPE, 8, 35, "'local_anchor_b' is beyond 50 m"},
    {"joint revolute 0 1 local_anchor_a 900 0\n", PG_OK, 0, 0, NULL},
    {"joint revolute 0 1 lower_angle 4\n", PG_ERR_ENVELOPE, 8, 32, "'lower_angle' is 4"},
    {"joint prismatic 0 1 local_axis_a 0 0\n", PG_ERR_DEGENERATE, 8, 34, "'local_axis_a' has no direction"},
    {"joint mouse 0 target 1 1\n", PG_ERR_BODY_TYPE, 8, 13, "a mouse joint's body must be dynamic"},
    {"joint mouse 1 local_anchor_a 0 0\n", PG_ERR_INVALID_ARGUMENT, 8, 15, "expected a property of a mouse joint"},
    {"wall 4 1 position 0 -3\njoint weld 0 3\n", PG_ERR_BODY_TYPE, 9, 12, "both bodies are static"},
    {"max_joints 1\n", PG_ERR_INVALID_ARGUMENT, 8, 1, "world settings must come before the first body"},
};

static void malformed(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; ++i) {
        const bad_case *c = &bad_cases[i];
        char text[512], want[200];
        pg_world_def d;
        pg_scene_error e;
        pg_result r;
        snprintf(text, sizeof text, "%s%s", BASE, c->joint_line);
        r = pg_scene_read_def(text, strlen(text), &d, &e);
        if (r != c->result || e.line != c->line || e.column != c->column) {
            print_error("case %u (%s): got %s at %u:%u (%s), want %s at %u:%u\n", (unsigned)i, c->joint_line, pg_result_name(r), e.line,
                        e.column, e.message, pg_result_name(c->result), c->line, c->column);
            fail();
        }
        if (c->message != NULL) {
            snprintf(want, sizeof want, "line %u, column %u: %s", c->line, c->column, c->message);
            if (strncmp(e.message, want, strlen(want)) != 0) {
                print_error("case %u: message '%s', want it to start with '%s'\n", (unsigned)i, e.message, want);
                fail();
            }
        }
    }
}

/* max_joints: given and exceeded; not given: at least the default, or the scene's count */
static void capacities(void **state)
{
    const char *over = "pogon-scene 1\nmax_joints 1\nwall 10 1\nbox 1 1 position 0 3\nball 0.5 position 3 3\n"
                       "joint revolute 0 1\njoint revolute 1 2\n";
    pg_world_def d;
    pg_scene_error e;
    (void)state;
    assert_int_equal(pg_scene_read_def(over, strlen(over), &d, &e), PG_ERR_CAPACITY);
    assert_int_equal(e.line, 7);
    assert_non_null(strstr(e.message, "joint 2 is beyond max_joints 1 (line 2)"));
    assert_int_equal(pg_scene_read_def(over + 27, strlen(over + 27), &d, &e), PG_ERR_INVALID_ARGUMENT); /* no version line */
    {
        const char *plain = BASE;
        assert_int_equal(pg_scene_read_def(plain, strlen(plain), &d, &e), PG_OK);
        assert_int_equal(d.max_joints, pg_default_world_def().max_joints);
    }
}

/* A failing load changes nothing: no room for the joints, or a world with a gap in its
 * body slots (the file's body numbers could not name the slots). */
static void failing_load(void **state)
{
    const char *text = BASE "joint revolute 0 1\njoint revolute 1 2\n";
    pg_world_def d;
    pg_scene_error e;
    test_world t;
    uint64_t before;
    pg_body_id extra[2];
    (void)state;
    assert_int_equal(pg_scene_read_def(text, strlen(text), &d, &e), PG_OK);
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_joints = 1;
    t = make_world_def(&d);
    before = pg_world_hash(t.w);
    assert_int_equal(pg_scene_load(t.w, text, strlen(text), &e), PG_ERR_CAPACITY);
    assert_int_equal(e.line, 9);
    assert_true(pg_world_hash(t.w) == before);
    free_world(&t);

    d.max_joints = 4;
    t = make_world_def(&d);
    extra[0] = body(t.w, PG_BODY_DYNAMIC, 0, 10);
    extra[1] = body(t.w, PG_BODY_DYNAMIC, 0, 12);
    assert_int_equal(pg_body_destroy(t.w, extra[0]), PG_OK);
    before = pg_world_hash(t.w);
    assert_int_equal(pg_scene_load(t.w, text, strlen(text), &e), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(e.message, "no gaps"));
    assert_true(pg_world_hash(t.w) == before);
    free_world(&t);

    /* after bodies already in the world (no gap), the file's numbers name its own bodies */
    t = make_world_def(&d);
    body(t.w, PG_BODY_DYNAMIC, 0, 10);
    assert_int_equal(pg_scene_load(t.w, text, strlen(text), &e), PG_OK);
    {
        pg_joint_id j = {0, 1};
        pg_body_id a = pg_joint_body_a(t.w, j), b = pg_joint_body_b(t.w, j);
        assert_int_equal(a.index, 1);
        assert_int_equal(b.index, 2);
    }
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_trip),
        cmocka_unit_test(written_form),
        cmocka_unit_test(malformed),
        cmocka_unit_test(capacities),
        cmocka_unit_test(failing_load),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
