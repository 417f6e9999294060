/* overlay.h — the text band at the top of the window and the playback timeline. */
#ifndef DESKTOP_OVERLAY_H
#define DESKTOP_OVERLAY_H

#include <SDL.h>

#include "view.h"

/* DESKTOP_OVERLAY_LINES lines of text (SDL2_gfx's 8x8 font) on a band across the top. */
void desktop_overlay_text(SDL_Renderer *r, int width, const char *const lines[], int count);
/* A bar across the bottom, filled to frame/total; `marker` (a fraction, or < 0 for none)
 * draws the target of a jump in progress. The bar's height is DESKTOP_TIMELINE_HEIGHT. */
void desktop_overlay_timeline(SDL_Renderer *r, int width, int height, double done, double marker, uint32_t color);

#endif
