/* command.c — the command form of every change made to a world from outside a step,
 * its canonical binary encoding, and a queue for later frames. */
#include <stddef.h>

#include "pogon/replay.h"
#include "wide.h"
#include "text.h"
#include "world_internal.h" /* pg__fail: messages in pg_world_last_error */

static const char *const kind_names[PG_CMD_KIND_COUNT] = {
    "none", "create_body", "destroy_body", "add_shape", "make", "set_transform", "set_linear_velocity",
    "set_angular_velocity", "apply_force", "apply_torque", "apply_linear_impulse", "apply_angular_impulse",
    "set_body_type", "set_awake", "set_gravity", "set_effects", "set_gravity_scale", "set_damping",
    "set_friction", "set_restitution", "set_density", "set_fixed_rotation", "set_filter", "set_user_data",
    "create_distance_joint", "create_revolute_joint", "create_weld_joint", "create_prismatic_joint", "create_mouse_joint",
    "destroy_joint", "set_joint_motor", "set_joint_limits", "set_mouse_target", "set_mouse_max_force"};

const char *pg_command_kind_name(pg_command_kind kind)
{
    return (unsigned)kind < PG_CMD_KIND_COUNT ? kind_names[kind] : "unknown";
}

/* The CREATE_*_JOINT kinds' defaults, copied without the padding bytes a whole-struct
 * copy may bring (the distance, revolute, weld and prismatic defs have none before
 * their cookie; the mouse def is copied field by field). */
#define COPY_TO_COOKIE(dst, src, type) memcpy_bytes((dst), (src), offsetof(type, pg__cookie) + sizeof(uint32_t))
static void memcpy_bytes(void *dst, const void *src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *p = (const unsigned char *)src;
    size_t i;
    for (i = 0; i < n; ++i) d[i] = p[i];
}

static void init_joint_def(pg_command *c)
{
    switch (c->kind) {
    case PG_CMD_CREATE_DISTANCE_JOINT: {
        pg_distance_joint_def d = pg_default_distance_joint_def();
        COPY_TO_COOKIE(&c->joint_def.distance, &d, pg_distance_joint_def);
        break;
    }
    case PG_CMD_CREATE_REVOLUTE_JOINT: {
        pg_revolute_joint_def d = pg_default_revolute_joint_def();
        COPY_TO_COOKIE(&c->joint_def.revolute, &d, pg_revolute_joint_def);
        break;
    }
    case PG_CMD_CREATE_WELD_JOINT: {
        pg_weld_joint_def d = pg_default_weld_joint_def();
        COPY_TO_COOKIE(&c->joint_def.weld, &d, pg_weld_joint_def);
        break;
    }
    case PG_CMD_CREATE_PRISMATIC_JOINT: {
        pg_prismatic_joint_def d = pg_default_prismatic_joint_def();
        COPY_TO_COOKIE(&c->joint_def.prismatic, &d, pg_prismatic_joint_def);
        break;
    }
    case PG_CMD_CREATE_MOUSE_JOINT: {
        pg_mouse_joint_def d = pg_default_mouse_joint_def();
        pg_mouse_joint_def *m = &c->joint_def.mouse;
        m->body = d.body;
        m->target = d.target;
        m->hertz = d.hertz;
        m->damping_ratio = d.damping_ratio;
        m->max_force = d.max_force;
        m->user_data = d.user_data;
        m->pg__cookie = d.pg__cookie;
        break;
    }
    default: break;
    }
}

pg_command pg_command_init(pg_command_kind kind)
{
    pg_command c;
    unsigned char *p = (unsigned char *)&c;
    size_t i;
    for (i = 0; i < sizeof c; ++i) p[i] = 0; /* padding too: a command has one byte image */
    c.kind = kind;
    /* the defs start from their defaults, as every def must (the defs have no padding) */
    c.body_def = pg_default_body_def();
    c.shape_def = pg_default_shape_def();
    init_joint_def(&c);
    /* cppcheck-suppress uninitvar ; every byte of c was set by the loop above */
    return c;
}

/* Which fields each kind carries (also the order they are encoded in). */
enum {
    F_BODY = 1u << 0, F_VEC = 1u << 1, F_POINT = 1u << 2, F_SCALAR = 1u << 3, F_SCALAR2 = 1u << 4,
    F_ANGLE = 1u << 5, F_VALUE = 1u << 6, F_VALUE2 = 1u << 7, F_FLAG = 1u << 8, F_USER = 1u << 9,
    F_MAKE = 1u << 10, F_BODY_DEF = 1u << 11, F_SHAPE_DEF = 1u << 12, F_GEOMETRY = 1u << 13,
    F_JOINT = 1u << 14, F_JOINT_DEF = 1u << 15
};

static const uint32_t kind_fields[PG_CMD_KIND_COUNT] = {
    0,
    F_BODY_DEF,                                  /* create_body */
    F_BODY,                                      /* destroy_body */
    F_BODY | F_SHAPE_DEF | F_GEOMETRY,           /* add_shape */
    F_MAKE | F_BODY_DEF | F_SHAPE_DEF,           /* make */
    F_BODY | F_VEC | F_ANGLE,                    /* set_transform */
    F_BODY | F_VEC,                              /* set_linear_velocity */
    F_BODY | F_SCALAR,                           /* set_angular_velocity */
    F_BODY | F_VEC | F_FLAG | F_POINT,           /* apply_force */
    F_BODY | F_SCALAR,                           /* apply_torque */
    F_BODY | F_VEC | F_POINT,                    /* apply_linear_impulse */
    F_BODY | F_SCALAR,                           /* apply_angular_impulse */
    F_BODY | F_VALUE,                            /* set_body_type */
    F_BODY | F_VALUE,                            /* set_awake */
    F_VEC,                                       /* set_gravity */
    F_VALUE,                                     /* set_effects */
    F_BODY | F_SCALAR,                           /* set_gravity_scale */
    F_BODY | F_SCALAR | F_SCALAR2,               /* set_damping */
    F_BODY | F_SCALAR,                           /* set_friction */
    F_BODY | F_SCALAR,                           /* set_restitution */
    F_BODY | F_SCALAR,                           /* set_density */
    F_BODY | F_VALUE,                            /* set_fixed_rotation */
    F_BODY | F_VALUE | F_VALUE2,                 /* set_filter */
    F_BODY | F_USER,                             /* set_user_data */
    F_JOINT_DEF,                                 /* create_distance_joint */
    F_JOINT_DEF,                                 /* create_revolute_joint */
    F_JOINT_DEF,                                 /* create_weld_joint */
    F_JOINT_DEF,                                 /* create_prismatic_joint */
    F_JOINT_DEF,                                 /* create_mouse_joint */
    F_JOINT,                                     /* destroy_joint */
    F_JOINT | F_FLAG | F_SCALAR | F_SCALAR2,     /* set_joint_motor */
    F_JOINT | F_FLAG | F_SCALAR | F_SCALAR2,     /* set_joint_limits */
    F_JOINT | F_VEC,                             /* set_mouse_target */
    F_JOINT | F_SCALAR                           /* set_mouse_max_force */
};

/* ---- messages (text.h) ----------------------------------------------------------------- */
typedef struct text { char buf[144]; pg__text out; } text;

static void put_text(text *t, const char *s) { pg__text_put(&t->out, s); }
static void put_uint(text *t, uint64_t v) { pg__text_u64(&t->out, v); }
static void put_int(text *t, int64_t v) { pg__text_i64(&t->out, v); }

static void start(text *t, const char *fn)
{
    t->out = pg__text_in(t->buf, sizeof t->buf);
    put_text(t, fn);
    put_text(t, ": ");
}

/* An enum member as the int it was given as, without implementation-defined conversion. */
static int64_t enum_value(uint32_t bits) { return pg__i32_from_bits(bits); }

/* Why the command's kind (and a MAKE command's make_kind) name nothing pg_command_apply
 * can do, into t; 0 when they are fine. */
static int kind_problem(const pg_command *c, text *t)
{
    if ((unsigned)c->kind >= PG_CMD_KIND_COUNT || c->kind == PG_CMD_NONE) {
        put_text(t, "command kind ");
        put_int(t, enum_value((uint32_t)c->kind));
        put_text(t, " is not a PG_CMD_* value (1..");
        put_int(t, PG_CMD_KIND_COUNT - 1);
        put_text(t, ")");
        return 1;
    }
    if (c->kind == PG_CMD_MAKE && (unsigned)c->make_kind >= PG_MAKE_KIND_COUNT) {
        put_text(t, "make command's make_kind ");
        put_int(t, enum_value((uint32_t)c->make_kind));
        put_text(t, " is not a PG_MAKE_* value (0..");
        put_int(t, PG_MAKE_KIND_COUNT - 1);
        put_text(t, ")");
        return 1;
    }
    return 0;
}

/* A chain segment's geometry has its two vertices and, after them, its neighbours
 * (pg_geometry_chain_segment), which its encoding carries after the vertices. */
static int chain_count_ok(const pg_geometry *g) { return g->kind != PG_SHAPE_CHAIN_SEGMENT || g->count == 2; }

/* kind_problem and the rest of what pg_command_encode refuses: a command with no
 * encoding, which no world can apply (and no replay can record). */
static int command_problem(const pg_command *c, text *t)
{
    uint32_t f;
    if (kind_problem(c, t)) return 1;
    f = kind_fields[c->kind];
    if ((f & F_GEOMETRY) != 0 && (c->geometry.count < 0 || c->geometry.count > PG_MAX_VERTICES)) {
        put_text(t, "add_shape command's geometry.count ");
        put_int(t, c->geometry.count);
        put_text(t, " is outside 0..8");
        return 1;
    }
    if ((f & F_GEOMETRY) != 0 && (unsigned)c->geometry.kind > (unsigned)PG_SHAPE_CHAIN_SEGMENT) {
        put_text(t, "add_shape command's geometry.kind ");
        put_int(t, enum_value((uint32_t)c->geometry.kind));
        put_text(t, " is not a PG_SHAPE_* value (0..");
        put_int(t, PG_SHAPE_CHAIN_SEGMENT);
        put_text(t, ")");
        return 1;
    }
    if ((f & F_GEOMETRY) != 0 && !chain_count_ok(&c->geometry)) {
        put_text(t, "add_shape command's chain segment has geometry.count ");
        put_int(t, c->geometry.count);
        put_text(t, ", not 2 (its neighbours are vertices[2] and [3])");
        return 1;
    }
    if ((f & F_BODY_DEF) != 0 && (unsigned)c->body_def.type > (unsigned)PG_BODY_DYNAMIC) {
        put_text(t, pg_command_kind_name(c->kind));
        put_text(t, " command's body_def.type ");
        put_int(t, enum_value((uint32_t)c->body_def.type));
        put_text(t, " is not a PG_BODY_* value (0..");
        put_int(t, PG_BODY_DYNAMIC);
        put_text(t, ")");
        return 1;
    }
    return 0;
}

/* The joint commands of pg_command_apply_made. */
static pg_result apply_joint(pg_world *w, const pg_command *c, pg_joint_id *created)
{
    pg_joint_id id = {0, 0};
    pg_result r;
    const pg_command_joint_def *d = &c->joint_def;
    switch (c->kind) {
    case PG_CMD_CREATE_DISTANCE_JOINT: r = pg_distance_joint_create(w, &d->distance, &id); break;
    case PG_CMD_CREATE_REVOLUTE_JOINT: r = pg_revolute_joint_create(w, &d->revolute, &id); break;
    case PG_CMD_CREATE_WELD_JOINT: r = pg_weld_joint_create(w, &d->weld, &id); break;
    case PG_CMD_CREATE_PRISMATIC_JOINT: r = pg_prismatic_joint_create(w, &d->prismatic, &id); break;
    case PG_CMD_CREATE_MOUSE_JOINT: r = pg_mouse_joint_create(w, &d->mouse, &id); break;
    case PG_CMD_DESTROY_JOINT: return pg_joint_destroy(w, c->joint);
    case PG_CMD_SET_JOINT_MOTOR:
        if (pg_joint_type_of(w, c->joint) == PG_JOINT_PRISMATIC) return pg_prismatic_joint_set_motor(w, c->joint, c->flag != 0, c->scalar, c->scalar2);
        return pg_revolute_joint_set_motor(w, c->joint, c->flag != 0, c->scalar, c->scalar2); /* names any other kind in its error */
    case PG_CMD_SET_JOINT_LIMITS:
        if (pg_joint_type_of(w, c->joint) == PG_JOINT_DISTANCE) return pg_distance_joint_set_limits(w, c->joint, c->flag != 0, c->scalar, c->scalar2);
        if (pg_joint_type_of(w, c->joint) == PG_JOINT_PRISMATIC) return pg_prismatic_joint_set_limits(w, c->joint, c->flag != 0, c->scalar, c->scalar2);
        return pg_revolute_joint_set_limits(w, c->joint, c->flag != 0, c->scalar, c->scalar2);
    case PG_CMD_SET_MOUSE_TARGET: return pg_mouse_joint_set_target(w, c->joint, c->vec);
    default: return pg_mouse_joint_set_max_force(w, c->joint, c->scalar); /* PG_CMD_SET_MOUSE_MAX_FORCE */
    }
    if (r == PG_OK && created != NULL) *created = id;
    return r;
}

pg_result pg_command_apply(pg_world *w, const pg_command *c, pg_body_id *created)
{
    return pg_command_apply_made(w, c, created, NULL);
}

pg_result pg_command_apply_made(pg_world *w, const pg_command *c, pg_body_id *created, pg_joint_id *created_joint)
{
    pg_body_id id = {0, 0};
    pg_shape_id sid;
    pg_result r;
    text t;
    if (created != NULL) *created = id;
    if (created_joint != NULL) created_joint->index = created_joint->generation = 0;
    if (w == NULL) return PG_ERR_NULL;
    if (c == NULL) return pg__fail(w, PG_ERR_NULL, "pg_command_apply: command is NULL");
    start(&t, "pg_command_apply");
    if (kind_problem(c, &t)) return pg__fail(w, PG_ERR_INVALID_ARGUMENT, t.buf);
    if (c->kind >= PG_CMD_CREATE_DISTANCE_JOINT) return apply_joint(w, c, created_joint);
    switch (c->kind) {
    case PG_CMD_CREATE_BODY: r = pg_body_create(w, &c->body_def, &id); break;
    case PG_CMD_DESTROY_BODY: return pg_body_destroy(w, c->body);
    case PG_CMD_ADD_SHAPE: return pg_shape_create(w, c->body, &c->shape_def, &c->geometry, &sid);
    case PG_CMD_MAKE:
        switch (c->make_kind) {
        case PG_MAKE_BALL: r = pg_make_ball(w, &c->body_def, &c->shape_def, c->size0, &id); break;
        case PG_MAKE_CAPSULE: r = pg_make_capsule(w, &c->body_def, &c->shape_def, c->size0, c->size1, &id); break;
        case PG_MAKE_BOX: r = pg_make_box(w, &c->body_def, &c->shape_def, c->size0, c->size1, &id); break;
        case PG_MAKE_TRIANGLE: r = pg_make_triangle(w, &c->body_def, &c->shape_def, c->size0, &id); break;
        case PG_MAKE_STAR: r = pg_make_star(w, &c->body_def, &c->shape_def, c->size0, &id); break;
        case PG_MAKE_WALL: r = pg_make_wall(w, &c->body_def, &c->shape_def, c->size0, c->size1, &id); break;
        default: return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "pg_command_apply: make_kind is not a PG_MAKE_* value"); /* kind_problem caught it */
        }
        break;
    case PG_CMD_SET_TRANSFORM: return pg_body_set_transform(w, c->body, c->vec, c->angle);
    case PG_CMD_SET_LINEAR_VELOCITY: return pg_body_set_linear_velocity(w, c->body, c->vec);
    case PG_CMD_SET_ANGULAR_VELOCITY: return pg_body_set_angular_velocity(w, c->body, c->scalar);
    case PG_CMD_APPLY_FORCE:
        return c->flag ? pg_body_apply_force_at(w, c->body, c->vec, c->point) : pg_body_apply_force(w, c->body, c->vec);
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
    default: return pg__fail(w, PG_ERR_INVALID_ARGUMENT, "pg_command_apply: command kind is not a PG_CMD_* value"); /* kind_problem caught it */
    }
    if (r == PG_OK && created != NULL) *created = id;
    return r;
}

/* ---- binary encoding ---------------------------------------------------------------- */
typedef struct writer { uint8_t *p; size_t cap, len; int ok; } writer;

static void put_u8(writer *w, uint32_t v)
{
    if (w->len + 1u > w->cap) { w->ok = 0; return; }
    w->p[w->len++] = (uint8_t)(v & 0xFFu);
}
static void put_u32(writer *w, uint32_t v) { put_u8(w, v); put_u8(w, v >> 8); put_u8(w, v >> 16); put_u8(w, v >> 24); }
static void put_i32(writer *w, int32_t v) { put_u32(w, (uint32_t)v); }
static void put_u64(writer *w, uint64_t v) { put_u32(w, (uint32_t)(v & 0xFFFFFFFFu)); put_u32(w, (uint32_t)(v >> 32)); }
static void put_vec(writer *w, pg_vec2 v) { put_i32(w, v.x); put_i32(w, v.y); }

static void put_id(writer *w, uint32_t index, uint32_t generation) { put_u32(w, index); put_u32(w, generation); }

/* A joint def: its fields in the order of the def (docs/formats.md), flags as one byte. */
static void put_joint_def(writer *w, const pg_command *c)
{
    const pg_command_joint_def *j = &c->joint_def;
    switch (c->kind) {
    case PG_CMD_CREATE_DISTANCE_JOINT: {
        const pg_distance_joint_def *d = &j->distance;
        put_id(w, d->body_a.index, d->body_a.generation), put_id(w, d->body_b.index, d->body_b.generation);
        put_vec(w, d->local_anchor_a), put_vec(w, d->local_anchor_b), put_i32(w, d->length);
        put_u8(w, d->enable_spring != 0), put_i32(w, d->hertz), put_i32(w, d->damping_ratio);
        put_u8(w, d->enable_limit != 0), put_i32(w, d->min_length), put_i32(w, d->max_length);
        put_u8(w, d->collide_connected != 0), put_u64(w, d->user_data);
        break;
    }
    case PG_CMD_CREATE_REVOLUTE_JOINT: {
        const pg_revolute_joint_def *d = &j->revolute;
        put_id(w, d->body_a.index, d->body_a.generation), put_id(w, d->body_b.index, d->body_b.generation);
        put_vec(w, d->local_anchor_a), put_vec(w, d->local_anchor_b), put_u32(w, d->reference_angle);
        put_u8(w, d->enable_limit != 0), put_i32(w, d->lower_angle), put_i32(w, d->upper_angle);
        put_u8(w, d->enable_motor != 0), put_i32(w, d->motor_speed), put_i32(w, d->max_motor_torque);
        put_u8(w, d->collide_connected != 0), put_u64(w, d->user_data);
        break;
    }
    case PG_CMD_CREATE_WELD_JOINT: {
        const pg_weld_joint_def *d = &j->weld;
        put_id(w, d->body_a.index, d->body_a.generation), put_id(w, d->body_b.index, d->body_b.generation);
        put_vec(w, d->local_anchor_a), put_vec(w, d->local_anchor_b), put_u32(w, d->reference_angle);
        put_i32(w, d->linear_hertz), put_i32(w, d->linear_damping_ratio), put_i32(w, d->angular_hertz), put_i32(w, d->angular_damping_ratio);
        put_u8(w, d->collide_connected != 0), put_u64(w, d->user_data);
        break;
    }
    case PG_CMD_CREATE_PRISMATIC_JOINT: {
        const pg_prismatic_joint_def *d = &j->prismatic;
        put_id(w, d->body_a.index, d->body_a.generation), put_id(w, d->body_b.index, d->body_b.generation);
        put_vec(w, d->local_anchor_a), put_vec(w, d->local_anchor_b), put_vec(w, d->local_axis_a), put_u32(w, d->reference_angle);
        put_u8(w, d->enable_limit != 0), put_i32(w, d->lower_translation), put_i32(w, d->upper_translation);
        put_u8(w, d->enable_motor != 0), put_i32(w, d->motor_speed), put_i32(w, d->max_motor_force);
        put_u8(w, d->collide_connected != 0), put_u64(w, d->user_data);
        break;
    }
    default: {
        const pg_mouse_joint_def *d = &j->mouse;
        put_id(w, d->body.index, d->body.generation), put_vec(w, d->target);
        put_i32(w, d->hertz), put_i32(w, d->damping_ratio), put_i32(w, d->max_force), put_u64(w, d->user_data);
        break;
    }
    }
}

size_t pg_command_encode(const pg_command *c, uint8_t *buffer, size_t capacity)
{
    writer w;
    uint32_t f;
    int32_t i;
    if (c == NULL || buffer == NULL || (unsigned)c->kind >= PG_CMD_KIND_COUNT || c->kind == PG_CMD_NONE) return 0;
    /* refuse what decode would refuse, so every encoding decodes */
    if ((kind_fields[c->kind] & F_GEOMETRY) != 0 &&
        (c->geometry.count < 0 || c->geometry.count > PG_MAX_VERTICES ||
         (unsigned)c->geometry.kind > (unsigned)PG_SHAPE_CHAIN_SEGMENT || !chain_count_ok(&c->geometry)))
        return 0;
    if ((kind_fields[c->kind] & F_MAKE) != 0 && (unsigned)c->make_kind >= PG_MAKE_KIND_COUNT) return 0;
    if ((kind_fields[c->kind] & F_BODY_DEF) != 0 && (unsigned)c->body_def.type > (unsigned)PG_BODY_DYNAMIC) return 0;
    w.p = buffer;
    w.cap = capacity;
    w.len = 0;
    w.ok = 1;
    f = kind_fields[c->kind];
    put_u8(&w, (uint32_t)c->kind);
    if (f & F_JOINT) { put_u32(&w, c->joint.index); put_u32(&w, c->joint.generation); }
    if (f & F_BODY) { put_u32(&w, c->body.index); put_u32(&w, c->body.generation); }
    if (f & F_VEC) put_vec(&w, c->vec);
    if (f & F_FLAG) put_u8(&w, c->flag != 0);
    if (f & F_POINT) put_vec(&w, c->point);
    if (f & F_SCALAR) put_i32(&w, c->scalar);
    if (f & F_SCALAR2) put_i32(&w, c->scalar2);
    if (f & F_ANGLE) put_u32(&w, c->angle);
    if (f & F_VALUE) put_u32(&w, c->value);
    if (f & F_VALUE2) put_u32(&w, c->value2);
    if (f & F_USER) put_u64(&w, c->user_data);
    if (f & F_MAKE) { put_u8(&w, (uint32_t)c->make_kind); put_i32(&w, c->size0); put_i32(&w, c->size1); }
    if (f & F_BODY_DEF) {
        const pg_body_def *d = &c->body_def;
        put_u8(&w, (uint32_t)d->type);
        put_vec(&w, d->position);
        put_u32(&w, d->angle);
        put_vec(&w, d->linear_velocity);
        put_i32(&w, d->angular_velocity);
        put_i32(&w, d->linear_damping);
        put_i32(&w, d->angular_damping);
        put_i32(&w, d->gravity_scale);
        put_u8(&w, d->fixed_rotation != 0);
        put_u8(&w, d->allow_sleep != 0);
        put_u8(&w, d->awake != 0);
        put_u64(&w, d->user_data);
    }
    if (f & F_SHAPE_DEF) {
        const pg_shape_def *d = &c->shape_def;
        put_i32(&w, d->density);
        put_i32(&w, d->friction);
        put_i32(&w, d->restitution);
        put_u32(&w, d->category);
        put_u32(&w, d->mask);
    }
    if (f & F_GEOMETRY) {
        put_u8(&w, (uint32_t)c->geometry.kind);
        put_u8(&w, (uint32_t)c->geometry.count);
        for (i = 0; i < c->geometry.count; ++i) put_vec(&w, c->geometry.vertices[i]);
        if (c->geometry.kind == PG_SHAPE_CHAIN_SEGMENT) { /* its neighbours, before then after */
            put_vec(&w, c->geometry.vertices[2]);
            put_vec(&w, c->geometry.vertices[3]);
        }
        put_i32(&w, c->geometry.radius);
    }
    if (f & F_JOINT_DEF) put_joint_def(&w, c);
    return w.ok ? w.len : 0;
}

typedef struct reader {
    const uint8_t *p;
    size_t size, pos;
    size_t error_offset;
    const char *error_field;
} reader;

static int need(reader *r, size_t n, const char *field)
{
    if (r->error_field != NULL) return 0;
    if (r->size - r->pos < n) {
        r->error_offset = r->pos;
        r->error_field = field;
        return 0;
    }
    return 1;
}
static uint32_t get_u8(reader *r, const char *field) { return need(r, 1, field) ? r->p[r->pos++] : 0u; }
static uint32_t get_u32(reader *r, const char *field)
{
    uint32_t v;
    if (!need(r, 4, field)) return 0;
    v = (uint32_t)r->p[r->pos] | (uint32_t)r->p[r->pos + 1] << 8 | (uint32_t)r->p[r->pos + 2] << 16 | (uint32_t)r->p[r->pos + 3] << 24;
    r->pos += 4;
    return v;
}
static int32_t get_i32(reader *r, const char *field) { return pg__i32_from_bits(get_u32(r, field)); }
static uint64_t get_u64(reader *r, const char *field)
{
    uint64_t lo = get_u32(r, field);
    return lo | (uint64_t)get_u32(r, field) << 32;
}
static pg_vec2 get_vec(reader *r, const char *field)
{
    pg_vec2 v;
    v.x = get_i32(r, field);
    v.y = get_i32(r, field);
    return v;
}
static int bad(reader *r, size_t at, const char *field)
{
    if (r->error_field == NULL) {
        r->error_offset = at;
        r->error_field = field;
    }
    return 0;
}
static uint32_t get_bool(reader *r, const char *field)
{
    size_t at = r->pos;
    uint32_t v = get_u8(r, field);
    if (v > 1u) bad(r, at, field);
    return v;
}

static pg_body_id get_id(reader *r, const char *field)
{
    pg_body_id id;
    id.index = get_u32(r, field);
    id.generation = get_u32(r, field);
    return id;
}

/* The fields put_joint_def writes, into the def pg_command_init left with its defaults. */
static void get_joint_def(reader *r, pg_command *c)
{
    pg_command_joint_def *j = &c->joint_def;
    switch (c->kind) {
    case PG_CMD_CREATE_DISTANCE_JOINT: {
        pg_distance_joint_def *d = &j->distance;
        d->body_a = get_id(r, "command.joint_def.body_a"), d->body_b = get_id(r, "command.joint_def.body_b");
        d->local_anchor_a = get_vec(r, "command.joint_def.local_anchor_a"), d->local_anchor_b = get_vec(r, "command.joint_def.local_anchor_b");
        d->length = get_i32(r, "command.joint_def.length");
        d->enable_spring = (int)get_bool(r, "command.joint_def.enable_spring");
        d->hertz = get_i32(r, "command.joint_def.hertz"), d->damping_ratio = get_i32(r, "command.joint_def.damping_ratio");
        d->enable_limit = (int)get_bool(r, "command.joint_def.enable_limit");
        d->min_length = get_i32(r, "command.joint_def.min_length"), d->max_length = get_i32(r, "command.joint_def.max_length");
        d->collide_connected = (int)get_bool(r, "command.joint_def.collide_connected");
        d->user_data = get_u64(r, "command.joint_def.user_data");
        break;
    }
    case PG_CMD_CREATE_REVOLUTE_JOINT: {
        pg_revolute_joint_def *d = &j->revolute;
        d->body_a = get_id(r, "command.joint_def.body_a"), d->body_b = get_id(r, "command.joint_def.body_b");
        d->local_anchor_a = get_vec(r, "command.joint_def.local_anchor_a"), d->local_anchor_b = get_vec(r, "command.joint_def.local_anchor_b");
        d->reference_angle = get_u32(r, "command.joint_def.reference_angle");
        d->enable_limit = (int)get_bool(r, "command.joint_def.enable_limit");
        d->lower_angle = get_i32(r, "command.joint_def.lower_angle"), d->upper_angle = get_i32(r, "command.joint_def.upper_angle");
        d->enable_motor = (int)get_bool(r, "command.joint_def.enable_motor");
        d->motor_speed = get_i32(r, "command.joint_def.motor_speed"), d->max_motor_torque = get_i32(r, "command.joint_def.max_motor_torque");
        d->collide_connected = (int)get_bool(r, "command.joint_def.collide_connected");
        d->user_data = get_u64(r, "command.joint_def.user_data");
        break;
    }
    case PG_CMD_CREATE_WELD_JOINT: {
        pg_weld_joint_def *d = &j->weld;
        d->body_a = get_id(r, "command.joint_def.body_a"), d->body_b = get_id(r, "command.joint_def.body_b");
        d->local_anchor_a = get_vec(r, "command.joint_def.local_anchor_a"), d->local_anchor_b = get_vec(r, "command.joint_def.local_anchor_b");
        d->reference_angle = get_u32(r, "command.joint_def.reference_angle");
        d->linear_hertz = get_i32(r, "command.joint_def.linear_hertz"), d->linear_damping_ratio = get_i32(r, "command.joint_def.linear_damping_ratio");
        d->angular_hertz = get_i32(r, "command.joint_def.angular_hertz"), d->angular_damping_ratio = get_i32(r, "command.joint_def.angular_damping_ratio");
        d->collide_connected = (int)get_bool(r, "command.joint_def.collide_connected");
        d->user_data = get_u64(r, "command.joint_def.user_data");
        break;
    }
    case PG_CMD_CREATE_PRISMATIC_JOINT: {
        pg_prismatic_joint_def *d = &j->prismatic;
        d->body_a = get_id(r, "command.joint_def.body_a"), d->body_b = get_id(r, "command.joint_def.body_b");
        d->local_anchor_a = get_vec(r, "command.joint_def.local_anchor_a"), d->local_anchor_b = get_vec(r, "command.joint_def.local_anchor_b");
        d->local_axis_a = get_vec(r, "command.joint_def.local_axis_a");
        d->reference_angle = get_u32(r, "command.joint_def.reference_angle");
        d->enable_limit = (int)get_bool(r, "command.joint_def.enable_limit");
        d->lower_translation = get_i32(r, "command.joint_def.lower_translation"), d->upper_translation = get_i32(r, "command.joint_def.upper_translation");
        d->enable_motor = (int)get_bool(r, "command.joint_def.enable_motor");
        d->motor_speed = get_i32(r, "command.joint_def.motor_speed"), d->max_motor_force = get_i32(r, "command.joint_def.max_motor_force");
        d->collide_connected = (int)get_bool(r, "command.joint_def.collide_connected");
        d->user_data = get_u64(r, "command.joint_def.user_data");
        break;
    }
    default: {
        pg_mouse_joint_def *d = &j->mouse;
        d->body = get_id(r, "command.joint_def.body");
        d->target = get_vec(r, "command.joint_def.target");
        d->hertz = get_i32(r, "command.joint_def.hertz"), d->damping_ratio = get_i32(r, "command.joint_def.damping_ratio");
        d->max_force = get_i32(r, "command.joint_def.max_force");
        d->user_data = get_u64(r, "command.joint_def.user_data");
        break;
    }
    }
}

pg_result pg_command_decode(const uint8_t *buffer, size_t size, pg_command *c, size_t *consumed, size_t *error_offset,
                            const char **error_field)
{
    reader r;
    uint32_t f, kind;
    int32_t i;
    size_t at;
    if (consumed != NULL) *consumed = 0;
    if (buffer == NULL || c == NULL) return PG_ERR_NULL;
    r.p = buffer;
    r.size = size;
    r.pos = 0;
    r.error_field = NULL;
    r.error_offset = 0;
    kind = get_u8(&r, "command.kind");
    if (r.error_field == NULL && (kind == 0 || kind >= PG_CMD_KIND_COUNT)) bad(&r, 0, "command.kind");
    *c = pg_command_init(r.error_field == NULL ? (pg_command_kind)kind : PG_CMD_NONE);
    f = r.error_field == NULL ? kind_fields[kind] : 0u;
    if (f & F_JOINT) { c->joint.index = get_u32(&r, "command.joint.index"); c->joint.generation = get_u32(&r, "command.joint.generation"); }
    if (f & F_BODY) { c->body.index = get_u32(&r, "command.body.index"); c->body.generation = get_u32(&r, "command.body.generation"); }
    if (f & F_VEC) c->vec = get_vec(&r, "command.vec");
    if (f & F_FLAG) c->flag = get_bool(&r, "command.flag");
    if (f & F_POINT) c->point = get_vec(&r, "command.point");
    if (f & F_SCALAR) c->scalar = get_i32(&r, "command.scalar");
    if (f & F_SCALAR2) c->scalar2 = get_i32(&r, "command.scalar2");
    if (f & F_ANGLE) c->angle = get_u32(&r, "command.angle");
    if (f & F_VALUE) c->value = get_u32(&r, "command.value");
    if (f & F_VALUE2) c->value2 = get_u32(&r, "command.value2");
    if (f & F_USER) c->user_data = get_u64(&r, "command.user_data");
    if (f & F_MAKE) {
        at = r.pos;
        c->make_kind = (pg_make_kind)get_u8(&r, "command.make_kind");
        if ((unsigned)c->make_kind >= PG_MAKE_KIND_COUNT) bad(&r, at, "command.make_kind");
        c->size0 = get_i32(&r, "command.size0");
        c->size1 = get_i32(&r, "command.size1");
    }
    if (f & F_BODY_DEF) {
        pg_body_def *d = &c->body_def;
        at = r.pos;
        d->type = (pg_body_type)get_u8(&r, "command.body_def.type");
        if ((unsigned)d->type > (unsigned)PG_BODY_DYNAMIC) bad(&r, at, "command.body_def.type");
        d->position = get_vec(&r, "command.body_def.position");
        d->angle = get_u32(&r, "command.body_def.angle");
        d->linear_velocity = get_vec(&r, "command.body_def.linear_velocity");
        d->angular_velocity = get_i32(&r, "command.body_def.angular_velocity");
        d->linear_damping = get_i32(&r, "command.body_def.linear_damping");
        d->angular_damping = get_i32(&r, "command.body_def.angular_damping");
        d->gravity_scale = get_i32(&r, "command.body_def.gravity_scale");
        d->fixed_rotation = (int)get_bool(&r, "command.body_def.fixed_rotation");
        d->allow_sleep = (int)get_bool(&r, "command.body_def.allow_sleep");
        d->awake = (int)get_bool(&r, "command.body_def.awake");
        d->user_data = get_u64(&r, "command.body_def.user_data");
    }
    if (f & F_SHAPE_DEF) {
        pg_shape_def *d = &c->shape_def;
        d->density = get_i32(&r, "command.shape_def.density");
        d->friction = get_i32(&r, "command.shape_def.friction");
        d->restitution = get_i32(&r, "command.shape_def.restitution");
        d->category = get_u32(&r, "command.shape_def.category");
        d->mask = get_u32(&r, "command.shape_def.mask");
    }
    if (f & F_GEOMETRY) {
        at = r.pos;
        c->geometry.kind = (pg_shape_kind)get_u8(&r, "command.geometry.kind");
        if ((unsigned)c->geometry.kind > (unsigned)PG_SHAPE_CHAIN_SEGMENT) bad(&r, at, "command.geometry.kind");
        at = r.pos;
        c->geometry.count = (int32_t)get_u8(&r, "command.geometry.count");
        if (c->geometry.count > PG_MAX_VERTICES || !chain_count_ok(&c->geometry)) bad(&r, at, "command.geometry.count");
        for (i = 0; r.error_field == NULL && i < c->geometry.count; ++i) c->geometry.vertices[i] = get_vec(&r, "command.geometry.vertex");
        if (r.error_field == NULL && c->geometry.kind == PG_SHAPE_CHAIN_SEGMENT) {
            c->geometry.vertices[2] = get_vec(&r, "command.geometry.neighbour");
            c->geometry.vertices[3] = get_vec(&r, "command.geometry.neighbour");
        }
        c->geometry.radius = get_i32(&r, "command.geometry.radius");
    }
    if (f & F_JOINT_DEF) get_joint_def(&r, c);
    if (r.error_field != NULL) {
        if (error_offset != NULL) *error_offset = r.error_offset;
        if (error_field != NULL) *error_field = r.error_field;
        *c = pg_command_init(PG_CMD_NONE);
        return PG_ERR_INVALID_ARGUMENT;
    }
    if (consumed != NULL) *consumed = r.pos;
    return PG_OK;
}

/* ---- queue ------------------------------------------------------------------------------ */
void pg_command_queue_init(pg_command_queue *q, pg_command *commands, uint64_t *frames, uint32_t capacity)
{
    if (q == NULL) return;
    q->commands = commands;
    q->frames = frames;
    q->capacity = (commands != NULL && frames != NULL) ? capacity : 0;
    q->count = 0;
}

pg_result pg_command_queue_push(pg_command_queue *q, const pg_world *world, uint64_t frame, const pg_command *command)
{
    static const char fn[] = "pg_command_queue_push";
    uint32_t i;
    text t;
    if (world == NULL) return PG_ERR_NULL;
    if (q == NULL) return pg__fail(world, PG_ERR_NULL, "pg_command_queue_push: queue is NULL");
    if (command == NULL) return pg__fail(world, PG_ERR_NULL, "pg_command_queue_push: command is NULL");
    start(&t, fn);
    if (command_problem(command, &t)) return pg__fail(world, PG_ERR_INVALID_ARGUMENT, t.buf);
    if (frame < pg_world_frame(world)) {
        put_text(&t, "frame ");
        put_uint(&t, frame);
        put_text(&t, " is already past (the world is at frame ");
        put_uint(&t, pg_world_frame(world));
        put_text(&t, "): use pg_world_frame(world) or later");
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, t.buf);
    }
    if (q->capacity == 0 || q->commands == NULL || q->frames == NULL)
        return pg__fail(world, PG_ERR_CAPACITY, "pg_command_queue_push: the queue has no storage: give pg_command_queue_init two arrays and their capacity");
    if (q->count >= q->capacity) {
        put_text(&t, "the queue is full (capacity ");
        put_uint(&t, q->capacity);
        put_text(&t, "): apply due commands (pg_command_queue_apply_due) or give it larger arrays");
        return pg__fail(world, PG_ERR_CAPACITY, t.buf);
    }
    /* insert after every command of the same or an earlier frame: stable by frame */
    i = q->count;
    while (i > 0 && q->frames[i - 1u] > frame) {
        q->frames[i] = q->frames[i - 1u];
        q->commands[i] = q->commands[i - 1u];
        --i;
    }
    q->frames[i] = frame;
    q->commands[i] = *command;
    q->count += 1u;
    return PG_OK;
}

uint32_t pg_command_queue_apply_due(pg_command_queue *q, pg_world *world, uint32_t *failures)
{
    uint32_t applied = 0, failed = 0, i, rest;
    uint64_t now;
    if (failures != NULL) *failures = 0;
    if (q == NULL || world == NULL) return 0;
    now = pg_world_frame(world);
    while (applied < q->count && q->frames[applied] <= now) {
        if (pg_command_apply(world, &q->commands[applied], NULL) != PG_OK) ++failed;
        ++applied;
    }
    for (i = 0, rest = q->count - applied; i < rest; ++i) {
        q->frames[i] = q->frames[i + applied];
        q->commands[i] = q->commands[i + applied];
    }
    q->count -= applied;
    if (failures != NULL) *failures = failed;
    return applied;
}
