/* state.c — the canonical encoding of a world's state: hashes, snapshots, diffs.
 *
 * One encoder serves all three: it walks the state in a fixed order and emits
 * little-endian fixed-width fields, either into a buffer (snapshot), into a running
 * FNV-1a hash per section (hashes) or nowhere (sizing). Restoring parses the same
 * layout twice: once to validate everything, then to write the world, so a corrupt
 * snapshot changes nothing.
 *
 * Layout (docs/formats.md, "Snapshots"):
 *   "PGSN" u16 version, u16 engine major, minor, patch (version.h), u32 numeric
 *   configuration (config.h), u32 max_bodies u32 max_shapes u32 max_contacts
 *   then for each section s in order: u8 s, u32 byte length, the section's bytes, u64
 *   the section's hash (FNV-1a of its bytes, as pg_world_section_hashes gives it);
 *   then u64 checksum, FNV-1a of every byte before it. Restoring checks the checksum
 *   (and names the section whose hash fails) before it reads a value, then refuses a
 *   snapshot of other numerics (another numeric configuration, or another major.minor
 *   version: they step differently), then validates the structure, then writes the
 *   world.
 * Derived data is not stored: a body's origin and rotation come from its centre and
 * angle, a shape's collision form from its geometry, every cached world geometry is
 * recomputed at the next step.
 */
#include "pogon/replay.h"
#include "wide.h"
#include "text.h"
#include "numeric_config.h"
#include "world_internal.h"

#define SNAPSHOT_MAGIC 0x4E534750u /* "PGSN" */
#define SNAPSHOT_VERSION 6u /* 2: inverse mass and inertia are derived, not stored; 3: a
                              contact point's push_impulse; 4: section hashes and a checksum;
                              5: the engine version and the numeric configuration; 6: joints */
#define SNAPSHOT_HEADER_SIZE 28u /* magic, version, engine version, numeric configuration,
                                    three capacities */
#define SNAPSHOT_OFF_ENGINE 6u   /* u16 major, minor, patch */
#define SNAPSHOT_OFF_CONFIG 12u  /* u32 pg_numeric_config() */

/* What a world can hold, from the code that writes each value. Restoring refuses a
 * value beyond these: only corruption makes one, and the step's arithmetic relies on
 * them (an accumulated force beyond FORCE_LIMIT overflows the next pg_body_apply_force,
 * a contact friction of -2^31 the solver's rows). Keep them in step with the sources. */
#define LIMIT_VELOCITY PG_SOLVER_VELOCITY_MAX /* the solver clamps each velocity
                                              component (m/s) and the angular velocity (rad/s) to it;
                                              the setters stay within max_linear_speed <= 4096 m/s and
                                              1000 rad/s, below it */
#define LIMIT_FORCE (INT64_C(1) << 60)     /* body.c FORCE_LIMIT: pg_body_apply_force* clamp the
                                              accumulated force and torque to it */
#define LIMIT_LAMBDA PG_SOLVER_LAMBDA_MAX   /* accumulated contact impulses */
#define LIMIT_DAMPING PG_FIX_C(1000)       /* body.c: damping 0..1000 per second */
#define LIMIT_GRAVITY_SCALE PG_FIX_C(100)  /* body.c: gravity scale -100..100 */
#define LIMIT_SLEEP_TIME PG_FIX_C(1001)    /* island.c: the timer grows by one step (<= 1 s) while
                                              it is below 1000 s */
#define LIMIT_PENETRATION PG_FIX_C(1024)   /* collide.c: two shapes (vertices within 50 m of their
                                              bodies, radii up to 50 m) overlap by less than the sum
                                              of their widths and radii, under 400 m. (A separation
                                              has no upper limit: the speculative window of
                                              continuous collision grows with the speeds.) */
#define LIMIT_LOCAL_CENTER PG_FIX_C(51)    /* shape.c: vertices and circle centres lie within 50 m
                                              of the body, so their centre of mass does (1 m slack) */
/* A contact normal is a unit vector in Q2.30 (pg_dir_normalize, or a polygon's normal
 * turned by a rotation): its squared length is within 2^-9 of 1, far beyond rounding. */
#define UNIT_Q60 (INT64_C(1) << 60)
#define UNIT_TOLERANCE_Q60 (INT64_C(1) << 51)

static const char *const section_names[PG_SECTION_COUNT] = {"settings", "bodies", "shapes", "contacts", "broadphase", "joints"};

const char *pg_section_name(pg_section s) { return (unsigned)s < PG_SECTION_COUNT ? section_names[s] : "unknown"; }

uint64_t pg_hash_bytes(uint64_t seed, const void *data, size_t size)
{
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    if (p == NULL) return seed; /* no bytes: the hash of nothing */
    for (i = 0; i < size; ++i) {
        seed ^= p[i];
        seed *= UINT64_C(0x100000001b3);
    }
    return seed;
}

/* ---- the encoder -------------------------------------------------------------------- */
typedef struct sink {
    uint8_t *buf;     /* NULL: count (and hash) only */
    size_t cap, len;
    int overflow;
    uint64_t hash;    /* FNV-1a of the current section */
} sink;

static void emit(sink *s, uint32_t byte)
{
    uint8_t b = (uint8_t)(byte & 0xFFu);
    s->hash = (s->hash ^ b) * UINT64_C(0x100000001b3);
    if (s->buf != NULL) {
        if (s->len < s->cap) s->buf[s->len] = b;
        else s->overflow = 1;
    }
    s->len += 1u;
}
static void emit_u32(sink *s, uint32_t v) { emit(s, v); emit(s, v >> 8); emit(s, v >> 16); emit(s, v >> 24); }
static void emit_i32(sink *s, int32_t v) { emit_u32(s, (uint32_t)v); }
static void emit_u64(sink *s, uint64_t v) { emit_u32(s, (uint32_t)(v & 0xFFFFFFFFu)); emit_u32(s, (uint32_t)(v >> 32)); }
static void emit_i64(sink *s, int64_t v) { emit_u64(s, (uint64_t)v); }
static void emit_vec(sink *s, pg_vec2 v) { emit_i32(s, v.x); emit_i32(s, v.y); }

/* Optional body fields, present when not at their usual value: a resting body then
 * costs a few bytes only. */
enum {
    B_VELOCITY = 1u << 0, B_ANGULAR = 1u << 1, B_FORCES = 1u << 2, B_DAMPING = 1u << 3, B_GRAVITY_SCALE = 1u << 4,
    B_USER = 1u << 5, B_SLEEP_TIME = 1u << 6, B_ISLAND = 1u << 7, B_MASS = 1u << 8
};

static uint32_t body_presence(const pg_body *b)
{
    uint32_t m = 0;
    if (b->v.x != 0 || b->v.y != 0) m |= B_VELOCITY;
    if (b->w != 0) m |= B_ANGULAR;
    if (b->force_x != 0 || b->force_y != 0 || b->torque != 0) m |= B_FORCES;
    if (b->linear_damping != 0 || b->angular_damping != 0) m |= B_DAMPING;
    if (b->gravity_scale != PG_FIX_ONE) m |= B_GRAVITY_SCALE;
    if (b->user_data != 0) m |= B_USER;
    if (b->sleep_time != 0) m |= B_SLEEP_TIME;
    if (b->island != PG_NULL_INDEX) m |= B_ISLAND;
    if (b->type == PG_BODY_DYNAMIC) m |= B_MASS;
    return m;
}

static void encode_settings(const pg_world *w, sink *s)
{
    const pg_world_def *d = &w->def;
    emit_vec(s, d->gravity);
    emit_u32(s, d->step_hz);
    emit_u32(s, d->substeps);
    emit_u32(s, d->effects);
    emit_i32(s, d->contact_hertz);
    emit_i32(s, d->contact_damping_ratio);
    emit_i32(s, d->contact_push_max);
    emit_i32(s, d->restitution_threshold);
    emit_i32(s, d->max_linear_speed);
    emit_i32(s, d->sleep_linear_tolerance);
    emit_i32(s, d->sleep_angular_tolerance);
    emit_i32(s, d->time_to_sleep);
    emit_u64(s, w->frame);
}

static void encode_body(const pg_body *b, sink *s)
{
    uint32_t m;
    emit_u32(s, b->generation);
    emit(s, (b->flags & PG_BODY_FLAG_USED) != 0);
    if ((b->flags & PG_BODY_FLAG_USED) == 0) return;
    m = body_presence(b);
    emit_u32(s, m);
    emit(s, (uint32_t)b->type);
    emit(s, b->flags & (PG_BODY_FLAG_AWAKE | PG_BODY_FLAG_FIXED_ROTATION | PG_BODY_FLAG_ALLOW_SLEEP));
    emit_vec(s, b->center);
    emit_u32(s, b->angle);
    emit_u32(s, b->first_shape);
    emit_u32(s, b->shape_count);
    if (m & B_VELOCITY) emit_vec(s, b->v);
    if (m & B_ANGULAR) emit_i32(s, b->w);
    if (m & B_FORCES) { emit_i64(s, b->force_x); emit_i64(s, b->force_y); emit_i64(s, b->torque); }
    if (m & B_DAMPING) { emit_i32(s, b->linear_damping); emit_i32(s, b->angular_damping); }
    if (m & B_GRAVITY_SCALE) emit_i32(s, b->gravity_scale);
    if (m & B_USER) emit_u64(s, b->user_data);
    if (m & B_SLEEP_TIME) emit_i32(s, b->sleep_time);
    if (m & B_ISLAND) emit_u32(s, b->island);
    if (m & B_MASS) {
        /* stored rather than recomputed from the shapes: mass properties take microseconds
         * per shape, and rollback restores often. The inverses are two divisions away
         * (pg__body_set_inverse_mass), so they are not stored. */
        emit_vec(s, b->local_center);
        emit_i64(s, b->mass);
        emit_i64(s, b->inertia);
    }
}

static void encode_shape(const pg_shape *sh, sink *s)
{
    int32_t i;
    emit_u32(s, sh->generation);
    emit(s, sh->used != 0);
    if (!sh->used) return;
    emit_u32(s, sh->body);
    emit_u32(s, sh->next);
    emit(s, (uint32_t)sh->geometry.kind);
    emit(s, (uint32_t)sh->geometry.count);
    for (i = 0; i < sh->geometry.count; ++i) emit_vec(s, sh->geometry.vertices[i]);
    if (sh->geometry.kind == PG_SHAPE_CHAIN_SEGMENT) { /* its neighbours decide its normals */
        emit_vec(s, sh->geometry.vertices[2]);
        emit_vec(s, sh->geometry.vertices[3]);
    }
    emit_i32(s, sh->geometry.radius);
    emit_i32(s, sh->density);
    emit_i32(s, sh->friction);
    emit_i32(s, sh->restitution);
    emit_u32(s, sh->category);
    emit_u32(s, sh->mask);
}

static void encode_contact(const pg_contact *c, sink *s)
{
    int32_t k;
    emit_u32(s, c->shape_a);
    emit_u32(s, c->shape_b);
    emit_u32(s, c->body_a);
    emit_u32(s, c->body_b);
    emit_i32(s, c->normal.x);
    emit_i32(s, c->normal.y);
    emit_i32(s, c->friction);
    emit_i32(s, c->restitution);
    emit(s, (uint32_t)c->point_count);
    for (k = 0; k < c->point_count; ++k) {
        const pg_contact_point *p = &c->points[k];
        emit_vec(s, p->point);
        emit_i32(s, p->separation);
        emit_u32(s, p->id);
        emit_i32(s, p->normal_impulse);
        emit_i32(s, p->tangent_impulse);
        emit_i32(s, p->max_normal_impulse);
        emit_i32(s, p->push_impulse);
    }
}

/* The broadphase keeps no state between steps: the grid is rebuilt from the bodies
 * and its order is a pure function of them. What persists and decides which pairs are
 * looked for is which proxies move: this section hashes that, per used shape. */
static void encode_broadphase(const pg_world *w, sink *s)
{
    uint32_t i;
    for (i = 0; i < w->shape_high; ++i) {
        const pg_shape *sh = &w->shapes[i];
        if (!sh->used) continue;
        emit_u32(s, i);
        emit(s, (uint32_t)pg__body_is_active(&w->bodies[sh->body]));
    }
}

/* A joint slot: its generation and whether it is used, then every field of its kind's
 * state (one layout for all kinds, docs/snapshots.md). The bodies' joint lists are
 * derived and not stored. */
static void encode_joint(const pg_joint *j, sink *s)
{
    emit_u32(s, j->generation);
    emit(s, (j->flags & PG_JOINT_FLAG_USED) != 0);
    if ((j->flags & PG_JOINT_FLAG_USED) == 0) return;
    emit(s, (uint32_t)j->type);
    emit(s, j->flags & PG_JOINT_STATE_FLAGS);
    emit_u32(s, j->body_a);
    emit_u32(s, j->body_b);
    emit_vec(s, j->anchor_a);
    emit_vec(s, j->anchor_b);
    emit_vec(s, j->axis);
    emit_vec(s, j->target);
    emit_u32(s, j->reference_angle);
    emit_i32(s, j->length);
    emit_i32(s, j->lower);
    emit_i32(s, j->upper);
    emit_i32(s, j->motor_speed);
    emit_i32(s, j->max_motor);
    emit_i32(s, j->hertz);
    emit_i32(s, j->damping);
    emit_i32(s, j->hertz2);
    emit_i32(s, j->damping2);
    emit_u64(s, j->user_data);
    emit_i32(s, j->point_impulse[0]);
    emit_i32(s, j->point_impulse[1]);
    emit_i32(s, j->axial_impulse);
    emit_i32(s, j->lower_impulse);
    emit_i32(s, j->upper_impulse);
    emit_i32(s, j->motor_impulse);
}

/* A world whose joint pool was never used encodes no byte here, so its hash is the one
 * it had before joints existed. */
static void encode_joints(const pg_world *w, sink *s)
{
    uint32_t i;
    if (w->joint_high == 0) return;
    emit_u32(s, w->joint_high);
    for (i = 0; i < w->joint_high; ++i) encode_joint(&w->joints[i], s);
}

static void encode_section(const pg_world *w, pg_section section, sink *s)
{
    uint32_t i;
    switch (section) {
    case PG_SECTION_SETTINGS: encode_settings(w, s); break;
    case PG_SECTION_BODIES:
        emit_u32(s, w->body_high);
        for (i = 0; i < w->body_high; ++i) encode_body(&w->bodies[i], s);
        break;
    case PG_SECTION_SHAPES:
        emit_u32(s, w->shape_high);
        for (i = 0; i < w->shape_high; ++i) encode_shape(&w->shapes[i], s);
        break;
    case PG_SECTION_CONTACTS:
        emit_u32(s, w->contact_count);
        for (i = 0; i < w->contact_count; ++i) encode_contact(&w->contacts[i], s);
        break;
    case PG_SECTION_BROADPHASE: encode_broadphase(w, s); break;
    case PG_SECTION_JOINTS: encode_joints(w, s); break;
    default: break;
    }
}

void pg_world_section_hashes(const pg_world *world, uint64_t out[PG_SECTION_COUNT])
{
    int k;
    if (out == NULL) return;
    for (k = 0; k < PG_SECTION_COUNT; ++k) {
        sink s;
        s.buf = NULL;
        s.cap = s.len = 0;
        s.overflow = 0;
        s.hash = PG_HASH_SEED;
        if (world != NULL) encode_section(world, (pg_section)k, &s);
        out[k] = s.hash;
    }
}

uint64_t pg_world_hash(const pg_world *world)
{
    uint64_t sections[PG_SECTION_COUNT], h = PG_HASH_SEED;
    uint8_t bytes[8];
    int k, i;
    pg_world_section_hashes(world, sections);
    for (k = 0; k < PG_SECTION_COUNT; ++k) { /* hash of the section hashes, little-endian */
        for (i = 0; i < 8; ++i) bytes[i] = (uint8_t)((sections[k] >> (8 * i)) & 0xFFu);
        h = pg_hash_bytes(h, bytes, 8);
    }
    return h;
}

static void encode_all(const pg_world *w, sink *s)
{
    int k;
    emit_u32(s, SNAPSHOT_MAGIC);
    emit(s, SNAPSHOT_VERSION);
    emit(s, SNAPSHOT_VERSION >> 8);
    emit(s, POGON_VERSION_MAJOR);
    emit(s, (uint32_t)POGON_VERSION_MAJOR >> 8);
    emit(s, POGON_VERSION_MINOR);
    emit(s, (uint32_t)POGON_VERSION_MINOR >> 8);
    emit(s, POGON_VERSION_PATCH);
    emit(s, (uint32_t)POGON_VERSION_PATCH >> 8);
    emit_u32(s, pg_numeric_config());
    emit_u32(s, w->def.max_bodies);
    emit_u32(s, w->def.max_shapes);
    emit_u32(s, w->def.max_contacts);
    for (k = 0; k < PG_SECTION_COUNT; ++k) {
        size_t length_at, start, length, i;
        emit(s, (uint32_t)k);
        length_at = s->len;
        emit_u32(s, 0); /* patched below */
        start = s->len;
        s->hash = PG_HASH_SEED;
        encode_section(w, (pg_section)k, s);
        length = s->len - start;
        if (s->buf != NULL && !s->overflow)
            for (i = 0; i < 4; ++i) s->buf[length_at + i] = (uint8_t)((length >> (8 * i)) & 0xFFu);
        emit_u64(s, s->hash); /* the section's hash: pg_world_section_hashes()[k] */
    }
    /* the checksum: FNV-1a of every byte before it. Each step of FNV-1a is a bijection of
     * its state, so any change of one byte (any number of its bits) changes it. */
    emit_u64(s, s->buf != NULL && !s->overflow ? pg_hash_bytes(PG_HASH_SEED, s->buf, s->len) : 0u);
}

size_t pg_world_snapshot_size(const pg_world *world)
{
    sink s;
    if (world == NULL) return 0;
    s.buf = NULL;
    s.cap = s.len = 0;
    s.overflow = 0;
    s.hash = PG_HASH_SEED;
    encode_all(world, &s);
    return s.len;
}

pg_result pg_world_snapshot_save(const pg_world *world, void *buffer, size_t capacity, size_t *written)
{
    sink s;
    if (written != NULL) *written = 0;
    if (world == NULL) return PG_ERR_NULL;
    if (buffer == NULL) return pg__fail(world, PG_ERR_NULL, "pg_world_snapshot_save: buffer is NULL (size it with pg_world_snapshot_size)");
    s.buf = (uint8_t *)buffer;
    s.cap = capacity;
    s.len = 0;
    s.overflow = 0;
    s.hash = PG_HASH_SEED;
    encode_all(world, &s);
    if (s.overflow) return pg__fail(world, PG_ERR_MEMORY, "snapshot buffer too small: size it with pg_world_snapshot_size");
    if (written != NULL) *written = s.len;
    return PG_OK;
}

/* ---- the decoder ------------------------------------------------------------------------ */
typedef struct source {
    const uint8_t *p;
    size_t size, pos;
    const char *error_field;
    size_t error_offset;
    /* validation pass only: what it has read so far, to check cross-references (kept
     * in the world's per-step scratch, which no state depends on) */
    uint32_t *body_info;    /* 5 per body: used (0, or 1 + its type), first shape, shape count, active, island */
    uint32_t n_bodies, n_shapes;
    uint32_t *shape_owner;  /* per shape: owning body, or PG_NULL_INDEX when unused */
    uint32_t *shape_next;
    uint8_t *shape_mark;
} source;

static int src_need(source *r, size_t n, const char *field)
{
    if (r->error_field != NULL) return 0;
    if (r->size - r->pos < n) {
        r->error_field = field;
        r->error_offset = r->pos;
        return 0;
    }
    return 1;
}
static uint32_t take(source *r, const char *field) { return src_need(r, 1, field) ? r->p[r->pos++] : 0u; }
static uint32_t take_u32(source *r, const char *field)
{
    uint32_t v;
    if (!src_need(r, 4, field)) return 0;
    v = (uint32_t)r->p[r->pos] | (uint32_t)r->p[r->pos + 1] << 8 | (uint32_t)r->p[r->pos + 2] << 16 | (uint32_t)r->p[r->pos + 3] << 24;
    r->pos += 4;
    return v;
}
static int32_t take_i32(source *r, const char *field) { return pg__i32_from_bits(take_u32(r, field)); }
static uint64_t take_u64(source *r, const char *field)
{
    uint64_t lo = take_u32(r, field);
    return lo | (uint64_t)take_u32(r, field) << 32;
}
static int64_t take_i64(source *r, const char *field) { return pg__i64_from_bits(take_u64(r, field)); }
static pg_vec2 take_vec(source *r, const char *field)
{
    pg_vec2 v;
    v.x = take_i32(r, field);
    v.y = take_i32(r, field);
    return v;
}
static void invalid(source *r, size_t at, const char *field)
{
    if (r->error_field == NULL) {
        r->error_field = field;
        r->error_offset = at;
    }
}

static int within(int32_t v, int32_t limit) { return v >= -limit && v <= limit; }
static int within64(int64_t v, int64_t limit) { return v >= -limit && v <= limit; }

/* A contact normal: a unit vector (see UNIT_TOLERANCE_Q60); (0, 0) also when the
 * contact has no points. */
static int normal_ok(pg_dir n, int32_t point_count)
{
    const int32_t big = (INT32_C(1) << 30) + (INT32_C(1) << 21);
    int64_t q;
    if (n.x == 0 && n.y == 0) return point_count == 0;
    if (!within(n.x, big) || !within(n.y, big)) return 0;
    q = (int64_t)n.x * n.x + (int64_t)n.y * n.y; /* < 2^61 */
    return q >= UNIT_Q60 - UNIT_TOLERANCE_Q60 && q <= UNIT_Q60 + UNIT_TOLERANCE_Q60;
}

/* The decoders of the sections, one per section as the encoders are. Each reads the
 * section that starts at `start` (after its id and length) and, with `w` non-NULL,
 * applies it; applying assumes a validated input. */

static void decode_settings(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    (void)length;
    pg_world_def d = *caps;
    uint64_t frame;
    d.gravity = take_vec(r, "settings.gravity");
    d.step_hz = take_u32(r, "settings.step_hz");
    d.substeps = take_u32(r, "settings.substeps");
    d.effects = take_u32(r, "settings.effects");
    d.contact_hertz = take_i32(r, "settings.contact_hertz");
    d.contact_damping_ratio = take_i32(r, "settings.contact_damping_ratio");
    d.contact_push_max = take_i32(r, "settings.contact_push_max");
    d.restitution_threshold = take_i32(r, "settings.restitution_threshold");
    d.max_linear_speed = take_i32(r, "settings.max_linear_speed");
    d.sleep_linear_tolerance = take_i32(r, "settings.sleep_linear_tolerance");
    d.sleep_angular_tolerance = take_i32(r, "settings.sleep_angular_tolerance");
    d.time_to_sleep = take_i32(r, "settings.time_to_sleep");
    frame = take_u64(r, "settings.frame");
    if (r->error_field == NULL && pg_world_memory_size(&d) == 0) invalid(r, start, "settings (a value is out of range)");
    if (w != NULL) {
        w->def = d;
        w->frame = frame;
    }
}

static void decode_bodies(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    uint32_t i, n;
    size_t at;
    (void)length;
    at = r->pos;
    n = take_u32(r, "bodies.count");
    if (n > caps->max_bodies) invalid(r, at, "bodies.count");
    r->n_bodies = n <= caps->max_bodies ? n : 0u;
    for (i = 0; i < n && r->error_field == NULL; ++i) {
        pg_body b;
        uint32_t used, m, flags;
        unsigned char *p = (unsigned char *)&b;
        size_t z;
        for (z = 0; z < sizeof b; ++z) p[z] = 0;
        b.generation = take_u32(r, "body.generation");
        at = r->pos;
        used = take(r, "body.used");
        if (used > 1u) invalid(r, at, "body.used");
        b.first_shape = PG_NULL_INDEX;
        b.island = PG_NULL_INDEX;
        b.gravity_scale = PG_FIX_ONE;
        if (used) {
            size_t presence_at = r->pos;
            m = take_u32(r, "body.presence");
            if (m >= (B_MASS << 1)) invalid(r, presence_at, "body.presence");
            at = r->pos;
            b.type = (pg_body_type)take(r, "body.type");
            if ((unsigned)b.type > (unsigned)PG_BODY_DYNAMIC) invalid(r, at, "body.type");
            if (r->error_field == NULL && ((m & B_MASS) != 0) != (b.type == PG_BODY_DYNAMIC)) invalid(r, at, "body.type (mass data)");
            at = r->pos;
            flags = take(r, "body.flags");
            if ((flags & ~(uint32_t)(PG_BODY_FLAG_AWAKE | PG_BODY_FLAG_FIXED_ROTATION | PG_BODY_FLAG_ALLOW_SLEEP)) != 0) invalid(r, at, "body.flags");
            b.flags = flags | PG_BODY_FLAG_USED | PG_BODY_FLAG_GEOMETRY_DIRTY;
            b.center = take_vec(r, "body.center");
            b.angle = take_u32(r, "body.angle");
            at = r->pos;
            b.first_shape = take_u32(r, "body.first_shape");
            if (b.first_shape != PG_NULL_INDEX && b.first_shape >= caps->max_shapes) invalid(r, at, "body.first_shape");
            b.shape_count = take_u32(r, "body.shape_count");
            /* every value within what a world can hold (the LIMIT_* above) */
            if (m & B_VELOCITY) {
                at = r->pos;
                b.v = take_vec(r, "body.velocity");
                if (!within(b.v.x, LIMIT_VELOCITY) || !within(b.v.y, LIMIT_VELOCITY))
                    invalid(r, at, "body.velocity (a component beyond 8192 m/s)");
                else if (b.type == PG_BODY_STATIC) invalid(r, at, "body.velocity (a static body does not move)");
            }
            if (m & B_ANGULAR) {
                at = r->pos;
                b.w = take_i32(r, "body.angular_velocity");
                if (!within(b.w, LIMIT_VELOCITY)) invalid(r, at, "body.angular_velocity (beyond 8192 rad/s)");
                else if (b.type == PG_BODY_STATIC) invalid(r, at, "body.angular_velocity (a static body does not move)");
                else if ((flags & PG_BODY_FLAG_FIXED_ROTATION) != 0) invalid(r, at, "body.angular_velocity (the body has fixed rotation)");
            }
            if (m & B_FORCES) {
                at = r->pos;
                b.force_x = take_i64(r, "body.force");
                b.force_y = take_i64(r, "body.force");
                if (!within64(b.force_x, LIMIT_FORCE) || !within64(b.force_y, LIMIT_FORCE))
                    invalid(r, at, "body.force (a component beyond 2^60, the accumulator's clamp)");
                at = r->pos;
                b.torque = take_i64(r, "body.torque");
                if (!within64(b.torque, LIMIT_FORCE)) invalid(r, at, "body.torque (beyond 2^60, the accumulator's clamp)");
            }
            if (m & B_DAMPING) {
                at = r->pos;
                b.linear_damping = take_i32(r, "body.linear_damping");
                if (b.linear_damping < 0 || b.linear_damping > LIMIT_DAMPING) invalid(r, at, "body.linear_damping (outside 0..1000)");
                at = r->pos;
                b.angular_damping = take_i32(r, "body.angular_damping");
                if (b.angular_damping < 0 || b.angular_damping > LIMIT_DAMPING) invalid(r, at, "body.angular_damping (outside 0..1000)");
            }
            if (m & B_GRAVITY_SCALE) {
                at = r->pos;
                b.gravity_scale = take_i32(r, "body.gravity_scale");
                if (!within(b.gravity_scale, LIMIT_GRAVITY_SCALE)) invalid(r, at, "body.gravity_scale (outside -100..100)");
            }
            if (m & B_USER) b.user_data = take_u64(r, "body.user_data");
            if (m & B_SLEEP_TIME) {
                at = r->pos;
                b.sleep_time = take_i32(r, "body.sleep_time");
                if (b.sleep_time < 0 || b.sleep_time > LIMIT_SLEEP_TIME) invalid(r, at, "body.sleep_time (outside 0..1001 s)");
            }
            if (m & B_ISLAND) {
                at = r->pos;
                b.island = take_u32(r, "body.island");
                if (b.island >= caps->max_bodies) invalid(r, at, "body.island");
            }
            if (m & B_MASS) {
                at = r->pos;
                b.local_center = take_vec(r, "body.local_center");
                if (!within(b.local_center.x, LIMIT_LOCAL_CENTER) || !within(b.local_center.y, LIMIT_LOCAL_CENTER))
                    invalid(r, at, "body.local_center (beyond the 50 m its shapes may reach)");
                at = r->pos;
                b.mass = take_i64(r, "body.mass");
                if (b.mass <= 0) invalid(r, at, "body.mass (a dynamic body's mass is positive)");
                at = r->pos;
                b.inertia = take_i64(r, "body.inertia");
                if (b.inertia < 0) invalid(r, at, "body.inertia (negative)");
                else if (r->error_field == NULL) {
                    /* what a world refuses to create, a snapshot may not hold */
                    pg_mass_data md;
                    md.mass = b.mass;
                    md.inertia = b.inertia;
                    md.center = b.local_center;
                    md.area = 0; /* not read: the struct is passed whole */
                    if (pg__mass_data_problem(md, (flags & PG_BODY_FLAG_FIXED_ROTATION) == 0) != NULL)
                        invalid(r, at, "body.mass or body.inertia (outside the envelope: its inverse leaves Q25.38)");
                }
            }
            pg__body_set_inverse_mass(&b);
            /* one encoding per state: a present optional field is not its default */
            if (((m & B_VELOCITY) && b.v.x == 0 && b.v.y == 0) || ((m & B_ANGULAR) && b.w == 0) ||
                ((m & B_FORCES) && b.force_x == 0 && b.force_y == 0 && b.torque == 0) ||
                ((m & B_DAMPING) && b.linear_damping == 0 && b.angular_damping == 0) ||
                ((m & B_GRAVITY_SCALE) && b.gravity_scale == PG_FIX_ONE) || ((m & B_USER) && b.user_data == 0) ||
                ((m & B_SLEEP_TIME) && b.sleep_time == 0) || ((m & B_ISLAND) && b.island == PG_NULL_INDEX))
                invalid(r, presence_at, "body.presence (a present field holds its default)");
            b.rot = pg_rot_from_angle(b.angle);
            b.origin = pg_v2_sub(b.center, pg_rot_apply(b.rot, b.local_center));
        }
        if (r->body_info != NULL) {
            r->body_info[(size_t)5u * i] = used ? 1u + (uint32_t)b.type : 0u;
            r->body_info[(size_t)5u * i + 1u] = used ? b.first_shape : PG_NULL_INDEX;
            r->body_info[(size_t)5u * i + 2u] = b.shape_count;
            r->body_info[(size_t)5u * i + 3u] = used ? (uint32_t)pg__body_is_active(&b) : 0u;
            r->body_info[(size_t)5u * i + 4u] = used ? b.island : PG_NULL_INDEX;
        }
        if (w != NULL) w->bodies[i] = b;
    }
    if (r->body_info != NULL) { /* islands name used bodies */
        for (i = 0; i < n && r->error_field == NULL; ++i) {
            uint32_t island = r->body_info[(size_t)5u * i + 4u];
            if (r->body_info[(size_t)5u * i] && island != PG_NULL_INDEX && (island >= n || !r->body_info[(size_t)5u * island]))
                invalid(r, start, "body.island (not a used body)");
        }
    }
    if (w != NULL) {
        for (i = n; i < w->def.max_bodies; ++i) { /* slots never used */
            w->bodies[i].flags = 0;
            w->bodies[i].generation = 0;
        }
        w->body_high = n;
    }
}

static void decode_shapes(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    uint32_t i, n;
    size_t at;
    (void)length;
    at = r->pos;
    n = take_u32(r, "shapes.count");
    if (n > caps->max_shapes) invalid(r, at, "shapes.count");
    r->n_shapes = n <= caps->max_shapes ? n : 0u;
    for (i = 0; i < n && r->error_field == NULL; ++i) {
        pg_shape sh;
        uint32_t used;
        int32_t v;
        unsigned char *p = (unsigned char *)&sh;
        size_t z;
        for (z = 0; z < sizeof sh; ++z) p[z] = 0;
        sh.generation = take_u32(r, "shape.generation");
        at = r->pos;
        used = take(r, "shape.used");
        if (used > 1u) invalid(r, at, "shape.used");
        sh.used = used;
        sh.next = PG_NULL_INDEX;
        if (used) {
            at = r->pos;
            sh.body = take_u32(r, "shape.body");
            if (sh.body >= caps->max_bodies) invalid(r, at, "shape.body");
            at = r->pos;
            sh.next = take_u32(r, "shape.next");
            if (sh.next != PG_NULL_INDEX && sh.next >= caps->max_shapes) invalid(r, at, "shape.next");
            at = r->pos;
            sh.geometry.kind = (pg_shape_kind)take(r, "shape.kind");
            if ((unsigned)sh.geometry.kind > (unsigned)PG_SHAPE_CHAIN_SEGMENT) invalid(r, at, "shape.kind");
            at = r->pos;
            sh.geometry.count = (int32_t)take(r, "shape.vertex_count");
            if (sh.geometry.count < 1 || sh.geometry.count > PG_MAX_VERTICES) invalid(r, at, "shape.vertex_count");
            for (v = 0; v < sh.geometry.count && r->error_field == NULL; ++v) sh.geometry.vertices[v] = take_vec(r, "shape.vertex");
            if (sh.geometry.kind == PG_SHAPE_CHAIN_SEGMENT && sh.geometry.count == 2 && r->error_field == NULL) {
                sh.geometry.vertices[2] = take_vec(r, "shape.neighbour");
                sh.geometry.vertices[3] = take_vec(r, "shape.neighbour");
            }
            sh.geometry.radius = take_i32(r, "shape.radius");
            sh.density = take_i32(r, "shape.density");
            sh.friction = take_i32(r, "shape.friction");
            sh.restitution = take_i32(r, "shape.restitution");
            sh.category = take_u32(r, "shape.category");
            sh.mask = take_u32(r, "shape.mask");
            if (r->error_field == NULL && pg__validate_geometry(&sh.geometry) != PG_OK) invalid(r, at, "shape.geometry");
            /* a moving body's shapes reach less far than a static one's (validation pass:
             * the bodies, read before the shapes, are in body_info) */
            if (r->error_field == NULL && r->body_info != NULL && sh.body < r->n_bodies && r->body_info[(size_t)5u * sh.body] != 0u &&
                pg__geometry_reach(&sh.geometry) > pg__body_reach_limit((pg_body_type)(r->body_info[(size_t)5u * sh.body] - 1u)))
                invalid(r, at, "shape.geometry (reaches farther from its body's origin than the body's type allows)");
            if (r->error_field == NULL && r->body_info != NULL && sh.geometry.kind == PG_SHAPE_CHAIN_SEGMENT && sh.body < r->n_bodies &&
                r->body_info[(size_t)5u * sh.body] != 1u + (uint32_t)PG_BODY_STATIC)
                invalid(r, at, "shape.kind (a chain segment on a body that is not static)");
            if (sh.density < 0 || sh.density > PG_FIX_C(100) || sh.friction < 0 || sh.friction > PG_FIX_C(10) ||
                sh.restitution < 0 || sh.restitution > PG_FIX_ONE)
                invalid(r, at, "shape.material");
            if (w != NULL && r->error_field == NULL) {
                pg__shape_build_local(&sh.geometry, &sh.local);
                pg__shape_set_extents(&sh); /* derived, like local: not stored */
            }
        }
        if (r->shape_owner != NULL) {
            r->shape_owner[i] = used ? sh.body : PG_NULL_INDEX;
            r->shape_next[i] = sh.next;
            r->shape_mark[i] = 0;
        }
        if (w != NULL) w->shapes[i] = sh;
    }
    if (r->shape_owner != NULL && r->error_field == NULL) {
        /* every used body's list holds exactly its shape_count shapes, each owned
         * by it and met once; every used shape is on its owner's list */
        uint32_t b;
        for (b = 0; b < r->n_bodies && r->error_field == NULL; ++b) {
            uint32_t sidx = r->body_info[(size_t)5u * b + 1u], k2;
            if (!r->body_info[(size_t)5u * b]) continue;
            for (k2 = 0; k2 < r->body_info[(size_t)5u * b + 2u]; ++k2) {
                if (sidx >= n || r->shape_owner[sidx] != b || r->shape_mark[sidx]) { invalid(r, start, "shape lists (body.first_shape, shape.next, shape.body)"); break; }
                r->shape_mark[sidx] = 1;
                sidx = r->shape_next[sidx];
            }
            if (r->error_field == NULL && sidx != PG_NULL_INDEX) invalid(r, start, "shape lists (body.shape_count)");
        }
        for (i = 0; i < n && r->error_field == NULL; ++i) /* owners are used bodies */
            if (r->shape_owner[i] != PG_NULL_INDEX && (r->shape_owner[i] >= r->n_bodies || !r->body_info[(size_t)5u * r->shape_owner[i]]))
                invalid(r, start, "shape.body (not a used body)");
        for (i = 0; i < n && r->error_field == NULL; ++i)
            if (r->shape_owner[i] != PG_NULL_INDEX && !r->shape_mark[i]) invalid(r, start, "shape lists (a shape is on no list)");
    }
    if (w != NULL) {
        uint32_t count = 0;
        for (i = n; i < w->def.max_shapes; ++i) {
            w->shapes[i].used = 0;
            w->shapes[i].generation = 0;
        }
        w->shape_high = n;
        for (i = 0; i < n; ++i) count += w->shapes[i].used ? 1u : 0u;
        w->shape_count = count;
        /* derived from the shapes and the bodies' centres of mass: not stored */
        for (i = 0; i < w->body_high; ++i)
            if ((w->bodies[i].flags & PG_BODY_FLAG_USED) != 0) pg__body_set_turn_extents(w, i);
    }
}

static void decode_contacts(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    uint32_t i, n;
    size_t at;
    (void)start;
    (void)length;
    uint32_t prev_a = 0, prev_b = 0;
    at = r->pos;
    n = take_u32(r, "contacts.count");
    if (n > caps->max_contacts) invalid(r, at, "contacts.count");
    for (i = 0; i < n && r->error_field == NULL; ++i) {
        pg_contact c;
        int32_t q;
        size_t normal_at;
        unsigned char *p = (unsigned char *)&c;
        size_t z;
        for (z = 0; z < sizeof c; ++z) p[z] = 0;
        at = r->pos;
        c.shape_a = take_u32(r, "contact.shape_a");
        c.shape_b = take_u32(r, "contact.shape_b");
        if (c.shape_a >= caps->max_shapes || c.shape_b >= caps->max_shapes || c.shape_a >= c.shape_b) invalid(r, at, "contact.shapes");
        if (r->shape_owner != NULL && r->error_field == NULL) {
            if (c.shape_b >= r->n_shapes || r->shape_owner[c.shape_a] == PG_NULL_INDEX || r->shape_owner[c.shape_b] == PG_NULL_INDEX)
                invalid(r, at, "contact.shapes (unused shape)");
            else if (i > 0 && (c.shape_a < prev_a || (c.shape_a == prev_a && c.shape_b <= prev_b)))
                invalid(r, at, "contact.shapes (not in order)");
            prev_a = c.shape_a;
            prev_b = c.shape_b;
        }
        at = r->pos;
        c.body_a = take_u32(r, "contact.body_a");
        c.body_b = take_u32(r, "contact.body_b");
        if (c.body_a >= caps->max_bodies || c.body_b >= caps->max_bodies) invalid(r, at, "contact.bodies");
        if (r->shape_owner != NULL && r->error_field == NULL &&
            (c.body_a != r->shape_owner[c.shape_a] || c.body_b != r->shape_owner[c.shape_b]))
            invalid(r, at, "contact.bodies (not the shapes' owners)");
        normal_at = r->pos;
        c.normal.x = take_i32(r, "contact.normal");
        c.normal.y = take_i32(r, "contact.normal");
        /* a mix of two shapes' materials (contact.c): friction sqrt(fa fb) <= 10,
         * restitution max(ra, rb) <= 1 */
        at = r->pos;
        c.friction = take_i32(r, "contact.friction");
        if (c.friction < 0 || c.friction > PG_ENV_MAX_FRICTION) invalid(r, at, "contact.friction (outside 0..10)");
        at = r->pos;
        c.restitution = take_i32(r, "contact.restitution");
        if (c.restitution < 0 || c.restitution > PG_FIX_ONE) invalid(r, at, "contact.restitution (outside 0..1)");
        at = r->pos;
        c.point_count = (int32_t)take(r, "contact.point_count");
        if (c.point_count > 2) invalid(r, at, "contact.point_count");
        else if (r->error_field == NULL && !normal_ok(c.normal, c.point_count)) invalid(r, normal_at, "contact.normal (not a unit vector)");
        for (q = 0; q < c.point_count && r->error_field == NULL; ++q) {
            pg_contact_point *cp = &c.points[q];
            cp->point = take_vec(r, "contact.point");
            at = r->pos;
            cp->separation = take_i32(r, "contact.separation");
            if (cp->separation < -LIMIT_PENETRATION) invalid(r, at, "contact.separation (deeper than two shapes can overlap)");
            cp->id = take_u32(r, "contact.id");
            /* the solver keeps the accumulated impulses within its LAMBDA_MAX */
            at = r->pos;
            cp->normal_impulse = take_i32(r, "contact.normal_impulse");
            if (cp->normal_impulse < 0 || cp->normal_impulse > LIMIT_LAMBDA) invalid(r, at, "contact.normal_impulse (outside 0..2^29)");
            at = r->pos;
            cp->tangent_impulse = take_i32(r, "contact.tangent_impulse");
            if (!within(cp->tangent_impulse, LIMIT_LAMBDA)) invalid(r, at, "contact.tangent_impulse (beyond +-2^29)");
            at = r->pos;
            cp->max_normal_impulse = take_i32(r, "contact.max_normal_impulse");
            if (cp->max_normal_impulse < 0 || cp->max_normal_impulse > LIMIT_LAMBDA)
                invalid(r, at, "contact.max_normal_impulse (outside 0..2^29)");
            at = r->pos;
            cp->push_impulse = take_i32(r, "contact.push_impulse");
            if (cp->push_impulse < 0 || cp->push_impulse > LIMIT_LAMBDA) invalid(r, at, "contact.push_impulse (outside 0..2^29)");
        }
        if (w != NULL) w->contacts[i] = c;
    }
    if (w != NULL) w->contact_count = n;
}

static void decode_broadphase(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    uint32_t i;
    size_t at;
    (void)w;
    (void)caps;
    /* derived: must be exactly what the bodies and shapes above imply */
    for (i = 0; r->shape_owner != NULL && i < r->n_shapes && r->error_field == NULL; ++i) {
        uint32_t owner = r->shape_owner[i];
        if (owner == PG_NULL_INDEX) continue;
        at = r->pos;
        if (take_u32(r, "broadphase.shape") != i) invalid(r, at, "broadphase.shape");
        at = r->pos;
        if (take(r, "broadphase.active") != r->body_info[(size_t)5u * owner + 3u]) invalid(r, at, "broadphase.active");
    }
    if (r->shape_owner == NULL) r->pos = r->error_field == NULL ? start + length : r->pos;
}

static int joint_param_ok(int32_t v, int32_t lo, int32_t hi) { return v >= lo && v <= hi; }

static void decode_joints(source *r, pg_world *w, const pg_world_def *caps, size_t start, size_t length)
{
    uint32_t i, n = 0;
    size_t at;
    (void)start;
    if (length > 0) {
        at = r->pos;
        n = take_u32(r, "joints.count");
        if (n == 0 || n > caps->max_joints) invalid(r, at, "joints.count (0, or beyond the world's max_joints)");
    }
    for (i = 0; i < n && r->error_field == NULL; ++i) {
        pg_joint j;
        uint32_t used, flags;
        unsigned char *p = (unsigned char *)&j;
        size_t z;
        for (z = 0; z < sizeof j; ++z) p[z] = 0;
        j.generation = take_u32(r, "joint.generation");
        at = r->pos;
        used = take(r, "joint.used");
        if (used > 1u) invalid(r, at, "joint.used");
        if (used) {
            int mouse;
            at = r->pos;
            j.type = (pg_joint_type)take(r, "joint.type");
            if ((unsigned)j.type >= (unsigned)PG_JOINT_TYPE_COUNT) invalid(r, at, "joint.type");
            mouse = j.type == PG_JOINT_MOUSE;
            at = r->pos;
            flags = take(r, "joint.flags");
            if ((flags & ~(uint32_t)PG_JOINT_STATE_FLAGS) != 0) invalid(r, at, "joint.flags");
            j.flags = flags | PG_JOINT_FLAG_USED;
            at = r->pos;
            j.body_a = take_u32(r, "joint.body_a");
            j.body_b = take_u32(r, "joint.body_b");
            if (r->error_field == NULL && r->body_info != NULL) {
                /* used bodies, two different ones (a mouse joint has no body A), the rules
                 * pg_body_set_type keeps for a joint's life: not both static, a mouse
                 * joint's body dynamic */
                const uint32_t static_code = 1u + (uint32_t)PG_BODY_STATIC;
                int a_ok = mouse ? j.body_a == PG_NULL_INDEX : j.body_a < r->n_bodies && r->body_info[(size_t)5u * j.body_a] != 0;
                int b_ok = j.body_b < r->n_bodies && r->body_info[(size_t)5u * j.body_b] != 0;
                if (!a_ok || !b_ok || j.body_a == j.body_b) {
                    invalid(r, at, "joint.bodies (not two used bodies)");
                } else if (mouse ? r->body_info[(size_t)5u * j.body_b] != 1u + (uint32_t)PG_BODY_DYNAMIC
                                 : r->body_info[(size_t)5u * j.body_a] == static_code && r->body_info[(size_t)5u * j.body_b] == static_code) {
                    invalid(r, at, mouse ? "joint.body_b (a mouse joint's body is not dynamic)" : "joint.bodies (both static)");
                }
            }
            j.anchor_a = take_vec(r, "joint.anchor_a");
            j.anchor_b = take_vec(r, "joint.anchor_b");
            at = r->pos;
            j.axis = take_vec(r, "joint.axis");
            if (j.type == PG_JOINT_PRISMATIC && r->error_field == NULL) {
                int64_t q = (int64_t)j.axis.x * j.axis.x + (int64_t)j.axis.y * j.axis.y - (INT64_C(1) << 32);
                if (!within64(q, INT64_C(1) << 20)) invalid(r, at, "joint.axis (not a unit vector)");
            }
            j.target = take_vec(r, "joint.target");
            j.reference_angle = take_u32(r, "joint.reference_angle");
            at = r->pos;
            j.length = take_i32(r, "joint.length");
            if (!joint_param_ok(j.length, 0, PG_FIX_C(100))) invalid(r, at, "joint.length (outside 0..100 m)");
            at = r->pos;
            j.lower = take_i32(r, "joint.lower");
            j.upper = take_i32(r, "joint.upper");
            if (!within(j.lower, PG_FIX_C(100)) || !within(j.upper, PG_FIX_C(100)) || j.lower > j.upper) invalid(r, at, "joint.lower/upper");
            at = r->pos;
            j.motor_speed = take_i32(r, "joint.motor_speed");
            if (!within(j.motor_speed, PG_FIX_C(1000))) invalid(r, at, "joint.motor_speed (beyond +-1000)");
            at = r->pos;
            j.max_motor = take_i32(r, "joint.max_motor");
            if (j.max_motor < 0) invalid(r, at, "joint.max_motor (negative)");
            at = r->pos;
            j.hertz = take_i32(r, "joint.hertz");
            j.damping = take_i32(r, "joint.damping");
            j.hertz2 = take_i32(r, "joint.hertz2");
            j.damping2 = take_i32(r, "joint.damping2");
            if (!joint_param_ok(j.hertz, 0, PG_FIX_C(1000)) || !joint_param_ok(j.damping, 0, PG_FIX_C(1000)) ||
                !joint_param_ok(j.hertz2, 0, PG_FIX_C(1000)) || !joint_param_ok(j.damping2, 0, PG_FIX_C(1000)))
                invalid(r, at, "joint softness (outside 0..1000)");
            j.user_data = take_u64(r, "joint.user_data");
            at = r->pos;
            j.point_impulse[0] = take_i32(r, "joint.impulse");
            j.point_impulse[1] = take_i32(r, "joint.impulse");
            j.axial_impulse = take_i32(r, "joint.impulse");
            j.lower_impulse = take_i32(r, "joint.impulse");
            j.upper_impulse = take_i32(r, "joint.impulse");
            j.motor_impulse = take_i32(r, "joint.impulse");
            if (!within(j.point_impulse[0], LIMIT_LAMBDA) || !within(j.point_impulse[1], LIMIT_LAMBDA) || !within(j.axial_impulse, LIMIT_LAMBDA) ||
                j.lower_impulse < 0 || j.lower_impulse > LIMIT_LAMBDA || j.upper_impulse < 0 || j.upper_impulse > LIMIT_LAMBDA ||
                !within(j.motor_impulse, LIMIT_LAMBDA))
                invalid(r, at, "joint impulses (beyond the solver's 2^29)");
        }
        j.next_a = j.next_b = PG_NULL_INDEX;
        if (w != NULL) w->joints[i] = j;
    }
    if (w != NULL) {
        uint32_t count = 0;
        for (i = n; i < w->joint_high; ++i) { /* slots past the snapshot's: never used */
            pg_joint zero = {0};
            zero.next_a = zero.next_b = PG_NULL_INDEX;
            w->joints[i] = zero;
        }
        w->joint_high = n;
        for (i = 0; i < n; ++i) count += (w->joints[i].flags & PG_JOINT_FLAG_USED) != 0;
        w->joint_count = count;
        pg__joint_rebuild_lists(w);
    }
}

/* Parse (and with `w` non-NULL, apply) one snapshot whose checksums have been checked
 * (see pg_world_snapshot_restore). Applying assumes a validated input. */
static void decode(source *r, pg_world *w, const pg_world_def *caps)
{
    static void (*const decoders[PG_SECTION_COUNT])(source *, pg_world *, const pg_world_def *, size_t, size_t) = {
        decode_settings, decode_bodies, decode_shapes, decode_contacts, decode_broadphase, decode_joints};
    int k;
    size_t at;
    if (take_u32(r, "magic") != SNAPSHOT_MAGIC) invalid(r, 0, "magic");
    at = r->pos;
    if ((take(r, "version") | take(r, "version") << 8) != SNAPSHOT_VERSION) invalid(r, at, "version");
    take_u32(r, "engine_version"); /* major, minor: checked with the checksum, before decoding */
    take(r, "engine_version");     /* patch: any */
    take(r, "engine_version");
    take_u32(r, "numeric_config"); /* checked with the checksum */
    at = r->pos;
    if (take_u32(r, "max_bodies") != caps->max_bodies) invalid(r, at, "max_bodies (must equal the world's)");
    at = r->pos;
    if (take_u32(r, "max_shapes") != caps->max_shapes) invalid(r, at, "max_shapes (must equal the world's)");
    at = r->pos;
    if (take_u32(r, "max_contacts") != caps->max_contacts) invalid(r, at, "max_contacts (must equal the world's)");
    for (k = 0; k < PG_SECTION_COUNT && r->error_field == NULL; ++k) {
        size_t length, start;
        at = r->pos;
        if (take(r, "section id") != (uint32_t)k) invalid(r, at, "section id");
        length = take_u32(r, "section length");
        start = r->pos;
        if (r->error_field == NULL && length > r->size - r->pos) invalid(r, start - 4u, "section length");
        if (r->error_field != NULL) break;
        decoders[k](r, w, caps, start, length);
        if (r->error_field == NULL && r->pos != start + length) invalid(r, start - 4u, "section length");
        take_u64(r, "section hash"); /* checked with the checksum, before decoding */
    }
    take_u64(r, "checksum");
    if (r->error_field == NULL && r->pos != r->size) invalid(r, r->pos, "trailing bytes");
}

static int sections_of(const uint8_t *p, size_t size, size_t start[PG_SECTION_COUNT], size_t length[PG_SECTION_COUNT]);

static uint64_t read_u64_at(const uint8_t *p)
{
    uint64_t v = 0;
    int i;
    for (i = 7; i >= 0; --i) v = v << 8 | p[i];
    return v;
}

static uint32_t u16_at(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }

/* PG_OK when the snapshot was saved by numerics like this build's: the same numeric
 * configuration and the same major.minor version (the patch version never changes a
 * bit, version.h); otherwise PG_ERR_INCOMPATIBLE and a message naming both. */
static pg_result check_numerics(const uint8_t *p, pg__text *t)
{
    uint32_t major = u16_at(p + SNAPSHOT_OFF_ENGINE), minor = u16_at(p + SNAPSHOT_OFF_ENGINE + 2u);
    uint32_t patch = u16_at(p + SNAPSHOT_OFF_ENGINE + 4u);
    uint32_t config = u16_at(p + SNAPSHOT_OFF_CONFIG) | u16_at(p + SNAPSHOT_OFF_CONFIG + 2u) << 16;
    if (major == POGON_VERSION_MAJOR && minor == POGON_VERSION_MINOR && config == pg_numeric_config()) return PG_OK;
    pg__text_put(t, "snapshot of pogon ");
    pg__text_u64(t, major);
    pg__text_char(t, '.');
    pg__text_u64(t, minor);
    pg__text_char(t, '.');
    pg__text_u64(t, patch);
    pg__text_put(t, ", ");
    pg__numeric_config_put(t, config);
    pg__text_put(t, "; this is " POGON_VERSION_STRING ", ");
    pg__numeric_config_put(t, pg_numeric_config());
    pg__text_put(t, ": other numerics");
    return PG_ERR_INCOMPATIBLE;
}

/* Whether the snapshot's bytes are the ones saved: its magic and version (so that a
 * snapshot of another version is named as one, not as damage), then the checksum, then
 * its numerics (check_numerics). On failure writes a message with the offset into t and
 * returns PG_ERR_INVALID_ARGUMENT or PG_ERR_INCOMPATIBLE. */
static pg_result check_integrity(const uint8_t *p, size_t size, pg__text *t)
{
    size_t start[PG_SECTION_COUNT], length[PG_SECTION_COUNT];
    uint32_t version;
    int k;
    if (size < SNAPSHOT_HEADER_SIZE + 8u) {
        pg__text_put(t, "corrupt snapshot at offset ");
        pg__text_u64(t, size);
        pg__text_put(t, ": it ends there, before any snapshot's end (cut short)");
        return PG_ERR_INVALID_ARGUMENT;
    }
    if (((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24) != SNAPSHOT_MAGIC) {
        pg__text_put(t, "corrupt snapshot at offset 0, field magic (not a pogon snapshot)");
        return PG_ERR_INVALID_ARGUMENT;
    }
    version = u16_at(p + 4);
    if (version != SNAPSHOT_VERSION) {
        pg__text_put(t, "snapshot format version ");
        pg__text_u64(t, version);
        pg__text_put(t, " at offset 4; this build reads version ");
        pg__text_u64(t, SNAPSHOT_VERSION);
        pg__text_put(t, " only (save it again with this build)");
        return PG_ERR_INCOMPATIBLE;
    }
    if (pg_hash_bytes(PG_HASH_SEED, p, size - 8u) == read_u64_at(p + size - 8u)) return check_numerics(p, t);
    /* name the section whose bytes no longer match its hash, when the framing allows */
    if (sections_of(p, size, start, length))
        for (k = 0; k < PG_SECTION_COUNT; ++k)
            if (pg_hash_bytes(PG_HASH_SEED, p + start[k], length[k]) != read_u64_at(p + start[k] + length[k])) {
                pg__text_put(t, "corrupt snapshot at offset ");
                pg__text_u64(t, start[k]);
                pg__text_put(t, ", section ");
                pg__text_put(t, pg_section_name((pg_section)k));
                pg__text_put(t, " (its bytes do not match its hash)");
                return PG_ERR_INVALID_ARGUMENT;
            }
    pg__text_put(t, "corrupt snapshot at offset ");
    pg__text_u64(t, size - 8u);
    pg__text_put(t, ", field checksum (the bytes before it do not match it: damaged or cut)");
    return PG_ERR_INVALID_ARGUMENT;
}

pg_result pg_world_snapshot_restore(pg_world *world, const void *snapshot, size_t size)
{
    source r;
    uint32_t i, bodies = 0;
    char detail[140]; /* what last_error holds after "PG_ERR_INCOMPATIBLE: " */
    pg__text t = pg__text_in(detail, sizeof detail);
    pg_result verdict;
    if (world == NULL) return PG_ERR_NULL;
    if (snapshot == NULL) return pg__fail(world, PG_ERR_NULL, "pg_world_snapshot_restore: snapshot is NULL");
    verdict = check_integrity((const uint8_t *)snapshot, size, &t);
    if (verdict != PG_OK) return pg__fail(world, verdict, detail);
    r.p = (const uint8_t *)snapshot;
    r.size = size;
    r.pos = 0;
    r.error_field = NULL;
    r.error_offset = 0;
    r.n_bodies = r.n_shapes = 0;
    /* per-step scratch, free between steps: the solver scratch holds 5 u32 per body,
     * the compacted proxy arrays one entry per shape (decode_bodies and decode_shapes
     * write at most max_bodies and max_shapes entries: their counts are checked first) */
    if (world->solver_scratch_bytes < (size_t)5u * sizeof(uint32_t) * world->def.max_bodies ||
        sizeof *world->proxy_boxes < sizeof(uint32_t))
        return pg__fail(world, PG_ERR_MEMORY, "pg_world_snapshot_restore: the world's scratch is too small to validate a snapshot");
    r.body_info = (uint32_t *)world->solver_scratch;
    r.shape_owner = world->proxy_shape;
    r.shape_next = (uint32_t *)(void *)world->proxy_boxes;
    r.shape_mark = world->proxy_flags_compact;
    decode(&r, NULL, &world->def); /* validate everything first */
    if (r.error_field != NULL) {
        pg__text_put(&t, "corrupt snapshot at offset ");
        pg__text_u64(&t, r.error_offset);
        pg__text_put(&t, ", field ");
        pg__text_put(&t, r.error_field);
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, detail);
    }
    r.pos = 0;
    r.body_info = NULL;
    r.shape_owner = NULL;
    r.shape_next = NULL;
    r.shape_mark = NULL;
    decode(&r, world, &world->def);
    for (i = 0; i < world->body_high; ++i) bodies += (world->bodies[i].flags & PG_BODY_FLAG_USED) != 0;
    world->body_count = bodies;
    world->begin_count = 0;
    world->end_count = 0;
    world->last_error[0] = '\0';
    return PG_OK;
}

/* ---- diff ---------------------------------------------------------------------------------- */
/* Section byte ranges of a snapshot (no validation beyond the framing). */
static int sections_of(const uint8_t *p, size_t size, size_t start[PG_SECTION_COUNT], size_t length[PG_SECTION_COUNT])
{
    size_t pos = SNAPSHOT_HEADER_SIZE;
    int k;
    if (size < pos) return 0;
    for (k = 0; k < PG_SECTION_COUNT; ++k) {
        size_t len;
        if (size - pos < 5 || p[pos] != (uint8_t)k) return 0;
        len = (size_t)p[pos + 1] | (size_t)p[pos + 2] << 8 | (size_t)p[pos + 3] << 16 | (size_t)p[pos + 4] << 24;
        pos += 5;
        if (len > size - pos || size - pos - len < 8) return 0;
        start[k] = pos;
        length[k] = len;
        pos += len + 8u; /* and the section hash */
    }
    return 1;
}

/* Length of the record at p (a body, shape or contact encoding), or 0 if malformed. */
static size_t record_length(pg_section section, const uint8_t *p, size_t avail)
{
    size_t n = 0;
    if (section == PG_SECTION_BODIES) {
        uint32_t m;
        if (avail < 5) return 0;
        if (p[4] == 0) return 5;
        if (avail < 9) return 0;
        m = (uint32_t)p[5] | (uint32_t)p[6] << 8 | (uint32_t)p[7] << 16 | (uint32_t)p[8] << 24;
        n = 9 + 2 + 8 + 4 + 4 + 4;
        if (m & B_VELOCITY) n += 8;
        if (m & B_ANGULAR) n += 4;
        if (m & B_FORCES) n += 24;
        if (m & B_DAMPING) n += 8;
        if (m & B_GRAVITY_SCALE) n += 4;
        if (m & B_USER) n += 8;
        if (m & B_SLEEP_TIME) n += 4;
        if (m & B_ISLAND) n += 4;
        if (m & B_MASS) n += 24; /* local centre, mass, inertia */
    } else if (section == PG_SECTION_SHAPES) {
        if (avail < 5) return 0;
        if (p[4] == 0) return 5;
        if (avail < 15) return 0;
        n = 5 + 8 + 2 + (size_t)p[14] * 8u + 4 + 12 + 8;
    } else if (section == PG_SECTION_CONTACTS) {
        if (avail < 33) return 0;
        n = 33 + (size_t)p[32] * 32u; /* a point: point, separation, id, four impulses */
    }
    return n <= avail ? n : 0;
}

static int bytes_equal(const uint8_t *a, const uint8_t *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i)
        if (a[i] != b[i]) return 0;
    return 1;
}

int pg_world_diff_snapshots(const void *a, size_t a_size, const void *b, size_t b_size, pg_divergence *out)
{
    const uint8_t *pa = (const uint8_t *)a, *pb = (const uint8_t *)b;
    size_t sa[PG_SECTION_COUNT], la[PG_SECTION_COUNT], sb[PG_SECTION_COUNT], lb[PG_SECTION_COUNT];
    int k;
    if (out != NULL) out->section = PG_SECTION_SETTINGS, out->index = -1;
    if (a == NULL || b == NULL) return 1;
    if (a_size == b_size && bytes_equal(pa, pb, a_size)) return 0;
    if (!sections_of(pa, a_size, sa, la) || !sections_of(pb, b_size, sb, lb)) return 1;
    for (k = 0; k < PG_SECTION_COUNT; ++k) {
        size_t ia, ib;
        int64_t index = 0;
        if (la[k] == lb[k] && bytes_equal(pa + sa[k], pb + sb[k], la[k])) continue;
        if (out != NULL) out->section = (pg_section)k;
        if (k != PG_SECTION_BODIES && k != PG_SECTION_SHAPES && k != PG_SECTION_CONTACTS) return 1;
        /* walk the records in step: the first that differs names the object */
        for (ia = sa[k] + 4, ib = sb[k] + 4;; ++index) {
            size_t ra = ia < sa[k] + la[k] ? record_length((pg_section)k, pa + ia, sa[k] + la[k] - ia) : 0;
            size_t rb = ib < sb[k] + lb[k] ? record_length((pg_section)k, pb + ib, sb[k] + lb[k] - ib) : 0;
            if (ra == 0 || rb == 0 || ra != rb || !bytes_equal(pa + ia, pb + ib, ra)) break;
            ia += ra;
            ib += rb;
        }
        if (out != NULL) out->index = index;
        return 1;
    }
    return 1; /* the header differs */
}
