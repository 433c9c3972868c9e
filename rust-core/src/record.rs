//! The record an engine keeps for each neighbour pair that has a granbond
//! model: `[contact | bond | bond loads]`. The contact part is the Voigt
//! contact's state where granbond owns the contact (LAMMPS `pair granbond`)
//! and absent where the engine's own models keep it (LIGGGHTS `cohesion
//! bond/nonlinear`). One table gives every slot's name and swap rule, and
//! [`RecordLayout`] its named offsets, so adapters restate none of them.

use crate::bond::output_slots::{BOND_OUTPUT_LEN, BOND_OUTPUT_SLOTS};
use crate::bond::state::slot_of;
use crate::bond::{BOND_SLOTS, BOND_STATE_LEN};
use crate::contact::{CONTACT_SLOTS, CONTACT_STATE_LEN};
use crate::state_layout::StateSlot;

/// Where the parts of a pair record lie, in doubles from its start.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecordLayout {
    /// The contact state: `contact_len` doubles from 0 (0 where the engine
    /// keeps the contact's state).
    pub contact_len: usize,
    /// The bond state ([`crate::bond::BondState`]).
    pub bond: usize,
    /// The bond's rest length, whose sign is its status
    /// ([`crate::bond::BondStatus::from_rest`]): what an adapter reads to
    /// know whether a pair is bonded.
    pub status: usize,
    /// The loads of the bond's latest force pass
    /// ([`crate::bond::output_slots`]).
    pub loads: usize,
    /// The whole record.
    pub len: usize,
}

/// Index of the status (the rest length's sign) in the bond state.
const STATUS_SLOT: usize = slot_of!(rest);

impl RecordLayout {
    /// The record with the Voigt contact's state first (`with_contact`) or
    /// without it.
    pub const fn new(with_contact: bool) -> Self {
        let contact_len = if with_contact { CONTACT_STATE_LEN } else { 0 };
        Self {
            contact_len,
            bond: contact_len,
            status: contact_len + STATUS_SLOT,
            loads: contact_len + BOND_STATE_LEN,
            len: contact_len + BOND_STATE_LEN + BOND_OUTPUT_LEN,
        }
    }

    /// The bond's loads part of `record`.
    pub fn loads<'r>(&self, record: &'r mut [f64]) -> &'r mut [f64; BOND_OUTPUT_LEN] {
        (&mut record[self.loads..self.loads + BOND_OUTPUT_LEN])
            .try_into()
            .expect("the loads part has BOND_OUTPUT_LEN slots")
    }
}

/// Every slot of a record, with the contact's state or without it, in memory
/// order.
pub fn record_slots(with_contact: bool) -> impl Iterator<Item = StateSlot> {
    let contact: &'static [StateSlot] = if with_contact { &CONTACT_SLOTS } else { &[] };
    contact
        .iter()
        .chain(BOND_SLOTS.iter())
        .chain(BOND_OUTPUT_SLOTS.iter())
        .copied()
}
