/* window.h — the SDL2 window: live play with recording, and replay playback. */
#ifndef DESKTOP_WINDOW_H
#define DESKTOP_WINDOW_H

#include "options.h"

/* Runs until the window is closed (or --bench seconds pass). Exit status 0, or 2 when
 * the window or the first scene or replay cannot be opened. */
int desktop_window_run(const desktop_options *o);

#endif
