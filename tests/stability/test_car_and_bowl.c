/* test_car_and_bowl.c — the car and the soft blob bowl of issue 28 (scenes/car.scene,
 * scenes/soft_blob_bowl.scene) do what their scenes say, on chains and concave bodies:
 *
 *   - car: on a chain of one-sided segments (hills, a bump, a dip, a climb) the motorised
 *     car covers at least 34 m in 10 s (600 frames at 60 Hz; its wheels' motors allow
 *     4 m/s): over the hill, the bump and the dip, onto the climb. Its chassis stays within 30 degrees of level (the steepest
 *     face is the bump's 26.6) and no wheel sinks more than 0.05 m into the terrain: the
 *     least distance of a wheel's centre to the chain stays above 0.45 m (radius 0.5 m).
 *   - soft_blob_bowl: no ball of the blob ever goes below the concave U's floor by more
 *     than 0.02 m (it lands at 10 m/s), and after 10 s its 13 balls lie inside the U
 *     (between its inner walls, below its rim) and the blob is at rest but for a slow roll:
 *     its centre of mass slower than 0.04 m/s, every ball slower than 0.1 m/s. (The blob
 *     rolls along the floor at about 0.025 m/s and does not stop, in the old bowl of
 *     boxes as in this one: docs/soft-bodies.md.)
 *
 * Each run prints its figures (distance, worst angle, least clearance; the blob's extent
 * and fastest ball), so that a change of the bounds' margins shows in the log. */
#include "../unit/pg_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../unit/pg_test_world.h"
#include "pogon/scene_file.h"

#ifndef POGON_SCENES_DIR
#error "POGON_SCENES_DIR must name the scenes/ folder"
#endif


static char *scene_text(const char *name, size_t *size)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", POGON_SCENES_DIR, name);
    return pgt_read_file(path, size);
}

static test_world load(const char *name)
{
    size_t size;
    char *text = scene_text(name, &size);
    pg_world_def d;
    pg_scene_error e;
    test_world t;
    assert_int_equal(pg_scene_read_def(text, size, &d, &e), PG_OK);
    t = make_world_def(&d);
    assert_int_equal(pg_scene_load(t.w, text, size, &e), PG_OK);
    free(text);
    return t;
}

static pg_body_id slot(uint32_t index)
{
    pg_body_id id;
    id.index = index;
    id.generation = 1;
    return id;
}

/* The car scene's terrain, as in the file's chain line (left to right here). */
static const double terrain[][2] = {{-10, 0}, {4, 0}, {8, 0.6}, {11, 0.8}, {14, 0.6}, {18, 0}, {20, 0},
                                    {20.5, 0.25}, {21.5, 0.25}, {22, 0}, {25, 0}, {27, -0.6}, {30, -0.6},
                                    {32, 0}, {36, 0}, {42, 1.5}, {48, 1.5}, {54, 0.5}, {70, 0.5}};

/* Least distance of (x, y) to the terrain's polyline. */
static double clearance(double x, double y)
{
    double best = 1e9;
    size_t i;
    for (i = 0; i + 1 < sizeof terrain / sizeof terrain[0]; ++i) {
        double ax = terrain[i][0], ay = terrain[i][1], dx = terrain[i + 1][0] - ax, dy = terrain[i + 1][1] - ay;
        double s = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), ex, ey, dist;
        if (s < 0) s = 0;
        if (s > 1) s = 1;
        ex = x - (ax + s * dx);
        ey = y - (ay + s * dy);
        dist = sqrt(ex * ex + ey * ey);
        if (dist < best) best = dist;
    }
    return best;
}

static double degrees_of(pg_angle a)
{
    return (double)(int32_t)a * (180.0 / 2147483648.0); /* a turn is 2^32: (-180, 180] */
}

static void car_drives_over_the_chain(void **state)
{
    test_world t = load("car.scene");
    double x0 = fd(pg_body_position(t.w, slot(1)).x), worst_angle = 0, least = 1e9, covered;
    int f;
    uint32_t wheel;
    (void)state;
    for (f = 0; f < 600; ++f) {
        double a;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        a = fabs(degrees_of(pg_body_angle(t.w, slot(1))));
        if (a > worst_angle) worst_angle = a;
        for (wheel = 2; wheel <= 3; ++wheel) {
            pg_vec2 p = pg_body_position(t.w, slot(wheel));
            double c = clearance(fd(p.x), fd(p.y));
            if (c < least) least = c;
        }
    }
    covered = fd(pg_body_position(t.w, slot(1)).x) - x0;
    printf("car: %.3f m in 10 s, chassis at most %.2f degrees from level, wheels at least %.4f m from the chain\n", covered,
           worst_angle, least);
    PG_EXPECT_GE(covered, 34.0, "%s", "the car drives over the hill, the bump and the dip in 10 s");
    PG_EXPECT_LE(worst_angle, 30.0, "%s", "the chassis stays upright");
    PG_EXPECT_GE(least, 0.45, "%s", "no wheel sinks into the terrain by more than 0.05 m");
    free_world(&t);
}

/* The lowest bottom of the blob's balls (bodies 1..13; the centre's radius 0.3 m, the ring's 0.2 m). */
static double lowest_bottom(pg_world *w)
{
    double lowest = 1e9;
    uint32_t i;
    for (i = 1; i <= 13; ++i) {
        double bottom = fd(pg_body_position(w, slot(i)).y) - (i == 1 ? 0.3 : 0.2);
        if (bottom < lowest) lowest = bottom;
    }
    return lowest;
}

static void blob_comes_to_rest_in_the_bowl(void **state)
{
    test_world t = load("soft_blob_bowl.scene");
    double fastest = 0, lowest = 1e9, widest = 0, highest = -1e9, mass = 0, px = 0, py = 0, blob_speed;
    uint32_t i;
    int f;
    (void)state;
    for (f = 0; f < 600; ++f) {
        double l;
        assert_int_equal(pg_world_step(t.w), PG_OK);
        l = lowest_bottom(t.w);
        if (l < lowest) lowest = l;
    }
    for (i = 1; i <= 13; ++i) {
        pg_vec2 p = pg_body_position(t.w, slot(i)), v = pg_body_linear_velocity(t.w, slot(i));
        double r = i == 1 ? 0.3 : 0.2, x = fd(p.x), y = fd(p.y), s = sqrt(fd(v.x) * fd(v.x) + fd(v.y) * fd(v.y));
        double m = r * r; /* density 1 for all: mass in proportion to r^2 */
        /* the inner walls are x - y = 4 and x + y = -4: a ball inside is r sqrt 2 off them */
        double wall = fabs(x) - y + r * sqrt(2.0);
        if (s > fastest) fastest = s;
        if (wall > widest) widest = wall;
        if (y + r > highest) highest = y + r;
        mass += m;
        px += m * fd(v.x);
        py += m * fd(v.y);
    }
    blob_speed = sqrt(px * px + py * py) / mass;
    printf("blob: lowest ball bottom over 10 s %.4f m (floor 0); after 10 s top %.3f m (rim 3), "
           "most |x| - y + r sqrt 2 %.3f (walls 4), centre of mass at %.4f m/s, fastest ball %.4f m/s\n",
           lowest, highest, widest, blob_speed, fastest);
    PG_EXPECT_GE(lowest, -0.02, "%s", "no ball below the bowl's floor");
    PG_EXPECT_LE(highest, 3.0, "%s", "every ball below the rim");
    PG_EXPECT_LE(widest, 4.0, "%s", "every ball between the inner walls");
    PG_EXPECT_LE(blob_speed, 0.04, "%s", "the blob at rest but for its slow roll");
    PG_EXPECT_LE(fastest, 0.1, "%s", "every ball at rest but for the roll");
    free_world(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(car_drives_over_the_chain),
        cmocka_unit_test(blob_comes_to_rest_in_the_bowl),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
