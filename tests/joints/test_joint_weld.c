/* test_joint_weld.c — weld joints hold a cantilever of 10 boxes out from a wall with a
 * documented sag, and a soft weld bends as its hertz says (docs/joints.md).
 *
 * The boxes are 1 m x 0.25 m (density 1), welded end to end; the first to a static
 * body at the wall. A rigid weld's rows are soft constraints of a quarter of the substep
 * rate like every joint row (60 Hz at the defaults), so under load each weld gives an
 * angle of about K torque / omega^2 (K: the row's inverse inertia): the tip sags by
 * CANTILEVER_SAG at most at the default 4 substeps, and 16 times less at 16 substeps,
 * where the joints are 4 times stiffer. */
#include "pg_test.h"
#include "pg_test_world.h"
#include "joint_test.h"

#define BOXES 10
#define CANTILEVER_SAG 2.0 /* m at the tip of the 10 m cantilever, 4 substeps: docs/joints.md */
#define CANTILEVER_SAG_16 0.15 /* m, 16 substeps */

static void build_cantilever(test_world *t, pg_body_id *boxes, double angular_hertz)
{
    pg_body_id wall = static_anchor(t->w, 0.0, 10.0);
    int i;
    for (i = 0; i < BOXES; ++i) {
        pg_weld_joint_def jd = pg_default_weld_joint_def();
        pg_joint_id j;
        boxes[i] = box_at(t->w, i + 0.5, 10.0, 1.0, 0.25, 1.0);
        jd.body_a = i == 0 ? wall : boxes[i - 1];
        jd.body_b = boxes[i];
        jd.local_anchor_a = i == 0 ? pg_v2_zero() : pg_v2(fx(0.5), 0);
        jd.local_anchor_b = pg_v2(fx(-0.5), 0);
        jd.angular_hertz = fx(angular_hertz);
        jd.angular_damping_ratio = fx(1.0);
        assert_int_equal(pg_weld_joint_create(t->w, &jd, &j), PG_OK);
    }
}

/* The tip's sag after 5 s, and its fastest speed in the last second. */
static double cantilever_sag(uint32_t substeps, double *tip_speed_out)
{
    pg_world_def d = pg_default_world_def();
    test_world t;
    pg_body_id boxes[BOXES];
    double sag, tip_speed = 0.0;
    int step;
    d.max_bodies = d.max_shapes = BOXES + 2;
    d.max_joints = BOXES + 2;
    d.substeps = substeps;
    t = make_world_def(&d);
    build_cantilever(&t, boxes, 0.0);
    for (step = 0; step < 300; ++step) {
        assert_int_equal(pg_world_step(t.w), PG_OK);
        if (step >= 240) {
            pg_vec2 v = pg_body_linear_velocity(t.w, boxes[BOXES - 1]);
            double speed = sqrt(fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y));
            if (speed > tip_speed) tip_speed = speed;
        }
    }
    sag = 10.0 - body_y(t.w, boxes[BOXES - 1]);
    printf("weld cantilever of %d boxes, %u substeps: tip sags %.5f m, fastest in the last second %.5f m/s\n", BOXES, substeps, sag, tip_speed);
    free_world(&t);
    *tip_speed_out = tip_speed;
    return sag;
}

static void test_weld_cantilever_sag(void **state)
{
    double speed4, speed16, sag4 = cantilever_sag(4, &speed4), sag16 = cantilever_sag(16, &speed16);
    (void)state;
    JT_LE(sag4, CANTILEVER_SAG);
    JT_LE(sag16, CANTILEVER_SAG_16);
    JT_LE(0.0, sag16); /* it does sag: gravity pulls */
    /* the give goes as 1 / hertz^2, and the joints' hertz as the substep rate */
    printf("sag ratio 4 / 16 substeps: %.3f (16 for give as 1 / hertz^2)\n", sag4 / sag16);
    JT_LE(fabs(sag4 / sag16 / 16.0 - 1.0), 0.1);
    /* and it holds still: the tip moves less than 0.1 m/s (a few mm a step) in the last second */
    JT_LE(speed4, 0.1);
    JT_LE(speed16, 0.1);
}

static void test_soft_weld_bends_like_its_spring(void **state)
{
    /* one box on a soft angular weld: a torsion spring of stiffness k = I omega^2 (I:
     * the box's own inertia, what the angular row sees), which gravity's torque
     * m g l cos(theta) about the anchor bends to theta = m g l cos(theta) / k; the
     * linear part is rigid */
    const double hz = 2.0;
    test_world t = joint_world(4, 2);
    pg_body_id wall = static_anchor(t.w, 0.0, 10.0), box = box_at(t.w, 0.5, 10.0, 1.0, 0.25, 1.0);
    pg_weld_joint_def jd = pg_default_weld_joint_def();
    pg_joint_id j;
    double m, ip, omega = 2.0 * PGT_PI * hz, theta, expected;
    int step;
    (void)state;
    jd.body_a = wall;
    jd.body_b = box;
    jd.local_anchor_b = pg_v2(fx(-0.5), 0);
    jd.angular_hertz = fx(hz);
    jd.angular_damping_ratio = fx(1.0);
    assert_int_equal(pg_weld_joint_create(t.w, &jd, &j), PG_OK);
    m = body_mass(t.w, box);
    ip = body_inertia(t.w, box);
    for (step = 0; step < 600; ++step) assert_int_equal(pg_world_step(t.w), PG_OK);
    theta = -fd(pg_angle_to_radians(pg_body_angle(t.w, box)));
    expected = 0.0;
    for (step = 0; step < 50; ++step) expected = m * 10.0 * 0.5 * cos(expected) / (ip * omega * omega); /* the fixed point */
    printf("soft weld %.1f Hz: bends %.5f rad, torsion spring of the box's inertia gives %.5f rad\n", hz, theta, expected);
    JT_LE(fabs(theta / expected - 1.0), 0.02);
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weld_cantilever_sag),
        cmocka_unit_test(test_soft_weld_bends_like_its_spring),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
