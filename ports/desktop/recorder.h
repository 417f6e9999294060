/* recorder.h — keep the app's recording on disk while the program runs.
 *
 * Once a second (and at the end) the app's finished recording (pga_recording) is
 * written to FILE.tmp and renamed over FILE, so a kill, a crash or a closed window
 * loses at most the last second and always leaves a whole replay file. When the app
 * restarts its recording (another scene, a preset), the file so far is kept and the
 * new session goes to FILE-2.pgr, FILE-3.pgr, ... No file is written before the first
 * live frame (a window opened only to play a replay leaves none).
 */
#ifndef DESKTOP_RECORDER_H
#define DESKTOP_RECORDER_H

#include <stdint.h>

#include "pogon_app.h"

typedef struct desktop_recorder {
    char base[1024];        /* the path given, without a trailing .pgr */
    char path[1040];        /* the file being written now */
    int segment;            /* 1 for the first file */
    uint64_t scene_hash;    /* of the scene text of the recording being written */
    uint32_t frames;        /* frames of the recording last written */
    double last_write;      /* seconds (the caller's clock) */
    int written;            /* a file has been written for this segment */
    int quiet;
} desktop_recorder;

/* `path` NULL: pogon-session-YYYYMMDD-HHMMSS.pgr in the current directory. Prints the name. */
void desktop_recorder_start(desktop_recorder *r, const char *path, int quiet);
/* Write when a second has passed since the last write (or `force`). Returns 0 and
 * prints why when a write failed. */
int desktop_recorder_tick(desktop_recorder *r, pga_app *app, double now, int force);
/* The last write, and the names of the files written. */
int desktop_recorder_finish(desktop_recorder *r, pga_app *app, double now);

#endif
