/* render.h — draw a draw list (the app's or world_draw's) with SDL2_gfx. */
#ifndef DESKTOP_RENDER_H
#define DESKTOP_RENDER_H

#include <SDL.h>

#include "pogon_app.h"
#include "view.h"

void desktop_render_clear(SDL_Renderer *r);
void desktop_render_shapes(SDL_Renderer *r, const desktop_view *v, const pga_draw_shape *shapes, uint32_t count);
/* Joints over the bodies: a pin a ringed dot with thin arms from the bodies' origins, a rod a line with dotted ends, a spring a
 * zigzag, a mouse joint a thin line from the body's anchor to a ring at its target; in
 * the colours of the list. Everything lies within DESKTOP_JOINT_REACH px of the segments
 * between the anchors and from each origin to its anchor (image_check.c leaves those
 * pixels out). */
#define DESKTOP_JOINT_REACH 8
void desktop_render_joints(SDL_Renderer *r, const desktop_view *v, const pga_draw_joint *joints, uint32_t count);
/* The points collected for a triangle, a wall or a joint's first end, joined. */
void desktop_render_pending(SDL_Renderer *r, const desktop_view *v, const pg_vec2 *points, uint32_t count);

#endif
