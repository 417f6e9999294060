/* joint_scenes.c — joint_grid and chain (the layout is in joint_scenes.h). */
#include "joint_scenes.h"
#include "pogon/joint.h"
#include <math.h>
#include <string.h>

#define GRID_RADIUS ((pg_fix)26214)   /* 0.4 m */
#define CHAIN_LINKS 40u
#define LINK_LENGTH PG_FIX_ONE        /* between the cap centres */
#define LINK_RADIUS ((pg_fix)8192)    /* 0.125 m */
#define CHAIN_SPACING PG_FIX_C(2)     /* between the chains' pins, across and up */
#define NO_COLLISION_CATEGORY 2u

int pg_is_joint_scene(const char *name)
{
    return name != NULL && (strcmp(name, "joint_grid") == 0 || strcmp(name, "chain") == 0);
}

uint32_t pg_joint_scene_default_count(const char *name)
{
    return name != NULL && strcmp(name, "chain") == 0 ? 20u : 40u;
}

/* every body, static ones included */
static uint32_t bodies_for(const char *name, uint32_t count)
{
    if (strcmp(name, "joint_grid") == 0) return count * count;
    return count * CHAIN_LINKS + 1u; /* and the pins' static body */
}

static uint32_t joints_for(const char *name, uint32_t count)
{
    if (strcmp(name, "joint_grid") == 0) return count < 1u ? 0u : (2u * count - 1u) * (count - 1u);
    return count * CHAIN_LINKS;
}

pg_world_def pg_joint_scene_world_def(const char *name, uint32_t count)
{
    pg_world_def d = pg_default_world_def();
    if (count == 0) count = pg_joint_scene_default_count(name);
    d.effects = PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING;
    d.max_bodies = bodies_for(name, count);
    d.max_shapes = d.max_bodies;
    /* Nothing collides, but the broadphase still finds the pairs of overlapping boxes and
     * the filter drops them; the pair buffer (max_contacts) holds them all, so none is
     * dropped for want of room (stats.capacity_misses stays 0). */
    d.max_contacts = d.max_bodies * 8u;
    d.max_joints = joints_for(name, count);
    return d;
}

static pg_world_def effective_def(const char *name, uint32_t count, const pg_world_def *def)
{
    pg_world_def need = pg_joint_scene_world_def(name, count), d = def != NULL ? *def : need;
    if (d.max_bodies < need.max_bodies) d.max_bodies = need.max_bodies;
    if (d.max_shapes < need.max_shapes) d.max_shapes = need.max_shapes;
    if (d.max_contacts < need.max_contacts) d.max_contacts = need.max_contacts;
    if (d.max_joints < need.max_joints) d.max_joints = need.max_joints;
    return d;
}

size_t pg_joint_scene_memory_size(const char *name, uint32_t count, const pg_world_def *def)
{
    pg_world_def d;
    if (!pg_is_joint_scene(name)) return 0;
    if (count == 0) count = pg_joint_scene_default_count(name);
    d = effective_def(name, count, def);
    return pg_world_memory_size(&d);
}

/* Creates a body and checks it took the slot after `prev` (or any slot, for the first),
 * so the sanity check can name every body from the first one. */
static pg_result made_in_order(pg_result r, pg_body_id id, uint32_t made, const pg_joint_scene *out)
{
    if (r != PG_OK) return r;
    if (made > 0u && (id.index != out->first.index + made || id.generation != out->first.generation))
        return PG_ERR_INVALID_ARGUMENT;
    return PG_OK;
}

static pg_result revolute(pg_world *w, pg_body_id a, pg_vec2 anchor_a, pg_body_id b, pg_vec2 anchor_b)
{
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_joint_id id;
    jd.body_a = a;
    jd.body_b = b;
    jd.local_anchor_a = anchor_a;
    jd.local_anchor_b = anchor_b;
    return pg_revolute_joint_create(w, &jd, &id);
}

static pg_body_id nth_body(const pg_joint_scene *sc, uint32_t n)
{
    pg_body_id id = sc->first;
    id.index += n;
    return id;
}

static pg_result build_grid(uint32_t n, pg_joint_scene *out)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    uint32_t row, col, made = 0;
    const pg_fix half = PG_FIX_HALF;
    sd.category = NO_COLLISION_CATEGORY;
    sd.mask = ~NO_COLLISION_CATEGORY;
    for (row = 0; row < n; ++row) {
        for (col = 0; col < n; ++col) {
            pg_body_id id;
            pg_result r;
            bd.type = row == 0u ? PG_BODY_STATIC : PG_BODY_DYNAMIC;
            bd.position = pg_v2(PG_FIX_C((int32_t)col), PG_FIX_C(-(int32_t)row));
            r = made_in_order(pg_make_ball(out->world, &bd, &sd, GRID_RADIUS, &id), id, made, out);
            if (r != PG_OK) return r;
            if (made == 0u) out->first = id;
            ++made;
            if (row > 0u) {
                r = revolute(out->world, nth_body(out, (row - 1u) * n + col), pg_v2(0, -half), id, pg_v2(0, half));
                if (r == PG_OK && col > 0u)
                    r = revolute(out->world, nth_body(out, row * n + col - 1u), pg_v2(half, 0), id, pg_v2(-half, 0));
                if (r != PG_OK) return r;
                out->body_count += 1u;
            }
        }
    }
    return PG_OK;
}

static pg_result build_chains(uint32_t chains, pg_joint_scene *out)
{
    pg_body_def bd = pg_default_body_def();
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id pins, prev;
    uint32_t j, i, made = 0;
    const pg_fix half = LINK_LENGTH / 2;
    pg_result r = pg_body_create(out->world, &bd, &pins); /* static, no shapes: the pins */
    if (r != PG_OK) return r;
    sd.category = NO_COLLISION_CATEGORY;
    sd.mask = ~NO_COLLISION_CATEGORY;
    bd.type = PG_BODY_DYNAMIC;
    for (j = 0; j < chains; ++j) {
        pg_fix y = (pg_fix)((int32_t)j * CHAIN_SPACING), x0 = y;
        for (i = 0; i < CHAIN_LINKS; ++i) {
            pg_body_id id;
            bd.position = pg_v2(x0 + (pg_fix)((int32_t)i * LINK_LENGTH + half), y);
            r = made_in_order(pg_make_capsule(out->world, &bd, &sd, LINK_LENGTH, LINK_RADIUS, &id), id, made, out);
            if (r != PG_OK) return r;
            if (made == 0u) out->first = id;
            ++made;
            if (i == 0u) r = revolute(out->world, pins, pg_v2(x0, y), id, pg_v2(-half, 0));
            else r = revolute(out->world, prev, pg_v2(half, 0), id, pg_v2(-half, 0));
            if (r != PG_OK) return r;
            prev = id;
            out->body_count += 1u;
        }
    }
    return PG_OK;
}

pg_result pg_joint_scene_build(const char *name, uint32_t count, const pg_world_def *def, void *memory, size_t memory_size,
                               pg_joint_scene *out)
{
    pg_world_def d;
    pg_result r;
    if (name == NULL || out == NULL) return PG_ERR_NULL;
    memset(out, 0, sizeof *out);
    if (!pg_is_joint_scene(name)) return PG_ERR_INVALID_ARGUMENT;
    if (count == 0) count = pg_joint_scene_default_count(name);
    d = effective_def(name, count, def);
    r = pg_world_create(&d, memory, memory_size, &out->world);
    if (r != PG_OK) return r;
    out->joint_count = joints_for(name, count);
    return strcmp(name, "joint_grid") == 0 ? build_grid(count, out) : build_chains(count, out);
}

/* ---- sanity: read in integers, reported in metres --------------------------------------- */
static pg_vec2 world_anchor(const pg_world *w, pg_body_id body, pg_vec2 local)
{
    return pg_v2_add(pg_body_position(w, body), pg_rot_apply(pg_rot_from_angle(pg_body_angle(w, body)), local));
}

static double gap_m(pg_vec2 a, pg_vec2 b)
{
    double dx = ((double)a.x - (double)b.x) / 65536.0, dy = ((double)a.y - (double)b.y) / 65536.0;
    return sqrt(dx * dx + dy * dy);
}

int pg_joint_scene_sanity(const char *name, uint32_t count, const pg_joint_scene *sc, pg_joint_sanity *out)
{
    const pg_world *w;
    const pg_fix half = PG_FIX_HALF;
    uint32_t a, b;
    if (name == NULL || sc == NULL || out == NULL || sc->world == NULL || !pg_is_joint_scene(name)) return 0;
    if (count == 0) count = pg_joint_scene_default_count(name);
    w = sc->world;
    memset(out, 0, sizeof *out);
    if (strcmp(name, "joint_grid") == 0) {
        double drop = 0.0;
        out->figure = "sag";
        for (b = 1; b < count; ++b) {
            for (a = 0; a < count; ++a) {
                pg_body_id body = nth_body(sc, b * count + a);
                double g = gap_m(world_anchor(w, nth_body(sc, (b - 1u) * count + a), pg_v2(0, -half)),
                                 world_anchor(w, body, pg_v2(0, half)));
                if (g > out->worst_gap_m) out->worst_gap_m = g;
                if (a > 0u) {
                    g = gap_m(world_anchor(w, nth_body(sc, b * count + a - 1u), pg_v2(half, 0)),
                              world_anchor(w, body, pg_v2(-half, 0)));
                    if (g > out->worst_gap_m) out->worst_gap_m = g;
                }
                /* the bottom row started at y = -(count - 1) m */
                if (b == count - 1u) drop += -(double)(count - 1u) - (double)pg_body_position(w, body).y / 65536.0;
            }
        }
        out->value_m = count > 1u ? drop / (double)count : 0.0;
        return 1;
    }
    out->figure = "stretch";
    for (b = 0; b < count; ++b) {
        double stretch = 0.0;
        for (a = 0; a < CHAIN_LINKS; ++a) {
            pg_body_id link = nth_body(sc, b * CHAIN_LINKS + a);
            pg_fix pin = (pg_fix)((int32_t)b * CHAIN_SPACING);
            pg_vec2 from = a == 0u ? pg_v2(pin, pin)
                                   : world_anchor(w, nth_body(sc, b * CHAIN_LINKS + a - 1u), pg_v2(half, 0));
            double g = gap_m(from, world_anchor(w, link, pg_v2(-half, 0)));
            stretch += g;
            if (g > out->worst_gap_m) out->worst_gap_m = g;
        }
        if (stretch > out->value_m) out->value_m = stretch;
    }
    return 1;
}
