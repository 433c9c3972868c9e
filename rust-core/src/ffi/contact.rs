//! `extern "C"` surface of the Voigt contact.

use super::bond::check_bodies;
use super::error::{Failure, Status};
use super::guard::{call, check_dt, reference, reference_mut, slice, slice_mut};
use crate::contact::model::sphere_plane;
use crate::contact::{ContactOutput, ContactState, Plane, VoigtModel, VoigtParams, CONTACT_STATE_LEN};
use crate::kinematics::{KinematicsError, PairKinematics, SphereKinematics};

/// Fills `params` with Table 1 of the seed.
///
/// # Safety
/// `params` must be null or valid for writes.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_default(params: *mut VoigtParams) -> Status {
    call("granbond_voigt_params_default", || {
        *reference_mut(params, "params")? = VoigtParams::default();
        Ok(())
    })
}

/// Validates `params` and builds a model (see `granbond_bond_model_new`).
///
/// # Safety
/// `params` must be null or point to a `GbVoigtParams`; `model` null or
/// valid for writes. Free with `granbond_voigt_model_free`.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_model_new(
    params: *const VoigtParams,
    model: *mut *mut VoigtModel,
) -> Status {
    call("granbond_voigt_model_new", || {
        let out = reference_mut(model, "model")?;
        *out = std::ptr::null_mut();
        let m = VoigtModel::new(*reference(params, "params")?)?;
        *out = Box::into_raw(Box::new(m));
        Ok(())
    })
}

/// Frees a model from `granbond_voigt_model_new` (null is ignored).
///
/// # Safety
/// `model` must come from `granbond_voigt_model_new` and not be used again.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_model_free(model: *mut VoigtModel) {
    if !model.is_null() {
        drop(Box::from_raw(model));
    }
}

unsafe fn contact_state<'a>(state: *mut f64) -> Result<&'a mut ContactState, Failure> {
    let slots = reference_mut(state as *mut [f64; CONTACT_STATE_LEN], "state")?;
    Ok(ContactState::from_slots_mut(slots))
}

/// Advances one sphere-sphere contact by `dt` (`state`:
/// `double[GRANBOND_CONTACT_STATE_LEN]`, zero for a new contact). Spheres
/// apart exert nothing and their state is zeroed.
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute(
    model: *const VoigtModel,
    kinematics: *const PairKinematics,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    call("granbond_voigt_compute", || {
        let m = reference(model, "model")?;
        let k = reference(kinematics, "kinematics")?;
        let s = contact_state(state)?;
        let o = reference_mut(out, "out")?;
        check_dt(dt)?;
        m.step(k, dt, s, o)?;
        Ok(())
    })
}

/// `granbond_voigt_compute` over `count` contacts (`states[count *
/// GRANBOND_CONTACT_STATE_LEN]`); stops at the first bad input and writes
/// its index to `failed_index` (if not null).
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_batch(
    model: *const VoigtModel,
    count: usize,
    kinematics: *const PairKinematics,
    dt: f64,
    states: *mut f64,
    out: *mut ContactOutput,
    failed_index: *mut usize,
) -> Status {
    call("granbond_voigt_compute_batch", || {
        let m = reference(model, "model")?;
        let k = slice(kinematics, count, "kinematics")?;
        let s = slice_mut(states as *mut ContactState, count, "states")?;
        let o = slice_mut(out, count, "out")?;
        check_dt(dt)?;
        for (index, ((k, s), o)) in k.iter().zip(s.iter_mut()).zip(o.iter_mut()).enumerate() {
            if let Err(e) = m.step(k, dt, s, o) {
                if !failed_index.is_null() {
                    *failed_index = index;
                }
                let f = Failure::from(e);
                return Err(Failure::new(f.status, format!("contact {index}: {}", f.message)));
            }
        }
        Ok(())
    })
}

/// Advances a sphere-plane contact (the plane's normal points towards the
/// sphere's side and must be a unit vector).
///
/// # Safety
/// Pointers must be null or valid; `state` holds `GRANBOND_CONTACT_STATE_LEN` doubles.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_plane(
    model: *const VoigtModel,
    sphere: *const SphereKinematics,
    plane: *const Plane,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    call("granbond_voigt_compute_plane", || {
        let m = reference(model, "model")?;
        let sp = reference(sphere, "sphere")?;
        let pl = reference(plane, "plane")?;
        let s = contact_state(state)?;
        let o = reference_mut(out, "out")?;
        check_dt(dt)?;
        let numbers =
            sp.x.iter()
                .chain(&sp.v)
                .chain(&sp.w)
                .chain(&pl.point)
                .chain(&pl.normal)
                .chain(&pl.velocity);
        if !numbers.chain(std::iter::once(&sp.radius)).all(|x| x.is_finite()) {
            return Err(KinematicsError::NonFinite.into());
        }
        if !(sp.radius > 0.0) {
            return Err(KinematicsError::NonPositiveRadius.into());
        }
        let len = pl.normal.iter().map(|c| c * c).sum::<f64>().sqrt();
        if (len - 1.0).abs() > 1e-9 {
            return Err(Failure::new(
                Status::InvalidArgument,
                format!("plane normal must be a unit vector; |n| = {len}"),
            ));
        }
        let (g, v) = sphere_plane(sp.x, sp.v, sp.w, sp.radius, pl);
        m.step_geometry(&g, &v, dt, s, o);
        Ok(())
    })
}

/// Critical time step of a contact of this type between spheres of the
/// given radii and masses.
///
/// # Safety
/// Pointers must be null or valid.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_critical_timestep(
    model: *const VoigtModel,
    radius_i: f64,
    radius_j: f64,
    mass_i: f64,
    mass_j: f64,
    out: *mut f64,
) -> Status {
    call("granbond_voigt_critical_timestep", || {
        let m = reference(model, "model")?;
        let o = reference_mut(out, "out")?;
        check_bodies(radius_i, radius_j, mass_i, mass_j)?;
        *o = m.critical_timestep(radius_i, radius_j, mass_i, mass_j);
        Ok(())
    })
}
