/* headless_play.h — verify, jump in and check a replay file without a window. */
#ifndef DESKTOP_HEADLESS_PLAY_H
#define DESKTOP_HEADLESS_PLAY_H

#include "options.h"

/* Exit status: 0 every checkpoint matched, 1 one diverged (or an image check failed),
 * 2 the file is corrupt or unreadable. */
int desktop_headless_play(const desktop_options *o);

#endif
