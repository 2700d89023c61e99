/* ContactBounce for Arduino: the C API of contact-bounce. The precompiled archive for the Uno's
 * ATmega328P is src/atmega328p/libContactBounce.a; scripts/arduino-library.sh builds this
 * folder (archive and generated header) from the repository. On the Uno, the lean paths
 * (cb_preload_bounce_time and the like), the debouncer, and the closed, averaged and map tiers
 * through cb_preload_seconds_* fit; the exact tier and either Auto do not (the repository's
 * docs/c-api-uno.md measures each entry point alone). */
#ifndef CONTACT_BOUNCE_ARDUINO_H
#define CONTACT_BOUNCE_ARDUINO_H
#include "contact_bounce.h"
#endif
