/* fixed.c — the out-of-line Q16.16 scalar operations: division, ratios, square root,
 * decimal parsing and formatting. The rounding rule is the one in fixed.h. */
#include "pogon/fixed.h"

static uint64_t magnitude64(int64_t v) { return v < 0 ? (uint64_t)(-(v + 1)) + 1u : (uint64_t)v; }

/* round(num * 2^16 / den), ties away from zero, saturated. Long division, so any
 * int64 operands work (no 128-bit type is needed). */
static pg_fix_status div64_q16(int64_t num, int64_t den, pg_fix *out)
{
    int negative = (num < 0) != (den < 0);
    uint64_t un = magnitude64(num), ud = magnitude64(den), q, r;
    int i;
    if (den == 0) {
        *out = num > 0 ? PG_FIX_MAX : num < 0 ? PG_FIX_MIN : 0;
        return PG_FIX_DIV_ZERO;
    }
    q = un / ud;
    r = un % ud;
    if (q > (uint64_t)INT32_MAX >> 16) {
        *out = negative ? PG_FIX_MIN : PG_FIX_MAX;
        return PG_FIX_OVERFLOW;
    }
    for (i = 0; i < 16; ++i) { /* r < ud <= 2^63, so 2r fits in uint64 */
        q <<= 1;
        r <<= 1;
        if (r >= ud) { q |= 1u; r -= ud; }
    }
    if (r >= ud - r) ++q; /* 2r >= ud: at or past the half, away from zero */
    if (q > (uint64_t)INT32_MAX) {
        *out = negative ? PG_FIX_MIN : PG_FIX_MAX;
        return PG_FIX_OVERFLOW;
    }
    *out = negative ? -(pg_fix)q : (pg_fix)q;
    return PG_FIX_OK;
}

pg_fix pg_fix_from_ratio(int64_t num, int64_t den)
{
    pg_fix r;
    (void)div64_q16(num, den, &r);
    return r;
}

pg_fix_status pg_fix_div_checked(pg_fix a, pg_fix b, pg_fix *out)
{
    uint64_t un, ud, q;
    if (b == 0) return div64_q16(a, b, out);
    un = magnitude64((int64_t)a) << 16; /* < 2^48 */
    ud = magnitude64((int64_t)b);
    q = (2u * un + ud) / (2u * ud); /* floor(un/ud + 1/2): ties away from zero */
    if (q > (uint64_t)INT32_MAX) {
        *out = ((a < 0) != (b < 0)) ? PG_FIX_MIN : PG_FIX_MAX;
        return PG_FIX_OVERFLOW;
    }
    *out = ((a < 0) != (b < 0)) ? -(pg_fix)q : (pg_fix)q;
    return PG_FIX_OK;
}

pg_fix pg_fix_div(pg_fix a, pg_fix b)
{
    pg_fix r;
    (void)pg_fix_div_checked(a, b, &r);
    return r;
}

pg_fix pg_fix_recip(pg_fix a) { return pg_fix_div(PG_FIX_ONE, a); }

static pg_fix_status from_wide(int64_t exact, pg_fix *out)
{
    *out = pg__sat64(exact);
    return (exact > PG_FIX_MAX || exact < PG_FIX_MIN) ? PG_FIX_OVERFLOW : PG_FIX_OK;
}

pg_fix_status pg_fix_add_checked(pg_fix a, pg_fix b, pg_fix *out) { return from_wide((int64_t)a + b, out); }
pg_fix_status pg_fix_sub_checked(pg_fix a, pg_fix b, pg_fix *out) { return from_wide((int64_t)a - b, out); }
pg_fix_status pg_fix_mul_checked(pg_fix a, pg_fix b, pg_fix *out)
{
    return from_wide(pg__round_shift64((int64_t)a * b, 16), out);
}

uint32_t pg_isqrt64(uint64_t v)
{
    /* Digit-by-digit square root, branch-free in its loop (a data-dependent branch
     * mispredicts half the time), starting at the highest bit pair of v. */
    uint64_t res = 0, one = (uint64_t)1 << 62, t = v;
    int shift = 62;
    while (shift >= 8 && (t >> (shift - 6)) == 0) shift -= 8; /* t < 2^(shift - 6): skip a byte */
    while (shift > 0 && (t >> shift) == 0) shift -= 2;
    one = (uint64_t)1 << shift;
    while (one != 0) {
        uint64_t b = res + one;
        uint64_t ge = (uint64_t)0 - (uint64_t)(v >= b); /* all ones when v >= b */
        v -= b & ge;
        res = (res >> 1) + (one & ge);
        one >>= 2;
    }
    return (uint32_t)res;
}

pg_fix_status pg_fix_sqrt_checked(pg_fix a, pg_fix *out)
{
    uint64_t v;
    uint32_t r;
    if (a < 0) { *out = 0; return PG_FIX_DOMAIN; }
    v = (uint64_t)a << 16; /* sqrt(a / 2^16) * 2^16 == sqrt(a * 2^16) */
    r = pg_isqrt64(v);
    if (v - (uint64_t)r * r > r) ++r; /* v > r^2 + r means v > (r + 1/2)^2: no ties */
    *out = (pg_fix)r;
    return PG_FIX_OK;
}

pg_fix pg_fix_sqrt(pg_fix a)
{
    pg_fix r;
    (void)pg_fix_sqrt_checked(a, &r);
    return r;
}

const char *pg_fix_status_message(pg_fix_status status)
{
    switch (status) {
    case PG_FIX_OK: return "PG_FIX_OK: exact result in range";
    case PG_FIX_OVERFLOW: return "PG_FIX_OVERFLOW: result beyond +-32767.99998, saturated; scale the inputs down";
    case PG_FIX_DIV_ZERO: return "PG_FIX_DIV_ZERO: division by zero, result saturated by the sign of the dividend";
    case PG_FIX_DOMAIN: return "PG_FIX_DOMAIN: argument outside the function's domain (e.g. sqrt of a negative)";
    case PG_FIX_SYNTAX: return "PG_FIX_SYNTAX: not a decimal number [+|-]digits[.digits] (\".5\", \"5.\" accepted; no spaces or exponent)";
    }
    return "unknown pg_fix_status";
}

/* ---- decimal text ------------------------------------------------------------ */

/* A Q16.16 fraction is k / 2^16 = k * 5^16 / 10^16, so its decimal expansion stops
 * after 16 digits and every halfway point (2k+1) / 2^17 stops after 17. The first 17
 * fraction digits therefore decide the rounding exactly; later digits only tell
 * whether the value lies above a halfway point, and below one they cannot reach it. */
#define FRACTION_DIGITS 17
#define FIVE_POW_17 UINT64_C(762939453125)

pg_fix_status pg_fix_parse(const char *text, size_t len, pg_fix *out)
{
    size_t i = 0;
    int negative = 0, digits = 0, frac_digits = 0;
    uint64_t int_part = 0, frac = 0, q, r, divisor = 2u * FIVE_POW_17, magnitude;
    *out = 0;
    if (text == NULL) return PG_FIX_SYNTAX;
    if (i < len && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    for (; i < len && text[i] >= '0' && text[i] <= '9'; ++i, ++digits) {
        if (int_part <= UINT64_C(1) << 40) int_part = int_part * 10u + (uint64_t)(text[i] - '0');
    }
    if (i < len && text[i] == '.') {
        for (++i; i < len && text[i] >= '0' && text[i] <= '9'; ++i, ++digits) {
            if (frac_digits < FRACTION_DIGITS) {
                frac = frac * 10u + (uint64_t)(text[i] - '0');
                ++frac_digits;
            } /* later digits cannot move the rounding: see above */
        }
    }
    if (digits == 0 || i != len) return PG_FIX_SYNTAX;
    for (; frac_digits < FRACTION_DIGITS; ++frac_digits) frac *= 10u;
    /* frac / 10^17 * 2^16 == frac / (2 * 5^17) */
    q = frac / divisor;
    r = frac % divisor;
    /* At the half or past it: away from zero. Below it, 2r <= divisor - 2 (divisor is
     * even), so digits past the 17th cannot lift the value to the half. */
    if (2u * r >= divisor) ++q;
    if (int_part > (uint64_t)INT32_MAX >> 16) {
        *out = negative ? PG_FIX_MIN : PG_FIX_MAX;
        return PG_FIX_OVERFLOW;
    }
    magnitude = (int_part << 16) + q;
    if (magnitude > (uint64_t)INT32_MAX) {
        *out = negative ? PG_FIX_MIN : PG_FIX_MAX;
        return PG_FIX_OVERFLOW;
    }
    *out = negative ? -(pg_fix)magnitude : (pg_fix)magnitude;
    return PG_FIX_OK;
}

size_t pg_fix_format(pg_fix a, char *buf, size_t size)
{
    char tmp[PG_FIX_FORMAT_MAX];
    uint64_t mag = magnitude64(a), ip = mag >> 16, fr = mag & 0xFFFFu, digits = 0, pow10 = 1;
    size_t n = 0, k, j;
    int places;
    /* The fewest fraction digits whose rounded value parses back to fr exactly. Five
     * always suffice: 10^-5 / 2 < 2^-16 / 2. */
    for (places = 0; places <= 5; ++places, pow10 *= 10u) {
        uint64_t back;
        digits = (fr * pow10 * 2u + 65536u) / (2u * 65536u);              /* round(fr * 10^p / 2^16) */
        back = (2u * digits * 65536u + pow10) / (2u * pow10);             /* round(digits * 2^16 / 10^p) */
        if (back == fr) break;
    }
    if (digits == pow10) { ip += 1u; digits = 0; } /* only reachable for places == 0 */
    if (a < 0) tmp[n++] = '-';
    {
        char rev[12];
        size_t m = 0;
        do { rev[m++] = (char)('0' + (int)(ip % 10u)); ip /= 10u; } while (ip != 0);
        while (m > 0) tmp[n++] = rev[--m];
    }
    if (places > 0 && digits != 0) {
        tmp[n++] = '.';
        for (j = (size_t)places; j > 0; --j) {
            uint64_t p = 1;
            for (k = 1; k < j; ++k) p *= 10u;
            tmp[n++] = (char)('0' + (int)(digits / p % 10u));
        }
        while (tmp[n - 1] == '0') --n;
    }
    if (buf != NULL && size > 0) {
        size_t c = n < size - 1 ? n : size - 1;
        for (k = 0; k < c; ++k) buf[k] = tmp[k];
        buf[c] = '\0';
    }
    return n;
}
