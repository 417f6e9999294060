/* test_app_tools.c — adding bodies by clicks, the overlap check and nudge, delete. */
#include "app_test_util.h"

/* The mass pg_make_* gives a body of this kind and size, made directly in a fresh world. */
static int64_t reference_mass(pg_make_kind kind, pg_fix s0, pg_fix s1, pg_fix density)
{
    pg_world_def wd = pg_default_world_def();
    pg_world *w;
    pg_command c = pg_command_init(PG_CMD_MAKE);
    pg_body_id id;
    void *memory;
    int64_t mass;
    wd.max_bodies = wd.max_shapes = 4;
    wd.max_contacts = 16;
    memory = malloc(pg_world_memory_size(&wd));
    assert_int_equal(pg_world_create(&wd, memory, pg_world_memory_size(&wd), &w), PG_OK);
    c.make_kind = kind;
    c.body_def = pg_default_body_def();
    c.body_def.type = PG_BODY_DYNAMIC;
    c.shape_def = pg_default_shape_def();
    c.shape_def.density = density;
    c.size0 = s0;
    c.size1 = s1;
    assert_int_equal(pg_command_apply(w, &c, &id), PG_OK);
    mass = pg_body_mass(w, id);
    free(memory);
    return mass;
}

static char *scene_text(const pga_app *app)
{
    size_t n = pg_scene_write(pga_world(app), NULL, 0);
    char *t = (char *)malloc(n + 1);
    pg_scene_write(pga_world(app), t, n + 1);
    return t;
}

static pga_params params_for_test(void)
{
    pga_params p = pga_default_params();
    p.radius = fx(0.75);
    p.width = fx(2);
    p.height = fx(0.5);
    p.density = fx(3);
    p.friction = fx(0.25);
    p.restitution = fx(0.5);
    p.color = 0x12ab34u;
    return p;
}

/* Add one body with `tool` at (x, y) and return it, checking it landed there with the
 * parameters' colour, density, friction and restitution. */
static pg_body_id add_one(pga_app *app, pga_tool tool, double x, double y, pg_make_kind kind, pg_fix s0, pg_fix s1)
{
    pga_params p = params_for_test();
    uint32_t before = pga_body_count(app);
    pg_body_id id;
    pga_body_info info;
    char *text;
    assert_int_equal(pga_set_params(app, &p), PG_OK);
    assert_int_equal(pga_set_tool(app, tool), PG_OK);
    pga_pointer_down(app, at(x, y));
    pga_pointer_up(app, at(x, y));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_INFO);
    assert_int_equal(pga_body_count(app), before); /* queued, not yet applied */
    assert_int_equal(pga_frame(app), 1);
    assert_int_equal(pga_body_count(app), before + 1);
    id = body_at(app, at(x, y));
    assert_true(pg_body_is_valid(pga_world(app), id));
    assert_int_equal(pga_get_body_info(app, id, &info), PG_OK);
    assert_int_equal(info.position.x, fx(x)); /* no gravity, no contact: exactly where clicked */
    assert_int_equal(info.position.y, fx(y));
    assert_int_equal(info.type, PG_BODY_DYNAMIC);
    assert_int_equal(info.color, 0x12ab34u);
    assert_int_equal(pga_body_color(app, id), 0x12ab34u);
    assert_true(pg_body_mass(pga_world(app), id) == reference_mass(kind, s0, s1, p.density));
    text = scene_text(app);
    assert_non_null(strstr(text, "friction 0.25"));
    assert_non_null(strstr(text, "restitution 0.5"));
    free(text);
    return id;
}

static void shape0(const pga_app *app, pg_body_id id, pg_geometry *g)
{
    pg_shape_id s;
    assert_int_equal(pg_body_shapes(pga_world(app), id, &s, 1), 1);
    assert_int_equal(pg_shape_geometry(pga_world(app), s, g), PG_OK);
}

static void test_one_click_kinds(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pg_geometry g;
    pg_shape_id s[4];
    pg_body_id id;
    (void)state;

    id = add_one(app, PGA_TOOL_BALL, -12, 3, PG_MAKE_BALL, fx(0.75), 0);
    shape0(app, id, &g);
    assert_int_equal(g.kind, PG_SHAPE_CIRCLE);
    assert_int_equal(g.radius, fx(0.75));

    id = add_one(app, PGA_TOOL_CAPSULE, -6, 3, PG_MAKE_CAPSULE, fx(2), fx(0.75));
    shape0(app, id, &g);
    assert_int_equal(g.kind, PG_SHAPE_CAPSULE);
    assert_int_equal(g.radius, fx(0.75));
    assert_int_equal(g.vertices[1].x - g.vertices[0].x, fx(2));

    id = add_one(app, PGA_TOOL_BOX, 0, 3, PG_MAKE_BOX, fx(2), fx(0.5));
    shape0(app, id, &g);
    assert_int_equal(g.kind, PG_SHAPE_POLYGON);
    assert_int_equal(g.count, 4);
    assert_int_equal(g.vertices[2].x - g.vertices[0].x, fx(2));
    assert_int_equal(g.vertices[2].y - g.vertices[0].y, fx(0.5));

    id = add_one(app, PGA_TOOL_STAR, 6, 3, PG_MAKE_STAR, fx(0.75), 0);
    assert_int_equal(pg_body_shapes(pga_world(app), id, s, 4), 2);
    pga_destroy(app);
}

static void test_triangle_by_three_clicks(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    uint32_t n = 0;
    pg_body_id id;
    pg_geometry g;
    pg_vec2 pos;
    int i, k, found;
    const pg_vec2 clicks[3] = {{0, PG_FIX_C(1)}, {PG_FIX_C(3), PG_FIX_C(1)}, {PG_FIX_C(0), PG_FIX_C(4)}};
    (void)state;
    assert_int_equal(pga_set_tool(app, PGA_TOOL_TRIANGLE), PG_OK);
    pga_pointer_down(app, clicks[0]);
    pga_pointer_down(app, clicks[1]);
    assert_non_null(pga_pending_points(app, &n));
    assert_int_equal(n, 2);
    assert_int_equal(pga_body_count(app), 1);
    pga_pointer_down(app, clicks[2]);
    pga_pending_points(app, &n);
    assert_int_equal(n, 0);
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 2);
    id = body_at(app, at(1, 2));
    assert_true(pg_body_is_valid(pga_world(app), id));
    shape0(app, id, &g);
    assert_int_equal(g.count, 3);
    pos = pg_body_position(pga_world(app), id);
    assert_int_equal(pos.x, PG_FIX_C(1)); /* the centroid */
    assert_int_equal(pos.y, PG_FIX_C(2));
    for (i = 0; i < 3; ++i) { /* each click is a vertex, in world coordinates */
        found = 0;
        for (k = 0; k < 3; ++k)
            if (pg_v2_equal(pg_v2_add(pos, g.vertices[k]), clicks[i])) found = 1;
        assert_true(found);
    }
    /* three points on a line make no triangle: refused, nothing queued */
    pga_pointer_down(app, at(-10, 1));
    pga_pointer_down(app, at(-9, 1));
    pga_pointer_down(app, at(-8, 1));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 2);
    pga_destroy(app);
}

static void test_wall_by_two_clicks(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pga_params p = pga_default_params();
    pg_body_id id;
    pg_geometry g;
    pg_vec2 pos;
    (void)state;
    p.height = fx(0.25);
    assert_int_equal(pga_set_params(app, &p), PG_OK);
    assert_int_equal(pga_set_tool(app, PGA_TOOL_WALL), PG_OK);
    pga_pointer_down(app, at(-4, 2));
    assert_int_equal(pga_body_count(app), 1);
    pga_pointer_down(app, at(4, 8)); /* 10 m long, rising at atan(6/8) */
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 2);
    id = body_at(app, at(0, 5));
    assert_true(pg_body_is_valid(pga_world(app), id));
    assert_int_equal(pg_body_type_of(pga_world(app), id), PG_BODY_STATIC);
    pos = pg_body_position(pga_world(app), id);
    assert_int_equal(pos.x, 0); /* the midpoint */
    assert_int_equal(pos.y, PG_FIX_C(5));
    assert_true(pg_body_angle(pga_world(app), id) == pg_angle_atan2(PG_FIX_C(6), PG_FIX_C(8)));
    shape0(app, id, &g);
    assert_int_equal(g.vertices[2].x - g.vertices[0].x, PG_FIX_C(10));
    assert_int_equal(g.vertices[2].y - g.vertices[0].y, fx(0.25));
    /* both ends are on the wall */
    assert_true(pg_body_id_equal(body_at(app, at(-3.9, 2.1)), id));
    assert_true(pg_body_id_equal(body_at(app, at(3.9, 7.9)), id));
    pga_destroy(app);
}

static void test_overlap_refused(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    uint64_t hash;
    uint32_t serial;
    (void)state;
    assert_int_equal(pga_set_tool(app, PGA_TOOL_BOX), PG_OK);
    pga_pointer_down(app, at(0, 2));
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 2);
    pga_set_paused(app, 1);
    hash = pga_state_hash(app);
    serial = pga_message_serial(app);
    pga_pointer_down(app, at(0.5, 2.5)); /* half a box away: overlaps */
    assert_true(pga_message_serial(app) > serial);
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    assert_non_null(strstr(pga_message(app), "overlap"));
    assert_int_equal(pga_frame(app), 0);
    assert_true(pga_state_hash(app) == hash);
    assert_int_equal(pga_body_count(app), 2);
    /* a ball in the ground is refused too */
    pga_set_tool(app, PGA_TOOL_BALL);
    pga_pointer_down(app, at(5, 0));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    pga_frame(app);
    assert_true(pga_state_hash(app) == hash);
    pga_destroy(app);
}

static void test_nudge_places_at_free_spot(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pga_params p = pga_default_params();
    pg_body_id ids[8], added = {0, 0};
    pg_geometry g;
    pg_vec2 pos, d;
    uint32_t n, i;
    const pga_draw_shape *list;
    (void)state;
    assert_int_equal(pga_set_tool(app, PGA_TOOL_BOX), PG_OK);
    pga_pointer_down(app, at(0, 2));
    pga_frame(app);
    p.nudge = 1;
    assert_int_equal(pga_set_params(app, &p), PG_OK);
    pga_pointer_down(app, at(0.25, 2.25));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_INFO);
    assert_non_null(strstr(pga_message(app), "free spot"));
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 3);
    list = pga_draw_list(app, &n);
    for (i = 0; i < n; ++i)
        if (list[i].body.index == 2) added = list[i].body;
    assert_true(pg_body_is_valid(pga_world(app), added));
    pos = pg_body_position(pga_world(app), added);
    d = pg_v2_sub(pos, at(0.25, 2.25));
    assert_true(pg_v2_length(d) > 0);
    assert_true(pg_v2_length(d) <= PG_FIX_C(8));
    /* it overlaps nothing but itself */
    shape0(app, added, &g);
    assert_int_equal(pg_world_query_geometry(pga_world(app), &g, pos, pg_body_angle(pga_world(app), added), ids, 8, &n), PG_OK);
    assert_int_equal(n, 1);
    assert_true(pg_body_id_equal(ids[0], added));
    pga_destroy(app);
}

static void test_delete(void **state)
{
    pga_app *app = app_with("flat", flat_scene);
    pg_body_id box;
    (void)state;
    pga_set_tool(app, PGA_TOOL_BOX);
    pga_pointer_down(app, at(3, 2));
    pga_frame(app);
    box = body_at(app, at(3, 2));
    assert_int_equal(pga_set_tool(app, PGA_TOOL_MOVE), PG_OK);
    pga_pointer_down(app, at(3, 2));
    pga_pointer_up(app, at(3, 2));
    assert_true(pg_body_id_equal(pga_selected(app), box));
    assert_int_equal(pga_set_tool(app, PGA_TOOL_DELETE), PG_OK);
    pga_pointer_down(app, at(3, 2));
    pga_frame(app);
    assert_false(pg_body_is_valid(pga_world(app), box));
    assert_int_equal(pga_body_count(app), 1);
    assert_int_equal(pga_selected(app).generation, 0); /* the selection went with it */
    /* empty space: nothing to delete, refused with a message */
    pga_pointer_down(app, at(3, 2));
    assert_int_equal(pga_message_level_of(app), PGA_MESSAGE_REFUSED);
    /* static walls can be deleted too */
    pga_pointer_down(app, at(0, -0.5));
    pga_frame(app);
    assert_int_equal(pga_body_count(app), 0);
    pga_destroy(app);
}

/* The draw list: every shape in world coordinates, colours by type and shape for scene
 * bodies, flags for the selected, static and kinematic bodies. */
static void test_draw_list(void **state)
{
    pga_app *app = app_with("d", "pogon-scene 1\nwall 40 1 position 0 -0.5\n"
                                  "box 2 1 position 3 4 angle 90\n"
                                  "ball 0.5 position -3 4\n"
                                  "star 0.8 position 0 8\n"
                                  "box 1 2 type kinematic position 10 1 user_data 1\n");
    const pga_draw_shape *d;
    uint32_t n, i, selected = 0;
    (void)state;
    d = pga_draw_list(app, &n);
    assert_int_equal(n, 6); /* the star has two shapes */
    assert_int_equal(d[0].flags, PGA_DRAW_STATIC);
    assert_int_equal(d[0].color, 0x6b7280u);
    /* the box turned by 90 degrees: its 2 m side is vertical, centred on (3, 4) */
    assert_int_equal(d[1].kind, PG_SHAPE_POLYGON);
    assert_int_equal(d[1].count, 4);
    assert_int_equal(d[1].color, 0x3b82f6u);
    for (i = 0; i < 4; ++i) {
        assert_true(labs((long)d[1].vertices[i].x - PG_FIX_C(3)) <= PG_FIX_HALF + 2);
        assert_true(labs((long)d[1].vertices[i].y - PG_FIX_C(4)) <= PG_FIX_ONE + 2);
        assert_true(labs((long)d[1].vertices[i].y - PG_FIX_C(4)) >= PG_FIX_ONE - 2);
    }
    assert_int_equal(d[2].kind, PG_SHAPE_CIRCLE);
    assert_int_equal(d[2].color, 0xef4444u);
    assert_true(pg_v2_equal(d[2].vertices[0], at(-3, 4)));
    assert_int_equal(d[2].radius, PG_FIX_HALF);
    assert_int_equal(d[3].color, 0xeab308u);
    assert_true(pg_body_id_equal(d[3].body, d[4].body));
    for (i = 0; i < n; ++i)
        if (d[i].flags & PGA_DRAW_SELECTED) {
            selected++;
            assert_int_equal(d[i].flags, PGA_DRAW_SELECTED | PGA_DRAW_KINEMATIC);
            assert_int_equal(d[i].color, 0xf59e0bu);
        }
    assert_int_equal(selected, 1); /* the player, tag 1, selected at load */
    pga_destroy(app);
}

/* A chain of one-sided segments is drawn as its segments: the front ends draw circles,
 * segments, capsules and polygons only. */
static void test_draw_list_chain(void **state)
{
    pga_app *app = app_with("c", "pogon-scene 1\nchain 6 0 2 -1 -2 -1 -6 0\n");
    const pga_draw_shape *d;
    uint32_t n, i;
    (void)state;
    d = pga_draw_list(app, &n);
    assert_int_equal(n, 3);
    for (i = 0; i < n; ++i) {
        assert_int_equal(d[i].kind, PG_SHAPE_SEGMENT);
        assert_int_equal(d[i].count, 2);
        assert_int_equal(d[i].color, 0x6b7280u);
    }
    assert_true(pg_v2_equal(d[0].vertices[0], at(6, 0)));
    assert_true(pg_v2_equal(d[0].vertices[1], at(2, -1)));
    pga_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_click_kinds),
        cmocka_unit_test(test_triangle_by_three_clicks),
        cmocka_unit_test(test_wall_by_two_clicks),
        cmocka_unit_test(test_overlap_refused),
        cmocka_unit_test(test_nudge_places_at_free_spot),
        cmocka_unit_test(test_delete),
        cmocka_unit_test(test_draw_list),
        cmocka_unit_test(test_draw_list_chain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
