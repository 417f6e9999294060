/* body.c — the body pool, mass from shapes, getters, setters, forces and impulses. */
#include "body.h"
#include "contact.h"
#include "continuous.h"
#include "def_cookie.h"
#include "envelope.h"
#include "error.h"
#include "island.h"
#include "joint_pool.h"
#include "mass.h"
#include "reach.h"
#include "speed_cap.h"
#include "wide.h"

/* A handle's body, or NULL when the handle is stale or out of range. */
pg_body *pg__body(const pg_world *world, pg_body_id id)
{
    pg_body *b;
    if (world == NULL || id.index >= world->def.max_bodies || id.generation == 0) return NULL;
    b = &world->bodies[id.index];
    return ((b->flags & PG_BODY_FLAG_USED) != 0 && b->generation == id.generation) ? b : NULL;
}

pg_body_def pg_default_body_def(void)
{
    pg_body_def d;
    d.type = PG_BODY_STATIC;
    d.position = pg_v2_zero();
    d.angle = 0;
    d.linear_velocity = pg_v2_zero();
    d.angular_velocity = 0;
    d.linear_damping = 0;
    d.angular_damping = 0;
    d.gravity_scale = PG_FIX_ONE;
    d.fixed_rotation = 0;
    d.allow_sleep = 1;
    d.awake = 1;
    d.pg__cookie = PG__DEF_COOKIE;
    d.user_data = 0;
    return d;
}

static int in_position_envelope(pg_vec2 p) { return pg__in_position_envelope(p); }

static pg_result check_speed(const pg_world *world, pg_vec2 v)
{
    uint64_t cap = (uint64_t)world->def.max_linear_speed;
    if (pg__speed_squared(v) > cap * cap) {
        int64_t len = pg__speed_ceil(v);
        return pg__fail_limit(world, PG_ERR_ENVELOPE, "linear velocity: speed", len > PG_FIX_MAX ? PG_FIX_MAX : (pg_fix)len,
                              "m/s exceeds the world's max_linear_speed", (pg_fix)cap, "m/s");
    }
    return PG_OK;
}

static int damping_ok(pg_fix c) { return c >= 0 && c <= PG_FIX_C(1000); }

static pg_result check_damping(const pg_world *world, pg_fix linear, pg_fix angular)
{
    if (!damping_ok(linear)) return pg__fail_value(world, PG_ERR_ENVELOPE, "linear damping", linear, "per second is outside 0..1000");
    if (!damping_ok(angular)) return pg__fail_value(world, PG_ERR_ENVELOPE, "angular damping", angular, "per second is outside 0..1000");
    return PG_OK;
}

/* The first component of p outside +-1000 m, for the message. */
static pg_fix outside_component(pg_vec2 p) { return p.x < -PG_ENV_MAX_POSITION || p.x > PG_ENV_MAX_POSITION ? p.x : p.y; }

static pg_result check_body_def(const pg_world *world, const pg_body_def *d)
{
    pg_result r;
    if (d->pg__cookie != PG__DEF_COOKIE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT,
                        "the body def was not made by pg_default_body_def(): start from pg_default_body_def() and change the fields you need");
    if (d->type != PG_BODY_STATIC && d->type != PG_BODY_KINEMATIC && d->type != PG_BODY_DYNAMIC)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "type must be PG_BODY_STATIC, PG_BODY_KINEMATIC or PG_BODY_DYNAMIC");
    if (!in_position_envelope(d->position))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "position component", outside_component(d->position), "m is outside +-1000 m");
    if (d->type == PG_BODY_STATIC && (d->linear_velocity.x != 0 || d->linear_velocity.y != 0 || d->angular_velocity != 0))
        return pg__fail(world, PG_ERR_BODY_TYPE, "a static body cannot move: its linear_velocity and angular_velocity must be 0 (use a kinematic body)");
    r = check_speed(world, d->linear_velocity);
    if (r != PG_OK) return r;
    if (d->angular_velocity < -PG_FIX_C(1000) || d->angular_velocity > PG_FIX_C(1000))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "angular_velocity", d->angular_velocity, "rad/s is outside +-1000 rad/s");
    r = check_damping(world, d->linear_damping, d->angular_damping);
    if (r != PG_OK) return r;
    if (d->gravity_scale < -PG_FIX_C(100) || d->gravity_scale > PG_FIX_C(100))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "gravity_scale", d->gravity_scale, "is outside -100..100");
    return PG_OK;
}

pg_result pg_body_create(pg_world *world, const pg_body_def *def, pg_body_id *out)
{
    uint32_t i;
    pg_body *b;
    pg_result r;
    if (out != NULL) out->index = 0, out->generation = 0;
    if (world == NULL) return PG_ERR_NULL;
    if (def == NULL || out == NULL) return pg__fail(world, PG_ERR_NULL, def == NULL ? "pg_body_create: def is NULL" : "pg_body_create: out is NULL");
    r = check_body_def(world, def);
    if (r != PG_OK) return r;
    /* The lowest free slot: the pool's state is then just "which slots are used",
     * with no free list whose order would have to be saved. */
    for (i = 0; i < world->def.max_bodies; ++i)
        if ((world->bodies[i].flags & PG_BODY_FLAG_USED) == 0) break;
    if (i == world->def.max_bodies) return pg__fail(world, PG_ERR_CAPACITY, "max_bodies reached");
    b = &world->bodies[i];
    {
        uint32_t generation = b->generation + 1u;
        pg_body zero;
        unsigned char *p = (unsigned char *)&zero;
        size_t k;
        for (k = 0; k < sizeof zero; ++k) p[k] = 0;
        /* cppcheck-suppress uninitvar ; every byte of zero was set by the loop above */
        *b = zero;
        b->generation = generation == 0 ? 1u : generation;
    }
    b->flags = PG_BODY_FLAG_USED | PG_BODY_FLAG_GEOMETRY_DIRTY;
    if (def->fixed_rotation) b->flags |= PG_BODY_FLAG_FIXED_ROTATION;
    if (def->allow_sleep) b->flags |= PG_BODY_FLAG_ALLOW_SLEEP;
    if (def->awake || def->type == PG_BODY_KINEMATIC || (world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) == 0) b->flags |= PG_BODY_FLAG_AWAKE;
    b->type = def->type;
    b->origin = def->position;
    b->center = def->position;
    b->angle = def->angle;
    b->rot = pg_rot_from_angle(def->angle);
    if (def->type != PG_BODY_STATIC) {
        b->v = def->linear_velocity;
        b->w = def->fixed_rotation ? 0 : def->angular_velocity;
    }
    b->linear_damping = def->linear_damping;
    b->angular_damping = def->angular_damping;
    b->gravity_scale = def->gravity_scale;
    b->first_shape = PG_NULL_INDEX;
    b->first_joint = PG_NULL_INDEX;
    b->island = PG_NULL_INDEX;
    b->user_data = def->user_data;
    if (def->type == PG_BODY_DYNAMIC) { /* a dynamic body without shapes weighs 1 kg */
        b->mass = INT64_C(1) << 32;
        b->inv_mass = INT64_C(1) << 38;
    }
    if (i >= world->body_high) world->body_high = i + 1u;
    world->body_count += 1u;
    out->index = i;
    out->generation = b->generation;
    return PG_OK;
}

pg_result pg_body_destroy(pg_world *world, pg_body_id id)
{
    pg_body *b = pg__body(world, id);
    uint32_t s, next;
    if (world == NULL) return PG_ERR_NULL;
    if (b == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_body_destroy: body handle is stale or invalid");
    pg__joints_remove_of_body(world, id.index);
    pg__remove_body_contacts(world, id.index);
    for (s = b->first_shape; s != PG_NULL_INDEX; s = next) {
        next = world->shapes[s].next;
        world->shapes[s].used = 0;
        world->shape_count -= 1u;
    }
    b->flags = 0;
    b->first_shape = PG_NULL_INDEX;
    world->body_count -= 1u;
    return PG_OK;
}

int pg_body_is_valid(const pg_world *world, pg_body_id body) { return pg__body(world, body) != NULL; }

/* ---- mass ------------------------------------------------------------------------------------ */
/* Mass properties that do not fit their formats are refused, never silently saturated.
 * Above: a 100 m box at density 100 has an inertia of 1.7e9 kg m^2, beyond Q28.36's
 * 1.3e8. Below: the inverses are Q25.38 (2^70 / mass, 2^74 / inertia), so a mass must
 * exceed 2^7 in Q32.32 (3.0e-8 kg) and an inertia 2^11 in Q28.36 (3.0e-8 kg m^2). The
 * shape and density limits do not guarantee the second: a triangle of circumradius
 * 0.025 m at density 0.1 has 1.27e-8 kg m^2, and its inverse would saturate at 0.43 of
 * the true value (angular impulses would turn it too little). */
#define MASS_MIN_Q32 (INT64_C(1) << 7)
#define INERTIA_MIN_Q36 (INT64_C(1) << 11)
/* And the solver's lever-arm coefficients, invI (r x n) / K, reach 1 / (2 k) for a
 * radius of gyration k = sqrt(I / m), which must stay within their Q8.24 (128 per
 * metre): k >= 2^-8 m. k^2 = I / m = (I_q36 / 2^36) / (m_q32 / 2^32), so the condition
 * is I_q36 >= m_q32 / 2^12. Only small dense polygons get there (an equilateral
 * triangle of 0.012 m edges at density 100 has k = 0.0035 m); every shape made by the
 * pg_make_* functions inside the size limits has k >= 0.0125 m. */
static int too_compact(pg_mass_data md) { return md.inertia < (md.mass >> 12); }

const char *pg__mass_data_problem(pg_mass_data md, int rotates)
{
    if (md.mass == INT64_MAX || md.inertia == INT64_MAX)
        return "the body's inertia would exceed 1.3e8 kg m^2 (Q28.36): make it smaller or lighter";
    if (md.mass > 0 && md.mass <= MASS_MIN_Q32)
        return "the body's mass would be below 3.0e-8 kg (its inverse leaves Q25.38): make it larger or denser";
    if (rotates && md.inertia > 0 && md.inertia <= INERTIA_MIN_Q36)
        return "the body's inertia would be below 3.0e-8 kg m^2 (its inverse leaves Q25.38): make it larger or denser, or give it fixed rotation";
    if (rotates && md.inertia > 0 && too_compact(md))
        return "the body would be too compact: its radius of gyration below 0.0039 m (the solver's Q8.24 lever arms): make it larger, or give it fixed rotation";
    return NULL;
}

/* A body's geometries and densities for pg_compound_mass (at most 64 shapes, plus one
 * being added), in the world's solver scratch, which is free between steps; the
 * compound's work space follows them (pg__body_mass_scratch_bytes). */
typedef struct mass_lists {
    const pg_geom *geoms[65];
    pg_fix densities[65];
} mass_lists;

#define MASS_LISTS_BYTES ((sizeof(mass_lists) + 7u) & ~(size_t)7u) /* the work space is 8-aligned */

size_t pg__body_mass_scratch_bytes(void) { return MASS_LISTS_BYTES + pg__mass_work_bytes(); }

static mass_lists *lists_of(const pg_world *world) { return (mass_lists *)world->solver_scratch; }

void *pg__body_mass_work(const pg_world *world) { return (unsigned char *)world->solver_scratch + MASS_LISTS_BYTES; }

void pg__body_mass_lists(const pg_world *world, const pg_geom ***geoms, pg_fix **densities)
{
    mass_lists *l = lists_of(world);
    *geoms = l->geoms;
    *densities = l->densities;
}

const char *pg__body_mass_problem(const pg_world *world, uint32_t body_index, pg_fix density, uint32_t skip,
                                  const pg_geom *extra, pg_fix extra_density, int rotates)
{
    const pg_body *b = &world->bodies[body_index];
    mass_lists *l = lists_of(world);
    const pg_geom **geoms = l->geoms;
    pg_fix *densities = l->densities;
    int n = 0;
    uint32_t s;
    pg_mass_data md;
    for (s = b->first_shape; s != PG_NULL_INDEX && n < 64; s = world->shapes[s].next) {
        if (s == skip) continue;
        geoms[n] = &world->shapes[s].local;
        densities[n] = density != 0 ? density : world->shapes[s].density;
        ++n;
    }
    if (extra != NULL) {
        geoms[n] = extra;
        densities[n] = extra_density;
        ++n;
    }
    md = pg_compound_mass(geoms, densities, n, pg__body_mass_work(world));
    return pg__mass_data_problem(md, rotates);
}

/* round(2^(63 + e) / d), ties up, exactly as pg__div64_shl(2^(25 + e), d, 38) rounds it.
 * When 2^e < d < 2^(62 - e) two hardware divisions do it: 2^63 = a d + r, so
 * 2^(63 + e) / d = a 2^e + (r 2^e) / d with r 2^e < 2^62 and a 2^e < 2^63. Otherwise the
 * long division. (Restoring a snapshot derives every dynamic body's inverses, and the
 * long division alone made restoring rain 1 000 three times slower.) */
int64_t pg__reciprocal_pow2(int e, int64_t d)
{
    if (d > ((int64_t)1 << e) && d < ((int64_t)1 << (62 - e))) {
        uint64_t ud = (uint64_t)d, a = (UINT64_C(1) << 63) / ud, r = (UINT64_C(1) << 63) % ud;
        uint64_t sr = r << e, q = (a << e) + sr / ud, rem = sr % ud;
        if (rem >= ud - rem) ++q;
        return (int64_t)q;
    }
    return pg__div64_shl(INT64_C(1) << (25 + e), d, 38);
}

void pg__body_set_inverse_mass(pg_body *b)
{
    b->inv_mass = 0;
    b->inv_inertia = 0;
    if (b->type != PG_BODY_DYNAMIC || b->mass <= 0) return;
    b->inv_mass = pg__reciprocal_pow2(7, b->mass); /* 2^70 / mass: Q32.32 -> Q25.38 */
    if (b->inertia > 0 && (b->flags & PG_BODY_FLAG_FIXED_ROTATION) == 0)
        b->inv_inertia = pg__reciprocal_pow2(11, b->inertia); /* 2^74 / inertia: Q28.36 -> Q25.38 */
}

void pg__body_update_mass(pg_world *world, uint32_t body_index)
{
    pg_body *b = &world->bodies[body_index];
    mass_lists *l = lists_of(world);
    const pg_geom **geoms = l->geoms;
    pg_fix *densities = l->densities;
    int n = 0;
    uint32_t s;
    pg_mass_data md;
    b->mass = 0;
    b->inertia = 0;
    b->inv_mass = 0;
    b->inv_inertia = 0;
    b->local_center = pg_v2_zero();
    if (b->type != PG_BODY_DYNAMIC) {
        b->center = b->origin;
        pg__body_set_turn_extents(world, body_index);
        return;
    }
    for (s = b->first_shape; s != PG_NULL_INDEX && n < 64; s = world->shapes[s].next) {
        geoms[n] = &world->shapes[s].local;
        densities[n] = world->shapes[s].density;
        ++n;
    }
    md = pg_compound_mass(geoms, densities, n, pg__body_mass_work(world));
    if (md.mass <= 0) { /* only segments, or density 0: a point of 1 kg */
        b->mass = INT64_C(1) << 32;
    } else {
        b->mass = md.mass;
        b->local_center = md.center;
        b->inertia = md.inertia;
    }
    pg__body_set_inverse_mass(b);
    b->center = pg_v2_add(b->origin, pg_rot_apply(b->rot, b->local_center));
    pg__body_set_turn_extents(world, body_index);
}

void pg__body_sync_geometry(pg_world *world, uint32_t body_index)
{
    pg_body *b = &world->bodies[body_index];
    uint32_t s;
    int turning;
    pg_fix margin = PG_SPECULATIVE_DISTANCE;
    pg_fix sweep_x = 0, sweep_y = 0;
    if (b->type != PG_BODY_STATIC && (world->def.effects & PG__EFFECT(PG_EFFECT_CONTINUOUS)) != 0) {
        /* A fast body's box grows by the distance it may travel in this step, so the
         * speculative contacts can stop it at a surface instead of letting it tunnel. */
        pg_fix dx = (pg_fix)(pg_fix_abs(b->v.x) / (int32_t)world->def.step_hz);
        pg_fix dy = (pg_fix)(pg_fix_abs(b->v.y) / (int32_t)world->def.step_hz);
        sweep_x = dx;
        sweep_y = dy;
    }
    /* fast-turning (continuous.c): each shape may face any way during the step, and its
     * time of impact is looked for only against the pairs found here */
    turning = PG__EFFECT(PG_EFFECT_CONTINUOUS) != 0 && b->w != 0 && b->turn_reach != 0 && pg__turns_fast_now(world, b);
    for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next) {
        pg_aabb box;
        pg__geom_place_slot(&world->shapes[s].local, b->origin, b->rot, &world->world_geoms[s]);
        box = pg_geom_aabb(&world->world_geoms[s]);
        if (turning) {
            int64_t turn_radius = pg__shape_turn_radius(b, &world->shapes[s]);
            pg_fix lx = pg__sat64((int64_t)b->center.x - turn_radius), hx = pg__sat64((int64_t)b->center.x + turn_radius);
            pg_fix ly = pg__sat64((int64_t)b->center.y - turn_radius), hy = pg__sat64((int64_t)b->center.y + turn_radius);
            if (lx < box.lo.x) box.lo.x = lx;
            if (ly < box.lo.y) box.lo.y = ly;
            if (hx > box.hi.x) box.hi.x = hx;
            if (hy > box.hi.y) box.hi.y = hy;
        }
        /* saturating: a body that has flown out of the envelope reaches the edge of the
         * Q16.16 range, where a plain add would overflow. Inside the envelope these sums
         * (and the turn radius's above) never clamp: origin 1000 m + static reach 1000 m
         * + margin + a sweep of max_linear_speed / step_hz <= 4096 m is below 6100 m */
        box.lo.x = pg__sat64((int64_t)box.lo.x - margin - (b->v.x < 0 ? sweep_x : 0));
        box.lo.y = pg__sat64((int64_t)box.lo.y - margin - (b->v.y < 0 ? sweep_y : 0));
        box.hi.x = pg__sat64((int64_t)box.hi.x + margin + (b->v.x < 0 ? 0 : sweep_x));
        box.hi.y = pg__sat64((int64_t)box.hi.y + margin + (b->v.y < 0 ? 0 : sweep_y));
        world->boxes[s] = box;
    }
    b->flags &= ~(uint32_t)PG_BODY_FLAG_GEOMETRY_DIRTY;
}

/* ---- getters ------------------------------------------------------------------------------------ */
pg_body_type pg_body_type_of(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->type : PG_BODY_STATIC; }
pg_vec2 pg_body_position(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->origin : pg_v2_zero(); }
pg_vec2 pg_body_world_center(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->center : pg_v2_zero(); }
pg_angle pg_body_angle(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->angle : 0; }
pg_vec2 pg_body_linear_velocity(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->v : pg_v2_zero(); }
pg_fix pg_body_angular_velocity(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->w : 0; }
int64_t pg_body_mass(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->mass : 0; }
int64_t pg_body_inertia(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->inertia : 0; }
int pg_body_is_awake(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? (b->flags & PG_BODY_FLAG_AWAKE) != 0 : 0; }
uint64_t pg_body_user_data(const pg_world *w, pg_body_id id) { const pg_body *b = pg__body(w, id); return b ? b->user_data : 0; }

uint32_t pg_body_limits(const pg_world *w, pg_body_id id)
{
    const pg_body *b = pg__body(w, id);
    uint32_t m = 0;
    if (b == NULL) return 0;
    if ((b->flags & PG_BODY_FLAG_SPEED_CLAMPED) != 0) m |= PG_BODY_LIMIT_SPEED_CLAMPED;
    if ((b->flags & PG_BODY_FLAG_SPIN_CLAMPED) != 0) m |= PG_BODY_LIMIT_SPIN_CLAMPED;
    if (!pg__in_position_envelope(b->origin)) m |= PG_BODY_LIMIT_OUTSIDE;
    return m;
}

uint32_t pg_body_shapes(const pg_world *w, pg_body_id id, pg_shape_id *out, uint32_t capacity)
{
    const pg_body *b = pg__body(w, id);
    uint32_t s, n = 0;
    if (b == NULL) return 0;
    for (s = b->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next, ++n) {
        if (out != NULL && n < capacity) {
            out[n].index = s;
            out[n].generation = w->shapes[s].generation;
        }
    }
    return n;
}

/* ---- setters ------------------------------------------------------------------------------------- */
#define GET_BODY(fn)                                                                         \
    pg_body *b = pg__body(world, id);                                                       \
    if (world == NULL) return PG_ERR_NULL;                                                  \
    if (b == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, fn)

pg_result pg_body_set_transform(pg_world *world, pg_body_id id, pg_vec2 position, pg_angle angle)
{
    GET_BODY("pg_body_set_transform: body handle is stale or invalid");
    if (!in_position_envelope(position)) return pg__fail_value(world, PG_ERR_ENVELOPE, "position component", outside_component(position), "m is outside +-1000 m");
    b->origin = position;
    b->angle = angle;
    b->rot = pg_rot_from_angle(angle);
    b->center = pg_v2_add(position, pg_rot_apply(b->rot, b->local_center));
    b->flags |= PG_BODY_FLAG_GEOMETRY_DIRTY;
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_linear_velocity(pg_world *world, pg_body_id id, pg_vec2 v)
{
    pg_result r;
    GET_BODY("pg_body_set_linear_velocity: body handle is stale or invalid");
    if (b->type == PG_BODY_STATIC) return pg__fail(world, PG_ERR_BODY_TYPE, "a static body has no velocity");
    r = check_speed(world, v);
    if (r != PG_OK) return r;
    b->v = v;
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_angular_velocity(pg_world *world, pg_body_id id, pg_fix w)
{
    GET_BODY("pg_body_set_angular_velocity: body handle is stale or invalid");
    if (b->type == PG_BODY_STATIC) return pg__fail(world, PG_ERR_BODY_TYPE, "a static body has no velocity");
    if (w < -PG_FIX_C(1000) || w > PG_FIX_C(1000)) return pg__fail_value(world, PG_ERR_ENVELOPE, "angular velocity", w, "rad/s is outside +-1000");
    if ((b->flags & PG_BODY_FLAG_FIXED_ROTATION) != 0) return PG_OK;
    b->w = w;
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_type(pg_world *world, pg_body_id id, pg_body_type type)
{
    GET_BODY("pg_body_set_type: body handle is stale or invalid");
    if (type != PG_BODY_STATIC && type != PG_BODY_KINEMATIC && type != PG_BODY_DYNAMIC)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "type must be PG_BODY_STATIC, PG_BODY_KINEMATIC or PG_BODY_DYNAMIC");
    if (b->type == type) return PG_OK;
    {
        const char *joint_problem = pg__joint_type_change_problem(world, id.index, type);
        if (joint_problem != NULL) return pg__fail(world, PG_ERR_BODY_TYPE, joint_problem);
    }
    if (type != PG_BODY_STATIC) { /* a static body's shapes may reach farther than a moving body's */
        uint32_t s;
        for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next)
            if (world->shapes[s].geometry.kind == PG_SHAPE_CHAIN_SEGMENT)
                return pg__fail(world, PG_ERR_BODY_TYPE, "a body with chain segments stays static (terrain)");
        for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next)
            if (pg__geometry_reach(&world->shapes[s].geometry) > pg__body_reach_limit(type))
                return pg__fail_reach(world, pg__geometry_reach(&world->shapes[s].geometry), type);
    }
    if (type == PG_BODY_DYNAMIC) {
        const char *why;
        uint32_t s;
        for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next) {
            pg_fix d = world->shapes[s].density;
            if (d < PG_ENV_MIN_DENSITY || d > PG_ENV_MAX_DENSITY)
                return pg__fail_value(world, PG_ERR_ENVELOPE, "a shape's density", d,
                                      "kg/m^2 is outside 0.1..100 for a dynamic body: set it first (pg_body_set_density)");
        }
        why = pg__body_mass_problem(world, id.index, 0, PG_NULL_INDEX, NULL, 0, (b->flags & PG_BODY_FLAG_FIXED_ROTATION) == 0);
        if (why != NULL) return pg__fail(world, PG_ERR_ENVELOPE, why);
    }
    pg__remove_body_contacts(world, id.index); /* pairs are found again next step */
    b->type = type;
    if (type == PG_BODY_STATIC) b->v = pg_v2_zero(), b->w = 0;
    b->flags |= PG_BODY_FLAG_AWAKE | PG_BODY_FLAG_GEOMETRY_DIRTY;
    b->island = PG_NULL_INDEX;
    b->sleep_time = 0;
    pg__body_update_mass(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_awake(pg_world *world, pg_body_id id, int awake)
{
    GET_BODY("pg_body_set_awake: body handle is stale or invalid");
    if (b->type == PG_BODY_STATIC) return PG_OK;
    if (awake) {
        pg__wake_body(world, id.index);
    } else if ((world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) != 0 && b->type == PG_BODY_DYNAMIC) {
        b->flags = (b->flags & ~(uint32_t)PG_BODY_FLAG_AWAKE) | PG_BODY_FLAG_GEOMETRY_DIRTY;
        b->v = pg_v2_zero();
        b->w = 0;
        b->island = id.index;
    }
    return PG_OK;
}

pg_result pg_body_set_gravity_scale(pg_world *world, pg_body_id id, pg_fix scale)
{
    GET_BODY("pg_body_set_gravity_scale: body handle is stale or invalid");
    if (scale < -PG_FIX_C(100) || scale > PG_FIX_C(100)) return pg__fail_value(world, PG_ERR_ENVELOPE, "gravity_scale", scale, "is outside -100..100");
    b->gravity_scale = scale;
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_damping(pg_world *world, pg_body_id id, pg_fix linear, pg_fix angular)
{
    pg_result r;
    GET_BODY("pg_body_set_damping: body handle is stale or invalid");
    r = check_damping(world, linear, angular);
    if (r != PG_OK) return r;
    b->linear_damping = linear;
    b->angular_damping = angular;
    return PG_OK;
}

pg_result pg_body_set_fixed_rotation(pg_world *world, pg_body_id id, int fixed)
{
    GET_BODY("pg_body_set_fixed_rotation: body handle is stale or invalid");
    if (!fixed && b->type == PG_BODY_DYNAMIC) {
        const char *why = pg__body_mass_problem(world, id.index, 0, PG_NULL_INDEX, NULL, 0, 1);
        if (why != NULL) return pg__fail(world, PG_ERR_ENVELOPE, why);
    }
    if (fixed) b->flags |= PG_BODY_FLAG_FIXED_ROTATION, b->w = 0;
    else b->flags &= ~(uint32_t)PG_BODY_FLAG_FIXED_ROTATION;
    pg__body_update_mass(world, id.index);
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_user_data(pg_world *world, pg_body_id id, uint64_t user_data)
{
    GET_BODY("pg_body_set_user_data: body handle is stale or invalid");
    b->user_data = user_data;
    return PG_OK;
}

static pg_result set_material(pg_world *world, pg_body_id id, int which, pg_fix value, const char *fn)
{
    uint32_t s;
    GET_BODY(fn);
    if (which == 0 && (value < 0 || value > PG_ENV_MAX_FRICTION)) return pg__fail_value(world, PG_ERR_ENVELOPE, "friction", value, "is outside 0..10");
    if (which == 1 && (value < 0 || value > PG_FIX_ONE)) return pg__fail_value(world, PG_ERR_ENVELOPE, "restitution", value, "is outside 0..1");
    if (which == 2 && b->type == PG_BODY_DYNAMIC && (value < PG_ENV_MIN_DENSITY || value > PG_ENV_MAX_DENSITY))
        return pg__fail_value(world, PG_ERR_ENVELOPE, "density", value, "is outside 0.1..100 kg/m^2");
    if (which == 2 && (value < 0 || value > PG_ENV_MAX_DENSITY)) return pg__fail_value(world, PG_ERR_ENVELOPE, "density", value, "is outside 0..100 kg/m^2");
    if (which == 2 && b->type == PG_BODY_DYNAMIC) {
        const char *why = pg__body_mass_problem(world, id.index, value, PG_NULL_INDEX, NULL, 0, (b->flags & PG_BODY_FLAG_FIXED_ROTATION) == 0);
        if (why != NULL) return pg__fail(world, PG_ERR_ENVELOPE, why);
    }
    for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next) {
        if (which == 0) world->shapes[s].friction = value;
        else if (which == 1) world->shapes[s].restitution = value;
        else world->shapes[s].density = value;
    }
    if (which == 2) pg__body_update_mass(world, id.index);
    else pg__refresh_contact_materials(world, id.index);
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_set_friction(pg_world *w, pg_body_id id, pg_fix f) { return set_material(w, id, 0, f, "pg_body_set_friction: body handle is stale or invalid"); }
pg_result pg_body_set_restitution(pg_world *w, pg_body_id id, pg_fix r) { return set_material(w, id, 1, r, "pg_body_set_restitution: body handle is stale or invalid"); }
pg_result pg_body_set_density(pg_world *w, pg_body_id id, pg_fix d) { return set_material(w, id, 2, d, "pg_body_set_density: body handle is stale or invalid"); }

pg_result pg_body_set_filter(pg_world *world, pg_body_id id, uint32_t category, uint32_t mask)
{
    uint32_t s;
    GET_BODY("pg_body_set_filter: body handle is stale or invalid");
    for (s = b->first_shape; s != PG_NULL_INDEX; s = world->shapes[s].next) {
        world->shapes[s].category = category;
        world->shapes[s].mask = mask;
    }
    /* its pairs are looked at again in the next step even where nothing wakes (a static
     * body): a pair the filter now excludes must end (pg_world_step) */
    b->flags |= PG_BODY_FLAG_GEOMETRY_DIRTY;
    pg__wake_body(world, id.index);
    return PG_OK;
}

/* ---- forces and impulses ------------------------------------------------------------------------- */
static pg_result dynamic_body(pg_world *world, pg_body_id id, const char *fn, pg_body **out)
{
    pg_body *b = pg__body(world, id);
    if (world == NULL) return PG_ERR_NULL;
    /* each failure returns its code here, not pg__fail's: clang's analyzer, which sees
     * one file, would otherwise take a failure for PG_OK and the callers' b for NULL */
    if (b == NULL) {
        (void)pg__fail(world, PG_ERR_STALE_HANDLE, fn);
        return PG_ERR_STALE_HANDLE;
    }
    if (b->type != PG_BODY_DYNAMIC) {
        (void)pg__fail(world, PG_ERR_BODY_TYPE, "forces and impulses act on dynamic bodies only");
        return PG_ERR_BODY_TYPE;
    }
    *out = b;
    return PG_OK;
}

/* Accumulators are int64 Q48.16 and are clamped far beyond any envelope value, so a
 * user who keeps adding cannot overflow them. */
#define FORCE_LIMIT (INT64_C(1) << 60)
static int64_t accumulate(int64_t acc, int64_t add)
{
    int64_t r = acc + add; /* |acc| <= 2^60 and |add| < 2^48: no overflow */
    return r > FORCE_LIMIT ? FORCE_LIMIT : r < -FORCE_LIMIT ? -FORCE_LIMIT : r;
}

pg_result pg_body_apply_force(pg_world *world, pg_body_id id, pg_vec2 force)
{
    pg_body *b = NULL;
    pg_result r = dynamic_body(world, id, "pg_body_apply_force: body handle is stale or invalid", &b);
    if (r != PG_OK) return r;
    b->force_x = accumulate(b->force_x, force.x);
    b->force_y = accumulate(b->force_y, force.y);
    pg__wake_body(world, id.index);
    return PG_OK;
}

/* (point - centre) x v, Q16.16 result in int64. The point is inside the envelope, and so
 * is the centre of a body that did not fly out of it: |r| < 2^28, |v| <= 2^31, and the
 * difference of the two products is below 2^60. A body may fly out to the saturated
 * edge (+-32768 m); then |r| reaches 2^32 and each product is rounded on its own by the
 * 128-bit multiply (the result, far beyond any torque limit, is clamped by the caller). */
static int64_t moment_about_center(const pg_body *b, pg_vec2 point, pg_vec2 v)
{
    int64_t rx = (int64_t)point.x - b->center.x, ry = (int64_t)point.y - b->center.y;
    if (rx < (INT64_C(1) << 28) && rx > -(INT64_C(1) << 28) && ry < (INT64_C(1) << 28) && ry > -(INT64_C(1) << 28))
        return pg__round_shift64(rx * v.y - ry * v.x, 16);
    return pg__mul64_shr(rx, v.y, 16) - pg__mul64_shr(ry, v.x, 16); /* each below 2^48 */
}

/* a + b for an int32 a and a b that pg__mul64_shr may have saturated to +-INT64_MAX */
static int64_t add_to_fix(pg_fix a, int64_t b)
{
    if (b > INT64_MAX - (INT64_C(1) << 31)) return INT64_MAX - (INT64_C(1) << 31);
    if (b < -INT64_MAX + (INT64_C(1) << 31)) return -INT64_MAX + (INT64_C(1) << 31);
    return (int64_t)a + b;
}

/* w += invI * angular_impulse, within the +-1000 rad/s envelope (a clamp is counted in
 * stats.spin_clamps and flagged); no-op for fixed rotation. */
static void add_angular_impulse(pg_world *world, pg_body *b, int64_t impulse)
{
    int64_t w;
    if ((b->flags & PG_BODY_FLAG_FIXED_ROTATION) != 0) return;
    w = add_to_fix(b->w, pg__mul64_shr(impulse, b->inv_inertia, 38));
    if (w > PG_ENV_MAX_SPIN || w < -PG_ENV_MAX_SPIN) {
        w = w > 0 ? PG_ENV_MAX_SPIN : -PG_ENV_MAX_SPIN;
        world->stats.spin_clamps += 1u;
        b->flags |= PG_BODY_FLAG_SPIN_CLAMPED;
    }
    b->w = (pg_fix)w;
}

pg_result pg_body_apply_force_at(pg_world *world, pg_body_id id, pg_vec2 force, pg_vec2 point)
{
    pg_body *b = NULL;
    pg_result r = dynamic_body(world, id, "pg_body_apply_force_at: body handle is stale or invalid", &b);
    int64_t torque;
    if (r != PG_OK) return r;
    if (!in_position_envelope(point)) return pg__fail(world, PG_ERR_ENVELOPE, "point is outside +-1000 m");
    torque = moment_about_center(b, point, force);
    b->force_x = accumulate(b->force_x, force.x);
    b->force_y = accumulate(b->force_y, force.y);
    b->torque = accumulate(b->torque, torque);
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_apply_torque(pg_world *world, pg_body_id id, pg_fix torque)
{
    pg_body *b = NULL;
    pg_result r = dynamic_body(world, id, "pg_body_apply_torque: body handle is stale or invalid", &b);
    if (r != PG_OK) return r;
    b->torque = accumulate(b->torque, torque);
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_apply_linear_impulse(pg_world *world, pg_body_id id, pg_vec2 impulse, pg_vec2 point)
{
    pg_body *b = NULL;
    pg_result r = dynamic_body(world, id, "pg_body_apply_linear_impulse: body handle is stale or invalid", &b);
    if (r != PG_OK) return r;
    if (!in_position_envelope(point)) return pg__fail(world, PG_ERR_ENVELOPE, "point is outside +-1000 m");
    /* a sum past Q16.16 is past every max_linear_speed too: the cap scales it and counts
     * it in stats.speed_clamps */
    b->v = pg__clamp_speed(world, pg_v2(pg__sat64(add_to_fix(b->v.x, pg__mul64_shr(impulse.x, b->inv_mass, 38))),
                                        pg__sat64(add_to_fix(b->v.y, pg__mul64_shr(impulse.y, b->inv_mass, 38)))),
                           &b->flags);
    add_angular_impulse(world, b, moment_about_center(b, point, impulse));
    pg__wake_body(world, id.index);
    return PG_OK;
}

pg_result pg_body_apply_angular_impulse(pg_world *world, pg_body_id id, pg_fix impulse)
{
    pg_body *b = NULL;
    pg_result r = dynamic_body(world, id, "pg_body_apply_angular_impulse: body handle is stale or invalid", &b);
    if (r != PG_OK) return r;
    add_angular_impulse(world, b, impulse);
    pg__wake_body(world, id.index);
    return PG_OK;
}
