//! A bond step's output as engines keep it between passes: the loads of the
//! latest force pass, stored in the pair's history next to the state so
//! that passes which must not advance the bond (a run's setup pass, an
//! engine's per-contact output pass) report what was applied, and so that
//! the engine's history dumps show it.
//!
//! The slots are laid out for the engine's swap rule ([`StateSlot`]): when
//! the pair is seen from the other sphere, `force_i` becomes `-force_i`
//! and the torques trade places, so the force flips; of the torques,
//! `T_i + T_j` stays and `T_i - T_j` flips. The stresses are scalars.

use super::state::{BondOutput, BondStatus};
use super::BreakMode;
use crate::state_layout::{slot, StateSlot};

/// Number of `double` slots of a bond output as engines keep it
/// (`granbond_bond_output_store`, `GB_STATE_KIND_BOND_OUTPUT`).
pub const BOND_OUTPUT_LEN: usize = 11;

/// Names and swap rules of the stored output, in memory order.
pub const BOND_OUTPUT_SLOTS: [StateSlot; BOND_OUTPUT_LEN] = [
    slot("bond_force_x", true),
    slot("bond_force_y", true),
    slot("bond_force_z", true),
    slot("bond_torque_sum_x", false),
    slot("bond_torque_sum_y", false),
    slot("bond_torque_sum_z", false),
    slot("bond_torque_diff_x", true),
    slot("bond_torque_diff_y", true),
    slot("bond_torque_diff_z", true),
    slot("bond_sigma", false),
    slot("bond_tau", false),
];

/// The slots of `out`: `force_i`, `T_i + T_j`, `T_i - T_j`, `sigma`, `tau`.
pub fn store_output(out: &BondOutput) -> [f64; BOND_OUTPUT_LEN] {
    let (f, ti, tj) = (out.force_i, out.torque_i, out.torque_j);
    [
        f[0],
        f[1],
        f[2],
        ti[0] + tj[0],
        ti[1] + tj[1],
        ti[2] + tj[2],
        ti[0] - tj[0],
        ti[1] - tj[1],
        ti[2] - tj[2],
        out.sigma,
        out.tau,
    ]
}

/// The output [`store_output`] stored: the loads and stresses of an intact
/// bond (`T_i = (sum + diff) / 2`, `T_j = (sum - diff) / 2`), no break. The
/// slots keep neither the normal force nor `delta`: both are 0.
pub fn load_output(slots: &[f64; BOND_OUTPUT_LEN]) -> BondOutput {
    let (sum, diff) = ([slots[3], slots[4], slots[5]], [slots[6], slots[7], slots[8]]);
    BondOutput {
        force_i: [slots[0], slots[1], slots[2]],
        torque_i: std::array::from_fn(|c| 0.5 * (sum[c] + diff[c])),
        torque_j: std::array::from_fn(|c| 0.5 * (sum[c] - diff[c])),
        normal_force: 0.0,
        sigma: slots[9],
        tau: slots[10],
        delta: 0.0,
        status: BondStatus::Intact as i32,
        break_mode: BreakMode::None as i32,
    }
}
