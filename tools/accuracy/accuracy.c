/* pogon-accuracy — what accuracy costs in time.
 *
 * Usage:
 *   pogon-accuracy [--out DIR] [--quick] [--repeat N]
 *       Runs every scene below for every setting of the sweep and prints markdown
 *       tables: all runs, the recommended presets, what fixed point itself costs and the
 *       rain divergence over time. With --out, writes DIR/results.csv
 *       (scene,setting,value,error,error_unit,ms_per_step), DIR/pareto.svg (error against
 *       time, one marker per run, the Pareto front highlighted), DIR/rain_divergence.csv
 *       and DIR/tables.md (the printed tables). --quick runs the three presets only,
 *       once each (the CTest smoke test, a few seconds).
 *       It also writes DIR/runs.tsv: every run's figures at full precision, with the date,
 *       the machine and the command, from which --render prints the same tables again.
 *   pogon-accuracy --render DIR [--section TITLE]
 *       Prints the tables of the run saved in DIR/runs.tsv (or the one under the heading
 *       TITLE, without the heading) without running anything: the
 *       documents' generated tables come from here (tools/docs/regions.js, CTest
 *       docs_generated_regions), so a hand edit of a figure is caught.
 *   pogon-accuracy --worker SUBSTEPS HERTZ BITS PUSH_RAW RATE SLEEP CCD REPEAT
 *       Internal: run one setting and print its rows as tab-separated lines. The sine
 *       table size is fixed when the library is compiled, so the tool is built once per
 *       size (pogon-accuracy-trig8 .. -trig11, this program being the 12-bit one) and
 *       runs the settings of another size through that build.
 *
 * SETTINGS (the knobs that trade accuracy for time): substeps (1, 2, 4, 8), contact_hertz
 * (15, 30, 60), the sine table (8 .. 12 bits), contact_push_max (1, 3, 10 m/s), the step
 * rate (30, 60, 120 Hz), sleeping and continuous collision. The default is 4 substeps,
 * 30 Hz, 12 bits, 3 m/s, 60 Hz, continuous on; every scene runs with sleeping OFF unless
 * the setting turns it on, so each step does the solver's whole work and drift shows.
 *
 * SCENES AND GROUND TRUTH
 *   freefall    ball dropped from rest, 2 s: max |position - (x0, y0 - g t^2 / 2)| (m)
 *   projectile  ball launched at (10, 15) m/s, 2 s: max |position - exact parabola| (m)
 *   spin        a body turning at 2 rad/s without gravity whose origin is 20 m from its
 *               centre of mass, 2 s: max |origin - exact circle| (m)
 *   spin_table  the same run, the origin against where the body's own angle puts it:
 *               the sine table's error alone, scaled by 20 m
 *   collision_momentum, collision_energy
 *               two frictionless balls (r 0.5 and 0.3 m, restitution 1) colliding off
 *               centre without gravity: |p1 - p0| / |p0| and |E1 - E0| / E0 after 1 s
 *   bounce      a ball (r 0.25 m, restitution 1) dropped from 2 m onto the ground: the
 *               energy per unit mass g h + v^2 / 2 lost by the top of the first bounce,
 *               against the 20 J/kg it started with (relative)
 *   friction_stop  a 1 m box sliding at 5 m/s on friction 0.5: stopping distance against
 *               v0^2 / (2 mu g) = 2.5 m (m)
 *   incline     a 1 m box on a 30 degree slope, friction 0.25: acceleration from the
 *               velocity change between 0.5 s and 2 s against g (sin - mu cos) (m/s^2)
 *   stack       20 boxes in a column, 10 s: max displacement of any box from where it
 *               was after 1 s (settled) (m)
 *   pyramid     20 rows (210 boxes), 10 s: |top box(pogon) - top box(reference)| (m),
 *               the reference being tools/accuracy/ref, the same algorithm in double run
 *               with the same setting: the difference is what the arithmetic costs
 *   rain500     500 circles dropped into a 40 m container, 2 s: mean |position(pogon) -
 *               position(reference)| over the circles (m); a chaotic scene, so the
 *               divergence over time is reported too
 *
 * Time is the mean ms per pg_world_step: each scene is stepped once with its
 * measurements, then `repeat` more times bare, timed with the thread's CPU time
 * (clock_gettime(CLOCK_THREAD_CPUTIME_ID)) around the steps only; the figure is the
 * fastest of those repeats (3 by default, 1 with --quick). friction_stop and incline
 * are also run in the reference, for the "what fixed point costs" table. Worlds and
 * measurements are integer; double is used for the truth, the reference and the report.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "pogon/pogon.h"
#include "ref/ref.h"

#define PI 3.14159265358979323846
#define MAX_ROWS 16
#define MAX_DIV 16
#define MAX_SETTINGS 64
#define MAX_REPEAT 15
#define FLOOR (1.0 / 65536.0) /* errors below one Q16.16 step count as one step in the score */

/* ---- settings ------------------------------------------------------------------------ */
typedef struct setting {
    int substeps, hertz, bits;
    pg_fix push;          /* contact_push_max, raw Q16.16 */
    int rate, sleep, ccd;
} setting;

static setting balanced_setting(void)
{
    setting s;
    s.substeps = 4;
    s.hertz = 30;
    s.bits = 12;
    s.push = PG_FIX_C(3);
    s.rate = 60;
    s.sleep = 0;
    s.ccd = 1;
    return s;
}

static int setting_equal(const setting *a, const setting *b)
{
    return a->substeps == b->substeps && a->hertz == b->hertz && a->bits == b->bits && a->push == b->push &&
           a->rate == b->rate && a->sleep == b->sleep && a->ccd == b->ccd;
}

static void setting_label(const setting *s, char *out, size_t size)
{
    snprintf(out, size, "sub=%d hz=%d bits=%d push=%g rate=%d%s%s", s->substeps, s->hertz, s->bits, (double)s->push / 65536.0,
             s->rate, s->sleep ? " sleep" : "", s->ccd ? "" : " no-ccd");
}

/* ---- results ------------------------------------------------------------------------- */
typedef struct row {
    char scene[32];
    double value, error;
    char unit[16];
    double ms;
} row;

typedef struct run_result {
    setting s;
    int ok;
    row rows[MAX_ROWS];
    int nrows;
    double div_t[MAX_DIV], div[MAX_DIV]; /* rain: mean |difference| at times div_t */
    int ndiv;
    /* the reference's own figures (what fixed point costs) */
    double ref_pyramid_ms, ref_rain_ms, ref_pyramid_sink, rain_max_diff;
    double ref_stop, ref_incline; /* the reference's stopping distance and incline acceleration */
} run_result;

static void add_row(run_result *r, const char *scene, double value, double error, const char *unit, double ms)
{
    row *w;
    if (r->nrows >= MAX_ROWS) return;
    w = &r->rows[r->nrows++];
    snprintf(w->scene, sizeof w->scene, "%s", scene);
    w->value = value;
    w->error = error;
    snprintf(w->unit, sizeof w->unit, "%s", unit);
    w->ms = ms;
}

static const row *find_row(const run_result *r, const char *scene)
{
    int i;
    for (i = 0; i < r->nrows; ++i)
        if (strcmp(r->rows[i].scene, scene) == 0) return &r->rows[i];
    return NULL;
}

/* ---- helpers ----------------------------------------------------------------------------- */
/* CPU time of this thread: other programs on a busy machine take the CPU away from the
 * run without adding to it (wall time would count that). */
static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* ms per step of `steps` bare steps of w (a timing pass: nothing measured). */
static double timed_steps(pg_world *w, int steps)
{
    double t0 = now_ms();
    int k;
    for (k = 0; k < steps; ++k) pg_world_step(w);
    return (now_ms() - t0) / steps;
}

static double wall_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static double fx(int64_t q16) { return (double)q16 / 65536.0; }
static pg_fix fix_of(double v) { return (pg_fix)lround(v * 65536.0); }

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The fastest of the repeats: the figure least disturbed by other load on the machine. */
static double fastest(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return v[0];
}

static pg_world_def world_def(const setting *s, uint32_t bodies, pg_fix gravity_y)
{
    pg_world_def d = pg_default_world_def();
    d.gravity = pg_v2(0, gravity_y);
    d.substeps = (uint32_t)s->substeps;
    d.step_hz = (uint32_t)s->rate;
    d.contact_hertz = PG_FIX_C(s->hertz);
    d.contact_push_max = s->push;
    if (!s->sleep) d.effects &= ~(uint32_t)PG_EFFECT_SLEEPING;
    if (!s->ccd) d.effects &= ~(uint32_t)PG_EFFECT_CONTINUOUS;
    d.max_bodies = bodies + 16u;
    d.max_shapes = bodies + 16u;
    d.max_contacts = 4u * (bodies + 16u) + 64u;
    return d;
}

static ref_def reference_def(const setting *s, double gravity_y)
{
    ref_def d = ref_default_def();
    pg_world_def p = pg_default_world_def();
    d.gravity_y = gravity_y;
    d.step_hz = s->rate;
    d.substeps = s->substeps;
    d.hertz = s->hertz;
    d.damping_ratio = fx(p.contact_damping_ratio);
    d.push_max = fx(s->push);
    d.restitution_threshold = fx(p.restitution_threshold);
    d.continuous = s->ccd;
    return d;
}

/* A world in its own malloc'd block; NULL (and a message) on failure. */
static pg_world *new_world(const pg_world_def *d, void **memory)
{
    size_t need = pg_world_memory_size(d);
    pg_world *w = NULL;
    *memory = need ? malloc(need) : NULL;
    if (*memory == NULL || pg_world_create(d, *memory, need, &w) != PG_OK) {
        fprintf(stderr, "pogon-accuracy: cannot create a world\n");
        free(*memory);
        *memory = NULL;
        return NULL;
    }
    return w;
}

static int check(pg_result r, const char *what)
{
    if (r == PG_OK) return 1;
    fprintf(stderr, "pogon-accuracy: %s: %s\n", what, pg_result_name(r));
    return 0;
}

/* ---- scene descriptions shared by pogon and the reference ---------------------------------- */
typedef struct desc {
    int dynamic, box;
    pg_fix x, y, hw, hh, r, friction, restitution;
} desc;

static int build_pogon(pg_world *w, const desc *d, int n, pg_body_id *ids)
{
    int i;
    for (i = 0; i < n; ++i) {
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_result r;
        bd.type = d[i].dynamic ? PG_BODY_DYNAMIC : PG_BODY_STATIC;
        bd.position = pg_v2(d[i].x, d[i].y);
        sd.friction = d[i].friction;
        sd.restitution = d[i].restitution;
        if (d[i].box && !d[i].dynamic) r = pg_make_wall(w, &bd, &sd, 2 * d[i].hw, 2 * d[i].hh, &ids[i]);
        else if (d[i].box) r = pg_make_box(w, &bd, &sd, 2 * d[i].hw, 2 * d[i].hh, &ids[i]);
        else r = pg_make_ball(w, &bd, &sd, d[i].r, &ids[i]);
        if (!check(r, "building a scene")) return 0;
    }
    return 1;
}

static int build_ref(ref_world *w, const desc *d, int n)
{
    int i;
    double density = fx(pg_default_shape_def().density);
    for (i = 0; i < n; ++i) {
        int k = d[i].box ? ref_add_box(w, d[i].dynamic, fx(d[i].x), fx(d[i].y), 0, fx(d[i].hw), fx(d[i].hh), density,
                                       fx(d[i].friction), fx(d[i].restitution))
                         : ref_add_circle(w, d[i].dynamic, fx(d[i].x), fx(d[i].y), fx(d[i].r), density, fx(d[i].friction),
                                          fx(d[i].restitution));
        if (k != i) return 0;
    }
    return 1;
}

static desc box_desc(int dynamic, pg_fix x, pg_fix y, pg_fix hw, pg_fix hh)
{
    desc d;
    memset(&d, 0, sizeof d);
    d.dynamic = dynamic;
    d.box = 1;
    d.x = x;
    d.y = y;
    d.hw = hw;
    d.hh = hh;
    d.friction = pg_default_shape_def().friction;
    return d;
}

/* scenes.c's pyramid: ground 100 x 2 with its top at y = 0, rows of 1 m boxes. */
static int pyramid_desc(desc *d, int rows)
{
    int n = 0, row_i, i;
    d[n++] = box_desc(0, 0, PG_FIX_C(-1), PG_FIX_C(50), PG_FIX_C(1));
    for (row_i = 0; row_i < rows; ++row_i) {
        int cnt = rows - row_i;
        for (i = 0; i < cnt; ++i)
            d[n++] = box_desc(1, (pg_fix)((int32_t)(2 * i + 1) * 32768 - cnt * 32768), PG_FIX_HALF + PG_FIX_C(row_i), PG_FIX_HALF,
                              PG_FIX_HALF);
    }
    return n;
}

static uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

/* scenes.c's rain: a 40 m container, circles of 0.25 .. 0.5 m on a 1 m lattice. */
static int rain_desc(desc *d, int count)
{
    int n = 0, i;
    uint32_t seed = 12345u;
    d[n++] = box_desc(0, 0, PG_FIX_C(-1), PG_FIX_C(21), PG_FIX_C(1));
    for (i = 0; i < 10; ++i)
        d[n++] = box_desc(0, (i & 1) ? PG_FIX_C(20) + PG_FIX_C(1) / 4 : PG_FIX_C(-20) - PG_FIX_C(1) / 4,
                          PG_FIX_C(50 + 100 * (i / 2)), PG_FIX_C(1) / 4, PG_FIX_C(50));
    for (i = 0; i < count; ++i) {
        desc c;
        pg_fix radius = (pg_fix)(16384 + (int32_t)(next_random(&seed) % 16385u));
        int column = i % 39, layer = i / 39;
        pg_fix jitter = (pg_fix)((int32_t)(next_random(&seed) % 8193u) - 4096);
        memset(&c, 0, sizeof c);
        c.dynamic = 1;
        c.x = PG_FIX_C(column) - PG_FIX_C(19) + jitter;
        c.y = PG_FIX_C(2) + PG_FIX_C(layer);
        c.r = radius;
        c.friction = pg_default_shape_def().friction;
        d[n++] = c;
    }
    return n;
}

/* ---- analytic scenes ----------------------------------------------------------------------- */

/* Ballistic flight (freefall: v0 = 0; projectile: v0 = (10, 15)); max position error. */
static int scene_ballistic(const setting *s, int repeat, int launch, run_result *res)
{
    double ms[MAX_REPEAT], err = 0, final_y = 0;
    int rep, steps = 2 * s->rate;
    for (rep = 0; rep <= repeat; ++rep) { /* pass 0 measures, the others time */
        pg_world_def d = world_def(s, 1, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id ball;
        double x0 = launch ? -10 : 0, y0 = launch ? 0 : 50, vx = launch ? 10 : 0, vy = launch ? 15 : 0;
        int k;
        if (w == NULL) return 0;
        bd.type = PG_BODY_DYNAMIC;
        bd.position = pg_v2(fix_of(x0), fix_of(y0));
        bd.linear_velocity = pg_v2(fix_of(vx), fix_of(vy));
        if (!check(pg_make_ball(w, &bd, &sd, PG_FIX_HALF, &ball), "ball")) { free(mem); return 0; }
        if (rep > 0) { /* timing passes: the bare steps */
            ms[rep - 1] = timed_steps(w, steps);
            free(mem);
            continue;
        }
        err = 0;
        for (k = 1; k <= steps; ++k) {
            double t = (double)k / s->rate, ex, ey, e;
            pg_vec2 p;
            pg_world_step(w);
            p = pg_body_position(w, ball);
            ex = x0 + vx * t;
            ey = y0 + vy * t - 5.0 * t * t;
            e = hypot(fx(p.x) - ex, fx(p.y) - ey);
            if (e > err) err = e;
            final_y = fx(p.y);
        }
        free(mem);
    }
    add_row(res, launch ? "projectile" : "freefall", final_y, err, "m", fastest(ms, repeat));
    return 1;
}

/* A body turning at 2 rad/s whose origin is 20 m from its centre of mass. */
static int scene_spin(const setting *s, int repeat, run_result *res)
{
    double ms[MAX_REPEAT], err = 0, err_table = 0, final_angle = 0;
    int rep, steps = 2 * s->rate;
    for (rep = 0; rep <= repeat; ++rep) { /* pass 0 measures, the others time */
        pg_world_def d = world_def(s, 1, 0);
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_geometry g;
        pg_body_id b;
        pg_shape_id sh;
        int k;
        if (w == NULL) return 0;
        bd.type = PG_BODY_DYNAMIC;
        bd.angular_velocity = PG_FIX_C(2);
        if (!check(pg_body_create(w, &bd, &b), "spin body") || !check(pg_geometry_circle(pg_v2(PG_FIX_C(20), 0), PG_FIX_HALF, &g), "circle") ||
            !check(pg_shape_create(w, b, &sd, &g, &sh), "spin shape")) {
            free(mem);
            return 0;
        }
        if (rep > 0) { /* timing passes: the bare steps */
            ms[rep - 1] = timed_steps(w, steps);
            free(mem);
            continue;
        }
        err = err_table = 0;
        for (k = 1; k <= steps; ++k) {
            double th = 2.0 * k / s->rate, e, a;
            pg_vec2 p;
            pg_world_step(w);
            p = pg_body_position(w, b);
            e = hypot(fx(p.x) - (20.0 - 20.0 * cos(th)), fx(p.y) - (-20.0 * sin(th)));
            if (e > err) err = e;
            /* the same against the body's own angle: what the sine table alone costs */
            a = (double)pg_body_angle(w, b) * (2.0 * PI / 4294967296.0);
            e = hypot(fx(p.x) - (20.0 - 20.0 * cos(a)), fx(p.y) - (-20.0 * sin(a)));
            if (e > err_table) err_table = e;
        }
        {
            pg_angle a = pg_body_angle(w, b);
            final_angle = (double)a * (2.0 * PI / 4294967296.0);
        }
        free(mem);
    }
    add_row(res, "spin", final_angle, err, "m", fastest(ms, repeat));
    add_row(res, "spin_table", final_angle, err_table, "m", fastest(ms, repeat));
    return 1;
}

static void momentum_energy(pg_world *w, const pg_body_id *b, int n, double *px, double *py, double *e)
{
    int i;
    *px = *py = *e = 0;
    for (i = 0; i < n; ++i) {
        double m = (double)pg_body_mass(w, b[i]) / 4294967296.0, I = (double)pg_body_inertia(w, b[i]) / 68719476736.0;
        pg_vec2 v = pg_body_linear_velocity(w, b[i]);
        double om = fx(pg_body_angular_velocity(w, b[i]));
        *px += m * fx(v.x);
        *py += m * fx(v.y);
        *e += 0.5 * m * (fx(v.x) * fx(v.x) + fx(v.y) * fx(v.y)) + 0.5 * I * om * om;
    }
}

/* Two frictionless elastic balls colliding off centre, no gravity. */
static int scene_collision(const setting *s, int repeat, run_result *res)
{
    double ms[MAX_REPEAT], ep = 0, ee = 0, vb_final = 0;
    int rep, steps = s->rate;
    for (rep = 0; rep < repeat; ++rep) {
        pg_world_def d = world_def(s, 2, 0);
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id b[2];
        double px0, py0, e0, px1, py1, e1, t0;
        int k;
        if (w == NULL) return 0;
        sd.friction = 0;
        sd.restitution = PG_FIX_ONE;
        bd.type = PG_BODY_DYNAMIC;
        bd.position = pg_v2(PG_FIX_C(-2), 0);
        bd.linear_velocity = pg_v2(PG_FIX_C(6), 0);
        if (!check(pg_make_ball(w, &bd, &sd, PG_FIX_HALF, &b[0]), "ball a")) { free(mem); return 0; }
        bd.position = pg_v2(PG_FIX_C(2), PG_FIX_C(1) / 4);
        bd.linear_velocity = pg_v2(PG_FIX_C(-2), 0);
        if (!check(pg_make_ball(w, &bd, &sd, fix_of(0.3), &b[1]), "ball b")) { free(mem); return 0; }
        momentum_energy(w, b, 2, &px0, &py0, &e0);
        t0 = now_ms();
        for (k = 0; k < steps; ++k) pg_world_step(w);
        ms[rep] = (now_ms() - t0) / steps;
        momentum_energy(w, b, 2, &px1, &py1, &e1);
        ep = hypot(px1 - px0, py1 - py0) / hypot(px0, py0);
        ee = fabs(e1 - e0) / e0;
        vb_final = fx(pg_body_linear_velocity(w, b[1]).x);
        if (vb_final <= 0) ee = ep = 1; /* no collision happened: count it as a total failure */
        free(mem);
    }
    add_row(res, "collision_momentum", vb_final, ep, "relative", fastest(ms, repeat));
    add_row(res, "collision_energy", vb_final, ee, "relative", fastest(ms, repeat));
    return 1;
}

/* A ball of restitution 1 dropped from 2 m (its bottom) onto the ground: the energy lost
 * by the top of the first bounce. Elastic, so the truth is none. */
static int scene_bounce(const setting *s, int repeat, run_result *res)
{
    const double r = 0.25, h0 = 2.0, g = 10.0, e0 = g * h0;
    double ms[MAX_REPEAT], err = 1, apex = 0;
    int rep, steps = 3 * s->rate; /* down in 0.63 s, up again by 1.3 s */
    for (rep = 0; rep <= repeat; ++rep) { /* pass 0 measures, the others time */
        pg_world_def d = world_def(s, 2, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id ground, ball;
        double prev_vy = 0;
        int k, bounced = 0;
        if (w == NULL) return 0;
        bd.position = pg_v2(0, PG_FIX_C(-1));
        if (!check(pg_make_wall(w, &bd, &sd, PG_FIX_C(100), PG_FIX_C(2), &ground), "ground")) { free(mem); return 0; }
        bd.type = PG_BODY_DYNAMIC;
        bd.position = pg_v2(0, fix_of(h0 + r));
        sd.restitution = PG_FIX_ONE;
        if (!check(pg_make_ball(w, &bd, &sd, fix_of(r), &ball), "ball")) { free(mem); return 0; }
        if (rep > 0) {
            ms[rep - 1] = timed_steps(w, steps);
            free(mem);
            continue;
        }
        err = 1; /* no bounce: all of it lost */
        for (k = 0; k < steps; ++k) {
            double vy, hgt;
            pg_world_step(w);
            vy = fx(pg_body_linear_velocity(w, ball).y);
            hgt = fx(pg_body_position(w, ball).y) - r;
            if (prev_vy < 0 && vy > 0) bounced = 1;
            if (bounced && prev_vy > 0 && vy <= 0) { /* the top of the first bounce */
                apex = hgt;
                err = fabs(e0 - (g * hgt + 0.5 * vy * vy)) / e0;
                break;
            }
            prev_vy = vy;
        }
        free(mem);
    }
    add_row(res, "bounce", apex, err, "relative", fastest(ms, repeat));
    return 1;
}

/* A 1 m box sliding at 5 m/s on friction 0.5 (both shapes 0.5: the mixed value is 0.5). */
static int scene_friction_stop(const setting *s, int repeat, run_result *res)
{
    double ms[MAX_REPEAT], dist = 0, exact = 25.0 / (2 * 0.5 * 10);
    int rep, steps = 3 * s->rate;
    for (rep = 0; rep < repeat; ++rep) {
        pg_world_def d = world_def(s, 2, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id ground, box;
        double t0;
        int k;
        if (w == NULL) return 0;
        sd.friction = PG_FIX_HALF;
        bd.position = pg_v2(0, PG_FIX_C(-1));
        if (!check(pg_make_wall(w, &bd, &sd, PG_FIX_C(100), PG_FIX_C(2), &ground), "ground")) { free(mem); return 0; }
        bd.type = PG_BODY_DYNAMIC;
        bd.position = pg_v2(PG_FIX_C(-20), PG_FIX_HALF);
        bd.linear_velocity = pg_v2(PG_FIX_C(5), 0);
        if (!check(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), "box")) { free(mem); return 0; }
        t0 = now_ms();
        for (k = 0; k < steps; ++k) pg_world_step(w);
        ms[rep] = (now_ms() - t0) / steps;
        dist = fx(pg_body_position(w, box).x) + 20.0;
        free(mem);
    }
    {
        ref_def rd = reference_def(s, -10);
        ref_world *r = ref_create(&rd, 2);
        double x;
        int k, b;
        if (r == NULL) return 0;
        ref_add_box(r, 0, 0, -1, 0, 50, 1, 1, 0.5, 0);
        b = ref_add_box(r, 1, -20, 0.5, 0, 0.5, 0.5, 1, 0.5, 0);
        ref_set_velocity(r, b, 5, 0, 0);
        for (k = 0; k < steps; ++k) ref_step(r);
        ref_position(r, b, &x, NULL, NULL);
        res->ref_stop = x + 20;
        ref_destroy(r);
    }
    add_row(res, "friction_stop", dist, fabs(dist - exact), "m", fastest(ms, repeat));
    return 1;
}

/* A 1 m box sliding down a 30 degree slope (friction 0.25 on both shapes). */
static int scene_incline(const setting *s, int repeat, run_result *res)
{
    const pg_angle angle = 357913941u; /* 30 degrees, rounded to a binary angle */
    const double th = (double)angle * (2.0 * PI / 4294967296.0), mu = 0.25;
    const double exact = 10.0 * (sin(th) - mu * cos(th));
    double ms[MAX_REPEAT], accel = 0;
    int rep, steps = 2 * s->rate, k1 = s->rate / 2;
    for (rep = 0; rep < repeat; ++rep) {
        pg_world_def d = world_def(s, 2, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_body_def bd = pg_default_body_def();
        pg_shape_def sd = pg_default_shape_def();
        pg_body_id slope, box;
        double t0, v1 = 0, v2 = 0, ux = cos(th), uy = sin(th);
        int k;
        if (w == NULL) return 0;
        sd.friction = PG_FIX_C(1) / 4;
        /* the slope's top face passes through the origin along (cos, sin) */
        bd.angle = angle;
        bd.position = pg_v2(fix_of(sin(th)), fix_of(-cos(th)));
        if (!check(pg_make_wall(w, &bd, &sd, PG_FIX_C(60), PG_FIX_C(2), &slope), "slope")) { free(mem); return 0; }
        bd.type = PG_BODY_DYNAMIC;
        bd.position = pg_v2(fix_of(20 * ux - 0.5 * uy), fix_of(20 * uy + 0.5 * ux));
        if (!check(pg_make_box(w, &bd, &sd, PG_FIX_ONE, PG_FIX_ONE, &box), "box")) { free(mem); return 0; }
        t0 = now_ms();
        for (k = 1; k <= steps; ++k) {
            pg_world_step(w);
            if (k == k1 || k == steps) {
                pg_vec2 v = pg_body_linear_velocity(w, box);
                double along = -(fx(v.x) * ux + fx(v.y) * uy); /* down the slope */
                if (k == k1) v1 = along; else v2 = along;
            }
        }
        ms[rep] = (now_ms() - t0) / steps;
        accel = (v2 - v1) / (2.0 - (double)k1 / s->rate);
        free(mem);
    }
    {
        ref_def rd = reference_def(s, -10);
        ref_world *r = ref_create(&rd, 2);
        double ux = cos(th), uy = sin(th), vx, vy, v1 = 0, v2 = 0;
        int k, b;
        if (r == NULL) return 0;
        ref_add_box(r, 0, fx(fix_of(sin(th))), fx(fix_of(-cos(th))), th, 30, 1, 1, 0.25, 0);
        b = ref_add_box(r, 1, fx(fix_of(20 * ux - 0.5 * uy)), fx(fix_of(20 * uy + 0.5 * ux)), th, 0.5, 0.5, 1, 0.25, 0);
        for (k = 1; k <= steps; ++k) {
            ref_step(r);
            if (k == k1 || k == steps) {
                ref_velocity(r, b, &vx, &vy, NULL);
                if (k == k1) v1 = -(vx * ux + vy * uy); else v2 = -(vx * ux + vy * uy);
            }
        }
        res->ref_incline = (v2 - v1) / (2.0 - (double)k1 / s->rate);
        ref_destroy(r);
    }
    add_row(res, "incline", accel, fabs(accel - exact), "m/s^2", fastest(ms, repeat));
    return 1;
}

/* 20 boxes in a column for 10 s: max displacement of any box after the first second. */
static int scene_stack(const setting *s, int repeat, run_result *res)
{
    desc dsc[32];
    pg_body_id ids[32];
    double ms[MAX_REPEAT], drift = 0, sink = 0;
    int rep, n = 0, i, steps = 10 * s->rate, settle = s->rate;
    dsc[n++] = box_desc(0, 0, PG_FIX_C(-1), PG_FIX_C(50), PG_FIX_C(1));
    for (i = 0; i < 20; ++i) dsc[n++] = box_desc(1, 0, PG_FIX_HALF + PG_FIX_C(i), PG_FIX_HALF, PG_FIX_HALF);
    for (rep = 0; rep <= repeat; ++rep) { /* pass 0 measures, the others time */
        pg_world_def d = world_def(s, (uint32_t)n, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        pg_vec2 settled[32];
        int k;
        if (w == NULL) return 0;
        if (!build_pogon(w, dsc, n, ids)) { free(mem); return 0; }
        if (rep > 0) { /* timing passes: the bare steps */
            ms[rep - 1] = timed_steps(w, steps);
            free(mem);
            continue;
        }
        drift = 0;
        for (k = 1; k <= steps; ++k) {
            pg_world_step(w);
            if (k == settle)
                for (i = 1; i < n; ++i) settled[i] = pg_body_position(w, ids[i]);
            if (k > settle)
                for (i = 1; i < n; ++i) {
                    pg_vec2 p = pg_body_position(w, ids[i]);
                    double e = hypot(fx(p.x) - fx(settled[i].x), fx(p.y) - fx(settled[i].y));
                    if (e > drift) drift = e;
                }
        }
        {
            pg_vec2 p = pg_body_position(w, ids[n - 1]);
            sink = hypot(fx(p.x) - fx(dsc[n - 1].x), fx(p.y) - fx(dsc[n - 1].y));
        }
        free(mem);
    }
    add_row(res, "stack", sink, drift, "m", fastest(ms, repeat));
    return 1;
}

/* ---- scenes against the double-precision reference ----------------------------------------- */
static int scene_pyramid(const setting *s, int repeat, int ref_repeat, run_result *res)
{
    static desc dsc[256];
    static pg_body_id ids[256];
    double ms[MAX_REPEAT], rms[MAX_REPEAT], px = 0, py = 0, rx = 0, ry = 0;
    int n = pyramid_desc(dsc, 20), rep, k, steps = 10 * s->rate;
    for (rep = 0; rep < repeat; ++rep) {
        pg_world_def d = world_def(s, (uint32_t)n, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        double t0;
        pg_vec2 p;
        if (w == NULL) return 0;
        if (!build_pogon(w, dsc, n, ids)) { free(mem); return 0; }
        t0 = now_ms();
        for (k = 0; k < steps; ++k) pg_world_step(w);
        ms[rep] = (now_ms() - t0) / steps;
        p = pg_body_position(w, ids[n - 1]);
        px = fx(p.x);
        py = fx(p.y);
        free(mem);
    }
    for (rep = 0; rep < ref_repeat; ++rep) {
        ref_def rd = reference_def(s, -10);
        ref_world *r = ref_create(&rd, n);
        double t0;
        if (r == NULL || !build_ref(r, dsc, n)) { ref_destroy(r); return 0; }
        t0 = now_ms();
        for (k = 0; k < steps; ++k) ref_step(r);
        rms[rep] = (now_ms() - t0) / steps;
        ref_position(r, n - 1, &rx, &ry, NULL);
        ref_destroy(r);
    }
    res->ref_pyramid_ms = fastest(rms, ref_repeat);
    res->ref_pyramid_sink = hypot(rx - fx(dsc[n - 1].x), ry - fx(dsc[n - 1].y));
    add_row(res, "pyramid", hypot(px - fx(dsc[n - 1].x), py - fx(dsc[n - 1].y)), hypot(px - rx, py - ry), "m", fastest(ms, repeat));
    return 1;
}

static int scene_rain(const setting *s, int repeat, int ref_repeat, run_result *res)
{
    static desc dsc[600];
    static pg_body_id ids[600];
    static double pos[6][600][2];  /* pogon positions at the sample times */
    const int count = 500, samples = 6;
    double ms[MAX_REPEAT], rms[MAX_REPEAT], maxd = 0;
    int n = rain_desc(dsc, count), first = n - count, rep, k, i, steps = 2 * s->rate, every = steps / samples;
    for (rep = 0; rep <= repeat; ++rep) { /* pass 0 measures, the others time */
        pg_world_def d = world_def(s, (uint32_t)n, PG_FIX_C(-10));
        void *mem;
        pg_world *w = new_world(&d, &mem);
        if (w == NULL) return 0;
        if (!build_pogon(w, dsc, n, ids)) { free(mem); return 0; }
        if (rep > 0) { /* timing passes: the bare steps */
            ms[rep - 1] = timed_steps(w, steps);
            free(mem);
            continue;
        }
        for (k = 1; k <= steps; ++k) {
            pg_world_step(w);
            if (k % every == 0 && k / every <= samples)
                for (i = first; i < n; ++i) {
                    pg_vec2 p = pg_body_position(w, ids[i]);
                    pos[k / every - 1][i][0] = fx(p.x);
                    pos[k / every - 1][i][1] = fx(p.y);
                }
        }
        free(mem);
    }
    res->ndiv = 0;
    for (rep = 0; rep <= ref_repeat; ++rep) { /* pass 0 measures, the others time */
        ref_def rd = reference_def(s, -10);
        ref_world *r = ref_create(&rd, n);
        if (r == NULL || !build_ref(r, dsc, n)) { ref_destroy(r); return 0; }
        if (rep > 0) {
            double t0 = now_ms();
            for (k = 0; k < steps; ++k) ref_step(r);
            rms[rep - 1] = (now_ms() - t0) / steps;
            ref_destroy(r);
            continue;
        }
        res->ndiv = 0;
        for (k = 1; k <= steps; ++k) {
            ref_step(r);
            if (k % every == 0 && k / every <= samples) {
                double sum = 0;
                maxd = 0;
                for (i = first; i < n; ++i) {
                    double x, y, e;
                    ref_position(r, i, &x, &y, NULL);
                    e = hypot(x - pos[k / every - 1][i][0], y - pos[k / every - 1][i][1]);
                    sum += e;
                    if (e > maxd) maxd = e;
                }
                res->div_t[res->ndiv] = (double)k / s->rate;
                res->div[res->ndiv++] = sum / count;
            }
        }
        ref_destroy(r);
    }
    res->ref_rain_ms = fastest(rms, ref_repeat);
    res->rain_max_diff = maxd;
    add_row(res, "rain500", maxd, res->ndiv ? res->div[res->ndiv - 1] : -1, "m", fastest(ms, repeat));
    return 1;
}

/* Every scene for one setting, in this process (its sine table is PG_TRIG_TABLE_BITS). */
static int run_local(const setting *s, int repeat, int ref_repeat, run_result *res)
{
    memset(res, 0, sizeof *res);
    res->s = *s;
    res->ok = scene_ballistic(s, repeat, 0, res) && scene_ballistic(s, repeat, 1, res) && scene_spin(s, repeat, res) &&
              scene_collision(s, repeat, res) && scene_bounce(s, repeat, res) && scene_friction_stop(s, repeat, res) && scene_incline(s, repeat, res) &&
              scene_stack(s, repeat, res) && scene_pyramid(s, repeat, ref_repeat, res) && scene_rain(s, repeat, ref_repeat, res);
    return res->ok;
}

/* ---- workers: the builds with other sine tables ---------------------------------------------- */
/* One run's figures as tab-separated lines at full precision: what a worker prints and
 * what runs.tsv holds. read_run_line() reads them back. */
static void write_run(FILE *f, const run_result *r)
{
    int i;
    for (i = 0; i < r->nrows; ++i)
        fprintf(f, "row\t%s\t%.17g\t%.17g\t%s\t%.17g\n", r->rows[i].scene, r->rows[i].value, r->rows[i].error, r->rows[i].unit, r->rows[i].ms);
    for (i = 0; i < r->ndiv; ++i) fprintf(f, "div\t%.17g\t%.17g\n", r->div_t[i], r->div[i]);
    fprintf(f, "ref\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", r->ref_pyramid_ms, r->ref_rain_ms, r->ref_pyramid_sink,
            r->rain_max_diff, r->ref_stop, r->ref_incline);
    fprintf(f, "done\n");
}

static void print_worker(const run_result *r) { write_run(stdout, r); }

/* One line of write_run's output into res; returns 1 on the closing "done". */
static int read_run_line(run_result *res, const char *line)
{
    char scene[32], unit[16];
    double a, b, c, e, g, h;
    if (sscanf(line, "row\t%31s\t%lf\t%lf\t%15s\t%lf", scene, &a, &b, unit, &c) == 5) add_row(res, scene, a, b, unit, c);
    else if (sscanf(line, "div\t%lf\t%lf", &a, &b) == 2 && res->ndiv < MAX_DIV) {
        res->div_t[res->ndiv] = a;
        res->div[res->ndiv++] = b;
    } else if (sscanf(line, "ref\t%lf\t%lf\t%lf\t%lf\t%lf\t%lf", &a, &b, &c, &e, &g, &h) == 6) {
        res->ref_pyramid_ms = a;
        res->ref_rain_ms = b;
        res->ref_pyramid_sink = c;
        res->rain_max_diff = e;
        res->ref_stop = g;
        res->ref_incline = h;
    } else if (strncmp(line, "done", 4) == 0) return 1;
    return 0;
}

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

static int run_worker(const char *dir, const setting *s, int repeat, run_result *res)
{
    char exe[4300], cmd[4600], line[512];
    FILE *f;
    int done = 0;
    memset(res, 0, sizeof *res);
    res->s = *s;
    snprintf(exe, sizeof exe, "%spogon-accuracy-trig%d", dir, s->bits);
    if (access(exe, X_OK) != 0 || strchr(exe, '\'') != NULL) {
        fprintf(stderr, "pogon-accuracy: %s not found: the %d-bit settings are skipped\n", exe, s->bits);
        return 0;
    }
    snprintf(cmd, sizeof cmd, "'%s' --worker %d %d %d %ld %d %d %d %d", exe, s->substeps, s->hertz, s->bits, (long)s->push,
             s->rate, s->sleep, s->ccd, repeat);
    f = popen(cmd, "r");
    if (f == NULL) return 0;
    while (fgets(line, sizeof line, f) != NULL)
        if (read_run_line(res, line)) done = 1;
    res->ok = pclose(f) == 0 && done;
    return res->ok;
}

/* ---- the sweep ------------------------------------------------------------------------------ */
typedef struct preset { const char *name; setting s; const char *why; } preset;

static int presets(preset *p)
{
    setting b = balanced_setting();
    p[0].name = "fast";
    p[0].s = b;
    p[0].s.substeps = 2;
    p[0].s.bits = 10;
    p[0].why = "2 substeps, 10-bit table (4 KiB)";
    p[1].name = "balanced";
    p[1].s = b;
    p[1].why = "the defaults: 4 substeps, 12-bit table";
    p[2].name = "accurate";
    p[2].s = b;
    p[2].s.substeps = 8;
    p[2].why = "8 substeps, contact_hertz 30, 12-bit table (only the substeps differ from the defaults; at 8 substeps "
               "60 Hz scores about as well, and which of the two stops the sliding box closer to the exact distance, the one "
               "error against an exact solution that is larger than rounding, has swapped with changes of rounding, as have "
               "the incline, the stack drift and the pyramid against its double run: see every run below)";
    return 3;
}

static int add_setting(setting *list, int n, setting s)
{
    int i;
    for (i = 0; i < n; ++i)
        if (setting_equal(&list[i], &s)) return n;
    if (n < MAX_SETTINGS) list[n++] = s;
    return n;
}

static int sweep(setting *list, int quick)
{
    static const int subs[] = {1, 2, 4, 8}, hz[] = {15, 30, 60}, bits[] = {8, 10, 12};
    preset p[3];
    int n = 0, i, j, k, np = presets(p);
    setting b = balanced_setting(), s;
    for (i = 0; i < np; ++i) n = add_setting(list, n, p[i].s);
    if (quick) return n;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 3; ++j)
            for (k = 0; k < 3; ++k) {
                s = b;
                s.substeps = subs[i];
                s.hertz = hz[j];
                s.bits = bits[k];
                n = add_setting(list, n, s);
            }
    s = b; s.bits = 9; n = add_setting(list, n, s);
    s = b; s.bits = 11; n = add_setting(list, n, s);
    s = b; s.push = PG_FIX_C(1); n = add_setting(list, n, s);
    s = b; s.push = PG_FIX_C(10); n = add_setting(list, n, s);
    s = b; s.rate = 30; n = add_setting(list, n, s);
    s = b; s.rate = 120; n = add_setting(list, n, s);
    s = b; s.sleep = 1; n = add_setting(list, n, s);
    s = b; s.ccd = 0; n = add_setting(list, n, s);
    return n;
}

static const run_result *find_result(const run_result *all, int n, const setting *s)
{
    int i;
    for (i = 0; i < n; ++i)
        if (all[i].ok && setting_equal(&all[i].s, s)) return &all[i];
    return NULL;
}

/* ---- report ------------------------------------------------------------------------------------ */
static const char *const SCENES[] = {"freefall", "projectile", "spin", "spin_table", "collision_momentum", "collision_energy",
                                     "bounce", "friction_stop", "incline", "stack", "pyramid", "rain500"};
#define N_SCENES ((int)(sizeof SCENES / sizeof SCENES[0]))
static const char *const SHORT[] = {"free fall", "projectile", "spin", "spin (table)", "momentum", "energy", "bounce", "stop", "incline", "stack drift",
                                    "pyramid vs ref", "rain vs ref"};

/* ms per step of the heavy scenes: pyramid + rain 500 + stack. */
static double heavy_ms_per_step(const run_result *r)
{
    const row *a = find_row(r, "pyramid"), *b = find_row(r, "rain500"), *c = find_row(r, "stack");
    return (a ? a->ms : 0) + (b ? b->ms : 0) + (c ? c->ms : 0);
}

/* Time of a run on the chart: ms per simulated second of the heavy scenes, so that
 * step rates compare fairly. */
static double heavy_ms_per_second(const run_result *r) { return heavy_ms_per_step(r) * r->s.rate; }

/* Score: geometric mean over the scenes of error / error of the balanced run (errors
 * below one Q16.16 step count as one step). 1 = as accurate as the defaults. rain500 is
 * left out: after 2 s its difference measures how fast chaos amplifies any difference,
 * not accuracy (its divergence table shows the early, arithmetic part). */
static double score(const run_result *r, const run_result *base)
{
    double sum = 0;
    int i, n = 0;
    for (i = 0; i < N_SCENES; ++i) {
        const row *a = find_row(r, SCENES[i]), *b = base ? find_row(base, SCENES[i]) : NULL;
        if (a == NULL || b == NULL || strcmp(SCENES[i], "rain500") == 0) continue;
        sum += log((a->error > FLOOR ? a->error : FLOOR) / (b->error > FLOOR ? b->error : FLOOR));
        ++n;
    }
    return n ? exp(sum / n) : 1;
}

static void fmt_err(double e, char *out, size_t size)
{
    if (e < 0) snprintf(out, size, "n/a");
    else if (e == 0) snprintf(out, size, "0");
    else snprintf(out, size, "%.2e", e);
}

/* Where and how the figures were measured, printed under every table: "Measured DATE on
 * MACHINE by `COMMAND`: ...". Set by the run, or read back from runs.tsv by --render. */
typedef struct measured {
    char date[32], machine[256], command[512];
    int settings, repeat;
    double seconds;
} measured;
static measured g_run;

static void out(const char *fmt, ...);
static void out_measured(void)
{
    out("Measured %s on %s by `%s`: %d settings, %d repeat(s) each, %.0f s in all; times are CPU time.\n\n", g_run.date,
        g_run.machine, g_run.command, g_run.settings, g_run.repeat, g_run.seconds);
}

/* The output goes both to stdout and (when given) to a file. */
static FILE *g_md;

/* A table's heading, left out when --render prints one section into a document that has
 * its own heading (g_no_heading). */
static int g_no_heading;
static void heading(const char *title)
{
    if (!g_no_heading) out("### %s\n\n", title);
}
static void out(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static void out(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    if (g_md != NULL) {
        va_start(ap, fmt);
        vfprintf(g_md, fmt, ap);
        va_end(ap);
    }
}

static void print_all(const run_result *all, int n, const run_result *base)
{
    int i, j;
    heading("Every run");
    out("Errors against the ground truth of each scene (units in docs/accuracy.md); ms/step of the "
        "pyramid (210 boxes, sleeping off) and rain 500; score = geometric mean of error / the defaults' error over the "
        "scenes but rain (1 = as accurate as the defaults, lower is better).\n\n");
    out("| setting |");
    for (j = 0; j < N_SCENES; ++j) out(" %s |", SHORT[j]);
    out(" pyramid ms/step | rain ms/step | score |\n|---|");
    for (j = 0; j < N_SCENES; ++j) out("---:|");
    out("---:|---:|---:|\n");
    for (i = 0; i < n; ++i) {
        char label[128];
        const row *p, *r;
        if (!all[i].ok) continue;
        setting_label(&all[i].s, label, sizeof label);
        out("| %s |", label);
        for (j = 0; j < N_SCENES; ++j) {
            const row *w = find_row(&all[i], SCENES[j]);
            char e[32];
            fmt_err(w ? w->error : -1, e, sizeof e);
            out(" %s |", e);
        }
        p = find_row(&all[i], "pyramid");
        r = find_row(&all[i], "rain500");
        out(" %.3f | %.3f | %.2f |\n", p ? p->ms : 0, r ? r->ms : 0, score(&all[i], base));
    }
    out("\n");
    out_measured();
}

static void print_presets(const run_result *all, int n)
{
    preset p[3];
    const run_result *r[3];
    int np = presets(p), i, j;
    static const char *const UNIT[] = {"m", "m", "m", "m", "relative", "relative", "relative", "m", "m/s^2", "m", "m", "m"};
    typedef char unit_per_scene[(int)(sizeof UNIT / sizeof UNIT[0]) == N_SCENES ? 1 : -1]; /* one unit a scene */
    (void)sizeof(unit_per_scene);
    for (i = 0; i < np; ++i) r[i] = find_result(all, n, &p[i].s);
    heading("Presets");
    for (i = 0; i < np; ++i) out("- **%s**: %s\n", p[i].name, p[i].why);
    out("\n| scene | unit | fast error | fast ms/step | balanced error | balanced ms/step | accurate error | accurate ms/step |\n");
    out("|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (j = 0; j < N_SCENES; ++j) {
        out("| %s | %s |", SHORT[j], UNIT[j]);
        for (i = 0; i < np; ++i) {
            const row *w = r[i] ? find_row(r[i], SCENES[j]) : NULL;
            char e[32];
            fmt_err(w ? w->error : -1, e, sizeof e);
            if (w) out(" %s | %.4f |", e, w->ms);
            else out(" n/a | n/a |");
        }
        out("\n");
    }
    out("| **score** (1 = defaults) | |");
    for (i = 0; i < np; ++i) {
        if (r[i]) out(" %.2f | %.3f |", score(r[i], r[1]), heavy_ms_per_step(r[i]));
        else out(" n/a | |");
    }
    out("\n\n(The score row's time is the pyramid + rain 500 + stack ms/step.)\n\n");
    out_measured();
}

static void print_fixed_cost(const run_result *b)
{
    const row *p = find_row(b, "pyramid"), *r = find_row(b, "rain500"), *f = find_row(b, "friction_stop"), *i = find_row(b, "incline");
    const pg_angle angle = 357913941u;
    const double th = (double)angle * (2.0 * PI / 4294967296.0), a_exact = 10.0 * (sin(th) - 0.25 * cos(th));
    if (p == NULL || r == NULL || f == NULL || i == NULL) return;
    heading("What fixed point costs (the defaults, sleeping off)");
    out("The same scene stepped by pogon (Q16.16, 12-bit sine table) and by the double-precision reference of the same "
        "algorithm (tools/accuracy/ref), in the same run.\n\n");
    out("| scene | pogon ms/step | double ms/step | pogon / double | pogon result | double result | difference |\n");
    out("|---|---:|---:|---:|---|---|---:|\n");
    out("| pyramid, 10 s | %.3f | %.3f | %.2f | top sank %.4f m | top sank %.4f m | %.2e m (top box) |\n", p->ms, b->ref_pyramid_ms,
        b->ref_pyramid_ms > 0 ? p->ms / b->ref_pyramid_ms : 0, p->value, b->ref_pyramid_sink, p->error);
    out("| rain 500, 2 s | %.3f | %.3f | %.2f | | | mean %.2e m, max %.2e m |\n", r->ms, b->ref_rain_ms,
        b->ref_rain_ms > 0 ? r->ms / b->ref_rain_ms : 0, r->error, b->rain_max_diff);
    out("| friction stop (exact 2.5 m) | | | | %.4f m | %.4f m | %.2e m |\n", f->value, b->ref_stop, fabs(f->value - b->ref_stop));
    out("| incline (exact %.4f m/s^2) | | | | %.4f m/s^2 | %.4f m/s^2 | %.2e m/s^2 |\n\n", a_exact, i->value, b->ref_incline,
        fabs(i->value - b->ref_incline));
    out_measured();
}

static void print_divergence(const run_result *all, int n)
{
    preset p[3];
    int np = presets(p), i, k;
    const run_result *r0 = find_result(all, n, &p[1].s);
    if (r0 == NULL || r0->ndiv == 0) return;
    heading("Rain 500: divergence from the reference over time");
    out("Mean |position(pogon) - position(double)| over the 500 "
        "circles (m), each preset against the reference run with the same setting.\n\n| preset |");
    for (k = 0; k < r0->ndiv; ++k) out(" t = %.2f s |", r0->div_t[k]);
    out("\n|---|");
    for (k = 0; k < r0->ndiv; ++k) out("---:|");
    out("\n");
    for (i = 0; i < np; ++i) {
        const run_result *r = find_result(all, n, &p[i].s);
        if (r == NULL) continue;
        out("| %s |", p[i].name);
        for (k = 0; k < r->ndiv; ++k) out(" %.2e |", r->div[k]);
        out("\n");
    }
    out("\n");
    out_measured();
}

/* Every table, in the order tables.md holds them. */
/* One table by its heading, without the heading (--render DIR --section TITLE). */
static int print_section(const char *title, const run_result *all, int n, const run_result *base)
{
    g_no_heading = 1;
    if (strcmp(title, "Presets") == 0) print_presets(all, n);
    else if (strcmp(title, "What fixed point costs (the defaults, sleeping off)") == 0 && base != NULL) print_fixed_cost(base);
    else if (strcmp(title, "Rain 500: divergence from the reference over time") == 0) print_divergence(all, n);
    else if (strcmp(title, "Every run") == 0) print_all(all, n, base);
    else {
        fprintf(stderr, "pogon-accuracy: no section \"%s\" (Presets; What fixed point costs (the defaults, sleeping off); "
                        "Rain 500: divergence from the reference over time; Every run)\n", title);
        return 0;
    }
    return 1;
}

static void print_tables(const run_result *all, int n, const run_result *base)
{
    out("## pogon accuracy against time\n\n");
    out_measured();
    print_presets(all, n);
    if (base != NULL) print_fixed_cost(base);
    print_divergence(all, n);
    print_all(all, n, base);
}

/* ---- files ------------------------------------------------------------------------------------- */
static int make_dirs(const char *path)
{
    char buf[4096];
    size_t i, len = strlen(path);
    if (len == 0 || len >= sizeof buf) return 0;
    memcpy(buf, path, len + 1);
    for (i = 1; i <= len; ++i) {
        if (buf[i] == '/' || buf[i] == '\0') {
            char c = buf[i];
            buf[i] = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) return 0;
            buf[i] = c;
        }
    }
    return 1;
}

static FILE *open_out(const char *dir, const char *name)
{
    char path[4400];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (f == NULL) fprintf(stderr, "pogon-accuracy: cannot write %s: %s\n", path, strerror(errno));
    return f;
}

static int write_csv(const char *dir, const run_result *all, int n)
{
    FILE *f = open_out(dir, "results.csv"), *g;
    int i, j;
    if (f == NULL) return 0;
    fprintf(f, "scene,setting,value,error,error_unit,ms_per_step\n");
    for (i = 0; i < n; ++i) {
        char label[128];
        if (!all[i].ok) continue;
        setting_label(&all[i].s, label, sizeof label);
        for (j = 0; j < all[i].nrows; ++j) {
            const row *w = &all[i].rows[j];
            fprintf(f, "%s,%s,%.6g,%.6g,%s,%.6f\n", w->scene, label, w->value, w->error, w->unit, w->ms);
        }
    }
    if (fclose(f) != 0) return 0;
    g = open_out(dir, "rain_divergence.csv");
    if (g == NULL) return 0;
    fprintf(g, "setting,time_s,mean_position_difference_m\n");
    for (i = 0; i < n; ++i) {
        char label[128];
        if (!all[i].ok) continue;
        setting_label(&all[i].s, label, sizeof label);
        for (j = 0; j < all[i].ndiv; ++j) fprintf(g, "%s,%.4f,%.6g\n", label, all[i].div_t[j], all[i].div[j]);
    }
    return fclose(g) == 0;
}

static int parse_int(const char *t, int *v);

/* runs.tsv: a "measured" line (date, machine, command, settings, repeats, seconds), then
 * per setting a "setting" line and write_run's lines. Tabs separate the fields, so the
 * machine and the command may hold spaces but no tab. */
static int write_runs(const char *dir, const run_result *all, int n)
{
    FILE *f = open_out(dir, "runs.tsv");
    int i;
    if (f == NULL) return 0;
    fprintf(f, "measured\t%s\t%s\t%s\t%d\t%d\t%.0f\n", g_run.date, g_run.machine, g_run.command, g_run.settings, g_run.repeat,
            g_run.seconds);
    for (i = 0; i < n; ++i) {
        const setting *s = &all[i].s;
        if (!all[i].ok) continue;
        fprintf(f, "setting\t%d\t%d\t%d\t%ld\t%d\t%d\t%d\n", s->substeps, s->hertz, s->bits, (long)s->push, s->rate, s->sleep,
                s->ccd);
        write_run(f, &all[i]);
    }
    return fclose(f) == 0;
}

/* Copies the tab-separated field number `k` (0 = the line's tag) of `line` into out. */
static int tsv_field(const char *line, int k, char *out, size_t size)
{
    const char *p = line, *end;
    size_t len;
    while (k-- > 0) {
        p = strchr(p, '\t');
        if (p == NULL) return 0;
        ++p;
    }
    end = p + strcspn(p, "\t\r\n");
    len = (size_t)(end - p);
    if (len >= size) return 0;
    memcpy(out, p, len);
    out[len] = '\0';
    return 1;
}

/* Reads DIR/runs.tsv into all[] and g_run; returns the number of runs, or -1 with a message
 * naming the file and line. */
static int read_runs(const char *dir, run_result *all, int cap)
{
    char path[4400], line[1024];
    FILE *f;
    int n = 0, lineno = 0, have_measured = 0, open_run = 0;
    snprintf(path, sizeof path, "%s/runs.tsv", dir);
    f = fopen(path, "r");
    if (f == NULL) {
        fprintf(stderr, "pogon-accuracy: cannot read %s: %s (write it with --out %s)\n", path, strerror(errno), dir);
        return -1;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        ++lineno;
        if (strncmp(line, "measured\t", 9) == 0) {
            char a[32], b[32], c[32];
            if (!tsv_field(line, 1, g_run.date, sizeof g_run.date) || !tsv_field(line, 2, g_run.machine, sizeof g_run.machine) ||
                !tsv_field(line, 3, g_run.command, sizeof g_run.command) || !tsv_field(line, 4, a, sizeof a) ||
                !tsv_field(line, 5, b, sizeof b) || !tsv_field(line, 6, c, sizeof c) || !parse_int(a, &g_run.settings) ||
                !parse_int(b, &g_run.repeat)) {
                fprintf(stderr, "pogon-accuracy: %s:%d: malformed measured line\n", path, lineno);
                fclose(f);
                return -1;
            }
            g_run.seconds = strtod(c, NULL);
            have_measured = 1;
        } else if (strncmp(line, "setting\t", 8) == 0) {
            long push;
            setting s;
            if (n >= cap || open_run ||
                sscanf(line, "setting\t%d\t%d\t%d\t%ld\t%d\t%d\t%d", &s.substeps, &s.hertz, &s.bits, &push, &s.rate, &s.sleep,
                       &s.ccd) != 7) {
                fprintf(stderr, "pogon-accuracy: %s:%d: malformed or unexpected setting line\n", path, lineno);
                fclose(f);
                return -1;
            }
            s.push = (pg_fix)push;
            memset(&all[n], 0, sizeof all[n]);
            all[n].s = s;
            open_run = 1;
        } else if (open_run) {
            if (read_run_line(&all[n], line)) {
                all[n++].ok = 1;
                open_run = 0;
            }
        } else {
            fprintf(stderr, "pogon-accuracy: %s:%d: a line outside any setting\n", path, lineno);
            fclose(f);
            return -1;
        }
    }
    fclose(f);
    if (!have_measured || open_run || n == 0) {
        fprintf(stderr, "pogon-accuracy: %s: %s\n", path,
                !have_measured ? "no measured line" : open_run ? "the last run has no done line" : "no runs");
        return -1;
    }
    return n;
}

static void describe_machine(char *out, size_t size)
{
    char model[160] = "unknown CPU", line[512];
    double load = -1;
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f != NULL) {
        while (fgets(line, sizeof line, f) != NULL) {
            if (strncmp(line, "model name", 10) == 0 && strchr(line, ':') != NULL) {
                snprintf(model, sizeof model, "%s", strchr(line, ':') + 2);
                model[strcspn(model, "\r\n\t")] = '\0';
                break;
            }
        }
        fclose(f);
    }
    f = fopen("/proc/loadavg", "r");
    if (f != NULL) {
        if (fscanf(f, "%lf", &load) != 1) load = -1;
        fclose(f);
    }
    if (load >= 0) snprintf(out, size, "%s, %ld CPUs, load %.1f at the start", model, cpus, load);
    else snprintf(out, size, "%s, %ld CPUs", model, cpus);
}

/* ---- the chart --------------------------------------------------------------------------------- */
typedef struct point { double x, y; int color, front, preset; const char *label; } point;

static const char *const COLORS[] = {"#d62728", "#ff7f0e", "#2ca02c", "#1f77b4"}; /* substeps 1, 2, 4, 8 */

static int color_of(const setting *s) { return s->substeps >= 8 ? 3 : s->substeps >= 4 ? 2 : s->substeps >= 2 ? 1 : 0; }

static int cmp_point_x(const void *a, const void *b)
{
    const point *p = *(const point *const *)a, *q = *(const point *const *)b;
    if (p->x != q->x) return p->x < q->x ? -1 : 1;
    return p->y < q->y ? -1 : p->y > q->y;
}

/* Marks the points no other point beats in both time and error; returns them sorted by x. */
static int pareto(point *pts, int n, point **front)
{
    point *sorted[MAX_SETTINGS];
    double best = INFINITY;
    int i, m = 0;
    for (i = 0; i < n; ++i) sorted[i] = &pts[i];
    qsort(sorted, (size_t)n, sizeof sorted[0], cmp_point_x);
    for (i = 0; i < n; ++i) {
        sorted[i]->front = sorted[i]->y < best;
        if (sorted[i]->front) {
            best = sorted[i]->y;
            front[m++] = sorted[i];
        }
    }
    return m;
}

/* Tick values for a log axis from 10^lo to 10^hi: 1-2-5 steps, or finer / coarser to
 * get between 3 and 8 of them. */
static int log_ticks(double lo, double hi, double *out, int cap)
{
    static const double fine[] = {1, 1.5, 2, 3, 4, 5, 6, 7, 8, 9}, mid[] = {1, 2, 5}, coarse[] = {1};
    const double *sets[3];
    int sizes[3] = {10, 3, 1}, k, n = 0;
    sets[0] = fine;
    sets[1] = mid;
    sets[2] = coarse;
    for (k = 2; k >= 0; --k) {
        int d, j;
        n = 0;
        for (d = (int)floor(lo); d <= (int)ceil(hi); ++d)
            for (j = 0; j < sizes[k]; ++j) {
                double v = sets[k][j] * pow(10, d);
                if (log10(v) >= lo - 1e-9 && log10(v) <= hi + 1e-9 && n < cap) out[n++] = v;
            }
        if (n >= 3) break;
    }
    if (n > 8) { /* many decades: every other one */
        int m = 0, i;
        for (i = 0; i < n; i += 2) out[m++] = out[i];
        n = m;
    }
    return n;
}

static void svg_panel(FILE *f, double X, double Y, double W, double H, const char *title, const char *xlabel, const char *ylabel,
                      point *pts, int n, int big)
{
    double x0 = X + (big ? 70 : 52), y0 = Y + 28, w = W - (big ? 90 : 64), h = H - (big ? 70 : 62);
    double lx0 = INFINITY, lx1 = -INFINITY, ly0 = INFINITY, ly1 = -INFINITY;
    point *front[MAX_SETTINGS];
    int i, m;
    if (n == 0) return;
    for (i = 0; i < n; ++i) {
        double lx = log10(pts[i].x), ly = log10(pts[i].y);
        if (lx < lx0) lx0 = lx;
        if (lx > lx1) lx1 = lx;
        if (ly < ly0) ly0 = ly;
        if (ly > ly1) ly1 = ly;
    }
    lx0 = floor(lx0 * 10) / 10 - 0.05;
    lx1 = ceil(lx1 * 10) / 10 + 0.05;
    ly0 = floor(ly0) - 0.0;
    ly1 = ceil(ly1) + 0.0;
    if (ly1 - ly0 < 1) ly1 = ly0 + 1;
    if (lx1 - lx0 < 0.2) { lx0 -= 0.1; lx1 += 0.1; }
#define PX(v) (x0 + (log10(v) - lx0) / (lx1 - lx0) * w)
#define PY(v) (y0 + h - (log10(v) - ly0) / (ly1 - ly0) * h)
    fprintf(f, "<g>\n<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fff\" stroke=\"#ccc\"/>\n", x0, y0, w, h);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\" font-weight=\"bold\">%s</text>\n", X + 8, Y + 18, big ? 15 : 12, title);
    {
        double tv[64];
        int nt = log_ticks(ly0, ly1, tv, 64), q;
        for (q = 0; q < nt; ++q) {
            double py = PY(tv[q]);
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#eee\"/>\n", x0, py, x0 + w, py);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"end\">%.3g</text>\n", x0 - 4, py + 3, tv[q]);
        }
        nt = log_ticks(lx0, lx1, tv, 64);
        for (q = 0; q < nt; ++q) {
            double px = PX(tv[q]);
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#eee\"/>\n", px, y0, px, y0 + h);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"middle\">%.3g</text>\n", px, y0 + h + 13, tv[q]);
        }
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\">%s</text>\n", x0 + w / 2, y0 + h + (big ? 32 : 28), xlabel);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">%s</text>\n",
            X + 12, y0 + h / 2, X + 12, y0 + h / 2, ylabel);
    m = pareto(pts, n, front);
    if (m > 1) {
        fprintf(f, "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\" stroke-dasharray=\"4 2\" points=\"");
        for (i = 0; i < m; ++i) fprintf(f, "%.1f,%.1f ", PX(front[i]->x), PY(front[i]->y));
        fprintf(f, "\"/>\n");
    }
    for (i = 0; i < n; ++i) {
        const point *p = &pts[i];
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\" fill-opacity=\"%s\" stroke=\"%s\" stroke-width=\"%s\"><title>%s</title></circle>\n",
                PX(p->x), PY(p->y), p->front ? (big ? 6.0 : 4.5) : (big ? 4.0 : 3.0), COLORS[p->color], p->front ? "1" : "0.35",
                p->front ? "#000" : "none", p->front ? "1.5" : "0", p->label);
        if (p->preset >= 0)
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\" font-weight=\"bold\">%s</text>\n", PX(p->x) + 7, PY(p->y) - 6,
                    big ? 12 : 9, p->preset == 0 ? "fast" : p->preset == 1 ? "balanced" : "accurate");
        else if (big && p->front)
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9\" fill=\"#444\">%s</text>\n", PX(p->x) + 7, PY(p->y) + 12, p->label);
    }
    fprintf(f, "</g>\n");
#undef PX
#undef PY
}

static int write_svg(const char *dir, const run_result *all, int n, const run_result *base)
{
    static point pts[MAX_SETTINGS];
    static char labels[MAX_SETTINGS][128];
    preset p[3];
    FILE *f = open_out(dir, "pareto.svg");
    const double W = 1200, BIG_H = 560, SMALL_W = 300, SMALL_H = 250;
    int np = presets(p), i, j, k, m;
    if (f == NULL) return 0;
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
               "font-family=\"sans-serif\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"#fafafa\"/>\n",
            W, BIG_H + 3 * SMALL_H + 20, W, BIG_H + 3 * SMALL_H + 20);
    m = 0;
    for (i = 0; i < n; ++i) {
        if (!all[i].ok) continue;
        setting_label(&all[i].s, labels[m], sizeof labels[m]);
        pts[m].x = heavy_ms_per_second(&all[i]);
        pts[m].y = score(&all[i], base);
        pts[m].color = color_of(&all[i].s);
        pts[m].label = labels[m];
        pts[m].preset = -1;
        for (k = 0; k < np; ++k)
            if (setting_equal(&all[i].s, &p[k].s)) pts[m].preset = k;
        ++m;
    }
    svg_panel(f, 0, 0, W, BIG_H - 20, "pogon: accuracy against time, all scenes (Pareto front: black outline, dashed)",
              "ms of CPU per simulated second: pyramid (210 boxes) + rain 500 + stack 20, sleeping off",
              "error score: geometric mean of error / defaults' error (rain excluded)", pts, m, 1);
    /* legend */
    for (k = 0; k < 4; ++k) {
        static const char *const names[] = {"1 substep", "2 substeps", "4 substeps", "8 substeps"};
        fprintf(f, "<circle cx=\"%.0f\" cy=\"%.0f\" r=\"5\" fill=\"%s\"/><text x=\"%.0f\" y=\"%.0f\" font-size=\"11\">%s</text>\n",
                W - 130, 50.0 + 16 * k, COLORS[k], W - 120, 54.0 + 16 * k, names[k]);
    }
    for (j = 0; j < N_SCENES; ++j) {
        char title[96], ylabel[64];
        const char *unit = "";
        m = 0;
        for (i = 0; i < n; ++i) {
            const row *w;
            if (!all[i].ok || (w = find_row(&all[i], SCENES[j])) == NULL) continue;
            setting_label(&all[i].s, labels[m], sizeof labels[m]);
            unit = w->unit;
            pts[m].x = w->ms * 1000.0; /* microseconds per step */
            pts[m].y = w->error > FLOOR * 1e-3 ? w->error : FLOOR * 1e-3;
            pts[m].color = color_of(&all[i].s);
            pts[m].label = labels[m];
            pts[m].preset = -1;
            for (k = 0; k < np; ++k)
                if (setting_equal(&all[i].s, &p[k].s)) pts[m].preset = k;
            ++m;
        }
        snprintf(title, sizeof title, "%s", SHORT[j]);
        snprintf(ylabel, sizeof ylabel, "error (%s)", unit);
        svg_panel(f, (j % 4) * SMALL_W, BIG_H + (j / 4) * SMALL_H, SMALL_W, SMALL_H, title, "us per step", ylabel, pts, m, 0);
    }
    fprintf(f, "</svg>\n");
    return fclose(f) == 0;
}

/* ---- main -------------------------------------------------------------------------------------- */
static int parse_int(const char *t, int *v)
{
    char *end;
    long x;
    if (t == NULL) return 0;
    errno = 0;
    x = strtol(t, &end, 10);
    if (errno != 0 || *end != '\0' || x < -2147483647L || x > 2147483647L) return 0;
    *v = (int)x;
    return 1;
}

static void usage_to(FILE *f)
{
    fprintf(f, "usage: pogon-accuracy [--out DIR] [--quick] [--repeat N]\n"
               "       pogon-accuracy --render DIR [--section TITLE]\n"
               "       pogon-accuracy --worker SUBSTEPS HERTZ BITS PUSH_RAW RATE SLEEP CCD REPEAT\n"
               "Measures the accuracy of each solver setting against a double reference and its time,\n"
               "and prints the tables (to DIR/tables.md with --out). A full sweep runs every setting\n"
               "--repeat times (default 3) and takes tens of seconds; --quick runs fewer settings once.\n"
               "--render prints the tables of DIR/runs.tsv without measuring.\n"
               "--worker is how the sweep runs settings built with another sine table.\n");
}
static void usage(void) { usage_to(stderr); }

int main(int argc, char **argv)
{
    static run_result all[MAX_SETTINGS];
    static setting list[MAX_SETTINGS];
    const char *outdir = NULL;
    char dir[4096];
    int quick = 0, repeat = 0, i, n, failures = 0;
    const run_result *base;
    double t_start = wall_ms();

    if (argc >= 2 && strcmp(argv[1], "--worker") == 0) {
        setting s;
        int v[8], k, push;
        run_result r;
        if (argc != 10) { usage(); return 2; }
        for (k = 0; k < 8; ++k)
            if (!parse_int(argv[2 + k], &v[k])) { usage(); return 2; }
        s.substeps = v[0];
        s.hertz = v[1];
        s.bits = v[2];
        push = v[3];
        s.push = (pg_fix)push;
        s.rate = v[4];
        s.sleep = v[5];
        s.ccd = v[6];
        if (s.bits != PG_TRIG_TABLE_BITS || v[7] < 1 || v[7] > MAX_REPEAT) {
            fprintf(stderr, "pogon-accuracy: this build has a %d-bit table, asked for %d\n", PG_TRIG_TABLE_BITS, s.bits);
            return 2;
        }
        if (!run_local(&s, v[7], 1, &r)) return 1;
        print_worker(&r);
        return 0;
    }
    if (argc >= 2 && strcmp(argv[1], "--render") == 0) {
        char title[256] = "";
        if (argc < 3 || (argc > 3 && (strcmp(argv[3], "--section") != 0 || argc < 5))) { usage(); return 2; }
        for (i = 4; i < argc; ++i) { /* the title's words, as a document's marker splits them */
            size_t len = strlen(title);
            snprintf(title + len, sizeof title - len, "%s%s", i > 4 ? " " : "", argv[i]);
        }
        n = read_runs(argv[2], all, MAX_SETTINGS);
        if (n < 0) return 1;
        {
            setting b = balanced_setting();
            base = find_result(all, n, &b);
        }
        if (argc > 3) return print_section(title, all, n, base) ? 0 : 2;
        print_tables(all, n, base);
        return base != NULL ? 0 : 1;
    }
    {
        /* the command as run, with the program's own name: "pogon-accuracy --out DIR ..." */
        const char *name = strrchr(argv[0], '/');
        size_t len;
        snprintf(g_run.command, sizeof g_run.command, "%s", name != NULL ? name + 1 : argv[0]);
        for (i = 1; i < argc; ++i) {
            len = strlen(g_run.command);
            snprintf(g_run.command + len, sizeof g_run.command - len, " %s", argv[i]);
        }
        g_run.command[strcspn(g_run.command, "\t\r\n")] = '\0';
    }
    {
        time_t now = time(NULL);
        struct tm tm;
        if (gmtime_r(&now, &tm) == NULL || strftime(g_run.date, sizeof g_run.date, "%Y-%m-%d %H:%M UTC", &tm) == 0)
            snprintf(g_run.date, sizeof g_run.date, "unknown date");
    }
    describe_machine(g_run.machine, sizeof g_run.machine);
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage_to(stdout);
            return 0;
        }
    }
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) outdir = argv[++i];
        else if (strcmp(argv[i], "--quick") == 0) quick = 1;
        else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc && parse_int(argv[i + 1], &repeat) && repeat >= 1 &&
                 repeat <= MAX_REPEAT) ++i;
        else { usage(); return 2; }
    }
    if (repeat == 0) repeat = quick ? 1 : 3;
    self_dir(argv[0], dir, sizeof dir);
    n = sweep(list, quick);
    fprintf(stderr, "pogon-accuracy: %d settings, %d repeat(s), this build's sine table: %d bits\n", n, repeat, PG_TRIG_TABLE_BITS);
    if (argc == 1)
        fprintf(stderr, "pogon-accuracy: running the full sweep (tens of seconds); --quick for a short run, --help for options\n");
    for (i = 0; i < n; ++i) {
        char label[128];
        setting b = balanced_setting();
        int cost = setting_equal(&list[i], &b);
        setting_label(&list[i], label, sizeof label);
        fprintf(stderr, "  [%2d/%d] %s\n", i + 1, n, label);
        if (list[i].bits == PG_TRIG_TABLE_BITS) run_local(&list[i], repeat, cost ? repeat : 1, &all[i]);
        else run_worker(dir, &list[i], repeat, &all[i]);
        if (!all[i].ok) {
            fprintf(stderr, "pogon-accuracy: setting %s failed\n", label);
            ++failures;
        }
    }
    {
        setting b = balanced_setting();
        base = find_result(all, n, &b);
    }
    if (outdir != NULL) {
        char path[4400];
        if (!make_dirs(outdir)) {
            fprintf(stderr, "pogon-accuracy: cannot create %s\n", outdir);
            return 1;
        }
        snprintf(path, sizeof path, "%s/tables.md", outdir);
        g_md = fopen(path, "w");
        if (g_md == NULL) {
            fprintf(stderr, "pogon-accuracy: cannot write %s\n", path);
            return 1;
        }
    }
    g_run.settings = n;
    g_run.repeat = repeat;
    g_run.seconds = (wall_ms() - t_start) / 1000.0;
    print_tables(all, n, base);
    if (g_md != NULL && fclose(g_md) != 0) ++failures;
    g_md = NULL;
    if (outdir != NULL) {
        if (!write_csv(outdir, all, n) || !write_svg(outdir, all, n, base) || !write_runs(outdir, all, n)) ++failures;
        else fprintf(stderr, "pogon-accuracy: wrote %s/results.csv, rain_divergence.csv, runs.tsv, pareto.svg, tables.md\n", outdir);
    }
    return failures == 0 && base != NULL ? 0 : 1;
}
