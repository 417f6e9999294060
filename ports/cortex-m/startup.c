/* startup.c — reset handler and vector table for the Cortex-M firmware (mps2.ld).
 *
 * The reset handler copies .data from flash, clears .bss, opens the semihosting console
 * (newlib's librdimon: printf reaches the host through qemu -semihosting), runs main and
 * passes its status to exit, which ends qemu. Every exception other than reset and
 * SysTick is a fault: it is reported through semihosting and ends qemu with a failure. */
#include <stdint.h>
#include <stdlib.h>

extern uint32_t __data_load__[], __data_start__[], __data_end__[];
extern uint32_t __bss_start__[], __bss_end__[];
extern uint32_t __stack_top__[];

extern int main(void);
extern void initialise_monitor_handles(void);
void pg_reset_handler(void);
void pg_systick_handler(void);

/* Semihosting call (ARMv6-M and v7-M alike): operation in r0, argument in r1. */
static void pg_semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
}

/* Any exception but reset and SysTick is a fault here: say so on the host's console
 * (SYS_WRITE0) and end qemu with a failure (SYS_EXIT, ADP_Stopped_RunTimeErrorUnknown),
 * so a test fails at once instead of timing out. No C library: it may be what faulted. */
static void pg_unexpected_exception(void)
{
    pg_semihost(0x04u, "pogon cortex-m: unexpected exception (fault)\n");
    pg_semihost(0x18u, (const void *)0x20023u);
    for (;;) {
    }
}

/* SysTick is the firmware's instruction counter (bench.c); a weak default keeps the
 * probe firmware free of it. */
__attribute__((weak)) void pg_systick_handler(void) {}

typedef void (*pg_vector)(void);

__attribute__((section(".vectors"), used)) static const pg_vector vectors[16] = {
    (pg_vector)(uintptr_t)__stack_top__,
    pg_reset_handler,
    pg_unexpected_exception, /* NMI */
    pg_unexpected_exception, /* HardFault */
    pg_unexpected_exception, /* MemManage (v7-M) */
    pg_unexpected_exception, /* BusFault (v7-M) */
    pg_unexpected_exception, /* UsageFault (v7-M) */
    0, 0, 0, 0,
    pg_unexpected_exception, /* SVCall */
    pg_unexpected_exception, /* DebugMonitor (v7-M) */
    0,
    pg_unexpected_exception, /* PendSV */
    pg_systick_handler,
};

/* newlib's exit runs __libc_fini_array, which calls _fini (crti.o's, left out by
 * -nostartfiles); C has no static destructors, so there is nothing to run. */
void _init(void);
void _fini(void);
void _init(void) {}
void _fini(void) {}

void pg_reset_handler(void)
{
    uint32_t *dst = __data_start__;
    const uint32_t *src = __data_load__;
    while (dst < __data_end__) *dst++ = *src++;
    for (dst = __bss_start__; dst < __bss_end__; ++dst) *dst = 0;
#if defined(__ARM_FP)
    /* Hard-float ABI: the C library may use the FPU (printf saves its registers), so
     * grant access to CP10 and CP11. pogon never does: scripts/check-no-float.sh proves
     * that on its objects (the cortex_m_size_and_no_float test). */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    initialise_monitor_handles();
    exit(main());
}
