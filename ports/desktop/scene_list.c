/* scene_list.c — see scene_list.h. POSIX readdir. */
#define _POSIX_C_SOURCE 200809L
#include "scene_list.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

void desktop_scene_list_read(desktop_scene_list *l, const char *folder)
{
    DIR *d = opendir(folder);
    struct dirent *e;
    int cap = 0;
    l->paths = NULL;
    l->count = 0;
    if (d == NULL) return;
    while ((e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name), size;
        char *path;
        if (n < 7 || strcmp(e->d_name + n - 6, ".scene") != 0) continue;
        if (l->count == cap) {
            int ncap = cap != 0 ? cap * 2 : 16;
            char **np = (char **)realloc(l->paths, (size_t)ncap * sizeof *np);
            if (np == NULL) break;
            l->paths = np;
            cap = ncap;
        }
        size = strlen(folder) + n + 2u;
        path = (char *)malloc(size);
        if (path == NULL) break;
        snprintf(path, size, "%s/%s", folder, e->d_name);
        l->paths[l->count++] = path;
    }
    closedir(d);
    if (l->count > 1) qsort(l->paths, (size_t)l->count, sizeof *l->paths, by_name);
}

void desktop_scene_list_free(desktop_scene_list *l)
{
    int i;
    for (i = 0; i < l->count; ++i) free(l->paths[i]);
    free(l->paths);
    l->paths = NULL;
    l->count = 0;
}

static const char *file_part(const char *p)
{
    const char *s = strrchr(p, '/');
    return s != NULL ? s + 1 : p;
}

int desktop_scene_list_find(const desktop_scene_list *l, const char *path)
{
    int i;
    for (i = 0; i < l->count; ++i)
        if (strcmp(file_part(l->paths[i]), file_part(path)) == 0) return i;
    return -1;
}
