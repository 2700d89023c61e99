/* The switches and the sample sequence the C examples print lines for; examples/lines.rs
 * prints the same lines from the Rust core, and scripts/c-api.sh compares them. */
#ifndef SWITCHES_H
#define SWITCHES_H

#include "contact_bounce.h"

/* mass kg, stiffness N/m, offset m, R, zeta, closing speed m/s, threshold fraction */
static const cb_switch SWITCHES[] = {
    /* The tactile dome: 1 N preload on 5000 N/m. */
    {5e-5f, 5000.0f, -2e-4f, 0.7f, 0.03f, 0.5f, 0.0f},
    /* A leaf over a 0.1 mm gap, counted down to 1 % of its first impulse. */
    {1e-3f, 100.0f, 1e-4f, 0.8f, 0.05f, 0.3f, 0.01f},
    /* A preload without damping: Zeno accumulation, summed exactly. */
    {2e-6f, 400.0f, -5e-5f, 0.6f, 0.0f, 0.2f, 0.0f},
};
#define SWITCH_COUNT (sizeof SWITCHES / sizeof SWITCHES[0])

/* Samples of one pin (1 = closed): a press that bounces, then a release that bounces. */
static const uint8_t SAMPLES[] = {0, 1, 0, 1, 1, 0, 1, 1, 1, 1, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0};
#define SAMPLE_COUNT (sizeof SAMPLES / sizeof SAMPLES[0])

#endif
