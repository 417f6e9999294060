/* scene_name.c — see scene_name.h. */
#include "scene_name.h"

#include <stdio.h>
#include <string.h>

void desktop_scene_name(const char *path, char *out, size_t capacity)
{
    const char *base = strrchr(path, '/');
    size_t n;
    base = base != NULL ? base + 1 : path;
    snprintf(out, capacity, "%s", base);
    n = strlen(out);
    if (n > 6 && strcmp(out + n - 6, ".scene") == 0) out[n - 6] = '\0';
}
