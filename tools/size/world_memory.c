/* world_memory.c — firmware (ports/cortex-m) that prints pg_world_memory_size on the
 * target, whose pointers and alignment decide it: for a reference world and with one
 * more body, shape or contact slot, so size_table.py can state the bytes per slot.
 * Output: "memory BODIES SHAPES CONTACTS BYTES" lines. */
#include "pogon/pogon.h"
#include "scenes.h"
#include <stdio.h>

static void print_size(uint32_t bodies, uint32_t shapes, uint32_t contacts)
{
    pg_world_def wd = pg_default_world_def();
    wd.max_bodies = bodies;
    wd.max_shapes = shapes;
    wd.max_contacts = contacts;
    printf("memory %lu %lu %lu %lu\n", (unsigned long)bodies, (unsigned long)shapes, (unsigned long)contacts,
           (unsigned long)pg_world_memory_size(&wd));
}

int main(void)
{
    pg_world_def pyramid = pg_scene_world_def("pyramid", 20);
    print_size(32, 32, 128);
    print_size(33, 32, 128);
    print_size(32, 33, 128);
    print_size(32, 32, 129);
    print_size(1024, 1024, 4096);
    print_size(1025, 1024, 4096);
    print_size(pyramid.max_bodies, pyramid.max_shapes, pyramid.max_contacts);
    return 0;
}
