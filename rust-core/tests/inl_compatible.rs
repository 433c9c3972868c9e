//! `inl_compatible` (LIGGGHTS `inlCompatible on`) follows LIGGGHTS-INL's
//! code where it differs from the write-up's law: each test states one of
//! the differences with the value INL's equations give.

use granbond_test_support as common;

use common::*;
use granbond::bond::section::section;
use granbond::bond::{BondModel, BondParams, BondState, BondStatus, WallBondState};
use granbond::kinematics::{PairKinematics, SphereKinematics};

const DT: f64 = 1e-8;

fn inl(p: BondParams) -> BondParams {
    BondParams {
        inl_compatible: 1,
        ..p
    }
}

/// Equal but for the round-off of the positions (d = r0 - r).
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
}

/// The normal force of a bond of rest length `2 R` moved to compression `d`
/// (i displaced along x), after the compressions of `path`.
fn normal_after(m: &BondModel, path: &[f64]) -> f64 {
    let r0 = 2.0 * RADIUS;
    let mut state = bond_at(r0);
    let mut force = f64::NAN;
    for &d in path {
        let out = step(m, &pair_at(r0 - d), DT, &mut state);
        force = out.force_i[0];
        assert_eq!(
            out.normal_force, force,
            "at rest, undamped: the force is the normal force"
        );
    }
    force
}

#[test]
fn inl_compression_has_no_section_area_in_any_of_its_branches() {
    let p = params();
    let (k, ku, kc) = (p.k_fn1, p.ku_fn1, p.kc_fn1);
    let m = model(inl(p));
    let default = model(p);
    let area = section(p.lambda, RADIUS, RADIUS).area;
    let dmax = 1e-6;
    let c1 = ((ku - k) / (ku + kc)).powi(2) * dmax;
    let unloading = 0.5 * (c1 + dmax);
    let reverse = 0.5 * c1;
    let cases = [
        (vec![dmax], k * dmax.sqrt()),
        (
            vec![dmax, unloading],
            ku * unloading.sqrt() + (k - ku) * dmax.sqrt(),
        ),
        (vec![dmax, reverse], -kc * reverse.sqrt()),
    ];
    for (path, expected) in cases {
        let got = normal_after(&m, &path);
        assert!(
            close(got, expected),
            "{path:?}: {got} against k sqrt(d) = {expected}"
        );
        let seed = normal_after(&default, &path);
        assert!(close(seed, expected * area), "the default law keeps A: {seed}");
    }
    // Tension keeps A in both.
    let stretched = [-1e-7];
    assert!(close(
        normal_after(&m, &stretched),
        normal_after(&default, &stretched)
    ));
    assert!(close(normal_after(&m, &stretched), -p.k_fn2 * area * 1e-7));
}

#[test]
fn inl_history_forgets_the_compression_extreme_once_stretched() {
    let p = params();
    let m = model(inl(p));
    let (dmax, d) = (1e-6, 0.6e-6);
    // Compressed to dmax, stretched, compressed again below dmax: INL is
    // back on the virgin line; the default law unloads from dmax.
    let got = normal_after(&m, &[dmax, -1e-8, d]);
    assert!(close(got, p.k_fn1 * d.sqrt()), "{got}");
    let kept = normal_after(&model(p), &[dmax, -1e-8, d]);
    let area = section(p.lambda, RADIUS, RADIUS).area;
    let unloading = (p.ku_fn1 * d.sqrt() + (p.k_fn1 - p.ku_fn1) * dmax.sqrt()) * area;
    assert!(close(kept, unloading), "{kept}");
}

#[test]
fn inl_has_no_normal_force_within_1e_15_m_of_the_rest_length() {
    let m = model(inl(params()));
    let r0 = 2.0 * RADIUS;
    let mut state = bond_at(r0);
    let out = step(&m, &pair_at(r0 - 4e-16), DT, &mut state);
    assert_eq!(out.force_i, [0.0; 3]);
    let out = step(&m, &pair_at(r0 - 4e-15), DT, &mut state);
    assert!(out.force_i[0] > 0.0);
}

/// A bond along x with a shear spring force not along the slip: INL damps
/// each Cartesian component by the sign of the slip's component.
#[test]
fn inl_damps_the_shear_force_per_cartesian_component() {
    let p = inl(BondParams {
        damping: 1,
        eta_ft: 0.3,
        ..params()
    });
    let m = model(p);
    let r0 = 2.0 * RADIUS;
    let mut state = bond_at(r0);
    state.shear_force = [0.0, 2.0, -1.0];
    let (vy, vz) = (1e-3, 2e-3);
    let kin = PairKinematics {
        v_i: [0.0, vy, vz],
        ..pair_at(r0)
    };
    let area = section(p.lambda, RADIUS, RADIUS).area;
    let spring = [0.0, 2.0 - p.k_ft * area * DT * vy, -1.0 - p.k_ft * area * DT * vz];
    let out = step(&m, &kin, DT, &mut state);
    // Both slip components are positive: each component loses 0.3 of its size.
    let expected = [
        0.0,
        spring[1] - 0.3 * spring[1].abs(),
        spring[2] - 0.3 * spring[2].abs(),
    ];
    assert!(
        close3(out.force_i, expected, 1e-12, 2.0),
        "{:?} against {expected:?}",
        out.force_i
    );
    // The write-up's damping acts along the slip: it would add to the z force.
    let along = model(BondParams {
        inl_compatible: 0,
        ..p
    });
    let mut seed = bond_at(r0);
    seed.shear_force = [0.0, 2.0, -1.0];
    let out = step(&along, &kin, DT, &mut seed);
    assert!(out.force_i[2] < spring[2], "{:?}", out.force_i);
}

/// With smooth damping INL scales each component's sign down below
/// `1e-5 min(R_i, R_j) / dt`.
#[test]
fn inl_smooth_damping_scales_below_its_minimum_velocity() {
    let p = inl(BondParams {
        damping: 1,
        damping_smooth: 1,
        eta_fn: 0.4,
        ..params()
    });
    let m = model(p);
    let r0 = 2.0 * RADIUS;
    let d = 1e-7;
    let min_rate = 1e-5 * RADIUS / DT;
    let vn = -0.25 * min_rate;
    let mut state = bond_at(r0);
    // i moves towards j: (v_i - v_j) . n < 0.
    let kin = PairKinematics {
        v_i: [vn, 0.0, 0.0],
        ..pair_at(r0 - d)
    };
    let out = step(&m, &kin, DT, &mut state);
    let f = p.k_fn1 * d.sqrt();
    let expected = f - 0.4 * f * (vn / min_rate);
    assert!(
        close(out.force_i[0], expected),
        "{} against {expected}",
        out.force_i[0]
    );
}

/// Twisting about x, then back through zero: INL's loop on the x component
/// unloads from its extreme, reverses, and on the other side loads
/// the virgin line with that side's history zeroed.
#[test]
fn inl_twists_on_each_cartesian_component_with_its_own_loop() {
    let p = params();
    let m = model(inl(p));
    let r0 = 2.0 * RADIUS;
    let polar = section(p.lambda, RADIUS, RADIUS).polar;
    let mut state = bond_at(r0);
    let rate = 1.0;
    let turn = |state: &mut BondState, w: f64, steps: usize| {
        let kin = PairKinematics {
            w_i: [w, 0.0, 0.0],
            ..pair_at(r0)
        };
        let mut out = Default::default();
        for _ in 0..steps {
            m.step(&kin, DT, state, &mut out).unwrap();
        }
        out
    };
    let out = turn(&mut state, rate, 100);
    let max = state.twist_angle[0];
    assert!(close(out.torque_i[0], -p.k_tn * polar * max));
    let ratio = (p.ku_tn - p.k_tn) / (p.ku_tn + p.kc_tn);
    let out = turn(&mut state, -rate, 30);
    let theta = state.twist_angle[0];
    assert!(theta > ratio * max);
    let unloading = -p.ku_tn * polar * theta + (p.ku_tn - p.k_tn) * polar * max;
    assert!(
        close(out.torque_i[0], unloading),
        "{} {unloading}",
        out.torque_i[0]
    );
    let out = turn(&mut state, -rate, 50);
    let theta = state.twist_angle[0];
    assert!(theta > 0.0 && theta < ratio * max);
    assert!(close(out.torque_i[0], p.kc_tn * polar * theta));
    let out = turn(&mut state, -rate, 40);
    let theta = state.twist_angle[0];
    assert!(theta < 0.0);
    assert!(
        close(out.torque_i[0], -p.k_tn * polar * theta),
        "virgin on the negative side"
    );
    // Back to the positive side: its maximum was forgotten, virgin again.
    let out = turn(&mut state, rate, 60);
    let theta = state.twist_angle[0];
    assert!(theta > 0.0 && theta < max);
    assert!(close(out.torque_i[0], -p.k_tn * polar * theta));
}

#[test]
fn inl_wall_bond_runs_to_the_contact_point() {
    let p = params();
    let m = model(inl(BondParams {
        create_distance: 2.5 * RADIUS,
        ..p
    }));
    let sphere = |z: f64| SphereKinematics {
        x: [0.0, 0.0, z],
        radius: RADIUS,
        ..SphereKinematics::default()
    };
    let mut state = WallBondState::default();
    assert!(m
        .try_create_wall(&sphere(RADIUS), [0.0; 3], 0, &mut state)
        .unwrap());
    assert_eq!(state.bond.r0(), RADIUS, "the distance to the contact point");
    let d = 1e-7;
    let mut out = Default::default();
    m.step_wall(&sphere(RADIUS - d), [0.0; 3], DT, &mut state, &mut out)
        .unwrap();
    assert!(close(out.force_i[2], p.k_fn1 * d.sqrt()), "{:?}", out.force_i);
    assert!(close(out.delta, d));
}

#[test]
fn inl_keeps_the_contacts_tangential_loads_under_the_bond() {
    assert!(model(inl(params())).keeps_contact_tangential());
    assert!(!model(params()).keeps_contact_tangential());
}

/// A run's setup pass under INL's code applies the loads of a trial step
/// (the next step's, without keeping its angles or shear force), moving
/// only the history extremes, and breaks nothing; the default law applies
/// the latest loads and computes nothing.
#[test]
fn inl_setup_pass_applies_a_trial_step_that_keeps_only_the_extremes() {
    let p = params();
    let m = model(inl(BondParams {
        max_distance: 2.0 * RADIUS * (1.0 + 1e-9),
        ..p
    }));
    let r0 = 2.0 * RADIUS;
    let mut state = bond_at(r0);
    let kin = PairKinematics {
        v_i: [0.0, 1e-3, 0.0],
        w_i: [2.0, 0.0, 0.0],
        ..pair_at(r0 - 1e-7)
    };
    let mut trial = state;
    let mut setup = Default::default();
    assert!(m.setup_step(&kin, DT, &mut trial, &mut setup, false).unwrap());
    let mut stepped = Default::default();
    step_into(&m, &kin, &mut state, &mut stepped);
    assert_eq!(setup.force_i, stepped.force_i, "the loads of the step ahead");
    assert_eq!(setup.torque_i, stepped.torque_i);
    assert_eq!(trial.shear_force, [0.0; 3], "the shear force is not kept");
    assert_eq!(trial.twist_angle, [0.0; 3], "nor the angles");
    assert_eq!(trial.delta_max, state.delta_max, "the extremes are");
    assert_eq!(trial.twist_max, state.twist_max);
    // Stretched beyond max_distance: a force pass breaks, a setup pass not.
    let far = pair_at(r0 * (1.0 + 1e-8));
    let mut out = Default::default();
    assert!(m.setup_step(&far, DT, &mut trial, &mut out, false).unwrap());
    assert_eq!(trial.status(), BondStatus::Intact);
    let mut seed_state = bond_at(r0);
    assert!(!model(p)
        .setup_step(&kin, DT, &mut seed_state, &mut out, false)
        .unwrap());
    assert_eq!(seed_state, bond_at(r0), "the default law computes nothing");
}

fn step_into(
    m: &BondModel,
    kin: &PairKinematics,
    state: &mut BondState,
    out: &mut granbond::bond::BondOutput,
) {
    m.step(kin, DT, state, out).unwrap();
}

/// Under an intact bond of INL's code the contact keeps its tangential and
/// rolling loads and loses its normal force (INL's cohesion model takes the
/// normal model's place only); under the write-up's law the bond replaces
/// every load; under INL's linear bond every load stays.
#[test]
fn inl_bond_leaves_the_contact_its_tangential_and_rolling_loads_only() {
    use granbond::contact::ContactOutput;
    use granbond::under_bond::contact_loads_under_bond;
    let del = [1.2e-3, -0.9e-3, 2.0e-3];
    let rsq: f64 = del.iter().map(|c| c * c).sum();
    let n = del.map(|c| c / rsq.sqrt());
    // a tangential force across n, and the normal force 3 N along it
    let tangential = [0.9, 1.2, 0.0];
    assert!((0..3).map(|k| tangential[k] * n[k]).sum::<f64>().abs() < 1e-12);
    let fn_ = 3.0;
    let given = ContactOutput {
        force_i: [0, 1, 2].map(|k| fn_ * n[k] + tangential[k]),
        torque_i: [1e-3, -2e-3, 5e-4],
        torque_j: [2e-3, 1e-3, -5e-4],
        normal_force: fn_,
        overlap: 1e-6,
        touching: 1,
        ..ContactOutput::default()
    };
    let mut under = given;
    contact_loads_under_bond(&model(inl(params())), del, rsq, &mut under);
    for k in 0..3 {
        assert!(
            (under.force_i[k] - tangential[k]).abs() <= 1e-15 * fn_,
            "INL's code: force {:?}, tangential part {tangential:?}",
            under.force_i
        );
    }
    assert_eq!((under.torque_i, under.torque_j), (given.torque_i, given.torque_j));
    let mut under = given;
    contact_loads_under_bond(&model(params()), del, rsq, &mut under);
    assert_eq!(
        (under.force_i, under.torque_i, under.torque_j),
        ([0.0; 3], [0.0; 3], [0.0; 3])
    );
    let linear = BondParams {
        linear: 1,
        lambda: 0.8,
        k_n: 1e12,
        k_t: 4e11,
        create_distance: 2.5 * RADIUS,
        ..BondParams::default()
    };
    let mut under = given;
    contact_loads_under_bond(&model(linear), del, rsq, &mut under);
    assert_eq!(under, given, "INL's linear bond keeps every load of the contact");
}
