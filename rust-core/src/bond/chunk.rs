//! Several bonds per instruction: [`super::kernel::advance`] on packed
//! registers of 4 or 8 bonds ([`Pack`]), for [`BondModel::step_scattered`].
//!
//! A chunk of bonds is transposed from the engine's structs into lanes (one
//! register per quantity), advanced, and transposed back. Every lane
//! gets the bits one [`super::kernel::bond_step`] gives its bond: the laws
//! are the same code, each lane operation is the `f64` operation (see
//! [`crate::real`]), and nothing mixes lanes, so it does not matter which
//! lane or chunk a bond lands in.
//!
//! What `bond_step` decides per bond with a jump is a mask here, except
//! what is rare and has side effects of its own: a chunk with a bond that
//! is not intact or whose kinematics are unusable is left to the scalar
//! kernel, which zeroes the first kind and reports the first bad one with
//! its index.

use super::kernel::bond_step;
use super::model::BondModel;
use super::state::{BondOutput, BondState};
use crate::kinematics::KinematicsError;
use crate::pair_source::PairSource;
use std::borrow::BorrowMut;
use std::ops::Range;
#[cfg(target_arch = "x86_64")]
use {
    super::kernel::{advance, History, Motion},
    super::state::BondStatus,
    super::twist_bend::{BendHistory, TwistHistory},
    crate::kinematics::{axis, separated, usable},
    crate::real::packed::Pack,
    crate::vector::{Vector, V3},
};

/// Steps bonds `range` one by one, states in place or behind pointers; an
/// error carries the index of its bond.
#[inline(always)]
pub(crate) fn one_by_one<const F: u32, K: PairSource + ?Sized, S: BorrowMut<BondState>>(
    model: &BondModel,
    kin: &K,
    range: Range<usize>,
    dt: f64,
    states: &mut [S],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    for b in range {
        bond_step::<F>(model, &kin.pair(b), dt, states[b].borrow_mut(), &mut outs[b]).map_err(|e| (b, e))?;
    }
    Ok(())
}

/// All bonds of `kin` (as many as the shortest of the three holds) one by
/// one.
#[inline(always)]
pub(crate) fn all_one_by_one<const F: u32, K: PairSource + ?Sized, S: BorrowMut<BondState>>(
    model: &BondModel,
    kin: &K,
    dt: f64,
    states: &mut [S],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    let count = kin.len().min(states.len()).min(outs.len());
    one_by_one::<F, K, S>(model, kin, 0..count, dt, states, outs)
}

/// [`one_by_one`] in chunks of `P::WIDTH` lanes; the bonds after the last full
/// chunk one by one.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) fn in_chunks<const F: u32, P: Pack, K: PairSource + ?Sized>(
    model: &BondModel,
    kin: &K,
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    let count = kin.len().min(states.len()).min(outs.len());
    let mut start = 0;
    while start + P::WIDTH <= count {
        let end = start + P::WIDTH;
        if !step_chunk::<F, P, K>(
            model,
            kin,
            start,
            dt,
            &mut states[start..end],
            &mut outs[start..end],
        ) {
            one_by_one::<F, K, _>(model, kin, start..end, dt, states, outs)?;
        }
        start = end;
    }
    one_by_one::<F, K, _>(model, kin, start..count, dt, states, outs)
}

/// Advances the `P::WIDTH` bonds of a chunk, from bond `first` of `kin` on,
/// in lanes, or returns false without touching anything when one of them is
/// not intact or has unusable kinematics.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn step_chunk<const F: u32, P: Pack, K: PairSource + ?Sized>(
    model: &BondModel,
    kin: &K,
    first: usize,
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> bool {
    let n = P::WIDTH;
    let (states, outs) = (&mut states[..n], &mut outs[..n]);
    let kin = |lane: usize| kin.pair(first + lane);
    if states.iter().any(|s| s.status() != BondStatus::Intact) {
        return false;
    }
    let (x_i, x_j) = (lanes3(kin, |k| k.x_i), lanes3(kin, |k| k.x_j));
    let motion = Motion {
        v_i: lanes3(kin, |k| k.v_i),
        v_j: lanes3(kin, |k| k.v_j),
        w_i: lanes3(kin, |k| k.w_i),
        w_j: lanes3(kin, |k| k.w_j),
        radius_i: P::gather(|lane| kin(lane).radius_i),
        radius_j: P::gather(|lane| kin(lane).radius_j),
    };
    let m = &motion;
    let vectors = [x_i, x_j, m.v_i, m.v_j, m.w_i, m.w_j].map(|v| [v.x, v.y, v.z]);
    let (finite, positive) = usable(vectors, m.radius_i, m.radius_j);
    let d = x_i - x_j;
    let r2 = d.norm_squared();
    if !P::all(finite & positive & separated(r2)) {
        return false;
    }

    let mut h = History {
        r0: gather(states, |s| s.r0),
        delta_max: gather(states, |s| s.delta_max),
        delta_min: gather(states, |s| s.delta_min),
        shear_force: gather3(states, |s| s.shear_force),
        twist_angle: gather3(states, |s| s.twist_angle),
        bend_angle: gather3(states, |s| s.bend_angle),
        twist: TwistHistory {
            max: gather(states, |s| s.twist_max),
            min: gather(states, |s| s.twist_min),
        },
        bend: BendHistory {
            leading: gather3(states, |s| s.bend_history),
            opposite: gather(states, |s| s.bend_opposite),
        },
    };
    let loads = advance::<F, P, V3<P>>(model, &motion, axis(d, r2), P::splat(dt), &mut h);

    // Back into the structs one quantity at a time: each register is
    // stored once and its lanes copied out.
    let broken = loads.mode.gt(P::splat(0.0));
    let status = |s: BondStatus| P::splat(s as i32 as f64);
    let status = P::select(broken, status(BondStatus::Broken), status(BondStatus::Intact));
    scatter(states, status, |s, x| s.status = x);
    scatter(states, h.delta_max, |s, x| s.delta_max = x);
    scatter(states, h.delta_min, |s, x| s.delta_min = x);
    scatter3(states, h.shear_force, |s| &mut s.shear_force);
    scatter3(states, h.twist_angle, |s| &mut s.twist_angle);
    scatter3(states, h.bend_angle, |s| &mut s.bend_angle);
    scatter(states, h.twist.max, |s, x| s.twist_max = x);
    scatter(states, h.twist.min, |s, x| s.twist_min = x);
    scatter3(states, h.bend.leading, |s| &mut s.bend_history);
    scatter(states, h.bend.opposite, |s, x| s.bend_opposite = x);
    scatter3(outs, loads.force_i, |o| &mut o.force_i);
    scatter3(outs, loads.torque_i, |o| &mut o.torque_i);
    scatter3(outs, loads.torque_j, |o| &mut o.torque_j);
    scatter(outs, loads.normal_force, |o, x| o.normal_force = x);
    scatter(outs, loads.sigma, |o, x| o.sigma = x);
    scatter(outs, loads.tau, |o, x| o.tau = x);
    scatter(outs, loads.delta, |o, x| o.delta = x);
    scatter(outs, status, |o, x| o.status = x as i32);
    scatter(outs, loads.mode, |o, x| o.break_mode = x as i32);
    true
}

/// One quantity of `P::WIDTH` items, lane `i` from `items[i]`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn gather<T, P: Pack>(items: &[T], f: impl Fn(&T) -> f64) -> P {
    P::gather(|i| f(&items[i]))
}

/// [`gather`] of a vector quantity.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn gather3<T, P: Pack>(items: &[T], f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    lanes3(|i| &items[i], |t| f(t))
}

/// A vector quantity of `P::WIDTH` items, lane `i` from `item(i)`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lanes3<T, P: Pack>(item: impl Fn(usize) -> T, f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    V3::new(
        P::gather(|i| f(&item(i))[0]),
        P::gather(|i| f(&item(i))[1]),
        P::gather(|i| f(&item(i))[2]),
    )
}

/// Lane `i` of `v` into `items[i]`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn scatter<T, P: Pack>(items: &mut [T], v: P, mut f: impl FnMut(&mut T, f64)) {
    v.for_each_lane(|i, x| f(&mut items[i], x));
}

/// [`scatter`] of a vector quantity.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn scatter3<T, P: Pack>(items: &mut [T], v: V3<P>, f: impl Fn(&mut T) -> &mut [f64; 3]) {
    v.x.for_each_lane(|i, x| f(&mut items[i])[0] = x);
    v.y.for_each_lane(|i, y| f(&mut items[i])[1] = y);
    v.z.for_each_lane(|i, z| f(&mut items[i])[2] = z);
}
