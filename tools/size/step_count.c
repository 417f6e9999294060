/* step_count.c — firmware (ports/cortex-m) that counts the instructions of the pyramid
 * step under qemu -icount shift=0, where QEMU advances its clocks by instructions (it
 * has no DWT cycle counter). SysTick counts down from 2^24 - 1 on the processor clock
 * and its handler counts wraps; a calibration loop of a known number of instructions
 * gives the instructions per SysTick tick (40 at shift=0 on the mps2 boards), so no
 * factor is assumed. Output:
 *   calibration INSTRUCTIONS TICKS
 *   pyramid ROWS STEP_FIRST STEP_LAST TICKS
 * size_table.py turns the ticks into instructions per step. Built with
 * -DPOGON_COUNT_DIVISIONS and count_divisions.S (its own build, so the counting does
 * not add to the instructions above) it also prints
 *   divisions STEP_FIRST STEP_LAST LDIVMOD_CALLS ULDIVMOD_CALLS
 * the calls of libgcc's 64-bit division helpers in those steps. */
#include "pogon/pogon.h"
#include "scenes.h"
#include <stdio.h>
#include <stdlib.h>

/* size_table.py's profile builds this twice, with STEP_LAST 0 and its PROFILE_STEPS and a short
 * calibration, and subtracts what the two runs execute. */
#ifndef STEP_LAST
#define STEP_LAST 10u
#endif
#ifndef CALIBRATION_SPINS
#define CALIBRATION_SPINS 10000000u
#endif

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SYST_RELOAD 0x00FFFFFFu

static volatile uint32_t wraps;

#ifdef POGON_COUNT_DIVISIONS
extern volatile uint32_t pg_count_ldivmod, pg_count_uldivmod; /* count_divisions.S */
#endif

void pg_systick_handler(void);
void pg_systick_handler(void) { ++wraps; }

static void ticks_start(void)
{
    SYST_CSR = 0;
    SYST_RVR = SYST_RELOAD;
    SYST_CVR = 0;
    wraps = 0;
    SYST_CSR = 7u; /* enable, interrupt on wrap, processor clock */
    while (SYST_CVR == 0) {
        /* the first tick loads the reload value: until then the count would read full */
    }
}

static uint64_t ticks_now(void)
{
    uint32_t w, v;
    do {
        w = wraps;
        v = SYST_CVR;
    } while (w != wraps);
    return (uint64_t)w * (SYST_RELOAD + 1u) + (SYST_RELOAD - v);
}

/* 2 instructions an iteration (subs, bne), in ARMv6-M and v7-M alike. */
static void spin(uint32_t iterations)
{
    /* unified syntax also for ARMv6-M, where gcc hands inline asm to the assembler in
     * divided syntax (and switches back after it) */
    __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n\tbne 1b" : "+l"(iterations) : : "cc");
}

static void print_u64(const char *prefix, uint64_t v)
{
    char s[21];
    int i = 20;
    s[i] = '\0';
    do {
        s[--i] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0);
    printf("%s%s", prefix, s + i);
}

int main(void)
{
    const uint32_t rows = 20, first = 1, last = STEP_LAST, spins = CALIBRATION_SPINS;
    pg_world_def def = pg_scene_world_def("pyramid", rows);
    size_t size = pg_scene_memory_size("pyramid", rows, &def);
    void *memory = malloc(size);
    pg_scene scene;
    uint64_t t0, t1;
    uint32_t step;
    ticks_start();
    t0 = ticks_now();
    spin(spins);
    t1 = ticks_now();
    print_u64("calibration ", 2u * (uint64_t)spins);
    print_u64(" ", t1 - t0);
    printf("\n");
    if (memory == NULL || pg_scene_build("pyramid", rows, &def, memory, size, &scene) != PG_OK) {
        printf("pyramid could not be built\n");
        return 1;
    }
    for (step = 1; step < first; ++step) pg_world_step(scene.world);
#ifdef POGON_COUNT_DIVISIONS
    pg_count_ldivmod = 0;
    pg_count_uldivmod = 0;
#endif
    t0 = ticks_now();
    for (step = first; step <= last; ++step) {
        if (pg_world_step(scene.world) != PG_OK) return 1;
    }
    t1 = ticks_now();
    printf("pyramid %lu %lu %lu", (unsigned long)rows, (unsigned long)first, (unsigned long)last);
    print_u64(" ", t1 - t0);
    printf("\n");
#ifdef POGON_COUNT_DIVISIONS
    printf("divisions %lu %lu %lu %lu\n", (unsigned long)first, (unsigned long)last, (unsigned long)pg_count_ldivmod,
           (unsigned long)pg_count_uldivmod);
#endif
    return 0;
}
