/* app_test_util.h — helpers shared by the tests of ports/app: files, a flat test scene,
 * and replaying a recording with the core's player. */
#ifndef POGON_APP_TEST_UTIL_H
#define POGON_APP_TEST_UTIL_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "pogon_app.h"
#include "pogon/scene_file.h"

/* A ground 40 m wide whose top is at y = 0; no gravity, so added bodies stay put. */
static const char flat_scene[] = "pogon-scene 1\n"
                                 "gravity 0 0\n"
                                 "wall 40 1 position 0 -0.5\n";

static inline pg_fix fx(double v) { return (pg_fix)(v * 65536.0 + (v < 0 ? -0.5 : 0.5)); }
static inline pg_vec2 at(double x, double y) { return pg_v2(fx(x), fx(y)); }
static inline double dbl(pg_fix v) { return (double)v / 65536.0; }

static inline uint8_t *read_whole(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    uint8_t *data;
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    data = (uint8_t *)malloc((size_t)n + 1);
    assert_non_null(data);
    assert_int_equal(fread(data, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    data[n] = 0;
    *size = (size_t)n;
    return data;
}

static inline pga_app *app_with(const char *name, const char *text)
{
    pga_app *app = pga_create();
    assert_non_null(app);
    assert_int_equal(pga_load_scene(app, name, text, strlen(text)), PG_OK);
    return app;
}

static inline pga_app *app_with_file(const char *name)
{
    char path[512];
    size_t size;
    uint8_t *text;
    pga_app *app = pga_create();
    assert_non_null(app);
    snprintf(path, sizeof path, "%s/%s.scene", POGON_SCENES_DIR, name);
    text = read_whole(path, &size);
    assert_int_equal(pga_load_scene(app, name, (const char *)text, size), PG_OK);
    free(text);
    return app;
}

/* The body under a point, or the zero handle. */
static inline pg_body_id body_at(const pga_app *app, pg_vec2 p)
{
    pg_body_id ids[8], none = {0, 0};
    uint32_t n = 0;
    assert_int_equal(pg_world_query_point(pga_world(app), p, ids, 8, &n), PG_OK);
    return n == 0 ? none : ids[n < 8 ? n - 1 : 7];
}

static inline void frames(pga_app *app, int n)
{
    int i;
    for (i = 0; i < n; ++i) pga_frame(app);
}

/* Replay a file with the core's player: every checkpoint must match. Returns the
 * number of frames played; *final_hash receives the world's hash at the end. */
static inline uint32_t replay_all(const uint8_t *data, size_t size, uint64_t *final_hash)
{
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player player;
    pg_replay_frame_result fr;
    size_t need = 0;
    void *memory;
    uint32_t checked = 1;
    assert_int_equal(pg_replay_read(data, size, &info, &err), PG_OK);
    assert_int_equal(pg_replay_world_memory_size(&info, &need, &err), PG_OK);
    memory = malloc(need);
    assert_non_null(memory);
    assert_int_equal(pg_replay_player_begin(&player, data, &info, memory, need, &fr, &err), PG_OK);
    assert_true(fr.match);
    while (!pg_replay_player_done(&player)) {
        assert_int_equal(pg_replay_player_step(&player, &fr), PG_OK);
        assert_int_equal(fr.command_failures, 0);
        if (fr.checkpoint) {
            assert_true(fr.match);
            checked++;
        }
    }
    assert_int_equal(checked, info.checkpoint_count);
    *final_hash = pg_world_hash(player.world);
    assert_true(*final_hash == info.final_hash);
    free(memory);
    return player.frame;
}

#endif
