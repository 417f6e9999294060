/* test_app_control.c — the player and keys, gravity, pause and single step, the drag,
 * accuracy presets. */
#include "app_test_util.h"

/* The demo selects its kinematic player (user_data 1); keys set its velocity. */
static void test_demo_player_keys(void **state)
{
    pga_app *app = app_with_file("demo");
    const pg_world *w = pga_world(app);
    pg_body_id player = pga_selected(app);
    pg_vec2 p0, p1;
    (void)state;
    assert_true(pg_body_is_valid(w, player));
    assert_true((pg_body_user_data(w, player) & 0xffffffffu) == 1u);
    assert_int_equal(pg_body_type_of(w, player), PG_BODY_KINEMATIC);
    p0 = pg_body_position(w, player);
    pga_key(app, PGA_KEY_LEFT, 1);
    frames(app, 30);
    p1 = pg_body_position(w, player);
    assert_int_equal(pg_body_linear_velocity(w, player).x, PG_FIX_C(-6));
    assert_true(p1.x < p0.x - PG_FIX_C(2)); /* 6 m/s for half a second: about 3 m */
    assert_int_equal(p1.y, p0.y);
    pga_key(app, PGA_KEY_LEFT, 0);
    pga_frame(app);
    assert_int_equal(pg_body_linear_velocity(w, player).x, 0); /* released: it stops */
    p0 = pg_body_position(w, player);
    frames(app, 10);
    assert_true(pg_v2_equal(pg_body_position(w, player), p0));
    /* selecting another body while the player moves: the player stops */
    frames(app, 60);
    pga_key(app, PGA_KEY_UP, 1);
    frames(app, 5);
    assert_int_equal(pg_body_linear_velocity(w, player).y, PG_FIX_C(6));
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(-10, 0.5)); /* the demo's ball, resting on the ground */
    pga_pointer_up(app, at(-10, 0.5));
    assert_false(pg_body_id_equal(pga_selected(app), player));
    assert_true(pg_body_is_valid(w, pga_selected(app)));
    pga_frame(app);
    assert_true(pg_v2_equal(pg_body_linear_velocity(w, player), pg_v2_zero()));
    pga_key(app, PGA_KEY_UP, 0);
    pga_destroy(app);
}

/* Selecting a dynamic box with the move tool; keys push it with forces. */
static void test_select_and_push_dynamic(void **state)
{
    pga_app *app = app_with("flat", "pogon-scene 1\nwall 40 1 position 0 -0.5\nbox 1 1 position 0 0.5\n");
    const pg_world *w = pga_world(app);
    pg_body_id box;
    pg_vec2 p0, p1;
    (void)state;
    frames(app, 30); /* settle */
    assert_int_equal(pga_set_tool(app, PGA_TOOL_MOVE), PG_OK);
    pga_pointer_down(app, at(0, 0.5));
    pga_pointer_up(app, at(0, 0.5));
    box = pga_selected(app);
    assert_true(pg_body_is_valid(w, box));
    assert_int_equal(pg_body_type_of(w, box), PG_BODY_DYNAMIC);
    p0 = pg_body_position(w, box);
    pga_key(app, PGA_KEY_RIGHT, 1);
    frames(app, 60);
    pga_key(app, PGA_KEY_RIGHT, 0);
    p1 = pg_body_position(w, box);
    assert_true(p1.x > p0.x + PG_FIX_C(1)); /* it moved right */
    assert_true(pg_body_linear_velocity(w, box).x > PG_FIX_C(2));
    assert_true(pg_body_linear_velocity(w, box).x <= PG_FIX_C(7));
    /* up lifts it against gravity */
    p0 = pg_body_position(w, box);
    pga_key(app, PGA_KEY_UP, 1);
    frames(app, 20);
    pga_key(app, PGA_KEY_UP, 0);
    assert_true(pg_body_position(w, box).y > p0.y + PG_FIX_ONE / 2);
    /* Q spins it counter-clockwise */
    pga_key(app, PGA_KEY_SPIN_CCW, 1);
    frames(app, 5);
    assert_true(pg_body_angular_velocity(w, box) > 0);
    pga_key(app, PGA_KEY_SPIN_CCW, 0);
    /* clicking empty space clears the selection */
    pga_pointer_down(app, at(10, 10));
    assert_int_equal(pga_selected(app).generation, 0);
    pga_destroy(app);
}

static void test_gravity_toggle(void **state)
{
    pga_app *app = app_with("g", "pogon-scene 1\nwall 40 1 position 0 -0.5\nball 0.5 position 0 5\n");
    const pg_world *w = pga_world(app);
    pg_body_id ball = body_at(app, at(0, 5));
    pg_vec2 p;
    (void)state;
    assert_true(pga_gravity_enabled(app));
    assert_int_equal(pga_toggle_gravity(app), PG_OK);
    assert_false(pga_gravity_enabled(app));
    assert_int_equal(pg_world_gravity(w).y, PG_FIX_C(-10)); /* queued, not yet applied */
    pga_frame(app);
    assert_int_equal(pg_world_gravity(w).y, 0);
    p = pg_body_position(w, ball);
    frames(app, 30);
    assert_true(pg_v2_equal(pg_body_position(w, ball), p)); /* floats */
    assert_int_equal(pga_toggle_gravity(app), PG_OK);
    pga_frame(app);
    assert_int_equal(pg_world_gravity(w).y, PG_FIX_C(-10));
    frames(app, 10);
    assert_true(pg_body_position(w, ball).y < p.y); /* falls */
    pga_destroy(app);
}

static void test_pause_and_step_once(void **state)
{
    pga_app *app = app_with_file("demo");
    uint64_t f0, h0;
    int i;
    (void)state;
    frames(app, 3);
    pga_set_paused(app, 1);
    assert_true(pga_paused(app));
    f0 = pga_frame_number(app);
    h0 = pga_state_hash(app);
    for (i = 0; i < 5; ++i) assert_int_equal(pga_frame(app), 0);
    assert_true(pga_frame_number(app) == f0);
    assert_true(pga_state_hash(app) == h0);
    pga_step_once(app);
    assert_int_equal(pga_frame(app), 1);
    assert_true(pga_frame_number(app) == f0 + 1);
    assert_int_equal(pga_frame(app), 0); /* exactly one */
    assert_true(pga_frame_number(app) == f0 + 1);
    pga_set_paused(app, 0);
    assert_int_equal(pga_frame(app), 1);
    assert_true(pga_frame_number(app) == f0 + 2);
    pga_destroy(app);
}

static void test_drag_moves_toward_pointer(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id ball;
    pg_fix d0, d1;
    (void)state;
    pga_set_tool(app, PGA_TOOL_BALL);
    pga_pointer_down(app, at(-5, 3));
    pga_frame(app);
    ball = body_at(app, at(-5, 3));
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(-5, 3));
    pga_pointer_move(app, at(-1, 6));
    d0 = pg_v2_length(pg_v2_sub(pg_body_position(w, ball), at(-1, 6)));
    frames(app, 5);
    assert_true(pg_body_linear_velocity(w, ball).x > 0);
    assert_true(pg_body_linear_velocity(w, ball).y > 0);
    frames(app, 55);
    d1 = pg_v2_length(pg_v2_sub(pg_body_position(w, ball), at(-1, 6)));
    assert_true(d0 == PG_FIX_C(5));
    assert_true(d1 < PG_FIX_ONE / 10); /* it arrived */
    pga_pointer_up(app, at(-1, 6));
    pga_destroy(app);
}

static void test_preset_keeps_bodies(void **state)
{
    pga_app *app = app_with_file("demo");
    pga_draw_shape before[64];
    const pga_draw_shape *after;
    uint32_t nb, na, i;
    pg_body_id player;
    const uint8_t *rec;
    size_t rec_size;
    pg_replay_info info;
    (void)state;
    frames(app, 40);
    after = pga_draw_list(app, &nb);
    assert_true(nb <= 64);
    memcpy(before, after, sizeof(pga_draw_shape) * nb);
    player = pga_selected(app);
    assert_true(pg_body_is_valid(pga_world(app), player));
    assert_int_equal(pga_set_preset(app, PGA_PRESET_ACCURATE), PG_OK);
    assert_int_equal(pga_get_preset(app), PGA_PRESET_ACCURATE);
    assert_int_equal(pg_world_get_def(pga_world(app)).substeps, 8);
    after = pga_draw_list(app, &na);
    assert_int_equal(na, nb);
    for (i = 0; i < na; ++i) { /* same shapes at the same places, in the same order */
        assert_int_equal(after[i].kind, before[i].kind);
        assert_int_equal(after[i].color, before[i].color);
        assert_memory_equal(after[i].vertices, before[i].vertices, sizeof(pg_vec2) * (size_t)after[i].count);
    }
    /* the player is still selected */
    assert_true((pg_body_user_data(pga_world(app), pga_selected(app)) & 0xffffffffu) == 1u);
    /* the recording restarted from here */
    assert_int_equal(pga_recording(app, &rec, &rec_size), PG_OK);
    assert_int_equal(pg_replay_read(rec, rec_size, &info, NULL), PG_OK);
    assert_int_equal(info.frame_count, 0);
    assert_int_equal(pga_set_preset(app, PGA_PRESET_FAST), PG_OK);
    assert_int_equal(pg_world_get_def(pga_world(app)).substeps, 2);
    assert_int_equal(pga_set_preset(app, PGA_PRESET_COUNT), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pga_get_preset(app), PGA_PRESET_FAST);
    pga_destroy(app);
}

static void test_effects_and_material(void **state)
{
    pga_app *app = app_with_file("demo");
    pg_body_id player = pga_selected(app);
    (void)state;
    assert_int_equal(pga_set_effects(app, PG_EFFECT_GRAVITY | PG_EFFECT_FRICTION), PG_OK);
    assert_int_equal(pga_effects(app), PG_EFFECT_GRAVITY | PG_EFFECT_FRICTION);
    pga_frame(app);
    assert_int_equal(pg_world_effects(pga_world(app)), PG_EFFECT_GRAVITY | PG_EFFECT_FRICTION);
    assert_int_equal(pga_set_selected_color(app, 0xff00ffu), PG_OK);
    pga_frame(app);
    assert_int_equal(pga_body_color(app, player), 0xff00ffu);
    assert_true((pg_body_user_data(pga_world(app), player) & 0xffffffffu) == 1u); /* its tag stays */
    assert_int_equal(pga_effect_count(), 7);
    assert_string_equal(pga_effect_name(6), "continuous");
    assert_int_equal(pga_effect_bit(6), PG_EFFECT_CONTINUOUS);
    pga_destroy(app);
}

/* A body that flies beyond +-1000 m is removed (by a logged command), so the world can
 * still be written as a scene: the preset change works and the recording replays. */
static void test_escaped_body_removed(void **state)
{
    pga_app *app = app_with("open", "pogon-scene 1\ngravity 0 0\nwall 4 1 position 0 -10\n"
                                     "ball 0.5 position 0 0 linear_velocity 300 0 user_data 1\n");
    const uint8_t *rec;
    size_t size;
    uint8_t *copy;
    uint64_t hash;
    uint32_t stepped = 0;
    int i;
    (void)state;
    assert_int_equal(pga_body_count(app), 2);
    assert_true(pg_body_is_valid(pga_world(app), pga_selected(app)));
    for (i = 0; i < 180; ++i) stepped += (uint32_t)pga_frame(app); /* 3 s at 300 m/s: 900 m */
    assert_int_equal(pga_body_count(app), 2);
    for (i = 0; i < 60; ++i) stepped += (uint32_t)pga_frame(app);
    assert_int_equal(pga_body_count(app), 1);
    assert_non_null(strstr(pga_message(app), "left the world"));
    assert_int_equal(pga_selected(app).generation, 0);
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    assert_int_equal(replay_all(copy, size, &hash), stepped);
    assert_true(hash == pga_state_hash(app));
    free(copy);
    assert_int_equal(pga_set_preset(app, PGA_PRESET_FAST), PG_OK);
    assert_int_equal(pga_body_count(app), 1);
    pga_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_demo_player_keys),
        cmocka_unit_test(test_select_and_push_dynamic),
        cmocka_unit_test(test_gravity_toggle),
        cmocka_unit_test(test_pause_and_step_once),
        cmocka_unit_test(test_drag_moves_toward_pointer),
        cmocka_unit_test(test_preset_keeps_bodies),
        cmocka_unit_test(test_effects_and_material),
        cmocka_unit_test(test_escaped_body_removed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
