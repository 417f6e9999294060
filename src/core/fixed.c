/* fixed.c — the out-of-line Q16.16 scalar operations: division, ratios, square root,
 * decimal parsing and formatting. The rounding rule is the one in fixed.h. */
#include "pogon/config.h"
#include "pogon/fixed.h"
#include "fixed_internal.h"
#include "intmath.h"

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

static pg_fix_status div_q16(pg_fix a, pg_fix b, pg_fix *out)
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

/* The public *_checked functions and pg_fix_parse accept out == NULL (fixed.h): the
 * status is computed all the same and the value dropped. */
pg_fix_status pg_fix_div_checked(pg_fix a, pg_fix b, pg_fix *out)
{
    pg_fix r;
    pg_fix_status st = div_q16(a, b, &r);
    if (out != NULL) *out = r;
    return st;
}

pg_fix pg_fix_div(pg_fix a, pg_fix b)
{
    pg_fix r;
    (void)div_q16(a, b, &r);
    return r;
}

pg_fix pg_fix_recip(pg_fix a) { return pg_fix_div(PG_FIX_ONE, a); }

static pg_fix_status from_wide(int64_t exact, pg_fix *out)
{
    if (out != NULL) *out = pg__sat64(exact);
    return (exact > PG_FIX_MAX || exact < PG_FIX_MIN) ? PG_FIX_OVERFLOW : PG_FIX_OK;
}

pg_fix_status pg_fix_add_checked(pg_fix a, pg_fix b, pg_fix *out) { return from_wide((int64_t)a + b, out); }
pg_fix_status pg_fix_sub_checked(pg_fix a, pg_fix b, pg_fix *out) { return from_wide((int64_t)a - b, out); }
pg_fix_status pg_fix_mul_checked(pg_fix a, pg_fix b, pg_fix *out)
{
    return from_wide(pg__round_shift64((int64_t)a * b, 16), out);
}

/* ---- integer square root ----------------------------------------------------------
 * Two exact implementations of floor(sqrt(v)); PG_FAST_DIV64 (config.h) picks the one
 * behind pg_isqrt64. Both return the same value for every v (the unit test compares
 * them), so the switch changes speed only, never a result. */


/* Digit-by-digit square root, branch-free in its loop (a data-dependent branch
 * mispredicts half the time), starting at the highest bit pair of v. Up to 32
 * iterations; no division, so it is the choice where 64-bit division is slow. */
static inline uint32_t isqrt64_digits(uint64_t v)
{
    uint64_t res = 0, one;
    int shift = pg__bit_length64(v) - 1; /* highest set bit; -1 for v == 0 */
    if (shift < 0) return 0;
    one = (uint64_t)1 << (shift & ~1);   /* the highest power of 4 <= v */
    while (one != 0) {
        uint64_t b = res + one;
        uint64_t ge = (uint64_t)0 - (uint64_t)(v >= b); /* all ones when v >= b */
        v -= b & ge;
        res = (res >> 1) + (one & ge);
        one >>= 2;
    }
    return (uint32_t)res;
}

#if PG_FAST_DIV64
/* isqrt_nodes[i] = round(sqrt(64 + i) * 2^27), i = 0..192: sqrt on [64, 256] (that is
 * sqrt(m) * 2^30 for m = (64 + i) / 64 in [1, 4]) at steps of 1/64 in m, from 2^30 to
 * 2^31. Increasing, and every entry is at least 2^30. */
static const uint32_t isqrt_nodes[193] = {
    1073741824u, 1082097918u, 1090389977u, 1098619452u, 1106787739u, 1114896182u, 1122946079u,
    1130938678u, 1138875187u, 1146756771u, 1154584553u, 1162359621u, 1170083026u, 1177755783u,
    1185378878u, 1192953261u, 1200479854u, 1207959552u, 1215393219u, 1222781696u, 1230125796u,
    1237426310u, 1244684005u, 1251899625u, 1259073893u, 1266207514u, 1273301169u, 1280355523u,
    1287371222u, 1294348895u, 1301289153u, 1308192592u, 1315059792u, 1321891318u, 1328687719u,
    1335449532u, 1342177280u, 1348871473u, 1355532607u, 1362161168u, 1368757628u, 1375322451u,
    1381856086u, 1388358974u, 1394831545u, 1401274219u, 1407687407u, 1414071510u, 1420426919u,
    1426754019u, 1433053185u, 1439324782u, 1445569171u, 1451786701u, 1457977717u, 1464142555u,
    1470281545u, 1476395008u, 1482483261u, 1488546612u, 1494585366u, 1500599818u, 1506590260u,
    1512556978u, 1518500250u, 1524420351u, 1530317551u, 1536192112u, 1542044294u, 1547874349u,
    1553682529u, 1559469076u, 1565234231u, 1570978229u, 1576701302u, 1582403676u, 1588085574u,
    1593747216u, 1599388817u, 1605010588u, 1610612736u, 1616195466u, 1621758978u, 1627303469u,
    1632829134u, 1638336161u, 1643824740u, 1649295054u, 1654747284u, 1660181608u, 1665598202u,
    1670997238u, 1676378885u, 1681743312u, 1687090681u, 1692421154u, 1697734891u, 1703032049u,
    1708312781u, 1713577240u, 1718825574u, 1724057932u, 1729274458u, 1734475296u, 1739660585u,
    1744830464u, 1749985070u, 1755124538u, 1760249000u, 1765358587u, 1770453428u, 1775533649u,
    1780599376u, 1785650732u, 1790687838u, 1795710816u, 1800719782u, 1805714853u, 1810696145u,
    1815663770u, 1820617842u, 1825558469u, 1830485761u, 1835399826u, 1840300769u, 1845188694u,
    1850063706u, 1854925906u, 1859775393u, 1864612269u, 1869436629u, 1874248572u, 1879048192u,
    1883835584u, 1888610840u, 1893374053u, 1898125312u, 1902864709u, 1907592330u, 1912308264u,
    1917012597u, 1921705413u, 1926386797u, 1931056833u, 1935715602u, 1940363185u, 1944999662u,
    1949625114u, 1954239618u, 1958843251u, 1963436090u, 1968018211u, 1972589688u, 1977150595u,
    1981701005u, 1986240991u, 1990770623u, 1995289972u, 1999799107u, 2004298098u, 2008787014u,
    2013265920u, 2017734884u, 2022193972u, 2026643249u, 2031082780u, 2035512628u, 2039932856u,
    2044343526u, 2048744702u, 2053136442u, 2057518809u, 2061891861u, 2066255659u, 2070610259u,
    2074955721u, 2079292101u, 2083619457u, 2087937844u, 2092247318u, 2096547933u, 2100839745u,
    2105122807u, 2109397173u, 2113662894u, 2117920024u, 2122168614u, 2126408716u, 2130640379u,
    2134863654u, 2139078592u, 2143285240u, 2147483648u,
};

/* One Newton step from a seed good to about 2^-16, then an exact correction.
 *   Seed: v = m * 2^e with e even and m in [1, 4). The top 18 bits of v give m to
 *   2^-16 (x = m * 2^16 below); the chord between the two nodes around m gives
 *   sqrt(m) * 2^30 to about 2^-17 (sqrt is concave: the chord lies below it, by at
 *   most h^2/8 * |sqrt''| = 2^-12 / 8 / 4 at m = 1). Scaled by 2^(e/2) it is at
 *   least 1 (the nodes are at least 2^30), so the division below never sees 0.
 *   Newton: r' = floor((r + floor(v / r)) / 2) = floor((r + v / r) / 2) for integer
 *   r > 0, and (r + v / r) / 2 >= sqrt(v) for every r > 0, so r' >= floor(sqrt(v))
 *   whatever the seed. From this seed (off by at most sqrt(v) * 2^-16 + 1, the 1 from
 *   truncating to an integer) r' - sqrt(v) <= (r - sqrt(v))^2 / (2r) < 1 once
 *   v >= 2^28 (about 1/2 at v = 2^64), so r' is floor(sqrt(v)) or one more; below 2^28
 *   an exhaustive check finds the same.
 *   Correction: step down while r^2 > v (r^2 is evaluated only once r < 2^32, so it
 *   cannot wrap). It ends at floor(sqrt(v)) whatever the seed; the seed's quality only
 *   keeps it at zero or one step. */
static inline uint32_t isqrt64_newton(uint64_t v)
{
    uint64_t x, lo, hi, r;
    int e;
    if (v == 0) return 0;
    e = (pg__bit_length64(v) - 1) & ~1;                       /* v in [2^e, 2^(e+2)) */
    x = e >= 16 ? v >> (e - 16) : v << (16 - e);              /* m * 2^16, in [2^16, 2^18) */
    lo = isqrt_nodes[(x >> 10) - 64];
    hi = isqrt_nodes[(x >> 10) - 63];
    r = lo + (((hi - lo) * (x & 1023u)) >> 10);               /* ~ sqrt(m) * 2^30, < 2^31 */
    r = (r << (e / 2)) >> 30;                                 /* ~ sqrt(v), >= 1 */
    r = (r + v / r) >> 1;                                     /* r + v / r < 2^34 */
    while (r > UINT64_C(0xFFFFFFFF) || r * r > v) --r;
    return (uint32_t)r;
}
#endif

uint32_t pg_isqrt64(uint64_t v)
{
#if PG_FAST_DIV64
    return isqrt64_newton(v);
#else
    return isqrt64_digits(v);
#endif
}

uint32_t pg__isqrt64_digits(uint64_t v) { return isqrt64_digits(v); }

const uint32_t *pg__isqrt64_seed_nodes(uint32_t *count)
{
#if PG_FAST_DIV64
    *count = (uint32_t)(sizeof isqrt_nodes / sizeof isqrt_nodes[0]);
    return isqrt_nodes;
#else
    *count = 0;
    return 0;
#endif
}

static pg_fix_status sqrt_q16(pg_fix a, pg_fix *out)
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

pg_fix_status pg_fix_sqrt_checked(pg_fix a, pg_fix *out)
{
    pg_fix r;
    pg_fix_status st = sqrt_q16(a, &r);
    if (out != NULL) *out = r;
    return st;
}

pg_fix pg_fix_sqrt(pg_fix a)
{
    pg_fix r;
    (void)sqrt_q16(a, &r);
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

static pg_fix_status parse_q16(const char *text, size_t len, pg_fix *out)
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

pg_fix_status pg_fix_parse(const char *text, size_t len, pg_fix *out)
{
    pg_fix v;
    pg_fix_status st = parse_q16(text, len, &v);
    if (out != NULL) *out = v;
    return st;
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
        digits = (fr * pow10 * 2u + 65536u) / (UINT64_C(2) * 65536u);              /* round(fr * 10^p / 2^16) */
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
