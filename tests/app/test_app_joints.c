/* test_app_joints.c — the pin, rod and spring tools, the mouse-joint drag, deleting
 * joints, refusals, the joint draw list, and a recording with every tool that replays
 * checkpoint by checkpoint. */
#include "app_test_util.h"

#include <math.h>

/* The flat ground with gravity: what a pendulum needs. */
static const char fall_scene[] = "pogon-scene 1\n"
                                 "gravity 0 -10\n"
                                 "wall 40 1 position 0 -0.5\n";

/* Add a body with a one-click tool while paused (it stays where it is made). */
static pg_body_id add(pga_app *app, pga_tool tool, double x, double y)
{
    pg_body_id b;
    pga_set_tool(app, tool);
    pga_pointer_down(app, at(x, y));
    pga_frame(app);
    b = body_at(app, at(x, y));
    assert_true(b.generation != 0);
    return b;
}

static void clicks(pga_app *app, pga_tool tool, double x0, double y0, double x1, double y1)
{
    uint32_t n = 0;
    pga_set_tool(app, tool);
    pga_pointer_down(app, at(x0, y0));
    pga_pending_points(app, &n);
    assert_int_equal(n, 1); /* the first click is drawn as pending */
    pga_pointer_down(app, at(x1, y1));
    pga_pending_points(app, &n);
    assert_int_equal(n, 0);
    pga_frame(app);
}

/* The only joint of `body`. */
static pg_joint_id joint_of(const pga_app *app, pg_body_id body)
{
    pg_joint_id j = {0, 0};
    assert_int_equal(pg_body_joints(pga_world(app), body, &j, 1), 1);
    return j;
}

static pg_vec2 world_point(const pg_world *w, pg_body_id b, pg_vec2 local)
{
    return pg_v2_add(pg_body_position(w, b), pg_rot_apply(pg_rot_from_angle(pg_body_angle(w, b)), local));
}

static double dist(pg_vec2 a, pg_vec2 b) { return dbl(pg_v2_length(pg_v2_sub(a, b))); }

/* A box pinned to the world 3 m to its left swings down about the pin, which stays put. */
static void test_pin_to_world_swings(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const pg_world *w = pga_world(app);
    pg_body_id box, anchor;
    pg_joint_id j;
    pg_revolute_joint_def def;
    double lowest = 1e9;
    int f;
    (void)state;
    pga_set_paused(app, 1);
    box = add(app, PGA_TOOL_BOX, 3, 8);
    clicks(app, PGA_TOOL_PIN, 3, 8, 0, 8);
    assert_int_equal(pga_joint_count(app), 1);
    j = joint_of(app, box);
    assert_int_equal(pg_joint_type_of(w, j), PG_JOINT_REVOLUTE);
    assert_int_equal(pg_revolute_joint_get_def(w, j, &def), PG_OK);
    assert_true(pg_body_id_equal(def.body_b, box));
    assert_true(pg_v2_equal(def.local_anchor_b, at(-3, 0)));
    anchor = def.body_a; /* the world's end: a shapeless static body at the pin */
    assert_int_equal(pg_body_type_of(w, anchor), PG_BODY_STATIC);
    assert_int_equal(pg_body_shapes(w, anchor, NULL, 0), 0);
    assert_true(pg_v2_equal(pg_body_position(w, anchor), at(0, 8)));
    assert_true(pg_v2_equal(def.local_anchor_a, pg_v2_zero()));
    pga_set_paused(app, 0);
    for (f = 0; f < 120; ++f) {
        pga_frame(app);
        assert_true(dist(world_point(w, box, at(-3, 0)), at(0, 8)) < 0.05); /* the pin holds */
        if (dbl(pg_body_position(w, box).y) < lowest) lowest = dbl(pg_body_position(w, box).y);
    }
    print_message("pin: lowest centre y %.4f m (pin at y 8, arm 3 m)\n", lowest);
    assert_true(lowest < 5.2);                                    /* it swung down to the bottom, 3 m below */
    assert_true(fabs(dist(pg_body_position(w, box), at(0, 8)) - 3.0) < 0.05); /* on its circle */
    pga_destroy(app);
}

/* A second click on another body pins the first to it there. */
static void test_pin_two_bodies(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id a, b;
    pg_revolute_joint_def def;
    (void)state;
    pga_set_paused(app, 1);
    a = add(app, PGA_TOOL_BOX, 0, 5);
    b = add(app, PGA_TOOL_BOX, 1.5, 5);
    clicks(app, PGA_TOOL_PIN, 1.5, 5, 0.25, 5);
    assert_int_equal(pg_revolute_joint_get_def(w, joint_of(app, b), &def), PG_OK);
    assert_true(pg_body_id_equal(def.body_a, a));
    assert_true(pg_body_id_equal(def.body_b, b));
    assert_true(pg_v2_equal(def.local_anchor_a, at(0.25, 0)));
    assert_true(pg_v2_equal(def.local_anchor_b, at(-1.25, 0)));
    assert_int_equal(pga_joint_count(app), 1);
    pga_destroy(app);
}

/* A rod from a ball to the world keeps its length while the ball swings. */
static void test_rod_keeps_length(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const pg_world *w = pga_world(app);
    pg_body_id ball;
    pg_joint_id j;
    pg_distance_joint_def def;
    double rest, worst = 0;
    int f;
    (void)state;
    pga_set_paused(app, 1);
    ball = add(app, PGA_TOOL_BALL, 2, 6);
    clicks(app, PGA_TOOL_ROD, 2, 6, 0, 9); /* the world's end is body A */
    j = joint_of(app, ball);
    assert_int_equal(pg_distance_joint_get_def(w, j, &def), PG_OK);
    assert_true(pg_body_id_equal(def.body_b, ball));
    assert_int_equal(def.enable_spring, 0);
    assert_true(pg_v2_equal(def.local_anchor_b, pg_v2_zero()));
    assert_true(pg_v2_equal(pg_body_position(w, def.body_a), at(0, 9)));
    rest = dbl(def.length);
    assert_true(fabs(rest - sqrt(13.0)) < 1e-4);
    pga_set_paused(app, 0);
    for (f = 0; f < 120; ++f) {
        double e;
        pga_frame(app);
        e = fabs(dbl(pg_distance_joint_current_length(w, j)) - rest);
        if (e > worst) worst = e;
    }
    print_message("rod: largest length error %.5f m of %.4f m\n", worst, rest);
    assert_true(worst < 0.02);
    assert_true(dbl(pg_body_position(w, ball).x) < 1.0); /* it swung */
    pga_destroy(app);
}

/* A spring to the world, stretched by a drag and let go, oscillates about its rest length
 * at its frequency (4 Hz, ratio 0.3: the damped period 1 / (4 sqrt(1 - 0.09)) s). */
static void test_spring_oscillates(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id ball;
    pg_joint_id j;
    pg_distance_joint_def def;
    double rest, prev, up[8];
    int f, crossings = 0, ups = 0;
    (void)state;
    pga_set_paused(app, 1);
    ball = add(app, PGA_TOOL_BALL, 3, 5);
    clicks(app, PGA_TOOL_SPRING, 0, 5, 3, 5);
    j = joint_of(app, ball);
    assert_int_equal(pg_distance_joint_get_def(w, j, &def), PG_OK);
    assert_int_equal(def.enable_spring, 1);
    assert_true(def.hertz == PG_FIX_C(4));
    assert_true(def.damping_ratio == pga_default_params().spring_damping);
    rest = dbl(def.length);
    assert_true(fabs(rest - 3.0) < 1e-4);
    pga_set_paused(app, 0);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(3, 5));
    pga_pointer_move(app, at(5, 5));
    frames(app, 30);
    assert_true(dbl(pg_distance_joint_current_length(w, j)) > rest + 1.0); /* stretched */
    pga_pointer_up(app, at(5, 5));
    prev = dbl(pg_distance_joint_current_length(w, j)) - rest;
    for (f = 1; f <= 60; ++f) {
        double now;
        pga_frame(app);
        now = dbl(pg_distance_joint_current_length(w, j)) - rest;
        if ((prev < 0) != (now < 0)) crossings++;
        if (prev < 0 && now >= 0 && ups < 8) up[ups++] = f + now / (now - prev) - 1.0; /* frames, interpolated */
        prev = now;
    }
    print_message("spring: %d crossings in 1 s, period %.4f s (damped 4 Hz: %.4f s)\n", crossings,
                  ups >= 2 ? (up[1] - up[0]) / 60.0 : 0.0, 1.0 / (4.0 * sqrt(1.0 - 0.09)));
    assert_true(crossings >= 4);
    assert_true(ups >= 2);
    assert_true(fabs((up[1] - up[0]) / 60.0 - 1.0 / (4.0 * sqrt(1.0 - 0.09))) < 0.03);
    pga_destroy(app);
}

/* Dragging a dynamic body makes a mouse joint at the pressed point that pulls it to the
 * pointer; releasing destroys it. Pressed at its centre the box does not swing, and the
 * joint's 5 Hz spring holds its weight with a sag of g / omega^2 = 0.010 m. */
static void test_drag_with_mouse_joint(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const pg_world *w = pga_world(app);
    pg_body_id box;
    pg_joint_id j;
    pg_mouse_joint_def def;
    pg_vec2 local, carried;
    const pga_draw_joint *dj;
    uint32_t n;
    (void)state;
    box = add(app, PGA_TOOL_BOX, 0, 0.5);
    frames(app, 30); /* resting on the ground */
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, pg_body_position(w, box));
    local = pg_rot_apply_inv(pg_rot_from_angle(pg_body_angle(w, box)), pg_v2_zero());
    pga_pointer_move(app, at(3, 4));
    pga_frame(app);
    assert_int_equal(pga_joint_count(app), 1);
    j = joint_of(app, box);
    assert_int_equal(pg_joint_type_of(w, j), PG_JOINT_MOUSE);
    assert_int_equal(pg_mouse_joint_get_def(w, j, &def), PG_OK);
    assert_true(pg_v2_equal(def.target, at(3, 4)));
    assert_true(def.max_force == PG_FIX_C(1000)); /* 1000 N per kg: the box is 1 kg */
    assert_true(pga_anchor_from_user_data(def.user_data, &carried)); /* the anchor, for drawing */
    assert_true(pg_v2_equal(carried, local));
    dj = pga_draw_joints(app, &n);
    assert_int_equal(n, 1);
    assert_int_equal(dj[0].type, PG_JOINT_MOUSE);
    assert_true(pg_v2_equal(dj[0].a, at(3, 4)));
    assert_true(pg_v2_equal(dj[0].b, world_point(w, box, local)));
    frames(app, 89);
    print_message("drag: pressed point %.4f m from the pointer after 1.5 s\n", dist(world_point(w, box, local), at(3, 4)));
    assert_true(dist(world_point(w, box, local), at(3, 4)) < 0.03);
    pga_pointer_move(app, at(-2, 3));
    frames(app, 60);
    assert_true(dist(world_point(w, box, local), at(-2, 3)) < 0.03);
    pga_pointer_up(app, at(-2, 3));
    pga_frame(app);
    assert_int_equal(pga_joint_count(app), 0);
    assert_int_equal(pg_body_joints(w, box, NULL, 0), 0);
    pga_destroy(app);
}

/* Pressed off its centre, the joint's anchor is the pressed point of the body. */
static void test_drag_anchor_off_centre(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id box;
    pg_mouse_joint_def def;
    pg_vec2 carried;
    (void)state;
    box = add(app, PGA_TOOL_BOX, 0, 3);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(0.25, 3.375));
    pga_frame(app);
    assert_int_equal(pg_mouse_joint_get_def(w, joint_of(app, box), &def), PG_OK);
    assert_true(pga_anchor_from_user_data(def.user_data, &carried));
    assert_true(pg_v2_equal(carried, at(0.25, 0.375)));
    pga_pointer_move(app, at(-1, 5));
    frames(app, 90);
    {
        /* the box spins about the pressed point; the joint's 5 Hz spring gives the pull
         * that keeps its centre circling, spin^2 r, with a stretch of spin^2 r / omega^2 */
        double spin = dbl(pg_body_angular_velocity(w, box)), omega = 2.0 * 3.14159265358979 * 5.0;
        double stretch = spin * spin * dbl(pg_v2_length(carried)) / (omega * omega);
        double off = dist(world_point(w, box, carried), at(-1, 5));
        print_message("drag off centre: %.4f m from the pointer, spin %.3f rad/s, expected stretch %.4f m\n", off, spin, stretch);
        assert_true(fabs(off - stretch) < 0.01);
    }
    pga_destroy(app);
}

/* A press and release between two steps make no joint. */
static void test_click_makes_no_joint(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pg_body_id box;
    (void)state;
    box = add(app, PGA_TOOL_BOX, 0, 3);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(0, 3));
    pga_pointer_up(app, at(0, 3));
    pga_frame(app);
    assert_int_equal(pga_joint_count(app), 0);
    assert_true(pg_body_id_equal(pga_selected(app), box));
    pga_destroy(app);
}

/* Released and pressed again on another body while paused: the next step moves the drag
 * to the new body (one mouse joint, on it), and the first body is let go. */
static void test_new_press_replaces_drag(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id a, b;
    (void)state;
    a = add(app, PGA_TOOL_BOX, -3, 3);
    b = add(app, PGA_TOOL_BOX, 3, 3);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(-3, 3));
    pga_pointer_move(app, at(-3, 5));
    frames(app, 3);
    assert_int_equal(pg_body_joints(w, a, NULL, 0), 1);
    pga_set_paused(app, 1);
    pga_pointer_up(app, at(-3, 5));
    pga_pointer_down(app, at(3, 3));
    pga_pointer_move(app, at(3, 6));
    pga_set_paused(app, 0);
    pga_frame(app);
    assert_int_equal(pga_joint_count(app), 1);
    assert_int_equal(pg_body_joints(w, a, NULL, 0), 0);
    assert_int_equal(pg_body_joints(w, b, NULL, 0), 1);
    pga_destroy(app);
}

/* A replay stopped during a recorded drag keeps its mouse joint; the delete tool removes it. */
static void test_replay_stopped_mid_drag(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const uint8_t *rec;
    size_t size;
    uint8_t *copy;
    const pga_draw_joint *d;
    uint32_t n;
    (void)state;
    (void)add(app, PGA_TOOL_BOX, 0, 0.5);
    frames(app, 20);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(0, 0.5));
    pga_pointer_move(app, at(0, 3));
    frames(app, 30);
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    assert_int_equal(pga_play_replay(app, copy, size), PG_OK);
    free(copy);
    while (pga_frame(app)) {
    }
    assert_int_equal(pga_stop_playback(app), PG_OK);
    d = pga_draw_joints(app, &n);
    assert_int_equal(n, 1);
    assert_int_equal(d[0].type, PG_JOINT_MOUSE);
    assert_true(pg_v2_equal(d[0].a, at(0, 3)));
    pga_set_tool(app, PGA_TOOL_DELETE);
    pga_pointer_down(app, at(0, 3));
    pga_frame(app);
    assert_int_equal(pga_joint_count(app), 0);
    pga_destroy(app);
}

static void refused(pga_app *app, uint64_t hash, const char *words)
{
    uint32_t n = 1;
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    assert_non_null(strstr(pga_message(app), words));
    pga_frame(app); /* paused: applies the queue, if anything were queued */
    assert_true(pga_state_hash(app) == hash);
    assert_int_equal(pga_joint_count(app), 0);
    pga_pending_points(app, &n);
    assert_int_equal(n, 0);
}

static void test_refusals(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pga_params p = pga_default_params();
    uint64_t hash;
    (void)state;
    pga_set_paused(app, 1);
    (void)add(app, PGA_TOOL_BALL, 0, 5);
    hash = pga_state_hash(app);
    pga_set_tool(app, PGA_TOOL_PIN);
    pga_pointer_down(app, at(5, 5)); /* nothing to pin */
    refused(app, hash, "Nothing to pin");
    pga_set_tool(app, PGA_TOOL_PIN);
    pga_pointer_down(app, at(0, -0.5)); /* the static ground, then empty space */
    pga_pointer_down(app, at(0, 10));
    refused(app, hash, "static");
    pga_set_tool(app, PGA_TOOL_ROD);
    pga_pointer_down(app, at(0, 5)); /* a rod from the ball to itself */
    pga_pointer_down(app, at(0.2, 5.2));
    refused(app, hash, "both ends");
    pga_set_tool(app, PGA_TOOL_SPRING);
    pga_pointer_down(app, at(5, 5)); /* nothing at either end */
    pga_pointer_down(app, at(6, 6));
    refused(app, hash, "neither end");
    pga_set_tool(app, PGA_TOOL_ROD);
    pga_pointer_down(app, at(0, 5.498)); /* too short: from the ball's edge to just outside it */
    pga_pointer_down(app, at(0, 5.5015));
    refused(app, hash, "0.005..100 m");
    pga_set_tool(app, PGA_TOOL_ROD);
    pga_pointer_down(app, at(0, 5)); /* too long */
    pga_pointer_down(app, at(0, 106));
    refused(app, hash, "0.005..100 m");
    p.spring_hertz = 0;
    assert_int_equal(pga_set_params(app, &p), PG_ERR_ENVELOPE);
    assert_non_null(strstr(pga_message(app), "spring frequency"));
    p = pga_default_params();
    p.spring_damping = -1;
    assert_int_equal(pga_set_params(app, &p), PG_ERR_ENVELOPE);
    assert_true(pga_get_params(app).spring_hertz == PG_FIX_C(4));
    pga_destroy(app);
}

/* The delete tool removes a joint clicked near it with its anchor, and deleting a body
 * removes its joints and the anchors they leave. */
static void test_delete_joints(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pg_world *w = pga_world(app);
    pg_body_id ball, box, anchor;
    pg_joint_id pin, rod;
    (void)state;
    pga_set_paused(app, 1);
    ball = add(app, PGA_TOOL_BALL, 0, 5);
    box = add(app, PGA_TOOL_BOX, 4, 5);
    clicks(app, PGA_TOOL_PIN, 0, 5, 0, 8);
    pin = joint_of(app, ball);
    anchor = pg_joint_body_a(w, pin);
    clicks(app, PGA_TOOL_ROD, 0, 5, 4, 5);
    assert_int_equal(pga_joint_count(app), 2);
    rod = joint_of(app, box);
    pga_set_tool(app, PGA_TOOL_DELETE);
    pga_pointer_down(app, at(2, 5.2)); /* 0.2 m from the rod's line */
    pga_frame(app);
    assert_false(pg_joint_is_valid(w, rod));
    assert_true(pg_body_is_valid(w, ball) && pg_body_is_valid(w, box));
    assert_int_equal(pga_joint_count(app), 1);
    pga_pointer_down(app, at(0.1, 7.9)); /* near the pin */
    pga_frame(app);
    assert_false(pg_joint_is_valid(w, pin));
    assert_false(pg_body_is_valid(w, anchor));
    assert_true(pg_body_is_valid(w, ball));
    /* pin again, then delete the ball: its anchor goes with it */
    clicks(app, PGA_TOOL_PIN, 0, 5, 0, 8);
    anchor = pg_joint_body_a(w, joint_of(app, ball));
    pga_set_tool(app, PGA_TOOL_DELETE);
    pga_pointer_down(app, at(0, 4.6)); /* on the ball, away from the pin */
    pga_frame(app);
    assert_false(pg_body_is_valid(w, ball));
    assert_false(pg_body_is_valid(w, anchor));
    assert_int_equal(pga_joint_count(app), 0);
    pga_destroy(app);
}

/* What every front end draws: kind, spring flag, world anchors, colours by kind. */
static void test_draw_joints(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    const pga_draw_joint *d;
    uint32_t n, i, pins = 0, rods = 0, springs = 0;
    (void)state;
    pga_set_paused(app, 1);
    (void)add(app, PGA_TOOL_BALL, 0, 5);
    (void)add(app, PGA_TOOL_BOX, 4, 5);
    clicks(app, PGA_TOOL_PIN, 0, 5, 0, 5); /* an axle through the ball's centre */
    clicks(app, PGA_TOOL_ROD, 0.25, 5, 4, 5.25);
    clicks(app, PGA_TOOL_SPRING, 4, 5, 4, 9);
    d = pga_draw_joints(app, &n);
    assert_int_equal(n, 3);
    for (i = 0; i < n; ++i) {
        if (d[i].type == PG_JOINT_REVOLUTE) {
            pins++;
            assert_true(pg_v2_equal(d[i].a, at(0, 5)) && pg_v2_equal(d[i].b, at(0, 5)));
            assert_true(pg_v2_equal(d[i].origin_a, at(0, 5)) && pg_v2_equal(d[i].origin_b, at(0, 5)));
        } else if (d[i].spring) {
            springs++;
            assert_true(pg_v2_equal(d[i].a, at(4, 9)) && pg_v2_equal(d[i].b, at(4, 5)));
        } else {
            rods++;
            assert_true(pg_v2_equal(d[i].a, at(0.25, 5)) && pg_v2_equal(d[i].b, at(4, 5.25)));
            assert_true(pg_v2_equal(d[i].origin_a, at(0, 5)) && pg_v2_equal(d[i].origin_b, at(4, 5)));
        }
    }
    assert_int_equal(pins, 1);
    assert_int_equal(rods, 1);
    assert_int_equal(springs, 1);
    for (i = 1; i < n; ++i) assert_true(d[i].color != d[0].color);
    pga_destroy(app);
}

/* A session with each tool, recorded, replays checkpoint by checkpoint. */
static void test_recording_with_joints_verifies(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const uint8_t *rec;
    size_t size;
    uint8_t *copy;
    uint64_t hash = 0;
    int f;
    (void)state;
    for (f = 0; f < 300; ++f) {
        switch (f) {
        case 1: pga_set_tool(app, PGA_TOOL_BALL); pga_pointer_down(app, at(-4, 6)); break;
        case 2: pga_set_tool(app, PGA_TOOL_BOX); pga_pointer_down(app, at(0, 6)); break;
        case 3: pga_set_tool(app, PGA_TOOL_BOX); pga_pointer_down(app, at(5, 0.5)); break;
        case 4:
            pga_set_tool(app, PGA_TOOL_PIN);
            pga_pointer_down(app, at(-4, 5.9));
            pga_pointer_down(app, at(-6, 8));
            pga_set_tool(app, PGA_TOOL_ROD);
            pga_pointer_down(app, at(-4, 5.9));
            pga_pointer_down(app, at(0, 5.9));
            pga_set_tool(app, PGA_TOOL_SPRING);
            pga_pointer_down(app, at(0, 5.9));
            pga_pointer_down(app, at(2, 9));
            break;
        case 90: pga_set_tool(app, PGA_TOOL_MOVE); pga_pointer_down(app, at(5.2, 0.7)); break;
        case 91: pga_pointer_move(app, at(6, 3)); break;
        case 120: pga_pointer_move(app, at(8, 2)); break;
        case 150: pga_pointer_up(app, at(8, 2)); break;
        case 200: pga_set_tool(app, PGA_TOOL_DELETE); pga_pointer_down(app, at(-6, 8)); break; /* the pin */
        default: break;
        }
        pga_frame(app);
        if (f == 5) assert_int_equal(pga_joint_count(app), 3);
        if (f == 100) assert_int_equal(pga_joint_count(app), 4);
        if (f == 160) assert_int_equal(pga_joint_count(app), 3);
    }
    assert_int_equal(pga_joint_count(app), 2);
    assert_int_equal(pga_recording(app, &rec, &size), PG_OK);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, rec, size);
    assert_true(replay_all(copy, size, &hash) == pga_frame_number(app));
    assert_true(hash == pga_state_hash(app));
    free(copy);
    pga_destroy(app);
}

/* A preset change keeps the pins, rods and springs (their anchors are written with the
 * world), but a drag does not survive it: no mouse joint is left behind. */
static void test_preset_keeps_joints_drops_drag(void **state)
{
    pga_app *app = app_with("fall", fall_scene);
    const pga_draw_joint *d;
    uint32_t n;
    (void)state;
    pga_set_paused(app, 1);
    (void)add(app, PGA_TOOL_BOX, 0, 0.5);
    (void)add(app, PGA_TOOL_BALL, 4, 6);
    clicks(app, PGA_TOOL_PIN, 4, 6, 2, 6);
    clicks(app, PGA_TOOL_SPRING, 0, 0.5, 0, 4);
    pga_set_paused(app, 0);
    pga_set_tool(app, PGA_TOOL_MOVE);
    pga_pointer_down(app, at(0, 0.5));
    pga_pointer_move(app, at(0, 3));
    frames(app, 5);
    assert_int_equal(pga_joint_count(app), 3);
    assert_int_equal(pga_set_preset(app, PGA_PRESET_ACCURATE), PG_OK);
    assert_int_equal(pga_joint_count(app), 2);
    frames(app, 5);
    d = pga_draw_joints(app, &n);
    assert_int_equal(n, 2);
    assert_true(d[0].type != PG_JOINT_MOUSE && d[1].type != PG_JOINT_MOUSE);
    pga_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pin_to_world_swings),
        cmocka_unit_test(test_pin_two_bodies),
        cmocka_unit_test(test_rod_keeps_length),
        cmocka_unit_test(test_spring_oscillates),
        cmocka_unit_test(test_drag_with_mouse_joint),
        cmocka_unit_test(test_drag_anchor_off_centre),
        cmocka_unit_test(test_click_makes_no_joint),
        cmocka_unit_test(test_new_press_replaces_drag),
        cmocka_unit_test(test_replay_stopped_mid_drag),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_delete_joints),
        cmocka_unit_test(test_draw_joints),
        cmocka_unit_test(test_recording_with_joints_verifies),
        cmocka_unit_test(test_preset_keeps_joints_drops_drag),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
