/* test_app_replay.c — the recording reproduces the session, playback of a corpus replay,
 * damaged files, bad arguments, and the picker's scene files. */
#include "app_test_util.h"
#include "app_session.h"

static void test_recording_verifies(void **state)
{
    pga_app *app = app_with_file("demo");
    const uint8_t *rec;
    size_t size;
    uint8_t *copy;
    uint64_t hash = 0;
    uint32_t played;
    (void)state;
    app_session_run(app);
    assert_int_equal(pga_joint_count(app), 2); /* the rod and the spring; the pin was deleted, the drag let go */
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    played = replay_all(copy, size, &hash);
    assert_true(played == pga_frame_number(app));
    assert_true(hash == pga_state_hash(app));
    free(copy);
    /* recording goes on: a later copy holds more frames and verifies too */
    pga_set_paused(app, 1);
    pga_set_tool(app, PGA_TOOL_BALL);
    pga_pointer_down(app, at(12, 12));
    pga_frame(app); /* applied while paused, not yet logged */
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    assert_true(replay_all(copy, size, &hash) == played);
    free(copy);
    pga_step_once(app);
    pga_frame(app);
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    assert_true(replay_all(copy, size, &hash) == played + 1);
    assert_true(hash == pga_state_hash(app));
    free(copy);
    pga_destroy(app);
}

/* The app plays its own recording back and every checkpoint matches. */
static void test_playback_of_own_recording(void **state)
{
    pga_app *app = app_with_file("demo");
    const uint8_t *rec;
    size_t size;
    uint8_t *copy;
    pga_playback pb;
    uint64_t live_hash;
    (void)state;
    app_session_run(app);
    live_hash = pga_state_hash(app);
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    pga_set_paused(app, 0);
    assert_int_equal(pga_play_replay(app, copy, size), PG_OK);
    free(copy); /* the app keeps its own copy */
    while (pga_frame(app)) {
    }
    pb = pga_playback_state(app);
    assert_int_equal(pb.active, 1);
    assert_int_equal(pb.frame, pb.frame_count);
    assert_int_equal(pb.checkpoints_failed, 0);
    assert_int_equal(pb.checkpoints_checked, pb.frame_count / 60 + 1);
    assert_true(pga_state_hash(app) == live_hash);
    pga_destroy(app);
}

static void test_playback_of_corpus_replay(void **state)
{
    pga_app *app;
    size_t size;
    uint8_t *data;
    pg_replay_info info;
    pga_playback pb;
    uint32_t bodies;
    (void)state;
    app = app_with_file("demo");
    data = read_whole(POGON_REPLAYS_DIR "/demo.pgr", &size);
#if PG_TRIG_TABLE_BITS != 12
    /* the corpus was recorded with the 12-bit sine table, which the file records: a build
     * with another table refuses it, saying so, and keeps its live world */
    {
        uint32_t live = pga_body_count(app);
        assert_int_equal(pga_play_replay(app, data, size), PG_ERR_INCOMPATIBLE);
        assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_ERROR);
        if (strstr(pga_message(app), "recorded with a 12-bit sine table; this build has") == NULL)
            fail_msg("message: %s", pga_message(app));
        assert_int_equal(pga_playback_state(app).active, 0);
        assert_int_equal(pga_body_count(app), live);
        free(data);
        pga_destroy(app);
        return;
    }
#endif
    assert_int_equal(pg_replay_read(data, size, &info, NULL), PG_OK);
    assert_int_equal(pga_play_replay(app, data, size), PG_OK);
    pb = pga_playback_state(app);
    assert_int_equal(pb.active, 1);
    assert_int_equal(pb.frame, 0);
    assert_int_equal(pb.frame_count, info.frame_count);
    assert_int_equal(pb.last_match, 1); /* checkpoint 0 */
    /* pause and single step */
    pga_set_paused(app, 1);
    assert_int_equal(pga_frame(app), 0);
    pga_step_once(app);
    assert_int_equal(pga_frame(app), 1);
    assert_int_equal(pga_playback_state(app).frame, 1);
    assert_int_equal(pga_frame(app), 0);
    /* world changes are refused during playback */
    pga_set_tool(app, PGA_TOOL_BALL);
    pga_pointer_down(app, at(0, 10));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    pga_set_paused(app, 0);
    while (pga_frame(app)) {
    }
    pb = pga_playback_state(app);
    assert_int_equal(pb.frame, info.frame_count);
    assert_int_equal(pb.checkpoints_checked, info.checkpoint_count);
    assert_int_equal(pb.checkpoints_failed, 0);
    assert_true(pga_state_hash(app) == info.final_hash);
    /* stop: live from here, with the same bodies and a new recording */
    bodies = pga_body_count(app);
    assert_int_equal(pga_stop_playback(app), PG_OK);
    assert_int_equal(pga_playback_state(app).active, 0);
    assert_int_equal(pga_body_count(app), bodies);
    pga_pointer_down(app, at(0, 15));
    pga_frame(app);
    assert_int_equal(pga_body_count(app), bodies + 1);
    free(data);
    pga_destroy(app);
}

static void assert_refused_and_working(pga_app *app, const uint8_t *data, size_t size)
{
    uint64_t hash = pga_state_hash(app);
    uint32_t bodies = pga_body_count(app);
    assert_int_equal(pga_play_replay(app, data, size), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_ERROR);
    assert_non_null(strstr(pga_message(app), "offset "));
    assert_non_null(strstr(pga_message(app), "field "));
    assert_int_equal(pga_playback_state(app).active, 0);
    assert_true(pga_state_hash(app) == hash);
    assert_int_equal(pga_body_count(app), bodies);
    assert_int_equal(pga_frame(app), 1); /* still live */
}

static void test_corrupt_and_truncated_files(void **state)
{
    pga_app *app = app_with_file("demo");
    size_t size;
    uint8_t *data = read_whole(POGON_REPLAYS_DIR "/demo.pgr", &size);
    char expect[64];
    (void)state;
    frames(app, 5);
    data[size / 2] ^= 0x10; /* a flipped bit in a frame record */
    assert_refused_and_working(app, data, size);
    data[size / 2] ^= 0x10;
    assert_refused_and_working(app, data, size - 7); /* truncated */
    snprintf(expect, sizeof expect, "offset %d, header field magic", 7); /* the byte that differs */
    assert_refused_and_working(app, data, 3); /* not even a header */
    assert_non_null(strstr(pga_message(app), "header"));
    memcpy(data, "PGREPLAX", 8);
    assert_refused_and_working(app, data, size);
    assert_non_null(strstr(pga_message(app), expect));
    free(data);
    pga_destroy(app);
}

static void test_bad_arguments(void **state)
{
    pga_app *app = app_with_file("demo");
    pga_params p = pga_get_params(app), bad;
    uint64_t hash = pga_state_hash(app);
    pg_body_id stale = {200, 7};
    const uint8_t *rec;
    size_t size;
    uint32_t n;
    (void)state;
    /* NULL app: errors or nothing, never a crash */
    assert_int_equal(pga_load_scene(NULL, "x", flat_scene, sizeof flat_scene - 1), PG_ERR_NULL);
    assert_int_equal(pga_set_tool(NULL, PGA_TOOL_BOX), PG_ERR_NULL);
    assert_int_equal(pga_set_params(NULL, &p), PG_ERR_NULL);
    assert_int_equal(pga_toggle_gravity(NULL), PG_ERR_NULL);
    assert_int_equal(pga_recording(NULL, &rec, &size), PG_ERR_NULL);
    assert_int_equal(pga_play_replay(NULL, rec, 0), PG_ERR_NULL);
    assert_int_equal(pga_frame(NULL), 0);
    assert_null(pga_draw_list(NULL, &n));
    assert_int_equal(n, 0);
    pga_pointer_down(NULL, at(0, 0));
    pga_key(NULL, PGA_KEY_LEFT, 1);
    pga_destroy(NULL);
    /* NULL pointers given to an app */
    assert_int_equal(pga_set_params(app, NULL), PG_ERR_NULL);
    assert_int_equal(pga_load_scene(app, "x", NULL, 5), PG_ERR_NULL);
    assert_int_equal(pga_recording(app, NULL, &size), PG_ERR_NULL);
    assert_int_equal(pga_play_replay(app, NULL, 10), PG_ERR_NULL);
    /* parameters outside the envelope: refused, unchanged */
    bad = p;
    bad.radius = fx(0.01);
    assert_int_equal(pga_set_params(app, &bad), PG_ERR_ENVELOPE);
    assert_non_null(strstr(pga_message(app), "radius"));
    bad = p;
    bad.density = fx(200);
    assert_int_equal(pga_set_params(app, &bad), PG_ERR_ENVELOPE);
    bad = p;
    bad.restitution = fx(1.5);
    assert_int_equal(pga_set_params(app, &bad), PG_ERR_ENVELOPE);
    bad = p;
    bad.width = PG_FIX_C(101);
    assert_int_equal(pga_set_params(app, &bad), PG_ERR_ENVELOPE);
    bad = p;
    bad.color = 0x1000000u;
    assert_int_equal(pga_set_params(app, &bad), PG_ERR_ENVELOPE);
    assert_memory_equal(&p, &bad, offsetof(pga_params, color)); /* the sizes are as before */
    assert_true(pga_get_params(app).radius == p.radius && pga_get_params(app).density == p.density);
    /* other bad values */
    assert_int_equal(pga_set_tool(app, PGA_TOOL_COUNT), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pga_get_tool(app), PGA_TOOL_MOVE);
    assert_int_equal(pga_set_effects(app, 0x80), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pga_select(app, stale), PG_ERR_STALE_HANDLE);
    assert_int_equal(pga_set_selected_material(app, fx(0.01), 0, 0), PG_ERR_ENVELOPE);
    pga_key(app, PGA_KEY_COUNT, 1);
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    pga_set_tool(app, PGA_TOOL_BOX);
    pga_pointer_down(app, at(5000, 0)); /* beyond the world */
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    /* a broken scene: the reader's line and column, the old world stays */
    assert_int_equal(pga_load_scene(app, "broken", "pogon-scene 1\nbox 1 x\n", 22), PG_ERR_INVALID_ARGUMENT);
    assert_non_null(strstr(pga_message(app), "line 2"));
    assert_string_equal(pga_scene_name(app), "demo");
    /* capacities that would need gigabytes: refused with a message, not an allocation */
    assert_int_equal(pga_load_scene(app, "huge", "pogon-scene 1\nmax_bodies 16000000\nmax_shapes 16000000\n", 54),
                     PG_ERR_CAPACITY);
    assert_non_null(strstr(pga_message(app), "MiB"));
    assert_string_equal(pga_scene_name(app), "demo");
    assert_true(pga_state_hash(app) == hash);
    assert_int_equal(pga_frame(app), 1);
    pga_destroy(app);
}

/* The picker's scenes load with the core's reader and step. */
static void test_scene_files_load(void **state)
{
    static const char *const names[] = {"demo", "pile", "dominoes", "pyramid", "stack", "shapes", "pendulum", "double_pendulum", "newtons_cradle", "chain40", "bridge", "car", "ragdoll", "soft_blob_bowl"};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
        char path[512];
        size_t size, need;
        uint8_t *text;
        pg_world_def def;
        pg_scene_error err;
        pg_world *w;
        void *memory;
        pga_app *app;
        snprintf(path, sizeof path, "%s/%s.scene", POGON_SCENES_DIR, names[i]);
        text = read_whole(path, &size);
        assert_int_equal(pg_scene_read_def((const char *)text, size, &def, &err), PG_OK);
        need = pg_world_memory_size(&def);
        memory = malloc(need);
        assert_int_equal(pg_world_create(&def, memory, need, &w), PG_OK);
        assert_int_equal(pg_scene_load(w, (const char *)text, size, &err), PG_OK);
        free(memory);
        app = pga_create();
        assert_int_equal(pga_load_scene(app, names[i], (const char *)text, size), PG_OK);
        frames(app, 10);
        assert_true(pga_frame_number(app) == 10);
        pga_destroy(app);
        free(text);
    }
}

/* A reproducible pseudo-random stream for the random sessions. */
static uint32_t next_random(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8;
}

/* Random input of every kind for many frames: whatever happens, the recording replays with
 * every checkpoint and the final hash matching (since the last restart by a preset). */
static void test_random_sessions_replay(void **state)
{
    uint32_t seed;
    (void)state;
    for (seed = 1; seed <= 4; ++seed) {
        pga_app *app = app_with_file(seed % 2 ? "demo" : "pile");
        uint32_t r = seed * 7919u, f, since_restart = 0;
        const uint8_t *rec;
        size_t size;
        uint8_t *copy;
        uint64_t hash;
        for (f = 0; f < 900; ++f) {
            uint32_t what = next_random(&r) % 40;
            pg_vec2 p = pg_v2((pg_fix)(next_random(&r) % (38u << 16)) - PG_FIX_C(19),
                              (pg_fix)(next_random(&r) % (18u << 16)));
            pga_params params = pga_default_params();
            switch (what) {
            case 0: pga_set_tool(app, (pga_tool)(next_random(&r) % PGA_TOOL_COUNT)); break;
            case 1: case 2: case 3: pga_pointer_down(app, p); break;
            case 4: pga_pointer_move(app, p); break;
            case 5: pga_pointer_up(app, p); break;
            case 6: case 7: pga_key(app, (pga_key_code)(next_random(&r) % PGA_KEY_COUNT), (int)(next_random(&r) % 2)); break;
            case 8: pga_toggle_gravity(app); break;
            case 9: pga_set_effects(app, next_random(&r) & PG_EFFECTS_ALL); break;
            case 10: pga_set_paused(app, 1); break;
            case 11: pga_step_once(app); break;
            case 12:
                params.radius = PG_FIX_ONE / 8 + (pg_fix)(next_random(&r) % PG_FIX_ONE);
                params.width = PG_FIX_ONE / 4 + (pg_fix)(next_random(&r) % (2u << 16));
                params.height = PG_FIX_ONE / 4 + (pg_fix)(next_random(&r) % (2u << 16));
                params.density = PG_FIX_ONE / 2 + (pg_fix)(next_random(&r) % (5u << 16));
                params.restitution = (pg_fix)(next_random(&r) % PG_FIX_ONE);
                params.color = next_random(&r) & 0xffffffu;
                params.nudge = (int)(next_random(&r) % 2);
                assert_int_equal(pga_set_params(app, &params), PG_OK);
                break;
            case 13: pga_set_selected_material(app, PG_FIX_C(2), PG_FIX_ONE / 3, PG_FIX_ONE / 5); break;
            case 14: pga_set_selected_color(app, next_random(&r) & 0xffffffu); break;
            default: break;
            }
            if (pga_paused(app) && next_random(&r) % 8 == 0) pga_set_paused(app, 0);
            if (f == 300 && seed > 2) { /* a preset restarts the world and the recording */
                assert_int_equal(pga_set_preset(app, (pga_preset)(seed % PGA_PRESET_COUNT)), PG_OK);
                since_restart = 0;
            }
            since_restart += (uint32_t)pga_frame(app);
        }
        pga_set_paused(app, 0); /* one more step logs what waits while paused */
        since_restart += (uint32_t)pga_frame(app);
        assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
        copy = (uint8_t *)malloc(size);
        memcpy(copy, rec, size);
        assert_int_equal(replay_all(copy, size, &hash), since_restart);
        assert_true(hash == pga_state_hash(app));
        if (getenv("POGON_APP_TEST_VERBOSE") != NULL) {
            pg_replay_info info;
            assert_int_equal(pg_replay_read(copy, size, &info, NULL), PG_OK);
            printf("seed %u: %u frames, %llu commands, %u bodies\n", seed, info.frame_count,
                   (unsigned long long)info.command_count, pga_body_count(app));
        }
        free(copy);
        pga_destroy(app);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recording_verifies),
        cmocka_unit_test(test_playback_of_own_recording),
        cmocka_unit_test(test_playback_of_corpus_replay),
        cmocka_unit_test(test_corrupt_and_truncated_files),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_scene_files_load),
        cmocka_unit_test(test_random_sessions_replay),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
