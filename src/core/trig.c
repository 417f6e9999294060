/* trig.c — binary angles, table sine and cosine, CORDIC atan2, rotations. */
#include "pogon/config.h"
#include "trig.h"
#include "trig_table.inc"

#define PG__TABLE_NAME2(bits) pg_sin_quarter_##bits
#define PG__TABLE_NAME(bits) PG__TABLE_NAME2(bits)
#define PG__SIN_TABLE PG__TABLE_NAME(PG_TRIG_TABLE_BITS)

/* 2^32 / (2 pi) in Q16.16 and 2 pi in Q3.29, both rounded to nearest. */
#define TURN_PER_RADIAN_Q16 INT64_C(683565276)
#define TWO_PI_Q29 INT64_C(3373259426)

pg_angle pg_angle_from_radians(pg_fix radians)
{
    int64_t turns = pg__round_shift64((int64_t)radians * TURN_PER_RADIAN_Q16, 16);
    return (pg_angle)(uint64_t)turns; /* modulo 2^32: defined for unsigned types */
}

pg_fix pg_angle_to_radians(pg_angle a)
{
    int64_t s = a >= PG_ANGLE_HALF ? (int64_t)a - INT64_C(4294967296) : (int64_t)a;
    return (pg_fix)pg__round_shift64(s * TWO_PI_Q29, 45);
}

pg_fix pg_fix_wrap_angle(pg_fix radians) { return pg_angle_to_radians(pg_angle_from_radians(radians)); }

int32_t pg_angle_sin_q30(pg_angle a) { return pg__quarter_sin_q30(PG__SIN_TABLE, PG_TRIG_TABLE_BITS, a); }
int32_t pg_angle_cos_q30(pg_angle a) { return pg_angle_sin_q30(a + PG_ANGLE_QUARTER); }

pg_fix pg_fix_sin(pg_fix radians) { return (pg_fix)pg__round_shift64(pg_angle_sin_q30(pg_angle_from_radians(radians)), 14); }
pg_fix pg_fix_cos(pg_fix radians) { return (pg_fix)pg__round_shift64(pg_angle_cos_q30(pg_angle_from_radians(radians)), 14); }

/* Linear interpolation between table entries runs along a chord, inside the unit
 * circle: |(cos, sin)| falls short of 1 by up to (2 pi / 2^bits)^2 / 8. One Newton step
 * for 1/sqrt(q) near q = 1, r' = r (3 - q) / 2, brings it back to within rounding, so
 * rotations never shrink the shapes they place. */
pg_rot pg_rot_from_angle(pg_angle a)
{
    pg_rot r;
    int64_t c = pg_angle_cos_q30(a), s = pg_angle_sin_q30(a);
    int64_t q = c * c + s * s;                                        /* Q60, 1 - 2^-18 < q <= 1 */
    int64_t f = pg__round_shift64(3 * (INT64_C(1) << 60) - q, 31);   /* (3 - q) / 2 in Q30 */
    r.c = (int32_t)pg__round_shift64(c * f, 30);
    r.s = (int32_t)pg__round_shift64(s * f, 30);
    return r;
}

/* Vectoring CORDIC on magnitudes in the first quadrant; the quadrant is restored by
 * exact symmetries afterwards, so atan2(-y, x) == -atan2(y, x) holds bit for bit. */
pg_angle pg_angle_atan2(pg_fix y, pg_fix x)
{
    int64_t ux = x < 0 ? -(int64_t)x : x, uy = y < 0 ? -(int64_t)y : y, big, t;
    uint32_t z = 0;
    int i;
    if (ux == 0 && uy == 0) return 0;
    big = ux > uy ? ux : uy;
    while (big < (INT64_C(1) << 29)) { big <<= 1; ux <<= 1; uy <<= 1; }
    for (i = 0; i < 31; ++i) {
        if (uy > 0) {
            t = ux + (uy >> i); uy -= ux >> i; ux = t; z += pg_cordic_atan_table[i];
        } else if (uy < 0) {
            /* cppcheck-suppress shiftNegativeLHS ; a right shift (implementation-defined, not undefined), pinned to arithmetic by fixed.h's check */
            t = ux - (uy >> i); uy += ux >> i; ux = t; z -= pg_cordic_atan_table[i];
        } else {
            break;
        }
    }
    /* z is now the first-quadrant angle in [0, quarter]. */
    if (x < 0) z = PG_ANGLE_HALF - z;
    if (y < 0) z = 0u - z;
    return z;
}

pg_fix pg_fix_atan2(pg_fix y, pg_fix x) { return pg_angle_to_radians(pg_angle_atan2(y, x)); }
