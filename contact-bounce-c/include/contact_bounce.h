/*
 * contact-bounce: predict a switch's bounce from physics, turn it into a debounce window, and
 * debounce each pin. Link libcontact_bounce_c.a built for your target (see the README).
 */

#ifndef CONTACT_BOUNCE_H
#define CONTACT_BOUNCE_H

/* Generated from contact-bounce-c/src/lib.rs: do not edit. */

#include <stdbool.h>
#include <stdint.h>

// The API's version, raised when a signature changes. 2: the lean preload paths take a
// `cb_preloaded` (the Rust crate's `Preloaded`, in its order) under the Rust crate's names
// (`cb_preload_viscous_bounce_time`, `cb_preload_viscous_bounce_seconds`,
// `cb_preload_restitution_bounce_seconds`); version 1 took six loose floats in another order.
#define CB_API_VERSION 2

// One key's learning debouncer: 24 bytes, aligned as a uint16_t. Set it with `cb_learner_init`
// or `cb_learner_restore`.
typedef struct cb_learner {
  // The state; not to be read or written by the caller (any 24 bytes are a state, so a
  // corrupted one cannot make an update fail, only start the key mid-event).
  uint16_t state[12];
} cb_learner;

// `cb_prediction.flags`: the end time is finite.
#define CB_HAS_END 1

// `cb_prediction.flags`: the last impact above the threshold is at a finite time.
#define CB_HAS_LAST_ABOVE 2

// `cb_prediction.flags`: the count of impacts above the threshold is finite.
#define CB_HAS_COUNT 4

// `cb_prediction.flags`: the expected relative error is known (the scene is within the
// tier's stated validity).
#define CB_HAS_EXPECTED_ERROR 8

// The longest window in samples.
#define CB_MAX_WINDOW_TICKS 32767

// The fastest real tap by default, nanoseconds: 16 taps a second, 31 ms down and 31 ms up.
#define CB_FASTEST_TAP_NS 31000000

// `cb_learner_flags`: the switch reverts for at least half the fastest tap, so it will also
// revert for as long as a tap, and those reversions are reported as taps would be.
#define CB_LEARNER_REVERTS_LIKE_A_TAP 1

// What a sample debounced to.
enum cb_edge
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // No change.
  CB_EDGE_NONE = 0,
  // The contact closed.
  CB_EDGE_PRESS,
  // The contact opened.
  CB_EDGE_RELEASE,
  // An argument was NULL or the windows were not made by `cb_windows_init`: the pin is
  // unchanged.
  CB_EDGE_ERROR,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_edge cb_edge;
#else
typedef uint8_t cb_edge;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// Why (`CB_OK` when there is no error).
enum cb_code
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // No error.
  CB_OK = 0,
  // A pointer argument was NULL.
  CB_ERR_NULL,
  // NaN.
  CB_ERR_NAN,
  // Infinite.
  CB_ERR_INFINITE,
  // Must be > 0.
  CB_ERR_NOT_POSITIVE,
  // Must be >= 0.
  CB_ERR_NEGATIVE,
  // Outside its allowed interval.
  CB_ERR_OUT_OF_RANGE,
  // The regime never ends by itself: give a threshold.
  CB_ERR_THRESHOLD_REQUIRED,
  // Valid alone, but it overflows (or loses all precision) with the other parameters.
  CB_ERR_OVERFLOW,
  // The threshold is at or above the first impulse: no impact would count.
  CB_ERR_ABOVE_FIRST_IMPULSE,
  // The bounce never ends, so no finite window exists.
  CB_ERR_ENDLESS,
  // A reason this header does not know (a newer core).
  CB_ERR_OTHER,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_code cb_code;
#else
typedef uint8_t cb_code;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// Which parameter an error names (`CB_PARAM_NONE` when there is no error).
enum cb_parameter
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // No parameter: no error.
  CB_PARAM_NONE = 0,
  // A pointer argument was NULL.
  CB_PARAM_POINTER,
  // `mass`.
  CB_PARAM_MASS,
  // `stiffness`.
  CB_PARAM_STIFFNESS,
  // `offset`.
  CB_PARAM_OFFSET,
  // `restitution`.
  CB_PARAM_RESTITUTION,
  // `damping_ratio`.
  CB_PARAM_DAMPING_RATIO,
  // `closing_speed`.
  CB_PARAM_CLOSING_SPEED,
  // `threshold_fraction`.
  CB_PARAM_THRESHOLD,
  // The tolerance asked of `cb_predict_auto`.
  CB_PARAM_TOLERANCE,
  // A window's margin factor.
  CB_PARAM_MARGIN_FACTOR,
  // A window's extra time.
  CB_PARAM_MARGIN_EXTRA,
  // The sample (tick) period.
  CB_PARAM_SAMPLE_PERIOD,
  // A time: the bounce a window must cover, or a window in ticks.
  CB_PARAM_TIME,
  // The debouncer's mode.
  CB_PARAM_MODE,
  // The preload force of `cb_preload_viscous_bounce_time`.
  CB_PARAM_PRELOAD_FORCE,
  // A parameter this header does not know (a newer core).
  CB_PARAM_OTHER,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_parameter cb_parameter;
#else
typedef uint8_t cb_parameter;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// How the bounce behaves over time.
enum cb_regime
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // Infinitely many impacts in a finite time, then the contact stays closed.
  CB_REGIME_ZENO = 0,
  // Finitely many impacts; the last one ends the bounce.
  CB_REGIME_LAST_IMPACT,
  // Impacts decay but never end: the threshold ends the bounce.
  CB_REGIME_ENDLESS,
  // No dissipation: constant impacts forever.
  CB_REGIME_PERIODIC,
  // The contact separates once and never returns.
  CB_REGIME_SINGLE_IMPACT,
  // A regime this header does not know (a newer core).
  CB_REGIME_OTHER,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_regime cb_regime;
#else
typedef uint8_t cb_regime;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// Which tier answered.
enum cb_tier
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // The regime alone answered.
  CB_TIER_REGIME = 0,
  // A closed form.
  CB_TIER_CLOSED,
  // The averaged model.
  CB_TIER_AVERAGED,
  // The semi-discrete map.
  CB_TIER_MAP,
  // The exact solution.
  CB_TIER_EXACT,
  // A tier this header does not know (a newer core).
  CB_TIER_OTHER,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_tier cb_tier;
#else
typedef uint8_t cb_tier;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// How a debounce window is used.
enum cb_mode
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint8_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  // Report a change after the new level has held for the window.
  CB_MODE_CONFIRM = 0,
  // Report a change at once, then ignore the pin for the window.
  CB_MODE_HOLD_OFF,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum cb_mode cb_mode;
#else
typedef uint8_t cb_mode;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

// An error: which parameter, and why, in 16 bits: the `cb_code` in the low byte, the
// `cb_parameter` in the high byte (`CB_ERROR_CODE(e)`, `CB_ERROR_PARAMETER(e)`). 0 (`CB_OK`)
// means success.
//
// An integer, not a struct: a small struct returned by value is where compilers for the
// small targets (avr-gcc and rustc on the ATmega328P) disagree on the ABI, and any 16 bits
// from C are a valid `cb_error` on the Rust side.
typedef uint16_t cb_error;

// A switch in SI units: one moving contact (effective mass on a spring), its stop, the impact
// law, viscous damping and how fast it closes.
typedef struct cb_switch {
  // Effective (moving) mass, kg (> 0).
  float mass;
  // Effective stiffness of the contact spring, N/m (> 0).
  float stiffness;
  // Where the stop is from the spring's free rest position, m: a gap > 0, a preload < 0
  // (preload force / stiffness), grazing 0.
  float offset;
  // Coefficient of restitution R, in (0, 1].
  float restitution;
  // Viscous damping ratio zeta (>= 0; 0 for none).
  float damping_ratio;
  // Closing speed at the first impact, m/s (> 0).
  float closing_speed;
  // The impacts that count: those whose impulse is above this fraction of the first, in
  // (0, 1); 0 for no threshold (then a regime that never ends by itself is an error).
  float threshold_fraction;
} cb_switch;

// A prediction. A field whose flag is not set is 0 and means nothing.
typedef struct cb_prediction {
  // When the bounce ends, s after the first impact (`CB_HAS_END`).
  float end_time;
  // When the last impact above the threshold happens, s (`CB_HAS_LAST_ABOVE`).
  float last_above_time;
  // How many impacts are above the threshold (`CB_HAS_COUNT`; a real number for the
  // averaged tier).
  float impacts_above;
  // The relative error to expect of the bounce time (`CB_HAS_EXPECTED_ERROR`).
  float expected_error;
  // The regime: a `cb_regime`.
  uint8_t regime;
  // The tier that answered: a `cb_tier`.
  uint8_t tier;
  // `CB_HAS_*` bits.
  uint8_t flags;
} cb_prediction;

// A preloaded switch for the lean paths, in SI units: the six numbers of the Rust crate's
// `Preloaded`, in its order (mass, stiffness, preload force, closing speed, restitution,
// damping ratio). Fill it by name (`.closing_speed = 0.5f`): the lean functions took six
// loose floats before, in another order than Rust's, where a swap compiled and gave a wrong
// time.
typedef struct cb_preloaded {
  // Effective (moving) mass, kg (> 0).
  float mass;
  // Effective stiffness of the contact spring, N/m (> 0).
  float stiffness;
  // Contact (preload) force at rest, N (> 0).
  float preload_force;
  // Closing speed at the first impact, m/s (> 0).
  float closing_speed;
  // Coefficient of restitution R, in (0, 1).
  float restitution;
  // Viscous damping ratio zeta (>= 0; 0 for none).
  float damping_ratio;
} cb_preloaded;

// A closed-form estimate: the time and the relative error to expect of it.
typedef struct cb_estimate {
  // The bounce time, s.
  float time;
  // The relative error to expect (`has_expected_error`), else 0.
  float expected_error;
  // Whether the inputs are within the formula's stated validity (1) or not (0).
  uint8_t has_expected_error;
} cb_estimate;

// Press and release windows in samples, shared by every pin of one kind of switch. Fill it
// with `cb_windows_init`.
typedef struct cb_windows {
  // Press window, samples (at most `CB_MAX_WINDOW_TICKS`).
  uint16_t press;
  // Release window, samples (at most `CB_MAX_WINDOW_TICKS`).
  uint16_t release;
  // How the windows are used: a `cb_mode`.
  uint8_t mode;
} cb_windows;

// One pin's debouncer state: 2 bytes. Set it with `cb_pin_init`.
typedef struct cb_pin {
  // The state; not to be read or written by the caller.
  uint16_t state;
} cb_pin;

// What a learning debouncer starts from, in samples: the prior press and release windows and
// the fastest real tap (a change that lasts that long is always reported; no window is
// longer). Set it with `cb_learner_prior_init` or `cb_learner_prior_at_period`.
typedef struct cb_learner_prior {
  // Prior press window, samples (1 to `CB_MAX_WINDOW_TICKS`).
  uint16_t press;
  // Prior release window, samples (1 to `CB_MAX_WINDOW_TICKS`).
  uint16_t release;
  // The fastest real tap, samples (1 to `CB_MAX_WINDOW_TICKS`).
  uint16_t fastest_tap;
} cb_learner_prior;

// What a learner has learned, to save (for example in EEPROM) and restore: 12 bytes.
typedef struct cb_learned {
  // The bytes, as `cb_learner_save` writes them.
  uint8_t bytes[12];
} cb_learned;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

// The name of a `cb_parameter` as `cb_switch` and the functions spell it (a static,
// NUL-terminated string); "unknown" for a value that is no `cb_parameter`.
const char *cb_parameter_name(uint8_t parameter);

// Validates a switch: `CB_OK`, or the first invalid parameter and why.
cb_error cb_switch_check(const struct cb_switch *sw);

// The closed forms: the cheapest tier (exact sums without damping, `t_b1v` / `t_b2r` with it).
cb_error cb_predict_closed(const struct cb_switch *sw, struct cb_prediction *out);

// The averaged model J' = E1(J), 8 Gauss-Legendre nodes per panel.
cb_error cb_predict_averaged(const struct cb_switch *sw, struct cb_prediction *out);

// The semi-discrete map, impact by impact (the averaged model beyond its default cap).
cb_error cb_predict_map(const struct cb_switch *sw, struct cb_prediction *out);

// The exact solution, flight by flight: expected error at the float's rounding.
cb_error cb_predict_exact(const struct cb_switch *sw, struct cb_prediction *out);

// The cheapest tier whose expected error is within `tolerance` (relative, e.g. 0.01); every
// tier is linked. Check `expected_error` against the tolerance: where nothing meets it the
// smallest expected error answers.
cb_error cb_predict_auto(const struct cb_switch *sw, float tolerance, struct cb_prediction *out);

// As `cb_predict_auto`, weighing only the exact tier after the closed forms: the closed forms
// where they meet `tolerance`, else the exact tier (which does on every one-body switch). No
// map and no averaged quadrature are linked (beyond the exact tier's rest past its cap):
// in Rust firmware 4.2-4.5 KB less than Auto among every tier on Cortex-M and 9.8 KB less on the
// Uno (`docs/reports/cost-report.md`, auto-exact).
cb_error cb_predict_auto_exact(const struct cb_switch *sw,
                               float tolerance,
                               struct cb_prediction *out);

// The bounce a window must cover (its end, else its last impact above the threshold), s, by
// the closed forms: what `cb_predict_closed` gives, without the counts and the expected error
// (a firmware that calls only this links neither). `cb_seconds_to_ticks` makes it a window.
cb_error cb_bounce_seconds_closed(const struct cb_switch *sw, float *seconds);

// The bounce time by the averaged model, as `cb_bounce_seconds_closed`.
cb_error cb_bounce_seconds_averaged(const struct cb_switch *sw, float *seconds);

// The bounce time by the map, as `cb_bounce_seconds_closed`.
cb_error cb_bounce_seconds_map(const struct cb_switch *sw, float *seconds);

// The bounce time by the exact solution, as `cb_bounce_seconds_closed`.
cb_error cb_bounce_seconds_exact(const struct cb_switch *sw, float *seconds);

// The bounce time of a preloaded switch (`offset` < 0) by the closed forms: as
// `cb_bounce_seconds_closed`, but a gap or an offset of 0 is `CB_PARAM_OFFSET` /
// `CB_ERR_OUT_OF_RANGE`, and no gap's code is linked (on the Uno the closed, averaged and map
// tiers fit from C only this way, and the exact tier not even so: `docs/reports/c-api-uno.md`).
cb_error cb_preload_seconds_closed(const struct cb_switch *sw, float *seconds);

// The bounce time of a preloaded switch by the averaged model, as `cb_preload_seconds_closed`.
cb_error cb_preload_seconds_averaged(const struct cb_switch *sw, float *seconds);

// The bounce time of a preloaded switch by the map, as `cb_preload_seconds_closed`.
cb_error cb_preload_seconds_map(const struct cb_switch *sw, float *seconds);

// The bounce time of a preloaded switch by the exact solution, as `cb_preload_seconds_closed`.
cb_error cb_preload_seconds_exact(const struct cb_switch *sw, float *seconds);

// The debounce window covering a prediction's bounce (its end, else its last impact above the
// threshold) in ticks of `sample_period` seconds: `ceil((margin_factor * bounce +
// margin_extra) / sample_period)`, at least 1 for a positive bounce. `margin_factor` >= 1,
// `margin_extra` >= 0 s.
cb_error cb_window_ticks(const struct cb_prediction *prediction,
                         float margin_factor,
                         float margin_extra,
                         float sample_period,
                         uint32_t *ticks);

// The window covering `seconds` of bounce, as `cb_window_ticks` (for `cb_preload_viscous_bounce_time`).
cb_error cb_seconds_to_ticks(float seconds,
                             float margin_factor,
                             float margin_extra,
                             float sample_period,
                             uint32_t *ticks);

// The lean path: a preloaded contact's bounce time `t_b1v` (restitution and viscous damping;
// `damping_ratio` 0 gives `t_b1`) straight from its inputs, with no scene and no tier: the
// smallest firmware (about 4 KB of the Uno's flash from C, a tier through this API 17 KB and
// more: `docs/reports/c-api-uno.md`). Expected error within 2.5 % plus the arctangent linearisation
// for a small first impulse; the estimate says when the inputs are beyond that. Rust's
// `tiers::preload_viscous_bounce_time`.
cb_error cb_preload_viscous_bounce_time(const struct cb_preloaded *sw, struct cb_estimate *out);

// The lean path's time alone: `t_b1v` (s) as `cb_preload_viscous_bounce_time` computes it (the
// same value, the same errors), without its expected error, into `seconds`: for firmware that
// sets its margin itself (`cb_seconds_to_ticks`). Rust's
// `tiers::preload_viscous_bounce_seconds`.
cb_error cb_preload_viscous_bounce_seconds(const struct cb_preloaded *sw, float *seconds);

// The lean averaged path: a preloaded contact's bounce (s) under restitution alone, the averaged
// model's time in closed form, straight from its inputs, with no scene and no expected error,
// into `seconds` (for a first impulse up to the preload's scale, j0 <= 1, long by at most 4.7 %
// at R = 0.05 and 1.7 % from R = 0.5; the averaged tier's expected error needs a scene). Its
// `damping_ratio` must be 0 (`CB_PARAM_DAMPING_RATIO` / `CB_ERR_OUT_OF_RANGE` otherwise: the
// path has no damping). Rust's `tiers::preload_restitution_bounce_seconds`.
cb_error cb_preload_restitution_bounce_seconds(const struct cb_preloaded *sw, float *seconds);

// Fills `out` with windows of `press` and `release` samples (each at most
// `CB_MAX_WINDOW_TICKS`, else `CB_PARAM_TIME` out of range).
cb_error cb_windows_init(struct cb_windows *out, uint32_t press, uint32_t release, uint8_t mode);

// A pin settled closed (`closed` true) or open.
cb_error cb_pin_init(struct cb_pin *pin, bool closed);

// Feeds one sample (`closed`: the contact reads closed) and returns the edge it debounces.
cb_edge cb_pin_update(struct cb_pin *pin, bool closed, const struct cb_windows *windows);

// Whether the pin is debounced closed.
bool cb_pin_is_closed(const struct cb_pin *pin);

// A learner's prior from windows and a fastest tap in samples. `CB_ERR_NOT_POSITIVE` for a 0,
// `CB_ERR_OUT_OF_RANGE` above `CB_MAX_WINDOW_TICKS` (both naming `CB_PARAM_TIME`); `out` is
// written only on success.
cb_error cb_learner_prior_init(struct cb_learner_prior *out,
                               uint16_t press,
                               uint16_t release,
                               uint16_t fastest_tap);

// A learner's prior from windows in samples of `period_ns` nanoseconds, with the default
// fastest tap (`CB_FASTEST_TAP_NS`) in whole samples of that period. Errors as
// `cb_learner_prior_init`, and `CB_PARAM_SAMPLE_PERIOD` for a period of 0 or one longer than
// the tap; `out` is written only on success.
cb_error cb_learner_prior_at_period(struct cb_learner_prior *out,
                                    uint16_t press,
                                    uint16_t release,
                                    uint32_t period_ns);

// A key settled closed (`closed` true) or open, with nothing learned.
cb_error cb_learner_init(cb_learner *learner, bool closed);

// Feeds one sample (`closed`: the contact reads closed) and returns the edge it debounces;
// `CB_EDGE_ERROR` (the learner unchanged) for a NULL argument or a prior not made by
// `cb_learner_prior_init`.
cb_edge cb_learner_update(cb_learner *learner, bool closed, const struct cb_learner_prior *prior);

// Whether the key is debounced closed (false for NULL).
bool cb_learner_is_closed(const cb_learner *learner);

// The press and release windows the learner uses now with `prior` (samples); `press` and
// `release` are written only on success.
cb_error cb_learner_windows(const cb_learner *learner,
                            const struct cb_learner_prior *prior,
                            uint16_t *press,
                            uint16_t *release);

// The learner's flags with `prior` (`CB_LEARNER_REVERTS_LIKE_A_TAP`); 0 for a NULL argument
// or a bad prior.
uint8_t cb_learner_flags(const cb_learner *learner, const struct cb_learner_prior *prior);

// What the learner has learned, as 12 bytes to save.
cb_error cb_learner_save(const cb_learner *learner, struct cb_learned *out);

// A key settled closed (`closed` true) or open that has learned what `cb_learner_save` saved.
// `CB_ERR_OUT_OF_RANGE` (naming `CB_PARAM_TIME`) for bytes no learner saved (erased or
// corrupted storage): the learner is then unchanged.
cb_error cb_learner_restore(cb_learner *learner, bool closed, const struct cb_learned *saved);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* CONTACT_BOUNCE_H */

/* The parts of a cb_error. */
#define CB_ERROR_CODE(e) ((uint8_t)((e) & 0xFFu))
#define CB_ERROR_PARAMETER(e) ((uint8_t)((e) >> 8))
