/* firmware.c — the hash-check firmware: pogon-probe on a Cortex-M.
 *
 * Steps the probe's named scenes and verifies the replay corpus compiled into the image
 * (replay_corpus.c), printing through semihosting exactly the lines the native
 * pogon-probe prints (probe_run.c is shared), so that the cortex_m_* tests compare the
 * two outputs line by line. Exit status 0 when every scene stepped and every replay
 * verified.
 *
 * POGON_FIRMWARE_MAX_COUNT (optional) leaves out the scenes whose count is above it: the
 * Cortex-M0+ test skips rain 1000, the one scene that takes most of a slow core's run
 * (the five rain 300 variants take the same paths). */
#include "probe_run.h"
#include "replay_corpus.h"
#include <stdio.h>

int main(void)
{
    int status = 0;
    size_t k;
    for (k = 0; k < PROBE_SCENE_COUNT; ++k) {
#ifdef POGON_FIRMWARE_MAX_COUNT
        if (PROBE_SCENES[k].count > POGON_FIRMWARE_MAX_COUNT) continue;
#endif
        if (!probe_run_scene(&PROBE_SCENES[k], 0)) status = 1;
        fflush(stdout);
    }
    for (k = 0; k < PG_EMBEDDED_REPLAY_COUNT; ++k) {
        const pg_embedded_replay *r = &PG_EMBEDDED_REPLAYS[k];
        if (!probe_verify_replay(r->name, r->data, r->size)) status = 1;
        fflush(stdout);
    }
    return status;
}
