/* test_joint_scenes.c — the joint benchmark scenes (tools/scenes/joint_scenes.h) are what
 * the header says, and their sanity figures measure what the benchmark reports them as:
 *
 *   - a scene holds the bodies and joints its layout counts, and starts with every joint's
 *     anchors together (sag, stretch and worst gap exactly 0);
 *   - moving one bottom-row body of the grid down by 0.5 m makes the sag 0.5 m / columns
 *     and the worst gap 0.5 m; moving one link of a chain by 0.25 m opens its two joints
 *     by 0.25 m each: stretch 0.5 m, worst gap 0.25 m;
 *   - a name that is not a joint scene is refused.
 */
#include "pg_test.h"

#include <math.h>
#include <stdlib.h>

#include "pogon/pogon.h"
#include "joint_scenes.h"

typedef struct built {
    void *memory;
    pg_joint_scene sc;
} built;

static built build(const char *name, uint32_t count)
{
    built b;
    size_t need = pg_joint_scene_memory_size(name, count, NULL);
    assert_true(need > 0);
    b.memory = malloc(need);
    assert_non_null(b.memory);
    assert_int_equal(pg_joint_scene_build(name, count, NULL, b.memory, need, &b.sc), PG_OK);
    return b;
}

static pg_body_id nth(const built *b, uint32_t n)
{
    pg_body_id id = b->sc.first;
    id.index += n;
    assert_true(pg_body_is_valid(b->sc.world, id));
    return id;
}

static void moved(const built *b, uint32_t n, pg_fix dx, pg_fix dy)
{
    pg_body_id id = nth(b, n);
    pg_vec2 p = pg_body_position(b->sc.world, id);
    assert_int_equal(pg_body_set_transform(b->sc.world, id, pg_v2(p.x + dx, p.y + dy), pg_body_angle(b->sc.world, id)), PG_OK);
}

static void grid_counts_and_sag(void **state)
{
    built b = build("joint_grid", 4);
    pg_joint_sanity s;
    (void)state;
    assert_int_equal(b.sc.body_count, 12);  /* 3 rows below the static one */
    assert_int_equal(b.sc.joint_count, 21); /* 4 x 3 vertical + 3 x 3 horizontal */
    assert_int_equal(pg_world_get_stats(b.sc.world).body_count, 16);
    assert_int_equal(pg_world_get_stats(b.sc.world).awake_body_count, 12);
    assert_true(pg_joint_scene_sanity("joint_grid", 4, &b.sc, &s));
    assert_string_equal(s.figure, "sag");
    assert_true(s.value_m == 0.0 && s.worst_gap_m == 0.0);
    moved(&b, 3u * 4u + 1u, 0, -PG_FIX_HALF); /* row 3 (the bottom), column 1 */
    assert_true(pg_joint_scene_sanity("joint_grid", 4, &b.sc, &s));
    PG_EXPECT_LE(fabs(s.value_m - 0.125), 1e-12, "%s", "sag after one bottom body moved 0.5 m down");
    PG_EXPECT_LE(fabs(s.worst_gap_m - 0.5), 1e-12, "%s", "its joints opened by 0.5 m");
    free(b.memory);
}

static void chain_counts_and_stretch(void **state)
{
    built b = build("chain", 2);
    pg_joint_sanity s;
    (void)state;
    assert_int_equal(b.sc.body_count, 80);
    assert_int_equal(b.sc.joint_count, 80);
    assert_int_equal(pg_world_get_stats(b.sc.world).body_count, 81); /* and the pins' body */
    assert_true(pg_joint_scene_sanity("chain", 2, &b.sc, &s));
    assert_string_equal(s.figure, "stretch");
    assert_true(s.value_m == 0.0 && s.worst_gap_m == 0.0);
    moved(&b, 40u + 5u, 0, PG_FIX_ONE / 4); /* chain 1, link 5 */
    assert_true(pg_joint_scene_sanity("chain", 2, &b.sc, &s));
    PG_EXPECT_LE(fabs(s.value_m - 0.5), 1e-12, "%s", "two joints opened by 0.25 m");
    PG_EXPECT_LE(fabs(s.worst_gap_m - 0.25), 1e-12, "%s", "the largest gap");
    free(b.memory);
}

static void other_names_refused(void **state)
{
    char memory[64];
    pg_joint_scene sc;
    pg_joint_sanity s;
    (void)state;
    assert_int_equal(pg_joint_scene_memory_size("pyramid", 20, NULL), 0);
    assert_int_equal(pg_joint_scene_build("pyramid", 20, NULL, memory, sizeof memory, &sc), PG_ERR_INVALID_ARGUMENT);
    assert_false(pg_joint_scene_sanity("pyramid", 20, &sc, &s));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(grid_counts_and_sag),
        cmocka_unit_test(chain_counts_and_stretch),
        cmocka_unit_test(other_names_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
