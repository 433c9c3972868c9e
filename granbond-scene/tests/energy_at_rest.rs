//! Bonds at rest under the square root, in the crate's scene runner (its
//! own integrator, symplectic Euler): the tetrahedron of
//! `tests/validation/decks/energy/energy_tetra.in` (four spheres, six
//! elastic bonds formed at zero compression, one sphere started at
//! 0.1 m/s, nothing else acting), its budget kinetic energy plus the energy
//! the bonds store (`BondModel::stored_energy`, every spring).
//!
//! - With `compression_linear_below = (k_fn1/k_fn2)^2` (the slope at rest
//!   matches tension, what the warning suggests) the budget stays at its
//!   start up to the recommended step.
//! - With the plain square root it grows, at half the recommended step,
//!   far beyond the integrator's error: the time-step check warns there
//!   at every step (`rest_stable_fraction` 0).

use granbond::bond::{BondModel, BondParams};
use granbond::vector::Vec3;
use granbond_scene::runner::{Scene, Sphere};

const RADIUS: f64 = 1e-3;
const DENSITY: f64 = 2500.0;
const K_FN2: f64 = 5.0e10;
const K_FN1: f64 = 1.5811388300841898e8;
const K_S: f64 = 2.0e10;

fn elastic(eps: f64) -> BondParams {
    BondParams {
        lambda: 1.0,
        k_fn1: K_FN1,
        ku_fn1: K_FN1,
        k_fn2: K_FN2,
        ku_fn2: K_FN2,
        k_ft: K_S,
        k_tn: K_S,
        ku_tn: K_S,
        k_tt: K_S,
        ku_tt: K_S,
        damping: 0,
        compression_linear_below: eps,
        create_distance: 2.02e-3,
        create_step: 0,
        max_distance: 3e-3,
        ..BondParams::default()
    }
}

/// The budget's mean over the last fifth of `duration` seconds at
/// `fraction` of the recommended step, over its mean over the first fifth
/// (the integrator's error oscillates about the budget, by a few percent at
/// half the step: the velocities lag the positions by half a step), its
/// largest over its start, and the recommended step.
fn run(params: BondParams, fraction: f64, duration: f64) -> (f64, f64, f64) {
    let model = BondModel::new(params).unwrap();
    let mass = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let recommended = model.recommended_timestep(RADIUS, RADIUS, mass, mass);
    let mut scene = Scene::new(fraction * recommended);
    let h = std::f64::consts::SQRT_2 * RADIUS;
    for x in [[0.0, 0.0, 0.0], [h, h, 0.0], [h, 0.0, h], [0.0, h, h]] {
        scene
            .spheres
            .push(Sphere::new(Vec3::new(x[0], x[1], x[2]), RADIUS, DENSITY));
    }
    scene.spheres[0].body.v = Vec3::new(0.08, 0.05, 0.033166247903554);
    scene.bond_model = Some(model.clone());
    assert_eq!(scene.create_bonds().unwrap(), 6);
    let budget = |scene: &Scene| {
        let stored: f64 = scene
            .bonds
            .iter()
            .map(|b| {
                let (xi, xj) = (scene.spheres[b.i].body.x, scene.spheres[b.j].body.x);
                let n = (xi - xj) / (xi - xj).norm();
                model
                    .stored_energy(&b.state, n.into(), b.last.delta, RADIUS, RADIUS)
                    .total()
            })
            .sum();
        scene.kinetic_energy() + stored
    };
    let start = budget(&scene);
    let steps = (duration / scene.dt) as usize;
    let series: Vec<f64> = (0..steps)
        .map(|_| {
            scene.advance().unwrap();
            budget(&scene)
        })
        .collect();
    let fifth = steps / 5;
    let mean = |part: &[f64]| part.iter().sum::<f64>() / part.len() as f64;
    let drift = mean(&series[steps - fifth..]) / mean(&series[..fifth]);
    let largest = series.iter().cloned().fold(0.0, f64::max) / start;
    (drift, largest, recommended)
}

#[test]
fn the_regularisation_matched_to_tension_keeps_the_budget_up_to_the_recommended_step() {
    let matched = (K_FN1 / K_FN2).powi(2);
    for fraction in [0.2, 0.5, 0.99] {
        let (drift, largest, step) = run(elastic(matched), fraction, 0.03);
        println!(
            "matched, {fraction} of {step:.4e} s: budget last/first fifth x{drift:.4}, at most x{largest:.4}"
        );
        assert!(drift < 1.01, "x{drift} at {fraction} of the step");
    }
}

#[test]
fn the_plain_square_root_at_rest_grows_the_budget_below_the_recommended_step() {
    let (drift, largest, step) = run(elastic(0.0), 0.5, 0.03);
    println!("plain, 0.5 of {step:.4e} s: budget last/first fifth x{drift:.4}, at most x{largest:.4}");
    assert!(drift > 2.0, "x{drift}");
    let model = BondModel::new(elastic(0.0)).unwrap();
    assert_eq!(model.rest_stable_fraction(), 0.0);
}
