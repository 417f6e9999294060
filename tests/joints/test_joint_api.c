/* test_joint_api.c — the joint API's promises: handles, bad input refused with nothing
 * changed, joints destroyed with their bodies, joined bodies not colliding, islands,
 * the state hash and snapshots, the mouse joint and the reaction force. */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"
#include "pogon/replay.h"

static pg_joint_id rod(pg_world *w, pg_body_id a, pg_body_id b, double length)
{
    pg_distance_joint_def jd = pg_default_distance_joint_def();
    pg_joint_id j;
    jd.body_a = a;
    jd.body_b = b;
    jd.length = fx(length);
    assert_int_equal(pg_distance_joint_create(w, &jd, &j), PG_OK);
    return j;
}

/* A call that must fail with `want`, leave the hash as it was and say why. */
#define EXPECT_REFUSED(world, call, want)                                                                              \
    do {                                                                                                             \
        uint64_t h_ = pg_world_hash(world);                                                                          \
        assert_int_equal((call), (want));                                                                            \
        assert_true(pg_world_hash(world) == h_);                                                                     \
        assert_true(strlen(pg_world_last_error(world)) > 0);                                                         \
    } while (0)

static void test_bad_input_is_refused_and_changes_nothing(void **state)
{
    test_world t = joint_world(8, 2);
    pg_body_id ground = static_anchor(t.w, 0.0, 0.0), ground2 = static_anchor(t.w, 5.0, 0.0);
    pg_body_id a = ball_at(t.w, 0.0, 2.0, 0.25, 1.0), b = ball_at(t.w, 1.0, 2.0, 0.25, 1.0);
    pg_distance_joint_def dd = pg_default_distance_joint_def();
    pg_revolute_joint_def rd = pg_default_revolute_joint_def();
    pg_prismatic_joint_def pd = pg_default_prismatic_joint_def();
    pg_weld_joint_def wd = pg_default_weld_joint_def();
    pg_mouse_joint_def md = pg_default_mouse_joint_def();
    pg_distance_joint_def zeroed;
    pg_joint_id j, j2, stale;
    pg_body_id gone;
    (void)state;
    memset(&zeroed, 0, sizeof zeroed);
    dd.body_a = a;
    dd.body_b = b;
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &zeroed, &j), PG_ERR_INVALID_ARGUMENT); /* no cookie */
    assert_int_equal(pg_distance_joint_create(NULL, &dd, &j), PG_ERR_NULL);
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, NULL, &j), PG_ERR_NULL);
    dd.body_b = a;
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_INVALID_ARGUMENT); /* the same body twice */
    dd.body_a = ground;
    dd.body_b = ground2;
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_BODY_TYPE); /* two static bodies */
    dd.body_a = a;
    dd.body_b = b;
    dd.length = 0;
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_ENVELOPE);
    dd.length = fx(1.0);
    dd.min_length = fx(2.0);
    dd.max_length = fx(1.0);
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_INVALID_ARGUMENT); /* min > max */
    dd.min_length = 0;
    dd.max_length = fx(100.0);
    dd.hertz = -1;
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_INVALID_ARGUMENT);
    dd.hertz = 0;
    dd.local_anchor_a = pg_v2(fx(51.0), 0);
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &j), PG_ERR_ENVELOPE); /* beyond a moving body's reach */
    dd.local_anchor_a = pg_v2_zero();
    rd.body_a = a;
    rd.body_b = b;
    rd.lower_angle = fx(1.0);
    rd.upper_angle = fx(0.5);
    EXPECT_REFUSED(t.w, pg_revolute_joint_create(t.w, &rd, &j), PG_ERR_INVALID_ARGUMENT);
    rd.lower_angle = fx(-4.0);
    EXPECT_REFUSED(t.w, pg_revolute_joint_create(t.w, &rd, &j), PG_ERR_INVALID_ARGUMENT); /* beyond -pi */
    rd.lower_angle = 0;
    rd.upper_angle = 0;
    rd.max_motor_torque = -1;
    EXPECT_REFUSED(t.w, pg_revolute_joint_create(t.w, &rd, &j), PG_ERR_INVALID_ARGUMENT);
    pd.body_a = a;
    pd.body_b = b;
    pd.local_axis_a = pg_v2_zero();
    EXPECT_REFUSED(t.w, pg_prismatic_joint_create(t.w, &pd, &j), PG_ERR_DEGENERATE);
    wd.body_a = a;
    wd.body_b = b;
    wd.angular_hertz = fx(2000.0);
    EXPECT_REFUSED(t.w, pg_weld_joint_create(t.w, &wd, &j), PG_ERR_INVALID_ARGUMENT);
    md.body = ground;
    EXPECT_REFUSED(t.w, pg_mouse_joint_create(t.w, &md, &j), PG_ERR_BODY_TYPE); /* a mouse joint drags a dynamic body */
    md.body = a;
    md.target = pg_v2(fx(2000.0), 0);
    EXPECT_REFUSED(t.w, pg_mouse_joint_create(t.w, &md, &j), PG_ERR_ENVELOPE);
    md.target = pg_v2_zero();
    md.hertz = 0;
    EXPECT_REFUSED(t.w, pg_mouse_joint_create(t.w, &md, &j), PG_ERR_INVALID_ARGUMENT);

    /* the pool: capacity, stale handles, the wrong kind */
    dd.body_a = a;
    dd.body_b = b;
    dd.hertz = 0;
    assert_int_equal(pg_distance_joint_create(t.w, &dd, &j), PG_OK);
    assert_int_equal(pg_distance_joint_create(t.w, &dd, &j2), PG_OK);
    EXPECT_REFUSED(t.w, pg_distance_joint_create(t.w, &dd, &stale), PG_ERR_CAPACITY);
    assert_int_equal(pg_joint_type_of(t.w, j), PG_JOINT_DISTANCE);
    EXPECT_REFUSED(t.w, pg_revolute_joint_set_motor(t.w, j, 1, 0, 0), PG_ERR_INVALID_ARGUMENT);
    EXPECT_REFUSED(t.w, pg_distance_joint_set_length(t.w, j, fx(1000.0)), PG_ERR_ENVELOPE);
    EXPECT_REFUSED(t.w, pg_distance_joint_set_limits(t.w, j, 1, fx(3.0), fx(2.0)), PG_ERR_INVALID_ARGUMENT);
    stale = j;
    assert_int_equal(pg_joint_destroy(t.w, j), PG_OK);
    assert_false(pg_joint_is_valid(t.w, stale));
    EXPECT_REFUSED(t.w, pg_joint_destroy(t.w, stale), PG_ERR_STALE_HANDLE);
    EXPECT_REFUSED(t.w, pg_distance_joint_set_length(t.w, stale, fx(1.0)), PG_ERR_STALE_HANDLE);
    EXPECT_REFUSED(t.w, pg_joint_set_collide_connected(t.w, stale, 1), PG_ERR_STALE_HANDLE);
    assert_int_equal(pg_joint_type_of(t.w, stale), PG_JOINT_TYPE_COUNT);
    assert_int_equal(pg_joint_body_a(t.w, stale).generation, 0);
    /* the slot is taken again, under a new generation */
    assert_int_equal(pg_distance_joint_create(t.w, &dd, &j), PG_OK);
    assert_int_equal(j.index, stale.index);
    assert_true(j.generation != stale.generation);
    assert_false(pg_joint_is_valid(t.w, stale));

    /* destroying a body destroys its joints */
    gone = b;
    assert_int_equal(pg_body_joints(t.w, a, NULL, 0), 2u);
    assert_int_equal(pg_body_destroy(t.w, gone), PG_OK);
    assert_false(pg_joint_is_valid(t.w, j));
    assert_false(pg_joint_is_valid(t.w, j2));
    assert_int_equal(pg_body_joints(t.w, a, NULL, 0), 0u);
    free_world(&t);
}

static void test_defs_round_trip(void **state)
{
    test_world t = joint_world(8, 8);
    pg_body_id a = ball_at(t.w, 0.0, 2.0, 0.25, 1.0), b = box_at(t.w, 1.0, 2.0, 0.5, 0.5, 1.0);
    pg_revolute_joint_def rd = pg_default_revolute_joint_def(), rg;
    pg_prismatic_joint_def pd = pg_default_prismatic_joint_def(), pgd;
    pg_joint_id r, p;
    (void)state;
    rd.body_a = a;
    rd.body_b = b;
    rd.local_anchor_a = pg_v2(fx(0.5), fx(0.25));
    rd.local_anchor_b = pg_v2(fx(-0.5), 0);
    rd.enable_limit = 1;
    rd.lower_angle = fx(-1.0);
    rd.upper_angle = fx(2.0);
    rd.enable_motor = 1;
    rd.motor_speed = fx(3.0);
    rd.max_motor_torque = fx(7.0);
    rd.collide_connected = 1;
    rd.user_data = 42u;
    assert_int_equal(pg_revolute_joint_create(t.w, &rd, &r), PG_OK);
    assert_int_equal(pg_revolute_joint_get_def(t.w, r, &rg), PG_OK);
    /* field by field: the struct has padding */
    assert_true(pg_body_id_equal(rg.body_a, a) && pg_body_id_equal(rg.body_b, b));
    assert_int_equal(rg.local_anchor_a.x, rd.local_anchor_a.x);
    assert_int_equal(rg.local_anchor_a.y, rd.local_anchor_a.y);
    assert_int_equal(rg.local_anchor_b.x, rd.local_anchor_b.x);
    assert_int_equal(rg.local_anchor_b.y, rd.local_anchor_b.y);
    assert_int_equal(rg.reference_angle, rd.reference_angle);
    assert_int_equal(rg.enable_limit, 1);
    assert_int_equal(rg.lower_angle, rd.lower_angle);
    assert_int_equal(rg.upper_angle, rd.upper_angle);
    assert_int_equal(rg.enable_motor, 1);
    assert_int_equal(rg.motor_speed, rd.motor_speed);
    assert_int_equal(rg.max_motor_torque, rd.max_motor_torque);
    assert_int_equal(rg.collide_connected, 1);
    assert_int_equal(rg.user_data, 42u);
    assert_int_equal(rg.pg__cookie, rd.pg__cookie);
    pd.body_a = a;
    pd.body_b = b;
    pd.local_axis_a = pg_v2(0, fx(2.0)); /* normalised to (0, 1) */
    assert_int_equal(pg_prismatic_joint_create(t.w, &pd, &p), PG_OK);
    assert_int_equal(pg_prismatic_joint_get_def(t.w, p, &pgd), PG_OK);
    assert_int_equal(pgd.local_axis_a.x, 0);
    assert_int_equal(pgd.local_axis_a.y, PG_FIX_ONE);
    assert_int_equal(pg_joint_user_data(t.w, r), 42u);
    assert_true(pg_joint_collide_connected(t.w, r));
    assert_false(pg_joint_collide_connected(t.w, p));
    free_world(&t);
}

static void test_joined_bodies_do_not_collide_unless_asked(void **state)
{
    /* two boxes overlapping, joined by a rod: they pass through each other; with
     * collide_connected they push apart */
    test_world t = joint_world(8, 4);
    pg_body_id a = box_at(t.w, 0.0, 5.0, 1.0, 1.0, 1.0), b = box_at(t.w, 0.5, 5.0, 1.0, 1.0, 1.0);
    pg_joint_id j;
    pg_world_stats st;
    int step;
    (void)state;
    assert_int_equal(pg_world_set_gravity(t.w, pg_v2_zero()), PG_OK);
    j = rod(t.w, a, b, 0.5);
    for (step = 0; step < 10; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    st = pg_world_get_stats(t.w);
    assert_int_equal(st.contact_count, 0u);
    assert_int_equal(pg_joint_set_collide_connected(t.w, j, 1), PG_OK);
    for (step = 0; step < 10; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    st = pg_world_get_stats(t.w);
    assert_int_equal(st.contact_count, 1u);
    free_world(&t);
}

static void test_a_sleeping_chain_sleeps_and_wakes_as_one(void **state)
{
    /* a chain of 5 balls on rods hanging from a static pin, resting on nothing: it comes
     * to rest and falls asleep as one island; pushing its last ball wakes every ball */
    test_world t = joint_world(8, 8);
    pg_body_id pin = static_anchor(t.w, 0.0, 10.0), balls[5];
    int i, step;
    (void)state;
    for (i = 0; i < 5; ++i) {
        balls[i] = ball_at(t.w, 0.0, 10.0 - (i + 1) * 0.6, 0.2, 1.0);
        rod(t.w, i == 0 ? pin : balls[i - 1], balls[i], 0.6);
    }
    for (step = 0; step < 600 && pg_body_is_awake(t.w, balls[0]); ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    for (i = 0; i < 5; ++i) assert_false(pg_body_is_awake(t.w, balls[i]));
    /* asleep, a step changes nothing */
    {
        uint64_t h = pg_world_hash(t.w);
        uint64_t before[PG_SECTION_COUNT], after[PG_SECTION_COUNT];
        pg_world_section_hashes(t.w, before);
        assert_int_equal(pg_world_step(t.w), PG_OK);
        pg_world_section_hashes(t.w, after);
        assert_true(before[PG_SECTION_JOINTS] == after[PG_SECTION_JOINTS]);
        assert_true(before[PG_SECTION_BODIES] == after[PG_SECTION_BODIES]);
        (void)h;
    }
    assert_int_equal(pg_body_apply_linear_impulse(t.w, balls[4], pg_v2(fx(0.1), 0), pg_body_world_center(t.w, balls[4])), PG_OK);
    for (i = 0; i < 5; ++i) assert_true(pg_body_is_awake(t.w, balls[i]));
    free_world(&t);
}

static void test_hash_and_snapshot(void **state)
{
    /* a world that never had a joint hashes its (empty) joint section as the empty
     * string; a joint changes it; a snapshot restores joints and their impulses, and the
     * steps after it are bit-identical */
    test_world t = joint_world(16, 8), u = joint_world(16, 8);
    pg_body_id pin, a, b;
    uint64_t sections[PG_SECTION_COUNT], ha, hb;
    size_t size, written;
    void *snap;
    int step;
    (void)state;
    pg_world_section_hashes(t.w, sections);
    assert_true(sections[PG_SECTION_JOINTS] == PG_HASH_SEED);
    pin = static_anchor(t.w, 0.0, 10.0);
    a = ball_at(t.w, 1.0, 10.0, 0.2, 1.0);
    b = box_at(t.w, 2.0, 10.0, 0.5, 0.3, 2.0);
    {
        pg_revolute_joint_def rd = pg_default_revolute_joint_def();
        pg_joint_id j;
        rd.body_a = pin;
        rd.body_b = a;
        rd.local_anchor_b = pg_v2(fx(-1.0), 0);
        rd.enable_limit = 1;
        rd.lower_angle = fx(-1.0);
        rd.upper_angle = fx(0.3);
        assert_int_equal(pg_revolute_joint_create(t.w, &rd, &j), PG_OK);
        rod(t.w, a, b, 1.0);
    }
    pg_world_section_hashes(t.w, sections);
    assert_true(sections[PG_SECTION_JOINTS] != PG_HASH_SEED);
    for (step = 0; step < 30; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    size = pg_world_snapshot_size(t.w);
    snap = malloc(size);
    assert_non_null(snap);
    assert_int_equal(pg_world_snapshot_save(t.w, snap, size, &written), PG_OK);
    assert_int_equal(pg_world_snapshot_restore(u.w, snap, written), PG_OK);
    assert_true(pg_world_hash(u.w) == pg_world_hash(t.w));
    for (step = 0; step < 60; ++step) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        assert_int_equal(pg_world_step(u.w), PG_OK);
    }
    ha = pg_world_hash(t.w);
    hb = pg_world_hash(u.w);
    assert_true(ha == hb);
    /* the restored joints are there, with their handles (slot 0 and 1, generation 1) */
    {
        pg_joint_id j0 = {0u, 1u};
        assert_int_equal(pg_joint_type_of(u.w, j0), PG_JOINT_REVOLUTE);
        assert_int_equal(pg_body_joints(u.w, a, NULL, 0), 2u);
    }
    /* a world with fewer joint slots refuses it, and changes nothing */
    {
        test_world v = joint_world(16, 1);
        uint64_t hv = pg_world_hash(v.w);
        assert_int_equal(pg_world_snapshot_restore(v.w, snap, written), PG_ERR_INVALID_ARGUMENT);
        assert_non_null(strstr(pg_world_last_error(v.w), "joints.count"));
        assert_true(pg_world_hash(v.w) == hv);
        free_world(&v);
    }
    free(snap);
    free_world(&t);
    free_world(&u);
}

static void test_mouse_joint_drags_and_reaction_holds_the_weight(void **state)
{
    test_world t = joint_world(8, 4);
    pg_body_id box = box_at(t.w, 0.0, 5.0, 1.0, 1.0, 2.0);
    pg_mouse_joint_def md = pg_default_mouse_joint_def();
    pg_joint_id m;
    pg_joint_reaction r;
    double mass = body_mass(t.w, box);
    int step;
    (void)state;
    md.body = box;
    md.target = pg_v2(0, fx(5.0));
    md.max_force = fx(1000.0);
    assert_int_equal(pg_mouse_joint_create(t.w, &md, &m), PG_OK);
    assert_int_equal(pg_mouse_joint_set_target(t.w, m, pg_v2(fx(3.0), fx(6.0))), PG_OK);
    for (step = 0; step < 300; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    /* it hangs below the target by the spring's give under its weight, m g / (m omega^2) */
    printf("mouse joint: box at (%.4f, %.4f), target (3, 6); sag %.4f m, spring gives %.4f m\n", body_x(t.w, box), body_y(t.w, box),
           6.0 - body_y(t.w, box), 10.0 / pow(2.0 * PGT_PI * 5.0, 2.0));
    JT_LE(fabs(body_x(t.w, box) - 3.0), 0.001);
    JT_LE(fabs(6.0 - body_y(t.w, box) - 10.0 / pow(2.0 * PGT_PI * 5.0, 2.0)), 0.002);
    assert_int_equal(pg_joint_get_reaction(t.w, m, &r), PG_OK);
    printf("mouse joint reaction (%.4f, %.4f) N, weight %.4f N\n", (double)r.force_x / 65536.0, (double)r.force_y / 65536.0, mass * 10.0);
    JT_LE(fabs((double)r.force_y / 65536.0 / (mass * 10.0) - 1.0), 0.01);
    JT_LE(fabs((double)r.force_x / 65536.0), 0.01 * mass * 10.0);
    /* a maximum force below the weight cannot hold it */
    assert_int_equal(pg_mouse_joint_set_max_force(t.w, m, fx(mass * 10.0 * 0.5)), PG_OK);
    for (step = 0; step < 60; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_joint_get_reaction(t.w, m, &r), PG_OK);
    printf("mouse joint capped at half the weight: reaction %.4f N, box at y %.4f\n", (double)r.force_y / 65536.0, body_y(t.w, box));
    JT_LE(fabs((double)r.force_y / 65536.0 / (mass * 10.0 * 0.5) - 1.0), 0.01);
    JT_LE(body_y(t.w, box), 4.0);
    free_world(&t);
}

static void test_rod_reaction_is_the_tension(void **state)
{
    /* a ball hanging at rest on a rod: the rod pulls it up with its weight */
    test_world t = joint_world(8, 4);
    pg_body_id pin = static_anchor(t.w, 0.0, 10.0), ball = ball_at(t.w, 0.0, 8.0, 0.25, 3.0);
    pg_joint_id j = rod(t.w, pin, ball, 2.0);
    pg_joint_reaction r;
    int step;
    (void)state;
    for (step = 0; step < 120; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    assert_int_equal(pg_joint_get_reaction(t.w, j, &r), PG_OK);
    printf("rod tension %.4f N, weight %.4f N\n", (double)r.force_y / 65536.0, body_mass(t.w, ball) * 10.0);
    JT_LE(fabs((double)r.force_y / 65536.0 / (body_mass(t.w, ball) * 10.0) - 1.0), 0.005);
    free_world(&t);
}

/* A body's type change that would break a rule its joints were made under is refused
 * with nothing changed, so every world stays one its scene and state readers accept. */
static void test_type_change_keeps_the_joint_rules(void **state)
{
    test_world t = joint_world(8, 4);
    pg_body_id ground = static_anchor(t.w, 0.0, 0.0), a = ball_at(t.w, 0.0, 2.0, 0.25, 1.0);
    pg_body_id b = ball_at(t.w, 3.0, 2.0, 0.25, 1.0), far = ball_at(t.w, 60.0, 2.0, 0.25, 1.0);
    pg_body_def sbd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_revolute_joint_def rd = pg_default_revolute_joint_def();
    pg_mouse_joint_def md = pg_default_mouse_joint_def();
    pg_distance_joint_def dd = pg_default_distance_joint_def();
    pg_body_id slab;
    pg_joint_id pin, drag, reach;
    (void)state;
    sbd.position = pg_v2(fx(0.0), fx(-1.0));
    assert_int_equal(pg_make_box(t.w, &sbd, &sd, fx(1.0), fx(0.5), &slab), PG_OK);
    rd.body_a = ground;
    rd.body_b = a;
    rd.local_anchor_b = pg_v2(0, fx(-2.0));
    assert_int_equal(pg_revolute_joint_create(t.w, &rd, &pin), PG_OK);
    md.body = b;
    md.target = pg_v2(fx(3.0), fx(2.0));
    assert_int_equal(pg_mouse_joint_create(t.w, &md, &drag), PG_OK);
    dd.body_a = slab;
    dd.body_b = far;
    dd.local_anchor_a = pg_v2(fx(60.0), fx(3.0)); /* 60 m from the slab's origin: a static body's reach */
    dd.length = fx(1.0);
    assert_int_equal(pg_distance_joint_create(t.w, &dd, &reach), PG_OK);

    EXPECT_REFUSED(t.w, pg_body_set_type(t.w, a, PG_BODY_STATIC), PG_ERR_BODY_TYPE);    /* pinned to a static body */
    EXPECT_REFUSED(t.w, pg_body_set_type(t.w, b, PG_BODY_KINEMATIC), PG_ERR_BODY_TYPE); /* a mouse joint's body */
    EXPECT_REFUSED(t.w, pg_body_set_type(t.w, b, PG_BODY_STATIC), PG_ERR_BODY_TYPE);
    EXPECT_REFUSED(t.w, pg_body_set_type(t.w, slab, PG_BODY_DYNAMIC), PG_ERR_BODY_TYPE); /* its anchor beyond 50 m */
    assert_int_equal(pg_body_type_of(t.w, a), PG_BODY_DYNAMIC);
    assert_int_equal(pg_body_type_of(t.w, slab), PG_BODY_STATIC);

    assert_int_equal(pg_body_set_type(t.w, a, PG_BODY_KINEMATIC), PG_OK); /* a kinematic body may be pinned */
    assert_int_equal(pg_joint_destroy(t.w, pin), PG_OK);
    assert_int_equal(pg_body_set_type(t.w, a, PG_BODY_STATIC), PG_OK);
    assert_int_equal(pg_joint_destroy(t.w, drag), PG_OK);
    assert_int_equal(pg_body_set_type(t.w, b, PG_BODY_STATIC), PG_OK);
    assert_int_equal(pg_joint_destroy(t.w, reach), PG_OK);
    assert_int_equal(pg_body_set_type(t.w, slab, PG_BODY_DYNAMIC), PG_OK);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_input_is_refused_and_changes_nothing),
        cmocka_unit_test(test_defs_round_trip),
        cmocka_unit_test(test_joined_bodies_do_not_collide_unless_asked),
        cmocka_unit_test(test_a_sleeping_chain_sleeps_and_wakes_as_one),
        cmocka_unit_test(test_hash_and_snapshot),
        cmocka_unit_test(test_mouse_joint_drags_and_reaction_holds_the_weight),
        cmocka_unit_test(test_rod_reaction_is_the_tension),
        cmocka_unit_test(test_type_change_keeps_the_joint_rules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
