/* broadphase.c — uniform-grid broadphase (see broadphase.h for the rules).
 *
 * Scratch layout, all of it uint64_t words (so the memory is only ever accessed as one
 * type), for n = count proxies and K = pair_capacity:
 *   ent   [16 n]   (cell key << 32 | flags | proxy) entries: active ones, then passive
 *                  ones
 *   etmp  [16 n]   the entries sorted by cell; while passive proxies are binned, it may
 *                  hold a bitmap of the active cells. Of ent and etmp, the one that does
 *                  not hold the sorted entries then holds the counting tables of the pair
 *                  sort (the first n words: the pairs of each lower proxy)
 *   pk    [2 K]    collected pair keys (a << nb | b); with ptmp, first the cell counts
 *                  of a small rectangle (a counting sort of the entries)
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

/* An entry is (cell key << 32) | flags | proxy: the proxy index in the low 29 bits, and
 * which of the proxy's binned cells it is (FX: its lowest column, FY: its lowest row; for
 * a passive proxy those of its clipped range), for the first-shared-cell rule. */
#define BP_MAX_PROXIES ((uint32_t)1 << 29)
#define BP_IDX ((uint64_t)BP_MAX_PROXIES - 1u)
#define BP_FX ((uint64_t)1 << 29)
#define BP_FY ((uint64_t)1 << 30)
#define BP_PASSIVE ((uint64_t)1 << 31)

/* ---- scratch size ------------------------------------------------------------ */
static uint64_t bp_words(uint64_t n, uint64_t k)
{
    return n * (2u * BP_ENTRIES_PER_PROXY + 1u) + (n + 63u) / 64u + 4u * k;
}

size_t pg_broadphase_scratch_bytes(uint32_t max_proxies, uint32_t max_pairs)
{
    uint64_t bytes = 8u * bp_words(max_proxies, max_pairs); /* < 2^47: no overflow */
    if (max_proxies > BP_MAX_PROXIES) return SIZE_MAX;
#if SIZE_MAX < UINT64_MAX
    if (bytes > (uint64_t)SIZE_MAX) return SIZE_MAX;
#endif
    return (size_t)bytes;
}

/* ---- stable LSD radix sort ------------------------------------------------------ */
/* Sorts keys[0..n) by bits [lo, lo + nbits) (nbits <= 64 - lo), stably, with tmp as the
 * second buffer. Returns the buffer that holds the result (keys or tmp). Each pass counts
 * its own digit, so one table of 256 counts is live at a time (1 KiB of stack on a
 * 32-bit target) rather than one per pass. */
static uint64_t *bp_radix(uint64_t *keys, uint64_t *tmp, size_t n, unsigned lo, unsigned nbits)
{
    size_t hist[256];
    unsigned passes = (nbits + 7u) / 8u, p;
    size_t i;
    uint64_t *src = keys, *dst = tmp;
    if (n < 2 || passes == 0) return keys;
    for (p = 0; p < passes; ++p) {
        unsigned shift = lo + 8u * p, d, left = nbits - 8u * p; /* bits of the range from this digit on */
        uint64_t mask = left >= 8u ? 0xffu : ((uint64_t)1 << left) - 1u;
        size_t sum = 0;
        uint64_t *t;
        for (d = 0; d < 256u; ++d) hist[d] = 0;
        for (i = 0; i < n; ++i) hist[(src[i] >> shift) & mask]++;
        if (hist[(src[0] >> shift) & mask] == n) continue; /* one bucket: a no-op pass */
        for (d = 0; d < 256u; ++d) {
            size_t c = hist[d];
            hist[d] = sum;
            sum += c;
        }
        for (i = 0; i < n; ++i) dst[hist[(src[i] >> shift) & mask]++] = src[i];
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

/* Stable LSD radix sort of keys[0..n) by their bits [0, nbits) (no key has a bit above),
 * in digits of w bits, with tmp as the second buffer and hist (2^w words) for the
 * counts. Returns the buffer that holds the result (keys or tmp). */
static uint64_t *bp_radix_w(uint64_t *keys, uint64_t *tmp, size_t n, unsigned nbits, unsigned w, uint64_t *hist)
{
    uint64_t *src = keys, *dst = tmp, *t, mask = ((uint64_t)1 << w) - 1u;
    size_t size = (size_t)1 << w, i, d;
    unsigned sh;
    if (n < 2) return keys;
    for (sh = 0; sh < nbits; sh += w) {
        uint64_t at = 0;
        for (d = 0; d < size; ++d) hist[d] = 0;
        for (i = 0; i < n; ++i) hist[(src[i] >> sh) & mask]++;
        if (hist[(src[0] >> sh) & mask] == n) continue; /* one bucket: a no-op pass */
        for (d = 0; d < size; ++d) {
            uint64_t c = hist[d];
            hist[d] = at;
            at += c;
        }
        for (i = 0; i < n; ++i) {
            uint64_t k = src[i];
            dst[hist[(k >> sh) & mask]++] = k;
        }
        t = src;
        src = dst;
        dst = t;
    }
    return src;
}

/* ---- pair collection: keeps the K smallest pair keys in bounded memory ----------- */
typedef struct bp_out {
    uint64_t *pk, *ptmp;  /* buffers of cap2 = 2 K keys */
    uint64_t *hist;       /* hist_words words of counting tables for sorting them */
    uint64_t *per_a;      /* while not over: keys counted by their lower proxy (in hist) */
    size_t n, cap2, k, hist_words;
    unsigned nb;          /* bits of a proxy index in a key */
    int over;             /* some pair was dropped (more than K exist) */
    uint64_t thr;         /* when over: keys above thr are not among the first K */
    uint64_t emitted;     /* pairs emitted in all, counted from the first slow emit on
                             (each pair is emitted once: the dropped ones are emitted - K) */
    int counting;         /* emitted holds the count */
} bp_out;

/* Sorts n pair keys (2 nb bits) in as few passes as pay: a pass costs about 8
 * instructions a key and 4 a counting-table entry. Two passes of nb bits always fit the
 * tables (2^nb < 2 count <= hist_words). */
static uint64_t *bp_sort_keys(const bp_out *o, uint64_t *keys, uint64_t *tmp, size_t n)
{
    unsigned nbits = 2u * o->nb, p, best_w = o->nb;
    uint64_t best = UINT64_MAX;
    for (p = 1; p <= nbits; ++p) {
        unsigned w = (nbits + p - 1u) / p;
        uint64_t cost;
        if (w > 20u || ((size_t)1 << w) > o->hist_words) continue;
        cost = (uint64_t)p * (8u * (uint64_t)n + 4u * ((uint64_t)1 << w));
        if (cost < best) {
            best = cost;
            best_w = w;
        }
        if (w <= 4u) break;
    }
    return bp_radix_w(keys, tmp, n, nbits, best_w, o->hist);
}

static void bp_trim(bp_out *o)
{
    uint64_t *s = bp_sort_keys(o, o->pk, o->ptmp, o->n);
    if (s != o->pk) {
        o->ptmp = o->pk;
        o->pk = s;
    }
    o->n = o->k;
    o->thr = o->pk[o->k - 1];
    o->over = 1;
}

/* A pair that does not simply go into pk: pk is full, or some were dropped. */
static void bp_emit_slow(bp_out *o, uint64_t key)
{
    if (!o->counting) { /* the fast path emitted o->n pairs so far */
        o->emitted = o->n;
        o->counting = 1;
    }
    o->emitted += 1u;
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

static inline void bp_emit(bp_out *o, uint32_t a, uint32_t b)
{
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    uint64_t key = ((uint64_t)lo << o->nb) | hi;
    if (o->n < o->cap2 && !o->over) {
        o->pk[o->n++] = key;
        o->per_a[lo]++;
        return;
    }
    bp_emit_slow(o, key);
}

/* The pairs in (a, b) order when all of them fit (not over, n <= K): a counting sort by
 * a, from the counts made while they were emitted, then each a's few partners sorted by
 * b (they are distinct, so any correct sort gives the same order): by insertion when
 * there are up to 16 of them (the cells were walked in order, so they come nearly
 * sorted), else by radix, so that no input costs quadratic time. */
static void bp_pairs_by_a(bp_out *o, uint32_t count, pg_pair *pairs)
{
    uint64_t *per_a = o->per_a, at = 0, mask = ((uint64_t)1 << o->nb) - 1u;
    uint32_t a;
    size_t t, start = 0;
    for (a = 0; a < count; ++a) {
        uint64_t c = per_a[a];
        per_a[a] = at;
        at += c;
    }
    for (t = 0; t < o->n; ++t) {
        uint64_t key = o->pk[t];
        pg_pair *p = &pairs[per_a[key >> o->nb]++];
        p->a = (uint32_t)(key >> o->nb);
        p->b = (uint32_t)(key & mask);
    }
    /* per_a[a] is now the end of a's pairs */
    for (a = 0; a < count; ++a) {
        size_t end = (size_t)per_a[a], m = end - start;
        if (m > 16u) {
            /* after per_a: 2^min(nb, 8) <= 256 words, and hist_words = 16 count >= count + 256
             * as a proxy with more than 16 partners means count >= 18 */
            unsigned w = o->nb < 8u ? o->nb : 8u;
            uint64_t *sorted;
            for (t = 0; t < m; ++t) o->pk[t] = pairs[start + t].b;
            sorted = bp_radix_w(o->pk, o->ptmp, m, o->nb, w, per_a + count);
            for (t = 0; t < m; ++t) pairs[start + t].b = (uint32_t)sorted[t];
        } else if (m > 1u) {
            size_t u, v;
            for (u = start + 1u; u < end; ++u) {
                uint32_t b = pairs[u].b;
                for (v = u; v > start && pairs[v - 1u].b > b; --v) pairs[v].b = pairs[v - 1u].b;
                pairs[v].b = b;
            }
        }
        start = end;
    }
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

/* First index of the sorted entries e[0..n) whose cell key is at least `key`. */
static size_t bp_first_at(const uint64_t *e, size_t n, uint64_t key)
{
    uint64_t want = key << 32;
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2u;
        if (e[mid] < want) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

/* Is there an entry with cell `key` in the sorted entries e[0..n)? */
static int bp_has_cell(const uint64_t *e, size_t n, uint32_t key)
{
    size_t t = bp_first_at(e, n, key);
    return t < n && (uint32_t)(e[t] >> 32) == key;
}

/* ---- the grid ---------------------------------------------------------------------- */
typedef struct bp_grid {
    const pg_aabb *boxes;
    const uint8_t *flags;
    uint32_t count;
    int have;                      /* some active proxy can be binned */
    int s;                         /* cell size 2^s */
    int32_t x0, y0, x1, y1;        /* the active rectangle, in cells */
    uint64_t wx, cells;            /* its width and its number of cells */
    size_t ecap, ea, ep;           /* entry budget; active and passive entries made */
    uint64_t *ent, *etmp, *cnt;    /* cnt: the cell counts, or NULL */
    uint64_t *list, *lbits;
    uint32_t nlarge, nbact;
} bp_grid;

static void bp_set_large(bp_grid *g, uint32_t i)
{
    g->list[g->nlarge++] = i;
    g->lbits[i >> 6] |= (uint64_t)1 << (i & 63u);
}

/* Active proxies in index order: binned into every cell of their range, or large. The
 * entries of a range go out in one flat loop: nested loops were vectorised with run-time
 * alias checks that cost more than the 1 to 4 cells of a typical proxy. */
static void bp_bin_actives(bp_grid *g)
{
    uint64_t *ent = g->ent, *cnt = g->cnt, wx = g->wx;
    int32_t x0 = g->x0, y0 = g->y0;
    size_t ea = g->ea;
    uint32_t i;
    for (i = 0; i < g->count; ++i) {
        const pg_aabb *b = &g->boxes[i];
        int32_t lx, ly, hx, hy, nx, ny, cx;
        uint64_t key, low, f;
        size_t cells;
        if (!(g->flags[i] & PG_PROXY_ACTIVE)) continue;
        lx = b->lo.x >> g->s;
        ly = b->lo.y >> g->s;
        hx = b->hi.x >> g->s;
        hy = b->hi.y >> g->s;
        if (hx < lx || hy < ly) continue; /* malformed box: not binned */
        cells = (hx - lx >= BP_MAX_SPAN || hy - ly >= BP_MAX_SPAN)
                    ? 0
                    : (size_t)(hx - lx + 1) * (size_t)(hy - ly + 1);
        if (!g->have || cells == 0 || cells > g->ecap - ea) {
            bp_set_large(g, i);
            continue;
        }
        g->list[g->count - 1u - g->nbact++] = i;
        nx = hx - lx + 1;
        ny = hy - ly + 1;
        key = (uint64_t)(ly - y0) * wx + (uint64_t)(lx - x0);
        low = i;
        f = low | BP_FX | BP_FY;
        for (cx = 0;;) {
            ent[ea++] = (key << 32) | f;
            if (cnt) cnt[key]++;
            if (++cx < nx) {
                ++key;
                f &= ~BP_FX;
            } else {
                if (--ny == 0) break;
                cx = 0;
                key += wx - (uint64_t)nx + 1u;
                f = low | BP_FX;
            }
        }
    }
    g->ea = ea;
}

/* Passive proxies in index order: clipped to the active rectangle and binned only into
 * active cells, or large when they span too many cells or the budget runs out. */
static void bp_bin_passives(bp_grid *g)
{
    uint64_t *pe = g->ent + g->ea, *bm = 0;
    size_t t, room = g->ecap - g->ea;
    uint32_t i;
    /* Which cells hold an active entry: the counts, else a bitmap over the rectangle
     * when it is small enough (in etmp, dead before the entries are sorted there), else
     * a binary search in the sorted active entries. Same answer every way. */
    if (!g->cnt) {
        size_t bm_words = (size_t)((g->cells + 63u) / 64u);
        if (bm_words <= 2u * (size_t)g->count) {
            bm = g->etmp;
            for (t = 0; t < bm_words; ++t) bm[t] = 0;
            for (t = 0; t < g->ea; ++t) {
                uint32_t key = (uint32_t)(g->ent[t] >> 32);
                bm[key >> 6] |= (uint64_t)1 << (key & 63u);
            }
        } else {
            /* sorted in place (stably: the final sort keeps this order in a cell) */
            uint64_t *as = bp_radix(g->ent, g->etmp, g->ea, 32, bp_bits(g->cells - 1u));
            if (as != g->ent)
                for (t = 0; t < g->ea; ++t) g->ent[t] = as[t];
        }
    }
    for (i = 0; i < g->count; ++i) {
        const pg_aabb *b = &g->boxes[i];
        int32_t lx, ly, hx, hy, cx, cy;
        size_t start = g->ep;
        int spill = 0;
        if (g->flags[i] & PG_PROXY_ACTIVE) continue;
        lx = bp_max32(b->lo.x >> g->s, g->x0);
        ly = bp_max32(b->lo.y >> g->s, g->y0);
        hx = bp_min32(b->hi.x >> g->s, g->x1);
        hy = bp_min32(b->hi.y >> g->s, g->y1);
        if (hx < lx || hy < ly) continue; /* outside: only large actives can meet it */
        if (hx - lx < BP_MAX_SPAN && hy - ly < BP_MAX_SPAN) {
            for (cy = ly; cy <= hy && !spill; ++cy) {
                uint64_t row = (uint64_t)(cy - g->y0) * g->wx, fy = cy == ly ? BP_FY : 0u;
                for (cx = lx; cx <= hx; ++cx) {
                    uint32_t key = (uint32_t)(row + (uint64_t)(cx - g->x0));
                    if (g->cnt ? g->cnt[key] == 0
                               : bm ? !((bm[key >> 6] >> (key & 63u)) & 1u) : !bp_has_cell(g->ent, g->ea, key))
                        continue;
                    if (g->ep == room) {
                        spill = 1;
                        break;
                    }
                    pe[g->ep++] = ((uint64_t)key << 32) | BP_PASSIVE | fy | (cx == lx ? BP_FX : 0u) | i;
                    if (g->cnt) g->cnt[key]++;
                }
            }
        } else {
            spill = 1;
        }
        if (spill) {
            if (g->cnt)
                for (t = start; t < g->ep; ++t) g->cnt[pe[t] >> 32]--;
            g->ep = start;
            bp_set_large(g, i);
        }
    }
}

/* All entries by cell, stably: in each cell the active entries (in index order), then
 * the passive ones. Returns the buffer that holds them. */
static uint64_t *bp_sort_entries(bp_grid *g)
{
    size_t ne = g->ea + g->ep, t;
    if (g->cnt) {
        uint64_t at = 0, *cnt = g->cnt;
        for (t = 0; t < (size_t)g->cells; ++t) {
            uint64_t c = cnt[t];
            cnt[t] = at;
            at += c;
        }
        for (t = 0; t < ne; ++t) {
            uint64_t e = g->ent[t];
            g->etmp[cnt[e >> 32]++] = e;
        }
        return g->etmp;
    }
    return bp_radix(g->ent, g->etmp, ne, 32, bp_bits(g->cells - 1u));
}

/* Pairs within cells: active x active and active x passive, each from the first cell
 * both boxes share: the one of the larger lo cell coordinate on each axis, which is this
 * cell when either entry has FX, and either has FY (both boxes cover it). */
static void bp_walk(const pg_aabb *boxes, const uint64_t *es, size_t ne, bp_out *out)
{
    size_t ia = 0;
    while (ia < ne) {
        uint32_t key = (uint32_t)(es[ia] >> 32);
        size_t ga = ia + 1u, u, v;
        while (ga < ne && (uint32_t)(es[ga] >> 32) == key) ++ga;
        for (u = ia; u + 1u < ga; ++u) {
            uint64_t eu = es[u], need = ~eu & (BP_FX | BP_FY);
            uint32_t pa = (uint32_t)(eu & BP_IDX);
            int32_t alx, aly, ahx, ahy;
            if (eu & BP_PASSIVE) break; /* the rest of the cell is passive */
            alx = boxes[pa].lo.x;
            aly = boxes[pa].lo.y;
            ahx = boxes[pa].hi.x;
            ahy = boxes[pa].hi.y;
            for (v = u + 1u; v < ga; ++v) {
                uint64_t ev = es[v];
                const pg_aabb *bb;
                if ((ev & need) != need) continue;
                bb = &boxes[(uint32_t)(ev & BP_IDX)];
                if (alx <= bb->hi.x && bb->lo.x <= ahx && aly <= bb->hi.y && bb->lo.y <= ahy)
                    bp_emit(out, pa, (uint32_t)(ev & BP_IDX));
            }
        }
        ia = ga;
    }
}

/* Pairs of the large passive proxy l with the binned active proxies. Every active box
 * that overlaps it has a cell in its clipped cell range (that range is never empty for a
 * large passive proxy, and each axis of an overlapping box reaches it even where l's box
 * is malformed within one cell), so the actives are looked for there when that is
 * cheaper than testing all of them: each row of the range is one run of the sorted
 * entries (found by binary search), and each active is taken from the first cell the two
 * ranges share, as in the cell walk. */
static void bp_large_passive(const bp_grid *g, const uint64_t *es, size_t ne, uint32_t l, bp_out *out)
{
    const pg_aabb *bl = &g->boxes[l];
    int32_t lx = bp_max32(bl->lo.x >> g->s, g->x0), ly = bp_max32(bl->lo.y >> g->s, g->y0);
    int32_t hx = bp_min32(bl->hi.x >> g->s, g->x1), hy = bp_min32(bl->hi.y >> g->s, g->y1), cy;
    uint64_t nrows = (uint64_t)((int64_t)hy - ly) + 1u, ncells = nrows * ((uint64_t)((int64_t)hx - lx) + 1u);
    /* the entries of the range, estimated from the average per cell: ncells < 2^31 and
     * ne <= 2^33 keep the product below 2^64 */
    uint64_t scan = 2u * ncells >= g->cells ? ne : ncells * ne / g->cells;
    uint32_t u;
    if (nrows * 80u + scan * 8u >= (uint64_t)g->nbact * 10u) {
        for (u = 0; u < g->nbact; ++u) {
            uint32_t j = (uint32_t)g->list[g->count - 1u - u];
            if (bp_overlap(bl, &g->boxes[j])) bp_emit(out, l, j);
        }
        return;
    }
    for (cy = ly; cy <= hy; ++cy) {
        uint64_t row = (uint64_t)(cy - g->y0) * g->wx, k0 = row + (uint64_t)(lx - g->x0), k1 = row + (uint64_t)(hx - g->x0);
        uint64_t need = cy == ly ? 0u : BP_FY; /* below l's first row: the active's first row */
        size_t t;
        for (t = bp_first_at(es, ne, k0); t < ne && (es[t] >> 32) <= k1; ++t) {
            uint64_t e = es[t];
            uint32_t a = (uint32_t)(e & BP_IDX);
            if ((e & BP_PASSIVE) || (e & need) != need) continue;
            if (!(e & BP_FX) && (e >> 32) != k0) continue; /* neither's first column */
            if (bp_overlap(bl, &g->boxes[a])) bp_emit(out, l, a);
        }
    }
}

int pg_broadphase_pairs(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                        pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count,
                        void *scratch, size_t scratch_bytes)
{
    uint64_t dropped;
    return pg_broadphase_pairs_counted(boxes, flags, count, pairs, pair_capacity, pair_count, &dropped, scratch, scratch_bytes);
}

int pg_broadphase_pairs_counted(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                                pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count, uint64_t *dropped,
                                void *scratch, size_t scratch_bytes)
{
    uint64_t sum = 0, mean;
    uint32_t nact = 0, i;
    int have = 0;
    int64_t min_side = 0, max_side = 0;
    int32_t lo_x = INT32_MAX, lo_y = INT32_MAX, hi_x = INT32_MIN, hi_y = INT32_MIN;
    size_t t, ne;
    uint64_t *es;
    bp_grid g;
    bp_out out;

    *pair_count = 0;
    *dropped = 0;
    if (count > BP_MAX_PROXIES || scratch_bytes < pg_broadphase_scratch_bytes(count, pair_capacity)) return -2;

    /* the mean extent of the active proxies, and the bounds of their boxes */
    for (i = 0; i < count; ++i) {
        const pg_aabb *b = &boxes[i];
        int64_t w, h;
        if (!(flags[i] & PG_PROXY_ACTIVE)) continue;
        ++nact;
        sum += bp_extent(b);
        w = (int64_t)b->hi.x - b->lo.x;
        h = (int64_t)b->hi.y - b->lo.y;
        if (w < min_side) min_side = w;
        if (h < min_side) min_side = h;
        if (w > max_side) max_side = w;
        if (h > max_side) max_side = h;
        lo_x = bp_min32(lo_x, b->lo.x);
        lo_y = bp_min32(lo_y, b->lo.y);
        hi_x = bp_max32(hi_x, b->hi.x);
        hi_y = bp_max32(hi_y, b->hi.y);
    }
    if (nact == 0) return 0; /* a fully passive world costs one pass over the flags */

    g.boxes = boxes;
    g.flags = flags;
    g.count = count;
    g.x0 = g.y0 = g.x1 = g.y1 = 0;
    g.wx = 0;
    g.cells = 0;

    /* cell size: smallest power of two >= the mean extent, clamped */
    mean = sum / nact;
    g.s = BP_MIN_SHIFT;
    while (g.s < BP_MAX_SHIFT && ((uint64_t)1 << g.s) < mean) ++g.s;

    /* rectangle of the cells covered by binnable active proxies; grow the cells until
     * a cell key of that rectangle fits in 32 bits (always true from s = 16 on).
     * When no active box is inverted and none is 7 cells wide or high, each spans at most
     * 8 cells ((hi >> s) - (lo >> s) <= ((hi - lo) >> s) + 1 <= 7), so all are binnable
     * and the rectangle is the bounds above in cells (the shift is monotone): the pass
     * below is not needed when that rectangle fits. */
    if (min_side >= 0 && max_side < ((int64_t)7 << g.s)) {
        int32_t x0 = lo_x >> g.s, y0 = lo_y >> g.s, x1 = hi_x >> g.s, y1 = hi_y >> g.s;
        uint64_t wx = (uint64_t)((int64_t)x1 - x0) + 1u, wy = (uint64_t)((int64_t)y1 - y0) + 1u;
        if (wx * wy <= ((uint64_t)1 << 32)) {
            g.x0 = x0; g.y0 = y0; g.x1 = x1; g.y1 = y1;
            g.wx = wx;
            g.cells = wx * wy;
            have = 1;
        }
    }
    while (!have) {
        int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        uint64_t wx, wy;
        have = 0;
        for (i = 0; i < count; ++i) {
            const pg_aabb *b = &boxes[i];
            int32_t lx, ly, hx, hy;
            if (!(flags[i] & PG_PROXY_ACTIVE)) continue;
            lx = b->lo.x >> g.s;
            ly = b->lo.y >> g.s;
            hx = b->hi.x >> g.s;
            hy = b->hi.y >> g.s;
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
        if (wx * wy <= ((uint64_t)1 << 32)) {
            g.x0 = x0; g.y0 = y0; g.x1 = x1; g.y1 = y1;
            g.wx = wx;
            g.cells = wx * wy;
            break;
        }
        have = 0;
        ++g.s;
    }

    /* scratch */
    g.ecap = (size_t)count * BP_ENTRIES_PER_PROXY;
    g.ent = (uint64_t *)scratch;
    g.etmp = g.ent + g.ecap;
    out.pk = g.etmp + g.ecap;
    out.cap2 = (size_t)pair_capacity * 2u;
    out.ptmp = out.pk + out.cap2;
    g.list = out.ptmp + out.cap2;
    g.lbits = g.list + count;
    for (t = 0; t < ((size_t)count + 63u) / 64u; ++t) g.lbits[t] = 0;
    g.ea = g.ep = 0;
    g.nlarge = g.nbact = 0;
    g.cnt = 0;
    out.n = 0;
    out.k = pair_capacity;
    out.nb = bp_bits(count > 1u ? count - 1u : 1u);
    out.over = 0;
    out.thr = 0;
    out.emitted = 0;
    out.counting = 0;

    if (have) {
        /* A small rectangle is counted cell by cell while the entries are made, in pk and
         * ptmp (unused until the entries are sorted): the counts tell the passive proxies
         * which cells are active, and one counting sort orders the entries. A large one
         * (few proxies spread far apart) is sorted by radix instead. */
        if (g.cells <= 2u * (uint64_t)out.cap2 && g.cells <= 4u * (uint64_t)count + 64u) {
            g.cnt = out.pk;
            for (t = 0; t < (size_t)g.cells; ++t) g.cnt[t] = 0;
        }
    }
    g.have = have;
    bp_bin_actives(&g);
    if (have) bp_bin_passives(&g);
    ne = g.ea + g.ep;
    es = ne != 0 ? bp_sort_entries(&g) : g.ent;
    out.hist = es == g.ent ? g.etmp : g.ent; /* the other buffer */
    out.hist_words = g.ecap;
    out.per_a = out.hist;
    for (i = 0; i < count; ++i) out.per_a[i] = 0;

    bp_walk(boxes, es, ne, &out);

    /* large proxies */
    for (t = 0; t < g.nlarge; ++t) {
        uint32_t l = (uint32_t)g.list[t];
        const pg_aabb *bl = &boxes[l];
        if (flags[l] & PG_PROXY_ACTIVE) {
            /* against everyone; a pair of two large actives is tested by the lower index */
            for (i = 0; i < count; ++i) {
                if (i == l) continue;
                if (i < l && (flags[i] & PG_PROXY_ACTIVE) && bp_is_large(g.lbits, i)) continue;
                if (bp_overlap(bl, &boxes[i])) bp_emit(&out, l, i);
            }
        } else {
            /* against the binned actives (large actives test it themselves) */
            bp_large_passive(&g, es, ne, l, &out);
        }
    }

    /* the first K pairs in (a, b) order */
    if (!out.over && out.n <= out.k) {
        bp_pairs_by_a(&out, count, pairs);
        *pair_count = (uint32_t)out.n;
        return 0;
    } else {
        const uint64_t *sorted = bp_sort_keys(&out, out.pk, out.ptmp, out.n);
        uint64_t mask = ((uint64_t)1 << out.nb) - 1u;
        size_t n_out = out.n < out.k ? out.n : out.k;
        for (t = 0; t < n_out; ++t) {
            pairs[t].a = (uint32_t)(sorted[t] >> out.nb);
            pairs[t].b = (uint32_t)(sorted[t] & mask);
        }
        *pair_count = (uint32_t)n_out;
        *dropped = (out.counting ? out.emitted : out.n) - n_out;
        return -1;
    }
}
