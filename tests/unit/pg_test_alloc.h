/* pg_test_alloc.h — tracked allocations for tests that allocate inside test bodies
 * (test_commands, test_snapshot). A failing test leaves by cmocka's longjmp, past its
 * own frees; tracking lets the group teardown (free_leftovers) free what is left, so
 * leak reports do not hide the real failure. Include after pg_test.h. */
#ifndef POGON_TEST_PG_TEST_ALLOC_H
#define POGON_TEST_PG_TEST_ALLOC_H

#include <stdlib.h>
#include <string.h>

#define MAX_TRACKED 1024
static void *tracked[MAX_TRACKED];

static void *t_malloc(size_t n)
{
    int i;
    void *p = malloc(n > 0 ? n : 1u);
    if (p == NULL) return NULL;
    for (i = 0; i < MAX_TRACKED; ++i)
        if (tracked[i] == NULL) { tracked[i] = p; return p; }
    fail_msg("%s", "too many tracked allocations");
    return p;
}

static inline void *t_calloc(size_t n, size_t size)
{
    void *p = t_malloc(n * size);
    if (p != NULL) memset(p, 0, n * size);
    return p;
}

static void t_free(void *p)
{
    int i;
    if (p == NULL) return;
    for (i = 0; i < MAX_TRACKED; ++i)
        if (tracked[i] == p) { tracked[i] = NULL; break; }
    free(p);
}

/* cmocka group teardown: frees whatever a failed test left allocated. */
static int free_leftovers(void **state)
{
    int i;
    (void)state;
    for (i = 0; i < MAX_TRACKED; ++i)
        if (tracked[i] != NULL) { free(tracked[i]); tracked[i] = NULL; }
    return 0;
}
#endif
