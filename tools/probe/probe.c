/* probe.c — pogon-probe: runs the named scenes and prints one hash per scene, so that
 * builds for different compilers, optimisation levels and CPUs can be compared bit for
 * bit (tests/targets: the determinism_* tests).
 *
 * Usage: pogon-probe [--every N] [--list] [--corpus LIST] [SCENE...]
 *   SCENE     one or more labels from the table below (default: all of them)
 *   --every N also print a line every N steps (to find the first step that differs)
 *   --list    print the labels and exit
 *   --corpus LIST  after the scenes, verify the replay files named in LIST (one path a
 *             line) against their checkpoints: a line "replay NAME ... OK" each. Default:
 *             POGON_PROBE_CORPUS_LIST (set for the native build by tools/CMakeLists.txt;
 *             the determinism_* builds pass the list at run time instead, so their
 *             compile command, and so the programs, are the same in every build tree).
 *             Needs POGON_PROBE_REPLAY (implied by POGON_PROBE_CORPUS_LIST).
 *
 * Output, one line per scene (and per checkpoint with --every):
 *   LABEL COUNT STEPS HASH [world=WORLDHASH]
 * HASH is FNV-1a 64 over, for every body slot in index order, the body's position x, y,
 * angle, linear velocity x, y and angular velocity, each written as 4 little-endian
 * bytes (explicitly, never the memory of a struct, so byte order and padding do not
 * matter). WORLDHASH is pg_world_hash() (include/pogon/replay.h: the whole state, also
 * contacts and sleep timers) when the library has it (POGON_PROBE_HAVE_WORLD_HASH,
 * set by tools/CMakeLists.txt and tests/targets from the library's sources).
 *
 * Portable C99 on purpose: it is built for wasm32, 32-bit ARM and big-endian s390x by
 * tests/targets/build_and_run.sh with nothing but a C compiler. */
#include "pogon/pogon.h"
#include "scenes.h"
#if POGON_PROBE_HAVE_WORLD_HASH
#include "pogon/replay.h"
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct probe_scene {
    const char *label;
    const char *scene;   /* pg_scene_build name */
    uint32_t count;
    uint32_t steps;
    uint32_t effects;
} probe_scene;

#define ALL PG_EFFECTS_ALL
static const probe_scene SCENES[] = {
    {"pyramid", "pyramid", 20, 600, ALL},
    {"stack", "stack", 20, 600, ALL},
    {"rain", "rain", 1000, 300, ALL},
    /* effect subsets, each taking other paths through the step (smaller rain: these
     * run under qemu too, and the whole determinism_* set should stay well below a
     * minute per build) */
    {"rain-gravity-only", "rain", 300, 300, PG_EFFECT_GRAVITY},
    {"rain-no-rotation", "rain", 300, 300, ALL & ~PG_EFFECT_ROTATION},
    {"rain-no-friction", "rain", 300, 300, ALL & ~PG_EFFECT_FRICTION},
    {"rain-no-sleeping", "rain", 300, 300, ALL & ~PG_EFFECT_SLEEPING},
    {"rain-no-continuous", "rain", 300, 300, ALL & ~PG_EFFECT_CONTINUOUS},
    {"pyramid-no-friction", "pyramid", 20, 300, ALL & ~PG_EFFECT_FRICTION},
    {"pyramid-no-sleeping", "pyramid", 20, 300, ALL & ~PG_EFFECT_SLEEPING},
};
#define SCENE_COUNT (sizeof SCENES / sizeof SCENES[0])

#define FNV_OFFSET 0xcbf29ce484222325ull
#define FNV_PRIME 0x100000001b3ull

static uint64_t fnv_u32(uint64_t h, uint32_t v)
{
    int i;
    for (i = 0; i < 4; ++i) {               /* little-endian: low byte first */
        h ^= (uint64_t)((v >> (8 * i)) & 0xFFu);
        h *= FNV_PRIME;
    }
    return h;
}

static uint64_t fnv_fix(uint64_t h, pg_fix v) { return fnv_u32(h, (uint32_t)v); }

/* Body hash over every live body. The scenes never destroy a body, so body slot i holds
 * generation 1 (the first use of a slot); the count is checked against the world's stats
 * so a body that would be missed is an error, not a silently weaker hash. */
static int body_hash(const pg_world *world, uint64_t *out)
{
    pg_world_def def = pg_world_get_def(world);
    pg_world_stats stats = pg_world_get_stats(world);
    uint64_t h = FNV_OFFSET;
    uint32_t i, found = 0;
    for (i = 0; i < def.max_bodies; ++i) {
        pg_body_id id;
        pg_vec2 p, v;
        id.index = i;
        id.generation = 1;
        if (!pg_body_is_valid(world, id)) continue;
        p = pg_body_position(world, id);
        v = pg_body_linear_velocity(world, id);
        h = fnv_u32(h, i);
        h = fnv_fix(h, p.x);
        h = fnv_fix(h, p.y);
        h = fnv_u32(h, pg_body_angle(world, id));
        h = fnv_fix(h, v.x);
        h = fnv_fix(h, v.y);
        h = fnv_fix(h, pg_body_angular_velocity(world, id));
        ++found;
    }
    *out = h;
    return found == stats.body_count;
}

static void print_hex64(uint64_t v)
{
    char s[17];
    int i;
    for (i = 15; i >= 0; --i) {
        s[i] = "0123456789abcdef"[v & 0xFu];
        v >>= 4;
    }
    s[16] = '\0';
    fputs(s, stdout);
}

static int print_line(const probe_scene *sc, const pg_world *world, uint32_t steps)
{
    uint64_t h;
    if (!body_hash(world, &h)) {
        fprintf(stderr, "pogon-probe: %s: bodies are not in slots 0.. with generation 1\n", sc->label);
        return 0;
    }
    printf("%s %lu %lu ", sc->label, (unsigned long)sc->count, (unsigned long)steps);
    print_hex64(h);
#if POGON_PROBE_HAVE_WORLD_HASH
    fputs(" world=", stdout);
    print_hex64(pg_world_hash(world));
#endif
    putchar('\n');
    return 1;
}

static int run(const probe_scene *sc, uint32_t every)
{
    pg_world_def def = pg_scene_world_def(sc->scene, sc->count);
    size_t size;
    void *memory;
    pg_scene scene;
    pg_result r;
    uint32_t step;
    int ok = 1;
    def.effects = sc->effects;
    size = pg_scene_memory_size(sc->scene, sc->count, &def);
    memory = malloc(size);
    if (memory == NULL) {
        fprintf(stderr, "pogon-probe: %s: out of memory (%lu bytes)\n", sc->label, (unsigned long)size);
        return 0;
    }
    r = pg_scene_build(sc->scene, sc->count, &def, memory, size, &scene);
    if (r != PG_OK) {
        fprintf(stderr, "pogon-probe: %s: scene build failed: %s\n", sc->label, pg_result_name(r));
        free(memory);
        return 0;
    }
    for (step = 1; ok && step <= sc->steps; ++step) {
        r = pg_world_step(scene.world);
        if (r != PG_OK) {
            fprintf(stderr, "pogon-probe: %s: step %lu failed: %s\n", sc->label, (unsigned long)step, pg_result_name(r));
            ok = 0;
        } else if (every != 0 && step % every == 0 && step != sc->steps) {
            ok = print_line(sc, scene.world, step);
        }
    }
    if (ok) ok = print_line(sc, scene.world, sc->steps);
    free(memory);
    return ok;
}

#if defined(POGON_PROBE_CORPUS_LIST) && !defined(POGON_PROBE_REPLAY)
#define POGON_PROBE_REPLAY 1
#endif
#ifndef POGON_PROBE_CORPUS_LIST
#define POGON_PROBE_CORPUS_LIST NULL
#endif

#if POGON_PROBE_REPLAY
#include "pogon/replay_file.h"
/* Verify one replay of the regression corpus against its recorded checkpoints, like
 * `pogon-replay verify`: prints frames, checkpoints, mismatches and the final hash, so
 * a target that diverges prints a different line (and the count says it failed). */
static int verify_replay(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *data = NULL;
    long size;
    void *memory = NULL;
    size_t need = 0;
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player player;
    pg_replay_frame_result fr;
    uint32_t mismatches = 0;
    const char *name = strrchr(path, '/') != NULL ? strrchr(path, '/') + 1 : path;
    int ok = 0;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) goto done;
    data = (uint8_t *)malloc((size_t)size + 1u);
    if (data == NULL || fread(data, 1, (size_t)size, f) != (size_t)size) goto done;
    if (pg_replay_read(data, (size_t)size, &info, &err) != PG_OK) goto done;
    if (pg_replay_world_memory_size(&info, &need, &err) != PG_OK) goto done;
    memory = malloc(need);
    if (memory == NULL || pg_replay_player_begin(&player, data, &info, memory, need, &fr, &err) != PG_OK) goto done;
    if (!fr.match) ++mismatches;
    while (!pg_replay_player_done(&player)) {
        if (pg_replay_player_step(&player, &fr) != PG_OK) goto done;
        if (fr.checkpoint && !fr.match) ++mismatches;
    }
    printf("replay %s frames %u checkpoints %u mismatches %u final %016llx %s\n", name, info.frame_count, info.checkpoint_count,
           mismatches, (unsigned long long)pg_world_hash(player.world), mismatches == 0 && pg_world_hash(player.world) == info.final_hash ? "OK" : "DIVERGED");
    ok = mismatches == 0 && pg_world_hash(player.world) == info.final_hash;
done:
    if (!ok && data != NULL && mismatches == 0) printf("replay %s could not be played\n", name);
    if (f != NULL) fclose(f);
    free(memory);
    free(data);
    return ok;
}

static int verify_corpus(const char *list_path)
{
    FILE *list = fopen(list_path, "r");
    char line[1024];
    int ok = 1;
    if (list == NULL) {
        printf("corpus list %s not found\n", list_path);
        return 0;
    }
    while (fgets(line, sizeof line, list) != NULL) {
        size_t n = strlen(line);
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r')) line[--n] = '\0';
        if (n == 0) continue;
        if (!verify_replay(line)) ok = 0;
        fflush(stdout);
    }
    fclose(list);
    return ok;
}
#endif

int main(int argc, char **argv)
{
    unsigned char selected[SCENE_COUNT];
    uint32_t every = 0;
    const char *corpus = POGON_PROBE_CORPUS_LIST;
    int any = 0, i, status = 0;
    size_t k;
    memset(selected, 0, sizeof selected);
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--list") == 0) {
            for (k = 0; k < SCENE_COUNT; ++k) printf("%s\n", SCENES[k].label);
            return 0;
        } else if (strcmp(argv[i], "--every") == 0 && i + 1 < argc) {
            every = (uint32_t)strtoul(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--corpus") == 0 && i + 1 < argc) {
            corpus = argv[++i];
        } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            printf("usage: pogon-probe [--every N] [--list] [--corpus LIST] [SCENE...]\n");
            return 0;
        } else {
            for (k = 0; k < SCENE_COUNT; ++k) {
                if (strcmp(argv[i], SCENES[k].label) == 0) break;
            }
            if (k == SCENE_COUNT) {
                fprintf(stderr, "pogon-probe: unknown scene '%s' (--list shows them)\n", argv[i]);
                return 2;
            }
            selected[k] = 1;
            any = 1;
        }
    }
    for (k = 0; k < SCENE_COUNT; ++k) {
        if (any && !selected[k]) continue;
        if (!run(&SCENES[k], every)) status = 1;
        fflush(stdout);
    }
#if POGON_PROBE_REPLAY
    if (!any && corpus != NULL && !verify_corpus(corpus)) status = 1;
#else
    if (corpus != NULL) {
        fprintf(stderr, "pogon-probe: --corpus needs a build with POGON_PROBE_REPLAY\n");
        status = 1;
    }
#endif
    return status;
}
