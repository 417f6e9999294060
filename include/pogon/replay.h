/** @file
 * pogon/replay.h — determinism you can prove: commands, state hashes, snapshots,
 * scene files and replay files.
 *
 * COMMANDS
 *   Every change made to a world from outside a step has a command form (pg_command).
 *   A front end that drives its world only through commands can log them, and the log
 *   reproduces the run bit for bit. pg_command_apply() applies one now; a
 *   pg_command_queue (caller memory) holds commands for later frames and applies the due
 *   ones before a step.
 *
 * STATE HASH
 *   pg_world_hash() is a 64-bit hash of everything that influences future steps,
 *   computed over the canonical little-endian encoding that snapshots use, so it is the
 *   same on every platform. pg_world_section_hashes() splits it by section, and
 *   pg_world_diff_snapshots() names the first body or contact where two states differ.
 *
 * SNAPSHOTS
 *   pg_world_snapshot_save() writes the whole world state into a caller buffer in a
 *   compact canonical encoding (not a memory dump); pg_world_snapshot_restore() puts it
 *   back into a world created with the same capacities. Stepping after a restore is
 *   bit-identical to never having saved. Handles that existed at the snapshot are valid
 *   after a restore; handles made after it are stale.
 *
 * SCENE FILES (text) and REPLAY FILES (binary) are specified in docs/formats.md.
 */
#ifndef POGON_REPLAY_H
#define POGON_REPLAY_H

#include "pogon/joint.h"
#include "pogon/pogon.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- commands ------------------------------------------------------------------------- */
/** What a command does; each value lists the pg_command fields it reads. */
typedef enum pg_command_kind {
    PG_CMD_NONE = 0,               /**< nothing */
    PG_CMD_CREATE_BODY = 1,        /**< body_def -> a new body (its id in the result) */
    PG_CMD_DESTROY_BODY = 2,       /**< body */
    PG_CMD_ADD_SHAPE = 3,          /**< body, shape_def, geometry */
    PG_CMD_MAKE = 4,               /**< make_kind, body_def, shape_def, size0, size1 */
    PG_CMD_SET_TRANSFORM = 5,      /**< body, vec (position), angle */
    PG_CMD_SET_LINEAR_VELOCITY = 6,/**< body, vec */
    PG_CMD_SET_ANGULAR_VELOCITY = 7,/**< body, scalar */
    PG_CMD_APPLY_FORCE = 8,        /**< body, vec (force), point: at the centre of mass when flag is 0 */
    PG_CMD_APPLY_TORQUE = 9,       /**< body, scalar */
    PG_CMD_APPLY_LINEAR_IMPULSE = 10, /**< body, vec (impulse), point */
    PG_CMD_APPLY_ANGULAR_IMPULSE = 11,/**< body, scalar */
    PG_CMD_SET_BODY_TYPE = 12,     /**< body, value (pg_body_type) */
    PG_CMD_SET_AWAKE = 13,         /**< body, value (0 or 1) */
    PG_CMD_SET_GRAVITY = 14,       /**< vec */
    PG_CMD_SET_EFFECTS = 15,       /**< value (PG_EFFECT_* bits) */
    PG_CMD_SET_GRAVITY_SCALE = 16, /**< body, scalar */
    PG_CMD_SET_DAMPING = 17,       /**< body, scalar (linear), scalar2 (angular) */
    PG_CMD_SET_FRICTION = 18,      /**< body, scalar */
    PG_CMD_SET_RESTITUTION = 19,   /**< body, scalar */
    PG_CMD_SET_DENSITY = 20,       /**< body, scalar */
    PG_CMD_SET_FIXED_ROTATION = 21,/**< body, value */
    PG_CMD_SET_FILTER = 22,        /**< body, value (category), value2 (mask) */
    PG_CMD_SET_USER_DATA = 23,     /**< body, user_data */
    PG_CMD_CREATE_DISTANCE_JOINT = 24, /**< joint_def.distance -> a new joint (pg_command_apply_made) */
    PG_CMD_CREATE_REVOLUTE_JOINT = 25, /**< joint_def.revolute */
    PG_CMD_CREATE_WELD_JOINT = 26,     /**< joint_def.weld */
    PG_CMD_CREATE_PRISMATIC_JOINT = 27,/**< joint_def.prismatic */
    PG_CMD_CREATE_MOUSE_JOINT = 28,    /**< joint_def.mouse: what a drag starts with */
    PG_CMD_DESTROY_JOINT = 29,     /**< joint */
    PG_CMD_SET_JOINT_MOTOR = 30,   /**< joint (revolute or prismatic), flag (enable), scalar (speed), scalar2 (max torque or force) */
    PG_CMD_SET_JOINT_LIMITS = 31,  /**< joint (distance, revolute or prismatic), flag (enable), scalar (lower), scalar2 (upper) */
    PG_CMD_SET_MOUSE_TARGET = 32,  /**< joint (mouse), vec (the target): what a drag moves */
    PG_CMD_SET_MOUSE_MAX_FORCE = 33,/**< joint (mouse), scalar (N) */
    PG_CMD_KIND_COUNT              /**< the number of kinds (not a kind) */
} pg_command_kind;

/** Which ready-made kind a PG_CMD_MAKE command makes (the pg_make_* functions). */
typedef enum pg_make_kind {
    PG_MAKE_BALL = 0,     /**< size0 = radius */
    PG_MAKE_CAPSULE = 1,  /**< size0 = length, size1 = radius */
    PG_MAKE_BOX = 2,      /**< size0 = width, size1 = height */
    PG_MAKE_TRIANGLE = 3, /**< size0 = circumradius */
    PG_MAKE_STAR = 4,     /**< size0 = circumradius */
    PG_MAKE_WALL = 5,     /**< size0 = width, size1 = height */
    PG_MAKE_KIND_COUNT    /**< the number of kinds (not a kind) */
} pg_make_kind;

/** The def a CREATE_*_JOINT command carries: the member its kind names. */
typedef union pg_command_joint_def {
    pg_distance_joint_def distance;   /**< CREATE_DISTANCE_JOINT */
    pg_revolute_joint_def revolute;   /**< CREATE_REVOLUTE_JOINT */
    pg_weld_joint_def weld;           /**< CREATE_WELD_JOINT */
    pg_prismatic_joint_def prismatic; /**< CREATE_PRISMATIC_JOINT */
    pg_mouse_joint_def mouse;         /**< CREATE_MOUSE_JOINT */
} pg_command_joint_def;

/** One command. Only the fields its kind names are read; the rest must be as
 * pg_command_init leaves them, so a command has one byte image (set a joint def's
 * fields one by one: assigning a whole def may copy padding bytes). */
typedef struct pg_command {
    pg_command_kind kind;   /**< what the command does */
    pg_body_id body;        /**< the body it acts on */
    pg_vec2 vec;            /**< a position, velocity, force, impulse or gravity */
    pg_vec2 point;          /**< where a force or impulse acts, world frame */
    pg_fix scalar;          /**< an angular velocity, torque, damping or material value */
    pg_fix scalar2;         /**< SET_DAMPING: the angular damping */
    pg_angle angle;         /**< SET_TRANSFORM: the angle */
    uint32_t value;         /**< a body type, awake flag, effects bits or filter category */
    uint32_t value2;        /**< SET_FILTER: the mask */
    uint32_t flag;          /**< APPLY_FORCE: 1 = at `point`; SET_JOINT_MOTOR, SET_JOINT_LIMITS: enable */
    uint64_t user_data;     /**< SET_USER_DATA: the value */
    pg_make_kind make_kind; /**< MAKE: which kind */
    pg_fix size0;           /**< MAKE: the first size (see pg_make_kind) */
    pg_fix size1;           /**< MAKE: the second size */
    pg_body_def body_def;   /**< CREATE_BODY, MAKE: the body */
    pg_shape_def shape_def; /**< ADD_SHAPE, MAKE: the material and filter */
    pg_geometry geometry;   /**< ADD_SHAPE: the geometry */
    pg_joint_id joint;      /**< the joint a joint command acts on */
    pg_command_joint_def joint_def; /**< CREATE_*_JOINT: the def */
} pg_command;

/** A command of the given kind: zeroed, but for body_def and shape_def, which hold
 * pg_default_body_def() and pg_default_shape_def(), and a CREATE_*_JOINT command's
 * joint_def member, which holds its kind's defaults. */
pg_command pg_command_init(pg_command_kind kind);
/** Stable lower-case names ("set_linear_velocity") for files and messages. */
const char *pg_command_kind_name(pg_command_kind kind);
/** Apply one command now. `created` (may be NULL) receives the new body of CREATE_BODY
 * and MAKE. Returns the result of the call the command stands for. */
pg_result pg_command_apply(pg_world *world, const pg_command *command, pg_body_id *created);
/** pg_command_apply, and `created_joint` (may be NULL) receives the new joint of a
 * CREATE_*_JOINT command (the zero handle otherwise). */
pg_result pg_command_apply_made(pg_world *world, const pg_command *command, pg_body_id *created, pg_joint_id *created_joint);

/** Binary form of a command, little-endian fixed-width fields (docs/formats.md):
 * u8 kind, then the fields that kind uses in the order of docs/formats.md (the order of the
 * struct, except that APPLY_FORCE's flag comes before its point). Encoding is
 * canonical: decode(encode(c)) == c for every valid command. */
#define PG_COMMAND_ENCODED_MAX 256 /**< the most bytes one encoded command takes */
/** Bytes written (0 if the command is invalid or `capacity` is short). */
size_t pg_command_encode(const pg_command *command, uint8_t *buffer, size_t capacity);
/** Decode one command from `size` bytes. On success *consumed is its length. On failure
 * returns PG_ERR_INVALID_ARGUMENT and sets *error_offset (from `buffer`) and
 * *error_field (a static string naming the field) when those pointers are not NULL. */
pg_result pg_command_decode(const uint8_t *buffer, size_t size, pg_command *command, size_t *consumed,
                            size_t *error_offset, const char **error_field);

/** A queue of commands for later frames, in caller memory. Commands for the same
 * frame keep the order they were pushed in. */
typedef struct pg_command_queue {
    pg_command *commands; /**< the caller's array of `capacity` commands */
    uint64_t *frames;     /**< the caller's array of `capacity` frames, one per command */
    uint32_t capacity;    /**< the arrays' length */
    uint32_t count;       /**< commands queued */
} pg_command_queue;
/** An empty queue over the caller's two arrays of `capacity` entries. */
void pg_command_queue_init(pg_command_queue *q, pg_command *commands, uint64_t *frames, uint32_t capacity);
/** PG_ERR_CAPACITY when full; PG_ERR_INVALID_ARGUMENT for a frame already past. */
pg_result pg_command_queue_push(pg_command_queue *q, const pg_world *world, uint64_t frame, const pg_command *command);
/** Apply (in order) and remove the commands due at the world's current frame. Returns
 * the number applied; a failing command is applied as its call would be (no change)
 * and counted in *failures (may be NULL). */
uint32_t pg_command_queue_apply_due(pg_command_queue *q, pg_world *world, uint32_t *failures);

/* ---- hashes ---------------------------------------------------------------------------- */
/** The sections of a world's state, hashed separately to say where two states differ. */
typedef enum pg_section {
    PG_SECTION_SETTINGS = 0,  /**< world def in force and the frame counter (statistics are not state) */
    PG_SECTION_BODIES = 1,    /**< body pool: slots, generations, motion, sleep timers, islands */
    PG_SECTION_SHAPES = 2,    /**< shape pool: slots, generations, geometry, material, filter */
    PG_SECTION_CONTACTS = 3,  /**< contact list in order: manifolds, warm-start impulses */
    PG_SECTION_BROADPHASE = 4,/**< the broadphase's inputs kept between steps (proxy boxes) */
    PG_SECTION_JOINTS = 5,    /**< the joint pool: each joint's kind, bodies, definition and solver state; empty (no bytes) while the pool was never used */
    PG_SECTION_COUNT          /**< the number of sections (not a section) */
} pg_section;

/** The section's lower-case name ("bodies"), for files and messages. */
const char *pg_section_name(pg_section s);
/** 64-bit hash of the canonical encoding of the whole state (all sections). */
uint64_t pg_world_hash(const pg_world *world);
/** The hash of each section, in out[section]. A NULL out writes nothing. */
void pg_world_section_hashes(const pg_world *world, uint64_t out[PG_SECTION_COUNT]);

/** The hash function itself (FNV-1a 64 over bytes), for files and tools. A NULL data
 * hashes no bytes, whatever `size` says: the result is `seed`. */
uint64_t pg_hash_bytes(uint64_t seed, const void *data, size_t size);
#define PG_HASH_SEED UINT64_C(0xcbf29ce484222325) /**< FNV-1a 64's offset basis, the usual seed */

/* ---- snapshots ------------------------------------------------------------------------- */
/** Bytes a snapshot of this world needs now (it grows with bodies, shapes, contacts). */
size_t pg_world_snapshot_size(const pg_world *world);
/** Write the snapshot; *written receives its size. PG_ERR_MEMORY if `capacity` is short;
 * PG_ERR_NULL for a NULL world or buffer (with a message in pg_world_last_error() when
 * the world is given). */
pg_result pg_world_snapshot_save(const pg_world *world, void *buffer, size_t capacity, size_t *written);
/** Restore into `world` (created with the same capacities as the saved world).
 * The snapshot is validated first: a corrupt one changes nothing and returns
 * PG_ERR_INVALID_ARGUMENT with the offset and field in pg_world_last_error(). A snapshot
 * carries a hash per section and a checksum over all its bytes, checked before anything
 * else: any one damaged byte is refused, with the offset of the section it lies in. A
 * sound snapshot this build cannot continue returns PG_ERR_INCOMPATIBLE, naming both
 * sides: another format version, another numeric configuration (pg_numeric_config) or
 * another major.minor engine version (docs/snapshots.md). Behind the
 * checksum, corrupt also means anything no world can hold: broken links between bodies, shapes and contacts,
 * shapes or mass data pg_shape_create would refuse, and values beyond what the setters
 * and the step ever write (velocities beyond 8192 m/s or rad/s per component, forces and
 * torques beyond the accumulators' 2^60, damping, gravity scale or sleep timers outside
 * their ranges, contact materials outside the shapes', normals that are not unit
 * vectors, overlaps deeper than 1024 m, impulses beyond the solver's 2^29). Positions
 * are not limited: a body may have flown out of the envelope. PG_ERR_NULL for a NULL
 * world or snapshot. */
pg_result pg_world_snapshot_restore(pg_world *world, const void *snapshot, size_t size);

/** Where two states first differ. */
typedef struct pg_divergence {
    pg_section section; /**< the first section that differs */
    int64_t index;      /**< the first body, shape or contact that differs in it, or -1 */
} pg_divergence;
/** Compare two snapshots: returns 0 when they are identical, otherwise nonzero with
 * where they first differ in *out. */
int pg_world_diff_snapshots(const void *a, size_t a_size, const void *b, size_t b_size, pg_divergence *out);

#ifdef __cplusplus
}
#endif
#endif
