/* count_divisions.S — counts the 64-bit divisions of a firmware (tools/size/step_count.c
 * built with -DPOGON_COUNT_DIVISIONS): linked with -Wl,--wrap=__aeabi_ldivmod and
 * -Wl,--wrap=__aeabi_uldivmod, every call of those libgcc helpers comes here first,
 * adds one to its counter and goes on to the helper with r0-r3 and lr untouched (the
 * helpers return the quotient and the remainder in r0-r3, so no C wrapper could pass
 * them on). ARMv6-M instructions only, so it also runs on the Cortex-M0+. */
    .syntax unified
    .thumb
    .text

    .macro counted helper, counter
    .global __wrap_\helper
    .type __wrap_\helper, %function
    .thumb_func
__wrap_\helper:
    push {r4, r5}
    ldr r4, =\counter
    ldr r5, [r4]
    adds r5, r5, #1
    str r5, [r4]
    ldr r4, =__real_\helper
    mov ip, r4
    pop {r4, r5}
    bx ip
    .ltorg
    .endm

    counted __aeabi_ldivmod, pg_count_ldivmod
    counted __aeabi_uldivmod, pg_count_uldivmod

    .bss
    .align 2
    .global pg_count_ldivmod
pg_count_ldivmod:
    .space 4
    .global pg_count_uldivmod
pg_count_uldivmod:
    .space 4
