/* headless_record.c — record a session from a scene and an input script, no window.
 *
 * The script's events go through the same app calls as the window's input, so a
 * headless recording is a desktop session without the clock: tick T's events, then
 * pga_frame(). The file is written the way the window writes it (recorder.c).
 */
#include "headless_record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file_io.h"
#include "input_script.h"
#include "recorder.h"
#include "scene_name.h"

#define EXIT_BAD 2

int desktop_headless_record(const desktop_options *o)
{
    uint8_t *scene = NULL, *script_text = NULL;
    size_t scene_size = 0, script_size = 0, next = 0;
    desktop_script script = {NULL, 0};
    desktop_recorder rec;
    char why[400], name[128];
    pga_app *app;
    uint32_t tick;
    int ok;
    if (!desktop_read_file(o->scene_path, &scene, &scene_size, why, sizeof why)) {
        fprintf(stderr, "pogon-desktop: %s\n", why);
        return EXIT_BAD;
    }
    if (o->script_path != NULL) {
        if (!desktop_read_file(o->script_path, &script_text, &script_size, why, sizeof why)) {
            fprintf(stderr, "pogon-desktop: %s\n", why);
            free(scene);
            return EXIT_BAD;
        }
        if (!desktop_script_parse((const char *)script_text, script_size, &script, why, sizeof why)) {
            fprintf(stderr, "pogon-desktop: %s:%s\n", o->script_path, why);
            free(scene);
            free(script_text);
            return EXIT_BAD;
        }
        free(script_text);
    }
    app = pga_create();
    if (app == NULL) {
        fprintf(stderr, "pogon-desktop: out of memory\n");
        free(scene);
        desktop_script_free(&script);
        return EXIT_BAD;
    }
    desktop_scene_name(o->scene_path, name, sizeof name);
    if (pga_load_scene(app, name, (const char *)scene, scene_size) != PG_OK) {
        fprintf(stderr, "pogon-desktop: %s: %s\n", o->scene_path, pga_message(app));
        free(scene);
        desktop_script_free(&script);
        pga_destroy(app);
        return EXIT_BAD;
    }
    free(scene);
    if (o->effects != NULL) {
        desktop_event e;
        char line[200];
        desktop_script one;
        snprintf(line, sizeof line, "0 effects %s\n", o->effects);
        if (!desktop_script_parse(line, strlen(line), &one, why, sizeof why) || one.count != 1) {
            fprintf(stderr, "pogon-desktop: --effects %s: %s\n", o->effects, why);
            desktop_script_free(&script);
            pga_destroy(app);
            return EXIT_BAD;
        }
        e = one.events[0];
        desktop_script_free(&one);
        desktop_event_apply(app, &e);
    }
    desktop_recorder_start(&rec, o->output_path, o->quiet);
    for (tick = 0; tick < o->frames; ++tick) {
        uint32_t serial = pga_message_serial(app);
        while (next < script.count && script.events[next].tick == tick) {
            /* A preset restarts the app's recording: write the one that ends here first. */
            if (script.events[next].kind == DESKTOP_EV_PRESET) desktop_recorder_tick(&rec, app, tick / 60.0, 1);
            desktop_event_apply(app, &script.events[next]);
            if (!o->quiet && pga_message_serial(app) != serial) {
                printf("tick %u (line %d): %s\n", tick, script.events[next].line, pga_message(app));
                serial = pga_message_serial(app);
            }
            next++;
        }
        pga_frame(app);
    }
    if (next < script.count)
        printf("pogon-desktop: %zu events at tick %u and later were not reached (--frames %u)\n", script.count - next,
               script.events[next].tick, o->frames);
    ok = desktop_recorder_finish(&rec, app, 0.0);
    desktop_script_free(&script);
    pga_destroy(app);
    return ok ? 0 : EXIT_BAD;
}
