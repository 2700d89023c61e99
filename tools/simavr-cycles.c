/* Exact AVR cycles between calls of a marker function, and the stack's peak, with libsimavr
 * (Debian libsimavr-dev).
 *
 * Usage: simavr-cycles FIRMWARE.elf [MARKER_BYTE_ADDRESS_HEX]
 * Runs the firmware on an ATmega328P at 16 MHz until it sleeps with interrupts off (or 2e9
 * cycles). Prints the cycle count each time the program counter reaches the marker (if one is
 * given), one per line, and at the end `stack N`: the peak stack in bytes (RAMEND minus the
 * lowest stack pointer seen, read after every instruction). With the firmware's .data and .bss
 * (from avr-size) that is the RAM a run needs: they sit at the bottom of the 2 KB, the stack at
 * the top. */
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    if (argc != 2 && argc != 3) {
        fprintf(stderr, "usage: %s FIRMWARE.elf [MARKER_HEX]\n", argv[0]);
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
    int marked = argc == 3;
    avr_flashaddr_t marker = marked ? (avr_flashaddr_t)strtoul(argv[2], NULL, 16) : 0;
    /* SPL and SPH in data space (I/O 0x3d and 0x3e, after the 0x20 bytes of registers). */
    unsigned lowest = avr->ramend;
    for (;;) {
        int state = avr_run(avr);
        if (state == cpu_Done || state == cpu_Crashed) {
            break;
        }
        if (marked && avr->pc == marker) {
            printf("%llu\n", (unsigned long long)avr->cycle);
        }
        unsigned sp = avr->data[0x5d] | (unsigned)avr->data[0x5e] << 8;
        if (sp < lowest) {
            lowest = sp;
        }
        if (avr->cycle > 2000000000ULL) {
            fprintf(stderr, "more than 2e9 cycles\n");
            return 1;
        }
    }
    printf("stack %u\n", avr->ramend - lowest);
    return 0;
}
