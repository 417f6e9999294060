/* test_commands.c — commands (include/pogon/replay.h): the canonical binary encoding,
 * decoding errors, pg_command_apply against the direct API calls, and the queue.
 *
 * The layout is docs/formats.md's ("Commands"): a u8 kind, then the fields the kind
 * uses, little-endian and fixed-width: u8 for enums, the vertex count and booleans,
 * 4 bytes for every pg_fix, angle, uint32 and each handle half, 8 for user data. The
 * order is the struct's (replay.h), except that apply_force puts its flag between the
 * force and the point (docs/formats.md: "body, vec (force), flag (1: at point), point").
 * decode(encode(c)) == c, and the fields each kind uses are those listed next to
 * pg_command_kind.
 */
#include "pg_test.h"

#include <math.h>
#include <stdlib.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pg_test_alloc.h"

static pg_fix fx(double v) { return (pg_fix)llround(v * 65536.0); }



/* The body and world commands, which this file checks field by field; the joint
 * commands (PG_CMD_CREATE_DISTANCE_JOINT on) are checked in test_joint_commands.c. */
#define BODY_COMMANDS_END PG_CMD_CREATE_DISTANCE_JOINT

/* ---- the fields each kind uses (replay.h, next to pg_command_kind) ----------------------- */
enum {
    U_BODY = 1u << 0, U_VEC = 1u << 1, U_POINT = 1u << 2, U_SCALAR = 1u << 3, U_SCALAR2 = 1u << 4,
    U_ANGLE = 1u << 5, U_VALUE = 1u << 6, U_VALUE2 = 1u << 7, U_FLAG = 1u << 8, U_USER = 1u << 9,
    U_MAKE = 1u << 10, U_BODY_DEF = 1u << 11, U_SHAPE_DEF = 1u << 12, U_GEOMETRY = 1u << 13
};

static uint32_t uses(pg_command_kind k)
{
    switch (k) {
    case PG_CMD_CREATE_BODY: return U_BODY_DEF;
    case PG_CMD_DESTROY_BODY: return U_BODY;
    case PG_CMD_ADD_SHAPE: return U_BODY | U_SHAPE_DEF | U_GEOMETRY;
    case PG_CMD_MAKE: return U_MAKE | U_BODY_DEF | U_SHAPE_DEF; /* make_kind, size0, size1 */
    case PG_CMD_SET_TRANSFORM: return U_BODY | U_VEC | U_ANGLE;
    case PG_CMD_SET_LINEAR_VELOCITY: return U_BODY | U_VEC;
    case PG_CMD_SET_ANGULAR_VELOCITY: return U_BODY | U_SCALAR;
    case PG_CMD_APPLY_FORCE: return U_BODY | U_VEC | U_POINT | U_FLAG;
    case PG_CMD_APPLY_TORQUE: return U_BODY | U_SCALAR;
    case PG_CMD_APPLY_LINEAR_IMPULSE: return U_BODY | U_VEC | U_POINT;
    case PG_CMD_APPLY_ANGULAR_IMPULSE: return U_BODY | U_SCALAR;
    case PG_CMD_SET_BODY_TYPE: return U_BODY | U_VALUE;
    case PG_CMD_SET_AWAKE: return U_BODY | U_VALUE;
    case PG_CMD_SET_GRAVITY: return U_VEC;
    case PG_CMD_SET_EFFECTS: return U_VALUE;
    case PG_CMD_SET_GRAVITY_SCALE: return U_BODY | U_SCALAR;
    case PG_CMD_SET_DAMPING: return U_BODY | U_SCALAR | U_SCALAR2;
    case PG_CMD_SET_FRICTION: return U_BODY | U_SCALAR;
    case PG_CMD_SET_RESTITUTION: return U_BODY | U_SCALAR;
    case PG_CMD_SET_DENSITY: return U_BODY | U_SCALAR;
    case PG_CMD_SET_FIXED_ROTATION: return U_BODY | U_VALUE;
    case PG_CMD_SET_FILTER: return U_BODY | U_VALUE | U_VALUE2;
    case PG_CMD_SET_USER_DATA: return U_BODY | U_USER;
    default: return 0;
    }
}

/* ---- a reference encoder that follows the documented layout ------------------------------- */
#define MAX_ITEMS 128
typedef struct ref_item { size_t offset, size; const char *name; } ref_item;
typedef struct ref_enc {
    uint8_t bytes[PG_COMMAND_ENCODED_MAX];
    size_t len;
    ref_item items[MAX_ITEMS]; /* one per field (a vec or a u64 is one field) */
    int n;
} ref_enc;

static void ref_put(ref_enc *e, uint64_t v, size_t size, const char *name)
{
    size_t i;
    assert_true(e->n < MAX_ITEMS);
    assert_true(e->len + size <= sizeof e->bytes);
    e->items[e->n].offset = e->len;
    e->items[e->n].size = size;
    e->items[e->n].name = name;
    e->n += 1;
    for (i = 0; i < size; ++i) e->bytes[e->len++] = (uint8_t)(v >> (8 * i));
}
static void ref_vec(ref_enc *e, pg_vec2 v, const char *name)
{
    ref_put(e, (uint64_t)(uint32_t)v.x | (uint64_t)(uint32_t)v.y << 32, 8, name);
}

static void ref_encode(const pg_command *c, ref_enc *e)
{
    uint32_t f = uses(c->kind);
    int32_t i;
    memset(e, 0, sizeof *e);
    ref_put(e, (uint32_t)c->kind, 1, "kind");
    /* struct order: body, vec, point, scalar, scalar2, angle, value, value2, flag,
     * user_data, make_kind, size0, size1, body_def, shape_def, geometry; the only kind
     * with a flag (apply_force) has it before its point (docs/formats.md) */
    if (f & U_BODY) { ref_put(e, c->body.index, 4, "body.index"); ref_put(e, c->body.generation, 4, "body.generation"); }
    if (f & U_VEC) ref_vec(e, c->vec, "vec");
    if (f & U_FLAG) ref_put(e, c->flag, 1, "flag");
    if (f & U_POINT) ref_vec(e, c->point, "point");
    if (f & U_SCALAR) ref_put(e, (uint32_t)c->scalar, 4, "scalar");
    if (f & U_SCALAR2) ref_put(e, (uint32_t)c->scalar2, 4, "scalar2");
    if (f & U_ANGLE) ref_put(e, c->angle, 4, "angle");
    if (f & U_VALUE) ref_put(e, c->value, 4, "value");
    if (f & U_VALUE2) ref_put(e, c->value2, 4, "value2");
    if (f & U_USER) ref_put(e, c->user_data, 8, "user_data");
    if (f & U_MAKE) {
        ref_put(e, (uint32_t)c->make_kind, 1, "make_kind");
        ref_put(e, (uint32_t)c->size0, 4, "size0");
        ref_put(e, (uint32_t)c->size1, 4, "size1");
    }
    if (f & U_BODY_DEF) {
        const pg_body_def *d = &c->body_def;
        ref_put(e, (uint32_t)d->type, 1, "body_def.type");
        ref_vec(e, d->position, "body_def.position");
        ref_put(e, d->angle, 4, "body_def.angle");
        ref_vec(e, d->linear_velocity, "body_def.linear_velocity");
        ref_put(e, (uint32_t)d->angular_velocity, 4, "body_def.angular_velocity");
        ref_put(e, (uint32_t)d->linear_damping, 4, "body_def.linear_damping");
        ref_put(e, (uint32_t)d->angular_damping, 4, "body_def.angular_damping");
        ref_put(e, (uint32_t)d->gravity_scale, 4, "body_def.gravity_scale");
        ref_put(e, (uint32_t)d->fixed_rotation, 1, "body_def.fixed_rotation");
        ref_put(e, (uint32_t)d->allow_sleep, 1, "body_def.allow_sleep");
        ref_put(e, (uint32_t)d->awake, 1, "body_def.awake");
        ref_put(e, d->user_data, 8, "body_def.user_data");
    }
    if (f & U_SHAPE_DEF) {
        const pg_shape_def *d = &c->shape_def;
        ref_put(e, (uint32_t)d->density, 4, "shape_def.density");
        ref_put(e, (uint32_t)d->friction, 4, "shape_def.friction");
        ref_put(e, (uint32_t)d->restitution, 4, "shape_def.restitution");
        ref_put(e, d->category, 4, "shape_def.category");
        ref_put(e, d->mask, 4, "shape_def.mask");
    }
    if (f & U_GEOMETRY) {
        ref_put(e, (uint32_t)c->geometry.kind, 1, "geometry.kind");
        ref_put(e, (uint32_t)c->geometry.count, 1, "geometry.count");
        for (i = 0; i < c->geometry.count; ++i) ref_vec(e, c->geometry.vertices[i], "geometry.vertex");
        if (c->geometry.kind == PG_SHAPE_CHAIN_SEGMENT) {
            ref_vec(e, c->geometry.vertices[2], "geometry.neighbour");
            ref_vec(e, c->geometry.vertices[3], "geometry.neighbour");
        }
        ref_put(e, (uint32_t)c->geometry.radius, 4, "geometry.radius");
    }
}

/* Encoded length from the field widths alone (docs/formats.md's table). */
static size_t documented_length(const pg_command *c)
{
    uint32_t f = uses(c->kind);
    size_t n = 1;
    if (f & U_BODY) n += 8;
    if (f & U_VEC) n += 8;
    if (f & U_POINT) n += 8;
    if (f & U_SCALAR) n += 4;
    if (f & U_SCALAR2) n += 4;
    if (f & U_ANGLE) n += 4;
    if (f & U_VALUE) n += 4;
    if (f & U_VALUE2) n += 4;
    if (f & U_FLAG) n += 1;
    if (f & U_USER) n += 8;
    if (f & U_MAKE) n += 1 + 4 + 4;
    if (f & U_BODY_DEF) n += 1 + 8 + 4 + 8 + 4 * 4 + 3 + 8;
    if (f & U_SHAPE_DEF) n += 5 * 4;
    if (f & U_GEOMETRY) n += 2 + 8 * (size_t)c->geometry.count + (c->geometry.kind == PG_SHAPE_CHAIN_SEGMENT ? 16 : 0) + 4;
    return n;
}

static const ref_item *ref_find(const ref_enc *e, const char *name)
{
    int i;
    for (i = 0; i < e->n; ++i)
        if (strcmp(e->items[i].name, name) == 0) return &e->items[i];
    fail_msg("no field %s in the reference layout", name);
    return NULL;
}

/* ---- commands with a non-zero value in every field they use -------------------------------- */
static const pg_vec2 TARGET_POSITION = {131072, 196608}; /* (2, 3): the dynamic box of the test world */

static void set_body_def(pg_body_def *d)
{
    d->type = PG_BODY_DYNAMIC;
    d->position = pg_v2(fx(-3), fx(6));
    d->angle = 0x01000000u;
    d->linear_velocity = pg_v2(fx(0.5), fx(-0.25));
    d->angular_velocity = fx(0.5);
    d->linear_damping = fx(0.1);
    d->angular_damping = fx(0.2);
    d->gravity_scale = fx(0.75);
    d->fixed_rotation = 1;
    d->allow_sleep = 1;
    d->awake = 1;
    d->user_data = UINT64_C(0x1122334455667788);
}

static void set_shape_def(pg_shape_def *d)
{
    d->density = fx(1.25);
    d->friction = fx(0.4);
    d->restitution = fx(0.2);
    d->category = 4u;
    d->mask = 0xFFFFFFF7u;
}

/* Field by field: a struct assignment could copy padding. */
static void set_geometry(pg_geometry *g, const pg_geometry *from)
{
    int32_t i;
    g->kind = from->kind;
    g->count = from->count;
    for (i = 0; i < from->count; ++i) g->vertices[i] = from->vertices[i];
    if (from->kind == PG_SHAPE_CHAIN_SEGMENT) g->vertices[2] = from->vertices[2], g->vertices[3] = from->vertices[3];
    g->radius = from->radius;
}

static pg_geometry capsule_geometry(void)
{
    pg_geometry g;
    memset(&g, 0, sizeof g);
    assert_int_equal(pg_geometry_capsule(pg_v2(fx(-0.5), fx(0.125)), pg_v2(fx(0.5), fx(-0.125)), fx(0.25), &g), PG_OK);
    return g;
}

static pg_command full_command(pg_command_kind kind, pg_body_id body)
{
    pg_command c = pg_command_init(kind);
    uint32_t f = uses(kind);
    if (f & U_BODY) { c.body.index = body.index; c.body.generation = body.generation; }
    if (f & U_VEC) {
        switch (kind) {
        case PG_CMD_SET_TRANSFORM: c.vec = pg_v2(fx(3), fx(4)); break;
        case PG_CMD_APPLY_FORCE: c.vec = pg_v2(fx(20), fx(30)); break;
        case PG_CMD_APPLY_LINEAR_IMPULSE: c.vec = pg_v2(fx(0.5), fx(1)); break;
        case PG_CMD_SET_GRAVITY: c.vec = pg_v2(fx(1), fx(-5)); break;
        default: c.vec = pg_v2(fx(1.5), fx(-2.25)); break;
        }
    }
    if (f & U_POINT) c.point = pg_v2(TARGET_POSITION.x + fx(0.25), TARGET_POSITION.y + fx(0.375));
    if (f & U_SCALAR) {
        switch (kind) {
        case PG_CMD_SET_ANGULAR_VELOCITY: c.scalar = fx(1.5); break;
        case PG_CMD_APPLY_TORQUE: c.scalar = fx(5); break;
        case PG_CMD_APPLY_ANGULAR_IMPULSE: c.scalar = fx(0.75); break;
        case PG_CMD_SET_GRAVITY_SCALE: c.scalar = fx(0.5); break;
        case PG_CMD_SET_DAMPING: c.scalar = fx(0.25); break;
        case PG_CMD_SET_FRICTION: c.scalar = fx(0.3); break;
        case PG_CMD_SET_RESTITUTION: c.scalar = fx(0.5); break;
        case PG_CMD_SET_DENSITY: c.scalar = fx(2.5); break;
        default: c.scalar = fx(1); break;
        }
    }
    if (f & U_SCALAR2) c.scalar2 = fx(0.125);
    if (f & U_ANGLE) c.angle = 0x12345678u;
    if (f & U_VALUE) {
        switch (kind) {
        case PG_CMD_SET_BODY_TYPE: c.value = (uint32_t)PG_BODY_KINEMATIC; break;
        case PG_CMD_SET_EFFECTS: c.value = PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING; break;
        case PG_CMD_SET_FILTER: c.value = 2u; break;
        default: c.value = 1u; break; /* set_awake, set_fixed_rotation */
        }
    }
    if (f & U_VALUE2) c.value2 = 0xFFFF0003u;
    if (f & U_FLAG) c.flag = 1u;
    if (f & U_USER) c.user_data = UINT64_C(0x0123456789ABCDEF);
    if (f & U_MAKE) { c.make_kind = PG_MAKE_BOX; c.size0 = fx(1.5); c.size1 = fx(0.75); }
    if (f & U_BODY_DEF) set_body_def(&c.body_def);
    if (f & U_SHAPE_DEF) set_shape_def(&c.shape_def);
    if (f & U_GEOMETRY) {
        pg_geometry g = capsule_geometry();
        set_geometry(&c.geometry, &g);
    }
    return c;
}

static const pg_body_id SOME_BODY = {3u, 7u};

static void expect_same_command(const pg_command *got, const pg_command *want)
{
    int32_t i;
    PG_EXPECT_EQ(got->kind, want->kind, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body.index, want->body.index, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body.generation, want->body.generation, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->vec.x, want->vec.x, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->vec.y, want->vec.y, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->point.x, want->point.x, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->point.y, want->point.y, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->scalar, want->scalar, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->scalar2, want->scalar2, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->angle, want->angle, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->value, want->value, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->value2, want->value2, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->flag, want->flag, "%s", pg_command_kind_name(want->kind));
    assert_true(got->user_data == want->user_data);
    PG_EXPECT_EQ(got->make_kind, want->make_kind, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->size0, want->size0, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->size1, want->size1, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.type, want->body_def.type, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.position.x, want->body_def.position.x, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.position.y, want->body_def.position.y, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.angle, want->body_def.angle, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.linear_velocity.x, want->body_def.linear_velocity.x, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.linear_velocity.y, want->body_def.linear_velocity.y, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.angular_velocity, want->body_def.angular_velocity, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.linear_damping, want->body_def.linear_damping, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.angular_damping, want->body_def.angular_damping, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.gravity_scale, want->body_def.gravity_scale, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.fixed_rotation, want->body_def.fixed_rotation, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.allow_sleep, want->body_def.allow_sleep, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->body_def.awake, want->body_def.awake, "%s", pg_command_kind_name(want->kind));
    assert_true(got->body_def.user_data == want->body_def.user_data);
    PG_EXPECT_EQ(got->shape_def.density, want->shape_def.density, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->shape_def.friction, want->shape_def.friction, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->shape_def.restitution, want->shape_def.restitution, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->shape_def.category, want->shape_def.category, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->shape_def.mask, want->shape_def.mask, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->geometry.kind, want->geometry.kind, "%s", pg_command_kind_name(want->kind));
    PG_EXPECT_EQ(got->geometry.count, want->geometry.count, "%s", pg_command_kind_name(want->kind));
    for (i = 0; i < PG_MAX_VERTICES; ++i) {
        PG_EXPECT_EQ(got->geometry.vertices[i].x, want->geometry.vertices[i].x, "%s vertex %d", pg_command_kind_name(want->kind), (int)i);
        PG_EXPECT_EQ(got->geometry.vertices[i].y, want->geometry.vertices[i].y, "%s vertex %d", pg_command_kind_name(want->kind), (int)i);
    }
    PG_EXPECT_EQ(got->geometry.radius, want->geometry.radius, "%s", pg_command_kind_name(want->kind));
    /* both built from pg_command_init, fields set one by one: one byte image */
    if (memcmp(got, want, sizeof *got) != 0) fail_msg("%s: decoded command differs in its byte image", pg_command_kind_name(want->kind));
}

/* encode -> decode, length, one byte short; returns the encoded length */
static size_t check_round_trip(const pg_command *c)
{
    uint8_t buf[PG_COMMAND_ENCODED_MAX + 16], shortbuf[PG_COMMAND_ENCODED_MAX + 16];
    pg_command back;
    size_t n, consumed = 0, off = 12345, i;
    const char *field = "untouched";
    const char *name = pg_command_kind_name(c->kind);

    memset(buf, 0xAA, sizeof buf);
    n = pg_command_encode(c, buf, sizeof buf);
    PG_EXPECT_EQ(n, documented_length(c), "%s: encoded length", name);
    PG_EXPECT_LE(n, PG_COMMAND_ENCODED_MAX, "%s", name);
    PG_EXPECT_EQ(buf[0], c->kind, "%s: the first byte is the kind", name);
    for (i = n; i < sizeof buf; ++i) PG_EXPECT_EQ(buf[i], 0xAA, "%s: byte %d written past the encoding", name, (int)i);

    /* exactly enough room works; one byte short fails and writes nothing past it */
    PG_EXPECT_EQ(pg_command_encode(c, shortbuf, n), n, "%s: capacity == length", name);
    memset(shortbuf, 0xAA, sizeof shortbuf);
    PG_EXPECT_EQ(pg_command_encode(c, shortbuf, n - 1u), 0, "%s: capacity one byte short", name);
    for (i = n - 1u; i < sizeof shortbuf; ++i) PG_EXPECT_EQ(shortbuf[i], 0xAA, "%s: byte %d written past capacity", name, (int)i);
    PG_EXPECT_EQ(pg_command_encode(c, shortbuf, 0), 0, "%s: capacity 0", name);

    memset(&back, 0x5C, sizeof back);
    PG_EXPECT_EQ(pg_command_decode(buf, n, &back, &consumed, &off, &field), PG_OK, "%s", name);
    PG_EXPECT_EQ(consumed, n, "%s: consumed", name);
    expect_same_command(&back, c);

    /* trailing bytes are not part of the command */
    memset(&back, 0x5C, sizeof back);
    consumed = 0;
    PG_EXPECT_EQ(pg_command_decode(buf, sizeof buf, &back, &consumed, NULL, NULL), PG_OK, "%s with trailing bytes", name);
    PG_EXPECT_EQ(consumed, n, "%s: consumed with trailing bytes", name);
    expect_same_command(&back, c);

    /* and the re-encoding is the same bytes */
    PG_EXPECT_EQ(pg_command_encode(&back, shortbuf, sizeof shortbuf), n, "%s", name);
    if (memcmp(buf, shortbuf, n) != 0) fail_msg("%s: re-encoding differs", name);
    return n;
}

/* ---- tests: encoding --------------------------------------------------------------------------- */
static void test_round_trip_every_kind(void **state)
{
    int k;
    (void)state;
    for (k = 1; k < BODY_COMMANDS_END; ++k) {
        pg_command c = full_command((pg_command_kind)k, SOME_BODY);
        check_round_trip(&c);
    }
}

static void test_round_trip_variants(void **state)
{
    pg_command c;
    pg_geometry g;
    int m;
    (void)state;
    /* every make kind */
    for (m = 0; m < PG_MAKE_KIND_COUNT; ++m) {
        c = full_command(PG_CMD_MAKE, SOME_BODY);
        c.make_kind = (pg_make_kind)m;
        check_round_trip(&c);
    }
    /* every geometry kind, and the largest polygon */
    {
        pg_vec2 octagon[8];
        int i;
        for (i = 0; i < 8; ++i) {
            double a = 2.0 * PGT_PI * (i + 0.3) / 8.0;
            octagon[i] = pg_v2(fx(1.5 * cos(a)), fx(1.5 * sin(a)));
        }
        memset(&g, 0, sizeof g);
        assert_int_equal(pg_geometry_polygon(octagon, 8, &g), PG_OK);
        c = full_command(PG_CMD_ADD_SHAPE, SOME_BODY);
        memset(&c.geometry, 0, sizeof c.geometry);
        set_geometry(&c.geometry, &g);
        PG_EXPECT_EQ(check_round_trip(&c), 1 + 8 + 20 + 2 + 64 + 4, "%s", "octagon");

        memset(&g, 0, sizeof g);
        assert_int_equal(pg_geometry_circle(pg_v2(fx(0.25), fx(-0.5)), fx(0.75), &g), PG_OK);
        memset(&c.geometry, 0, sizeof c.geometry);
        set_geometry(&c.geometry, &g);
        PG_EXPECT_EQ(check_round_trip(&c), 1 + 8 + 20 + 2 + 8 + 4, "%s", "circle");

        memset(&g, 0, sizeof g);
        assert_int_equal(pg_geometry_segment(pg_v2(fx(-1), fx(0.25)), pg_v2(fx(1), fx(-0.25)), &g), PG_OK);
        memset(&c.geometry, 0, sizeof c.geometry);
        set_geometry(&c.geometry, &g);
        check_round_trip(&c);

        /* a chain segment carries its neighbours after its two vertices */
        memset(&g, 0, sizeof g);
        assert_int_equal(pg_geometry_chain_segment(pg_v2(fx(3), fx(1)), pg_v2(fx(1), 0), pg_v2(fx(-1), 0), pg_v2(fx(-3), fx(0.5)), &g), PG_OK);
        memset(&c.geometry, 0, sizeof c.geometry);
        set_geometry(&c.geometry, &g);
        PG_EXPECT_EQ(check_round_trip(&c), 1 + 8 + 20 + 2 + 16 + 16 + 4, "%s", "chain segment");
    }
    /* extreme values survive: negative, INT32_MIN/MAX bit patterns, all-ones user data */
    c = full_command(PG_CMD_APPLY_LINEAR_IMPULSE, SOME_BODY);
    c.body.index = 0xFFFFFFFFu;
    c.body.generation = 0xFFFFFFFEu;
    c.vec = pg_v2(INT32_MIN, INT32_MAX);
    c.point = pg_v2(-1, 1);
    check_round_trip(&c);
    c = full_command(PG_CMD_SET_USER_DATA, SOME_BODY);
    c.user_data = UINT64_MAX;
    check_round_trip(&c);
    c = full_command(PG_CMD_SET_DAMPING, SOME_BODY);
    c.scalar = INT32_MIN;
    c.scalar2 = -1;
    check_round_trip(&c);
    c = full_command(PG_CMD_APPLY_FORCE, SOME_BODY);
    c.flag = 0; /* at the centre of mass */
    check_round_trip(&c);
    c = full_command(PG_CMD_CREATE_BODY, SOME_BODY);
    c.body_def.fixed_rotation = 0;
    c.body_def.awake = 0;
    c.body_def.type = PG_BODY_STATIC;
    check_round_trip(&c);
}

/* The bytes themselves, against docs/formats.md's layout. */
static void test_encoding_follows_documented_layout(void **state)
{
    int k;
    (void)state;
    for (k = 1; k < BODY_COMMANDS_END; ++k) {
        pg_command c = full_command((pg_command_kind)k, SOME_BODY);
        uint8_t buf[PG_COMMAND_ENCODED_MAX];
        ref_enc e;
        size_t n, i;
        ref_encode(&c, &e);
        n = pg_command_encode(&c, buf, sizeof buf);
        PG_EXPECT_EQ(n, e.len, "%s", pg_command_kind_name(c.kind));
        for (i = 0; i < n; ++i)
            if (buf[i] != e.bytes[i]) {
                int j;
                const char *field = "?";
                for (j = 0; j < e.n; ++j)
                    if (i >= e.items[j].offset && i < e.items[j].offset + e.items[j].size) field = e.items[j].name;
                fail_msg("%s: byte %d is 0x%02x, the documented layout puts 0x%02x of field %s there",
                         pg_command_kind_name(c.kind), (int)i, buf[i], e.bytes[i], field);
            }
    }
}

static void test_encode_rejects_invalid_commands(void **state)
{
    uint8_t buf[PG_COMMAND_ENCODED_MAX];
    pg_command c;
    (void)state;
    c = pg_command_init(PG_CMD_NONE);
    assert_int_equal(pg_command_encode(&c, buf, sizeof buf), 0);
    c = pg_command_init(PG_CMD_KIND_COUNT);
    assert_int_equal(pg_command_encode(&c, buf, sizeof buf), 0);
    c = full_command(PG_CMD_SET_GRAVITY, SOME_BODY);
    assert_int_equal(pg_command_encode(NULL, buf, sizeof buf), 0);
    assert_int_equal(pg_command_encode(&c, NULL, sizeof buf), 0);
    c = full_command(PG_CMD_ADD_SHAPE, SOME_BODY);
    c.geometry.count = PG_MAX_VERTICES + 1;
    assert_int_equal(pg_command_encode(&c, buf, sizeof buf), 0);
    c.geometry.count = -1;
    assert_int_equal(pg_command_encode(&c, buf, sizeof buf), 0);
}

/* "Bytes written (0 if the command is invalid ...)": a command whose encoding decode
 * would reject is invalid. */
static void test_encode_rejects_values_decode_rejects(void **state)
{
    uint8_t buf[PG_COMMAND_ENCODED_MAX];
    pg_command c;
    (void)state;
    c = full_command(PG_CMD_MAKE, SOME_BODY);
    c.make_kind = (pg_make_kind)9;
    PG_EXPECT_EQ(pg_command_encode(&c, buf, sizeof buf), 0, "%s", "make_kind 9");
    c = full_command(PG_CMD_CREATE_BODY, SOME_BODY);
    c.body_def.type = (pg_body_type)3;
    PG_EXPECT_EQ(pg_command_encode(&c, buf, sizeof buf), 0, "%s", "body_def.type 3");
    c = full_command(PG_CMD_ADD_SHAPE, SOME_BODY);
    c.geometry.kind = (pg_shape_kind)5;
    PG_EXPECT_EQ(pg_command_encode(&c, buf, sizeof buf), 0, "%s", "geometry.kind 5");
    c = full_command(PG_CMD_ADD_SHAPE, SOME_BODY); /* a capsule's count, 2, is a chain segment's */
    c.geometry.kind = PG_SHAPE_CHAIN_SEGMENT;
    c.geometry.count = 3;
    PG_EXPECT_EQ(pg_command_encode(&c, buf, sizeof buf), 0, "%s", "a chain segment of 3 vertices");
}

/* ---- tests: decoding errors -------------------------------------------------------------------- */
static void test_decode_every_prefix(void **state)
{
    int k;
    (void)state;
    for (k = 1; k < PG_CMD_KIND_COUNT; ++k) {
        pg_command c = full_command((pg_command_kind)k, SOME_BODY), back;
        uint8_t buf[PG_COMMAND_ENCODED_MAX];
        size_t n = pg_command_encode(&c, buf, sizeof buf), p;
        assert_true(n > 0);
        for (p = 0; p < n; ++p) {
            /* a copy of exactly p bytes, so reading past it is caught by ASan */
            uint8_t *prefix = (uint8_t *)t_malloc(p > 0 ? p : 1u);
            size_t off = 99999, consumed = 77;
            const char *field = NULL;
            pg_result r;
            assert_non_null(prefix);
            memcpy(prefix, buf, p);
            memset(&back, 0x5C, sizeof back);
            r = pg_command_decode(prefix, p, &back, &consumed, &off, &field);
            PG_EXPECT_EQ(r, PG_ERR_INVALID_ARGUMENT, "%s prefix of %d bytes", pg_command_kind_name(c.kind), (int)p);
            PG_EXPECT_LE(off, p, "%s prefix of %d bytes: the read stopped at or before the end", pg_command_kind_name(c.kind), (int)p);
            PG_EXPECT_LE(p - off, 7, "%s prefix of %d bytes: no field is wider than 8 bytes", pg_command_kind_name(c.kind), (int)p);
            assert_non_null(field);
            assert_true(strlen(field) > 0);
            if (p == 0) assert_string_equal(field, "command.kind");
            PG_EXPECT_EQ(consumed, 0, "%s prefix %d: nothing consumed on failure", pg_command_kind_name(c.kind), (int)p);
            t_free(prefix);
        }
        /* the NULL out-pointers are optional */
        PG_EXPECT_EQ(pg_command_decode(buf, n - 1u, &back, NULL, NULL, NULL), PG_ERR_INVALID_ARGUMENT, "%s", pg_command_kind_name(c.kind));
    }
}

/* Prefix errors name the field the documented layout has there. */
static void test_decode_prefix_names_field(void **state)
{
    int k;
    (void)state;
    for (k = 1; k < PG_CMD_KIND_COUNT; ++k) {
        pg_command c = full_command((pg_command_kind)k, SOME_BODY), back;
        ref_enc e;
        int j;
        ref_encode(&c, &e);
        for (j = 0; j < e.n; ++j) {
            /* cut in the middle of field j (or at its start for one-byte fields) */
            size_t p = e.items[j].offset + e.items[j].size / 2u, off = 99999;
            const char *field = NULL;
            assert_int_equal(pg_command_decode(e.bytes, p, &back, NULL, &off, &field), PG_ERR_INVALID_ARGUMENT);
            assert_non_null(field);
            if (off < e.items[j].offset || off > p)
                fail_msg("%s cut at %d inside %s (at %d): error offset %d", pg_command_kind_name(c.kind), (int)p, e.items[j].name,
                         (int)e.items[j].offset, (int)off);
            if (strstr(field, j == 0 ? "kind" : e.items[j].name) == NULL)
                fail_msg("%s cut at %d inside %s: error names \"%s\"", pg_command_kind_name(c.kind), (int)p, e.items[j].name, field);
        }
    }
}

static void expect_decode_error(const uint8_t *buf, size_t n, size_t want_offset, const char *want_field, const char *what)
{
    pg_command back;
    size_t off = 99999, consumed = 77;
    const char *field = NULL;
    pg_result r;
    memset(&back, 0x5C, sizeof back);
    r = pg_command_decode(buf, n, &back, &consumed, &off, &field);
    PG_EXPECT_EQ(r, PG_ERR_INVALID_ARGUMENT, "%s", what);
    PG_EXPECT_EQ(off, want_offset, "%s: error offset", what);
    assert_non_null(field);
    if (strcmp(field, want_field) != 0) fail_msg("%s: error field \"%s\", want \"%s\"", what, field, want_field);
    PG_EXPECT_EQ(consumed, 0, "%s", what);
}

static void test_decode_invalid_kind(void **state)
{
    static const uint8_t bad_kinds[] = {0u, (uint8_t)PG_CMD_KIND_COUNT, (uint8_t)(PG_CMD_KIND_COUNT + 1), 200u, 255u};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad_kinds; ++i) {
        uint8_t buf[PG_COMMAND_ENCODED_MAX];
        char what[64];
        memset(buf, 0, sizeof buf);
        buf[0] = bad_kinds[i];
        snprintf(what, sizeof what, "kind byte %u", (unsigned)bad_kinds[i]);
        expect_decode_error(buf, sizeof buf, 0, "command.kind", what);
        expect_decode_error(buf, 1, 0, "command.kind", what);
    }
    expect_decode_error((const uint8_t *)"", 0, 0, "command.kind", "empty buffer");
    {
        pg_command c;
        uint8_t b = 1;
        assert_int_equal(pg_command_decode(NULL, 4, &c, NULL, NULL, NULL), PG_ERR_NULL);
        assert_int_equal(pg_command_decode(&b, 1, NULL, NULL, NULL, NULL), PG_ERR_NULL);
    }
}

/* Set the byte of field `name` (documented layout) to `value` in a valid encoding and
 * expect decode to reject it at that offset, naming the field. */
static void expect_bad_byte(pg_command_kind kind, const char *name, uint8_t value, const char *want_field)
{
    pg_command c = full_command(kind, SOME_BODY);
    ref_enc e;
    const ref_item *it;
    char what[96];
    ref_encode(&c, &e);
    it = ref_find(&e, name);
    e.bytes[it->offset] = value;
    snprintf(what, sizeof what, "%s with %s = %u", pg_command_kind_name(kind), name, (unsigned)value);
    expect_decode_error(e.bytes, e.len, it->offset, want_field, what);
}

static void test_decode_invalid_values(void **state)
{
    (void)state;
    expect_bad_byte(PG_CMD_MAKE, "make_kind", 9, "command.make_kind");
    expect_bad_byte(PG_CMD_MAKE, "make_kind", (uint8_t)PG_MAKE_KIND_COUNT, "command.make_kind");
    expect_bad_byte(PG_CMD_MAKE, "body_def.type", 3, "command.body_def.type");
    expect_bad_byte(PG_CMD_CREATE_BODY, "body_def.type", 3, "command.body_def.type");
    expect_bad_byte(PG_CMD_CREATE_BODY, "body_def.type", 255, "command.body_def.type");
    expect_bad_byte(PG_CMD_CREATE_BODY, "body_def.fixed_rotation", 2, "command.body_def.fixed_rotation");
    expect_bad_byte(PG_CMD_CREATE_BODY, "body_def.allow_sleep", 2, "command.body_def.allow_sleep");
    expect_bad_byte(PG_CMD_CREATE_BODY, "body_def.awake", 255, "command.body_def.awake");
    expect_bad_byte(PG_CMD_ADD_SHAPE, "geometry.count", 9, "command.geometry.count");
    expect_bad_byte(PG_CMD_ADD_SHAPE, "geometry.count", 255, "command.geometry.count");
    expect_bad_byte(PG_CMD_ADD_SHAPE, "geometry.kind", 5, "command.geometry.kind");
    expect_bad_byte(PG_CMD_ADD_SHAPE, "geometry.kind", 255, "command.geometry.kind");
}

/* The flag of APPLY_FORCE is checked as a boolean at its documented place (offset 17). */
static void test_decode_invalid_flag(void **state)
{
    (void)state;
    expect_bad_byte(PG_CMD_APPLY_FORCE, "flag", 2, "command.flag");
    expect_bad_byte(PG_CMD_APPLY_FORCE, "flag", 255, "command.flag");
    {
        pg_command c = full_command(PG_CMD_APPLY_FORCE, SOME_BODY);
        ref_enc e;
        ref_encode(&c, &e);
        PG_EXPECT_EQ(ref_find(&e, "flag")->offset, 1 + 8 + 8, "%s", "flag after body and force");
    }
}

/* A failed decode leaves a zeroed command, not half a command. */
static void test_decode_failure_zeroes_command(void **state)
{
    pg_command c = full_command(PG_CMD_CREATE_BODY, SOME_BODY), back, zero = pg_command_init(PG_CMD_NONE);
    uint8_t buf[PG_COMMAND_ENCODED_MAX];
    size_t n = pg_command_encode(&c, buf, sizeof buf);
    (void)state;
    assert_true(n > 10);
    memset(&back, 0x5C, sizeof back);
    assert_int_equal(pg_command_decode(buf, n - 3u, &back, NULL, NULL, NULL), PG_ERR_INVALID_ARGUMENT);
    assert_memory_equal(&back, &zero, sizeof back);
}

static void test_kind_names(void **state)
{
    int i, j;
    (void)state;
    for (i = 0; i < PG_CMD_KIND_COUNT; ++i) {
        const char *n = pg_command_kind_name((pg_command_kind)i);
        const char *p;
        assert_non_null(n);
        assert_true(strlen(n) > 0);
        for (p = n; *p != '\0'; ++p)
            if (!((*p >= 'a' && *p <= 'z') || *p == '_')) fail_msg("kind %d name \"%s\" is not lower-case", i, n);
        for (j = 0; j < i; ++j)
            if (strcmp(n, pg_command_kind_name((pg_command_kind)j)) == 0) fail_msg("kinds %d and %d share the name \"%s\"", j, i, n);
    }
    assert_string_equal(pg_command_kind_name(PG_CMD_SET_LINEAR_VELOCITY), "set_linear_velocity");
    assert_non_null(pg_command_kind_name(PG_CMD_KIND_COUNT));
    assert_non_null(pg_command_kind_name((pg_command_kind)255));
}

/* ---- apply: each command does what its call does -------------------------------------------- */
typedef struct test_world {
    void *memory;
    pg_world *w;
    pg_body_id ground, target, ball;
} test_world;

static test_world make_world(void)
{
    test_world t;
    pg_world_def d = pg_default_world_def();
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    size_t need;
    d.max_bodies = 16;
    d.max_shapes = 16;
    d.max_contacts = 64;
    need = pg_world_memory_size(&d);
    assert_true(need > 0);
    t.memory = t_malloc(need);
    assert_non_null(t.memory);
    assert_int_equal(pg_world_create(&d, t.memory, need, &t.w), PG_OK);
    bd.position = pg_v2(0, fx(-1));
    assert_int_equal(pg_make_wall(t.w, &bd, &sd, fx(40), fx(2), &t.ground), PG_OK);
    bd.type = PG_BODY_DYNAMIC;
    bd.position = pg_v2(fx(-2), fx(0.5));
    assert_int_equal(pg_make_ball(t.w, &bd, &sd, fx(0.5), &t.ball), PG_OK);
    bd.position = TARGET_POSITION;
    assert_int_equal(pg_make_box(t.w, &bd, &sd, fx(1), fx(1), &t.target), PG_OK);
    /* asleep, so that set_awake has something to do */
    assert_int_equal(pg_body_set_awake(t.w, t.target, 0), PG_OK);
    assert_false(pg_body_is_awake(t.w, t.target));
    return t;
}

static void free_world(test_world *t) { t_free(t->memory); t->memory = NULL; t->w = NULL; }

/* The direct call a command stands for. */
static pg_result direct_call(pg_world *w, const pg_command *c, pg_body_id *created)
{
    pg_shape_id sid;
    created->index = created->generation = 0;
    switch (c->kind) {
    case PG_CMD_CREATE_BODY: return pg_body_create(w, &c->body_def, created);
    case PG_CMD_DESTROY_BODY: return pg_body_destroy(w, c->body);
    case PG_CMD_ADD_SHAPE: return pg_shape_create(w, c->body, &c->shape_def, &c->geometry, &sid);
    case PG_CMD_MAKE:
        switch (c->make_kind) {
        case PG_MAKE_BALL: return pg_make_ball(w, &c->body_def, &c->shape_def, c->size0, created);
        case PG_MAKE_CAPSULE: return pg_make_capsule(w, &c->body_def, &c->shape_def, c->size0, c->size1, created);
        case PG_MAKE_BOX: return pg_make_box(w, &c->body_def, &c->shape_def, c->size0, c->size1, created);
        case PG_MAKE_TRIANGLE: return pg_make_triangle(w, &c->body_def, &c->shape_def, c->size0, created);
        case PG_MAKE_STAR: return pg_make_star(w, &c->body_def, &c->shape_def, c->size0, created);
        case PG_MAKE_WALL: return pg_make_wall(w, &c->body_def, &c->shape_def, c->size0, c->size1, created);
        default: fail_msg("make kind %d", (int)c->make_kind); return PG_ERR_INVALID_ARGUMENT;
        }
    case PG_CMD_SET_TRANSFORM: return pg_body_set_transform(w, c->body, c->vec, c->angle);
    case PG_CMD_SET_LINEAR_VELOCITY: return pg_body_set_linear_velocity(w, c->body, c->vec);
    case PG_CMD_SET_ANGULAR_VELOCITY: return pg_body_set_angular_velocity(w, c->body, c->scalar);
    case PG_CMD_APPLY_FORCE: return c->flag ? pg_body_apply_force_at(w, c->body, c->vec, c->point) : pg_body_apply_force(w, c->body, c->vec);
    case PG_CMD_APPLY_TORQUE: return pg_body_apply_torque(w, c->body, c->scalar);
    case PG_CMD_APPLY_LINEAR_IMPULSE: return pg_body_apply_linear_impulse(w, c->body, c->vec, c->point);
    case PG_CMD_APPLY_ANGULAR_IMPULSE: return pg_body_apply_angular_impulse(w, c->body, c->scalar);
    case PG_CMD_SET_BODY_TYPE: return pg_body_set_type(w, c->body, (pg_body_type)c->value);
    case PG_CMD_SET_AWAKE: return pg_body_set_awake(w, c->body, c->value != 0);
    case PG_CMD_SET_GRAVITY: return pg_world_set_gravity(w, c->vec);
    case PG_CMD_SET_EFFECTS: return pg_world_set_effects(w, c->value);
    case PG_CMD_SET_GRAVITY_SCALE: return pg_body_set_gravity_scale(w, c->body, c->scalar);
    case PG_CMD_SET_DAMPING: return pg_body_set_damping(w, c->body, c->scalar, c->scalar2);
    case PG_CMD_SET_FRICTION: return pg_body_set_friction(w, c->body, c->scalar);
    case PG_CMD_SET_RESTITUTION: return pg_body_set_restitution(w, c->body, c->scalar);
    case PG_CMD_SET_DENSITY: return pg_body_set_density(w, c->body, c->scalar);
    case PG_CMD_SET_FIXED_ROTATION: return pg_body_set_fixed_rotation(w, c->body, c->value != 0);
    case PG_CMD_SET_FILTER: return pg_body_set_filter(w, c->body, c->value, c->value2);
    case PG_CMD_SET_USER_DATA: return pg_body_set_user_data(w, c->body, c->user_data);
    default: fail_msg("kind %d", (int)c->kind); return PG_ERR_INVALID_ARGUMENT;
    }
}

static void check_apply_matches_call(const pg_command *c)
{
    test_world a = make_world(), b = make_world();
    pg_body_id via_command = {99u, 99u}, via_call = {0, 0};
    pg_result ra, rb;
    uint64_t h0 = pg_world_hash(a.w);
    const char *name = pg_command_kind_name(c->kind);
    int f;
    assert_true(h0 == pg_world_hash(b.w));
    ra = pg_command_apply(a.w, c, &via_command);
    rb = direct_call(b.w, c, &via_call);
    PG_EXPECT_EQ(ra, PG_OK, "%s (make kind %d)", name, (int)c->make_kind);
    PG_EXPECT_EQ(rb, PG_OK, "%s (make kind %d)", name, (int)c->make_kind);
    if (pg_world_hash(a.w) != pg_world_hash(b.w)) fail_msg("%s: command and call leave different states", name);
    if (pg_world_hash(a.w) == h0) fail_msg("%s: the command changed nothing (test values too weak)", name);
    if (c->kind == PG_CMD_CREATE_BODY || c->kind == PG_CMD_MAKE) {
        assert_true(pg_body_id_equal(via_command, via_call));
        assert_true(pg_body_is_valid(a.w, via_command));
    } else {
        PG_EXPECT_EQ(via_command.index, 0, "%s: created is zero for a command that creates nothing", name);
        PG_EXPECT_EQ(via_command.generation, 0, "%s", name);
    }
    for (f = 0; f < 5; ++f) {
        assert_int_equal(pg_world_step(a.w), PG_OK);
        assert_int_equal(pg_world_step(b.w), PG_OK);
        if (pg_world_hash(a.w) != pg_world_hash(b.w)) fail_msg("%s: states differ %d steps later", name, f + 1);
    }
    free_world(&a);
    free_world(&b);
}

static void test_apply_equals_direct_call(void **state)
{
    test_world t = make_world();
    pg_body_id target = t.target;
    int k, m;
    (void)state;
    free_world(&t);
    for (k = 1; k < BODY_COMMANDS_END; ++k) {
        pg_command c = full_command((pg_command_kind)k, target);
        check_apply_matches_call(&c);
    }
    for (m = 0; m < PG_MAKE_KIND_COUNT; ++m) {
        pg_command c = full_command(PG_CMD_MAKE, target);
        c.make_kind = (pg_make_kind)m;
        check_apply_matches_call(&c);
    }
    {   /* force at the centre of mass */
        pg_command c = full_command(PG_CMD_APPLY_FORCE, target);
        c.flag = 0;
        c.point = pg_v2(0, 0);
        check_apply_matches_call(&c);
    }
}

/* add_shape carries a chain segment through encode and decode and adds it as
 * pg_shape_create does, neighbours included (the state hash covers them); on a body that
 * is not static it fails as the call does (PG_ERR_BODY_TYPE) and changes nothing. */
static void test_apply_chain_segment(void **state)
{
    test_world a = make_world(), b = make_world();
    pg_command c = full_command(PG_CMD_ADD_SHAPE, a.ground), decoded;
    pg_geometry g, got;
    pg_shape_id sid, shapes[4];
    uint8_t buf[PG_COMMAND_ENCODED_MAX];
    size_t n, used = 0;
    uint64_t h;
    (void)state;
    assert_int_equal(pg_geometry_chain_segment(pg_v2(fx(8), fx(1)), pg_v2(fx(6), 0), pg_v2(fx(4), 0), pg_v2(fx(2), fx(-1)), &g), PG_OK);
    c.geometry = g;
    n = pg_command_encode(&c, buf, sizeof buf);
    assert_true(n > 0);
    assert_int_equal(pg_command_decode(buf, n, &decoded, &used, NULL, NULL), PG_OK);
    assert_int_equal(used, n);
    assert_int_equal(pg_command_apply(a.w, &decoded, NULL), PG_OK);
    assert_int_equal(pg_shape_create(b.w, b.ground, &c.shape_def, &g, &sid), PG_OK);
    if (pg_world_hash(a.w) != pg_world_hash(b.w)) fail_msg("%s", "the command's chain segment differs from the call's");
    assert_int_equal(pg_body_shapes(a.w, a.ground, shapes, 4), 2u);
    assert_int_equal(pg_shape_geometry(a.w, shapes[1], &got), PG_OK);
    assert_int_equal(got.kind, PG_SHAPE_CHAIN_SEGMENT);
    assert_true(got.vertices[2].x == fx(8) && got.vertices[2].y == fx(1) && got.vertices[3].x == fx(2) && got.vertices[3].y == fx(-1));
    /* another neighbour changes the world: the decoded one was used */
    c.geometry.vertices[3] = pg_v2(fx(2), fx(1));
    assert_int_equal(pg_command_apply(b.w, &c, NULL), PG_OK);
    assert_int_equal(pg_command_apply(a.w, &decoded, NULL), PG_OK);
    if (pg_world_hash(a.w) == pg_world_hash(b.w)) fail_msg("%s", "a neighbour is not in the state");
    /* on the dynamic box */
    h = pg_world_hash(a.w);
    decoded.body = a.target;
    assert_int_equal(pg_command_apply(a.w, &decoded, NULL), PG_ERR_BODY_TYPE);
    if (pg_world_hash(a.w) != h) fail_msg("%s", "a refused chain segment changed the world");
    free_world(&a);
    free_world(&b);
}

/* A failing command fails as its call does and changes nothing. */
static void test_apply_failures(void **state)
{
    test_world t = make_world();
    pg_body_id stale = t.ball, created;
    uint64_t h;
    int k;
    (void)state;
    assert_int_equal(pg_body_destroy(t.w, t.ball), PG_OK);
    assert_false(pg_body_is_valid(t.w, stale));
    h = pg_world_hash(t.w);
    for (k = 1; k < PG_CMD_KIND_COUNT; ++k) {
        pg_command c;
        if ((uses((pg_command_kind)k) & U_BODY) == 0) continue;
        c = full_command((pg_command_kind)k, stale);
        created.index = created.generation = 7;
        PG_EXPECT_EQ(pg_command_apply(t.w, &c, &created), PG_ERR_STALE_HANDLE, "%s", pg_command_kind_name(c.kind));
        if (pg_world_hash(t.w) != h) fail_msg("%s on a stale handle changed the world", pg_command_kind_name(c.kind));
        PG_EXPECT_EQ(created.index, 0, "%s", pg_command_kind_name(c.kind));
        PG_EXPECT_EQ(created.generation, 0, "%s", pg_command_kind_name(c.kind));
        /* a handle that never existed */
        c.body.index = 12;
        c.body.generation = 1;
        PG_EXPECT_EQ(pg_command_apply(t.w, &c, NULL), PG_ERR_STALE_HANDLE, "%s never-created", pg_command_kind_name(c.kind));
        if (pg_world_hash(t.w) != h) fail_msg("%s on a never-created handle changed the world", pg_command_kind_name(c.kind));
    }
    {
        pg_command c = pg_command_init(PG_CMD_NONE);
        assert_int_equal(pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT);
        c = full_command(PG_CMD_MAKE, t.target);
        c.make_kind = (pg_make_kind)9;
        created.index = 5;
        assert_int_equal(pg_command_apply(t.w, &c, &created), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(created.index, 0);
        c = full_command(PG_CMD_SET_BODY_TYPE, t.target);
        c.value = 7;
        assert_int_not_equal(pg_command_apply(t.w, &c, NULL), PG_OK);
        assert_true(pg_world_hash(t.w) == h);
        assert_int_equal(pg_command_apply(NULL, &c, NULL), PG_ERR_NULL);
        assert_int_equal(pg_command_apply(t.w, NULL, NULL), PG_ERR_NULL);
    }
    free_world(&t);
}

/* ---- the queue ------------------------------------------------------------------------------- */
static pg_command tagged_create(uint64_t tag)
{
    pg_command c = pg_command_init(PG_CMD_CREATE_BODY);
    c.body_def = pg_default_body_def(); /* padding is irrelevant here */
    c.body_def.position = pg_v2(fx(10), fx(10 + (double)tag));
    c.body_def.user_data = tag;
    return c;
}

static void test_queue_order(void **state)
{
    test_world t = make_world();
    pg_command commands[8];
    uint64_t frames[8];
    pg_command_queue q;
    static const uint64_t push_frames[4] = {5, 3, 5, 4};
    static const uint32_t due_at[7] = {0, 0, 0, 1, 1, 2, 0};
    static const uint64_t want_order[4] = {2, 4, 1, 3}; /* tags: frame 3, frame 4, then frame 5 in push order */
    uint32_t first_slot = 3; /* ground, ball, target are slots 0..2 */
    int i;
    uint64_t f;
    (void)state;
    pg_command_queue_init(&q, commands, frames, 8);
    for (i = 0; i < 4; ++i) {
        pg_command c = tagged_create((uint64_t)i + 1u);
        assert_int_equal(pg_command_queue_push(&q, t.w, push_frames[i], &c), PG_OK);
    }
    assert_int_equal(q.count, 4);
    for (f = 0; f <= 6; ++f) {
        uint32_t failures = 99;
        assert_true(pg_world_frame(t.w) == f);
        PG_EXPECT_EQ(pg_command_queue_apply_due(&q, t.w, &failures), due_at[f], "frame %d", (int)f);
        PG_EXPECT_EQ(failures, 0, "frame %d", (int)f);
        assert_int_equal(pg_world_step(t.w), PG_OK);
    }
    assert_int_equal(q.count, 0);
    for (i = 0; i < 4; ++i) {
        pg_body_id id;
        id.index = first_slot + (uint32_t)i;
        id.generation = 1;
        assert_true(pg_body_is_valid(t.w, id));
        PG_EXPECT_EQ(pg_body_user_data(t.w, id), want_order[i], "body created %d-th", i);
    }
    free_world(&t);
}

static void test_queue_errors_and_failures(void **state)
{
    test_world t = make_world();
    pg_command commands[4];
    uint64_t frames[4];
    pg_command_queue q;
    pg_command c = full_command(PG_CMD_SET_GRAVITY, t.target), stale;
    pg_body_id dead = t.ball;
    uint32_t failures = 99;
    uint64_t h;
    int i;
    (void)state;
    pg_command_queue_init(&q, commands, frames, 4);
    for (i = 0; i < 3; ++i) assert_int_equal(pg_world_step(t.w), PG_OK);
    /* a frame already past */
    assert_int_equal(pg_command_queue_push(&q, t.w, 2, &c), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_command_queue_push(&q, t.w, 0, &c), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(q.count, 0);
    /* the current frame is not past */
    assert_int_equal(pg_command_queue_push(&q, t.w, 3, &c), PG_OK);
    /* a failing command is counted and changes nothing */
    assert_int_equal(pg_body_destroy(t.w, dead), PG_OK);
    stale = full_command(PG_CMD_SET_LINEAR_VELOCITY, dead);
    assert_int_equal(pg_command_queue_push(&q, t.w, 3, &stale), PG_OK);
    assert_int_equal(pg_command_queue_push(&q, t.w, 9, &c), PG_OK);
    assert_int_equal(pg_command_queue_push(&q, t.w, 100, &c), PG_OK);
    /* full */
    assert_int_equal(pg_command_queue_push(&q, t.w, 10, &c), PG_ERR_CAPACITY);
    assert_int_equal(q.count, 4);
    h = pg_world_hash(t.w);
    PG_EXPECT_EQ(pg_command_queue_apply_due(&q, t.w, &failures), 2, "%s", "frame 3");
    PG_EXPECT_EQ(failures, 1, "%s", "frame 3");
    assert_true(pg_world_hash(t.w) != h); /* the gravity command did apply */
    assert_int_equal(q.count, 2);
    /* room again */
    assert_int_equal(pg_command_queue_push(&q, t.w, 10, &c), PG_OK);
    assert_int_equal(q.count, 3);
    PG_EXPECT_EQ(pg_command_queue_apply_due(&q, t.w, NULL), 0, "%s", "nothing due yet");
    /* a queue with no capacity */
    {
        pg_command_queue empty;
        pg_command_queue_init(&empty, NULL, NULL, 4);
        assert_int_equal(pg_command_queue_push(&empty, t.w, 5, &c), PG_ERR_CAPACITY);
    }
    assert_int_equal(pg_command_queue_push(NULL, t.w, 5, &c), PG_ERR_NULL);
    assert_int_equal(pg_command_queue_push(&q, NULL, 5, &c), PG_ERR_NULL);
    assert_int_equal(pg_command_queue_push(&q, t.w, 5, NULL), PG_ERR_NULL);
    free_world(&t);
}

/* Late commands (their frame passed without apply_due) are applied at the next call, in
 * frame order. */
static void test_queue_late(void **state)
{
    test_world t = make_world();
    pg_command commands[4];
    uint64_t frames[4];
    pg_command_queue q;
    int i;
    (void)state;
    pg_command_queue_init(&q, commands, frames, 4);
    for (i = 0; i < 3; ++i) {
        pg_command c = tagged_create((uint64_t)(10 - i));
        assert_int_equal(pg_command_queue_push(&q, t.w, (uint64_t)(3 - i), &c), PG_OK); /* frames 3, 2, 1 */
    }
    for (i = 0; i < 5; ++i) assert_int_equal(pg_world_step(t.w), PG_OK);
    PG_EXPECT_EQ(pg_command_queue_apply_due(&q, t.w, NULL), 3, "%s", "late");
    for (i = 0; i < 3; ++i) {
        pg_body_id id;
        id.index = 3u + (uint32_t)i;
        id.generation = 1;
        PG_EXPECT_EQ(pg_body_user_data(t.w, id), 8 + i, "%d", i);
    }
    free_world(&t);
}

/* ---- messages and validation at push -------------------------------------------------------- */
/* r is `code` and pg_world_last_error starts with the code's name and mentions both texts. */
static void expect_message(const pg_world *w, pg_result r, pg_result code, const char *text1, const char *text2, int line)
{
    const char *e = pg_world_last_error(w), *name = pg_result_name(code);
    if (r != code || strncmp(e, name, strlen(name)) != 0 || strstr(e, text1) == NULL || strstr(e, text2) == NULL) {
        print_error("line %d: got %s \"%s\", want %s mentioning \"%s\" and \"%s\"\n", line, pg_result_name(r), e, name,
                    text1, text2);
        fail();
    }
}
#define EXPECT_MESSAGE(w, call, code, text1, text2) expect_message((w), (call), (code), (text1), (text2), __LINE__)

/* pg_command_apply says which command was refused and why. */
static void test_apply_messages(void **state)
{
    test_world t = make_world();
    pg_command c;
    pg_body_id created;
    uint64_t h = pg_world_hash(t.w);
    (void)state;
    c = pg_command_init((pg_command_kind)55);
    EXPECT_MESSAGE(t.w, pg_command_apply(t.w, &c, &created), PG_ERR_INVALID_ARGUMENT, "pg_command_apply", "kind 55");
    c = pg_command_init((pg_command_kind)-3);
    EXPECT_MESSAGE(t.w, pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT, "pg_command_apply", "kind -3");
    c = pg_command_init(PG_CMD_NONE);
    EXPECT_MESSAGE(t.w, pg_command_apply(t.w, &c, NULL), PG_ERR_INVALID_ARGUMENT, "pg_command_apply", "kind 0");
    c = full_command(PG_CMD_MAKE, t.target);
    c.make_kind = (pg_make_kind)17;
    EXPECT_MESSAGE(t.w, pg_command_apply(t.w, &c, &created), PG_ERR_INVALID_ARGUMENT, "pg_command_apply", "make_kind 17");
    assert_int_equal(created.index, 0);
    EXPECT_MESSAGE(t.w, pg_command_apply(t.w, NULL, &created), PG_ERR_NULL, "pg_command_apply", "command is NULL");
    assert_true(pg_world_hash(t.w) == h);
    free_world(&t);
}

/* pg_command_queue_push refuses what can never be applied (what pg_command_encode refuses)
 * and says why, in the world's pg_world_last_error, for every refusal. */
static void test_queue_push_validates(void **state)
{
    test_world t = make_world();
    pg_command commands[2], c;
    uint64_t frames[2];
    pg_command_queue q, none;
    uint64_t h;
    int k;
    (void)state;
    pg_command_queue_init(&q, commands, frames, 2);
    for (k = 0; k < 3; ++k) assert_int_equal(pg_world_step(t.w), PG_OK);
    h = pg_world_hash(t.w);
    c = pg_command_init((pg_command_kind)55);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "kind 55");
    c = pg_command_init(PG_CMD_NONE);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "kind 0");
    c = pg_command_init(PG_CMD_KIND_COUNT);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "kind 34");
    c = full_command(PG_CMD_MAKE, t.target);
    c.make_kind = (pg_make_kind)9;
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "make_kind 9");
    c = full_command(PG_CMD_CREATE_BODY, t.target);
    c.body_def.type = (pg_body_type)3;
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "body_def.type 3");
    c = full_command(PG_CMD_ADD_SHAPE, t.target);
    c.geometry.count = 9;
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "geometry.count 9");
    c = full_command(PG_CMD_ADD_SHAPE, t.target);
    c.geometry.kind = (pg_shape_kind)5;
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "geometry.kind 5");
    c = full_command(PG_CMD_ADD_SHAPE, t.target);
    c.geometry.kind = PG_SHAPE_CHAIN_SEGMENT;
    c.geometry.count = 3;
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "geometry.count 3");
    assert_int_equal(q.count, 0);
    /* the other refusals say why too */
    c = full_command(PG_CMD_SET_GRAVITY, t.target);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 2, &c), PG_ERR_INVALID_ARGUMENT, "pg_command_queue_push", "frame 2");
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, NULL), PG_ERR_NULL, "pg_command_queue_push", "command is NULL");
    EXPECT_MESSAGE(t.w, pg_command_queue_push(NULL, t.w, 5, &c), PG_ERR_NULL, "pg_command_queue_push", "queue is NULL");
    pg_command_queue_init(&none, NULL, frames, 2);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&none, t.w, 5, &c), PG_ERR_CAPACITY, "pg_command_queue_push", "no storage");
    assert_int_equal(pg_command_queue_push(&q, t.w, 3, &c), PG_OK);
    assert_int_equal(pg_command_queue_push(&q, t.w, 5, &c), PG_OK);
    EXPECT_MESSAGE(t.w, pg_command_queue_push(&q, t.w, 5, &c), PG_ERR_CAPACITY, "pg_command_queue_push", "full (capacity 2)");
    assert_int_equal(q.count, 2);
    assert_true(pg_world_hash(t.w) == h);
    /* every valid kind is accepted */
    for (k = 1; k < PG_CMD_KIND_COUNT; ++k) {
        pg_command_queue one;
        c = full_command((pg_command_kind)k, t.target);
        pg_command_queue_init(&one, commands, frames, 1);
        PG_EXPECT_EQ(pg_command_queue_push(&one, t.w, 3, &c), PG_OK, "%s", pg_command_kind_name(c.kind));
    }
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_round_trip_every_kind, free_leftovers),
        cmocka_unit_test_teardown(test_round_trip_variants, free_leftovers),
        cmocka_unit_test_teardown(test_apply_chain_segment, free_leftovers),
        cmocka_unit_test_teardown(test_encoding_follows_documented_layout, free_leftovers),
        cmocka_unit_test_teardown(test_encode_rejects_invalid_commands, free_leftovers),
        cmocka_unit_test_teardown(test_encode_rejects_values_decode_rejects, free_leftovers),
        cmocka_unit_test_teardown(test_decode_every_prefix, free_leftovers),
        cmocka_unit_test_teardown(test_decode_prefix_names_field, free_leftovers),
        cmocka_unit_test_teardown(test_decode_invalid_kind, free_leftovers),
        cmocka_unit_test_teardown(test_decode_invalid_values, free_leftovers),
        cmocka_unit_test_teardown(test_decode_invalid_flag, free_leftovers),
        cmocka_unit_test_teardown(test_decode_failure_zeroes_command, free_leftovers),
        cmocka_unit_test_teardown(test_kind_names, free_leftovers),
        cmocka_unit_test_teardown(test_apply_equals_direct_call, free_leftovers),
        cmocka_unit_test_teardown(test_apply_failures, free_leftovers),
        cmocka_unit_test_teardown(test_queue_order, free_leftovers),
        cmocka_unit_test_teardown(test_queue_errors_and_failures, free_leftovers),
        cmocka_unit_test_teardown(test_queue_late, free_leftovers),
        cmocka_unit_test_teardown(test_apply_messages, free_leftovers),
        cmocka_unit_test_teardown(test_queue_push_validates, free_leftovers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
