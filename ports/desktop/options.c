/* options.c — command-line parsing for pogon-desktop. */
#include "options.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void desktop_print_usage(void)
{
    fputs("Usage:\n"
          "  pogon-desktop [--scene FILE] [-o REPLAY] [--effects LIST] [--size WxH] [--view X Y PX]\n"
          "      A window: play with the scene and record the session to REPLAY (default\n"
          "      pogon-session-TIME.pgr), rewritten once a second.\n"
          "  pogon-desktop [--play] REPLAY.pgr      a window playing a replay file\n"
          "  pogon-desktop --headless --scene FILE [--script FILE] --frames N -o REPLAY\n"
          "      Record without a window: the script's input events (docs/desktop.md).\n"
          "  pogon-desktop --headless --play REPLAY [--jump F]... [--until F [--check-image BMP]]\n"
          "      Verify a replay: exit 0 when every checkpoint matches, 1 when one diverged,\n"
          "      2 for a corrupt file or a usage error. --jump plays through, then jumps to F\n"
          "      (restoring a kept snapshot) and prints the hash there. --until plays straight\n"
          "      to frame F and prints the hash; with --check-image it checks that the\n"
          "      screenshot BMP shows each body where the replay has it at F.\n"
          "Other options: --screenshot BMP (F12 writes BMP-FRAME.bmp), --bench S (window:\n"
          "  unthrottled for S seconds, prints frames per second), --quiet.\n",
          stdout);
}

static int parse_u32(const char *s, uint32_t *out)
{
    char *end;
    unsigned long v;
    if (s == NULL || *s == '\0' || *s == '-') return 0;
    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno != 0 || *end != '\0' || v > 0xffffffffUL) return 0;
    *out = (uint32_t)v;
    return 1;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    if (s == NULL || *s == '\0') return 0;
    errno = 0;
    *out = strtod(s, &end);
    return errno == 0 && *end == '\0';
}

static int usage_error(const char *what, const char *arg)
{
    fprintf(stderr, "pogon-desktop: %s%s%s (try --help)\n", what, arg != NULL ? ": " : "", arg != NULL ? arg : "");
    return 0;
}

int desktop_parse_options(int argc, char **argv, desktop_options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->until = -1;
    o->width = 960;
    o->height = 600;
    o->view_x = 0.0;
    o->view_y = 9.0;
    o->view_scale = 22.0;
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            desktop_print_usage();
            return 2;
        } else if (strcmp(a, "--headless") == 0) {
            o->headless = 1;
        } else if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
        } else if (strcmp(a, "--scene") == 0 && next != NULL) {
            o->scene_path = argv[++i];
        } else if (strcmp(a, "--script") == 0 && next != NULL) {
            o->script_path = argv[++i];
        } else if (strcmp(a, "-o") == 0 && next != NULL) {
            o->output_path = argv[++i];
        } else if (strcmp(a, "--play") == 0 && next != NULL) {
            o->play_path = argv[++i];
        } else if (strcmp(a, "--screenshot") == 0 && next != NULL) {
            o->screenshot_path = argv[++i];
        } else if (strcmp(a, "--check-image") == 0 && next != NULL) {
            o->check_image = argv[++i];
        } else if (strcmp(a, "--effects") == 0 && next != NULL) {
            o->effects = argv[++i];
        } else if (strcmp(a, "--frames") == 0 && next != NULL) {
            if (!parse_u32(argv[++i], &o->frames)) return usage_error("--frames needs a whole number", argv[i]);
            o->frames_given = 1;
        } else if (strcmp(a, "--jump") == 0 && next != NULL) {
            if (o->jump_count >= DESKTOP_MAX_JUMPS) return usage_error("too many --jump (at most 16)", NULL);
            if (!parse_u32(argv[++i], &o->jumps[o->jump_count])) return usage_error("--jump needs a frame number", argv[i]);
            o->jump_count++;
        } else if (strcmp(a, "--until") == 0 && next != NULL) {
            uint32_t f;
            if (!parse_u32(argv[++i], &f)) return usage_error("--until needs a frame number", argv[i]);
            o->until = f;
        } else if (strcmp(a, "--size") == 0 && next != NULL) {
            if (sscanf(argv[++i], "%dx%d", &o->width, &o->height) != 2 || o->width < 320 || o->height < 240 ||
                o->width > 8192 || o->height > 8192)
                return usage_error("--size needs WxH, at least 320x240", argv[i]);
        } else if (strcmp(a, "--view") == 0 && i + 3 < argc) {
            if (!parse_double(argv[i + 1], &o->view_x) || !parse_double(argv[i + 2], &o->view_y) ||
                !parse_double(argv[i + 3], &o->view_scale) || o->view_scale <= 0.0)
                return usage_error("--view needs X Y PIXELS_PER_METRE", argv[i + 1]);
            i += 3;
        } else if (strcmp(a, "--bench") == 0 && next != NULL) {
            if (!parse_double(argv[++i], &o->bench_seconds) || o->bench_seconds <= 0.0)
                return usage_error("--bench needs seconds", argv[i]);
        } else if (a[0] != '-' && o->play_path == NULL) {
            o->play_path = a;
        } else {
            return usage_error("unknown option or missing value", a);
        }
    }
    if (o->headless) {
        if (o->play_path == NULL && (o->scene_path == NULL || !o->frames_given || o->output_path == NULL))
            return usage_error("--headless needs --play FILE, or --scene FILE --frames N -o FILE", NULL);
        if (o->play_path != NULL && (o->scene_path != NULL || o->script_path != NULL))
            return usage_error("--play does not take --scene or --script", NULL);
        if (o->check_image != NULL && o->until < 0) return usage_error("--check-image needs --until F", NULL);
    } else if (o->script_path != NULL || o->jump_count != 0 || o->until >= 0 || o->check_image != NULL) {
        return usage_error("--script, --jump, --until and --check-image are headless options", NULL);
    }
    return 1;
}
