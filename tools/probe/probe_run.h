/* probe_run.h — what pogon-probe prints, without the host around it: the named scenes
 * and their hashes, and the verification of one replay file held in memory. Shared by
 * the native pogon-probe (probe.c: arguments, files) and the Cortex-M firmware
 * (ports/cortex-m/firmware.c: the corpus embedded in flash), so both print the same
 * lines by construction.
 *
 * Output goes through printf/fputs with no 64-bit conversion (%llx is wrong or missing
 * in newlib-nano): 64-bit hashes are formatted by hand. */
#ifndef POGON_PROBE_RUN_H
#define POGON_PROBE_RUN_H
#include "pogon/pogon.h"
#include <stddef.h>

typedef struct probe_scene {
    const char *label;
    const char *scene;   /* pg_scene_build name */
    uint32_t count;
    uint32_t steps;
    uint32_t effects;
} probe_scene;

/* The scenes in the order they are printed (at most PROBE_SCENE_MAX). */
#define PROBE_SCENE_MAX 32
extern const probe_scene PROBE_SCENES[];
extern const size_t PROBE_SCENE_COUNT;

/* Step one scene (world memory from malloc) and print its line, and one every `every`
 * steps when `every` is not 0. Returns 1 when every step succeeded. */
int probe_run_scene(const probe_scene *sc, uint32_t every);

/* Verify the replay file data[0..size) against its checkpoints and final hash and print
 * "replay NAME frames F checkpoints C mismatches M final HASH OK|DIVERGED", or
 * "replay NAME could not be played". Returns 1 when it verified. */
int probe_verify_replay(const char *name, const uint8_t *data, size_t size);

#endif
