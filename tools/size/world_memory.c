/* world_memory.c — firmware (ports/cortex-m) that prints pg_world_memory_size on the
 * target, whose pointers and alignment decide it: for a reference world and with one
 * more body, shape or contact slot, so size_table.py can state the bytes per slot, and
 * the parts of the memory block (src/core/world.c's layout) for each of those worlds, so it
 * can say which part a slot's bytes go to.
 * Output: "memory BODIES SHAPES CONTACTS BYTES" and "part BODIES SHAPES CONTACTS BYTES
 * NAME" lines. */
#include "pogon/pogon.h"
#include "scenes.h"
#include "world_internal.h"
#include <stdio.h>

/* lean: a world made with max_joints 0 and max_contact_events 0 (lines "memory-lean",
 * "part-lean"), what a program without joints that reads no events asks for */
static void print_size_of(uint32_t bodies, uint32_t shapes, uint32_t contacts, int lean)
{
    pg_world_def wd = pg_default_world_def();
    const char *name;
    size_t bytes;
    unsigned i;
    wd.max_bodies = bodies;
    wd.max_shapes = shapes;
    wd.max_contacts = contacts;
    if (lean) wd.max_joints = wd.max_contact_events = 0;
    printf("memory%s %lu %lu %lu %lu\n", lean ? "-lean" : "", (unsigned long)bodies, (unsigned long)shapes,
           (unsigned long)contacts, (unsigned long)pg_world_memory_size(&wd));
    for (i = 0; (name = pg__world_memory_part(&wd, i, &bytes)) != NULL; ++i)
        printf("part%s %lu %lu %lu %lu %s\n", lean ? "-lean" : "", (unsigned long)bodies, (unsigned long)shapes,
               (unsigned long)contacts, (unsigned long)bytes, name);
}

static void print_size(uint32_t bodies, uint32_t shapes, uint32_t contacts) { print_size_of(bodies, shapes, contacts, 0); }

int main(void)
{
    pg_world_def pyramid = pg_scene_world_def("pyramid", 20);
    print_size(32, 32, 128);
    print_size(1024, 1024, 4096);
    print_size(1032, 1024, 4096); /* 8 more of a kind: the parts are aligned to 8 bytes */
    print_size(1024, 1032, 4096);
    print_size(1024, 1024, 4104);
    print_size(pyramid.max_bodies, pyramid.max_shapes, pyramid.max_contacts);
    print_size_of(1024, 1024, 4096, 1);
    print_size_of(1032, 1024, 4096, 1);
    print_size_of(1024, 1024, 4104, 1);
    return 0;
}
