/* ref.c — pogon's step in double precision, circles and boxes only (see ref.h).
 * Each function follows the pogon function named in its comment; the formulas are the
 * same, written for real numbers instead of Q16.16/Q2.30 integers. */
#include "ref.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define REF_SPECULATIVE 0.02          /* PG_SPECULATIVE_DISTANCE */
#define REF_TOLERANCE (33.0 / 65536.0) /* PG__REF_TOLERANCE: 0.1 linear slop */
#define REF_PI 3.14159265358979323846

#define KIND_FACE_A 0u
#define KIND_FACE_B 1u
#define KIND_POINTS 2u
#define ID(kind, ia, ib) (((unsigned)(kind) << 16) | ((unsigned)(ia) << 8) | (unsigned)(ib))

typedef struct vec { double x, y; } vec;

static vec v2(double x, double y) { vec v; v.x = x; v.y = y; return v; }
static vec vadd(vec a, vec b) { return v2(a.x + b.x, a.y + b.y); }
static vec vsub(vec a, vec b) { return v2(a.x - b.x, a.y - b.y); }
static vec vscale(vec a, double s) { return v2(a.x * s, a.y * s); }
static double vdot(vec a, vec b) { return a.x * b.x + a.y * b.y; }
static double vcross(vec a, vec b) { return a.x * b.y - a.y * b.x; }
static double vlen(vec a) { return sqrt(a.x * a.x + a.y * a.y); }
static vec vnorm(vec a)
{
    double l = vlen(a);
    return l > 0 ? vscale(a, 1.0 / l) : v2(0, 0);
}
static vec tangent_ccw(vec n) { return v2(-n.y, n.x); } /* collide.c: along v[i] -> v[i+1] */

typedef struct geom {
    int count;        /* 1: circle, 4: box */
    double radius;
    vec v[4], n[4];
} geom;

typedef struct body {
    int dynamic;
    geom local, world;
    vec c, vel;       /* centre (= origin: the shapes are centred), velocity */
    double a, w;
    double im, ii;    /* inverse mass and inertia (0 for static) */
    double friction, restitution;
    double lo_x, lo_y, hi_x, hi_y;
    int placed;       /* static bodies are placed once */
} body;

typedef struct cpoint {
    vec p;
    double sep;
    unsigned id;
    double ln, lt;    /* stored lambdas (m/s) */
    double pl;        /* stored pseudo lambda (pogon's DEEP PUSH) */
} cpoint;

typedef struct contact {
    int a, b;
    vec n;
    int count;
    cpoint p[2];
    double friction, restitution;
} contact;

typedef struct manifold { vec n; int count; cpoint p[2]; } manifold;

typedef struct spoint {
    vec rA, rB;
    double adjusted;
    double cnA, cnB, ctA, ctB;
    vec lnA, lnB, ltA, ltB;     /* kA n, kB n, kA t, kB t */
    double gnA, gnB, gtA, gtB;
    double friction_ratio, relative_velocity;
    double approach_start, approach_accel; /* pogon's APPROACH: at the step's start, and gravity's part per second */
    double ln, lt, max_ln;
    double Kn, Kt;              /* the rows' effective inverse masses */
    double s_soft, bias, deep_push, pl; /* DEEP PUSH: the soft pass's separation, its velocity
                                           bias, the excess for the pseudo row, and its lambda */
} spoint;

typedef struct sbody { vec v; double w; vec c0, c; double a0, a; double dqc, dqs; int dynamic, turns_anchors; vec pv; int pushed; } sbody;

typedef struct constraint {
    int a, b;         /* solver body index, or -1 for a static side */
    int contact;
    vec n;
    int count, soft_static;
    int round_a, round_b; /* a circle: its surface looks the same however it turns */
    double restitution;
    int block;        /* the two normal rows solved together, as pogon does */
    double e01, e10;  /* what a unit of lambda on point 1 does to point 0's normal speed, and back */
    int deep;         /* DEEP PUSH: a point has pushed past its velocity cap in this step */
    int central;      /* two points, friction on: one friction row at the mean anchor, in
                         p[0] (pogon's CENTRAL FRICTION) */
    spoint p[2];
} constraint;

typedef struct pair { int a, b; } pair;

struct ref_world {
    ref_def def;
    int capacity, count;
    body *bodies;
    int *order;       /* bodies sorted by lo_x (broadphase) */
    pair *pairs;
    int pair_count, pair_capacity;
    contact *contacts, *contacts_next;
    int contact_count, contact_capacity;
    sbody *sbodies;
    sbody dummy;
    constraint *cons;
    int *deep_list;   /* the constraints of a substep's pseudo pass (DEEP PUSH) */
};

ref_def ref_default_def(void)
{
    ref_def d;
    d.gravity_x = 0;
    d.gravity_y = -10;
    d.step_hz = 60;
    d.substeps = 4;
    d.hertz = 30;
    d.damping_ratio = 10;
    d.push_max = 3;
    d.restitution_threshold = 1;
    d.friction = d.restitution = d.rotation = d.continuous = 1;
    return d;
}

ref_world *ref_create(const ref_def *def, int capacity)
{
    ref_world *w = (ref_world *)calloc(1, sizeof *w);
    if (w == NULL) return NULL;
    w->def = *def;
    w->capacity = capacity;
    w->bodies = (body *)calloc((size_t)capacity, sizeof(body));
    w->order = (int *)calloc((size_t)capacity, sizeof(int));
    w->sbodies = (sbody *)calloc((size_t)capacity, sizeof(sbody));
    w->pair_capacity = capacity * 8 + 64;
    w->pairs = (pair *)calloc((size_t)w->pair_capacity, sizeof(pair));
    w->contact_capacity = w->pair_capacity;
    w->contacts = (contact *)calloc((size_t)w->contact_capacity, sizeof(contact));
    w->contacts_next = (contact *)calloc((size_t)w->contact_capacity, sizeof(contact));
    w->cons = (constraint *)calloc((size_t)w->contact_capacity, sizeof(constraint));
    w->deep_list = (int *)calloc((size_t)w->contact_capacity, sizeof(int));
    if (!w->bodies || !w->order || !w->sbodies || !w->pairs || !w->contacts || !w->contacts_next || !w->cons || !w->deep_list) {
        ref_destroy(w);
        return NULL;
    }
    return w;
}

void ref_destroy(ref_world *w)
{
    if (w == NULL) return;
    free(w->bodies);
    free(w->order);
    free(w->sbodies);
    free(w->pairs);
    free(w->contacts);
    free(w->contacts_next);
    free(w->deep_list);
    free(w->cons);
    free(w);
}

static int add_body(ref_world *w, int dynamic, double x, double y, double angle, double friction, double restitution)
{
    body *b;
    if (w->count >= w->capacity) return -1;
    b = &w->bodies[w->count];
    memset(b, 0, sizeof *b);
    b->dynamic = dynamic;
    b->c = v2(x, y);
    b->a = angle;
    b->friction = friction;
    b->restitution = restitution;
    w->order[w->count] = w->count;
    return w->count++;
}

int ref_add_box(ref_world *w, int dynamic, double x, double y, double angle, double hw, double hh, double density,
                double friction, double restitution)
{
    int i = add_body(w, dynamic, x, y, angle, friction, restitution), k;
    body *b;
    if (i < 0) return i;
    b = &w->bodies[i];
    b->local.count = 4;
    b->local.radius = 0;
    /* pg_geometry_box: counter-clockwise from (-hw, -hh) */
    b->local.v[0] = v2(-hw, -hh);
    b->local.v[1] = v2(hw, -hh);
    b->local.v[2] = v2(hw, hh);
    b->local.v[3] = v2(-hw, hh);
    for (k = 0; k < 4; ++k) {
        vec e = vsub(b->local.v[(k + 1) % 4], b->local.v[k]);
        b->local.n[k] = vnorm(v2(e.y, -e.x));
    }
    if (dynamic) {
        double m = density * 4.0 * hw * hh;
        b->im = 1.0 / m;
        b->ii = 1.0 / (m * (hw * hw + hh * hh) / 3.0); /* m (w^2 + h^2) / 12 with w = 2 hw */
    }
    return i;
}

int ref_add_circle(ref_world *w, int dynamic, double x, double y, double radius, double density, double friction,
                   double restitution)
{
    int i = add_body(w, dynamic, x, y, 0, friction, restitution);
    body *b;
    if (i < 0) return i;
    b = &w->bodies[i];
    b->local.count = 1;
    b->local.radius = radius;
    b->local.v[0] = v2(0, 0);
    if (dynamic) {
        double m = density * REF_PI * radius * radius;
        b->im = 1.0 / m;
        b->ii = 1.0 / (0.5 * m * radius * radius);
    }
    return i;
}

void ref_set_velocity(ref_world *w, int i, double vx, double vy, double omega)
{
    w->bodies[i].vel = v2(vx, vy);
    w->bodies[i].w = omega;
}

void ref_position(const ref_world *w, int i, double *x, double *y, double *angle)
{
    if (x) *x = w->bodies[i].c.x;
    if (y) *y = w->bodies[i].c.y;
    if (angle) *angle = w->bodies[i].a;
}

int ref_contact_count(const ref_world *w) { return w->contact_count; }

/* ---- geometry (pg__body_sync_geometry, pg_geom_transform, pg_geom_aabb) ------------- */
static void sync_geometry(ref_world *w, body *b)
{
    double c = cos(b->a), s = sin(b->a), sx = 0, sy = 0;
    int k;
    geom *g = &b->world;
    g->count = b->local.count;
    g->radius = b->local.radius;
    for (k = 0; k < g->count; ++k) {
        vec lv = b->local.v[k], ln = b->local.n[k];
        g->v[k] = vadd(b->c, v2(c * lv.x - s * lv.y, s * lv.x + c * lv.y));
        g->n[k] = v2(c * ln.x - s * ln.y, s * ln.x + c * ln.y);
    }
    b->lo_x = b->hi_x = g->v[0].x;
    b->lo_y = b->hi_y = g->v[0].y;
    for (k = 1; k < g->count; ++k) {
        if (g->v[k].x < b->lo_x) b->lo_x = g->v[k].x;
        if (g->v[k].x > b->hi_x) b->hi_x = g->v[k].x;
        if (g->v[k].y < b->lo_y) b->lo_y = g->v[k].y;
        if (g->v[k].y > b->hi_y) b->hi_y = g->v[k].y;
    }
    b->lo_x -= g->radius + REF_SPECULATIVE;
    b->lo_y -= g->radius + REF_SPECULATIVE;
    b->hi_x += g->radius + REF_SPECULATIVE;
    b->hi_y += g->radius + REF_SPECULATIVE;
    if (b->dynamic && w->def.continuous) {
        sx = fabs(b->vel.x) / w->def.step_hz;
        sy = fabs(b->vel.y) / w->def.step_hz;
    }
    if (b->vel.x < 0) b->lo_x -= sx; else b->hi_x += sx;
    if (b->vel.y < 0) b->lo_y -= sy; else b->hi_y += sy;
    b->placed = 1;
}

/* ---- narrowphase (collide.c) ---------------------------------------------------------- */
static void push(manifold *m, vec p, double sep, unsigned id)
{
    cpoint *c = &m->p[m->count++];
    c->p = p;
    c->sep = sep;
    c->id = id;
    c->ln = c->lt = 0;
}

/* a + ((b - a) + k n) / 2: pg__mid_half */
static vec mid_half(vec a, vec b, vec n, double k) { return vadd(a, vscale(vadd(vsub(b, a), vscale(n, k)), 0.5)); }
/* p + n k / 2: pg__add_half */
static vec add_half(vec p, vec n, double k) { return vadd(p, vscale(n, 0.5 * k)); }

static double face_offset(const geom *g, int i) { return 0.5 * (vdot(g->v[i], g->n[i]) + vdot(g->v[(i + 1) % g->count], g->n[i])); }

static void collide_circles(const geom *a, const geom *b, double spec, manifold *m)
{
    vec d = vsub(b->v[0], a->v[0]);
    double dist = vlen(d), sep = dist - a->radius - b->radius;
    vec n = dist == 0 ? v2(0, 1) : vscale(d, 1.0 / dist);
    if (sep > spec) return;
    m->n = n;
    push(m, mid_half(a->v[0], b->v[0], n, a->radius - b->radius), sep, ID(KIND_POINTS, 0, 0));
}

static void collide_poly_circle(const geom *poly, const geom *circ, int circle_is_a, double spec, manifold *m)
{
    vec c = circ->v[0], n, point;
    int i, face = 0, vertex = -1;
    double best = -INFINITY, radius = poly->radius + circ->radius, rdiff = poly->radius - circ->radius, sep;
    unsigned id;
    for (i = 0; i < poly->count; ++i) {
        double s = vdot(c, poly->n[i]) - face_offset(poly, i);
        if (s > best) { best = s; face = i; }
    }
    if (best > spec + radius) return;
    if (best > 0) {
        int i2 = (face + 1) % poly->count;
        vec t = tangent_ccw(poly->n[face]);
        if (vdot(vsub(c, poly->v[face]), t) < 0) vertex = face;
        else if (vdot(vsub(poly->v[i2], c), t) < 0) vertex = i2;
    }
    if (vertex >= 0 && vlen(vsub(c, poly->v[vertex])) != 0) {
        vec v = poly->v[vertex];
        double dist = vlen(vsub(c, v));
        sep = dist - radius;
        if (sep > spec) return;
        n = vnorm(vsub(c, v));
        point = mid_half(v, c, n, rdiff);
        id = circle_is_a ? ID(KIND_POINTS, 0, vertex) : ID(KIND_POINTS, vertex, 0);
    } else {
        n = poly->n[face];
        sep = best - radius;
        if (sep > spec) return;
        point = add_half(c, n, rdiff - best);
        id = circle_is_a ? ID(KIND_FACE_B, 0, face) : ID(KIND_FACE_A, face, 0);
    }
    m->n = circle_is_a ? v2(-n.x, -n.y) : n;
    push(m, point, sep, id);
}

static double max_separation(const geom *a, const geom *b, int *edge)
{
    double best = -INFINITY;
    int i, j;
    *edge = 0;
    for (i = 0; i < a->count; ++i) {
        double off = face_offset(a, i), si = INFINITY;
        for (j = 0; j < b->count; ++j) {
            double s = vdot(b->v[j], a->n[i]) - off;
            if (s < si) si = s;
        }
        if (si > best) { best = si; *edge = i; }
    }
    return best;
}

/* pg__point_segment: squared distance from p to a..b (normal n); *end 0/1 at an end, -1 inside. */
static double point_segment(vec p, vec a, vec b, vec n, int *end)
{
    vec t = tangent_ccw(n);
    double d;
    if (vdot(vsub(p, a), t) < -REF_TOLERANCE) { *end = 0; return vdot(vsub(p, a), vsub(p, a)); }
    if (vdot(vsub(b, p), t) < -REF_TOLERANCE) { *end = 1; return vdot(vsub(p, b), vsub(p, b)); }
    *end = -1;
    d = vdot(vsub(p, a), n);
    return d * d;
}

static void collide_polygons(const geom *a, const geom *b, double spec, manifold *m)
{
    const geom *ref, *inc;
    int ea, eb, i11, i12, i21, i22, j, k, flip, far;
    double sa = max_separation(a, b, &ea), sb = max_separation(b, a, &eb);
    double radius = a->radius + b->radius, rdiff, off, s21, s22, dl21, dl22, du21, du22, best_dot;
    vec n, t, v11, v12, v21, v22;
    unsigned kind;
    if (sa > spec + radius || sb > spec + radius) return;
    far = (sa > sb ? sa : sb) > REF_TOLERANCE;
    flip = far ? sb > sa : sb > sa + REF_TOLERANCE;
    ref = flip ? b : a;
    inc = flip ? a : b;
    i11 = flip ? eb : ea;
    i12 = (i11 + 1) % ref->count;
    n = ref->n[i11];
    t = tangent_ccw(n);
    j = 0;
    best_dot = INFINITY;
    for (k = 0; k < inc->count; ++k) {
        double dd = vdot(n, inc->n[k]);
        if (dd < best_dot) { best_dot = dd; j = k; }
    }
    i21 = j;
    i22 = (j + 1) % inc->count;
    v11 = ref->v[i11];
    v12 = ref->v[i12];
    v21 = inc->v[i21];
    v22 = inc->v[i22];
    rdiff = ref->radius - inc->radius;
    kind = flip ? KIND_FACE_B : KIND_FACE_A;

    if (far) {
        vec n2 = inc->n[j];
        double d2[4];
        int ends[4], best_k = 0, interior = 0;
        d2[0] = point_segment(v21, v11, v12, n, &ends[0]);
        d2[1] = point_segment(v22, v11, v12, n, &ends[1]);
        d2[2] = point_segment(v11, v21, v22, n2, &ends[2]);
        d2[3] = point_segment(v12, v21, v22, n2, &ends[3]);
        for (k = 1; k < 4; ++k)
            if (d2[k] < d2[best_k]) best_k = k;
        for (k = 0; k < 4; ++k)
            if (d2[k] == d2[best_k] && ends[k] < 0) interior = 1;
        if (!interior && d2[best_k] > 0) {
            int ir, ii, ia, ib;
            vec va, vb, nn;
            double dist, sep;
            if (best_k < 2) { ii = best_k == 0 ? i21 : i22; ir = ends[best_k] == 0 ? i11 : i12; }
            else { ir = best_k == 2 ? i11 : i12; ii = ends[best_k] == 0 ? i21 : i22; }
            ia = flip ? ii : ir;
            ib = flip ? ir : ii;
            va = a->v[ia];
            vb = b->v[ib];
            dist = vlen(vsub(vb, va));
            sep = dist - radius;
            if (sep > spec) return;
            nn = vnorm(vsub(vb, va));
            m->n = nn;
            push(m, mid_half(va, vb, nn, a->radius - b->radius), sep, ID(KIND_POINTS, ia, ib));
            return;
        }
    }

    off = face_offset(ref, i11);
    s21 = vdot(v21, n) - off;
    s22 = vdot(v22, n) - off;
    dl21 = vdot(vsub(v21, v11), t);
    dl22 = vdot(vsub(v22, v11), t);
    du21 = vdot(vsub(v12, v21), t);
    du22 = vdot(vsub(v12, v22), t);
    m->n = flip ? v2(-n.x, -n.y) : n;
    if ((dl21 < 0 && dl22 < 0) || (du21 < 0 && du22 < 0)) {
        int use21 = s21 <= s22;
        double s = use21 ? s21 : s22;
        int iv = use21 ? i21 : i22;
        vec v = use21 ? v21 : v22;
        if (s - radius <= spec) push(m, add_half(v, n, rdiff - s), s - radius, flip ? ID(kind, iv, i11) : ID(kind, i11, iv));
    } else {
        vec p[2];
        double sep[2];
        int iv[2];
        if (dl22 >= 0) {
            p[0] = add_half(v22, n, rdiff - s22);
            sep[0] = s22;
        } else {
            double h = (s22 * dl21 - s21 * dl22) / (dl21 - dl22), e = off - vdot(v11, n);
            p[0] = add_half(v11, n, 2 * e + h + rdiff);
            sep[0] = h;
        }
        iv[0] = i22;
        if (du21 >= 0) {
            p[1] = add_half(v21, n, rdiff - s21);
            sep[1] = s21;
        } else {
            double h = (s21 * du22 - s22 * du21) / (du22 - du21), e = off - vdot(v12, n);
            p[1] = add_half(v12, n, 2 * e + h + rdiff);
            sep[1] = h;
        }
        iv[1] = i21;
        for (k = 0; k < 2; ++k) {
            if (sep[k] - radius > spec) continue;
            if (k == 1 && m->count == 1 && m->p[0].p.x == p[1].x && m->p[0].p.y == p[1].y) continue;
            push(m, p[k], sep[k] - radius, flip ? ID(kind, iv[k], i11) : ID(kind, i11, iv[k]));
        }
    }
    if (m->count == 0) m->n = v2(0, 0);
}

static void collide(const geom *a, const geom *b, double spec, manifold *m)
{
    m->count = 0;
    m->n = v2(0, 0);
    if (a->count == 1 && b->count == 1) collide_circles(a, b, spec, m);
    else if (b->count == 1) collide_poly_circle(a, b, 0, spec, m);
    else if (a->count == 1) collide_poly_circle(b, a, 1, spec, m);
    else collide_polygons(a, b, spec, m);
}

/* ---- broadphase and the contact list (contact.c) ------------------------------------ */
static int cmp_pair(const void *pa, const void *pb)
{
    const pair *a = (const pair *)pa, *b = (const pair *)pb;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : a->b > b->b;
}

static void add_pair(ref_world *w, int i, int j)
{
    if (w->pair_count >= w->pair_capacity) {
        int cap = w->pair_capacity * 2;
        pair *np = (pair *)realloc(w->pairs, (size_t)cap * sizeof(pair));
        if (np == NULL) return;
        w->pairs = np;
        w->pair_capacity = cap;
    }
    w->pairs[w->pair_count].a = i < j ? i : j;
    w->pairs[w->pair_count].b = i < j ? j : i;
    ++w->pair_count;
}

static void find_pairs(ref_world *w)
{
    int i, j, n = w->count;
    /* sort and sweep on x; insertion sort (the order barely changes between steps) */
    for (i = 1; i < n; ++i) {
        int key = w->order[i];
        double kx = w->bodies[key].lo_x;
        j = i - 1;
        while (j >= 0 && w->bodies[w->order[j]].lo_x > kx) {
            w->order[j + 1] = w->order[j];
            --j;
        }
        w->order[j + 1] = key;
    }
    w->pair_count = 0;
    for (i = 0; i < n; ++i) {
        const body *a = &w->bodies[w->order[i]];
        for (j = i + 1; j < n; ++j) {
            const body *b = &w->bodies[w->order[j]];
            if (b->lo_x > a->hi_x) break;
            if (!a->dynamic && !b->dynamic) continue;
            if (b->lo_y > a->hi_y || b->hi_y < a->lo_y) continue;
            add_pair(w, w->order[i], w->order[j]);
        }
    }
    qsort(w->pairs, (size_t)w->pair_count, sizeof(pair), cmp_pair);
}

static void update_contacts(ref_world *w)
{
    int i = 0, j, out = 0;
    contact *old = w->contacts, *next = w->contacts_next;
    find_pairs(w);
    if (w->pair_count > w->contact_capacity) {
        int cap = w->pair_count * 2;
        contact *a = (contact *)realloc(w->contacts, (size_t)cap * sizeof(contact));
        contact *b = a ? (contact *)realloc(w->contacts_next, (size_t)cap * sizeof(contact)) : NULL;
        constraint *c = b ? (constraint *)realloc(w->cons, (size_t)cap * sizeof(constraint)) : NULL;
        if (a) w->contacts = a;
        if (b) w->contacts_next = b;
        if (c) w->cons = c;
        if (!a || !b || !c) return;
        w->contact_capacity = cap;
        old = w->contacts;
        next = w->contacts_next;
    }
    for (j = 0; j < w->pair_count; ++j) {
        int pa = w->pairs[j].a, pb = w->pairs[j].b, k, q;
        const contact *prev = NULL;
        const body *A = &w->bodies[pa], *B = &w->bodies[pb];
        contact *c = &next[out];
        manifold m;
        double spec = REF_SPECULATIVE;
        while (i < w->contact_count && (old[i].a < pa || (old[i].a == pa && old[i].b < pb))) ++i;
        if (i < w->contact_count && old[i].a == pa && old[i].b == pb) prev = &old[i];
        if (w->def.continuous) {
            double reach = (fabs(A->vel.x) + fabs(A->vel.y) + fabs(B->vel.x) + fabs(B->vel.y)) / w->def.step_hz;
            if (reach > spec) spec = reach;
        }
        collide(&A->world, &B->world, spec, &m);
        if (m.count == 0) continue;
        c->a = pa;
        c->b = pb;
        c->n = m.n;
        c->count = m.count;
        c->friction = sqrt(A->friction * B->friction);
        c->restitution = A->restitution > B->restitution ? A->restitution : B->restitution;
        for (k = 0; k < m.count; ++k) {
            c->p[k] = m.p[k];
            c->p[k].ln = c->p[k].lt = c->p[k].pl = 0;
            if (prev == NULL) continue;
            for (q = 0; q < prev->count; ++q)
                if (prev->p[q].id == c->p[k].id) {
                    c->p[k].ln = prev->p[q].ln;
                    c->p[k].lt = prev->p[q].lt;
                    c->p[k].pl = prev->p[q].pl;
                    break;
                }
        }
        ++out;
    }
    w->contacts = next;
    w->contacts_next = old;
    w->contact_count = out;
}

/* ---- solver (solver.c) ------------------------------------------------------------------ */
typedef struct softness { double bias_rate, mass_scale, impulse_scale; } softness;

static softness make_soft(double hertz, double zeta, double h)
{
    softness s;
    double omega = 2.0 * REF_PI * hertz, a1 = 2.0 * zeta + h * omega, a2 = h * omega * a1, a3 = 1.0 / (1.0 + a2);
    s.bias_rate = a1 > 0 ? omega / a1 : 0;
    s.mass_scale = a2 * a3;
    s.impulse_scale = a3;
    return s;
}

static sbody *sb_of(ref_world *w, int i) { return i < 0 ? &w->dummy : &w->sbodies[i]; }

static void row(const body *A, const body *B, double cA, double cB, vec d, int rotation, vec *lA, vec *lB, double *gA,
                double *gB, double *K_out)
{
    double K = A->im + B->im, tA = 0, tB = 0;
    if (rotation) {
        tA = A->ii * cA;
        tB = B->ii * cB;
        K += tA * cA + tB * cB;
    }
    *lA = vscale(d, K > 0 ? A->im / K : 0);
    *lB = vscale(d, K > 0 ? B->im / K : 0);
    *gA = K > 0 ? tA / K : 0;
    *gB = K > 0 ? tB / K : 0;
    *K_out = K;
}

static void apply(sbody *A, sbody *B, double lambda, vec lA, vec lB, double gA, double gB)
{
    A->v = vsub(A->v, vscale(lA, lambda));
    A->w -= lambda * gA;
    B->v = vadd(B->v, vscale(lB, lambda));
    B->w += lambda * gB;
}

static double rel_speed(const sbody *A, const sbody *B, vec d, double cA, double cB)
{
    return vdot(d, vsub(B->v, A->v)) + B->w * cB - A->w * cA;
}

/* Where anchor r is now, relative to the body's centre at the step's start; a circle's
 * anchor (on its surface along the normal) does not turn with it. */
static vec anchor_now(const sbody *b, vec r, int round)
{
    if (round) return v2(b->c.x - b->c0.x + r.x, b->c.y - b->c0.y + r.y);
    return v2(b->c.x - b->c0.x + b->dqc * r.x - b->dqs * r.y, b->c.y - b->c0.y + b->dqs * r.x + b->dqc * r.y);
}

typedef struct step_ctx {
    double n;
    softness soft, soft_static;
    double push_max, push_floor; /* push_floor: push_max / 32 (DEEP PUSH) */
    int friction;
    double t_end; /* the current substep's end, s */
    double h;     /* the substep, s */
    int last;     /* this is the step's last substep */
} step_ctx;

/* The normal row of point p at separation s: b = relative speed + bias (what the row
 * drives to 0) and whether it is soft. */
static double normal_target(const step_ctx *ctx, const spoint *p, double s, double rel, int use_bias, int *is_soft)
{
    *is_soft = 0;
    if (s > 0) return rel + s * ctx->n;
    if (use_bias) {
        *is_soft = 1;
        return rel + p->bias;
    }
    return rel;
}

/* pogon's DEEP PUSH: of the bias (capped at push_max), velocity gets at most the floor
 * plus what holds the impulse at rest (impulse_scale / mass_scale lambda); the rest goes
 * to the pseudo velocities. */
static void set_push(const step_ctx *ctx, const softness *soft, spoint *p, double s)
{
    double bias = soft->bias_rate * s, hold;
    p->s_soft = s;
    p->deep_push = 0;
    p->bias = 0;
    if (s >= 0) return;
    if (bias < -ctx->push_max) bias = -ctx->push_max;
    hold = (soft->mass_scale > 0 ? p->ln * soft->impulse_scale / soft->mass_scale : 1e300) + ctx->push_floor;
    if (bias < -hold) {
        p->deep_push = bias + hold;
        bias = -hold;
    }
    p->bias = bias;
}

static double normal_update(const softness *soft, const spoint *p, double y, int is_soft)
{
    return is_soft ? p->ln - soft->mass_scale * y - soft->impulse_scale * p->ln : p->ln - y;
}

/* rel: the relative normal speed the row was solved from, s its separation, relax the
 * pass; a point's approach speed for restitution is, as in pogon (APPROACH, SUBSTEP
 * PHASE), the closing speed at the instant the gap closes: u + a (tau - h/2), u the less
 * of the speed just before it first pushes (a relax pass adds the coming kick) and the
 * step's start speed plus what gravity added by the end of the closing substep,
 * tau = s / |u| at most h (0 when the last relax pass foresees the next step). */
static void normal_apply(const step_ctx *ctx, sbody *A, sbody *B, spoint *p, double acc, double rel, double s, int relax)
{
    if (p->max_ln == 0) {
        double a = p->approach_accel, external = p->approach_start + a * (ctx->t_end + (relax ? ctx->h : 0)), u, tau = 0;
        if (relax) rel += a * ctx->h;
        u = rel > external ? rel : external;
        if (s > 0 && u < 0 && !(relax && ctx->last)) tau = s / -u < ctx->h ? s / -u : ctx->h;
        p->relative_velocity = u + a * (tau - ctx->h / 2);
    }
    if (acc < 0) acc = 0;
    apply(A, B, acc - p->ln, p->lnA, p->lnB, p->gnA, p->gnB);
    p->ln = acc;
    if (acc > p->max_ln) p->max_ln = acc;
}

/* What a unit of lambda on point q's normal row does to point p's relative normal speed. */
static double coupling(vec n, const spoint *p, const spoint *q)
{
    return vdot(n, vadd(q->lnA, q->lnB)) + p->cnA * q->gnA + p->cnB * q->gnB;
}

static void setup_block(constraint *c)
{
    double det;
    c->block = 0;
    c->e01 = c->e10 = 0;
    if (c->count != 2) return;
    c->e01 = coupling(c->n, &c->p[0], &c->p[1]);
    c->e10 = coupling(c->n, &c->p[1], &c->p[0]);
    det = 1 - c->e01 * c->e10;
    c->block = fabs(c->e01) <= 1 && fabs(c->e10) <= 1 && det >= 1.0 / 16;
}

static void solve(ref_world *w, const step_ctx *ctx, constraint *c, int use_bias, int order)
{
    sbody *A = sb_of(w, c->a), *B = sb_of(w, c->b);
    const softness *soft = c->soft_static ? &ctx->soft_static : &ctx->soft;
    vec n = c->n, t = v2(n.y, -n.x);
    double s[2];
    int k, done = 0;
    for (k = 0; k < c->count; ++k) {
        spoint *p = &c->p[k];
        vec da = anchor_now(A, p->rA, c->round_a), db = anchor_now(B, p->rB, c->round_b);
        s[k] = vdot(n, vsub(db, da)) + p->adjusted;
        if (use_bias) {
            set_push(ctx, soft, p, s[k]);
            if (p->deep_push < 0) c->deep = 1;
        }
    }
    if (c->block) {
        /* both rows at once: the change -E^-1 b (pogon: docs/solver-design.md, BLOCK) */
        spoint *p0 = &c->p[0], *p1 = &c->p[1];
        int soft0, soft1;
        double rel0 = rel_speed(A, B, n, p0->cnA, p0->cnB), rel1 = rel_speed(A, B, n, p1->cnA, p1->cnB);
        double b0 = normal_target(ctx, p0, s[0], rel0, use_bias, &soft0);
        double b1 = normal_target(ctx, p1, s[1], rel1, use_bias, &soft1);
        double det = 1 - c->e01 * c->e10, y0 = (b0 - c->e01 * b1) / det, y1 = (b1 - c->e10 * b0) / det;
        double acc0 = normal_update(soft, p0, y0, soft0), acc1 = normal_update(soft, p1, y1, soft1);
        if (acc0 >= 0 && acc1 >= 0) {
            normal_apply(ctx, A, B, p0, acc0, rel0, s[0], !use_bias);
            normal_apply(ctx, A, B, p1, acc1, rel1, s[1], !use_bias);
            done = 1;
        }
    }
    for (k = 0; !done && k < c->count; ++k) {
        int i = order ? c->count - 1 - k : k, is_soft;
        spoint *p = &c->p[i];
        double rel = rel_speed(A, B, n, p->cnA, p->cnB), b = normal_target(ctx, p, s[i], rel, use_bias, &is_soft);
        normal_apply(ctx, A, B, p, normal_update(soft, p, b, is_soft), rel, s[i], !use_bias);
    }
    if (ctx->friction) {
        /* one row, as in pogon: a single point's, or a face contact's central row (with
         * friction on every two-point manifold has one), bounded by both points */
        spoint *p = &c->p[0];
        double max_f = p->friction_ratio * p->ln + (c->central ? c->p[1].friction_ratio * c->p[1].ln : 0);
        double vt = rel_speed(A, B, t, p->ctA, p->ctB), acc = p->lt - vt;
        acc = acc < -max_f ? -max_f : acc > max_f ? max_f : acc;
        apply(A, B, acc - p->lt, p->ltA, p->ltB, p->gtA, p->gtB);
        p->lt = acc;
    }
}

/* pogon's DEEP PUSH: the pseudo rows (linear only) of the constraints in the list, one
 * sweep, forwards or backwards. */
static void deep_sweep(ref_world *w, const step_ctx *ctx, const int *list, int n_list, int order, int backward)
{
    int k, j;
    for (k = 0; k < n_list; ++k) {
        constraint *c = &w->cons[list[backward ? n_list - 1 - k : k]];
        sbody *A = sb_of(w, c->a), *B = sb_of(w, c->b);
        for (j = 0; j < c->count; ++j) {
            spoint *p = &c->p[(c->count == 2 && order) ? 1 - j : j];
            double offset = p->s_soft > 0 ? p->s_soft * ctx->n : p->deep_push;
            double b = vdot(c->n, vsub(B->pv, A->pv)) + offset, acc = p->pl - b;
            if (acc < 0) acc = 0;
            A->pv = vsub(A->pv, vscale(p->lnA, acc - p->pl));
            B->pv = vadd(B->pv, vscale(p->lnB, acc - p->pl));
            p->pl = acc;
        }
    }
    w->dummy.pv = v2(0, 0);
}

void ref_step(ref_world *w)
{
    const ref_def *d = &w->def;
    double n_per_s = (double)d->step_hz * d->substeps, h = 1.0 / n_per_s, hertz = d->hertz;
    step_ctx ctx;
    int i, sub, n_cons = 0, k, pass;

    /* 1. geometry of moving bodies (static ones keep theirs) */
    for (i = 0; i < w->count; ++i)
        if (w->bodies[i].dynamic || !w->bodies[i].placed) sync_geometry(w, &w->bodies[i]);
    /* 2. contacts */
    update_contacts(w);
    /* 3. solve */
    /* the softness cap of src/core/contact_solver.c: neither softness stiffer than a quarter of the
     * substep rate */
    if (hertz * 4 > n_per_s) hertz = n_per_s / 4;
    ctx.n = n_per_s;
    ctx.soft = make_soft(hertz, d->damping_ratio, h);
    ctx.soft_static = make_soft(2 * hertz * 4 > n_per_s ? n_per_s / 4 : 2 * hertz, d->damping_ratio, h);
    ctx.push_max = d->push_max;
    ctx.push_floor = d->push_max / 32;
    ctx.friction = d->friction;
    memset(&w->dummy, 0, sizeof w->dummy);
    w->dummy.dqc = 1;
    for (i = 0; i < w->count; ++i) {
        const body *b = &w->bodies[i];
        sbody *s = &w->sbodies[i];
        s->dynamic = b->dynamic;
        s->v = b->dynamic ? b->vel : v2(0, 0);
        s->w = b->dynamic && d->rotation ? b->w : 0;
        s->c0 = s->c = b->c;
        s->a0 = s->a = b->a;
        s->dqc = 1;
        s->dqs = 0;
        s->turns_anchors = 0;
        s->pv = v2(0, 0);
        s->pushed = 0;
    }
    /* as in pogon (ORDER): the contacts between two moving bodies first, then those with a
     * side that cannot move, each group in contact order */
    for (pass = 0; pass < 2; ++pass)
    for (i = 0; i < w->contact_count; ++i) {
        const contact *ct = &w->contacts[i];
        const body *A = &w->bodies[ct->a], *B = &w->bodies[ct->b];
        constraint *c;
        vec t = v2(ct->n.y, -ct->n.x);
        if (pass != (!A->dynamic || !B->dynamic || A->im == 0 || B->im == 0)) continue;
        c = &w->cons[n_cons++];
        c->a = A->dynamic ? ct->a : -1;
        c->b = B->dynamic ? ct->b : -1;
        c->contact = i;
        c->n = ct->n;
        c->count = ct->count;
        c->soft_static = A->im == 0 || B->im == 0;
        c->round_a = A->local.count == 1;
        c->round_b = B->local.count == 1;
        /* as in pogon: only bodies with an anchor that turns need the substep rotation */
        if (!c->round_a && c->a >= 0) w->sbodies[c->a].turns_anchors = 1;
        if (!c->round_b && c->b >= 0) w->sbodies[c->b].turns_anchors = 1;
        c->restitution = d->restitution ? ct->restitution : 0;
        c->deep = 0;
        c->central = c->count == 2 && d->friction;
        for (k = 0; k < c->count; ++k) {
            spoint *p = &c->p[k];
            const cpoint *cp = &ct->p[k];
            /* anchors on each body's own surface; the manifold point is midway between them */
            p->rA = vsub(vsub(cp->p, vscale(c->n, 0.5 * cp->sep)), A->c);
            p->rB = vsub(vadd(cp->p, vscale(c->n, 0.5 * cp->sep)), B->c);
            p->adjusted = cp->sep - vdot(c->n, vsub(p->rB, p->rA));
            p->cnA = vcross(p->rA, c->n);
            p->cnB = vcross(p->rB, c->n);
            p->ctA = vcross(p->rA, t);
            p->ctB = vcross(p->rB, t);
            if (c->central && k == 1) {
                /* the central friction row's lever arms: those of the mean anchor */
                c->p[0].ctA = 0.5 * (c->p[0].ctA + p->ctA);
                c->p[0].ctB = 0.5 * (c->p[0].ctB + p->ctB);
            }
            row(A, B, p->cnA, p->cnB, c->n, d->rotation, &p->lnA, &p->lnB, &p->gnA, &p->gnB, &p->Kn);
            p->friction_ratio = 0;
            p->ltA = p->ltB = v2(0, 0);
            p->gtA = p->gtB = 0;
            p->ln = cp->ln;
            p->lt = d->friction ? cp->lt : 0;
            p->pl = cp->pl;
            p->deep_push = p->s_soft = p->bias = 0;
            if (p->pl != 0) {
                /* warm start of the pseudo velocities (DEEP PUSH) */
                sbody *sa = sb_of(w, c->a), *sbb = sb_of(w, c->b);
                c->deep = 1;
                sa->pv = vsub(sa->pv, vscale(p->lnA, p->pl));
                sbb->pv = vadd(sbb->pv, vscale(p->lnB, p->pl));
                w->dummy.pv = v2(0, 0);
            }
            p->max_ln = 0;
            p->relative_velocity = 0; /* set before the point first pushes (normal_apply) */
            {
                const sbody *sa = sb_of(w, c->a), *sbb = sb_of(w, c->b);
                vec ga = sa->dynamic ? v2(d->gravity_x, d->gravity_y) : v2(0, 0), gb = sbb->dynamic ? v2(d->gravity_x, d->gravity_y) : v2(0, 0);
                p->approach_start = rel_speed(sa, sbb, c->n, p->cnA, p->cnB);
                p->approach_accel = vdot(c->n, vsub(gb, ga));
            }
        }
        /* the friction rows once the anchors are known: one per point, or the central row
         * in p[0], whose bound takes each point's normal impulse times Kt / Kn of its own */
        for (k = 0; d->friction && k < c->count; ++k) {
            spoint *p = &c->p[k];
            double Kt = 0;
            if (!c->central || k == 0) row(A, B, p->ctA, p->ctB, t, d->rotation, &p->ltA, &p->ltB, &p->gtA, &p->gtB, &Kt);
            else Kt = c->p[0].Kt;
            p->Kt = Kt;
            p->friction_ratio = p->Kn > 0 ? ct->friction * Kt / p->Kn : 0;
        }
        if (c->central) {
            c->p[0].lt += c->p[1].lt;
            c->p[1].lt = 0;
        }
        setup_block(c);
    }
    for (sub = 0; sub < d->substeps; ++sub) {
        int order = sub & 1;
        ctx.t_end = h * (sub + 1);
        ctx.h = h;
        ctx.last = sub + 1 == d->substeps;
        for (i = 0; i < w->count; ++i) {
            sbody *s = &w->sbodies[i];
            if (!s->dynamic) continue;
            s->v.x += d->gravity_x * h;
            s->v.y += d->gravity_y * h;
        }
        for (i = 0; i < n_cons; ++i) {
            constraint *c = &w->cons[i];
            sbody *A = sb_of(w, c->a), *B = sb_of(w, c->b);
            for (k = 0; k < c->count; ++k) {
                spoint *p = &c->p[k];
                apply(A, B, p->ln, p->lnA, p->lnB, p->gnA, p->gnB);
                apply(A, B, p->lt, p->ltA, p->ltB, p->gtA, p->gtB);
            }
        }
        for (i = 0; i < n_cons; ++i) solve(w, &ctx, &w->cons[i], 1, order);
        {
            /* DEEP PUSH: the deep constraints and every other holding a body they push or a
             * body with pseudo motion, 4 sweeps alternating direction */
            int any = 0, n_list = 0, it;
            for (i = 0; i < n_cons; ++i) any |= w->cons[i].deep;
            if (any) {
                for (i = 0; i < n_cons; ++i) {
                    const constraint *c = &w->cons[i];
                    if (!c->deep) continue;
                    if (c->a >= 0) w->sbodies[c->a].pushed = sub + 1;
                    if (c->b >= 0) w->sbodies[c->b].pushed = sub + 1;
                }
                for (i = 0; i < n_cons; ++i) {
                    const constraint *c = &w->cons[i];
                    const sbody *A = sb_of(w, c->a), *B = sb_of(w, c->b);
                    if (c->deep || (c->a >= 0 && A->pushed == sub + 1) || (c->b >= 0 && B->pushed == sub + 1) || A->pv.x != 0 || A->pv.y != 0 ||
                        B->pv.x != 0 || B->pv.y != 0)
                        w->deep_list[n_list++] = i;
                }
                for (it = 0; it < 4; ++it) deep_sweep(w, &ctx, w->deep_list, n_list, order, it & 1);
            }
        }
        for (i = 0; i < w->count; ++i) {
            sbody *s = &w->sbodies[i];
            if (!s->dynamic) continue;
            s->c = vadd(s->c, vscale(vadd(s->v, s->pv), h));
            if (d->rotation && s->w != 0) {
                s->a += s->w * h;
                if (s->turns_anchors) {
                    s->dqc = cos(s->a - s->a0);
                    s->dqs = sin(s->a - s->a0);
                }
            }
        }
        for (i = 0; i < n_cons; ++i) solve(w, &ctx, &w->cons[i], 0, order);
    }
    if (d->restitution) {
        for (i = 0; i < n_cons; ++i) {
            constraint *c = &w->cons[i];
            sbody *A = sb_of(w, c->a), *B = sb_of(w, c->b);
            if (c->restitution == 0) continue;
            if (c->block && c->p[0].relative_velocity <= -d->restitution_threshold && c->p[0].max_ln != 0 &&
                c->p[1].relative_velocity <= -d->restitution_threshold && c->p[1].max_ln != 0) {
                /* both points bounce: together (pogon: docs/solver-design.md, BLOCK) */
                spoint *p0 = &c->p[0], *p1 = &c->p[1];
                /* plus a h / 2: the rebound in the phase of the substep it leaves in (SUBSTEP PHASE) */
                double b0 = rel_speed(A, B, c->n, p0->cnA, p0->cnB) + c->restitution * p0->relative_velocity + p0->approach_accel * h / 2;
                double b1 = rel_speed(A, B, c->n, p1->cnA, p1->cnB) + c->restitution * p1->relative_velocity + p1->approach_accel * h / 2;
                double det = 1 - c->e01 * c->e10, acc0 = p0->ln - (b0 - c->e01 * b1) / det, acc1 = p1->ln - (b1 - c->e10 * b0) / det;
                if (acc0 >= 0 && acc1 >= 0) {
                    apply(A, B, acc0 - p0->ln, p0->lnA, p0->lnB, p0->gnA, p0->gnB);
                    apply(A, B, acc1 - p1->ln, p1->lnA, p1->lnB, p1->gnA, p1->gnB);
                    p0->ln = acc0;
                    p1->ln = acc1;
                    continue;
                }
            }
            for (k = 0; k < c->count; ++k) {
                spoint *p = &c->p[k];
                double lambda, acc;
                if (p->relative_velocity > -d->restitution_threshold || p->max_ln == 0) continue;
                lambda = -(rel_speed(A, B, c->n, p->cnA, p->cnB) + c->restitution * p->relative_velocity + p->approach_accel * h / 2);
                acc = p->ln + lambda;
                if (acc < 0) acc = 0;
                lambda = acc - p->ln;
                p->ln = acc;
                apply(A, B, lambda, p->lnA, p->lnB, p->gnA, p->gnB);
            }
        }
    }
    for (i = 0; i < n_cons; ++i) {
        const constraint *c = &w->cons[i];
        contact *ct = &w->contacts[c->contact];
        for (k = 0; k < c->count; ++k) {
            ct->p[k].ln = c->p[k].ln;
            ct->p[k].lt = c->p[k].lt;
            if (c->central) {
                /* split in proportion to the normal impulses, as pogon stores it */
                double total = c->p[0].lt, sum = c->p[0].ln + c->p[1].ln, part0 = sum > 0 ? total * c->p[0].ln / sum : 0.5 * total;
                ct->p[k].lt = k == 0 ? part0 : total - part0;
            }
            ct->p[k].pl = c->p[k].deep_push < 0 ? c->p[k].pl : 0;
        }
    }
    for (i = 0; i < w->count; ++i) {
        body *b = &w->bodies[i];
        const sbody *s = &w->sbodies[i];
        if (!b->dynamic) continue;
        b->vel = s->v;
        if (d->rotation) b->w = s->w;
        b->c = s->c;
        b->a = s->a;
    }
}

void ref_velocity(const ref_world *w, int i, double *vx, double *vy, double *omega)
{
    if (vx) *vx = w->bodies[i].vel.x;
    if (vy) *vy = w->bodies[i].vel.y;
    if (omega) *omega = w->bodies[i].w;
}
