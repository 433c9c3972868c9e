//! When a bond step's results count as finite. The checked C entries refuse
//! results that are not (`ffi::results`); the batch steps apply the rule as
//! they go, one bond or one register of bonds at a time, so no second pass
//! reads the results again.

use super::state::{BondOutput, BondState, BOND_STATE_LEN};
use crate::kinematics::KinematicsError;
#[cfg(target_arch = "x86_64")]
use crate::real::packed::Pack;
use crate::real::Real;

/// What a batch step answers: `Ok(first)`, where `first` is the first bond
/// whose results are not finite ([`results_finite`]), if any (every bond
/// advanced); `Err((bond, e))` for the first bond whose kinematics are
/// unusable (the bonds after it not advanced).
pub type BatchResult = Result<Option<usize>, (usize, KinematicsError)>;

/// Whether a bond step's loads (`force_i`, `torque_i`, `torque_j`), its
/// scalars (`normal_force`, `sigma`, `tau`, `delta`) and its state slots are
/// finite, per lane. One add per value, as the check runs on the engines'
/// hot paths: a value of infinity or NaN makes its group's sum non-finite;
/// so do finite values so large that their sum overflows (beyond 1e308),
/// which are as far outside any physical range. The sums run left to right
/// in every lane, so a lane decides as the scalar check does.
#[inline(always)]
pub fn results_finite<R: Real>(loads: [R; 9], scalars: [R; 4], state: [R; BOND_STATE_LEN]) -> R::Mask {
    results_finite_summed(sum(&loads), scalars, sum(&state))
}

/// [`results_finite`] given the sums of the loads and of the state's
/// slots, each added left to right in their order (by a step that adds
/// each as it writes it).
#[inline(always)]
pub(crate) fn results_finite_summed<R: Real>(loads_sum: R, scalars: [R; 4], state_sum: R) -> R::Mask {
    is_finite(loads_sum + sum(&scalars)) & is_finite(state_sum)
}

/// Whether [`results_finite`] holds for every lane of a register of bonds
/// whose loads add up, left to right in their order, to `loads_sum`, whose
/// first state slots add up so to `head_sum` and whose other slots are
/// read from `rest(lane)`: all lanes
/// true only if it does. The rest is not added
/// lane by lane in order: the step proves its sums finite with a bound
/// instead (the first slots' sum and all the rest's magnitudes together
/// under a quarter of the largest double each: no sum of them in any order
/// then reaches it), and a lane false only asks the caller to decide with
/// [`bond_finite`] (values near the bound, or not finite).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) fn results_surely_finite<'a, P: Pack>(
    loads_sum: P,
    scalars: [P; 4],
    head_sum: P,
    rest: impl Fn(usize) -> &'a [f64],
) -> P::Mask {
    let outputs = loads_sum + sum(&scalars);
    let bound = P::splat(f64::MAX / 4.0);
    let head = head_sum.abs().lt(bound);
    let mut magnitudes = P::splat(0.0);
    for lane in 0..P::WIDTH {
        magnitudes = add_magnitudes(magnitudes, rest(lane));
    }
    // Each lane of `magnitudes` sums a quarter or so of the magnitudes; the
    // bound on each keeps their total, and so every bond's, under the
    // largest double.
    let bound = P::splat(f64::MAX / (4 * P::WIDTH) as f64);
    is_finite(outputs) & head & P::mask(P::all(magnitudes.lt(bound)))
}

/// `acc` plus the magnitudes of `row` loaded `P::WIDTH` at a time, the last
/// register ending with the row (so it may repeat some numbers of the one
/// before): every number counted at least once, none read from beyond the
/// row.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn add_magnitudes<P: Pack>(mut acc: P, row: &[f64]) -> P {
    let n = P::WIDTH;
    assert!(row.is_empty() || row.len() >= n, "a rest shorter than a register");
    let mut start = 0;
    while start < row.len() {
        acc = acc + P::load(&row[start.min(row.len() - n)..]).abs();
        start += n;
    }
    acc
}

/// [`results_finite`] of one bond.
#[inline(always)]
pub fn bond_finite(state: &BondState, o: &BondOutput) -> bool {
    let (f, ti, tj) = (o.force_i, o.torque_i, o.torque_j);
    let loads = [f[0], f[1], f[2], ti[0], ti[1], ti[2], tj[0], tj[1], tj[2]];
    results_finite(
        loads,
        [o.normal_force, o.sigma, o.tau, o.delta],
        *state.as_slots(),
    )
}

#[inline(always)]
fn sum<R: Real>(values: &[R]) -> R {
    values[1..].iter().fold(values[0], |acc, &x| acc + x)
}

/// `x - x` is `+0` for a finite `x` and NaN otherwise.
#[inline(always)]
#[allow(clippy::eq_op)]
fn is_finite<R: Real>(x: R) -> R::Mask {
    (x - x).ge(R::splat(0.0))
}
