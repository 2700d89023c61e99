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
//! | my tactile button (example.toml) | 1,205 | 191 | 6.3 | 125 | 54 |
//! | MEMS micro-switch | 1,505 | 220 | 6.8 | 162 | 78 |
//! | miniature reed | 2,490 | 1,191 | 2.1 | 1,147 | 1,039 |
//! | tactile dome | 1,558 | 156 | 10.0 | 131 | 59 |
//! | keyboard leaf contact | 1,398 | 352 | 4.0 | 310 | 234 |
//! | signal relay | 2,029 | 717 | 2.8 | 676 | 611 |
//! | power relay 30 A | 2,742 | 1,614 | 1.7 | 1,512 | 1,447 |
//! | contactor 100 A | 2,447 | 1,333 | 1.8 | 1,226 | 1,142 |
//! | large contactor | 4,417 | 1,882 | 2.3 | 1,733 | 1,604 |
//!
//! Runs of one binary differ by up to a fifth on this machine (the example file's draw: 182-199
//! ns here, 140-150 ns in runs of that case alone; the version before, 1,097-1,313 ns), so the
//! ratios are known to about that. The core's share of a draw (scene + prediction) is 65-96 %.
//! Where `Auto` answers with a closed form the prediction proper is a quarter to a third of a
//! draw and building the `Scene` (validation, regime, asymptote) about as much; the goal of 10
//! times (a prediction at least half of a draw) would need a `Scene` that costs little more than
//! its arithmetic. The scene used to be moved out of its `Result` through two `?` and a
//! `map_err` (a couple of hundred bytes copied three times, a fifth of a draw on the example
//! file); it is now read where it is built, through a reference (bound by value, it was still
//! copied once: 1.00-1.10x on the example file, 1.05-1.08x on the dome, paired runs).

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
