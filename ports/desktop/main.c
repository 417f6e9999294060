/* main.c — pogon-desktop: the playground in an SDL2 window, its recorder, a replay
 * player that can jump, and the same without a window for tests (docs/desktop.md). */
#include <stdio.h>

#include "headless_play.h"
#include "headless_record.h"
#include "options.h"
#include "window.h"

int main(int argc, char **argv)
{
    desktop_options o;
    int parsed = desktop_parse_options(argc, argv, &o);
    if (parsed == 2) return 0;
    if (parsed == 0) return 2;
    if (o.headless) return o.play_path != NULL ? desktop_headless_play(&o) : desktop_headless_record(&o);
    return desktop_window_run(&o);
}
