//! Several bonds per instruction: the assembled step ([`super::step`]) on
//! packed registers of 4 or 8 bonds ([`Pack`]).
//!
//! A chunk of bonds is transposed from the engine's structs into lanes (one
//! register per quantity), advanced, and transposed back. Every lane
//! gets the bits one [`super::scalar::bond_step`] gives its bond: the laws
//! are the same code, each lane operation is the `f64` operation (see
//! [`crate::real`]), and nothing mixes lanes, so it does not matter which
//! lane or chunk a bond lands in.
//!
//! Each register of results is checked ([`super::finite`]) while it is
//! still in registers.
//!
//! What `bond_step` decides per bond with a jump is a mask here, except
//! what is rare and has side effects of its own: a chunk with a bond that
//! is not intact or whose kinematics are unusable is left to the scalar
//! kernel, which zeroes the first kind and reports the first bad one with
//! its index.

use super::features::{BEND, COMPRESSION, SHEAR, TENSION, TWIST};
use super::finite::{bond_finite, results_finite, results_surely_finite, BatchResult};
use super::laws::BondLaws;
use super::scalar::one_by_one;
use super::state::{BondOutput, BondState, BondStatus, BOND_STATE_LEN};
use super::step::{advance, History, Motion};
use super::switches::Switches;
use super::twist_bend::{BendHistory, TwistHistory};
use crate::kinematics::{axis, separated, surely_usable};
use crate::pair_source::PairSource;
use crate::real::packed::Pack;
use crate::vector::{Vector, V3};
use std::borrow::{Borrow, BorrowMut};

/// [`one_by_one`] in chunks of `P::WIDTH` lanes; the bonds after the last full
/// chunk one by one.
#[inline(always)]
pub(crate) fn in_chunks<S: Switches, P: Pack, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
    laws: &BondLaws,
    kin: &K,
    dt: f64,
    states: &mut [T],
    outs: &mut [BondOutput],
) -> BatchResult {
    let count = kin.len().min(states.len()).min(outs.len());
    let mut first = None;
    let mut start = 0;
    while start + P::WIDTH <= count {
        let end = start + P::WIDTH;
        let found = match step_chunk::<S, P, K, T>(
            laws,
            kin,
            start,
            dt,
            &mut states[start..end],
            &mut outs[start..end],
        ) {
            // rare: which lane, from what was stored
            Some(finite) if !P::all(finite) => {
                (start..end).find(|&b| !bond_finite(states[b].borrow(), &outs[b]))
            }
            Some(_) => None,
            None => one_by_one::<S, K, T>(laws, kin, start..end, dt, states, outs)?,
        };
        first = first.or(found);
        start = end;
    }
    let found = one_by_one::<S, K, T>(laws, kin, start..count, dt, states, outs)?;
    Ok(first.or(found))
}

/// Advances the `P::WIDTH` bonds of a chunk, from bond `first` of `kin` on,
/// in lanes, and returns a mask whose lanes are all true only if every
/// bond's results are finite (a false lane leaves the caller to find which
/// bond, if any, is not); or returns `None` without touching anything when
/// one of them is not intact or its kinematics are not surely usable (the
/// scalar kernel then decides).
#[inline(always)]
fn step_chunk<S: Switches, P: Pack, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
    laws: &BondLaws,
    kin: &K,
    first: usize,
    dt: f64,
    states: &mut [T],
    outs: &mut [BondOutput],
) -> Option<P::Mask> {
    let n = P::WIDTH;
    let (states, outs) = (&mut states[..n], &mut outs[..n]);
    let kin = |lane: usize| kin.pair(first + lane);
    let (status, r0): (P, P) = gather2(states, |s: &BondState| [s.status, s.r0]);
    let intact = P::splat(BondStatus::Intact as i32 as f64);
    if !P::all(status.ge(intact) & intact.ge(status)) {
        return None;
    }
    let on = |bits| S::of(laws).any(bits);
    let (x_i, x_j) = (lanes3(kin, |k| k.x_i), lanes3(kin, |k| k.x_j));
    let (v_i, v_j) = (lanes3(kin, |k| k.v_i), lanes3(kin, |k| k.v_j));
    let (radius_i, radius_j) = (
        P::gather(|lane| kin(lane).radius_i),
        P::gather(|lane| kin(lane).radius_j),
    );
    let [a, b, c, e] = [x_i, x_j, v_i, v_j].map(|v| [v.x, v.y, v.z]);
    let zero = V3::new(P::splat(0.0), P::splat(0.0), P::splat(0.0));
    // Spins that no law switched on reads are only checked: added up as
    // they are loaded, not moved into their lanes.
    let ((w_i, w_j), (finite, positive)) = if !S::FIXED || on(SHEAR | TWIST | BEND) {
        let (w_i, w_j) = (lanes3(kin, |k| k.w_i), lanes3(kin, |k| k.w_j));
        let numbers = [a, b, c, e, [w_i.x, w_i.y, w_i.z], [w_j.x, w_j.y, w_j.z]];
        let numbers: [P; 18] = std::array::from_fn(|i| numbers[i / 3][i % 3]);
        ((w_i, w_j), surely_usable(numbers, radius_i, radius_j))
    } else {
        let spins = P::gather2_sum(|lane| [kin(lane).w_i[0], kin(lane).w_i[1]])
            + P::gather2_sum(|lane| [kin(lane).w_i[2], kin(lane).w_j[0]])
            + P::gather2_sum(|lane| [kin(lane).w_j[1], kin(lane).w_j[2]]);
        let numbers = [
            a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], e[0], e[1], e[2], spins,
        ];
        ((zero, zero), surely_usable(numbers, radius_i, radius_j))
    };
    let motion = Motion {
        v_i,
        v_j,
        w_i,
        w_j,
        radius_i,
        radius_j,
    };
    let d = x_i - x_j;
    let r2 = d.norm_squared();
    let usable = finite & positive & separated(r2);

    // The slots after the last one a law switched on uses stay in memory:
    // the step leaves them alone, and only the results check reads them.
    // (Where the bits are read at run time, a rest of varying length costs
    // more than it saves: every slot is moved.)
    let live = if S::FIXED {
        live_slots(on(SHEAR), on(TWIST), on(BEND))
    } else {
        BOND_STATE_LEN
    };
    let vector = |first: usize, f: fn(&BondState) -> [f64; 3]| {
        if first < live {
            gather3(states, f)
        } else {
            zero
        }
    };
    let scalar = |slot: usize, f: fn(&BondState) -> f64| {
        if slot < live {
            gather(states, f)
        } else {
            P::splat(0.0)
        }
    };
    let (delta_max, delta_min) = gather2(states, |s: &BondState| [s.delta_max, s.delta_min]);
    let mut h = History {
        r0,
        delta_max,
        delta_min,
        shear_force: vector(4, |s| s.shear_force),
        twist_angle: vector(7, |s| s.twist_angle),
        bend_angle: vector(10, |s| s.bend_angle),
        twist: if 13 < live {
            let (max, min) = gather2(states, |s: &BondState| [s.twist_max, s.twist_min]);
            TwistHistory { max, min }
        } else {
            TwistHistory {
                max: P::splat(0.0),
                min: P::splat(0.0),
            }
        },
        bend: BendHistory {
            leading: vector(15, |s| s.bend_history),
            opposite: scalar(18, |s| s.bend_opposite),
        },
    };
    let loads = advance::<S, P, V3<P>>(laws, &motion, axis(d, r2), P::splat(dt), &mut h);
    // Decided here rather than before the step, so that the numbers read
    // need not be held from their loads to the branch; lanes that fail it
    // computed nothing that is kept.
    if !P::all(usable) {
        return None;
    }

    // Back into the structs one quantity at a time: each register is
    // stored once and its lanes copied out.
    let broken = loads.mode.gt(P::splat(0.0));
    let status = |s: BondStatus| P::splat(s as i32 as f64);
    let status = P::select(broken, status(BondStatus::Broken), status(BondStatus::Intact));
    // The slots of a law switched off still hold what was loaded (`advance`
    // leaves them alone): they are not stored back.
    scatter(states, status, |s: &mut BondState, x| s.status = x);
    if on(TENSION | COMPRESSION) {
        scatter2(states, h.delta_max, h.delta_min, |s: &mut BondState, [hi, lo]| {
            (s.delta_max, s.delta_min) = (hi, lo)
        });
    }
    if on(SHEAR) {
        scatter3(states, h.shear_force, |s: &mut BondState| &mut s.shear_force);
    }
    if on(TWIST) {
        scatter3(states, h.twist_angle, |s: &mut BondState| &mut s.twist_angle);
        scatter2(
            states,
            h.twist.max,
            h.twist.min,
            |s: &mut BondState, [max, min]| (s.twist_max, s.twist_min) = (max, min),
        );
    }
    if on(BEND) {
        scatter3(states, h.bend_angle, |s: &mut BondState| &mut s.bend_angle);
        scatter3(states, h.bend.leading, |s: &mut BondState| &mut s.bend_history);
        scatter(states, h.bend.opposite, |s: &mut BondState, x| {
            s.bend_opposite = x
        });
    }
    scatter3(outs, loads.force_i, |o: &mut BondOutput| &mut o.force_i);
    scatter3(outs, loads.torque_i, |o: &mut BondOutput| &mut o.torque_i);
    scatter3(outs, loads.torque_j, |o: &mut BondOutput| &mut o.torque_j);
    scatter2(
        outs,
        loads.normal_force,
        loads.sigma,
        |o: &mut BondOutput, [f, s]| (o.normal_force, o.sigma) = (f, s),
    );
    scatter2(outs, loads.tau, loads.delta, |o: &mut BondOutput, [t, d]| {
        (o.tau, o.delta) = (t, d)
    });
    P::for_each_lane_codes(status, loads.mode, |i, [status, mode]| {
        (outs[i].status, outs[i].break_mode) = (status, mode)
    });

    // in the order of the slots and fields (finite.rs)
    let (f, ti, tj) = (loads.force_i, loads.torque_i, loads.torque_j);
    let (sf, ta, ba, bh) = (h.shear_force, h.twist_angle, h.bend_angle, h.bend.leading);
    let state = [
        status,
        h.r0,
        h.delta_max,
        h.delta_min,
        sf.x,
        sf.y,
        sf.z,
        ta.x,
        ta.y,
        ta.z,
        ba.x,
        ba.y,
        ba.z,
        h.twist.max,
        h.twist.min,
        bh.x,
        bh.y,
        bh.z,
        h.bend.opposite,
    ];
    let (loads, scalars) = (
        [f.x, f.y, f.z, ti.x, ti.y, ti.z, tj.x, tj.y, tj.z],
        [loads.normal_force, loads.sigma, loads.tau, loads.delta],
    );
    Some(if live == BOND_STATE_LEN {
        results_finite(loads, scalars, state)
    } else {
        results_surely_finite(loads, scalars, &state[..live], |lane| {
            &states[lane].borrow().as_slots()[live..]
        })
    })
}

/// How many slots, from the first, a step with these laws switched on
/// keeps in registers: up to the last one it changes. The rest, which it
/// leaves alone, only the results check reads, from memory (at least a
/// register's worth a bond, as it reads them a register at a time).
#[inline(always)]
fn live_slots(shear: bool, twist: bool, bend: bool) -> usize {
    if bend {
        BOND_STATE_LEN
    } else if twist {
        15
    } else if shear {
        7
    } else {
        4
    }
}

/// One quantity of `P::WIDTH` items, lane `i` from `items[i]`.
#[inline(always)]
fn gather<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> f64) -> P {
    P::gather(|i| f(items[i].borrow()))
}

/// [`gather`] of two quantities, next to each other in memory.
#[inline(always)]
fn gather2<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> [f64; 2]) -> (P, P) {
    P::gather2(|i| f(items[i].borrow()))
}

/// [`gather`] of a vector quantity.
#[inline(always)]
fn gather3<T, S: Borrow<T>, P: Pack>(items: &[S], f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    lanes3(|i| items[i].borrow(), |t| f(t))
}

/// A vector quantity of `P::WIDTH` items, lane `i` from `item(i)`.
#[inline(always)]
fn lanes3<T, P: Pack>(item: impl Fn(usize) -> T, f: impl Fn(&T) -> [f64; 3]) -> V3<P> {
    let (x, y) = P::gather2(|i| {
        let v = f(&item(i));
        [v[0], v[1]]
    });
    V3::new(x, y, P::gather(|i| f(&item(i))[2]))
}

/// Lane `i` of `v` into `items[i]`.
#[inline(always)]
fn scatter<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], v: P, mut f: impl FnMut(&mut T, f64)) {
    v.for_each_lane(|i, x| f(items[i].borrow_mut(), x));
}

/// [`scatter`] of two quantities.
#[inline(always)]
fn scatter2<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], a: P, b: P, mut f: impl FnMut(&mut T, [f64; 2])) {
    P::for_each_lane2(a, b, |i, pair| f(items[i].borrow_mut(), pair));
}

/// [`scatter`] of a vector quantity.
#[inline(always)]
fn scatter3<T, S: BorrowMut<T>, P: Pack>(items: &mut [S], v: V3<P>, f: impl Fn(&mut T) -> &mut [f64; 3]) {
    P::for_each_lane2(v.x, v.y, |i, [x, y]| {
        let v = f(items[i].borrow_mut());
        (v[0], v[1]) = (x, y)
    });
    v.z.for_each_lane(|i, z| f(items[i].borrow_mut())[2] = z);
}
