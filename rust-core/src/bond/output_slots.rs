//! A bond step's output as engines keep it between passes: the loads of the
//! latest force pass, stored in the pair's record next to the state so
//! that passes which must not advance the bond (a run's setup pass, an
//! engine's per-contact output pass) apply exactly what the force pass
//! applied, and so that the engine's history dumps show it.
//!
//! The slots are laid out for the engines' swap rule ([`StateSlot`]), which
//! can only change signs: when the pair is seen from the other sphere,
//! `force_i` becomes `-force_i` and the two torques trade places. So the
//! torques are kept as they were computed, sphere 1's and sphere 2's, and
//! `side` (+1 when written) flips with the force: it says which of the two
//! is the torque on the sphere that reads the record. No arithmetic is done
//! on the way, so a load read back is bit for bit the load applied.

use super::state::{BondOutput, BondStatus};
use super::BreakMode;
use crate::state_layout::{slot, StateSlot};

/// Number of `double` slots of a bond output as engines keep it
/// (`granbond_bond_output_store`, `GB_STATE_KIND_BOND_OUTPUT`).
pub const BOND_OUTPUT_LEN: usize = 12;

/// Where the side flag lies in the stored output.
const SIDE: usize = 9;

/// Names and swap rules of the stored output, in memory order.
pub const BOND_OUTPUT_SLOTS: [StateSlot; BOND_OUTPUT_LEN] = [
    slot("bond_force_x", true),
    slot("bond_force_y", true),
    slot("bond_force_z", true),
    slot("bond_torque_1_x", false),
    slot("bond_torque_1_y", false),
    slot("bond_torque_1_z", false),
    slot("bond_torque_2_x", false),
    slot("bond_torque_2_y", false),
    slot("bond_torque_2_z", false),
    slot("bond_side", true),
    slot("bond_sigma", false),
    slot("bond_tau", false),
];

/// The slots of `out`: `force_i`, `T_i` (sphere 1), `T_j` (sphere 2),
/// side +1, `sigma`, `tau`.
pub fn store_output(out: &BondOutput) -> [f64; BOND_OUTPUT_LEN] {
    let (f, ti, tj) = (out.force_i, out.torque_i, out.torque_j);
    [
        f[0], f[1], f[2], ti[0], ti[1], ti[2], tj[0], tj[1], tj[2], 1.0, out.sigma, out.tau,
    ]
}

/// The output [`store_output`] stored, as the sphere reading it sees it:
/// the loads and stresses of an intact bond, no break. Where `side` is
/// negative the record was swapped, and sphere 2's torque is this sphere's.
/// The slots keep neither the normal force nor `delta`: both are 0.
pub fn load_output(slots: &[f64; BOND_OUTPUT_LEN]) -> BondOutput {
    let t1 = [slots[3], slots[4], slots[5]];
    let t2 = [slots[6], slots[7], slots[8]];
    let (torque_i, torque_j) = if slots[SIDE] < 0.0 { (t2, t1) } else { (t1, t2) };
    BondOutput {
        force_i: [slots[0], slots[1], slots[2]],
        torque_i,
        torque_j,
        normal_force: 0.0,
        sigma: slots[10],
        tau: slots[11],
        delta: 0.0,
        status: BondStatus::Intact as i32,
        break_mode: BreakMode::None as i32,
    }
}
