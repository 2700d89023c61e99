//! The desk tool's Monte Carlo, per sample, on the example scene file and the
//! catalogue (every entry with ranges): the whole draw (sample,
//! scene, prediction, order statistics), the model's share of it (the core's `Scene` built
//! and predicted), and the prediction alone (scenes built beforehand). Medians, by criterion.
//!
//! `cargo bench -p bounce-table --bench monte_carlo`; CI only builds it and runs each case
//! once (`-- --test`).
//!
//! Measured on a 2-core x86-64 host, nanoseconds per sample (criterion medians over 10,000
//! samples, one thread), built with the release profile (opt-level 3). "before": the same
//! `draw` built on the version that drew each sample as a JSON value and parsed it again
//! (commit 414e7c3, this bench's `draw` added to it, opt-level 3 as here: 1,215 ns on the
//! example file, where at opt-level "s" it took 1,205); "scene + prediction": the core's `Scene`
//! built and `Method::Auto` asked for the 10 % the tool asks (`SceneInput::predict`);
//! "prediction": that call alone, on scenes built beforehand.
//!
//! | switch | draw before | draw | ratio | scene + prediction | prediction |
//! |---|---:|---:|---:|---:|---:|
//! | my tactile button (example.toml) | 1,215 | 117 | 10.4 | 77 | 32 |
//! | MEMS micro-switch | 1,515 | 141 | 10.7 | 112 | 60 |
//! | miniature reed | 2,037 | 1,082 | 1.9 | 1,004 | 929 |
//! | tactile dome | 1,267 | 159 | 8.0 | 79 | 37 |
//! | keyboard leaf contact | 1,549 | 304 | 5.1 | 245 | 201 |
//! | signal relay | 2,013 | 691 | 2.9 | 581 | 531 |
//! | power relay 30 A | 2,757 | 1,515 | 1.8 | 1,371 | 1,286 |
//! | contactor 100 A | 2,221 | 1,113 | 2.0 | 1,038 | 1,024 |
//! | large contactor | 3,950 | 1,483 | 2.7 | 1,432 | 1,444 |
//!
//! Runs of one binary differ by up to a fifth on this machine (the example file's draw: 117 ns
//! here, 138 ns in a run an hour before), so the ratios are known to about that. Where `Auto`
//! answers with a closed form (the example file, the dome) the prediction proper is a quarter
//! to a third of a draw, and building the `Scene` (validation, regime, asymptote) about half
//! again as much: the goal of a prediction at least half of a draw would need a `Scene` that
//! costs little more than its arithmetic, where it checks every derived scale a tier forms
//! (the hostile-input guarantees). A draw's remainder is the sample itself, its order
//! statistics and the analysis's fixed part (the nominal estimate and the sensitivity runs,
//! spread over its 10,000 samples); no sample of these runs went to the exact reference. The
//! scene is read where it is built, through a reference (moved out of its
//! `Result` by value it was copied, a fifth of a draw); the workers publish their progress every
//! 256 samples (an atomic add a sample cost 1.23 times the time on two threads).

use std::hint::black_box;
use std::time::Duration;

use bounce_table::scene::file::{catalogue, read};
use bounce_table::stats::analysis::{analyse, Settings};
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
