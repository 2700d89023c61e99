/* The C API on an Arduino Uno (ATmega328P), in C: the lean paths (t_b1v, and the averaged
 * restitution-only time, from a preload's inputs), the closed tier's time on a preloaded switch
 * (cb_preload_seconds_closed) for the switches of switches.h, and the debouncer, printed over the
 * UART. (The tiers through cb_predict_* or cb_bounce_seconds_*, which take a gap or a preload and
 * link both sides' code, do not fit.) scripts/c-api.sh builds it with avr-gcc
 * against libcontact_bounce_c.a, runs it in simavr and compares its lines with the Rust core's
 * (examples/lines.rs) on the host. */
#include <avr/io.h>
#include <avr/sleep.h>

#include "lines.h"

static void uart_init(void) {
    UBRR0H = 0; /* 9600 baud at 16 MHz */
    UBRR0L = 103;
    UCSR0C = (1 << UCSZ01) | (1 << UCSZ00);
    UCSR0B = (1 << TXEN0);
}

static void uart_put(const char *line) {
    for (; *line != '\0'; line++) {
        while ((UCSR0A & (1 << UDRE0)) == 0) {
        }
        UDR0 = (uint8_t)*line;
    }
    while ((UCSR0A & (1 << UDRE0)) == 0) {
    }
    UDR0 = '\n';
}

int main(void) {
    uart_init();
    for (uint32_t i = 0; i < SWITCH_COUNT; i++) {
        tb1v_line(uart_put, i);
        restitution_line(uart_put, i);
        closed_preload_line(uart_put, i);
    }
    debouncer_lines(uart_put);
    learner_lines(uart_put);
    uart_put("done");
    /* Interrupts off and sleep: simavr ends the run. */
    __asm__ volatile("cli");
    sleep_enable();
    sleep_cpu();
    for (;;) {
    }
}
