/** @file
 * pogon/pogon.h — a deterministic 2D rigid-body world.
 *
 * WHAT IT IS
 *   Bodies made of convex shapes (circle, capsule, segment, box, convex polygon up to 8
 *   vertices; a concave polygon becomes its convex pieces, terrain a chain of one-sided
 *   segments: pg_make_concave, pg_make_chain) collide, stack, slide and bounce. Everything is integer arithmetic
 *   (Q16.16, see fixed.h), so a world stepped with the same inputs gives the same bits
 *   on every compiler and CPU.
 *
 * HOW TO USE IT
 *     pg_world_def wd = pg_default_world_def();          // gravity, 60 Hz, 4 substeps, ...
 *     wd.max_bodies = 256;                               // capacities are fixed at creation
 *     wd.max_shapes = 256;
 *     wd.max_contacts = 512;
 *     static uint64_t memory[1 << 17];                   // the caller owns all memory:
 *     pg_world *world;                                   // pg_world_memory_size(&wd) bytes
 *     if (pg_world_create(&wd, memory, sizeof memory, &world) != PG_OK) return 1;
 *
 *     pg_body_def bd = pg_default_body_def();            // a static ground
 *     pg_shape_def sd = pg_default_shape_def();
 *     pg_body_id ground, box;
 *     pg_make_wall(world, &bd, &sd, PG_FIX_C(40), PG_FIX_C(1), &ground);
 *     bd.type = PG_BODY_DYNAMIC;
 *     bd.position = pg_v2(0, PG_FIX_C(4));
 *     pg_make_box(world, &bd, &sd, PG_FIX_C(1), PG_FIX_C(1), &box);
 *     for (int i = 0; i < 60; ++i) pg_world_step(world);
 *     pg_vec2 p = pg_body_position(world, box);
 *
 * CONVENTIONS
 *   - Every function that can fail returns pg_result; PG_OK is 0. pg_result_message()
 *     explains a code and pg_world_last_error() gives the detail of the world's last
 *     failure ("PG_ERR_ENVELOPE: density 0.01 kg/m^2 is outside 0.1..100 for a dynamic
 *     body", ...). A failing call
 *     leaves the world unchanged.
 *   - Handles (pg_body_id, pg_shape_id) hold an index and a generation: a handle to a
 *     destroyed object is detected (PG_ERR_STALE_HANDLE), never dereferenced. The zero
 *     handle is never valid.
 *   - Objects are made from definition structs that start from a defaults function, so
 *     new fields never break callers.
 *   - Units: metres, kilograms, seconds, radians per second; angles of bodies are binary
 *     angles (pg_angle, a full turn = 2^32; pg_angle_from_radians converts).
 *   - No callbacks run during a step; events are read from arrays after it.
 *
 * WIDE FORMATS (quantities that do not fit Q16.16)
 *   mass      int64 Q32.32 kg          inertia   int64 Q28.36 kg m^2
 *   forces and torques accumulate in int64 Q48.16 within a step.
 *
 * THE ENVELOPE (checked at creation; docs/envelope.md says why each limit holds)
 *   thickness: every shape at least 0.01 m across in every direction, one rule for every
 *     way of making it: a radius of 0.005 .. 50 m, a box's sides, a polygon's narrowest
 *     width (pg_geometry_polygon and pg_geometry_box alike), a segment's length; polygon
 *     edges >= 0.005 m.
 *   reach: a shape's vertices within 50 m of the origin of a dynamic or kinematic body
 *     (their lever arms), within 1000 m of a static body's origin (no mass, no lever
 *     arm: a 2 000 m ground from -1000 to 1000 m is one shape).
 *   a rotating dynamic body's inertia 3.0e-8 .. 1.3e8 kg m^2 and radius of gyration
 *   >= 2^-8 m (its inverses' formats; a 0.01 m ball needs fixed rotation);
 *   density 0.1 .. 100 kg/m^2 (0 allowed on static bodies), friction 0 .. 10,
 *   restitution 0 .. 1, positions within +-1000 m, speeds up to max_linear_speed
 *   (default 400 m/s) and angular speeds up to 1000 rad/s: caps the step keeps (counted
 *   in pg_world_stats.speed_clamps and spin_clamps, flagged by pg_body_limits), so every
 *   velocity a getter returns is one its setter accepts.
 *   Everything outside is refused with PG_ERR_ENVELOPE and a message naming the limit.
 */
#ifndef POGON_POGON_H
#define POGON_POGON_H

#include "pogon/config.h"
#include "pogon/fixed.h"
#include "pogon/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- results ------------------------------------------------------------------ */
/** What a call did: PG_OK (0) or the reason it refused; pg_result_message() explains a
 * code and pg_world_last_error() the detail. A failing call changes nothing. */
typedef enum pg_result {
    PG_OK = 0,               /**< success */
    PG_ERR_NULL,             /**< a required pointer argument is NULL */
    PG_ERR_INVALID_ARGUMENT, /**< a value is not one the function accepts */
    PG_ERR_STALE_HANDLE,     /**< the handle names an object that no longer exists */
    PG_ERR_CAPACITY,         /**< a pool given at creation is full */
    PG_ERR_MEMORY,           /**< the memory block given is too small */
    PG_ERR_ENVELOPE,         /**< a value is outside the documented envelope */
    PG_ERR_DEGENERATE,       /**< geometry with no area or length, or collinear points */
    PG_ERR_NOT_CONVEX,       /**< polygon vertices not convex (pg_geometry_polygon accepts
                                either winding; a geometry filled in by hand must be
                                counter-clockwise) */
    PG_ERR_BODY_TYPE,        /**< the operation does not apply to this body type */
    PG_ERR_NOT_FOUND,        /**< a query found nothing (e.g. no free position) */
    PG_ERR_INCOMPATIBLE,     /**< a file is sound but this build cannot use it: another
                                numeric configuration (pg_numeric_config), numerics
                                version or format version; the message names both */
    PG_RESULT_COUNT          /**< the number of codes (not a result) */
} pg_result;

/** The code's name, e.g. "PG_ERR_CAPACITY" (static text). */
const char *pg_result_name(pg_result r);
/** A sentence saying what the code means and what to do about it (static text). */
const char *pg_result_message(pg_result r);

/* ---- build -------------------------------------------------------------------- */
/** The numeric configuration this library was built with: PG_NUMERIC_CONFIG (config.h),
 * the compile-time switches that change results, as replay files and snapshots record it. */
uint32_t pg_numeric_config(void);
/** A configuration in words, e.g. "a 12-bit sine table", into buffer (always
 * NUL-terminated, cut to capacity). Bits no field of this build knows are named as
 * "unknown switches 0x...". Returns the length of the whole text, so a return >=
 * capacity means it was cut. */
size_t pg_numeric_config_describe(uint32_t config, char *buffer, size_t capacity);

/* ---- handles ---------------------------------------------------------------------- */
/** A handle to a body: a slot and its generation, so a handle to a destroyed body is
 * detected (PG_ERR_STALE_HANDLE). The zero handle is never valid. */
typedef struct pg_body_id {
    uint32_t index;      /**< the slot */
    uint32_t generation; /**< the slot's generation when the body was made */
} pg_body_id;
/** A handle to a shape, as pg_body_id. */
typedef struct pg_shape_id {
    uint32_t index;      /**< the slot */
    uint32_t generation; /**< the slot's generation when the shape was made */
} pg_shape_id;
/** Nonzero when a and b name the same body. */
static inline int pg_body_id_equal(pg_body_id a, pg_body_id b) { return a.index == b.index && a.generation == b.generation; }

/** A world: opaque, it lives in the memory block given to pg_world_create(). */
typedef struct pg_world pg_world;

/* ---- effects: what a step simulates ------------------------------------------------ */
/** A step leaves out the work of an effect that is off (it does not multiply by zero). */
#define PG_EFFECT_GRAVITY     (1u << 0) /**< gravity acceleration */
#define PG_EFFECT_ROTATION    (1u << 1) /**< bodies turn; off: every body keeps its angle */
#define PG_EFFECT_FRICTION    (1u << 2) /**< Coulomb friction at contacts */
#define PG_EFFECT_RESTITUTION (1u << 3) /**< bounce */
#define PG_EFFECT_DAMPING     (1u << 4) /**< linear and angular damping */
#define PG_EFFECT_SLEEPING    (1u << 5) /**< resting islands fall asleep and cost nothing */
#define PG_EFFECT_CONTINUOUS  (1u << 6) /**< fast bodies sweep their path within the substeps:
                                           speculative contacts so they cannot tunnel; a
                                           body turning too far for those is put back at
                                           its time of impact with static shapes */
#define PG_EFFECTS_ALL        0x7Fu     /**< every effect: the default */

/* ---- world ---------------------------------------------------------------------------- */
/** pg_world_def.max_contact_events: keep one begin and one end event per contact slot. */
#define PG_EVENTS_AS_CONTACTS 0xFFFFFFFFu

/** A world's settings and capacities. Start from pg_default_world_def() and change the
 * fields you need: a def that did not come from it is refused. */
typedef struct pg_world_def {
    pg_vec2 gravity;            /**< m/s^2, default (0, -10) */
    uint32_t step_hz;           /**< steps per simulated second, default 60 (1..1000) */
    uint32_t substeps;          /**< solver substeps per step, default 4 (1..16) */
    uint32_t effects;           /**< PG_EFFECT_* bits, default PG_EFFECTS_ALL */
    pg_fix contact_hertz;       /**< contact stiffness, default 30 Hz; twice it against a side that cannot move
                                   and between masses 4:1 or more; both capped at a quarter of the substep rate */
    pg_fix contact_damping_ratio; /**< default 10 */
    pg_fix contact_push_max;    /**< fastest push-out of overlap, default 3 m/s; of it, only
                                   what holds a contact's load (plus 1/32 of this) becomes
                                   velocity, the rest moves bodies apart without momentum */
    pg_fix restitution_threshold; /**< approach speeds below this do not bounce, default 1 m/s */
    pg_fix max_linear_speed;    /**< cap, default 400 m/s, counted in stats.speed_clamps */
    pg_fix sleep_linear_tolerance;  /**< default 0.05 m/s */
    pg_fix sleep_angular_tolerance; /**< default 2 degrees/s (0.0349 rad/s). A body rests when
                                   its centre moves no faster than the linear tolerance and
                                   either it turns no faster than the angular one or no
                                   point of it moves faster than the linear one
                                   (|v| + extent |w|: a small ball rolling slowly rests).
                                   Either its velocity or its motion in the step (how far
                                   it moved) may show it: docs/world.md, Sleeping */
    pg_fix time_to_sleep;       /**< seconds at rest before an island sleeps, default 0.5;
                                   counted in steps, to the nearest (30 at 60 Hz) */
    uint32_t max_bodies;        /**< most bodies at once, default 1024 */
    uint32_t max_shapes;        /**< most shapes at once, default 2048 */
    uint32_t max_contacts;      /**< most contacts at once, default 4096 */
    uint32_t max_joints;        /**< most joints at once (pogon/joint.h), default 64 (0 .. 2^24) */
    uint32_t max_contact_events; /**< begin events, and apart end events, kept per step
                                   (pg_world_begin_events): default PG_EVENTS_AS_CONTACTS, as
                                   many as max_contacts, so none is ever dropped; 0 .. 2^24 to
                                   keep fewer, 0 for none (a program that does not read events
                                   saves their memory). Events past it are counted in
                                   stats.events_dropped; they never change the simulation */
    uint32_t pg__cookie;        /**< internal: set by pg_default_world_def(), which every def
                                   must start from; a def without it is refused */
} pg_world_def;

/** The default settings (see each field): every world def starts from here. */
pg_world_def pg_default_world_def(void);

/** Bytes of memory a world with these capacities needs (0 if the def is invalid). */
size_t pg_world_memory_size(const pg_world_def *def);

/** Why a def is invalid, e.g. "substeps must be 1..16"; NULL when it is valid. This is
 * the check pg_world_memory_size and pg_world_create make (they return 0 and
 * PG_ERR_INVALID_ARGUMENT, and have no world to keep the message in). */
const char *pg_world_def_problem(const pg_world_def *def);

/** Create a world inside `memory` (at least pg_world_memory_size bytes, aligned to 8).
 * The world lives in that block; it never allocates. There is no destroy: release
 * the block when done. */
pg_result pg_world_create(const pg_world_def *def, void *memory, size_t memory_size, pg_world **out);

/** Advance one fixed step of 1/step_hz seconds. */
pg_result pg_world_step(pg_world *world);

/** Detail of the last failing call on this world (empty when none). */
const char *pg_world_last_error(const pg_world *world);

/** Set the gravity (m/s^2, each component within +-1000). */
pg_result pg_world_set_gravity(pg_world *world, pg_vec2 gravity);
/** The gravity in force. */
pg_vec2 pg_world_gravity(const pg_world *world);
/** Turn effects on and off (PG_EFFECT_* bits). */
pg_result pg_world_set_effects(pg_world *world, uint32_t effects);
/** The PG_EFFECT_* bits in force. */
uint32_t pg_world_effects(const pg_world *world);
uint64_t pg_world_frame(const pg_world *world);   /**< steps taken */
pg_world_def pg_world_get_def(const pg_world *world); /**< settings in force */

/** Counts of a world's objects, and of what it clamped or dropped. */
typedef struct pg_world_stats {
    uint32_t body_count;             /**< bodies */
    uint32_t awake_body_count;       /**< bodies awake */
    uint32_t shape_count;            /**< shapes */
    uint32_t contact_count;          /**< contacts, touching or within the speculative distance */
    uint32_t touching_contact_count; /**< contacts whose shapes touch */
    uint32_t pair_count;             /**< pairs the broadphase found in the last step */
    uint32_t speed_clamps;     /**< linear velocities scaled down to max_linear_speed (by a
                                    step or an impulse), all time */
    uint32_t capacity_misses;  /**< contacts and candidate pairs dropped because max_contacts
                                    was reached, one per pair, all time (saturates) */
    uint32_t spin_clamps;      /**< angular velocities clamped to +-1000 rad/s, all time */
    uint32_t envelope_exits;   /**< times a step carried a body's origin out of +-1000 m, all
                                    time (beyond it precision falls and at +-32768 m positions
                                    stop: see pg_body_limits) */
    uint32_t saturations;      /**< values a step clamped to the range of its formats, all
                                    time (saturates): a body's velocity in the contact solver
                                    beyond +-8192 m/s or rad/s (once per body and step), a
                                    contact point's impulse held at the solver's bound of
                                    8192 m/s (once per point and step), an acceleration or
                                    angular acceleration from forces beyond +-32768 (once per
                                    body and step). Results stay defined; a nonzero count says
                                    the scene left what the formats hold (mass ratios far
                                    past 1:1000, forces far past the envelope) */
    uint32_t events_dropped;   /**< begin and end events not kept because max_contact_events
                                    was reached, all time (saturates) */
} pg_world_stats;
/** The world's counts now. */
pg_world_stats pg_world_get_stats(const pg_world *world);

/* ---- bodies ----------------------------------------------------------------------------- */
/** How a body moves. */
typedef enum pg_body_type {
    PG_BODY_STATIC = 0,    /**< never moves; infinite mass */
    PG_BODY_KINEMATIC = 1, /**< moves at its set velocity; pushes, is not pushed */
    PG_BODY_DYNAMIC = 2    /**< moved by gravity, forces and contacts */
} pg_body_type;

/** A body's initial state. Start from pg_default_body_def() and change the fields you
 * need: a def that did not come from it is refused. */
typedef struct pg_body_def {
    pg_body_type type;          /**< default static */
    pg_vec2 position;           /**< body origin, m */
    pg_angle angle;             /**< binary angle */
    pg_vec2 linear_velocity;    /**< m/s */
    pg_fix angular_velocity;    /**< rad/s */
    pg_fix linear_damping;      /**< 1/s, default 0 */
    pg_fix angular_damping;     /**< 1/s, default 0 */
    pg_fix gravity_scale;       /**< default 1 */
    int fixed_rotation;         /**< nonzero: never rotates */
    int allow_sleep;            /**< default 1 */
    int awake;                  /**< default 1 */
    uint32_t pg__cookie;        /**< internal: set by pg_default_body_def(), which every def
                                   must start from; a def without it is refused */
    uint64_t user_data;         /**< yours; saved in snapshots */
} pg_body_def;

/** The default body def (see each field): every body def starts from here. */
pg_body_def pg_default_body_def(void);
/** Create a body without shapes (add them with pg_shape_create()). */
pg_result pg_body_create(pg_world *world, const pg_body_def *def, pg_body_id *out);
/** Destroys the body, its shapes and its contacts (end events are reported). */
pg_result pg_body_destroy(pg_world *world, pg_body_id body);
/** Nonzero when the handle names a body of this world. */
int pg_body_is_valid(const pg_world *world, pg_body_id body);

/** Getters return zero values for an invalid handle. */
pg_body_type pg_body_type_of(const pg_world *world, pg_body_id body);
pg_vec2 pg_body_position(const pg_world *world, pg_body_id body);        /**< origin */
pg_vec2 pg_body_world_center(const pg_world *world, pg_body_id body);    /**< centre of mass */
pg_angle pg_body_angle(const pg_world *world, pg_body_id body);                  /**< binary angle */
pg_vec2 pg_body_linear_velocity(const pg_world *world, pg_body_id body);        /**< m/s, of the centre of mass */
pg_fix pg_body_angular_velocity(const pg_world *world, pg_body_id body);        /**< rad/s */
int64_t pg_body_mass(const pg_world *world, pg_body_id body);             /**< Q32.32 kg */
int64_t pg_body_inertia(const pg_world *world, pg_body_id body);          /**< Q28.36 kg m^2 */
int pg_body_is_awake(const pg_world *world, pg_body_id body);                   /**< nonzero: awake */
uint64_t pg_body_user_data(const pg_world *world, pg_body_id body);             /**< as set */
/** Up to `capacity` shape handles of the body; returns the body's shape count. */
uint32_t pg_body_shapes(const pg_world *world, pg_body_id body, pg_shape_id *out, uint32_t capacity);

/** Which limits of the envelope the body meets: PG_BODY_LIMIT_* bits (0 for an invalid
 * handle). The step keeps every velocity within what the setters accept, and says so
 * here; a position it cannot keep inside the envelope (a body pushed or flung past
 * +-1000 m) it reports, since pg_body_set_transform and scene files refuse it. */
uint32_t pg_body_limits(const pg_world *world, pg_body_id body);
/** pg_body_limits(): the last step or an impulse since scaled its linear velocity down to max_linear_speed */
#define PG_BODY_LIMIT_SPEED_CLAMPED (1u << 0)
/** pg_body_limits(): the last step or an impulse since clamped its angular velocity to +-1000 rad/s */
#define PG_BODY_LIMIT_SPIN_CLAMPED  (1u << 1)
/** pg_body_limits(): its origin is beyond +-1000 m now */
#define PG_BODY_LIMIT_OUTSIDE       (1u << 2)

/** Move the body's origin to `position` and turn it to `angle` (within the envelope). */
pg_result pg_body_set_transform(pg_world *world, pg_body_id body, pg_vec2 position, pg_angle angle);
/** Set the linear velocity (m/s); static bodies refuse. */
pg_result pg_body_set_linear_velocity(pg_world *world, pg_body_id body, pg_vec2 v);
/** Set the angular velocity (rad/s); static bodies refuse. */
pg_result pg_body_set_angular_velocity(pg_world *world, pg_body_id body, pg_fix w);
/** Change the body's type (to dynamic only when its shapes are within the envelope).
 *  Refused (PG_ERR_BODY_TYPE) when a joint of the body would break the rules it was made
 *  under: both its bodies static, a mouse joint's body not dynamic, an anchor beyond a
 *  moving body's 50 m. */
pg_result pg_body_set_type(pg_world *world, pg_body_id body, pg_body_type type);
/** Nonzero wakes the body's island; 0 puts a dynamic body to sleep (its velocities
 * become 0) when sleeping is on. Static bodies ignore it. */
pg_result pg_body_set_awake(pg_world *world, pg_body_id body, int awake);
/** Scale the gravity this body feels (-100..100; 0: none). */
pg_result pg_body_set_gravity_scale(pg_world *world, pg_body_id body, pg_fix scale);
/** Set linear and angular damping (1/s). */
pg_result pg_body_set_damping(pg_world *world, pg_body_id body, pg_fix linear, pg_fix angular);
/** Nonzero: the body never rotates. */
pg_result pg_body_set_fixed_rotation(pg_world *world, pg_body_id body, int fixed);
/** Store a value of yours with the body (saved in snapshots). */
pg_result pg_body_set_user_data(pg_world *world, pg_body_id body, uint64_t user_data);
/** @{ */
/** Material and filter of every shape of the body. */
pg_result pg_body_set_friction(pg_world *world, pg_body_id body, pg_fix friction);
pg_result pg_body_set_restitution(pg_world *world, pg_body_id body, pg_fix restitution);
pg_result pg_body_set_density(pg_world *world, pg_body_id body, pg_fix density);
pg_result pg_body_set_filter(pg_world *world, pg_body_id body, uint32_t category, uint32_t mask);
/** @} */

/** @{ */
/** Forces and torques act during the next step only. Force in N at the centre of mass or
 * at a world point; torque in N m; impulses in N s change velocity at once. They wake
 * the body. Dynamic bodies only. */
pg_result pg_body_apply_force(pg_world *world, pg_body_id body, pg_vec2 force);
pg_result pg_body_apply_force_at(pg_world *world, pg_body_id body, pg_vec2 force, pg_vec2 point);
pg_result pg_body_apply_torque(pg_world *world, pg_body_id body, pg_fix torque);
pg_result pg_body_apply_linear_impulse(pg_world *world, pg_body_id body, pg_vec2 impulse, pg_vec2 point);
pg_result pg_body_apply_angular_impulse(pg_world *world, pg_body_id body, pg_fix impulse);
/** @} */

/* ---- geometry and shapes --------------------------------------------------------------- */
#define PG_MAX_VERTICES 8 /**< most vertices of a polygon */

/** The kind of a convex primitive. */
typedef enum pg_shape_kind {
    PG_SHAPE_CIRCLE = 0,  /**< a point and a radius */
    PG_SHAPE_SEGMENT = 1, /**< two points */
    PG_SHAPE_CAPSULE = 2, /**< two points and a radius */
    PG_SHAPE_POLYGON = 3, /**< 3..8 vertices, convex */
    PG_SHAPE_CHAIN_SEGMENT = 4 /**< a one-sided segment of a chain: vertices[0..1] the
                                  segment, vertices[2..3] its neighbours ("ghost" vertices:
                                  the chain's point before vertices[0] and after vertices[1],
                                  or the segment's own end where the chain ends); count 2.
                                  It collides on its right-hand side only, and only with
                                  normals its neighbours allow (pg_make_chain) */
} pg_shape_kind;

/** A convex primitive in its own frame. Build one with the pg_geometry_* functions,
 * which validate it. A circle is vertices[0] + radius; a capsule or segment is
 * vertices[0..1] + radius (0 for a segment); a polygon is 3..8 vertices,
 * counter-clockwise and convex, radius 0. A geometry on its own may reach 1000 m from
 * its frame's origin (a static body's limit) and must be 0.01 m thick (THE ENVELOPE);
 * pg_shape_create and pg_make_* hold a dynamic or kinematic body's shapes to 50 m. */
typedef struct pg_geometry {
    pg_shape_kind kind;                /**< which primitive */
    int32_t count;                     /**< vertices in use */
    pg_vec2 vertices[PG_MAX_VERTICES]; /**< in the body's frame, m */
    pg_fix radius;                     /**< m; 0 for segments and polygons */
} pg_geometry;

/** A circle of `radius` around `center`. */
pg_result pg_geometry_circle(pg_vec2 center, pg_fix radius, pg_geometry *out);
/** The segment from a to b. */
pg_result pg_geometry_segment(pg_vec2 a, pg_vec2 b, pg_geometry *out);
/** The capsule round the segment from a to b, of `radius`. */
pg_result pg_geometry_capsule(pg_vec2 a, pg_vec2 b, pg_fix radius, pg_geometry *out);
/** A box of half extents (hw, hh) centred at `center`, turned by `angle`. */
pg_result pg_geometry_box(pg_fix half_width, pg_fix half_height, pg_vec2 center, pg_angle angle, pg_geometry *out);
/** Convex polygon; vertices in either winding (they are stored counter-clockwise). */
pg_result pg_geometry_polygon(const pg_vec2 *vertices, int32_t count, pg_geometry *out);
/** A chain segment from a to b (see PG_SHAPE_CHAIN_SEGMENT) whose chain comes from
 * `before` and goes on to `after`; pass a itself as `before` (b as `after`) where the
 * chain ends there. It collides on the right-hand side of a -> b. Static bodies only. */
pg_result pg_geometry_chain_segment(pg_vec2 before, pg_vec2 a, pg_vec2 b, pg_vec2 after, pg_geometry *out);

/** Most vertices of a concave polygon (pg_geometry_decompose, pg_make_concave): 64, so
 * that the decomposition's work space stays under 1 KiB of stack and its at most 62
 * pieces fit one body (64 shapes). */
#define PG_CONCAVE_MAX_VERTICES 64
/** Most convex pieces a polygon of PG_CONCAVE_MAX_VERTICES vertices gives (n - 2). */
#define PG_CONCAVE_MAX_PIECES (PG_CONCAVE_MAX_VERTICES - 2)

/** Split a simple polygon (3..PG_CONCAVE_MAX_VERTICES vertices, either winding, no two
 * equal points, no three consecutive points on a line, no two edges crossing or
 * touching) into convex pieces of at most PG_MAX_VERTICES vertices, each one that
 * pg_geometry_polygon accepts (counter-clockwise, at least 0.01 m thick), whose areas
 * add up exactly to the polygon's. Ear clipping in exact integer arithmetic (the
 * thickest ear first, counted counter-clockwise from vertex 0 on ties), then merging
 * neighbouring pieces while they stay convex (Hertel-Mehlhorn): the result is a pure
 * function of the input (docs/concave.md). Writes *piece_count pieces to `pieces` (`capacity` of them;
 * PG_CONCAVE_MAX_PIECES always suffice). Refuses with PG_ERR_INVALID_ARGUMENT (count,
 * edges that cross or touch), PG_ERR_DEGENERATE (repeated point, collinear vertex, edge
 * under 0.005 m), PG_ERR_ENVELOPE (a vertex beyond 1000 m, a part thinner than 0.01 m),
 * PG_ERR_CAPACITY (capacity too small); `message` (may be NULL) then names the vertex or
 * edge at fault. */
pg_result pg_geometry_decompose(const pg_vec2 *vertices, int32_t count, pg_geometry *pieces, int32_t capacity,
                                int32_t *piece_count, char *message, size_t message_capacity);

/** Equilateral triangle with circumradius r, centred at `center`, one vertex at `angle`
 * (PG_ANGLE_QUARTER: pointing up). */
pg_result pg_geometry_triangle(pg_vec2 center, pg_fix circumradius, pg_angle angle, pg_geometry *out);

/** A shape's material and collision filter. Start from pg_default_shape_def() and change
 * the fields you need: a def that did not come from it is refused. */
typedef struct pg_shape_def {
    pg_fix density;      /**< kg/m^2, default 1 */
    pg_fix friction;     /**< default 0.6; mixing: sqrt(fa * fb) */
    pg_fix restitution;  /**< default 0; mixing: max(ra, rb) */
    uint32_t category;   /**< default 1 */
    uint32_t mask;       /**< default all bits; two shapes collide when each one's category
                            meets the other's mask */
    uint32_t pg__cookie; /**< internal: set by pg_default_shape_def(), which every def must
                            start from; a def without it is refused */
} pg_shape_def;

/** The default shape def (see each field): every shape def starts from here. */
pg_shape_def pg_default_shape_def(void);
/** Add a shape (geometry in the body's frame) and update the body's mass. */
pg_result pg_shape_create(pg_world *world, pg_body_id body, const pg_shape_def *def, const pg_geometry *geometry, pg_shape_id *out);
/** Remove a shape and update its body's mass. */
pg_result pg_shape_destroy(pg_world *world, pg_shape_id shape);
/** The body a shape belongs to (the zero handle for an invalid shape handle). */
pg_body_id pg_shape_body(const pg_world *world, pg_shape_id shape);
/** The geometry in the body frame; PG_ERR_STALE_HANDLE for an invalid handle. */
pg_result pg_shape_geometry(const pg_world *world, pg_shape_id shape, pg_geometry *out);

/* ---- the six ready-made kinds (one call: a body and its shapes) -------------------------- */
/** A body with one circle of `radius` at its origin. */
pg_result pg_make_ball(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix radius, pg_body_id *out);
/** A rectangle of `length` between the two cap centres with a circle of `radius` at each end. */
pg_result pg_make_capsule(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix length, pg_fix radius, pg_body_id *out);
/** A box of `width` by `height` centred at the body's origin. */
pg_result pg_make_box(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix width, pg_fix height, pg_body_id *out);
/** Equilateral, circumradius r, pointing up at angle 0. */
pg_result pg_make_triangle(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix circumradius, pg_body_id *out);
/** Six-pointed star: two equilateral triangles of circumradius r; area r^2 sqrt(3). */
pg_result pg_make_star(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix circumradius, pg_body_id *out);
/** A static box (bd->type is ignored). */
pg_result pg_make_wall(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, pg_fix width, pg_fix height, pg_body_id *out);
/** A body of any type whose shapes are the convex pieces pg_geometry_decompose makes of
 * the simple polygon `vertices` (body frame, either winding); its mass, centre and
 * inertia are the polygon's. Refuses as pg_geometry_decompose does, naming the vertex or
 * edge at fault in pg_world_last_error. */
pg_result pg_make_concave(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, const pg_vec2 *vertices, int32_t count,
                          pg_body_id *out);

/** Most points of a chain: 65 open (64 segments, a body's most shapes), 64 as a loop. */
#define PG_CHAIN_MAX_POINTS 65
/** A static body (bd->type is ignored) of chain segments between consecutive points
 * (and from the last back to the first when `loop` is nonzero), for terrain: each
 * segment knows its neighbours, so a body sliding across a joint between two segments
 * gets no normal from the joint's end (no "ghost bump"). Segments collide on their
 * right-hand side: walk the points with free space on your right (terrain from right
 * to left, a loop clockwise to hold bodies inside, counter-clockwise to be solid).
 * Needs 2..65 points (3..64 for a loop), consecutive points at least 0.01 m apart,
 * within 1000 m of the body origin. */
pg_result pg_make_chain(pg_world *w, const pg_body_def *bd, const pg_shape_def *sd, const pg_vec2 *points, int32_t count, int loop,
                        pg_body_id *out);

/* ---- queries ------------------------------------------------------------------------------ */
/** @{ */
/** Each writes up to `capacity` distinct bodies in ascending index order and stores in
 * *count how many there are in all (so *count > capacity means the list was cut). */
pg_result pg_world_query_point(const pg_world *world, pg_vec2 point, pg_body_id *out, uint32_t capacity, uint32_t *count);
pg_result pg_world_query_aabb(const pg_world *world, pg_aabb box, pg_body_id *out, uint32_t capacity, uint32_t *count);
/** @} */
/** Bodies whose shapes overlap `geometry` placed at (position, angle). */
pg_result pg_world_query_geometry(const pg_world *world, const pg_geometry *geometry, pg_vec2 position, pg_angle angle,
                                  pg_body_id *out, uint32_t capacity, uint32_t *count);
/** The free position nearest to `position` (within max_distance) where `geometry` at
 * `angle` overlaps nothing: searched on rings of growing radius, step `resolution`.
 * PG_ERR_NOT_FOUND when there is none. The caller decides whether to refuse or move. */
pg_result pg_world_find_free_position(const pg_world *world, const pg_geometry *geometry, pg_vec2 position, pg_angle angle,
                                      pg_fix max_distance, pg_fix resolution, pg_vec2 *out);

/** Where a ray hit a shape. */
typedef struct pg_ray_hit {
    pg_body_id body;    /**< the body hit */
    pg_shape_id shape;  /**< the shape hit */
    pg_vec2 point;      /**< the point hit, world frame */
    pg_vec2 normal;     /**< unit, Q16.16 */
    pg_fix fraction;    /**< along the translation, 0..1 */
} pg_ray_hit;
/** Closest hit along origin .. origin + translation; PG_ERR_NOT_FOUND when none. */
pg_result pg_world_raycast(const pg_world *world, pg_vec2 origin, pg_vec2 translation, pg_ray_hit *hit);

/* ---- events (valid until the next step) -------------------------------------------------- */
/** Two shapes that began or ended touching. */
typedef struct pg_contact_event {
    pg_shape_id shape_a; /**< one shape of the pair */
    pg_shape_id shape_b; /**< the other shape */
    pg_body_id body_a;   /**< shape_a's body */
    pg_body_id body_b;   /**< shape_b's body */
} pg_contact_event;
/** @{ */
/** Pairs that started or stopped touching during the last step (or by a body's
 * destruction since it). */
const pg_contact_event *pg_world_begin_events(const pg_world *world, uint32_t *count);
const pg_contact_event *pg_world_end_events(const pg_world *world, uint32_t *count);
/** @} */

#ifdef __cplusplus
}
#endif

#include "pogon/joint.h"
#endif
