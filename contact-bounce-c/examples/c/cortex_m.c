/* The C API on a Cortex-M4F (QEMU's mps2-an386) and a Cortex-M0 (QEMU's microbit, for the M0+ of
 * the SAMD21 and RP2040: the same ARMv6-M instructions), in C, with no C library: every tier on the
 * switches of switches.h, the debouncer and the learner, printed through semihosting.
 * scripts/c-api.sh builds it with arm-none-eabi-gcc against libcontact_bounce_c.a built for
 * thumbv7em-none-eabihf and thumbv6m-none-eabi, and compares its lines with the Rust core's on
 * the host. */
#include "lines.h"

/* Semihosting: operation in r0, argument in r1, then bkpt 0xAB; the result in r0. */
static uint32_t semihost(uint32_t op, const void *arg) {
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

/* The host's standard output: SYS_OPEN of ":tt" for writing. */
static uint32_t stdout_handle(void) {
    static uint32_t handle = 0xFFFFFFFFu;
    if (handle == 0xFFFFFFFFu) {
        const uint32_t open[3] = {(uint32_t)":tt", 4u /* "w" */, 3u};
        handle = semihost(0x01, open);
    }
    return handle;
}

static void put(const char *line) {
    char buf[100];
    char *at = put_str(buf, line);
    *at++ = '\n';
    const uint32_t write[3] = {stdout_handle(), (uint32_t)buf, (uint32_t)(at - buf)};
    semihost(0x05, write); /* SYS_WRITE */
}

int main(void) {
    for (uint32_t i = 0; i < SWITCH_COUNT; i++) {
        switch_lines(put, i);
    }
    debouncer_lines(put);
    learner_lines(put);
    return 0;
}

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;

void reset(void) {
    for (uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;) {
        *dst++ = *src++;
    }
    for (uint32_t *dst = &_sbss; dst < &_ebss;) {
        *dst++ = 0;
    }
#if defined(__ARM_FP)
    /* The FPU on (CPACR: full access to CP10 and CP11) before any float instruction. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n isb");
#endif
    main();
    semihost(0x18, (const void *)0x20026u); /* SYS_EXIT, ADP_Stopped_ApplicationExit: status 0 */
    for (;;) {
    }
}

static void halt(void) {
    semihost(0x18, (const void *)0x20023u); /* SYS_EXIT, ADP_Stopped_RunTimeErrorUnknown: status 1 */
    for (;;) {
    }
}

/* The initial stack pointer, reset, and every exception a fault that stops QEMU. */
__attribute__((section(".vectors"), used)) static void (*const VECTORS[16])(void) = {
    (void (*)(void))&_estack, reset, halt, halt, halt, halt, halt, 0, 0, 0, 0, halt, halt, 0, halt, halt,
};
