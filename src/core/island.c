/* island.c — sleeping. Bodies at rest accumulate a sleep timer; bodies that touch form
 * islands (union-find over touching contacts and joints between moving bodies, the lower index
 * always the root, so the result is a pure function of the state); an island whose
 * every body has rested for time_to_sleep falls asleep at once. A sleeping body keeps
 * the lowest body index of its island, so waking one wakes the whole island. */
#include "island.h"
#include "world_types.h"

static uint32_t find_root(uint32_t *parent, uint32_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void unite(uint32_t *parent, uint32_t a, uint32_t b)
{
    uint32_t ra = find_root(parent, a), rb = find_root(parent, b);
    if (ra < rb) parent[rb] = ra;
    else if (rb < ra) parent[ra] = rb;
}

/* Rest is counted in whole steps: an island sleeps after time_to_sleep x step_hz steps
 * at rest, rounded to the nearest step (30 for 0.5 s at 60 Hz; 5 for 0.1 s at 50 Hz,
 * although 0.1 is 0.10000610 in Q16.16). Comparing the summed seconds instead took 31
 * at 60 Hz, because dt = 1/60 s rounds down to 1092 / 65536 s and 30 of them fall 8 LSB
 * short of 0.5 s. `rested` is a whole number of dt (a restored value is rounded). */
static int rested_long_enough(const pg_world *w, pg_fix rested, pg_fix dt)
{
    int64_t steps = ((int64_t)rested + dt / 2) / dt;
    int64_t needed = ((int64_t)w->def.time_to_sleep * w->def.step_hz + 32768) / 65536;
    return steps >= needed;
}

/* The same test as one comparison, rested >= rest_threshold(w, dt), for the loops over
 * bodies (two divisions per body before). With x = rested + dt / 2 and dt > 0, C's
 * truncating x / dt is at least needed >= 1 exactly when x >= needed dt, and at least
 * needed <= 0 exactly when x > (needed - 1) dt. |needed| < 2^26 (time_to_sleep < 2^31,
 * step_hz <= 1000) and dt <= 2^16: the products fit. */
static int64_t rest_threshold(const pg_world *w, pg_fix dt)
{
    int64_t needed = ((int64_t)w->def.time_to_sleep * w->def.step_hz + 32768) / 65536;
    return (needed > 0 ? needed * dt : (needed - 1) * dt + 1) - dt / 2;
}

/* An upper bound on how far any point of body b lies from its centre of mass (Q16.16 m):
 * the farthest vertex of its shapes plus that shape's radius, the square root rounded up. */
static int64_t body_extent(const pg_world *w, const pg_body *b)
{
    int64_t extent = 0;
    uint32_t s;
    for (s = b->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next) {
        const pg_geom *g = &w->shapes[s].local;
        int32_t k;
        for (k = 0; k < g->count; ++k) {
            /* body-frame coordinates within the envelope (50 m): |d| < 2^24, d^2 < 2^49 */
            int64_t dx = (int64_t)g->vertices[k].x - b->local_center.x, dy = (int64_t)g->vertices[k].y - b->local_center.y;
            int64_t e = (int64_t)pg_isqrt64((uint64_t)(dx * dx + dy * dy)) + 1 + g->radius;
            if (e > extent) extent = e;
        }
    }
    return extent;
}

/* Whether a body whose centre moves at (vx, vy) and turns at w (Q16.16 m/s and rad/s,
 * any int64) is slow enough to rest: its centre no faster than the linear tolerance, and
 * either it turns no faster than the angular tolerance or no point of it moves faster than
 * the linear tolerance (|v| + extent |w|, Box2D v3's measure). The second clause lets small
 * round bodies rest: a ball of radius 0.08 m rolling at 6 mm/s turns at 0.075 rad/s, twice
 * the angular tolerance, and with nothing to slow a rolling ball it kept its whole pile
 * awake. It is evaluated only when the first fails (rarely). */
static int slow_enough(const pg_world *w, const pg_body *b, int64_t vx, int64_t vy, int64_t wr, int64_t lin_tol2, pg_fix ang_tol)
{
    int64_t v2, turn, left;
    if (vx > PG_FIX_MAX || vx < -PG_FIX_MAX || vy > PG_FIX_MAX || vy < -PG_FIX_MAX) return 0; /* far too fast */
    v2 = vx * vx + vy * vy;
    if (v2 > lin_tol2) return 0;
    if (wr <= ang_tol && wr >= -ang_tol) return 1;
    if (wr > PG_FIX_MAX || wr < -PG_FIX_MAX) return 0;
    /* extent < 2^25 and |wr| < 2^31: the product fits */
    turn = pg__round_shift64(body_extent(w, b) * (wr < 0 ? -wr : wr), 16);
    left = (int64_t)w->def.sleep_linear_tolerance - turn;
    return left >= 0 && v2 <= left * left;
}

/* Whether body i is at rest (REST), moving (MOVING), or moved by the deep push only
 * (PUSHED), by two measures of its speed: the velocity it ends the step with, and its
 * motion in the step (how far its centre moved and how far it turned from where it was
 * when the step began, times the step rate). Either one slow is rest, but for a body the
 * deep push moves, which only its motion shows.
 * - Slow motion, fast velocity: under a heavy load (the bottom of a pile 60 m deep) one
 *   relax pass a substep leaves a few cm/s of velocity that the next step's soft pass takes
 *   back; the body stays where it is. That velocity kept a settled 4 000-body pile awake.
 * - Slow velocity, fast motion: the soft pass moves a resting body back and forth within a
 *   step (its push-out velocity, taken off again by the relax pass), which kept a settled
 *   1 000-body pile awake when motion alone was tested. But the deep push moves positions
 *   without velocity (docs/solver-design.md, DEEP PUSH): a body with a push impulse on one
 *   of its contacts and a slow velocity but fast motion is PUSHED. Its island does not
 *   sleep in this step, but its rest is not reset either: the push comes and goes at single
 *   points of a settled pile, and resetting it there kept a 1 000-body pile awake twice as
 *   long. A push that is still separating bodies keeps them awake
 *   (test_slow_push_out_is_not_put_to_sleep), and they sleep only after their timer has run
 *   out since it stopped. */
enum { MOVING, REST, PUSHED };
static int body_rest_state(const pg_world *w, uint32_t i, int64_t lin_tol2, pg_fix ang_tol)
{
    const pg_body *b = &w->bodies[i];
    const pg_step_start *s = &w->step_start[i];
    int64_t hz = (int64_t)w->def.step_hz, moved_x, moved_y, turned;
    int32_t turn = (int32_t)(b->angle - s->angle); /* binary angle: wraps, defined on uint32 */
    int slow_velocity;
    if ((b->flags & PG_BODY_FLAG_ALLOW_SLEEP) == 0) return MOVING;
    slow_velocity = slow_enough(w, b, b->v.x, b->v.y, b->w, lin_tol2, ang_tol);
    if (slow_velocity && s->pushed == 0) return REST;
    /* |d| < 2^32 and step_hz <= 1000: the products fit; |turn| <= 2^31, times step_hz and
     * 2 pi (below 2^19): below 2^60 */
    moved_x = ((int64_t)b->center.x - s->center.x) * hz;
    moved_y = ((int64_t)b->center.y - s->center.y) * hz;
    turned = pg__round_shift64((int64_t)turn * hz * PG_FIX_TWO_PI, 32);
    if (slow_enough(w, b, moved_x, moved_y, turned, lin_tol2, ang_tol)) return REST;
    return slow_velocity ? PUSHED : MOVING;
}

void pg__note_step_start(pg_world *w)
{
    uint32_t i;
    for (i = 0; i < w->body_high; ++i) {
        const pg_body *b = &w->bodies[i];
        if (!pg__body_is_active(b)) continue;
        w->step_start[i].center = b->center;
        w->step_start[i].angle = b->angle;
    }
}

/* Mark the bodies of the contacts that hold a deep-push impulse after this step's solve. */
static void mark_pushed_bodies(pg_world *w)
{
    uint32_t i;
    for (i = 0; i < w->body_high; ++i) w->step_start[i].pushed = 0;
    for (i = 0; i < w->contact_count; ++i) {
        const pg_contact *c = &w->contacts[i];
        int32_t n = c->point_count; /* 0, 1 or 2 */
        if (!((n > 0 && c->points[0].push_impulse != 0) || (n > 1 && c->points[1].push_impulse != 0))) continue;
        w->step_start[c->body_a].pushed = 1;
        w->step_start[c->body_b].pushed = 1;
    }
}

static int body_still(const pg_body *b) { return b->v.x == 0 && b->v.y == 0 && b->w == 0; }

void pg__update_sleep(pg_world *w)
{
    uint32_t *parent = w->island_parent, i, n_contacts = w->contact_count;
    pg_fix dt = (pg_fix)((65536 + (int32_t)w->def.step_hz / 2) / (int32_t)w->def.step_hz);
    int64_t lin_tol2 = (int64_t)w->def.sleep_linear_tolerance * w->def.sleep_linear_tolerance, rest;
    pg_fix ang_tol = w->def.sleep_angular_tolerance;
    pg_fix *min_time = (pg_fix *)(void *)w->solver_scratch; /* solver scratch is free after the solve */
    pg_fix longest = 0; /* the longest rest of an awake body */
    int state;

    mark_pushed_bodies(w);

    /* parent[i] is PG_NULL_INDEX for a body that is not active (nothing here changes which
     * are until the last loop, and only active bodies are ever united), so the loops
     * below ask it instead of the body. */
    for (i = 0; i < w->body_high; ++i) {
        pg_body *b = &w->bodies[i];
        parent[i] = PG_NULL_INDEX;
        if (!pg__body_is_active(b)) continue;
        parent[i] = i;
        state = body_rest_state(w, i, lin_tol2, ang_tol);
        w->step_start[i].pushed = state == PUSHED; /* now: its island does not sleep this step */
        if (state == MOVING) {
            b->sleep_time = 0;
        } else if (state == REST && b->sleep_time < PG_FIX_C(1000)) {
            b->sleep_time += dt;
        }
        if (b->sleep_time > longest) longest = b->sleep_time;
    }
    /* An island sleeps when its shortest rest is long enough; when even the longest is not,
     * none can, and the islands need not be found (rain: most of the pile is moving). */
    if (!rested_long_enough(w, longest, dt)) return;
    for (i = 0; i < n_contacts; ++i) {
        const pg_contact *c = &w->contacts[i];
        if (c->point_count == 0 || parent[c->body_a] == PG_NULL_INDEX || parent[c->body_b] == PG_NULL_INDEX) continue;
        if (w->bodies[c->body_a].type == PG_BODY_DYNAMIC && w->bodies[c->body_b].type == PG_BODY_DYNAMIC)
            unite(parent, c->body_a, c->body_b);
    }
    /* a joint links the islands of two dynamic bodies; one to a static or kinematic body
     * does not (as a contact), but a kinematic body that moves keeps the other awake */
    for (i = 0; i < w->joint_high; ++i) {
        const pg_joint *j = &w->joints[i];
        uint32_t a = j->body_a, b = j->body_b;
        if ((j->flags & PG_JOINT_FLAG_USED) == 0 || a == PG_NULL_INDEX) continue;
        if (parent[a] != PG_NULL_INDEX && parent[b] != PG_NULL_INDEX && w->bodies[a].type == PG_BODY_DYNAMIC &&
            w->bodies[b].type == PG_BODY_DYNAMIC)
            unite(parent, a, b);
    }
    /* Each active body's root, kept in parent[i] so the loops below read it directly. The
     * root is the lowest index of its island (at most i) and is itself active, so its
     * min_time was initialised earlier in this same loop. */
    for (i = 0; i < w->body_high; ++i) {
        uint32_t r;
        min_time[i] = PG_FIX_MAX;
        if (parent[i] == PG_NULL_INDEX) continue;
        r = find_root(parent, i);
        parent[i] = r;
        if (w->bodies[i].sleep_time < min_time[r]) min_time[r] = w->bodies[i].sleep_time;
        if (w->step_start[i].pushed) min_time[r] = 0; /* moved by the deep push in this step */
    }
    for (i = 0; i < w->joint_high; ++i) {
        const pg_joint *j = &w->joints[i];
        uint32_t a = j->body_a, b = j->body_b;
        if ((j->flags & PG_JOINT_FLAG_USED) == 0 || a == PG_NULL_INDEX) continue;
        if (w->bodies[a].type == PG_BODY_KINEMATIC && parent[b] != PG_NULL_INDEX && !body_still(&w->bodies[a])) min_time[parent[b]] = 0;
        if (w->bodies[b].type == PG_BODY_KINEMATIC && parent[a] != PG_NULL_INDEX && !body_still(&w->bodies[b])) min_time[parent[a]] = 0;
    }
    rest = rest_threshold(w, dt);
    for (i = 0; i < w->body_high; ++i) {
        uint32_t r = parent[i];
        if (r == PG_NULL_INDEX || min_time[r] < rest) continue;
        {
            /* its cached world geometry is from the start of this step: recompute it at
             * the next, so cached geometry is always a function of the saved state */
            pg_body *b = &w->bodies[i];
            b->flags = (b->flags & ~(uint32_t)PG_BODY_FLAG_AWAKE) | PG_BODY_FLAG_GEOMETRY_DIRTY;
            b->v = pg_v2_zero();
            b->w = 0;
            b->island = r;
        }
    }
}

void pg__wake_joined_bodies(pg_world *world)
{
    uint32_t i;
    for (i = 0; i < world->joint_high; ++i) {
        const pg_joint *j = &world->joints[i];
        const pg_body *a, *b;
        if ((j->flags & PG_JOINT_FLAG_USED) == 0 || j->body_a == PG_NULL_INDEX) continue;
        a = &world->bodies[j->body_a];
        b = &world->bodies[j->body_b];
        if (pg__body_is_active(a) && b->type == PG_BODY_DYNAMIC && !pg__body_is_active(b)) pg__wake_body(world, j->body_b);
        if (pg__body_is_active(b) && a->type == PG_BODY_DYNAMIC && !pg__body_is_active(a)) pg__wake_body(world, j->body_a);
    }
}

void pg__wake_body(pg_world *world, uint32_t body_index)
{
    pg_body *b = &world->bodies[body_index];
    uint32_t island = b->island, i;
    if (b->type == PG_BODY_STATIC) return;
    if ((b->flags & PG_BODY_FLAG_AWAKE) != 0) {
        b->sleep_time = 0;
        return;
    }
    if (island == PG_NULL_INDEX) {
        b->flags |= PG_BODY_FLAG_AWAKE;
        b->sleep_time = 0;
        return;
    }
    for (i = 0; i < world->body_high; ++i) {
        pg_body *o = &world->bodies[i];
        if ((o->flags & PG_BODY_FLAG_USED) != 0 && (o->flags & PG_BODY_FLAG_AWAKE) == 0 && o->island == island) {
            o->flags |= PG_BODY_FLAG_AWAKE;
            o->sleep_time = 0;
            o->island = PG_NULL_INDEX;
        }
    }
}
