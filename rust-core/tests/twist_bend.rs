//! The twisting and bending torques follow the signed two-sided hysteresis
//! law (docs/models/bond-nonlinear.md, "Twisting and bending"): each side of
//! the angle has its own history extreme, so an angle that reverses through
//! zero loads the other side on its own virgin line (kept history) or
//! starts afresh there (`historyReset on`, the reference code's rule). The
//! expected torques are computed here, independently of the core, from the
//! law's table.

use granbond_test_support as common;

use common::signed_law::{Branch, SignedLaw};
use common::*;
use granbond::bond::section::section;
use granbond::bond::{BondModel, BondOutput, BondParams, BondState, BOND_SLOTS};
use granbond::kinematics::PairKinematics;
use granbond::state_layout::swap_state;
use granbond::vector::{v3, Vec3};

const DT: f64 = 1e-6;
/// Angular speed of the prescribed rotation: 1e-6 rad per step.
const SPIN: f64 = 1.0;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Dof {
    Twist,
    Bend,
}

/// Only the degree of freedom under test: the others are compiled out, so
/// the torque on `i` is the law's torque alone.
fn only(dof: Dof, history_reset: bool) -> BondModel {
    model(BondParams {
        tension: 0,
        compression: 0,
        shear: 0,
        twist: (dof == Dof::Twist) as i32,
        bend: (dof == Dof::Bend) as i32,
        history_reset: history_reset as i32,
        ..params()
    })
}

fn unit(a: [f64; 3]) -> Vec3 {
    v3(a) * (1.0 / v3(a).norm())
}

/// Spin of sphere `i` about `axis` at each step: up to `+theta1`, back
/// through zero to `-theta2`, then up to `+theta3` (angles in steps of
/// `SPIN * DT`).
fn cycle(theta1: f64, theta2: f64, theta3: f64) -> Vec<f64> {
    let steps = |angle: f64| (angle / (SPIN * DT)).round() as usize;
    let mut w = vec![SPIN; steps(theta1)];
    w.extend(vec![-SPIN; steps(theta1 + theta2)]);
    w.extend(vec![SPIN; steps(theta2 + theta3)]);
    w
}

/// Drives the bond through `spins` about `axis` (the bond axis `n` for
/// twisting, a direction across it for bending) and checks the torque on
/// both spheres against the signed law of the accumulated angle at every
/// step. Returns the branches visited on each side.
fn check_cycle(dof: Dof, n: Vec3, axis: Vec3, spins: &[f64], reset: bool) -> Vec<(bool, Branch)> {
    let m = only(dof, reset);
    let p = m.params;
    let sec = section(p.lambda, RADIUS, RADIUS);
    let (law, moment) = match dof {
        Dof::Twist => ((p.k_tn, p.ku_tn, p.kc_tn), sec.polar),
        Dof::Bend => ((p.k_tt, p.ku_tt, p.kc_tt), sec.inertia),
    };
    let r0 = 2.0 * RADIUS;
    let mut state = BondState::created(r0);
    let mut expected = SignedLaw::default();
    let mut integral = 0.0;
    let mut visited = Vec::new();
    for (k, &w) in spins.iter().enumerate() {
        let kin = PairKinematics {
            x_i: (n * r0).into(),
            w_i: (axis * w).into(),
            ..pair_at(0.0)
        };
        let out = step(&m, &kin, DT, &mut state);
        integral += w * DT;
        let angle = match dof {
            Dof::Twist => v3(state.twist_angle),
            Dof::Bend => v3(state.bend_angle),
        };
        // The stored angle is the integral of the spin, along the axis.
        assert!(
            (angle - axis * integral).norm() <= 1e-12 * 2e-3,
            "step {k}: angle {angle:?} vs {integral}"
        );
        let s = angle.dot(&axis);
        let (f, branch, positive) = expected.value(law, s, reset);
        visited.push((positive, branch));
        let want = axis * (-f * moment);
        // Where the angle crosses zero it is a round-off residual of the
        // accumulated sum (1e-16 of the peak), with no meaningful direction:
        // the torque of such an angle is the floor.
        let floor = law.0.max(law.1).max(law.2) * moment * 1e-15 * peak(spins);
        let tol = 1e-12 * want.norm() + floor;
        assert!(
            (v3(out.torque_i) - want).norm() <= tol,
            "step {k} ({branch:?}, angle {s}): torque on i {:?}, law {want:?}",
            out.torque_i
        );
        assert!((v3(out.torque_j) + want).norm() <= tol, "step {k}: torque on j");
        assert_eq!(out.force_i, [0.0; 3]);
    }
    visited.sort();
    visited.dedup();
    visited
}

/// The largest angle a cycle of spins reaches.
fn peak(spins: &[f64]) -> f64 {
    let mut angle: f64 = 0.0;
    let mut largest: f64 = 0.0;
    for w in spins {
        angle += w * DT;
        largest = largest.max(angle.abs());
    }
    largest
}

/// An axis and a direction across it, neither along a coordinate axis.
fn oblique() -> (Vec3, Vec3) {
    let n = unit([0.36, -0.48, 0.8]);
    let across = unit([0.8, 0.6, 0.0]);
    assert!(n.dot(&across).abs() < 1e-15);
    (n, across)
}

/// Both sides: virgin, unloading and reverse branches on the first side,
/// virgin loading and at least its unloading on the second.
fn assert_both_sides_loaded(visited: &[(bool, Branch)]) {
    for b in [Branch::Virgin, Branch::Unloading, Branch::Reverse] {
        assert!(
            visited.contains(&(true, b)),
            "positive side never on {b:?}: {visited:?}"
        );
    }
    assert!(visited.contains(&(false, Branch::Virgin)), "{visited:?}");
    assert!(visited.contains(&(false, Branch::Unloading)), "{visited:?}");
}

#[test]
fn bending_in_an_oblique_plane_follows_the_signed_two_sided_law_with_kept_history() {
    let (n, across) = oblique();
    // Reversal to a smaller angle on the other side, then past the first peak.
    let a = check_cycle(Dof::Bend, n, across, &cycle(1e-3, 0.5e-3, 1.5e-3), false);
    assert_both_sides_loaded(&a);
    // Reversal past the first peak's size on the other side.
    let b = check_cycle(Dof::Bend, n, across, &cycle(1e-3, 1.5e-3, 2e-3), false);
    assert_both_sides_loaded(&b);
}

#[test]
fn twisting_about_an_oblique_axis_follows_the_signed_two_sided_law_with_kept_history() {
    let (n, _) = oblique();
    for spins in [cycle(1e-3, 0.5e-3, 1.5e-3), cycle(1e-3, 1.5e-3, 2e-3)] {
        assert_both_sides_loaded(&check_cycle(Dof::Twist, n, n, &spins, false));
    }
}

#[test]
fn with_history_reset_bending_about_a_coordinate_axis_is_the_reference_rule_per_component() {
    let n = v3([1.0, 0.0, 0.0]);
    for axis in [[0.0, 0.0, 1.0], [0.0, -1.0, 0.0]] {
        for spins in [cycle(1e-3, 0.5e-3, 1.5e-3), cycle(1e-3, 1.5e-3, 2e-3)] {
            let visited = check_cycle(Dof::Bend, n, v3(axis), &spins, true);
            // Each zero crossing starts the side entered afresh.
            assert!(visited.contains(&(false, Branch::Virgin)));
        }
    }
}

#[test]
fn with_history_reset_twisting_about_a_coordinate_axis_is_the_reference_rule() {
    for axis in [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0]] {
        let n = v3(axis);
        for spins in [cycle(1e-3, 0.5e-3, 1.5e-3), cycle(1e-3, 1.5e-3, 2e-3)] {
            check_cycle(Dof::Twist, n, n, &spins, true);
        }
    }
}

#[test]
fn a_reversal_through_zero_loads_the_other_side_on_its_virgin_line() {
    // What distinguishes the signed law from a loop on |theta| with one
    // maximum: just past zero on the other side, the torque is the virgin
    // `k theta`, not the unloading line of the first side's peak.
    let (n, across) = oblique();
    for dof in [Dof::Twist, Dof::Bend] {
        let m = only(dof, false);
        let p = m.params;
        let axis = if dof == Dof::Twist { n } else { across };
        let (k, moment) = match dof {
            Dof::Twist => (p.k_tn, section(p.lambda, RADIUS, RADIUS).polar),
            Dof::Bend => (p.k_tt, section(p.lambda, RADIUS, RADIUS).inertia),
        };
        let mut state = BondState::created(2.0 * RADIUS);
        let mut out = BondOutput::default();
        // Up to 1e-3, then back to -0.2e-3.
        let spins = cycle(1e-3, 0.2e-3, 0.0);
        for &w in &spins[..2200] {
            let kin = PairKinematics {
                x_i: (n * 2.0 * RADIUS).into(),
                w_i: (axis * w).into(),
                ..pair_at(0.0)
            };
            out = step(&m, &kin, DT, &mut state);
        }
        let theta = -0.2e-3;
        let virgin = -k * theta * moment;
        let along = v3(out.torque_i).dot(&axis);
        assert!(
            (along / virgin - 1.0).abs() < 1e-9,
            "{dof:?}: {along} vs virgin {virgin}"
        );
    }
}

/// Spins that wander in 3D and reverse, for the invariance tests.
fn wandering_spins(count: usize) -> Vec<([f64; 3], [f64; 3])> {
    (0..count)
        .map(|k| {
            let t = k as f64 * DT;
            let w_i = [
                300.0 * (2.0e3 * t).cos(),
                200.0 * (3.1e3 * t + 0.3).cos(),
                250.0 * (1.3e3 * t).sin() * (0.7e3 * t).cos(),
            ];
            let w_j = [-80.0 * (2.7e3 * t).cos(), 120.0 * (1.9e3 * t).sin(), 60.0];
            (w_i, w_j)
        })
        .collect()
}

fn moving_pair(k: usize, w: ([f64; 3], [f64; 3])) -> PairKinematics {
    let t = k as f64 * DT;
    let r0 = 2.0 * RADIUS;
    PairKinematics {
        x_i: [
            r0 * (1.0 + 1e-4 * (5e3 * t).sin()),
            1e-5 * (2e3 * t).sin(),
            0.5e-5 * t * 1e3,
        ],
        v_i: [0.5 * (5e3 * t).cos(), 0.02 * (2e3 * t).cos(), 5e-3],
        w_i: w.0,
        w_j: w.1,
        radius_i: RADIUS,
        radius_j: 0.8 * RADIUS,
        ..PairKinematics::default()
    }
}

fn hysteretic(history_reset: bool, damped: bool) -> BondModel {
    model(BondParams {
        history_reset: history_reset as i32,
        damping: damped as i32,
        eta_fn: 0.2,
        eta_ft: 0.2,
        eta_tn: 0.2,
        eta_tt: 0.2,
        ..params()
    })
}

#[test]
fn rotating_a_scene_with_a_three_dimensional_history_rotates_every_load() {
    let q = rotation([0.3, -0.7, 0.4], 1.234);
    let spins = wandering_spins(4000);
    for damped in [false, true] {
        let m = hysteretic(false, damped);
        let (mut a, mut b) = (bond_at(2.0 * RADIUS), bond_at(2.0 * RADIUS));
        let mut opposite_seen = false;
        for (k, &w) in spins.iter().enumerate() {
            let kin = moving_pair(k, w);
            let x = step(&m, &kin, DT, &mut a);
            let y = step(&m, &rotate_kinematics(&q, &kin), DT, &mut b);
            let scale = norm(x.torque_i) + norm(x.torque_j) + 1e-300;
            assert!(
                close3(rotate(&q, x.torque_i), y.torque_i, 1e-9, scale),
                "step {k}"
            );
            assert!(
                close3(rotate(&q, x.torque_j), y.torque_j, 1e-9, scale),
                "step {k}"
            );
            assert!(close3(
                rotate(&q, x.force_i),
                y.force_i,
                1e-9,
                norm(x.force_i) + 1e-300
            ));
            let r = rotate_bond_state(&q, &a);
            assert!(close3(
                r.bend_history,
                b.bend_history,
                1e-9,
                norm(a.bend_history) + 1e-300
            ));
            assert!((a.twist_max - b.twist_max).abs() <= 1e-9 * a.twist_max.abs() + 1e-300);
            assert!((a.twist_min - b.twist_min).abs() <= 1e-9 * a.twist_min.abs() + 1e-300);
            assert!((a.bend_opposite - b.bend_opposite).abs() <= 1e-9 * a.bend_opposite + 1e-300);
            opposite_seen |= a.bend_opposite > 0.0 && a.twist_min < 0.0 && a.twist_max > 0.0;
        }
        // The history is non-trivial: both sides of both laws were loaded.
        assert!(opposite_seen);
    }
}

#[test]
fn swapping_i_and_j_mid_history_mirrors_every_load_through_the_flip_table() {
    let spins = wandering_spins(3000);
    for reset in [false, true] {
        let m = hysteretic(reset, true);
        let mut from_i = bond_at(2.0 * RADIUS);
        for (k, &w) in spins.iter().enumerate() {
            let kin = moving_pair(k, w);
            let mut from_j = from_i;
            swap_state(&BOND_SLOTS, BondState::as_slots_mut(&mut from_j));
            let a = step(&m, &kin, DT, &mut from_i);
            let b = step(&m, &kin.swapped(), DT, &mut from_j);
            let ts = norm(a.torque_i) + norm(a.torque_j) + 1e-300;
            assert!(close3(
                b.force_i,
                (-v3(a.force_i)).into(),
                1e-12,
                norm(a.force_i) + 1e-300
            ));
            assert!(close3(b.torque_i, a.torque_j, 1e-12, ts), "step {k}");
            assert!(close3(b.torque_j, a.torque_i, 1e-12, ts), "step {k}");
            swap_state(&BOND_SLOTS, BondState::as_slots_mut(&mut from_j));
            for (x, y) in from_i.as_slots().iter().zip(from_j.as_slots()) {
                assert!(
                    (x - y).abs() <= 1e-12 * (x.abs() + y.abs()) + 1e-300,
                    "step {k}: {x} vs {y}"
                );
            }
        }
    }
}

/// Work done on the bond by the spins of a closed cycle of the angle:
/// `-sum T_i . d theta` with the torque at the middle of each step
/// (trapezoid: exact for a piecewise-linear law between branch switches).
fn cycle_work(m: &BondModel, dof: Dof, path: &[[f64; 3]], n: Vec3) -> (f64, f64) {
    let mut state = bond_at(2.0 * RADIUS);
    let (mut work, mut scale) = (0.0, 0.0);
    let mut previous = Vec3::zeros();
    for w in path {
        let kin = PairKinematics {
            x_i: (n * 2.0 * RADIUS).into(),
            w_i: *w,
            ..pair_at(0.0)
        };
        let t = v3(step(m, &kin, DT, &mut state).torque_i);
        let (along, across, _) = granbond::bond::twist_bend::split_relative_spin(v3(*w), n);
        let d_theta = if dof == Dof::Twist { along } else { across } * DT;
        work -= (t + previous).dot(&d_theta) * 0.5;
        scale += t.norm() * d_theta.norm();
        previous = t;
    }
    (work, scale)
}

#[test]
fn a_closed_cycle_of_the_angle_never_creates_energy() {
    let (n, across) = oblique();
    let other = n.cross(&across);
    for reset in [false, true] {
        for dof in [Dof::Twist, Dof::Bend] {
            let m = only(dof, reset);
            // Planar cycles, each ending where it started, in both orders.
            for (a, b) in [(1e-3, 0.5e-3), (1e-3, 1.5e-3), (0.3e-3, 2e-3)] {
                let axis = if dof == Dof::Twist { n } else { across };
                let mut path: Vec<[f64; 3]> = Vec::new();
                let steps = |x: f64| (x / (SPIN * DT)).round() as usize;
                path.extend(vec![<[f64; 3]>::from(axis * SPIN); steps(a)]);
                path.extend(vec![<[f64; 3]>::from(axis * -SPIN); steps(a + b)]);
                path.extend(vec![<[f64; 3]>::from(axis * SPIN); steps(b)]);
                let (work, scale) = cycle_work(&m, dof, &path, n);
                assert!(
                    work >= -1e-12 * scale,
                    "{dof:?} reset {reset}: work {work} (scale {scale})"
                );
                assert!(
                    work > 1e-3 * scale,
                    "the hysteretic loop dissipates: {work} of {scale}"
                );
            }
            if dof == Dof::Bend {
                // A closed square in the tangent plane (a non-planar bend).
                let mut path: Vec<[f64; 3]> = Vec::new();
                for (dir, s) in [(across, 1.0), (other, 1.0), (across, -1.0), (other, -1.0)] {
                    path.extend(vec![<[f64; 3]>::from(dir * (s * SPIN)); 1000]);
                }
                path.extend(path.clone());
                let (work, scale) = cycle_work(&m, dof, &path, n);
                assert!(
                    work >= -1e-12 * scale,
                    "square, reset {reset}: work {work} (scale {scale})"
                );
            }
        }
    }
}

#[test]
fn an_elastic_torque_law_stores_and_returns_the_work_of_a_closed_cycle() {
    // The control for the test above: with ku = k, kc = 0 the cycle's work
    // vanishes (to round-off), so a positive figure there is hysteresis,
    // not the quadrature.
    let (n, across) = oblique();
    for dof in [Dof::Twist, Dof::Bend] {
        let m = model(BondParams {
            tension: 0,
            compression: 0,
            shear: 0,
            twist: (dof == Dof::Twist) as i32,
            bend: (dof == Dof::Bend) as i32,
            ..elastic_params()
        });
        let axis = if dof == Dof::Twist { n } else { across };
        let mut path = vec![<[f64; 3]>::from(axis * SPIN); 1000];
        path.extend(vec![<[f64; 3]>::from(axis * -SPIN); 2500]);
        path.extend(vec![<[f64; 3]>::from(axis * SPIN); 1500]);
        let (work, scale) = cycle_work(&m, dof, &path, n);
        assert!(work.abs() <= 1e-9 * scale, "{dof:?}: {work} of {scale}");
    }
}
