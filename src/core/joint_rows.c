/* joint_rows.c — the set-up of the joints' rows (joint_rows.h): sides, the point
 * block's normalised inverse and the scalar rows' coefficients, made once a step with
 * wide products and divisions (wide.h), then used by the substeps' int64 rows. */
#include "intmath.h"
#include "joint_rows.h"

static int64_t add_sat(int64_t a, int64_t b) { return a > INT64_MAX - b ? INT64_MAX : a + b; } /* a, b >= 0 */
/* a - b for |a|, |b| <= INT64_MAX, saturated to +-INT64_MAX (never INT64_MIN, so the result
 * can be negated): only lever arms and inertias far outside the envelope reach it */
static int64_t sub_sat(int64_t a, int64_t b)
{
    if (b > 0) return a < -INT64_MAX + b ? -INT64_MAX : a - b;
    return a > INT64_MAX + b ? INT64_MAX : a - b;
}

static int32_t sat32(int64_t v) { return v > INT32_MAX ? INT32_MAX : v < -INT32_MAX ? -INT32_MAX : (int32_t)v; }

void pg__joint_side_init(joint_side *s, const pg_world *w, uint32_t body, pg_vec2 anchor, int active, uint32_t slot, int rotation)
{
    const pg_body *b = &w->bodies[body];
    s->active = active;
    s->slot = slot;
    s->change = NULL; /* joint_solver.c points a moving side at its body's */
    s->inv_mass = active ? b->inv_mass : 0;
    s->inv_inertia = active && rotation ? b->inv_inertia : 0;
    s->local = pg_v2(pg__sat64((int64_t)anchor.x - b->local_center.x), pg__sat64((int64_t)anchor.y - b->local_center.y));
    s->lever = pg_rot_apply(b->rot, s->local);
    s->lever_now = s->lever;
    s->dq_seen = pg_rot_identity();
    s->fixed_point = pg_v2_add(b->center, s->lever);
    s->fixed_angle = b->angle;
}

/* (1/I) / S in Q2.30 (<= 2^16 for a radius of gyration >= 2^-8 m; saturates beyond);
 * 0 without a division for a side that does not move (inv = 0) */
static int64_t per_s(int64_t inv, int64_t S) { return S > 0 && inv != 0 ? pg__div64_shl(inv, S, 30) : 0; }

/* per_s(1/mA, S) for S = 1/mA + 1/mB: exactly a half when the two are equal and S did not
 * saturate, as for the identical bodies a chain or a grid joins */
static int64_t per_s_first(int64_t inv, int64_t S, int64_t other)
{
    return inv == other && S - inv == other ? INT64_C(1) << 29 : per_s(inv, S);
}

/* per_s(1/mB, S) for S = 1/mA + 1/mB, from other_per_s = per_s(1/mA, S): the exact
 * quotients add up to 2^30, so their roundings do too unless both are ties, and a tie
 * needs 1/mA 2^31 = (2 n + 1) S, which makes S a multiple of 2^31. For such an S, or a
 * saturated sum, the division itself: the same bits either way, one division fewer. */
static int64_t per_s_rest(int64_t inv, int64_t S, int64_t other, int64_t other_per_s)
{
    if ((S & INT64_C(0x7FFFFFFF)) != 0 && S - other == inv) return (INT64_C(1) << 30) - other_per_s;
    return per_s(inv, S);
}

/* pg__mul64_shr without its 128-bit product when a factor is 0 (the result is then 0):
 * a static side's inverse inertia, and the lever components that are 0 while a body is
 * not turned from an axis-aligned anchor */
static int64_t mul_shr_or_0(int64_t a, int64_t b, int shift) { return a == 0 || b == 0 ? 0 : pg__mul64_shr(a, b, shift); }

static pg_u128 square_u(int64_t v) { return pg__mul_u64(pg__mag64(v), pg__mag64(v)); }

static pg_u128 sub_u128(pg_u128 a, pg_u128 b)
{
    pg_u128 r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo);
    return r;
}

/* 1 / det for det >= 2^60 (the determinant of K' >= I in Q60), as a mantissa and a
 * shift: num 2^60 / det is then mul64_shr(num, recip, shift). One division of det's top
 * 40 bits (truncated: 2^-39 relative) makes the three entries of K'^-1, each within
 * 0.5 + 2^30 2^-39 < 0.51 of a Q30 unit of the exact quotient (|entries| <= 2^30). */
typedef struct det_reciprocal { int64_t recip; int shift; } det_reciprocal;

static det_reciprocal reciprocal_of_det(pg_u128 det)
{
    det_reciprocal r;
    /* det < 2^124 when K' is what it models (entries < 2^62, k12^2 <= k11 k22); a K'
     * saturated far outside the envelope can break that, and det is then held below 2^124
     * so that every shift below stays defined */
    if ((det.hi >> 60) != 0) det.hi = ((uint64_t)1 << 60) - 1u, det.lo = UINT64_MAX;
    int bits = det.hi != 0 ? 64 + pg__bit_length64(det.hi) : pg__bit_length64(det.lo); /* >= 61 */
    int s = bits > 61 ? bits - 40 : 21; /* 21..84; bits >= 61 as det >= 2^60, the floor keeps every shift defined */
    uint64_t d = s >= 64 ? det.hi >> (s - 64) : (det.lo >> s) | (det.hi << (64 - s));  /* [2^39, 2^40) */
    r.recip = pg__div64_shl(INT64_C(1) << 40, (int64_t)d, 61); /* round(2^101 / d), (2^61, 2^62] */
    r.shift = 41 + s;                                           /* 2^60 / det = recip / 2^(41 + s) */
    return r;
}

static int32_t over_det(int64_t num, det_reciprocal r) { return sat32(mul_shr_or_0(num, r.recip, r.shift)); }

void pg__joint_point_init(joint_point *p, const joint_side *A, const joint_side *B)
{
    int64_t S = add_sat(A->inv_mass, B->inv_mass), ia = per_s(A->inv_inertia, S);
    int64_t ib = B->inv_inertia == A->inv_inertia ? ia : per_s(B->inv_inertia, S); /* the same quotient */
    int64_t k11, k12, k22, mAs, mBs;
    pg_vec2 rA = A->lever, rB = B->lever;
    det_reciprocal inv_det;
    p->S = S;
    p->ia = ia;
    p->ib = ib;
    if (S == 0) {
        int k;
        for (k = 0; k < 3; ++k) p->mA[k] = p->mB[k] = p->kinv[k] = 0;
        p->gA[0] = p->gA[1] = p->gB[0] = p->gB[1] = 0;
        p->ia = p->ib = 0;
        return;
    }
    /* K' = I + (1/IA / S) rA_perp rA_perp^T + (1/IB / S) rB_perp rB_perp^T, Q2.30 (r^2 in Q32 < 2^62) */
    k11 = add_sat(add_sat(INT64_C(1) << 30, mul_shr_or_0(ia, (int64_t)rA.y * rA.y, 32)), mul_shr_or_0(ib, (int64_t)rB.y * rB.y, 32));
    k22 = add_sat(add_sat(INT64_C(1) << 30, mul_shr_or_0(ia, (int64_t)rA.x * rA.x, 32)), mul_shr_or_0(ib, (int64_t)rB.x * rB.x, 32));
    k12 = sub_sat(-mul_shr_or_0(ia, (int64_t)rA.x * rA.y, 32), mul_shr_or_0(ib, (int64_t)rB.x * rB.y, 32));
    if (k11 >= INT64_C(1) << 62 || k22 >= INT64_C(1) << 62) { /* lever arms far outside the envelope: keep the products in range */
        const int64_t lim = INT64_MAX - 128; /* pg__round_shift64's range at 8 bits; a saturated k12 stays saturated */
        k11 >>= 8, k22 >>= 8, k12 = pg__round_shift64(k12 > lim ? lim : k12 < -lim ? -lim : k12, 8);
    }
    inv_det = reciprocal_of_det(sub_u128(pg__mul_u64((uint64_t)k11, (uint64_t)k22), square_u(k12)));
    p->kinv[0] = over_det(k22, inv_det);
    p->kinv[1] = over_det(-k12, inv_det);
    p->kinv[2] = over_det(k11, inv_det);
    mAs = per_s_first(A->inv_mass, S, B->inv_mass);
    mBs = per_s_rest(B->inv_mass, S, A->inv_mass, mAs);
    {
        int k;
        for (k = 0; k < 3; ++k) {
            p->mA[k] = (int32_t)row_round(mAs * p->kinv[k], 30);
            p->mB[k] = (int32_t)row_round(mBs * p->kinv[k], 30);
        }
    }
    pg__joint_point_orient(p, rA, rB);
}

void pg__joint_point_orient(joint_point *p, pg_vec2 rA, pg_vec2 rB)
{
    /* g_j = (1/I / S) sum_i r_perp_i kinv_ij, r_perp = (-r.y, r.x): Q16 x Q30 = Q46, then Q30 x Q46 >> 52 = Q24 */
    p->gA[0] = sat32(mul_shr_or_0(p->ia, -(int64_t)rA.y * p->kinv[0] + (int64_t)rA.x * p->kinv[1], 52));
    p->gA[1] = sat32(mul_shr_or_0(p->ia, -(int64_t)rA.y * p->kinv[1] + (int64_t)rA.x * p->kinv[2], 52));
    p->gB[0] = sat32(mul_shr_or_0(p->ib, -(int64_t)rB.y * p->kinv[0] + (int64_t)rB.x * p->kinv[1], 52));
    p->gB[1] = sat32(mul_shr_or_0(p->ib, -(int64_t)rB.y * p->kinv[1] + (int64_t)rB.x * p->kinv[2], 52));
}

void pg__joint_row_linear(joint_row *r, const joint_side *A, const joint_side *B, pg_dir d, pg_vec2 rA, pg_vec2 rB)
{
    int64_t S = add_sat(A->inv_mass, B->inv_mass), ia = per_s(A->inv_inertia, S), ib = per_s(B->inv_inertia, S), Kp, kA, kB;
    pg_fix cA = pg__sat64(row_round((int64_t)rA.x * d.y - (int64_t)rA.y * d.x, 30));
    pg_fix cB = pg__sat64(row_round((int64_t)rB.x * d.y - (int64_t)rB.y * d.x, 30));
    r->on = S > 0;
    r->kA = r->kB = r->qA = r->qB = r->K = 0;
    if (r->on) {
        Kp = add_sat(add_sat(INT64_C(1) << 30, pg__mul64_shr(ia, (int64_t)cA * cA, 32)), pg__mul64_shr(ib, (int64_t)cB * cB, 32));
        kA = pg__div64_shl(per_s(A->inv_mass, S), Kp, 30);
        kB = pg__div64_shl(per_s(B->inv_mass, S), Kp, 30);
        r->kA = kA;
        r->kB = kB;
        r->qA = pg__div64_shl(ia, Kp, 30);
        r->qB = pg__div64_shl(ib, Kp, 30);
        r->K = pg__mul64_shr(S, Kp, 30);
    }
    pg__joint_row_orient(r, d, rA, rB);
}

void pg__joint_row_orient(joint_row *r, pg_dir d, pg_vec2 rA, pg_vec2 rB)
{
    r->d = d;
    r->cA = pg__sat64(row_round((int64_t)rA.x * d.y - (int64_t)rA.y * d.x, 30));
    r->cB = pg__sat64(row_round((int64_t)rB.x * d.y - (int64_t)rB.y * d.x, 30));
    r->lA_x = (int32_t)row_round(r->kA * d.x, 30);
    r->lA_y = (int32_t)row_round(r->kA * d.y, 30);
    r->lB_x = (int32_t)row_round(r->kB * d.x, 30);
    r->lB_y = (int32_t)row_round(r->kB * d.y, 30);
    /* Q30 x Q16 >> 22 = Q24 */
    r->gA = r->qA == 0 ? 0 : sat32(pg__mul64_shr(r->qA, r->cA, 22));
    r->gB = r->qB == 0 ? 0 : sat32(pg__mul64_shr(r->qB, r->cB, 22));
}

void pg__joint_row_angular(joint_row *r, const joint_side *A, const joint_side *B)
{
    int64_t S = add_sat(A->inv_inertia, B->inv_inertia);
    r->d.x = r->d.y = 0;
    r->cA = r->cB = PG_FIX_ONE;
    r->lA_x = r->lA_y = r->lB_x = r->lB_y = 0;
    r->kA = r->kB = r->qA = r->qB = 0;
    r->on = S > 0;
    r->gA = r->on ? sat32(pg__div64_shl(A->inv_inertia, S, 24)) : 0;
    r->gB = r->on ? sat32(pg__div64_shl(B->inv_inertia, S, 24)) : 0;
    r->K = S;
}

/* Box2D v3's b2MakeSoft (solver_kernel.h's pg__make_soft) with h omega and a2 in Q32
 * instead of Q16: at 60 Hz and 240 substeps a second Q16 keeps a2 = (h omega)^2 ... to
 * 2 % only, and a spring's frequency goes as sqrt(a2). hertz is capped at a quarter of
 * the substep rate, as the contacts'. */
static softness precise_soft(pg_fix hertz, pg_fix zeta, uint32_t n)
{
    softness s;
    pg_fix cap = (pg_fix)((int64_t)n * 16384); /* n / 4 Hz, Q16.16 */
    int64_t omega = (int64_t)(hertz < cap ? hertz : cap) * PG_FIX_TWO_PI; /* Q32 rad/s: < 2^26 2^18.7 */
    int64_t h_omega = (omega + (int64_t)n / 2) / (int64_t)n;                      /* Q32, <= pi / 2 */
    int64_t a1 = 2 * (int64_t)zeta * 65536 + h_omega; /* Q32 */
    int64_t a2 = pg__mul64_shr(h_omega, a1, 32);                                   /* Q32 */
    s.bias_rate = a1 > 0 ? pg__sat64(pg__div64_shl(omega, a1, 16)) : 0;
    s.mass_scale = (int32_t)pg__div64_shl(a2, (INT64_C(1) << 32) + a2, 30);
    s.impulse_scale = (int32_t)pg__div64_shl(INT64_C(1) << 32, (INT64_C(1) << 32) + a2, 30);
    s.hold_rate = 0;   /* the contacts' (DEEP PUSH): not used by joints */
    s.floor_depth = 0;
    return s;
}

softness pg__joint_rigid_softness(uint32_t n_per_second) { return precise_soft(PG_FIX_C(1000), PG_FIX_C(5), n_per_second); }

softness pg__joint_spring_softness(pg_fix hertz, pg_fix zeta, uint32_t n_per_second) { return precise_soft(hertz, zeta, n_per_second); }

int64_t pg__joint_row_cap(int64_t K, pg_fix f, int64_t h_q32)
{
    int64_t fh = pg__mul64_shr(f, h_q32, 32); /* Q16 N s */
    int64_t cap = pg__mul64_shr(K, fh, 38);
    return cap > LAMBDA_MAX ? LAMBDA_MAX : cap;
}

int64_t pg__joint_row_impulse(const joint_row *r, int64_t lambda) { return r->K > 0 ? pg__div64_shl(lambda, r->K, 38) : 0; }

void pg__joint_point_impulse(const joint_point *p, const int64_t L[2], int64_t out[2])
{
    /* P = K'^-1 L / S */
    int64_t qx = row_round(p->kinv[0] * L[0] + p->kinv[1] * L[1], 30), qy = row_round(p->kinv[1] * L[0] + p->kinv[2] * L[1], 30);
    out[0] = p->S > 0 ? pg__div64_shl(qx, p->S, 38) : 0;
    out[1] = p->S > 0 ? pg__div64_shl(qy, p->S, 38) : 0;
}

/* ---- the passes' rows (joint_rows.h); out of line: five kinds call them ---- */
int64_t pg__joint_soft_delta(int64_t v, int64_t bias, int64_t acc, const softness *s, int use_soft)
{
    return joint_soft_delta(v, bias, acc, s, use_soft);
}

void pg__joint_point_speed(const velocity *A, const velocity *B, pg_vec2 rA, pg_vec2 rB, int64_t *cx, int64_t *cy)
{
    joint_point_speed(A, B, rA, rB, cx, cy);
}

void pg__joint_point_apply(const joint_point *p, velocity *A, velocity *B, int64_t dx, int64_t dy)
{
    joint_point_apply(p, A, B, dx, dy);
}

void pg__joint_point_solve(joint_constraint *c, velocity *A, velocity *B, int64_t Cx, int64_t Cy, const softness *s, int use_soft)
{
    joint_point_solve(c, A, B, Cx, Cy, s, use_soft);
}

/* An equality row's pass (C: its position error). */
void pg__joint_row_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t C, const softness *s, int use_soft)
{
    int64_t v, bias = 0, n;
    if (!r->on) return;
    v = joint_row_speed(r, A, B);
    if (use_soft) bias = row_round(s->bias_rate * clamp64(C, INT32_MAX), 16);
    n = clamp64(*acc + pg__joint_soft_delta(v, bias, *acc, s, use_soft), LAMBDA_MAX);
    joint_row_apply(r, A, B, n - *acc);
    *acc = n;
}

/* A one-sided row: keeps C >= 0 (sign 1) or C <= 0 (sign -1); lambda >= 0 pushes C up
 * (sign 1) or down. Box2D v3's limit: a gap closes at most by C / h (speculative), an
 * overlap is pushed out softly in the solve pass and only stopped in the relax pass. */
void pg__joint_limit_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t C, int sign,
                                     const softness *s, int use_soft, uint32_t n_per_second)
{
    int64_t v, bias = 0, n, dl;
    int soft = 0;
    if (!r->on) return;
    v = sign * joint_row_speed(r, A, B);
    C = sign * clamp64(C, INT32_MAX);
    if (C > 0) bias = C * (int64_t)n_per_second; /* C / h: may close the gap, no more */
    else if (use_soft) {
        bias = row_round(s->bias_rate * C, 16);
        soft = 1;
    }
    dl = soft ? pg__joint_soft_delta(v, bias, *acc, s, 1) : -clamp64(v + bias, INT64_C(1) << 32);
    n = *acc + dl;
    n = n < 0 ? 0 : n > LAMBDA_MAX ? LAMBDA_MAX : n;
    joint_row_apply(r, A, B, sign * (n - *acc));
    *acc = n;
}

/* A motor row: drives the row's speed to `speed`, its lambda within +-cap. */
void pg__joint_motor_solve(const joint_row *r, int64_t *acc, velocity *A, velocity *B, int64_t speed, int64_t cap)
{
    int64_t v, n;
    if (!r->on) return;
    v = joint_row_speed(r, A, B) - speed;
    n = clamp64(*acc - clamp64(v, INT64_C(1) << 32), cap);
    joint_row_apply(r, A, B, n - *acc);
    *acc = n;
}

