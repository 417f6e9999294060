/* joint_def.c — the checks every joint kind shares (bodies, anchors, softness) and
 * taking a slot for a checked joint. */
#include "body.h"
#include "envelope.h"
#include "error.h"
#include "joint_def.h"
#include "joint_pool.h"
#include "reach.h"
#include "text.h"

static pg_fix reach_of(pg_vec2 p)
{
    pg_fix x = pg_fix_abs(p.x), y = pg_fix_abs(p.y);
    return x > y ? x : y;
}

static pg_result check_anchor(const pg_world *world, const char *which, pg_vec2 anchor, const pg_body *b)
{
    pg_fix limit = pg__body_reach_limit(b->type);
    int beyond = anchor.x < PG_FIX_MIN || anchor.y < PG_FIX_MIN; /* -2^31: no magnitude in Q16.16 */
    if (beyond || reach_of(anchor) > limit) {
        char buf[96];
        pg__text t = pg__text_in(buf, sizeof buf);
        pg__text_put(&t, which);
        pg__text_put(&t, " reaches");
        return pg__fail_limit(world, PG_ERR_ENVELOPE, buf, beyond ? PG_FIX_MAX : reach_of(anchor),
                              "m from its body's origin, beyond", limit, "m (50 m for a moving body, 1000 m for a static one)");
    }
    return PG_OK;
}

pg_result pg__joint_check_bodies(const pg_world *world, const char *who, pg_body_id a, pg_body_id b, pg_vec2 anchor_a,
                                 pg_vec2 anchor_b, pg_joint *j)
{
    const pg_body *ba = pg__body(world, a), *bb = pg__body(world, b);
    pg_result r;
    char buf[128];
    pg__text t = pg__text_in(buf, sizeof buf);
    pg__text_put(&t, who);
    if (ba == NULL || bb == NULL) {
        pg__text_put(&t, ba == NULL ? ": body_a" : ": body_b");
        pg__text_put(&t, " is stale or invalid");
        return pg__fail(world, PG_ERR_STALE_HANDLE, buf);
    }
    if (a.index == b.index) {
        pg__text_put(&t, ": body_a and body_b are the same body: a joint joins two bodies");
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, buf);
    }
    if (ba->type == PG_BODY_STATIC && bb->type == PG_BODY_STATIC) {
        pg__text_put(&t, ": both bodies are static: at least one must be able to move");
        return pg__fail(world, PG_ERR_BODY_TYPE, buf);
    }
    r = check_anchor(world, "local_anchor_a", anchor_a, ba);
    if (r != PG_OK) return r;
    r = check_anchor(world, "local_anchor_b", anchor_b, bb);
    if (r != PG_OK) return r;
    j->body_a = a.index;
    j->body_b = b.index;
    j->anchor_a = anchor_a;
    j->anchor_b = anchor_b;
    return PG_OK;
}

pg_result pg__joint_check_softness(const pg_world *world, pg_fix hertz, pg_fix damping_ratio, int allow_zero)
{
    if (hertz < 0 || hertz > PG_FIX_C(1000) || (!allow_zero && hertz == 0))
        return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "hertz", hertz, allow_zero ? "is outside 0..1000 Hz" : "is outside (0, 1000] Hz");
    if (damping_ratio < 0 || damping_ratio > PG_FIX_C(1000))
        return pg__fail_value(world, PG_ERR_INVALID_ARGUMENT, "damping ratio", damping_ratio, "is outside 0..1000");
    return PG_OK;
}

static const char *const type_names[PG_JOINT_TYPE_COUNT] = {"distance", "revolute", "weld", "prismatic", "mouse"};

pg_joint *pg__joint_of_type(pg_world *world, pg_joint_id id, pg_joint_type type, const char *who, pg_result *r)
{
    pg_joint *j;
    char buf[128];
    pg__text t = pg__text_in(buf, sizeof buf);
    pg__text_put(&t, who);
    if (world == NULL) {
        *r = PG_ERR_NULL;
        return NULL;
    }
    j = pg__joint(world, id);
    if (j == NULL) {
        pg__text_put(&t, ": joint handle is stale or invalid");
        *r = pg__fail(world, PG_ERR_STALE_HANDLE, buf);
        return NULL;
    }
    if (j->type != type) {
        pg__text_put(&t, ": the joint is a ");
        pg__text_put(&t, type_names[j->type]);
        pg__text_put(&t, " joint, not a ");
        pg__text_put(&t, type_names[type]);
        pg__text_put(&t, " joint");
        *r = pg__fail(world, PG_ERR_INVALID_ARGUMENT, buf);
        return NULL;
    }
    *r = PG_OK;
    return j;
}

const pg_joint *pg__joint_of_type_const(const pg_world *world, pg_joint_id id, pg_joint_type type)
{
    const pg_joint *j = pg__joint(world, id);
    return j != NULL && j->type == type ? j : NULL;
}

pg_result pg__joint_add(pg_world *world, const pg_joint *j, pg_joint_id *out)
{
    uint32_t slot = pg__joint_free_slot(world);
    if (slot == PG_NULL_INDEX) return pg__fail(world, PG_ERR_CAPACITY, "max_joints reached: create the world with a larger max_joints");
    *out = pg__joint_insert(world, slot, j);
    return PG_OK;
}

pg_body_id pg__body_handle(const pg_world *world, uint32_t body)
{
    pg_body_id id;
    id.index = body == PG_NULL_INDEX ? 0u : body;
    id.generation = body == PG_NULL_INDEX ? 0u : world->bodies[body].generation;
    return id;
}

pg_vec2 pg__joint_world_lever(const pg_world *world, uint32_t body, pg_vec2 anchor)
{
    const pg_body *b = &world->bodies[body];
    pg_vec2 local = pg_v2(pg__sat64((int64_t)anchor.x - b->local_center.x), pg__sat64((int64_t)anchor.y - b->local_center.y));
    return pg_rot_apply(b->rot, local);
}

void pg__joint_store_limits(pg_world *world, pg_joint *j, int enable, pg_fix lower, pg_fix upper)
{
    j->flags = enable ? j->flags | PG_JOINT_FLAG_LIMIT : j->flags & ~(uint32_t)PG_JOINT_FLAG_LIMIT;
    j->lower = lower;
    j->upper = upper;
    if (!enable) j->lower_impulse = j->upper_impulse = 0;
    pg__joint_wake(world, j);
}

void pg__joint_store_motor(pg_world *world, pg_joint *j, int enable, pg_fix speed, pg_fix max_motor)
{
    j->flags = enable ? j->flags | PG_JOINT_FLAG_MOTOR : j->flags & ~(uint32_t)PG_JOINT_FLAG_MOTOR;
    j->motor_speed = speed;
    j->max_motor = max_motor;
    if (!enable) j->motor_impulse = 0;
    pg__joint_wake(world, j);
}
