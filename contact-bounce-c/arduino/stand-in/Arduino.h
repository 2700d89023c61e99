/* A stand-in for a board's Arduino core: the part of its API the ContactBounce examples use
 * (pins, micros(), Serial, setup() and loop()), so that scripts/arduino-library.sh can compile
 * each example for each board family with Debian's cross compilers, link it against the
 * library laid out as the Arduino builder lays it out, and run it in simavr or QEMU. It is not
 * a board core: no board's cores install from Debian's packages.
 *
 * Its pins are a simulated hand on switches that bounce (stand_in.cpp): a button on any pin,
 * or a 4x4 key matrix whose rows are driven LOW one at a time and whose columns read LOW where
 * a pressed key joins them to the driven row. Time is simulated too: each micros() call
 * advances it, and the program stops when the script of taps is over. */
#ifndef STAND_IN_ARDUINO_H
#define STAND_IN_ARDUINO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define HIGH 1
#define LOW 0
#define INPUT 0
#define OUTPUT 1
#define INPUT_PULLUP 2

void pinMode(uint8_t pin, uint8_t mode);
void digitalWrite(uint8_t pin, uint8_t level);
int digitalRead(uint8_t pin);
unsigned long micros(void);
unsigned long millis(void);

/* The simulated switches: a button on STAND_IN_BUTTON_PIN, or the matrix's rows and columns. */
#define STAND_IN_BUTTON_PIN 2
#define STAND_IN_ROW_PIN0 2
#define STAND_IN_COL_PIN0 6

class StandInSerial {
public:
    void begin(unsigned long baud) { (void)baud; }
    operator bool() const { return true; }
    void print(const char *text);
    void print(unsigned long value);
    void print(long value);
    void print(unsigned int value) { print((unsigned long)value); }
    void print(int value) { print((long)value); }
    void println() { print("\n"); }
    template <typename T> void println(T value) {
        print(value);
        println();
    }
};
extern StandInSerial Serial;

void setup();
void loop();

#endif
