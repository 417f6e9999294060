/* test_scene_work.c — the scene and replay readers with a work area from the caller
 * (the `_in` calls of include/pogon/scene_file.h and replay_file.h): every shipped scene
 * loads to the same world as through the plain calls, corpus replays read and play to
 * their end with every checkpoint matching (in a build with another sine table, which
 * refuses the corpus, replays of the same scenes recorded by the test), and a work area that is NULL, one byte short
 * or misaligned is refused with PG_ERR_INVALID_ARGUMENT, a message naming the size, and
 * nothing else written.
 */
#include "pg_test.h"

#include <stdlib.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay_file.h"
#include "pogon/scene_file.h"

#ifndef POGON_SCENES_DIR
#error "POGON_SCENES_DIR must name the scenes/ folder"
#endif
#ifndef POGON_REPLAYS_DIR
#error "POGON_REPLAYS_DIR must name the tests/replays/ folder"
#endif

static const char *const scenes[] = {"bridge.scene",   "car.scene",         "chain40.scene", "demo.scene",
                                     "dominoes.scene", "double_pendulum.scene", "newtons_cradle.scene",
                                     "pendulum.scene", "pile.scene",        "pyramid.scene", "ragdoll.scene",
                                     "shapes.scene",   "soft_blob_bowl.scene", "stack.scene"};
/* a scene without joints, one with joints and a concave bowl, and one with commands every frame */
static const char *const replays[] = {"demo.pgr", "car.pgr", "commands.pgr", "bridge.pgr"};

static pg_world *world_of(const pg_world_def *def, void **memory);

static char *read_in(const char *dir, const char *name, size_t *size)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return pgt_read_file(path, size);
}

/* A replay this build can play. The corpus file itself when this build has its numeric
 * configuration (the 12-bit sine table); another build (the table8 preset) refuses it,
 * so the same scene is recorded here instead, 180 frames with the gravity changed every
 * 30 frames, so that the calls under test still read and play a file with commands. */
static uint8_t *replay_for_this_build(const char *name, size_t *size)
{
    static const char *const scene_of[][2] = {
        {"demo.pgr", "demo.scene"}, {"car.pgr", "car.scene"}, {"commands.pgr", "demo.scene"}, {"bridge.pgr", "bridge.scene"}};
    uint8_t *file = (uint8_t *)read_in(POGON_REPLAYS_DIR, name, size);
    pg_replay_info info;
    pg_replay_error err;
    const size_t cap = (size_t)1 << 22;
    uint8_t *out;
    char *text = NULL;
    size_t text_size = 0, k;
    pg_world_def def;
    pg_scene_error serr;
    pg_replay_writer wr;
    pg_world *w;
    void *memory;
    int frame;
    assert_non_null(file);
    if (pg_replay_read(file, *size, &info, &err) != PG_ERR_INCOMPATIBLE) return file;
    free(file);
    for (k = 0; k < sizeof scene_of / sizeof scene_of[0] && text == NULL; ++k)
        if (strcmp(scene_of[k][0], name) == 0) text = read_in(POGON_SCENES_DIR, scene_of[k][1], &text_size);
    assert_non_null(text);
    assert_int_equal(pg_scene_read_def(text, text_size, &def, &serr), PG_OK);
    w = world_of(&def, &memory);
    assert_int_equal(pg_scene_load(w, text, text_size, &serr), PG_OK);
    out = malloc(cap);
    assert_non_null(out);
    assert_int_equal(pg_replay_writer_begin(&wr, out, cap, text, text_size, 30), PG_OK);
    assert_int_equal(pg_replay_writer_add_checkpoint_world(&wr, w), PG_OK);
    for (frame = 0; frame < 180; ++frame) {
        pg_command c = pg_command_init(PG_CMD_SET_GRAVITY);
        uint32_t n = frame % 30 == 10 ? 1u : 0u;
        c.vec = pg_v2(0, frame % 60 == 10 ? -PG_FIX_C(5) : -PG_FIX_C(10));
        assert_int_equal(pg_replay_writer_add_frame(&wr, &c, n), PG_OK);
        if (n > 0) assert_int_equal(pg_command_apply(w, &c, NULL), PG_OK);
        assert_int_equal(pg_world_step(w), PG_OK);
        if (pg_replay_writer_checkpoint_due(&wr)) assert_int_equal(pg_replay_writer_add_checkpoint_world(&wr, w), PG_OK);
    }
    assert_int_equal(pg_replay_writer_finish(&wr, pg_world_hash(w), size), PG_OK);
    free(memory);
    free(text);
    return out;
}

/* A buffer of `bytes` aligned to 8 (malloc's alignment is at least that). */
static void *work_of(size_t bytes)
{
    void *w = malloc(bytes + 16u);
    assert_non_null(w);
    assert_int_equal((uintptr_t)w & 7u, 0);
    return w;
}

static pg_world *world_of(const pg_world_def *def, void **memory)
{
    pg_world *w = NULL;
    size_t need = pg_world_memory_size(def);
    assert_true(need > 0);
    *memory = malloc(need);
    assert_non_null(*memory);
    assert_int_equal(pg_world_create(def, *memory, need, &w), PG_OK);
    return w;
}

/* "... = N bytes ..." with N the size the call needs. */
static void assert_names_size(const char *message, size_t need)
{
    char want[64];
    snprintf(want, sizeof want, "= %lu bytes aligned to 8", (unsigned long)need);
    if (strstr(message, want) == NULL) fail_msg("message '%s' does not name '%s'", message, want);
}

/* ---- sizes -------------------------------------------------------------------------------- */
static void test_work_sizes_within_their_bounds(void **state)
{
    (void)state;
    assert_true(pg_scene_work_size() > 0);
    assert_true(pg_scene_work_size() <= PG_SCENE_WORK_BYTES);
    assert_true(pg_replay_work_size() > pg_scene_work_size());
    assert_true(pg_replay_work_size() <= PG_REPLAY_WORK_BYTES);
}

/* ---- scenes ------------------------------------------------------------------------------- */
static void test_scenes_load_in_as_plain(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; ++i) {
        size_t size = 0, bytes = pg_scene_work_size();
        char *text = read_in(POGON_SCENES_DIR, scenes[i], &size);
        void *work = work_of(bytes), *m1 = NULL, *m2 = NULL;
        pg_world_def def, def_in;
        pg_scene_error err;
        pg_world *w1, *w2;
        assert_non_null(text);
        assert_int_equal(pg_scene_read_def(text, size, &def, &err), PG_OK);
        memset(&def_in, 0xA5, sizeof def_in);
        PG_EXPECT_EQ(pg_scene_read_def_in(text, size, &def_in, &err, work, bytes), PG_OK, "%s: %s", scenes[i], err.message);
        assert_memory_equal(&def, &def_in, sizeof def);
        w1 = world_of(&def, &m1);
        w2 = world_of(&def, &m2);
        assert_int_equal(pg_scene_load(w1, text, size, &err), PG_OK);
        PG_EXPECT_EQ(pg_scene_load_in(w2, text, size, &err, work, bytes), PG_OK, "%s: %s", scenes[i], err.message);
        assert_int_equal(err.line, 0);
        assert_string_equal(err.message, "");
        PG_EXPECT_EQ(pg_world_hash(w2), pg_world_hash(w1), "%s", scenes[i]);
        free(m1);
        free(m2);
        free(work);
        free(text);
    }
}

/* The same error, line, column and message as the plain call, for a text that fails. */
static void test_scene_errors_in_as_plain(void **state)
{
    static const char *const bad[] = {
        "pogon-scene 1\nconcave 0 0 2 0 2 2 1 1 0 2 density -1\n",
        "pogon-scene 1\nconcave 0 0 1 0\n",
        "pogon-scene 1\nbox 1 1 frobnicate 2\n",
        "pogon-scene 1\nchain 0 0 1 0 1 0\n",
        "pogon-scene 1\nbox 1 1 position 0 1\nbody dynamic\n  shape circle 0.5\n",
    };
    size_t i, bytes = pg_scene_work_size();
    void *work = work_of(bytes);
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        pg_world_def def;
        pg_scene_error plain, in;
        pg_result r = pg_scene_read_def(bad[i], strlen(bad[i]), &def, &plain);
        PG_EXPECT_EQ(r != PG_OK, 1, "text %u is accepted", (unsigned)i);
        assert_int_equal(pg_scene_read_def_in(bad[i], strlen(bad[i]), &def, &in, work, bytes), r);
        assert_int_equal(in.line, plain.line);
        assert_int_equal(in.column, plain.column);
        assert_string_equal(in.message, plain.message);
    }
    free(work);
}

static void test_scene_work_refused(void **state)
{
    size_t size = 0, bytes = pg_scene_work_size();
    char *text = read_in(POGON_SCENES_DIR, "shapes.scene", &size);
    unsigned char *work = work_of(bytes + 8u);
    void *memory = NULL;
    pg_world_def def, untouched;
    pg_scene_error err;
    pg_world *w;
    uint64_t before;
    int k;
    (void)state;
    assert_non_null(text);
    assert_int_equal(pg_scene_read_def(text, size, &def, &err), PG_OK);
    w = world_of(&def, &memory);
    before = pg_world_hash(w);
    for (k = 0; k < 3; ++k) { /* one byte short, NULL, misaligned (by 4, with room to spare) */
        void *at = k == 1 ? NULL : k == 2 ? (void *)(work + 4) : (void *)work;
        size_t given = k == 0 ? bytes - 1u : bytes + 4u;
        memset(&untouched, 0x5A, sizeof untouched);
        assert_int_equal(pg_scene_read_def_in(text, size, &untouched, &err, at, given), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(err.line, 0);
        assert_int_equal(err.column, 0);
        assert_names_size(err.message, bytes);
        {
            pg_world_def pattern;
            memset(&pattern, 0x5A, sizeof pattern);
            assert_memory_equal(&untouched, &pattern, sizeof pattern);
        }
        assert_int_equal(pg_scene_load_in(w, text, size, &err, at, given), PG_ERR_INVALID_ARGUMENT);
        assert_names_size(err.message, bytes);
        assert_true(pg_world_hash(w) == before);
        assert_int_equal(pg_world_get_stats(w).body_count, 0);
        /* an error pointer may be NULL there too */
        assert_int_equal(pg_scene_load_in(w, text, size, NULL, at, given), PG_ERR_INVALID_ARGUMENT);
    }
    /* NULL text, def or world stay PG_ERR_NULL, checked first */
    assert_int_equal(pg_scene_read_def_in(NULL, 0, &def, &err, NULL, 0), PG_ERR_NULL);
    assert_int_equal(pg_scene_load_in(NULL, text, size, &err, work, bytes), PG_ERR_NULL);
    /* and the exact size is enough */
    assert_int_equal(pg_scene_load_in(w, text, size, &err, work, bytes), PG_OK);
    assert_true(pg_world_hash(w) != before);
    free(memory);
    free(work);
    free(text);
}

/* ---- replays ------------------------------------------------------------------------------ */
/* Play the file to its end with the plain calls or the `_in` ones; the final hash. */
static uint64_t play(const uint8_t *file, size_t size, int with_work, uint32_t *checkpoints)
{
    size_t bytes = pg_replay_work_size(), mem = 0;
    void *work = work_of(bytes), *memory;
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    uint64_t hash;
    if (with_work) {
        PG_EXPECT_EQ(pg_replay_read_in(file, size, &info, &err, work, bytes), PG_OK, "%s", err.message);
        assert_int_equal(pg_replay_world_memory_size_in(&info, &mem, &err, work, bytes), PG_OK);
    } else {
        assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
        assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    }
    memory = malloc(mem);
    assert_non_null(memory);
    if (with_work)
        assert_int_equal(pg_replay_player_begin_in(&p, file, &info, memory, mem, &fr, &err, work, bytes), PG_OK);
    else
        assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, &fr, &err), PG_OK);
    memset(work, 0xEE, bytes); /* the player keeps nothing in it */
    assert_true(fr.match);
    *checkpoints = 1;
    while (!pg_replay_player_done(&p)) {
        assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
        if (fr.checkpoint) {
            PG_EXPECT_EQ(fr.match, 1, "checkpoint %u", (unsigned)fr.checkpoint_index);
            assert_int_equal(fr.section_mismatch, 0);
            ++*checkpoints;
        }
    }
    assert_int_equal(*checkpoints, info.checkpoint_count);
    hash = pg_world_hash(p.world);
    assert_true(hash == info.final_hash);
    free(memory);
    free(work);
    return hash;
}

static void test_replays_play_in_as_plain(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof replays / sizeof replays[0]; ++i) {
        size_t size = 0;
        uint8_t *file = replay_for_this_build(replays[i], &size);
        uint32_t plain_checkpoints = 0, in_checkpoints = 0;
        assert_non_null(file);
        PG_EXPECT_EQ(play(file, size, 1, &in_checkpoints), play(file, size, 0, &plain_checkpoints), "%s", replays[i]);
        assert_int_equal(in_checkpoints, plain_checkpoints);
        free(file);
    }
}

static void test_replay_info_and_upgrade_in_as_plain(void **state)
{
    size_t size = 0, bytes = pg_replay_work_size(), n_plain = 0, n_in = 0;
    uint8_t *file = replay_for_this_build("car.pgr", &size);
    void *work = work_of(bytes);
    uint8_t *out_plain, *out_in;
    pg_replay_info plain, in;
    pg_replay_error err;
    (void)state;
    assert_non_null(file);
    memset(&plain, 0, sizeof plain);
    memset(&in, 0xFF, sizeof in);
    assert_int_equal(pg_replay_read(file, size, &plain, &err), PG_OK);
    assert_int_equal(pg_replay_read_in(file, size, &in, &err, work, bytes), PG_OK);
    assert_memory_equal(&plain, &in, sizeof plain);
    out_plain = malloc(size);
    out_in = malloc(size);
    assert_non_null(out_plain);
    assert_non_null(out_in);
    assert_int_equal(pg_replay_upgrade(file, size, pg_numeric_config(), out_plain, size, &n_plain, &err), PG_OK);
    assert_int_equal(pg_replay_upgrade_in(file, size, pg_numeric_config(), out_in, size, &n_in, &err, work, bytes), PG_OK);
    assert_int_equal(n_in, n_plain);
    assert_memory_equal(out_in, out_plain, n_plain);
    /* a damaged scene text (its hash no longer matches): the same error at the same offset */
    {
        pg_replay_error e_plain, e_in;
        uint8_t *bad = malloc(size);
        assert_non_null(bad);
        memcpy(bad, file, size);
        bad[plain.scene_offset + 2] ^= 0x20;
        assert_int_equal(pg_replay_read(bad, size, &plain, &e_plain), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(pg_replay_read_in(bad, size, &in, &e_in, work, bytes), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(e_in.offset, e_plain.offset);
        assert_string_equal(e_in.field, e_plain.field);
        assert_string_equal(e_in.message, e_plain.message);
        free(bad);
    }
    free(out_plain);
    free(out_in);
    free(work);
    free(file);
}

static void test_replay_work_refused(void **state)
{
    size_t size = 0, bytes = pg_replay_work_size(), mem = 0;
    uint8_t *file = replay_for_this_build("demo.pgr", &size);
    unsigned char *work = work_of(bytes + 8u);
    uint8_t *out;
    pg_replay_info info, pattern;
    pg_replay_error err;
    pg_replay_player p, p_pattern;
    int k;
    (void)state;
    assert_non_null(file);
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    out = malloc(size > mem ? size : mem);
    assert_non_null(out);
    memset(&pattern, 0x5A, sizeof pattern);
    for (k = 0; k < 3; ++k) { /* one byte short, NULL, misaligned */
        void *at = k == 1 ? NULL : k == 2 ? (void *)(work + 4) : (void *)work;
        size_t given = k == 0 ? bytes - 1u : bytes + 4u, n = 12345u, got = 777u;
        pg_replay_info untouched = pattern;
        assert_int_equal(pg_replay_read_in(file, size, &untouched, &err, at, given), PG_ERR_INVALID_ARGUMENT);
        assert_memory_equal(&untouched, &pattern, sizeof pattern);
        assert_string_equal(err.region, "work");
        assert_string_equal(err.field, "work_size");
        assert_names_size(err.message, bytes);
        assert_int_equal(pg_replay_world_memory_size_in(&info, &got, &err, at, given), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(got, 777u);
        assert_names_size(err.message, bytes);
        memset(&p, 0x33, sizeof p);
        memset(&p_pattern, 0x33, sizeof p_pattern);
        assert_int_equal(pg_replay_player_begin_in(&p, file, &info, out, mem, NULL, &err, at, given), PG_ERR_INVALID_ARGUMENT);
        assert_memory_equal(&p, &p_pattern, sizeof p);
        assert_names_size(err.message, bytes);
        assert_int_equal(pg_replay_upgrade_in(file, size, pg_numeric_config(), out, size, &n, &err, at, given),
                         PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(n, 12345u);
        assert_names_size(err.message, bytes);
        assert_int_equal(pg_replay_read_in(file, size, &untouched, NULL, at, given), PG_ERR_INVALID_ARGUMENT);
    }
    free(out);
    free(work);
    free(file);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_work_sizes_within_their_bounds),
        cmocka_unit_test(test_scenes_load_in_as_plain),
        cmocka_unit_test(test_scene_errors_in_as_plain),
        cmocka_unit_test(test_scene_work_refused),
        cmocka_unit_test(test_replays_play_in_as_plain),
        cmocka_unit_test(test_replay_info_and_upgrade_in_as_plain),
        cmocka_unit_test(test_replay_work_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
