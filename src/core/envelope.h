/* envelope.h (internal) — the numbers that bound what pogon accepts and what its solver
 * computes: contact distances, the envelope checked at creation, the solver's bounds. */
#ifndef POGON_SRC_ENVELOPE_H
#define POGON_SRC_ENVELOPE_H
#include "pogon/fixed.h"

/* Linear slop and speculative distance: contacts begin this far apart so resting bodies
 * keep their manifold without jitter. Geometry has no skin: boxes placed edge to edge
 * do not start overlapping. */
#define PG_LINEAR_SLOP ((pg_fix)328)           /* 0.005 m */
#define PG_SPECULATIVE_DISTANCE ((pg_fix)1311) /* 0.02 m: 4 slops */

/* Envelope, Q16.16 (pogon.h's THE ENVELOPE and docs/envelope.md say why each holds).
 * Thickness: every shape of every body is at least 2 PG_ENV_MIN_HALF_THICKNESS across in
 * every direction (a circle's or capsule's radius, a polygon's narrowest width; a
 * segment's length), 0.00998 m, so that pg_make_box(0.01 m) (half extent 327 LSB) passes.
 * Reach: a shape's vertices lie within PG_ENV_MAX_SIZE of the origin of a dynamic or
 * kinematic body (its lever arms, squared, must fit the solver's formats) and within
 * PG_ENV_MAX_STATIC_REACH of a static body's origin (no mass, no lever arm: only the
 * position envelope limits it). Radii are at most PG_ENV_MAX_SIZE on every body. */
#define PG_ENV_MIN_HALF_THICKNESS ((pg_fix)327) /* 0.005 m, rounded down */
#define PG_ENV_MIN_THICKNESS (2 * PG_ENV_MIN_HALF_THICKNESS)
#define PG_ENV_MAX_SIZE PG_FIX_C(50)
#define PG_ENV_MAX_STATIC_REACH PG_FIX_C(1000)
#define PG_ENV_MIN_DENSITY ((pg_fix)6554)       /* 0.1 */
#define PG_ENV_MAX_DENSITY PG_FIX_C(100)
#define PG_ENV_MAX_POSITION PG_FIX_C(1000)
#define PG_ENV_MAX_FRICTION PG_FIX_C(10)
#define PG_ENV_MAX_SPIN PG_FIX_C(1000)          /* rad/s, either way */

/* The contact solver's bounds (contact_solver.c derives its int64 arithmetic from them;
 * state.c refuses a snapshot beyond them). Velocities, m/s and rad/s: every component is
 * clamped to +-PG_SOLVER_VELOCITY_MAX (8192). Accumulated contact "impulses" (lambda: the
 * change of relative velocity along the row, m/s) to +-PG_SOLVER_LAMBDA_MAX (8192): two
 * bodies meeting head-on at the largest max_linear_speed (4096 m/s) close at 8192 m/s,
 * and one row must be able to stop them, or a speculative contact lets them pass through. */
#define PG_SOLVER_VELOCITY_MAX (INT32_C(1) << 29)
#define PG_SOLVER_LAMBDA_MAX (INT32_C(1) << 29)

#endif
