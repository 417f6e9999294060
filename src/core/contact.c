/* contact.c — the contact list: broadphase pairs, narrowphase manifolds, warm-start
 * matching by feature id, and begin/end events.
 *
 * The list is kept sorted by (shape_a, shape_b) and rebuilt every step by merging the
 * previous list with the new sorted pair list, so its order is a pure function of the
 * state. Contacts between two passive bodies (static or asleep) are carried over
 * unchanged: a sleeping pile keeps its manifolds and impulses for when it wakes.
 */
#include "collide.h"
#include "contact.h"
#include "envelope.h"
#include "events.h"
#include "island.h"
#include "joint_pool.h"
#include "world_types.h"


static int shapes_should_collide(const pg_world *w, uint32_t sa, uint32_t sb)
{
    const pg_shape *a = &w->shapes[sa], *b = &w->shapes[sb];
    const pg_body *ba = &w->bodies[a->body], *bb = &w->bodies[b->body];
    if (a->body == b->body) return 0;
    if (ba->type != PG_BODY_DYNAMIC && bb->type != PG_BODY_DYNAMIC) return 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

/* Joined bodies collide only when a joint says so (collide_connected). Apart from
 * shapes_should_collide so that stays small enough to inline in the merge. */
static int joined_apart(const pg_world *w, uint32_t sa, uint32_t sb)
{
    uint32_t a = w->shapes[sa].body, b = w->shapes[sb].body;
    return PG_CONFIG_JOINTS && w->bodies[a].first_joint != PG_NULL_INDEX && w->bodies[b].first_joint != PG_NULL_INDEX && pg__joint_blocks_collision(w, a, b);
}

/* The same for continuous.c; the merge below keeps its inlined copy. */
int pg__shapes_should_collide(const pg_world *w, uint32_t sa, uint32_t sb) { return shapes_should_collide(w, sa, sb) && !joined_apart(w, sa, sb); }

/* Geometric mean, the usual rule: one slippery surface makes the pair slippery. */
static pg_fix mix_friction(pg_fix a, pg_fix b) { return pg_fix_sqrt(pg_fix_mul(a, b)); }
/* The bouncier surface wins. */
static pg_fix mix_restitution(pg_fix a, pg_fix b) { return a > b ? a : b; }

/* The sort key (shape_a, shape_b) as one number. */
static uint64_t pair_key(uint32_t sa, uint32_t sb) { return ((uint64_t)sa << 32) | sb; }

/* The neighbours of chain segment s in the world frame (NULL where the chain ends). */
static const pg_vec2 *chain_neighbour(const pg_world *w, const pg_shape *s, int which, pg_vec2 *at)
{
    const pg_body *b = &w->bodies[s->body];
    pg_vec2 local = s->geometry.vertices[2 + which], end = s->geometry.vertices[which];
    if (local.x == end.x && local.y == end.y) return NULL;
    *at = pg_geom_place_point(local, b->origin, b->rot);
    return at;
}

/* The manifold of shapes sa and sb, A to B: chain segments keep to their neighbours'
 * normals and do not collide with each other (collide.h). */
static void collide_shapes(const pg_world *w, uint32_t sa, uint32_t sb, pg_fix speculative, pg_manifold *m)
{
    const pg_shape *a = &w->shapes[sa], *b = &w->shapes[sb];
    int chain_a = PG_SHAPES_KEPT(PG_SHAPES_CHAIN) && a->geometry.kind == PG_SHAPE_CHAIN_SEGMENT;
    int chain_b = PG_SHAPES_KEPT(PG_SHAPES_CHAIN) && b->geometry.kind == PG_SHAPE_CHAIN_SEGMENT;
    if (!chain_a && !chain_b) {
        pg_collide(&w->world_geoms[sa], &w->world_geoms[sb], speculative, m);
    } else if (chain_a && chain_b) {
        int k;
        m->normal.x = m->normal.y = 0;
        m->count = 0;
        for (k = 0; k < 2; ++k) {
            m->points[k].point = pg_v2_zero();
            m->points[k].separation = 0;
            m->points[k].id = 0;
        }
    } else {
        const pg_shape *ch = chain_a ? a : b;
        pg_vec2 p0, p1;
        const pg_vec2 *before = chain_neighbour(w, ch, 0, &p0), *after = chain_neighbour(w, ch, 1, &p1);
        pg_collide_chain(&w->world_geoms[chain_a ? sa : sb], before, after, &w->world_geoms[chain_a ? sb : sa], speculative, m);
        if (chain_b) {
            m->normal.x = -m->normal.x;
            m->normal.y = -m->normal.y;
        }
    }
}

/* Run the narrowphase for (sa, sb) into *c, warm-starting from `old` when given. */
static void collide_pair(pg_world *w, uint32_t sa, uint32_t sb, const pg_contact *old, pg_contact *c)
{
    pg_manifold m;
    int32_t i, j;
    pg_fix speculative = PG_SPECULATIVE_DISTANCE;
    if ((w->def.effects & PG__EFFECT(PG_EFFECT_CONTINUOUS)) != 0) {
        /* Continuous collision: the speculative window covers how far the pair can close
         * in one step, so a fast body gets a contact before it reaches the surface and
         * the solver stops it there instead of letting it tunnel. */
        const pg_body *a = &w->bodies[w->shapes[sa].body], *b = &w->bodies[w->shapes[sb].body];
        int64_t sum = (int64_t)pg_fix_abs(a->v.x) + pg_fix_abs(a->v.y) + pg_fix_abs(b->v.x) + pg_fix_abs(b->v.y);
        int64_t hz = (int64_t)w->def.step_hz;
        /* reach = sum / hz (sum >= 0: the quotient is its floor) exceeds the distance
         * exactly when sum >= (distance + 1) hz; a resting pair skips the division */
        /* never clamps: four speeds within max_linear_speed (<= 4096 m/s) and hz >= 1 */
        if (sum >= ((int64_t)PG_SPECULATIVE_DISTANCE + 1) * hz) speculative = pg__sat64(sum / hz);
    }
    collide_shapes(w, sa, sb, speculative, &m);
    c->shape_a = sa;
    c->shape_b = sb;
    c->body_a = w->shapes[sa].body;
    c->body_b = w->shapes[sb].body;
    c->normal = m.normal;
    c->point_count = m.count;
    if (old != NULL) { /* materials change only through pg__refresh_contact_materials */
        c->friction = old->friction;
        c->restitution = old->restitution;
    } else {
        c->friction = mix_friction(w->shapes[sa].friction, w->shapes[sb].friction);
        c->restitution = mix_restitution(w->shapes[sa].restitution, w->shapes[sb].restitution);
    }
    for (i = 0; i < 2; ++i) {
        pg_contact_point *p = &c->points[i];
        p->point = i < m.count ? m.points[i].point : pg_v2_zero();
        p->separation = i < m.count ? m.points[i].separation : 0;
        p->id = i < m.count ? m.points[i].id : 0;
        p->normal_impulse = 0;
        p->tangent_impulse = 0;
        p->max_normal_impulse = 0;
        p->push_impulse = 0;
        if (old == NULL || i >= m.count) continue;
        for (j = 0; j < old->point_count; ++j) {
            if (old->points[j].id == p->id) {
                p->normal_impulse = old->points[j].normal_impulse;
                p->tangent_impulse = old->points[j].tangent_impulse;
                p->push_impulse = old->points[j].push_impulse;
                break;
            }
        }
    }
}

/* stats.capacity_misses, saturating at UINT32_MAX */
static void count_misses(pg_world *w, uint64_t n)
{
    uint64_t sum = (uint64_t)w->stats.capacity_misses + n;
    w->stats.capacity_misses = sum > UINT32_MAX ? UINT32_MAX : (uint32_t)sum;
}

static int body_was_active(const pg_world *w, uint32_t shape) { return (w->proxy_flags[shape] & PG_PROXY_ACTIVE) != 0; }

pg_result pg__update_contacts(pg_world *w)
{
    uint32_t n_proxies = 0, n_pairs = 0, s, i = 0, j, out = 0, n_old = w->contact_count;
    uint64_t okey;
    /* The merged list is built in the scratch, free once the broadphase has written the
     * pairs, and copied over the old one at the end: one list of max_contacts in the
     * world's memory instead of two. */
    pg_contact *old = w->contacts, *next = (pg_contact *)w->broadphase_scratch;
    int overflow;
    uint64_t dropped;

    /* Proxies: the used shape slots in index order, so proxy order == shape order. */
    for (s = 0; s < w->shape_high; ++s) {
        const pg_shape *sh = &w->shapes[s];
        w->proxy_flags[s] = 0;
        if (!sh->used) continue;
        if (pg__body_is_active(&w->bodies[sh->body])) w->proxy_flags[s] = PG_PROXY_ACTIVE;
        w->proxy_boxes[n_proxies] = w->boxes[s];
        w->proxy_flags_compact[n_proxies] = w->proxy_flags[s];
        w->proxy_shape[n_proxies] = s;
        ++n_proxies;
    }
    overflow = pg_broadphase_pairs_counted(w->proxy_boxes, w->proxy_flags_compact, n_proxies, w->pairs, w->pair_capacity,
                                           &n_pairs, &dropped, w->broadphase_scratch, w->broadphase_scratch_bytes);
    /* every candidate pair the pair buffer could not hold is a contact that may be missed */
    if (overflow != 0) count_misses(w, dropped);
    w->stats.pair_count = n_pairs;

    /* Merge the old contact list with the new pairs, both sorted by shape pair: each pair
     * that can collide, after the old contacts that sort before it. okey is the next old
     * contact's key; past the end (and for the end of the pairs) UINT64_MAX, above every
     * key (shape indices are below 2^24). */
    okey = n_old > 0 ? pair_key(old[0].shape_a, old[0].shape_b) : UINT64_MAX;
    for (j = 0; j <= n_pairs; ++j) {
        uint32_t pa = 0, pb = 0;
        uint64_t pkey = UINT64_MAX;
        const pg_contact *prev = NULL;
        pg_contact *c;
        if (j < n_pairs) {
            pa = w->proxy_shape[w->pairs[j].a];
            pb = w->proxy_shape[w->pairs[j].b];
            if (!shapes_should_collide(w, pa, pb) || joined_apart(w, pa, pb)) continue;
            pkey = pair_key(pa, pb);
        }
        while (okey < pkey) {
            /* not found this step: keep it if both sides were passive, else it ended */
            const pg_contact *o = &old[i];
            int kept = 0;
            if (w->shapes[o->shape_a].used && w->shapes[o->shape_b].used && !body_was_active(w, o->shape_a) &&
                !body_was_active(w, o->shape_b) && shapes_should_collide(w, o->shape_a, o->shape_b) && !joined_apart(w, o->shape_a, o->shape_b)) {
                if (out < w->def.max_contacts) {
                    next[out++] = *o;
                    kept = 1;
                } else {
                    count_misses(w, 1u);
                }
            }
            if (!kept) pg__push_end_event(w, o);
            ++i;
            okey = i < n_old ? pair_key(old[i].shape_a, old[i].shape_b) : UINT64_MAX;
        }
        if (j == n_pairs) break;
        if (okey == pkey) {
            prev = &old[i++];
            okey = i < n_old ? pair_key(old[i].shape_a, old[i].shape_b) : UINT64_MAX;
        }
        if (out >= w->def.max_contacts) {
            count_misses(w, 1u);
            if (prev != NULL) pg__push_end_event(w, prev);
            continue;
        }
        c = &next[out];
        collide_pair(w, pa, pb, prev, c);
        if (c->point_count == 0) { /* boxes overlap, shapes do not touch: no contact */
            if (prev != NULL) pg__push_end_event(w, prev);
            continue;
        }
        ++out;
        if (prev == NULL) pg__push_begin_event(w, c);
        /* A moving body touching a sleeping one wakes its island. Waking only ever adds
         * active bodies during the merge, so two shapes whose bodies were both active at
         * its start still are, and neither can wake the other. */
        if ((w->proxy_flags[pa] & w->proxy_flags[pb] & PG_PROXY_ACTIVE) == 0) {
            pg_body *ba = &w->bodies[c->body_a], *bb = &w->bodies[c->body_b];
            if (pg__body_is_active(ba) && bb->type != PG_BODY_STATIC && !pg__body_is_active(bb)) pg__wake_body(w, c->body_b);
            if (pg__body_is_active(bb) && ba->type != PG_BODY_STATIC && !pg__body_is_active(ba)) pg__wake_body(w, c->body_a);
        }
    }
    for (j = 0; j < out; ++j) old[j] = next[j];
    w->contact_count = out;
    return PG_OK;
}

void pg__remove_body_contacts(pg_world *w, uint32_t body_index)
{
    uint32_t i, out = 0;
    for (i = 0; i < w->contact_count; ++i) {
        pg_contact *c = &w->contacts[i];
        if (c->body_a == body_index || c->body_b == body_index) {
            pg_body *other = &w->bodies[c->body_a == body_index ? c->body_b : c->body_a];
            pg__push_end_event(w, c);
            if (other->type != PG_BODY_STATIC) pg__wake_body(w, c->body_a == body_index ? c->body_b : c->body_a);
            continue;
        }
        w->contacts[out++] = *c;
    }
    w->contact_count = out;
}

void pg__refresh_contact_materials(pg_world *w, uint32_t body_index)
{
    uint32_t i;
    for (i = 0; i < w->contact_count; ++i) {
        pg_contact *c = &w->contacts[i];
        if (c->body_a != body_index && c->body_b != body_index) continue;
        c->friction = mix_friction(w->shapes[c->shape_a].friction, w->shapes[c->shape_b].friction);
        c->restitution = mix_restitution(w->shapes[c->shape_a].restitution, w->shapes[c->shape_b].restitution);
    }
}
