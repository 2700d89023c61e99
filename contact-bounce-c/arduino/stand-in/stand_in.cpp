/* The stand-in core (see Arduino.h): simulated time, a hand tapping bouncing switches, Serial
 * out through the simulator (the Uno's UART in simavr, semihosting in QEMU), and main(). */
#include "Arduino.h"
#include "EEPROM.h"

StandInSerial Serial;
StandInEeprom EEPROM = {{
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,
}}; /* erased, as a new chip's */

/* The script: TAPS taps, tap i pressed at start(i) and held hold(i) microseconds, on key
 * i % 16 of the matrix (or on the button). Press to press 149 to 179 ms, held 35 to 94 ms, up
 * at least 56 ms, so every tap and every gap between taps lasts more than the fastest tap
 * (31 ms); each press
 * bounces for up to 4.5 ms and each release for up to 3 ms, the contact changing every 100 to
 * 340 us meanwhile. The examples must report exactly TAPS presses (the physics window of a
 * tactile dome, shorter than these bounces, reports more: PhysicsWindow's note). */
static const uint32_t TAPS = 40;
static const uint32_t FIRST = 300000;
static uint32_t start(uint32_t i) { return FIRST + i * 150000u + (i * 7919u % 30u) * 1000u; }
static uint32_t hold(uint32_t i) { return 35000u + (i * 37u % 60u) * 1000u; }
static uint32_t press_bounce(uint32_t i) { return 500u + i * 1237u % 4000u; }
static uint32_t release_bounce(uint32_t i) { return 300u + i * 911u % 2700u; }
static uint32_t flip(uint32_t i) { return 100u + (i % 5u) * 60u; }

static uint32_t now_us;
static const uint32_t STEP_US = 25; /* simulated time per micros() call */

/* The key (0 to 15) whose contact is closed at `t`, or -1. */
static int closed_key(uint32_t t) {
    if (t < FIRST) {
        return -1;
    }
    uint32_t i = (t - FIRST) / 150000u; /* the tap whose slot t is in; the one before may bounce */
    for (uint32_t k = (i > 0 ? i - 1 : 0); k <= i && k < TAPS; k++) {
        uint32_t s = start(k), h = hold(k);
        if (t < s || t >= s + h + release_bounce(k)) {
            continue;
        }
        bool on;
        if (t < s + press_bounce(k)) {
            on = (t - s) / flip(k) % 2u == 0; /* closes at s, then bounces */
        } else if (t < s + h) {
            on = true;
        } else {
            on = (t - s - h) / flip(k) % 2u == 1; /* opens at s + h, then bounces */
        }
        return on ? (int)(k % 16u) : -1;
    }
    return -1;
}

static uint8_t modes[16];
static uint8_t levels[16];

void pinMode(uint8_t pin, uint8_t mode) {
    if (pin < 16) {
        modes[pin] = mode;
        levels[pin] = HIGH;
    }
}

void digitalWrite(uint8_t pin, uint8_t level) {
    if (pin < 16) {
        levels[pin] = level;
    }
}

int digitalRead(uint8_t pin) {
#if defined(STAND_IN_MATRIX)
    /* A column reads LOW where a closed key joins it to a row driven LOW. */
    if (pin >= STAND_IN_COL_PIN0 && pin < STAND_IN_COL_PIN0 + 4) {
        int key = closed_key(now_us);
        for (uint8_t row = 0; row < 4; row++) {
            uint8_t r = STAND_IN_ROW_PIN0 + row;
            if (modes[r] == OUTPUT && levels[r] == LOW && key == row * 4 + (pin - STAND_IN_COL_PIN0)) {
                return LOW;
            }
        }
    }
    return HIGH;
#else
    /* Every tap is the button's: it pulls its pin LOW while closed. */
    return pin == STAND_IN_BUTTON_PIN && closed_key(now_us) >= 0 ? LOW : HIGH;
#endif
}

unsigned long micros(void) {
    now_us += STEP_US;
    return now_us;
}

unsigned long millis(void) { return micros() / 1000u; }

/* Output and the end of the run, per simulator. */
#if defined(__AVR__)
#include <avr/io.h>
#include <avr/sleep.h>
static void out(char c) {
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    UDR0 = (uint8_t)c;
}
static void stop(void) {
    __asm__ volatile("cli");
    sleep_cpu(); /* simavr stops on sleep with interrupts off */
}
#elif defined(__arm__)
static uint32_t semihost(uint32_t op, const void *arg) {
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}
/* Lines to the host's standard output: SYS_OPEN of ":tt" for writing, then SYS_WRITE. */
static void out(char c) {
    static uint32_t handle = 0xFFFFFFFFu;
    static char line[80];
    static uint32_t n;
    line[n++] = c;
    if (c != '\n' && n < sizeof line) {
        return;
    }
    if (handle == 0xFFFFFFFFu) {
        const uint32_t open[3] = {(uint32_t)":tt", 4u /* "w" */, 3u};
        handle = semihost(0x01, open);
    }
    const uint32_t write[3] = {handle, (uint32_t)line, n};
    semihost(0x05, write);
    n = 0;
}
static void stop(void) { semihost(0x18, (const void *)0x20026u); } /* SYS_EXIT, status 0 */
#else
static volatile char sink;
static void out(char c) { sink = c; } /* compiled and linked only (ESP32-C3): no simulator */
static void stop(void) {}
#endif

void StandInSerial::print(const char *text) {
    while (*text) {
        out(*text++);
    }
}

void StandInSerial::print(unsigned long value) {
    char digits[10];
    int n = 0;
    do {
        digits[n++] = (char)('0' + value % 10u);
        value /= 10u;
    } while (value);
    while (n) {
        out(digits[--n]);
    }
}

void StandInSerial::print(long value) {
    if (value < 0) {
        out('-');
        print((unsigned long)(-(value + 1)) + 1u);
    } else {
        print((unsigned long)value);
    }
}

int main(void) {
    setup();
    while (now_us < start(TAPS - 1) + 500000u) {
        loop();
    }
    Serial.print("end\n");
    stop();
    for (;;) {
    }
}

#if defined(__arm__)
/* Reset for QEMU (cortex_m.ld's layout): data, bss, the FPU, main. */
extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
extern "C" void reset(void) {
    for (uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;) {
        *dst++ = *src++;
    }
    for (uint32_t *dst = &_sbss; dst < &_ebss;) {
        *dst++ = 0;
    }
#if defined(__ARM_FP)
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20; /* CP10 and CP11: full access */
    __asm__ volatile("dsb\n isb");
#endif
    main();
}
static void halt(void) {
    Serial.print("fault\n");
    semihost(0x18, (const void *)0x20023u); /* SYS_EXIT, status 1 */
    for (;;) {
    }
}
__attribute__((section(".vectors"), used)) static void (*const VECTORS[16])(void) = {
    (void (*)(void))&_estack, reset, halt, halt, halt, halt, halt, 0, 0, 0, 0, halt, halt, 0, halt, halt,
};
#endif
