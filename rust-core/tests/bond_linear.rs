//! LIGGGHTS-INL's linear bond (`linear`, LIGGGHTS `cohesion bond`): its
//! springs against their closed forms, its breakage thresholds, its
//! damping and dissipation, the balance and frame of its loads, its energy
//! and its parameter names.

use granbond_test_support as common;

use common::*;
use granbond::bond::section::section;
use granbond::bond::{
    liggghts_name, BondModel, BondOutput, BondParams, BondState, BondStatus, BreakMode, PARAMETERS,
};
use granbond::kinematics::PairKinematics;

const DT: f64 = 1e-7;
const K_N: f64 = 1e12;
const K_T: f64 = 4e11;

/// Linear bond, every law on, damping off, no breakage.
fn linear() -> BondParams {
    BondParams {
        linear: 1,
        lambda: 0.8,
        k_n: K_N,
        k_t: K_T,
        damping: 0,
        create_distance: 2.5 * RADIUS,
        ..BondParams::default()
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = norm(a);
    a.map(|c| c / n)
}

/// Two spheres of radius RADIUS, `i` at `r` along `axis` from `j` (at the
/// origin).
fn pair_along(axis: [f64; 3], r: f64) -> PairKinematics {
    let a = unit(axis);
    PairKinematics {
        x_i: a.map(|c| c * r),
        ..pair_at(r)
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[test]
fn linear_normal_force_is_k_n_area_times_the_compression_on_both_sides() {
    let p = linear();
    let m = model(p);
    let area = section(p.lambda, RADIUS, RADIUS).area;
    let r0 = 2.0 * RADIUS;
    for d in [1e-6, -1e-6, 3e-8, -2e-7] {
        let mut s = bond_at(r0);
        let out = step(&m, &pair_at(r0 - d), DT, &mut s);
        let expected = K_N * area * (r0 - (r0 - d));
        assert!(
            close(out.force_i[0], expected, 1e-12),
            "d {d}: {} against {expected}",
            out.force_i[0]
        );
        assert_eq!(out.normal_force, out.force_i[0]);
    }
    // no force within 1e-15 m of the rest length, nor on a side switched off
    let mut s = bond_at(r0);
    assert_eq!(step(&m, &pair_at(r0 + 5e-16), DT, &mut s).force_i, [0.0; 3]);
    let tension_off = model(BondParams { tension: 0, ..p });
    let mut s = bond_at(r0);
    assert_eq!(
        step(&tension_off, &pair_at(r0 + 1e-7), DT, &mut s).force_i,
        [0.0; 3]
    );
    let mut s = bond_at(r0);
    assert!(step(&tension_off, &pair_at(r0 - 1e-7), DT, &mut s).force_i[0] > 0.0);
}

#[test]
fn linear_shear_force_builds_up_as_k_t_area_times_the_slip() {
    let p = BondParams {
        twist: 0,
        bend: 0,
        ..linear()
    };
    let m = model(p);
    let area = section(p.lambda, RADIUS, RADIUS).area;
    let r0 = 2.0 * RADIUS;
    let v = 0.02;
    let k = PairKinematics {
        v_i: [0.0, v, 0.0],
        ..pair_at(r0)
    };
    let mut s = bond_at(r0);
    let steps = 50;
    let mut out = BondOutput::default();
    for _ in 0..steps {
        out = step(&m, &k, DT, &mut s);
    }
    let expected = -K_T * area * v * DT * steps as f64;
    assert!(
        close(out.force_i[1], expected, 1e-12),
        "{} against {expected}",
        out.force_i[1]
    );
    // its torque: the moment about each centre of the force at the contact
    // point, r R_i / (R_i + R_j) from it toward the other sphere
    let arm = 0.5 * r0;
    assert!(close(out.torque_i[2], -arm * expected, 1e-12));
    assert!(close(out.torque_j[2], -arm * expected, 1e-12));
}

#[test]
fn linear_twisting_and_bending_torques_build_up_as_k_t_j_and_k_n_i() {
    let p = BondParams { shear: 0, ..linear() };
    let m = model(p);
    let sec = section(p.lambda, RADIUS, RADIUS);
    let r0 = 2.0 * RADIUS;
    let w = 3.0;
    let steps = 40;
    let twist = PairKinematics {
        w_i: [w, 0.0, 0.0],
        ..pair_at(r0)
    };
    let bend = PairKinematics {
        w_i: [0.0, 0.0, w],
        ..pair_at(r0)
    };
    for (k, c, stiffness) in [(twist, 0, K_T * sec.polar), (bend, 2, K_N * sec.inertia)] {
        let mut s = bond_at(r0);
        let mut out = BondOutput::default();
        for _ in 0..steps {
            out = step(&m, &k, DT, &mut s);
        }
        let expected = -stiffness * w * DT * steps as f64;
        assert!(
            close(out.torque_i[c], expected, 1e-12),
            "{} against {expected}",
            out.torque_i[c]
        );
        assert!(close(out.torque_j[c], -expected, 1e-12));
    }
    // without a relative spin across the axis the bending torque is kept,
    // but not applied (INL's code)
    let mut s = bond_at(r0);
    for _ in 0..steps {
        step(&m, &bend, DT, &mut s);
    }
    let out = step(&m, &pair_at(r0), DT, &mut s);
    assert_eq!(out.torque_i, [0.0; 3]);
    assert!(norm(s.bend_angle) > 0.0);
}

#[test]
fn linear_bond_breaks_by_distance_just_beyond_max_distance() {
    let r0 = 2.0 * RADIUS;
    let max = r0 * 1.01;
    let m = model(BondParams {
        max_distance: max,
        ..linear()
    });
    let mut s = bond_at(r0);
    let out = step(&m, &pair_at(max), DT, &mut s);
    assert_eq!(s.status(), BondStatus::Intact, "at max_distance it holds");
    assert!(out.force_i[0] < 0.0);
    let out = step(&m, &pair_at(max * (1.0 + 1e-12)), DT, &mut s);
    assert_eq!(s.status(), BondStatus::Broken);
    assert_eq!(out.break_mode, BreakMode::Distance as i32);
    assert_eq!(out.force_i, [0.0; 3], "a bond that breaks exerts nothing");
}

#[test]
fn linear_bond_breaks_by_stress_strictly_above_its_strengths() {
    let r0 = 2.0 * RADIUS;
    let d = 1e-7;
    // sigma = k_n d for a pure stretch or squeeze
    let sigma = K_N * d;
    let strong = 1.0 + 1e-9;
    let weak = 1.0 - 1e-9;
    let stress = |max_sigma: f64, ratio: Option<f64>| {
        model(BondParams {
            stress_break: 1,
            max_sigma,
            max_tau: f64::INFINITY,
            use_ratio: ratio.is_some() as i32,
            tension_compression_ratio: ratio.unwrap_or(1.0),
            ..linear()
        })
    };
    for (distance, mode) in [(r0 + d, BreakMode::Tension), (r0 - d, BreakMode::Compression)] {
        let mut s = bond_at(r0);
        step(&stress(sigma * strong, None), &pair_at(distance), DT, &mut s);
        assert_eq!(s.status(), BondStatus::Intact);
        let mut s = bond_at(r0);
        let out = step(&stress(sigma * weak, None), &pair_at(distance), DT, &mut s);
        assert_eq!(s.status(), BondStatus::Broken);
        assert_eq!(out.break_mode, mode as i32);
    }
    // the ratio scales the strength while stretched only
    let mut s = bond_at(r0);
    step(&stress(sigma * weak, Some(2.0)), &pair_at(r0 + d), DT, &mut s);
    assert_eq!(s.status(), BondStatus::Intact);
    let mut s = bond_at(r0);
    step(&stress(sigma * weak, Some(2.0)), &pair_at(r0 - d), DT, &mut s);
    assert_eq!(s.status(), BondStatus::Broken);
    // shear: tau = |F_t| / A after one step of slip
    let p = BondParams {
        stress_break: 1,
        max_sigma: f64::INFINITY,
        twist: 0,
        bend: 0,
        ..linear()
    };
    let v = 0.05;
    let tau = K_T * v * DT;
    let k = PairKinematics {
        v_i: [0.0, 0.0, v],
        ..pair_at(r0)
    };
    for (max_tau, broken) in [(tau * strong, false), (tau * weak, true)] {
        let m = model(BondParams { max_tau, ..p });
        let mut s = bond_at(r0);
        let out = step(&m, &k, DT, &mut s);
        assert_eq!(
            s.status() == BondStatus::Broken,
            broken,
            "max_tau {max_tau} against tau {tau}"
        );
        if broken {
            assert_eq!(out.break_mode, BreakMode::Shear as i32);
        }
    }
    // Drucker-Prager: compression adds sigma tan(phi) to the shear strength
    let squeeze = PairKinematics {
        v_i: [0.0, 0.0, v],
        ..pair_at(r0 - d)
    };
    let dp = model(BondParams {
        max_tau: tau * weak,
        drucker_prager: 1,
        friction_angle: 45.0,
        ..p
    });
    let mut s = bond_at(r0);
    step(&dp, &squeeze, DT, &mut s);
    assert_eq!(
        s.status(),
        BondStatus::Intact,
        "the squeeze strengthens it by {sigma}"
    );
}

#[test]
fn linear_damping_does_no_positive_work_in_any_mode() {
    let mut rng = Numbers(7);
    let eta = 0.3;
    let damped = |p: BondParams| {
        model(BondParams {
            damping: 1,
            eta_fn: eta,
            eta_ft: eta,
            eta_tn: eta,
            eta_tt: eta,
            ..p
        })
    };
    let r0 = 2.0 * RADIUS;
    for trial in 0..200 {
        let axis = unit(rng.vec(1.0));
        let across = {
            let v = rng.vec(1.0);
            let along = dot(v, axis);
            unit([
                v[0] - along * axis[0],
                v[1] - along * axis[1],
                v[2] - along * axis[2],
            ])
        };
        let r = r0 * (1.0 + 0.01 * rng.uniform());
        let mode = trial % 4;
        let p = match mode {
            0 => linear(),
            1 => BondParams {
                twist: 0,
                bend: 0,
                ..linear()
            },
            _ => BondParams { shear: 0, ..linear() },
        };
        let speed = 0.1 * rng.uniform();
        let mut k = pair_along(axis, r);
        // one mode's motion alone: along the axis, across it, spin about it,
        // spin across it
        let rate = match mode {
            0 => {
                k.v_i = axis.map(|c| c * speed);
                k.v_i
            }
            1 => {
                k.v_i = across.map(|c| c * speed);
                k.v_i
            }
            2 => {
                k.w_i = axis.map(|c| c * speed * 1e3);
                k.w_i
            }
            _ => {
                k.w_i = across.map(|c| c * speed * 1e3);
                k.w_i
            }
        };
        let mut state = bond_at(r0);
        // a history to damp
        for _ in 0..3 {
            step(&model(p), &k, DT, &mut state);
        }
        let mut plain = state;
        let undamped = step(&model(p), &k, DT, &mut plain);
        let mut with = state;
        let out = step(&damped(p), &k, DT, &mut with);
        let (a, b) = if mode < 2 {
            (out.force_i, undamped.force_i)
        } else {
            (out.torque_i, undamped.torque_i)
        };
        let power = dot([a[0] - b[0], a[1] - b[1], a[2] - b[2]], rate);
        let scale = norm(b) * norm(rate);
        assert!(
            power <= 1e-12 * scale,
            "trial {trial}, mode {mode}: the damping's power {power} (scale {scale})"
        );
        if scale > 0.0 {
            assert!(power < 0.0, "trial {trial}: damping on but no work taken");
        }
    }
}

/// Random kinematics around a bond of rest length 2 R: positions, speeds
/// and spins of every direction.
fn random_pair(rng: &mut Numbers) -> PairKinematics {
    let axis = unit(rng.vec(1.0));
    let mut k = pair_along(axis, 2.0 * RADIUS * (1.0 + 0.005 * rng.uniform()));
    k.x_j = rng.vec(RADIUS);
    k.x_i = [k.x_i[0] + k.x_j[0], k.x_i[1] + k.x_j[1], k.x_i[2] + k.x_j[2]];
    k.v_i = rng.vec(0.05);
    k.v_j = rng.vec(0.05);
    k.w_i = rng.vec(50.0);
    k.w_j = rng.vec(50.0);
    k
}

#[test]
fn linear_loads_balance_forces_and_moments_without_damping() {
    let m = model(linear());
    let mut rng = Numbers(11);
    for trial in 0..100 {
        let k = random_pair(&mut rng);
        let mut s = bond_at(2.0 * RADIUS);
        let mut out = BondOutput::default();
        for _ in 0..20 {
            out = step(&m, &k, DT, &mut s);
        }
        let moment = net_moment(&k, &out).norm();
        let scale = norm(out.force_i) * 2.0 * RADIUS + norm(out.torque_i) + norm(out.torque_j);
        assert!(
            moment <= 1e-12 * scale,
            "trial {trial}: net moment {moment} of {scale}"
        );
    }
}

#[test]
fn linear_loads_turn_with_the_frame_without_damping() {
    let m = model(linear());
    let mut rng = Numbers(5);
    for trial in 0..50 {
        let k = random_pair(&mut rng);
        let q = rotation(rng.vec(1.0), 3.0 * rng.uniform());
        let (mut s, mut sq) = (bond_at(2.0 * RADIUS), bond_at(2.0 * RADIUS));
        let kq = rotate_kinematics(&q, &k);
        let (mut out, mut outq) = (BondOutput::default(), BondOutput::default());
        for _ in 0..20 {
            out = step(&m, &k, DT, &mut s);
            outq = step(&m, &kq, DT, &mut sq);
        }
        let scale = norm(out.force_i) + norm(out.torque_i);
        assert!(
            close3(rotate(&q, out.force_i), outq.force_i, 1e-10, scale),
            "trial {trial}: force"
        );
        assert!(
            close3(rotate(&q, out.torque_i), outq.torque_i, 1e-10, scale),
            "trial {trial}: torque i"
        );
        assert!(
            close3(rotate(&q, out.torque_j), outq.torque_j, 1e-10, scale),
            "trial {trial}: torque j"
        );
        let sr = rotate_bond_state(&q, &s);
        assert!(close3(sr.shear_force, sq.shear_force, 1e-10, norm(s.shear_force)));
    }
}

#[test]
fn linear_dissipation_relaxes_the_rest_length_and_the_loads_by_dt_over_its_time() {
    let time = 10.0 * DT;
    let p = BondParams {
        dissipation: 1,
        dissipation_fn: time,
        dissipation_ft: time,
        dissipation_tn: time,
        dissipation_tt: time,
        ..linear()
    };
    let r0 = 2.0 * RADIUS;
    let d = 1e-7;
    let m = model(p);
    let mut s = bond_at(r0);
    step(&m, &pair_at(r0 - d), DT, &mut s);
    assert!(close(s.r0(), r0 - 0.1 * d, 1e-12), "r0 {} after one step", s.r0());
    // a shear force and torques at rest: scaled by 1 - dt/T each step
    let mut s = BondState {
        shear_force: [0.0, 1.0, 0.0],
        twist_angle: [1e-3, 0.0, 0.0],
        ..bond_at(r0)
    };
    step(&m, &pair_at(r0), DT, &mut s);
    assert!(close(s.shear_force[1], 0.9, 1e-12));
    assert!(close(s.twist_angle[0], 0.9e-3, 1e-12));
    // without the switch nothing relaxes
    let mut s = bond_at(r0);
    step(
        &model(BondParams { dissipation: 0, ..p }),
        &pair_at(r0 - d),
        DT,
        &mut s,
    );
    assert_eq!(s.r0(), r0);
}

#[test]
fn linear_stored_energy_is_the_springs_and_its_loads_are_its_gradient() {
    let p = linear();
    let m = model(p);
    let sec = section(p.lambda, RADIUS, RADIUS);
    let r0 = 2.0 * RADIUS;
    let d = -2e-7;
    let mut s = bond_at(r0);
    let out = step(&m, &pair_at(r0 - d), DT, &mut s);
    let e = m.stored_energy(&s, [1.0, 0.0, 0.0], d, RADIUS, RADIUS);
    assert!(close(e.normal, 0.5 * K_N * sec.area * d * d, 1e-12));
    // dE/dr = -dE/dd = force on i along +x (r grows with x_i)
    let h = 1e-10;
    let at = |dd: f64| m.stored_energy(&s, [1.0, 0.0, 0.0], dd, RADIUS, RADIUS).normal;
    let gradient = (at(d + h) - at(d - h)) / (2.0 * h);
    assert!(
        close(gradient, out.force_i[0], 1e-6),
        "{gradient} against {}",
        out.force_i[0]
    );
    let s = BondState {
        shear_force: [0.0, 2.0, 0.0],
        twist_angle: [1e-3, 0.0, 0.0],
        bend_angle: [0.0, 0.0, 2e-3],
        ..bond_at(r0)
    };
    let e = m.stored_energy(&s, [1.0, 0.0, 0.0], 0.0, RADIUS, RADIUS);
    assert!(close(e.shear, 4.0 / (2.0 * K_T * sec.area), 1e-12));
    assert!(close(e.twist, 0.5 * K_T * sec.polar * 1e-6, 1e-12));
    assert!(close(e.bend, 0.5 * K_N * sec.inertia * 4e-6, 1e-12));
}

#[test]
fn linear_setup_step_moves_nothing_and_gives_the_next_steps_loads() {
    let m = model(linear());
    let mut rng = Numbers(3);
    let k = random_pair(&mut rng);
    let mut s = bond_at(2.0 * RADIUS);
    for _ in 0..5 {
        step(&m, &k, DT, &mut s);
    }
    let before = s;
    let mut trial = BondOutput::default();
    assert!(m.setup_step(&k, DT, &mut s, &mut trial, false).unwrap());
    assert_eq!(s, before);
    let next = step(&m, &k, DT, &mut s);
    assert_eq!(trial.force_i, next.force_i);
    assert_eq!(trial.torque_i, next.torque_i);
}

#[test]
fn linear_bond_reads_inl_cohesion_bond_names_and_bond_nonlinear_not_its_rows() {
    let id = |k: &str| PARAMETERS.iter().position(|r| r.name == k).unwrap();
    for (keyword, name) in [
        ("lambda", "radiusMultiplierBond"),
        ("k_n", "normalBondStiffnessPerUnitArea"),
        ("k_t", "tangentialBondStiffnessPerUnitArea"),
        ("max_distance", "maxDistanceBond"),
        ("max_sigma", "maxSigmaBond"),
        ("max_tau", "maxTauBond"),
        ("create_distance", "createDistanceBond"),
        ("create_step", "tsCreateBond"),
        ("eta_fn", "dampingNormalForceBond"),
        ("damping", "dampingBond"),
        ("create_always", "createBondAlways"),
        ("stress_break", "stressBreak"),
        ("use_ratio", "ratioTensionCompression"),
        ("dissipation", "dissipationBond"),
    ] {
        assert_eq!(liggghts_name(true, id(keyword)), Some(name), "{keyword}");
    }
    for keyword in ["k_fn1", "history_reset", "inl_compatible", "linear"] {
        assert_eq!(liggghts_name(true, id(keyword)), None, "{keyword}");
    }
    for keyword in ["k_n", "k_t", "dissipation", "drucker_prager", "linear"] {
        assert_eq!(liggghts_name(false, id(keyword)), None, "{keyword}");
    }
    assert_eq!(
        liggghts_name(false, id("lambda")),
        Some("radiusMultiplierBondnonlinear")
    );
    let p = linear();
    assert!(p.reads(id("k_n")) && !p.reads(id("k_fn1")));
    assert!(!BondParams::default().reads(id("k_n")));
    // a refusal names the linear bond's parameter as its decks do
    let e = BondModel::new(BondParams {
        lambda: -1.0,
        ..linear()
    })
    .unwrap_err();
    assert!(
        e.message.contains("bond/linear") && e.message.contains("(radiusMultiplierBond)"),
        "{}",
        e.message
    );
}

#[test]
fn linear_shear_force_stays_across_the_axis_as_the_bond_turns() {
    let m = model(BondParams {
        twist: 0,
        bend: 0,
        ..linear()
    });
    let r0 = 2.0 * RADIUS;
    let mut s = bond_at(r0);
    let mut k = pair_at(r0);
    k.v_i = [0.0, 0.03, 0.0];
    for n in 0..200 {
        let angle = 0.002 * n as f64;
        k.x_i = [r0 * angle.cos(), r0 * angle.sin(), 0.0];
        step(&m, &k, DT, &mut s);
        let along = dot(s.shear_force, unit(k.x_i));
        assert!(
            along.abs() <= 1e-12 * norm(s.shear_force),
            "step {n}: {along} along the axis"
        );
    }
}

#[test]
fn a_parameter_of_the_other_bond_law_is_refused_not_ignored() {
    let e = BondModel::new(BondParams {
        k_fn1: 1e9,
        ..linear()
    })
    .unwrap_err();
    assert!(
        e.message.contains("k_fn1") && e.message.contains("bond/linear does not read"),
        "{}",
        e.message
    );
    let e = BondModel::new(BondParams { k_n: 1e9, ..params() }).unwrap_err();
    assert!(
        e.message.contains("k_n") && e.message.contains("bond/nonlinear does not read"),
        "{}",
        e.message
    );
    assert!(BondModel::new(linear()).is_ok() && BondModel::new(params()).is_ok());
}
