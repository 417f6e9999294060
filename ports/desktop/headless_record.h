/* headless_record.h — `--headless --scene FILE [--script FILE] --frames N -o FILE`. */
#ifndef DESKTOP_HEADLESS_RECORD_H
#define DESKTOP_HEADLESS_RECORD_H

#include "options.h"

/* Exit status 0, or 2 for an unreadable scene or script, or a file not written. */
int desktop_headless_record(const desktop_options *o);

#endif
