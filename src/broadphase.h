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

/* Bytes of scratch memory the broadphase needs for `max_proxies` proxies. */
size_t pg_broadphase_scratch_bytes(uint32_t max_proxies);

/* Overlapping pairs (closed boxes: touching counts) of the `count` proxies, in
 * ascending (a, b) order, written to pairs[0 .. *pair_count). Returns 0 on success,
 * -1 when more than `pair_capacity` pairs exist (pairs then holds the first
 * pair_capacity in order and *pair_count the capacity). `scratch` must be
 * pg_broadphase_scratch_bytes(count) bytes aligned for uint64_t. */
int pg_broadphase_pairs(const pg_aabb *boxes, const uint8_t *flags, uint32_t count,
                        pg_pair *pairs, uint32_t pair_capacity, uint32_t *pair_count,
                        void *scratch, size_t scratch_bytes);
#endif
