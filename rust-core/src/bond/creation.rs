//! When a pair becomes bonded.

use super::model::BondModel;
use super::params::BondParams;
use super::state::{BondState, BondStatus};
use crate::kinematics::{centre_line, KinematicsError, PairKinematics};

/// A pair is bonded when its centres are closer than `create_distance` and
/// either this is step `create_step` or bonds are created every step. An
/// intact bond is kept; a broken one comes back only under `create_always`.
pub fn may_create(params: &BondParams, status: BondStatus, r: f64, step: i64) -> bool {
    status_and_step_allow(params, status, step) && r < params.create_distance
}

/// The part of [`may_create`] that needs no kinematics.
pub fn status_and_step_allow(params: &BondParams, status: BondStatus, step: i64) -> bool {
    match status {
        BondStatus::Intact => false,
        BondStatus::Broken => BondParams::switch(params.create_always),
        BondStatus::Unbonded => creates_at(params, step),
    }
}

/// Whether bonds may form at `step` at all.
pub fn creates_at(params: &BondParams, step: i64) -> bool {
    BondParams::switch(params.create_always) || step == params.create_step
}

/// The centre distance within which a pair may bond at `from_step` or any
/// later step: `create_distance` while a creation step lies ahead (or under
/// `create_always`), 0 after it. Engines that search for pairs to bond need
/// look no farther.
pub fn creation_reach(params: &BondParams, from_step: i64) -> f64 {
    if BondParams::switch(params.create_always) || from_step <= params.create_step {
        params.create_distance
    } else {
        0.0
    }
}

/// Bonds formed by an engine's own rule (e.g. the spheres of one clump
/// inserted with `bonded yes`) skip the step rule but keep the others: an
/// intact bond is kept, and the centres must be closer than
/// `create_distance`.
pub fn may_create_now(params: &BondParams, status: BondStatus, r: f64) -> bool {
    status != BondStatus::Intact && r < params.create_distance
}

impl BondModel {
    /// Whether bonds may form at `step` (callers skip the pair search
    /// otherwise).
    pub fn creates_at(&self, step: i64) -> bool {
        creates_at(&self.params, step)
    }

    /// [`creation_reach`] of this model's parameters.
    pub fn creation_reach(&self, from_step: i64) -> f64 {
        creation_reach(&self.params, from_step)
    }

    /// Creates the bond in `state` if the rules allow it at `step`; returns
    /// whether it did. The rest length is the current centre distance.
    pub fn try_create(
        &self,
        kin: &PairKinematics,
        step: i64,
        state: &mut BondState,
    ) -> Result<bool, KinematicsError> {
        // Engines call this for every pair every step: decide what the
        // status and step allow before touching the kinematics (an intact
        // bond, the common case, costs one comparison).
        let status = state.status();
        if !status_and_step_allow(&self.params, status, step) {
            return Ok(false);
        }
        kin.check()?;
        let line = centre_line(kin)?;
        if may_create(&self.params, status, line.r, step) {
            *state = BondState::created(line.r);
            Ok(true)
        } else {
            Ok(false)
        }
    }

    /// Creates the bond now if the pair is unbonded (or broken) and closer
    /// than `create_distance`, whatever the step; returns whether it did.
    pub fn create_now(&self, kin: &PairKinematics, state: &mut BondState) -> Result<bool, KinematicsError> {
        kin.check()?;
        let line = centre_line(kin)?;
        if may_create_now(&self.params, state.status(), line.r) {
            *state = BondState::created(line.r);
            Ok(true)
        } else {
            Ok(false)
        }
    }
}
