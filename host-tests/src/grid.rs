//! The grid of scenes the core is checked on against the reference: every regime of
//! docs/physics.md sec. 4 and the switches of sec. 7 (j0, R, zeta and the sign of Delta varied).

use contact_bounce::{Contact, Float, Frequency, Offset, Restitution, Scene, Threshold, Viscous};

use crate::reference::OneBody;

/// One scene of the grid, in the reference's terms and the core's.
#[derive(Debug, Clone)]
pub struct GridScene {
    /// A readable name.
    pub name: String,
    /// The regime family it was built for.
    pub family: &'static str,
    /// The reference's input.
    pub reference: OneBody,
    /// j0 = 2 R v0 / (Omega |Delta|) (Omega 1e-5 m scale at Delta = 0).
    pub j0: f64,
}

impl GridScene {
    /// A scene outside the grid, from the reference's input (for a test of its own).
    #[must_use]
    pub fn of(name: &str, family: &'static str, reference: OneBody) -> Self {
        let scale = reference.omega
            * if reference.delta == 0.0 {
                1e-5
            } else {
                reference.delta.abs()
            };
        Self {
            name: name.to_owned(),
            family,
            j0: 2.0 * reference.restitution * reference.closing_speed / scale,
            reference,
        }
    }

    /// The core's scene in f64.
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core(&self) -> Result<Scene<f64, Option<Viscous<f64>>>, contact_bounce::Error> {
        self.core_in()
    }

    /// The core's scene in f32 (each input rounded from f64; `1 - R` taken in f64).
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core_f32(&self) -> Result<Scene<f32, Option<Viscous<f32>>>, contact_bounce::Error> {
        self.core_in()
    }

    /// The core's scene typed `Viscous` (always damped: the type firmware with a damped switch
    /// uses, whose code leaves the undamped paths out at compile time); `None` for zeta = 0.
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core_damped<F: Float>(
        &self,
    ) -> Option<Result<Scene<F, Viscous<F>>, contact_bounce::Error>> {
        (self.reference.zeta != 0.0).then(|| {
            Scene::new(
                self.contact(),
                Viscous::new(F::from_f64(self.reference.zeta))?,
            )
        })
    }

    /// The core's contact, in either float (what [`GridScene::core_in`] validates).
    #[must_use]
    pub fn contact<F: Float>(&self) -> Contact<F> {
        let r = &self.reference;
        Contact {
            frequency: Frequency::Omega(F::from_f64(r.omega)),
            offset: Offset::Delta(F::from_f64(r.delta)),
            restitution: Restitution::Loss(F::from_f64(1.0 - r.restitution)),
            closing_speed: F::from_f64(r.closing_speed),
            threshold: r
                .threshold
                .map_or(Threshold::None, |p| Threshold::Impulse(F::from_f64(p))),
        }
    }

    /// The core's scene as [`GridScene::core`] builds it, in either float.
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core_in<F: Float>(&self) -> Result<Scene<F, Option<Viscous<F>>>, contact_bounce::Error> {
        Scene::new(
            self.contact(),
            Viscous::optional(F::from_f64(self.reference.zeta))?,
        )
    }
}

fn scene(
    family: &'static str,
    delta: f64,
    r: f64,
    zeta: f64,
    j0: f64,
    fraction: Option<f64>,
) -> GridScene {
    let omega = 1000.0;
    let scale = if delta == 0.0 {
        omega * 1e-3
    } else {
        omega * delta.abs()
    };
    let v0 = j0 * scale / (2.0 * r);
    GridScene {
        name: format!(
            "{family} R={r} zeta={zeta} j0={j0}{}",
            fraction.map_or(String::new(), |f| format!(" P_end={f}P0"))
        ),
        family,
        reference: OneBody {
            omega,
            delta,
            restitution: r,
            zeta,
            closing_speed: v0,
            threshold: fraction.map(|f| f * (1.0 + r) * v0),
        },
        j0,
    }
}

/// The grid: about 400 scenes.
#[must_use]
pub fn grid() -> Vec<GridScene> {
    let mut out = Vec::new();
    for r in [0.05, 0.3, 0.5, 0.7, 0.9, 0.99] {
        for zeta in [0.0, 0.001, 0.01, 0.05, 0.1, 0.3] {
            for j0 in [0.1, 0.5, 1.0, 3.0, 10.0] {
                out.push(scene("preload", -1e-3, r, zeta, j0, None));
            }
        }
    }
    for r in [0.5, 0.9, 0.99] {
        for zeta in [0.001, 0.01, 0.05] {
            for j0 in [0.5, 2.0, 10.0, 50.0] {
                out.push(scene("gap", 1e-3, r, zeta, j0, None));
            }
        }
    }
    for r in [0.5, 0.9, 0.99] {
        for j0 in [0.1, 1.0, 10.0] {
            out.push(scene("gap-undamped", 1e-3, r, 0.0, j0, Some(1e-3)));
        }
    }
    for r in [0.3, 0.9, 1.0] {
        for zeta in [0.0, 0.01, 0.1] {
            if r == 1.0 && zeta == 0.0 {
                continue;
            }
            out.push(scene("grazing", 0.0, r, zeta, 1.0, Some(1e-3)));
        }
    }
    for zeta in [0.001, 0.01, 0.1] {
        for j0 in [0.1, 1.0, 10.0] {
            out.push(scene("preload-R1", -1e-3, 1.0, zeta, j0, Some(1e-2)));
        }
    }
    for r in [0.5, 0.9] {
        for j0 in [0.5, 5.0] {
            out.push(scene("preload-threshold", -1e-3, r, 0.01, j0, Some(1e-2)));
        }
    }
    for switch in contact_bounce::scene::catalogue::ALL {
        let omega = (switch.stiffness / switch.mass).sqrt();
        let delta = -switch.preload_force / switch.stiffness;
        let r = switch.restitution;
        out.push(GridScene {
            name: switch.name.to_owned(),
            family: "catalogue",
            reference: OneBody {
                omega,
                delta,
                restitution: r,
                zeta: switch.damping_ratio,
                closing_speed: switch.closing_speed,
                threshold: None,
            },
            j0: 2.0 * r * switch.closing_speed / (omega * delta.abs()),
        });
    }
    out.push(scene("single", 1e-3, 0.5, 1.5, 1.0, None));
    out
}

/// One tier's prediction of one grid scene against the reference.
#[derive(Debug, Clone)]
pub struct Row {
    /// The scene's name.
    pub scene: String,
    /// Its family.
    pub family: &'static str,
    /// The tier, as the core reports it.
    pub tier: String,
    /// The reference's bounce time (end, else last above the threshold); `None` if endless.
    pub truth: Option<f64>,
    /// The core's.
    pub predicted: Option<f64>,
    /// |predicted - truth| / truth (0 when both are 0, infinite when only truth is 0).
    pub error: f64,
    /// The core's expected error, if it states one.
    pub expected: Option<f64>,
    /// The reference's regime and the core's agree (endless is endless).
    pub regime_agrees: bool,
}

/// The tiers checked, as methods.
#[must_use]
pub fn methods() -> [contact_bounce::Method<f64>; 7] {
    use contact_bounce::{Method, Nodes};
    [
        Method::Closed,
        Method::Averaged(Nodes::N2),
        Method::Averaged(Nodes::N4),
        Method::Averaged(Nodes::N8),
        Method::Averaged(Nodes::N16),
        Method::Map {
            max_impacts: 10_000_000,
        },
        Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        },
    ]
}

/// Every tier on one scene against the reference.
///
/// # Errors
/// When the core refuses the scene or the reference fails, as a message.
pub fn compare(scene: &GridScene) -> Result<Vec<Row>, String> {
    use crate::reference::{simulate, DEFAULT_BUDGET};
    let core = scene
        .core()
        .map_err(|e| format!("{}: core: {e}", scene.name))?;
    let outcome = simulate(&scene.reference, DEFAULT_BUDGET)
        .map_err(|e| format!("{}: reference: {e}", scene.name))?;
    let truth = outcome.end_time.or(outcome.last_above_time);
    let regime_agrees = outcome.regime.core() == core.regime();
    Ok(methods()
        .into_iter()
        .map(|method| {
            let p = core.predict(method);
            let predicted = p.bounce_time();
            let error = match (truth, predicted) {
                (Some(0.0), Some(0.0)) | (None, None) => 0.0,
                (Some(t), Some(c)) if t > 0.0 => (c - t).abs() / t,
                _ => f64::INFINITY,
            };
            Row {
                scene: scene.name.clone(),
                family: scene.family,
                tier: format!("{:?}", p.tier),
                truth,
                predicted,
                error,
                expected: p.expected_error,
                regime_agrees,
            }
        })
        .collect())
}

/// Uniform numbers in [0, 1) from `seed` (xorshift64*): the random scenes' source.
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed.max(1);
    move || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        #[allow(clippy::cast_precision_loss)]
        let unit = (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
        unit
    }
}

/// Scenes off the grid (deterministic pseudo-random, between and around the grid's points):
/// a check that the expected errors were not fitted to the grid alone.
#[must_use]
pub fn off_grid(count: usize, seed: u64) -> Vec<GridScene> {
    let mut next = uniform(seed);
    let log_uniform = |u: f64, lo: f64, hi: f64| (lo.ln() + u * (hi.ln() - lo.ln())).exp();
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let r = 0.05 + 0.945 * next();
        let zeta = if next() < 0.2 {
            0.0
        } else {
            log_uniform(next(), 1e-3, 0.3)
        };
        let j0 = log_uniform(next(), 0.05, 20.0);
        let s = match i % 5 {
            0 | 1 => scene("off-grid preload", -1e-3, r, zeta, j0, None),
            2 => scene(
                "off-grid gap",
                1e-3,
                r,
                zeta.max(1e-3),
                j0.max(0.5) * 2.0,
                None,
            ),
            3 => scene(
                "off-grid gap-undamped",
                1e-3,
                r,
                0.0,
                j0,
                Some(log_uniform(next(), 1e-4, 1e-2)),
            ),
            _ => scene(
                "off-grid grazing",
                0.0,
                r,
                zeta.min(0.1),
                1.0,
                Some(log_uniform(next(), 1e-4, 1e-2)),
            ),
        };
        out.push(s);
    }
    out
}

/// A two-body scene: the exact two-body reference against the core's reduction.
#[derive(Debug, Clone)]
pub struct TwoBodyScene {
    /// A readable name.
    pub name: String,
    /// The larger partial frequency over the smaller.
    pub mismatch: f64,
    /// The reference's input.
    pub reference: crate::reference::two_body::TwoBodies,
}

impl TwoBodyScene {
    /// The core's scene (reduced exactly, or at the Rayleigh frequency).
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core(
        &self,
    ) -> Result<Scene<f64, contact_bounce::scene::AnyDissipation<f64>>, contact_bounce::Error> {
        let r = &self.reference;
        Scene::two_body(
            contact_bounce::scene::TwoBody {
                m1: r.m[0],
                c1: r.c[0],
                d1: r.d[0],
                m2: r.m[1],
                c2: r.c[1],
                d2: r.d[1],
            },
            Offset::Delta(r.delta),
            Restitution::Coefficient(r.restitution),
            r.closing_speed,
            r.threshold.map_or(Threshold::None, Threshold::Impulse),
            None,
        )
    }
}

/// Preloaded two-body scenes: mass ratios 0.3-3, partial-frequency mismatch 1-3, with and
/// without damping (each body zeta = 0.02), j0 ~ 0.5-2.
#[must_use]
pub fn two_body_grid() -> Vec<TwoBodyScene> {
    let mut out = Vec::new();
    for mismatch in [1.0, 1.02, 1.05, 1.1, 1.2, 1.3, 1.5, 2.0, 3.0] {
        for ratio in [0.3, 1.0, 3.0] {
            for zeta in [0.0, 0.02] {
                for (r, v0) in [(0.6, 0.5), (0.9, 0.2)] {
                    let m = [1e-3, 1e-3 * ratio];
                    let c = [1e3, m[1] * 1e6 * mismatch * mismatch];
                    let d = [2.0 * zeta * 1e3 * m[0], 2.0 * zeta * 1e3 * mismatch * m[1]];
                    out.push(TwoBodyScene {
                        name: format!(
                            "two-body mismatch={mismatch} m2/m1={ratio} zeta={zeta} R={r}"
                        ),
                        mismatch,
                        reference: crate::reference::two_body::TwoBodies {
                            m,
                            c,
                            d,
                            delta: -1e-3,
                            restitution: r,
                            closing_speed: v0,
                            x2: 0.0,
                            v2: 0.0,
                            threshold: None,
                        },
                    });
                }
            }
        }
    }
    out
}

/// Viscous damping (or none) beside a relaxation kernel: the dissipation of
/// [`KernelScene::core_with_viscous`].
pub type ViscousAndKernel = (Option<Viscous<f64>>, contact_bounce::Hereditary<f64>);

/// A scene with a relaxation kernel: the exact hereditary reference against the core.
#[derive(Debug, Clone)]
pub struct KernelScene {
    /// A readable name.
    pub name: String,
    /// The reference's input.
    pub reference: crate::reference::hereditary::Kernelled,
}

impl KernelScene {
    /// The core's scene (restitution and the kernel; no viscous damping: the reference's
    /// zeta is not read, and is 0 on [`kernel_grid`]; see [`KernelScene::core_with_viscous`]).
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core(
        &self,
    ) -> Result<Scene<f64, contact_bounce::Hereditary<f64>>, contact_bounce::Error> {
        let r = &self.reference;
        Scene::new(
            Contact {
                frequency: Frequency::Omega(r.omega),
                offset: Offset::Delta(r.delta),
                restitution: Restitution::Coefficient(r.restitution),
                closing_speed: r.closing_speed,
                threshold: r.threshold.map_or(Threshold::None, Threshold::Impulse),
            },
            contact_bounce::Hereditary::exponential(r.kappa, r.tau)?,
        )
    }

    /// The core's scene with the reference's viscous damping beside the kernel (zeta may be
    /// 0: the scenes of [`kernel_off_grid`]), at `threshold` (the reference's own is not
    /// read, so that one scene can be tried at several).
    ///
    /// # Errors
    /// When the core refuses the scene.
    pub fn core_with_viscous(
        &self,
        threshold: Threshold<f64>,
    ) -> Result<Scene<f64, ViscousAndKernel>, contact_bounce::Error> {
        let r = &self.reference;
        Scene::new(
            Contact {
                frequency: Frequency::Omega(r.omega),
                offset: Offset::Delta(r.delta),
                restitution: Restitution::Coefficient(r.restitution),
                closing_speed: r.closing_speed,
                threshold,
            },
            (
                Viscous::optional(r.zeta)?,
                contact_bounce::Hereditary::exponential(r.kappa, r.tau)?,
            ),
        )
    }
}

/// Kernel scenes: preload and gap, Omega tau 0.1-10, kernel damping (kappa tau^2 / (2 Omega))
/// 0.002-0.03, static stiffness kappa tau / Omega^2 below 0.2.
#[must_use]
pub fn kernel_grid() -> Vec<KernelScene> {
    let mut out = Vec::new();
    for (delta, r, v0) in [
        (-1e-3, 0.5, 0.3),
        (-1e-3, 0.9, 0.1),
        (1e-3, 0.9, 3.0),
        (1e-3, 1.0, 3.0),
    ] {
        for omega_tau in [0.1, 1.0, 10.0] {
            for zeta_equivalent in [0.002, 0.01, 0.03] {
                let omega = 1000.0;
                let tau = omega_tau / omega;
                let kappa = 2.0 * zeta_equivalent * omega / (tau * tau);
                if r == 1.0 && zeta_equivalent < 0.01 {
                    continue; // thousands of impacts: slow, and covered by the others
                }
                out.push(KernelScene {
                    name: format!("kernel Delta={delta} R={r} Omega tau={omega_tau} zeta_eq={zeta_equivalent}"),
                    reference: crate::reference::hereditary::Kernelled {
                        omega,
                        zeta: 0.0,
                        delta,
                        restitution: r,
                        closing_speed: v0,
                        kappa,
                        tau,
                        state: None,
                        threshold: None,
                    },
                });
            }
        }
    }
    out
}

/// Kernel scenes off the grid: preloads and gaps, Omega tau log-uniform in 0.05-20, kernel
/// damping (kappa tau^2 / (2 Omega)) in 0.001-0.05 with the static stiffness kappa tau kept
/// below 0.8 Omega^2, viscous damping 0 or up to 0.05, R 0.3-0.95, j0 0.1-10 (a gap's at
/// least 1). `seed` picks them.
#[must_use]
pub fn kernel_off_grid(count: usize, seed: u64) -> Vec<KernelScene> {
    let mut next = uniform(seed);
    let log_uniform = |u: f64, lo: f64, hi: f64| (lo.ln() + u * (hi.ln() - lo.ln())).exp();
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let omega = 1000.0;
        let tau = log_uniform(next(), 0.05, 20.0) / omega;
        let kappa = 2.0 * log_uniform(next(), 1e-3, 0.05) * omega / (tau * tau);
        let zeta = if next() < 0.5 {
            0.0
        } else {
            log_uniform(next(), 1e-3, 0.05)
        };
        let r = 0.3 + 0.65 * next();
        let gap = next() < 0.5;
        let j0 = log_uniform(next(), if gap { 1.0 } else { 0.1 }, 10.0);
        if kappa * tau >= 0.8 * omega * omega {
            continue;
        }
        let delta = if gap { 1e-3 } else { -1e-3 };
        out.push(KernelScene {
            name: format!(
                "kernel off-grid Delta={delta} R={r:.3} Omega tau={:.3} kappa={kappa:.3e} zeta={zeta:.4} j0={j0:.3}",
                omega * tau
            ),
            reference: crate::reference::hereditary::Kernelled {
                omega,
                zeta,
                delta,
                restitution: r,
                closing_speed: j0 * omega * 1e-3 / (2.0 * r),
                kappa,
                tau,
                state: None,
                threshold: None,
            },
        });
    }
    out
}
