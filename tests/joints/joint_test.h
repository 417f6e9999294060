/* joint_test.h — what the joint tests share: a world with a static anchor body and
 * helpers to read bodies as doubles. Include after pg_test.h and pg_test_world.h. */
#ifndef POGON_TEST_JOINT_TEST_H
#define POGON_TEST_JOINT_TEST_H

#include "pogon/joint.h"

/* got <= bound, printing both on failure */
#define JT_LE(got, bound) PG_EXPECT_LE(got, bound, "%s", "")

static inline test_world joint_world(uint32_t max_bodies, uint32_t max_joints)
{
    pg_world_def d = pg_default_world_def();
    d.max_bodies = max_bodies;
    d.max_shapes = max_bodies;
    d.max_contacts = 4u * max_bodies;
    d.max_joints = max_joints;
#ifdef JT_HZ
    d.step_hz = JT_HZ;
    d.substeps = JT_SUB;
#endif
    return make_world_def(&d);
}

/* A static body with no shapes at (x, y): something to hang things from. */
static inline pg_body_id static_anchor(pg_world *w, double x, double y)
{
    pg_body_def bd = pg_default_body_def();
    pg_body_id id;
    bd.position = pg_v2(fx(x), fx(y));
    assert_int_equal(pg_body_create(w, &bd, &id), PG_OK);
    return id;
}

static inline pg_body_id ball_at(pg_world *w, double x, double y, double radius, double density)
{
    pg_body_def bd = dynamic_at(x, y);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    sd.density = fx(density);
    assert_int_equal(pg_make_ball(w, &bd, &sd, fx(radius), &id), PG_OK);
    return id;
}

static inline pg_body_id box_at(pg_world *w, double x, double y, double width, double height, double density)
{
    pg_body_def bd = dynamic_at(x, y);
    pg_shape_def sd = pg_default_shape_def();
    pg_body_id id;
    sd.density = fx(density);
    assert_int_equal(pg_make_box(w, &bd, &sd, fx(width), fx(height), &id), PG_OK);
    return id;
}

static inline double body_x(pg_world *w, pg_body_id b) { return fd(pg_body_world_center(w, b).x); }
static inline double body_y(pg_world *w, pg_body_id b) { return fd(pg_body_world_center(w, b).y); }
static inline double body_mass(pg_world *w, pg_body_id b) { return (double)pg_body_mass(w, b) / 4294967296.0; }
static inline double body_inertia(pg_world *w, pg_body_id b) { return (double)pg_body_inertia(w, b) / 68719476736.0; }

#endif
