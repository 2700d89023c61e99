// A push button debounced by the learning debouncer: wire the button from pin 2 to ground.
//
// It starts from the prior of a hand-operated button (31 ms windows at 1 ms samples) and learns
// how long this button really bounces, so its windows shrink to what the button needs; no
// window is ever longer than the fastest real tap (31 ms: 16 taps a second), so no tap is lost.
// Every press is counted and printed. What it learned is saved to EEPROM (where the board has
// one, or the core emulates one in flash) so a reboot does not start from the prior again.
//
// Use this for anything a hand presses (buttons, keys, rocker switches). For a switch whose
// mechanics you know (a relay, a reed switch), PhysicsWindow computes its window instead.
#include <ContactBounce.h>

#if defined(ARDUINO_ARCH_AVR) || defined(ARDUINO_ARCH_MEGAAVR) || defined(ARDUINO_ARCH_RENESAS) || \
    defined(ARDUINO_ARCH_ESP32) || defined(ARDUINO_ARCH_RP2040)
#include <EEPROM.h>
#define HAS_EEPROM 1
#else
#define HAS_EEPROM 0 // (SAMD, mbed: bring your own flash storage for the 12 bytes)
#endif

const uint8_t BUTTON_PIN = 2;
const unsigned long PERIOD_US = 1000; // one sample a millisecond
const int SAVED_AT = 0;               // the EEPROM address of the 12 learned bytes

cb_learner_prior prior;
cb_learner button;
cb_learned saved;
unsigned long next_sample;
unsigned long presses;

bool pressed() { return digitalRead(BUTTON_PIN) == LOW; } // INPUT_PULLUP: LOW when pressed

void setup() {
  pinMode(BUTTON_PIN, INPUT_PULLUP);
  Serial.begin(115200);
  // The prior of a hand-operated button: 31-sample windows, samples of PERIOD_US.
  if (cb_learner_prior_at_period(&prior, 31, 31, PERIOD_US * 1000UL) != CB_OK) {
    Serial.println("bad prior");
    for (;;) {
    }
  }
  bool restored = false;
#if HAS_EEPROM
#if defined(ARDUINO_ARCH_ESP32) || defined(ARDUINO_ARCH_RP2040)
  EEPROM.begin(64); // these cores emulate EEPROM in flash
#endif
  EEPROM.get(SAVED_AT, saved);
  // Erased or foreign bytes are refused (an error code): then it starts from the prior.
  restored = cb_learner_restore(&button, pressed(), &saved) == CB_OK;
#endif
  if (!restored) {
    cb_learner_init(&button, pressed());
  }
  Serial.println(restored ? "restored" : "from the prior");
  next_sample = micros();
}

void save() {
#if HAS_EEPROM
  cb_learned now;
  // Written only when it changed: a learner's bytes settle after 255 presses of each kind.
  if (cb_learner_save(&button, &now) == CB_OK && memcmp(&now, &saved, sizeof now) != 0) {
    saved = now;
    EEPROM.put(SAVED_AT, saved);
#if defined(ARDUINO_ARCH_ESP32) || defined(ARDUINO_ARCH_RP2040)
    EEPROM.commit();
#endif
  }
#endif
}

void loop() {
  if ((long)(micros() - next_sample) < 0) {
    return; // not yet: one sample each PERIOD_US
  }
  next_sample += PERIOD_US;
  cb_edge edge = cb_learner_update(&button, pressed(), &prior);
  if (edge == CB_EDGE_PRESS) {
    presses++;
    Serial.print("press ");
    Serial.println(presses);
  } else if (edge == CB_EDGE_RELEASE) {
    save();
  }
}
