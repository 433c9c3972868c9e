//! Run-time description of the state arrays, for adapters that register
//! them with their engine (names for restart files and dumps, swap rules
//! for the engine's history transfer).

use super::entry;
use super::error::{Failure, Status};
use super::guard::reference_mut;
use crate::bond::output_slots::BOND_OUTPUT_SLOTS;
use crate::bond::{BOND_SLOTS, WALL_BOND_SLOTS};
use crate::contact::CONTACT_SLOTS;
use crate::state_layout::StateSlot;
use std::ffi::{c_char, CString};
use std::sync::OnceLock;

/// Which state array.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateKind {
    /// A bond between two spheres (`GRANBOND_BOND_STATE_LEN` slots).
    Bond = 0,
    /// A bond to a wall (`GRANBOND_WALL_BOND_STATE_LEN` slots).
    WallBond = 1,
    /// A Voigt contact (`GRANBOND_CONTACT_STATE_LEN` slots).
    Contact = 2,
    /// A bond step's output as an engine keeps it in the pair's history
    /// (`granbond_bond_output_store`).
    BondOutput = 3,
}

fn slots(kind: StateKind) -> &'static [StateSlot] {
    match kind {
        StateKind::Bond => &BOND_SLOTS,
        StateKind::WallBond => &WALL_BOND_SLOTS,
        StateKind::Contact => &CONTACT_SLOTS,
        StateKind::BondOutput => &BOND_OUTPUT_SLOTS,
    }
}

fn c_names(kind: StateKind) -> &'static [CString] {
    static TABLES: [OnceLock<Vec<CString>>; 4] = [const { OnceLock::new() }; 4];
    TABLES[kind as usize].get_or_init(|| {
        slots(kind)
            .iter()
            .map(|s| CString::new(s.name).expect("slot names have no NUL"))
            .collect()
    })
}

/// A `GbStateKind` value as the caller passes it.
fn state_kind(raw: i32, _name: &str) -> Result<StateKind, Failure> {
    match raw {
        0 => Ok(StateKind::Bond),
        1 => Ok(StateKind::WallBond),
        2 => Ok(StateKind::Contact),
        3 => Ok(StateKind::BondOutput),
        _ => Err(Failure::new(
            Status::InvalidArgument,
            format!("unknown state kind {raw}"),
        )),
    }
}

/// Number of `double` slots in a state array of `kind` (a `GbStateKind`
/// value; 0 for an unknown kind).
#[entry(or = 0, kind: state_kind)]
#[no_mangle]
pub extern "C" fn granbond_state_len(kind: i32) -> usize {
    slots(kind).len()
}

/// Name of slot `index` of state `kind` (a `GbStateKind`; static storage) and whether it changes sign when
/// the pair is seen from the other sphere (1) or is copied unchanged (0).
///
/// # Safety
/// `name` and `flips_on_swap` must be null or valid for writes.
#[entry(kind: state_kind, name: reference_mut, flips_on_swap: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_state_slot(
    kind: i32,
    index: usize,
    name: *mut *const c_char,
    flips_on_swap: *mut i32,
) -> Status {
    let table = slots(kind);
    if index >= table.len() {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!(
                "slot index {index} out of range (state has {} slots)",
                table.len()
            ),
        ));
    }
    *name = c_names(kind)[index].as_ptr();
    *flips_on_swap = table[index].flips_on_swap as i32;
    Ok(())
}
