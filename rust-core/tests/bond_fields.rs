//! A bond's named output fields (`bond::fields`, `granbond_bond_fields`):
//! the table, and the fields of a hand-checked bond against the closed
//! forms of the normal law and the section (docs/models/bond-nonlinear.md
//! eq. 2-6, 14).

use granbond_test_support as common;

use common::{bond_at, model, pair_at, params, step, RADIUS};
use granbond::bond::fields::{BOND_FIELDS, BOND_FIELD_COUNT};
use granbond::bond::output_slots::{store_output, BOND_OUTPUT_SLOTS};
use granbond::bond::{BondParams, BOND_SLOTS, BOND_STATE_LEN};
use granbond::ffi::error::granbond_last_error_message;
use granbond::ffi::fields::{granbond_bond_field_count, granbond_bond_field_info, granbond_bond_fields};
use granbond::ffi::Status;
use granbond::state_layout::swap_state;
use std::f64::consts::PI;
use std::ffi::{c_char, CStr};

const R0: f64 = 2.0 * RADIUS;
const STRETCH: f64 = 1e-6;
const SIGMA_MAX: f64 = 5e7;
const TAU_MAX: f64 = 4e7;
const GAMMA: f64 = 0.5;

fn stress_params() -> BondParams {
    BondParams {
        stress_break: 1,
        max_sigma: SIGMA_MAX,
        max_tau: TAU_MAX,
        use_ratio: 1,
        tension_compression_ratio: GAMMA,
        ..params()
    }
}

/// The record (state, then output) of a bond created at `R0` and stretched
/// by `STRETCH` along x in one step at rest, as sphere i keeps it.
fn stretched_record(p: BondParams) -> Vec<f64> {
    let m = model(p);
    let mut state = bond_at(R0);
    let out = step(&m, &pair_at(R0 + STRETCH), 1e-7, &mut state);
    let mut record = state.as_slots().to_vec();
    record.extend_from_slice(&store_output(&out));
    assert_eq!(record.len(), BOND_STATE_LEN + BOND_OUTPUT_SLOTS.len());
    record
}

fn fields_of(p: BondParams, record: &[f64], x_i: [f64; 3], x_j: [f64; 3]) -> Vec<f64> {
    let m = model(p);
    let mut values = vec![f64::NAN; BOND_FIELD_COUNT];
    let status = unsafe {
        granbond_bond_fields(
            &m,
            record.as_ptr(),
            x_i.as_ptr(),
            x_j.as_ptr(),
            values.as_mut_ptr(),
        )
    };
    assert_eq!(status, Status::Ok);
    values
}

fn field(values: &[f64], name: &str) -> f64 {
    let k = BOND_FIELDS
        .iter()
        .position(|f| f.name == name)
        .unwrap_or_else(|| panic!("no field {name}"));
    values[k]
}

fn close(got: f64, want: f64, what: &str) {
    // a few roundings of double arithmetic on each side
    assert!(
        (got - want).abs() <= 1e-12 * want.abs().max(1e-30),
        "{what}: got {got}, want {want}"
    );
}

#[test]
fn every_field_has_a_unique_name_a_unit_and_a_description() {
    let mut names: Vec<&str> = BOND_FIELDS.iter().map(|f| f.name).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), BOND_FIELD_COUNT);
    assert!(BOND_FIELDS
        .iter()
        .all(|f| !f.unit.is_empty() && !f.description.is_empty()));
    assert_eq!(granbond_bond_field_count(), BOND_FIELD_COUNT);
    for (id, f) in BOND_FIELDS.iter().enumerate() {
        let (mut name, mut unit, mut description): (*const c_char, *const c_char, *const c_char) =
            (std::ptr::null(), std::ptr::null(), std::ptr::null());
        assert_eq!(
            unsafe { granbond_bond_field_info(id, &mut name, &mut unit, &mut description) },
            Status::Ok
        );
        assert_eq!(unsafe { CStr::from_ptr(name) }.to_str().unwrap(), f.name);
        assert_eq!(unsafe { CStr::from_ptr(unit) }.to_str().unwrap(), f.unit);
        assert_eq!(
            unsafe { CStr::from_ptr(description) }.to_str().unwrap(),
            f.description
        );
    }
}

#[test]
fn a_stretched_bond_shows_the_closed_forms_of_the_virgin_tension_line() {
    let record = stretched_record(stress_params());
    let v = fields_of(stress_params(), &record, [R0 + STRETCH, 0.0, 0.0], [0.0; 3]);
    let area = PI * (0.5 * RADIUS) * (0.5 * RADIUS); // rb = lambda R
    let force = params().k_fn2 * area * STRETCH; // eq. 5, virgin tension: k_fn2 |delta| on A
    close(field(&v, "status"), 1.0, "status");
    close(field(&v, "r0"), R0, "r0");
    close(field(&v, "r"), R0 + STRETCH, "r");
    close(field(&v, "stretch"), STRETCH, "stretch");
    close(field(&v, "normal_force"), -force, "normal_force (attractive)");
    close(field(&v, "force_x"), -force, "force_x");
    assert_eq!(field(&v, "force_y"), 0.0);
    assert_eq!(field(&v, "shear_force"), 0.0);
    assert_eq!(field(&v, "torque_i"), 0.0);
    close(field(&v, "sigma"), force / area, "sigma = |Fn| / A");
    close(field(&v, "sigma_max"), GAMMA * SIGMA_MAX, "the tensile limit");
    close(
        field(&v, "sigma_ratio"),
        force / area / (GAMMA * SIGMA_MAX),
        "sigma_ratio",
    );
    assert_eq!(field(&v, "tau"), 0.0);
    close(field(&v, "tau_max"), TAU_MAX, "tau_max");
    close(field(&v, "delta_min"), -STRETCH, "delta_min");
    assert_eq!(field(&v, "delta_max"), 0.0);
}

#[test]
fn the_other_sphere_sees_the_same_bond() {
    let record = stretched_record(stress_params());
    let mut swapped = record.clone();
    let slots: Vec<_> = BOND_SLOTS.iter().chain(&BOND_OUTPUT_SLOTS).copied().collect();
    swap_state(&slots, &mut swapped);
    let x_i = [R0 + STRETCH, 0.0, 0.0];
    let mine = fields_of(stress_params(), &record, x_i, [0.0; 3]);
    let theirs = fields_of(stress_params(), &swapped, [0.0; 3], x_i);
    for (k, f) in BOND_FIELDS.iter().enumerate() {
        let want = if f.name.starts_with("force_") {
            -mine[k]
        } else {
            mine[k]
        };
        assert_eq!(theirs[k], want, "{}", f.name);
    }
}

#[test]
fn distance_mode_has_no_stress_limits() {
    let p = BondParams {
        max_distance: 3.0 * RADIUS,
        ..params()
    };
    let v = fields_of(p, &stretched_record(p), [R0 + STRETCH, 0.0, 0.0], [0.0; 3]);
    assert!(field(&v, "sigma") > 0.0);
    for name in ["sigma_max", "sigma_ratio", "tau_max", "tau_ratio"] {
        assert_eq!(field(&v, name), 0.0, "{name}");
    }
}

#[test]
fn bad_inputs_are_refused_naming_the_argument() {
    let record = stretched_record(stress_params());
    let m = model(stress_params());
    let mut values = vec![0.0; BOND_FIELD_COUNT];
    let x = [R0, 0.0, 0.0];
    let nan = [f64::NAN, 0.0, 0.0];
    let call = |rec: *const f64, xi: &[f64; 3], xj: &[f64; 3], out: *mut f64| unsafe {
        granbond_bond_fields(&m, rec, xi.as_ptr(), xj.as_ptr(), out)
    };
    let message = || {
        unsafe { CStr::from_ptr(granbond_last_error_message()) }
            .to_string_lossy()
            .into_owned()
    };
    assert_eq!(
        call(record.as_ptr(), &x, &x, values.as_mut_ptr()),
        Status::InvalidArgument
    );
    assert!(message().contains("coincide"), "{}", message());
    assert_eq!(
        call(record.as_ptr(), &nan, &[0.0; 3], values.as_mut_ptr()),
        Status::NonFiniteInput
    );
    assert!(message().contains("x_i"), "{}", message());
    assert_eq!(
        call(std::ptr::null(), &x, &[0.0; 3], values.as_mut_ptr()),
        Status::NullPointer
    );
    assert!(message().contains("record"), "{}", message());
    assert_eq!(
        call(record.as_ptr(), &x, &[0.0; 3], std::ptr::null_mut()),
        Status::NullPointer
    );
    assert!(message().contains("values"), "{}", message());
    let (mut a, mut b, mut c) = (std::ptr::null(), std::ptr::null(), std::ptr::null());
    assert_eq!(
        unsafe { granbond_bond_field_info(BOND_FIELD_COUNT, &mut a, &mut b, &mut c) },
        Status::InvalidArgument
    );
}

#[test]
fn the_stress_limits_are_those_the_break_rule_applies() {
    let m = model(stress_params());
    let (mut sigma_max, mut tau_max) = (f64::NAN, f64::NAN);
    let limits = |delta: f64, s: &mut f64, t: &mut f64| unsafe {
        granbond::ffi::fields::granbond_bond_stress_limits(&m, delta, s, t)
    };
    assert_eq!(limits(-1e-6, &mut sigma_max, &mut tau_max), Status::Ok);
    assert_eq!((sigma_max, tau_max), (GAMMA * SIGMA_MAX, TAU_MAX));
    assert_eq!(limits(1e-6, &mut sigma_max, &mut tau_max), Status::Ok);
    assert_eq!((sigma_max, tau_max), (SIGMA_MAX, TAU_MAX));
    assert_eq!(
        limits(f64::NAN, &mut sigma_max, &mut tau_max),
        Status::NonFiniteInput
    );
    let d = model(BondParams {
        max_distance: 3.0 * RADIUS,
        ..params()
    });
    assert_eq!(
        unsafe {
            granbond::ffi::fields::granbond_bond_stress_limits(&d, -1e-6, &mut sigma_max, &mut tau_max)
        },
        Status::Ok
    );
    assert_eq!((sigma_max, tau_max), (0.0, 0.0));
}
