/* Exact AVR cycles between calls of a marker function, with libsimavr (Debian libsimavr-dev).
 *
 * Usage: simavr-cycles FIRMWARE.elf MARKER_BYTE_ADDRESS_HEX
 * Prints the cycle count each time the program counter reaches the marker, one per line, and
 * stops when the firmware sleeps with interrupts off or after 2e9 cycles. */
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: %s FIRMWARE.elf MARKER_HEX\n", argv[0]);
        return 2;
    }
    elf_firmware_t firmware = {0};
    if (elf_read_firmware(argv[1], &firmware) != 0) {
        fprintf(stderr, "cannot read %s\n", argv[1]);
        return 2;
    }
    avr_t *avr = avr_make_mcu_by_name("atmega328p");
    if (!avr) {
        fprintf(stderr, "no atmega328p in libsimavr\n");
        return 2;
    }
    avr_init(avr);
    avr->frequency = 16000000;
    avr->log = LOG_NONE;
    avr_load_firmware(avr, &firmware);
    avr_flashaddr_t marker = (avr_flashaddr_t)strtoul(argv[2], NULL, 16);
    for (;;) {
        int state = avr_run(avr);
        if (state == cpu_Done || state == cpu_Crashed) {
            break;
        }
        if (avr->pc == marker) {
            printf("%llu\n", (unsigned long long)avr->cycle);
        }
        if (avr->cycle > 2000000000ULL) {
            fprintf(stderr, "more than 2e9 cycles\n");
            return 1;
        }
    }
    return 0;
}
