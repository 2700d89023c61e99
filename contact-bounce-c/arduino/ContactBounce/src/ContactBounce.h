/* ContactBounce for Arduino: the C API of contact-bounce (the learning debouncer cb_learner_*,
 * the debouncer cb_pin_*, and windows from a switch's physics). One precompiled archive per board
 * family under src/ (the library's README lists them and how the Arduino builder picks one);
 * scripts/arduino-library.sh builds this folder from the repository. On the Uno, the learner,
 * the debouncer, the lean paths (cb_preload_viscous_bounce_time and the like) and the closed, averaged
 * and map tiers through cb_preload_seconds_* fit; the exact tier and either Auto do not (the
 * repository's docs/reports/c-api-uno.md measures each entry point alone). */
#ifndef CONTACT_BOUNCE_ARDUINO_H
#define CONTACT_BOUNCE_ARDUINO_H
#include "contact_bounce.h"
#endif
