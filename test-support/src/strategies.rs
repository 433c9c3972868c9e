//! proptest strategies of the property tests: bond parameters and bonded
//! pairs with arbitrary motion and load history.

use super::norm;
use granbond::bond::{BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond::vector::v3;
use proptest::prelude::*;

pub fn vec3(scale: f64) -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-scale..scale)
}

/// Stiffness triples with ku >= k and kc >= 0 over several decades.
pub fn stiffness_loop() -> impl Strategy<Value = (f64, f64, f64)> {
    (8.0f64..13.0, 1.0f64..100.0, 0.0f64..2.0).prop_map(|(e, ratio, kc)| {
        let k = 10f64.powf(e);
        (k, k * ratio, k * kc)
    })
}

pub fn bond_params() -> impl Strategy<Value = BondParams> {
    (
        stiffness_loop(),
        stiffness_loop(),
        stiffness_loop(),
        stiffness_loop(),
        (9.0f64..13.0),
        (0.1f64..1.5),
        prop::array::uniform4(0.0f64..0.9),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(c, t, tn, tt, kt, lambda, eta, damping, smooth)| BondParams {
            lambda,
            k_fn1: c.0,
            ku_fn1: c.1,
            kc_fn1: c.2,
            k_fn2: t.0,
            ku_fn2: t.1,
            kc_fn2: t.2,
            k_ft: 10f64.powf(kt),
            k_tn: tn.0,
            ku_tn: tn.1,
            kc_tn: tn.2,
            k_tt: tt.0,
            ku_tt: tt.1,
            kc_tt: tt.2,
            eta_fn: eta[0],
            eta_ft: eta[1],
            eta_tn: eta[2],
            eta_tt: eta[3],
            damping: damping as i32,
            damping_smooth: smooth as i32,
            smooth_velocity: 1e-3,
            smooth_angular_velocity: 1e-1,
            ..BondParams::default()
        })
}

/// A bonded pair near its rest length with arbitrary motion and history.
pub fn bonded_pair() -> impl Strategy<Value = (PairKinematics, BondState)> {
    (
        vec3(1.0),
        (0.5f64..2.0),
        (0.5f64..2.0),
        (-2e-3f64..2e-3),
        vec3(0.1),
        vec3(0.1),
        vec3(50.0),
        vec3(50.0),
        (
            vec3(1.0),
            vec3(1e-3),
            vec3(1e-3),
            (0.0f64..1e-5),
            (-1e-5f64..0.0),
            (-2.0f64..2.0),
        ),
    )
        .prop_map(
            |(dir, ri, rj, strain, vi, vj, wi, wj, (ft, tn, tt, dmax, dmin, side))| {
                let (ri, rj) = (ri * 1e-3, rj * 1e-3);
                let n = {
                    let d = v3(dir);
                    if d.norm() < 1e-3 {
                        v3([1.0, 0.0, 0.0])
                    } else {
                        d.normalize()
                    }
                };
                let r0 = ri + rj;
                let r = r0 * (1.0 + strain);
                let kin = PairKinematics {
                    x_i: (n * r).into(),
                    x_j: [0.0; 3],
                    v_i: vi,
                    v_j: vj,
                    w_i: wi,
                    w_j: wj,
                    radius_i: ri,
                    radius_j: rj,
                };
                let mut s = BondState::created(r0);
                s.shear_force = (v3(ft) - n * v3(ft).dot(&n)).into();
                s.twist_angle = (n * v3(tn).dot(&n)).into();
                s.bend_angle = (v3(tt) - n * v3(tt).dot(&n)).into();
                s.delta_max = dmax;
                s.delta_min = dmin;
                // History extremes that include the current angles; the
                // bend on either side of its leading extreme (`side < 0`:
                // the opposite side), the extremes beyond or below it.
                let phi = v3(tn).dot(&n);
                s.twist_max = phi.max(0.0) + 0.5 * side.abs() * norm(tn);
                s.twist_min = phi.min(0.0) - 0.5 * side.abs() * norm(tn);
                s.bend_history = (v3(s.bend_angle) * side).into();
                s.bend_opposite = (1.0 - side.abs()).abs() * norm(tt);
                (kin, s)
            },
        )
}
