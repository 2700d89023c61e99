//! The desk tool's Monte Carlo, per sample, on the example scene file and the
//! catalogue (every entry with ranges): the whole draw (sample,
//! scene, prediction, order statistics), the model's share of it (the core's `Scene` built
//! and predicted), and the prediction alone (scenes built beforehand). Medians, by criterion.
//!
//! `cargo bench -p bounce-table --bench monte_carlo`; CI only builds it and runs each case
//! once (`-- --test`).
//!
//! Measured on a 2-core x86-64 host, nanoseconds per sample (criterion medians over 10,000
//! samples, one thread). "before": the same `draw` on the version that drew each sample as a
//! JSON value and parsed it again (commit 414e7c3); "scene + prediction": the core's `Scene`
//! built and `Method::Auto` asked for the 10 % the tool asks; "prediction": that call alone.
//!
//! | switch | draw before | draw | ratio | scene + prediction | prediction |
//! |---|---:|---:|---:|---:|---:|
//! | my tactile button (example.toml) | 969 | 165 | 5.9 | 135 | 56 |
//! | MEMS micro-switch | 1,049 | 193 | 5.4 | 160 | 79 |
//! | miniature reed | 1,964 | 1,106 | 1.8 | 1,044 | 962 |
//! | tactile dome | 1,020 | 168 | 6.1 | 135 | 56 |
//! | keyboard leaf contact | 1,210 | 345 | 3.5 | 304 | 224 |
//! | signal relay | 1,602 | 708 | 2.3 | 650 | 570 |
//! | power relay 30 A | 2,342 | 1,470 | 1.6 | 1,421 | 1,330 |
//! | contactor 100 A | 2,046 | 1,177 | 1.7 | 1,110 | 1,026 |
//! | large contactor | 3,786 | 2,941 | 1.3 | 2,795 | 2,705 |
//!
//! The core's share of a draw (scene + prediction) is 80-95 %; where `Auto` answers with a
//! closed form the prediction proper is a third of it and the `Scene`'s validation most of the
//! rest.

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
                            let scene = i.core::<f64>().expect("a valid sample");
                            scene.predict(Method::Auto(tolerance)).promises(tolerance)
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
