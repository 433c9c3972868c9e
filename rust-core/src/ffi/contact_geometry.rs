//! Voigt entries that take the geometry an engine's pair loop has (the
//! separation vector, or the engine's normal and centre distance) and the
//! radii, a wall written as radius 0: the core builds the frame
//! ([`ContactFrame::from_separation`], [`ContactFrame::from_normal`]).
//!
//! The `*_unchecked` entries are the engines' per-contact calls, once per
//! contact and step: no pointer or argument checks, and a success leaves
//! the error record alone. The result is checked: a non-finite force or
//! torque gives `GB_STATUS_NON_FINITE_RESULT` with a message. Same physics,
//! same bits as `granbond_voigt_compute` on the same contact. The
//! geometry and the state are read one double at a time, the velocities
//! where the engine keeps them (pass the engine's arrays rather than fresh
//! copies). On a CPU with AVX2 the step runs a copy compiled for AVX2:
//! same bits, fewer instructions ([`crate::contact::dispatch`]).

use super::contact::non_finite_loads;
use super::entry;
use super::error::{record, Failure, Status};
use super::guard::{reference_mut, vector3};
use crate::contact::{ContactFrame, ContactOutput, Motion, VoigtModel};
use crate::kinematics::{separated, KinematicsError};

/// The body of an unchecked per-contact entry: `$step` (one of
/// `contact::dispatch`'s steps) on the chosen instruction set, `Status::Ok` when it
/// answers true, else `$failed` (evaluated where the entry's arguments and
/// `FUNCTION` are in scope). Each copy is a function of its own with the
/// entry's arguments, which the entry only chooses and jumps to: the
/// failure is handled inside the copy, so the entry's call is its last act.
macro_rules! chosen_step {
    ($step:ident($($arg:ident),*) else $failed:expr) => {{
        step_copy! {
            #[inline(never)]
            fn baseline($($arg),*) {
                if $crate::contact::dispatch::$step::<$crate::vector::Vec3>($($arg),*) {
                    return Status::Ok;
                }
                $failed
            }
        }
        step_copy! {
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            fn wide($($arg),*) {
                if $crate::contact::dispatch::$step::<$crate::contact::wide::Y3>($($arg),*) {
                    return Status::Ok;
                }
                $failed
            }
        }
        step_copy! {
            /// The first call, before the instruction set is found.
            #[cold]
            #[inline(never)]
            fn first($($arg),*) {
                $crate::simd::Simd::chosen();
                chosen($($arg),*)
            }
        }
        step_copy! {
            #[inline(always)]
            fn chosen($($arg),*) {
                match $crate::simd::Simd::known() {
                    None => first($($arg),*),
                    #[cfg(target_arch = "x86_64")]
                    Some(simd) if simd != $crate::simd::Simd::Scalar => wide($($arg),*),
                    Some(_) => baseline($($arg),*),
                }
            }
        }
        chosen($($arg),*)
    }};
}

/// A function with the arguments of the unchecked per-contact entries
/// (their names as given), returning a status.
macro_rules! step_copy {
    ($(#[$attribute:meta])* fn $name:ident($model:ident, $geometry:ident, $length:ident, $radius_i:ident,
        $radius_j:ident, $v_i:ident, $v_j:ident, $w_i:ident, $w_j:ident, $dt:ident, $state:ident, $out:ident)
        $body:block) => {
        $(#[$attribute])*
        #[allow(clippy::too_many_arguments)]
        unsafe extern "C" fn $name(
            $model: *const $crate::contact::VoigtModel,
            $geometry: *const f64,
            $length: f64,
            $radius_i: f64,
            $radius_j: f64,
            $v_i: *const f64,
            $v_j: *const f64,
            $w_i: *const f64,
            $w_j: *const f64,
            $dt: f64,
            $state: *mut f64,
            $out: *mut $crate::contact::ContactOutput,
        ) -> Status $body
    };
}

/// One step of a Voigt contact given by its separation `del = x_i - x_j`
/// (3 doubles) and `rsq = |del|^2`: the normal is `del / sqrt(rsq)` (one
/// reciprocal), the overlap `(radius_i + radius_j) - sqrt(rsq)`, the levers
/// the radii and `R*` (only with rolling) `R_i R_j / (R_i + R_j)`.
/// Coincident centres (`rsq = 0`) are named as such.
///
/// # Safety
/// No pointer may be null. `model` from `granbond_voigt_model_new`; `del`,
/// `v_*`, `w_*` three doubles each; every number finite, `rsq > 0`, radii
/// > 0; `state` `GRANBOND_CONTACT_STATE_LEN` doubles; `out` valid for
/// writes; `dt` finite and >= 0.
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
    chosen_step!(step_separation(model, del, rsq, radius_i, radius_j, v_i, v_j, w_i, w_j, dt, state, out) else {
        if !separated(rsq) {
            // the cause, named (only on the failure path: the step has no branch for it)
            return coincident(FUNCTION);
        }
        non_finite_loads(FUNCTION)
    })
}

/// Records that the centres coincide: the pair has no axis.
#[cold]
fn coincident(function: &str) -> Status {
    let failure = Failure::from(KinematicsError::CoincidentCentres);
    record(function, &failure);
    failure.status
}

/// One step of a Voigt contact whose unit normal `n` (from `j` to `i`) the
/// engine has built, with the centre distance `distance`; for a wall
/// `radius_j = 0` and `distance` is the centre's distance from the wall
/// along `n` (so the overlap is `radius_i - distance`, the lever of the
/// wall 0 and `R* = R_i`).
///
/// # Safety
/// As `granbond_voigt_compute_separation_unchecked`, with `n` a unit
/// vector (three doubles) in place of `del`, and `radius_j >= 0`.
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
    chosen_step!(step_normal(model, n, distance, radius_i, radius_j, v_i, v_j, w_i, w_j, dt, state, out) else {
        non_finite_loads(FUNCTION)
    })
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{ContactState, VoigtParams, CONTACT_STATE_LEN};

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
    fn the_normal_entry_gives_the_bits_of_the_kernel() {
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
                let radius_i = 1e-3 * (1.0 + 0.3 * r.next());
                let radius_j = if wall { 0.0 } else { 1e-3 };
                let d = r.vec(1.0);
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                let n = d.map(|c| c / len);
                let mut m = Motion {
                    v_i: r.vec(0.05),
                    v_j: r.vec(0.05),
                    w_i: r.vec(50.0),
                    w_j: if wall { [0.0; 3] } else { r.vec(50.0) },
                };
                for step in 0..100 {
                    // in and out of contact, slowly
                    let overlap = 1e-6 * (r.next() + 0.3 + (step as f64 * 0.1).sin());
                    let distance = radius_i + radius_j - overlap;
                    let frame = ContactFrame::from_normal(n, distance, radius_i, radius_j, rolling == 1, m);
                    let (mut b, mut c) = (ContactOutput::default(), ContactOutput::default());
                    model.step_frame(&frame, 1e-7, &mut sc, &mut c);
                    let status = unsafe {
                        granbond_voigt_compute_normal_unchecked(
                            &model,
                            n.as_ptr(),
                            distance,
                            radius_i,
                            radius_j,
                            m.v_i.as_ptr(),
                            m.v_j.as_ptr(),
                            m.w_i.as_ptr(),
                            m.w_j.as_ptr(),
                            1e-7,
                            &mut sb as *mut ContactState as *mut f64,
                            &mut b,
                        )
                    };
                    assert_eq!(status, Status::Ok);
                    let what = format!("rolling {rolling} contact {contact} step {step}");
                    assert_eq!(
                        bits(&b, sb.as_slots()),
                        bits(&c, sc.as_slots()),
                        "normal entry, {what}"
                    );
                    touching += b.touching;
                    sliding += b.sliding;
                    rolling_slips += b.rolling_slip;
                    m.w_i = m.w_i.map(|w| w * 0.97);
                }
            }
        }
        assert!(
            touching > 2000 && sliding > 100 && rolling_slips > 100,
            "the sample missed a regime: {touching} touching, {sliding} sliding, {rolling_slips} rolling-slip steps"
        );
    }

    #[test]
    fn the_normal_entry_reports_a_non_finite_result() {
        let model = VoigtModel::new(VoigtParams::default()).unwrap();
        let n = [0.0, 0.0, 1.0];
        let (v, w_bad) = ([0.0; 3], [0.0, f64::NAN, 0.0]);
        let mut state = [0.0; CONTACT_STATE_LEN];
        let mut out = ContactOutput::default();
        let status = unsafe {
            granbond_voigt_compute_normal_unchecked(
                &model,
                n.as_ptr(),
                2e-3 - 1e-6,
                1e-3,
                1e-3,
                v.as_ptr(),
                v.as_ptr(),
                w_bad.as_ptr(),
                v.as_ptr(),
                1e-7,
                state.as_mut_ptr(),
                &mut out,
            )
        };
        assert_eq!(status, Status::NonFiniteResult);
    }
}
