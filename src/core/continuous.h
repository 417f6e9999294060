/* continuous.h (internal) — time of impact for bodies that turn too far in a step for
 * their speculative contacts (see continuous.c's header). */
#ifndef POGON_SRC_CONTINUOUS_H
#define POGON_SRC_CONTINUOUS_H
#include "world_types.h"

typedef struct pg_sweep {
    uint32_t body;
    pg_vec2 c0, c1;     /* centre of mass at the step's start and end */
    pg_angle a0;        /* angle at the start */
    int64_t turn;       /* the step's turn in binary-angle units, unwrapped (pg__turn_of_step) */
    pg_fix fraction;    /* earliest time of impact, Q16.16 of the step; PG_FIX_ONE: none */
    int32_t moved;      /* c1 was moved: a core circle was held at a surface */
} pg_sweep;
void pg__shape_set_extents(pg_shape *s); /* whenever s->local is built */
void pg__body_set_turn_extents(pg_world *w, uint32_t body); /* whenever its shapes or local_center change */
/* Whether body b is fast-turning at its angular velocity now (for its broadphase boxes at
 * the step's start), and then the radius about its centre of mass that shape s sweeps
 * while it turns: the box covers that disc (otherwise the pose's box is enough). */
int pg__turns_fast_now(const pg_world *w, const pg_body *b);
int64_t pg__shape_turn_radius(const pg_body *b, const pg_shape *s);
/* The turn from a0 to a1 in binary-angle units, unwrapped: the whole turns are taken from
 * `radians` (Q32), the solver's sum of w h over the substeps. Beyond 8 turns either way,
 * a value past PG__MAX_TURN: such a body is not swept. */
int64_t pg__turn_of_step(pg_angle a0, pg_angle a1, int64_t radians);
/* Whether the body of sweep s turned too far for its speculative contacts in the step,
 * or would have at w0, its angular velocity at the step's start (a spin its contacts
 * stopped in the first substep: the contacts were made for the features facing at the
 * start, and a turning body's are the wrong ones). */
int pg__sweep_is_fast(const pg_world *w, const pg_sweep *s, pg_fix w0);
/* Put each swept body back at its earliest time of impact with a static shape whose
 * broadphase box its own overlapped in this step (w->pairs, still this step's after the
 * solve). sweep_of_body: scratch of body_high entries. */
void pg__sweep_fast_turns(pg_world *w, pg_sweep *sweeps, uint32_t n, uint32_t *sweep_of_body);

#endif
