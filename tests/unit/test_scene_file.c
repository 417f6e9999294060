/* test_scene_file.c — the scene text format (include/pogon/scene_file.h, docs/formats.md):
 * the shipped scenes load, pyramid.scene is the pyramid of tools/scenes, write -> load ->
 * write gives the same text (also after stepping), every kind of malformed input gives
 * the documented result with the right line and column, and angles convert exactly.
 */
#include "pg_test.h"

#include <stdlib.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pogon/scene_file.h"
#include "world_internal.h"
#ifdef POGON_HAVE_SCENES
#include "scenes.h"
#endif

#ifndef POGON_SCENES_DIR
#error "POGON_SCENES_DIR must name the scenes/ folder"
#endif

/* ---- helpers ------------------------------------------------------------------------------ */
typedef struct loaded {
    void *memory;
    pg_world *w;
} loaded;

static char *read_file(const char *name, size_t *size)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", POGON_SCENES_DIR, name);
    return pgt_read_file(path, size);
}

static loaded world_for_def(const pg_world_def *def)
{
    loaded l;
    size_t need = pg_world_memory_size(def);
    assert_true(need > 0);
    l.memory = malloc(need);
    assert_non_null(l.memory);
    assert_int_equal(pg_world_create(def, l.memory, need, &l.w), PG_OK);
    return l;
}

/* read_def, create, load; the load must succeed. */
static loaded load_text(const char *text, size_t size)
{
    pg_world_def def;
    pg_scene_error err;
    loaded l;
    pg_result r = pg_scene_read_def(text, size, &def, &err);
    if (r != PG_OK) {
        print_error("read_def: %s: %s\n", pg_result_name(r), err.message);
        fail();
    }
    l = world_for_def(&def);
    r = pg_scene_load(l.w, text, size, &err);
    if (r != PG_OK) {
        print_error("load: %s: %s\n", pg_result_name(r), err.message);
        fail();
    }
    assert_int_equal(err.line, 0);
    assert_string_equal(err.message, "");
    return l;
}

static loaded load_string(const char *text) { return load_text(text, strlen(text)); }

static void free_loaded(loaded *l) { free(l->memory); l->memory = NULL; l->w = NULL; }

/* The whole scene text of a world, NUL-terminated, in malloc'd memory. */
static char *write_text(const pg_world *w, size_t *size)
{
    size_t n = pg_scene_write(w, NULL, 0), m;
    char *text = malloc(n + 1);
    assert_non_null(text);
    m = pg_scene_write(w, text, n + 1);
    assert_int_equal(m, n);
    assert_int_equal(text[n], '\0');
    assert_int_equal(strlen(text), n);
    *size = n;
    return text;
}

static pg_body_id body_at(const pg_world *w, uint32_t index)
{
    pg_body_id id;
    id.index = index;
    id.generation = w->bodies[index].generation;
    return id;
}

/* Every body and shape of a and b (in slot order, both compacted) is the same. */
static void expect_same_bodies(const pg_world *a, const pg_world *b)
{
    uint32_t i, j;
    assert_int_equal(pg_world_get_stats(a).body_count, pg_world_get_stats(b).body_count);
    assert_int_equal(pg_world_get_stats(a).shape_count, pg_world_get_stats(b).shape_count);
    for (i = 0; i < a->body_high; ++i) {
        pg_body_id ia = body_at(a, i), ib = body_at(b, i);
        pg_shape_id sa[64], sb[64];
        uint32_t na, nb;
        const pg_body *ba = &a->bodies[i], *bb = &b->bodies[i];
        assert_true(pg_body_is_valid(a, ia));
        assert_true(pg_body_is_valid(b, ib));
        PG_EXPECT_EQ(pg_body_type_of(a, ia), pg_body_type_of(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_position(a, ia).x, pg_body_position(b, ib).x, "body %u", i);
        PG_EXPECT_EQ(pg_body_position(a, ia).y, pg_body_position(b, ib).y, "body %u", i);
        PG_EXPECT_EQ(pg_body_angle(a, ia), pg_body_angle(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_linear_velocity(a, ia).x, pg_body_linear_velocity(b, ib).x, "body %u", i);
        PG_EXPECT_EQ(pg_body_linear_velocity(a, ia).y, pg_body_linear_velocity(b, ib).y, "body %u", i);
        PG_EXPECT_EQ(pg_body_angular_velocity(a, ia), pg_body_angular_velocity(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_mass(a, ia), pg_body_mass(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_inertia(a, ia), pg_body_inertia(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_is_awake(a, ia), pg_body_is_awake(b, ib), "body %u", i);
        PG_EXPECT_EQ(pg_body_user_data(a, ia), pg_body_user_data(b, ib), "body %u", i);
        /* flags, less the scratch bit "world geometry must be recomputed" */
        PG_EXPECT_EQ(ba->flags & ~(uint32_t)PG_BODY_FLAG_GEOMETRY_DIRTY, bb->flags & ~(uint32_t)PG_BODY_FLAG_GEOMETRY_DIRTY, "body %u", i);
        PG_EXPECT_EQ(ba->linear_damping, bb->linear_damping, "body %u", i);
        PG_EXPECT_EQ(ba->angular_damping, bb->angular_damping, "body %u", i);
        PG_EXPECT_EQ(ba->gravity_scale, bb->gravity_scale, "body %u", i);
        na = pg_body_shapes(a, ia, sa, 64);
        nb = pg_body_shapes(b, ib, sb, 64);
        PG_EXPECT_EQ(na, nb, "body %u", i);
        for (j = 0; j < na && j < 64; ++j) {
            const pg_shape *xa = &a->shapes[sa[j].index], *xb = &b->shapes[sb[j].index];
            pg_geometry ga, gb;
            int k;
            assert_int_equal(pg_shape_geometry(a, sa[j], &ga), PG_OK);
            assert_int_equal(pg_shape_geometry(b, sb[j], &gb), PG_OK);
            PG_EXPECT_EQ(ga.kind, gb.kind, "body %u shape %u", i, j);
            PG_EXPECT_EQ(ga.count, gb.count, "body %u shape %u", i, j);
            PG_EXPECT_EQ(ga.radius, gb.radius, "body %u shape %u", i, j);
            for (k = 0; k < ga.count; ++k) {
                PG_EXPECT_EQ(ga.vertices[k].x, gb.vertices[k].x, "body %u shape %u vertex %d", i, j, k);
                PG_EXPECT_EQ(ga.vertices[k].y, gb.vertices[k].y, "body %u shape %u vertex %d", i, j, k);
            }
            PG_EXPECT_EQ(xa->density, xb->density, "body %u shape %u", i, j);
            PG_EXPECT_EQ(xa->friction, xb->friction, "body %u shape %u", i, j);
            PG_EXPECT_EQ(xa->restitution, xb->restitution, "body %u shape %u", i, j);
            PG_EXPECT_EQ(xa->category, xb->category, "body %u shape %u", i, j);
            PG_EXPECT_EQ(xa->mask, xb->mask, "body %u shape %u", i, j);
        }
    }
}

static void expect_same_def(const pg_world_def *a, const pg_world_def *b)
{
    assert_int_equal(a->gravity.x, b->gravity.x);
    assert_int_equal(a->gravity.y, b->gravity.y);
    assert_int_equal(a->step_hz, b->step_hz);
    assert_int_equal(a->substeps, b->substeps);
    assert_int_equal(a->effects, b->effects);
    assert_int_equal(a->contact_hertz, b->contact_hertz);
    assert_int_equal(a->contact_damping_ratio, b->contact_damping_ratio);
    assert_int_equal(a->contact_push_max, b->contact_push_max);
    assert_int_equal(a->restitution_threshold, b->restitution_threshold);
    assert_int_equal(a->max_linear_speed, b->max_linear_speed);
    assert_int_equal(a->sleep_linear_tolerance, b->sleep_linear_tolerance);
    assert_int_equal(a->sleep_angular_tolerance, b->sleep_angular_tolerance);
    assert_int_equal(a->time_to_sleep, b->time_to_sleep);
    assert_int_equal(a->max_bodies, b->max_bodies);
    assert_int_equal(a->max_shapes, b->max_shapes);
    assert_int_equal(a->max_contacts, b->max_contacts);
}

/* Write w, load the text into a new world, write that: the same text and the same bodies. */
static void expect_round_trip(const pg_world *w)
{
    size_t n1, n2;
    char *t1 = write_text(w, &n1), *t2;
    loaded b = load_text(t1, n1);
    pg_world_def da = pg_world_get_def(w), db = pg_world_get_def(b.w);
    expect_same_def(&da, &db);
    expect_same_bodies(w, b.w);
    t2 = write_text(b.w, &n2);
    if (n1 != n2 || memcmp(t1, t2, n1) != 0) {
        print_error("second write differs:\n---- first\n%s\n---- second\n%s\n", t1, t2);
        fail();
    }
    free(t1);
    free(t2);
    free_loaded(&b);
}

static const char *const shipped[] = {"pyramid.scene", "stack.scene", "demo.scene", "shapes.scene"};

/* ---- the shipped scenes ---------------------------------------------------------------------------- */
static void test_shipped_scenes_load(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof shipped / sizeof shipped[0]; ++i) {
        size_t size;
        char *text = read_file(shipped[i], &size);
        loaded l = load_text(text, size);
        pg_world_stats s = pg_world_get_stats(l.w);
        if (strcmp(shipped[i], "pyramid.scene") == 0) {
            assert_int_equal(s.body_count, 211);
            assert_int_equal(s.shape_count, 211);
        } else if (strcmp(shipped[i], "stack.scene") == 0) {
            assert_int_equal(s.body_count, 21);
        } else if (strcmp(shipped[i], "demo.scene") == 0) {
            uint32_t k, kinematic = 0, player = 0;
            assert_int_equal(s.body_count, 3 + 6);
            for (k = 0; k < l.w->body_high; ++k) {
                pg_body_id id = body_at(l.w, k);
                if (pg_body_type_of(l.w, id) == PG_BODY_KINEMATIC) ++kinematic, player = k;
            }
            assert_int_equal(kinematic, 1);
            assert_int_equal(pg_body_user_data(l.w, body_at(l.w, player)), 1);
        } else {
            assert_true(s.body_count >= 12);
        }
        /* a few steps must run */
        for (int k = 0; k < 10; ++k) assert_int_equal(pg_world_step(l.w), PG_OK);
        free_loaded(&l);
        free(text);
    }
}

static void test_shapes_scene_has_everything(void **state)
{
    size_t size;
    char *text = read_file("shapes.scene", &size);
    loaded l = load_text(text, size);
    pg_world_def d = pg_world_get_def(l.w);
    int kinds[4] = {0, 0, 0, 0}, types[3] = {0, 0, 0}, asleep = 0, fixed = 0, no_sleep = 0, big_polygon = 0;
    uint32_t i;
    (void)state;
    assert_int_equal(d.step_hz, 120);
    assert_int_equal(d.effects, PG_EFFECTS_ALL & ~PG_EFFECT_CONTINUOUS);
    for (i = 0; i < l.w->body_high; ++i) {
        const pg_body *b = &l.w->bodies[i];
        uint32_t s;
        types[b->type] += 1;
        asleep += (b->flags & PG_BODY_FLAG_AWAKE) == 0;
        fixed += (b->flags & PG_BODY_FLAG_FIXED_ROTATION) != 0;
        no_sleep += (b->flags & PG_BODY_FLAG_ALLOW_SLEEP) == 0;
        for (s = b->first_shape; s != PG_NULL_INDEX; s = l.w->shapes[s].next) {
            kinds[l.w->shapes[s].geometry.kind] += 1;
            big_polygon += l.w->shapes[s].geometry.count == 8;
        }
    }
    for (i = 0; i < 4; ++i) assert_true(kinds[i] > 0);
    for (i = 0; i < 3; ++i) assert_true(types[i] > 0);
    assert_true(asleep > 0 && fixed > 0 && no_sleep > 0 && big_polygon > 0);
    free_loaded(&l);
    free(text);
}

#ifdef POGON_HAVE_SCENES
static void test_pyramid_matches_tools_scene(void **state)
{
    size_t size, need;
    char *text = read_file("pyramid.scene", &size);
    loaded l = load_text(text, size);
    pg_world_def want = pg_scene_world_def("pyramid", 20), got = pg_world_get_def(l.w);
    pg_scene scene;
    void *memory;
    (void)state;
    expect_same_def(&got, &want);
    need = pg_scene_memory_size("pyramid", 20, NULL);
    memory = malloc(need);
    assert_non_null(memory);
    assert_int_equal(pg_scene_build("pyramid", 20, NULL, memory, need, &scene), PG_OK);
    assert_int_equal(scene.body_count, 210);
    expect_same_bodies(scene.world, l.w);
    /* and the whole state, bit for bit */
    assert_true(pg_world_hash(scene.world) == pg_world_hash(l.w));
    /* still the same after a second of simulation */
    for (int k = 0; k < 60; ++k) {
        assert_int_equal(pg_world_step(scene.world), PG_OK);
        assert_int_equal(pg_world_step(l.w), PG_OK);
    }
    assert_true(pg_world_hash(scene.world) == pg_world_hash(l.w));
    free(memory);
    free_loaded(&l);
    free(text);
}
#endif

/* ---- write -> load -> write ------------------------------------------------------------------------------ */
static void test_round_trip_shipped(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof shipped / sizeof shipped[0]; ++i) {
        size_t size;
        char *text = read_file(shipped[i], &size);
        loaded l = load_text(text, size);
        size_t n1;
        char *t1 = write_text(l.w, &n1);
        loaded b = load_text(t1, n1);
        /* nothing stepped yet: the two worlds are the same state, bit for bit */
        assert_true(pg_world_hash(l.w) == pg_world_hash(b.w));
        expect_round_trip(l.w);
        free(t1);
        free_loaded(&b);
        free_loaded(&l);
        free(text);
    }
}

/* max_contact_events is written only when it is not the default, which has no number
 * (PG_EVENTS_AS_CONTACTS), and reads back as written. */
static void test_contact_events_setting(void **state)
{
    loaded a = load_string("pogon-scene 1\nmax_contact_events 3\nball 0.5 position 0 2\n");
    loaded b = load_string("pogon-scene 1\nball 0.5 position 0 2\n");
    size_t na, nb;
    char *ta = write_text(a.w, &na), *tb = write_text(b.w, &nb);
    pg_world_def def;
    pg_scene_error err;
    (void)state;
    assert_non_null(strstr(ta, "max_contact_events 3\n"));
    assert_null(strstr(tb, "max_contact_events"));
    assert_int_equal(pg_scene_read_def(ta, na, &def, &err), PG_OK);
    assert_int_equal(def.max_contact_events, 3);
    assert_int_equal(pg_scene_read_def(tb, nb, &def, &err), PG_OK);
    assert_int_equal(def.max_contact_events, PG_EVENTS_AS_CONTACTS);
    /* the same world but for what it keeps of its events: the same state */
    assert_true(pg_world_hash(a.w) == pg_world_hash(b.w));
    assert_int_equal(pg_scene_read_def("pogon-scene 1\nmax_contact_events 16777217\n", 42, &def, &err), PG_ERR_ENVELOPE);
    assert_non_null(strstr(err.message, "max_contact_events"));
    free(ta);
    free(tb);
    free_loaded(&a);
    free_loaded(&b);
}

static void test_round_trip_after_steps(void **state)
{
    size_t i;
    (void)state;
    for (i = 0; i < sizeof shipped / sizeof shipped[0]; ++i) {
        size_t size;
        char *text = read_file(shipped[i], &size);
        loaded l = load_text(text, size);
        int k;
        for (k = 0; k < 90; ++k) {
            assert_int_equal(pg_world_step(l.w), PG_OK);
            if (k % 30 == 29) expect_round_trip(l.w); /* moving, turning, some asleep */
        }
        free_loaded(&l);
        free(text);
    }
}

static void test_round_trip_edited_world(void **state)
{
    /* a world changed through the API: destroyed bodies (holes), changed settings,
     * materials, a body turned by an angle that whole degrees cannot express */
    loaded l = load_string("pogon-scene 1\nmax_bodies 8\nmax_shapes 16\n"
                           "wall 20 1 position 0 -0.5\nball 0.5 position 0 2\nbox 1 1 position 2 2\nstar 0.5 position -2 2\n");
    pg_body_id ball = body_at(l.w, 1), box = body_at(l.w, 2), star = body_at(l.w, 3);
    (void)state;
    assert_int_equal(pg_body_destroy(l.w, ball), PG_OK);
    assert_int_equal(pg_world_set_gravity(l.w, pg_v2(PG_FIX_C(1), PG_FIX_C(-3))), PG_OK);
    assert_int_equal(pg_world_set_effects(l.w, PG_EFFECT_GRAVITY | PG_EFFECT_ROTATION), PG_OK);
    assert_int_equal(pg_body_set_transform(l.w, box, pg_v2(PG_FIX_C(3), PG_FIX_C(4)), 0x12345679u), PG_OK);
    assert_int_equal(pg_body_set_friction(l.w, star, PG_FIX_C(2)), PG_OK);
    assert_int_equal(pg_body_set_filter(l.w, star, 0x80000000u, 0x7u), PG_OK);
    assert_int_equal(pg_body_set_user_data(l.w, box, UINT64_MAX), PG_OK);
    assert_int_equal(pg_body_set_damping(l.w, box, PG_FIX_C(1) / 3, PG_FIX_C(2)), PG_OK);
    assert_int_equal(pg_body_set_gravity_scale(l.w, box, -PG_FIX_C(100)), PG_OK);
    assert_int_equal(pg_body_set_type(l.w, star, PG_BODY_KINEMATIC), PG_OK);
    assert_int_equal(pg_body_set_angular_velocity(l.w, star, PG_FIX_C(-7)), PG_OK);
    {
        size_t n;
        char *t = write_text(l.w, &n);
        assert_non_null(strstr(t, "angle_bits 0x12345679"));
        assert_non_null(strstr(t, "gravity 1 -3\n"));
        assert_non_null(strstr(t, "effects gravity rotation\n"));
        assert_non_null(strstr(t, "user_data 18446744073709551615\n"));
        assert_non_null(strstr(t, "category 0x80000000 mask 0x7"));
        free(t);
    }
    /* the hole at slot 1 is not kept: bodies load compacted, in slot order */
    {
        size_t n;
        char *t = write_text(l.w, &n);
        loaded b = load_text(t, n);
        assert_int_equal(pg_world_get_stats(b.w).body_count, 3);
        PG_EXPECT_EQ(pg_body_angle(b.w, body_at(b.w, 1)), 0x12345679u, "%s", "box angle");
        assert_int_equal(b.w->bodies[1].user_data, UINT64_MAX);
        free_loaded(&b);
        free(t);
    }
    free_loaded(&l);
}

static void test_sleeping_body_round_trip(void **state)
{
    loaded l = load_string("pogon-scene 1\nwall 20 1 position 0 -0.5\n"
                           "body dynamic\n  position 0 3\n  linear_velocity 1 0\n  awake 0\n  shape circle 0.5\nend\n"
                           "ball 0.5 position 3 3 awake 0\nbox 1 1 type kinematic position 5 5 awake 0\n");
    (void)state;
    assert_false(pg_body_is_awake(l.w, body_at(l.w, 1)));
    assert_int_equal(pg_body_linear_velocity(l.w, body_at(l.w, 1)).x, 0); /* asleep: at rest */
    assert_false(pg_body_is_awake(l.w, body_at(l.w, 2)));
    assert_false(pg_body_is_awake(l.w, body_at(l.w, 3)));
    expect_round_trip(l.w);
    assert_int_equal(pg_world_step(l.w), PG_OK);
    PG_EXPECT_EQ(pg_body_position(l.w, body_at(l.w, 1)).y, PG_FIX_C(3), "%s", "a sleeping body does not fall");
    assert_int_equal(pg_body_set_awake(l.w, body_at(l.w, 1), 1), PG_OK);
    assert_int_equal(pg_world_step(l.w), PG_OK);
    assert_true(pg_body_position(l.w, body_at(l.w, 1)).y < PG_FIX_C(3));
    free_loaded(&l);
}

static void test_crlf_and_comments(void **state)
{
    const char *lf = "pogon-scene 1\n# comment\ngravity 0 -9.5\nbody dynamic\n  position 1 2 # trailing\n"
                     "  shape box 1 2 angle 45\nend\nball 0.25 position 3 4";
    const char *crlf = "pogon-scene 1\r\n# comment \xc2\xb2 UTF-8 is fine here\r\n\tgravity  0\t-9.5\r\nbody dynamic\r\n"
                       "  position 1 2 #trailing\r\n  shape box 1 2 angle 45\r\nend\r\nball 0.25 position 3 4\r\n";
    loaded a = load_string(lf), b = load_string(crlf);
    size_t na, nb;
    char *ta = write_text(a.w, &na), *tb = write_text(b.w, &nb);
    (void)state;
    assert_int_equal(na, nb);
    assert_memory_equal(ta, tb, na);
    expect_same_bodies(a.w, b.w);
    free(ta);
    free(tb);
    free_loaded(&a);
    free_loaded(&b);
}

static void test_write_truncates_like_snprintf(void **state)
{
    size_t size, n, cap;
    char *text = read_file("shapes.scene", &size);
    loaded l = load_text(text, size);
    char *full = write_text(l.w, &n);
    char small[64];
    (void)state;
    assert_int_equal(pg_scene_write(l.w, NULL, 0), n);
    assert_int_equal(pg_scene_write(NULL, small, sizeof small), 0);
    assert_int_equal(small[0], '\0');
    for (cap = 1; cap <= sizeof small; ++cap) {
        memset(small, 'x', sizeof small);
        assert_int_equal(pg_scene_write(l.w, small, cap), n);
        assert_int_equal(small[cap - 1], '\0');
        assert_memory_equal(small, full, cap - 1);
        if (cap < sizeof small) assert_int_equal(small[cap], 'x'); /* nothing past capacity */
    }
    free(full);
    free_loaded(&l);
    free(text);
}

/* ---- errors -------------------------------------------------------------------------------------------- */
typedef struct bad_case {
    const char *text;
    pg_result result;
    uint32_t line, column;
    const char *message; /* a part of the message */
} bad_case;

static void expect_error(const char *text, size_t size, pg_result want, uint32_t line, uint32_t column, const char *part)
{
    pg_world_def def = pg_default_world_def(), before = def;
    pg_scene_error err;
    pg_result r = pg_scene_read_def(text, size, &def, &err);
    char prefix[64];
    if (r != want || err.line != line || err.column != column || strstr(err.message, part) == NULL) {
        print_error("input %.60s...\n  got %s line %u column %u '%s'\n  want %s line %u column %u '...%s...'\n", text,
                    pg_result_name(r), err.line, err.column, err.message, pg_result_name(want), line, column, part);
        fail();
    }
    snprintf(prefix, sizeof prefix, "line %u, column %u: ", line, column);
    assert_true(strncmp(err.message, prefix, strlen(prefix)) == 0);
    expect_same_def(&def, &before); /* untouched on failure */
    /* pg_scene_load reports the same, and makes nothing */
    {
        pg_world_def small = before;
        loaded l;
        small.max_bodies = small.max_shapes = small.max_contacts = 4; /* capacities are not compared */
        l = world_for_def(&small);
        pg_scene_error err2;
        assert_int_equal(pg_scene_load(l.w, text, size, &err2), want);
        assert_int_equal(err2.line, line);
        assert_int_equal(err2.column, column);
        assert_string_equal(err2.message, err.message);
        assert_int_equal(pg_world_get_stats(l.w).body_count, 0);
        free_loaded(&l);
    }
}

static void test_malformed_inputs(void **state)
{
    static const bad_case cases[] = {
        /* version line */
        {"", PG_ERR_INVALID_ARGUMENT, 1, 1, "expected 'pogon-scene 1' as the first line, got end of line"},
        {"pogon-scene 2\n", PG_ERR_INVALID_ARGUMENT, 1, 13, "unsupported version '2': this reader knows version 1"},
        {"pogon-scene\n", PG_ERR_INVALID_ARGUMENT, 1, 12, "expected the format version (1) after 'pogon-scene', got end of line"},
        {"pogon-scene 1 extra\n", PG_ERR_INVALID_ARGUMENT, 1, 15, "unexpected 'extra' after the version line"},
        {"# comment first\npogon-scene 1\n", PG_ERR_INVALID_ARGUMENT, 1, 1, "expected 'pogon-scene 1' as the first line"},
        {"pogon-scenery 1\n", PG_ERR_INVALID_ARGUMENT, 1, 1, "got 'pogon-scenery'"},
        /* keywords */
        {"pogon-scene 1\nfoo 1 2\n", PG_ERR_INVALID_ARGUMENT, 2, 1,
         "expected a setting, 'body', a ready-made kind (ball capsule box triangle star wall concave chain) or 'joint', got 'foo'"},
        {"pogon-scene 1\nbody dynamic\n  spin 3\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 3, "expected a body property, 'shape' or 'end', got 'spin'"},
        {"pogon-scene 1\nball 1 colour red\n", PG_ERR_INVALID_ARGUMENT, 2, 8, "expected a property of ball, got 'colour'"},
        {"pogon-scene 1\nbody dynamic\n  shape hexagon 1\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 9, "expected a shape kind"},
        {"pogon-scene 1\nbody sideways\nend\n", PG_ERR_INVALID_ARGUMENT, 2, 6, "expected static, kinematic or dynamic for 'body', got 'sideways'"},
        {"pogon-scene 1\nend\n", PG_ERR_INVALID_ARGUMENT, 2, 1, "'end' outside a body"},
        {"pogon-scene 1\nshape circle 1\n", PG_ERR_INVALID_ARGUMENT, 2, 1, "'shape' outside a body"},
        {"pogon-scene 1\nposition 1 2\n", PG_ERR_INVALID_ARGUMENT, 2, 1, "'position' outside a body"},
        {"pogon-scene 1\nball 1\nstep_hz 30\n", PG_ERR_INVALID_ARGUMENT, 3, 1, "world settings must come before the first body"},
        {"pogon-scene 1\nstep_hz 30\nstep_hz 60\n", PG_ERR_INVALID_ARGUMENT, 3, 1, "'step_hz' is already set on line 2"},
        {"pogon-scene 1\nball 1 position 0 0 position 1 1\n", PG_ERR_INVALID_ARGUMENT, 2, 21, "'position' is given twice for ball"},
        {"pogon-scene 1\nball 1 angle 3 angle_bits 0x10\n", PG_ERR_INVALID_ARGUMENT, 2, 16, "'angle_bits' is given twice for ball"},
        {"pogon-scene 1\nbody dynamic\n  shape segment 0 0 1 0 offset 1 1\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 25,
         "'offset' does not apply to a segment shape"},
        {"pogon-scene 1\nbody dynamic\n  shape circle 1\n  position 1 1\nend\n", PG_ERR_INVALID_ARGUMENT, 4, 3,
         "body properties must come before the body's shapes"},
        {"pogon-scene 1\nbody dynamic\nball 1\n", PG_ERR_INVALID_ARGUMENT, 3, 1, "expected 'end' to close the body of line 2 before 'ball'"},
        {"pogon-scene 1\nbody dynamic\nend now\n", PG_ERR_INVALID_ARGUMENT, 3, 5, "unexpected 'now' after 'end'"},
        {"pogon-scene 1\nwall 4 1 type dynamic\n", PG_ERR_BODY_TYPE, 2, 15, "a wall is always static"},
        {"pogon-scene 1\nbody static\n  linear_velocity 1 0\nend\n", PG_ERR_BODY_TYPE, 3, 19, "a static body has no velocity"},
        /* missing and malformed numbers */
        {"pogon-scene 1\nball 1 density abc\n", PG_ERR_INVALID_ARGUMENT, 2, 16, "expected a number for 'density', got 'abc'"},
        {"pogon-scene 1\n\n\n\n\n\n\n\n\n\n\nball 1 density abc\n", PG_ERR_INVALID_ARGUMENT, 12, 16,
         "line 12, column 16: expected a number for 'density', got 'abc'"},
        {"pogon-scene 1\nbox 1\n", PG_ERR_INVALID_ARGUMENT, 2, 6, "expected a number for 'height', got end of line"},
        {"pogon-scene 1\nball 1 position 2 # y is missing\n", PG_ERR_INVALID_ARGUMENT, 2, 18, "expected a number for 'position' (y), got end of line"},
        {"pogon-scene 1\nball 1 position 2", PG_ERR_INVALID_ARGUMENT, 2, 18, "expected a number for 'position' (y), got end of line"},
        {"pogon-scene 1\nball 1e3\n", PG_ERR_INVALID_ARGUMENT, 2, 6, "expected a number for 'radius', got '1e3'"},
        {"pogon-scene 1\nball 0,5\n", PG_ERR_INVALID_ARGUMENT, 2, 6, "got '0,5'"},
        {"pogon-scene 1\nstep_hz 6.5\n", PG_ERR_INVALID_ARGUMENT, 2, 9, "expected an integer for 'step_hz', got '6.5'"},
        {"pogon-scene 1\nball 1 mask 0xfg\n", PG_ERR_INVALID_ARGUMENT, 2, 13, "expected a hexadecimal integer for 'mask'"},
        {"pogon-scene 1\nball 1 awake yes\n", PG_ERR_INVALID_ARGUMENT, 2, 14, "expected 0 or 1 for 'awake', got 'yes'"},
        {"pogon-scene 1\neffects gravity warp\n", PG_ERR_INVALID_ARGUMENT, 2, 17, "expected a property of the world settings, got 'warp'"},
        {"pogon-scene 1\neffects\n", PG_ERR_INVALID_ARGUMENT, 2, 8, "expected all, none, an integer or effect names"},
        {"pogon-scene 1\nball 1 position 1 2 3\n", PG_ERR_INVALID_ARGUMENT, 2, 21, "got '3'"},
        /* numbers out of range */
        {"pogon-scene 1\nball 1 density 99999\n", PG_ERR_ENVELOPE, 2, 16, "number out of range for 'density': '99999'"},
        {"pogon-scene 1\nball 1 density 200\n", PG_ERR_ENVELOPE, 2, 16, "'density' is 200, outside 0..100 kg/m^2"},
        {"pogon-scene 1\nball 1 density 0.05\n", PG_ERR_ENVELOPE, 2, 16, "'density' is 0.05, outside 0.1..100 kg/m^2 (a dynamic body)"},
        {"pogon-scene 1\nball 1 position 1000.5 0\n", PG_ERR_ENVELOPE, 2, 17, "'position' is 1000.5, outside -1000..1000 m"},
        {"pogon-scene 1\nstep_hz 0\n", PG_ERR_ENVELOPE, 2, 9, "'step_hz' is 0, outside 1..1000"},
        {"pogon-scene 1\nsubsteps 17\n", PG_ERR_ENVELOPE, 2, 10, "'substeps' is 17, outside 1..16"},
        {"pogon-scene 1\nstep_hz 99999999999999999999999\n", PG_ERR_ENVELOPE, 2, 9, "integer out of range for 'step_hz'"},
        {"pogon-scene 1\nball 1 user_data 18446744073709551616\n", PG_ERR_ENVELOPE, 2, 18, "integer out of range for 'user_data'"},
        {"pogon-scene 1\nball 1 category 0x100000000\n", PG_ERR_ENVELOPE, 2, 17, "integer out of range for 'category'"},
        {"pogon-scene 1\neffects 0x80\n", PG_ERR_ENVELOPE, 2, 9, "'effects' has bits outside 0x7f"},
        {"pogon-scene 1\ncontact_hertz 0\n", PG_ERR_ENVELOPE, 2, 15, "'contact_hertz' is 0, outside (0, 1000] Hz"},
        {"pogon-scene 1\nmax_linear_speed 10\nball 1 linear_velocity 8 8\n", PG_ERR_ENVELOPE, 3, 24, "above max_linear_speed 10"},
        {"pogon-scene 1\nball 60\n", PG_ERR_ENVELOPE, 2, 6, "the ball is outside the envelope"},
        {"pogon-scene 1\nbox 0 1\n", PG_ERR_DEGENERATE, 2, 5, "the box is degenerate"},
        /* a moving body's shapes reach 50 m from its origin, a static body's 1000 m */
        {"pogon-scene 1\nbox 120 1\n", PG_ERR_ENVELOPE, 2, 5, "the box reaches 60 m from its body's origin, beyond 50 m"},
        {"pogon-scene 1\nbody kinematic\n  shape box 120 1\nend\n", PG_ERR_ENVELOPE, 3, 9, "the box reaches 60 m"},
        {"pogon-scene 1\nwall 2000.5 1\n", PG_ERR_ENVELOPE, 2, 6, "the wall is outside the envelope"},
        {"pogon-scene 1\nbox 1 0.009\n", PG_ERR_ENVELOPE, 2, 5, "the box is outside the envelope"},
        /* mass data a dynamic body cannot have (pg__mass_data_problem), checked as loading
         * will: for a ready-made body, and for each shape of a body block in turn */
        {"pogon-scene 1\nbox 100 100 density 100\n", PG_ERR_ENVELOPE, 2, 5,
         "line 2, column 5: cannot make the box: the body's inertia would exceed 1.3e8 kg m^2"},
        {"pogon-scene 1\nbody dynamic\n  shape box 100 100 density 100\nend\n", PG_ERR_ENVELOPE, 3, 9,
         "cannot add the box to the body of line 2: the body's inertia would exceed 1.3e8 kg m^2"},
        {"pogon-scene 1\nbody dynamic\n  shape box 50 50 offset -25 0 density 100\n  shape box 50 50 offset 25 0 density 100\nend\n",
         PG_ERR_ENVELOPE, 4, 9, "cannot add the box to the body of line 2: the body's inertia would exceed"},
        {"pogon-scene 1\ntriangle 0.025 density 0.1\n", PG_ERR_ENVELOPE, 2, 10,
         "cannot make the triangle: the body's inertia would be below 3.0e-8 kg m^2"},
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 0.012 0 0.006 0.0104 density 100\n  shape circle 1 offset 5 0\nend\n",
         PG_ERR_ENVELOPE, 3, 9, "cannot add the polygon to the body of line 2: the body would be too compact"},
        /* polygons */
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 1 0\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 9,
         "a polygon needs 3 to 8 vertices (x y pairs), got 2"},
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 1 0 2 1 2 2 1 3 0 3 -1 2 -1 1 -0.5 0.5\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 51,
         "a polygon has at most 8 vertices; this is vertex 9"},
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 2 0 1 0.5 2 2 0 2\nend\n", PG_ERR_NOT_CONVEX, 3, 9, "the polygon is not convex"},
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 1 1 2 2\nend\n", PG_ERR_DEGENERATE, 3, 9, "the polygon is degenerate"},
        {"pogon-scene 1\nbody dynamic\n  shape polygon 0 0 1 0 1\nend\n", PG_ERR_INVALID_ARGUMENT, 3, 26,
         "expected a number for 'polygon' (vertex 3 y), got end of line"},
        /* capacities */
        {"pogon-scene 1\nmax_bodies 2\nball 1\nball 1 position 3 0\nball 1 position 6 0\n", PG_ERR_CAPACITY, 5, 1,
         "body 3 is beyond max_bodies 2 (line 2)"},
        {"pogon-scene 1\nmax_shapes 2\nball 1\nstar 1 position 3 0\n", PG_ERR_CAPACITY, 4, 1, "shape 3 is beyond max_shapes 2"},
        {"pogon-scene 1\nmax_shapes 1\nbody dynamic\n  shape circle 1\n  shape circle 1 offset 1 0\nend\n", PG_ERR_CAPACITY, 5, 1,
         "shape 2 is beyond max_shapes 1"},
        /* truncated text */
        {"pogon-scene 1\nbody dynamic\n  shape circle 1", PG_ERR_INVALID_ARGUMENT, 3, 17, "expected 'end' to close the body of line 2, got end of file"},
        {"pogon-scene 1\nbody dynamic\n", PG_ERR_INVALID_ARGUMENT, 3, 1, "expected 'end' to close the body of line 2, got end of file"},
        {"pogon-scene 1\nbody dynamic\n  shape capsule 0 0 1", PG_ERR_INVALID_ARGUMENT, 3, 22, "expected a number for 'capsule' (y2), got end of line"},
        /* bytes that are not text */
        {"pogon-scene 1\nball 1\x01\n", PG_ERR_INVALID_ARGUMENT, 2, 7, "unexpected byte 0x01: a scene file is ASCII text"},
        {"pogon-scene 1\nball \xff\xfe\n", PG_ERR_INVALID_ARGUMENT, 2, 6, "unexpected byte 0xff"},
        {"\x7f" "ELF\x02\x01\x01", PG_ERR_INVALID_ARGUMENT, 1, 1, "unexpected byte 0x7f"},
        {"pogon-scene 1\x0b\n", PG_ERR_INVALID_ARGUMENT, 1, 14, "unexpected byte 0x0b"},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        expect_error(cases[i].text, strlen(cases[i].text), cases[i].result, cases[i].line, cases[i].column, cases[i].message);
    /* a NUL byte is not text either, and the length, not the NUL, ends the text */
    expect_error("pogon-scene 1\nball 1\0 2\n", 22, PG_ERR_INVALID_ARGUMENT, 2, 7, "unexpected byte 0x00");
    expect_error("pogon-scene 1\nball 1 position 2 3\n", 31, PG_ERR_INVALID_ARGUMENT, 2, 18, "(y), got end of line");
}

/* Mass checks that depend on the body: a body with fixed rotation has no inverse
 * inertia, so a tiny or compact one is fine; static and kinematic bodies have no mass.
 * Whatever pg_scene_read_def accepts, pg_scene_load makes. */
static void test_mass_checked_like_the_world(void **state)
{
    static const char *const fine[] = {
        "pogon-scene 1\ntriangle 0.025 density 0.1 fixed_rotation 1\n",
        "pogon-scene 1\nbody dynamic\n  fixed_rotation 1\n  shape polygon 0 0 0.012 0 0.006 0.0104 density 100\nend\n",
        "pogon-scene 1\nbox 100 100 density 100 type kinematic\n",
        "pogon-scene 1\nbody static\n  shape box 100 100 density 100\nend\n",
        "pogon-scene 1\nbox 50 50 density 100\n",
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof fine / sizeof fine[0]; ++i) {
        pg_world_def def;
        pg_scene_error err;
        loaded l;
        if (pg_scene_read_def(fine[i], strlen(fine[i]), &def, &err) != PG_OK) fail_msg("%s: %s", fine[i], err.message);
        l = world_for_def(&def);
        if (pg_scene_load(l.w, fine[i], strlen(fine[i]), &err) != PG_OK) fail_msg("%s: load: %s", fine[i], err.message);
        assert_int_equal(pg_world_get_stats(l.w).body_count, 1);
        free_loaded(&l);
    }
}

static void test_null_arguments(void **state)
{
    pg_world_def def;
    pg_scene_error err;
    loaded l = load_string("pogon-scene 1\n");
    (void)state;
    assert_int_equal(pg_scene_read_def(NULL, 0, &def, &err), PG_ERR_NULL);
    assert_int_equal(err.line, 0);
    assert_string_equal(err.message, "text is NULL");
    assert_int_equal(pg_scene_read_def("pogon-scene 1", 13, NULL, &err), PG_ERR_NULL);
    assert_int_equal(pg_scene_read_def("pogon-scene 1", 13, &def, NULL), PG_OK);
    assert_int_equal(pg_scene_read_def("junk", 4, &def, NULL), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_scene_load(NULL, "pogon-scene 1", 13, &err), PG_ERR_NULL);
    assert_int_equal(pg_scene_load(l.w, NULL, 0, &err), PG_ERR_NULL);
    assert_int_equal(pg_scene_load(l.w, "pogon-scene 1\nball 1", 20, NULL), PG_OK);
    /* an empty scene: capacities of at least one */
    assert_int_equal(pg_scene_read_def("pogon-scene 1", 13, &def, &err), PG_OK);
    assert_int_equal(def.max_bodies, 1);
    assert_int_equal(def.max_shapes, 1);
    assert_int_equal(def.max_contacts, 64);
    free_loaded(&l);
}

static void test_load_needs_matching_world(void **state)
{
    const char *text = "pogon-scene 1\nstep_hz 30\nball 1\nball 1 position 3 0\nball 1 position 6 0\n";
    pg_world_def def;
    pg_scene_error err;
    loaded l;
    (void)state;
    /* a world with other settings */
    def = pg_default_world_def();
    l = world_for_def(&def);
    assert_int_equal(pg_scene_load(l.w, text, strlen(text), &err), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(err.line, 2);
    assert_int_equal(err.column, 1);
    assert_non_null(strstr(err.message, "the world's step_hz differs from the scene's"));
    assert_int_equal(pg_world_get_stats(l.w).body_count, 0);
    free_loaded(&l);
    /* a default the scene relies on */
    def = pg_default_world_def();
    def.step_hz = 30;
    def.substeps = 2;
    l = world_for_def(&def);
    assert_int_equal(pg_scene_load(l.w, text, strlen(text), &err), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(err.line, 1);
    assert_non_null(strstr(err.message, "substeps differs from the default the scene uses"));
    free_loaded(&l);
    /* too small a world: refused before anything is made, naming the first body that
     * does not fit */
    assert_int_equal(pg_scene_read_def(text, strlen(text), &def, &err), PG_OK);
    assert_int_equal(def.max_bodies, 3);
    def.max_bodies = 2;
    l = world_for_def(&def);
    {
        uint64_t h = pg_world_hash(l.w);
        assert_int_equal(pg_scene_load(l.w, text, strlen(text), &err), PG_ERR_CAPACITY);
        assert_int_equal(err.line, 5);
        assert_int_equal(err.column, 1);
        assert_string_equal(err.message, "line 5, column 1: body 3 of the scene does not fit: the world has 2 free body slots of max_bodies 2, the scene needs 3");
        assert_int_equal(pg_world_get_stats(l.w).body_count, 0);
        assert_true(pg_world_hash(l.w) == h);
    }
    free_loaded(&l);
    /* a body block that does not fit is not begun */
    {
        const char *two = "pogon-scene 1\nmax_shapes 2\nbody dynamic\n  shape circle 1\n  shape circle 1 offset 1 0\nend\n";
        assert_int_equal(pg_scene_read_def(two, strlen(two), &def, &err), PG_OK);
        def.max_shapes = 1;
        l = world_for_def(&def);
        assert_int_equal(pg_scene_load(l.w, two, strlen(two), &err), PG_ERR_CAPACITY);
        assert_int_equal(err.line, 5);
        assert_non_null(strstr(err.message, "shape 2 of the scene does not fit: the world has 1 free shape slots of max_shapes 1"));
        assert_int_equal(pg_world_get_stats(l.w).body_count, 0);
        assert_int_equal(pg_world_get_stats(l.w).shape_count, 0);
        free_loaded(&l);
    }
    /* loading into a world that already holds bodies: the free slots count, and a load
     * that does not fit leaves the earlier loads as they were */
    {
        const char *three = "pogon-scene 1\nball 1\nstar 1 position 3 0\nbox 1 1 position 6 0\n";
        uint64_t h;
        assert_int_equal(pg_scene_read_def(three, strlen(three), &def, &err), PG_OK);
        def.max_bodies = 8;
        def.max_shapes = 16;
        l = world_for_def(&def);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_OK);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_OK);
        h = pg_world_hash(l.w);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_ERR_CAPACITY); /* body 3 of 3 */
        assert_int_equal(err.line, 4);
        assert_non_null(strstr(err.message, "body 3 of the scene does not fit: the world has 2 free body slots of max_bodies 8"));
        assert_int_equal(pg_world_get_stats(l.w).body_count, 6);
        assert_true(pg_world_hash(l.w) == h);
        free_loaded(&l);
        def.max_bodies = 9;
        def.max_shapes = 10;
        l = world_for_def(&def);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_OK);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_OK);
        h = pg_world_hash(l.w);
        assert_int_equal(pg_scene_load(l.w, three, strlen(three), &err), PG_ERR_CAPACITY); /* the star's second shape */
        assert_int_equal(err.line, 3);
        assert_non_null(strstr(err.message, "shape 3 of the scene does not fit: the world has 2 free shape slots of max_shapes 10"));
        assert_int_equal(pg_world_get_stats(l.w).body_count, 6);
        assert_int_equal(pg_world_get_stats(l.w).shape_count, 8);
        assert_true(pg_world_hash(l.w) == h);
        free_loaded(&l);
    }
}

static void test_every_prefix_is_handled(void **state)
{
    /* every prefix of a scene (a file cut anywhere) is read without reading past its
     * end (each in a buffer of exactly that size) and gives a result with a position */
    size_t size, n;
    char *text = read_file("shapes.scene", &size);
    (void)state;
    for (n = 0; n <= size; ++n) {
        char *cut = malloc(n > 0 ? n : 1);
        pg_world_def def;
        pg_scene_error err;
        pg_result r;
        assert_non_null(cut);
        memcpy(cut, text, n);
        r = pg_scene_read_def(cut, n, &def, &err);
        if (r != PG_OK) {
            assert_true(err.line >= 1 && err.column >= 1);
            assert_true(strlen(err.message) < sizeof err.message);
        }
        free(cut);
    }
    free(text);
}

static void test_random_bytes_never_crash(void **state)
{
    /* garbage and mutated scenes: any result, never a crash (the fuzzer does more) */
    pgt_rng rng = pgt_rng_seed(42);
    size_t size;
    char *text = read_file("shapes.scene", &size);
    int round;
    (void)state;
    for (round = 0; round < 1500; ++round) {
        size_t n = (size_t)(pgt_next(&rng) % (size + 1)), k;
        char *buf = malloc(n > 0 ? n : 1);
        pg_world_def def;
        pg_scene_error err;
        assert_non_null(buf);
        memcpy(buf, text, n);
        for (k = 0; k < 1 + pgt_next(&rng) % 4; ++k)
            if (n > 0) buf[pgt_next(&rng) % n] = (char)(pgt_next(&rng) & 0xFF);
        if (pg_scene_read_def(buf, n, &def, &err) == PG_OK) {
            loaded l = world_for_def(&def);
            assert_int_equal(pg_scene_load(l.w, buf, n, &err), PG_OK);
            expect_round_trip(l.w);
            free_loaded(&l);
        }
        free(buf);
    }
    free(text);
}

/* ---- numbers and angles ------------------------------------------------------------------------------------ */
static void test_angle_conversion_exact(void **state)
{
    pgt_rng rng = pgt_rng_seed(7);
    int i;
    (void)state;
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(90)), PG_ANGLE_QUARTER);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(45)), 0x20000000u);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(180)), PG_ANGLE_HALF);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(-180)), PG_ANGLE_HALF);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(-90)), 0xC0000000u);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(360)), 0u);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(450)), PG_ANGLE_QUARTER);
    assert_int_equal(pg_scene_angle_from_degrees(PG_FIX_C(-720)), 0u);
    assert_int_equal(pg_scene_angle_from_degrees(0), 0u);
    /* against a 128-bit reference: round(deg * 2^32 / 360), ties away from zero */
    for (i = 0; i < 200000; ++i) {
        pg_fix d = (pg_fix)(int32_t)(uint32_t)pgt_next(&rng);
        pgt_i128 x = (pgt_i128)d * 65536, mag = x < 0 ? -x : x, q = (mag + 180) / 360;
        uint32_t want = (uint32_t)(uint64_t)(x < 0 ? -q : q);
        if (d == INT32_MIN) continue;
        PG_EXPECT_EQ(pg_scene_angle_from_degrees(d), want, "degrees bits %d", d);
    }
    /* through a file */
    {
        loaded l = load_string("pogon-scene 1\nball 1 angle 90\nball 1 position 3 0 angle 45\nball 1 position 6 0 angle -45\n"
                               "ball 1 position 9 0 angle 0.5\nball 1 position 12 0 angle_bits 0xdeadbeef\n");
        assert_int_equal(pg_body_angle(l.w, body_at(l.w, 0)), PG_ANGLE_QUARTER);
        assert_int_equal(pg_body_angle(l.w, body_at(l.w, 1)), 0x20000000u);
        assert_int_equal(pg_body_angle(l.w, body_at(l.w, 2)), 0xE0000000u);
        assert_int_equal(pg_body_angle(l.w, body_at(l.w, 3)), 5965232u); /* round(2^32 / 720) */
        assert_int_equal(pg_body_angle(l.w, body_at(l.w, 4)), 0xDEADBEEFu);
        free_loaded(&l);
    }
}

static void test_numbers_exact(void **state)
{
    /* decimal text -> the correctly rounded Q16.16 value, whatever its length */
    loaded l = load_string("pogon-scene 1\ngravity 0.1 -9.80665\n"
                           "ball 0.333333333333333333333333333333 position -.5 +7. user_data 0xFFFFFFFFFFFFFFFF\n");
    pg_world_def d = pg_world_get_def(l.w);
    pg_geometry g;
    pg_shape_id s;
    (void)state;
    assert_int_equal(d.gravity.x, 6554);      /* round(0.1 * 65536) */
    assert_int_equal(d.gravity.y, -642689);   /* round(9.80665 * 65536) = 642689.3 */
    assert_int_equal(pg_body_shapes(l.w, body_at(l.w, 0), &s, 1), 1);
    assert_int_equal(pg_shape_geometry(l.w, s, &g), PG_OK);
    assert_int_equal(g.radius, 21845);        /* round(65536 / 3) */
    assert_int_equal(pg_body_position(l.w, body_at(l.w, 0)).x, -PG_FIX_HALF);
    assert_int_equal(pg_body_position(l.w, body_at(l.w, 0)).y, PG_FIX_C(7));
    assert_true(pg_body_user_data(l.w, body_at(l.w, 0)) == UINT64_MAX);
    free_loaded(&l);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped_scenes_load),
        cmocka_unit_test(test_shapes_scene_has_everything),
#ifdef POGON_HAVE_SCENES
        cmocka_unit_test(test_pyramid_matches_tools_scene),
#endif
        cmocka_unit_test(test_round_trip_shipped),
        cmocka_unit_test(test_contact_events_setting),
        cmocka_unit_test(test_round_trip_after_steps),
        cmocka_unit_test(test_round_trip_edited_world),
        cmocka_unit_test(test_sleeping_body_round_trip),
        cmocka_unit_test(test_crlf_and_comments),
        cmocka_unit_test(test_write_truncates_like_snprintf),
        cmocka_unit_test(test_malformed_inputs),
        cmocka_unit_test(test_mass_checked_like_the_world),
        cmocka_unit_test(test_null_arguments),
        cmocka_unit_test(test_load_needs_matching_world),
        cmocka_unit_test(test_every_prefix_is_handled),
        cmocka_unit_test(test_random_bytes_never_crash),
        cmocka_unit_test(test_angle_conversion_exact),
        cmocka_unit_test(test_numbers_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
