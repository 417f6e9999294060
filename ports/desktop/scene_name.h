/* scene_name.h — the name a scene is shown under: its file name without folder and .scene. */
#ifndef DESKTOP_SCENE_NAME_H
#define DESKTOP_SCENE_NAME_H

#include <stddef.h>

void desktop_scene_name(const char *path, char *out, size_t capacity);

#endif
