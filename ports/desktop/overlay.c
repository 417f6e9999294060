/* overlay.c — see overlay.h. */
#include "overlay.h"

#include <SDL2_gfxPrimitives.h>

#include "view.h"

void desktop_overlay_text(SDL_Renderer *r, int width, const char *const lines[], int count)
{
    int i;
    boxRGBA(r, 0, 0, (Sint16)(width - 1), (Sint16)(DESKTOP_OVERLAY_HEIGHT - 1), 30, 41, 59, 255);
    for (i = 0; i < count && i < DESKTOP_OVERLAY_LINES; ++i)
        stringRGBA(r, 6, (Sint16)(4 + 10 * i), lines[i], 241, 245, 249, 255);
}

void desktop_overlay_timeline(SDL_Renderer *r, int width, int height, double done, double marker, uint32_t color)
{
    Sint16 top = (Sint16)(height - DESKTOP_TIMELINE_HEIGHT), bottom = (Sint16)(height - 1);
    if (done < 0.0) done = 0.0;
    if (done > 1.0) done = 1.0;
    boxRGBA(r, 0, top, (Sint16)(width - 1), bottom, 203, 213, 225, 255);
    boxRGBA(r, 0, top, (Sint16)((width - 1) * done), bottom, (Uint8)(color >> 16), (Uint8)(color >> 8), (Uint8)color, 255);
    if (marker >= 0.0 && marker <= 1.0)
        boxRGBA(r, (Sint16)((width - 3) * marker), top, (Sint16)((width - 3) * marker + 2), bottom, 15, 23, 42, 255);
}
