//! Several bonds per instruction: [`super::kernel::advance`] on [`Lanes`]
//! of `N` bonds, for [`BondModel::step_scattered`].
//!
//! A chunk of `N` bonds is transposed from the engine's structs into lanes
//! (one [`Lanes`] per quantity), advanced, and transposed back. Every lane
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

use std::borrow::BorrowMut;

use super::kernel::{advance, bond_step, History, Motion};
use super::model::BondModel;
use super::state::{BondOutput, BondState, BondStatus};
use crate::kinematics::{axis, separated, KinematicsError, PairKinematics};
use crate::real::{Lanes, Real};
use crate::vector::{Vector, V3};

/// Steps the bonds (as many as the shortest of the three slices hold) one
/// by one, states in place or behind pointers; an error carries the index
/// of its bond plus `first`.
#[inline(always)]
pub(crate) fn one_by_one<const F: u32, S: BorrowMut<BondState>>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [S],
    outs: &mut [BondOutput],
    first: usize,
) -> Result<(), (usize, KinematicsError)> {
    for (idx, ((k, s), o)) in kin.iter().zip(states.iter_mut()).zip(outs.iter_mut()).enumerate() {
        bond_step::<F>(model, k, dt, s.borrow_mut(), o).map_err(|e| (first + idx, e))?;
    }
    Ok(())
}

/// [`one_by_one`] in chunks of `N` lanes; the bonds after the last full
/// chunk one by one.
#[inline(always)]
pub(crate) fn in_chunks<const F: u32, const N: usize>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    let count = kin.len().min(states.len()).min(outs.len());
    let mut start = 0;
    while start + N <= count {
        let end = start + N;
        let (k, s, o) = (&kin[start..end], &mut states[start..end], &mut outs[start..end]);
        if !step_chunk::<F, N>(model, k, dt, s, o) {
            one_by_one::<F, _>(model, k, dt, s, o, start)?;
        }
        start = end;
    }
    one_by_one::<F, _>(
        model,
        &kin[start..count],
        dt,
        &mut states[start..count],
        &mut outs[start..count],
        start,
    )
}

/// Advances the `N` bonds of a chunk in lanes, or returns false without
/// touching anything when one of them is not intact or has unusable
/// kinematics.
#[inline(always)]
fn step_chunk<const F: u32, const N: usize>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> bool {
    let (kin, states, outs) = (&kin[..N], &mut states[..N], &mut outs[..N]);
    for (k, s) in kin.iter().zip(states.iter()) {
        if s.status() != BondStatus::Intact || k.check().is_err() {
            return false;
        }
    }
    let d = gather3(kin, |k| k.x_i) - gather3(kin, |k| k.x_j);
    let r2 = d.norm_squared();
    if !Lanes::all(separated(r2)) {
        return false;
    }
    let motion = Motion {
        v_i: gather3(kin, |k| k.v_i),
        v_j: gather3(kin, |k| k.v_j),
        w_i: gather3(kin, |k| k.w_i),
        w_j: gather3(kin, |k| k.w_j),
        radius_i: gather(kin, |k| k.radius_i),
        radius_j: gather(kin, |k| k.radius_j),
    };

    let mut h = History {
        r0: gather(states, |s| s.r0),
        delta_max: gather(states, |s| s.delta_max),
        delta_min: gather(states, |s| s.delta_min),
        shear_force: gather3(states, |s| s.shear_force),
        twist_angle: gather3(states, |s| s.twist_angle),
        bend_angle: gather3(states, |s| s.bend_angle),
        twist_max: gather(states, |s| s.twist_max),
        bend_max: gather(states, |s| s.bend_max),
    };
    let loads = advance::<F, Lanes<N>, V3<Lanes<N>>>(model, &motion, axis(d, r2), Lanes::splat(dt), &mut h);

    let lane = |v: &V3<Lanes<N>>, i: usize| [v.x.0[i], v.y.0[i], v.z.0[i]];
    for (i, (s, o)) in states.iter_mut().zip(outs.iter_mut()).enumerate() {
        let mode = loads.mode.0[i];
        let status = if mode == 0.0 {
            BondStatus::Intact
        } else {
            BondStatus::Broken
        };
        s.status = status as i32 as f64;
        s.delta_max = h.delta_max.0[i];
        s.delta_min = h.delta_min.0[i];
        s.shear_force = lane(&h.shear_force, i);
        s.twist_angle = lane(&h.twist_angle, i);
        s.bend_angle = lane(&h.bend_angle, i);
        s.twist_max = h.twist_max.0[i];
        s.bend_max = h.bend_max.0[i];
        o.force_i = lane(&loads.force_i, i);
        o.torque_i = lane(&loads.torque_i, i);
        o.torque_j = lane(&loads.torque_j, i);
        o.normal_force = loads.normal_force.0[i];
        o.sigma = loads.sigma.0[i];
        o.tau = loads.tau.0[i];
        o.delta = loads.delta.0[i];
        o.status = status as i32;
        o.break_mode = mode as i32;
    }
    true
}

/// One quantity of `N` items, lane `i` from `items[i]`.
#[inline(always)]
fn gather<T, const N: usize>(items: &[T], f: impl Fn(&T) -> f64) -> Lanes<N> {
    Lanes(std::array::from_fn(|i| f(&items[i])))
}

/// [`gather`] of a vector quantity.
#[inline(always)]
fn gather3<T, const N: usize>(items: &[T], f: impl Fn(&T) -> [f64; 3]) -> V3<Lanes<N>> {
    V3::new(
        gather(items, |t| f(t)[0]),
        gather(items, |t| f(t)[1]),
        gather(items, |t| f(t)[2]),
    )
}
