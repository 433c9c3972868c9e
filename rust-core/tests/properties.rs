//! Property-based checks of the invariants over random parameters and
//! kinematics (proptest shrinks any counterexample to a small one).

use granbond_test_support as common;

use common::strategies::{bond_params, bonded_pair, vec3};
use common::{close3, net_moment, norm, rotate, rotate_bond_state, rotate_kinematics, rotation};
use granbond::bond::{BondModel, BondOutput, BondParams, BondState, BOND_SLOTS};
use granbond::contact::{ContactOutput, ContactState, VoigtModel, VoigtParams};
use granbond::kinematics::PairKinematics;
use granbond::state_layout::swap_state;
use granbond::vector::v3;
use proptest::prelude::*;

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
