/* app_world.c — worlds built from scene text, and the bodies of a world.
 *
 * A live world is always built from its own canonical text: the scene is loaded once with
 * raised capacities, written back with pg_scene_write (every setting, capacities
 * included), and the world the app keeps is loaded from that text. The recording's scene
 * is that same text, so a replay starts from the same bits and has room for the bodies
 * a visitor adds. */
#include "app_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void copy_error(char *error, size_t size, const char *text)
{
    if (error != NULL && size > 0) snprintf(error, size, "%s", text);
}

void pga__world_free(pga_world_box *box)
{
    free(box->memory);
    free(box->text);
    memset(box, 0, sizeof *box);
}

char *pga__world_text(const pg_world *world, size_t *size)
{
    size_t n = pg_scene_write(world, NULL, 0);
    char *text = (char *)malloc(n + 1);
    if (text == NULL) return NULL;
    pg_scene_write(world, text, n + 1);
    *size = n;
    return text;
}

/* Create a world for `def` and load `text` into it. */
static pg_result load(const pg_world_def *def, const char *text, size_t length, pga_world_box *box, char *error,
                      size_t error_size)
{
    pg_scene_error se;
    size_t need = pg_world_memory_size(def);
    pg_result r;
    memset(box, 0, sizeof *box);
    if (need == 0) {
        const char *why = pg_world_def_problem(def);
        copy_error(error, error_size, why != NULL ? why : "the world settings are invalid");
        return PG_ERR_INVALID_ARGUMENT;
    }
    if (need > PGA_MAX_WORLD_BYTES) {
        if (error != NULL && error_size > 0)
            snprintf(error, error_size, "its capacities (max_bodies %lu, max_shapes %lu, max_contacts %lu) need %lu MiB of "
                     "world memory; the app allows at most %lu MiB", (unsigned long)def->max_bodies,
                     (unsigned long)def->max_shapes, (unsigned long)def->max_contacts, (unsigned long)(need >> 20),
                     (unsigned long)(PGA_MAX_WORLD_BYTES >> 20));
        return PG_ERR_CAPACITY;
    }
    box->memory = malloc(need);
    if (box->memory == NULL) {
        copy_error(error, error_size, "out of memory for the world");
        return PG_ERR_MEMORY;
    }
    r = pg_world_create(def, box->memory, need, &box->world);
    if (r == PG_OK) {
        r = pg_scene_load(box->world, text, length, &se);
        if (r != PG_OK) copy_error(error, error_size, se.message);
    } else {
        copy_error(error, error_size, pg_result_message(r));
    }
    if (r != PG_OK) pga__world_free(box);
    return r;
}

/* Replace the value of the setting line "<key> <value>\n" (pg_scene_write writes every
 * setting on its own line). Returns a new malloc'd text or NULL. */
static char *replace_setting(const char *text, size_t size, const char *key, uint32_t value, size_t *out_size)
{
    char line[64], *out;
    size_t klen = strlen(key), i, start = 0, end, n;
    int found = 0;
    for (i = 0; i + klen + 1 < size; ++i) {
        if ((i == 0 || text[i - 1] == '\n') && memcmp(text + i, key, klen) == 0 && text[i + klen] == ' ') {
            start = i;
            found = 1;
            break;
        }
    }
    if (!found) return NULL;
    for (end = start; end < size && text[end] != '\n'; ++end) {
    }
    n = (size_t)snprintf(line, sizeof line, "%s %lu", key, (unsigned long)value);
    out = (char *)malloc(size - (end - start) + n + 1);
    if (out == NULL) return NULL;
    memcpy(out, text, start);
    memcpy(out + start, line, n);
    memcpy(out + start + n, text + end, size - end);
    *out_size = size - (end - start) + n;
    out[*out_size] = '\0';
    return out;
}

pg_result pga__world_build(pga_world_box *box, const char *text, size_t length, uint32_t substeps, char *error,
                           size_t error_size)
{
    pg_world_def def;
    pg_scene_error se;
    pga_world_box first;
    char *canon, *edited;
    size_t canon_size, edited_size;
    pg_result r;

    memset(box, 0, sizeof *box);
    r = pg_scene_read_def(text, length, &def, &se);
    if (r != PG_OK) {
        copy_error(error, error_size, se.message);
        return r;
    }
    if (def.max_bodies < PGA_MIN_BODIES) def.max_bodies = PGA_MIN_BODIES;
    if (def.max_shapes < PGA_MIN_SHAPES) def.max_shapes = PGA_MIN_SHAPES;
    if (def.max_contacts < PGA_MIN_CONTACTS) def.max_contacts = PGA_MIN_CONTACTS;
    if (def.max_joints < PGA_MIN_JOINTS) def.max_joints = PGA_MIN_JOINTS;
    r = load(&def, text, length, &first, error, error_size);
    if (r != PG_OK) return r;
    canon = pga__world_text(first.world, &canon_size);
    pga__world_free(&first);
    if (canon == NULL) {
        copy_error(error, error_size, "out of memory for the scene text");
        return PG_ERR_MEMORY;
    }
    if (substeps != 0 && substeps != def.substeps) {
        edited = replace_setting(canon, canon_size, "substeps", substeps, &edited_size);
        free(canon);
        if (edited == NULL) {
            copy_error(error, error_size, "out of memory for the scene text");
            return PG_ERR_MEMORY;
        }
        canon = edited;
        canon_size = edited_size;
    }
    r = pg_scene_read_def(canon, canon_size, &def, &se);
    if (r == PG_OK) r = load(&def, canon, canon_size, box, error, error_size);
    else copy_error(error, error_size, se.message);
    if (r != PG_OK) {
        free(canon);
        return r;
    }
    box->text = canon;
    box->text_size = canon_size;
    return PG_OK;
}

const pg_body_id *pga__list_bodies(const pga_app *app, const pg_world *world, uint32_t *count)
{
    pga_scratch *s = app->scratch;
    pg_world_def def = pg_world_get_def(world);
    pg_aabb all;
    uint32_t n = 0;
    *count = 0;
    if (s->body_capacity < def.max_bodies) {
        pg_body_id *grown = (pg_body_id *)realloc(s->bodies, sizeof *grown * def.max_bodies);
        if (grown == NULL) return s->bodies;
        s->bodies = grown;
        s->body_capacity = def.max_bodies;
    }
    all.lo = pg_v2(PG_FIX_MIN, PG_FIX_MIN);
    all.hi = pg_v2(PG_FIX_MAX, PG_FIX_MAX);
    if (pg_world_query_aabb(world, all, s->bodies, s->body_capacity, &n) != PG_OK) n = 0;
    *count = n < s->body_capacity ? n : s->body_capacity;
    return s->bodies;
}

pg_body_id pga__body_at(const pga_app *app, pg_vec2 point)
{
    pg_body_id hits[16], none = {0, 0};
    uint32_t n = 0;
    const pg_world *w = pga__world(app);
    if (w == NULL || pg_world_query_point(w, point, hits, 16, &n) != PG_OK || n == 0) return none;
    return hits[(n < 16 ? n : 16) - 1];
}

pg_body_id pga__find_player(const pga_app *app)
{
    pg_body_id none = {0, 0};
    const pg_world *w = pga__world(app);
    uint32_t n, i;
    const pg_body_id *ids;
    if (w == NULL) return none;
    ids = pga__list_bodies(app, w, &n);
    for (i = 0; i < n; ++i)
        if ((pg_body_user_data(w, ids[i]) & 0xffffffffu) == 1u) return ids[i];
    return none;
}
