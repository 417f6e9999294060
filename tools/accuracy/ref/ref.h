/* ref.h — a double-precision reference of pogon's step, for circles and boxes only.
 *
 * It exists to measure what pogon's fixed-point arithmetic and sine table cost: the same
 * algorithm in double, so a difference between the two runs of one scene is arithmetic,
 * not method. It lives in tools/ and is never part of the library.
 *
 * Same scheme as pogon (src/core/solver.c, src/core/contact_solver.c, src/core/collide.c, src/core/contact.c): bodies are one
 * circle or one box each (the body's shape index is its body index); broadphase boxes
 * grow by the 0.02 m speculative distance and, with continuous on, by the distance a
 * body travels in a step; manifolds of up to two points (SAT with reference-face
 * clipping and the same 0.0005 m reference hysteresis, circle-box, circle-circle) with
 * the same feature ids; contacts sorted by shape pair and warm started by feature id;
 * the soft step: per substep integrate velocities, warm start, solve with a soft bias
 * (hertz capped at a quarter of the substep rate, doubled against static bodies, damping
 * ratio, push-out cap), integrate positions, relax without bias; restitution once
 * after the substeps (threshold 1 m/s); Coulomb friction solved after the normal rows;
 * the points of a manifold in alternating order; anchors on each body's own surface (a
 * circle's does not turn with it). Impulses are stored, as in pogon, as
 * the velocity change they cause (m/s). No sleeping, no damping, no speed cap.
 */
#ifndef POGON_ACCURACY_REF_H
#define POGON_ACCURACY_REF_H

typedef struct ref_def {
    double gravity_x, gravity_y;  /* m/s^2 */
    int step_hz, substeps;
    double hertz, damping_ratio, push_max, restitution_threshold;
    int friction, restitution, rotation, continuous; /* effects: nonzero = on */
} ref_def;

typedef struct ref_world ref_world;

/* pogon's defaults: gravity (0, -10), 60 Hz, 4 substeps, 30 Hz, 10, 3 m/s, 1 m/s, all on. */
ref_def ref_default_def(void);

/* NULL when out of memory. */
ref_world *ref_create(const ref_def *def, int capacity);
void ref_destroy(ref_world *w);

/* Add a body of one shape; returns its index or -1 when full. Static when !dynamic.
 * angle in radians. */
int ref_add_box(ref_world *w, int dynamic, double x, double y, double angle, double half_width, double half_height,
                double density, double friction, double restitution);
int ref_add_circle(ref_world *w, int dynamic, double x, double y, double radius, double density, double friction,
                   double restitution);
void ref_set_velocity(ref_world *w, int body, double vx, double vy, double omega);

void ref_step(ref_world *w);

void ref_position(const ref_world *w, int body, double *x, double *y, double *angle);
void ref_velocity(const ref_world *w, int body, double *vx, double *vy, double *omega);
int ref_contact_count(const ref_world *w);

#endif
