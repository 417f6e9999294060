/* contact_solver.c — the contact constraint kind: a normal row per manifold point (two
 * solved as a block where they are well conditioned), one friction row a manifold, the
 * deep push's pseudo rows and the rebound, through each stage of the soft step.
 *
 * The rows work in velocity space: a row's accumulated "impulse" is lambda = P K (m/s,
 * the change of relative velocity along the row it makes), with per-step coefficients
 * kA = (1/mA)/K (Q2.30) and gA = (rA x n)/IA/K (Q8.24), so the substeps need int32
 * values of bounded range and int64 products only. The names in capitals (BLOCK,
 * CENTRAL FRICTION, LAZY ROWS, APPROACH, DEEP PUSH, WARM START, ORDER, ROUNDING, TWINS,
 * SYMMETRY, SOFTNESS CAP) are the sections of docs/solver-design.md that give the reasons.
 */
#include "contact_solver.h"
#include "intmath.h"
#include "speed_cap.h"
#include "wide.h"

/* One row's coefficients: the linear ones kA d, kB d (Q2.30) and the angular ones gA, gB
 * (Q8.24 1/m). */
typedef struct row_coeffs { int32_t lA_x, lA_y, lB_x, lB_y, gA, gB; } row_coeffs;

/* The int64 fields come first so that none needs padding (144 bytes). */
typedef struct constraint_point {
    int64_t nrA, xrA, nrB, xrB;      /* each anchor r as n . r and r x n (Q16.16 m, at the
                                        step's start): what the separation needs of it;
                                        below 2^31.5, the length of r */
    int64_t separation;              /* from the last relax pass, or the step's start:
                                        positions have not moved since, so the next soft
                                        pass reuses it */
    pg_fix adjusted_separation;
    pg_fix cnA, cnB, ctA, ctB;       /* r x n, r x t: Q16.16 m */
    row_coeffs nrow, trow;           /* the normal and the tangent row */
    pg_fix friction_ratio;           /* f Kt / Kn */
    pg_fix relative_velocity;        /* normal, just before the point first pushes in this
                                        step (APPROACH); read only once it has pushed */
    pg_fix approach_start, approach_accel; /* with restitution: the relative normal speed
                                        at the step's start, and what gravity and forces
                                        add to it per second (APPROACH) */
    pg_fix normal_impulse, tangent_impulse, max_normal_impulse;
    pg_fix deep_push;                /* < 0: the push-out past that cap, which the pseudo row
                                        adds to the pseudo relative speed; else 0 (DEEP
                                        PUSH); this substep's */
    pg_fix deep_impulse;             /* the pseudo row's accumulated lambda (DEEP PUSH), from
                                        the contact's push_impulse */
} constraint_point;

/* One per contact slot in the world's scratch (336 bytes): the point count and the flags
 * (each 0 or 1) are bytes, after the 32-bit fields. */
typedef struct contact_constraint {
    uint32_t a, b;           /* solver body slots; the static dummy for a static side */
    uint32_t contact;
    pg_dir n;
    pg_fix restitution;
    int32_t e01, e10;        /* Q2.30: what a unit of lambda on point 1 does to point 0's
                                normal speed, and the other way; |e| <= 1 */
    int32_t inv_det;         /* Q8.24: 1 / (1 - e01 e10), at most 16 */
    uint8_t count;           /* 1 or 2 */
    uint8_t soft_static;     /* one side cannot move: stiffer softness; 0 or 1, an index */
    uint8_t round_a, round_b;/* a circle centred on its body's centre of mass: its surface
                                looks the same however it turns, and its normal passes
                                through the centre (no torque) */
    uint8_t normal_linear;   /* r x n = 0 on both sides of every point: the normal rows have
                                no angular part (two round sides, or round and static) */
    uint8_t block;           /* the two normal rows are solved together (BLOCK) */
    uint8_t deep;            /* a point has had deep_push < 0 in this step, or starts it
                                with a pseudo impulse (DEEP PUSH) */
    uint8_t central_friction;/* two points and friction on: the one friction row of the
                                manifold, in p[0] (CENTRAL FRICTION) */
    uint8_t twin;            /* equal inverse masses on both sides (TWINS) */
    uint8_t rows_ready;      /* the rows' coefficients, friction ratios and the block are set
                                (LAZY ROWS, in prepare_constraints) */
    constraint_point p[2];
} constraint;

/* The separation from which up |round(bias_rate s / 2^16)| <= floor (DEEP PUSH): there
 * |bias_rate s| <= floor 2^16, so the rounded bias is within the floor too. */
static int64_t floor_depth(const softness *s, pg_fix floor)
{
    return s->bias_rate > 0 ? -(((int64_t)floor * 65536) / s->bias_rate) : INT64_MIN;
}

/* One denominator, normalised: K scaled by 2^-shift into [2^30, 2^31), and its
 * reciprocal 2^62 / K31 in (2^31, 2^32], so every ratio num / K costs a multiply. */
typedef struct denominator { int shift; int64_t inv; } denominator;

static denominator make_denominator(int64_t K)
{
    denominator d;
    int64_t K31;
    d.shift = pg__bit_length64((uint64_t)K) - 31;
    if (d.shift > 0) K31 = row_round(K, d.shift);
    else if (d.shift < 0) K31 = K * ((int64_t)1 << -d.shift);
    else K31 = K;
    d.inv = K31 > 0 ? (int64_t)pg__udiv64_32((UINT64_C(1) << 62) + (uint64_t)K31 / 2u, (uint32_t)K31) : 0; /* K31 < 2^31 */
    return d;
}

/* round(num / K * 2^q) for 16 <= q <= 30 with |num / K| < 2^(31 - q) (checked by the
 * envelope: see the bounds at each caller). */
static int32_t ratio_q(int64_t num, denominator d, int q)
{
    int64_t n = d.shift >= 0 ? (d.shift > 0 ? row_round(num, d.shift) : num) : num * ((int64_t)1 << -d.shift);
    int64_t r;
    if (q == 30) {
        r = row_round(n * d.inv, 32); /* |n| <= K31 < 2^31 here: kA, kB <= 1 */
    } else {
        r = row_round(n * (d.inv >> 8), 54 - q); /* |n| < 2^36, inv >> 8 <= 2^24 */
    }
    return (int32_t)(r > INT32_MAX ? INT32_MAX : r < -INT32_MAX ? -INT32_MAX : r);
}

/* A row's denominator (make_denominator's, for K >= 0) with what its ratios need, made
 * without a branch on the sign of the shift. ratio_q's n, num scaled by 2^-shift, is
 * (num + half) >> s, row_round's rounding, for shift > 0; for shift <= 0 it is
 * num 2^-shift, exact, so there the factor joins the reciprocal instead:
 * n inv = num (inv 2^-shift), the same product. With s = max(shift, 0) and l = s - shift
 * = max(-shift, 0) both are one form: half = 2^s / 2 (0 for s = 0), inv30 = inv 2^l and
 * inv24 = (inv >> 8) 2^l. K31 is made the same way. l <= 30 for
 * K >= 1, so inv 2^l <= 2^62 (K = 0: l = 31 and inv = 0); (inv >> 8) 2^l <= 2^54. */
typedef struct row_den { denominator d; int64_t half, inv30, inv24; int s; } row_den;

static inline row_den make_row_denominator(int64_t K)
{
    row_den r;
    int shift = pg__bit_length64((uint64_t)K) - 31;
    int s = shift > 0 ? shift : 0, l = s - shift;
    int64_t K31;
    r.half = ((int64_t)1 << s) >> 1;
    r.s = s;
    K31 = ((K + r.half) >> s) << l; /* in [2^30, 2^31) for K > 0 */
    r.d.shift = shift;
    /* K31 < 2^31: a division by a 32-bit number, no 64-bit division per row */
    r.d.inv = K31 > 0 ? (int64_t)pg__udiv64_32((UINT64_C(1) << 62) + (uint64_t)K31 / 2u, (uint32_t)K31) : 0;
    r.inv30 = r.d.inv << l;
    r.inv24 = (r.d.inv >> 8) << l;
    return r;
}

/* ratio_q(num, d, 30) for an inverse mass 0 <= num <= K: n <= K31 (rounding is monotone)
 * and inv <= 2^62 / K31 + 1/2, so 0 <= n inv < 2^62 + 2^30 and the result is at most
 * 2^30 + 1: ratio_q's clamp never acts, and for n inv >= 0 its rounding is (x + 2^31) >> 32. */
static inline int32_t ratio_q30_mass(int64_t num, const row_den *r)
{
    return (int32_t)((((num + r->half) >> r->s) * r->inv30 + (INT64_C(1) << 31)) >> 32);
}

/* ratio_q(num, d, 24), with the bounds and the clamp of ratio_q. */
static inline int32_t ratio_q24(int64_t num, const row_den *r)
{
    int64_t x = row_round(((num + r->half) >> r->s) * r->inv24, 30);
    return (int32_t)(x > INT32_MAX ? INT32_MAX : x < -INT32_MAX ? -INT32_MAX : x);
}

/* Kt / Kn in Q16.16 from the two normalised reciprocals: (inv_n / inv_t) 2^(shift_t - shift_n). */
static pg_fix k_ratio(denominator t, denominator n)
{
    int diff = t.shift - n.shift;
    uint64_t r;
    if (t.inv <= 0) return 0;
    r = ((uint64_t)n.inv << 16) + (uint64_t)t.inv / 2u;
    /* in [2^15, 2^17]; t.inv <= 2^32, which is 2^62 / K31 rounded for K31 = 2^30 only */
    r = (uint64_t)t.inv <= UINT32_MAX ? pg__udiv64_32(r, (uint32_t)t.inv) : r / (uint64_t)t.inv;
    if (diff >= 15) return PG_FIX_MAX;
    if (diff >= 0) r <<= diff;
    else r = diff <= -40 ? 0 : (r + ((uint64_t)1 << (-diff - 1))) >> -diff;
    return r > (uint64_t)PG_FIX_MAX ? PG_FIX_MAX : (pg_fix)r;
}

/* round(a c / 2^16) for a wide a and a Q16.16 c: one int64 product when it cannot
 * overflow (-2^41 <= a < 2^41 and -2^21 <= c < 2^21, so |a c| <= 2^62: ordinary bodies),
 * the 128-bit path otherwise; both are exact and round alike. The range test is one
 * branch: a + 2^41 and c + 2^21, taken as unsigned, are below 2^42 and 2^22. */
static inline int64_t mul_q16(int64_t a, pg_fix c)
{
    uint64_t ua, uc, hi, lo, r;
    uint64_t ra = (uint64_t)a + (UINT64_C(1) << 41), rc = (uint64_t)(int64_t)c + (UINT64_C(1) << 21);
    if (c == 0) return 0; /* often: a circle's anchor lies on its normal (and a small ball's
                             invI is past 2^41) */
    if (((ra >> 42) | (rc >> 22)) == 0) return row_round(a * c, 16);
    /* |a| |c| = hi 2^32 + lo with hi = (|a| >> 32) |c| < 2^62 and lo = (|a| mod 2^32) |c|
     * < 2^63, so round(|a| |c| / 2^16) = hi 2^16 + (lo + half) / 2^16, rounded as the
     * fast path's row_round (ties toward +infinity: half = 2^15 for a positive product,
     * 2^15 - 1 for the magnitude of a negative one) and saturated like pg__mul64_shr. */
    ua = pg__mag64(a);
    uc = pg__mag64(c);
    hi = (ua >> 32) * uc;
    lo = ((ua & 0xFFFFFFFFu) * uc + ((a < 0) != (c < 0) ? 0x7FFFu : 0x8000u)) >> 16;
    if (hi >= (UINT64_C(1) << 47)) return (a < 0) != (c < 0) ? -INT64_MAX : INT64_MAX;
    r = (hi << 16) + lo; /* < 2^63 + 2^47: may pass INT64_MAX */
    if (r > (uint64_t)INT64_MAX) r = (uint64_t)INT64_MAX;
    return (a < 0) != (c < 0) ? -(int64_t)r : (int64_t)r;
}

/* One row's coefficients into point p: its normal row's, or its tangent row's. */
static inline void store_row(constraint_point *p, int tangent, int32_t lA_x, int32_t lA_y, int32_t lB_x, int32_t lB_y, int32_t gA,
                             int32_t gB)
{
    row_coeffs *r = tangent ? &p->trow : &p->nrow;
    r->lA_x = lA_x;
    r->lA_y = lA_y;
    r->lB_x = lB_x;
    r->lB_y = lB_y;
    r->gA = gA;
    r->gB = gB;
}

/* row_coefficients for a row whose K does not fit int64: K, tA and tB scaled by 2^-s.
 * invI c^2 / 2^32 < 2^(bits(invI) + 2 bits(c) - 32) =: 2^(b - 32); with s = b - 92 each
 * scaled term is below 2^60 and K below 2^62. b >= 94 here (a term or the sum passed
 * 2^62), so s >= 2; and s <= 63 + 64 - 92 = 35. gA, gB are ratios of values scaled
 * alike; kA = invm_A / (K 2^s), so for kA, kB and for k_ratio, which compares two rows,
 * the scale joins the denominator's shift (inverse masses are below 2^54: past a shift
 * of 62 their ratio rounds to 0). */
PG__NOINLINE denominator row_coefficients_scaled(const pg_body *A, const pg_body *B, pg_fix cA, pg_fix cB, pg_dir d,
                                                 constraint_point *p, int tangent)
{
    int bA = pg__bit_length64((uint64_t)A->inv_inertia) + 2 * pg__bit_length64(pg__mag64(cA));
    int bB = pg__bit_length64((uint64_t)B->inv_inertia) + 2 * pg__bit_length64(pg__mag64(cB));
    int s = (bA > bB ? bA : bB) - 92;
    int64_t tA = pg__mul64_shr(A->inv_inertia, cA, 16 + s), tB = pg__mul64_shr(B->inv_inertia, cB, 16 + s);
    int64_t K = row_round(A->inv_mass + B->inv_mass, s) + mul_q16(tA, cA) + mul_q16(tB, cB);
    denominator den = make_denominator(K);
    int32_t kA, kB, gA, gB;
    gA = tA != 0 ? ratio_q(tA, den, 24) : 0;
    gB = tB != 0 ? ratio_q(tB, den, 24) : 0;
    den.shift += s;
    kA = den.shift > 62 ? 0 : ratio_q(A->inv_mass, den, 30);
    kB = den.shift > 62 ? 0 : ratio_q(B->inv_mass, den, 30);
    store_row(p, tangent, (int32_t)row_round((int64_t)kA * d.x, 30), (int32_t)row_round((int64_t)kA * d.y, 30),
              (int32_t)row_round((int64_t)kB * d.x, 30), (int32_t)row_round((int64_t)kB * d.y, 30), gA, gB);
    return den;
}

/* Coefficients of one row (normal or tangent) for one point. gA = invI_A (rA x d) / K is
 * bounded by 1 / (2 k) for the radius of gyration k >= 2^-8 m, which body.c makes a
 * condition of a rotating body (pg__mass_data_problem), so it fits Q8.24.
 * K itself need not fit int64: invI (r x d)^2 reaches 2^63 (Q38) for a ball of radius
 * 0.025 m and density 0.1 (invI = 1.6e7) at a lever arm of 1.44 m, which a massless
 * segment on the same body provides (the envelope allows 50 m). Such a row is computed
 * with every term scaled down (row_coefficients_scaled); a row whose K fits int64 is
 * computed directly. Forced inline into prepare_point_rows, its only caller, so that its
 * six results stay in registers instead of going through pointers.
 * The four products invI c and t c are mul_q16's; where both sides are ordinary (the
 * offset values OR-ed are below the limits exactly when each is) they are plain int64
 * products and K needs no test. Two sides of one inverse mass (the pyramid's boxes on
 * each other) share kA and k n. */
PG__INLINE_ROW denominator row_coefficients(const pg_body *A, const pg_body *B, pg_fix cA, pg_fix cB, pg_dir d, int rotation,
                                            constraint_point *p, int tangent)
{
    int64_t K = A->inv_mass + B->inv_mass, tA = 0, tB = 0;
    int32_t kA, kB, lA_x, lA_y, lB_x, lB_y;
    row_den rd;
    if (rotation) {
        int64_t qA, qB;
        /* the common case in one test: inverse inertias below 2^46 (a ball of radius 0.25 m
         * and density 1 has 2^45.4) and |c| <= 2^16 (1 m), so |invI c| < 2^62, |t| <= 2^46,
         * |t c| <= 2^62 and 0 <= q <= 2^46: every product fits and K too, and each is
         * exactly what mul_q16 returns */
        uint64_t rc = ((uint64_t)(int64_t)cA + (UINT64_C(1) << 16)) | ((uint64_t)(int64_t)cB + (UINT64_C(1) << 16));
        if ((((uint64_t)A->inv_inertia | (uint64_t)B->inv_inertia) >> 46 | rc >> 17) == 0) {
            tA = row_round(A->inv_inertia * cA, 16); /* invI (r x d): Q38 per metre */
            tB = row_round(B->inv_inertia * cB, 16);
            qA = row_round(tA * cA, 16); /* >= 0 */
            qB = row_round(tB * cB, 16);
        } else {
            tA = mul_q16(A->inv_inertia, cA);
            tB = mul_q16(B->inv_inertia, cB);
            qA = mul_q16(tA, cA); /* >= 0; INT64_MAX when tA saturated (then |c| >= 1 m) */
            qB = mul_q16(tB, cB);
            /* K < 2^54 and qA, qB >= 0: below 2^61 each, the sum fits; else test exactly */
            if (((uint64_t)qA | (uint64_t)qB) >= (UINT64_C(1) << 61) && (qA > INT64_MAX - K || qB > INT64_MAX - K - qA))
                return row_coefficients_scaled(A, B, cA, cB, d, p, tangent);
        }
        K += qA + qB;
    }
    rd = make_row_denominator(K); /* K >= 0: a sum of terms >= 0 that fits */
    kA = ratio_q30_mass(A->inv_mass, &rd);
    lA_x = (int32_t)row_round((int64_t)kA * d.x, 30);
    lA_y = (int32_t)row_round((int64_t)kA * d.y, 30);
    if (B->inv_mass == A->inv_mass) {
        lB_x = lA_x;
        lB_y = lA_y;
    } else {
        kB = ratio_q30_mass(B->inv_mass, &rd);
        lB_x = (int32_t)row_round((int64_t)kB * d.x, 30);
        lB_y = (int32_t)row_round((int64_t)kB * d.y, 30);
    }
    store_row(p, tangent, lA_x, lA_y, lB_x, lB_y, tA != 0 ? ratio_q24(tA, &rd) : 0, tB != 0 ? ratio_q24(tB, &rd) : 0);
    return rd.d;
}

/* What a unit of lambda on point q's normal row does to point p's relative normal speed,
 * Q2.30: exactly what apply_row and relative_speed make of it, the linear part
 * n . (kA + kB) n and the angular part (r x n)_p g_q on each side. */
static int64_t coupling(pg_dir n, const constraint_point *p, const constraint_point *q)
{
    int64_t lin = row_round((int64_t)n.x * ((int64_t)q->nrow.lA_x + q->nrow.lB_x) + (int64_t)n.y * ((int64_t)q->nrow.lA_y + q->nrow.lB_y), 30);
    return lin + row_round((int64_t)p->cnA * q->nrow.gA + (int64_t)p->cnB * q->nrow.gB, 10);
}

/* Whether the two normal rows of c are solved together, and their coupling. Only when
 * both couplings are within +-1 and the 2x2 system is well conditioned, det = 1 - e01 e10
 * >= 1/16 (Box2D 2.4 asks for a condition number below 1000 of its block solver): two
 * points far apart on a body's face. A tall thin box standing on its end (the rows nearly
 * alike, det -> 0), a body that cannot turn in this step (the rows are alike) and a
 * single point are solved row by row. */
static void setup_block(constraint *c)
{
    const int64_t one = INT64_C(1) << 30;
    int64_t e01, e10, det;
    c->block = 0;
    c->e01 = c->e10 = 0;
    c->inv_det = 1 << 24;
    if (c->count != 2 || c->normal_linear) return;
    e01 = coupling(c->n, &c->p[0], &c->p[1]);
    e10 = coupling(c->n, &c->p[1], &c->p[0]);
    if (e01 > one || e01 < -one || e10 > one || e10 < -one) return;
    det = one - row_round(e01 * e10, 30);
    if (det < one / 16) return;
    c->block = 1;
    c->e01 = (int32_t)e01;
    c->e10 = (int32_t)e10;
    c->inv_det = (int32_t)pg__udiv64_32((UINT64_C(1) << 54) + (uint64_t)det / 2u, (uint32_t)det); /* det <= 2^31 */
}

/* What a side that does not move in this step looks like to the rows: no inverse mass,
 * no inverse inertia. */
static const pg_body immovable;

/* A circle whose centre is its body's centre of mass. */
static int centred_circle(const pg_world *w, uint32_t shape, uint32_t body)
{
    const pg_geometry *g = &w->shapes[shape].geometry;
    const pg_body *b = &w->bodies[body];
    return g->kind == PG_SHAPE_CIRCLE && g->vertices[0].x == b->local_center.x && g->vertices[0].y == b->local_center.y;
}

/* prepare_rows' loop over the points, with whether the normal and the tangent rows turn
 * as constants where the caller has them. */
PG__INLINE_ROW void prepare_point_rows(const step_context *ctx, constraint *c, const pg_body *A, const pg_body *B, int normal_turns,
                                       int tangent_turns)
{
    const int friction = (ctx->effects & PG__EFFECT(PG_EFFECT_FRICTION)) != 0;
    const pg_fix mu = friction ? ctx->world->contacts[c->contact].friction : 0;
    pg_dir t;
    denominator dt = { 0, 0 };
    int32_t k;
    t.x = c->n.y;
    t.y = -c->n.x;
    for (k = 0; k < c->count; ++k) {
        constraint_point *p = &c->p[k];
        denominator dn = row_coefficients(A, B, p->cnA, p->cnB, c->n, normal_turns, p, 0);
        /* with CENTRAL FRICTION, p[1] has no tangent row of its own: its ratio turns its
         * normal impulse into the bound of p[0]'s row, Kt of that row over its own Kn */
        if (friction && (k == 0 || !c->central_friction)) dt = row_coefficients(A, B, p->ctA, p->ctB, t, tangent_turns, p, 1);
        else p->trow.lA_x = p->trow.lA_y = p->trow.lB_x = p->trow.lB_y = p->trow.gA = p->trow.gB = 0;
        p->friction_ratio = friction ? pg_fix_mul(mu, k_ratio(dt, dn)) : 0;
    }
}

/* The rows' coefficients of every point of c (normal and, with friction, tangent), the
 * friction ratios and the block: what LAZY ROWS defers. A pure function of the step's
 * start, so it gives the same values whenever it runs. Normal rows whose every r x n is
 * 0 (normal_linear: two balls, a ball on the ground) have no angular part, exactly as
 * without rotation: t = q = 0 and K = 1/mA + 1/mB either way; the common case, both
 * rows turning, gets a copy of the loop of its own. A and B are c's bodies (immovable for
 * the dummy): prepare_constraint has them at hand, prepare_rows (a pass that finds the
 * rows first needed) looks them up. */
PG__NOINLINE void prepare_rows_of(const step_context *ctx, constraint *c, const pg_body *A, const pg_body *B)
{
    if (ctx->rotation && !c->normal_linear) prepare_point_rows(ctx, c, A, B, 1, 1);
    else prepare_point_rows(ctx, c, A, B, 0, ctx->rotation);
    setup_block(c);
    c->rows_ready = 1;
}

PG__NOINLINE void prepare_rows(const step_context *ctx, constraint *c)
{
    const pg_world *w = ctx->world;
    prepare_rows_of(ctx, c, c->a == ctx->dummy ? &immovable : &w->bodies[c->a], c->b == ctx->dummy ? &immovable : &w->bodies[c->b]);
}

/* How far along the normal n a side's anchor r lies from the side's centre now, Q46:
 * n . R r for the side's turn since the step's start q = R = (c, s), which is
 * c (n . r) + s (r x n), two products of the step's constants nr = n . r and xr = r x n
 * (constraint_point). A round side's anchor does not turn with it: its q is the identity
 * (turn_of). At the step's start (q = 1: c = 2^30, s = 0) it is nr 2^30 exactly.
 * |(c, s)| <= 2^30 (1 + 2^-29) and |(nr, xr)|, r's length rounded, is at most 2^31.5
 * (a restored snapshot's anchors may sit at the edge of the range), so the sum is below
 * 2^61.5. */
static const pg_rot no_turn = { PG_ROT_ONE, 0 };
static inline const pg_rot *turn_of(const solver_body *b, int round) { return round ? &no_turn : &b->dq; }
static inline int64_t anchor_along(const pg_rot *q, int64_t nr, int64_t xr) { return q->c * nr + q->s * xr; }

/* A point's part of its friction row's bound, f (Kt/Kn) lambda_n in Q32 (solve_friction). */
static inline int64_t friction_bound(const constraint_point *p) { return (int64_t)p->friction_ratio * p->normal_impulse; }

/* One friction row whose tangent "impulse" stays within +-round(bound / 2^16): bound is
 * the Q16 ratio f (Kt/Kn) times the Q16 lambda_n of the row's point, or for a manifold's
 * central row the sum of that over both points (CENTRAL FRICTION); each product is below
 * 2^31 2^29, so the sum of two fits int64 and is rounded once. */
PG__INLINE_ROW void solve_friction(velocity *va, velocity *vb, constraint_point *p, pg_dir t, int64_t bound, int twin)
{
    /* bound >= 0: f is 0..10 (shape.c and restoring check it), Kt/Kn >= 0, lambda_n >= 0 */
    int64_t max_f = row_round(bound, 16), acc;
    if (max_f > LAMBDA_MAX) max_f = LAMBDA_MAX;
    if (max_f == 0) {
        /* an unloaded contact: the bound is 0 whatever the sliding speed */
        if (p->tangent_impulse == 0) return;
        acc = 0;
    } else {
        acc = clamp_lambda((int64_t)p->tangent_impulse - relative_speed(va, vb, t, p->ctA, p->ctB), -max_f, max_f);
    }
    if (acc == p->tangent_impulse) return; /* held at its bound: nothing changes */
    {
        /* TWINS: B's linear change is A's */
        int64_t lambda = acc - p->tangent_impulse;
        int64_t ax = row_round(lambda * p->trow.lA_x, 30), ay = row_round(lambda * p->trow.lA_y, 30);
        va->x -= ax;
        va->y -= ay;
        va->w -= row_round(lambda * p->trow.gA, 24);
        vb->x += twin ? ax : row_round(lambda * p->trow.lB_x, 30);
        vb->y += twin ? ay : row_round(lambda * p->trow.lB_y, 30);
        vb->w += row_round(lambda * p->trow.gB, 24);
    }
    p->tangent_impulse = (pg_fix)acc;
}

/* round(m x / 2^30) for the soft mass scale 0 <= m < 2^30 and a relative speed x (Q16.16
 * m/s). x is not bounded by 2^33, where m x would leave int64: an anchor far from a
 * fast-turning body's centre moves at w (r x n), 8192 rad/s (VELOCITY_MAX) times 16.5 m
 * already 2^33 (and up to 32768 rad/s times 50 m, 2^36.6, right after a saturated
 * torque). Beyond 2^33 the 128-bit product, rounded the same way (row_round's ties toward
 * +infinity): pg__mul64_shr rounds ties away from zero, so a negative product exactly
 * halfway, whose low 30 bits (decided by the low 30 bits of each factor) are 2^29, is
 * moved up by one. Out of line, the rare path costs the row one unsigned comparison. */
PG__NOINLINE int64_t mass_scale_times_wide(int32_t m, int64_t x)
{
    const uint64_t low30 = (UINT64_C(1) << 30) - 1u;
    int64_t r = pg__mul64_shr(m, x, 30); /* |m x| < 2^30 2^37: never saturated */
    uint64_t low = ((pg__mag64(m) & low30) * (pg__mag64(x) & low30)) & low30;
    if (m > 0 && x < 0 && low == (UINT64_C(1) << 29)) ++r;
    return r;
}
static inline int64_t mass_scale_times(int32_t m, int64_t x)
{
    if ((uint64_t)x + (UINT64_C(1) << 33) < (UINT64_C(1) << 34)) return row_round(m * x, 30);
    return mass_scale_times_wide(m, x);
}

/* The current separation of a point: in the relax pass from where its anchors are now,
 * which it stores; in the soft pass the one stored last, since nothing has moved since:
 * the relax pass's, or in the first substep the one prepare_constraints measured at the
 * step's start. */
PG__INLINE_PASS int64_t normal_separation(const constraint *c, const solver_body *A, const solver_body *B, constraint_point *p,
                                          int use_bias)
{
    int64_t s, lin;
    if (use_bias) return p->separation;
    lin = c->n.x * ((int64_t)B->dp.x - A->dp.x) + c->n.y * ((int64_t)B->dp.y - A->dp.y);
    s = row_round(lin + anchor_along(turn_of(B, c->round_b), p->nrB, p->xrB) - anchor_along(turn_of(A, c->round_a), p->nrA, p->xrA), 30) +
        p->adjusted_separation;
    p->separation = s;
    return s;
}

/* The relax pass's separations of both points of a two-point manifold, as
 * normal_separation finds them, the linear part n . (dpB - dpA) computed once. */
PG__INLINE_PASS void relax_separations(constraint *c, const solver_body *A, const solver_body *B, int64_t *s0, int64_t *s1)
{
    constraint_point *p0 = &c->p[0], *p1 = &c->p[1];
    const pg_rot *qA = turn_of(A, c->round_a), *qB = turn_of(B, c->round_b);
    int64_t lin = c->n.x * ((int64_t)B->dp.x - A->dp.x) + c->n.y * ((int64_t)B->dp.y - A->dp.y);
    *s0 = row_round(lin + anchor_along(qB, p0->nrB, p0->xrB) - anchor_along(qA, p0->nrA, p0->xrA), 30) + p0->adjusted_separation;
    *s1 = row_round(lin + anchor_along(qB, p1->nrB, p1->xrB) - anchor_along(qA, p1->nrA, p1->xrA), 30) + p1->adjusted_separation;
    p0->separation = *s0;
    p1->separation = *s1;
}

PG__INLINE_ROW int64_t normal_speed(const constraint *c, const velocity *va, const velocity *vb, const constraint_point *p)
{
    return c->normal_linear ? linear_speed(va, vb, c->n) : relative_speed(va, vb, c->n, p->cnA, p->cnB);
}

/* What a normal row wants of the relative normal speed rel at separation s: b = rel +
 * bias, which the row drives to 0, and whether the row is soft (scaled by the soft mass
 * and impulse scales) or rigid. Speculative (s > 0): close the gap in one substep, no
 * more; touching, in the soft pass: push out at the soft bias rate, capped; in the
 * relax pass: no bias. */
PG__INLINE_ROW int64_t normal_target(const step_context *ctx, const softness *soft, const constraint_point *p, int64_t s, int64_t rel,
                                     int use_bias, int *is_soft)
{
    *is_soft = 0;
    if (s > 0) return rel + s * ctx->n;
    if (use_bias) {
        /* the bias, capped at push_max, less what goes to the pseudo velocities (DEEP PUSH) */
        /* s <= 0 here and bias_rate >= 0 (contact_hertz > 0, the damping ratio >= 0) */
        int64_t bias = row_round((int64_t)soft->bias_rate * s, 16);
        if (bias < -ctx->push_max) bias = -ctx->push_max;
        *is_soft = 1;
        return rel + bias - p->deep_push;
    }
    return rel;
}

/* A point's push-out for this substep's soft pass (DEEP PUSH): of the bias bias_rate s,
 * capped at push_max, the velocity rows get at most the floor plus what holds the point's
 * impulse at rest (|lambda| < 2^29 and hold_rate < 2^31: the product fits); the rest is
 * deep_push, for the pseudo velocities, which normal_target takes off the bias. One
 * comparison for a gap or a shallow point. */
PG__INLINE_ROW void set_push(const step_context *ctx, const softness *soft, constraint *c, constraint_point *p, int64_t s)
{
    int64_t bias, hold;
    p->deep_push = 0;
    if (s >= soft->floor_depth) return; /* a gap, or shallow: all of it is velocity */
    bias = row_round((int64_t)soft->bias_rate * s, 16);
    if (bias < -ctx->push_max) bias = -ctx->push_max;
    hold = row_round((int64_t)p->normal_impulse * soft->hold_rate, 16) + ctx->push_floor;
    if (bias < -hold) {
        p->deep_push = (pg_fix)(bias + hold);
        c->deep = 1;
        *ctx->deep_seen = 1;
    }
}

/* The new accumulated lambda of a row whose unscaled change is -y: lambda - y (rigid), or
 * lambda - soft mass scale y - soft impulse scale lambda (soft). */
PG__INLINE_ROW int64_t normal_update(const softness *soft, const constraint_point *p, int64_t y, int is_soft)
{
    if (!is_soft) return (int64_t)p->normal_impulse - y;
    /* impulse_scale > 0 and lambda >= 0 (every store clamps it to [0, LAMBDA_MAX]) */
    return (int64_t)p->normal_impulse - mass_scale_times(soft->mass_scale, y) - row_round((int64_t)soft->impulse_scale * p->normal_impulse, 30);
}

/* Store a normal row's new lambda acc (clamped to [0, LAMBDA_MAX]) and apply the change. */
PG__INLINE_ROW void normal_apply(const constraint *c, velocity *va, velocity *vb, constraint_point *p, int64_t acc)
{
    acc = clamp_lambda(acc, 0, LAMBDA_MAX);
    if (acc > p->max_normal_impulse) p->max_normal_impulse = (pg_fix)acc;
    if (acc == p->normal_impulse) return; /* nothing held, nothing to hold: open gaps */
    if (c->normal_linear) apply_linear(va, vb, acc - p->normal_impulse, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y);
    else apply_row(va, vb, acc - p->normal_impulse, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y, p->nrow.gA, p->nrow.gB);
    p->normal_impulse = (pg_fix)acc;
}

/* normal_apply for both rows of a block (acc0, acc1 >= 0), their changes added at once:
 * the same sums of the same roundings (each term below 2^29 2^7, as in apply_row), where
 * a row whose lambda did not change adds round(0) = 0. A block is never normal_linear
 * (setup_block), so both rows are whole. Written out, without the test for a change,
 * so that the compilers keep the velocities in registers (apply_row row by row did not). */
PG__INLINE_ROW void normal_apply_pair(velocity *va, velocity *vb, constraint_point *p0, int64_t acc0, constraint_point *p1, int64_t acc1, int twin)
{
    int64_t d0, d1;
    if (acc0 > LAMBDA_MAX) acc0 = LAMBDA_MAX;
    if (acc1 > LAMBDA_MAX) acc1 = LAMBDA_MAX;
    if (acc0 > p0->max_normal_impulse) p0->max_normal_impulse = (pg_fix)acc0;
    if (acc1 > p1->max_normal_impulse) p1->max_normal_impulse = (pg_fix)acc1;
    d0 = acc0 - p0->normal_impulse;
    d1 = acc1 - p1->normal_impulse;
    p0->normal_impulse = (pg_fix)acc0;
    p1->normal_impulse = (pg_fix)acc1;
    {
        int64_t ax = row_round(d0 * p0->nrow.lA_x, 30) + row_round(d1 * p1->nrow.lA_x, 30);
        int64_t ay = row_round(d0 * p0->nrow.lA_y, 30) + row_round(d1 * p1->nrow.lA_y, 30);
        va->x -= ax;
        va->y -= ay;
        va->w -= row_round(d0 * p0->nrow.gA, 24) + row_round(d1 * p1->nrow.gA, 24);
        vb->x += twin ? ax : row_round(d0 * p0->nrow.lB_x, 30) + row_round(d1 * p1->nrow.lB_x, 30);
        vb->y += twin ? ay : row_round(d0 * p0->nrow.lB_y, 30) + row_round(d1 * p1->nrow.lB_y, 30);
        vb->w += row_round(d0 * p0->nrow.gB, 24) + row_round(d1 * p1->nrow.gB, 24);
    }
}

/* The approach speed of a point that first pushes now, at relative normal speed rel and
 * separation s, in the soft pass (relax 0) or the relax pass (relax 1) of this substep:
 * the closing speed at the instant the gap closes (APPROACH, SUBSTEP PHASE).
 * u is the speed the gap closes at, the less negative of rel and what external forces
 * alone would have made it: a relax pass foresees the next substep, whose velocity
 * integration adds a h first. A substep's velocity is its mean (semi-implicit Euler
 * drifts at the velocity after the kick), so at the instant the gap closes, tau into the
 * substep, the speed is u + a (tau - h/2), tau = s / |u| (0 when touching, or when the
 * relax pass of the last substep foresees a closing in the next step, which the rebound
 * then leaves at the gap). Out of line: it runs once per bouncing point and step. */
PG__NOINLINE void record_approach(const step_context *ctx, constraint_point *p, int64_t rel, int64_t s, int relax)
{
    const int64_t h = ctx->h_q32, a = p->approach_accel;
    int64_t t = h * (int64_t)(ctx->sub + 1u + (uint32_t)relax); /* the end of the closing substep, Q32 s */
    int64_t external = (int64_t)p->approach_start + pg__mul64_shr(a, t, 32), u, tau = 0;
    if (relax) rel += pg__mul64_shr(a, h, 32);
    u = rel > external ? rel : external;
    if (s > 0 && u < 0 && !(relax && ctx->sub + 1u == ctx->world->def.substeps)) {
        /* |u| >= 1 and, below 2^38, s 2^24 / |u| < 2^62: Q24, then Q32; at most h (a gap
         * of 2^38, 4.2 million m, closes in no substep) */
        tau = s >= (INT64_C(1) << 38) ? h : (s << 24) / -u;
        tau = tau >= (h >> 8) + 1 ? h : tau << 8;
    }
    /* reachable inside the envelope (a 50 m body's rim at 1000 rad/s moves 50000 m/s):
     * a clamped value is counted by pg__contacts_store */
    p->relative_velocity = pg__sat64(u + pg__mul64_shr(a, tau - h / 2, 32));
}

/* The approach speed a bouncing point rebounds from (APPROACH), recorded just before it
 * first pushes in this step and kept from then on. */
PG__INLINE_ROW void note_approach(const step_context *ctx, const constraint *c, constraint_point *p, int64_t rel, int64_t s, int relax)
{
    if (c->restitution != 0 && p->max_normal_impulse == 0) record_approach(ctx, p, rel, s, relax);
}

/* One normal row at separation s with relative normal speed rel (measured from va, vb
 * as they are now). */
PG__INLINE_PASS void solve_normal(const step_context *ctx, const softness *soft, const constraint *c, velocity *va, velocity *vb,
                                 constraint_point *p, int64_t s, int64_t rel, int use_bias)
{
    int is_soft;
    int64_t b = normal_target(ctx, soft, p, s, rel, use_bias, &is_soft);
    note_approach(ctx, c, p, rel, s, !use_bias);
    normal_apply(c, va, vb, p, normal_update(soft, p, b, is_soft));
}

/* y = E^-1 b for the pair's coupling E = [1 e01; e10 1]; |b0|, |b1| < 2^32, so
 * |b - e b'| < 2^33 (|e| <= 1) and with inv_det <= 2^28 the products fit. */
PG__INLINE_ROW void block_inverse(const constraint *c, int32_t e01, int32_t e10, int64_t b0, int64_t b1, int64_t *y0, int64_t *y1)
{
    *y0 = row_round((b0 - row_round((int64_t)e01 * b1, 30)) * c->inv_det, 24);
    *y1 = row_round((b1 - row_round((int64_t)e10 * b0, 30)) * c->inv_det, 24);
}

/* Both |b| below 2^32 (65536 m/s): the block's fast path. */
static inline int block_targets_fit(int64_t b0, int64_t b1)
{
    const uint64_t lim = UINT64_C(1) << 32;
    return (uint64_t)b0 + lim < 2 * lim && (uint64_t)b1 + lim < 2 * lim;
}

/* The two normal rows of a manifold solved together (BLOCK): with E
 * the rows' coupling (E b is what lambda changes b by), the change -E^-1 b solves both
 * at once, where one after the other the first takes the blow. Returns 0, having
 * changed nothing, when a row would pull (lambda < 0) or a target is beyond the fast
 * path; the rows are then solved one after the other. */
PG__INLINE_PASS int solve_normal_pair(const step_context *ctx, const softness *soft, const constraint *c, velocity *va, velocity *vb,
                                      constraint_point *p0, constraint_point *p1, int64_t s0, int64_t s1, int64_t rel0, int64_t rel1,
                                      int use_bias)
{
    int soft0, soft1;
    int64_t b0 = normal_target(ctx, soft, p0, s0, rel0, use_bias, &soft0);
    int64_t b1 = normal_target(ctx, soft, p1, s1, rel1, use_bias, &soft1);
    int64_t y0, y1, acc0, acc1;
    /* both gaps open or opening and nothing held: each row, alone or together, would only
     * clamp at 0 (a quarter of the pyramid's pairs: boxes side by side in a row) */
    if (b0 >= 0 && b1 >= 0 && p0->normal_impulse == 0 && p1->normal_impulse == 0) return 1;
    if (!block_targets_fit(b0, b1)) return 0;
    block_inverse(c, c->e01, c->e10, b0, b1, &y0, &y1);
    acc0 = normal_update(soft, p0, y0, soft0);
    acc1 = normal_update(soft, p1, y1, soft1);
    if (acc0 < 0 || acc1 < 0) return 0;
    note_approach(ctx, c, p0, rel0, s0, !use_bias);
    note_approach(ctx, c, p1, rel1, s1, !use_bias);
    normal_apply_pair(va, vb, p0, acc0, p1, acc1, c->twin);
    return 1;
}

/* Whether a normal row at separation s and relative speed rel wants nothing of a point
 * that holds no impulse: its target b >= 0, so the rigid and the soft update both leave
 * lambda at 0, alone or solved as a block (see LAZY ROWS). */
PG__INLINE_ROW int row_idle(const step_context *ctx, const softness *soft, const constraint_point *p, int64_t s, int64_t rel, int use_bias)
{
    int is_soft;
    return normal_target(ctx, soft, p, s, rel, use_bias, &is_soft) >= 0;
}

PG__INLINE_PASS void solve_constraint(const step_context *ctx, const softness *softs, constraint *c, solver_body *bodies, int use_bias, int order)
{
    solver_body *A = &bodies[c->a], *B = &bodies[c->b];
    velocity va, vb;
    const softness *soft = &softs[c->soft_static];
    /* The separations first, then the velocities, and the sides found again for the
     * store: positions, velocities and the two sides' addresses are not all live at
     * once, which would spill them. */
    if (c->count < 2) {
        constraint_point *p = &c->p[0];
        int64_t s = normal_separation(c, A, B, p, use_bias), rel;
        if (use_bias) set_push(ctx, soft, c, p, s);
        va = load_velocity(A);
        vb = load_velocity(B);
        rel = normal_speed(c, &va, &vb, p);
        if (!c->rows_ready) {
            /* nothing held (LAZY ROWS): and while nothing is wanted, nothing moves */
            if (row_idle(ctx, soft, p, s, rel, use_bias)) return; /* va, vb untouched: nothing to store */
            prepare_rows(ctx, c);
        }
        solve_normal(ctx, soft, c, &va, &vb, p, s, rel, use_bias);
    } else {
        constraint_point *p0 = &c->p[0], *p1 = &c->p[1];
        int64_t s0, s1, lin, rel0, rel1;
        if (use_bias) {
            /* the soft pass: positions have not moved since the last relax pass (or the
             * step's start), so its separations hold */
            s0 = p0->separation;
            s1 = p1->separation;
            set_push(ctx, soft, c, p0, s0);
            set_push(ctx, soft, c, p1, s1);
        } else {
            relax_separations(c, A, B, &s0, &s1);
        }
        va = load_velocity(A);
        vb = load_velocity(B);
        /* both points see the same linear part of the relative normal speed; with
         * normal_linear every r x n is 0, so the angular part adds round(0) = 0 */
        lin = linear_speed(&va, &vb, c->n);
        rel0 = lin + angular_speed(&va, &vb, p0->cnA, p0->cnB);
        rel1 = lin + angular_speed(&va, &vb, p1->cnA, p1->cnB);
        if (!c->block && !c->rows_ready) { /* a block's rows are ready: one test on the common path */
            if (row_idle(ctx, soft, p0, s0, rel0, use_bias) && row_idle(ctx, soft, p1, s1, rel1, use_bias)) return;
            prepare_rows(ctx, c);
        }
        /* the block is the same in either order (SYMMETRY), so it takes the points as
         * they are; the rows one after the other alternate */
        if (!c->block || !solve_normal_pair(ctx, soft, c, &va, &vb, p0, p1, s0, s1, rel0, rel1, use_bias)) {
            /* one after the other, alternating which goes first (SYMMETRY); the
             * block changed nothing when it declined, so the first's speed still holds */
            constraint_point *first = order ? p1 : p0, *second = order ? p0 : p1;
            solve_normal(ctx, soft, c, &va, &vb, first, order ? s1 : s0, order ? rel1 : rel0, use_bias);
            solve_normal(ctx, soft, c, &va, &vb, second, order ? s0 : s1, normal_speed(c, &va, &vb, second), use_bias);
        }
    }
    /* Friction after the normal rows, bounded by this pass's normal impulse (Box2D v3's
     * order). Before them, the relax pass would bound friction by the soft pass's impulse,
     * which carries less than the load until the contact has sunk to the soft spring's
     * resting depth; in Q16.16 it may never get there (the last of the sinking moves a
     * body less than half a position step per substep), and friction would be weak. */
    if ((ctx->effects & PG__EFFECT(PG_EFFECT_FRICTION)) != 0) {
        /* one row: a single point's, or a face contact's central row (CENTRAL FRICTION:
         * with friction on, every two-point manifold has one), bounded by both points */
        int64_t bound = friction_bound(&c->p[0]);
        pg_dir t;
        t.x = c->n.y;
        t.y = -c->n.x;
        if (c->central_friction) bound += friction_bound(&c->p[1]);
        solve_friction(&va, &vb, &c->p[0], t, bound, c->twin);
    }
    store_velocity(&bodies[c->a], &va);
    store_velocity(&bodies[c->b], &vb);
}

/* A body's pseudo velocity as a velocity (no turn: the pseudo rows are linear), and back,
 * clamped to the row kernel's bounds as store_velocity clamps v (DEEP PUSH). */
static inline velocity load_pseudo(const solver_body *b)
{
    velocity v;
    v.x = b->pv.x;
    v.y = b->pv.y;
    v.w = 0;
    return v;
}

static inline void store_pseudo(solver_body *b, const velocity *v)
{
    b->pv = pg_v2(clamp_velocity(v->x), clamp_velocity(v->y));
    b->saturated |= (uint32_t)(b->pv.x != v->x || b->pv.y != v->y);
}

/* One pseudo row (DEEP PUSH): the accumulated pseudo lambda becomes acc, clamped to
 * [0, LAMBDA_MAX], and the change moves the pseudo velocities along the normal only. */
PG__INLINE_ROW void deep_row(velocity *pa, velocity *pb, constraint_point *p, int64_t acc)
{
    int64_t lambda = clamp_lambda(acc, 0, LAMBDA_MAX) - p->deep_impulse;
    if (lambda == 0) return;
    p->deep_impulse = (pg_fix)(p->deep_impulse + lambda);
    apply_linear(pa, pb, lambda, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y);
}

/* One sweep of the pseudo rows over the constraints, forwards or backwards; DEEP_PUSH_SWEEPS
 * of them per substep, alternating, so a push travels both ways along a chain (a column
 * of twenty overlapping boxes). */
#define DEEP_PUSH_SWEEPS 4
PG__NOINLINE void solve_deep_push(const step_context *ctx, constraint *cons, const uint32_t *list, uint32_t n_list, solver_body *bodies,
                                  int order, int backward)
{
    uint32_t k;
    for (k = 0; k < n_list; ++k) {
        constraint *c = &cons[list[backward ? n_list - 1u - k : k]];
        solver_body *A = &bodies[c->a], *B = &bodies[c->b];
        velocity pa = load_pseudo(A), pb = load_pseudo(B);
        int32_t j;
        for (j = 0; j < c->count; ++j) {
            constraint_point *p = &c->p[(c->count == 2 && order) ? 1 - j : j];
            /* a gap (the separation this substep's soft pass used): pseudo motion may
             * close it in the substep, as v may; touching: the excess push-out or 0.
             * The clamp changes nothing: an offset of 32768 m/s or more outweighs any
             * linear_speed (|.| <= 2^30.5, 23170 m/s), so b > 0 with or without it, and
             * deep_row's acc, deep_impulse - b < 8192 - 9598, clamps to 0 either way. */
            int64_t offset = p->separation > 0 ? pg__sat64(p->separation * ctx->n) : p->deep_push;
            int64_t b = linear_speed(&pa, &pb, c->n) + offset;
            if (b >= 0 && p->deep_impulse == 0) continue; /* wants nothing, holds nothing */
            if (!c->rows_ready) prepare_rows(ctx, c);  /* the coefficients, first needed now */
            deep_row(&pa, &pb, p, (int64_t)p->deep_impulse - b);
        }
        store_pseudo(A, &pa);
        store_pseudo(B, &pb);
    }
}

/* The constraints of this substep's pseudo pass, in constraint order: the deep ones, and
 * every other that holds a body they push or a body with pseudo motion, so that a push
 * never drives a body through what it rests on. Returns how many. */
PG__NOINLINE uint32_t list_deep_push(const step_context *ctx, const constraint *cons, uint32_t n_cons, solver_body *bodies, uint32_t *list)
{
    const uint32_t stamp = ctx->sub + 1u;
    uint32_t i, n = 0;
    for (i = 0; i < n_cons; ++i) {
        if (!cons[i].deep) continue;
        bodies[cons[i].a].pushed = bodies[cons[i].b].pushed = stamp;
    }
    bodies[ctx->dummy].pushed = 0; /* the static side of every contact: never a reason */
    for (i = 0; i < n_cons; ++i) {
        const constraint *c = &cons[i];
        const solver_body *A = &bodies[c->a], *B = &bodies[c->b];
        if (c->deep || A->pushed == stamp || B->pushed == stamp || (A->pv.x | A->pv.y | B->pv.x | B->pv.y) != 0) list[n++] = i;
    }
    return n;
}

/* The pseudo velocities at the step's start: the last step's pseudo impulses applied
 * again (DEEP PUSH), from which the passes go on, as warm_start does for v. */
PG__NOINLINE void warm_start_deep_push(constraint *cons, uint32_t n_cons, solver_body *bodies)
{
    uint32_t i;
    for (i = 0; i < n_cons; ++i) {
        constraint *c = &cons[i];
        solver_body *A = &bodies[c->a], *B = &bodies[c->b];
        velocity pa, pb;
        int32_t k;
        if (!c->deep) continue;
        pa = load_pseudo(A);
        pb = load_pseudo(B);
        for (k = 0; k < c->count; ++k)
            if (c->p[k].deep_impulse != 0) apply_linear(&pa, &pb, c->p[k].deep_impulse, c->p[k].nrow.lA_x, c->p[k].nrow.lA_y, c->p[k].nrow.lB_x, c->p[k].nrow.lB_y);
        store_pseudo(A, &pa);
        store_pseudo(B, &pb);
    }
}

PG__INLINE_PASS void warm_start(constraint *c, solver_body *bodies)
{
    solver_body *A, *B;
    velocity va, vb;
    int32_t k;
    if (!c->rows_ready) return; /* nothing held, and nothing wanted since (LAZY ROWS) */
    A = &bodies[c->a];
    B = &bodies[c->b];
    va = load_velocity(A);
    vb = load_velocity(B);
    if (c->count == 2) {
        /* a manifold's three rows at once: its two normal rows and p[0]'s tangent row (p[1]
         * holds no tangent impulse: it is the central row's, CENTRAL FRICTION, or friction
         * is off), each component changed by the sum of the same roundings (a row whose
         * impulse is 0, or a side's g = 0 where normal_linear, adds round(0) = 0) */
        const constraint_point *p0 = &c->p[0], *p1 = &c->p[1];
        int64_t n0 = p0->normal_impulse, n1 = p1->normal_impulse, t0 = p0->tangent_impulse;
        int64_t ax = row_round(n0 * p0->nrow.lA_x, 30) + row_round(n1 * p1->nrow.lA_x, 30) + row_round(t0 * p0->trow.lA_x, 30);
        int64_t ay = row_round(n0 * p0->nrow.lA_y, 30) + row_round(n1 * p1->nrow.lA_y, 30) + row_round(t0 * p0->trow.lA_y, 30);
        va.x -= ax;
        va.y -= ay;
        va.w -= row_round(n0 * p0->nrow.gA, 24) + row_round(n1 * p1->nrow.gA, 24) + row_round(t0 * p0->trow.gA, 24);
        vb.x += c->twin ? ax : row_round(n0 * p0->nrow.lB_x, 30) + row_round(n1 * p1->nrow.lB_x, 30) + row_round(t0 * p0->trow.lB_x, 30);
        vb.y += c->twin ? ay : row_round(n0 * p0->nrow.lB_y, 30) + row_round(n1 * p1->nrow.lB_y, 30) + row_round(t0 * p0->trow.lB_y, 30);
        vb.w += row_round(n0 * p0->nrow.gB, 24) + row_round(n1 * p1->nrow.gB, 24) + row_round(t0 * p0->trow.gB, 24);
    } else {
        for (k = 0; k < c->count; ++k) {
            constraint_point *p = &c->p[k];
            if (p->normal_impulse == 0 && p->tangent_impulse == 0) continue; /* nothing to apply */
            if (c->normal_linear) apply_linear(&va, &vb, p->normal_impulse, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y);
            else apply_row(&va, &vb, p->normal_impulse, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y, p->nrow.gA, p->nrow.gB);
            if (p->tangent_impulse != 0) apply_row(&va, &vb, p->tangent_impulse, p->trow.lA_x, p->trow.lA_y, p->trow.lB_x, p->trow.lB_y, p->trow.gA, p->trow.gB);
        }
    }
    store_velocity(A, &va);
    store_velocity(B, &vb);
}

/* A point bounces when it approached faster than the threshold just before it first
 * pushed (APPROACH), and it did push during the step. */
static inline int bounces(const constraint_point *p, pg_fix threshold) { return p->relative_velocity <= -threshold && p->max_normal_impulse != 0; }

/* What the rebound row drives to 0: the relative normal speed now plus e times the
 * approach speed, plus half a substep of external acceleration, a h / 2 (lag): the speed
 * a body leaves with is the mean of its next substep less that substep's a h / 2, the
 * same phase record_approach took the approach at (SUBSTEP PHASE). */
static inline int64_t rebound_target(const constraint *c, const velocity *va, const velocity *vb, const constraint_point *p, int64_t lag)
{
    return relative_speed(va, vb, c->n, p->cnA, p->cnB) + pg_fix_mul(c->restitution, p->relative_velocity) +
           pg__mul64_shr(p->approach_accel, lag, 32);
}

static inline void rebound_apply(velocity *va, velocity *vb, constraint_point *p, int64_t acc)
{
    acc = clamp_lambda(acc, 0, LAMBDA_MAX);
    apply_row(va, vb, acc - p->normal_impulse, p->nrow.lA_x, p->nrow.lA_y, p->nrow.lB_x, p->nrow.lB_y, p->nrow.gA, p->nrow.gB);
    p->normal_impulse = (pg_fix)acc;
}

/* lag: half a substep, Q32 s (rebound_target) */
static void restitution(constraint *c, solver_body *bodies, pg_fix threshold, int64_t lag)
{
    solver_body *A = &bodies[c->a], *B = &bodies[c->b];
    velocity va = load_velocity(A), vb = load_velocity(B);
    int32_t k;
    int done = 0;
    if (c->restitution == 0) return;
    if (c->block && bounces(&c->p[0], threshold) && bounces(&c->p[1], threshold)) {
        /* both points bounce: together, as the rows were solved (BLOCK), or the first
         * point takes the whole rebound and a box landing flat leaves spinning */
        constraint_point *p0 = &c->p[0], *p1 = &c->p[1];
        int64_t b0 = rebound_target(c, &va, &vb, p0, lag), b1 = rebound_target(c, &va, &vb, p1, lag);
        if (block_targets_fit(b0, b1)) {
            int64_t y0, y1, acc0, acc1;
            block_inverse(c, c->e01, c->e10, b0, b1, &y0, &y1);
            acc0 = (int64_t)p0->normal_impulse - y0;
            acc1 = (int64_t)p1->normal_impulse - y1;
            if (acc0 >= 0 && acc1 >= 0) {
                rebound_apply(&va, &vb, p0, acc0);
                rebound_apply(&va, &vb, p1, acc1);
                done = 1;
            }
        }
    }
    for (k = 0; !done && k < c->count; ++k) {
        constraint_point *p = &c->p[k];
        if (bounces(p, threshold)) rebound_apply(&va, &vb, p, (int64_t)p->normal_impulse - rebound_target(c, &va, &vb, p, lag));
    }
    store_velocity(A, &va);
    store_velocity(B, &vb);
}

/* Constraint c for contact i (which has points and a moving side): anchors, lever arms and
 * impulses from the state at the step's start, and the rows' coefficients when a point
 * holds an impulse (LAZY ROWS). activeA, activeB: pg__body_is_active of its two bodies,
 * which prepare_constraints has found. */
static void prepare_constraint(const step_context *ctx, solver_body *bodies, constraint *c, uint32_t i, int activeA, int activeB)
{
    const pg_world *w = ctx->world;
    const uint32_t dummy = ctx->dummy, effects = ctx->effects;
    const int rotation = ctx->rotation;
    pg_contact *ct = &w->contacts[i];
    const pg_body *A = &w->bodies[ct->body_a], *B = &w->bodies[ct->body_b];
    int32_t k;
    int held = 0; /* a point has an impulse to warm start with */
    int turnA, turnB;
    pg_vec2 A_center = A->center, B_center = B->center;
    /* A side that does not take part in this step is the dummy, and the rows must see
     * it as infinitely heavy so that no impulse ever moves the dummy, which stands in
     * for every static side. (A sleeping body touching a moving one is woken by the
     * contact update before the solve, so in practice that side is static.) */
    if (!activeA) A = &immovable;
    if (!activeB) B = &immovable;
    c->a = activeA ? ct->body_a : dummy;
    c->b = activeB ? ct->body_b : dummy;
    c->contact = i;
    c->n = ct->normal;
    c->count = (uint8_t)ct->point_count; /* 1 or 2: contacts without points have no constraint */
    /* A side that cannot move gets the stiffer softness, and so does a pair whose
     * masses differ 4:1 or more: a soft contact's steady overlap grows with the load
     * over the lighter body's mass, and this halves it where the ratio is large.
     * (Inverse masses are >= 0: x / 4 is x >> 2, without the rounding toward 0.) */
    c->twin = A->inv_mass == B->inv_mass;
    c->soft_static = A->inv_mass == 0 || B->inv_mass == 0 || (A->inv_mass >> 2) >= B->inv_mass || (B->inv_mass >> 2) >= A->inv_mass;
    c->round_a = (uint8_t)centred_circle(w, ct->shape_a, ct->body_a);
    c->round_b = (uint8_t)centred_circle(w, ct->shape_b, ct->body_b);
    if (!c->round_a) bodies[c->a].turns_anchors = 1;
    if (!c->round_b) bodies[c->b].turns_anchors = 1;
    c->normal_linear = 1;
    c->restitution = (effects & PG__EFFECT(PG_EFFECT_RESTITUTION)) != 0 ? ct->restitution : 0;
    c->deep = 0; /* deep_push is set by every soft pass (set_push) before it is read */
    /* No torque about a round side's centre, and none on a side that cannot turn in this
     * step (its angular velocity is 0 and its inverse inertia too). */
    turnA = !c->round_a && activeA && rotation;
    turnB = !c->round_b && activeB && rotation;
    for (k = 0; k < c->count; ++k) {
        constraint_point *p = &c->p[k];
        const pg_contact_point *cp = &ct->points[k];
        {
            /* Anchors on each body's own surface (the manifold point is midway between
             * them): a speculative point can be far from both bodies, and an anchor out
             * there would swing with the body's rotation and fake the gap. */
            int64_t hx = row_round((int64_t)c->n.x * cp->separation, 31);
            int64_t hy = row_round((int64_t)c->n.y * cp->separation, 31);
            /* rA, rB never clamp inside the envelope: an anchor lies on its body's
             * surface, within its reach (50 m, a static body's 1000 m) of the centre */
            pg_vec2 rA = pg_v2(pg__sat64((int64_t)cp->point.x - hx - A_center.x), pg__sat64((int64_t)cp->point.y - hy - A_center.y));
            pg_vec2 rB = pg_v2(pg__sat64((int64_t)cp->point.x + hx - B_center.x), pg__sat64((int64_t)cp->point.y + hy - B_center.y));
            /* in int64: a restored snapshot may hold any contact point, and anchors
             * saturated at the edge of the range are up to 2^32 apart; n . r and r x n are
             * below 2^61.5 in Q46 and 2^31.5 rounded to Q16, kept in int64 (only the lever
             * arms, pg_fix, saturate). r x t = -(n . r) exactly (t = (n.y, -n.x)): the
             * tangent lever arms round the same products */
            int64_t nrA = (int64_t)c->n.x * rA.x + (int64_t)c->n.y * rA.y;
            int64_t nrB = (int64_t)c->n.x * rB.x + (int64_t)c->n.y * rB.y;
            int64_t along;
            p->nrA = row_round(nrA, 30);
            p->nrB = row_round(nrB, 30);
            p->xrA = row_round((int64_t)rA.x * c->n.y - (int64_t)rA.y * c->n.x, 30); /* r x n */
            p->xrB = row_round((int64_t)rB.x * c->n.y - (int64_t)rB.y * c->n.x, 30);
            /* what normal_separation finds before anything moves (dp = 0, dq = 1: each
             * anchor_along is nr 2^30), for the first substep's soft pass */
            along = p->nrB - p->nrA;
            /* never clamps inside the envelope: the separation is within the speculative
             * window (16384 m, contact.c) and |along| within two reaches (2000 m) */
            p->adjusted_separation = pg__sat64((int64_t)cp->separation - along);
            p->separation = along + p->adjusted_separation;
            p->ctA = (pg_fix)row_round(-nrA, 30); /* rA x t */
            p->ctB = (pg_fix)row_round(-nrB, 30);
        }
        /* a turning body is dynamic or kinematic: |r| <= 50 m, no clamp. The cached
         * impulses below are what pg__contacts_store wrote (within [0, L] and [-L, L]) or
         * what a restore accepted (state.c refuses beyond L): those clamps never bite. */
        p->cnA = turnA ? pg__sat64(p->xrA) : 0;
        p->cnB = turnB ? pg__sat64(p->xrB) : 0;
        if (p->cnA != 0 || p->cnB != 0) c->normal_linear = 0;
        p->normal_impulse = (pg_fix)clamp_lambda(cp->normal_impulse, 0, LAMBDA_MAX);
        p->tangent_impulse = (effects & PG__EFFECT(PG_EFFECT_FRICTION)) != 0 ? (pg_fix)clamp_lambda(cp->tangent_impulse, -LAMBDA_MAX, LAMBDA_MAX) : 0;
        p->max_normal_impulse = 0;
        if (p->normal_impulse != 0 || p->tangent_impulse != 0) held = 1;
        p->relative_velocity = 0; /* set before the point first pushes (APPROACH) */
        p->approach_start = p->approach_accel = 0;
        if ((p->deep_impulse = (pg_fix)clamp_lambda(cp->push_impulse, 0, LAMBDA_MAX)) != 0) {
            c->deep = 1;
            held = *ctx->deep_seen = 1;
        }
    }
    if (c->restitution != 0) {
        velocity va = load_velocity(&bodies[c->a]), vb = load_velocity(&bodies[c->b]), aa, ab;
        aa.x = bodies[c->a].accel.x; aa.y = bodies[c->a].accel.y; aa.w = bodies[c->a].alpha;
        ab.x = bodies[c->b].accel.x; ab.y = bodies[c->b].accel.y; ab.w = bodies[c->b].alpha;
        for (k = 0; k < c->count; ++k) {
            constraint_point *p = &c->p[k];
            /* reachable (rim speeds, as relative_velocity): counted by pg__contacts_store */
            p->approach_start = pg__sat64(relative_speed(&va, &vb, c->n, p->cnA, p->cnB));
            p->approach_accel = pg__sat64(relative_speed(&aa, &ab, c->n, p->cnA, p->cnB));
        }
    }
    /* CENTRAL FRICTION: the row's lever arms are those of the mean anchor (r x t is linear
     * in r), and its lambda is what the two points stored */
    c->central_friction = c->count == 2 && (effects & PG__EFFECT(PG_EFFECT_FRICTION)) != 0;
    if (c->central_friction) {
        constraint_point *p0 = &c->p[0], *p1 = &c->p[1];
        p0->ctA = (pg_fix)row_round((int64_t)p0->ctA + p1->ctA, 1);
        p0->ctB = (pg_fix)row_round((int64_t)p0->ctB + p1->ctB, 1);
        p0->tangent_impulse = (pg_fix)clamp_lambda((int64_t)p0->tangent_impulse + p1->tangent_impulse, -LAMBDA_MAX, LAMBDA_MAX);
        p1->tangent_impulse = 0;
    }
    c->rows_ready = 0;
    c->block = 0; /* restitution reads it: a constraint whose rows never get set never pushed */
    if (held) prepare_rows_of(ctx, c, A, B);
}

/* The step's constraints, one per contact with points and a moving side: first those
 * between two moving bodies, then those with a side that cannot move, each group in
 * contact order (ORDER). `later` (room for every contact) holds the second group's
 * contacts meanwhile. Returns how many. Out of line: its divisions and wide products are
 * set-up, done once a step, and kept out of the stage loops. */
PG__NOINLINE uint32_t prepare_constraints(const step_context *ctx, solver_body *bodies, constraint *cons, uint32_t *later)
{
    const pg_world *w = ctx->world;
    uint32_t n_cons = 0, n_later = 0, i;
    for (i = 0; i < w->contact_count; ++i) {
        const pg_contact *ct = &w->contacts[i];
        const pg_body *A = &w->bodies[ct->body_a], *B = &w->bodies[ct->body_b];
        int activeA = pg__body_is_active(A), activeB = pg__body_is_active(B);
        if (ct->point_count == 0 || (!activeA && !activeB)) continue;
        /* a side that cannot move in this step: static, kinematic or asleep */
        if (!activeA || !activeB || A->inv_mass == 0 || B->inv_mass == 0) later[n_later++] = i;
        else prepare_constraint(ctx, bodies, &cons[n_cons++], i, 1, 1);
    }
    for (i = 0; i < n_later; ++i) {
        const pg_contact *ct = &w->contacts[later[i]];
        prepare_constraint(ctx, bodies, &cons[n_cons++], later[i], pg__body_is_active(&w->bodies[ct->body_a]),
                           pg__body_is_active(&w->bodies[ct->body_b]));
    }
    return n_cons;
}

/* The central friction row's lambda stored on the contact's two points in proportion to
 * their normal impulses (CENTRAL FRICTION); half each, rounded, when neither holds one.
 * |total| <= 2^29 and each normal impulse <= 2^29, so total n0 fits int64; the quotient
 * rounds to nearest, ties away from zero (wide.h), and the two parts add up to the
 * total exactly. */
static void split_central_friction(const constraint *c, pg_contact *ct)
{
    int64_t total = c->p[0].tangent_impulse, n0 = c->p[0].normal_impulse, n1 = c->p[1].normal_impulse, part0;
    if (n0 + n1 > 0 && n0 + n1 <= (int64_t)UINT32_MAX) {
        /* pg__div64_shl(total n0, n0 + n1, 0) with a division by a 32-bit number: the same
         * quotient, rounded the same way (|total n0| <= 2^58, so no clamp applies) */
        uint64_t un = pg__mag64(total * n0), q = pg__udiv64_32(un, (uint32_t)(n0 + n1)), r = un - q * (uint64_t)(n0 + n1);
        if (r >= (uint64_t)(n0 + n1) - r) ++q;
        part0 = total * n0 < 0 ? -(int64_t)q : (int64_t)q;
    } else {
        part0 = n0 + n1 > 0 ? pg__div64_shl(total * n0, n0 + n1, 0) : row_round(total, 1);
    }
    ct->points[0].tangent_impulse = (pg_fix)part0;
    ct->points[1].tangent_impulse = (pg_fix)(total - part0);
}

/* ---- the stages ------------------------------------------------------------------------ */

size_t pg__contact_constraint_bytes(uint32_t max_contacts) { return sizeof(constraint) * max_contacts; }

void pg__contacts_set_softness(step_context *ctx, const pg_world_def *def)
{
    pg_fix hertz, hertz_static, hertz_cap;
    /* SOFTNESS CAP: no softness is stiffer than a quarter of the substep rate, omega h =
     * pi / 2 (Box2D v3's first cap on its contact hertz; its later versions cap that at
     * an eighth, so that the doubled static softness stays within a quarter). The
     * stiffer softness of a side that cannot move or a 4:1 pair, twice the contact's, is
     * capped too: at the defaults (30 Hz, 240 substeps a second) it is exactly at the
     * cap, but at 2 substeps (60 Hz at 120 a second, omega h = pi), at 1, or at 60 Hz it
     * was past it, where the soft step is not stable: a heavy box on a light one shook at
     * 0.5-4 m/s or fell through it (test_mass_ratio_within_the_softness_cap). */
    /* cppcheck-suppress ctuuninitvar ; pg__solve sets ctx->n before this call, which fills in the rest */
    hertz_cap = (pg_fix)((int64_t)ctx->n * 16384); /* n / 4 in Q16.16, exact; n <= 16000 */
    hertz = def->contact_hertz < hertz_cap ? def->contact_hertz : hertz_cap;
    hertz_static = pg_fix_add(hertz, hertz);
    if (hertz_static > hertz_cap) hertz_static = hertz_cap;
    ctx->soft = pg__make_soft(hertz, def->contact_damping_ratio, ctx->n);
    ctx->soft_static = pg__make_soft(hertz_static, def->contact_damping_ratio, ctx->n);
    ctx->push_max = def->contact_push_max;
    ctx->push_floor = ctx->push_max / 32;
    ctx->soft.floor_depth = floor_depth(&ctx->soft, ctx->push_floor);
    ctx->soft_static.floor_depth = floor_depth(&ctx->soft_static, ctx->push_floor);
}

void pg__contacts_prepare(pg_contact_stage *s, step_context *ctx, solver_body *bodies, void *area, uint32_t *deep_list)
{
    s->cons = (constraint *)area;
    s->deep_list = deep_list;
    s->deep = 0;
    ctx->deep_seen = &s->deep;
    /* two moving sides first, then one that cannot move (ORDER); deep_list is free until
     * the substeps */
    s->count = prepare_constraints(ctx, bodies, s->cons, deep_list);
    if (s->deep) warm_start_deep_push(s->cons, s->count, bodies);
}

/* WARM START: the first substep applies each constraint's stored impulses with this
 * step's coefficients; every later one applies again, per body, what the contacts changed
 * over the substep before (solver_body's dv), which is the sum of the same impulses'
 * changes, each already rounded. That is the contacts' change alone while they are the
 * only kind that moves velocities: a kind added beside them subtracts what it changed
 * from dv, and warm starts its own rows. */
void pg__contacts_warm_start(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies, const uint32_t *active,
                             uint32_t n_active)
{
    uint32_t i;
    if (ctx->sub == 0) {
        constraint *cons = s->cons;
        const uint32_t n_cons = s->count;
        for (i = 0; i < n_cons; ++i) warm_start(&cons[i], bodies);
        return;
    }
    for (i = 0; i < n_active; ++i) {
        solver_body *sb = &bodies[active[i]];
        /* v within the kernel's bounds and |dv| < 2^32: the sums are clamped like a store */
        if ((sb->dv_x | sb->dv_y | sb->dw) != 0) {
            int64_t vx = (int64_t)sb->v.x + sb->dv_x, vy = (int64_t)sb->v.y + sb->dv_y, w = sb->w + sb->dw;
            sb->v.x = clamp_velocity(vx);
            sb->v.y = clamp_velocity(vy);
            sb->w = clamp_velocity(w);
            sb->saturated |= (uint32_t)(sb->v.x != vx || sb->v.y != vy || sb->w != w);
        }
    }
}

/* The solve and relax stages copy the context and the constraint list into locals: the
 * rows' stores through the bodies could otherwise alias them, and every row would load
 * them again. */
void pg__contacts_solve(const pg_contact_stage *s, const step_context *ctx_in, solver_body *bodies)
{
    const step_context ctx = *ctx_in;
    constraint *cons = s->cons;
    const uint32_t n_cons = s->count;
    const int order = (int)(ctx.sub & 1u);
    softness softs[2]; /* indexed by a constraint's soft_static (0 or 1) */
    uint32_t i;
    softs[0] = ctx.soft;
    softs[1] = ctx.soft_static;
    for (i = 0; i < n_cons; ++i) solve_constraint(&ctx, softs, &cons[i], bodies, 1, order);
    if (s->deep) {
        uint32_t n_list = list_deep_push(&ctx, cons, n_cons, bodies, s->deep_list);
        int it;
        for (it = 0; it < DEEP_PUSH_SWEEPS; ++it) solve_deep_push(&ctx, cons, s->deep_list, n_list, bodies, order, it & 1);
    }
}

void pg__contacts_relax(const pg_contact_stage *s, const step_context *ctx_in, solver_body *bodies)
{
    const step_context ctx = *ctx_in;
    constraint *cons = s->cons;
    const uint32_t n_cons = s->count;
    const int order = (int)(ctx.sub & 1u);
    softness softs[2];
    uint32_t i;
    softs[0] = ctx.soft;
    softs[1] = ctx.soft_static;
    for (i = 0; i < n_cons; ++i) solve_constraint(&ctx, softs, &cons[i], bodies, 0, order);
}

void pg__contacts_restitution(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies)
{
    uint32_t i;
    if ((ctx->effects & PG__EFFECT(PG_EFFECT_RESTITUTION)) == 0) return;
    for (i = 0; i < s->count; ++i) restitution(&s->cons[i], bodies, ctx->world->def.restitution_threshold, ctx->h_q32 / 2);
}

static inline int at_edge(pg_fix v) { return v == PG_FIX_MAX || v == PG_FIX_MIN; }

void pg__contacts_store(const pg_contact_stage *s, pg_world *w)
{
    uint32_t i, held_at_bound = 0;
    for (i = 0; i < s->count; ++i) {
        const constraint *c = &s->cons[i];
        pg_contact *ct = &w->contacts[c->contact];
        int32_t k;
        if (c->central_friction) split_central_friction(c, ct);
        for (k = 0; k < c->count; ++k) {
            ct->points[k].normal_impulse = c->p[k].normal_impulse;
            if (!c->central_friction) ct->points[k].tangent_impulse = c->p[k].tangent_impulse;
            ct->points[k].max_normal_impulse = c->p[k].max_normal_impulse;
            /* only a point still deep keeps its pseudo impulse: the pseudo pass ends with
             * the overlap that called for it (DEEP PUSH) */
            ct->points[k].push_impulse = c->p[k].deep_push < 0 ? c->p[k].deep_impulse : 0;
            /* stats.saturations: an impulse the rows clamped to LAMBDA_MAX (normal_apply,
             * rebound_apply, deep_row, the friction bound and the central row's sum;
             * max_normal_impulse is the largest normal one of the step), or a speed of the
             * approach left at the edge of Q16.16 */
            held_at_bound += (uint32_t)(c->p[k].max_normal_impulse == LAMBDA_MAX || c->p[k].normal_impulse == LAMBDA_MAX ||
                                        c->p[k].deep_impulse == LAMBDA_MAX || c->p[k].tangent_impulse == LAMBDA_MAX ||
                                        c->p[k].tangent_impulse == -LAMBDA_MAX || at_edge(c->p[k].relative_velocity) ||
                                        at_edge(c->p[k].approach_start) || at_edge(c->p[k].approach_accel));
        }
    }
    if (held_at_bound != 0) pg__count_saturations(w, held_at_bound);
}
