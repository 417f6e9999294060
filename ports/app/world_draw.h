/* world_draw.h — the shapes and joints of any world as a draw list, for views that show a world
 * the app does not own (a replay being played or jumped in, see replay_seek.h).
 *
 * The list has the app's form (pga_draw_shape of pogon_app.h) and its colours (from
 * user_data, which replays keep), so a front end draws both with one routine and a
 * replay looks like the session it recorded. No body is drawn as selected.
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

/* Writes up to `capacity` joints (see pga_draw_joint: every joint whose body B, or when
 * B has no shape body A, has a shape; in that body's slot order, then the body's joint
 * order) and returns how many there are. */
uint32_t pga_world_draw_joints(const pg_world *world, pga_draw_joint *out, uint32_t capacity);

/* The colour of `body`, whose first shape is `kind`, of `shape_count` shapes. */
uint32_t pga_world_draw_color(const pg_world *world, pg_body_id body, pg_shape_kind kind, uint32_t shape_count);

#ifdef __cplusplus
}
#endif
#endif
