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

#if PG_CONFIG_JOINTS
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

#else
/* A build without joints (PG_CONFIG_JOINTS=0, pogon/config.h): no joint scratch and no
 * joint stage, so the step's joint calls fold away and joint_solver.c is empty. */
static inline size_t pg__joint_scratch_bytes(uint32_t max_joints, uint32_t max_bodies)
{
    (void)max_joints;
    (void)max_bodies;
    return 0;
}
static inline void pg__joints_prepare(pg_joint_stage *s, const step_context *ctx, solver_body *bodies, void *area,
                                      const uint32_t *active, uint32_t n_active)
{
    (void)ctx;
    (void)bodies;
    (void)area;
    (void)active;
    (void)n_active;
    s->count = 0;
}
static inline void pg__joints_warm_start(const pg_joint_stage *s, solver_body *bodies)
{
    (void)s;
    (void)bodies;
}
static inline void pg__joints_solve(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies)
{
    (void)s;
    (void)ctx;
    (void)bodies;
}
static inline void pg__joints_relax(const pg_joint_stage *s, const step_context *ctx, solver_body *bodies)
{
    (void)s;
    (void)ctx;
    (void)bodies;
}
static inline void pg__joints_store(const pg_joint_stage *s, pg_world *w)
{
    (void)s;
    (void)w;
}
#endif
#endif
