// A debounce window computed from the switch's physics, and the 2-byte debouncer.
//
// Use this for a switch whose mechanics are known and repeatable: a relay, a reed switch, a
// contactor (its moving mass, stiffness, preload, restitution, damping and closing speed). For
// anything a hand presses, use LearnButton: a hand's switch bounces longer and less regularly
// than its mechanics predict (a tactile dome's physics window, about 0.2 ms, lets a real push
// button's bounces through as extra presses), and the learner finds the window from the switch
// itself. Wire the contact from pin 2 to ground.
#include <ContactBounce.h>

const uint8_t CONTACT_PIN = 2;
const unsigned long PERIOD_US = 100; // one sample each 0.1 ms

cb_windows windows;
cb_pin contact;
unsigned long next_sample;
unsigned long presses;

void setup() {
  pinMode(CONTACT_PIN, INPUT_PULLUP);
  Serial.begin(115200);
  // A tactile dome: 50 mg moving mass on 5000 N/m, 1 N preload, R 0.7, zeta 0.03, 0.5 m/s.
  cb_preloaded dome;
  dome.mass = 5e-5f;
  dome.stiffness = 5000.0f;
  dome.preload_force = 1.0f;
  dome.closing_speed = 0.5f;
  dome.restitution = 0.7f;
  dome.damping_ratio = 0.03f;
  cb_estimate bounce;
  uint32_t ticks = 0;
  if (cb_preload_viscous_bounce_time(&dome, &bounce) != CB_OK ||
      cb_seconds_to_ticks(bounce.time, 1.5f, 0.0f, PERIOD_US * 1e-6f, &ticks) != CB_OK ||
      cb_windows_init(&windows, ticks, ticks, CB_MODE_HOLD_OFF) != CB_OK ||
      cb_pin_init(&contact, digitalRead(CONTACT_PIN) == LOW) != CB_OK) {
    Serial.println("bad switch");
    for (;;) {
    }
  }
  Serial.print("window, samples: ");
  Serial.println((unsigned long)ticks);
  next_sample = micros();
}

void loop() {
  if ((long)(micros() - next_sample) < 0) {
    return;
  }
  next_sample += PERIOD_US;
  if (cb_pin_update(&contact, digitalRead(CONTACT_PIN) == LOW, &windows) == CB_EDGE_PRESS) {
    presses++;
    Serial.print("press ");
    Serial.println(presses);
  }
}
