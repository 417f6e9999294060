/* world_draw.h — the shapes of any world as a draw list, for views that show a world
 * the app does not own (a replay being played or jumped in, see replay_seek.h).
 *
 * The list has the app's form (pga_draw_shape of pogon_app.h), so a front end draws
 * both with one routine. Replay files carry no colours: a shape's colour here follows
 * its body's type and its kind.
 */
#ifndef PGA_WORLD_DRAW_H
#define PGA_WORLD_DRAW_H

#include "pogon_app.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Writes up to `capacity` shapes (bodies in ascending slot order, each body's shapes in
 * its order) with vertices in the world frame, and returns how many the world has, so
 * a return above `capacity` means the list was cut. Bodies without shapes are not seen. */
uint32_t pga_world_draw_shapes(const pg_world *world, pga_draw_shape *out, uint32_t capacity);

/* The colour pga_world_draw_shapes gives a shape of this kind on a body of this type. */
uint32_t pga_world_draw_color(pg_body_type type, pg_shape_kind kind, int32_t vertex_count);

#ifdef __cplusplus
}
#endif
#endif
