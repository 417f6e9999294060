/* pogon-replay — verify, inspect, record, re-hash and sync-test replay files.
 *
 * Usage:
 *   pogon-replay verify FILE...
 *       Replays each file and compares every checkpoint. Prints the final hash of each.
 *   pogon-replay info FILE
 *       Header (engine version, numeric configuration), scene summary, frame count,
 *       command counts per kind. A file this build cannot play (another numeric
 *       configuration) shows its header and the reason, exit 2.
 *   pogon-replay record --scene SCENE --frames N [--script SCRIPT] [--checkpoint K] -o FILE
 *       Makes a replay from a scene file and a script of timed commands (format below).
 *       K (default 60) is the checkpoint interval in frames.
 *   pogon-replay rehash FILE...
 *       Replays each file and rewrites its checkpoints, final hash, checksums and engine
 *       version in place (after an intended change of the numerics).
 *   pogon-replay upgrade IN OUT
 *       Converts a file of an older format version into this build's (pg_replay_upgrade),
 *       stamped with this build's numeric configuration, and writes OUT only when the
 *       result replays here checkpoint for checkpoint (IN and OUT may be the same file).
 *   pogon-replay synctest FILE... --rollback K
 *       Steps each replay saving a snapshot every frame; from frame K on, restores the
 *       snapshot of K frames ago, re-steps those K frames and compares the whole and the
 *       per-section hashes with the first pass.
 *
 * Exit status: 0 all good; 1 a replay diverged (verify, synctest); 2 a file is corrupt,
 * truncated, of another format version (an older one: upgrade) or of another numeric
 * configuration (recorded with another sine table: it cannot replay here, so it is
 * refused, never reported as a divergence) or fails its checksums, or the command line
 * or a script is wrong. Messages name the file offset and the field.
 *
 * SCRIPT FORMAT (one command per line; '#' starts a comment; blank lines are ignored)
 *     FRAME COMMAND ARGS...
 *   FRAME is the frame whose step the command precedes (0 = before the first step;
 *   must be < --frames). Lines of the same frame keep their order. Numbers are decimal
 *   (pg_fix_parse: "-1.25", ".5"); angles are in degrees; integers (VALUE, category,
 *   mask, user data) are decimal or 0x hex. BODY is one of
 *     #I      the live body in slot I (scene bodies fill slots 0, 1, ... in scene order)
 *     I:G     the handle with index I and generation G, as is (may be stale on purpose)
 *     last    the body made by the latest create_body / make of the script
 *     $K      the K-th body (0-based) made by create_body / make in the script
 *   Commands and arguments:
 *     create_body [OPTIONS]                  make KIND SIZE0 [SIZE1] [OPTIONS]
 *     destroy_body BODY                      add_shape BODY GEOMETRY [OPTIONS]
 *     set_transform BODY X Y ANGLE           set_linear_velocity BODY VX VY
 *     set_angular_velocity BODY W            apply_force BODY FX FY [PX PY]
 *     apply_torque BODY T                    apply_linear_impulse BODY IX IY PX PY
 *     apply_angular_impulse BODY I           set_body_type BODY static|kinematic|dynamic
 *     set_awake BODY 0|1                     set_gravity GX GY
 *     set_effects EFFECTS                    set_gravity_scale BODY S
 *     set_damping BODY LINEAR ANGULAR        set_friction BODY F
 *     set_restitution BODY R                 set_density BODY D
 *     set_fixed_rotation BODY 0|1            set_filter BODY CATEGORY MASK
 *     set_user_data BODY U64
 *     create_distance_joint BODY_A BODY_B [J]  create_revolute_joint BODY_A BODY_B [J]
 *     create_weld_joint BODY_A BODY_B [J]      create_prismatic_joint BODY_A BODY_B [J]
 *     create_mouse_joint BODY [J]              destroy_joint JOINT
 *     set_joint_motor JOINT 0|1 SPEED MAX      set_joint_limits JOINT 0|1 LOWER UPPER
 *     set_mouse_target JOINT X Y               set_mouse_max_force JOINT F
 *   JOINT is jI:G (the handle with index I and generation G), jlast (the joint made by
 *   the latest create_*_joint of the script) or j$K (the K-th joint it made, from 0).
 *   J (key=value, the def's fields; the rest keep the def's defaults): ax ay bx by
 *   (local anchors), length, spring, hertz, damping (distance: spring; mouse), limit,
 *   lower, upper (distance: min/max length; revolute: angles in rad; prismatic:
 *   translations), motor, speed, max_motor (torque or force), reference_angle
 *   (degrees), axis_x axis_y, linear_hertz linear_damping angular_hertz angular_damping
 *   (weld), tx ty (mouse target), max_force (mouse), collide, user_data.
 *   KIND: ball (SIZE0 radius), capsule (length radius), box (width height), triangle
 *   (circumradius), star (circumradius), wall (width height).
 *   GEOMETRY: circle CX CY R | segment AX AY BX BY | capsule AX AY BX BY R |
 *             box HW HH [CX CY ANGLE] | triangle CX CY R [ANGLE] | polygon X1 Y1 X2 Y2 X3 Y3 ... |
 *             chain_segment BX BY X1 Y1 X2 Y2 AX AY (the point before, the segment, the point after)
 *   OPTIONS (key=value): body: type=static|kinematic|dynamic (default dynamic), x, y,
 *   angle, vx, vy, w, linear_damping, angular_damping, gravity_scale, fixed_rotation,
 *   allow_sleep, awake, user_data; shape: density, friction, restitution, category, mask.
 *   EFFECTS: a number, or names joined by '+' or '|': gravity rotation friction
 *   restitution damping sleeping continuous all none.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/replay.h"
#include "pogon/replay_file.h"
#include "pogon/scene_file.h"

#define EXIT_DIVERGED 1
#define EXIT_BAD 2

/* ---- small helpers -------------------------------------------------------------------- */
static void *xmalloc(size_t n)
{
    void *p = malloc(n != 0 ? n : 1);
    if (p == NULL) {
        fprintf(stderr, "pogon-replay: out of memory (%zu bytes)\n", n);
        exit(EXIT_BAD);
    }
    return p;
}

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n != 0 ? n : 1);
    if (q == NULL) {
        fprintf(stderr, "pogon-replay: out of memory (%zu bytes)\n", n);
        exit(EXIT_BAD);
    }
    return q;
}

/* Read a whole file; NULL (message printed) on failure. */
static uint8_t *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t cap = 0, len = 0;
    if (f == NULL) {
        fprintf(stderr, "%s: cannot open: %s\n", path, strerror(errno));
        return NULL;
    }
    for (;;) {
        size_t n;
        if (len == cap) {
            cap = cap != 0 ? cap * 2 : 65536;
            buf = (uint8_t *)xrealloc(buf, cap);
        }
        n = fread(buf + len, 1, cap - len, f);
        len += n;
        if (n == 0) break;
    }
    if (ferror(f)) {
        fprintf(stderr, "%s: read error\n", path);
        fclose(f);
        free(buf);
        return NULL;
    }
    fclose(f);
    *size = len;
    return buf;
}

/* Write atomically: PATH.tmp then rename. */
static int write_file(const char *path, const uint8_t *data, size_t size)
{
    size_t n = strlen(path) + 5;
    char *tmp = (char *)xmalloc(n);
    FILE *f;
    int ok;
    snprintf(tmp, n, "%s.tmp", path);
    f = fopen(tmp, "wb");
    if (f == NULL) {
        fprintf(stderr, "%s: cannot write: %s\n", tmp, strerror(errno));
        free(tmp);
        return 0;
    }
    ok = fwrite(data, 1, size, f) == size;
    ok = (fclose(f) == 0) && ok;
    if (ok && rename(tmp, path) != 0) ok = 0;
    if (!ok) {
        fprintf(stderr, "%s: write failed: %s\n", path, strerror(errno));
        remove(tmp);
    }
    free(tmp);
    return ok;
}

static void print_replay_error(const char *path, const pg_replay_error *e)
{
    fprintf(stderr, "%s: error at offset %zu (0x%zx), %s.%s", path, e->offset, e->offset, e->region, e->field);
    if (e->frame >= 0) fprintf(stderr, ", frame %lld", (long long)e->frame);
    if (e->command >= 0) fprintf(stderr, ", command %lld", (long long)e->command);
    fprintf(stderr, ": %s\n", e->message);
}

static const char *fix_str(pg_fix v, char buf[PG_FIX_FORMAT_MAX])
{
    pg_fix_format(v, buf, PG_FIX_FORMAT_MAX);
    return buf;
}

static const char *const effect_names[] = {"gravity", "rotation", "friction", "restitution",
                                           "damping", "sleeping", "continuous"};

static void print_effects(FILE *out, uint32_t effects)
{
    unsigned i;
    int any = 0;
    if (effects == PG_EFFECTS_ALL) {
        fprintf(out, "all");
        return;
    }
    for (i = 0; i < 7; ++i) {
        if (effects & (1u << i)) {
            fprintf(out, "%s%s", any ? "+" : "", effect_names[i]);
            any = 1;
        }
    }
    if (!any) fprintf(out, "none");
}

static void print_sections(FILE *out, uint32_t mask)
{
    unsigned s;
    int any = 0;
    for (s = 0; s < PG_SECTION_COUNT; ++s) {
        if (mask & (1u << s)) {
            fprintf(out, "%s%s", any ? ", " : "", pg_section_name((pg_section)s));
            any = 1;
        }
    }
    if (!any) fprintf(out, "none differs (only the state hash, which the file checked against its section hashes)");
}

/* ---- a loaded replay ---------------------------------------------------------------- */
typedef struct replay {
    const char *path;
    uint8_t *data;
    size_t size;
    pg_replay_info info;
    void *memory;
    size_t memory_size;
    pg_replay_player player;
} replay;

static void replay_free(replay *r)
{
    free(r->data);
    free(r->memory);
    r->data = NULL;
    r->memory = NULL;
}

/* Validate the file in `data` (size bytes, malloc'ed: the replay owns it from here) and
 * load its scene into the player; `path` names it in messages. Returns 0 or EXIT_BAD (a
 * file of another format version or numeric configuration is one too). */
static int replay_load(replay *r, const char *path, uint8_t *data, size_t size, pg_replay_frame_result *first)
{
    pg_replay_error e;
    pg_result res;
    memset(r, 0, sizeof *r);
    r->path = path;
    r->data = data;
    r->size = size;
    res = pg_replay_read(r->data, r->size, &r->info, &e);
    if (res != PG_OK) {
        print_replay_error(path, &e);
        replay_free(r);
        return EXIT_BAD;
    }
    res = pg_replay_world_memory_size(&r->info, &r->memory_size, &e);
    if (res != PG_OK) {
        print_replay_error(path, &e);
        replay_free(r);
        return EXIT_BAD;
    }
    r->memory = xmalloc(r->memory_size);
    res = pg_replay_player_begin(&r->player, r->data, &r->info, r->memory, r->memory_size, first, &e);
    if (res != PG_OK) {
        print_replay_error(path, &e);
        replay_free(r);
        return EXIT_BAD;
    }
    return 0;
}

/* Read, validate and load (replay_load). */
static int replay_open(replay *r, const char *path, pg_replay_frame_result *first)
{
    size_t size = 0;
    uint8_t *data = read_file(path, &size);
    if (data == NULL) {
        memset(r, 0, sizeof *r);
        return EXIT_BAD;
    }
    return replay_load(r, path, data, size, first);
}

static void warn_engine_version(const replay *r)
{
    const pg_replay_info *in = &r->info;
    if (in->engine_major != POGON_VERSION_MAJOR || in->engine_minor != POGON_VERSION_MINOR ||
        in->engine_patch != POGON_VERSION_PATCH)
        fprintf(stderr, "%s: note: recorded with pogon %u.%u.%u, this is %d.%d.%d\n", r->path, in->engine_major,
                in->engine_minor, in->engine_patch, POGON_VERSION_MAJOR, POGON_VERSION_MINOR, POGON_VERSION_PATCH);
}

/* ---- snapshots ------------------------------------------------------------------------ */
typedef struct snap { uint8_t *data; size_t size, cap; } snap;

static void snap_save(snap *s, const pg_world *world)
{
    size_t need = pg_world_snapshot_size(world);
    if (need > s->cap) {
        s->cap = need + need / 2 + 64;
        s->data = (uint8_t *)xrealloc(s->data, s->cap);
    }
    if (pg_world_snapshot_save(world, s->data, s->cap, &s->size) != PG_OK) {
        fprintf(stderr, "pogon-replay: pg_world_snapshot_save failed\n");
        exit(EXIT_BAD);
    }
}

static int snap_restore(pg_world *world, const snap *s)
{
    pg_result r = pg_world_snapshot_restore(world, s->data, s->size);
    if (r != PG_OK) {
        fprintf(stderr, "pogon-replay: snapshot restore failed: %s (%s)\n", pg_result_name(r), pg_world_last_error(world));
        return 0;
    }
    return 1;
}

static void print_divergence(FILE *out, const snap *a, const snap *b)
{
    pg_divergence d;
    if (pg_world_diff_snapshots(a->data, a->size, b->data, b->size, &d)) {
        fprintf(out, "first difference in section %s", pg_section_name(d.section));
        if (d.index >= 0) fprintf(out, ", item %lld", (long long)d.index);
    } else {
        fprintf(out, "snapshots identical");
    }
}

/* ---- verify ------------------------------------------------------------------------- */
/* After a checkpoint mismatch: re-step the frames since the last matching checkpoint from
 * its snapshot and compare with the first pass, to tell "this build is not
 * deterministic" from "the recording was made with other numerics". */
static void diagnose(replay *r, const snap *good, uint32_t good_frame, const size_t *offsets, uint32_t count)
{
    pg_world *w = r->player.world;
    snap now = {0, 0, 0}, again = {0, 0, 0};
    uint32_t i;
    snap_save(&now, w);
    if (!snap_restore(w, good)) goto done;
    for (i = 0; i < count; ++i) {
        pg_replay_apply_frame(w, r->data, &r->info, offsets[i], NULL, NULL);
        pg_world_step(w);
    }
    snap_save(&again, w);
    if (now.size == again.size && memcmp(now.data, again.data, now.size) == 0) {
        fprintf(stderr,
                "%s:   re-stepping frames %u..%u from the snapshot at frame %u reproduces this build's state: the "
                "recording was made with other numerics (if the change is intended: pogon-replay rehash)\n",
                r->path, good_frame, good_frame + count - 1, good_frame);
    } else {
        fprintf(stderr, "%s:   re-stepping frames %u..%u from the snapshot at frame %u gives another state (", r->path,
                good_frame, good_frame + count - 1, good_frame);
        print_divergence(stderr, &now, &again);
        fprintf(stderr, "): this build is not deterministic\n");
    }
    snap_restore(w, &now);
done:
    free(now.data);
    free(again.data);
}

/* Play a loaded replay (replay_load) to its end, comparing every checkpoint; frees it. */
static int verify_loaded(replay *rp, pg_replay_frame_result fr)
{
    replay r = *rp;
    const char *path = r.path;
    snap good = {0, 0, 0};
    size_t *offsets;
    uint32_t n_off = 0, good_frame = 0, last_cp_frame = 0;
    int rc = 0;
    warn_engine_version(&r);
    offsets = (size_t *)xmalloc(sizeof(size_t) * r.info.checkpoint_interval);
    if (!fr.match) {
        fprintf(stderr, "%s: DIVERGED at checkpoint 0 (frame 0, the loaded scene): expected %016llx, got %016llx; "
                        "sections: ",
                path, (unsigned long long)fr.expected_hash, (unsigned long long)fr.actual_hash);
        print_sections(stderr, fr.section_mismatch);
        fprintf(stderr, "\n");
        rc = EXIT_DIVERGED;
        goto out;
    }
    snap_save(&good, r.player.world);
    while (!pg_replay_player_done(&r.player)) {
        pg_replay_player_step(&r.player, &fr);
        if (n_off < r.info.checkpoint_interval) offsets[n_off++] = fr.record_offset;
        if (fr.checkpoint) {
            if (!fr.match) {
                fprintf(stderr,
                        "%s: DIVERGED at checkpoint %u (frame %u): expected %016llx, got %016llx; first diverging "
                        "frame in %u..%u; sections: ",
                        path, fr.checkpoint_index, fr.frame + 1, (unsigned long long)fr.expected_hash,
                        (unsigned long long)fr.actual_hash, last_cp_frame, fr.frame);
                print_sections(stderr, fr.section_mismatch);
                fprintf(stderr, "\n");
                diagnose(&r, &good, good_frame, offsets, n_off);
                rc = EXIT_DIVERGED;
                goto out;
            }
            last_cp_frame = fr.frame + 1;
            good_frame = last_cp_frame;
            n_off = 0;
            snap_save(&good, r.player.world);
        }
    }
    {
        uint64_t h = pg_world_hash(r.player.world);
        if (h != r.info.final_hash) {
            fprintf(stderr, "%s: DIVERGED at the final hash (frame %u): expected %016llx, got %016llx; first diverging "
                            "frame in %u..%u\n",
                    path, r.player.frame, (unsigned long long)r.info.final_hash, (unsigned long long)h, last_cp_frame,
                    r.player.frame - 1);
            rc = EXIT_DIVERGED;
            goto out;
        }
        printf("%s: OK %u frames, %u checkpoints, %llu commands (%u failed as recorded), final hash %016llx\n", path,
               r.info.frame_count, r.info.checkpoint_count, (unsigned long long)r.info.command_count,
               r.player.command_failures, (unsigned long long)h);
    }
out:
    free(good.data);
    free(offsets);
    replay_free(&r);
    return rc;
}

static int verify_one(const char *path)
{
    replay r;
    pg_replay_frame_result fr;
    int rc = replay_open(&r, path, &fr);
    if (rc != 0) return rc;
    return verify_loaded(&r, fr);
}

static int cmd_verify(int argc, char **argv)
{
    int i, worst = 0;
    if (argc < 1) {
        fprintf(stderr, "usage: pogon-replay verify FILE...\n");
        return EXIT_BAD;
    }
    for (i = 0; i < argc; ++i) {
        int rc = verify_one(argv[i]);
        if (rc > worst) worst = rc;
    }
    return worst;
}

/* ---- info ----------------------------------------------------------------------------- */
static void print_numeric_config(const pg_replay_info *in)
{
    char text[128];
    pg_numeric_config_describe(in->numeric_config, text, sizeof text);
    printf("numerics        %s (numeric configuration 0x%08x; this build: ", text, in->numeric_config);
    pg_numeric_config_describe(pg_numeric_config(), text, sizeof text);
    printf("%s)\n", in->numeric_config == pg_numeric_config() ? "the same" : text);
}

/* What the header of a file this build cannot play says (pg_replay_read filled *in). */
static int info_of_unplayable(const char *path, const uint8_t *data, size_t size)
{
    pg_replay_info in;
    pg_replay_error e;
    pg_result res = pg_replay_read(data, size, &in, &e);
    if (res != PG_ERR_INCOMPATIBLE || in.format_version != PG_REPLAY_FORMAT_VERSION) {
        print_replay_error(path, &e);
        return EXIT_BAD;
    }
    printf("file            %s (%zu bytes)\n", path, size);
    printf("format          pogon replay, format version %u, recorded with pogon %u.%u.%u\n", in.format_version,
           in.engine_major, in.engine_minor, in.engine_patch);
    print_numeric_config(&in);
    printf("frames          %u, %llu commands, final hash %016llx\n", in.frame_count,
           (unsigned long long)in.command_count, (unsigned long long)in.final_hash);
    print_replay_error(path, &e);
    return EXIT_BAD;
}

static int cmd_info(int argc, char **argv)
{
    replay r;
    pg_replay_frame_result fr;
    pg_world_def def;
    pg_world_stats st;
    char a[PG_FIX_FORMAT_MAX], b[PG_FIX_FORMAT_MAX];
    uint32_t types[3] = {0, 0, 0}, kinds[5] = {0, 0, 0, 0, 0}, i;
    int rc;
    if (argc != 1) {
        fprintf(stderr, "usage: pogon-replay info FILE\n");
        return EXIT_BAD;
    }
    {
        size_t size = 0;
        uint8_t *data = read_file(argv[0], &size);
        pg_replay_info in;
        if (data == NULL) return EXIT_BAD;
        if (pg_replay_read(data, size, &in, NULL) == PG_ERR_INCOMPATIBLE) {
            rc = info_of_unplayable(argv[0], data, size);
            free(data);
            return rc;
        }
        rc = replay_load(&r, argv[0], data, size, &fr);
    }
    if (rc != 0) return rc;
    def = pg_world_get_def(r.player.world);
    st = pg_world_get_stats(r.player.world);
    for (i = 0; i < def.max_bodies; ++i) {
        pg_body_id id;
        pg_shape_id shapes[64];
        uint32_t n, k;
        id.index = i;
        id.generation = 1;
        if (!pg_body_is_valid(r.player.world, id)) continue;
        types[pg_body_type_of(r.player.world, id)]++;
        n = pg_body_shapes(r.player.world, id, shapes, 64);
        for (k = 0; k < n && k < 64; ++k) {
            pg_geometry g;
            if (pg_shape_geometry(r.player.world, shapes[k], &g) == PG_OK && (unsigned)g.kind < 5) kinds[g.kind]++;
        }
    }
    printf("file            %s (%zu bytes)\n", argv[0], r.size);
    printf("format          pogon replay, format version %u, recorded with pogon %u.%u.%u\n", r.info.format_version,
           r.info.engine_major, r.info.engine_minor, r.info.engine_patch);
    print_numeric_config(&r.info);
    printf("checkpoints     every %u frames: %u, %u section hashes each\n", r.info.checkpoint_interval,
           r.info.checkpoint_count, r.info.section_count);
    printf("frames          %u\n", r.info.frame_count);
    printf("final hash      %016llx\n", (unsigned long long)r.info.final_hash);
    printf("checksum        %016llx\n", (unsigned long long)r.info.checksum);
    printf("scene           %zu bytes of text at offset %zu\n", r.info.scene_size, r.info.scene_offset);
    printf("  bodies        %u (static %u, kinematic %u, dynamic %u), shapes %u (circle %u, segment %u, capsule %u, "
           "polygon %u, chain segment %u)\n",
           st.body_count, types[0], types[1], types[2], st.shape_count, kinds[0], kinds[1], kinds[2], kinds[3], kinds[4]);
    printf("  gravity       (%s, %s) m/s^2\n", fix_str(def.gravity.x, a), fix_str(def.gravity.y, b));
    printf("  step          %u Hz, %u substeps\n", def.step_hz, def.substeps);
    printf("  effects       ");
    print_effects(stdout, def.effects);
    printf(" (0x%02x)\n", def.effects);
    printf("  capacities    bodies %u, shapes %u, contacts %u\n", def.max_bodies, def.max_shapes, def.max_contacts);
    printf("  scene hash    %016llx (checkpoint 0: %s)\n", (unsigned long long)fr.actual_hash,
           fr.match ? "matches" : "DIFFERS");
    printf("commands        %llu (at most %u in one frame)\n", (unsigned long long)r.info.command_count,
           r.info.max_frame_commands);
    for (i = 1; i < PG_CMD_KIND_COUNT; ++i) {
        if (r.info.kind_counts[i] != 0)
            printf("  %-22s %llu\n", pg_command_kind_name((pg_command_kind)i), (unsigned long long)r.info.kind_counts[i]);
    }
    replay_free(&r);
    return 0;
}

/* ---- rehash --------------------------------------------------------------------------- */
typedef struct growbuf { uint8_t *data; size_t cap; } growbuf;

/* Retry a writer call after growing its buffer while it reports PG_ERR_MEMORY. */
#define WRITE_GROWING(w, gb, call)                                                   \
    do {                                                                             \
        pg_result wr_;                                                               \
        while ((wr_ = (call)) == PG_ERR_MEMORY) {                                    \
            (gb)->cap *= 2;                                                          \
            (gb)->data = (uint8_t *)xrealloc((gb)->data, (gb)->cap);                 \
            pg_replay_writer_set_buffer((w), (gb)->data, (gb)->cap);                 \
        }                                                                            \
        if (wr_ != PG_OK) {                                                          \
            fprintf(stderr, "pogon-replay: replay writer: %s\n", pg_result_name(wr_)); \
            exit(EXIT_BAD);                                                          \
        }                                                                            \
    } while (0)

static void begin_growing(pg_replay_writer *w, growbuf *gb, const char *scene, size_t scene_size, uint32_t interval)
{
    pg_result r;
    gb->cap = scene_size + 65536;
    gb->data = (uint8_t *)xmalloc(gb->cap);
    while ((r = pg_replay_writer_begin(w, gb->data, gb->cap, scene, scene_size, interval)) == PG_ERR_MEMORY) {
        gb->cap *= 2;
        gb->data = (uint8_t *)xrealloc(gb->data, gb->cap);
    }
    if (r != PG_OK) {
        fprintf(stderr, "pogon-replay: replay writer: %s\n", pg_result_name(r));
        exit(EXIT_BAD);
    }
}

/* Decode the commands of a frame record of a valid file. */
static uint32_t frame_commands(const replay *r, size_t off, pg_command *out)
{
    uint32_t n = (uint32_t)r->data[off + 1] | ((uint32_t)r->data[off + 2] << 8), c;
    size_t pos = off + 3;
    for (c = 0; c < n; ++c) {
        size_t used = 0;
        if (pg_command_decode(r->data + pos, r->info.end_offset - pos, &out[c], &used, NULL, NULL) != PG_OK) break;
        pos += used;
    }
    return c;
}

static int rehash_one(const char *path)
{
    replay r;
    pg_replay_frame_result fr;
    pg_replay_writer w;
    growbuf gb;
    pg_command *cmds;
    uint32_t changed = 0;
    size_t size;
    int rc = replay_open(&r, path, &fr);
    if (rc != 0) return rc;
    cmds = (pg_command *)xmalloc(sizeof(pg_command) * (r.info.max_frame_commands + 1u));
    begin_growing(&w, &gb, r.info.scene_text, r.info.scene_size, r.info.checkpoint_interval);
    WRITE_GROWING(&w, &gb, pg_replay_writer_add_checkpoint_world(&w, r.player.world));
    changed += !fr.match;
    while (!pg_replay_player_done(&r.player)) {
        size_t off = r.player.cursor;
        uint32_t n = frame_commands(&r, off, cmds);
        WRITE_GROWING(&w, &gb, pg_replay_writer_add_frame(&w, cmds, n));
        pg_replay_player_step(&r.player, &fr);
        if (pg_replay_writer_checkpoint_due(&w)) {
            WRITE_GROWING(&w, &gb, pg_replay_writer_add_checkpoint_world(&w, r.player.world));
            changed += !fr.match;
        }
    }
    WRITE_GROWING(&w, &gb, pg_replay_writer_finish(&w, pg_world_hash(r.player.world), &size));
    if (size == r.size && memcmp(gb.data, r.data, size) == 0) {
        printf("%s: unchanged (final hash %016llx)\n", path, (unsigned long long)pg_world_hash(r.player.world));
    } else if (!write_file(path, gb.data, size)) {
        rc = EXIT_BAD;
    } else {
        printf("%s: rehashed: %u of %u checkpoints changed, final hash %016llx -> %016llx\n", path, changed,
               r.info.checkpoint_count, (unsigned long long)r.info.final_hash,
               (unsigned long long)pg_world_hash(r.player.world));
    }
    free(gb.data);
    free(cmds);
    replay_free(&r);
    return rc;
}

static int cmd_rehash(int argc, char **argv)
{
    int i, worst = 0;
    if (argc < 1) {
        fprintf(stderr, "usage: pogon-replay rehash FILE...\n");
        return EXIT_BAD;
    }
    for (i = 0; i < argc; ++i) {
        int rc = rehash_one(argv[i]);
        if (rc > worst) worst = rc;
    }
    return worst;
}

/* ---- upgrade -------------------------------------------------------------------------- */
/* An older format into this build's (pg_replay_upgrade), stamped with this build's
 * numeric configuration and written only when it replays with this build. */
static int cmd_upgrade(int argc, char **argv)
{
    const char *in, *out;
    uint8_t *data, *conv;
    size_t size = 0, need = 0;
    pg_replay_error e;
    pg_replay_frame_result fr;
    replay r;
    pg_result res;
    int rc;
    uint32_t from;
    char config[128];
    if (argc != 2) {
        fprintf(stderr, "usage: pogon-replay upgrade IN OUT\n");
        return EXIT_BAD;
    }
    in = argv[0];
    out = argv[1];
    data = read_file(in, &size);
    if (data == NULL) return EXIT_BAD;
    from = size >= 10 ? (uint32_t)data[8] | (uint32_t)data[9] << 8 : 0u;
    res = pg_replay_upgrade(data, size, pg_numeric_config(), data, 0, &need, &e);
    if (res == PG_ERR_MEMORY) {
        conv = (uint8_t *)xmalloc(need);
        res = pg_replay_upgrade(data, size, pg_numeric_config(), conv, need, &need, &e);
    } else {
        conv = NULL;
    }
    free(data);
    if (res != PG_OK) {
        print_replay_error(in, &e);
        free(conv);
        return EXIT_BAD;
    }
    /* prove the stamp: the upgraded file must replay with this build (replay_load owns conv) */
    pg_numeric_config_describe(pg_numeric_config(), config, sizeof config);
    rc = replay_load(&r, in, conv, need, &fr);
    if (rc == 0) {
        uint8_t *copy = (uint8_t *)xmalloc(need);
        memcpy(copy, conv, need);
        rc = verify_loaded(&r, fr);
        if (rc == 0 && !write_file(out, copy, need)) rc = EXIT_BAD;
        if (rc == 0)
            printf("%s: format %u -> %u, numeric configuration: %s; written to %s\n", in, from,
                   PG_REPLAY_FORMAT_VERSION, config, out);
        free(copy);
    }
    if (rc != 0)
        fprintf(stderr, "%s: not upgraded: it does not replay with this build (%s); upgrade it with a build "
                        "configured like its recorder\n", in, config);
    return rc != 0 ? EXIT_BAD : 0;
}

/* ---- synctest ------------------------------------------------------------------------- */
static int synctest_one(const char *path, uint32_t k)
{
    replay r;
    pg_replay_frame_result fr;
    snap *ring;     /* ring[f % (k+1)]: the state at frame f, before its commands */
    size_t *offs;   /* offs[f % (k+1)]: frame f's record */
    snap first = {0, 0, 0}, again = {0, 0, 0};
    uint32_t slots = k + 1u, i, errors = 0, rollbacks = 0;
    int rc = replay_open(&r, path, &fr);
    pg_world *w;
    if (rc != 0) return rc;
    w = r.player.world;
    ring = (snap *)xmalloc(sizeof(snap) * slots);
    offs = (size_t *)xmalloc(sizeof(size_t) * slots);
    memset(ring, 0, sizeof(snap) * slots);
    if (!fr.match) {
        fprintf(stderr, "%s: checkpoint 0 (the loaded scene) does not match the file\n", path);
        errors++;
    }
    while (!pg_replay_player_done(&r.player)) {
        uint32_t f = r.player.frame, g;
        uint64_t h1, s1[PG_SECTION_COUNT], h2, s2[PG_SECTION_COUNT];
        snap_save(&ring[f % slots], w);
        offs[f % slots] = r.player.cursor;
        pg_replay_player_step(&r.player, &fr); /* now at frame f + 1 */
        if (fr.checkpoint && !fr.match) {
            fprintf(stderr, "%s: checkpoint %u (frame %u) does not match the file (run verify)\n", path,
                    fr.checkpoint_index, f + 1);
            errors++;
        }
        if (f + 1u < k) continue;
        /* roll back k frames and re-simulate them */
        h1 = pg_world_hash(w);
        pg_world_section_hashes(w, s1);
        snap_save(&first, w);
        g = f + 1u - k;
        if (!snap_restore(w, &ring[g % slots])) {
            errors++;
            break;
        }
        for (i = g; i <= f; ++i) {
            pg_replay_apply_frame(w, r.data, &r.info, offs[i % slots], NULL, NULL);
            pg_world_step(w);
        }
        rollbacks++;
        h2 = pg_world_hash(w);
        pg_world_section_hashes(w, s2);
        if (h1 != h2) {
            uint32_t mask = 0, s;
            for (s = 0; s < PG_SECTION_COUNT; ++s) mask |= (uint32_t)(s1[s] != s2[s]) << s;
            snap_save(&again, w);
            fprintf(stderr, "%s: SYNC ERROR at frame %u after rolling back to frame %u: hash %016llx vs %016llx; "
                            "sections: ",
                    path, f + 1, g, (unsigned long long)h1, (unsigned long long)h2);
            print_sections(stderr, mask);
            fprintf(stderr, "; ");
            print_divergence(stderr, &first, &again);
            fprintf(stderr, "\n");
            if (++errors >= 10) {
                fprintf(stderr, "%s: too many sync errors, stopping\n", path);
                break;
            }
        }
    }
    if (errors == 0 && rollbacks == 0) {
        /* nothing was rolled back, so nothing was tested: a failure, not an OK */
        fprintf(stderr, "%s: synctest tested nothing: --rollback %u is more than the file's %u frames (use 1..%u)\n", path, k,
                r.player.frame, r.player.frame);
        rc = EXIT_BAD;
    } else if (errors == 0) {
        printf("%s: OK synctest rollback %u: %u frames, %u rollbacks, final hash %016llx\n", path, k, r.player.frame,
               rollbacks, (unsigned long long)pg_world_hash(w));
    } else {
        rc = EXIT_DIVERGED;
    }
    for (i = 0; i < slots; ++i) free(ring[i].data);
    free(ring);
    free(offs);
    free(first.data);
    free(again.data);
    replay_free(&r);
    return rc;
}

static int cmd_synctest(int argc, char **argv)
{
    int i, worst = 0, nfiles = 0;
    long k = -1;
    for (i = 0; i < argc; ++i) {
        if (strcmp(argv[i], "--rollback") == 0 && i + 1 < argc) {
            char *end;
            k = strtol(argv[++i], &end, 10);
            if (*end != '\0' || k < 1 || k > 100000) {
                fprintf(stderr, "pogon-replay synctest: --rollback wants 1..100000, got '%s'\n", argv[i]);
                return EXIT_BAD;
            }
        } else {
            nfiles++;
        }
    }
    if (k < 1 || nfiles == 0) {
        fprintf(stderr, "usage: pogon-replay synctest FILE... --rollback K\n");
        return EXIT_BAD;
    }
    for (i = 0; i < argc; ++i) {
        int rc;
        if (strcmp(argv[i], "--rollback") == 0) {
            ++i;
            continue;
        }
        rc = synctest_one(argv[i], (uint32_t)k);
        if (rc > worst) worst = rc;
    }
    return worst;
}

/* ---- record: the script ------------------------------------------------------------------ */
typedef enum ref_kind { REF_NONE, REF_SLOT, REF_HANDLE, REF_LAST, REF_MADE } ref_kind;
typedef struct body_ref { ref_kind kind; uint32_t a, b; } body_ref;

typedef struct script_cmd {
    uint32_t frame, line;
    pg_command cmd;
    body_ref ref, ref2; /* ref2: a joint's body B */
    body_ref jref;      /* the joint a joint command acts on (REF_HANDLE, REF_LAST, REF_MADE) */
} script_cmd;

typedef struct script {
    const char *path;
    script_cmd *items;
    size_t count, cap;
} script;

typedef struct tokens { char *v[64]; int n; } tokens;

static int script_error(const script *s, uint32_t line, const char *what, const char *detail)
{
    fprintf(stderr, "%s:%u: %s%s%s\n", s->path, line, what, detail != NULL ? ": " : "", detail != NULL ? detail : "");
    return 0;
}

static int parse_fix(const char *t, pg_fix *out)
{
    return pg_fix_parse(t, strlen(t), out) == PG_FIX_OK;
}

static int parse_u64(const char *t, uint64_t *out)
{
    char *end;
    if (*t == '-' || *t == '\0') return 0;
    errno = 0;
    *out = strtoull(t, &end, 0);
    return errno == 0 && *end == '\0';
}

static int parse_u32(const char *t, uint32_t *out)
{
    uint64_t v;
    if (!parse_u64(t, &v) || v > 0xFFFFFFFFu) return 0;
    *out = (uint32_t)v;
    return 1;
}

/* Degrees (decimal) to a binary angle, rounded. */
static int parse_angle(const char *t, pg_angle *out)
{
    pg_fix deg;
    if (!parse_fix(t, &deg)) return 0;
    *out = pg_scene_angle_from_degrees(deg); /* exactly as scene files do */
    return 1;
}

static int parse_body_type(const char *t, uint32_t *out)
{
    if (strcmp(t, "static") == 0) *out = PG_BODY_STATIC;
    else if (strcmp(t, "kinematic") == 0) *out = PG_BODY_KINEMATIC;
    else if (strcmp(t, "dynamic") == 0) *out = PG_BODY_DYNAMIC;
    else return 0;
    return 1;
}

static int parse_effects(const char *t, uint32_t *out)
{
    char buf[256], *p, *save = NULL;
    uint32_t v = 0;
    if (parse_u32(t, out)) return 1;
    if (strlen(t) >= sizeof buf) return 0;
    strcpy(buf, t);
    for (p = strtok_r(buf, "+|", &save); p != NULL; p = strtok_r(NULL, "+|", &save)) {
        unsigned i;
        int found = 0;
        if (strcmp(p, "all") == 0) v |= PG_EFFECTS_ALL, found = 1;
        else if (strcmp(p, "none") == 0) found = 1;
        for (i = 0; i < 7 && !found; ++i) {
            if (strcmp(p, effect_names[i]) == 0) {
                v |= 1u << i;
                found = 1;
            }
        }
        if (!found) return 0;
    }
    *out = v;
    return 1;
}

static int parse_ref(const char *t, body_ref *ref)
{
    char *end;
    unsigned long a, b;
    if (strcmp(t, "last") == 0) {
        ref->kind = REF_LAST;
        return 1;
    }
    if (t[0] == '#' || t[0] == '$') {
        if (t[1] < '0' || t[1] > '9') return 0;
        a = strtoul(t + 1, &end, 10);
        if (*end != '\0' || a > 0xFFFFFFFFul) return 0;
        ref->kind = t[0] == '#' ? REF_SLOT : REF_MADE;
        ref->a = (uint32_t)a;
        return 1;
    }
    if (t[0] < '0' || t[0] > '9') return 0;
    a = strtoul(t, &end, 10);
    if (*end != ':' || end[1] < '0' || end[1] > '9') return 0;
    b = strtoul(end + 1, &end, 10);
    if (*end != '\0' || a > 0xFFFFFFFFul || b > 0xFFFFFFFFul) return 0;
    ref->kind = REF_HANDLE;
    ref->a = (uint32_t)a;
    ref->b = (uint32_t)b;
    return 1;
}

/* key=value options of create_body, make, add_shape. */
static int parse_options(const script *s, uint32_t line, tokens *tk, int from, pg_body_def *bd, pg_shape_def *sd)
{
    int i;
    for (i = from; i < tk->n; ++i) {
        char *eq = strchr(tk->v[i], '=');
        const char *key = tk->v[i], *val;
        int ok = 1;
        uint32_t u = 0;
        if (eq == NULL) return script_error(s, line, "expected key=value", tk->v[i]);
        *eq = '\0';
        val = eq + 1;
        if (bd != NULL && strcmp(key, "type") == 0) ok = parse_body_type(val, &u), bd->type = (pg_body_type)u;
        else if (bd != NULL && strcmp(key, "x") == 0) ok = parse_fix(val, &bd->position.x);
        else if (bd != NULL && strcmp(key, "y") == 0) ok = parse_fix(val, &bd->position.y);
        else if (bd != NULL && strcmp(key, "angle") == 0) ok = parse_angle(val, &bd->angle);
        else if (bd != NULL && strcmp(key, "vx") == 0) ok = parse_fix(val, &bd->linear_velocity.x);
        else if (bd != NULL && strcmp(key, "vy") == 0) ok = parse_fix(val, &bd->linear_velocity.y);
        else if (bd != NULL && strcmp(key, "w") == 0) ok = parse_fix(val, &bd->angular_velocity);
        else if (bd != NULL && strcmp(key, "linear_damping") == 0) ok = parse_fix(val, &bd->linear_damping);
        else if (bd != NULL && strcmp(key, "angular_damping") == 0) ok = parse_fix(val, &bd->angular_damping);
        else if (bd != NULL && strcmp(key, "gravity_scale") == 0) ok = parse_fix(val, &bd->gravity_scale);
        else if (bd != NULL && strcmp(key, "fixed_rotation") == 0) ok = parse_u32(val, &u) && u <= 1, bd->fixed_rotation = (int)u;
        else if (bd != NULL && strcmp(key, "allow_sleep") == 0) ok = parse_u32(val, &u) && u <= 1, bd->allow_sleep = (int)u;
        else if (bd != NULL && strcmp(key, "awake") == 0) ok = parse_u32(val, &u) && u <= 1, bd->awake = (int)u;
        else if (bd != NULL && strcmp(key, "user_data") == 0) ok = parse_u64(val, &bd->user_data);
        else if (sd != NULL && strcmp(key, "density") == 0) ok = parse_fix(val, &sd->density);
        else if (sd != NULL && strcmp(key, "friction") == 0) ok = parse_fix(val, &sd->friction);
        else if (sd != NULL && strcmp(key, "restitution") == 0) ok = parse_fix(val, &sd->restitution);
        else if (sd != NULL && strcmp(key, "category") == 0) ok = parse_u32(val, &sd->category);
        else if (sd != NULL && strcmp(key, "mask") == 0) ok = parse_u32(val, &sd->mask);
        else {
            *eq = '=';
            return script_error(s, line, "unknown option", tk->v[i]);
        }
        if (!ok) {
            *eq = '=';
            return script_error(s, line, "bad value", tk->v[i]);
        }
    }
    return 1;
}

/* Index of the first key=value token at or after `from`. */
static int options_start(const tokens *tk, int from)
{
    int i;
    for (i = from; i < tk->n; ++i)
        if (strchr(tk->v[i], '=') != NULL) return i;
    return tk->n;
}

static int parse_geometry(const script *s, uint32_t line, tokens *tk, int from, int end, pg_geometry *g)
{
    pg_fix v[16];
    int n = end - from - 1, i;
    const char *kind;
    pg_result r;
    pg_angle angle = 0;
    if (n < 0) return script_error(s, line, "missing geometry", NULL);
    kind = tk->v[from];
    if (n > 16) return script_error(s, line, "too many geometry numbers", NULL);
    for (i = 0; i < n; ++i) {
        /* the angle of box and triangle is in degrees */
        if (((strcmp(kind, "box") == 0 && i == 4) || (strcmp(kind, "triangle") == 0 && i == 3))) {
            if (!parse_angle(tk->v[from + 1 + i], &angle)) return script_error(s, line, "bad angle", tk->v[from + 1 + i]);
            v[i] = 0;
        } else if (!parse_fix(tk->v[from + 1 + i], &v[i])) {
            return script_error(s, line, "bad number", tk->v[from + 1 + i]);
        }
    }
    if (strcmp(kind, "circle") == 0 && n == 3) r = pg_geometry_circle(pg_v2(v[0], v[1]), v[2], g);
    else if (strcmp(kind, "segment") == 0 && n == 4) r = pg_geometry_segment(pg_v2(v[0], v[1]), pg_v2(v[2], v[3]), g);
    else if (strcmp(kind, "capsule") == 0 && n == 5)
        r = pg_geometry_capsule(pg_v2(v[0], v[1]), pg_v2(v[2], v[3]), v[4], g);
    else if (strcmp(kind, "box") == 0 && (n == 2 || n == 5))
        r = pg_geometry_box(v[0], v[1], n == 5 ? pg_v2(v[2], v[3]) : pg_v2(0, 0), angle, g);
    else if (strcmp(kind, "triangle") == 0 && (n == 3 || n == 4))
        r = pg_geometry_triangle(pg_v2(v[0], v[1]), v[2], n == 4 ? angle : PG_ANGLE_QUARTER, g);
    else if (strcmp(kind, "polygon") == 0 && n >= 6 && n <= 16 && n % 2 == 0) {
        pg_vec2 pts[PG_MAX_VERTICES];
        for (i = 0; i < n / 2; ++i) pts[i] = pg_v2(v[2 * i], v[2 * i + 1]);
        r = pg_geometry_polygon(pts, n / 2, g);
    } else if (strcmp(kind, "chain_segment") == 0 && n == 8)
        r = pg_geometry_chain_segment(pg_v2(v[0], v[1]), pg_v2(v[2], v[3]), pg_v2(v[4], v[5]), pg_v2(v[6], v[7]), g);
    else
        return script_error(s, line, "bad geometry (circle CX CY R | segment AX AY BX BY | capsule AX AY BX BY R | "
                                     "box HW HH [CX CY ANGLE] | triangle CX CY R [ANGLE] | polygon X1 Y1 ... | "
                                     "chain_segment BX BY X1 Y1 X2 Y2 AX AY)",
                            kind);
    if (r != PG_OK) return script_error(s, line, "invalid geometry", pg_result_name(r));
    return 1;
}

static int parse_make_kind(const char *t, pg_make_kind *k)
{
    static const char *const names[PG_MAKE_KIND_COUNT] = {"ball", "capsule", "box", "triangle", "star", "wall"};
    int i;
    for (i = 0; i < PG_MAKE_KIND_COUNT; ++i) {
        if (strcmp(t, names[i]) == 0) {
            *k = (pg_make_kind)i;
            return 1;
        }
    }
    return 0;
}

/* jI:G, jlast or j$K */
static int parse_joint_ref(const char *t, body_ref *ref)
{
    if (t[0] != 'j' || t[1] == '#') return 0; /* joints have no slot form */
    return parse_ref(t + 1, ref);             /* jlast, j$K, jI:G */
}

/* key=value fields of a joint def, into the def of c's kind. */
static int parse_joint_options(const script *s, uint32_t line, tokens *tk, int from, pg_command *c)
{
    pg_command_joint_def *j = &c->joint_def;
    int i;
    for (i = from; i < tk->n; ++i) {
        char *eq = strchr(tk->v[i], '='), *key = tk->v[i], *val;
        pg_fix f = 0;
        uint64_t u = 0;
        pg_angle ang = 0;
        int isfix, ok = 1;
        pg_command_kind k = c->kind;
        if (eq == NULL) return script_error(s, line, "expected key=value", tk->v[i]);
        *eq = '\0';
        val = eq + 1;
        isfix = parse_fix(val, &f);
#define FIXKEY(name, kind, field) else if (strcmp(key, name) == 0 && k == kind) { if (!isfix) ok = 0; else field = f; }
#define FLAGKEY(name, kind, field) else if (strcmp(key, name) == 0 && k == kind) { if (!parse_u64(val, &u) || u > 1) ok = 0; else field = (int)u; }
        if (0) {}
        FIXKEY("ax", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.local_anchor_a.x) FIXKEY("ay", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.local_anchor_a.y)
        FIXKEY("bx", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.local_anchor_b.x) FIXKEY("by", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.local_anchor_b.y)
        FIXKEY("length", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.length) FLAGKEY("spring", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.enable_spring)
        FIXKEY("hertz", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.hertz) FIXKEY("damping", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.damping_ratio)
        FLAGKEY("limit", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.enable_limit) FIXKEY("lower", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.min_length)
        FIXKEY("upper", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.max_length) FLAGKEY("collide", PG_CMD_CREATE_DISTANCE_JOINT, j->distance.collide_connected)
        FIXKEY("ax", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.local_anchor_a.x) FIXKEY("ay", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.local_anchor_a.y)
        FIXKEY("bx", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.local_anchor_b.x) FIXKEY("by", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.local_anchor_b.y)
        FLAGKEY("limit", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.enable_limit) FIXKEY("lower", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.lower_angle)
        FIXKEY("upper", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.upper_angle) FLAGKEY("motor", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.enable_motor)
        FIXKEY("speed", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.motor_speed) FIXKEY("max_motor", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.max_motor_torque)
        FLAGKEY("collide", PG_CMD_CREATE_REVOLUTE_JOINT, j->revolute.collide_connected)
        FIXKEY("ax", PG_CMD_CREATE_WELD_JOINT, j->weld.local_anchor_a.x) FIXKEY("ay", PG_CMD_CREATE_WELD_JOINT, j->weld.local_anchor_a.y)
        FIXKEY("bx", PG_CMD_CREATE_WELD_JOINT, j->weld.local_anchor_b.x) FIXKEY("by", PG_CMD_CREATE_WELD_JOINT, j->weld.local_anchor_b.y)
        FIXKEY("linear_hertz", PG_CMD_CREATE_WELD_JOINT, j->weld.linear_hertz) FIXKEY("linear_damping", PG_CMD_CREATE_WELD_JOINT, j->weld.linear_damping_ratio)
        FIXKEY("angular_hertz", PG_CMD_CREATE_WELD_JOINT, j->weld.angular_hertz) FIXKEY("angular_damping", PG_CMD_CREATE_WELD_JOINT, j->weld.angular_damping_ratio)
        FLAGKEY("collide", PG_CMD_CREATE_WELD_JOINT, j->weld.collide_connected)
        FIXKEY("ax", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_anchor_a.x) FIXKEY("ay", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_anchor_a.y)
        FIXKEY("bx", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_anchor_b.x) FIXKEY("by", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_anchor_b.y)
        FIXKEY("axis_x", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_axis_a.x) FIXKEY("axis_y", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.local_axis_a.y)
        FLAGKEY("limit", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.enable_limit) FIXKEY("lower", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.lower_translation)
        FIXKEY("upper", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.upper_translation) FLAGKEY("motor", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.enable_motor)
        FIXKEY("speed", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.motor_speed) FIXKEY("max_motor", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.max_motor_force)
        FLAGKEY("collide", PG_CMD_CREATE_PRISMATIC_JOINT, j->prismatic.collide_connected)
        FIXKEY("tx", PG_CMD_CREATE_MOUSE_JOINT, j->mouse.target.x) FIXKEY("ty", PG_CMD_CREATE_MOUSE_JOINT, j->mouse.target.y)
        FIXKEY("hertz", PG_CMD_CREATE_MOUSE_JOINT, j->mouse.hertz) FIXKEY("damping", PG_CMD_CREATE_MOUSE_JOINT, j->mouse.damping_ratio)
        FIXKEY("max_force", PG_CMD_CREATE_MOUSE_JOINT, j->mouse.max_force)
        else if (strcmp(key, "reference_angle") == 0 && (k == PG_CMD_CREATE_REVOLUTE_JOINT || k == PG_CMD_CREATE_WELD_JOINT || k == PG_CMD_CREATE_PRISMATIC_JOINT)) {
            if (!parse_angle(val, &ang)) ok = 0;
            else if (k == PG_CMD_CREATE_REVOLUTE_JOINT) j->revolute.reference_angle = ang;
            else if (k == PG_CMD_CREATE_WELD_JOINT) j->weld.reference_angle = ang;
            else j->prismatic.reference_angle = ang;
        } else if (strcmp(key, "user_data") == 0) {
            if (!parse_u64(val, &u)) ok = 0;
            else if (k == PG_CMD_CREATE_DISTANCE_JOINT) j->distance.user_data = u;
            else if (k == PG_CMD_CREATE_REVOLUTE_JOINT) j->revolute.user_data = u;
            else if (k == PG_CMD_CREATE_WELD_JOINT) j->weld.user_data = u;
            else if (k == PG_CMD_CREATE_PRISMATIC_JOINT) j->prismatic.user_data = u;
            else j->mouse.user_data = u;
        } else {
            *eq = '=';
            return script_error(s, line, "unknown option for this joint kind", tk->v[i]);
        }
#undef FIXKEY
#undef FLAGKEY
        if (!ok) {
            *eq = '=';
            return script_error(s, line, "bad value", tk->v[i]);
        }
    }
    return 1;
}

/* The joint commands' lines. */
static int parse_joint_line(const script *s, uint32_t line, tokens *tk, script_cmd *out)
{
    pg_command *c = &out->cmd;
    char **a = tk->v + 2;
    int nargs = tk->n - 2;
    switch (c->kind) {
    case PG_CMD_CREATE_MOUSE_JOINT:
        if (nargs < 1 || !parse_ref(a[0], &out->ref)) return script_error(s, line, "usage: create_mouse_joint BODY [key=value...]", NULL);
        return parse_joint_options(s, line, tk, 3, c);
    case PG_CMD_CREATE_DISTANCE_JOINT:
    case PG_CMD_CREATE_REVOLUTE_JOINT:
    case PG_CMD_CREATE_WELD_JOINT:
    case PG_CMD_CREATE_PRISMATIC_JOINT:
        if (nargs < 2 || !parse_ref(a[0], &out->ref) || !parse_ref(a[1], &out->ref2))
            return script_error(s, line, "usage: create_..._joint BODY_A BODY_B [key=value...]", NULL);
        return parse_joint_options(s, line, tk, 4, c);
    default: break;
    }
    if (nargs < 1 || !parse_joint_ref(a[0], &out->jref)) return script_error(s, line, "expected a joint (jI:G, jlast or j$K)", nargs > 0 ? a[0] : NULL);
    a++;
    nargs--;
    switch (c->kind) {
    case PG_CMD_DESTROY_JOINT:
        if (nargs != 0) return script_error(s, line, "usage: destroy_joint JOINT", NULL);
        return 1;
    case PG_CMD_SET_JOINT_MOTOR:
    case PG_CMD_SET_JOINT_LIMITS:
        if (nargs != 3 || !parse_u32(a[0], &c->flag) || c->flag > 1 || !parse_fix(a[1], &c->scalar) || !parse_fix(a[2], &c->scalar2))
            return script_error(s, line, "usage: set_joint_motor|set_joint_limits JOINT 0|1 NUMBER NUMBER", NULL);
        return 1;
    case PG_CMD_SET_MOUSE_TARGET:
        if (nargs != 2 || !parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y)) return script_error(s, line, "usage: set_mouse_target JOINT X Y", NULL);
        return 1;
    default: /* PG_CMD_SET_MOUSE_MAX_FORCE */
        if (nargs != 1 || !parse_fix(a[0], &c->scalar)) return script_error(s, line, "usage: set_mouse_max_force JOINT F", NULL);
        return 1;
    }
}

/* Parse one script line (already tokenised; v[0] is the frame). */
static int parse_line(const script *s, uint32_t line, tokens *tk, script_cmd *out)
{
    pg_command *c = &out->cmd;
    const char *name;
    int k, nargs, need = -1;
    char **a;
    if (!parse_u32(tk->v[0], &out->frame)) return script_error(s, line, "bad frame number", tk->v[0]);
    if (tk->n < 2) return script_error(s, line, "missing command", NULL);
    name = tk->v[1];
    out->line = line;
    out->ref.kind = REF_NONE;
    out->ref2.kind = REF_NONE;
    out->jref.kind = REF_NONE;
    for (k = 1; k < PG_CMD_KIND_COUNT; ++k)
        if (strcmp(name, pg_command_kind_name((pg_command_kind)k)) == 0) break;
    if (k == PG_CMD_KIND_COUNT) return script_error(s, line, "unknown command", name);
    *c = pg_command_init((pg_command_kind)k);
    a = tk->v + 2;
    nargs = tk->n - 2;

    if (c->kind >= PG_CMD_CREATE_DISTANCE_JOINT) return parse_joint_line(s, line, tk, out);
    switch (c->kind) {
    case PG_CMD_CREATE_BODY:
        c->body_def = pg_default_body_def();
        c->body_def.type = PG_BODY_DYNAMIC;
        return parse_options(s, line, tk, 2, &c->body_def, NULL);
    case PG_CMD_MAKE: {
        int end = options_start(tk, 2);
        c->body_def = pg_default_body_def();
        c->body_def.type = PG_BODY_DYNAMIC;
        c->shape_def = pg_default_shape_def();
        if (end - 2 < 2 || end - 2 > 3 || !parse_make_kind(a[0], &c->make_kind))
            return script_error(s, line, "usage: make ball|capsule|box|triangle|star|wall SIZE0 [SIZE1] [key=value...]",
                                NULL);
        if (!parse_fix(a[1], &c->size0)) return script_error(s, line, "bad number", a[1]);
        if (end - 2 == 3 && !parse_fix(a[2], &c->size1)) return script_error(s, line, "bad number", a[2]);
        return parse_options(s, line, tk, end, &c->body_def, &c->shape_def);
    }
    case PG_CMD_ADD_SHAPE: {
        int end = options_start(tk, 3);
        if (nargs < 2 || !parse_ref(a[0], &out->ref)) return script_error(s, line, "usage: add_shape BODY GEOMETRY...", NULL);
        c->shape_def = pg_default_shape_def();
        if (!parse_geometry(s, line, tk, 3, end, &c->geometry)) return 0;
        return parse_options(s, line, tk, end, NULL, &c->shape_def);
    }
    case PG_CMD_SET_GRAVITY:
        if (nargs != 2 || !parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y))
            return script_error(s, line, "usage: set_gravity GX GY", NULL);
        return 1;
    case PG_CMD_SET_EFFECTS:
        if (nargs != 1 || !parse_effects(a[0], &c->value)) return script_error(s, line, "usage: set_effects EFFECTS", NULL);
        return 1;
    default: break;
    }
    /* the rest: BODY then arguments */
    if (nargs < 1 || !parse_ref(a[0], &out->ref)) return script_error(s, line, "expected a body (#I, I:G, last or $K)", nargs > 0 ? a[0] : NULL);
    a++;
    nargs--;
    switch (c->kind) {
    case PG_CMD_DESTROY_BODY: need = 0; break;
    case PG_CMD_SET_TRANSFORM:
        need = 3;
        if (nargs == 3 && (!parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y) || !parse_angle(a[2], &c->angle))) need = -1;
        break;
    case PG_CMD_SET_LINEAR_VELOCITY:
        need = 2;
        if (nargs == 2 && (!parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y))) need = -1;
        break;
    case PG_CMD_APPLY_FORCE:
        need = nargs == 4 ? 4 : 2;
        if (nargs == need && (!parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y))) need = -1;
        if (need == 4) {
            c->flag = 1;
            if (!parse_fix(a[2], &c->point.x) || !parse_fix(a[3], &c->point.y)) need = -1;
        }
        break;
    case PG_CMD_APPLY_LINEAR_IMPULSE:
        need = 4;
        if (nargs == 4 && (!parse_fix(a[0], &c->vec.x) || !parse_fix(a[1], &c->vec.y) || !parse_fix(a[2], &c->point.x) ||
                           !parse_fix(a[3], &c->point.y)))
            need = -1;
        break;
    case PG_CMD_SET_ANGULAR_VELOCITY:
    case PG_CMD_APPLY_TORQUE:
    case PG_CMD_APPLY_ANGULAR_IMPULSE:
    case PG_CMD_SET_GRAVITY_SCALE:
    case PG_CMD_SET_FRICTION:
    case PG_CMD_SET_RESTITUTION:
    case PG_CMD_SET_DENSITY:
        need = 1;
        if (nargs == 1 && !parse_fix(a[0], &c->scalar)) need = -1;
        break;
    case PG_CMD_SET_DAMPING:
        need = 2;
        if (nargs == 2 && (!parse_fix(a[0], &c->scalar) || !parse_fix(a[1], &c->scalar2))) need = -1;
        break;
    case PG_CMD_SET_BODY_TYPE:
        need = 1;
        if (nargs == 1 && !parse_body_type(a[0], &c->value)) need = -1;
        break;
    case PG_CMD_SET_AWAKE:
    case PG_CMD_SET_FIXED_ROTATION:
        need = 1;
        if (nargs == 1 && (!parse_u32(a[0], &c->value) || c->value > 1)) need = -1;
        break;
    case PG_CMD_SET_FILTER:
        need = 2;
        if (nargs == 2 && (!parse_u32(a[0], &c->value) || !parse_u32(a[1], &c->value2))) need = -1;
        break;
    case PG_CMD_SET_USER_DATA:
        need = 1;
        if (nargs == 1 && !parse_u64(a[0], &c->user_data)) need = -1;
        break;
    default: return script_error(s, line, "command not allowed in scripts", name);
    }
    if (need < 0 || nargs != need) return script_error(s, line, "wrong arguments for", name);
    return 1;
}

static int load_script(script *s, const char *path)
{
    size_t size, pos = 0;
    uint8_t *data = read_file(path, &size);
    uint32_t line = 0;
    int ok = 1;
    memset(s, 0, sizeof *s);
    s->path = path;
    if (data == NULL) return 0;
    while (pos < size && ok) {
        size_t end = pos;
        char buf[4096], *p, *save = NULL;
        tokens tk;
        while (end < size && data[end] != '\n') ++end;
        line++;
        if (end - pos >= sizeof buf) {
            ok = script_error(s, line, "line too long", NULL);
            break;
        }
        memcpy(buf, data + pos, end - pos);
        buf[end - pos] = '\0';
        pos = end + 1;
        if ((p = strchr(buf, '#')) != NULL && (p == buf || p[-1] == ' ' || p[-1] == '\t') &&
            !(p[1] >= '0' && p[1] <= '9'))
            *p = '\0'; /* a comment ('#' followed by a digit is a body slot) */
        tk.n = 0;
        for (p = strtok_r(buf, " \t\r", &save); p != NULL; p = strtok_r(NULL, " \t\r", &save)) {
            if (*p == '#' && !(p[1] >= '0' && p[1] <= '9')) break;
            if (tk.n == 64) {
                ok = script_error(s, line, "too many words", NULL);
                break;
            }
            tk.v[tk.n++] = p;
        }
        if (!ok || tk.n == 0) continue;
        if (s->count == s->cap) {
            s->cap = s->cap ? s->cap * 2 : 64;
            s->items = (script_cmd *)xrealloc(s->items, s->cap * sizeof *s->items);
        }
        if (!parse_line(s, line, &tk, &s->items[s->count])) ok = 0;
        else s->count++;
    }
    free(data);
    return ok;
}

static int by_frame(const void *x, const void *y)
{
    const script_cmd *a = (const script_cmd *)x, *b = (const script_cmd *)y;
    if (a->frame != b->frame) return a->frame < b->frame ? -1 : 1;
    return a->line < b->line ? -1 : a->line > b->line;
}

/* ---- record ------------------------------------------------------------------------------ */
typedef struct tracker {
    uint32_t *gen;       /* generation of the live body in each slot, 0 if none */
    uint32_t slots;
    pg_body_id *made;    /* bodies made by the script, in order */
    size_t made_count, made_cap;
    pg_joint_id *joints; /* joints made by the script, in order */
    size_t joint_count, joint_cap;
} tracker;

/* A joint reference: a handle as is, or a joint the script made. */
static int resolve_joint(const script *s, const script_cmd *sc, const tracker *t, pg_joint_id *id)
{
    char detail[64];
    switch (sc->jref.kind) {
    case REF_HANDLE:
        id->index = sc->jref.a;
        id->generation = sc->jref.b;
        return 1;
    case REF_LAST:
        if (t->joint_count == 0) return script_error(s, sc->line, "'jlast' names no joint: no create_*_joint has succeeded before this line", NULL);
        *id = t->joints[t->joint_count - 1];
        return 1;
    case REF_MADE:
        if (sc->jref.a >= t->joint_count) {
            snprintf(detail, sizeof detail, "j$%u", sc->jref.a);
            return script_error(s, sc->line, "the script has not made this joint yet", detail);
        }
        *id = t->joints[sc->jref.a];
        return 1;
    default: return 1;
    }
}

static int resolve(const script *s, const script_cmd *sc, const tracker *t, pg_body_id *id)
{
    char detail[64];
    switch (sc->ref.kind) {
    case REF_NONE: return 1;
    case REF_HANDLE:
        id->index = sc->ref.a;
        id->generation = sc->ref.b;
        return 1;
    case REF_SLOT:
        if (sc->ref.a >= t->slots || t->gen[sc->ref.a] == 0) {
            snprintf(detail, sizeof detail, "#%u", sc->ref.a);
            return script_error(s, sc->line, "no live body in slot", detail);
        }
        id->index = sc->ref.a;
        id->generation = t->gen[sc->ref.a];
        return 1;
    case REF_LAST:
        if (t->made_count == 0)
            return script_error(s, sc->line, "'last' names no body: no create_body or make has succeeded before this line", NULL);
        *id = t->made[t->made_count - 1];
        return 1;
    case REF_MADE:
        if (sc->ref.a >= t->made_count) {
            snprintf(detail, sizeof detail, "$%u", sc->ref.a);
            return script_error(s, sc->line, "the script has not made this body yet", detail);
        }
        *id = t->made[sc->ref.a];
        return 1;
    }
    return 0;
}

static int cmd_record(int argc, char **argv)
{
    const char *scene_path = NULL, *script_path = NULL, *out_path = NULL;
    long frames = -1, interval = 60;
    uint8_t *scene_text;
    size_t scene_size, memory_size, next = 0;
    pg_world_def def;
    pg_scene_error se;
    pg_world *world;
    void *memory;
    script sc;
    tracker t;
    pg_replay_writer w;
    growbuf gb;
    pg_command *cmds = NULL;
    size_t cmds_cap = 0, size;
    uint32_t f, i, failures = 0;
    pg_result r;
    int a;

    memset(&sc, 0, sizeof sc);
    for (a = 0; a < argc; a += 2) { /* options come in pairs: --name value */
        const char *opt = argv[a];
        const char *val = a + 1 < argc ? argv[a + 1] : NULL;
        char *end = NULL;
        if (val == NULL) {
            fprintf(stderr, "pogon-replay record: %s needs a value\n", opt);
            return EXIT_BAD;
        }
        if (strcmp(opt, "--scene") == 0) scene_path = val;
        else if (strcmp(opt, "--script") == 0) script_path = val;
        else if (strcmp(opt, "-o") == 0 || strcmp(opt, "--output") == 0) out_path = val;
        else if (strcmp(opt, "--frames") == 0) {
            frames = strtol(val, &end, 10);
            if (*end != '\0' || end == val || frames < 0 || frames > 100000000L) {
                fprintf(stderr, "pogon-replay record: --frames wants a whole number 0..100000000, got '%s'\n", val);
                return EXIT_BAD;
            }
        } else if (strcmp(opt, "--checkpoint") == 0) {
            interval = strtol(val, &end, 10);
            if (*end != '\0' || end == val || interval < 1 || interval > 100000000L) {
                fprintf(stderr, "pogon-replay record: --checkpoint wants a whole number 1..100000000 (frames between checkpoints), got '%s'\n", val);
                return EXIT_BAD;
            }
        } else {
            fprintf(stderr, "pogon-replay record: unknown option %s\n", opt);
            return EXIT_BAD;
        }
    }
    if (scene_path == NULL || out_path == NULL || frames < 0) {
        fprintf(stderr, "pogon-replay record: %s is required\n", scene_path == NULL ? "--scene SCENE" : out_path == NULL ? "-o FILE" : "--frames N");
        fprintf(stderr, "usage: pogon-replay record --scene SCENE --frames N [--script SCRIPT] [--checkpoint K] -o FILE\n");
        return EXIT_BAD;
    }
    if (script_path != NULL && !load_script(&sc, script_path)) return EXIT_BAD;
    if (sc.count > 1) qsort(sc.items, sc.count, sizeof *sc.items, by_frame);
    if (sc.count > 0 && sc.items[sc.count - 1].frame >= (uint32_t)frames) {
        fprintf(stderr, "%s:%u: frame %u is not below --frames %ld\n", script_path, sc.items[sc.count - 1].line,
                sc.items[sc.count - 1].frame, frames);
        return EXIT_BAD;
    }

    scene_text = read_file(scene_path, &scene_size);
    if (scene_text == NULL) return EXIT_BAD;
    r = pg_scene_read_def((const char *)scene_text, scene_size, &def, &se);
    if (r != PG_OK) {
        fprintf(stderr, "%s: %s\n", scene_path, se.message);
        return EXIT_BAD;
    }
    memory_size = pg_world_memory_size(&def);
    if (memory_size == 0) {
        fprintf(stderr, "%s: the world settings are invalid\n", scene_path);
        return EXIT_BAD;
    }
    memory = xmalloc(memory_size);
    if ((r = pg_world_create(&def, memory, memory_size, &world)) != PG_OK ||
        (r = pg_scene_load(world, (const char *)scene_text, scene_size, &se)) != PG_OK) {
        fprintf(stderr, "%s: cannot load the scene: %s (%s)\n", scene_path, pg_result_name(r), se.message);
        return EXIT_BAD;
    }

    {   /* a scene without capacities holds exactly its own bodies and shapes: say so
         * before the script's makes fail for want of room */
        uint32_t bodies = 0, shapes = 0;
        pg_world_stats st = pg_world_get_stats(world);
        size_t k;
        for (k = 0; k < sc.count; ++k) {
            const pg_command *c = &sc.items[k].cmd;
            if (c->kind == PG_CMD_CREATE_BODY) bodies++;
            if (c->kind == PG_CMD_MAKE) bodies++, shapes += c->make_kind == PG_MAKE_STAR ? 2u : 1u;
            if (c->kind == PG_CMD_ADD_SHAPE) shapes++;
        }
        if (st.body_count + bodies > def.max_bodies || st.shape_count + shapes > def.max_shapes)
            fprintf(stderr,
                    "%s: note: the scene has %u bodies and %u shapes with room for %u and %u (max_bodies, max_shapes; a "
                    "scene that gives none has room for its own only); the script makes up to %u bodies and %u shapes, "
                    "so some will fail with PG_ERR_CAPACITY: add max_bodies and max_shapes lines to the scene to make room\n",
                    scene_path, st.body_count, st.shape_count, def.max_bodies, def.max_shapes, bodies, shapes);
    }

    memset(&t, 0, sizeof t);
    t.slots = def.max_bodies;
    t.gen = (uint32_t *)xmalloc(sizeof(uint32_t) * t.slots);
    for (i = 0; i < t.slots; ++i) {
        pg_body_id id;
        id.index = i;
        id.generation = 1;
        t.gen[i] = pg_body_is_valid(world, id) ? 1u : 0u;
    }

    begin_growing(&w, &gb, (const char *)scene_text, scene_size, (uint32_t)interval);
    WRITE_GROWING(&w, &gb, pg_replay_writer_add_checkpoint_world(&w, world));
    for (f = 0; f < (uint32_t)frames; ++f) {
        size_t first = next, n;
        while (next < sc.count && sc.items[next].frame == f) ++next;
        n = next - first;
        if (n > PG_REPLAY_MAX_FRAME_COMMANDS) {
            fprintf(stderr, "%s: frame %u has %zu commands (at most %u)\n", script_path, f, n, PG_REPLAY_MAX_FRAME_COMMANDS);
            return EXIT_BAD;
        }
        if (n > cmds_cap) {
            cmds_cap = n;
            cmds = (pg_command *)xrealloc(cmds, sizeof(pg_command) * cmds_cap);
        }
        /* Resolve and apply in order: a later command may name a body an earlier one made. */
        for (i = 0; i < n; ++i) {
            script_cmd *c = &sc.items[first + i];
            pg_body_id created, body_a = {0, 0}, body_b = {0, 0};
            pg_joint_id made_joint;
            if (c->cmd.kind >= PG_CMD_CREATE_DISTANCE_JOINT) { /* a joint's bodies are in its def */
                body_ref r1 = c->ref, r2 = c->ref2;
                script_cmd tmp = *c;
                if (!resolve(&sc, c, &t, &body_a)) return EXIT_BAD;
                tmp.ref = r2;
                if (!resolve(&sc, &tmp, &t, &body_b)) return EXIT_BAD;
                (void)r1;
                switch (c->cmd.kind) {
                case PG_CMD_CREATE_DISTANCE_JOINT: c->cmd.joint_def.distance.body_a = body_a, c->cmd.joint_def.distance.body_b = body_b; break;
                case PG_CMD_CREATE_REVOLUTE_JOINT: c->cmd.joint_def.revolute.body_a = body_a, c->cmd.joint_def.revolute.body_b = body_b; break;
                case PG_CMD_CREATE_WELD_JOINT: c->cmd.joint_def.weld.body_a = body_a, c->cmd.joint_def.weld.body_b = body_b; break;
                case PG_CMD_CREATE_PRISMATIC_JOINT: c->cmd.joint_def.prismatic.body_a = body_a, c->cmd.joint_def.prismatic.body_b = body_b; break;
                case PG_CMD_CREATE_MOUSE_JOINT: c->cmd.joint_def.mouse.body = body_a; break;
                default: if (!resolve_joint(&sc, c, &t, &c->cmd.joint)) return EXIT_BAD; break;
                }
            } else if (!resolve(&sc, c, &t, &c->cmd.body)) {
                return EXIT_BAD;
            }
            cmds[i] = c->cmd;
            r = pg_command_apply_made(world, &cmds[i], &created, &made_joint);
            if (r != PG_OK) {
                failures++;
                fprintf(stderr, "%s:%u: note: frame %u: %s fails: %s (recorded anyway: it fails the same on replay)\n",
                        script_path, c->line, f, pg_command_kind_name(c->cmd.kind), pg_world_last_error(world));
                continue;
            }
            if (c->cmd.kind >= PG_CMD_CREATE_DISTANCE_JOINT && c->cmd.kind <= PG_CMD_CREATE_MOUSE_JOINT) {
                if (t.joint_count == t.joint_cap) {
                    t.joint_cap = t.joint_cap ? t.joint_cap * 2 : 16;
                    t.joints = (pg_joint_id *)xrealloc(t.joints, sizeof(pg_joint_id) * t.joint_cap);
                }
                t.joints[t.joint_count++] = made_joint;
            } else if (c->cmd.kind == PG_CMD_CREATE_BODY || c->cmd.kind == PG_CMD_MAKE) {
                if (t.made_count == t.made_cap) {
                    t.made_cap = t.made_cap ? t.made_cap * 2 : 16;
                    t.made = (pg_body_id *)xrealloc(t.made, sizeof(pg_body_id) * t.made_cap);
                }
                t.made[t.made_count++] = created;
                if (created.index < t.slots) t.gen[created.index] = created.generation;
            } else if (c->cmd.kind == PG_CMD_DESTROY_BODY && c->cmd.body.index < t.slots) {
                t.gen[c->cmd.body.index] = 0;
            }
        }
        WRITE_GROWING(&w, &gb, pg_replay_writer_add_frame(&w, cmds, (uint32_t)n));
        pg_world_step(world);
        if (pg_replay_writer_checkpoint_due(&w)) WRITE_GROWING(&w, &gb, pg_replay_writer_add_checkpoint_world(&w, world));
    }
    WRITE_GROWING(&w, &gb, pg_replay_writer_finish(&w, pg_world_hash(world), &size));
    if (!write_file(out_path, gb.data, size)) return EXIT_BAD;
    printf("%s: %ld frames, %zu commands (%u fail as recorded), checkpoint every %ld, %zu bytes, final hash %016llx\n",
           out_path, frames, sc.count, failures, interval, size, (unsigned long long)pg_world_hash(world));
    free(gb.data);
    free(cmds);
    free(t.gen);
    free(t.made);
    free(t.joints);
    free(sc.items);
    free(memory);
    free(scene_text);
    return 0;
}

/* ---- main ------------------------------------------------------------------------------ */
static void usage(FILE *out)
{
    fprintf(out,
            "usage:\n"
            "  pogon-replay verify FILE...\n"
            "  pogon-replay info FILE\n"
            "  pogon-replay record --scene SCENE --frames N [--script SCRIPT] [--checkpoint K] -o FILE\n"
            "  pogon-replay rehash FILE...\n"
            "  pogon-replay upgrade IN OUT\n"
            "  pogon-replay synctest FILE... --rollback K\n"
            "exit status: 0 ok, 1 diverged, 2 bad file or usage\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return EXIT_BAD;
    }
    if (strcmp(argv[1], "verify") == 0) return cmd_verify(argc - 2, argv + 2);
    if (strcmp(argv[1], "info") == 0) return cmd_info(argc - 2, argv + 2);
    if (strcmp(argv[1], "record") == 0) return cmd_record(argc - 2, argv + 2);
    if (strcmp(argv[1], "rehash") == 0) return cmd_rehash(argc - 2, argv + 2);
    if (strcmp(argv[1], "upgrade") == 0) return cmd_upgrade(argc - 2, argv + 2);
    if (strcmp(argv[1], "synctest") == 0) return cmd_synctest(argc - 2, argv + 2);
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "pogon-replay: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return EXIT_BAD;
}
