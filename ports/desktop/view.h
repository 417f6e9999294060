/* view.h — where the world appears in the window: a centre point and a scale. Shared by
 * the drawing and by the screenshot check, so that both use one mapping. */
#ifndef DESKTOP_VIEW_H
#define DESKTOP_VIEW_H

#include "pogon/pogon.h"

#define DESKTOP_BACKGROUND 0xf4f1eau   /* window background, 0xRRGGBB */
#define DESKTOP_OVERLAY_LINES 3        /* text lines at the top (8 px font, 10 px a line) */
#define DESKTOP_OVERLAY_HEIGHT (DESKTOP_OVERLAY_LINES * 10 + 6)
#define DESKTOP_TIMELINE_HEIGHT 14     /* the playback bar at the bottom */

typedef struct desktop_view {
    double center_x, center_y;  /* world point at the window centre, m */
    double scale;               /* pixels per metre */
    int width, height;          /* window pixels */
} desktop_view;

/* Screen pixel (x right, y down) of a world point (y up). */
void desktop_view_to_screen(const desktop_view *v, pg_vec2 p, double *x, double *y);
/* World point under a screen pixel's centre, rounded to the nearest Q16.16 value. */
pg_vec2 desktop_view_to_world(const desktop_view *v, double x, double y);
/* Metres as Q16.16, rounded to nearest. */
pg_fix desktop_fix_from_double(double metres);
double desktop_fix_to_double(pg_fix value);

#endif
