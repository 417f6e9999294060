/* broadphase.c — uniform-grid broadphase (see broadphase.h for the rules).
 *
 * Scratch layout, all of it uint64_t words (so the memory is only ever accessed as one
 * type), for n = count proxies and K = pair_capacity:
 *   ent   [16 n]   (cell key << 32 | proxy) entries: active ones, then passive ones
 *   etmp  [16 n]   radix-sort buffer for ent; while passive proxies are binned, its end
 *                  may hold a bitmap of the active cells
 *   pk    [2 K]    collected pair keys (a << nb | b)
 *   ptmp  [2 K]    radix-sort buffer for pk
 *   list  [n]      large proxies from the front, binned active proxies from the back
 *   lbits [n/64]   bit i set when proxy i is large
 * Everything is computed from the inputs alone: no statics, no dependence on where the
 * scratch lives, integer arithmetic only.
 */
#include "broadphase.h"

#define BP_MIN_SHIFT 12         /* 1/16 m */
#define BP_MAX_SHIFT 22         /* 64 m */
#define BP_MAX_SPAN 8           /* cells per axis of a binned proxy */
#define BP_ENTRIES_PER_PROXY 16 /* entry budget per proxy (on average) */

/* ---- scratch size ------------------------------------------------------------ */
static uint64_t bp_words(uint64_t n, uint64_t k)
{
    return n * (2u * BP_ENTRIES_PER_PROXY + 1u) + (n + 63u) / 64u + 4u * k;
}

size_t pg_broadphase_scratch_bytes(uint32_t max_proxies, uint32_t max_pairs)
{
    uint64_t bytes = 8u * bp_words(max_proxies, max_pairs); /* < 2^47: no overflow */
#if SIZE_MAX < UINT64_MAX
    if (bytes > (uint64_t)SIZE_MAX) return SIZE_MAX;
#endif
    return (size_t)bytes;
}

/* ---- stable LSD radix sort ------------------------------------------------------ */
/* Sorts keys[0..n) by bits [lo, lo + nbits) (nbits <= 64 - lo), stably, with tmp as the
 * second buffer. Returns the buffer that holds the result (keys or tmp). */
static uint64_t *bp_radix(uint64_t *keys, uint64_t *tmp, size_t n, unsigned lo, unsigned nbits)
{
    size_t hist[8][256];
    uint64_t mask[8];
    unsigned passes = (nbits + 7u) / 8u, p;
    size_t i;
    uint64_t *src = keys, *dst = tmp;
    if (n < 2 || passes == 0) return keys;
    for (p = 0; p < passes; ++p) {
        unsigned d, left = nbits - 8u * p; /* bits of the range from this digit on */
        mask[p] = left >= 8u ? 0xffu : ((uint64_t)1 << left) - 1u;
        for (d = 0; d < 256u; ++d) hist[p][d] = 0;
    }
    for (i = 0; i < n; ++i) {
        uint64_t k = keys[i] >> lo;
        for (p = 0; p < passes; ++p) hist[p][(k >> (8u * p)) & mask[p]]++;
    }
    for (p = 0; p < passes; ++p) {
        unsigned shift = lo + 8u * p, d;
        size_t sum = 0;
        uint64_t *t;
        if (hist[p][(src[0] >> shift) & mask[p]] == n) continue; /* one bucket: a no-op pass */
        for (d = 0; d < 256u; ++d) {
            size_t c = hist[p][d];
            hist[p][d] = sum;
            sum += c;
        }
        for (i = 0; i < n; ++i) dst[hist[p][(src[i] >> shift) & mask[p]]++] = src[i];
        t = src;
        src = dst;
        dst = t;
    }
    return src;
}

/* Number of bits needed to write v (0 for 0). */
static unsigned bp_bits(uint64_t v)
{
    unsigned b = 0;
    while (v != 0) {
        ++b;
        v >>= 1;
    }
    return b;
}

/* ---- pair collection: keeps the K smallest pair keys in bounded memory ----------- */
typedef struct bp_out {
    uint64_t *pk, *ptmp; /* buffers of cap2 = 2 K keys */
    size_t n, cap2, k;
    unsigned nb;         /* bits of a proxy index in a key */
    int over;            /* some pair was dropped (more than K exist) */
    uint64_t thr;        /* when over: keys above thr are not among the first K */
} bp_out;

static void bp_trim(bp_out *o)
{
    uint64_t *s = bp_radix(o->pk, o->ptmp, o->n, 0, 2u * o->nb);
    if (s != o->pk) {
        o->ptmp = o->pk;
        o->pk = s;
    }
    o->n = o->k;
    o->thr = o->pk[o->k - 1];
    o->over = 1;
}

static void bp_emit(bp_out *o, uint32_t a, uint32_t b)
{
    uint64_t key = a < b ? ((uint64_t)a << o->nb) | b : ((uint64_t)b << o->nb) | a;
    if (o->over && key > o->thr) return;
    if (o->n == o->cap2) {
        if (o->cap2 == 0) { /* K == 0: every key (>= 1, as a != b) is beyond the first 0 */
            o->over = 1;
            o->thr = 0;
            return;
        }
        bp_trim(o);
        if (key > o->thr) return;
    }
    o->pk[o->n++] = key;
}

/* ---- geometry helpers ------------------------------------------------------------ */
static int bp_overlap(const pg_aabb *a, const pg_aabb *b)
{
    return a->lo.x <= b->hi.x && b->lo.x <= a->hi.x && a->lo.y <= b->hi.y && b->lo.y <= a->hi.y;
}

/* max(width, height) clamped to [0, 2^BP_MAX_SHIFT]. */
static uint64_t bp_extent(const pg_aabb *b)
{
    int64_t w = (int64_t)b->hi.x - b->lo.x, h = (int64_t)b->hi.y - b->lo.y;
    int64_t e = w > h ? w : h;
    if (e < 0) e = 0;
    if (e > ((int64_t)1 << BP_MAX_SHIFT)) e = (int64_t)1 << BP_MAX_SHIFT;
    return (uint64_t)e;
}

static int32_t bp_max32(int32_t a, int32_t b) { return a > b ? a : b; }
static int32_t bp_min32(int32_t a, int32_t b) { return a < b ? a : b; }

static int bp_is_large(const uint64_t *lbits, uint32_t i) { return (int)((lbits[i >> 6] >> (i & 63u)) & 1u); }

/* Is there an entry with cell `key` in the sorted entries e[0..n)? */
static int bp_has_cell(const uint64_t *e, size_t n, uint32_t key)
{
    uint64_t want = (uint64_t)key << 32;
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2u;
        if (e[mid] < want) lo = mid + 1u;
        else hi = mid;
    }
    return lo < n && (uint32_t)(e[lo] >> 32) == key;
}

int pg_broadphase_pairs(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                        pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count,
                        void *scratch, size_t scratch_bytes)
{
    uint64_t sum = 0, mean, wx = 0, wy = 0;
    uint32_t nact = 0, i, nlarge = 0, nbact = 0;
    int s, have = 0;
    int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    size_t ecap, ea = 0, ep = 0, n_out, t;
    unsigned kb = 0;
    uint64_t *ent, *etmp, *list, *lbits, *as, *ps;
    bp_out out;

    *pair_count = 0;
    if (scratch_bytes < pg_broadphase_scratch_bytes(count, pair_capacity)) return -2;

    for (i = 0; i < count; ++i) {
        if (flags[i] & PG_PROXY_ACTIVE) {
            ++nact;
            sum += bp_extent(&boxes[i]);
        }
    }
    if (nact == 0) return 0; /* a fully passive world costs one pass over the flags */

    /* cell size: smallest power of two >= the mean extent, clamped */
    mean = sum / nact;
    s = BP_MIN_SHIFT;
    while (s < BP_MAX_SHIFT && ((uint64_t)1 << s) < mean) ++s;

    /* rectangle of the cells covered by binnable active proxies; grow the cells until
     * a cell key of that rectangle fits in 32 bits (always true from s = 16 on) */
    for (;;) {
        have = 0;
        for (i = 0; i < count; ++i) {
            const pg_aabb *b = &boxes[i];
            int32_t lx, ly, hx, hy;
            if (!(flags[i] & PG_PROXY_ACTIVE)) continue;
            lx = b->lo.x >> s;
            ly = b->lo.y >> s;
            hx = b->hi.x >> s;
            hy = b->hi.y >> s;
            if (hx < lx || hy < ly || hx - lx >= BP_MAX_SPAN || hy - ly >= BP_MAX_SPAN) continue;
            if (!have) {
                x0 = lx; y0 = ly; x1 = hx; y1 = hy;
                have = 1;
            } else {
                x0 = bp_min32(x0, lx); y0 = bp_min32(y0, ly);
                x1 = bp_max32(x1, hx); y1 = bp_max32(y1, hy);
            }
        }
        if (!have) break;
        wx = (uint64_t)((int64_t)x1 - x0) + 1u;
        wy = (uint64_t)((int64_t)y1 - y0) + 1u;
        if (wx * wy <= ((uint64_t)1 << 32)) break;
        ++s;
    }
    if (have) kb = bp_bits(wx * wy - 1u);

    /* scratch */
    ecap = (size_t)count * BP_ENTRIES_PER_PROXY;
    ent = (uint64_t *)scratch;
    etmp = ent + ecap;
    out.pk = etmp + ecap;
    out.cap2 = (size_t)pair_capacity * 2u;
    out.ptmp = out.pk + out.cap2;
    list = out.ptmp + out.cap2;
    lbits = list + count;
    for (t = 0; t < ((size_t)count + 63u) / 64u; ++t) lbits[t] = 0;
    out.n = 0;
    out.k = pair_capacity;
    out.nb = bp_bits(count > 1u ? count - 1u : 1u);
    out.over = 0;
    out.thr = 0;

    /* active proxies: bin (in index order) or set aside as large */
    for (i = 0; i < count; ++i) {
        const pg_aabb *b = &boxes[i];
        int32_t lx, ly, hx, hy, cx, cy;
        size_t cells;
        if (!(flags[i] & PG_PROXY_ACTIVE)) continue;
        lx = b->lo.x >> s;
        ly = b->lo.y >> s;
        hx = b->hi.x >> s;
        hy = b->hi.y >> s;
        if (hx < lx || hy < ly) continue; /* malformed box: not binned */
        cells = (hx - lx >= BP_MAX_SPAN || hy - ly >= BP_MAX_SPAN)
                    ? 0
                    : (size_t)(hx - lx + 1) * (size_t)(hy - ly + 1);
        if (!have || cells == 0 || cells > ecap - ea) {
            list[nlarge++] = i;
            lbits[i >> 6] |= (uint64_t)1 << (i & 63u);
            continue;
        }
        list[count - 1u - nbact++] = i;
        for (cy = ly; cy <= hy; ++cy) {
            uint64_t row = (uint64_t)(cy - y0) * wx;
            for (cx = lx; cx <= hx; ++cx)
                ent[ea++] = ((row + (uint64_t)(cx - x0)) << 32) | i;
        }
    }
    as = bp_radix(ent, etmp, ea, 32, kb);

    /* passive proxies: clipped to the active rectangle, binned only into active cells */
    ps = ent + ea;
    if (have) {
        uint64_t *pe = ent + ea;
        /* Which cells hold an active entry: a bitmap over the rectangle when it is small
         * (in the unused end of etmp, dead before the passive entries are sorted there),
         * else a binary search in the sorted active entries. Same answer either way. */
        uint64_t *bm = 0, cells_rect = wx * wy;
        size_t bm_words = (size_t)((cells_rect + 63u) / 64u);
        if (bm_words <= ecap - ea && bm_words <= 2u * (size_t)count) {
            bm = etmp + ea;
            for (t = 0; t < bm_words; ++t) bm[t] = 0;
            for (t = 0; t < ea; ++t) {
                uint32_t key = (uint32_t)(as[t] >> 32);
                bm[key >> 6] |= (uint64_t)1 << (key & 63u);
            }
        }
        for (i = 0; i < count; ++i) {
            const pg_aabb *b = &boxes[i];
            int32_t lx, ly, hx, hy, cx, cy;
            size_t start = ep;
            int spill = 0;
            if (flags[i] & PG_PROXY_ACTIVE) continue;
            lx = bp_max32(b->lo.x >> s, x0);
            ly = bp_max32(b->lo.y >> s, y0);
            hx = bp_min32(b->hi.x >> s, x1);
            hy = bp_min32(b->hi.y >> s, y1);
            if (hx < lx || hy < ly) continue; /* outside: only large actives can meet it */
            if (hx - lx < BP_MAX_SPAN && hy - ly < BP_MAX_SPAN) {
                for (cy = ly; cy <= hy && !spill; ++cy) {
                    uint64_t row = (uint64_t)(cy - y0) * wx;
                    for (cx = lx; cx <= hx; ++cx) {
                        uint32_t key = (uint32_t)(row + (uint64_t)(cx - x0));
                        if (bm ? !((bm[key >> 6] >> (key & 63u)) & 1u) : !bp_has_cell(as, ea, key))
                            continue;
                        if (ep == ecap - ea) {
                            spill = 1;
                            break;
                        }
                        pe[ep++] = ((uint64_t)key << 32) | i;
                    }
                }
            } else {
                spill = 1;
            }
            if (spill) {
                ep = start;
                list[nlarge++] = i;
                lbits[i >> 6] |= (uint64_t)1 << (i & 63u);
            }
        }
        ps = bp_radix(pe, etmp + ea, ep, 32, kb);
    }

    /* pairs within cells: active x active and active x passive, from the first shared
     * cell only. Passive cells are a subset of the active ones, so one merge walk. */
    {
        size_t ia = 0, ip = 0;
        while (ia < ea) {
            uint32_t key = (uint32_t)(as[ia] >> 32);
            size_t ga = ia + 1u, gp;
            while (ga < ea && (uint32_t)(as[ga] >> 32) == key) ++ga;
            while (ip < ep && (uint32_t)(ps[ip] >> 32) < key) ++ip;
            gp = ip;
            while (gp < ep && (uint32_t)(ps[gp] >> 32) == key) ++gp;
            if (ga - ia + gp - ip >= 2u) {
                int32_t cx = (int32_t)((uint64_t)key % wx) + x0;
                int32_t cy = (int32_t)((uint64_t)key / wx) + y0;
                size_t u, v;
                for (u = ia; u < ga; ++u) {
                    uint32_t pa = (uint32_t)as[u];
                    const pg_aabb *ba = &boxes[pa];
                    int32_t ax = ba->lo.x >> s, ay = ba->lo.y >> s;
                    for (v = u + 1u; v < ga; ++v) {
                        uint32_t pb = (uint32_t)as[v];
                        const pg_aabb *bb = &boxes[pb];
                        if (bp_max32(ax, bb->lo.x >> s) == cx && bp_max32(ay, bb->lo.y >> s) == cy &&
                            bp_overlap(ba, bb))
                            bp_emit(&out, pa, pb);
                    }
                    for (v = ip; v < gp; ++v) {
                        uint32_t pb = (uint32_t)ps[v];
                        const pg_aabb *bb = &boxes[pb];
                        /* the passive box's lo cell, clipped to the rectangle; the active
                         * one lies inside it, so the maximum is unchanged by the clip */
                        int32_t bx = bp_max32(bb->lo.x >> s, x0), by = bp_max32(bb->lo.y >> s, y0);
                        if (bp_max32(ax, bx) == cx && bp_max32(ay, by) == cy && bp_overlap(ba, bb))
                            bp_emit(&out, pa, pb);
                    }
                }
            }
            ia = ga;
            ip = gp;
        }
    }

    /* large proxies */
    for (t = 0; t < nlarge; ++t) {
        uint32_t l = (uint32_t)list[t];
        const pg_aabb *bl = &boxes[l];
        if (flags[l] & PG_PROXY_ACTIVE) {
            /* against everyone; a pair of two large actives is tested by the lower index */
            for (i = 0; i < count; ++i) {
                if (i == l) continue;
                if (i < l && (flags[i] & PG_PROXY_ACTIVE) && bp_is_large(lbits, i)) continue;
                if (bp_overlap(bl, &boxes[i])) bp_emit(&out, l, i);
            }
        } else {
            /* against the binned actives (large actives test it themselves) */
            uint32_t u;
            for (u = 0; u < nbact; ++u) {
                uint32_t j = (uint32_t)list[count - 1u - u];
                if (bp_overlap(bl, &boxes[j])) bp_emit(&out, l, j);
            }
        }
    }

    /* the first K pairs in (a, b) order */
    {
        const uint64_t *sorted = bp_radix(out.pk, out.ptmp, out.n, 0, 2u * out.nb);
        uint64_t mask = ((uint64_t)1 << out.nb) - 1u;
        n_out = out.n < out.k ? out.n : out.k;
        for (t = 0; t < n_out; ++t) {
            pairs[t].a = (uint32_t)(sorted[t] >> out.nb);
            pairs[t].b = (uint32_t)(sorted[t] & mask);
        }
        *pair_count = (uint32_t)n_out;
        return (out.over || out.n > out.k) ? -1 : 0;
    }
}
