//! The per-contact steps of the engines' hot loops and the choice of
//! instruction set they run on, as `bond/dispatch.rs` is for bonds. Each
//! step reads the engine's memory through raw pointers (the caller vouches
//! for them), builds the [`ContactFrame`], steps the contact, stores the
//! state and loads, and answers whether the loads are finite.
//!
//! Each step is compiled twice: for the x86-64 baseline, and for AVX2,
//! run on CPUs that have it ([`Simd::chosen`], the bonds' choice too): the
//! 3-vectors fit one register instead of two, so fewer instructions per
//! contact. The same operations in the same order, and no fused
//! multiply-add (not enabled, and never formed from separate operations),
//! so the same bits on both.

use super::frame::{ContactFrame, Motion};
use super::model::VoigtModel;
use super::state::{ContactOutput, ContactState};
use crate::simd::Simd;

macro_rules! compiled_twice {
    ($(#[$doc:meta])* $vis:vis fn $base:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty $body:block) => {
        $(#[$doc])*
        // the caller only chooses (this is inlined into it); each copy is a
        // function of its own
        #[inline(always)]
        #[allow(clippy::too_many_arguments)]
        $vis unsafe fn $base($($arg: $ty),*) -> $ret {
            #[inline(always)]
            #[allow(clippy::too_many_arguments)]
            unsafe fn body($($arg: $ty),*) -> $ret $body

            #[inline(never)]
            #[allow(clippy::too_many_arguments)]
            unsafe fn baseline($($arg: $ty),*) -> $ret {
                body($($arg),*)
            }

            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2")]
            #[allow(clippy::too_many_arguments)]
            unsafe fn wide($($arg: $ty),*) -> $ret {
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

/// Whether the AVX2 copies run.
#[inline(always)]
fn avx2() -> bool {
    Simd::chosen() != Simd::Scalar
}

compiled_twice! {
    /// One step of a pair given by its separation `del` (3 doubles, read
    /// one double at a time) and `rsq = |del|^2`, with the radii
    /// ([`ContactFrame::from_separation`]; `R*` only with rolling), and the
    /// velocities (3 doubles each, read as the compiler likes). False when
    /// a load came out non-finite (non-finite input the caller let
    /// through, or input far outside the model's range).
    ///
    /// # Safety
    /// `model` valid; `del`, `v_*`, `w_*` three doubles each; `state`
    /// [`CONTACT_STATE_LEN`](super::CONTACT_STATE_LEN) doubles; `out` valid
    /// for writes.
    pub fn step_separation(
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
        let model = &*model;
        let motion = read_motion(v_i, v_j, w_i, w_j);
        let del = load3(del as *const [f64; 3]);
        let frame = ContactFrame::from_separation(del, rsq, radius_i, radius_j, model.rolling(), motion);
        step_stored(model, &frame, dt, state, out)
    }
}

compiled_twice! {
    /// [`step_separation`] of a contact given by the engine's unit normal
    /// `n` (3 doubles) and centre distance, with the radii, a wall as
    /// `radius_j = 0` ([`ContactFrame::from_normal`]; `R*` only with
    /// rolling).
    ///
    /// # Safety
    /// As [`step_separation`]; `n` three doubles.
    pub fn step_normal(
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
        let model = &*model;
        let motion = read_motion(v_i, v_j, w_i, w_j);
        let n = load3(n as *const [f64; 3]);
        let frame = ContactFrame::from_normal(n, distance, radius_i, radius_j, model.rolling(), motion);
        step_stored(model, &frame, dt, state, out)
    }
}

/// The velocities where the engine keeps them, read as the compiler likes
/// (the engine wrote them long before the call).
#[inline(always)]
unsafe fn read_motion(v_i: *const f64, v_j: *const f64, w_i: *const f64, w_j: *const f64) -> Motion {
    Motion {
        v_i: *(v_i as *const [f64; 3]),
        v_j: *(v_j as *const [f64; 3]),
        w_i: *(w_i as *const [f64; 3]),
        w_j: *(w_j as *const [f64; 3]),
    }
}

/// One step from the stored state; the state and loads are stored back,
/// and the answer is whether the loads are finite.
#[inline(always)]
unsafe fn step_stored(
    model: &VoigtModel,
    frame: &ContactFrame,
    dt: f64,
    state: *mut f64,
    out: *mut ContactOutput,
) -> bool {
    let mut s = load_state(state);
    let mut o = ContactOutput::default();
    model.step_frame(frame, dt, &mut s, &mut o);
    *(state as *mut ContactState) = s;
    *out = o;
    let loads = o.force_i.iter().chain(&o.torque_i).chain(&o.torque_j);
    // x * 0 is 0 for every finite x and NaN for NaN and infinity
    loads.fold(0.0, |sum, x| sum + x * 0.0) == 0.0
}

/// One double of a record the engine has just written. The engine writes
/// its records field by field just before the call, and the stores are
/// still in flight when the kernel starts. A 16-byte load that spans two
/// 8-byte stores cannot be served from the store buffer (store-to-load
/// forwarding fails, the load waits until both stores reach the cache),
/// and the compiler pairs neighbouring doubles into such loads at will. A
/// volatile read keeps the load exactly one double wide: it is served by
/// the store that wrote it, whatever width the engine's compiler chose.
#[inline(always)]
unsafe fn load(p: *const f64) -> f64 {
    std::ptr::read_volatile(p)
}

#[inline(always)]
unsafe fn load3(p: *const [f64; 3]) -> [f64; 3] {
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
