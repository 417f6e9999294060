/* fuzz_scene.c — libFuzzer target for the scene reader and writer (src/io/scene_file.c).
 *
 * For any input bytes:
 *   - pg_scene_read_def returns a pg_result, never reads past the input (libFuzzer hands
 *     over a heap block of exactly `size` bytes, ASan watches its end), and on failure
 *     gives a position and a NUL-terminated message that starts with it;
 *   - when it accepts the text, a world created from its def loads it (the reader checks
 *     everything a fresh world would refuse);
 *   - the loaded world writes text that reads back to the same def and loads into a world
 *     that writes the same text again (write -> load -> write is the identity), and a
 *     cut write (snprintf-style) is a prefix of the full one;
 *   - after a few steps the same holds, except that a body that left the envelope may be
 *     refused (PG_ERR_ENVELOPE, documented).
 * Any violation aborts, which libFuzzer reports as a crash.
 *
 * Build: cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DPOGON_BUILD_FUZZ=ON
 * Run:   build-fuzz/tests/fuzz/fuzz_scene -dict=tests/fuzz/scene.dict corpus/ scenes/
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/pogon.h"
#include "pogon/scene_file.h"

/* Worlds larger than this are skipped (default capacities need about 6 MB). */
#define WORLD_BYTES (8u << 20)
static uint64_t memory_a[WORLD_BYTES / 8], memory_b[WORLD_BYTES / 8];

static void check(int ok, const char *what, const char *detail)
{
    if (!ok) {
        fprintf(stderr, "fuzz_scene: %s%s%s\n", what, detail != NULL ? ": " : "", detail != NULL ? detail : "");
        abort();
    }
}

static void check_error(pg_result r, const pg_scene_error *e)
{
    size_t n = 0;
    char prefix[64];
    while (n < sizeof e->message && e->message[n] != '\0') ++n;
    check(n < sizeof e->message, "error message is not NUL-terminated", NULL);
    if (r == PG_OK) {
        check(e->line == 0 && e->column == 0 && n == 0, "error set on success", e->message);
        return;
    }
    check(r > PG_OK && r < PG_RESULT_COUNT, "result out of range", NULL);
    check(e->line >= 1 && e->column >= 1, "error without a position", e->message);
    snprintf(prefix, sizeof prefix, "line %u, column %u: ", e->line, e->column);
    check(strncmp(e->message, prefix, strlen(prefix)) == 0, "message does not start with its position", e->message);
}

static int same_def(const pg_world_def *a, const pg_world_def *b)
{
    return a->gravity.x == b->gravity.x && a->gravity.y == b->gravity.y && a->step_hz == b->step_hz &&
           a->substeps == b->substeps && a->effects == b->effects && a->contact_hertz == b->contact_hertz &&
           a->contact_damping_ratio == b->contact_damping_ratio && a->contact_push_max == b->contact_push_max &&
           a->restitution_threshold == b->restitution_threshold && a->max_linear_speed == b->max_linear_speed &&
           a->sleep_linear_tolerance == b->sleep_linear_tolerance && a->sleep_angular_tolerance == b->sleep_angular_tolerance &&
           a->time_to_sleep == b->time_to_sleep && a->max_bodies == b->max_bodies && a->max_shapes == b->max_shapes &&
           a->max_contacts == b->max_contacts;
}

/* The world's text in a malloc'd block of exactly its length (no NUL after it, so a
 * reader that looks for one trips ASan). */
static char *write_exact(const pg_world *w, size_t *size, unsigned cut)
{
    size_t n = pg_scene_write(w, NULL, 0), m;
    char *full = malloc(n + 1), *exact;
    check(full != NULL, "out of memory", NULL);
    m = pg_scene_write(w, full, n + 1);
    check(m == n && full[n] == '\0', "pg_scene_write length differs between calls", NULL);
    { /* a cut write is a prefix */
        size_t cap = (size_t)cut % (n + 2);
        char *part = malloc(cap + 1);
        check(part != NULL, "out of memory", NULL);
        part[cap] = 'x';
        m = pg_scene_write(w, part, cap);
        check(m == n, "pg_scene_write cut returns another length", NULL);
        if (cap > 0) check(part[cap - 1] == '\0' && memcmp(part, full, cap - 1) == 0, "cut write is not a prefix", NULL);
        check(part[cap] == 'x', "pg_scene_write wrote past capacity", NULL);
        free(part);
    }
    exact = malloc(n > 0 ? n : 1);
    check(exact != NULL, "out of memory", NULL);
    memcpy(exact, full, n);
    free(full);
    *size = n;
    return exact;
}

/* Write `w`, read and load the text into memory_b, write again: same text. A refusal
 * is accepted only when `may_refuse` (a stepped world may have left the envelope). */
static void round_trip(const pg_world *w, int may_refuse, unsigned cut)
{
    size_t n1, n2;
    char *t1 = write_exact(w, &n1, cut), *t2;
    pg_world_def def, wd = pg_world_get_def(w);
    pg_scene_error err;
    pg_world *b;
    pg_result r = pg_scene_read_def(t1, n1, &def, &err);
    check_error(r, &err);
    if (r != PG_OK && may_refuse && r == PG_ERR_ENVELOPE) {
        free(t1);
        return;
    }
    check(r == PG_OK, "written text does not read back", err.message);
    check(same_def(&def, &wd), "written text reads back to another def", NULL);
    check(pg_world_create(&def, memory_b, sizeof memory_b, &b) == PG_OK, "cannot create the second world", NULL);
    r = pg_scene_load(b, t1, n1, &err);
    check_error(r, &err);
    check(r == PG_OK, "written text does not load", err.message);
    t2 = write_exact(b, &n2, cut >> 8);
    if (n1 != n2 || memcmp(t1, t2, n1) != 0) {
        fprintf(stderr, "---- first write\n%.*s\n---- second write\n%.*s\n", (int)n1, t1, (int)n2, t2);
        check(0, "write -> load -> write changed the text", NULL);
    }
    free(t1);
    free(t2);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = (const char *)data;
    pg_world_def def;
    pg_scene_error err;
    pg_world *a;
    pg_result r;
    size_t need;
    unsigned cut = 0;
    size_t i;
    int steps;
    for (i = 0; i < size && i < 64; ++i) cut = cut * 31u + data[i];

    memset(&err, 0x55, sizeof err); /* garbage: it must be overwritten */
    r = pg_scene_read_def(text, size, &def, &err);
    check_error(r, &err);
    if (r != PG_OK) {
        /* pg_scene_load must agree (it checks the whole text first) */
        pg_world_def d = pg_default_world_def();
        pg_scene_error err2;
        d.max_bodies = d.max_shapes = d.max_contacts = 4;
        check(pg_world_create(&d, memory_a, sizeof memory_a, &a) == PG_OK, "cannot create a small world", NULL);
        check(pg_scene_load(a, text, size, &err2) == r, "pg_scene_load gives another result than pg_scene_read_def", err2.message);
        check(err2.line == err.line && err2.column == err.column && strcmp(err.message, err2.message) == 0,
              "pg_scene_load reports another error than pg_scene_read_def", err2.message);
        check(pg_world_get_stats(a).body_count == 0, "pg_scene_load made bodies from a text it refused", NULL);
        return 0;
    }
    need = pg_world_memory_size(&def);
    check(need > 0, "pg_scene_read_def gave an invalid def", NULL);
    if (need > sizeof memory_a) return 0;
    check(pg_world_create(&def, memory_a, sizeof memory_a, &a) == PG_OK, "cannot create a world from the def", NULL);
    r = pg_scene_load(a, text, size, &err);
    check_error(r, &err);
    check(r == PG_OK, "pg_scene_read_def accepted a text pg_scene_load refuses", err.message);

    round_trip(a, 0, cut);
    /* a few steps: velocities, angles that whole degrees do not express, sleep */
    steps = 1 + (int)(cut % 3u);
    for (i = 0; i < (size_t)steps; ++i) check(pg_world_step(a) == PG_OK, "pg_world_step failed", NULL);
    round_trip(a, 1, cut >> 4);
    return 0;
}
