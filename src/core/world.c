/* world.c — world creation inside caller memory, settings, and the step: the
 * orchestrator on top of the stages it runs (docs/architecture.md). */
#include "body.h"
#include "concave.h"
#include "contact.h"
#include "def_cookie.h"
#include "error.h"
#include "events.h"
#include "island.h"
#include "solver.h"
#include "world_types.h"
#include "world_internal.h"

/* ---- definition and memory ------------------------------------------------------------ */
/* An effect this build was compiled without (pogon/config.h) cannot be turned on. */
#define LEFT_OUT_JOINTS "max_joints must be 0: this build leaves joints out (PG_CONFIG_JOINTS=0 in pogon/config.h); build the library with PG_CONFIG_JOINTS=1 to use them"
#define LEFT_OUT_EFFECT "effects has an effect this build leaves out (PG_CONFIG_EFFECTS in pogon/config.h): build the library with it, or clear its PG_EFFECT_* bit"

pg_world_def pg_default_world_def(void)
{
    pg_world_def d;
    d.gravity = pg_v2(0, PG_FIX_C(-10));
    d.step_hz = 60;
    d.substeps = 4;
    d.effects = PG_EFFECTS_ALL & PG_CONFIG_EFFECTS; /* what this build has */
    d.contact_hertz = PG_FIX_C(30);
    d.contact_damping_ratio = PG_FIX_C(10);
    d.contact_push_max = PG_FIX_C(3);
    d.restitution_threshold = PG_FIX_C(1);
    d.max_linear_speed = PG_FIX_C(400);
    d.sleep_linear_tolerance = (pg_fix)3277;  /* 0.05 m/s */
    d.sleep_angular_tolerance = (pg_fix)2287; /* 2 degrees/s */
    d.time_to_sleep = PG_FIX_HALF;
    d.max_bodies = 1024;
    d.max_shapes = 2048;
    d.max_contacts = 4096;
    d.max_joints = PG_CONFIG_JOINTS ? 64 : 0; /* a build without joints has no joint pool */
    d.max_contact_events = PG_EVENTS_AS_CONTACTS;
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

#define PG_MAX_CAPACITY (1u << 24)

static const char *check_def(const pg_world_def *d)
{
    if (d->pg__cookie != PG__DEF_COOKIE)
        return "the def was not made by pg_default_world_def(): start from pg_default_world_def() and change the fields you need";
    if (d->step_hz < 1 || d->step_hz > 1000) return "step_hz must be 1..1000";
    if (d->substeps < 1 || d->substeps > 16) return "substeps must be 1..16";
    if ((d->effects & ~PG_EFFECTS_ALL) != 0) return "effects has bits that are not PG_EFFECT_*";
    if ((d->effects & ~PG_CONFIG_EFFECTS) != 0) return LEFT_OUT_EFFECT;
    if (d->max_bodies < 1 || d->max_bodies > PG_MAX_CAPACITY) return "max_bodies must be 1..2^24";
    if (d->max_shapes < 1 || d->max_shapes > PG_MAX_CAPACITY) return "max_shapes must be 1..2^24";
    if (d->max_contacts < 1 || d->max_contacts > PG_MAX_CAPACITY) return "max_contacts must be 1..2^24";
    if (d->max_joints > PG_MAX_CAPACITY) return "max_joints must be 0..2^24";
    if (!PG_CONFIG_JOINTS && d->max_joints > 0) return LEFT_OUT_JOINTS;
    if (d->max_contact_events != PG_EVENTS_AS_CONTACTS && d->max_contact_events > PG_MAX_CAPACITY)
        return "max_contact_events must be 0..2^24, or PG_EVENTS_AS_CONTACTS";
    if (d->contact_hertz <= 0 || d->contact_hertz > PG_FIX_C(1000)) return "contact_hertz must be in (0, 1000]";
    if (d->contact_damping_ratio < 0 || d->contact_damping_ratio > PG_FIX_C(1000)) return "contact_damping_ratio must be 0..1000";
    if (d->contact_push_max <= 0 || d->contact_push_max > PG_FIX_C(1000)) return "contact_push_max must be in (0, 1000] m/s";
    if (d->restitution_threshold < 0) return "restitution_threshold must be >= 0";
    if (d->max_linear_speed <= 0 || d->max_linear_speed > PG_FIX_C(4096)) return "max_linear_speed must be in (0, 4096] m/s";
    if (d->sleep_linear_tolerance < 0 || d->sleep_angular_tolerance < 0 || d->time_to_sleep < 0) return "sleep settings must be >= 0";
    if (d->gravity.x < -PG_FIX_C(1000) || d->gravity.x > PG_FIX_C(1000) || d->gravity.y < -PG_FIX_C(1000) || d->gravity.y > PG_FIX_C(1000))
        return "gravity components must be within +-1000 m/s^2";
    return NULL;
}

typedef struct layout {
    size_t world, bodies, shapes, joints, contacts, geoms, boxes, flags, pboxes, pflags, pshape, pairs, scratch, island, start, begin, end,
        total;
} layout;

static size_t align8(size_t n) { return (n + 7u) & ~(size_t)7u; }

static size_t max2(size_t a, size_t b) { return a > b ? a : b; }

static layout compute_layout(const pg_world_def *d)
{
    layout l;
    size_t at = 0;
    uint32_t pair_capacity = d->max_contacts;
#define PLACE(field, bytes) do { l.field = at; at += align8(bytes); } while (0)
    PLACE(world, sizeof(pg_world));
    PLACE(bodies, sizeof(pg_body) * d->max_bodies);
    PLACE(shapes, sizeof(pg_shape) * d->max_shapes);
    PLACE(joints, sizeof(pg_joint) * d->max_joints);
    PLACE(contacts, sizeof(pg_contact) * d->max_contacts);
    PLACE(geoms, sizeof(pg_geom) * d->max_shapes);
    PLACE(boxes, sizeof(pg_aabb) * d->max_shapes);
    PLACE(flags, d->max_shapes);
    PLACE(pboxes, sizeof(pg_aabb) * d->max_shapes);
    PLACE(pflags, d->max_shapes);
    PLACE(pshape, sizeof(uint32_t) * d->max_shapes);
    PLACE(pairs, sizeof(pg_pair) * pair_capacity);
    /* One scratch area for the stages that never hold it at the same time: the
     * broadphase (its output is the pairs above), then the next step's contact list
     * (contact.c, copied into the contacts above), then the solver and after it the
     * islands, and between steps the mass of a body being changed (body.h), a concave
     * body's decomposition (concave.h) or the check of a snapshot being restored. */
    PLACE(scratch, max2(max2(pg_broadphase_scratch_bytes(d->max_shapes, pair_capacity), sizeof(pg_contact) * d->max_contacts),
                        max2(pg__solver_scratch_bytes(d), pg__concave_scratch_bytes()))); /* the mass scratch and more */
    PLACE(island, sizeof(uint32_t) * d->max_bodies);
    PLACE(start, sizeof(pg_step_start) * d->max_bodies);
    PLACE(begin, sizeof(pg_contact_event) * pg__event_capacity(d));
    PLACE(end, sizeof(pg_contact_event) * pg__event_capacity(d));
#undef PLACE
    l.total = at;
    return l;
}

const char *pg_world_def_problem(const pg_world_def *def)
{
    return def == NULL ? "the world definition is NULL" : check_def(def);
}

size_t pg_world_memory_size(const pg_world_def *def)
{
    if (def == NULL || check_def(def) != NULL) return 0;
    return compute_layout(def).total;
}

const char *pg__world_memory_part(const pg_world_def *def, unsigned i, size_t *bytes)
{
    static const char *const names[] = {"world", "bodies", "shapes", "joints", "contacts",
                                        "world geometries", "boxes", "proxy flags", "proxy boxes",
                                        "proxy flags (compact)", "proxy shapes", "pairs",
                                        "scratch (broadphase / next contacts / solver / mass)", "island parents",
                                        "step starts", "begin events", "end events"};
    layout l;
    size_t at[sizeof names / sizeof names[0] + 1];
    *bytes = 0;
    if (def == NULL || check_def(def) != NULL || i >= sizeof names / sizeof names[0]) return NULL;
    l = compute_layout(def);
    at[0] = l.world; at[1] = l.bodies; at[2] = l.shapes; at[3] = l.joints; at[4] = l.contacts;
    at[5] = l.geoms; at[6] = l.boxes; at[7] = l.flags; at[8] = l.pboxes; at[9] = l.pflags; at[10] = l.pshape;
    at[11] = l.pairs; at[12] = l.scratch; at[13] = l.island; at[14] = l.start; at[15] = l.begin; at[16] = l.end;
    at[17] = l.total;
    *bytes = at[i + 1] - at[i];
    return names[i];
}

pg_result pg_world_create(const pg_world_def *def, void *memory, size_t memory_size, pg_world **out)
{
    const char *problem;
    layout l;
    unsigned char *m = (unsigned char *)memory;
    pg_world *w;
    size_t i;
    if (out != NULL) *out = NULL;
    if (def == NULL || memory == NULL || out == NULL) return PG_ERR_NULL;
    problem = check_def(def);
    if (problem != NULL) return PG_ERR_INVALID_ARGUMENT;
    if (((uintptr_t)memory & 7u) != 0) return PG_ERR_MEMORY;
    l = compute_layout(def);
    if (memory_size < l.total) return PG_ERR_MEMORY;
    for (i = 0; i < l.total; ++i) m[i] = 0; /* no uninitialised byte can leak into a hash */
    w = (pg_world *)(void *)(m + l.world);
    w->def = *def;
    w->bodies = (pg_body *)(void *)(m + l.bodies);
    w->shapes = (pg_shape *)(void *)(m + l.shapes);
    w->joints = (pg_joint *)(void *)(m + l.joints);
    w->contacts = (pg_contact *)(void *)(m + l.contacts);
    w->world_geoms = (pg_geom *)(void *)(m + l.geoms);
    w->boxes = (pg_aabb *)(void *)(m + l.boxes);
    w->proxy_flags = m + l.flags;
    w->proxy_boxes = (pg_aabb *)(void *)(m + l.pboxes);
    w->proxy_flags_compact = m + l.pflags;
    w->proxy_shape = (uint32_t *)(void *)(m + l.pshape);
    w->pairs = (pg_pair *)(void *)(m + l.pairs);
    w->pair_capacity = def->max_contacts;
    w->broadphase_scratch = m + l.scratch;
    w->broadphase_scratch_bytes = l.island - l.scratch;
    w->solver_scratch = m + l.scratch; /* the same area: see compute_layout */
    w->solver_scratch_bytes = l.island - l.scratch;
    w->island_parent = (uint32_t *)(void *)(m + l.island);
    w->step_start = (pg_step_start *)(void *)(m + l.start);
    w->begin_events = (pg_contact_event *)(void *)(m + l.begin);
    w->end_events = (pg_contact_event *)(void *)(m + l.end);
    *out = w;
    return PG_OK;
}

/* ---- settings --------------------------------------------------------------------------------- */
pg_result pg_world_set_gravity(pg_world *world, pg_vec2 gravity)
{
    pg_world_def d;
    if (world == NULL) return PG_ERR_NULL;
    d = world->def;
    d.gravity = gravity;
    if (check_def(&d) != NULL)
        return pg__fail_value(world, PG_ERR_ENVELOPE, "gravity component", gravity.x < -PG_FIX_C(1000) || gravity.x > PG_FIX_C(1000) ? gravity.x : gravity.y,
                              "m/s^2 is outside +-1000");
    world->def.gravity = gravity;
    return PG_OK;
}

pg_vec2 pg_world_gravity(const pg_world *world) { return world != NULL ? world->def.gravity : pg_v2_zero(); }

pg_result pg_world_set_effects(pg_world *world, uint32_t effects)
{
    uint32_t i;
    if (world == NULL) return PG_ERR_NULL;
    if ((effects & ~PG_EFFECTS_ALL) != 0) return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "effects has bits that are not PG_EFFECT_*");
    if ((effects & ~PG_CONFIG_EFFECTS) != 0) return pg__fail(world, PG_ERR_INVALID_ARGUMENT, LEFT_OUT_EFFECT);
    if ((world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) != 0 && (effects & PG__EFFECT(PG_EFFECT_SLEEPING)) == 0) {
        for (i = 0; i < world->body_high; ++i) /* without sleeping, nothing may stay asleep */
            if ((world->bodies[i].flags & PG_BODY_FLAG_USED) != 0 && world->bodies[i].type != PG_BODY_STATIC) {
                world->bodies[i].flags |= PG_BODY_FLAG_AWAKE;
                world->bodies[i].sleep_time = 0;
                world->bodies[i].island = PG_NULL_INDEX;
            }
    }
    world->def.effects = effects;
    return PG_OK;
}

uint32_t pg_world_effects(const pg_world *world) { return world != NULL ? world->def.effects : 0; }
uint64_t pg_world_frame(const pg_world *world) { return world != NULL ? world->frame : 0; }
pg_world_def pg_world_get_def(const pg_world *world) { return world != NULL ? world->def : pg_default_world_def(); }

pg_world_stats pg_world_get_stats(const pg_world *world)
{
    pg_world_stats s;
    uint32_t i;
    if (world == NULL) {
        pg_world_stats zero = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        return zero;
    }
    s = world->stats;
    s.body_count = world->body_count;
    s.shape_count = world->shape_count;
    s.contact_count = world->contact_count;
    s.awake_body_count = 0;
    s.touching_contact_count = 0;
    for (i = 0; i < world->body_high; ++i)
        if (pg__body_is_active(&world->bodies[i])) ++s.awake_body_count;
    for (i = 0; i < world->contact_count; ++i)
        if (world->contacts[i].point_count > 0) ++s.touching_contact_count;
    return s;
}

/* ---- the step ------------------------------------------------------------------------------------ */
pg_result pg_world_step(pg_world *world)
{
    pg_result r;
    uint32_t i, moving = 0;
    if (world == NULL) return PG_ERR_NULL;
    world->begin_count = 0;
    world->end_count = 0;
    if (PG_CONFIG_JOINTS && world->joint_count > 0) pg__wake_joined_bodies(world);
    /* 1. geometry of moving bodies (static and sleeping ones keep theirs) */
    for (i = 0; i < world->body_high; ++i) {
        pg_body *b = &world->bodies[i];
        if ((b->flags & PG_BODY_FLAG_USED) == 0) continue;
        b->flags &= ~(uint32_t)(PG_BODY_FLAG_SPEED_CLAMPED | PG_BODY_FLAG_SPIN_CLAMPED); /* this step's report */
        if (pg__body_is_active(b) || (b->flags & PG_BODY_FLAG_GEOMETRY_DIRTY) != 0) {
            pg__body_sync_geometry(world, i);
            ++moving;
        }
    }
    /* A world at rest (everything asleep or static, no geometry dirty): the contact update
     * would keep every contact as it is and report no pair, the solver would find no awake
     * body, and the sleep pass would touch no timer. Skip them, so a sleeping scene costs a
     * pass over its bodies and contacts, not a step. Every command that changes what a step
     * would do wakes a body or dirties its geometry: a shape created or destroyed, a body
     * destroyed (its contacts go with it), a type or a filter changed (a static body's too),
     * a restore; a filter change on a static body, which wakes nothing, dirties the body for
     * this reason. test_world_at_rest_skips_step_exactly,
     * test_world_at_rest_sees_a_static_filter_change and the replay corpus (recorded
     * through the full step) check that the state is the same. */
    if (moving == 0) {
        world->stats.pair_count = 0;
        world->frame += 1u;
        return PG_OK;
    }
    /* 2. broadphase + narrowphase + contact bookkeeping */
    r = pg__update_contacts(world);
    if (r != PG_OK) return r;
    if ((world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) != 0) pg__note_step_start(world);
    /* 3. forces, solver, integration */
    pg__solve(world);
    /* 4. islands and sleep */
    if ((world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) != 0) pg__update_sleep(world);
    world->frame += 1u;
    return PG_OK;
}
