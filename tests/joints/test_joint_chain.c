/* test_joint_chain.c — a chain of 40 links on revolute joints, hanging from a pin,
 * keeps its length, and carries a box of 50 times a link's mass without exploding
 * (docs/joints.md, "Tolerances").
 *
 * Links are boxes 0.5 m x 0.125 m, joined at their ends (0.25 m from their centres);
 * neighbours do not collide (collide_connected 0). The stretch is the sum over the
 * joints of the distance between each joint's two anchors: what the chain is longer
 * than its 20 m. */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"

#ifndef LINKS
#define LINKS 40
#endif
#define LINK_LENGTH 0.5
#define CHAIN_STRETCH_FRACTION 0.02       /* of 20 m, 10 s after falling from horizontal (docs/joints.md) */
#define HEAVY_CHAIN_STRETCH_FRACTION 0.03 /* of 20 m, holding a box of 50 links' mass (docs/joints.md) */

typedef struct chain {
    test_world t;
    pg_body_id links[LINKS + 1];
    pg_joint_id joints[LINKS + 1];
    uint32_t n_joints;
} chain;

/* The chain from the pin at (0, 30): along +x (horizontal) or down (vertical). */
static void build_chain(chain *c, int horizontal)
{
    pg_body_id pin;
    int i;
    c->t = joint_world(LINKS + 4, LINKS + 4);
    pin = static_anchor(c->t.w, 0.0, 30.0);
    c->n_joints = 0;
    for (i = 0; i < LINKS; ++i) {
        double s = (i + 0.5) * LINK_LENGTH;
        pg_revolute_joint_def jd = pg_default_revolute_joint_def();
        pg_body_def bd = dynamic_at(horizontal ? s : 0.0, horizontal ? 30.0 : 30.0 - s);
        pg_shape_def sd = pg_default_shape_def();
        bd.angle = horizontal ? 0 : (pg_angle)(0u - PG_ANGLE_QUARTER); /* +x down: anchor_b on top */
        sd.density = fx(20.0);
        assert_int_equal(pg_make_box(c->t.w, &bd, &sd, fx(LINK_LENGTH), fx(0.125), &c->links[i]), PG_OK);
        jd.body_a = i == 0 ? pin : c->links[i - 1];
        jd.body_b = c->links[i];
        jd.local_anchor_a = i == 0 ? pg_v2_zero() : pg_v2(fx(LINK_LENGTH / 2), 0);
        jd.local_anchor_b = pg_v2(fx(-LINK_LENGTH / 2), 0);
        assert_int_equal(pg_revolute_joint_create(c->t.w, &jd, &c->joints[c->n_joints++]), PG_OK);
    }
}

/* The world point of a body-frame point */
static void world_point(pg_world *w, pg_body_id b, pg_vec2 local, double *x, double *y)
{
    pg_vec2 o = pg_body_position(w, b);
    double a = (double)pg_angle_to_radians(pg_body_angle(w, b)) / 65536.0, lx = fd(local.x), ly = fd(local.y);
    *x = fd(o.x) + cos(a) * lx - sin(a) * ly;
    *y = fd(o.y) + sin(a) * lx + cos(a) * ly;
}

static double stretch(const chain *c)
{
    double sum = 0.0;
    uint32_t i;
    for (i = 0; i < c->n_joints; ++i) {
        pg_revolute_joint_def d;
        double ax, ay, bx, by;
        assert_int_equal(pg_revolute_joint_get_def(c->t.w, c->joints[i], &d), PG_OK);
        world_point(c->t.w, d.body_a, d.local_anchor_a, &ax, &ay);
        world_point(c->t.w, d.body_b, d.local_anchor_b, &bx, &by);
        sum += sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
    }
    return sum;
}

static void test_chain_swinging_keeps_its_length(void **state)
{
    chain c;
    double worst = 0.0, at_end;
    int step;
    (void)state;
    build_chain(&c, 1);
    for (step = 0; step < 600; ++step) {
        double s;
        assert_int_equal(pg_world_step(c.t.w), PG_OK);
        s = stretch(&c);
        if (s > worst) worst = s;
    }
    at_end = stretch(&c);
    printf("40-link chain from horizontal: stretch after 10 s %.5f m (%.4f %% of 20 m), worst %.5f m\n", at_end, 100.0 * at_end / 20.0, worst);
    JT_LE(at_end, CHAIN_STRETCH_FRACTION * 20.0);
    /* it hangs: the last link's centre is below the pin by most of the chain's length */
    JT_LE(body_y(c.t.w, c.links[LINKS - 1]), 30.0 - 10.0);
    free_world(&c.t);
}

static void test_chain_holds_a_heavy_box(void **state)
{
    chain c;
    pg_revolute_joint_def jd = pg_default_revolute_joint_def();
    pg_body_id box;
    double link_mass, fastest = 0.0, s = 0.0, end_y = 30.0 - LINKS * LINK_LENGTH;
    int step;
    (void)state;
    build_chain(&c, 0);
    link_mass = body_mass(c.t.w, c.links[0]);
    {
        /* a box of 50 link masses, hung from the last link's end */
        double side = sqrt(50.0 * link_mass / 20.0);
        box = box_at(c.t.w, 0.0, end_y - side / 2, side, side, 20.0);
        jd.body_a = c.links[LINKS - 1];
        jd.body_b = box;
        jd.local_anchor_a = pg_v2(fx(LINK_LENGTH / 2), 0);
        jd.local_anchor_b = pg_v2(0, fx(side / 2));
        assert_int_equal(pg_revolute_joint_create(c.t.w, &jd, &c.joints[c.n_joints++]), PG_OK);
        printf("box of %.2f kg on links of %.4f kg (ratio %.1f)\n", body_mass(c.t.w, box), link_mass, body_mass(c.t.w, box) / link_mass);
        JT_LE(49.0, body_mass(c.t.w, box) / link_mass);
    }
    for (step = 0; step < 1200; ++step) {
        uint32_t i;
        assert_int_equal(pg_world_step(c.t.w), PG_OK);
        if (step == 599) s = stretch(&c); /* after 10 s */
        if (step < 900) continue; /* it sags into the joints' softness and settles: the last 5 s of 20 */
        for (i = 0; i < LINKS; ++i) {
            pg_vec2 v = pg_body_linear_velocity(c.t.w, c.links[i]);
            double speed = sqrt(fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y));
            if (speed > fastest) fastest = speed;
        }
    }
    printf("40-link chain holding 50x: stretch after 10 s %.5f m (%.4f %% of 20 m), fastest link from 15 to 20 s %.4f m/s, box at (%.4f, %.4f)\n", s,
           100.0 * s / 20.0, fastest, body_x(c.t.w, box), body_y(c.t.w, box));
    JT_LE(s, HEAVY_CHAIN_STRETCH_FRACTION * 20.0);
    /* settled, it stays at rest: no link moves at 0.05 m/s from 15 s to 20 s */
    JT_LE(fastest, 0.05);
    /* and the box hangs where the chain's length and its stretch put it */
    JT_LE(fabs(body_y(c.t.w, box) - (end_y - sqrt(50.0 * link_mass / 20.0) / 2)), stretch(&c) + 0.01);
    JT_LE(fabs(body_x(c.t.w, box)), 0.01);
    free_world(&c.t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_swinging_keeps_its_length),
        cmocka_unit_test(test_chain_holds_a_heavy_box),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
