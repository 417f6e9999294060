/* app_record_session — runs the scripted session of app_session.h on a scene, writes the
 * app's recording to a file (for the native pogon-replay to verify), and replays it with
 * the core's player: exit 1 unless every checkpoint and the final hash match. Built for
 * wasm too, where it is the app's smoke test under node.
 * Usage: app_record_session SCENE_FILE OUTPUT_FILE */
#include <stdio.h>
#include <stdlib.h>

#include "app_session.h"

/* 1 when the file replays with every checkpoint matching and ends at `hash`. */
static int replays(const uint8_t *data, size_t size, uint64_t hash)
{
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    size_t need = 0;
    void *memory;
    int ok;
    if (pg_replay_read(data, size, &info, &err) != PG_OK || pg_replay_world_memory_size(&info, &need, &err) != PG_OK) {
        fprintf(stderr, "recording refused: offset %lu, %s: %s\n", (unsigned long)err.offset, err.field, err.message);
        return 0;
    }
    memory = malloc(need);
    if (memory == NULL || pg_replay_player_begin(&p, data, &info, memory, need, &fr, &err) != PG_OK) return 0;
    ok = fr.match;
    while (ok && !pg_replay_player_done(&p)) ok = pg_replay_player_step(&p, &fr) == PG_OK && fr.match;
    ok = ok && pg_world_hash(p.world) == hash && p.checkpoints_checked == info.checkpoint_count;
    if (!ok) fprintf(stderr, "recording DIVERGED at frame %u\n", p.frame);
    free(memory);
    return ok;
}

int main(int argc, char **argv)
{
    FILE *f;
    char *text;
    long n;
    pga_app *app;
    const uint8_t *rec;
    size_t size;
    if (argc != 3) {
        fprintf(stderr, "usage: app_record_session SCENE_FILE OUTPUT_FILE\n");
        return 2;
    }
    f = fopen(argv[1], "rb");
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fprintf(stderr, "%s: cannot read\n", argv[1]);
        return 2;
    }
    text = (char *)malloc((size_t)n + 1);
    if (text == NULL || fread(text, 1, (size_t)n, f) != (size_t)n) return 2;
    fclose(f);
    app = pga_create();
    if (app == NULL || pga_load_scene(app, "session", text, (size_t)n) != PG_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], app != NULL ? pga_message(app) : "out of memory");
        return 1;
    }
    app_session_run(app);
    if (pga_recording(app, &rec, &size) != PG_OK) {
        fprintf(stderr, "no recording: %s\n", pga_message(app));
        return 1;
    }
    f = fopen(argv[2], "wb");
    if (f == NULL || fwrite(rec, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "%s: cannot write\n", argv[2]);
        return 2;
    }
    if (!replays(rec, size, pga_state_hash(app))) return 1;
    printf("%s: %lu bytes, %llu frames, every checkpoint replays, final hash %016llx\n", argv[2], (unsigned long)size,
           (unsigned long long)pga_frame_number(app), (unsigned long long)pga_state_hash(app));
    pga_destroy(app);
    free(text);
    return 0;
}
