//! The bond store's global record in restart files: the counts and the
//! energy sums over all ranks, and the layout of the bonds' state that the
//! per-atom rows hold. The engines read a fix's global record before its
//! per-atom rows, so a file whose bonds have another layout is refused
//! before a bond is read.
//!
//! The record: its length after this field (`i64`), the counts
//! ([`StoreCounts`]), the energy sums ([`EnergySums`]), the state layout
//! version (`i64`), each in the machine's byte order.

use crate::bond_store::{EnergySums, StoreCounts};
use std::mem::size_of;

/// What follows the record's length.
const BODY_LEN: usize = size_of::<StoreCounts>() + size_of::<EnergySums>() + size_of::<i64>();

/// Bytes of the record.
pub const RECORD_LEN: usize = size_of::<i64>() + BODY_LEN;

/// The record of `counts` and `energy` (summed over the ranks), its bonds'
/// state of layout `version`.
pub fn write(counts: &StoreCounts, energy: &EnergySums, version: u32) -> [u8; RECORD_LEN] {
    let mut record = [0u8; RECORD_LEN];
    let mut at = 0;
    let mut put = |bytes: &[u8]| {
        record[at..at + bytes.len()].copy_from_slice(bytes);
        at += bytes.len();
    };
    put(&(BODY_LEN as i64).to_ne_bytes());
    let c = counts;
    for v in [
        c.created,
        c.broken_distance,
        c.broken_tension,
        c.broken_compression,
        c.broken_shear,
        c.lost_owner_gone,
        c.lost_partner_unreached,
        c.lost_id_reused,
        c.lost_no_model,
        c.intact,
    ] {
        put(&v.to_ne_bytes());
    }
    for v in [energy.damping, energy.hysteresis, energy.released] {
        put(&v.to_ne_bytes());
    }
    put(&i64::from(version).to_ne_bytes());
    record
}

/// The length a record says it has after its first field.
pub fn body_len(head: [u8; 8]) -> i64 {
    i64::from_ne_bytes(head)
}

/// Whether a record whose first field is `body_len` has this layout (and
/// so [`RECORD_LEN`] bytes).
pub fn is_current(body_len: i64) -> bool {
    body_len == BODY_LEN as i64
}

/// The counts and energy sums of a `record` of [`RECORD_LEN`] bytes, or
/// why its bonds cannot be read: written with a state layout other than
/// `version`.
pub fn read(record: &[u8; RECORD_LEN], version: u32) -> Result<(StoreCounts, EnergySums), String> {
    let i = |k: usize| i64::from_ne_bytes(record[8 * k..8 * k + 8].try_into().expect("8 bytes"));
    let f = |k: usize| f64::from_ne_bytes(record[8 * k..8 * k + 8].try_into().expect("8 bytes"));
    let layout = i(RECORD_LEN / 8 - 1);
    if layout != i64::from(version) {
        return Err(refusal(&format!("bond state layout {layout}"), version));
    }
    let counts = StoreCounts {
        created: i(1),
        broken_distance: i(2),
        broken_tension: i(3),
        broken_compression: i(4),
        broken_shear: i(5),
        lost_owner_gone: i(6),
        lost_partner_unreached: i(7),
        lost_id_reused: i(8),
        lost_no_model: i(9),
        intact: i(10),
    };
    let energy = EnergySums {
        damping: f(11),
        hysteresis: f(12),
        released: f(13),
    };
    Ok((counts, energy))
}

/// Why a record of another layout is refused: its bonds were `written`
/// with it, and this library reads layout `version`.
pub fn refusal(written: &str, version: u32) -> String {
    format!(
        "the restart file's bonds were written with {written}, and this granbond reads layout \
         {version} only: continue the run with the granbond that wrote the file, or start it \
         again from its data file or deck"
    )
}
