//! `extern "C"` surface of the Voigt contact.

use super::bond::pair_estimate;
use super::error::{record, Failure, Status};
use super::guard::{call, check_dt, reference, reference_mut, slice, slice_mut, FailedIndex};
use super::guard::{parameter_c_names, write_parameter_name};
use super::results;
use crate::contact::model::{sphere_plane, sphere_sphere};
use crate::contact::{
    ContactFrame, ContactOutput, ContactState, Plane, TangentialLoad, VoigtModel, VoigtParams,
    CONTACT_STATE_LEN, VOIGT_PARAMETERS,
};
use crate::kinematics::{KinematicsError, PairKinematics, SphereKinematics};
use std::ffi::{c_char, CString};
use std::sync::atomic::{AtomicBool, Ordering};
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
        detect_cpu();
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
        results::contact(s, o)
    })
}

/// `granbond_voigt_compute` over `count` contacts (`states[count *
/// GRANBOND_CONTACT_STATE_LEN]`); stops at the first bad input and writes
/// its index to `failed_index` (if not null; a misaligned one is refused
/// before any contact is advanced).
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
        let failed = FailedIndex::new(failed_index)?;
        let k = slice(kinematics, count, "kinematics")?;
        let s = slice_mut(states as *mut ContactState, count, "states")?;
        let o = slice_mut(out, count, "out")?;
        check_dt(dt)?;
        let fail_at = |index: usize, f: Failure| {
            failed.report(index);
            Failure::new(f.status, format!("contact {index}: {}", f.message))
        };
        m.step_batch(k, dt, s, o)
            .map_err(|(index, e)| fail_at(index, Failure::from(e)))?;
        for (index, (s, o)) in s.iter().zip(o.iter()).enumerate() {
            results::contact(s, o).map_err(|f| fail_at(index, f))?;
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
        results::contact(s, o)
    })
}

/// The unchecked entries' bodies are compiled twice: for the x86-64
/// baseline, and for AVX2, chosen at run time on CPUs that have it (the
/// 3-vectors fit one register instead of two, so fewer instructions per
/// contact). The same operations in the same order, and no
/// fused multiply-add (not enabled, and never formed from separate
/// operations), so the same bits; the baseline-vs-checked tests compare them.
macro_rules! compiled_twice {
    ($vis:vis fn $base:ident($($arg:ident: $ty:ty),* $(,)?) $body:block) => {
        // the entry only chooses (this is inlined into it); each copy is a
        // function of its own
        #[inline(always)]
        #[allow(clippy::too_many_arguments)]
        $vis unsafe fn $base($($arg: $ty),*) -> Status {
            #[inline(always)]
            #[allow(clippy::too_many_arguments)]
            unsafe fn body($($arg: $ty),*) -> Status $body

            #[inline(never)]
            #[allow(clippy::too_many_arguments)]
            unsafe fn baseline($($arg: $ty),*) -> Status {
                body($($arg),*)
            }

            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            #[allow(clippy::too_many_arguments)]
            unsafe fn wide($($arg: $ty),*) -> Status {
                body($($arg),*)
            }

            #[cfg(target_arch = "x86_64")]
            if avx2() {
                return wide($($arg),*);
            }
            baseline($($arg),*)
        }
    };
}

/// Whether this CPU runs the AVX2 copies: found when a model is built
/// (`granbond_voigt_model_new`), so the entries only load a flag (until
/// then, the baseline copies run).
static WIDE: AtomicBool = AtomicBool::new(false);

fn detect_cpu() {
    #[cfg(target_arch = "x86_64")]
    WIDE.store(std::arch::is_x86_feature_detected!("avx2"), Ordering::Relaxed);
}

#[inline(always)]
fn avx2() -> bool {
    WIDE.load(Ordering::Relaxed)
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
/// The frame and the state are read one double at a time, and the result is
/// checked before it is stored (see [`load_frame`]). On a CPU with AVX2
/// (detected when a model is built) the step runs a copy compiled for AVX2:
/// same bits, fewer instructions.
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
    frame_step(model, frame, dt, state, out)
}

compiled_twice! {
    fn frame_step(
        model: *const VoigtModel,
        frame: *const ContactFrame,
        dt: f64,
        state: *mut f64,
        out: *mut ContactOutput,
    ) {
        let function = "granbond_voigt_compute_frame_unchecked";
        step_unchecked(function, model, &load_frame(frame), dt, state, out)
    }
}

/// `granbond_voigt_compute_frame_unchecked` with the frame's fields handed
/// over one by one, for an engine that keeps them in its own arrays: `n`
/// (3 doubles, may have just been written: it is read one double at a
/// time), the overlap, levers and `R*` by value, and the velocities `v_i`,
/// `v_j`, `w_i`, `w_j` (3 doubles each) where the engine keeps them (they
/// are read as the compiler likes: pass the engine's arrays rather than
/// fresh copies). Same bits as the frame entry for the same numbers; no
/// frame is built and none is read back.
///
/// # Safety
/// As `granbond_voigt_compute_frame_unchecked`: no pointer may be null,
/// `model` from `granbond_voigt_model_new`, `n` a unit vector, every number
/// finite, `state` `GRANBOND_CONTACT_STATE_LEN` doubles, `out` valid for
/// writes, `dt` finite and >= 0.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_fields_unchecked(
    model: *const VoigtModel,
    n: *const f64,
    overlap: f64,
    lever_i: f64,
    lever_j: f64,
    r_eff: f64,
    v_i: *const f64,
    v_j: *const f64,
    w_i: *const f64,
    w_j: *const f64,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    fields_step(
        "granbond_voigt_compute_fields_unchecked",
        model,
        n,
        overlap,
        lever_i,
        lever_j,
        r_eff,
        v_i,
        v_j,
        w_i,
        w_j,
        dt,
        state,
        out,
    )
}

compiled_twice! {
    pub(super) fn fields_step(
        function: &'static str,
        model: *const VoigtModel,
        n: *const f64,
        overlap: f64,
        lever_i: f64,
        lever_j: f64,
        r_eff: f64,
        v_i: *const f64,
        v_j: *const f64,
        w_i: *const f64,
        w_j: *const f64,
        dt: f64,
        state: *mut f64,
        out: *mut ContactOutput,
    ) {
        let frame = ContactFrame {
            n: load3(n as *const [f64; 3]),
            overlap,
            lever_i,
            lever_j,
            r_eff,
            v_i: *(v_i as *const [f64; 3]),
            v_j: *(v_j as *const [f64; 3]),
            w_i: *(w_i as *const [f64; 3]),
            w_j: *(w_j as *const [f64; 3]),
        };
        step_unchecked(function, model, &frame, dt, state, out)
    }
}

/// The body of the unchecked entries: one step, the result checked before
/// it is stored.
#[inline(always)]
unsafe fn step_unchecked(
    function: &str,
    model: *const VoigtModel,
    frame: &ContactFrame,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    let mut s = load_state(state);
    let mut o = ContactOutput::default();
    (*model).step_frame(frame, dt, &mut s, &mut o);
    *(state as *mut ContactState) = s;
    *out = o;
    let loads = o.force_i.iter().chain(&o.torque_i).chain(&o.torque_j);
    if loads.fold(0.0, |sum, x| sum + x * 0.0) == 0.0 {
        // x * 0 is 0 for every finite x and NaN for NaN and infinity
        return Status::Ok;
    }
    let failure = Failure::new(
        Status::NonFiniteInput,
        "non-finite force or torque (non-finite frame, state or dt)",
    );
    record(function, &failure);
    failure.status
}

/// One double of a record the engine has just written.
#[inline(always)]
unsafe fn load(p: *const f64) -> f64 {
    std::ptr::read_volatile(p)
}

#[inline(always)]
pub(super) unsafe fn load3(p: *const [f64; 3]) -> [f64; 3] {
    let p = p as *const f64;
    [load(p), load(p.add(1)), load(p.add(2))]
}

/// The engine writes the frame field by field just before the call, and
/// the stores are still in flight when the kernel starts. A 16-byte load
/// that spans two 8-byte stores cannot be served from the store buffer
/// (store-to-load forwarding fails, the load waits until both stores reach
/// the cache: about a dozen cycles, a few times per contact), and the
/// compiler pairs neighbouring doubles into such loads at will. Volatile
/// reads keep every load exactly one double wide: each is served by the
/// store that wrote it, whatever width the engine's compiler chose.
#[inline(always)]
unsafe fn load_frame(f: *const ContactFrame) -> ContactFrame {
    use std::ptr::addr_of;
    ContactFrame {
        n: load3(addr_of!((*f).n)),
        overlap: load(addr_of!((*f).overlap)),
        lever_i: load(addr_of!((*f).lever_i)),
        lever_j: load(addr_of!((*f).lever_j)),
        r_eff: load(addr_of!((*f).r_eff)),
        v_i: load3(addr_of!((*f).v_i)),
        v_j: load3(addr_of!((*f).v_j)),
        w_i: load3(addr_of!((*f).w_i)),
        w_j: load3(addr_of!((*f).w_j)),
    }
}

/// The state as [`load_frame`] reads the frame (an engine may hand over a
/// copy it has just made).
#[inline(always)]
unsafe fn load_state(state: *const f64) -> ContactState {
    let p = state as *const [f64; 3];
    ContactState {
        tangential_spring: load3(p),
        rolling_angle: load3(p.add(1)),
    }
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
        // finite input whose distance to the plane overflows
        let built = sphere_plane(sp, pl);
        check_frame(&built)?;
        *f = built;
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
        results::vector("normal force", &[*o])
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
        *o = m.tangential(f, normal_force, dt, s).into();
        results::vector("tangential force or torque", &tangential_numbers(o))?;
        results::vector("tangential spring", s)
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
        results::vector("rolling torque", t)?;
        results::vector("rolling angle", a)
    })
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
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_evaluate_frame(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    state: *const f64,
    out: *mut ContactOutput,
) -> Status {
    call("granbond_voigt_evaluate_frame", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let slots = reference(state as *const [f64; CONTACT_STATE_LEN], "state")?;
        let o = reference_mut(out, "out")?;
        check_frame(f)?;
        let s = ContactState {
            tangential_spring: [slots[0], slots[1], slots[2]],
            rolling_angle: [slots[3], slots[4], slots[5]],
        };
        m.evaluate_frame(f, &s, o);
        results::contact(&s, o)
    })
}

/// `granbond_voigt_tangential` of the stored `spring` (3 doubles, read
/// only), not advanced (see `granbond_voigt_evaluate_frame`).
///
/// # Safety
/// Pointers must be null or valid; `spring` holds 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_tangential_evaluate(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    spring: *const f64,
    out: *mut TangentialOutput,
) -> Status {
    call("granbond_voigt_tangential_evaluate", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let s = reference(spring as *const [f64; 3], "spring")?;
        let o = reference_mut(out, "out")?;
        check_frame(f)?;
        check_finite(normal_force, "normal_force")?;
        *o = m.tangential_held(f, normal_force, s).into();
        results::vector("tangential force or torque", &tangential_numbers(o))
    })
}

/// `granbond_voigt_rolling` of the stored `angle` (3 doubles, read only),
/// not advanced (see `granbond_voigt_evaluate_frame`).
///
/// # Safety
/// Pointers must be null or valid; `angle` and `torque_i` hold 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_rolling_evaluate(
    model: *const VoigtModel,
    frame: *const ContactFrame,
    normal_force: f64,
    angle: *const f64,
    torque_i: *mut f64,
    slip: *mut i32,
) -> Status {
    call("granbond_voigt_rolling_evaluate", || {
        let m = reference(model, "model")?;
        let f = reference(frame, "frame")?;
        let a = reference(angle as *const [f64; 3], "angle")?;
        let t = reference_mut(torque_i as *mut [f64; 3], "torque_i")?;
        let sl = reference_mut(slip, "slip")?;
        check_frame(f)?;
        check_finite(normal_force, "normal_force")?;
        let (torque, capped) = if m.rolling() {
            m.rolling_torque_held(f, normal_force, a)
        } else {
            (crate::vector::Vec3::zeros(), false)
        };
        *t = torque.into();
        *sl = capped as i32;
        results::vector("rolling torque", t)
    })
}

/// Critical time step of a contact of this type between spheres of the
/// given radii and masses (refused as `granbond_bond_critical_timestep`).
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Numbers spread over [-1, 1): an additive recurrence (plastic number).
    struct Numbers(f64);

    impl Numbers {
        fn next(&mut self) -> f64 {
            self.0 = (self.0 + 0.754_877_666_246_692_8).fract();
            2.0 * self.0 - 1.0
        }
        fn vec(&mut self, scale: f64) -> [f64; 3] {
            [self.next() * scale, self.next() * scale, self.next() * scale]
        }
    }

    fn bits(o: &ContactOutput, s: &[f64; CONTACT_STATE_LEN]) -> Vec<u64> {
        let scalars = [o.normal_force, o.overlap];
        let loads = o.force_i.iter().chain(&o.torque_i).chain(&o.torque_j);
        let numbers = loads.chain(scalars.iter()).chain(s.iter());
        let mut v: Vec<u64> = numbers.map(|x| x.to_bits()).collect();
        v.extend([o.touching, o.sliding, o.rolling_slip].map(|x| x as u64));
        v
    }

    #[test]
    fn the_unchecked_entries_give_the_bits_of_the_kernel() {
        // the entries run their AVX2 copies where the CPU has AVX2, the
        // kernel called here its baseline code
        detect_cpu();
        let mut r = Numbers(0.3);
        let (mut touching, mut sliding, mut rolling_slips) = (0, 0, 0);
        for rolling in [0, 1] {
            let model = VoigtModel::new(VoigtParams {
                rolling,
                mu: 0.3,
                mu_r: 0.02,
                ..VoigtParams::default()
            })
            .unwrap();
            for contact in 0..40 {
                // even contacts: sphere pairs; odd: a sphere on a wall
                let wall = contact % 2 == 1;
                let mut sa = [0.0; CONTACT_STATE_LEN];
                let (mut sb, mut sc) = (ContactState::default(), ContactState::default());
                let radius = 1e-3 * (1.0 + 0.3 * r.next());
                let d = r.vec(1.0);
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                let mut f = ContactFrame {
                    n: d.map(|c| c / len),
                    lever_i: radius,
                    lever_j: if wall { 0.0 } else { 1e-3 },
                    r_eff: if wall {
                        radius
                    } else {
                        radius * 1e-3 / (radius + 1e-3)
                    },
                    v_i: r.vec(0.05),
                    v_j: r.vec(0.05),
                    w_i: r.vec(50.0),
                    w_j: if wall { [0.0; 3] } else { r.vec(50.0) },
                    ..ContactFrame::default()
                };
                for step in 0..100 {
                    // in and out of contact, slowly
                    f.overlap = 1e-6 * (r.next() + 0.3 + (step as f64 * 0.1).sin());
                    let mut a = ContactOutput::default();
                    let (mut b, mut c) = (ContactOutput::default(), ContactOutput::default());
                    model.step_frame(&f, 1e-7, &mut sc, &mut c);
                    let fast = unsafe {
                        granbond_voigt_compute_frame_unchecked(&model, &f, 1e-7, sa.as_mut_ptr(), &mut a)
                    };
                    let fields = unsafe {
                        granbond_voigt_compute_fields_unchecked(
                            &model,
                            f.n.as_ptr(),
                            f.overlap,
                            f.lever_i,
                            f.lever_j,
                            f.r_eff,
                            f.v_i.as_ptr(),
                            f.v_j.as_ptr(),
                            f.w_i.as_ptr(),
                            f.w_j.as_ptr(),
                            1e-7,
                            &mut sb as *mut ContactState as *mut f64,
                            &mut b,
                        )
                    };
                    assert_eq!((fast, fields), (Status::Ok, Status::Ok));
                    let what = format!("rolling {rolling} contact {contact} step {step}");
                    assert_eq!(bits(&a, &sa), bits(&c, sc.as_slots()), "frame entry, {what}");
                    assert_eq!(
                        bits(&b, sb.as_slots()),
                        bits(&c, sc.as_slots()),
                        "fields entry, {what}"
                    );
                    touching += a.touching;
                    sliding += a.sliding;
                    rolling_slips += a.rolling_slip;
                    f.w_i = f.w_i.map(|w| w * 0.97);
                }
            }
        }
        assert!(
            touching > 2000 && sliding > 100 && rolling_slips > 100,
            "the sample missed a regime: {touching} touching, {sliding} sliding, {rolling_slips} rolling-slip steps"
        );
    }

    #[test]
    fn the_fields_entry_reports_a_non_finite_result() {
        let model = VoigtModel::new(VoigtParams::default()).unwrap();
        let n = [0.0, 0.0, 1.0];
        let (v, w_bad) = ([0.0; 3], [0.0, f64::NAN, 0.0]);
        let mut state = [0.0; CONTACT_STATE_LEN];
        let mut out = ContactOutput::default();
        let status = unsafe {
            granbond_voigt_compute_fields_unchecked(
                &model,
                n.as_ptr(),
                1e-6,
                1e-3,
                1e-3,
                5e-4,
                v.as_ptr(),
                v.as_ptr(),
                w_bad.as_ptr(),
                v.as_ptr(),
                1e-7,
                state.as_mut_ptr(),
                &mut out,
            )
        };
        assert_eq!(status, Status::NonFiniteInput);
    }
}
