//! When a pair becomes bonded.

use super::model::BondModel;
use super::params::BondParams;
use super::state::{BondState, BondStatus};
use crate::kinematics::{centre_line, KinematicsError, PairKinematics};

/// A pair is bonded when its centres are closer than `create_distance` and
/// either this is step `create_step` or bonds are created every step. An
/// intact bond is kept; a broken one comes back only under `create_always`.
pub fn may_create(params: &BondParams, status: BondStatus, r: f64, step: i64) -> bool {
    let allowed = match status {
        BondStatus::Intact => false,
        BondStatus::Broken => BondParams::switch(params.create_always),
        BondStatus::Unbonded => creates_at(params, step),
    };
    allowed && r < params.create_distance
}

/// Whether bonds may form at `step` at all.
pub fn creates_at(params: &BondParams, step: i64) -> bool {
    BondParams::switch(params.create_always) || step == params.create_step
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

    /// Creates the bond in `state` if the rules allow it at `step`; returns
    /// whether it did. The rest length is the current centre distance.
    pub fn try_create(
        &self,
        kin: &PairKinematics,
        step: i64,
        state: &mut BondState,
    ) -> Result<bool, KinematicsError> {
        kin.check()?;
        let line = centre_line(kin)?;
        if may_create(&self.params, state.status(), line.r, step) {
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
