/* joints_left_out.c — the joint API of a build without joints (PG_CONFIG_JOINTS=0,
 * pogon/config.h). joint.c, joint_solver.c and the kinds' files compile to nothing in
 * such a build; these keep every function of pogon/joint.h linkable, so that programs and the file formats build
 * unchanged, and fail by name: a create call gets PG_ERR_INVALID_ARGUMENT and a message
 * naming the switch, a call with a joint handle PG_ERR_STALE_HANDLE (no handle can be
 * valid), a query the value it gives for an invalid handle. The defaults functions give
 * a zeroed def that only their create functions accept. world.c refuses max_joints above 0, so
 * no world of this build holds a joint; the step's joint stages are no-ops
 * (joint_solver.h), and the pool (joint_pool.c) stays for the code that walks a body's
 * joints, which finds none. */
#include <string.h>

#include "def_cookie.h"
#include "error.h"
#if !PG_CONFIG_JOINTS

#define LEFT_OUT "joints are left out of this build (PG_CONFIG_JOINTS=0 in pogon/config.h): build the library with PG_CONFIG_JOINTS=1 to use them"

/* A call with a joint handle: `who` is a string literal. */
#define STALE(world, who) ((world) == NULL ? PG_ERR_NULL : pg__fail((world), PG_ERR_STALE_HANDLE, who ": " LEFT_OUT))

/* ---- pogon/joint.h ------------------------------------------------------------------- */
pg_result pg_joint_destroy(pg_world *world, pg_joint_id joint)
{
    (void)joint;
    return STALE(world, "pg_joint_destroy");
}
int pg_joint_is_valid(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}
pg_joint_type pg_joint_type_of(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return PG_JOINT_TYPE_COUNT;
}
pg_body_id pg_joint_body_a(const pg_world *world, pg_joint_id joint)
{
    (void)joint;
    pg_body_id none = {0, 0}; /* the zero handle, never valid */
    (void)world;
    return none;
}
pg_body_id pg_joint_body_b(const pg_world *world, pg_joint_id joint)
{
    (void)joint;
    pg_body_id none = {0, 0}; /* the zero handle, never valid */
    (void)world;
    return none;
}
pg_result pg_joint_set_collide_connected(pg_world *world, pg_joint_id joint, int collide)
{
    (void)joint;
    (void)collide;
    return STALE(world, "pg_joint_set_collide_connected");
}
int pg_joint_collide_connected(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}
pg_result pg_joint_set_user_data(pg_world *world, pg_joint_id joint, uint64_t user_data)
{
    (void)joint;
    (void)user_data;
    return STALE(world, "pg_joint_set_user_data");
}
uint64_t pg_joint_user_data(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}
uint32_t pg_body_joints(const pg_world *world, pg_body_id body, pg_joint_id *out, uint32_t capacity)
{
    (void)world;
    (void)body;
    (void)out;
    (void)capacity;
    return 0;
}
pg_result pg_joint_get_reaction(const pg_world *world, pg_joint_id joint, pg_joint_reaction *out)
{
    (void)joint;
    if (out != NULL) out->force_x = out->force_y = out->torque = 0;
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_joint_get_reaction");
}

pg_distance_joint_def pg_default_distance_joint_def(void)
{
    pg_distance_joint_def d;
    memset(&d, 0, sizeof d);
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

pg_result pg_distance_joint_create(pg_world *world, const pg_distance_joint_def *def, pg_joint_id *out)
{
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_distance_joint_create: " LEFT_OUT);
}

pg_result pg_distance_joint_set_length(pg_world *world, pg_joint_id joint, pg_fix length)
{
    (void)joint; (void)length;
    return STALE(world, "pg_distance_joint_set_length");
}

pg_result pg_distance_joint_set_spring(pg_world *world, pg_joint_id joint, int enable, pg_fix hertz, pg_fix damping_ratio)
{
    (void)joint; (void)enable; (void)hertz; (void)damping_ratio;
    return STALE(world, "pg_distance_joint_set_spring");
}

pg_result pg_distance_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix min_length, pg_fix max_length)
{
    (void)joint; (void)enable; (void)min_length; (void)max_length;
    return STALE(world, "pg_distance_joint_set_limits");
}

pg_fix pg_distance_joint_current_length(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}

pg_result pg_distance_joint_get_def(const pg_world *world, pg_joint_id joint, pg_distance_joint_def *out)
{
    (void)joint;
    if (out != NULL) memset(out, 0, sizeof *out);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_distance_joint_get_def");
}

pg_revolute_joint_def pg_default_revolute_joint_def(void)
{
    pg_revolute_joint_def d;
    memset(&d, 0, sizeof d);
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

pg_result pg_revolute_joint_create(pg_world *world, const pg_revolute_joint_def *def, pg_joint_id *out)
{
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_revolute_joint_create: " LEFT_OUT);
}

pg_result pg_revolute_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix lower_angle, pg_fix upper_angle)
{
    (void)joint; (void)enable; (void)lower_angle; (void)upper_angle;
    return STALE(world, "pg_revolute_joint_set_limits");
}

pg_result pg_revolute_joint_set_motor(pg_world *world, pg_joint_id joint, int enable, pg_fix motor_speed, pg_fix max_motor_torque)
{
    (void)joint; (void)enable; (void)motor_speed; (void)max_motor_torque;
    return STALE(world, "pg_revolute_joint_set_motor");
}

pg_fix pg_revolute_joint_angle(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}

pg_result pg_revolute_joint_get_def(const pg_world *world, pg_joint_id joint, pg_revolute_joint_def *out)
{
    (void)joint;
    if (out != NULL) memset(out, 0, sizeof *out);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_revolute_joint_get_def");
}

pg_weld_joint_def pg_default_weld_joint_def(void)
{
    pg_weld_joint_def d;
    memset(&d, 0, sizeof d);
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

pg_result pg_weld_joint_create(pg_world *world, const pg_weld_joint_def *def, pg_joint_id *out)
{
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_weld_joint_create: " LEFT_OUT);
}

pg_result pg_weld_joint_set_softness(pg_world *world, pg_joint_id joint, pg_fix linear_hertz, pg_fix linear_damping_ratio, pg_fix angular_hertz, pg_fix angular_damping_ratio)
{
    (void)joint; (void)linear_hertz; (void)linear_damping_ratio; (void)angular_hertz; (void)angular_damping_ratio;
    return STALE(world, "pg_weld_joint_set_softness");
}

pg_result pg_weld_joint_get_def(const pg_world *world, pg_joint_id joint, pg_weld_joint_def *out)
{
    (void)joint;
    if (out != NULL) memset(out, 0, sizeof *out);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_weld_joint_get_def");
}

pg_prismatic_joint_def pg_default_prismatic_joint_def(void)
{
    pg_prismatic_joint_def d;
    memset(&d, 0, sizeof d);
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

pg_result pg_prismatic_joint_create(pg_world *world, const pg_prismatic_joint_def *def, pg_joint_id *out)
{
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_prismatic_joint_create: " LEFT_OUT);
}

pg_result pg_prismatic_joint_set_limits(pg_world *world, pg_joint_id joint, int enable, pg_fix lower, pg_fix upper)
{
    (void)joint; (void)enable; (void)lower; (void)upper;
    return STALE(world, "pg_prismatic_joint_set_limits");
}

pg_result pg_prismatic_joint_set_motor(pg_world *world, pg_joint_id joint, int enable, pg_fix motor_speed, pg_fix max_motor_force)
{
    (void)joint; (void)enable; (void)motor_speed; (void)max_motor_force;
    return STALE(world, "pg_prismatic_joint_set_motor");
}

pg_fix pg_prismatic_joint_translation(const pg_world *world, pg_joint_id joint)
{
    (void)world;
    (void)joint;
    return 0;
}

pg_result pg_prismatic_joint_get_def(const pg_world *world, pg_joint_id joint, pg_prismatic_joint_def *out)
{
    (void)joint;
    if (out != NULL) memset(out, 0, sizeof *out);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_prismatic_joint_get_def");
}

pg_mouse_joint_def pg_default_mouse_joint_def(void)
{
    pg_mouse_joint_def d;
    memset(&d, 0, sizeof d);
    d.pg__cookie = PG__DEF_COOKIE;
    return d;
}

pg_result pg_mouse_joint_create(pg_world *world, const pg_mouse_joint_def *def, pg_joint_id *out)
{
    if (out != NULL) out->index = out->generation = 0;
    if (world == NULL || def == NULL || out == NULL) return PG_ERR_NULL;
    return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_mouse_joint_create: " LEFT_OUT);
}

pg_result pg_mouse_joint_set_target(pg_world *world, pg_joint_id joint, pg_vec2 target)
{
    (void)joint; (void)target;
    return STALE(world, "pg_mouse_joint_set_target");
}

pg_result pg_mouse_joint_set_spring(pg_world *world, pg_joint_id joint, pg_fix hertz, pg_fix damping_ratio)
{
    (void)joint; (void)hertz; (void)damping_ratio;
    return STALE(world, "pg_mouse_joint_set_spring");
}

pg_result pg_mouse_joint_set_max_force(pg_world *world, pg_joint_id joint, pg_fix max_force)
{
    (void)joint; (void)max_force;
    return STALE(world, "pg_mouse_joint_set_max_force");
}

pg_result pg_mouse_joint_get_def(const pg_world *world, pg_joint_id joint, pg_mouse_joint_def *out)
{
    (void)joint;
    if (out != NULL) memset(out, 0, sizeof *out);
    if (world == NULL || out == NULL) return PG_ERR_NULL;
    return STALE(world, "pg_mouse_joint_get_def");
}
#endif
