//! `extern "C"` surface of the Voigt contact.

use super::bond::pair_estimate;
use super::error::{record, Failure, Status};
use super::guard::{call, check_dt, reference, reference_mut, slice, slice_mut};
use super::guard::{parameter_c_names, write_parameter_name};
use crate::contact::model::{sphere_plane, sphere_sphere};
use crate::contact::{
    ContactFrame, ContactOutput, ContactState, Plane, VoigtModel, VoigtParams, CONTACT_STATE_LEN,
    VOIGT_PARAMETERS,
};
use crate::kinematics::{KinematicsError, PairKinematics, SphereKinematics};
use std::ffi::{c_char, CString};
use std::sync::OnceLock;

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
        if let Err((index, e)) = m.step_batch(k, dt, s, o) {
            if !failed_index.is_null() {
                *failed_index = index;
            }
            let f = Failure::from(e);
            return Err(Failure::new(f.status, format!("contact {index}: {}", f.message)));
        }
        Ok(())
    })
}

fn check_plane(sp: &SphereKinematics, pl: &Plane) -> Result<(), Failure> {
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
    check_unit(&pl.normal, "plane normal")
}

fn check_unit(n: &[f64; 3], what: &str) -> Result<(), Failure> {
    let len = n.iter().map(|c| c * c).sum::<f64>().sqrt();
    if (len - 1.0).abs() > 1e-9 {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("{what} must be a unit vector; |n| = {len}"),
        ));
    }
    Ok(())
}

fn check_finite(x: f64, name: &str) -> Result<(), Failure> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Failure::new(
            Status::NonFiniteInput,
            format!("{name} must be finite; got {x}"),
        ))
    }
}

fn check_frame(f: &ContactFrame) -> Result<(), Failure> {
    let numbers = f.n.iter().chain(&f.v_i).chain(&f.v_j).chain(&f.w_i).chain(&f.w_j);
    let scalars = [f.overlap, f.lever_i, f.lever_j, f.r_eff];
    if !numbers.chain(scalars.iter()).all(|x| x.is_finite()) {
        return Err(KinematicsError::NonFinite.into());
    }
    check_unit(&f.n, "frame normal")
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
        check_plane(sp, pl)?;
        m.step_frame(&sphere_plane(sp, pl), dt, s, o);
        Ok(())
    })
}

/// `granbond_voigt_compute` / `granbond_voigt_compute_plane` for a contact
/// whose frame the engine has already built (the same frame
/// `granbond_contact_frame_pair` / `granbond_contact_frame_plane` give), for
/// engines that call once per contact and step. The hot path: no pointer or
/// frame checks, and a success leaves the error record alone. The result is
/// checked: a non-finite force or torque (non-finite input) gives
/// `GB_STATUS_NON_FINITE_INPUT` with a message. Same physics, same bits as
/// the checked calls given the same frame.
///
/// # Safety
/// None of the pointers may be null. `model` from
/// `granbond_voigt_model_new`; `frame` a frame with a unit normal and finite
/// numbers; `state` `GRANBOND_CONTACT_STATE_LEN` doubles; `out` valid for
/// writes; `dt` finite and >= 0.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_frame_unchecked(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    let o = &mut *out;
    let s = ContactState::from_slots_mut(&mut *(state as *mut [f64; CONTACT_STATE_LEN]));
    (*model).step_frame(&*frame, dt, s, o);
    let loads = o.force_i.iter().chain(&o.torque_i).chain(&o.torque_j);
    if loads.fold(0.0, |sum, x| sum + x * 0.0) == 0.0 {
        // x * 0 is 0 for every finite x and NaN for NaN and infinity
        return Status::Ok;
    }
    let failure = Failure::new(
        Status::NonFiniteInput,
        "non-finite force or torque (non-finite frame, state or dt)",
    );
    record("granbond_voigt_compute_frame_unchecked", &failure);
    failure.status
}

/// The contact frame (normal, overlap, levers, velocities) of two spheres,
/// for engines that evaluate the Voigt parts separately.
///
/// # Safety
/// Pointers must be null or valid.
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_pair(
    kinematics: *const PairKinematics,
    frame: *mut ContactFrame,
) -> Status {
    call("granbond_contact_frame_pair", || {
        let k = reference(kinematics, "kinematics")?;
        let f = reference_mut(frame, "frame")?;
        *f = sphere_sphere(k)?;
        Ok(())
    })
}

/// The contact frame of a sphere on a plane wall.
///
/// # Safety
/// Pointers must be null or valid.
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_plane(
    sphere: *const SphereKinematics,
    plane: *const Plane,
    frame: *mut ContactFrame,
) -> Status {
    call("granbond_contact_frame_plane", || {
        let sp = reference(sphere, "sphere")?;
        let pl = reference(plane, "plane")?;
        let f = reference_mut(frame, "frame")?;
        check_plane(sp, pl)?;
        *f = sphere_plane(sp, pl);
        Ok(())
    })
}

/// Voigt normal force `k_n delta_n - gamma_n v_n` (clamped at zero when the
/// model has no attraction) for a touching frame.
///
/// # Safety
/// Pointers must be null or valid.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_normal_force(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: *mut f64,
) -> Status {
    call("granbond_voigt_normal_force", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let o = reference_mut(normal_force, "normal_force")?;
        check_frame(f)?;
        *o = m.normal_force(f);
        Ok(())
    })
}

/// Tangential part of one Voigt step.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TangentialOutput {
    pub force_i: [f64; 3],
    pub torque_i: [f64; 3],
    pub torque_j: [f64; 3],
    pub sliding: i32,
}

/// Cundall-Strack tangential force with the Coulomb cap `mu |normal_force|`;
/// `spring` (3 doubles, zero for a new contact) is updated in place.
///
/// # Safety
/// Pointers must be null or valid; `spring` holds 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_tangential(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    dt: f64,
    spring: *mut f64,
    out: *mut TangentialOutput,
) -> Status {
    call("granbond_voigt_tangential", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let s = reference_mut(spring as *mut [f64; 3], "spring")?;
        let o = reference_mut(out, "out")?;
        check_dt(dt)?;
        check_frame(f)?;
        check_finite(normal_force, "normal_force")?;
        let t = m.tangential(f, normal_force, dt, s);
        *o = TangentialOutput {
            force_i: t.force.into(),
            torque_i: t.torque_i.into(),
            torque_j: t.torque_j.into(),
            sliding: t.sliding as i32,
        };
        Ok(())
    })
}

/// Iwashita-Oda rolling torque on `i` (apply its negative to `j`); `angle`
/// (3 doubles, zero for a new contact) is updated in place; `*slip` is 1
/// when the torque sits on its cap.
///
/// # Safety
/// Pointers must be null or valid; `angle` and `torque_i` hold 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_rolling(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    dt: f64,
    angle: *mut f64,
    torque_i: *mut f64,
    slip: *mut i32,
) -> Status {
    call("granbond_voigt_rolling", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let a = reference_mut(angle as *mut [f64; 3], "angle")?;
        let t = reference_mut(torque_i as *mut [f64; 3], "torque_i")?;
        let sl = reference_mut(slip, "slip")?;
        check_dt(dt)?;
        check_frame(f)?;
        check_finite(normal_force, "normal_force")?;
        if !m.rolling() {
            // Rolling resistance is off in this model: no torque, no memory.
            *a = [0.0; 3];
            *t = [0.0; 3];
            *sl = 0;
            return Ok(());
        }
        let (torque, capped) = m.rolling_torque(f, normal_force, dt, a);
        *t = torque.into();
        *sl = capped as i32;
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
    pair_estimate(
        "granbond_voigt_critical_timestep",
        model,
        [radius_i, radius_j, mass_i, mass_j],
        out,
        VoigtModel::critical_timestep,
    )
}

/// Number of rows in the Voigt parameter table.
#[no_mangle]
pub extern "C" fn granbond_voigt_parameter_count() -> usize {
    VOIGT_PARAMETERS.len()
}

/// LAMMPS keyword and LIGGGHTS name of Voigt parameter `id` (static storage).
///
/// # Safety
/// `keyword` and `liggghts_name` must be null or valid for writes.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_parameter_name(
    id: usize,
    keyword: *mut *const c_char,
    liggghts_name: *mut *const c_char,
) -> Status {
    call("granbond_voigt_parameter_name", || {
        static NAMES: OnceLock<Vec<(CString, CString)>> = OnceLock::new();
        let names = NAMES.get_or_init(|| parameter_c_names(VOIGT_PARAMETERS));
        write_parameter_name(names, id, keyword, liggghts_name)
    })
}
