/* contact_solver.h (internal) — the contact constraint kind: its rows through each stage
 * of the solve (solver.c runs the stages; docs/solver-design.md explains the rows). */
#ifndef POGON_SRC_CONTACT_SOLVER_H
#define POGON_SRC_CONTACT_SOLVER_H
#include "solver_kernel.h"

struct contact_constraint;

/* The step's contact constraints, in the scratch solver.c gives them. */
typedef struct pg_contact_stage {
    struct contact_constraint *cons;
    uint32_t count;
    uint32_t *deep_list;   /* scratch of max_contacts entries: the deep push's constraints */
    int deep;              /* a point pushes out past its velocity cap in this step, or
                              starts it with a pseudo impulse (deep push) */
} pg_contact_stage;

/* Bytes of max_contacts constraints. */
size_t pg__contact_constraint_bytes(uint32_t max_contacts);
/* The contacts' softness and push-out limits for the step, into ctx (needs ctx->n). */
void pg__contacts_set_softness(step_context *ctx, const pg_world_def *def);

/* The stages, in the order solver.c runs them. prepare: one constraint per contact with
 * points and a moving side, from the state at the step's start (needs the bodies'
 * accelerations); area holds the constraints, deep_list the deep push's scratch. */
void pg__contacts_prepare(pg_contact_stage *s, step_context *ctx, solver_body *bodies, void *area, uint32_t *deep_list);
/* Substep ctx->sub's warm start: the stored impulses in the first substep, then each
 * substep's change again in the next. */
void pg__contacts_warm_start(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies, const uint32_t *active,
                             uint32_t n_active);
/* The soft pass with bias, then the deep push's pseudo velocities (s->deep). */
void pg__contacts_solve(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies);
/* The relax pass: no bias, from the separations where the bodies are now. */
void pg__contacts_relax(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies);
/* Once after the substeps: the rebound of points that approached fast enough, in the
 * phase of the substep the bodies leave in (half a substep of a h: SUBSTEP PHASE). */
void pg__contacts_restitution(const pg_contact_stage *s, const step_context *ctx, solver_body *bodies);
/* The impulses back into the contacts, for the next step's warm start. */
void pg__contacts_store(const pg_contact_stage *s, pg_world *w);

#endif
