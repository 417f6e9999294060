/* pg_test_world.h — worlds in malloc'd memory for the physics tests (test_world_api,
 * test_world_physics, the hard cases): Q16.16 from and to double, a world made from a
 * definition, freed, and a dynamic body definition at a place. Include after pg_test.h. */
#ifndef POGON_TEST_PG_TEST_WORLD_H
#define POGON_TEST_PG_TEST_WORLD_H

#include <math.h>
#include <stdlib.h>

#include "pogon/pogon.h"

static inline pg_fix fx(double v) { return (pg_fix)llround(v * 65536.0); }
static inline double fd(pg_fix v) { return (double)v / 65536.0; }

typedef struct test_world {
    void *memory;
    pg_world *w;
} test_world;

static inline test_world make_world_def(const pg_world_def *d)
{
    test_world t;
    size_t need = pg_world_memory_size(d);
    assert_true(need > 0);
    t.memory = malloc(need); /* malloc's alignment is at least 8 */
    assert_non_null(t.memory);
    assert_int_equal(pg_world_create(d, t.memory, need, &t.w), PG_OK);
    assert_non_null(t.w);
    return t;
}

static inline void free_world(test_world *t) { free(t->memory); t->memory = NULL; t->w = NULL; }

static inline pg_body_def dynamic_at(double x, double y)
{
    pg_body_def bd = pg_default_body_def();
    bd.type = PG_BODY_DYNAMIC;
    bd.position = pg_v2(fx(x), fx(y));
    return bd;
}
#endif
