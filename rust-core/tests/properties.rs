//! Property-based checks of the invariants over random parameters and
//! kinematics (proptest shrinks any counterexample to a small one).

mod common;

use common::{close3, net_moment, norm, rotate, rotate_bond_state, rotate_kinematics, rotation};
use granbond::bond::{BondModel, BondOutput, BondParams, BondState, BOND_SLOTS};
use granbond::contact::{ContactOutput, ContactState, VoigtModel, VoigtParams};
use granbond::kinematics::PairKinematics;
use granbond::state_layout::swap_state;
use granbond::vector::v3;
use proptest::prelude::*;

fn vec3(scale: f64) -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-scale..scale)
}

/// Stiffness triples with ku >= k and kc >= 0 over several decades.
fn stiffness_loop() -> impl Strategy<Value = (f64, f64, f64)> {
    (8.0f64..13.0, 1.0f64..100.0, 0.0f64..2.0).prop_map(|(e, ratio, kc)| {
        let k = 10f64.powf(e);
        (k, k * ratio, k * kc)
    })
}

fn bond_params() -> impl Strategy<Value = BondParams> {
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
fn bonded_pair() -> impl Strategy<Value = (PairKinematics, BondState)> {
    (
        vec3(1.0),
        (0.5f64..2.0),
        (0.5f64..2.0),
        (-2e-3f64..2e-3),
        vec3(0.1),
        vec3(0.1),
        vec3(50.0),
        vec3(50.0),
        (vec3(1.0), vec3(1e-3), vec3(1e-3), (0.0f64..1e-5), (-1e-5f64..0.0)),
    )
        .prop_map(
            |(dir, ri, rj, strain, vi, vj, wi, wj, (ft, tn, tt, dmax, dmin))| {
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
                s.twist_max = norm(tn);
                s.bend_max = norm(tt);
                (kin, s)
            },
        )
}

fn run(m: &BondModel, k: &PairKinematics, s: &mut BondState) -> BondOutput {
    let mut out = BondOutput::default();
    m.step(k, 1e-7, s, &mut out).unwrap();
    out
}

fn load_scale(out: &BondOutput, k: &PairKinematics) -> f64 {
    norm(out.force_i) * (k.radius_i + k.radius_j) + norm(out.torque_i) + norm(out.torque_j) + 1e-300
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn bond_loads_balance_forces_and_moments(p in bond_params(), (k, s) in bonded_pair()) {
        let m = BondModel::new(p).unwrap();
        let out = run(&m, &k, &mut s.clone());
        prop_assert!(out.force_i.iter().chain(&out.torque_i).all(|x| x.is_finite()));
        prop_assert!(net_moment(&k, &out).norm() <= 1e-11 * load_scale(&out, &k));
    }

    #[test]
    fn bond_is_frame_indifferent(p in bond_params(), (k, s) in bonded_pair(),
                                 axis in vec3(1.0), angle in 0.0f64..6.0) {
        prop_assume!(norm(axis) > 1e-3);
        let m = BondModel::new(p).unwrap();
        let q = rotation(axis, angle);
        let a = run(&m, &k, &mut s.clone());
        let b = run(&m, &rotate_kinematics(&q, &k), &mut rotate_bond_state(&q, &s));
        let scale = load_scale(&a, &k) / (k.radius_i + k.radius_j);
        prop_assert!(close3(rotate(&q, a.force_i), b.force_i, 1e-9, scale));
        let tscale = load_scale(&a, &k);
        prop_assert!(close3(rotate(&q, a.torque_i), b.torque_i, 1e-9, tscale));
        prop_assert!(close3(rotate(&q, a.torque_j), b.torque_j, 1e-9, tscale));
    }

    #[test]
    fn bond_seen_from_j_is_the_mirror_image(p in bond_params(), (k, s) in bonded_pair()) {
        let m = BondModel::new(p).unwrap();
        let mut from_j = s;
        swap_state(&BOND_SLOTS, from_j.as_slots_mut());
        let a = run(&m, &k, &mut s.clone());
        let b = run(&m, &k.swapped(), &mut from_j);
        let scale = load_scale(&a, &k);
        prop_assert!(close3(b.force_i, (-v3(a.force_i)).into(), 1e-9, scale / (k.radius_i + k.radius_j)));
        prop_assert!(close3(b.torque_i, a.torque_j, 1e-9, scale));
        prop_assert!(close3(b.torque_j, a.torque_i, 1e-9, scale));
    }

    #[test]
    fn bond_damping_dissipates(p in bond_params(), (k, s) in bonded_pair()) {
        let damped = BondModel::new(BondParams { damping: 1, ..p }).unwrap();
        let undamped = BondModel::new(BondParams { damping: 0, ..p }).unwrap();
        let d = run(&damped, &k, &mut s.clone());
        let u = run(&undamped, &k, &mut s.clone());
        let power = (v3(d.force_i) - v3(u.force_i)).dot(&(v3(k.v_i) - v3(k.v_j)))
            + (v3(d.torque_i) - v3(u.torque_i)).dot(&v3(k.w_i))
            + (v3(d.torque_j) - v3(u.torque_j)).dot(&v3(k.w_j));
        let scale = norm(u.force_i) * 0.2 + (norm(u.torque_i) + norm(u.torque_j)) * 100.0;
        prop_assert!(power <= 1e-9 * scale, "damping power {} > 0", power);
    }

    #[test]
    fn voigt_contact_is_frame_indifferent_and_reciprocal(
        (k, _) in bonded_pair(), axis in vec3(1.0), angle in 0.0f64..6.0,
        spring in vec3(1e-6), roll in vec3(1e-3), mu in 0.0f64..1.0,
    ) {
        prop_assume!(norm(axis) > 1e-3);
        let model = VoigtModel::new(VoigtParams { mu, ..VoigtParams::default() }).unwrap();
        let n = v3(k.x_i).normalize();
        let state = ContactState {
            tangential_spring: (v3(spring) - n * v3(spring).dot(&n)).into(),
            rolling_angle: (v3(roll) - n * v3(roll).dot(&n)).into(),
        };
        let q = rotation(axis, angle);
        let (mut a, mut b) = (ContactOutput::default(), ContactOutput::default());
        model.step(&k, 1e-7, &mut state.clone(), &mut a).unwrap();
        let rotated = ContactState {
            tangential_spring: rotate(&q, state.tangential_spring),
            rolling_angle: rotate(&q, state.rolling_angle),
        };
        model.step(&rotate_kinematics(&q, &k), 1e-7, &mut rotated.clone(), &mut b).unwrap();
        let fs = norm(a.force_i) + 1e-300;
        let ts = norm(a.torque_i) + norm(a.torque_j) + 1e-300;
        prop_assert!(close3(rotate(&q, a.force_i), b.force_i, 1e-9, fs));
        prop_assert!(close3(rotate(&q, a.torque_i), b.torque_i, 1e-9, ts));
        // Coulomb: the tangential force never exceeds mu |Fn|.
        let ft = v3(a.force_i) - n * v3(a.force_i).dot(&n);
        prop_assert!(ft.norm() <= mu * a.normal_force.abs() * (1.0 + 1e-12) + 1e-300);
        // Seen from j, the force reverses.
        let mut c = ContactOutput::default();
        let mut swapped = state;
        for x in swapped.tangential_spring.iter_mut().chain(swapped.rolling_angle.iter_mut()) {
            *x = -*x;
        }
        model.step(&k.swapped(), 1e-7, &mut swapped, &mut c).unwrap();
        prop_assert!(close3(c.force_i, (-v3(a.force_i)).into(), 1e-9, fs));
        prop_assert!(close3(c.torque_i, a.torque_j, 1e-9, ts));
    }
}
