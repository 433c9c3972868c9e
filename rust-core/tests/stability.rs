//! The critical-step estimates are the real stability limits of symplectic
//! Euler: just below them an oscillator stays bounded, just above it blows up.

use granbond_test_support as common;

use common::*;
use granbond::bond::BondParams;
use granbond::contact::{VoigtModel, VoigtParams};
use granbond::stability::oscillator_limit;

/// Peak |x| relative to the start after many steps of symplectic Euler on
/// `m x'' = -k x - c x'`.
fn growth(m: f64, k: f64, c: f64, dt: f64) -> f64 {
    let (mut x, mut v) = (1.0f64, 0.0f64);
    let mut peak = 0.0f64;
    for _ in 0..20_000 {
        v += dt * (-k * x - c * v) / m;
        x += dt * v;
        peak = peak.max(x.abs());
    }
    peak
}

#[test]
fn oscillator_limit_separates_bounded_from_exploding_motion() {
    let (m, k) = (2.0f64, 50.0f64);
    for zeta in [0.0, 0.1, 0.5, 2.0] {
        let c = 2.0 * zeta * (k * m).sqrt();
        let dt = oscillator_limit(m, k, c);
        assert!(
            growth(m, k, c, 0.99 * dt) < 1e3,
            "zeta={zeta}: stable below the limit"
        );
        assert!(growth(m, k, c, 1.01 * dt) > 1e6, "zeta={zeta}: unstable above it");
    }
}

#[test]
fn bond_tension_limit_matches_its_axial_mode() {
    let p = BondParams {
        compression: 0,
        shear: 0,
        twist: 0,
        bend: 0,
        ..elastic_params()
    };
    let m = model(p);
    let mass = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let dt = m.critical_timestep(RADIUS, RADIUS, mass, mass);
    let area = std::f64::consts::PI * (0.5 * RADIUS).powi(2);
    let expected = 2.0 * (mass / 2.0 / (p.k_fn2 * area)).sqrt();
    assert!((dt - expected).abs() < 1e-12 * expected);
    // More degrees of freedom can only shorten the step.
    assert!(model(params()).critical_timestep(RADIUS, RADIUS, mass, mass) <= dt);
}

#[test]
fn voigt_limit_is_the_shortest_of_its_modes() {
    let model = VoigtModel::new(VoigtParams::default()).unwrap();
    let mass = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let dt = model.critical_timestep(RADIUS, RADIUS, mass, mass);
    let normal = oscillator_limit(mass / 2.0, 1e4, 1e-3);
    assert!(dt <= normal && dt > 0.0);
}
