//! The per-contact steps of the engines' hot loops, as `bond/dispatch.rs`
//! is for bonds. Each step reads the engine's memory through raw pointers
//! (the caller vouches for them), builds the
//! [`ContactFrame`](super::ContactFrame), steps the contact, stores the state
//! and loads, and answers whether the loads are finite.
//!
//! Each step is compiled twice, by the entries that run it
//! (`ffi::contact_geometry`), which choose between the copies: for the
//! x86-64 baseline, on `Vec3`, and for AVX2, run on CPUs that have it
//! ([`Simd::chosen`](crate::simd::Simd::chosen), the bonds' choice too), on
//! vectors held in one AVX register each (`contact::wide`): fewer
//! instructions per contact. The same operations in the same order, and no
//! fused multiply-add (not enabled, and never formed from separate
//! operations), so the same bits on both.
//!
//! Each step is also compiled once per value of the rolling switch, which
//! is read once per call: the frame's `R*` and the rolling part are left
//! out of a model without rolling.

use super::frame::{FrameIn, Motion};
use super::model::VoigtModel;
use super::state::{ContactOutput, ContactState};
use super::vectors::StepVector;
use std::mem::offset_of;

/// One step of a pair given by its separation `del` (3 doubles, read
/// one double at a time) and `rsq = |del|^2`, with the radii
/// ([`FrameIn::from_separation`]; `R*` only with rolling), and the
/// velocities (3 doubles each, read as the compiler likes). False when
/// a load came out non-finite (non-finite input the caller let
/// through, or input far outside the model's range).
///
/// # Safety
/// `model` valid; `del`, `v_*`, `w_*` three doubles each; `state`
/// [`CONTACT_STATE_LEN`](super::CONTACT_STATE_LEN) doubles; `out` valid
/// for writes.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn step_separation<V: StepVector>(
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
) -> bool {
    let del = V::read_fresh(del);
    let frame = |rolling, motion| FrameIn::from_separation(del, rsq, radius_i, radius_j, rolling, motion);
    step_framed(&*model, frame, [v_i, v_j, w_i, w_j], dt, state, out)
}

/// [`step_separation`] of a contact given by the engine's unit normal
/// `n` (3 doubles) and centre distance, with the radii, a wall as
/// `radius_j = 0` ([`FrameIn::from_normal`]; `R*` only with
/// rolling).
///
/// # Safety
/// As [`step_separation`]; `n` three doubles.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn step_normal<V: StepVector>(
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
) -> bool {
    let n = V::read_fresh(n);
    let frame = |rolling, motion| FrameIn::from_normal(n, distance, radius_i, radius_j, rolling, motion);
    step_framed(&*model, frame, [v_i, v_j, w_i, w_j], dt, state, out)
}

/// One step of the frame `frame(rolling, motion)` builds, with the model's
/// rolling switch (a constant in each of the two copies) and the
/// velocities where the engine keeps them (`v_i, v_j, w_i, w_j`), read as
/// the compiler likes: the engine wrote them long before the call.
#[inline(always)]
unsafe fn step_framed<V: StepVector>(
    model: &VoigtModel,
    frame: impl Fn(bool, Motion<V>) -> FrameIn<V>,
    [v_i, v_j, w_i, w_j]: [*const f64; 4],
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> bool {
    let motion = Motion {
        v_i: V::read(v_i),
        v_j: V::read(v_j),
        w_i: V::read(w_i),
        w_j: V::read(w_j),
    };
    if model.rolling() {
        step_stored::<V, true>(model, &frame(true, motion), dt, state, out)
    } else {
        step_stored::<V, false>(model, &frame(false, motion), dt, state, out)
    }
}

// The loads are written as three vectors side by side, each spilling into
// the first slot of the next (and the last into `normal_force`, written
// after it).
const _: () = assert!(offset_of!(ContactOutput, force_i) == 0);
const _: () = assert!(offset_of!(ContactOutput, torque_i) == 3 * 8);
const _: () = assert!(offset_of!(ContactOutput, torque_j) == 6 * 8);
const _: () = assert!(offset_of!(ContactOutput, normal_force) == 9 * 8);
const _: () = assert!(offset_of!(ContactState, rolling_angle) == 3 * 8);

/// One step from the stored state; the state and loads are stored back,
/// and the answer is whether the loads are finite. `ROLLING` is the
/// model's switch.
#[inline(always)]
unsafe fn step_stored<V: StepVector, const ROLLING: bool>(
    model: &VoigtModel,
    frame: &FrameIn<V>,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> bool {
    // the state one double at a time (an engine may hand over a copy it
    // has just made); without rolling, the angle's slots are not the
    // step's and stay as they are
    let mut spring = V::read_fresh(state);
    let mut angle = if ROLLING {
        V::read_fresh(state.add(3))
    } else {
        V::zeros()
    };
    let Some(l) = model.touching::<V, ROLLING, true>(frame, dt, &mut spring, &mut angle) else {
        *(state as *mut ContactState) = ContactState::default();
        *out = ContactOutput {
            overlap: frame.overlap,
            ..ContactOutput::default()
        };
        return true;
    };
    if ROLLING {
        spring.write_over(state);
        angle.write(state.add(3));
    } else {
        spring.write(state);
    }
    // force_i last, joined to torque_i's first component: each 16-byte
    // pair of the loads (an engine may read them so, LIGGGHTS's adapter
    // does) then lies within one store, which serves it while in flight
    let loads = out as *mut f64;
    l.torque_i.write_over(loads.add(3));
    l.torque_j.write_over(loads.add(6));
    l.force_i.write_joined(l.torque_i, loads);
    (*out).normal_force = l.normal_force;
    (*out).overlap = frame.overlap;
    (*out).touching = 1;
    (*out).sliding = l.sliding as i32;
    (*out).rolling_slip = l.rolling_slip as i32;
    V::finite3(l.force_i, l.torque_i, l.torque_j)
}
