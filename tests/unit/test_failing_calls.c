/* test_failing_calls.c — "a failing call leaves the world unchanged" (pogon.h).
 *
 * Lockstep peers that see the same failure must stay identical, so a failing call may
 * not move any state: not a pool's generation, not a high-water mark, not a body. The
 * state hash covers all of it. The star case is the one the issue found; the sweep
 * drives every command kind with values at and past the envelope's edges, stale and
 * zero handles, and checks the hash after every failure. */
#include "pg_test.h"
#include "pg_test_world.h"

#include "pogon/replay.h"

static pg_world_def small_def(void)
{
    pg_world_def d = pg_default_world_def();
    d.max_bodies = 12;
    d.max_shapes = 16;
    d.max_contacts = 64;
    return d;
}

/* pg_make_star with r = 0.025 m at density 0.1: the star is below the inertia limit.
 * The call fails with PG_ERR_ENVELOPE and the world is as before: the same hash, and
 * the next body gets the generation it would have got (1). (At density 0.1875 the star
 * is within the limit, and test_star_checked_as_a_whole makes one.) */
static void test_failed_star_changes_nothing(void **state)
{
    pg_world_def d = small_def();
    test_world t = make_world_def(&d);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_body_id star = {9, 9}, ball;
    uint64_t sections[PG_SECTION_COUNT], after[PG_SECTION_COUNT];
    uint64_t hash = pg_world_hash(t.w);
    (void)state;
    pg_world_section_hashes(t.w, sections);
    sd.density = fx(0.1);
    assert_int_equal(pg_make_star(t.w, &bd, &sd, fx(0.025), &star), PG_ERR_ENVELOPE);
    assert_int_equal(star.index, 0);
    assert_int_equal(star.generation, 0);
    assert_true(strstr(pg_world_last_error(t.w), "inertia") != NULL);
    pg_world_section_hashes(t.w, after);
    assert_memory_equal(sections, after, sizeof sections);
    assert_true(pg_world_hash(t.w) == hash);
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, PG_FIX_ONE, &ball), PG_OK);
    assert_int_equal(ball.index, 0);
    assert_int_equal(ball.generation, 1);
    free_world(&t);
}

/* A star both of whose triangles are each below the inertia limit but which, whole, is
 * above it, is made: the check is of the body that results, not of its halves. */
static void test_star_checked_as_a_whole(void **state)
{
    pg_world_def d = small_def();
    test_world t = make_world_def(&d);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_def bd = dynamic_at(0, 0);
    pg_geometry tri;
    pg_body_id star, probe;
    pg_shape_id sid;
    double density;
    (void)state;
    /* the densest triangle of r = 0.025 m that pg_shape_create refuses alone */
    assert_int_equal(pg_geometry_triangle(pg_v2_zero(), fx(0.025), PG_ANGLE_QUARTER, &tri), PG_OK);
    for (density = 0.1; density < 100.0; density *= 1.05) {
        sd.density = fx(density * 1.05);
        assert_int_equal(pg_body_create(t.w, &bd, &probe), PG_OK);
        if (pg_shape_create(t.w, probe, &sd, &tri, &sid) == PG_OK) {
            assert_int_equal(pg_body_destroy(t.w, probe), PG_OK);
            break;
        }
        assert_int_equal(pg_body_destroy(t.w, probe), PG_OK);
    }
    sd.density = fx(density);
    assert_int_equal(pg_body_create(t.w, &bd, &probe), PG_OK);
    assert_int_equal(pg_shape_create(t.w, probe, &sd, &tri, &sid), PG_ERR_ENVELOPE); /* one triangle: too small */
    assert_int_equal(pg_body_destroy(t.w, probe), PG_OK);
    print_message("density %.4f: a triangle alone is refused, the star is made\n", density);
    assert_int_equal(pg_make_star(t.w, &bd, &sd, fx(0.025), &star), PG_OK); /* two: enough */
    sd.density = fx(0.1875); /* the case: refused, and the pools moved on */
    assert_int_equal(pg_make_star(t.w, &bd, &sd, fx(0.025), &star), PG_OK);
    free_world(&t);
}

/* ---- the sweep ---------------------------------------------------------------------- */
static pg_fix edge_value(pgt_rng *r)
{
    static const double v[] = {0, 1e-5, 0.005, 0.0249, 0.025, 0.05, 0.1, 0.0999, 0.5, 1, 10, 10.01, 50, 50.01, 100, 100.01,
                               399.99, 400, 400.01, 999.99, 1000, 1000.01, 4096, 8192, 32767};
    double x = v[pgt_below(r, sizeof v / sizeof v[0])];
    if (pgt_below(r, 2) == 0) return fx(0.25 * (double)(1 + pgt_below(r, 4))); /* ordinary: most calls succeed */
    if (pgt_below(r, 8) == 0) return pgt_fix_any(r);
    return pgt_below(r, 3) == 0 ? -fx(x) : fx(x);
}

static pg_vec2 edge_vec(pgt_rng *r) { return pg_v2(edge_value(r), pgt_below(r, 2) ? edge_value(r) : 0); }

static pg_body_id pick_body(pgt_rng *r, const pg_body_id *ids, uint32_t n)
{
    pg_body_id stale;
    uint32_t k = (uint32_t)pgt_below(r, 10);
    if (k == 0) { pg_body_id z = {0, 0}; return z; }
    if (k == 1 && n > 0) { stale = ids[pgt_below(r, n)]; stale.generation += 1u; return stale; }
    if (n == 0) { pg_body_id z = {0, 0}; return z; }
    return ids[pgt_below(r, n)];
}

static pg_command random_command(pgt_rng *r, const pg_body_id *ids, uint32_t n)
{
    pg_command c = pg_command_init((pg_command_kind)(1 + pgt_below(r, PG_CMD_KIND_COUNT - 1)));
    c.body = pick_body(r, ids, n);
    c.body_def = pg_default_body_def();
    c.body_def.type = (pg_body_type)pgt_below(r, 4); /* 3: invalid */
    c.body_def.position = pg_v2(fx((double)pgt_below(r, 20) - 10.0), fx((double)pgt_below(r, 20)));
    if (pgt_below(r, 4) == 0) c.body_def.position = edge_vec(r);
    if (c.body_def.type != PG_BODY_STATIC && pgt_below(r, 2)) c.body_def.linear_velocity = edge_vec(r);
    if (c.body_def.type != PG_BODY_STATIC && pgt_below(r, 3) == 0) c.body_def.angular_velocity = edge_value(r);
    if (pgt_below(r, 4) == 0) c.body_def.linear_damping = edge_value(r);
    c.body_def.fixed_rotation = (int)pgt_below(r, 2);
    c.shape_def = pg_default_shape_def();
    c.shape_def.density = pgt_below(r, 2) ? edge_value(r) : fx(1);
    if (pgt_below(r, 4) == 0) c.shape_def.friction = edge_value(r);
    if (pgt_below(r, 4) == 0) c.shape_def.restitution = edge_value(r);
    c.make_kind = (pg_make_kind)pgt_below(r, PG_MAKE_KIND_COUNT + 1); /* the last: invalid */
    c.size0 = pgt_below(r, 2) ? edge_value(r) : fx(0.5);
    c.size1 = pgt_below(r, 2) ? edge_value(r) : fx(0.5);
    switch (pgt_below(r, 3)) {
    case 0: (void)pg_geometry_circle(edge_vec(r), edge_value(r), &c.geometry); break;
    case 1: (void)pg_geometry_triangle(pg_v2_zero(), edge_value(r), (pg_angle)pgt_next(r), &c.geometry); break;
    default: (void)pg_geometry_box(edge_value(r), edge_value(r), pg_v2_zero(), 0, &c.geometry); break;
    }
    c.vec = edge_vec(r);
    c.point = pgt_below(r, 2) ? pg_v2_zero() : edge_vec(r);
    c.scalar = edge_value(r);
    c.scalar2 = edge_value(r);
    c.angle = (pg_angle)pgt_next(r);
    c.value = (uint32_t)pgt_below(r, 4);
    if (c.kind == PG_CMD_SET_EFFECTS) c.value = (uint32_t)pgt_next(r) & 0xFFu;
    if (c.kind == PG_CMD_SET_FILTER) c.value = (uint32_t)pgt_next(r), c.value2 = (uint32_t)pgt_next(r);
    c.flag = (uint32_t)pgt_below(r, 3);
    c.user_data = pgt_next(r);
    return c;
}

/* 20 000 commands at and past the envelope's edges on a small world, stepping between
 * them: every failing one leaves the hash as it was. */
static void test_failing_commands_change_nothing(void **state)
{
    pg_world_def d = small_def();
    test_world t = make_world_def(&d);
    pgt_rng rng = pgt_rng_seed(0x31u);
    pg_body_id ids[64];
    uint32_t n = 0, failures = 0, i;
    uint32_t failed_kinds[PG_CMD_KIND_COUNT] = {0};
    (void)state;
    for (i = 0; i < 20000u; ++i) {
        pg_command c = random_command(&rng, ids, n);
        uint64_t before = pg_world_hash(t.w);
        pg_body_id made = {0, 0};
        pg_result res = pg_command_apply(t.w, &c, &made);
        if (res != PG_OK) {
            uint64_t after = pg_world_hash(t.w);
            ++failures;
            failed_kinds[c.kind]++;
            if (after != before) {
                print_error("command %u (%s, make kind %d) failed with %s (%s) and changed the world\n", (unsigned)i,
                            pg_command_kind_name(c.kind), (int)c.make_kind, pg_result_name(res), pg_world_last_error(t.w));
                fail();
            }
        } else if (made.generation != 0) {
            if (n < 64) ids[n++] = made;
            else ids[pgt_below(&rng, 64)] = made;
        }
        if (pgt_below(&rng, 8) == 0) assert_int_equal(pg_world_step(t.w), PG_OK);
    }
    print_message("%u of 20000 commands failed; the world was unchanged after each\n", (unsigned)failures);
    for (i = 1; i < PG_CMD_KIND_COUNT; ++i)
        if (failed_kinds[i] == 0 && i != PG_CMD_SET_USER_DATA && i != PG_CMD_SET_GRAVITY) {
            print_error("no %s command failed: the sweep does not reach its checks\n", pg_command_kind_name((pg_command_kind)i));
            fail();
        }
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_failed_star_changes_nothing),
        cmocka_unit_test(test_star_checked_as_a_whole),
        cmocka_unit_test(test_failing_commands_change_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
