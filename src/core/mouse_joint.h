/* mouse_joint.h (internal) — the mouse joint's rows through the solver's stages, which
 * joint.c dispatches to (docs/joints.md). */
#ifndef POGON_SRC_MOUSE_JOINT_H
#define POGON_SRC_MOUSE_JOINT_H
#include "joint_rows.h"

/* Its rows from the step's start (c's sides are set) and its stored impulses. */
void pg__mouse_joint_prepare(joint_constraint *c, const step_context *ctx);
/* Apply the accumulated impulses (every substep). */
void pg__mouse_joint_warm_start(joint_constraint *c, solver_body *bodies);
/* One pass: with the soft bias (solve) or without (relax). */
void pg__mouse_joint_solve(joint_constraint *c, solver_body *bodies, const step_context *ctx, int use_bias, int moved);
/* The impulses back into the joint. */
void pg__mouse_joint_store(const joint_constraint *c, pg_joint *j);
/* The impulse the accumulated lambdas stand for, on body B: x, y (Q16 N s) and the
 * angular impulse (Q16 N m s). */
void pg__mouse_joint_impulse(const joint_constraint *c, int64_t out[3]);

#endif
