//! `extern "C"` surface of the Voigt contact.

use super::bond::pair_estimate;
use super::entry;
use super::error::{record, Failure, Status};
use super::guard::{array, array_mut, finite, reference, reference_mut, time_step};
use super::results;
use crate::contact::{
    ContactFrame, ContactOutput, ContactState, TangentialLoad, VoigtModel, VoigtParams, CONTACT_STATE_LEN,
    VOIGT_PARAMETERS,
};
use crate::kinematics::PairKinematics;

/// Fills `params` with the defaults of docs/models/voigt.md's parameter
/// table (the write-up's values).
///
/// # Safety
/// `params` must be null or valid for writes.
#[entry(params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_default(params: *mut VoigtParams) -> Status {
    *params = VoigtParams::default();
    Ok(())
}

/// Validates `params` and builds a model (see `granbond_bond_model_new`).
///
/// # Safety
/// `params` must be null or point to a `GbVoigtParams`; `model` null or
/// valid for writes. Free with `granbond_voigt_model_free`.
#[entry(model: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_model_new(
    params: *const VoigtParams,
    model: *mut *mut VoigtModel,
) -> Status {
    // cleared before `params` is looked at: no failure leaves a pointer
    *model = std::ptr::null_mut();
    let m = VoigtModel::new(*reference(params, "params")?)?;
    *model = Box::into_raw(Box::new(m));
    Ok(())
}

/// Frees a model from `granbond_voigt_model_new` (null is ignored).
///
/// # Safety
/// `model` must come from `granbond_voigt_model_new` and not be used again.
#[entry(or = ())]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_model_free(model: *mut VoigtModel) {
    if !model.is_null() {
        drop(Box::from_raw(model));
    }
}

unsafe fn contact_state<'a>(state: *mut f64, name: &str) -> Result<&'a mut ContactState, Failure> {
    Ok(ContactState::from_slots_mut(array_mut(state, name)?))
}

/// A stored state that is read, not advanced (a copy).
unsafe fn held_state(state: *const f64, name: &str) -> Result<ContactState, Failure> {
    let slots: &[f64; CONTACT_STATE_LEN] = array(state, name)?;
    Ok(ContactState {
        tangential_spring: [slots[0], slots[1], slots[2]],
        rolling_angle: [slots[3], slots[4], slots[5]],
    })
}

/// Advances one sphere-sphere contact by `dt` (`state`:
/// `double[GRANBOND_CONTACT_STATE_LEN]`, zero for a new contact). Spheres
/// apart exert nothing and their state is zeroed.
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[entry(model: reference, kinematics: reference, state: contact_state, out: reference_mut, dt: time_step)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute(
    model: *const VoigtModel,
    kinematics: *const PairKinematics,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    model.step(kinematics, dt, state, out)?;
    results::contact(state, out)
}

/// Records that an unchecked step's loads came out non-finite. Cold: the
/// engines' steps never take this path, and its code stays out of theirs.
#[cold]
pub(super) fn non_finite_loads(function: &str) -> Status {
    let failure = Failure::new(
        Status::NonFiniteResult,
        "non-finite force or torque (a non-finite frame, state or dt, or input far outside the model's range)",
    );
    record(function, &failure);
    failure.status
}

/// Voigt normal force `k_n delta_n - gamma_n v_n` (clamped at zero when the
/// model has no attraction) for a touching frame.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, frame: reference, normal_force: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_normal_force(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: *mut f64,
) -> Status {
    frame.check()?;
    *normal_force = model.normal_force(frame);
    results::vector("normal force", &[*normal_force])
}

/// Tangential part of one Voigt step.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TangentialOutput {
    /// Tangential force on `i` (N).
    pub force_i: [f64; 3],
    /// Torque of that force on `i` (N m).
    pub torque_i: [f64; 3],
    /// Torque of that force on `j` (N m).
    pub torque_j: [f64; 3],
    /// 1 when the force sits on the Coulomb cap, else 0.
    pub sliding: i32,
}

impl From<TangentialLoad> for TangentialOutput {
    fn from(t: TangentialLoad) -> Self {
        Self {
            force_i: t.force.into(),
            torque_i: t.torque_i.into(),
            torque_j: t.torque_j.into(),
            sliding: t.sliding as i32,
        }
    }
}

fn tangential_numbers(o: &TangentialOutput) -> [f64; 9] {
    let (f, ti, tj) = (o.force_i, o.torque_i, o.torque_j);
    [f[0], f[1], f[2], ti[0], ti[1], ti[2], tj[0], tj[1], tj[2]]
}

/// Cundall-Strack tangential force with the Coulomb cap `mu |normal_force|`;
/// `spring` (3 doubles, zero for a new contact) is updated in place.
///
/// # Safety
/// Pointers must be null or valid; `spring` holds 3 doubles.
#[entry(model: reference, frame: reference, spring: array_mut, out: reference_mut, dt: time_step)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_tangential(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    dt: f64,
    spring: *mut f64,
    out: *mut TangentialOutput,
) -> Status {
    frame.check()?;
    let normal_force = finite(normal_force, "normal_force")?;
    *out = model.tangential(frame, normal_force, dt, spring).into();
    results::vector("tangential force or torque", &tangential_numbers(out))?;
    results::vector("tangential spring", spring)
}

/// Iwashita-Oda rolling torque on `i` (apply its negative to `j`); `angle`
/// (3 doubles, zero for a new contact) is updated in place; `*slip` is 1
/// when the torque sits on its cap.
///
/// # Safety
/// Pointers must be null or valid; `angle` and `torque_i` hold 3 doubles.
#[entry(
    model: reference,
    frame: reference,
    angle: array_mut,
    torque_i: array_mut,
    slip: reference_mut,
    dt: time_step,
)]
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
    frame.check()?;
    let normal_force = finite(normal_force, "normal_force")?;
    if !model.rolling() {
        // Rolling resistance is off in this model: no torque, no memory.
        *angle = [0.0; 3];
        *torque_i = [0.0; 3];
        *slip = 0;
        return Ok(());
    }
    let (torque, capped) = model.rolling_torque(frame, normal_force, dt, angle);
    *torque_i = torque.into();
    *slip = capped as i32;
    results::vector("rolling torque", torque_i)?;
    results::vector("rolling angle", angle)
}

/// The loads of a contact from its stored state without advancing it
/// (`state`: `GRANBOND_CONTACT_STATE_LEN` doubles, read only): no spring
/// increment, and a spring in the tangent plane to round-off used as
/// stored. For the passes of an engine that must not move the history on
/// (the setup pass of a run, per-contact output): in the frame of the last
/// step they report the loads it applied, so a second run or a restart
/// continues as an uninterrupted run.
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[entry(model: reference, frame: reference, state: held_state, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_evaluate_frame(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    state: *const f64,
    out: *mut ContactOutput,
) -> Status {
    frame.check()?;
    model.evaluate_frame(frame, &state, out);
    results::contact(&state, out)
}

/// `granbond_voigt_tangential` of the stored `spring` (3 doubles, read
/// only), not advanced (see `granbond_voigt_evaluate_frame`).
///
/// # Safety
/// Pointers must be null or valid; `spring` holds 3 doubles.
#[entry(model: reference, frame: reference, spring: array, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_tangential_evaluate(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    spring: *const f64,
    out: *mut TangentialOutput,
) -> Status {
    frame.check()?;
    let normal_force = finite(normal_force, "normal_force")?;
    *out = model.tangential_held(frame, normal_force, spring).into();
    results::vector("tangential force or torque", &tangential_numbers(out))
}

/// `granbond_voigt_rolling` of the stored `angle` (3 doubles, read only),
/// not advanced (see `granbond_voigt_evaluate_frame`).
///
/// # Safety
/// Pointers must be null or valid; `angle` and `torque_i` hold 3 doubles.
#[entry(model: reference, frame: reference, angle: array, torque_i: array_mut, slip: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_rolling_evaluate(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    angle: *const f64,
    torque_i: *mut f64,
    slip: *mut i32,
) -> Status {
    frame.check()?;
    let normal_force = finite(normal_force, "normal_force")?;
    let (torque, capped) = if model.rolling() {
        model.rolling_torque_held(frame, normal_force, angle)
    } else {
        (crate::vector::Vec3::zeros(), false)
    };
    *torque_i = torque.into();
    *slip = capped as i32;
    results::vector("rolling torque", torque_i)
}

/// Critical time step of a contact of this type between spheres of the
/// given radii and masses (refused as `granbond_bond_critical_timestep`).
///
/// # Safety
/// Pointers must be null or valid.
#[entry(model: reference, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_critical_timestep(
    model: *const VoigtModel,
    radius_i: f64,
    radius_j: f64,
    mass_i: f64,
    mass_j: f64,
    out: *mut f64,
) -> Status {
    *out = pair_estimate(
        model,
        [radius_i, radius_j, mass_i, mass_j],
        VoigtModel::critical_timestep,
    )?;
    Ok(())
}

/// Number of rows in the Voigt parameter table.
#[entry(or = 0)]
#[no_mangle]
pub extern "C" fn granbond_voigt_parameter_count() -> usize {
    VOIGT_PARAMETERS.len()
}
