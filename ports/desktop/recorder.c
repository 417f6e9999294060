/* recorder.c — see recorder.h. */
#define _POSIX_C_SOURCE 200809L
#include "recorder.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "file_io.h"

static void segment_path(desktop_recorder *r)
{
    if (r->segment <= 1) snprintf(r->path, sizeof r->path, "%s.pgr", r->base);
    else snprintf(r->path, sizeof r->path, "%s-%d.pgr", r->base, r->segment);
}

void desktop_recorder_start(desktop_recorder *r, const char *path, int quiet)
{
    size_t n;
    memset(r, 0, sizeof *r);
    r->quiet = quiet;
    r->segment = 1;
    if (path == NULL) {
        time_t t = time(NULL);
        struct tm tm_utc;
        char stamp[32];
        gmtime_r(&t, &tm_utc);
        strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm_utc);
        snprintf(r->base, sizeof r->base, "pogon-session-%s", stamp);
    } else {
        snprintf(r->base, sizeof r->base, "%s", path);
        n = strlen(r->base);
        if (n > 4 && strcmp(r->base + n - 4, ".pgr") == 0) r->base[n - 4] = '\0';
    }
    segment_path(r);
    printf("pogon-desktop: recording to %s\n", r->path);
    fflush(stdout);
}

int desktop_recorder_tick(desktop_recorder *r, pga_app *app, double now, int force)
{
    const uint8_t *data;
    size_t size;
    pg_replay_info info;
    pg_replay_error err;
    uint64_t scene_hash;
    char why[300];
    if (!force && now - r->last_write < 1.0) return 1;
    r->last_write = now;
    if (pga_recording(app, &data, &size) != PG_OK) {
        fprintf(stderr, "pogon-desktop: no recording to write: %s\n", pga_message(app));
        return 0;
    }
    if (pg_replay_read(data, size, &info, &err) != PG_OK) {
        fprintf(stderr, "pogon-desktop: the app's recording does not read back (offset %zu, %s %s: %s); not written\n",
                err.offset, err.region, err.field, err.message);
        return 0;
    }
    scene_hash = pg_hash_bytes(PG_HASH_SEED, info.scene_text, info.scene_size);
    if (!r->written && info.frame_count == 0) return 1; /* nothing played yet: leave no empty file */
    if (r->written && (scene_hash != r->scene_hash || info.frame_count < r->frames)) {
        /* A new recording: keep the file of the previous one and start the next. */
        r->segment++;
        segment_path(r);
        if (!r->quiet) printf("pogon-desktop: a new recording (scene or preset changed): now %s\n", r->path);
        fflush(stdout);
    }
    if (!desktop_write_file_atomic(r->path, data, size, why, sizeof why)) {
        fprintf(stderr, "pogon-desktop: %s\n", why);
        return 0;
    }
    r->scene_hash = scene_hash;
    r->frames = info.frame_count;
    r->written = 1;
    return 1;
}

int desktop_recorder_finish(desktop_recorder *r, pga_app *app, double now)
{
    int ok = desktop_recorder_tick(r, app, now, 1);
    if (!r->written) printf("pogon-desktop: nothing recorded (no frame was played live); %s not written\n", r->path);
    else if (r->segment == 1) printf("pogon-desktop: recorded %u frames to %s\n", r->frames, r->path);
    else printf("pogon-desktop: recorded %s.pgr .. %s (the last: %u frames)\n", r->base, r->path, r->frames);
    fflush(stdout);
    return ok;
}
