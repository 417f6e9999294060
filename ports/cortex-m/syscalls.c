/* syscalls.c — the heap for newlib's malloc: all of the boards' PSRAM (mps2.ld), where
 * the firmware's worlds live. Replaces librdimon's weak _sbrk, which would place the heap
 * after .bss in RAM and refuse to pass the stack pointer. */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>

extern char __heap_start__[], __heap_end__[];

void *_sbrk(ptrdiff_t increment);

void *_sbrk(ptrdiff_t increment)
{
    static char *top = __heap_start__;
    char *old = top;
    if (increment < 0 || (size_t)increment > (size_t)(__heap_end__ - top)) {
        errno = ENOMEM;
        return (void *)-1;
    }
    top += increment;
    return old;
}
