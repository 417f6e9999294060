/* def_cookie.h (internal) — how a def proves it started from its defaults function.
 *
 * pg_default_world_def(), pg_default_body_def() and pg_default_shape_def() put this value
 * in a def's pg__cookie, and every function that takes a def checks it: a def that did
 * not start from its defaults function (a zeroed struct, say, whose gravity_scale 0 or
 * capacities 0 would otherwise be taken at face value) is refused with a message naming
 * the function. Not state: never hashed, saved or encoded. ("pogn") */
#ifndef POGON_SRC_DEF_COOKIE_H
#define POGON_SRC_DEF_COOKIE_H
#define PG__DEF_COOKIE 0x706F676Eu
#endif
