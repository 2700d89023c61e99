/* The C API from C, on the host: prints the lines of every tier and of the debouncer (compared
 * with the Rust core's by scripts/c-api.sh), and checks that bad inputs return error codes.
 * Exit status 1 on a failed check. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lines.h"

static int failures = 0;

static void put(const char *line) { puts(line); }

static void expect(cb_error e, uint8_t code, uint8_t parameter, const char *what) {
    if (CB_ERROR_CODE(e) != code || CB_ERROR_PARAMETER(e) != parameter) {
        fprintf(stderr, "FAIL %s: code %u parameter %s, expected code %u parameter %s\n", what,
                CB_ERROR_CODE(e), cb_parameter_name(CB_ERROR_PARAMETER(e)), code, cb_parameter_name(parameter));
        failures++;
    }
}

static void bad_inputs(void) {
    const cb_switch dome = SWITCHES[0];
    cb_prediction p;
    cb_switch s;
    uint32_t ticks = 0;

    expect(cb_switch_check(&dome), CB_OK, CB_PARAM_NONE, "the dome is valid");
    expect(cb_switch_check(NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch");
    expect(cb_predict_closed(NULL, &p), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch, closed");
    expect(cb_predict_map(&dome, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL prediction");

    s = dome;
    s.mass = NAN;
    expect(cb_predict_exact(&s, &p), CB_ERR_NAN, CB_PARAM_MASS, "NaN mass");
    s = dome;
    s.stiffness = -1.0f;
    expect(cb_predict_closed(&s, &p), CB_ERR_NOT_POSITIVE, CB_PARAM_STIFFNESS, "negative stiffness");
    s = dome;
    s.offset = INFINITY;
    expect(cb_predict_averaged(&s, &p), CB_ERR_INFINITE, CB_PARAM_OFFSET, "infinite offset");
    s = dome;
    s.restitution = 1.5f;
    expect(cb_predict_map(&s, &p), CB_ERR_OUT_OF_RANGE, CB_PARAM_RESTITUTION, "R above 1");
    s = dome;
    s.damping_ratio = -0.1f;
    expect(cb_switch_check(&s), CB_ERR_NEGATIVE, CB_PARAM_DAMPING_RATIO, "negative zeta");
    s = dome;
    s.closing_speed = 0.0f;
    expect(cb_switch_check(&s), CB_ERR_NOT_POSITIVE, CB_PARAM_CLOSING_SPEED, "zero closing speed");
    s = dome;
    s.threshold_fraction = 1.0f;
    expect(cb_switch_check(&s), CB_ERR_OUT_OF_RANGE, CB_PARAM_THRESHOLD, "threshold of 1");
    /* Elastic impacts on a damped preload decay forever and never end: a threshold is needed. */
    s = dome;
    s.restitution = 1.0f;
    expect(cb_switch_check(&s), CB_ERR_THRESHOLD_REQUIRED, CB_PARAM_THRESHOLD, "endless, no threshold");
    expect(cb_predict_auto(&dome, NAN, &p), CB_ERR_NAN, CB_PARAM_TOLERANCE, "NaN tolerance");
    expect(cb_predict_auto(&dome, 0.0f, &p), CB_ERR_NOT_POSITIVE, CB_PARAM_TOLERANCE, "zero tolerance");
    expect(cb_predict_auto_exact(NULL, 0.01f, &p), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch (auto-exact)");
    expect(cb_predict_auto_exact(&dome, NAN, &p), CB_ERR_NAN, CB_PARAM_TOLERANCE, "NaN tolerance (auto-exact)");
    expect(cb_predict_auto_exact(&dome, -1.0f, &p), CB_ERR_NOT_POSITIVE, CB_PARAM_TOLERANCE, "negative tolerance (auto-exact)");

    expect(cb_predict_closed(&dome, &p), CB_OK, CB_PARAM_NONE, "the dome predicts");
    expect(cb_window_ticks(NULL, 1.5f, 0.0f, 1e-5f, &ticks), CB_ERR_NULL, CB_PARAM_POINTER, "NULL prediction, window");
    expect(cb_window_ticks(&p, 1.5f, 0.0f, 1e-5f, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL ticks");
    expect(cb_window_ticks(&p, 0.5f, 0.0f, 1e-5f, &ticks), CB_ERR_OUT_OF_RANGE, CB_PARAM_MARGIN_FACTOR, "factor below 1");
    expect(cb_window_ticks(&p, 1.5f, NAN, 1e-5f, &ticks), CB_ERR_NAN, CB_PARAM_MARGIN_EXTRA, "NaN extra");
    expect(cb_window_ticks(&p, 1.5f, 0.0f, 0.0f, &ticks), CB_ERR_NOT_POSITIVE, CB_PARAM_SAMPLE_PERIOD, "zero period");
    expect(cb_window_ticks(&p, 1.5f, 0.0f, 1e-30f, &ticks), CB_ERR_OVERFLOW, CB_PARAM_SAMPLE_PERIOD, "window beyond u32");
    /* A prediction with no end and no last impact (flags cleared by the caller). */
    p.flags = 0;
    expect(cb_window_ticks(&p, 1.5f, 0.0f, 1e-5f, &ticks), CB_ERR_ENDLESS, CB_PARAM_TIME, "endless window");

    /* The lean paths take the switch by name, in the Rust crate's order. */
    const cb_preloaded lean = {.mass = 5e-5f, .stiffness = 5000.0f, .preload_force = 1.0f,
                               .closing_speed = 0.5f, .restitution = 0.7f, .damping_ratio = 0.03f};
    cb_preloaded bad_lean = lean;
    cb_estimate est;
    expect(cb_preload_viscous_bounce_time(&lean, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL estimate");
    expect(cb_preload_viscous_bounce_time(NULL, &est), CB_ERR_NULL, CB_PARAM_POINTER, "NULL lean switch");
    bad_lean.preload_force = -1.0f;
    expect(cb_preload_viscous_bounce_time(&bad_lean, &est), CB_ERR_NOT_POSITIVE, CB_PARAM_PRELOAD_FORCE, "negative preload force");
    bad_lean = lean;
    bad_lean.restitution = NAN;
    expect(cb_preload_viscous_bounce_time(&bad_lean, &est), CB_ERR_NAN, CB_PARAM_RESTITUTION, "NaN R, lean path");
    float seconds = -1.0f;
    expect(cb_preload_viscous_bounce_seconds(&lean, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL seconds, lean path");
    bad_lean = lean;
    bad_lean.damping_ratio = -0.1f;
    expect(cb_preload_viscous_bounce_seconds(&bad_lean, &seconds), CB_ERR_NEGATIVE, CB_PARAM_DAMPING_RATIO, "negative zeta, lean path");
    expect(cb_preload_viscous_bounce_seconds(&lean, &seconds), CB_OK, CB_PARAM_NONE, "the lean time alone");
    expect(cb_preload_viscous_bounce_time(&lean, &est), CB_OK, CB_PARAM_NONE, "the lean estimate");
    if (seconds != est.time) {
        fprintf(stderr, "FAIL the lean time alone %g is not the estimate's %g\n", (double)seconds, (double)est.time);
        failures++;
    }
    /* Each input where its name says: t_b1v from the formula, in double, with the dome's
     * distinct numbers, to 1e-5. Closing speed and restitution swapped (0.7 m/s, R = 0.5) the
     * time is 40 % off; every other swap of two inputs is refused or moves it by 1.2 % (mass
     * with closing speed) or more. */
    {
        const double omega = sqrt(5000.0 / 5e-5), depth = 1.0 / 5000.0, zeta = 0.03;
        const double impulse = 2.0 * 0.7 * 0.5, loss = 1.0 - 0.7;
        const double want = 3.0 / (2.0 * zeta * omega) * log1p(2.0 * zeta * impulse / (3.0 * loss * omega * depth));
        if (fabs(est.time / want - 1.0) > 1e-5) {
            fprintf(stderr, "FAIL the lean t_b1v %g is not the formula's %g: an input in the wrong place?\n",
                    (double)est.time, want);
            failures++;
        }
        bad_lean = lean;
        bad_lean.closing_speed = 0.7f;
        bad_lean.restitution = 0.5f;
        cb_estimate swapped;
        expect(cb_preload_viscous_bounce_time(&bad_lean, &swapped), CB_OK, CB_PARAM_NONE, "the swapped inputs");
        if (fabs(swapped.time / want - 1.0) < 0.3) {
            fprintf(stderr, "FAIL a swap of closing speed and restitution moves t_b1v by only %g\n",
                    swapped.time / want - 1.0);
            failures++;
        }
    }
    const cb_preloaded undamped = {.mass = 5e-5f, .stiffness = 5000.0f, .preload_force = 1.0f,
                                   .closing_speed = 0.5f, .restitution = 0.7f, .damping_ratio = 0.0f};
    expect(cb_preload_restitution_bounce_seconds(&undamped, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL seconds, averaged lean path");
    expect(cb_preload_restitution_bounce_seconds(NULL, &seconds), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch, averaged lean path");
    expect(cb_preload_restitution_bounce_seconds(&lean, &seconds), CB_ERR_OUT_OF_RANGE, CB_PARAM_DAMPING_RATIO, "damping on the restitution path");
    bad_lean = undamped;
    bad_lean.restitution = NAN;
    expect(cb_preload_restitution_bounce_seconds(&bad_lean, &seconds), CB_ERR_NAN, CB_PARAM_RESTITUTION, "NaN R, averaged lean path");
    bad_lean.restitution = 1.0f;
    expect(cb_preload_restitution_bounce_seconds(&bad_lean, &seconds), CB_ERR_OUT_OF_RANGE, CB_PARAM_RESTITUTION, "R = 1, averaged lean path");
    bad_lean = undamped;
    bad_lean.mass = 0.0f;
    expect(cb_preload_restitution_bounce_seconds(&bad_lean, &seconds), CB_ERR_NOT_POSITIVE, CB_PARAM_MASS, "zero mass, averaged lean path");
    expect(cb_preload_restitution_bounce_seconds(&undamped, &seconds), CB_OK, CB_PARAM_NONE, "the averaged lean time");
    expect(cb_seconds_to_ticks(-1.0f, 1.5f, 0.0f, 1e-5f, &ticks), CB_ERR_NEGATIVE, CB_PARAM_TIME, "negative seconds");
    expect(cb_seconds_to_ticks(1e-3f, 1.5f, 0.0f, 1e-5f, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL ticks, seconds");

    cb_windows w;
    cb_pin pin;
    expect(cb_windows_init(NULL, 3, 3, CB_MODE_CONFIRM), CB_ERR_NULL, CB_PARAM_POINTER, "NULL windows");
    expect(cb_windows_init(&w, 40000, 3, CB_MODE_CONFIRM), CB_ERR_OUT_OF_RANGE, CB_PARAM_TIME, "window too long");
    expect(cb_windows_init(&w, 3, 3, 7), CB_ERR_OUT_OF_RANGE, CB_PARAM_MODE, "unknown mode");
    expect(cb_pin_init(NULL, false), CB_ERR_NULL, CB_PARAM_POINTER, "NULL pin");
    expect(cb_windows_init(&w, 3, 3, CB_MODE_HOLD_OFF), CB_OK, CB_PARAM_NONE, "windows");
    expect(cb_pin_init(&pin, false), CB_OK, CB_PARAM_NONE, "pin");
    if (cb_pin_update(NULL, true, &w) != CB_EDGE_ERROR || cb_pin_update(&pin, true, NULL) != CB_EDGE_ERROR) {
        fprintf(stderr, "FAIL NULL to cb_pin_update is not CB_EDGE_ERROR\n");
        failures++;
    }
    w.mode = 9; /* written by hand, not by cb_windows_init */
    if (cb_pin_update(&pin, true, &w) != CB_EDGE_ERROR || cb_pin_is_closed(&pin)) {
        fprintf(stderr, "FAIL bad windows to cb_pin_update\n");
        failures++;
    }
    cb_learner_prior prior;
    cb_learner key;
    cb_learned saved;
    uint16_t press = 0, release = 0;
    expect(cb_learner_prior_init(NULL, 31, 31, 31), CB_ERR_NULL, CB_PARAM_POINTER, "NULL learner prior");
    expect(cb_learner_prior_init(&prior, 0, 31, 31), CB_ERR_NOT_POSITIVE, CB_PARAM_TIME, "learner prior of 0");
    expect(cb_learner_prior_init(&prior, 31, 31, 0), CB_ERR_NOT_POSITIVE, CB_PARAM_TIME, "fastest tap of 0");
    expect(cb_learner_prior_init(&prior, 40000, 31, 31), CB_ERR_OUT_OF_RANGE, CB_PARAM_TIME, "learner prior too long");
    expect(cb_learner_prior_at_period(&prior, 31, 31, 0), CB_ERR_NOT_POSITIVE, CB_PARAM_SAMPLE_PERIOD, "period of 0");
    expect(cb_learner_prior_at_period(&prior, 31, 31, 40000000u), CB_ERR_OUT_OF_RANGE, CB_PARAM_SAMPLE_PERIOD, "period longer than a tap");
    expect(cb_learner_init(NULL, false), CB_ERR_NULL, CB_PARAM_POINTER, "NULL learner");
    expect(cb_learner_prior_init(&prior, 31, 31, 31), CB_OK, CB_PARAM_NONE, "learner prior");
    expect(cb_learner_init(&key, false), CB_OK, CB_PARAM_NONE, "learner");
    if (cb_learner_update(NULL, true, &prior) != CB_EDGE_ERROR || cb_learner_update(&key, true, NULL) != CB_EDGE_ERROR) {
        fprintf(stderr, "FAIL NULL to cb_learner_update is not CB_EDGE_ERROR\n");
        failures++;
    }
    prior.fastest_tap = 0; /* written by hand, not by cb_learner_prior_init */
    if (cb_learner_update(&key, true, &prior) != CB_EDGE_ERROR || cb_learner_is_closed(&key) || cb_learner_flags(&key, &prior) != 0) {
        fprintf(stderr, "FAIL bad prior to cb_learner_update\n");
        failures++;
    }
    expect(cb_learner_windows(&key, &prior, &press, &release), CB_ERR_NOT_POSITIVE, CB_PARAM_TIME, "learner windows, bad prior");
    expect(cb_learner_windows(&key, NULL, &press, &release), CB_ERR_NULL, CB_PARAM_POINTER, "learner windows, NULL");
    expect(cb_learner_save(&key, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL saved bytes");
    expect(cb_learner_restore(&key, false, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL bytes to restore");
    memset(saved.bytes, 0xFF, sizeof saved.bytes); /* erased EEPROM */
    expect(cb_learner_restore(&key, false, &saved), CB_ERR_OUT_OF_RANGE, CB_PARAM_TIME, "erased bytes to restore");
    expect(cb_learner_save(&key, &saved), CB_OK, CB_PARAM_NONE, "save");
    expect(cb_learner_restore(&key, true, &saved), CB_OK, CB_PARAM_NONE, "restore");
    if (!cb_learner_is_closed(&key) || cb_learner_is_closed(NULL)) {
        fprintf(stderr, "FAIL cb_learner_is_closed after a restore\n");
        failures++;
    }
    if (strcmp(cb_parameter_name(200), "unknown") != 0 || strcmp(cb_parameter_name(CB_PARAM_MASS), "mass") != 0) {
        fprintf(stderr, "FAIL cb_parameter_name\n");
        failures++;
    }
}

/* The window-only path (cb_bounce_seconds_*) gives each prediction's bounce time, bit for bit,
 * or the same error, on every switch and tier; and its bad inputs are error codes. */
typedef cb_error (*predict_fn)(const cb_switch *, cb_prediction *);
typedef cb_error (*seconds_fn)(const cb_switch *, float *);

static void bounce_seconds(void) {
    const predict_fn predict[] = {cb_predict_closed, cb_predict_averaged, cb_predict_map, cb_predict_exact};
    const seconds_fn seconds[] = {cb_bounce_seconds_closed, cb_bounce_seconds_averaged, cb_bounce_seconds_map,
                                  cb_bounce_seconds_exact};
    const seconds_fn preload[] = {cb_preload_seconds_closed, cb_preload_seconds_averaged, cb_preload_seconds_map,
                                  cb_preload_seconds_exact};
    int compared = 0;
    for (uint32_t i = 0; i < SWITCH_COUNT; i++) {
        for (int t = 0; t < 4; t++) {
            cb_prediction p;
            float s = -1.0f;
            cb_error e = predict[t](&SWITCHES[i], &p);
            cb_error f = seconds[t](&SWITCHES[i], &s);
            float want = (p.flags & CB_HAS_END) ? p.end_time : p.last_above_time;
            cb_error want_error = e;
            if (e == CB_OK && !(p.flags & (CB_HAS_END | CB_HAS_LAST_ABOVE))) {
                want_error = f; /* endless: the code is checked below */
                if (CB_ERROR_CODE(f) != CB_ERR_ENDLESS) {
                    fprintf(stderr, "FAIL switch %u tier %d: endless gives code %u\n", i, t, CB_ERROR_CODE(f));
                    failures++;
                }
            }
            if (f != want_error || (f == CB_OK && memcmp(&s, &want, sizeof s) != 0)) {
                fprintf(stderr, "FAIL switch %u tier %d: bounce seconds %g (error %u), prediction %g (error %u)\n",
                        i, t, (double)s, f, (double)want, want_error);
                failures++;
            }
            /* A preload's time by its typed scene is the same; a gap is refused, naming the offset. */
            float q = -1.0f;
            cb_error g = preload[t](&SWITCHES[i], &q);
            int same = SWITCHES[i].offset < 0.0f
                           ? g == f && (f != CB_OK || memcmp(&q, &s, sizeof q) == 0)
                           : CB_ERROR_CODE(g) == CB_ERR_OUT_OF_RANGE && CB_ERROR_PARAMETER(g) == CB_PARAM_OFFSET;
            if (!same) {
                fprintf(stderr, "FAIL switch %u tier %d: preload seconds %g (error %u), any sign %g (error %u)\n", i,
                        t, (double)q, g, (double)s, f);
                failures++;
            }
            compared++;
        }
    }
    const cb_switch dome = {5e-5f, 5000.0f, -2e-4f, 0.7f, 0.03f, 0.5f, 0.0f};
    cb_switch bad = dome;
    float s;
    expect(cb_bounce_seconds_closed(NULL, &s), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch, bounce seconds");
    expect(cb_bounce_seconds_map(&dome, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL seconds");
    bad.mass = NAN;
    expect(cb_bounce_seconds_exact(&bad, &s), CB_ERR_NAN, CB_PARAM_MASS, "NaN mass, bounce seconds");
    bad = dome;
    bad.restitution = 1.5f;
    expect(cb_bounce_seconds_averaged(&bad, &s), CB_ERR_OUT_OF_RANGE, CB_PARAM_RESTITUTION, "R above 1, bounce seconds");
    expect(cb_preload_seconds_averaged(&bad, &s), CB_ERR_OUT_OF_RANGE, CB_PARAM_RESTITUTION, "R above 1, preload seconds");
    expect(cb_preload_seconds_closed(NULL, &s), CB_ERR_NULL, CB_PARAM_POINTER, "NULL switch, preload seconds");
    expect(cb_preload_seconds_exact(&dome, NULL), CB_ERR_NULL, CB_PARAM_POINTER, "NULL preload seconds");
    bad = dome;
    bad.offset = 0.0f;
    expect(cb_preload_seconds_map(&bad, &s), CB_ERR_OUT_OF_RANGE, CB_PARAM_OFFSET, "offset 0, preload seconds");
    bad.offset = NAN;
    expect(cb_preload_seconds_closed(&bad, &s), CB_ERR_NAN, CB_PARAM_OFFSET, "NaN offset, preload seconds");
    if (compared != 4 * (int)SWITCH_COUNT) {
        fprintf(stderr, "FAIL %d bounce times compared\n", compared);
        failures++;
    }
}

int main(void) {
    for (uint32_t i = 0; i < SWITCH_COUNT; i++) {
        switch_lines(put, i);
    }
    debouncer_lines(put);
    learner_lines(put);
    bad_inputs();
    bounce_seconds();
    if (failures != 0) {
        fprintf(stderr, "%d checks failed\n", failures);
        return 1;
    }
    return 0;
}
