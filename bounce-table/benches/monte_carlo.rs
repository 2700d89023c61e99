//! The desk tool's Monte Carlo, per sample, on the example scene file and the
//! catalogue (every entry with ranges): the whole draw (sample,
//! scene, prediction, order statistics), the model's share of it (the core's `Scene` built
//! and predicted), and the prediction alone (scenes built beforehand). Medians, by criterion.
//!
//! `cargo bench -p bounce-table --bench monte_carlo`; CI only builds it and runs each case
//! once (`-- --test`).
//!
//! Measured on a 2-core x86-64 host, nanoseconds per sample (criterion medians over 10,000
//! samples, one thread; the mean of two runs of each binary, alternating). "before": the same
//! `draw` built on the version that drew each sample as a JSON value and parsed it again
//! (commit 414e7c3, this bench added to it); "scene + prediction": the core's `Scene` built and
//! `Method::Auto` asked for the 10 % the tool asks (`SceneInput::predict`); "prediction": that
//! call alone, on scenes built beforehand.
//!
//! | switch | draw before | draw | ratio | scene + prediction | prediction |
//! |---|---:|---:|---:|---:|---:|
//! | my tactile button (example.toml) | 1,702 | 204 | 8.3 | 171 | 71 |
//! | MEMS micro-switch | 1,610 | 231 | 7.0 | 196 | 96 |
//! | miniature reed | 2,672 | 1,322 | 2.0 | 1,230 | 1,091 |
//! | tactile dome | 1,488 | 213 | 7.0 | 155 | 66 |
//! | keyboard leaf contact | 1,967 | 414 | 4.8 | 342 | 243 |
//! | signal relay | 2,115 | 812 | 2.6 | 707 | 623 |
//! | power relay 30 A | 3,019 | 1,735 | 1.7 | 1,613 | 1,572 |
//! | contactor 100 A | 2,922 | 1,416 | 2.1 | 1,314 | 1,179 |
//! | large contactor | 4,387 | 1,894 | 2.3 | 1,706 | 1,668 |
//!
//! The core's share of a draw (scene + prediction) is 75-95 %. Where `Auto` answers with a
//! closed form the prediction proper is a third of a draw and building the `Scene` (validation,
//! regime, asymptote) half; the goal of 10 times (a prediction at least half of a draw) would
//! need a `Scene` that costs little more than its arithmetic. The scene used to be moved out of
//! its `Result` through two `?` and a `map_err` (a couple of hundred bytes copied three times, a
//! fifth of a draw on the example file); it is now read where it is built.

use std::hint::black_box;
use std::time::Duration;

use bounce_table::analysis::{analyse, Settings};
use bounce_table::scenes::{catalogue, read};
use contact_bounce::{Method, Tolerance};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

/// Samples per timed Monte Carlo.
const SAMPLES: u64 = 10_000;

fn monte_carlo(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/example.toml");
    let mut entries = read(path).expect("the example scene file reads");
    entries.extend(catalogue());
    let settings = Settings {
        samples: SAMPLES,
        threads: 1,
        ..Settings::default()
    };
    let tolerance = Tolerance::new(settings.tolerance).expect("tolerance");
    let mut group = c.benchmark_group("monte_carlo");
    group
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(SAMPLES));
    for entry in entries.iter().filter(|e| !e.template.params().is_empty()) {
        let name = entry.name.as_str();
        group.bench_with_input(BenchmarkId::new("draw", name), entry, |b, e| {
            b.iter(|| analyse(&e.name, black_box(&e.template), &settings).expect("analysis"));
        });
        let inputs: Vec<_> = (0..SAMPLES)
            .map(|i| entry.template.sample(settings.seed, i))
            .collect();
        group.bench_with_input(
            BenchmarkId::new("scene+prediction", name),
            &inputs,
            |b, s| {
                b.iter(|| {
                    s.iter()
                        .map(|i| {
                            i.predict::<f64>(Method::Auto(tolerance))
                                .expect("a valid sample")
                                .promises(tolerance)
                        })
                        .filter(|&p| p)
                        .count()
                });
            },
        );
        let scenes: Vec<_> = inputs
            .iter()
            .map(|i| i.core::<f64>().expect("a valid sample"))
            .collect();
        group.bench_with_input(BenchmarkId::new("prediction", name), &scenes, |b, s| {
            b.iter(|| {
                s.iter()
                    .filter(|scene| scene.predict(Method::Auto(tolerance)).promises(tolerance))
                    .count()
            });
        });
    }
    group.finish();
}

criterion_group!(benches, monte_carlo);
criterion_main!(benches);
