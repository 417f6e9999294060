/* test_scene_concave.c — concave bodies and chains in scene files (src/io/scene_file.c):
 * the `concave` and `chain` lines make what pg_make_concave and pg_make_chain make (the
 * same world hash), pg_scene_write writes them back (as their convex pieces and as
 * `shape chain_segment` lines with the neighbours) so that loading the text gives the
 * same hash and writing again the same text, and bad lines are refused with their line
 * and column. */
#include "pg_test.h"
#include "pg_test_world.h"

#include "pogon/replay.h"
#include "pogon/scene_file.h"

static const char scene[] =
    "pogon-scene 1\n"
    "# a bowl of terrain, an island and a U-shaped body\n"
    "chain 10 5 10 0 5 -1 0 -1.5 -5 -1 -10 0 -10 5 friction 0.4\n"
    "chain -2 2 -1 2 -1 3 -2 3 loop position 0 1\n"
    "concave -2 0 2 0 2 3 1.5 3 1.5 0.5 -1.5 0.5 -1.5 3 -2 3 position 3 4 angle 10 density 2\n";

static test_world world_for(const char *text, size_t length)
{
    pg_world_def def;
    pg_scene_error err;
    if (pg_scene_read_def(text, length, &def, &err) != PG_OK) fail_msg("%s", err.message);
    def.max_contacts = 256;
    return make_world_def(&def);
}

static test_world load(const char *text, size_t length)
{
    test_world t = world_for(text, length);
    pg_scene_error err;
    if (pg_scene_load(t.w, text, length, &err) != PG_OK) fail_msg("%s", err.message);
    return t;
}

static char *write_all(const pg_world *w, size_t *n)
{
    char *buf;
    *n = pg_scene_write(w, NULL, 0);
    buf = malloc(*n + 1);
    assert_non_null(buf);
    assert_int_equal(pg_scene_write(w, buf, *n + 1), *n);
    return buf;
}

static void test_lines_make_what_the_calls_make(void **state)
{
    test_world s = load(scene, sizeof scene - 1), d = world_for(scene, sizeof scene - 1);
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_vec2 terrain[7], island[4], u[8];
    static const double tp[7][2] = {{10, 5}, {10, 0}, {5, -1}, {0, -1.5}, {-5, -1}, {-10, 0}, {-10, 5}};
    static const double ip[4][2] = {{-2, 2}, {-1, 2}, {-1, 3}, {-2, 3}};
    static const double up[8][2] = {{-2, 0}, {2, 0}, {2, 3}, {1.5, 3}, {1.5, 0.5}, {-1.5, 0.5}, {-1.5, 3}, {-2, 3}};
    pg_body_id id;
    int i;
    (void)state;
    for (i = 0; i < 7; ++i) terrain[i] = pg_v2(fx(tp[i][0]), fx(tp[i][1]));
    for (i = 0; i < 4; ++i) island[i] = pg_v2(fx(ip[i][0]), fx(ip[i][1]));
    for (i = 0; i < 8; ++i) u[i] = pg_v2(fx(up[i][0]), fx(up[i][1]));
    sd.friction = fx(0.4);
    assert_int_equal(pg_make_chain(d.w, &bd, &sd, terrain, 7, 0, &id), PG_OK);
    sd = pg_default_shape_def();
    bd.position = pg_v2(0, fx(1));
    assert_int_equal(pg_make_chain(d.w, &bd, &sd, island, 4, 1, &id), PG_OK);
    bd = dynamic_at(3, 4);
    bd.angle = pg_scene_angle_from_degrees(fx(10));
    sd.density = fx(2);
    assert_int_equal(pg_make_concave(d.w, &bd, &sd, u, 8, &id), PG_OK);
    assert_true(pg_world_hash(s.w) == pg_world_hash(d.w));
    assert_int_equal(pg_world_get_stats(s.w).shape_count, 6 + 4 + 3);
    free_world(&s);
    free_world(&d);
}

static void test_round_trip(void **state)
{
    test_world a = load(scene, sizeof scene - 1), b;
    size_t n1, n2;
    char *t1, *t2;
    int i;
    (void)state;
    for (i = 0; i < 90; ++i) assert_int_equal(pg_world_step(a.w), PG_OK); /* the U falls into the bowl */
    t1 = write_all(a.w, &n1);
    assert_non_null(strstr(t1, "shape chain_segment"));
    b = load(t1, n1);
    t2 = write_all(b.w, &n2);
    if (n1 != n2 || memcmp(t1, t2, n1) != 0) fail_msg("second write differs:\n%s\n----\n%s", t1, t2);
    /* the hash without contacts and timers: a fresh load of the same text */
    {
        test_world c = load(t1, n1);
        assert_true(pg_world_hash(b.w) == pg_world_hash(c.w));
        free_world(&c);
    }
    free(t1);
    free(t2);
    free_world(&a);
    free_world(&b);
}

static void expect_error(const char *text, pg_result code, uint32_t line, const char *words)
{
    pg_world_def def;
    pg_scene_error err;
    assert_int_equal(pg_scene_read_def(text, strlen(text), &def, &err), code);
    PG_EXPECT_EQ(err.line, line, "%s", err.message);
    if (strstr(err.message, words) == NULL) fail_msg("'%s' does not say '%s'", err.message, words);
}

static void test_refusals(void **state)
{
    (void)state;
    expect_error("pogon-scene 1\nconcave 0 0 1 1 1 0 0 1\n", PG_ERR_INVALID_ARGUMENT, 2, "cross or touch");
    expect_error("pogon-scene 1\nconcave 0 0 1 0\n", PG_ERR_INVALID_ARGUMENT, 2, "3..64 vertices");
    expect_error("pogon-scene 1\nconcave 0 0 60 0 60 1 0 1\n", PG_ERR_ENVELOPE, 2, "beyond 50 m");
    expect_error("pogon-scene 1\nchain 0 0\n", PG_ERR_INVALID_ARGUMENT, 2, "2..65 points");
    expect_error("pogon-scene 1\nchain 0 0 1 0 1 0\n", PG_ERR_DEGENERATE, 2, "segment 1 ");
    expect_error("pogon-scene 1\nchain 0 0 1 0 type dynamic\n", PG_ERR_BODY_TYPE, 2, "always static");
    expect_error("pogon-scene 1\nbody dynamic\n  shape chain_segment 0 0 0 0 1 0 1 0\nend\n", PG_ERR_BODY_TYPE, 3, "static bodies only");
    expect_error("pogon-scene 1\nbody static\n  shape chain_segment 0 0 0 0 1 0\nend\n", PG_ERR_INVALID_ARGUMENT, 3, "after x");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lines_make_what_the_calls_make),
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
