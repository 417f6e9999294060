/** @file
 * pogon/scene_file.h — worlds as text: read and write pogon scene files.
 *
 * WHAT IT IS
 *   A scene file describes a world in a small line-oriented text format (specified in
 *   docs/formats.md, "Scene files"): the world's settings, then its bodies with their
 *   shapes and properties. It starts with the line `pogon-scene 1`:
 *
 *       pogon-scene 1
 *       # a ground and a box
 *       gravity 0 -10
 *       wall 40 2 position 0 -1              # ready-made kinds: one line each
 *       box 1 1 position 0 4 angle 30 friction 0.3
 *       body dynamic                         # or a body with any shapes
 *         position 2 6
 *         shape circle 0.5 offset 0 0.25 density 2
 *         shape polygon -0.5 0 0.5 0 0 0.8
 *       end
 *
 *   Every number is exact decimal read with pg_fix_parse (fixed.h), so a scene file
 *   gives the same bits on every machine; angles are degrees, converted exactly to a
 *   binary angle (round(degrees * 2^32 / 360) computed from the Q16.16 value).
 *
 * HOW TO USE IT
 *     pg_world_def def;
 *     pg_scene_error err;
 *     if (pg_scene_read_def(text, length, &def, &err) != PG_OK) {
 *         fprintf(stderr, "%s\n", err.message);    // "line 12, column 9: expected ..."
 *         return;
 *     }
 *     size_t need = pg_world_memory_size(&def);    // capacities may be raised first
 *     ... memory of `need` bytes, aligned to 8 ...
 *     pg_world_create(&def, memory, need, &world);
 *     if (pg_scene_load(world, text, length, &err) != PG_OK) ... // recreate the world
 *
 *     // on a small stack: the same calls with a work area that lives elsewhere
 *     static uint64_t work[PG_SCENE_WORK_BYTES / 8];
 *     pg_scene_read_def_in(text, length, &def, &err, work, sizeof work);
 *     pg_scene_load_in(world, text, length, &err, work, sizeof work);
 *
 *     size_t n = pg_scene_write(world, NULL, 0);   // bytes needed, without the NUL
 *     ... a buffer of n + 1 bytes ...
 *     pg_scene_write(world, buffer, n + 1);
 *
 * CONVENTIONS
 *   - Text is read from (text, length): never beyond `length`, and it need not end with
 *     a NUL. The reader does not allocate, does not recurse, and accepts LF or CRLF line
 *     ends. It returns a pg_result for any input (it is fuzzed: tests/fuzz/fuzz_scene.c).
 *   - Errors name the line and column (both from 1) and what was expected, in
 *     pg_scene_error.message: "line 12, column 9: expected a number for 'density',
 *     got 'abc'". Results: PG_ERR_INVALID_ARGUMENT for text that does not follow the
 *     format (bad version line, unknown keyword, missing or malformed value, wrong
 *     number of polygon vertices, bytes that are not text); PG_ERR_ENVELOPE for a
 *     well-formed number outside its allowed range (including numbers beyond Q16.16 or
 *     beyond an integer's width); PG_ERR_DEGENERATE / PG_ERR_NOT_CONVEX / PG_ERR_ENVELOPE
 *     from pg_geometry_* for bad shapes; PG_ERR_BODY_TYPE for a velocity on a static
 *     body or a wall of another type; PG_ERR_CAPACITY when the scene needs more bodies or
 *     shapes than its capacities (or a body more than 64 shapes).
 *   - `error` may be NULL everywhere. On success it is cleared (line and column 0,
 *     empty message).
 */
#ifndef POGON_SCENE_FILE_H
#define POGON_SCENE_FILE_H

#include "pogon/pogon.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The first line of every scene file of this version. */
#define PG_SCENE_MAGIC "pogon-scene"
#define PG_SCENE_VERSION 1 /**< the format version this build reads and writes */

/** Where and why reading failed. line and column count from 1 (0: no position, e.g. a
 * NULL argument); column counts bytes. message is NUL-terminated, starts with
 * "line L, column C: " when there is a position, and is cut to fit. */
typedef struct pg_scene_error {
    uint32_t line;      /**< line of the problem, from 1 (0: no position) */
    uint32_t column;    /**< byte column of the problem, from 1 (0: no position) */
    char message[160];  /**< what is wrong, NUL-terminated */
} pg_scene_error;

/** Read only the world settings from scene text, so the caller can size memory.
 * The whole text is checked (syntax, ranges, shapes, counts, and each dynamic body's
 * mass and inertia as pg_shape_create checks them, shape by shape), so a text accepted
 * here fails in pg_scene_load only for reasons that need a world (its free capacity, a
 * different def). *def starts from pg_default_world_def() with the file's settings on
 * top; capacities the file does not give are what the scene needs: max_bodies = its
 * bodies, max_shapes = its shapes (at least 1 each), max_contacts = 4 * shapes + 64.
 * Raise them before creating the world to leave room for more. *def is written only
 * on success. */
pg_result pg_scene_read_def(const char *text, size_t length, pg_world_def *def, pg_scene_error *error);

/** An upper bound of pg_scene_work_size() on every target, for a work area declared at
 * compile time (scene_file.c checks it when it compiles):
 *     static uint64_t scene_work[PG_SCENE_WORK_BYTES / 8];  // aligned to 8 */
#define PG_SCENE_WORK_BYTES 20480u

/** Bytes of the work area the `_in` readers need: the parser, the shapes of the body
 * being read and the work space of their mass check (about 18 KiB). The same for every
 * text; at most PG_SCENE_WORK_BYTES. */
size_t pg_scene_work_size(void);

/** Create the scene's bodies in `world`, in file order (each takes the lowest free body
 * slot). The world must have been created from the def pg_scene_read_def gives for
 * this text: every setting except the capacities must be equal (else
 * PG_ERR_INVALID_ARGUMENT naming the setting), and the world's free body and shape
 * slots must hold the scene's bodies and shapes besides any already in the world (else
 * PG_ERR_CAPACITY naming the line of the first body or shape that does not fit).
 * Everything is checked before the first body is made: the whole text as
 * pg_scene_read_def checks it, the settings and the free slots, so a failing load
 * leaves the world as it was. (Should making a body fail all the same, which would be
 * a check of pg_body_create or pg_shape_create that this reader does not repeat, the
 * error names that body's line and holds the world's detail (pg_world_last_error),
 * and the world keeps the bodies completed before that line; a partly built body is
 * destroyed.) */
pg_result pg_scene_load(pg_world *world, const char *text, size_t length, pg_scene_error *error);

/** pg_scene_read_def and pg_scene_load with a work area from the caller: for small
 * stacks (a microcontroller's). pg_scene_read_def and pg_scene_load put a work area of
 * PG_SCENE_WORK_BYTES on their own stack and call these; with the work area elsewhere
 * (a static buffer, the caller's heap), no frame on their path is larger than a few
 * hundred bytes and the deepest call stays under 4 KiB on a 32-bit target
 * (docs/embedded.md, "Stack"). Results, errors and messages are those of the plain calls.
 *
 * `work`: at least pg_scene_work_size() bytes, aligned to 8 (the alignment of uint64_t
 * on the targets pogon supports), whose contents do not matter; it is overwritten, and
 * nothing in it is needed after the call. A work area that is NULL, misaligned or too
 * small is refused with PG_ERR_INVALID_ARGUMENT and a message naming the size needed
 * (line and column 0), before anything else is written (NULL text, def or world are
 * still PG_ERR_NULL, checked first). */
pg_result pg_scene_read_def_in(const char *text, size_t length, pg_world_def *def, pg_scene_error *error, void *work,
                               size_t work_size);
/** pg_scene_load with a work area from the caller (pg_scene_read_def_in). */
pg_result pg_scene_load_in(pg_world *world, const char *text, size_t length, pg_scene_error *error, void *work,
                           size_t work_size);

/** Write the world's settings (the def in force, capacities included) and every body
 * with its shapes in their current state: type, position (the body origin), angle,
 * velocities, damping, gravity scale, flags (fixed rotation, allow sleep, awake),
 * user data; each shape's geometry, material and filter. Bodies are written in slot
 * order, each as a `body` block; properties equal to their defaults are left out.
 * Numbers are written with pg_fix_format (shortest exact decimal); an angle that
 * whole-Q16.16 degrees cannot express exactly is written as `angle_bits 0x...`.
 *
 * What a scene does not hold: contacts and their warm-start impulses, sleep timers,
 * which island a sleeping body belongs to (each loads as its own island), forces
 * pending for the next step, the frame counter and statistics, the handles' slots and
 * generations (bodies load compacted, in slot order). pg_scene_load of the text gives
 * bodies and shapes equal to the world's, and writing that world again gives the
 * same text. A body outside the envelope (e.g. one that fell beyond 1000 m) is written
 * as it is, and loading that text refuses it with PG_ERR_ENVELOPE.
 *
 * snprintf-style: writes at most `capacity` bytes including a terminating NUL (nothing
 * when capacity is 0; buffer may then be NULL) and returns the length of the whole
 * text without the NUL. The output was cut when the result is >= capacity. A NULL
 * world writes nothing and returns 0. */
size_t pg_scene_write(const pg_world *world, char *buffer, size_t capacity);

/** Degrees (Q16.16) to a binary angle exactly as the reader does: round(deg * 2^32 / 360)
 * computed in 64-bit integers from the Q16.16 value (ties away from zero), modulo a
 * full turn. 90 degrees gives PG_ANGLE_QUARTER, 45 gives 0x20000000. */
pg_angle pg_scene_angle_from_degrees(pg_fix degrees);

#ifdef __cplusplus
}
#endif
#endif
