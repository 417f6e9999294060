/* broadphase.h (internal) — candidate pairs from bounding boxes.
 *
 * A uniform grid whose cell size follows the moving proxies (a power of two near
 * their mean size), built anew every step: proxies are binned into the cells their
 * box covers, the (cell, proxy) entries are radix-sorted (stable, so the result is a
 * pure function of the input), and each overlapping pair is reported once, from the
 * first cell the two boxes share. Proxies that would cover very many cells (long
 * walls, the ground) are kept aside and tested against every proxy. The output is
 * sorted by (a, b). Cost: linear in the number of proxies for scenes of similar-sized
 * bodies. No heap: the caller provides the scratch memory.
 */
#ifndef POGON_SRC_BROADPHASE_H
#define POGON_SRC_BROADPHASE_H
#include <stddef.h>
#include "pogon/fixed.h"

typedef struct pg_pair { uint32_t a, b; } pg_pair; /* proxy indices, a < b */

/* Flags per proxy. A pair is reported only when at least one of its proxies is
 * ACTIVE (awake, movable); pairs of two passive proxies (static, asleep) are not. */
#define PG_PROXY_ACTIVE 1u

/* Bytes of scratch memory pg_broadphase_pairs needs for up to `max_proxies` proxies
 * and a pair capacity of `max_pairs` (SIZE_MAX if that does not fit in a size_t, or if
 * max_proxies > 2^29, more than the broadphase takes):
 *     8 * (33 * max_proxies + ceil(max_proxies / 64) + 4 * max_pairs)
 * i.e. 264 bytes per proxy (16 cell entries per proxy, sorted with a buffer of the same
 * size; one index list) and 32 bytes per pair of capacity (pairs are collected and
 * sorted in scratch, up to 2 * max_pairs at a time). Monotone in both arguments. */
size_t pg_broadphase_scratch_bytes(uint32_t max_proxies, uint32_t max_pairs);

/* Overlapping pairs (closed boxes: touching counts) of the `count` proxies, in
 * ascending (a, b) order, written to pairs[0 .. *pair_count). Returns 0 on success,
 * -1 when more than `pair_capacity` pairs exist (pairs then holds the first
 * pair_capacity in order and *pair_count the capacity), -2 when scratch_bytes is less
 * than pg_broadphase_scratch_bytes(count, pair_capacity) or count > 2^29 (nothing done,
 * *pair_count 0; a world has at most 2^24 shapes).
 * `scratch` must be aligned for uint64_t; its contents on entry do not matter and on
 * return are unspecified. When no proxy is ACTIVE the call returns 0 pairs after one
 * pass over `flags`. Boxes must have lo <= hi (otherwise the pairs are unspecified,
 * though memory stays safe). The result is a pure function of (boxes, flags, count,
 * pair_capacity).
 *
 * HOW (the rules that make it deterministic and bounded)
 *   Cell size 2^s (Q16.16 units): the smallest power of two >= the mean over ACTIVE
 *   proxies of max(width, height) (each clamped to 2^22 first), clamped to
 *   [2^12, 2^22] (1/16 m .. 64 m); raised further (at most to 2^16) if the cells
 *   spanned by the binned active proxies would number more than 2^32.
 *   Cell coordinates are floor(coordinate / 2^s) (arithmetic shift).
 *   A proxy is LARGE when its box spans more than 8 cells on either axis (a passive
 *   proxy is first clipped to the rectangle of cells holding binned active proxies;
 *   passive proxies wholly outside it are not binned at all), or when its cell
 *   entries do not fit in what is left of the entry budget of 16 * count entries.
 *   The budget is handed out to active proxies in index order first, then to passive
 *   ones in index order; a passive proxy is binned only into cells that hold an active
 *   entry. Large active proxies are tested against every other proxy, large passive
 *   ones against every binned active proxy. Binned proxies are paired within cells
 *   ((cell, proxy) entries sorted stably by cell: a counting sort when the rectangle
 *   has few cells, else an LSD radix sort), each pair from the first cell both boxes
 *   share. More than 16 entries per proxy on average (a sign of very mixed sizes)
 *   degrades speed, never correctness. */
int pg_broadphase_pairs(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                        pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count,
                        void *scratch, size_t scratch_bytes);
/* The same, and *dropped receives how many overlapping pairs were left out (0 unless
 * the call returns -1): every pair is emitted once, so they are counted exactly. */
int pg_broadphase_pairs_counted(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                                pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count, uint64_t *dropped,
                                void *scratch, size_t scratch_bytes);
#endif
