/* ContactBounce for Arduino: the C API of contact-bounce. The precompiled archive for the Uno's
 * ATmega328P is src/atmega328p/libContactBounce.a; scripts/arduino-library.sh builds this
 * folder (archive and generated header) from the repository. */
#ifndef CONTACT_BOUNCE_ARDUINO_H
#define CONTACT_BOUNCE_ARDUINO_H
#include "contact_bounce.h"
#endif
