//! Invariants of the assembled bond: Newton's third law, momentum,
//! rigid-motion indifference, frame indifference, swap symmetry, damping.

use granbond_test_support as common;

use common::*;
use granbond::bond::{BondOutput, BondParams, BondState, BOND_SLOTS};
use granbond::kinematics::PairKinematics;
use granbond::state_layout::swap_state;
use granbond::vector::{v3, Vec3};
use granbond_scene::{Scene, Sphere};

/// A loaded, moving, slightly oblique pair with history on every law.
fn loaded_pair() -> (PairKinematics, BondState) {
    let r0 = 2.0 * RADIUS;
    let kin = PairKinematics {
        x_i: [r0 * 0.999, 0.02 * RADIUS, -0.01 * RADIUS],
        x_j: [0.0, 0.0, 0.0],
        v_i: [0.01, -0.02, 0.005],
        v_j: [-0.003, 0.01, 0.0],
        w_i: [3.0, -1.0, 2.0],
        w_j: [-1.0, 0.5, 4.0],
        radius_i: RADIUS,
        radius_j: 0.8 * RADIUS,
    };
    let mut state = bond_at(r0);
    state.delta_max = 3e-6;
    state.delta_min = -2e-7;
    state.shear_force = [0.0, 0.3, -0.2];
    state.twist_angle = [1e-4, 0.0, 0.0];
    state.bend_angle = [0.0, -2e-4, 1e-4];
    state.twist_max = 3e-4;
    state.twist_min = -1e-4;
    // Leading side across the bend, a smaller extreme on the opposite side.
    state.bend_history = [0.0, 4e-4, 3e-4];
    state.bend_opposite = 1e-4;
    (kin, state)
}

fn all_damped() -> BondParams {
    BondParams {
        damping: 1,
        eta_fn: 0.3,
        eta_ft: 0.2,
        eta_tn: 0.25,
        eta_tt: 0.15,
        ..params()
    }
}

#[test]
fn loads_obey_newtons_third_law_and_carry_no_net_moment() {
    for p in [params(), all_damped()] {
        let m = model(p);
        let (kin, mut state) = loaded_pair();
        let out = step(&m, &kin, 1e-7, &mut state);
        assert!(norm(out.force_i) > 0.0 && norm(out.torque_i) > 0.0);
        let scale = norm(out.force_i) * RADIUS + norm(out.torque_i);
        assert!(
            net_moment(&kin, &out).norm() < 1e-12 * scale,
            "net moment {}",
            net_moment(&kin, &out)
        );
    }
}

#[test]
fn shear_couple_turns_both_spheres_the_same_way() {
    // Pure shear: j fixed, i slid along y. Seed eq. 13's T_j = -T_i would
    // turn them oppositely and leave a net moment.
    let m = model(BondParams {
        twist: 0,
        bend: 0,
        ..params()
    });
    let mut kin = pair_at(2.0 * RADIUS);
    kin.v_i = [0.0, 0.1, 0.0];
    let mut state = bond_at(2.0 * RADIUS);
    let out = step(&m, &kin, 1e-6, &mut state);
    assert!(out.torque_i[2] != 0.0);
    assert!(out.torque_i[2] * out.torque_j[2] > 0.0, "same sign about z");
    let seed_torque_j = -v3(out.torque_i);
    let seed_moment = v3(kin.x_i).cross(&v3(out.force_i)) + v3(out.torque_i) + seed_torque_j;
    assert!(
        seed_moment.norm() > 1e-3 * norm(out.torque_i),
        "the seed's form would not balance"
    );
}

#[test]
fn isolated_undamped_pair_conserves_momentum_over_1e5_steps() {
    let mut scene = Scene::new(2e-8);
    let mut a = Sphere::new(Vec3::zeros(), RADIUS, DENSITY);
    let mut b = Sphere::new(Vec3::new(2.0 * RADIUS, 0.0, 0.0), 0.7 * RADIUS, DENSITY);
    a.body.v = Vec3::new(0.02, -0.01, 0.03);
    a.body.w = Vec3::new(5.0, -3.0, 1.0);
    b.body.v = Vec3::new(-0.01, 0.04, 0.0);
    b.body.w = Vec3::new(-2.0, 6.0, -4.0);
    scene.spheres = vec![a, b];
    scene.bond_model = Some(model(elastic_params()));
    assert_eq!(scene.create_bonds().unwrap(), 1);
    let (p0, l0) = (scene.linear_momentum(), scene.angular_momentum());
    let mut max_load = 0.0f64;
    for _ in 0..100_000 {
        scene.advance().unwrap();
        max_load = max_load.max(scene.load(0).0.norm());
    }
    assert_eq!(scene.intact_bonds(), 1);
    assert!(max_load > 1e-3, "the bond was loaded ({max_load} N)");
    let p_scale = a.body.mass * 0.05;
    let l_scale = p_scale * 3.0 * RADIUS + a.body.inertia * 10.0;
    assert!(
        (scene.linear_momentum() - p0).norm() < 1e-12 * p_scale,
        "linear momentum drifted"
    );
    assert!(
        (scene.angular_momentum() - l0).norm() < 1e-10 * l_scale,
        "angular momentum drifted"
    );
}

#[test]
fn bonded_pair_in_rigid_rotation_builds_no_force_or_torque() {
    let m = model(params());
    let omega = Vec3::new(0.3, -2.0, 1.1);
    let mut state = bond_at(2.0 * RADIUS);
    let dt = 1e-5;
    let x0 = Vec3::new(2.0 * RADIUS, 0.0, 0.0);
    for k in 0..200 {
        let x_i = common::rotation(omega.into(), omega.norm() * dt * k as f64) * x0;
        let kin = PairKinematics {
            x_i: x_i.into(),
            x_j: [0.0; 3],
            v_i: omega.cross(&x_i).into(),
            v_j: [0.0; 3],
            w_i: omega.into(),
            w_j: omega.into(),
            radius_i: RADIUS,
            radius_j: RADIUS,
        };
        let out = step(&m, &kin, dt, &mut state);
        // The normal force sees only r, which rotation keeps up to round-off
        // (|delta| ~ 1e-19 m, amplified by the square root); everything
        // else must vanish.
        assert!(out.delta.abs() < 1e-17);
        let n = x_i.normalize();
        let tangential = v3(out.force_i) - n * v3(out.force_i).dot(&n);
        assert!(tangential.norm() < 1e-12, "shear force {tangential}");
        assert!(
            norm(state.shear_force) < 1e-12
                && norm(state.twist_angle) < 1e-15
                && norm(state.bend_angle) < 1e-15
        );
        assert!(norm(out.torque_i) < 1e-15 && norm(out.torque_j) < 1e-15);
    }
}

#[test]
fn rotating_the_scene_rotates_every_force_and_torque() {
    for p in [params(), all_damped()] {
        let m = model(p);
        let (kin, state) = loaded_pair();
        let q = rotation([0.3, -0.7, 0.4], 1.234);
        let (mut s1, mut s2) = (state, rotate_bond_state(&q, &state));
        let a = step(&m, &kin, 1e-7, &mut s1);
        let b = step(&m, &rotate_kinematics(&q, &kin), 1e-7, &mut s2);
        let fs = norm(a.force_i);
        let ts = norm(a.torque_i) + norm(a.torque_j);
        assert!(close3(rotate(&q, a.force_i), b.force_i, 1e-12, fs));
        assert!(close3(rotate(&q, a.torque_i), b.torque_i, 1e-12, ts));
        assert!(close3(rotate(&q, a.torque_j), b.torque_j, 1e-12, ts));
        assert!((a.sigma - b.sigma).abs() <= 1e-12 * a.sigma && (a.tau - b.tau).abs() <= 1e-12 * a.tau);
        let rotated = rotate_bond_state(&q, &s1);
        assert!(close3(
            rotated.bend_angle,
            s2.bend_angle,
            1e-12,
            norm(s1.bend_angle)
        ));
        assert!(close3(
            rotated.twist_angle,
            s2.twist_angle,
            1e-12,
            norm(s1.twist_angle)
        ));
    }
}

#[test]
fn swapping_i_and_j_mirrors_the_result_through_the_sign_flip_table() {
    for p in [params(), all_damped()] {
        let m = model(p);
        let (kin, state) = loaded_pair();
        let mut from_i = state;
        let mut from_j = state;
        swap_state(&BOND_SLOTS, BondState::as_slots_mut(&mut from_j));
        let a = step(&m, &kin, 1e-7, &mut from_i);
        let b: BondOutput = step(&m, &kin.swapped(), 1e-7, &mut from_j);
        let fs = norm(a.force_i);
        let ts = norm(a.torque_i) + norm(a.torque_j);
        assert!(close3(b.force_i, (-v3(a.force_i)).into(), 1e-12, fs));
        assert!(close3(b.torque_i, a.torque_j, 1e-12, ts));
        assert!(close3(b.torque_j, a.torque_i, 1e-12, ts));
        swap_state(&BOND_SLOTS, BondState::as_slots_mut(&mut from_j));
        for (x, y) in from_i.as_slots().iter().zip(from_j.as_slots()) {
            assert!(
                (x - y).abs() <= 1e-12 * (x.abs() + y.abs()) + 1e-300,
                "state differs: {x} vs {y}"
            );
        }
    }
}

#[test]
fn damping_never_adds_energy() {
    let damped = model(all_damped());
    let undamped = model(params());
    let (kin, state) = loaded_pair();
    // Many relative motions, including ones opposing each load.
    for k in 0..64 {
        let s = |c: usize| if (k >> c) & 1 == 1 { 1.0 } else { -1.0 };
        let moving = PairKinematics {
            v_i: [s(0) * 0.01, s(1) * 0.02, 0.003],
            w_i: [s(2) * 3.0, -1.0, s(3) * 2.0],
            w_j: [s(4) * 1.0, 0.5, s(5) * 4.0],
            ..kin
        };
        let (mut s1, mut s2) = (state, state);
        let d = step(&damped, &moving, 1e-7, &mut s1);
        let u = step(&undamped, &moving, 1e-7, &mut s2);
        let df = v3(d.force_i) - v3(u.force_i);
        let power = df.dot(&(v3(moving.v_i) - v3(moving.v_j)))
            + (v3(d.torque_i) - v3(u.torque_i)).dot(&v3(moving.w_i))
            + (v3(d.torque_j) - v3(u.torque_j)).dot(&v3(moving.w_j));
        let scale = norm(u.force_i) * 0.05 + (norm(u.torque_i) + norm(u.torque_j)) * 5.0;
        assert!(power <= 1e-12 * scale, "damping power {power} > 0 for case {k}");
        assert!(power < 0.0, "damping dissipates for case {k}");
    }
}

#[test]
fn smooth_damping_fades_out_below_the_velocity_scale() {
    let p = BondParams {
        damping_smooth: 1,
        smooth_velocity: 1.0,
        ..all_damped()
    };
    let m = model(p);
    let mut kin = pair_at(2.0 * RADIUS * (1.0 - 1e-4));
    let state = bond_at(2.0 * RADIUS);
    let mut undamped_state = state;
    let fn0 = step(&model(params()), &kin, 1e-7, &mut undamped_state).force_i[0];
    for (vn, expected_fraction) in [(0.0, 0.0), (-0.25, 0.25), (-0.5, 0.5), (-2.0, 1.0)] {
        kin.v_i = [vn, 0.0, 0.0];
        let mut s = state;
        let f = step(&m, &kin, 1e-7, &mut s).force_i[0];
        let damping = f - fn0;
        assert!(
            (damping - 0.3 * fn0.abs() * expected_fraction).abs() <= 1e-12 * fn0.abs(),
            "vn={vn}"
        );
    }
}

#[test]
fn the_seeds_slip_velocity_would_load_a_rigidly_rotating_bond() {
    // Seed eq. 7: v_tr = v_t + (w_i R_i - w_j R_j) x n. In rigid rotation
    // it equals r (omega x n), not zero, which is why the spec uses
    // v_t - (rc_i w_i + rc_j w_j) x n.
    let omega = Vec3::new(0.0, 0.0, 2.0);
    let x_i = Vec3::new(2.0 * RADIUS, 0.0, 0.0);
    let n = x_i.normalize();
    let v_rel = omega.cross(&x_i);
    let vt = v_rel - n * v_rel.dot(&n);
    let seed = vt + (omega * RADIUS - omega * RADIUS).cross(&n);
    let spec = granbond::kinematics::slip_velocity(v_rel, omega, omega, n, RADIUS, RADIUS);
    assert!(seed.norm() > 1e-3);
    assert!(spec.norm() < 1e-18);
}
