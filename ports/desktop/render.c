/* render.c — see render.h. Filled shapes with a darker outline; asleep bodies paler;
 * the selected body outlined in black, two pixels wide. */
#include "render.h"

#include <SDL2_gfxPrimitives.h>
#include <math.h>

static Uint8 channel(uint32_t color, int shift) { return (Uint8)((color >> shift) & 0xffu); }

static uint32_t mix(uint32_t a, uint32_t b, int percent_b)
{
    uint32_t out = 0;
    int s;
    for (s = 0; s <= 16; s += 8) {
        int ca = (int)channel(a, s), cb = (int)channel(b, s);
        out |= (uint32_t)((ca * (100 - percent_b) + cb * percent_b) / 100) << s;
    }
    return out;
}

void desktop_render_clear(SDL_Renderer *r)
{
    SDL_SetRenderDrawColor(r, channel(DESKTOP_BACKGROUND, 16), channel(DESKTOP_BACKGROUND, 8), channel(DESKTOP_BACKGROUND, 0), 255);
    SDL_RenderClear(r);
}

static void polygon(SDL_Renderer *r, const Sint16 *x, const Sint16 *y, int n, uint32_t fill, uint32_t line, int thick)
{
    int i;
    filledPolygonRGBA(r, x, y, n, channel(fill, 16), channel(fill, 8), channel(fill, 0), 255);
    for (i = 0; i < n; ++i) {
        int j = (i + 1) % n;
        if (thick > 1) thickLineRGBA(r, x[i], y[i], x[j], y[j], (Uint8)thick, channel(line, 16), channel(line, 8), channel(line, 0), 255);
        else aalineRGBA(r, x[i], y[i], x[j], y[j], channel(line, 16), channel(line, 8), channel(line, 0), 255);
    }
}

static Sint16 clamp16(double v)
{
    if (v > 32000.0) return 32000;
    if (v < -32000.0) return -32000;
    return (Sint16)floor(v);
}

void desktop_render_shapes(SDL_Renderer *r, const desktop_view *v, const pga_draw_shape *shapes, uint32_t count)
{
    uint32_t i;
    for (i = 0; i < count; ++i) {
        const pga_draw_shape *d = &shapes[i];
        uint32_t fill = d->color, line;
        int selected = (d->flags & PGA_DRAW_SELECTED) != 0, thick = selected ? 3 : 1, k;
        double rad = desktop_fix_to_double(d->radius) * v->scale;
        Sint16 x[PG_MAX_VERTICES], y[PG_MAX_VERTICES];
        if (d->flags & PGA_DRAW_ASLEEP) fill = mix(fill, 0xffffffu, 45);
        if (fill == DESKTOP_BACKGROUND) fill ^= 0x010101u; /* never the background colour */
        line = selected ? 0x000000u : mix(fill, 0x000000u, 45);
        for (k = 0; k < d->count && k < PG_MAX_VERTICES; ++k) {
            double sx, sy;
            desktop_view_to_screen(v, d->vertices[k], &sx, &sy);
            x[k] = clamp16(sx);
            y[k] = clamp16(sy);
        }
        switch (d->kind) {
        case PG_SHAPE_CIRCLE:
            filledCircleRGBA(r, x[0], y[0], clamp16(rad), channel(fill, 16), channel(fill, 8), channel(fill, 0), 255);
            circleRGBA(r, x[0], y[0], clamp16(rad), channel(line, 16), channel(line, 8), channel(line, 0), 255);
            if (selected) circleRGBA(r, x[0], y[0], clamp16(rad + 1.0), 0, 0, 0, 255);
            break;
        case PG_SHAPE_SEGMENT:
            thickLineRGBA(r, x[0], y[0], x[1], y[1], (Uint8)(selected ? 4 : 2), channel(line, 16), channel(line, 8), channel(line, 0), 255);
            break;
        case PG_SHAPE_CAPSULE: {
            double dx = x[1] - x[0], dy = y[1] - y[0], len = sqrt(dx * dx + dy * dy), nx = 0.0, ny = 0.0;
            Sint16 qx[4], qy[4];
            if (len > 0.0) {
                nx = -dy / len * rad;
                ny = dx / len * rad;
            }
            qx[0] = clamp16(x[0] + nx); qy[0] = clamp16(y[0] + ny);
            qx[1] = clamp16(x[1] + nx); qy[1] = clamp16(y[1] + ny);
            qx[2] = clamp16(x[1] - nx); qy[2] = clamp16(y[1] - ny);
            qx[3] = clamp16(x[0] - nx); qy[3] = clamp16(y[0] - ny);
            for (k = 0; k < 2; ++k) {
                filledCircleRGBA(r, x[k], y[k], clamp16(rad), channel(fill, 16), channel(fill, 8), channel(fill, 0), 255);
                circleRGBA(r, x[k], y[k], clamp16(rad), channel(line, 16), channel(line, 8), channel(line, 0), 255);
            }
            filledPolygonRGBA(r, qx, qy, 4, channel(fill, 16), channel(fill, 8), channel(fill, 0), 255);
            break;
        }
        case PG_SHAPE_POLYGON:
        default:
            if (d->count >= 3) polygon(r, x, y, d->count, fill, line, thick);
            break;
        }
    }
}

void desktop_render_pending(SDL_Renderer *r, const desktop_view *v, const pg_vec2 *points, uint32_t count)
{
    uint32_t i;
    double px = 0.0, py = 0.0;
    for (i = 0; i < count; ++i) {
        double sx, sy;
        desktop_view_to_screen(v, points[i], &sx, &sy);
        filledCircleRGBA(r, clamp16(sx), clamp16(sy), 4, 220, 38, 38, 255);
        if (i > 0) lineRGBA(r, clamp16(px), clamp16(py), clamp16(sx), clamp16(sy), 220, 38, 38, 255);
        px = sx;
        py = sy;
    }
}

/* A zigzag of `n` teeth `amp` px to each side of the line from (x0, y0) to (x1, y1). */
static void zigzag(SDL_Renderer *r, double x0, double y0, double x1, double y1, double amp, uint32_t color)
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy), nx, ny, px = x0, py = y0;
    int n, i;
    if (len < 1.0) return;
    nx = -dy / len * amp;
    ny = dx / len * amp;
    n = (int)(len / 6.0);
    if (n < 4) n = 4;
    if (n > 60) n = 60;
    for (i = 1; i <= n; ++i) {
        double t = (double)i / (n + 1), side = (i % 2) ? 1.0 : -1.0;
        double qx = x0 + dx * t + nx * side, qy = y0 + dy * t + ny * side;
        thickLineRGBA(r, clamp16(px), clamp16(py), clamp16(qx), clamp16(qy), 2, channel(color, 16), channel(color, 8), channel(color, 0), 255);
        px = qx;
        py = qy;
    }
    thickLineRGBA(r, clamp16(px), clamp16(py), clamp16(x1), clamp16(y1), 2, channel(color, 16), channel(color, 8), channel(color, 0), 255);
}

void desktop_render_joints(SDL_Renderer *r, const desktop_view *v, const pga_draw_joint *joints, uint32_t count)
{
    uint32_t i;
    for (i = 0; i < count; ++i) {
        const pga_draw_joint *j = &joints[i];
        uint32_t c = j->color;
        double ax, ay, bx, by;
        Uint8 cr = channel(c, 16), cg = channel(c, 8), cb = channel(c, 0);
        desktop_view_to_screen(v, j->a, &ax, &ay);
        desktop_view_to_screen(v, j->b, &bx, &by);
        switch (j->type) {
        case PG_JOINT_REVOLUTE: {
            double ox, oy;
            desktop_view_to_screen(v, j->origin_a, &ox, &oy);
            aalineRGBA(r, clamp16(ox), clamp16(oy), clamp16(bx), clamp16(by), cr, cg, cb, 255);
            desktop_view_to_screen(v, j->origin_b, &ox, &oy);
            aalineRGBA(r, clamp16(ox), clamp16(oy), clamp16(bx), clamp16(by), cr, cg, cb, 255);
            filledCircleRGBA(r, clamp16(bx), clamp16(by), 5, cr, cg, cb, 255);
            filledCircleRGBA(r, clamp16(bx), clamp16(by), 2, 255, 255, 255, 255);
            break;
        }
        case PG_JOINT_MOUSE:
            aalineRGBA(r, clamp16(bx), clamp16(by), clamp16(ax), clamp16(ay), cr, cg, cb, 255);
            circleRGBA(r, clamp16(ax), clamp16(ay), 4, cr, cg, cb, 255);
            filledCircleRGBA(r, clamp16(bx), clamp16(by), 2, cr, cg, cb, 255);
            break;
        case PG_JOINT_DISTANCE:
            if (j->spring) zigzag(r, ax, ay, bx, by, 5.0, c);
            else thickLineRGBA(r, clamp16(ax), clamp16(ay), clamp16(bx), clamp16(by), 3, cr, cg, cb, 255);
            filledCircleRGBA(r, clamp16(ax), clamp16(ay), 3, cr, cg, cb, 255);
            filledCircleRGBA(r, clamp16(bx), clamp16(by), 3, cr, cg, cb, 255);
            break;
        default: /* weld, prismatic: a line between the anchors */
            thickLineRGBA(r, clamp16(ax), clamp16(ay), clamp16(bx), clamp16(by), 2, cr, cg, cb, 255);
            boxRGBA(r, clamp16(bx - 3), clamp16(by - 3), clamp16(bx + 3), clamp16(by + 3), cr, cg, cb, 255);
            break;
        }
    }
}
