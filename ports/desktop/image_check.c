/* image_check.c — see image_check.h. Reads the BMP with SDL (no video needed). */
#include "image_check.h"

#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>

#include <math.h>

#include "render.h"
#include "world_draw.h"

/* Screen segments of the world's joints, to leave out the pixels they cover. */
typedef struct joint_marks {
    double (*seg)[4];
    uint32_t count;
} joint_marks;

static joint_marks joint_segments(const desktop_view *view, const pg_world *world)
{
    joint_marks m;
    pga_draw_joint *joints;
    uint32_t n = pga_world_draw_joints(world, NULL, 0), i;
    m.seg = NULL;
    m.count = 0;
    if (n == 0) return m;
    joints = (pga_draw_joint *)malloc((size_t)n * sizeof *joints);
    m.seg = (double (*)[4])malloc((size_t)n * 3 * sizeof *m.seg);
    if (joints == NULL || m.seg == NULL) {
        free(joints);
        free(m.seg);
        m.seg = NULL;
        return m;
    }
    n = pga_world_draw_joints(world, joints, n);
    for (i = 0; i < n; ++i) { /* the anchors' segment and each origin's arm to its anchor */
        desktop_view_to_screen(view, joints[i].a, &m.seg[3 * i][0], &m.seg[3 * i][1]);
        desktop_view_to_screen(view, joints[i].b, &m.seg[3 * i][2], &m.seg[3 * i][3]);
        desktop_view_to_screen(view, joints[i].origin_a, &m.seg[3 * i + 1][0], &m.seg[3 * i + 1][1]);
        desktop_view_to_screen(view, joints[i].a, &m.seg[3 * i + 1][2], &m.seg[3 * i + 1][3]);
        desktop_view_to_screen(view, joints[i].origin_b, &m.seg[3 * i + 2][0], &m.seg[3 * i + 2][1]);
        desktop_view_to_screen(view, joints[i].b, &m.seg[3 * i + 2][2], &m.seg[3 * i + 2][3]);
    }
    m.count = 3 * n;
    free(joints);
    return m;
}

/* Whether pixel (x, y) is within `reach` px of a joint's segment. */
static int near_joint(const joint_marks *m, double x, double y, double reach)
{
    uint32_t i;
    for (i = 0; i < m->count; ++i) {
        double ax = m->seg[i][0], ay = m->seg[i][1], dx = m->seg[i][2] - ax, dy = m->seg[i][3] - ay;
        double len2 = dx * dx + dy * dy, t = len2 > 0.0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0.0;
        double px, py;
        if (t < 0.0) t = 0.0;
        if (t > 1.0) t = 1.0;
        px = ax + dx * t - x;
        py = ay + dy * t - y;
        if (sqrt(px * px + py * py) <= reach) return 1;
    }
    return 0;
}

static uint32_t pixel_rgb(SDL_Surface *s, int x, int y)
{
    const Uint8 *row = (const Uint8 *)s->pixels + (size_t)y * (size_t)s->pitch;
    Uint32 value = *(const Uint32 *)(row + (size_t)x * 4u);
    Uint8 r, g, b;
    SDL_GetRGB(value, s->format, &r, &g, &b);
    return ((uint32_t)r << 16) | ((uint32_t)g << 8) | b;
}

static pg_vec2 shape_center(const pga_draw_shape *d)
{
    int64_t x = 0, y = 0;
    int32_t i, n = d->count > 0 ? d->count : 1;
    pg_vec2 c;
    if (d->kind == PG_SHAPE_CIRCLE) return d->vertices[0];
    for (i = 0; i < d->count; ++i) {
        x += d->vertices[i].x;
        y += d->vertices[i].y;
    }
    c.x = (pg_fix)(x / n);
    c.y = (pg_fix)(y / n);
    return c;
}

int desktop_check_image(const char *path, const desktop_view *view, const pg_world *world, char *report,
                        size_t report_capacity, unsigned *checked)
{
    SDL_Surface *loaded = SDL_LoadBMP(path), *img;
    pga_draw_shape *shapes;
    uint32_t count, i;
    int x, y, ok = 1;
    unsigned n = 0, bodies_seen = 0;
    joint_marks marks;
    *checked = 0;
    if (loaded == NULL) {
        snprintf(report, report_capacity, "cannot read %s: %s", path, SDL_GetError());
        return 0;
    }
    img = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_ARGB8888, 0);
    SDL_FreeSurface(loaded);
    if (img == NULL) {
        snprintf(report, report_capacity, "cannot convert %s: %s", path, SDL_GetError());
        return 0;
    }
    if (img->w != view->width || img->h != view->height) {
        snprintf(report, report_capacity, "%s is %dx%d, the view %dx%d", path, img->w, img->h, view->width, view->height);
        SDL_FreeSurface(img);
        return 0;
    }
    count = pga_world_draw_shapes(world, NULL, 0);
    shapes = (pga_draw_shape *)malloc((size_t)(count != 0 ? count : 1) * sizeof *shapes);
    if (shapes == NULL) {
        SDL_FreeSurface(img);
        snprintf(report, report_capacity, "out of memory");
        return 0;
    }
    count = pga_world_draw_shapes(world, shapes, count);
    marks = joint_segments(view, world);
    /* Each shape's centre shows a body's colour. */
    for (i = 0; i < count && ok; ++i) {
        pg_body_id hits[4];
        uint32_t hit_count = 0;
        double sx, sy;
        pg_vec2 c = shape_center(&shapes[i]);
        desktop_view_to_screen(view, c, &sx, &sy);
        x = (int)sx;
        y = (int)sy;
        if (x < 0 || y < DESKTOP_OVERLAY_HEIGHT || x >= img->w || y >= img->h - DESKTOP_TIMELINE_HEIGHT) continue;
        if (pg_world_query_point(world, c, hits, 4, &hit_count) != PG_OK || hit_count != 1) continue;
        n++;
        bodies_seen++;
        if (pixel_rgb(img, x, y) == DESKTOP_BACKGROUND) {
            snprintf(report, report_capacity,
                     "body %u:%u's shape centre (%.3f, %.3f) m is pixel (%d, %d), which shows the background",
                     shapes[i].body.index, shapes[i].body.generation, desktop_fix_to_double(c.x),
                     desktop_fix_to_double(c.y), x, y);
            ok = 0;
        }
    }
    /* Where no body is within 3 px and no joint is drawn, the background shows. */
    for (y = DESKTOP_OVERLAY_HEIGHT + 4; y < img->h - DESKTOP_TIMELINE_HEIGHT - 4 && ok; y += 7) {
        for (x = 4; x < img->w - 4 && ok; x += 7) {
            pg_aabb box;
            pg_body_id hit;
            uint32_t hit_count = 1;
            pg_vec2 a = desktop_view_to_world(view, x - 3.5, y + 3.5), b = desktop_view_to_world(view, x + 3.5, y - 3.5);
            box.lo = a;
            box.hi = b;
            if (pg_world_query_aabb(world, box, &hit, 1, &hit_count) != PG_OK || hit_count != 0) continue;
            if (near_joint(&marks, x, y, DESKTOP_JOINT_REACH + 3)) continue;
            n++;
            if (pixel_rgb(img, x, y) != DESKTOP_BACKGROUND) {
                pg_vec2 w = desktop_view_to_world(view, x, y);
                snprintf(report, report_capacity,
                         "pixel (%d, %d) at (%.3f, %.3f) m shows 0x%06x, but no body is within 3 px there", x, y,
                         desktop_fix_to_double(w.x), desktop_fix_to_double(w.y), (unsigned)pixel_rgb(img, x, y));
                ok = 0;
            }
        }
    }
    if (ok && bodies_seen == 0) {
        snprintf(report, report_capacity, "no body's centre is inside the view: nothing was compared");
        ok = 0;
    }
    if (ok) snprintf(report, report_capacity, "%u shape centres and %u empty pixels agree", bodies_seen, n - bodies_seen);
    free(shapes);
    free(marks.seg);
    SDL_FreeSurface(img);
    *checked = n;
    return ok;
}
