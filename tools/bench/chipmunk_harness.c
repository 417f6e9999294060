/* pogon-bench-chipmunk — the pogon-bench scenes in Chipmunk2D 7 (Debian libchipmunk-dev,
 * 7.0.3), for comparison.
 *
 * Usage: pogon-bench-chipmunk SCENE [--count N] [--steps N] [--repeat R] [--json]
 *                            [--variant defaults|best] [--no-sleep] [--sleep]
 *                            [--iterations N] [--hash DIM] [--tree] [--slop M]
 *        pogon-bench-chipmunk all [options]
 *
 * Same scenes as tools/scenes/scenes.c and box2d_harness.cpp: a static ground 100 x 2 m
 * whose top is at y = 0, 1 m boxes of density 1 and friction 0.6 (pyramid: `count` rows
 * centred on x = 0; stack: `count` boxes in a column), and rain: a 42 x 2 m floor, side
 * walls 0.5 m thick in 100 m pieces at x = +-20.25 up to 500 m, and `count` circles whose
 * radii (0.25 .. 0.5 m) and positions come from the same xorshift32 sequence (seed 12345)
 * in the same order, converted from the same Q16.16 integers. Gravity (0, -10), timestep
 * 1/60 s, one cpSpaceStep per step, no damping, elasticity 0.
 *
 * Chipmunk multiplies the two shapes' friction coefficients (Box2D and pogon take the
 * geometric mean), so every shape gets sqrt(0.6): each contact then has friction 0.6,
 * as in the other engines. Masses are density x area, moments from cpMomentForBox and
 * cpMomentForCircle. Chipmunk computes in double (CP_USE_DOUBLES on x86-64).
 *
 * Variants (--variant, default "defaults"):
 *   defaults  the library's defaults: 10 iterations, the bounding-box tree (cpBBTree),
 *             sleeping off (sleepTimeThreshold = INFINITY), collisionSlop 0.1 (a length in
 *             the user's units, chosen for pixels: 0.1 m here).
 *             Debian's libchipmunk is built without NDEBUG (cpSpaceNew prints "Debug
 *             Enabled" on stdout), so its runtime assertions run in both variants.
 *   best      the fastest setting tried that a user of Chipmunk would pick for the scene
 *             (tools/bench/peers.md lists what was tried). Pyramid: sleeping on
 *             (sleepTimeThreshold 0.5 s, as pogon's time_to_sleep; idle speed derived from
 *             gravity, the library's default), 10 iterations (the pyramid stands with them;
 *             20 or 30 only cost time), the tree. Rain: the spatial hash
 *             (cpSpaceUseSpatialHash, cell 1 m = the largest circle's diameter, 10 cells
 *             per body), sleeping off (nothing settles in the measured 5 s; on, it costs
 *             about 10 %), 10 iterations. collisionSlop stays 0.1: 0.01 gave the same
 *             pyramid to six digits and no measurable change in rain. joint_grid: 60
 *             iterations (the fewest that keep the grid from exploding; see below); chain:
 *             as the defaults. The single-threaded
 *             cpSpace; the threaded cpHastySpace is left out because pogon steps on one
 *             thread.
 * The joint scenes of tools/scenes/joint_scenes.h, from the same integers: joint_grid
 * (count = columns and rows, default 40: circles of radius 0.4 m, 1 m apart, the top row
 * static bodies, cpPivotJoint to the body above and the body on the left) and chain
 * (count = chains, default 20, of 40 links pinned by cpPivotJoint to the space's static
 * body at (2j, 2j) and starting horizontal). A link is Chipmunk's capsule, a segment shape
 * of radius 0.125 m, with the capsule's exact mass and moment (cpMomentForSegment
 * approximates it by a box). Every shape has category 2 and mask ~2, so nothing collides,
 * and sleeping is off in both variants. The joints keep Chipmunk's defaults (errorBias
 * (1 - 0.1)^60, maxBias and maxForce infinite). They report the same sanity figure as
 * pogon-bench: sag_m (the grid's bottom row, mean drop) or stretch_m (the largest over the
 * chains of the sum of anchor gaps), and worst_gap_m.
 * The single options override the variant: --iterations N, --hash DIM (spatial hash with
 * cell DIM m), --tree (bounding-box tree), --slop M, --sleep / --no-sleep.
 *
 * Method (as pogon-bench): build `repeat` times (default 3), time `steps` steps (default
 * 600 for pyramid/stack, 300 for rain) with clock_gettime(CLOCK_MONOTONIC) around the
 * stepping only, report the median of the per-run mean ms per step. The same metrics and
 * JSON keys as pogon-bench, with "engine":"chipmunk-7.0.3" and the settings used.
 */
#define _POSIX_C_SOURCE 200809L
#include <chipmunk/chipmunk.h>

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_REPEAT 101u
static const double PI = 3.14159265358979323846;

typedef struct options {
    uint32_t count, steps, repeat;
    int json;
    const char *variant; /* "defaults" or "best" */
    int sleep;           /* -1: the variant's, 0 off, 1 on */
    int iterations;      /* 0: the variant's */
    double hash_dim;     /* < 0: the variant's; 0: tree; > 0: spatial hash cell */
    double slop;         /* < 0: the variant's */
} options;

typedef struct settings {
    int iterations;
    int sleep;
    double hash_dim; /* 0: bbtree */
    double slop;
} settings;

typedef struct result {
    const char *scene;
    uint32_t count, bodies, steps, repeat;
    settings s;
    double ms, sps, ms_min, ms_max;
    int stands;
    double disp, dx, dy, angle_deg;
    uint32_t awake, touching;
    uint32_t joints;
    const char *figure; /* joint scenes: "sag" or "stretch" */
    double figure_m, worst_gap_m;
} result;

static int is_joint_scene(const char *scene) { return strcmp(scene, "joint_grid") == 0 || strcmp(scene, "chain") == 0; }

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static double q16(int32_t v) { return (double)v / 65536.0; }

static uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

static const double FRICTION = 0.6, DENSITY = 1.0;

/* a static box centred at (cx, cy) on the space's static body */
static void add_wall(cpSpace *space, double cx, double cy, double width, double height)
{
    cpShape *s = cpSpaceAddShape(space, cpBoxShapeNew2(cpSpaceGetStaticBody(space),
                                                        cpBBNew(cx - 0.5 * width, cy - 0.5 * height, cx + 0.5 * width,
                                                                cy + 0.5 * height),
                                                        0.0));
    cpShapeSetFriction(s, sqrt(FRICTION));
    cpShapeSetElasticity(s, 0.0);
}

static cpBody *add_box(cpSpace *space, double x, double y)
{
    double mass = DENSITY * 1.0 * 1.0;
    cpBody *b = cpSpaceAddBody(space, cpBodyNew(mass, cpMomentForBox(mass, 1.0, 1.0)));
    cpShape *s;
    cpBodySetPosition(b, cpv(x, y));
    s = cpSpaceAddShape(space, cpBoxShapeNew(b, 1.0, 1.0, 0.0));
    cpShapeSetFriction(s, sqrt(FRICTION));
    cpShapeSetElasticity(s, 0.0);
    return b;
}

static cpBody *add_ball(cpSpace *space, double x, double y, double radius)
{
    double mass = DENSITY * PI * radius * radius;
    cpBody *b = cpSpaceAddBody(space, cpBodyNew(mass, cpMomentForCircle(mass, 0.0, radius, cpvzero)));
    cpShape *s;
    cpBodySetPosition(b, cpv(x, y));
    s = cpSpaceAddShape(space, cpCircleShapeNew(b, radius, cpvzero));
    cpShapeSetFriction(s, sqrt(FRICTION));
    cpShapeSetElasticity(s, 0.0);
    return b;
}

/* Builds the scene; returns the top body (the last one created). */
static cpBody *build(cpSpace *space, const char *scene, uint32_t count, uint32_t *bodies)
{
    cpBody *top = NULL;
    uint32_t i, row;
    *bodies = 0;
    if (strcmp(scene, "pyramid") == 0 || strcmp(scene, "stack") == 0) {
        int pyramid = strcmp(scene, "pyramid") == 0;
        add_wall(space, 0.0, -1.0, 100.0, 2.0);
        for (row = 0; row < (pyramid ? count : 1u); ++row) {
            uint32_t n = pyramid ? count - row : count;
            for (i = 0; i < n; ++i) {
                if (pyramid)
                    top = add_box(space, q16((int32_t)(2 * i + 1) * 32768 - (int32_t)n * 32768), 0.5 + (double)row);
                else
                    top = add_box(space, 0.0, 0.5 + (double)i);
                ++*bodies;
            }
        }
    } else if (strcmp(scene, "rain") == 0) {
        uint32_t seed = 12345u;
        add_wall(space, 0.0, -1.0, 42.0, 2.0);
        for (i = 0; i < 10u; ++i)
            add_wall(space, (i & 1u) ? 20.25 : -20.25, 50.0 + 100.0 * (double)(i / 2u), 0.5, 100.0);
        for (i = 0; i < count; ++i) {
            int32_t radius = 16384 + (int32_t)(next_random(&seed) % 16385u);
            uint32_t column = i % 39u, layer = i / 39u;
            int32_t jitter = (int32_t)(next_random(&seed) % 8193u) - 4096;
            int32_t x = (int32_t)column * 65536 - 19 * 65536 + jitter;
            int32_t y = 2 * 65536 + (int32_t)layer * 65536;
            top = add_ball(space, q16(x), q16(y), q16(radius));
            ++*bodies;
        }
    }
    return top;
}

/* ---- joint scenes ------------------------------------------------------------------------ */
#define GRID_RADIUS 26214 /* 0.4 m in Q16.16, as tools/scenes/joint_scenes.c */
#define CHAIN_LINKS 40u
static const double LINK_LENGTH = 1.0, LINK_RADIUS = 0.125;
#define NO_COLLISION_CATEGORY 2u

static void no_collision(cpShape *s)
{
    cpShapeSetFilter(s, cpShapeFilterNew(CP_NO_GROUP, NO_COLLISION_CATEGORY, ~(cpBitmask)NO_COLLISION_CATEGORY));
}

static void pivot(cpSpace *space, cpBody *a, cpVect anchor_a, cpBody *b, cpVect anchor_b)
{
    cpSpaceAddConstraint(space, cpPivotJointNew2(a, b, anchor_a, anchor_b));
}

/* The bodies in the order tools/scenes/joint_scenes.c makes them (the grid row by row,
 * its static top row included; the chains link by link) into `bodies` (room for count^2
 * or count x 40). Returns the last body made. */
static cpBody *build_joints(cpSpace *space, const char *scene, uint32_t count, cpBody **bodies, result *res)
{
    uint32_t made = 0, row, col, j, i;
    res->bodies = 0;
    res->joints = 0;
    if (strcmp(scene, "joint_grid") == 0) {
        double radius = q16(GRID_RADIUS), mass = DENSITY * PI * radius * radius;
        for (row = 0; row < count; ++row) {
            for (col = 0; col < count; ++col) {
                cpBody *b = row == 0 ? cpBodyNewStatic() : cpBodyNew(mass, cpMomentForCircle(mass, 0.0, radius, cpvzero));
                cpShape *s;
                cpSpaceAddBody(space, b);
                cpBodySetPosition(b, cpv((double)col, -(double)row));
                s = cpSpaceAddShape(space, cpCircleShapeNew(b, radius, cpvzero));
                no_collision(s);
                bodies[made++] = b;
                if (row == 0) continue;
                pivot(space, bodies[(row - 1) * count + col], cpv(0.0, -0.5), b, cpv(0.0, 0.5));
                res->joints += 1u;
                if (col > 0) {
                    pivot(space, bodies[row * count + col - 1], cpv(0.5, 0.0), b, cpv(-0.5, 0.0));
                    res->joints += 1u;
                }
                res->bodies += 1u;
            }
        }
    } else {
        /* the capsule's mass and inertia about its centre (as src/core/mass.c): area 2rL + pi r^2,
         * I = rL^3/6 + 2r^3 L + pi r^2 (r^2/2 + L^2/4), density 1 */
        double r = LINK_RADIUS, l = LINK_LENGTH;
        double mass = DENSITY * (2.0 * r * l + PI * r * r);
        double moment = DENSITY * (r * l * l * l / 6.0 + 2.0 * r * r * r * l + PI * r * r * (r * r / 2.0 + l * l / 4.0));
        for (j = 0; j < count; ++j) {
            double pin = 2.0 * (double)j;
            for (i = 0; i < CHAIN_LINKS; ++i) {
                cpBody *b = cpSpaceAddBody(space, cpBodyNew(mass, moment));
                cpShape *s;
                cpBodySetPosition(b, cpv(pin + (double)i * l + 0.5 * l, pin));
                s = cpSpaceAddShape(space, cpSegmentShapeNew(b, cpv(-0.5 * l, 0.0), cpv(0.5 * l, 0.0), r));
                no_collision(s);
                if (i == 0) pivot(space, cpSpaceGetStaticBody(space), cpv(pin, pin), b, cpv(-0.5 * l, 0.0));
                else pivot(space, bodies[made - 1u], cpv(0.5 * l, 0.0), b, cpv(-0.5 * l, 0.0));
                res->joints += 1u;
                bodies[made++] = b;
                res->bodies += 1u;
            }
        }
    }
    return made > 0 ? bodies[made - 1u] : NULL;
}

static double gap(cpVect a, cpVect b) { return cpvlength(cpvsub(a, b)); }

/* The same figures as pg_joint_scene_sanity (tools/scenes/joint_scenes.c). */
static void joint_sanity(const char *scene, uint32_t count, cpBody *const *bodies, result *res)
{
    uint32_t row, col, j, i;
    res->worst_gap_m = 0.0;
    res->figure_m = 0.0;
    if (strcmp(scene, "joint_grid") == 0) {
        double drop = 0.0;
        res->figure = "sag";
        for (row = 1; row < count; ++row) {
            for (col = 0; col < count; ++col) {
                cpBody *b = bodies[row * count + col];
                double g = gap(cpBodyLocalToWorld(bodies[(row - 1) * count + col], cpv(0.0, -0.5)), cpBodyLocalToWorld(b, cpv(0.0, 0.5)));
                if (g > res->worst_gap_m) res->worst_gap_m = g;
                if (col > 0) {
                    g = gap(cpBodyLocalToWorld(bodies[row * count + col - 1], cpv(0.5, 0.0)), cpBodyLocalToWorld(b, cpv(-0.5, 0.0)));
                    if (g > res->worst_gap_m) res->worst_gap_m = g;
                }
                if (row == count - 1) drop += -(double)(count - 1) - cpBodyGetPosition(b).y;
            }
        }
        res->figure_m = count > 1 ? drop / (double)count : 0.0;
        return;
    }
    res->figure = "stretch";
    for (j = 0; j < count; ++j) {
        double stretch = 0.0;
        for (i = 0; i < CHAIN_LINKS; ++i) {
            cpBody *b = bodies[j * CHAIN_LINKS + i];
            cpVect from = i == 0 ? cpv(2.0 * (double)j, 2.0 * (double)j)
                                 : cpBodyLocalToWorld(bodies[j * CHAIN_LINKS + i - 1], cpv(0.5 * LINK_LENGTH, 0.0));
            double g = gap(from, cpBodyLocalToWorld(b, cpv(-0.5 * LINK_LENGTH, 0.0)));
            stretch += g;
            if (g > res->worst_gap_m) res->worst_gap_m = g;
        }
        if (stretch > res->figure_m) res->figure_m = stretch;
    }
}

/* ---- end-of-run counts ------------------------------------------------------------------ */
typedef struct counts {
    uint32_t awake;
    double touching; /* arbiters; one between two dynamic bodies is seen from both */
} counts;

static void count_arbiter(cpBody *body, cpArbiter *arb, void *data)
{
    counts *c = (counts *)data;
    cpBody *a, *b, *other;
    cpArbiterGetBodies(arb, &a, &b);
    other = a == body ? b : a;
    c->touching += cpBodyGetType(other) == CP_BODY_TYPE_DYNAMIC ? 0.5 : 1.0;
}

static void count_body(cpBody *body, void *data)
{
    counts *c = (counts *)data;
    if (cpBodyGetType(body) != CP_BODY_TYPE_DYNAMIC) return;
    if (!cpBodyIsSleeping(body)) c->awake += 1u;
    cpBodyEachArbiter(body, count_arbiter, data);
}

static void free_shape(cpSpace *space, void *shape, void *unused)
{
    (void)unused;
    cpSpaceRemoveShape(space, (cpShape *)shape);
    cpShapeFree((cpShape *)shape);
}

static void post_free_shape(cpShape *shape, void *space)
{
    cpSpaceAddPostStepCallback((cpSpace *)space, free_shape, shape, NULL);
}

static void free_body(cpSpace *space, void *body, void *unused)
{
    (void)unused;
    cpSpaceRemoveBody(space, (cpBody *)body);
    cpBodyFree((cpBody *)body);
}

static void post_free_body(cpBody *body, void *space)
{
    cpSpaceAddPostStepCallback((cpSpace *)space, free_body, body, NULL);
}

/* cpSpaceFree does not free the bodies and shapes (as in Chipmunk's demos). */
static void free_space(cpSpace *space)
{
    cpSpaceEachShape(space, post_free_shape, space);
    cpSpaceEachBody(space, post_free_body, space);
    cpSpaceStep(space, 0.0); /* runs the post-step callbacks */
    cpSpaceFree(space);
}

/* ---- one measurement ------------------------------------------------------------------- */
static settings pick_settings(const char *scene, const options *o)
{
    settings s;
    int best = strcmp(o->variant, "best") == 0;
    int rain = strcmp(scene, "rain") == 0;
    /* the grid of pivots explodes at 10, 20 and 40 iterations (its bottom row thousands of
     * metres off within 600 steps) and drifts 0.7 m at 50: 60 is the fewest that hold it */
    s.iterations = best && strcmp(scene, "joint_grid") == 0 ? 60 : 10;
    s.sleep = best && !rain && !is_joint_scene(scene);
    s.hash_dim = best && rain ? 1.0 : 0.0;
    s.slop = 0.1;
    if (o->iterations > 0) s.iterations = o->iterations;
    if (o->sleep >= 0 && !is_joint_scene(scene)) s.sleep = o->sleep; /* the joint scenes time awake joints */
    if (o->hash_dim >= 0.0) s.hash_dim = o->hash_dim;
    if (o->slop >= 0.0) s.slop = o->slop;
    return s;
}

static int run(const char *scene, const options *o, uint32_t count_override, result *res)
{
    int rain = strcmp(scene, "rain") == 0, joints = is_joint_scene(scene);
    uint32_t count = count_override ? count_override : o->count ? o->count : rain ? 1000u : strcmp(scene, "joint_grid") == 0 ? 40u : 20u;
    uint32_t steps = o->steps ? o->steps : rain ? 300u : 600u;
    uint32_t repeat = o->repeat ? o->repeat : 3u, r, i;
    double runs[MAX_REPEAT];
    if (repeat > MAX_REPEAT) repeat = MAX_REPEAT;
    memset(res, 0, sizeof *res);
    res->scene = scene;
    res->count = count;
    res->steps = steps;
    res->repeat = repeat;
    res->stands = !rain && !joints;
    res->s = pick_settings(scene, o);
    for (r = 0; r < repeat; ++r) {
        cpSpace *space = cpSpaceNew();
        cpBody *top;
        cpVect start, p;
        double t0, t1;
        counts c = {0u, 0.0};
        cpBody **bodies = NULL;
        cpSpaceSetGravity(space, cpv(0.0, -10.0));
        cpSpaceSetIterations(space, res->s.iterations);
        cpSpaceSetCollisionSlop(space, res->s.slop);
        if (res->s.sleep) cpSpaceSetSleepTimeThreshold(space, 0.5);
        /* cell count: Chipmunk's advice is about 10 x the number of objects */
        if (res->s.hash_dim > 0.0) cpSpaceUseSpatialHash(space, res->s.hash_dim, (int)(10u * count + 1000u));
        if (joints) {
            bodies = (cpBody **)malloc(sizeof *bodies * (size_t)count * (strcmp(scene, "chain") == 0 ? CHAIN_LINKS : count));
            top = bodies != NULL ? build_joints(space, scene, count, bodies, res) : NULL;
        } else {
            top = build(space, scene, count, &res->bodies);
        }
        if (top == NULL) {
            free(bodies);
            free_space(space);
            return 0;
        }
        start = cpBodyGetPosition(top);
        t0 = now_ms();
        for (i = 0; i < steps; ++i) cpSpaceStep(space, 1.0 / 60.0);
        t1 = now_ms();
        runs[r] = (t1 - t0) / (double)steps;
        p = cpBodyGetPosition(top);
        res->dx = p.x - start.x;
        res->dy = p.y - start.y;
        res->disp = sqrt(res->dx * res->dx + res->dy * res->dy);
        res->angle_deg = cpBodyGetAngle(top) * (180.0 / PI);
        if (joints) joint_sanity(scene, count, bodies, res);
        free(bodies);
        cpSpaceEachBody(space, count_body, &c);
        res->awake = c.awake;
        res->touching = (uint32_t)(c.touching + 0.5);
        free_space(space);
    }
    qsort(runs, repeat, sizeof runs[0], cmp_double);
    res->ms_min = runs[0];
    res->ms_max = runs[repeat - 1];
    res->ms = (repeat & 1u) ? runs[repeat / 2] : 0.5 * (runs[repeat / 2 - 1] + runs[repeat / 2]);
    res->sps = res->ms > 0.0 ? 1000.0 / res->ms : 0.0;
    return 1;
}

/* ---- output ------------------------------------------------------------------------------ */
static void print_json(const result *r, const char *variant)
{
    printf("{\"engine\":\"chipmunk-%d.%d.%d\",\"variant\":\"%s\",\"scene\":\"%s\",\"count\":%u,\"bodies\":%u,\"steps\":%u,"
           "\"warmup\":0,\"repeat\":%u,\"iterations\":%d,\"broadphase\":\"%s\",\"hash_dim_m\":%.3f,\"sleeping\":%s,"
           "\"collision_slop_m\":%.3f,\"ms_per_step\":%.6f,\"ms_min\":%.6f,\"ms_max\":%.6f,\"steps_per_second\":%.2f,",
           CP_VERSION_MAJOR, CP_VERSION_MINOR, CP_VERSION_RELEASE, variant, r->scene, r->count, r->bodies, r->steps,
           r->repeat, r->s.iterations, r->s.hash_dim > 0.0 ? "spatial-hash" : "bbtree", r->s.hash_dim,
           r->s.sleep ? "true" : "false", r->s.slop, r->ms, r->ms_min, r->ms_max, r->sps);
    if (r->stands)
        printf("\"top_displacement_m\":%.6f,\"dx_m\":%.6f,\"dy_m\":%.6f,\"angle_deg\":%.4f,", r->disp, r->dx, r->dy,
               r->angle_deg);
    if (r->figure != NULL)
        printf("\"joints\":%u,\"%s_m\":%.6f,\"worst_gap_m\":%.6f,", r->joints, r->figure, r->figure_m, r->worst_gap_m);
    printf("\"awake_bodies\":%u,\"touching\":%u}\n", r->awake, r->touching);
    fflush(stdout);
}

static void print_header(void)
{
    printf("| engine | variant | scene | count | bodies | steps | iterations | broadphase | sleeping | ms/step | steps/s | "
           "top disp m | dx m | dy m | angle deg | awake at end |\n");
    printf("| --- | --- | --- | ---: | ---: | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
}

static void print_row(const result *r, const char *variant)
{
    printf("| chipmunk-%d.%d.%d | %s | %s | %u | %u | %u | %d | %s | %s | %.4f | %.1f | ", CP_VERSION_MAJOR,
           CP_VERSION_MINOR, CP_VERSION_RELEASE, variant, r->scene, r->count, r->bodies, r->steps, r->s.iterations,
           r->s.hash_dim > 0.0 ? "spatial hash" : "bbtree", r->s.sleep ? "on" : "off", r->ms, r->sps);
    if (r->stands)
        printf("%.5f | %+.5f | %+.5f | %+.3f | ", r->disp, r->dx, r->dy, r->angle_deg);
    else if (r->figure != NULL)
        printf("%s %.5f m, worst gap %.5f m | - | - | - | ", r->figure, r->figure_m, r->worst_gap_m);
    else
        printf("- | - | - | - | ");
    printf("%u |\n", r->awake);
    fflush(stdout);
}

static int parse_u32(const char *text, uint32_t *out)
{
    char *end;
    unsigned long v;
    if (text == NULL || *text < '0' || *text > '9') return 0;
    errno = 0;
    v = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || v == 0 || v > 0xFFFFFFFFul) return 0;
    *out = (uint32_t)v;
    return 1;
}

static int parse_double(const char *text, double *out)
{
    char *end;
    if (text == NULL) return 0;
    errno = 0;
    *out = strtod(text, &end);
    return errno == 0 && end != text && *end == '\0' && *out >= 0.0;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: pogon-bench-chipmunk pyramid|stack|rain|joint_grid|chain|all [--count N] [--steps N] [--repeat R] [--json]\n"
               "         [--variant defaults|best] [--sleep|--no-sleep] [--iterations N] [--hash DIM|--tree] [--slop M]\n");
}

int main(int argc, char **argv)
{
    static const struct { const char *scene; uint32_t count; } all[] = {
        {"pyramid", 20u}, {"stack", 20u}, {"rain", 1000u}, {"rain", 2000u}, {"rain", 4000u}, {"rain", 8000u}, {"rain", 16000u},
        {"joint_grid", 40u}, {"chain", 20u}};
    options o;
    const char *mode = NULL;
    size_t k;
    int i;
    memset(&o, 0, sizeof o);
    o.variant = "defaults";
    o.sleep = -1;
    o.hash_dim = -1.0;
    o.slop = -1.0;
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--json") == 0) {
            o.json = 1;
        } else if (strcmp(a, "--no-sleep") == 0) {
            o.sleep = 0;
        } else if (strcmp(a, "--sleep") == 0) {
            o.sleep = 1;
        } else if (strcmp(a, "--tree") == 0) {
            o.hash_dim = 0.0;
        } else if (strcmp(a, "--variant") == 0) {
            if (i + 1 >= argc || (strcmp(argv[i + 1], "defaults") != 0 && strcmp(argv[i + 1], "best") != 0)) {
                fprintf(stderr, "pogon-bench-chipmunk: --variant takes defaults or best\n");
                return 2;
            }
            o.variant = argv[++i];
        } else if (strcmp(a, "--hash") == 0 || strcmp(a, "--slop") == 0) {
            double v;
            if (i + 1 >= argc || !parse_double(argv[i + 1], &v) || (a[2] == 'h' && v <= 0.0)) {
                fprintf(stderr, "pogon-bench-chipmunk: %s needs a positive number\n", a);
                return 2;
            }
            if (a[2] == 'h') o.hash_dim = v; else o.slop = v;
            ++i;
        } else if (strcmp(a, "--count") == 0 || strcmp(a, "--steps") == 0 || strcmp(a, "--repeat") == 0 ||
                   strcmp(a, "--iterations") == 0) {
            uint32_t v;
            if (i + 1 >= argc || !parse_u32(argv[i + 1], &v)) {
                fprintf(stderr, "pogon-bench-chipmunk: %s needs a positive integer\n", a);
                return 2;
            }
            if (a[2] == 'c') o.count = v;
            else if (a[2] == 's') o.steps = v;
            else if (a[2] == 'r') o.repeat = v;
            else o.iterations = v > 10000u ? 10000 : (int)v;
            ++i;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        } else if (a[0] != '-' && mode == NULL) {
            mode = a;
        } else {
            usage(stderr);
            return 2;
        }
    }
    if (mode == NULL) {
        usage(stderr);
        return 2;
    }
    if (!o.json) print_header();
    for (k = 0; k < sizeof all / sizeof all[0]; ++k) {
        result r;
        int is_all = strcmp(mode, "all") == 0;
        if (!is_all && strcmp(mode, all[k].scene) != 0) continue;
        if (!run(all[k].scene, &o, is_all ? all[k].count : 0u, &r)) {
            fprintf(stderr, "pogon-bench-chipmunk: could not build %s\n", all[k].scene);
            return 1;
        }
        if (o.json) print_json(&r, o.variant); else print_row(&r, o.variant);
        if (!is_all) return 0;
    }
    if (strcmp(mode, "all") != 0) {
        fprintf(stderr, "pogon-bench-chipmunk: unknown scene %s\n", mode);
        usage(stderr);
        return 2;
    }
    return 0;
}
