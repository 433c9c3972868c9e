//! Fixtures shared by the tests of `granbond` (rust-core/tests) and
//! `granbond-scene` (granbond-scene/tests): a realistic bond parameter set,
//! pair kinematics, rotations; proptest strategies; the header's names.

pub mod header;
pub mod signed_law;
pub mod strategies;

use granbond::bond::{BondModel, BondOutput, BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond::vector::{v3, Vec3};
use nalgebra::{Rotation3, Unit};

pub const RADIUS: f64 = 1e-3;
pub const DENSITY: f64 = 2500.0;

/// Stiffnesses with real hysteresis (ku = 3k, kc = k/10) on every law, all
/// degrees of freedom on, damping off, no breakage.
pub fn params() -> BondParams {
    BondParams {
        lambda: 0.5,
        k_fn1: 1e10,
        ku_fn1: 3e10,
        kc_fn1: 1e9,
        k_fn2: 1e13,
        ku_fn2: 3e13,
        kc_fn2: 1e12,
        k_ft: 5e12,
        k_tn: 5e12,
        ku_tn: 1.5e13,
        kc_tn: 5e11,
        k_tt: 5e12,
        ku_tt: 1.5e13,
        kc_tt: 5e11,
        damping: 0,
        create_distance: 2.5 * RADIUS,
        create_step: 0,
        ..BondParams::default()
    }
}

/// Elastic (no hysteresis: ku = k, kc = 0) version of [`params`].
pub fn elastic_params() -> BondParams {
    let p = params();
    BondParams {
        ku_fn1: p.k_fn1,
        kc_fn1: 0.0,
        ku_fn2: p.k_fn2,
        kc_fn2: 0.0,
        ku_tn: p.k_tn,
        kc_tn: 0.0,
        ku_tt: p.k_tt,
        kc_tt: 0.0,
        ..p
    }
}

pub fn model(p: BondParams) -> BondModel {
    BondModel::new(p).expect("valid parameters")
}

/// Two spheres of radius [`RADIUS`] at rest, centres `distance` apart on x.
pub fn pair_at(distance: f64) -> PairKinematics {
    PairKinematics {
        x_i: [distance, 0.0, 0.0],
        x_j: [0.0; 3],
        radius_i: RADIUS,
        radius_j: RADIUS,
        ..PairKinematics::default()
    }
}

/// A bond created at rest length `r0`.
pub fn bond_at(r0: f64) -> BondState {
    BondState::created(r0)
}

pub fn step(m: &BondModel, k: &PairKinematics, dt: f64, s: &mut BondState) -> BondOutput {
    let mut out = BondOutput::default();
    m.step(k, dt, s, &mut out).expect("valid kinematics");
    out
}

pub fn rotation(axis: [f64; 3], angle: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Unit::new_normalize(v3(axis)), angle)
}

pub fn rotate(q: &Rotation3<f64>, a: [f64; 3]) -> [f64; 3] {
    (q * v3(a)).into()
}

pub fn rotate_kinematics(q: &Rotation3<f64>, k: &PairKinematics) -> PairKinematics {
    PairKinematics {
        x_i: rotate(q, k.x_i),
        x_j: rotate(q, k.x_j),
        v_i: rotate(q, k.v_i),
        v_j: rotate(q, k.v_j),
        w_i: rotate(q, k.w_i),
        w_j: rotate(q, k.w_j),
        ..*k
    }
}

pub fn rotate_bond_state(q: &Rotation3<f64>, s: &BondState) -> BondState {
    BondState {
        shear_force: rotate(q, s.shear_force),
        twist_angle: rotate(q, s.twist_angle),
        bend_angle: rotate(q, s.bend_angle),
        bend_history: rotate(q, s.bend_history),
        ..*s
    }
}

/// |a - b| <= tol * scale, component-wise on vectors.
pub fn close3(a: [f64; 3], b: [f64; 3], tol: f64, scale: f64) -> bool {
    (v3(a) - v3(b)).norm() <= tol * scale
}

pub fn norm(a: [f64; 3]) -> f64 {
    v3(a).norm()
}

/// Total torque of a pair's loads about the origin: zero when the loads
/// conserve angular momentum.
pub fn net_moment(k: &PairKinematics, out: &BondOutput) -> Vec3 {
    let f = v3(out.force_i);
    v3(k.x_i).cross(&f) + v3(k.x_j).cross(&-f) + v3(out.torque_i) + v3(out.torque_j)
}

/// A deterministic stream of numbers in [-1, 1), for tests that sweep
/// many configurations reproducibly.
pub struct Numbers(pub u64);

impl Numbers {
    pub fn uniform(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    pub fn vec(&mut self, scale: f64) -> [f64; 3] {
        [
            self.uniform() * scale,
            self.uniform() * scale,
            self.uniform() * scale,
        ]
    }
}
