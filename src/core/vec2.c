/* vec2.c — the vector and matrix operations too large to inline. */
#include "pogon/fixed.h"
#include "intmath.h"

pg_fix pg_v2_length(pg_vec2 v)
{
    uint64_t ax = (uint64_t)(v.x < 0 ? -(int64_t)v.x : v.x), ay = (uint64_t)(v.y < 0 ? -(int64_t)v.y : v.y);
    uint64_t s = ax * ax + ay * ay; /* Q32.32, < 2^63 */
    uint64_t r = pg_isqrt64(s);
    if (s - r * r > r) ++r; /* nearest; there are no ties */
    return r > (uint64_t)PG_FIX_MAX ? PG_FIX_MAX : (pg_fix)r;
}

pg_vec2 pg_v2_normalize(pg_vec2 v)
{
    /* Scale the magnitudes so the larger lies in [2^29, 2^30): the length then has 29
     * significant bits, and each quotient is within one rounding of exact. */
    uint64_t ax = (uint64_t)(v.x < 0 ? -(int64_t)v.x : v.x), ay = (uint64_t)(v.y < 0 ? -(int64_t)v.y : v.y);
    uint64_t big = ax > ay ? ax : ay, len, nx, ny;
    int up;
    if (big == 0) return pg_v2_zero();
    up = 30 - pg__bit_length64(big); /* big <= 2^31, so up >= -2 */
    if (up > 0) { ax <<= up; ay <<= up; }
    else if (up < 0) { ax >>= 1; ay >>= 1; } /* magnitudes: symmetric in sign */
    len = pg_isqrt64(ax * ax + ay * ay);
    if (ax * ax + ay * ay - len * len > len) ++len;
    nx = (2u * (ax << 16) + len) / (2u * len);
    ny = (2u * (ay << 16) + len) / (2u * len);
    return pg_v2(v.x < 0 ? -(pg_fix)nx : (pg_fix)nx, v.y < 0 ? -(pg_fix)ny : (pg_fix)ny);
}

pg_vec2 pg_mat22_solve(pg_mat22 m, pg_vec2 b)
{
    int64_t det = (int64_t)m.col1.x * m.col2.y - (int64_t)m.col2.x * m.col1.y;
    int64_t nx = (int64_t)m.col2.y * b.x - (int64_t)m.col2.x * b.y;
    int64_t ny = (int64_t)m.col1.x * b.y - (int64_t)m.col1.y * b.x;
    if (det == 0) return pg_v2_zero();
    return pg_v2(pg_fix_from_ratio(nx, det), pg_fix_from_ratio(ny, det));
}
