/* joint.c — what every joint kind shares at the API (destroy, bodies, collide flag, user
 * data, reaction) and, in the step, the dispatch of each solver stage to the kinds'
 * rows (docs/joints.md). The kinds' defs and setters are in <kind>_joint.c. */
#include "body.h"
#include "error.h"
#include "joint_def.h"
#include "joint_pool.h"
#if PG_CONFIG_JOINTS /* else joints_left_out.c */

pg_result pg_joint_destroy(pg_world *world, pg_joint_id id)
{
    pg_joint *j = pg__joint(world, id);
    if (world == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_joint_destroy: joint handle is stale or invalid");
    pg__joint_remove(world, id.index);
    return PG_OK;
}

int pg_joint_is_valid(const pg_world *world, pg_joint_id id) { return pg__joint(world, id) != NULL; }

pg_joint_type pg_joint_type_of(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint(world, id);
    return j != NULL ? j->type : PG_JOINT_TYPE_COUNT;
}

pg_body_id pg_joint_body_a(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint(world, id);
    return pg__body_handle(world, j != NULL ? j->body_a : PG_NULL_INDEX);
}

pg_body_id pg_joint_body_b(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint(world, id);
    return pg__body_handle(world, j != NULL ? j->body_b : PG_NULL_INDEX);
}

pg_result pg_joint_set_collide_connected(pg_world *world, pg_joint_id id, int collide)
{
    pg_joint *j = pg__joint(world, id);
    if (world == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_joint_set_collide_connected: joint handle is stale or invalid");
    if (j->type == PG_JOINT_MOUSE) return PG_OK; /* one body: nothing to filter */
    j->flags = collide ? j->flags | PG_JOINT_FLAG_COLLIDE : j->flags & ~(uint32_t)PG_JOINT_FLAG_COLLIDE;
    pg__joint_wake(world, j); /* the contact update sees the pair again, or drops it */
    return PG_OK;
}

int pg_joint_collide_connected(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint(world, id);
    return j != NULL && (j->flags & PG_JOINT_FLAG_COLLIDE) != 0;
}

pg_result pg_joint_set_user_data(pg_world *world, pg_joint_id id, uint64_t user_data)
{
    pg_joint *j = pg__joint(world, id);
    if (world == NULL) return PG_ERR_NULL;
    if (j == NULL) return pg__fail(world, PG_ERR_STALE_HANDLE, "pg_joint_set_user_data: joint handle is stale or invalid");
    j->user_data = user_data;
    return PG_OK;
}

uint64_t pg_joint_user_data(const pg_world *world, pg_joint_id id)
{
    const pg_joint *j = pg__joint(world, id);
    return j != NULL ? j->user_data : 0u;
}

uint32_t pg_body_joints(const pg_world *world, pg_body_id body, pg_joint_id *out, uint32_t capacity)
{
    const pg_body *b = pg__body(world, body);
    uint32_t n = 0, j;
    if (b == NULL) return 0;
    /* slot order, whatever order the list holds them in */
    for (j = 0; j < world->joint_high; ++j) {
        const pg_joint *jt = &world->joints[j];
        if ((jt->flags & PG_JOINT_FLAG_USED) == 0 || (jt->body_a != body.index && jt->body_b != body.index)) continue;
        if (out != NULL && n < capacity) {
            out[n].index = j;
            out[n].generation = jt->generation;
        }
        ++n;
    }
    return n;
}
#endif
