//! Validation refuses every bad value with a message naming the parameter
//! (LAMMPS keyword and LIGGGHTS name) and its range.

use granbond::bond::{BondModel, BondParams, PARAMETERS};
use granbond::contact::{VoigtModel, VoigtParams, VOIGT_PARAMETERS};

/// Field names as `Debug` prints them: the table must have one row each.
fn field_names(debug: &str) -> Vec<String> {
    let body = &debug[debug.find('{').unwrap() + 1..debug.rfind('}').unwrap()];
    body.split(", ")
        .map(|f| f.split(':').next().unwrap().trim().to_string())
        .collect()
}

#[test]
fn every_field_has_a_row_in_its_table() {
    let bond: Vec<_> = PARAMETERS.iter().map(|p| p.name.to_string()).collect();
    assert_eq!(bond, field_names(&format!("{:?}", BondParams::default())));
    let voigt: Vec<_> = VOIGT_PARAMETERS.iter().map(|p| p.name.to_string()).collect();
    assert_eq!(voigt, field_names(&format!("{:?}", VoigtParams::default())));
}

#[test]
fn defaults_are_valid() {
    assert!(BondModel::new(BondParams::default()).is_ok());
    assert!(VoigtModel::new(VoigtParams::default()).is_ok());
}

fn refused(p: BondParams) -> (usize, String) {
    let e = BondModel::new(p).expect_err("must be refused");
    (e.parameter, e.message)
}

#[test]
fn bad_values_are_refused_with_the_parameter_named() {
    let d = BondParams::default();
    let cases: Vec<(BondParams, &str, &str)> = vec![
        (
            BondParams { lambda: 0.0, ..d },
            "lambda",
            "radiusMultiplierBondnonlinear",
        ),
        (
            BondParams { k_fn1: -1.0, ..d },
            "k_fn1",
            "stiffnessPerUnitAreaK_fn1",
        ),
        (
            BondParams {
                kc_fn2: f64::NAN,
                ..d
            },
            "kc_fn2",
            "stiffnessPerUnitAreaKc_fn2",
        ),
        (
            BondParams {
                k_ft: f64::INFINITY,
                ..d
            },
            "k_ft",
            "stiffnessPerUnitAreaK_ft",
        ),
        (
            BondParams { eta_fn: 1.0, ..d },
            "eta_fn",
            "dampingNormalForceBondnonlinear",
        ),
        (
            BondParams { eta_tt: -0.1, ..d },
            "eta_tt",
            "dampingTangentialTorqueBondnonlinear",
        ),
        (
            BondParams {
                max_distance: 0.0,
                ..d
            },
            "max_distance",
            "maxDistanceBondnonlinear",
        ),
        (
            BondParams {
                max_sigma: f64::NAN,
                ..d
            },
            "max_sigma",
            "maxSigmaBondnonlinear",
        ),
        (
            BondParams {
                create_distance: -1.0,
                ..d
            },
            "create_distance",
            "createDistanceBondnonlinear",
        ),
        (BondParams { stress_break: 2, ..d }, "stress_break", "stressBreak"),
        (BondParams { bend: -1, ..d }, "bend", "shearTorqueStress"),
        (
            BondParams {
                k_fn1: 2.0,
                ku_fn1: 1.0,
                ..d
            },
            "ku_fn1",
            "stiffnessPerUnitAreaKu_fn1",
        ),
        (
            BondParams {
                k_tt: 2.0,
                ku_tt: 1.0,
                ..d
            },
            "ku_tt",
            "stiffnessPerUnitAreaKu_tt",
        ),
    ];
    for (p, name, liggghts) in cases {
        let (id, message) = refused(p);
        assert_eq!(PARAMETERS[id].name, name, "{message}");
        assert!(message.contains(name) && message.contains(liggghts), "{message}");
        assert!(message.contains("must be"), "states the allowed range: {message}");
    }
}

#[test]
fn infinite_strengths_mean_never_break() {
    let p = BondParams {
        max_sigma: f64::INFINITY,
        max_tau: f64::INFINITY,
        stress_break: 1,
        ..BondParams::default()
    };
    assert!(BondModel::new(p).is_ok());
}

#[test]
fn bad_voigt_values_are_refused_with_the_parameter_named() {
    let d = VoigtParams::default();
    for (p, name) in [
        (VoigtParams { k_n: 0.0, ..d }, "kn"),
        (VoigtParams { mu: -0.1, ..d }, "coefficientFriction"),
        (VoigtParams { mu_r: f64::NAN, ..d }, "coefficientRollingFriction"),
        (VoigtParams { eta_r: -1.0, ..d }, "rollingViscousDamping"),
        (VoigtParams { rolling: 3, ..d }, "rolling_friction voigt"),
    ] {
        let e = VoigtModel::new(p).expect_err("must be refused");
        assert_eq!(VOIGT_PARAMETERS[e.parameter].liggghts_name, name);
        assert!(e.message.contains(name), "{}", e.message);
    }
}
