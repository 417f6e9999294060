/* fuzz_api.c — libFuzzer target for the public API: the input is a program of calls.
 *
 * Each operation takes one byte to choose what to do and as many more as it needs for
 * its values (an exhausted input reads zeros): a command of any kind (pg_command_apply,
 * fields drawn from ordinary values, the envelope's edges and raw bits, handles live,
 * stale or zero; geometry of every kind, degenerate or filled in by hand), a joint call
 * (pogon/joint.h: a create of any kind, a setter, a destroy), a shape destroyed, a query
 * of every kind, a step, a snapshot saved or restored into the running world (whole or with a byte changed), or a check. After every operation:
 *   - every result is a documented code, and a failing one has a message naming it in
 *     pg_world_last_error();
 *   - a call that failed left the state hash as it was (pogon.h: "A failing call leaves
 *     the world unchanged"), and a query changed nothing;
 *   - every live body's velocities are within the caps and their setters accept them
 *     back, and so does pg_body_set_transform its pose while it is inside the envelope,
 *     and pg_world_set_gravity / pg_world_set_effects what their getters return;
 * and on the check operations:
 *   - a snapshot restored into a second world gives the same hash, and both worlds give
 *     the same hash after the next step; one restored into the running world gives the
 *     hash it was saved with;
 *   - a written scene loads, the loaded world writes the same text, and that text read
 *     back gives the loaded world's hash.
 * Any violation aborts, which libFuzzer reports as a crash.
 *
 * Build: cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DPOGON_BUILD_FUZZ=ON
 * Run:   build-fuzz/tests/fuzz/fuzz_api -max_total_time=600 corpus/
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pogon/scene_file.h"

#define WORLD_BYTES (2u << 20)
static uint64_t memory_a[WORLD_BYTES / 8], memory_b[WORLD_BYTES / 8];
static uint64_t memory_c[WORLD_BYTES / 8];
static uint8_t snapshot[1u << 18], saved[1u << 18];
static size_t saved_size;
static uint64_t saved_hash;
static char text_a[1u << 16], text_b[1u << 16];

typedef struct input { const uint8_t *p; size_t size, pos; } input;

static uint32_t next8(input *in) { return in->pos < in->size ? in->p[in->pos++] : 0u; }
static uint32_t next32(input *in)
{
    uint32_t v = next8(in);
    v |= next8(in) << 8;
    v |= next8(in) << 16;
    return v | next8(in) << 24;
}

static void check(int ok, const char *what, const char *detail)
{
    if (!ok) {
        fprintf(stderr, "fuzz_api: %s%s%s\n", what, detail != NULL ? ": " : "", detail != NULL ? detail : "");
        abort();
    }
}

/* An ordinary value, one at an edge of the envelope (either sign), or raw bits. */
static pg_fix value(input *in)
{
    static const pg_fix edges[] = {0, 1, 328, 1637, 1638, 3277, 6553, 6554, 32768, 65536, 655360, 655361,
                                   3276800, 3276801, 6553600, 6553601, 26214400, 26214401, 65536000, 65536001,
                                   268435456, 536870912, INT32_MAX};
    uint32_t k = next8(in);
    if (k < 128) return (pg_fix)((k & 15u) + 1u) * 16384; /* 0.25 .. 4 */
    if (k < 240) {
        pg_fix e = edges[(k - 128u) % (sizeof edges / sizeof edges[0])];
        return (k & 1u) ? -e : e;
    }
    return (pg_fix)next32(in);
}

static pg_vec2 vec(input *in)
{
    pg_vec2 v;
    v.x = value(in);
    v.y = value(in);
    return v;
}

static pg_body_id body(input *in, const pg_body_id *ids, uint32_t n)
{
    uint32_t k = next8(in);
    pg_body_id id = {0, 0};
    if (n == 0 || k >= 240) { /* raw */
        id.index = k & 15u;
        id.generation = next8(in);
        return id;
    }
    id = ids[k % n];
    if (k >= 224) id.generation += 1u; /* stale */
    return id;
}

/* A result is one of the documented codes; a failure names itself in the world's message. */
static void check_result(const pg_world *w, pg_result r, const char *call)
{
    const char *name = pg_result_name(r), *message = pg_result_message(r);
    check((unsigned)r < PG_RESULT_COUNT, "an undocumented result code", call);
    check(message != NULL && message[0] != '\0', "a result code without a message", call);
    if (r != PG_OK)
        check(strncmp(pg_world_last_error(w), name, strlen(name)) == 0, "the last error does not name the result",
              pg_world_last_error(w));
}

/* Geometry of any kind: from the constructors (which may refuse, leaving what the
 * previous one wrote) or filled in by hand with any kind, count and radius. */
static void geometry(input *in, pg_geometry *g)
{
    pg_vec2 v[PG_MAX_VERTICES + 1];
    uint32_t k = next8(in), i, count;
    memset(g, 0, sizeof *g);
    switch (k % 7u) {
    case 0: (void)pg_geometry_circle(vec(in), value(in), g); break;
    case 1: (void)pg_geometry_capsule(vec(in), vec(in), value(in), g); break;
    case 2: (void)pg_geometry_triangle(vec(in), value(in), next32(in), g); break;
    case 3: (void)pg_geometry_segment(vec(in), vec(in), g); break;
    case 4:
        count = next8(in) % (PG_MAX_VERTICES + 2u);
        for (i = 0; i < count; ++i) v[i] = (next8(in) & 1u) && i > 0 ? v[i - 1] : vec(in); /* repeats too */
        (void)pg_geometry_polygon(v, (int32_t)count, g);
        break;
    case 5: /* by hand */
        g->kind = (pg_shape_kind)(next8(in) % 6u);
        g->count = (k & 8u) ? (int32_t)next32(in) : (int32_t)(next8(in) % (PG_MAX_VERTICES + 2u));
        for (i = 0; i < PG_MAX_VERTICES; ++i) g->vertices[i] = vec(in);
        g->radius = value(in);
        break;
    default: (void)pg_geometry_box(value(in), value(in), vec(in), next32(in), g); break;
    }
}

static pg_command command(input *in, const pg_body_id *ids, uint32_t n)
{
    pg_command c = pg_command_init((pg_command_kind)(1u + next8(in) % (PG_CMD_KIND_COUNT - 1u)));
    c.body = body(in, ids, n);
    c.body_def = pg_default_body_def();
    c.body_def.type = (pg_body_type)(next8(in) % 4u); /* 3: invalid */
    c.body_def.position = vec(in);
    if (c.body_def.type != PG_BODY_STATIC) {
        c.body_def.linear_velocity = vec(in);
        c.body_def.angular_velocity = value(in);
    }
    c.body_def.fixed_rotation = (int)(next8(in) & 1u);
    c.shape_def = pg_default_shape_def();
    c.shape_def.density = value(in);
    c.shape_def.friction = value(in);
    c.shape_def.restitution = value(in) & 0x1FFFF;
    c.make_kind = (pg_make_kind)(next8(in) % (PG_MAKE_KIND_COUNT + 1u));
    c.size0 = value(in);
    c.size1 = value(in);
    geometry(in, &c.geometry);
    c.vec = vec(in);
    c.point = vec(in);
    c.scalar = value(in);
    c.scalar2 = value(in);
    c.angle = next32(in);
    c.value = next8(in) % 4u;
    c.value2 = next32(in);
    if (c.kind == PG_CMD_SET_EFFECTS || c.kind == PG_CMD_SET_FILTER) c.value = next32(in);
    if (c.kind == PG_CMD_SET_EFFECTS) c.value &= 0xFFu;
    c.flag = next8(in) % 3u;
    c.user_data = next32(in);
    return c;
}

static pg_joint_id joint(input *in, const pg_joint_id *ids, uint32_t n)
{
    uint32_t k = next8(in);
    pg_joint_id id = {0, 0};
    if (n == 0 || k >= 240) { /* raw */
        id.index = k & 7u;
        id.generation = next8(in);
        return id;
    }
    id = ids[k % n];
    if (k >= 224) id.generation += 1u; /* stale */
    return id;
}

/* One joint call; returns its result and the joint it made in *made (if any). */
static pg_result joint_call(input *in, pg_world *w, const pg_body_id *bodies, uint32_t nb, const pg_joint_id *joints, uint32_t nj,
                            pg_joint_id *made)
{
    uint32_t k = next8(in) % 12u;
    pg_joint_id j = joint(in, joints, nj);
    switch (k) {
    case 0: {
        pg_distance_joint_def d = pg_default_distance_joint_def();
        d.body_a = body(in, bodies, nb);
        d.body_b = body(in, bodies, nb);
        d.local_anchor_a = vec(in);
        d.local_anchor_b = vec(in);
        d.length = value(in);
        d.enable_spring = (int)(next8(in) & 1u);
        d.hertz = value(in);
        d.damping_ratio = value(in);
        d.enable_limit = (int)(next8(in) & 1u);
        d.min_length = value(in);
        d.max_length = value(in);
        d.collide_connected = (int)(next8(in) & 1u);
        return pg_distance_joint_create(w, &d, made);
    }
    case 1: {
        pg_revolute_joint_def d = pg_default_revolute_joint_def();
        d.body_a = body(in, bodies, nb);
        d.body_b = body(in, bodies, nb);
        d.local_anchor_a = vec(in);
        d.local_anchor_b = vec(in);
        d.reference_angle = next32(in);
        d.enable_limit = (int)(next8(in) & 1u);
        d.lower_angle = value(in);
        d.upper_angle = value(in);
        d.enable_motor = (int)(next8(in) & 1u);
        d.motor_speed = value(in);
        d.max_motor_torque = value(in);
        return pg_revolute_joint_create(w, &d, made);
    }
    case 2: {
        pg_weld_joint_def d = pg_default_weld_joint_def();
        d.body_a = body(in, bodies, nb);
        d.body_b = body(in, bodies, nb);
        d.local_anchor_a = vec(in);
        d.local_anchor_b = vec(in);
        d.reference_angle = next32(in);
        d.linear_hertz = value(in);
        d.angular_hertz = value(in);
        d.linear_damping_ratio = value(in);
        d.angular_damping_ratio = value(in);
        return pg_weld_joint_create(w, &d, made);
    }
    case 3: {
        pg_prismatic_joint_def d = pg_default_prismatic_joint_def();
        d.body_a = body(in, bodies, nb);
        d.body_b = body(in, bodies, nb);
        d.local_anchor_a = vec(in);
        d.local_anchor_b = vec(in);
        d.local_axis_a = vec(in);
        d.enable_limit = (int)(next8(in) & 1u);
        d.lower_translation = value(in);
        d.upper_translation = value(in);
        d.enable_motor = (int)(next8(in) & 1u);
        d.motor_speed = value(in);
        d.max_motor_force = value(in);
        return pg_prismatic_joint_create(w, &d, made);
    }
    case 4: {
        pg_mouse_joint_def d = pg_default_mouse_joint_def();
        d.body = body(in, bodies, nb);
        d.target = vec(in);
        d.hertz = value(in);
        d.damping_ratio = value(in);
        d.max_force = value(in);
        return pg_mouse_joint_create(w, &d, made);
    }
    case 5: return pg_joint_destroy(w, j);
    case 6: return pg_revolute_joint_set_motor(w, j, (int)(next8(in) & 1u), value(in), value(in));
    case 7: return (next8(in) & 1u) ? pg_revolute_joint_set_limits(w, j, 1, value(in), value(in))
                                    : pg_prismatic_joint_set_limits(w, j, 1, value(in), value(in));
    case 8: return (next8(in) & 1u) ? pg_distance_joint_set_length(w, j, value(in))
                                    : pg_distance_joint_set_spring(w, j, 1, value(in), value(in));
    case 9: return (next8(in) & 1u) ? pg_mouse_joint_set_target(w, j, vec(in)) : pg_mouse_joint_set_max_force(w, j, value(in));
    case 10: return pg_joint_set_collide_connected(w, j, (int)(next8(in) & 1u));
    default: return pg_weld_joint_set_softness(w, j, value(in), value(in), value(in), value(in));
    }
}

/* Every live body's state is one the setters accept back, and so is the world's. */
static void check_getters_accepted(pg_world *w, const pg_body_id *ids, uint32_t n)
{
    uint32_t i;
    uint64_t before = pg_world_hash(w);
    check(pg_world_set_gravity(w, pg_world_gravity(w)) == PG_OK, "gravity refused back", pg_world_last_error(w));
    check(pg_world_set_effects(w, pg_world_effects(w)) == PG_OK, "effects refused back", pg_world_last_error(w));
    check(pg_world_hash(w) == before, "setting the world's own gravity and effects changed it", NULL);
    for (i = 0; i < n; ++i) {
        pg_body_id b = ids[i];
        if (!pg_body_is_valid(w, b)) continue;
        if (pg_body_type_of(w, b) != PG_BODY_STATIC) {
            check(pg_body_set_linear_velocity(w, b, pg_body_linear_velocity(w, b)) == PG_OK, "linear velocity refused back",
                  pg_world_last_error(w));
            check(pg_body_set_angular_velocity(w, b, pg_body_angular_velocity(w, b)) == PG_OK, "angular velocity refused back",
                  pg_world_last_error(w));
        }
        if ((pg_body_limits(w, b) & PG_BODY_LIMIT_OUTSIDE) == 0)
            check(pg_body_set_transform(w, b, pg_body_position(w, b), pg_body_angle(w, b)) == PG_OK, "pose refused back",
                  pg_world_last_error(w));
    }
}

/* Destroy one of a body's shapes, or a stale or made-up shape handle. */
static void destroy_shape(input *in, pg_world *w, const pg_body_id *ids, uint32_t n)
{
    pg_shape_id shapes[8], s = {0, 0};
    pg_body_id b = body(in, ids, n);
    uint32_t k = next8(in), count = pg_body_shapes(w, b, shapes, 8u);
    uint64_t before = pg_world_hash(w);
    pg_result r;
    if (count > 0u) s = shapes[k % (count < 8u ? count : 8u)];
    if (k >= 200u) s.generation += 1u; /* stale */
    if (k >= 240u) s.index = next8(in);
    r = pg_shape_destroy(w, s);
    check_result(w, r, "pg_shape_destroy");
    if (r != PG_OK) check(pg_world_hash(w) == before, "a failing pg_shape_destroy changed the world", pg_world_last_error(w));
}

/* A body list from a query: distinct live bodies in ascending index order. */
static void check_listed(const pg_world *w, const pg_body_id *out, uint32_t capacity, uint32_t count)
{
    uint32_t i, shown = count < capacity ? count : capacity;
    for (i = 0; i < shown; ++i) {
        check(pg_body_is_valid(w, out[i]), "a query listed a body that does not exist", NULL);
        check(i == 0 || out[i].index > out[i - 1].index, "a query's list is not in ascending index order", NULL);
    }
}

/* A query of any kind; none changes the world. */
static void query(input *in, pg_world *w)
{
    pg_body_id out[8];
    uint32_t capacity = next8(in) % 9u, count = 0, k = next8(in);
    uint64_t before = pg_world_hash(w);
    pg_geometry g;
    pg_ray_hit hit;
    pg_aabb box;
    pg_vec2 at, free_at;
    pg_result r;
    switch (k % 5u) {
    case 0:
        r = pg_world_query_point(w, vec(in), out, capacity, &count);
        check_result(w, r, "pg_world_query_point");
        if (r == PG_OK) check_listed(w, out, capacity, count);
        break;
    case 1:
        box.lo = vec(in);
        box.hi = vec(in);
        r = pg_world_query_aabb(w, box, out, capacity, &count);
        check_result(w, r, "pg_world_query_aabb");
        if (r == PG_OK) check_listed(w, out, capacity, count);
        break;
    case 2:
        geometry(in, &g);
        at = vec(in);
        r = pg_world_query_geometry(w, &g, at, next32(in), out, capacity, &count);
        check_result(w, r, "pg_world_query_geometry");
        if (r == PG_OK) check_listed(w, out, capacity, count);
        break;
    case 3:
        geometry(in, &g);
        at = vec(in);
        r = pg_world_find_free_position(w, &g, at, next32(in), value(in), value(in), &free_at);
        check_result(w, r, "pg_world_find_free_position");
        break;
    default:
        at = vec(in);
        r = pg_world_raycast(w, at, vec(in), &hit);
        check_result(w, r, "pg_world_raycast");
        if (r == PG_OK) {
            check(hit.fraction >= 0 && hit.fraction <= PG_FIX_ONE, "a ray hit outside 0..1 of its translation", NULL);
            check(pg_body_id_equal(pg_shape_body(w, hit.shape), hit.body), "a ray hit a shape not of the body it names", NULL);
        }
        break;
    }
    check(pg_world_hash(w) == before, "a query changed the world", NULL);
}

/* Keep a snapshot of the running world, to restore later at another frame. */
static void save(const pg_world *w)
{
    if (pg_world_snapshot_save(w, saved, sizeof saved, &saved_size) != PG_OK) saved_size = 0; /* too large */
    else saved_hash = pg_world_hash(w);
}

/* Restore the kept snapshot into the running world: whole, it gives the hash it was
 * saved with; with one byte changed it is refused and the world is unchanged. */
static void restore(input *in, pg_world *w)
{
    uint32_t k = next8(in);
    uint64_t before = pg_world_hash(w);
    pg_result r;
    if (saved_size == 0) return;
    if (k < 192u) {
        r = pg_world_snapshot_restore(w, saved, saved_size);
        check_result(w, r, "pg_world_snapshot_restore");
        check(r == PG_OK, "the world's own snapshot refused", pg_world_last_error(w));
        check(pg_world_hash(w) == saved_hash, "a restored snapshot gives another hash", NULL);
    } else {
        size_t at = (size_t)next32(in) % saved_size;
        uint8_t flip = (uint8_t)(1u + next8(in) % 255u);
        saved[at] ^= flip;
        r = pg_world_snapshot_restore(w, saved, (k & 1u) ? saved_size : at); /* a changed byte, or cut short */
        saved[at] ^= flip;
        check_result(w, r, "pg_world_snapshot_restore");
        check(r != PG_OK, "a damaged snapshot was accepted", NULL);
        check(pg_world_hash(w) == before, "a refused snapshot changed the world", pg_world_last_error(w));
    }
}

static void check_snapshot(pg_world *a, const pg_world_def *d)
{
    size_t written = 0;
    pg_world *b = NULL;
    uint64_t h = pg_world_hash(a);
    if (pg_world_snapshot_save(a, snapshot, sizeof snapshot, &written) != PG_OK) return; /* too large: skip */
    check(pg_world_create(d, memory_b, sizeof memory_b, &b) == PG_OK, "second world", NULL);
    check(pg_world_snapshot_restore(b, snapshot, written) == PG_OK, "own snapshot refused", pg_world_last_error(b));
    check(pg_world_hash(b) == h, "restored hash differs", NULL);
    check(pg_world_step(a) == PG_OK && pg_world_step(b) == PG_OK, "step failed", NULL);
    check(pg_world_hash(a) == pg_world_hash(b), "next step differs after a restore", NULL);
}

static void check_scene(const pg_world *a, const pg_body_id *ids, uint32_t n)
{
    size_t len = pg_scene_write(a, text_a, sizeof text_a), len2;
    pg_world *b = NULL, *c = NULL;
    pg_scene_error e;
    pg_world_def rd;
    uint32_t i;
    if (len >= sizeof text_a) return;
    for (i = 0; i < n; ++i) /* documented: a body outside the envelope is written but refused on reading */
        if (pg_body_is_valid(a, ids[i]) && (pg_body_limits(a, ids[i]) & PG_BODY_LIMIT_OUTSIDE) != 0) return;
    check(pg_scene_read_def(text_a, len, &rd, &e) == PG_OK, "written scene does not read", e.message);
    check(pg_world_memory_size(&rd) <= sizeof memory_b && pg_world_create(&rd, memory_b, sizeof memory_b, &b) == PG_OK,
          "a world from the written scene's def", NULL);
    check(pg_scene_load(b, text_a, len, &e) == PG_OK, "written scene does not load", e.message);
    len2 = pg_scene_write(b, text_b, sizeof text_b);
    check(len2 == len && memcmp(text_a, text_b, len) == 0, "write -> load -> write changed the text", NULL);
    /* A world as a scene holds it (no contacts yet, frame 0) reads back to its own hash. */
    check(pg_world_create(&rd, memory_c, sizeof memory_c, &c) == PG_OK, "a third world from the scene's def", NULL);
    check(pg_scene_load(c, text_b, len2, &e) == PG_OK, "rewritten scene does not load", e.message);
    check(pg_world_hash(c) == pg_world_hash(b), "a scene read back gives another hash", NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    pg_world_def d = pg_default_world_def();
    pg_world *w = NULL;
    pg_body_id ids[32];
    pg_joint_id joints[8];
    uint32_t n = 0, nj = 0, ops = 0;
    input in;
    in.p = data;
    in.size = size;
    in.pos = 0;
    d.max_bodies = 16;
    d.max_shapes = 32;
    d.max_contacts = 64;
    d.max_joints = 8;
    check(pg_world_memory_size(&d) <= sizeof memory_a, "world too large for the buffer", NULL);
    check(pg_world_create(&d, memory_a, sizeof memory_a, &w) == PG_OK, "world", NULL);
    saved_size = 0;
    while (in.pos < in.size && ops++ < 200u) {
        uint32_t op = next8(&in);
        if (op >= 140 && op < 160) {
            uint64_t before = pg_world_hash(w);
            pg_joint_id made = {0, 0};
            pg_result r = joint_call(&in, w, ids, n, joints, nj, &made);
            if (r != PG_OK) {
                check(pg_world_hash(w) == before, "a failing joint call changed the world", pg_world_last_error(w));
            } else if (made.generation != 0) {
                if (nj < 8u) joints[nj++] = made;
                else joints[made.index % 8u] = made;
            }
        } else if (op < 160) {
            pg_command c = command(&in, ids, n);
            uint64_t before = pg_world_hash(w);
            pg_body_id made = {0, 0};
            pg_result r = pg_command_apply(w, &c, &made);
            check_result(w, r, "pg_command_apply");
            if (r != PG_OK) {
                check(pg_world_hash(w) == before, "a failing call changed the world", pg_world_last_error(w));
            } else if (made.generation != 0) {
                if (n < 32u) ids[n++] = made;
                else ids[made.index % 32u] = made;
            }
        } else if (op < 175) {
            destroy_shape(&in, w, ids, n);
        } else if (op < 195) {
            query(&in, w);
        } else if (op < 235) {
            uint32_t k, steps = 1u + op % 8u;
            for (k = 0; k < steps; ++k) check(pg_world_step(w) == PG_OK, "step failed", pg_world_last_error(w));
        } else if (op < 241) {
            check_snapshot(w, &d);
        } else if (op < 245) {
            save(w);
        } else if (op < 250) {
            restore(&in, w);
        } else {
            check_scene(w, ids, n);
        }
        check_getters_accepted(w, ids, n);
    }
    return 0;
}
