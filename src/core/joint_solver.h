/* joint_solver.h (internal) — the joints as one constraint kind of the soft step: each
 * stage of solver.c calls the one here, which runs every joint's kind in slot order
 * (docs/joints.md, docs/solver-design.md). */
#ifndef POGON_SRC_JOINT_SOLVER_H
#define POGON_SRC_JOINT_SOLVER_H
#include "joint_rows.h"

typedef struct pg_joint_stage {
    joint_constraint *cons;
    uint32_t count;
    joint_change *change;  /* per solver body slot (solver_kernel.h) */
    uint32_t weld_count;   /* how many of cons are welds */
} pg_joint_stage;

/* Bytes of the joints' scratch: max_joints constraints and a joint change per body slot. */
size_t pg__joint_scratch_bytes(uint32_t max_joints, uint32_t max_bodies);
/* One constraint per joint with a side that moves in this step (needs the solver bodies
 * set); zeroes the joint change of the n_active bodies in `active`. */
void pg__joints_prepare(pg_joint_stage *s, const step_context *ctx, solver_body *bodies, void *area, const uint32_t *active,
                        uint32_t n_active);
void pg__joints_warm_start(const pg_joint_stage *s, solver_body *bodies);
void pg__joints_solve(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies);
void pg__joints_relax(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies);
void pg__joints_store(const pg_joint_stage *s, pg_world *w);

#endif
