//! Breakage happens exactly once, at the step its criterion is first met;
//! creation follows the distance and step rules.

use granbond_test_support as common;

use common::*;
use granbond::bond::section::section;
use granbond::bond::{BondParams, BondState, BondStatus, BreakMode, WallBondState};
use granbond::kinematics::{PairKinematics, SphereKinematics};

/// Pulls i away from j along x at `speed` from r0 = 2R; returns the step of
/// each break event and the loads after the first.
fn pull(p: BondParams, speed: [f64; 3], steps: usize, dt: f64) -> (Vec<(usize, i32)>, Vec<f64>) {
    let m = model(p);
    let r0 = 2.0 * RADIUS;
    let mut state = bond_at(r0);
    let mut events = Vec::new();
    let mut after = Vec::new();
    for k in 1..=steps {
        let t = k as f64 * dt;
        let kin = PairKinematics {
            x_i: [r0 + speed[0] * t, speed[1] * t, speed[2] * t],
            v_i: speed,
            ..pair_at(r0)
        };
        let out = step(&m, &kin, dt, &mut state);
        if out.break_mode != 0 {
            events.push((k, out.break_mode));
        }
        if !events.is_empty() {
            after.push(norm(out.force_i) + norm(out.torque_i) + norm(out.torque_j));
            assert_eq!(out.status, BondStatus::Broken as i32);
        }
    }
    (events, after)
}

#[test]
fn distance_mode_breaks_once_at_the_first_step_beyond_max_distance() {
    let r0 = 2.0 * RADIUS;
    let (speed, dt) = (1e-3, 1e-6);
    let max_distance = r0 * 1.001; // 2e-6 m of stretch = 2000 steps
    let p = BondParams {
        max_distance,
        ..params()
    };
    let (events, after) = pull(p, [speed, 0.0, 0.0], 4000, dt);
    let expected = (1..)
        .find(|k| r0 + speed * (*k as f64) * dt > max_distance)
        .unwrap();
    assert_eq!(events, vec![(expected, BreakMode::Distance as i32)]);
    assert!(after.iter().all(|&x| x == 0.0), "a broken bond exerts nothing");
}

#[test]
fn stress_mode_breaks_in_tension_when_sigma_reaches_the_limit() {
    let (speed, dt) = (1.0, 1e-9);
    let sec = section(0.5, RADIUS, RADIUS);
    let p = BondParams {
        stress_break: 1,
        max_sigma: 5e6,
        twist: 0,
        bend: 0,
        shear: 0,
        ..params()
    };
    let (events, after) = pull(p, [speed, 0.0, 0.0], 2000, dt);
    // sigma = k_fn2 |delta| on the virgin tension line.
    let expected = (1..)
        .find(|k| p.k_fn2 * speed * (*k as f64) * dt >= p.max_sigma)
        .unwrap();
    assert_eq!(events.len(), 1);
    assert!(
        events[0].0.abs_diff(expected) <= 1,
        "{events:?} vs step {expected}"
    );
    assert_eq!(events[0].1, BreakMode::Tension as i32);
    assert!(after.iter().all(|&x| x == 0.0));
    assert!(sec.area > 0.0);
}

#[test]
fn tension_compression_ratio_scales_the_tensile_strength() {
    let (speed, dt) = (1.0, 1e-9);
    let base = BondParams {
        stress_break: 1,
        max_sigma: 5e6,
        twist: 0,
        bend: 0,
        shear: 0,
        ..params()
    };
    let (plain, _) = pull(base, [speed, 0.0, 0.0], 4000, dt);
    let weaker = BondParams {
        use_ratio: 1,
        tension_compression_ratio: 0.5,
        ..base
    };
    let (half, _) = pull(weaker, [speed, 0.0, 0.0], 4000, dt);
    let ratio = half[0].0 as f64 / plain[0].0 as f64;
    assert!(
        (ratio - 0.5).abs() < 0.01,
        "gamma = 0.5 halves the tensile strength: {ratio}"
    );
}

#[test]
fn stress_mode_breaks_in_shear_when_tau_reaches_the_limit() {
    let (speed, dt) = (1.0, 1e-9);
    let p = BondParams {
        stress_break: 1,
        max_sigma: f64::INFINITY,
        max_tau: 2e6,
        twist: 0,
        bend: 0,
        ..params()
    };
    let (events, _) = pull(p, [0.0, speed, 0.0], 4000, dt);
    // tau = |Ft|/A = k_ft v t (the tiny stretch of the chord is second order).
    let expected = (1..)
        .find(|k| p.k_ft * speed * (*k as f64) * dt >= p.max_tau)
        .unwrap();
    assert_eq!(events.len(), 1);
    assert!(
        events[0].0.abs_diff(expected) <= 1,
        "{events:?} vs step {expected}"
    );
    assert_eq!(events[0].1, BreakMode::Shear as i32);
}

#[test]
fn a_broken_bond_stays_broken_and_silent() {
    let m = model(BondParams {
        max_distance: 2.1 * RADIUS,
        ..params()
    });
    let mut state = bond_at(2.0 * RADIUS);
    let far = pair_at(2.2 * RADIUS);
    assert_eq!(
        step(&m, &far, 1e-7, &mut state).break_mode,
        BreakMode::Distance as i32
    );
    let near = pair_at(2.05 * RADIUS);
    for _ in 0..3 {
        let out = step(&m, &near, 1e-7, &mut state);
        assert_eq!((out.break_mode, out.status), (0, BondStatus::Broken as i32));
        assert_eq!(out.force_i, [0.0; 3]);
    }
}

#[test]
fn creation_respects_distance_and_step() {
    let p = BondParams {
        create_distance: 2.1 * RADIUS,
        create_step: 5,
        ..params()
    };
    let m = model(p);
    let inside = pair_at(2.05 * RADIUS);
    let outside = pair_at(2.1 * RADIUS);
    let mut s = BondState::default();
    assert!(
        !m.try_create(&inside, 4, &mut s).unwrap(),
        "not at the creation step"
    );
    assert!(
        !m.try_create(&outside, 5, &mut s).unwrap(),
        "centre distance must be below create_distance"
    );
    assert!(m.try_create(&inside, 5, &mut s).unwrap());
    assert_eq!(s, BondState::created(2.05 * RADIUS));
    assert!(
        !m.try_create(&inside, 5, &mut s).unwrap(),
        "an intact bond is kept as it is"
    );
    s.mark_broken();
    assert!(
        !m.try_create(&inside, 5, &mut s).unwrap(),
        "a broken bond is not re-created"
    );
}

#[test]
fn continuous_creation_rebonds_broken_pairs_every_step() {
    let m = model(BondParams {
        create_distance: 2.1 * RADIUS,
        create_always: 1,
        ..params()
    });
    let inside = pair_at(2.05 * RADIUS);
    let mut s = BondState::default();
    s.mark_broken();
    assert!(m.try_create(&inside, 123, &mut s).unwrap());
    assert_eq!(s.status(), BondStatus::Intact);
    let mut fresh = BondState::default();
    assert!(m.try_create(&inside, 77, &mut fresh).unwrap());
}

#[test]
fn a_new_bond_starts_without_history_or_load() {
    let m = model(params());
    let kin = pair_at(2.0 * RADIUS);
    let mut s = BondState {
        delta_max: 1.0,
        shear_force: [1.0; 3],
        ..BondState::default()
    };
    assert!(m.try_create(&kin, 0, &mut s).unwrap());
    let out = step(&m, &kin, 1e-7, &mut s);
    assert_eq!(out.force_i, [0.0; 3]);
    assert_eq!(out.torque_i, [0.0; 3]);
}

#[test]
fn a_wall_bond_acts_like_a_bond_to_a_mirror_sphere() {
    let m = model(params());
    let sphere = SphereKinematics {
        x: [0.0, 0.0, RADIUS],
        radius: RADIUS,
        ..SphereKinematics::default()
    };
    let mut wall = WallBondState::default();
    assert!(m.try_create_wall(&sphere, [0.0; 3], 0, &mut wall).unwrap());
    assert_eq!(wall.partner, [0.0, 0.0, -RADIUS]);
    assert_eq!(wall.bond.r0(), 2.0 * RADIUS);
    // Lift the sphere by 1e-7 m: the tension is that of a pair stretched
    // by the same amount, pulling the sphere back to the wall (to the
    // round-off of delta = r0 - r: 1e-16 * r / delta ~ 1e-11).
    let lifted = SphereKinematics {
        x: [0.0, 0.0, RADIUS + 1e-7],
        ..sphere
    };
    let mut out = Default::default();
    m.step_wall(&lifted, [0.0; 3], 1e-7, &mut wall, &mut out).unwrap();
    let mut pair_state = bond_at(2.0 * RADIUS);
    let pair = step(&m, &pair_at(2.0 * RADIUS + 1e-7), 1e-7, &mut pair_state);
    assert!(
        (out.force_i[2] - pair.force_i[0]).abs() <= 1e-9 * pair.force_i[0].abs(),
        "{out:?} vs {pair:?}"
    );
    assert!(out.force_i[2] < 0.0);
    // A moving wall carries the stand-in sphere along.
    m.step_wall(&lifted, [0.5, 0.0, 0.0], 1e-3, &mut wall, &mut out)
        .unwrap();
    assert!((wall.partner[0] - 5e-4).abs() < 1e-15);
}

#[test]
fn neighbour_reach_covers_the_longest_intact_bond() {
    // Distance mode: max_distance, plus 10%.
    let m = model(BondParams {
        max_distance: 3.0 * RADIUS,
        ..params()
    });
    assert!((m.contact_distance_factor(RADIUS) - 1.1 * 1.5).abs() < 1e-12);
    // Stress mode: creation distance plus gamma sigma / k_fn2.
    let p = BondParams {
        stress_break: 1,
        max_sigma: 1e6,
        use_ratio: 1,
        tension_compression_ratio: 0.5,
        ..params()
    };
    let stretch = 0.5 * 1e6 / p.k_fn2;
    let expected = 1.1 * (p.create_distance + stretch) / (2.0 * RADIUS);
    assert!((model(p).contact_distance_factor(RADIUS) - expected).abs() < 1e-12);
    // Unbounded stretch is reported as such.
    assert!(model(BondParams {
        stress_break: 1,
        tension: 0,
        ..p
    })
    .contact_distance_factor(RADIUS)
    .is_infinite());
    assert!(model(params()).contact_distance_factor(RADIUS).is_infinite());
}

#[test]
fn immediate_creation_skips_the_step_rule_but_not_the_others() {
    let m = model(BondParams {
        create_distance: 2.1 * RADIUS,
        create_step: 5,
        ..params()
    });
    let mut s = BondState::default();
    assert!(!m.create_now(&pair_at(2.2 * RADIUS), &mut s).unwrap(), "too far");
    assert!(m.create_now(&pair_at(2.05 * RADIUS), &mut s).unwrap(), "any step");
    assert_eq!(s.r0(), 2.05 * RADIUS);
    s.delta_max = 1e-6;
    assert!(
        !m.create_now(&pair_at(2.0 * RADIUS), &mut s).unwrap(),
        "an intact bond is kept"
    );
    assert_eq!(s.delta_max, 1e-6);
}

#[test]
fn no_bond_forms_beyond_the_creation_reach() {
    // every pair try_create bonds at a step at or after `from` lies closer
    // than creation_reach(from); a reach of 0 means no bond forms at all
    for always in [0, 1] {
        let m = model(BondParams {
            create_distance: 2.1 * RADIUS,
            create_step: 5,
            create_always: always,
            ..params()
        });
        for from in 0..9 {
            let reach = m.creation_reach(from);
            for step in from..12 {
                for status in [BondStatus::Unbonded, BondStatus::Broken] {
                    for r in [1.9, 2.0, 2.05, 2.0999, 2.1, 2.2] {
                        let mut s = BondState::default();
                        if status == BondStatus::Broken {
                            s.mark_broken();
                        }
                        let made = m.try_create(&pair_at(r * RADIUS), step, &mut s).unwrap();
                        assert!(
                            !made || r * RADIUS < reach,
                            "create_always {always}: a bond formed at step {step}, {r} R apart, \
                             beyond the reach {reach} from step {from}"
                        );
                    }
                }
            }
            // and the reach is no wider than needed: at the creation step
            // itself a pair just inside it bonds
            if always == 1 || from <= 5 {
                assert_eq!(reach, 2.1 * RADIUS);
            } else {
                assert_eq!(reach, 0.0);
            }
        }
    }
}
