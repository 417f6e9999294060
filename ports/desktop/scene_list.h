/* scene_list.h — the scene files of one folder, sorted by name, for the scene picker. */
#ifndef DESKTOP_SCENE_LIST_H
#define DESKTOP_SCENE_LIST_H

typedef struct desktop_scene_list {
    char **paths;
    int count;
} desktop_scene_list;

/* Every *.scene in `folder` (none when it cannot be read). */
void desktop_scene_list_read(desktop_scene_list *l, const char *folder);
void desktop_scene_list_free(desktop_scene_list *l);
/* The index of `path` in the list (compared by file name), or -1. */
int desktop_scene_list_find(const desktop_scene_list *l, const char *path);

#endif
