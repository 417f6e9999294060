/* fuzz_api.c — libFuzzer target for the public API: the input is a program of calls.
 *
 * Each operation takes one byte to choose what to do and as many more as it needs for
 * its values (an exhausted input reads zeros): a command of any kind (pg_command_apply,
 * fields drawn from ordinary values, the envelope's edges and raw bits, handles live,
 * stale or zero), a joint call (pogon/joint.h: a create of any kind, a setter, a
 * destroy), a step, or a check. After every operation:
 *   - a call that failed left the state hash as it was (pogon.h: "A failing call leaves
 *     the world unchanged");
 *   - every live body's velocities are within the caps and their setters accept them
 *     back, and so does pg_body_set_transform its pose while it is inside the envelope;
 * and on the check operations:
 *   - a snapshot restored into a second world gives the same hash, and both worlds give
 *     the same hash after the next step;
 *   - a written scene loads, and the loaded world writes the same text.
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
static uint8_t snapshot[1u << 18];
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

static pg_command command(input *in, const pg_body_id *ids, uint32_t n)
{
    pg_command c = pg_command_init((pg_command_kind)(1u + next8(in) % (PG_CMD_KIND_COUNT - 1u)));
    uint32_t g = next8(in);
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
    switch (g % 4u) {
    case 0: (void)pg_geometry_circle(vec(in), value(in), &c.geometry); break;
    case 1: (void)pg_geometry_capsule(vec(in), vec(in), value(in), &c.geometry); break;
    case 2: (void)pg_geometry_triangle(vec(in), value(in), next32(in), &c.geometry); break;
    default: (void)pg_geometry_box(value(in), value(in), vec(in), next32(in), &c.geometry); break;
    }
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

/* Every live body's state is one the setters accept back. */
static void check_getters_accepted(pg_world *w, const pg_body_id *ids, uint32_t n)
{
    uint32_t i;
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
    pg_world *b = NULL;
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
    while (in.pos < in.size && ops++ < 200u) {
        uint32_t op = next8(&in);
        if (op >= 180 && op < 200) {
            uint64_t before = pg_world_hash(w);
            pg_joint_id made = {0, 0};
            pg_result r = joint_call(&in, w, ids, n, joints, nj, &made);
            if (r != PG_OK) {
                check(pg_world_hash(w) == before, "a failing joint call changed the world", pg_world_last_error(w));
            } else if (made.generation != 0) {
                if (nj < 8u) joints[nj++] = made;
                else joints[made.index % 8u] = made;
            }
        } else if (op < 200) {
            pg_command c = command(&in, ids, n);
            uint64_t before = pg_world_hash(w);
            pg_body_id made = {0, 0};
            pg_result r = pg_command_apply(w, &c, &made);
            if (r != PG_OK) {
                check(pg_world_hash(w) == before, "a failing call changed the world", pg_world_last_error(w));
            } else if (made.generation != 0) {
                if (n < 32u) ids[n++] = made;
                else ids[made.index % 32u] = made;
            }
        } else if (op < 240) {
            uint32_t k, steps = 1u + op % 8u;
            for (k = 0; k < steps; ++k) check(pg_world_step(w) == PG_OK, "step failed", pg_world_last_error(w));
        } else if (op < 250) {
            check_snapshot(w, &d);
        } else {
            check_scene(w, ids, n);
        }
        check_getters_accepted(w, ids, n);
    }
    return 0;
}
