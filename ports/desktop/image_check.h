/* image_check.h — does a screenshot show a world's bodies where the world has them? */
#ifndef DESKTOP_IMAGE_CHECK_H
#define DESKTOP_IMAGE_CHECK_H

#include <stddef.h>

#include "pogon/pogon.h"
#include "view.h"

/* Load the BMP at `path` (the program's F12 screenshot, drawn with `view`) and check
 * both ways: the pixel at each shape's centre, where no other body is, is not the
 * background, and pixels on a grid with no body within 3 px are the background (the
 * text overlay at the top is left out). Returns 1 when all agree; otherwise 0 and the
 * first disagreement in `report`. *checked receives the pixels compared. */
int desktop_check_image(const char *path, const desktop_view *view, const pg_world *world, char *report,
                        size_t report_capacity, unsigned *checked);

#endif
