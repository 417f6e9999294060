/* app_record_session — runs the scripted session of app_session.h on a scene and writes
 * the app's recording to a file, so the native pogon-replay can verify it.
 * Usage: app_record_session SCENE_FILE OUTPUT_FILE */
#include <stdio.h>
#include <stdlib.h>

#include "app_session.h"

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
    printf("%s: %lu bytes, %llu frames, final hash %016llx\n", argv[2], (unsigned long)size,
           (unsigned long long)pga_frame_number(app), (unsigned long long)pga_state_hash(app));
    pga_destroy(app);
    free(text);
    return 0;
}
