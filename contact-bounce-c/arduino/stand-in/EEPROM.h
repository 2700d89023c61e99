/* The stand-in's EEPROM (see Arduino.h): the API of the AVR core's EEPROM library with the
 * begin(size) and commit() of the ESP32 and RP2040 cores' emulations, on RAM (kept only for
 * the run). */
#ifndef STAND_IN_EEPROM_H
#define STAND_IN_EEPROM_H

#include <stddef.h>
#include <stdint.h>

class StandInEeprom {
public:
    void begin(size_t size) { (void)size; }
    bool commit() { return true; }
    size_t length() const { return sizeof bytes; }
    template <typename T> T &get(int address, T &value) {
        uint8_t *to = (uint8_t *)&value;
        for (size_t i = 0; i < sizeof value; i++) {
            to[i] = bytes[(size_t)address + i];
        }
        return value;
    }
    template <typename T> const T &put(int address, const T &value) {
        const uint8_t *from = (const uint8_t *)&value;
        for (size_t i = 0; i < sizeof value; i++) {
            bytes[(size_t)address + i] = from[i];
        }
        return value;
    }
    uint8_t bytes[64];
};
extern StandInEeprom EEPROM;

#endif
