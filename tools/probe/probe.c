/* probe.c — pogon-probe: runs the named scenes and prints one hash per scene, so that
 * builds for different compilers, optimisation levels and CPUs can be compared bit for
 * bit (tests/targets: the determinism_* tests).
 *
 * Usage: pogon-probe [--every N] [--list] [--corpus LIST] [SCENE...]
 *   SCENE     one or more labels from the table in probe_run.c (default: all of them)
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
 * The scenes, the hashes and the replay check are in probe_run.c, which the Cortex-M
 * firmware (ports/cortex-m) shares; this file is the host's part: arguments and files.
 * Portable C99 on purpose: it is built for wasm32, 32-bit ARM and big-endian s390x by
 * tests/targets/build_and_run.sh with nothing but a C compiler. */
#include "probe_run.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(POGON_PROBE_CORPUS_LIST) && !defined(POGON_PROBE_REPLAY)
#define POGON_PROBE_REPLAY 1
#endif
#ifndef POGON_PROBE_CORPUS_LIST
#define POGON_PROBE_CORPUS_LIST NULL
#endif

#if POGON_PROBE_REPLAY
/* Read one replay of the regression corpus and verify it (probe_verify_replay). */
static int verify_replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *data = NULL;
    long size = -1;
    const char *name = strrchr(path, '/') != NULL ? strrchr(path, '/') + 1 : path;
    int ok = 0;
    if (f != NULL && fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
        data = (uint8_t *)malloc((size_t)size + 1u);
        if (data != NULL && fread(data, 1, (size_t)size, f) == (size_t)size) {
            ok = probe_verify_replay(name, data, (size_t)size);
        } else {
            printf("replay %s could not be played\n", name);
        }
    } else {
        printf("replay %s could not be played\n", name);
    }
    if (f != NULL) fclose(f);
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
        if (!verify_replay_file(line)) ok = 0;
        fflush(stdout);
    }
    fclose(list);
    return ok;
}
#endif

int main(int argc, char **argv)
{
    unsigned char selected[PROBE_SCENE_MAX];
    uint32_t every = 0;
    const char *corpus = POGON_PROBE_CORPUS_LIST;
    int any = 0, i, status = 0;
    size_t k;
    memset(selected, 0, sizeof selected);
    if (PROBE_SCENE_COUNT > PROBE_SCENE_MAX) {
        fprintf(stderr, "pogon-probe: %lu scenes, PROBE_SCENE_MAX is %d\n", (unsigned long)PROBE_SCENE_COUNT, PROBE_SCENE_MAX);
        return 2;
    }
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--list") == 0) {
            for (k = 0; k < PROBE_SCENE_COUNT; ++k) printf("%s\n", PROBE_SCENES[k].label);
            return 0;
        } else if (strcmp(argv[i], "--every") == 0 && i + 1 < argc) {
            every = (uint32_t)strtoul(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--corpus") == 0 && i + 1 < argc) {
            corpus = argv[++i];
        } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            printf("usage: pogon-probe [--every N] [--list] [--corpus LIST] [SCENE...]\n");
            return 0;
        } else {
            for (k = 0; k < PROBE_SCENE_COUNT; ++k) {
                if (strcmp(argv[i], PROBE_SCENES[k].label) == 0) break;
            }
            if (k == PROBE_SCENE_COUNT) {
                fprintf(stderr, "pogon-probe: unknown scene '%s' (--list shows them)\n", argv[i]);
                return 2;
            }
            selected[k] = 1;
            any = 1;
        }
    }
    for (k = 0; k < PROBE_SCENE_COUNT; ++k) {
        if (any && !selected[k]) continue;
        if (!probe_run_scene(&PROBE_SCENES[k], every)) status = 1;
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
