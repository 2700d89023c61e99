// A 4x4 keypad, one learning debouncer per key (24 bytes of RAM each: 384 for the 16).
// Rows on pins 2-5 (driven LOW one at a time), columns on pins 6-9 (INPUT_PULLUP): a pressed
// key pulls its column LOW while its row is driven. The whole matrix is scanned once a
// millisecond; each key learns its own switch's bounce from the hand-operated prior, and no
// window is longer than the fastest real tap (31 ms), so no tap is lost.
#include <ContactBounce.h>

const uint8_t ROWS[4] = {2, 3, 4, 5};
const uint8_t COLS[4] = {6, 7, 8, 9};
const unsigned long PERIOD_US = 1000; // one scan a millisecond

cb_learner_prior prior;
cb_learner keys[16];
unsigned long next_scan;
unsigned long presses;

void setup() {
  Serial.begin(115200);
  for (uint8_t r = 0; r < 4; r++) {
    pinMode(ROWS[r], OUTPUT);
    digitalWrite(ROWS[r], HIGH);
  }
  for (uint8_t c = 0; c < 4; c++) {
    pinMode(COLS[c], INPUT_PULLUP);
  }
  if (cb_learner_prior_at_period(&prior, 31, 31, PERIOD_US * 1000UL) != CB_OK) {
    Serial.println("bad prior");
    for (;;) {
    }
  }
  for (uint8_t k = 0; k < 16; k++) {
    cb_learner_init(&keys[k], false);
  }
  next_scan = micros();
}

void loop() {
  if ((long)(micros() - next_scan) < 0) {
    return;
  }
  next_scan += PERIOD_US;
  for (uint8_t r = 0; r < 4; r++) {
    digitalWrite(ROWS[r], LOW);
    for (uint8_t c = 0; c < 4; c++) {
      uint8_t k = r * 4 + c;
      if (cb_learner_update(&keys[k], digitalRead(COLS[c]) == LOW, &prior) == CB_EDGE_PRESS) {
        presses++;
        Serial.print("key ");
        Serial.print(k);
        Serial.print(" press ");
        Serial.println(presses);
      }
    }
    digitalWrite(ROWS[r], HIGH);
  }
}
