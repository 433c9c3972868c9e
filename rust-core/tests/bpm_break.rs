//! The BPM mode of breakage (`break bpm`, docs/models/bond-nonlinear.md
//! "Breakage"): LAMMPS `bond_style bpm/rotational`'s summed rule
//! `F_t/F_rc + |F_s|/F_sc + |T_b|/T_bc + |T_t|/T_tc >= 1` on the undamped loads.

use granbond_test_support as common;

use granbond::bond::{BondModel, BondOutput, BondParams, BondStatus, BreakMode};
use granbond::kinematics::PairKinematics;

const R: f64 = common::RADIUS;
const DT: f64 = 1e-7;

/// A bond at rest length `2R`, stretched by `stretch` (negative: compressed)
/// and sheared over one step.
fn loaded(p: BondParams, stretch: f64) -> BondOutput {
    let model = BondModel::new(p).expect("valid parameters");
    let mut state = common::bond_at(2.0 * R);
    let k = PairKinematics {
        v_i: [0.0, 1e-3, 0.0],
        ..common::pair_at(2.0 * R + stretch)
    };
    common::step(&model, &k, DT, &mut state)
}

/// The tensile normal force and the shear force of a step without limits.
fn loads(stretch: f64) -> (f64, f64) {
    let out = loaded(common::elastic_params(), stretch);
    let area = std::f64::consts::PI * (common::elastic_params().lambda * R).powi(2);
    (-out.normal_force, out.tau * area)
}

fn bpm(normal: f64, shear: f64) -> BondParams {
    BondParams {
        bpm_break: 1,
        max_normal_force: normal,
        max_shear_force: shear,
        ..common::elastic_params()
    }
}

#[test]
fn the_summed_rule_breaks_where_the_terms_reach_one() {
    let (ft, fs) = loads(1e-10);
    assert!(ft > 0.0 && fs > 0.0, "stretched and sheared: {ft} {fs}");
    // each term about a half: a sum just above 1 breaks, just below holds
    let broke = loaded(bpm(1.9 * ft, 2.1 * fs), 1e-10);
    assert_eq!(broke.status, BondStatus::Broken as i32);
    assert_eq!(
        broke.break_mode,
        BreakMode::Tension as i32,
        "the normal term is the larger"
    );
    let held = loaded(bpm(2.1 * ft, 2.1 * fs), 1e-10);
    assert_eq!(held.status, BondStatus::Intact as i32);
    // the same sum with the shear term the larger is a shear break
    let sheared = loaded(bpm(2.1 * ft, 1.9 * fs), 1e-10);
    assert_eq!(sheared.break_mode, BreakMode::Shear as i32);
    // neither term alone reaches 1: the stress mode's separate limits hold it
    assert!(ft / (1.9 * ft) < 1.0 && fs / (2.1 * fs) < 1.0);
}

#[test]
fn compression_lowers_the_sum() {
    let (ft, fs) = loads(1e-10);
    let (ft_compressed, _) = loads(-1e-10);
    assert!(ft_compressed < 0.0, "compressed: {ft_compressed}");
    // the shear term alone is 0.95, the stretch's normal term 0.1: a stretch
    // adds to the sum, a compression takes away
    let limits = bpm(ft / 0.1, fs / 0.95);
    assert_eq!(loaded(limits, 1e-10).status, BondStatus::Broken as i32);
    assert_eq!(loaded(limits, -1e-10).status, BondStatus::Intact as i32);
}

#[test]
fn infinite_limits_never_break() {
    let out = loaded(bpm(f64::INFINITY, f64::INFINITY), 1e-6);
    assert_eq!(out.status, BondStatus::Intact as i32);
}

#[test]
fn a_bond_breaks_by_one_rule() {
    for other in [
        BondParams {
            stress_break: 1,
            ..bpm(1.0, 1.0)
        },
        BondParams {
            inl_compatible: 1,
            ..bpm(1.0, 1.0)
        },
    ] {
        let e = BondModel::new(other).expect_err("refused");
        assert!(e.to_string().contains("bpm_break"), "{e}");
    }
}
