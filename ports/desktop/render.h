/* render.h — draw a draw list (the app's or world_draw's) with SDL2_gfx. */
#ifndef DESKTOP_RENDER_H
#define DESKTOP_RENDER_H

#include <SDL.h>

#include "pogon_app.h"
#include "view.h"

void desktop_render_clear(SDL_Renderer *r);
void desktop_render_shapes(SDL_Renderer *r, const desktop_view *v, const pga_draw_shape *shapes, uint32_t count);
/* The points collected for a triangle or a wall, joined. */
void desktop_render_pending(SDL_Renderer *r, const desktop_view *v, const pg_vec2 *points, uint32_t count);

#endif
