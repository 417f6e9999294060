/* view.c — see view.h. Floating point is fine here: the port draws and reads the
 * mouse; every number that reaches the world is rounded to Q16.16 once, here, and the
 * replay records that rounded value. */
#include "view.h"

#include <math.h>

double desktop_fix_to_double(pg_fix value) { return (double)value / 65536.0; }

pg_fix desktop_fix_from_double(double metres)
{
    double q = floor(metres * 65536.0 + 0.5);
    if (q > 2147483647.0) q = 2147483647.0;
    if (q < -2147483647.0) q = -2147483647.0;
    return (pg_fix)q;
}

void desktop_view_to_screen(const desktop_view *v, pg_vec2 p, double *x, double *y)
{
    *x = v->width * 0.5 + (desktop_fix_to_double(p.x) - v->center_x) * v->scale;
    *y = v->height * 0.5 - (desktop_fix_to_double(p.y) - v->center_y) * v->scale;
}

pg_vec2 desktop_view_to_world(const desktop_view *v, double x, double y)
{
    pg_vec2 p;
    p.x = desktop_fix_from_double(v->center_x + (x + 0.5 - v->width * 0.5) / v->scale);
    p.y = desktop_fix_from_double(v->center_y - (y + 0.5 - v->height * 0.5) / v->scale);
    return p;
}
