use contact_bounce::*;
#[test]
fn scratch() {
    for (tau, kappa, j) in [(1e-4, 1e8, 1.0), (1e-3, 1e6, 0.1), (1e-5, 1e10, 1.0), (3e-4, 3e7, 3.0)] {
        let mut ends = vec![];
        for (tol, maxh) in [(1e-4, 4096u32), (1e-6, 100_000), (1e-8, 10_000_000), (1e-10, 100_000_000)] {
            let k = Hereditary::exponential(kappa, tau).unwrap().with_tolerance(tol).unwrap().with_max_harmonics(maxh);
            let c = Contact { frequency: Frequency::Omega(1000.0), offset: Offset::Delta(-1e-3), restitution: Restitution::Coefficient(0.7), closing_speed: j * 1000.0 * 1e-3 / 0.6, threshold: Threshold::None };
            let s = Scene::new(c, k).unwrap();
            let e = s.predict(Method::Averaged(Nodes::N20)).end_time.seconds().unwrap();
            ends.push(e);
        }
        let last = *ends.last().unwrap();
        println!("tau {tau} kappa {kappa}: {:?}", ends.iter().map(|e| e / last - 1.0).collect::<Vec<_>>());
    }
}
