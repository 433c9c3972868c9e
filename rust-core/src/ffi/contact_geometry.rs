//! Voigt entries that take the geometry an engine's pair loop has (the
//! separation vector, or the engine's normal and centre distance) and the
//! radii, a wall written as radius 0: the core builds the frame
//! ([`ContactFrame::from_separation`], [`ContactFrame::from_normal`]).

use super::contact::non_finite_loads;
use super::entry;
use super::error::{record, Failure, Status};
use super::guard::{reference_mut, vector3};
use crate::contact::dispatch::{step_normal, step_separation};
use crate::contact::{ContactFrame, ContactOutput, Motion, VoigtModel};
use crate::kinematics::{separated, KinematicsError};

/// `granbond_voigt_compute_fields_unchecked` for a touching pair given by
/// its separation `del = x_i - x_j` (3 doubles) and `rsq = |del|^2`: the
/// normal is `del / sqrt(rsq)` (one reciprocal), the overlap
/// `(radius_i + radius_j) - sqrt(rsq)`, the levers the radii and `R*` (only
/// with rolling) `R_i R_j / (R_i + R_j)`.
///
/// # Safety
/// As `granbond_voigt_compute_fields_unchecked`; `del` three doubles,
/// `rsq > 0`.
#[entry(unchecked)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_separation_unchecked(
    model: *const VoigtModel,
    del: *const f64,
    rsq: f64,
    radius_i: f64,
    radius_j: f64,
    v_i: *const f64,
    v_j: *const f64,
    w_i: *const f64,
    w_j: *const f64,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    if step_separation(
        model, del, rsq, radius_i, radius_j, v_i, v_j, w_i, w_j, dt, state, out,
    ) {
        return Status::Ok;
    }
    if !separated(rsq) {
        // the cause, named (only on the failure path: the step has no branch for it)
        return coincident(FUNCTION);
    }
    non_finite_loads(FUNCTION)
}

/// Records that the centres coincide: the pair has no axis.
#[cold]
fn coincident(function: &str) -> Status {
    let failure = Failure::from(KinematicsError::CoincidentCentres);
    record(function, &failure);
    failure.status
}

/// `granbond_voigt_compute_fields_unchecked` for a contact whose unit
/// normal `n` (from `j` to `i`) the engine has built, with the centre
/// distance `distance`; for a wall `radius_j = 0` and `distance` is the
/// centre's distance from the wall along `n` (so the overlap is
/// `radius_i - distance`, the lever of the wall 0 and `R* = R_i`).
///
/// # Safety
/// As `granbond_voigt_compute_fields_unchecked`.
#[entry(unchecked)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_normal_unchecked(
    model: *const VoigtModel,
    n: *const f64,
    distance: f64,
    radius_i: f64,
    radius_j: f64,
    v_i: *const f64,
    v_j: *const f64,
    w_i: *const f64,
    w_j: *const f64,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    if step_normal(
        model, n, distance, radius_i, radius_j, v_i, v_j, w_i, w_j, dt, state, out,
    ) {
        return Status::Ok;
    }
    non_finite_loads(FUNCTION)
}

/// The contact frame `granbond_voigt_compute_separation_unchecked` builds
/// (with `R*` whatever the model), for the calls that take a frame.
///
/// # Safety
/// Pointers must be null or valid (`del`, `v_*`, `w_*` three doubles each).
#[entry(del: vector3, v_i: vector3, v_j: vector3, w_i: vector3, w_j: vector3, frame: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_separation(
    del: *const f64,
    rsq: f64,
    radius_i: f64,
    radius_j: f64,
    v_i: *const f64,
    v_j: *const f64,
    w_i: *const f64,
    w_j: *const f64,
    frame: *mut ContactFrame,
) -> Status {
    if !separated(rsq) {
        return Err(KinematicsError::CoincidentCentres.into());
    }
    let motion = Motion { v_i, v_j, w_i, w_j };
    *frame = ContactFrame::from_separation(del, rsq, radius_i, radius_j, true, motion);
    Ok(())
}

/// The contact frame `granbond_voigt_compute_normal_unchecked` builds
/// (with `R*` whatever the model), for the calls that take a frame.
///
/// # Safety
/// Pointers must be null or valid (`n`, `v_*`, `w_*` three doubles each).
#[entry(n: vector3, v_i: vector3, v_j: vector3, w_i: vector3, w_j: vector3, frame: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_normal(
    n: *const f64,
    distance: f64,
    radius_i: f64,
    radius_j: f64,
    v_i: *const f64,
    v_j: *const f64,
    w_i: *const f64,
    w_j: *const f64,
    frame: *mut ContactFrame,
) -> Status {
    let motion = Motion { v_i, v_j, w_i, w_j };
    *frame = ContactFrame::from_normal(n, distance, radius_i, radius_j, true, motion);
    Ok(())
}
