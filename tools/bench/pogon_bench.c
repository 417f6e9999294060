/* pogon-bench — how long does a step of a whole world take?
 *
 * Usage:
 *   pogon-bench SCENE [--count N] [--steps N] [--repeat R] [--json] [--no-sleep]
 *       SCENE is pyramid (count = rows, default 20: 210 boxes), stack (count = boxes,
 *       default 20), rain (count = circles, default 1000), joint_grid (count = columns
 *       and rows, default 40: 1 560 bodies, 3 081 revolute joints) or chain (count =
 *       chains of 40 capsule links, default 20); tools/scenes/joint_scenes.h defines the
 *       last two. The joint scenes always run with sleeping off and report a sanity
 *       figure: the grid's sag and the chains' stretch.
 *   pogon-bench all       pyramid, stack, rain at 1000, 2000, 4000, 8000, 16000, then the
 *                         rain scaling table and the fitted exponent of ms ~ N^k.
 *   pogon-bench effects [SCENE]
 *                         the scene (default: pyramid and rain 4000) with every effect on,
 *                         then with each PG_EFFECT_* off in turn, and a settled scene
 *                         (steps 600..1200) with sleeping on and off.
 *   pogon-bench memory    bytes pg_world_memory_size asks for, per scene.
 *   pogon-bench snapshot  snapshot size of the settled pyramid and stack and of rain 1000
 *                         after 300 steps, and the median time of a save and a restore.
 *   pogon-bench compare   pogon next to Box2D 2.4.1 (the pogon-bench-box2d harness, run
 *                         as a subprocess when it was built next to this program) for
 *                         pyramid and rain 1000, with sleeping on and with it off.
 *   --no-sleep            PG_EFFECT_SLEEPING off (in Box2D: SetAllowSleeping(false)).
 *   --warmup-runs K       K whole untimed runs before the timed ones (default 0). For the
 *                         wasm build under node: V8 compiles wasm in tiers while it runs,
 *                         so the first runs of a short scene measure the compiler, not the
 *                         code.
 *   --warmup-seconds S    untimed runs go on until S seconds (0 to 60) have passed as well
 *                         (default 0). V8 compiles a large function in the background, on
 *                         the other core, and until that is done the runs are slow or share
 *                         the core with the compiler: a time, not a count of runs, says when
 *                         a scene is warm whatever it costs (tools/bench/peers gives node's
 *                         engines 2 runs and 1 s). The JSON's warmup_runs is how many ran.
 *   --substeps N, --contact-hertz HZ, --damping-ratio Z
 *                         world settings instead of the defaults (4, 30, 10; decimals are
 *                         read exactly as Q16.16), to see what a setting costs and whether
 *                         the scene still stands; pg_world_create's checks apply.
 *
 * Method: a run builds the scene (the shared tools/scenes code, memory from malloc),
 * takes `warmup` untimed steps (0 unless stated), then times `steps` steps with
 * clock_gettime(CLOCK_MONOTONIC) around the stepping only; a run's figure is its mean ms
 * per step and the reported figure is the median over `repeat` runs (default 3). Steps
 * default to 600 (pyramid, stack, joint_grid, chain) and 300 (rain).
 *
 * For the scenes that should stand (pyramid, stack) the top box's displacement from
 * where it started is reported: distance, dx, dy and its angle in degrees, and, with
 * sleeping on, the step after which every body was asleep ("asleep_step", 0: not within
 * the run), found by one more untimed run that reads the stats after every step. The world is
 * built and stepped in integers only; double is used for timing and for printing.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "joint_scenes.h"
#include "scenes.h"

#define DEFAULT_REPEAT 3u
#define SETTLE_STEPS 600u
#define MAX_REPEAT 101u

typedef struct options {
    uint32_t count;   /* 0: the scene's default */
    uint32_t steps;   /* 0: the scene's default */
    uint32_t repeat;
    int json;
    int no_sleep;     /* --no-sleep: PG_EFFECT_SLEEPING off */
} options;

/* World settings from the command line; 0: the scene's default. */
typedef struct settings {
    uint32_t substeps;
    pg_fix contact_hertz, damping_ratio;
} settings;

typedef struct result {
    const char *scene;
    const char *label;      /* effects mode: the row's name */
    uint32_t count, bodies, steps, warmup, repeat, effects;
    uint32_t warmup_runs;   /* untimed whole runs made (--warmup-runs, --warmup-seconds) */
    double ms_per_step, steps_per_second, ms_min, ms_max;
    int stands;             /* pyramid and stack: top displacement is meaningful */
    double top_disp, dx, dy, angle_deg;
    uint32_t awake_end, contacts_end, touching_end, capacity_misses, speed_clamps;
    uint32_t asleep_step;   /* stands, sleeping on: first step after which nothing was awake */
    uint32_t joints;        /* joint scenes: how many joints */
    pg_joint_sanity sanity; /* joint scenes: sag or stretch at the end (figure NULL otherwise) */
    uint32_t substeps;      /* the solver settings the run used */
    pg_fix contact_hertz, damping_ratio;
    size_t memory_bytes;
} result;

/* ---- helpers ------------------------------------------------------------------------- */
static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static double fix_to_double(int64_t q16) { return (double)q16 / 65536.0; }

/* A binary angle as signed degrees in [-180, 180). */
static double angle_to_degrees(pg_angle a)
{
    double t = (double)a;
    if (a >= 0x80000000u) t -= 4294967296.0;
    return t * (360.0 / 4294967296.0);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

static int is_scene(const char *s)
{
    return strcmp(s, "pyramid") == 0 || strcmp(s, "stack") == 0 || strcmp(s, "rain") == 0 || pg_is_joint_scene(s);
}

static uint32_t default_count(const char *scene)
{
    if (pg_is_joint_scene(scene)) return pg_joint_scene_default_count(scene);
    return strcmp(scene, "rain") == 0 ? 1000u : 20u;
}
static uint32_t default_steps(const char *scene) { return strcmp(scene, "rain") == 0 ? 300u : 600u; }
static int scene_stands(const char *scene) { return strcmp(scene, "rain") != 0 && !pg_is_joint_scene(scene); }

/* dynamic bodies */
static uint32_t scene_bodies(const char *scene, uint32_t count)
{
    if (strcmp(scene, "pyramid") == 0) return count * (count + 1u) / 2u;
    if (strcmp(scene, "joint_grid") == 0) return count * (count - 1u);
    if (strcmp(scene, "chain") == 0) return count * 40u;
    return count;
}

/* A built scene of either kind: the world, and for the standing scenes the top body. */
typedef struct built_scene {
    pg_scene plain;
    pg_joint_scene joints;
    int is_joint;
} built_scene;

static pg_world_def any_world_def(const char *scene, uint32_t count)
{
    return pg_is_joint_scene(scene) ? pg_joint_scene_world_def(scene, count) : pg_scene_world_def(scene, count);
}

static size_t any_memory_size(const char *scene, uint32_t count, const pg_world_def *def)
{
    return pg_is_joint_scene(scene) ? pg_joint_scene_memory_size(scene, count, def) : pg_scene_memory_size(scene, count, def);
}

static pg_result any_build(const char *scene, uint32_t count, const pg_world_def *def, void *memory, size_t size,
                           built_scene *out)
{
    memset(out, 0, sizeof *out);
    out->is_joint = pg_is_joint_scene(scene);
    if (out->is_joint) return pg_joint_scene_build(scene, count, def, memory, size, &out->joints);
    return pg_scene_build(scene, count, def, memory, size, &out->plain);
}

static pg_world *any_world(const built_scene *b) { return b->is_joint ? b->joints.world : b->plain.world; }

static int parse_u32(const char *text, uint32_t *out)
{
    char *end;
    unsigned long v;
    if (text == NULL || *text < '0' || *text > '9') return 0;
    errno = 0;
    v = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || v > 0xFFFFFFFFul) return 0;
    *out = (uint32_t)v;
    return 1;
}

/* ---- one measurement ------------------------------------------------------------------ */
static uint32_t g_warmup_runs; /* --warmup-runs: whole runs before the timed ones */
static uint32_t g_warmup_s;    /* --warmup-seconds: and until this much time has passed */
static settings g_settings;    /* --substeps, --contact-hertz, --damping-ratio */

/* The step (1-based) after which no body was awake, 0 if none within `steps`: an extra
 * run, because reading the stats every step would disturb the timing. */
static uint32_t find_asleep_step(const char *scene, uint32_t count, uint32_t steps, const pg_world_def *def, size_t size)
{
    pg_scene sc;
    uint32_t i, found = 0;
    void *memory = malloc(size);
    if (memory == NULL) return 0;
    if (!pg_is_joint_scene(scene) && pg_scene_build(scene, count, def, memory, size, &sc) == PG_OK) {
        for (i = 1; i <= steps && found == 0; ++i) {
            if (pg_world_step(sc.world) != PG_OK) break;
            if (pg_world_get_stats(sc.world).awake_body_count == 0) found = i;
        }
    }
    free(memory);
    return found;
}

/* Build `scene` `repeat` times with `effects`, step `warmup` untimed then `steps` timed.
 * Returns 0 on success; prints the failure otherwise. */
static int run_bench(const char *scene, uint32_t count, uint32_t steps, uint32_t warmup, uint32_t repeat,
                     uint32_t effects, result *res)
{
    double runs[MAX_REPEAT];
    pg_world_def def;
    size_t size;
    uint32_t r = 0, i, warm = 0;
    double warm_start;
    if (count == 0) count = default_count(scene);
    if (steps == 0) steps = default_steps(scene);
    if (repeat == 0) repeat = DEFAULT_REPEAT;
    if (repeat > MAX_REPEAT) repeat = MAX_REPEAT;
    memset(res, 0, sizeof *res);
    res->scene = scene;
    res->count = count;
    res->bodies = scene_bodies(scene, count);
    res->steps = steps;
    res->warmup = warmup;
    res->repeat = repeat;
    res->stands = scene_stands(scene);
    /* the joint scenes time awake joints: sleeping is always off in them */
    if (pg_is_joint_scene(scene)) effects &= ~PG_EFFECT_SLEEPING;
    res->effects = effects;
    def = any_world_def(scene, count);
    def.effects = effects;
    if (g_settings.substeps != 0) def.substeps = g_settings.substeps;
    if (g_settings.contact_hertz != 0) def.contact_hertz = g_settings.contact_hertz;
    if (g_settings.damping_ratio != 0) def.contact_damping_ratio = g_settings.damping_ratio;
    res->substeps = def.substeps;
    res->contact_hertz = def.contact_hertz;
    res->damping_ratio = def.contact_damping_ratio;
    size = any_memory_size(scene, count, &def);
    res->memory_bytes = size;
    if (size == 0) {
        const char *why = pg_world_def_problem(&def);
        fprintf(stderr, "pogon-bench: %s %u: invalid world settings: %s\n", scene, count, why != NULL ? why : "too large");
        return 1;
    }
    warm_start = now_ms();
    while (r < repeat) {
        /* untimed until both the runs and the time of the warm-up are done */
        int warming = warm < g_warmup_runs || now_ms() - warm_start < 1000.0 * (double)g_warmup_s;
        built_scene built;
        pg_world *world;
        pg_result pr;
        pg_world_stats st;
        double t0, t1;
        void *memory = malloc(size); /* malloc's alignment is at least 8 */
        if (memory == NULL) {
            fprintf(stderr, "pogon-bench: %s %u: out of memory (%zu bytes)\n", scene, count, size);
            return 1;
        }
        pr = any_build(scene, count, &def, memory, size, &built);
        world = any_world(&built);
        if (pr != PG_OK) {
            fprintf(stderr, "pogon-bench: building %s %u failed: %s (%s)\n", scene, count, pg_result_name(pr),
                    world != NULL ? pg_world_last_error(world) : pg_result_message(pr));
            free(memory);
            return 1;
        }
        for (i = 0; i < warmup; ++i) {
            pr = pg_world_step(world);
            if (pr != PG_OK) break;
        }
        t0 = now_ms();
        for (i = 0; pr == PG_OK && i < steps; ++i) pr = pg_world_step(world);
        t1 = now_ms();
        if (pr != PG_OK) {
            fprintf(stderr, "pogon-bench: %s %u: pg_world_step failed: %s (%s)\n", scene, count, pg_result_name(pr),
                    pg_world_last_error(world));
            free(memory);
            return 1;
        }
        if (warming) {
            ++warm;
            free(memory);
            continue;
        }
        runs[r++] = (t1 - t0) / (double)steps;
        /* every run is bit-identical, so the last one's state is the state */
        if (built.is_joint) {
            res->joints = built.joints.joint_count;
            pg_joint_scene_sanity(scene, count, &built.joints, &res->sanity);
        } else {
            const pg_scene *sc = &built.plain;
            pg_vec2 p = pg_body_position(world, sc->top);
            int64_t dx = (int64_t)p.x - sc->top_start.x, dy = (int64_t)p.y - sc->top_start.y;
            res->dx = fix_to_double(dx);
            res->dy = fix_to_double(dy);
            res->top_disp = sqrt(res->dx * res->dx + res->dy * res->dy);
            res->angle_deg = angle_to_degrees(pg_body_angle(world, sc->top));
        }
        st = pg_world_get_stats(world);
        res->awake_end = st.awake_body_count;
        res->contacts_end = st.contact_count;
        res->touching_end = st.touching_contact_count;
        res->capacity_misses = st.capacity_misses;
        res->speed_clamps = st.speed_clamps;
        free(memory);
    }
    res->warmup_runs = warm;
    if (res->stands && (effects & PG_EFFECT_SLEEPING) != 0) res->asleep_step = find_asleep_step(scene, count, steps, &def, size);
    qsort(runs, repeat, sizeof runs[0], cmp_double);
    res->ms_min = runs[0];
    res->ms_max = runs[repeat - 1];
    res->ms_per_step = (repeat & 1u) ? runs[repeat / 2] : 0.5 * (runs[repeat / 2 - 1] + runs[repeat / 2]);
    res->steps_per_second = res->ms_per_step > 0.0 ? 1000.0 / res->ms_per_step : 0.0;
    return 0;
}

/* ---- output --------------------------------------------------------------------------- */
static void print_json(const result *r)
{
    printf("{\"engine\":\"pogon\",\"scene\":\"%s\",\"count\":%u,\"bodies\":%u,\"steps\":%u,\"warmup\":%u,\"warmup_runs\":%u,"
           "\"warmup_seconds\":%u,\"repeat\":%u,\"effects\":%u,\"trig_table_bits\":%d,",
           r->scene, r->count, r->bodies, r->steps, r->warmup, r->warmup_runs, g_warmup_s, r->repeat, r->effects, PG_TRIG_TABLE_BITS);
    {
        char hz[PG_FIX_FORMAT_MAX], zeta[PG_FIX_FORMAT_MAX];
        pg_fix_format(r->contact_hertz, hz, sizeof hz);
        pg_fix_format(r->damping_ratio, zeta, sizeof zeta);
        printf("\"substeps\":%u,\"contact_hertz\":%s,\"damping_ratio\":%s,", r->substeps, hz, zeta);
    }
    if (r->label != NULL) printf("\"variant\":\"%s\",", r->label);
    printf("\"ms_per_step\":%.6f,\"ms_min\":%.6f,\"ms_max\":%.6f,\"steps_per_second\":%.2f,", r->ms_per_step, r->ms_min,
           r->ms_max, r->steps_per_second);
    if (r->stands)
        printf("\"top_displacement_m\":%.6f,\"dx_m\":%.6f,\"dy_m\":%.6f,\"angle_deg\":%.4f,\"asleep_step\":%u,", r->top_disp,
               r->dx, r->dy, r->angle_deg, r->asleep_step);
    if (r->sanity.figure != NULL)
        printf("\"joints\":%u,\"%s_m\":%.6f,\"worst_gap_m\":%.6f,", r->joints, r->sanity.figure, r->sanity.value_m,
               r->sanity.worst_gap_m);
    printf("\"awake_bodies\":%u,\"contacts\":%u,\"touching\":%u,\"capacity_misses\":%u,\"speed_clamps\":%u,"
           "\"memory_bytes\":%zu}\n", r->awake_end, r->contacts_end, r->touching_end, r->capacity_misses, r->speed_clamps,
           r->memory_bytes);
    fflush(stdout);
}

static void print_table_header(void)
{
    printf("| scene | count | bodies | steps | ms/step | steps/s | top disp m | dx m | dy m | angle deg | asleep after step | awake at end | touching | capacity misses |\n");
    printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
}

static void print_table_row(const result *r)
{
    printf("| %s | %u | %u | %u | %.4f | %.1f | ", r->scene, r->count, r->bodies, r->steps, r->ms_per_step,
           r->steps_per_second);
    if (r->stands && r->asleep_step != 0)
        printf("%.5f | %+.5f | %+.5f | %+.3f | %u | ", r->top_disp, r->dx, r->dy, r->angle_deg, r->asleep_step);
    else if (r->stands)
        printf("%.5f | %+.5f | %+.5f | %+.3f | - | ", r->top_disp, r->dx, r->dy, r->angle_deg);
    else
        printf("- | - | - | - | - | ");
    printf("%u | %u | %u |\n", r->awake_end, r->touching_end, r->capacity_misses);
    fflush(stdout);
}

/* ---- modes ------------------------------------------------------------------------------ */
static uint32_t base_effects(const options *o)
{
    return o->no_sleep ? PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING : PG_EFFECTS_ALL;
}

static int mode_scene(const char *scene, const options *o)
{
    result r;
    if (run_bench(scene, o->count, o->steps, 0, o->repeat, base_effects(o), &r) != 0) return 1;
    if (o->json) {
        print_json(&r);
    } else if (r.sanity.figure != NULL) {
        printf("| scene | count | bodies | joints | steps | ms/step | steps/s | %s m | worst joint gap m |\n", r.sanity.figure);
        printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
        printf("| %s | %u | %u | %u | %u | %.4f | %.1f | %.5f | %.5f |\n", r.scene, r.count, r.bodies, r.joints, r.steps,
               r.ms_per_step, r.steps_per_second, r.sanity.value_m, r.sanity.worst_gap_m);
    } else {
        print_table_header();
        print_table_row(&r);
    }
    return 0;
}

static const uint32_t rain_counts[] = {1000u, 2000u, 4000u, 8000u, 16000u};
#define RAIN_N (sizeof rain_counts / sizeof rain_counts[0])

static int mode_all(const options *o)
{
    result r, rain[RAIN_N];
    size_t i;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, k;
    if (!o->json) print_table_header();
    if (run_bench("pyramid", 0, o->steps, 0, o->repeat, base_effects(o), &r) != 0) return 1;
    if (o->json) print_json(&r); else print_table_row(&r);
    if (run_bench("stack", 0, o->steps, 0, o->repeat, base_effects(o), &r) != 0) return 1;
    if (o->json) print_json(&r); else print_table_row(&r);
    for (i = 0; i < RAIN_N; ++i) {
        if (run_bench("rain", rain_counts[i], o->steps, 0, o->repeat, base_effects(o), &rain[i]) != 0) return 1;
        if (o->json) print_json(&rain[i]); else print_table_row(&rain[i]);
    }
    for (i = 0; i < RAIN_N; ++i) {
        double x = log((double)rain[i].count), y = log(rain[i].ms_per_step);
        sx += x; sy += y; sxx += x * x; sxy += x * y;
    }
    k = ((double)RAIN_N * sxy - sx * sy) / ((double)RAIN_N * sxx - sx * sx);
    if (o->json) {
        printf("{\"engine\":\"pogon\",\"fit\":\"rain\",\"counts\":[1000,2000,4000,8000,16000],\"exponent\":%.4f,\"target\":1.2,"
               "\"below_target\":%s}\n", k, k < 1.2 ? "true" : "false");
        return 0;
    }
    printf("\nRain scaling (ms per step against circle count N):\n\n");
    printf("| N | ms/step | us per body-step | step exponent vs previous N |\n");
    printf("| ---: | ---: | ---: | ---: |\n");
    for (i = 0; i < RAIN_N; ++i) {
        printf("| %u | %.4f | %.4f | ", rain[i].count, rain[i].ms_per_step, 1000.0 * rain[i].ms_per_step / rain[i].count);
        if (i == 0)
            printf("- |\n");
        else
            printf("%.3f |\n", log(rain[i].ms_per_step / rain[i - 1].ms_per_step) /
                                   log((double)rain[i].count / (double)rain[i - 1].count));
    }
    printf("\nLeast-squares fit of log(ms) against log(N): exponent k = %.3f (%s 1.2)\n", k,
           k < 1.2 ? "below the target" : "NOT below the target");
    return 0;
}

static const struct { uint32_t bit; const char *name; } effect_names[] = {
    {PG_EFFECT_GRAVITY, "gravity"},       {PG_EFFECT_ROTATION, "rotation"}, {PG_EFFECT_FRICTION, "friction"},
    {PG_EFFECT_RESTITUTION, "restitution"}, {PG_EFFECT_DAMPING, "damping"},   {PG_EFFECT_SLEEPING, "sleeping"},
    {PG_EFFECT_CONTINUOUS, "continuous"},
};
#define EFFECT_N (sizeof effect_names / sizeof effect_names[0])

static void print_effect_row(const result *r, double base)
{
    printf("| %s | 0x%02X | %u..%u | %.4f | %.2f | %u | ", r->label, r->effects, r->warmup, r->warmup + r->steps,
           r->ms_per_step, base > 0.0 ? r->ms_per_step / base : 0.0, r->awake_end);
    if (r->stands)
        printf("%.5f |\n", r->top_disp);
    else
        printf("- |\n");
    fflush(stdout);
}

static int effects_for(const char *scene, uint32_t count, const options *o)
{
    static char labels[EFFECT_N][32];
    result r;
    double base;
    size_t i;
    if (!o->json) {
        if (count == 0) count = default_count(scene);
        printf("\n%s, count %u (%u bodies), median of %u runs:\n\n", scene, count, scene_bodies(scene, count),
               o->repeat ? o->repeat : DEFAULT_REPEAT);
        printf("| effects | mask | steps | ms/step | vs all on | awake at end | top disp m |\n");
        printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    }
    if (run_bench(scene, count, o->steps, 0, o->repeat, PG_EFFECTS_ALL, &r) != 0) return 1;
    r.label = "all on";
    base = r.ms_per_step;
    if (o->json) print_json(&r); else print_effect_row(&r, base);
    for (i = 0; i < EFFECT_N; ++i) {
        if (run_bench(scene, count, o->steps, 0, o->repeat, PG_EFFECTS_ALL & ~effect_names[i].bit, &r) != 0) return 1;
        snprintf(labels[i], sizeof labels[i], "%s off", effect_names[i].name);
        r.label = labels[i];
        if (o->json) print_json(&r); else print_effect_row(&r, base);
    }
    if (run_bench(scene, count, SETTLE_STEPS, SETTLE_STEPS, o->repeat, PG_EFFECTS_ALL, &r) != 0) return 1;
    r.label = "sleeping on, settled";
    if (o->json) print_json(&r); else print_effect_row(&r, base);
    if (run_bench(scene, count, SETTLE_STEPS, SETTLE_STEPS, o->repeat, PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING, &r) != 0) return 1;
    r.label = "sleeping off, settled";
    if (o->json) print_json(&r); else print_effect_row(&r, base);
    return 0;
}

static int mode_effects(const char *scene, const options *o)
{
    if (scene != NULL) return effects_for(scene, o->count, o);
    if (effects_for("pyramid", 0, o) != 0) return 1;
    return effects_for("rain", 4000u, o);
}

static int mode_memory(const options *o)
{
    static const struct { const char *scene; uint32_t count; } list[] = {
        {"pyramid", 20u}, {"stack", 20u}, {"rain", 1000u}, {"rain", 2000u}, {"rain", 4000u}, {"rain", 8000u}, {"rain", 16000u},
    };
    size_t i;
    if (!o->json) {
        printf("| scene | count | bodies | max_bodies | max_shapes | max_contacts | bytes | KiB | bytes per body slot |\n");
        printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    }
    for (i = 0; i < sizeof list / sizeof list[0]; ++i) {
        pg_world_def d = pg_scene_world_def(list[i].scene, list[i].count);
        size_t bytes = pg_world_memory_size(&d);
        if (o->json)
            printf("{\"engine\":\"pogon\",\"scene\":\"%s\",\"count\":%u,\"bodies\":%u,\"max_bodies\":%u,\"max_shapes\":%u,"
                   "\"max_contacts\":%u,\"memory_bytes\":%zu}\n",
                   list[i].scene, list[i].count, scene_bodies(list[i].scene, list[i].count), d.max_bodies, d.max_shapes,
                   d.max_contacts, bytes);
        else
            printf("| %s | %u | %u | %u | %u | %u | %zu | %.1f | %.0f |\n", list[i].scene, list[i].count,
                   scene_bodies(list[i].scene, list[i].count), d.max_bodies, d.max_shapes, d.max_contacts, bytes,
                   (double)bytes / 1024.0, d.max_bodies ? (double)bytes / d.max_bodies : 0.0);
    }
    {
        pg_world_def d = pg_default_world_def();
        size_t bytes = pg_world_memory_size(&d);
        if (o->json)
            printf("{\"engine\":\"pogon\",\"scene\":\"default_world_def\",\"max_bodies\":%u,\"max_shapes\":%u,"
                   "\"max_contacts\":%u,\"memory_bytes\":%zu}\n", d.max_bodies, d.max_shapes, d.max_contacts, bytes);
        else
            printf("| (pg_default_world_def) | - | - | %u | %u | %u | %zu | %.1f | %.0f |\n", d.max_bodies, d.max_shapes,
                   d.max_contacts, bytes, (double)bytes / 1024.0, d.max_bodies ? (double)bytes / d.max_bodies : 0.0);
    }
    return 0;
}

/* ---- snapshot: size and save/restore time -------------------------------------------- */
/* The settled pyramid (asleep), the 20-box stack (asleep) and rain 1 000 after its 300
 * steps (awake, falling onto the pile): the snapshot's bytes, in all and over the bodies
 * (shapes and contacts included; test_snapshot splits it by section), and the median
 * time of 101 saves and of 101 restores. */
static int mode_snapshot(const options *o)
{
    static const struct { const char *scene; uint32_t count, steps; } list[] = {
        {"pyramid", 20u, 1200u}, {"stack", 20u, 1200u}, {"rain", 1000u, 300u},
    };
    enum { RUNS = 101 };
    size_t i;
    if (!o->json) {
        printf("| scene | steps | awake | bodies | shapes | contacts | snapshot bytes | bytes per body | save us | restore us | restore ns per body |\n");
        printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    }
    for (i = 0; i < sizeof list / sizeof list[0]; ++i) {
        pg_world_def def = pg_scene_world_def(list[i].scene, list[i].count);
        size_t size = pg_scene_memory_size(list[i].scene, list[i].count, &def), snap_size, written = 0;
        void *memory = malloc(size);
        unsigned char *buf;
        pg_scene sc;
        pg_world_stats st;
        double save_t[RUNS], restore_t[RUNS];
        uint32_t k, steps = 0;
        int r;
        if (memory == NULL || pg_scene_build(list[i].scene, list[i].count, &def, memory, size, &sc) != PG_OK) {
            fprintf(stderr, "pogon-bench: building %s failed\n", list[i].scene);
            free(memory);
            return 1;
        }
        /* the standing scenes until they sleep (or the step budget), rain for its run */
        for (steps = 0; steps < list[i].steps; ++steps) {
            if (strcmp(list[i].scene, "rain") != 0 && pg_world_get_stats(sc.world).awake_body_count == 0) break;
            if (pg_world_step(sc.world) != PG_OK) break;
        }
        st = pg_world_get_stats(sc.world);
        snap_size = pg_world_snapshot_size(sc.world);
        buf = (unsigned char *)malloc(snap_size > 0 ? snap_size : 1u);
        if (buf == NULL) {
            free(memory);
            return 1;
        }
        for (r = 0; r < RUNS; ++r) {
            double t0 = now_ms(), t1;
            if (pg_world_snapshot_save(sc.world, buf, snap_size, &written) != PG_OK) break;
            t1 = now_ms();
            save_t[r] = (t1 - t0) * 1000.0;
            t0 = now_ms();
            if (pg_world_snapshot_restore(sc.world, buf, written) != PG_OK) {
                fprintf(stderr, "pogon-bench: %s: restore failed: %s\n", list[i].scene, pg_world_last_error(sc.world));
                free(buf);
                free(memory);
                return 1;
            }
            t1 = now_ms();
            restore_t[r] = (t1 - t0) * 1000.0;
        }
        qsort(save_t, RUNS, sizeof save_t[0], cmp_double);
        qsort(restore_t, RUNS, sizeof restore_t[0], cmp_double);
        k = RUNS / 2;
        if (o->json)
            printf("{\"engine\":\"pogon\",\"mode\":\"snapshot\",\"scene\":\"%s\",\"count\":%u,\"steps\":%u,\"awake\":%u,"
                   "\"bodies\":%u,\"shapes\":%u,\"contacts\":%u,\"snapshot_bytes\":%zu,\"save_us\":%.2f,\"restore_us\":%.2f}\n",
                   list[i].scene, list[i].count, steps, st.awake_body_count, st.body_count, st.shape_count, st.contact_count, written,
                   save_t[k], restore_t[k]);
        else
            printf("| %s %u | %u | %u | %u | %u | %u | %zu | %.1f | %.1f | %.1f | %.0f |\n", list[i].scene, list[i].count, steps,
                   st.awake_body_count, st.body_count, st.shape_count, st.contact_count, written,
                   st.body_count ? (double)written / st.body_count : 0.0, save_t[k], restore_t[k],
                   st.body_count ? restore_t[k] * 1000.0 / st.body_count : 0.0);
        free(buf);
        free(memory);
    }
    if (!o->json)
        printf("\nbytes per body counts the whole snapshot (shapes and contacts included) over the bodies; "
               "test_snapshot prints the bodies section alone (63 bytes per resting box).\n");
    return 0;
}

/* ---- compare: run the Box2D harness as a subprocess ---------------------------------- */
/* The directory this program lives in, with a trailing '/', or "" when unknown. */
static void self_dir(const char *argv0, char *out, size_t size)
{
    char path[4096];
    ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    char *slash;
    if (n > 0) {
        path[n] = '\0';
    } else if (argv0 != NULL && strchr(argv0, '/') != NULL && strlen(argv0) < sizeof path) {
        strcpy(path, argv0);
    } else {
        out[0] = '\0';
        return;
    }
    slash = strrchr(path, '/');
    slash[1] = '\0';
    snprintf(out, size, "%s", path);
}

static int json_number(const char *line, const char *key, double *out)
{
    char pattern[64];
    const char *p;
    snprintf(pattern, sizeof pattern, "\"%s\":", key);
    p = strstr(line, pattern);
    if (p == NULL) return 0;
    *out = strtod(p + strlen(pattern), NULL);
    return 1;
}

typedef struct peer_result { int ok; double ms, sps, disp, dx, dy, angle; int has_disp; } peer_result;

static peer_result run_peer(const char *exe, const char *scene, uint32_t count, uint32_t steps, uint32_t repeat, int no_sleep)
{
    char cmd[4600], line[2048];
    peer_result pr;
    FILE *f;
    memset(&pr, 0, sizeof pr);
    snprintf(cmd, sizeof cmd, "'%s' %s --count %u --steps %u --repeat %u --json%s", exe, scene, count, steps, repeat,
             no_sleep ? " --no-sleep" : "");
    f = popen(cmd, "r");
    if (f == NULL) return pr;
    while (fgets(line, sizeof line, f) != NULL) {
        char want[64];
        snprintf(want, sizeof want, "\"scene\":\"%s\"", scene);
        if (strstr(line, want) == NULL) continue;
        pr.ok = json_number(line, "ms_per_step", &pr.ms) && json_number(line, "steps_per_second", &pr.sps);
        pr.has_disp = json_number(line, "top_displacement_m", &pr.disp);
        json_number(line, "dx_m", &pr.dx);
        json_number(line, "dy_m", &pr.dy);
        json_number(line, "angle_deg", &pr.angle);
    }
    if (pclose(f) != 0) pr.ok = 0;
    return pr;
}

static int mode_compare(const char *argv0, const options *o)
{
    /* pogon's pyramid falls asleep within its first second, so a row with sleeping off in
     * both engines measures the solver on the whole scene */
    static const struct { const char *scene; uint32_t count; int no_sleep; } list[] = {
        {"pyramid", 20u, 0}, {"pyramid", 20u, 1}, {"rain", 1000u, 0}, {"rain", 1000u, 1}};
    char dir[4096], exe[4200];
    int have_peer;
    size_t i;
    self_dir(argv0, dir, sizeof dir);
    snprintf(exe, sizeof exe, "%spogon-bench-box2d", dir);
    have_peer = access(exe, X_OK) == 0 && strchr(exe, '\'') == NULL;
    if (!have_peer)
        fprintf(stderr, "pogon-bench: %s not found (Box2D harness not built): pogon only\n", exe);
    if (!o->json) {
        printf("| scene | count | steps | pogon ms/step | box2d ms/step | pogon / box2d | pogon steps/s | box2d steps/s | "
               "pogon top disp m | box2d top disp m |\n");
        printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    }
    for (i = 0; i < sizeof list / sizeof list[0]; ++i) {
        result r;
        peer_result p;
        uint32_t repeat = o->repeat ? o->repeat : DEFAULT_REPEAT;
        int no_sleep = list[i].no_sleep || o->no_sleep;
        if (run_bench(list[i].scene, list[i].count, o->steps, 0, repeat,
                      no_sleep ? PG_EFFECTS_ALL & ~PG_EFFECT_SLEEPING : PG_EFFECTS_ALL, &r) != 0) return 1;
        if (no_sleep) r.label = "sleeping off";
        memset(&p, 0, sizeof p);
        if (have_peer) {
            p = run_peer(exe, list[i].scene, list[i].count, r.steps, repeat, no_sleep);
            if (!p.ok) fprintf(stderr, "pogon-bench: %s %s gave no result\n", exe, list[i].scene);
        }
        if (o->json) {
            print_json(&r);
            if (p.ok)
                printf("{\"compare\":\"%s\",\"count\":%u,\"steps\":%u,\"sleeping\":%s,\"pogon_ms_per_step\":%.6f,"
                       "\"box2d_ms_per_step\":%.6f,\"ratio\":%.4f}\n", r.scene, r.count, r.steps, no_sleep ? "false" : "true",
                       r.ms_per_step, p.ms,
                       p.ms > 0.0 ? r.ms_per_step / p.ms : 0.0);
            continue;
        }
        printf("| %s%s | %u | %u | %.4f | ", r.scene, no_sleep ? " (sleeping off)" : "", r.count, r.steps, r.ms_per_step);
        if (p.ok)
            printf("%.4f | %.2f | %.1f | %.1f | ", p.ms, p.ms > 0.0 ? r.ms_per_step / p.ms : 0.0, r.steps_per_second, p.sps);
        else
            printf("- | - | %.1f | - | ", r.steps_per_second);
        if (r.stands) {
            printf("%.5f (dx %+.4f dy %+.4f, %+.2f deg) | ", r.top_disp, r.dx, r.dy, r.angle_deg);
            if (p.ok && p.has_disp)
                printf("%.5f (dx %+.4f dy %+.4f, %+.2f deg) |\n", p.disp, p.dx, p.dy, p.angle);
            else
                printf("- |\n");
        } else {
            printf("- | - |\n");
        }
        fflush(stdout);
    }
    return 0;
}

/* ---- main ----------------------------------------------------------------------------- */
static void usage(FILE *f)
{
    fprintf(f,
            "usage: pogon-bench SCENE [--count N] [--steps N] [--repeat R] [--warmup-runs K] [--warmup-seconds S] [--json] [--no-sleep]\n"
            "                         [--substeps N] [--contact-hertz HZ] [--damping-ratio Z]\n"
            "       pogon-bench all | effects [SCENE] | memory | snapshot | compare   [options]\n"
            "scenes: pyramid (count = rows, default 20), stack (boxes, default 20), rain (circles, default 1000),\n"
            "        joint_grid (columns and rows, default 40), chain (chains of 40 links, default 20)\n"
            "steps default to 600 (pyramid, stack) and 300 (rain); repeat defaults to 3 (median reported)\n");
}

int main(int argc, char **argv)
{
    options o;
    const char *words[2] = {NULL, NULL};
    int nwords = 0, i;
    memset(&o, 0, sizeof o);
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--json") == 0) {
            o.json = 1;
        } else if (strcmp(a, "--no-sleep") == 0) {
            o.no_sleep = 1;
        } else if (strcmp(a, "--count") == 0 || strcmp(a, "--steps") == 0 || strcmp(a, "--repeat") == 0) {
            uint32_t v;
            if (i + 1 >= argc || !parse_u32(argv[i + 1], &v) || v == 0) {
                fprintf(stderr, "pogon-bench: %s needs a positive integer\n", a);
                return 2;
            }
            if (a[2] == 'c') o.count = v;
            else if (a[2] == 's') o.steps = v;
            else o.repeat = v > MAX_REPEAT ? MAX_REPEAT : v;
            ++i;
        } else if (strcmp(a, "--warmup-runs") == 0 || strcmp(a, "--warmup-seconds") == 0) {
            int runs = strcmp(a, "--warmup-runs") == 0;
            uint32_t v, most = runs ? 100u : 60u;
            if (i + 1 >= argc || !parse_u32(argv[i + 1], &v) || v > most) {
                fprintf(stderr, "pogon-bench: %s needs an integer from 0 to %u\n", a, most);
                return 2;
            }
            if (runs) g_warmup_runs = v;
            else g_warmup_s = v;
            ++i;
        } else if (strcmp(a, "--substeps") == 0) {
            uint32_t v;
            if (i + 1 >= argc || !parse_u32(argv[i + 1], &v) || v == 0) {
                fprintf(stderr, "pogon-bench: --substeps needs a positive integer\n");
                return 2;
            }
            g_settings.substeps = v;
            ++i;
        } else if (strcmp(a, "--contact-hertz") == 0 || strcmp(a, "--damping-ratio") == 0) {
            pg_fix v;
            if (i + 1 >= argc || pg_fix_parse(argv[i + 1], strlen(argv[i + 1]), &v) != PG_FIX_OK || v <= 0) {
                fprintf(stderr, "pogon-bench: %s needs a positive decimal number (e.g. 30 or 2.5)\n", a);
                return 2;
            }
            if (a[2] == 'c') g_settings.contact_hertz = v;
            else g_settings.damping_ratio = v;
            ++i;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        } else if (a[0] == '-') {
            fprintf(stderr, "pogon-bench: unknown option %s\n", a);
            usage(stderr);
            return 2;
        } else if (nwords < 2) {
            words[nwords++] = a;
        } else {
            fprintf(stderr, "pogon-bench: unexpected argument %s\n", a);
            return 2;
        }
    }
    if (nwords == 0) {
        usage(stderr);
        return 2;
    }
    if (is_scene(words[0]) && nwords == 1) return mode_scene(words[0], &o);
    if (strcmp(words[0], "all") == 0 && nwords == 1) return mode_all(&o);
    if (strcmp(words[0], "memory") == 0 && nwords == 1) return mode_memory(&o);
    if (strcmp(words[0], "snapshot") == 0 && nwords == 1) return mode_snapshot(&o);
    if (strcmp(words[0], "compare") == 0 && nwords == 1) return mode_compare(argv[0], &o);
    if (strcmp(words[0], "effects") == 0) {
        if (nwords == 2 && !is_scene(words[1])) {
            fprintf(stderr, "pogon-bench: unknown scene %s\n", words[1]);
            return 2;
        }
        return mode_effects(nwords == 2 ? words[1] : NULL, &o);
    }
    fprintf(stderr, "pogon-bench: unknown scene or mode %s\n", words[0]);
    usage(stderr);
    return 2;
}
