/* test_joint_commands.c — the joint commands (include/pogon/replay.h, docs/formats.md):
 * each round-trips through its binary encoding to the same byte image and has the
 * documented length; applying one does what the call it stands for does (same result,
 * same joint handle, same state hash); a failing one changes nothing; a replay file of
 * format version 1 is refused with a message that names `pogon-replay upgrade`.
 */
#include "pg_test.h"

#include <stdlib.h>
#include <string.h>

#include "pg_test_world.h"
#include "pogon/joint.h"
#include "pogon/replay.h"
#include "pogon/replay_file.h"

/* A ground (slot 0) and three dynamic boxes (slots 1..3). */
static test_world joint_world(void)
{
    pg_world_def d = pg_default_world_def();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    test_world t;
    int i;
    d.max_bodies = 8;
    d.max_shapes = 8;
    d.max_joints = 4;
    t = make_world_def(&d);
    assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(20), fx(1), &id), PG_OK);
    for (i = 0; i < 3; ++i) {
        bd = dynamic_at(-2.0 + 2.0 * i, 3);
        assert_int_equal(pg_make_box(t.w, &bd, &sd, fx(1), fx(1), &id), PG_OK);
    }
    return t;
}

static pg_body_id slot(uint32_t i)
{
    pg_body_id id;
    id.index = i;
    id.generation = 1;
    return id;
}

/* A command of kind k with every field it uses away from its default. */
static pg_command full(pg_command_kind k)
{
    pg_command c = pg_command_init(k);
    pg_command_joint_def *j = &c.joint_def;
    switch (k) {
    case PG_CMD_CREATE_DISTANCE_JOINT:
        j->distance.body_a = slot(0), j->distance.body_b = slot(1);
        j->distance.local_anchor_a = pg_v2(fx(-2), fx(6)), j->distance.local_anchor_b = pg_v2(fx(0.25), fx(0.5));
        j->distance.length = fx(2.5), j->distance.enable_spring = 1, j->distance.hertz = fx(3), j->distance.damping_ratio = fx(0.5);
        j->distance.enable_limit = 1, j->distance.min_length = fx(1), j->distance.max_length = fx(4);
        j->distance.collide_connected = 1, j->distance.user_data = 0x0102030405060708u;
        break;
    case PG_CMD_CREATE_REVOLUTE_JOINT:
        j->revolute.body_a = slot(1), j->revolute.body_b = slot(2);
        j->revolute.local_anchor_a = pg_v2(fx(1), 0), j->revolute.local_anchor_b = pg_v2(fx(-1), 0);
        j->revolute.reference_angle = 0x10000000u, j->revolute.enable_limit = 1, j->revolute.lower_angle = fx(-0.5);
        j->revolute.upper_angle = fx(0.5), j->revolute.enable_motor = 1, j->revolute.motor_speed = fx(2);
        j->revolute.max_motor_torque = fx(40), j->revolute.collide_connected = 1, j->revolute.user_data = 7;
        break;
    case PG_CMD_CREATE_WELD_JOINT:
        j->weld.body_a = slot(2), j->weld.body_b = slot(3);
        j->weld.local_anchor_a = pg_v2(fx(1), fx(0.5)), j->weld.local_anchor_b = pg_v2(fx(-1), fx(0.5));
        j->weld.reference_angle = 0x00100000u, j->weld.linear_hertz = fx(5), j->weld.linear_damping_ratio = fx(0.7);
        j->weld.angular_hertz = fx(6), j->weld.angular_damping_ratio = fx(0.8), j->weld.collide_connected = 1, j->weld.user_data = 8;
        break;
    case PG_CMD_CREATE_PRISMATIC_JOINT:
        j->prismatic.body_a = slot(0), j->prismatic.body_b = slot(3);
        j->prismatic.local_anchor_a = pg_v2(fx(2), fx(4)), j->prismatic.local_anchor_b = pg_v2(0, fx(0.25));
        j->prismatic.local_axis_a = pg_v2(0, fx(2)), j->prismatic.reference_angle = 5;
        j->prismatic.enable_limit = 1, j->prismatic.lower_translation = fx(-1), j->prismatic.upper_translation = fx(1.5);
        j->prismatic.enable_motor = 1, j->prismatic.motor_speed = fx(-0.5), j->prismatic.max_motor_force = fx(60);
        j->prismatic.collide_connected = 1, j->prismatic.user_data = 9;
        break;
    case PG_CMD_CREATE_MOUSE_JOINT:
        j->mouse.body = slot(2), j->mouse.target = pg_v2(fx(0.25), fx(3.25));
        j->mouse.hertz = fx(4), j->mouse.damping_ratio = fx(0.9), j->mouse.max_force = fx(300), j->mouse.user_data = 10;
        break;
    default:
        c.joint.index = 0;
        c.joint.generation = 1;
        c.flag = 1;
        c.scalar = fx(-1.5);
        c.scalar2 = fx(2.5);
        c.vec = pg_v2(fx(1.25), fx(4));
        if (k == PG_CMD_DESTROY_JOINT) c.flag = 0, c.scalar = c.scalar2 = 0, c.vec = pg_v2_zero();
        if (k == PG_CMD_SET_MOUSE_TARGET) c.flag = 0, c.scalar = c.scalar2 = 0;
        if (k == PG_CMD_SET_MOUSE_MAX_FORCE) c.flag = 0, c.scalar = fx(80), c.scalar2 = 0, c.vec = pg_v2_zero();
        if (k == PG_CMD_SET_JOINT_MOTOR || k == PG_CMD_SET_JOINT_LIMITS) c.vec = pg_v2_zero();
        break;
    }
    return c;
}

/* docs/formats.md's table: u8 kind, then the fields */
static size_t documented_length(pg_command_kind k)
{
    switch (k) {
    case PG_CMD_CREATE_DISTANCE_JOINT: return 1 + 16 + 16 + 4 + 1 + 8 + 1 + 8 + 1 + 8;
    case PG_CMD_CREATE_REVOLUTE_JOINT: return 1 + 16 + 16 + 4 + 1 + 8 + 1 + 8 + 1 + 8;
    case PG_CMD_CREATE_WELD_JOINT: return 1 + 16 + 16 + 4 + 16 + 1 + 8;
    case PG_CMD_CREATE_PRISMATIC_JOINT: return 1 + 16 + 16 + 8 + 4 + 1 + 8 + 1 + 8 + 1 + 8;
    case PG_CMD_CREATE_MOUSE_JOINT: return 1 + 8 + 8 + 12 + 8;
    case PG_CMD_DESTROY_JOINT: return 1 + 8;
    case PG_CMD_SET_JOINT_MOTOR:
    case PG_CMD_SET_JOINT_LIMITS: return 1 + 8 + 1 + 4 + 4;
    case PG_CMD_SET_MOUSE_TARGET: return 1 + 8 + 8;
    default: return 1 + 8 + 4; /* SET_MOUSE_MAX_FORCE */
    }
}

static void round_trip(void **state)
{
    int k;
    (void)state;
    for (k = PG_CMD_CREATE_DISTANCE_JOINT; k < PG_CMD_KIND_COUNT; ++k) {
        pg_command c = full((pg_command_kind)k), back;
        uint8_t buf[PG_COMMAND_ENCODED_MAX], again[PG_COMMAND_ENCODED_MAX];
        size_t n = pg_command_encode(&c, buf, sizeof buf), used = 0, i;
        if (n != documented_length((pg_command_kind)k)) fail_msg("%s: %u bytes, documented %u", pg_command_kind_name(c.kind), (unsigned)n, (unsigned)documented_length((pg_command_kind)k));
        assert_int_equal(buf[0], k);
        memset(&back, 0x5C, sizeof back);
        assert_int_equal(pg_command_decode(buf, n, &back, &used, NULL, NULL), PG_OK);
        assert_int_equal(used, n);
        if (memcmp(&back, &c, sizeof c) != 0) fail_msg("%s: the decoded command differs in its byte image", pg_command_kind_name(c.kind));
        assert_int_equal(pg_command_encode(&back, again, sizeof again), n);
        assert_memory_equal(buf, again, n);
        for (i = 0; i < n; ++i) { /* every prefix is refused, none crashes */
            size_t off = 99;
            const char *field = NULL;
            assert_int_equal(pg_command_decode(buf, i, &back, &used, &off, &field), PG_ERR_INVALID_ARGUMENT);
            assert_true(off <= i);
            assert_non_null(field);
        }
    }
    {   /* a flag byte other than 0 or 1 is refused at its offset */
        pg_command c = full(PG_CMD_SET_JOINT_MOTOR), back;
        uint8_t buf[PG_COMMAND_ENCODED_MAX];
        size_t n = pg_command_encode(&c, buf, sizeof buf), off = 0;
        const char *field = NULL;
        buf[9] = 2;
        assert_int_equal(pg_command_decode(buf, n, &back, NULL, &off, &field), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(off, 9);
        assert_string_equal(field, "command.flag");
    }
}

/* The call each command stands for, on a world like the command's. */
static pg_result direct_call(pg_world *w, const pg_command *c, pg_joint_id *made)
{
    const pg_command_joint_def *j = &c->joint_def;
    switch (c->kind) {
    case PG_CMD_CREATE_DISTANCE_JOINT: { pg_distance_joint_def d = pg_default_distance_joint_def(); d = j->distance; return pg_distance_joint_create(w, &d, made); }
    case PG_CMD_CREATE_REVOLUTE_JOINT: { pg_revolute_joint_def d = j->revolute; return pg_revolute_joint_create(w, &d, made); }
    case PG_CMD_CREATE_WELD_JOINT: { pg_weld_joint_def d = j->weld; return pg_weld_joint_create(w, &d, made); }
    case PG_CMD_CREATE_PRISMATIC_JOINT: { pg_prismatic_joint_def d = j->prismatic; return pg_prismatic_joint_create(w, &d, made); }
    case PG_CMD_CREATE_MOUSE_JOINT: { pg_mouse_joint_def d = j->mouse; return pg_mouse_joint_create(w, &d, made); }
    case PG_CMD_DESTROY_JOINT: return pg_joint_destroy(w, c->joint);
    case PG_CMD_SET_JOINT_MOTOR: return pg_revolute_joint_set_motor(w, c->joint, (int)c->flag, c->scalar, c->scalar2);
    case PG_CMD_SET_JOINT_LIMITS: return pg_revolute_joint_set_limits(w, c->joint, (int)c->flag, c->scalar, c->scalar2);
    case PG_CMD_SET_MOUSE_TARGET: return pg_mouse_joint_set_target(w, c->joint, c->vec);
    default: return pg_mouse_joint_set_max_force(w, c->joint, c->scalar);
    }
}

/* Each command on two equal worlds, against its call; the setters act on joint 0, made
 * beforehand as a revolute joint (motor, limits) or a mouse joint (target, force). */
static void apply_equals_call(void **state)
{
    int k;
    (void)state;
    for (k = PG_CMD_CREATE_DISTANCE_JOINT; k < PG_CMD_KIND_COUNT; ++k) {
        test_world a = joint_world(), b = joint_world();
        pg_command c = full((pg_command_kind)k);
        pg_joint_id ja = {7, 7}, jb = {0, 0};
        pg_result ra, rb;
        int s;
        if (k >= PG_CMD_DESTROY_JOINT) {
            pg_command setup = full(k == PG_CMD_SET_MOUSE_TARGET || k == PG_CMD_SET_MOUSE_MAX_FORCE ? PG_CMD_CREATE_MOUSE_JOINT : PG_CMD_CREATE_REVOLUTE_JOINT);
            assert_int_equal(pg_command_apply(a.w, &setup, NULL), PG_OK);
            assert_int_equal(pg_command_apply(b.w, &setup, NULL), PG_OK);
        }
        ra = pg_command_apply_made(a.w, &c, NULL, &ja);
        rb = direct_call(b.w, &c, &jb);
        if (ra != PG_OK || ra != rb) fail_msg("%s: %s via the command, %s via the call (%s)", pg_command_kind_name(c.kind), pg_result_name(ra), pg_result_name(rb), pg_world_last_error(a.w));
        if (k < PG_CMD_DESTROY_JOINT) {
            assert_true(pg_joint_id_equal(ja, jb));
            assert_true(pg_joint_is_valid(a.w, ja));
        } else {
            assert_int_equal(ja.index, 0);
            assert_int_equal(ja.generation, 0);
        }
        for (s = 0; s < 30; ++s) {
            assert_true(pg_world_hash(a.w) == pg_world_hash(b.w));
            pg_world_step(a.w);
            pg_world_step(b.w);
        }
        free_world(&a);
        free_world(&b);
    }
}

/* A failing joint command changes nothing (the state hash) and says why. */
static void failures_change_nothing(void **state)
{
    test_world t = joint_world();
    pg_command c;
    pg_joint_id pin;
    uint64_t h;
    (void)state;
    c = full(PG_CMD_CREATE_DISTANCE_JOINT);
    assert_int_equal(pg_command_apply_made(t.w, &c, NULL, &pin), PG_OK);
    h = pg_world_hash(t.w);

    c = full(PG_CMD_CREATE_REVOLUTE_JOINT);
    c.joint_def.revolute.body_b = c.joint_def.revolute.body_a; /* one body twice */
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT);
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_CREATE_MOUSE_JOINT);
    c.joint_def.mouse.body = slot(0); /* static */
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_BODY_TYPE);
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_SET_JOINT_MOTOR); /* joint 0 is a distance joint: no motor */
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pg_world_last_error(t.w), "distance joint"));
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_SET_JOINT_LIMITS); /* on a distance joint: lengths, and -1.5 is no length */
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_ENVELOPE);
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_SET_MOUSE_TARGET);
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT);
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_DESTROY_JOINT);
    c.joint.generation = 2; /* stale */
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_STALE_HANDLE);
    assert_true(pg_world_hash(t.w) == h);

    c = full(PG_CMD_SET_JOINT_LIMITS);
    c.scalar = fx(1), c.scalar2 = fx(3);
    assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_OK); /* the distance joint's lengths */
    assert_true(pg_world_hash(t.w) != h);
    free_world(&t);
}

/* A format 2 file (before the joint commands) is refused with a message naming the
 * upgrade, and pg_replay_upgrade gives back the current (format 4) file byte for byte. */
static void old_replay_refused(void **state)
{
    static const char scene[] = "pogon-scene 1\nball 0.5 position 0 2\n";
    test_world t;
    pg_world_def d = pg_default_world_def();
    pg_replay_writer w;
    pg_replay_info info;
    pg_replay_error e;
    uint8_t *buf = malloc(4096), *v2 = malloc(4096), *out = malloc(4096);
    size_t size = 0, need = 0;
    uint64_t hash;
    int i;
    (void)state;
    assert_non_null(buf);
    assert_non_null(v2);
    assert_non_null(out);
    d.max_bodies = d.max_shapes = 1;
    t = make_world_def(&d);
    assert_int_equal(pg_replay_writer_begin(&w, buf, 4096, scene, sizeof scene - 1, 10), PG_OK);
    assert_int_equal(pg_replay_writer_add_checkpoint_world(&w, t.w), PG_OK);
    assert_int_equal(pg_replay_writer_finish(&w, pg_world_hash(t.w), &size), PG_OK);
    assert_int_equal(buf[8], 4);
    memcpy(v2, buf, size);
    v2[8] = 2; /* version 2, with the header hash and checksum it would have had */
    hash = pg_hash_bytes(PG_HASH_SEED, v2, 36);
    for (i = 0; i < 8; ++i) v2[36 + i] = (uint8_t)(hash >> (8 * i));
    hash = pg_hash_bytes(PG_HASH_SEED, v2, size - 8);
    for (i = 0; i < 8; ++i) v2[size - 8 + (size_t)i] = (uint8_t)(hash >> (8 * i));
    assert_int_equal(pg_replay_read(v2, size, &info, &e), PG_ERR_INCOMPATIBLE);
    assert_int_equal(e.offset, 8);
    assert_non_null(strstr(e.message, "format version 2 is older than this build's 4"));
    assert_non_null(strstr(e.message, "pogon-replay upgrade"));
    assert_int_equal(pg_replay_upgrade(v2, size, pg_numeric_config(), out, 4096, &need, &e), PG_OK);
    assert_int_equal(need, size);
    assert_memory_equal(out, buf, size);
    v2[size / 2] ^= 1; /* a damaged format 2 file is not sealed into a format 4 one */
    assert_int_equal(pg_replay_upgrade(v2, size, pg_numeric_config(), out, 4096, &need, &e), PG_ERR_INVALID_ARGUMENT);
    free(buf);
    free(v2);
    free(out);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_trip),
        cmocka_unit_test(apply_equals_call),
        cmocka_unit_test(failures_change_nothing),
        cmocka_unit_test(old_replay_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
