//! `extern "C"` surface of the Voigt contact.

use super::bond::pair_estimate;
use super::entry;
use super::error::{record, Failure, Status};
use super::guard::{
    array, array_mut, finite, reference, reference_mut, slice, slice_mut, time_step, FailedIndex,
};
use super::results;
use crate::contact::model::{sphere_plane, sphere_sphere};
use crate::contact::{
    ContactFrame, ContactOutput, ContactState, Plane, TangentialLoad, VoigtModel, VoigtParams,
    CONTACT_STATE_LEN, VOIGT_PARAMETERS,
};
use crate::kinematics::{KinematicsError, PairKinematics, SphereKinematics};
use crate::simd::Simd;
use std::ffi::c_char;

/// Fills `params` with Table 1 of the seed.
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

/// The states of a batch as struct views of a caller's
/// `double[count * GRANBOND_CONTACT_STATE_LEN]`.
unsafe fn contact_states<'a>(
    states: *mut f64,
    count: usize,
    name: &str,
) -> Result<&'a mut [ContactState], Failure> {
    slice_mut(states as *mut ContactState, count, name)
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

/// `granbond_voigt_compute` over `count` contacts (`states[count *
/// GRANBOND_CONTACT_STATE_LEN]`); stops at the first bad input and writes
/// its index to `failed_index` (if not null; a misaligned one is refused
/// before any contact is advanced).
///
/// # Safety
/// Pointers must be null or valid for the sizes above.
#[entry(
    model: reference,
    failed_index: FailedIndex::new,
    kinematics: slice(count),
    states: contact_states(count),
    out: slice_mut(count),
    dt: time_step,
)]
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
    model
        .step_batch(kinematics, dt, states, out)
        .map_err(|(index, e)| failed_index.fail("contact", index, e.into()))?;
    for (index, (s, o)) in states.iter().zip(out.iter()).enumerate() {
        results::contact(s, o).map_err(|f| failed_index.fail("contact", index, f))?;
    }
    Ok(())
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
#[entry(
    model: reference,
    sphere: reference,
    plane: reference,
    state: contact_state,
    out: reference_mut,
    dt: time_step,
)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_compute_plane(
    model: *const VoigtModel,
    sphere: *const SphereKinematics,
    plane: *const Plane,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> Status {
    check_plane(sphere, plane)?;
    model.step_frame(&sphere_plane(sphere, plane), dt, state, out);
    results::contact(state, out)
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

/// Whether the AVX2 copies run: [`Simd::chosen`], the bonds' choice too.
#[inline(always)]
fn avx2() -> bool {
    Simd::chosen() != Simd::Scalar
}

/// `granbond_voigt_compute` / `granbond_voigt_compute_plane` for a contact
/// whose frame the engine has already built (the fields of the frame
/// `granbond_contact_frame_pair` / `granbond_contact_frame_plane` give),
/// handed over one by one, for engines that call once per contact and step
/// and keep the fields in their own arrays: `n` (3 doubles, may have just
/// been written: it is read one double at a time), the overlap, levers and
/// `R*` by value, and the velocities `v_i`, `v_j`, `w_i`, `w_j` (3 doubles
/// each) where the engine keeps them (they are read as the compiler likes:
/// pass the engine's arrays rather than fresh copies). No frame is built
/// and none is read back.
///
/// The hot path: no pointer or frame checks, and a success leaves the error
/// record alone. The result is checked: a non-finite force or torque
/// (non-finite input) gives `GB_STATUS_NON_FINITE_INPUT` with a message.
/// Same physics, same bits as the checked calls given the same frame. The
/// normal and the state are read one double at a time, and the result is
/// checked before it is stored. On a CPU with AVX2 (detected when a model
/// is built) the step runs a copy compiled for AVX2: same bits, fewer
/// instructions.
///
/// # Safety
/// No pointer may be null. `model` from `granbond_voigt_model_new`, `n` a
/// unit vector, every number finite, `state` `GRANBOND_CONTACT_STATE_LEN`
/// doubles, `out` valid for writes, `dt` finite and >= 0.
#[entry(unchecked)]
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
        FUNCTION, model, n, overlap, lever_i, lever_j, r_eff, v_i, v_j, w_i, w_j, dt, state, out,
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

/// One double of a record the engine has just written. The engine writes
/// its records field by field just before the call, and the stores are
/// still in flight when the kernel starts. A 16-byte load that spans two
/// 8-byte stores cannot be served from the store buffer (store-to-load
/// forwarding fails, the load waits until both stores reach the cache:
/// about a dozen cycles, a few times per contact), and the compiler pairs
/// neighbouring doubles into such loads at will. A volatile read keeps the
/// load exactly one double wide: it is served by the store that wrote it,
/// whatever width the engine's compiler chose.
#[inline(always)]
unsafe fn load(p: *const f64) -> f64 {
    std::ptr::read_volatile(p)
}

#[inline(always)]
pub(super) unsafe fn load3(p: *const [f64; 3]) -> [f64; 3] {
    let p = p as *const f64;
    [load(p), load(p.add(1)), load(p.add(2))]
}

/// The state one double at a time (an engine may hand over a copy it has
/// just made).
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
#[entry(kinematics: reference, frame: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_pair(
    kinematics: *const PairKinematics,
    frame: *mut ContactFrame,
) -> Status {
    *frame = sphere_sphere(kinematics)?;
    Ok(())
}

/// The contact frame of a sphere on a plane wall.
///
/// # Safety
/// Pointers must be null or valid.
#[entry(sphere: reference, plane: reference, frame: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_contact_frame_plane(
    sphere: *const SphereKinematics,
    plane: *const Plane,
    frame: *mut ContactFrame,
) -> Status {
    check_plane(sphere, plane)?;
    // finite input whose distance to the plane overflows
    let built = sphere_plane(sphere, plane);
    check_frame(&built)?;
    *frame = built;
    Ok(())
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
    check_frame(frame)?;
    *normal_force = model.normal_force(frame);
    results::vector("normal force", &[*normal_force])
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
    check_frame(frame)?;
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
    check_frame(frame)?;
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
    check_frame(frame)?;
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
    check_frame(frame)?;
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
    check_frame(frame)?;
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

/// LAMMPS keyword and LIGGGHTS name of Voigt parameter `id` (static storage).
///
/// # Safety
/// `keyword` and `liggghts_name` must be null or valid for writes.
#[entry(keyword: reference_mut, liggghts_name: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_parameter_name(
    id: usize,
    keyword: *mut *const c_char,
    liggghts_name: *mut *const c_char,
) -> Status {
    super::parameters::write_names(super::parameters::voigt_rows(), id, keyword, liggghts_name)
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
    fn the_unchecked_entry_gives_the_bits_of_the_kernel() {
        // the entry runs its AVX2 copy where the CPU has AVX2, the
        // kernel called here its baseline code
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
                    let (mut b, mut c) = (ContactOutput::default(), ContactOutput::default());
                    model.step_frame(&f, 1e-7, &mut sc, &mut c);
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
                    assert_eq!(fields, Status::Ok);
                    let what = format!("rolling {rolling} contact {contact} step {step}");
                    assert_eq!(
                        bits(&b, sb.as_slots()),
                        bits(&c, sc.as_slots()),
                        "fields entry, {what}"
                    );
                    touching += b.touching;
                    sliding += b.sliding;
                    rolling_slips += b.rolling_slip;
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
