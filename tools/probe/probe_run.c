/* probe_run.c — the scenes pogon-probe steps, their hashes, and the verification of a
 * replay held in memory (probe_run.h). The output format is described in probe.c.
 * Portable C99 and free of 64-bit printf conversions, for newlib-nano. */
#include "probe_run.h"
#include "scenes.h"
#include "pogon/replay.h"
#include "pogon/replay_file.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ALL PG_EFFECTS_ALL
const probe_scene PROBE_SCENES[] = {
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
const size_t PROBE_SCENE_COUNT = sizeof PROBE_SCENES / sizeof PROBE_SCENES[0];

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
    fputs(" world=", stdout);
    print_hex64(pg_world_hash(world));
    putchar('\n');
    return 1;
}

int probe_run_scene(const probe_scene *sc, uint32_t every)
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

/* The replay reader's work area, static: the firmware (ports/cortex-m) runs this code on
 * a microcontroller's stack, which the `_in` calls keep under 4 KiB (docs/embedded.md). */
static uint64_t replay_work[PG_REPLAY_WORK_BYTES / 8u];

/* Like `pogon-replay verify`: frames, checkpoints, mismatches and the final hash, so a
 * target that diverges prints a different line. */
int probe_verify_replay(const char *name, const uint8_t *data, size_t size)
{
    void *memory = NULL;
    size_t need = 0;
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player player;
    pg_replay_frame_result fr;
    uint32_t mismatches = 0;
    uint64_t final_hash;
    int ok;
    if (pg_replay_read_in(data, size, &info, &err, replay_work, sizeof replay_work) != PG_OK) goto unplayable;
    if (pg_replay_world_memory_size_in(&info, &need, &err, replay_work, sizeof replay_work) != PG_OK) goto unplayable;
    memory = malloc(need);
    if (memory == NULL ||
        pg_replay_player_begin_in(&player, data, &info, memory, need, &fr, &err, replay_work, sizeof replay_work) != PG_OK)
        goto unplayable;
    if (!fr.match) ++mismatches;
    while (!pg_replay_player_done(&player)) {
        if (pg_replay_player_step(&player, &fr) != PG_OK) goto unplayable;
        if (fr.checkpoint && !fr.match) ++mismatches;
    }
    final_hash = pg_world_hash(player.world);
    ok = mismatches == 0 && final_hash == info.final_hash;
    printf("replay %s frames %lu checkpoints %lu mismatches %lu final ", name, (unsigned long)info.frame_count,
           (unsigned long)info.checkpoint_count, (unsigned long)mismatches);
    print_hex64(final_hash);
    fputs(ok ? " OK\n" : " DIVERGED\n", stdout);
    free(memory);
    return ok;
unplayable:
    printf("replay %s could not be played\n", name);
    free(memory);
    return 0;
}
