//! When a pair becomes bonded.

use super::model::BondModel;
use super::params::BondParams;
use super::state::{BondState, BondStatus};
use crate::kinematics::{centre_line, KinematicsError, PairKinematics};

/// A pair is bonded when its centres are closer than `create_distance` and
/// either this is step `create_step` or bonds are created every step. An
/// intact bond is kept; a broken one comes back only under `create_always`.
pub fn may_create(params: &BondParams, status: BondStatus, r: f64, step: i64) -> bool {
    let always = BondParams::switch(params.create_always);
    let allowed = match status {
        BondStatus::Intact => false,
        BondStatus::Broken => always,
        BondStatus::Unbonded => always || step == params.create_step,
    };
    allowed && r < params.create_distance
}

impl BondModel {
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
}
