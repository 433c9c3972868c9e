//! One bond at a time: a bond's state and kinematics into the assembled
//! step ([`super::step`]) and its loads back out.

use super::breakage::BreakMode;
use super::finite::{bond_finite, BatchResult};
use super::inl::inl_step;
use super::laws::BondLaws;
use super::linear::linear_step;
use super::state::{BondOutput, BondState, BondStatus};
use super::step::{advance, breaks_by_distance, broken_by_distance, relative, HistoryIo, MotionSource};
use super::switches::Switches;
use super::twist_bend::{BendHistory, TwistHistory};
use crate::kinematics::{centre_line, KinematicsError, PairKinematics};
use crate::pair_source::PairSource;
use crate::vector::{v3, Vec3};
use std::borrow::BorrowMut;
use std::ops::Range;

/// The outputs of a bond that exerts nothing: not intact (its state as it
/// is).
#[inline(always)]
fn finish(out: &mut BondOutput, status: BondStatus, mode: BreakMode) {
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
    mut kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    if S::LINEAR {
        return linear_step(laws, kin, dt, state, out, false, true);
    }
    if S::INL {
        return inl_step(laws, kin, dt, state, out, false, true);
    }
    let status = state.status();
    if status != BondStatus::Intact {
        *out = BondOutput::default();
        finish(out, status, BreakMode::None);
        return Ok(());
    }
    kin.check()?;
    let line = centre_line(kin)?;
    let loads = if breaks_by_distance(laws, line.r) {
        broken_by_distance(state.rest - line.r)
    } else {
        let relative = relative::<S, f64, Vec3>(laws, &mut kin, line, state.rest);
        advance::<S, f64, Vec3, _>(laws, &relative, dt, state)
    };
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
        // It exerts nothing.
        (out.force_i, out.torque_i, out.torque_j) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        state.mark_broken();
        BondStatus::Broken
    };
    out.status = status as i32;
    out.break_mode = mode as i32;
    Ok(())
}

impl MotionSource<f64, Vec3> for &PairKinematics {
    #[inline(always)]
    fn radii(&mut self) -> (f64, f64) {
        (self.radius_i, self.radius_j)
    }
    #[inline(always)]
    fn velocities(&mut self) -> (Vec3, Vec3) {
        (v3(self.v_i), v3(self.v_j))
    }
    #[inline(always)]
    fn spins(&mut self) -> (Vec3, Vec3) {
        (v3(self.w_i), v3(self.w_j))
    }
}

/// The history in place: a law switched off leaves its slots as they are.
impl HistoryIo<f64, Vec3> for BondState {
    #[inline(always)]
    fn delta_extremes(&mut self) -> (f64, f64) {
        (self.delta_max, self.delta_min)
    }
    #[inline(always)]
    fn shear_force(&mut self) -> Vec3 {
        v3(self.shear_force)
    }
    #[inline(always)]
    fn twist_angle(&mut self) -> Vec3 {
        v3(self.twist_angle)
    }
    #[inline(always)]
    fn bend_angle(&mut self) -> Vec3 {
        v3(self.bend_angle)
    }
    #[inline(always)]
    fn twist_extremes(&mut self) -> TwistHistory<f64> {
        TwistHistory {
            max: self.twist_max,
            min: self.twist_min,
        }
    }
    #[inline(always)]
    fn bend_history(&mut self) -> BendHistory<f64, Vec3> {
        BendHistory {
            leading: v3(self.bend_history),
            opposite: self.bend_opposite,
        }
    }
    #[inline(always)]
    fn put_delta_extremes(&mut self, new: Option<(f64, f64)>) {
        if let Some((max, min)) = new {
            (self.delta_max, self.delta_min) = (max, min);
        }
    }
    #[inline(always)]
    fn put_shear_force(&mut self, new: Option<Vec3>) {
        if let Some(v) = new {
            self.shear_force = v.into();
        }
    }
    #[inline(always)]
    fn put_twist_angle(&mut self, new: Option<Vec3>) {
        if let Some(v) = new {
            self.twist_angle = v.into();
        }
    }
    #[inline(always)]
    fn put_bend_angle(&mut self, new: Option<Vec3>) {
        if let Some(v) = new {
            self.bend_angle = v.into();
        }
    }
    #[inline(always)]
    fn put_twist_extremes(&mut self, new: Option<TwistHistory<f64>>) {
        if let Some(t) = new {
            (self.twist_max, self.twist_min) = (t.max, t.min);
        }
    }
    #[inline(always)]
    fn put_bend_history(&mut self, new: Option<BendHistory<f64, Vec3>>) {
        if let Some(b) = new {
            self.bend_history = b.leading.into();
            self.bend_opposite = b.opposite;
        }
    }
    /// The step's caller writes it with the other loads.
    #[inline(always)]
    fn put_force(&mut self, _: Vec3) {}
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
