/** @file
 * pogon/config.h — compile-time switches.
 *
 * Define these before building the library (CMake cache options of the same name set
 * them for you). Each one trades accuracy or features for time and size; the
 * accuracy-versus-time report measures them.
 */
#ifndef POGON_CONFIG_H
#define POGON_CONFIG_H

/** Entries per full turn of the sine table, as a power of two: 8 (256 entries) to 12
 * (4096). The library stores the first quarter of the turn and mirrors it, 2^bits / 4 + 1
 * entries of 4 bytes: 260 bytes at 8, 4100 at 12. Sine and cosine interpolate linearly between entries;
 * the interpolation error is about (2 pi / 2^bits)^2 / 8: 4.7e-6 at 10 bits and 2.9e-7
 * at 12. The default is 12 because rotations scale vertices by up to that error: at
 * 10 bits a vertex 50 m from its body's centre would wobble by 15 Q16.16 steps as the
 * body turns, at 12 bits by one. */
#ifndef PG_TRIG_TABLE_BITS
#define PG_TRIG_TABLE_BITS 12
#endif
#if PG_TRIG_TABLE_BITS < 8 || PG_TRIG_TABLE_BITS > 12
#error "PG_TRIG_TABLE_BITS must be between 8 and 12"
#endif

/** How pg_isqrt64 (and so every length, distance and normalisation) computes its
 * integer square root. 1 (default): a table seed, one Newton step with a 64-bit
 * division and an exact correction, several times faster where 64-bit division is a
 * hardware instruction (x86-64, AArch64, ...). 0: the digit-by-digit loop (up to 32
 * iterations, shifts and adds only), for targets without a hardware 64-bit divider,
 * such as Cortex-M (and most 32-bit targets), where each 64-bit division is a library
 * call. Both return exactly floor(sqrt(v)): the switch changes speed only,
 * never a result, so builds with different settings stay bit-identical. */
#ifndef PG_FAST_DIV64
#define PG_FAST_DIV64 1
#endif
#if PG_FAST_DIV64 != 0 && PG_FAST_DIV64 != 1
#error "PG_FAST_DIV64 must be 0 or 1"
#endif

/** The effects (PG_EFFECT_* bits of pogon.h, here as numbers) the library is built with;
 * default 0x7F, all of them. An effect left out has no code in the library: the step's
 * tests of its bit fold to constants, and --gc-sections drops what only it calls. For
 * example 0x1F keeps gravity, rotation, friction, restitution and damping and leaves out
 * sleeping (0x20) and continuous collision (0x40). Such a build refuses a world
 * definition or a pg_world_set_effects call that turns a left-out effect on
 * (PG_ERR_INVALID_ARGUMENT, with a message naming this switch), and
 * pg_default_world_def leaves it out of its effects. The effects it keeps step exactly
 * as in the full build (docs/modules.md). */
#ifndef PG_CONFIG_EFFECTS
#define PG_CONFIG_EFFECTS 0x7Fu
#endif
#if ((PG_CONFIG_EFFECTS) & ~0x7Fu) != 0
#error "PG_CONFIG_EFFECTS must be a combination of the PG_EFFECT_* bits (0x00 .. 0x7F)"
#endif

/** 1 (default): the library has joints (pogon/joint.h). 0: it leaves them out: no joint
 * solver, joint pool or joint code in the step. The functions of pogon/joint.h stay
 * declared and linkable (src/core/joints_left_out.c), so programs, commands and scene files
 * build unchanged, and each fails by name: creating a joint gets PG_ERR_INVALID_ARGUMENT
 * with a message naming this switch, a call with a joint handle PG_ERR_STALE_HANDLE. A
 * world definition with max_joints above 0 is refused the same way, and
 * pg_default_world_def gives max_joints 0. Bodies step exactly as in the full build. */
#ifndef PG_CONFIG_JOINTS
#define PG_CONFIG_JOINTS 1
#endif
#if PG_CONFIG_JOINTS != 0 && PG_CONFIG_JOINTS != 1
#error "PG_CONFIG_JOINTS must be 0 or 1"
#endif

/** @name Shape kinds
 * PG_CONFIG_SHAPES: the shape kinds the library is built with, a combination of the
 * PG_SHAPES_* bits below; default 0x3F, all of them. A kind left out is refused wherever
 * it would enter a world (pg_shape_create, the pg_make_* calls, snapshots and scene
 * files: PG_ERR_INVALID_ARGUMENT, with a message naming this switch); its pg_geometry_*
 * function returns PG_ERR_INVALID_ARGUMENT (it has no world to hold a message). What
 * only that kind needs (its validation, chain collision, ear clipping, a capsule's mass
 * terms) then has no code in the library. The kinds kept step exactly as in the full
 * build. For example 0x03 keeps circles and boxes; the box collider is the polygon
 * collider (boxes take its fast path), so it stays.
 * @{ */
#define PG_SHAPES_CIRCLE 0x01u  /**< circles: pg_geometry_circle, pg_make_ball */
#define PG_SHAPES_BOX 0x02u     /**< four-vertex polygons: pg_geometry_box, pg_make_box, pg_make_wall */
#define PG_SHAPES_POLYGON 0x04u /**< polygons of 3 and 5..8 vertices: triangles, stars, pg_geometry_decompose, pg_make_concave */
#define PG_SHAPES_CAPSULE 0x08u /**< capsules: pg_geometry_capsule, pg_make_capsule */
#define PG_SHAPES_SEGMENT 0x10u /**< two-sided segments: pg_geometry_segment */
#define PG_SHAPES_CHAIN 0x20u   /**< chain segments: pg_geometry_chain_segment, pg_make_chain */
#ifndef PG_CONFIG_SHAPES
#define PG_CONFIG_SHAPES 0x3Fu
#endif
#if ((PG_CONFIG_SHAPES) & ~0x3Fu) != 0 || ((PG_CONFIG_SHAPES) & 0x3Fu) == 0
#error "PG_CONFIG_SHAPES must be a non-empty combination of the PG_SHAPES_* bits (0x01 .. 0x3F)"
#endif
/** Nonzero when this build keeps the kinds of `bits` (PG_SHAPES_*). */
#define PG_SHAPES_KEPT(bits) (((bits) & (PG_CONFIG_SHAPES)) != 0)
/** @} */

/** @name Numeric configuration
 * The switches above that change results, packed into one 32-bit value: replay files
 * and snapshots record it, and a file of another configuration is refused on load with
 * a message naming both (a build with another sine table steps differently, so its
 * checkpoints could never match). pg_numeric_config() returns the library's value.
 *
 * Bits 0-3: PG_TRIG_TABLE_BITS (8..12). Bits 4-31: 0, free for the next switch.
 * A switch that changes only speed or size, never a result (PG_FAST_DIV64), is not in it.
 *
 * Adding a switch that changes results (or leaves a feature out): give it the next free
 * bits below (a _SHIFT and a _MASK), OR its value into PG_NUMERIC_CONFIG, and add a row
 * naming it to the table in src/core/numeric_config.c (its messages). Make its value 0 mean
 * what builds without the switch did, so that files recorded before it existed keep
 * loading in default builds.
 * @{ */
#define PG_NUMCFG_TRIG_BITS_SHIFT 0   /**< where PG_TRIG_TABLE_BITS sits */
#define PG_NUMCFG_TRIG_BITS_MASK 0xFu /**< its width: 4 bits */
/** This configuration, as compiled (pg_numeric_config() gives the library's). */
#define PG_NUMERIC_CONFIG (((unsigned long)PG_TRIG_TABLE_BITS & PG_NUMCFG_TRIG_BITS_MASK) << PG_NUMCFG_TRIG_BITS_SHIFT)
/** @} */

#endif
