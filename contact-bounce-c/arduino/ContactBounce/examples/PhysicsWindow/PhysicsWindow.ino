// A debounce window from the switch's physics, and the debouncer, with nothing but this library
// and <stdint.h> (so it compiles without any board's core headers). In a real sketch, read the
// pin with digitalRead(PIN) == LOW (a button to ground with INPUT_PULLUP) instead of `level`.
#include <stdint.h>
#include <ContactBounce.h>

static cb_windows windows;
static cb_pin pin;
volatile uint8_t level;   // the contact as sampled: 1 closed
volatile uint16_t presses; // debounced presses

void setup() {
  // A tactile dome: 50 mg moving mass on 5000 N/m, 1 N preload, R 0.7, zeta 0.03, 0.5 m/s.
  cb_estimate bounce;
  uint32_t ticks = 0;
  if (cb_preload_bounce_time(5e-5f, 5000.0f, 1.0f, 0.7f, 0.03f, 0.5f, &bounce) != CB_OK ||
      cb_seconds_to_ticks(bounce.time, 1.5f, 0.0f, 1e-4f, &ticks) != CB_OK || // 0.1 ms samples
      cb_windows_init(&windows, ticks, ticks, CB_MODE_HOLD_OFF) != CB_OK ||
      cb_pin_init(&pin, false) != CB_OK) {
    for (;;) {
    }
  }
}

void loop() {
  // Call once per sample period (0.1 ms here, from a timer in a real sketch).
  if (cb_pin_update(&pin, level != 0, &windows) == CB_EDGE_PRESS) {
    presses = presses + 1;
  }
}
