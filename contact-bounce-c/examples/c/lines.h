/* The lines the C examples print, through a `put` function of the platform's (a firmware that
 * calls only some of these functions links only those: the Uno's calls the lean path). */
#ifndef LINES_H
#define LINES_H

#include "switches.h"

typedef void (*put_line)(const char *line);

/* Writes an unsigned decimal into buf; returns the end. */
static inline char *put_u32(char *buf, uint32_t v) {
    char digits[10];
    int n = 0;
    do {
        digits[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (n > 0) {
        *buf++ = digits[--n];
    }
    return buf;
}

static inline char *put_str(char *buf, const char *s) {
    while (*s != '\0') {
        *buf++ = *s++;
    }
    return buf;
}

/* One prediction as a line: "switch S TIER end_ns N ticks K" (or the error). */
static inline void prediction_line(put_line put, uint32_t index, const char *tier, cb_error e,
                            const cb_prediction *p) {
    char line[96];
    char *at = put_str(line, "switch ");
    at = put_u32(at, index);
    at = put_str(at, " ");
    at = put_str(at, tier);
    if (e != CB_OK) {
        at = put_str(at, " error ");
        at = put_str(at, cb_parameter_name(CB_ERROR_PARAMETER(e)));
        at = put_str(at, " ");
        at = put_u32(at, CB_ERROR_CODE(e));
    } else {
        uint32_t ticks = 0;
        cb_error w = cb_window_ticks(p, 1.5f, 0.0f, 1e-5f, &ticks);
        at = put_str(at, " end_ns ");
        at = put_u32(at, (p->flags & CB_HAS_END) ? (uint32_t)(p->end_time * 1e9f) : 0u);
        at = put_str(at, " ticks ");
        at = put_u32(at, w == CB_OK ? ticks : 0u);
    }
    *at = '\0';
    put(line);
}

/* The lean path on a switch, its preload force -offset * stiffness, and its window from
 * cb_seconds_to_ticks: "switch S tb1v end_ns N ticks K" (or the error: a gap has no preload
 * force). */
static inline void tb1v_line(put_line put, uint32_t index) {
    const cb_switch *s = &SWITCHES[index];
    const cb_preloaded lean = {.mass = s->mass,
                               .stiffness = s->stiffness,
                               .preload_force = -s->offset * s->stiffness,
                               .closing_speed = s->closing_speed,
                               .restitution = s->restitution,
                               .damping_ratio = s->damping_ratio};
    cb_estimate e;
    cb_error r = cb_preload_viscous_bounce_time(&lean, &e);
    if (r != CB_OK) {
        cb_prediction none = {0};
        prediction_line(put, index, "tb1v", r, &none);
        return;
    }
    /* The window as a sketch takes it from the estimate: cb_seconds_to_ticks. */
    uint32_t ticks = 0;
    cb_error w = cb_seconds_to_ticks(e.time, 1.5f, 0.0f, 1e-5f, &ticks);
    char line[96];
    char *at = put_str(line, "switch ");
    at = put_u32(at, index);
    at = put_str(at, " tb1v end_ns ");
    at = put_u32(at, (uint32_t)(e.time * 1e9f));
    at = put_str(at, " ticks ");
    at = put_u32(at, w == CB_OK ? ticks : 0u);
    *at = '\0';
    put(line);
}

/* The lean averaged path on a switch (restitution alone: its damping left out), its preload force
 * -offset * stiffness: "switch S restitution-averaged end_ns N ticks K" (or the error). */
static inline void restitution_line(put_line put, uint32_t index) {
    const cb_switch *s = &SWITCHES[index];
    const cb_preloaded lean = {.mass = s->mass,
                               .stiffness = s->stiffness,
                               .preload_force = -s->offset * s->stiffness,
                               .closing_speed = s->closing_speed,
                               .restitution = s->restitution,
                               .damping_ratio = 0.0f};
    float seconds = 0.0f;
    cb_error r = cb_preload_restitution_bounce_seconds(&lean, &seconds);
    cb_prediction p = {0};
    if (r == CB_OK) {
        p.end_time = seconds;
        p.flags = CB_HAS_END;
    }
    prediction_line(put, index, "restitution-averaged", r, &p);
}

/* The closed tier's time alone on a preloaded switch (its scene typed as a preload: no gap's code
 * linked): "switch S closed-preload end_ns N ticks K" (or the error: a gap is refused, naming the
 * offset). */
static inline void closed_preload_line(put_line put, uint32_t index) {
    float seconds = 0.0f;
    cb_error r = cb_preload_seconds_closed(&SWITCHES[index], &seconds);
    cb_prediction p = {0};
    if (r == CB_OK) {
        p.end_time = seconds;
        p.flags = CB_HAS_END;
    }
    prediction_line(put, index, "closed-preload", r, &p);
}

/* Every tier and the lean paths on one switch of SWITCHES. */
static inline void switch_lines(put_line put, uint32_t i) {
    cb_prediction p;
    tb1v_line(put, i);
    restitution_line(put, i);
    closed_preload_line(put, i);
    prediction_line(put, i, "closed", cb_predict_closed(&SWITCHES[i], &p), &p);
    prediction_line(put, i, "averaged", cb_predict_averaged(&SWITCHES[i], &p), &p);
    prediction_line(put, i, "map", cb_predict_map(&SWITCHES[i], &p), &p);
    prediction_line(put, i, "exact", cb_predict_exact(&SWITCHES[i], &p), &p);
    prediction_line(put, i, "auto", cb_predict_auto(&SWITCHES[i], 0.01f, &p), &p);
    prediction_line(put, i, "auto-exact", cb_predict_auto_exact(&SWITCHES[i], 0.01f, &p), &p);
}

/* The debouncer over SAMPLES with 3-sample windows, in both modes: "pin MODE i EDGE". */
static inline void debouncer_lines(put_line put) {
    for (uint8_t mode = CB_MODE_CONFIRM; mode <= CB_MODE_HOLD_OFF; mode++) {
        cb_windows windows;
        cb_pin pin;
        if (cb_windows_init(&windows, 3, 3, mode) != CB_OK ||
            cb_pin_init(&pin, false) != CB_OK) {
            put("pin init failed");
            return;
        }
        for (uint32_t i = 0; i < SAMPLE_COUNT; i++) {
            cb_edge edge = cb_pin_update(&pin, SAMPLES[i] != 0u, &windows);
            if (edge != CB_EDGE_NONE) {
                char line[48];
                char *at = put_str(line, mode == CB_MODE_CONFIRM ? "pin confirm " : "pin hold-off ");
                at = put_u32(at, i);
                at = put_str(at, edge == CB_EDGE_PRESS ? " press" : edge == CB_EDGE_RELEASE ? " release" : " error");
                *at = '\0';
                put(line);
            }
        }
    }
}


/* A recorded tap sequence through the learning debouncer, from the type's prior at 1 ms samples
 * (31 samples, the fastest tap): 80 taps of 31-70 samples down and up (xorshift32 from
 * 2463534242), each press bouncing at its second sample, every fifth press opening again from
 * sample 8 to 19 (the switch's own reversion), each release closing again at its third sample.
 * "learner i EDGE" per edge, then the windows, the flags and the saved bytes. */
static inline uint32_t tap_next(uint32_t *x) {
    *x ^= *x << 13;
    *x ^= *x >> 17;
    *x ^= *x << 5;
    return *x;
}

static inline void learner_lines(put_line put) {
    cb_learner_prior prior;
    cb_learner key;
    if (cb_learner_prior_at_period(&prior, 31, 31, 1000000u) != CB_OK || cb_learner_init(&key, false) != CB_OK) {
        put("learner init failed");
        return;
    }
    uint32_t x = 2463534242u, i = 0;
    char line[64];
    for (uint32_t k = 0; k < 80; k++) {
        uint32_t down = 31 + tap_next(&x) % 40, up = 31 + tap_next(&x) % 40;
        for (uint32_t j = 0; j < down + up; j++, i++) {
            bool closed = j < down ? !(j == 1 || (k % 5 == 4 && j >= 8 && j < 20)) : (j - down == 2);
            cb_edge edge = cb_learner_update(&key, closed, &prior);
            if (edge != CB_EDGE_NONE) {
                char *at = put_str(line, "learner ");
                at = put_u32(at, i);
                at = put_str(at, edge == CB_EDGE_PRESS ? " press" : edge == CB_EDGE_RELEASE ? " release" : " error");
                *at = '\0';
                put(line);
            }
        }
    }
    uint16_t press = 0, release = 0;
    cb_learned saved;
    if (cb_learner_windows(&key, &prior, &press, &release) != CB_OK || cb_learner_save(&key, &saved) != CB_OK) {
        put("learner windows failed");
        return;
    }
    char *at = put_str(line, "learner windows ");
    at = put_u32(at, press);
    at = put_str(at, " ");
    at = put_u32(at, release);
    at = put_str(at, " flags ");
    at = put_u32(at, cb_learner_flags(&key, &prior));
    *at = '\0';
    put(line);
    at = put_str(line, "learner saved");
    for (uint32_t b = 0; b < 12; b++) {
        at = put_str(at, " ");
        at = put_u32(at, saved.bytes[b]);
    }
    *at = '\0';
    put(line);
}

#endif
