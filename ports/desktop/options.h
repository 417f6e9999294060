/* options.h — the desktop program's command line (usage text in options.c). */
#ifndef DESKTOP_OPTIONS_H
#define DESKTOP_OPTIONS_H

#include <stdint.h>

#define DESKTOP_MAX_JUMPS 16

typedef struct desktop_options {
    int headless;
    const char *scene_path;      /* --scene: the scene to start from (live mode) */
    const char *script_path;     /* --script: input events by frame (headless recording) */
    const char *output_path;     /* -o: the replay file recorded */
    const char *play_path;       /* --play or a lone FILE.pgr: play a replay */
    uint32_t frames;             /* --frames: frames to record headless */
    int frames_given;
    uint32_t jumps[DESKTOP_MAX_JUMPS]; /* --jump F (repeatable): headless jumps after playing through */
    int jump_count;
    int64_t until;               /* --until F: play straight to frame F only (-1: to the end) */
    const char *check_image;     /* --check-image BMP: with --until, the screenshot to compare */
    const char *screenshot_path; /* --screenshot BMP: where F12 writes (frame number appended) */
    int width, height;           /* --size WxH of the window, default 960x600 */
    double view_x, view_y, view_scale; /* --view X Y PX: world point at the window centre, pixels per metre */
    double bench_seconds;        /* --bench S: run unthrottled S seconds and print frames per second */
    const char *effects;         /* --effects LIST: set at start (e.g. all-sleeping) */
    int quiet;
} desktop_options;

/* Parse argv; returns 0 (after printing a message) on a usage error, 2 for --help. */
int desktop_parse_options(int argc, char **argv, desktop_options *o);
void desktop_print_usage(void);

#endif
