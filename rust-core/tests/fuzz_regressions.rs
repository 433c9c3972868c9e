//! What the C ABI fuzz target found (docs/fuzzing.md), one claim per
//! test; the inputs that found them are in `fuzz/corpus/abi/regression-*`.

use granbond::bond::BondState;
use granbond::bond::{BondModel, BondOutput, BondParams, BOND_STATE_LEN};
use granbond::contact::{ContactOutput, VoigtModel, VoigtParams, CONTACT_STATE_LEN};
use granbond::ffi::bond::{
    granbond_bond_compute, granbond_bond_compute_indexed, granbond_bond_critical_timestep,
    granbond_bond_recommended_timestep, AtomArrayPointers,
};
use granbond::ffi::contact::{granbond_voigt_compute, granbond_voigt_critical_timestep};
use granbond::ffi::error::granbond_last_error_message;
use granbond::ffi::Status;
use granbond::kinematics::PairKinematics;
use std::ffi::CStr;

fn message() -> String {
    // SAFETY: the library's NUL-terminated record.
    unsafe { CStr::from_ptr(granbond_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn bond_model() -> BondModel {
    BondModel::new(BondParams {
        k_fn1: 1e9,
        ku_fn1: 1e9,
        k_fn2: 1e9,
        ku_fn2: 1e9,
        k_ft: 1e9,
        k_tn: 1e9,
        ku_tn: 1e9,
        k_tt: 1e9,
        ku_tt: 1e9,
        ..BondParams::default()
    })
    .unwrap()
}

/// A `size_t` one byte past an aligned one, inside `words`.
fn misaligned(words: &mut [u64; 2]) -> *mut usize {
    (words.as_mut_ptr() as *mut u8).wrapping_add(1) as *mut usize
}

fn expect_failed_index_refused(function: &str, status: Status, words: &[u64; 2]) {
    assert_eq!(status, Status::Misaligned, "{function}: {}", message());
    let m = message();
    assert!(
        m.starts_with(function) && m.contains("`failed_index`") && m.contains("misaligned"),
        "{function}: message \"{m}\""
    );
    assert_eq!(
        *words,
        [0, 0],
        "{function} wrote through the misaligned failed_index"
    );
}

#[test]
fn a_misaligned_failed_index_is_refused_not_written_through() {
    let model = bond_model();
    let mut state = [0.0; BOND_STATE_LEN];
    let mut out = BondOutput::default();

    let mut states = [state.as_mut_ptr()];

    let (x, v, r) = ([0.0; 3], [0.0; 3], [1e-3]);
    let atoms = AtomArrayPointers {
        x: x.as_ptr(),
        v: v.as_ptr(),
        omega: v.as_ptr(),
        radius: r.as_ptr(),
        count: 1,
    };
    // an index outside the one atom
    let pairs = [0i32, 5];
    let mut words = [0u64; 2];
    // SAFETY: as above.
    let status = unsafe {
        granbond_bond_compute_indexed(
            &model,
            1,
            &atoms,
            pairs.as_ptr(),
            1e-7,
            states.as_mut_ptr(),
            &mut out,
            misaligned(&mut words),
        )
    };
    expect_failed_index_refused("granbond_bond_compute_indexed", status, &words);
}

#[test]
fn the_critical_step_of_a_micrometre_sphere_with_rolling_damping_is_positive() {
    // default rolling damping on a 1 um sphere: damping ratio ~1e8, where
    // sqrt(1 + zeta^2) - zeta cancels to zero
    let voigt = VoigtModel::new(VoigtParams::default()).unwrap();
    let radius: f64 = 1e-6;
    let mass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3);
    let mut dt = f64::NAN;
    // SAFETY: valid pointers.
    let status = unsafe { granbond_voigt_critical_timestep(&voigt, radius, radius, mass, mass, &mut dt) };
    assert_eq!(status, Status::Ok, "{}", message());
    // the rolling mode, overdamped: 2 (sqrt(1 + z^2) - z) / omega -> 2 I / c
    // for the reduced inertia I = 0.2 m R^2 and the damping c
    let p = VoigtParams::default();
    let overdamped = 2.0 * 0.2 * mass * radius * radius / (p.gamma_r + p.eta_r);
    assert!(
        (dt - overdamped).abs() <= 1e-6 * overdamped,
        "critical step {dt}, the overdamped rolling limit is {overdamped}"
    );
}

#[test]
fn estimates_that_underflow_are_refused_rather_than_answered_with_zero_or_nan() {
    let model = bond_model();
    let voigt = VoigtModel::new(VoigtParams::default()).unwrap();
    for (radius_j, mass_j) in [(1.3e-3, 5e-324), (1.3e-3, f64::MIN_POSITIVE), (1e-300, 1e-300)] {
        let bodies = (1e-3, radius_j, 1e-5, mass_j);
        for function in [
            "granbond_bond_critical_timestep",
            "granbond_bond_recommended_timestep",
            "granbond_voigt_critical_timestep",
        ] {
            let mut dt = -1.0;
            // SAFETY: valid pointers.
            let status = unsafe {
                match function {
                    "granbond_bond_critical_timestep" => {
                        granbond_bond_critical_timestep(&model, 1e-3, radius_j, 1e-5, mass_j, &mut dt)
                    }
                    "granbond_bond_recommended_timestep" => {
                        granbond_bond_recommended_timestep(&model, 1e-3, radius_j, 1e-5, mass_j, &mut dt)
                    }
                    _ => granbond_voigt_critical_timestep(&voigt, 1e-3, radius_j, 1e-5, mass_j, &mut dt),
                }
            };
            assert!(
                status == Status::InvalidArgument || (status == Status::Ok && dt > 0.0),
                "{function}{bodies:?}: {status:?} with {dt}"
            );
            if status == Status::InvalidArgument {
                assert!(message().contains("mass_j"), "{}", message());
                assert_eq!(dt, -1.0, "{function} wrote {dt} on failure");
            }
        }
    }
}

#[test]
fn a_centre_distance_that_overflows_gives_no_contact_frame() {
    use granbond::contact::sphere_sphere;
    use granbond::kinematics::KinematicsError;
    let k = PairKinematics {
        x_i: [2.2e-3, -7.5e240, 0.0],
        radius_i: 1e-3,
        radius_j: 1e-3,
        ..PairKinematics::default()
    };
    let frame = sphere_sphere(&k);
    assert_eq!(frame, Err(KinematicsError::DistanceOverflows), "frame {frame:?}");
    let voigt = VoigtModel::new(VoigtParams::default()).unwrap();
    let mut state = [0.0; CONTACT_STATE_LEN];
    let mut out = ContactOutput::default();
    // SAFETY: valid pointers.
    let status = unsafe { granbond_voigt_compute(&voigt, &k, 1e-7, state.as_mut_ptr(), &mut out) };
    assert_eq!(status, Status::NonFiniteResult, "{out:?}");
    assert!(message().contains("centre distance overflows"), "{}", message());
}

#[test]
fn a_bond_whose_section_underflows_is_refused_rather_than_answered_with_nan_stresses() {
    let model = bond_model();
    // radii of 1e-150 m: the section's rb^3 underflows to 0, so the bending
    // and twisting stresses are 0 / 0
    let r = 1e-150;
    let k = PairKinematics {
        x_i: [1.5 * r, 0.0, 0.0],
        radius_i: r,
        radius_j: r,
        ..PairKinematics::default()
    };
    let mut state = BondState::created(2.0 * r);
    let mut out = BondOutput::default();
    // SAFETY: valid pointers of the documented sizes.
    let status = unsafe {
        granbond_bond_compute(
            &model,
            &k,
            1e-7,
            &mut state as *mut BondState as *mut f64,
            &mut out,
        )
    };
    assert_eq!(status, Status::NonFiniteResult, "{:?}: {}", out, message());
    let m = message();
    assert!(
        m.starts_with("granbond_bond_compute") && m.contains("non-finite"),
        "message \"{m}\""
    );
}

#[test]
fn a_bond_whose_spring_increment_overflows_is_refused_in_the_indexed_path() {
    let model = bond_model();
    let k = PairKinematics {
        x_i: [2e-3, 0.0, 0.0],
        v_i: [0.0, 1e300, 0.0],
        w_i: [0.0, 0.0, 1e300],
        radius_i: 1e-3,
        radius_j: 1e-3,
        ..PairKinematics::default()
    };
    let fresh = BondState::created(2e-3);
    let mut out = [BondOutput::default(); 2];
    let calm = PairKinematics {
        v_i: [0.0; 3],
        w_i: [0.0; 3],
        ..k
    };
    let kin = [calm, k];
    let mut states = [fresh, fresh];
    let mut pointers: Vec<*mut f64> = states
        .iter_mut()
        .map(|s| s as *mut BondState as *mut f64)
        .collect();
    // bond b joins atoms 2b (i) and 2b + 1 (j)
    let x: Vec<f64> = kin.iter().flat_map(|k| k.x_i.into_iter().chain(k.x_j)).collect();
    let v: Vec<f64> = kin.iter().flat_map(|k| k.v_i.into_iter().chain(k.v_j)).collect();
    let w: Vec<f64> = kin.iter().flat_map(|k| k.w_i.into_iter().chain(k.w_j)).collect();
    let radius: Vec<f64> = kin.iter().flat_map(|k| [k.radius_i, k.radius_j]).collect();
    let atoms = AtomArrayPointers {
        x: x.as_ptr(),
        v: v.as_ptr(),
        omega: w.as_ptr(),
        radius: radius.as_ptr(),
        count: 4,
    };
    let pairs = [0i32, 1, 2, 3];
    let mut failed = usize::MAX;
    // SAFETY: as above, four atoms, two distinct states.
    let status = unsafe {
        granbond_bond_compute_indexed(
            &model,
            2,
            &atoms,
            pairs.as_ptr(),
            1e-7,
            pointers.as_mut_ptr(),
            out.as_mut_ptr(),
            &mut failed,
        )
    };
    assert_eq!(status, Status::NonFiniteResult, "{}", message());
    assert_eq!(failed, 1, "{}", message());
}

#[test]
fn a_contact_whose_tangential_spring_overflows_is_refused() {
    let model = VoigtModel::new(VoigtParams {
        k_n: 1e4,
        k_t: 1e4,
        mu: 0.5,
        ..VoigtParams::default()
    })
    .unwrap();
    let k = PairKinematics {
        x_i: [1.9e-3, 0.0, 0.0],
        v_i: [0.0, 1e300, 0.0],
        v_j: [0.0, -1e300, 0.0],
        radius_i: 1e-3,
        radius_j: 1e-3,
        ..PairKinematics::default()
    };
    let mut state = [0.0; CONTACT_STATE_LEN];
    let mut out = ContactOutput::default();
    // SAFETY: valid pointers of the documented sizes.
    let status = unsafe { granbond_voigt_compute(&model, &k, 1e300, state.as_mut_ptr(), &mut out) };
    assert_eq!(status, Status::NonFiniteResult, "{out:?}: {}", message());
    assert!(message().starts_with("granbond_voigt_compute"), "{}", message());
}
