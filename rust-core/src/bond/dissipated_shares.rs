//! Each atom's share of a bond's damping loads, as LIGGGHTS-INL's
//! `computeDissipatedEnergy` switch files them (docs/models/bond-linear.md,
//! "Energy"): INL's linear bond adds, every force pass, minus the damping
//! loads acting on each of its two atoms (force, then torque) to the atom's
//! per-atom `dissipated_energy` columns 2-7; a later fix of INL's, not in
//! its public source, turns such sums into energies. INL's bond/nonlinear
//! adds nothing there.

use super::laws::BondLaws;
use crate::bond_store::DAMPING_LOADS_LEN;

/// Doubles of one atom's share: minus the damping force on it, then minus
/// the damping torque on it.
pub const SHARE_LEN: usize = 6;

impl BondLaws {
    /// The shares of atoms `i` and `j` of a bond's damping loads
    /// `damping_loads` (the force on `i`, the torques on `i` and `j`; the
    /// loads of a step less those of the same step undamped), or `None`
    /// where the law files none (LIGGGHTS-INL's bond/nonlinear, `inl`).
    pub fn dissipated_shares(
        &self,
        damping_loads: &[f64; DAMPING_LOADS_LEN],
    ) -> Option<[[f64; SHARE_LEN]; 2]> {
        if self.inl && !self.linear {
            return None;
        }
        let d = damping_loads;
        // the force on j is minus the force on i
        Some([
            [-d[0], -d[1], -d[2], -d[3], -d[4], -d[5]],
            [d[0], d[1], d[2], -d[6], -d[7], -d[8]],
        ])
    }
}
