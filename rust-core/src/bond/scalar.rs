//! One bond at a time: a bond's state and kinematics into the assembled
//! step ([`super::step`]) and its loads back out.

use super::breakage::BreakMode;
use super::features::{BEND, COMPRESSION, SHEAR, TENSION, TWIST};
use super::finite::{bond_finite, BatchResult};
use super::laws::BondLaws;
use super::state::{BondOutput, BondState, BondStatus};
use super::step::{advance, History, Motion};
use super::switches::Switches;
use super::twist_bend::{BendHistory, TwistHistory};
use crate::kinematics::{centre_line, KinematicsError, PairKinematics};
use crate::pair_source::PairSource;
use crate::vector::{v3, Vec3};
use std::borrow::BorrowMut;
use std::ops::Range;

#[inline(always)]
fn finish(state: &mut BondState, out: &mut BondOutput, status: BondStatus, mode: BreakMode) {
    state.status = status as i32 as f64;
    out.force_i = [0.0; 3];
    out.torque_i = [0.0; 3];
    out.torque_j = [0.0; 3];
    out.status = status as i32;
    out.break_mode = mode as i32;
}

/// Advances one bond by `dt` and writes the loads on both spheres. A bond
/// that is not intact, or breaks in this step, exerts nothing.
#[inline(always)]
pub(crate) fn bond_step<S: Switches>(
    laws: &BondLaws,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    let status = state.status();
    if status != BondStatus::Intact {
        *out = BondOutput::default();
        finish(state, out, status, BreakMode::None);
        return Ok(());
    }
    kin.check()?;
    let line = centre_line(kin)?;
    let motion = Motion {
        v_i: v3(kin.v_i),
        v_j: v3(kin.v_j),
        w_i: v3(kin.w_i),
        w_j: v3(kin.w_j),
        radius_i: kin.radius_i,
        radius_j: kin.radius_j,
    };
    let mut history = History {
        r0: state.r0,
        delta_max: state.delta_max,
        delta_min: state.delta_min,
        shear_force: v3(state.shear_force),
        twist_angle: v3(state.twist_angle),
        bend_angle: v3(state.bend_angle),
        twist: TwistHistory {
            max: state.twist_max,
            min: state.twist_min,
        },
        bend: BendHistory {
            leading: v3(state.bend_history),
            opposite: state.bend_opposite,
        },
    };
    let loads = advance::<S, f64, Vec3>(laws, &motion, line, dt, &mut history);
    // The slots of a law switched off are left as they are (as `advance`
    // leaves them).
    let on = |bits| S::of(laws).any(bits);
    if on(TENSION | COMPRESSION) {
        state.delta_max = history.delta_max;
        state.delta_min = history.delta_min;
    }
    if on(SHEAR) {
        state.shear_force = history.shear_force.into();
    }
    if on(TWIST) {
        state.twist_angle = history.twist_angle.into();
        state.twist_max = history.twist.max;
        state.twist_min = history.twist.min;
    }
    if on(BEND) {
        state.bend_angle = history.bend_angle.into();
        state.bend_history = history.bend.leading.into();
        state.bend_opposite = history.bend.opposite;
    }
    out.delta = loads.delta;
    out.normal_force = loads.normal_force;
    out.sigma = loads.sigma;
    out.tau = loads.tau;
    out.force_i = loads.force_i.into();
    out.torque_i = loads.torque_i.into();
    out.torque_j = loads.torque_j.into();
    let mode = BreakMode::from_number(loads.mode);
    let status = if mode == BreakMode::None {
        BondStatus::Intact
    } else {
        BondStatus::Broken
    };
    state.status = status as i32 as f64;
    out.status = status as i32;
    out.break_mode = mode as i32;
    Ok(())
}

/// Steps bonds `range` one by one, states in place or behind pointers,
/// checking each bond's results as it goes ([`BatchResult`]).
#[inline(always)]
pub(crate) fn one_by_one<S: Switches, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
    laws: &BondLaws,
    kin: &K,
    range: Range<usize>,
    dt: f64,
    states: &mut [T],
    outs: &mut [BondOutput],
) -> BatchResult {
    let mut first = None;
    for b in range {
        let state = states[b].borrow_mut();
        bond_step::<S>(laws, &kin.pair(b), dt, state, &mut outs[b]).map_err(|e| (b, e))?;
        if first.is_none() && !bond_finite(state, &outs[b]) {
            first = Some(b);
        }
    }
    Ok(first)
}

/// All bonds of `kin` (as many as the shortest of the three holds) one by
/// one.
#[inline(always)]
pub(crate) fn all_one_by_one<S: Switches, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
    laws: &BondLaws,
    kin: &K,
    dt: f64,
    states: &mut [T],
    outs: &mut [BondOutput],
) -> BatchResult {
    let count = kin.len().min(states.len()).min(outs.len());
    one_by_one::<S, K, T>(laws, kin, 0..count, dt, states, outs)
}
