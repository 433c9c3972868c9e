//! `extern "C"` surface of the ledger (`crate::ledger`): what both engines
//! count, warn about and log for their bonds. The adapters sum numbers
//! over their ranks, gather the break events and the store check's keys,
//! and print or write what these entries compose.

use super::abi::GRANBOND_STATE_LAYOUT_VERSION;
use super::checks::CheckReport;
use super::deck::{text, word_list};
use super::entry;
use super::error::{Failure, Status};
use super::fields::record_fields;
use super::guard::{
    array, array_mut, finite_vector3, non_negative, positive, reference, reference_mut, slice, slice_mut,
};
use super::store::{ids as id_list, AtomIds};
use crate::bond::fields::BOND_ENERGY_FIELD_COUNT;
use crate::bond::output_slots::BOND_OUTPUT_LEN;
use crate::bond::{BondModel, BondOutput, BOND_STATE_LEN};
use crate::bond_store::{BondStore, EnergySums, StoreCounts, WallStore};
use crate::ledger::break_log::{self, BreakEvent};
use crate::ledger::check::{findings, flag_finding, pair_keys, wall_keys, Keys};
use crate::ledger::columns::BondColumns;
use crate::ledger::record::{self, RECORD_LEN};
use crate::ledger::run_checks::{thin_periodic_box, PeriodicBox};
use crate::ledger::{counts_row, notice, Notice, COUNTS_ROW_LEN};
use std::ffi::c_char;

/// Bytes a line of the break log takes at most, newline included
/// (`granbond_break_log_text`).
pub const GRANBOND_BREAK_LOG_LINE_LEN: usize = 256;
const _: () = assert!(GRANBOND_BREAK_LOG_LINE_LEN == break_log::LINE_LEN);

/// Bytes of the bond store's record in restart files
/// (`granbond_store_record_write`).
pub const GRANBOND_STORE_RECORD_LEN: usize = 120;
const _: () = assert!(GRANBOND_STORE_RECORD_LEN == RECORD_LEN);

/// Values of `granbond_store_counts_row`.
pub const GRANBOND_COUNTS_ROW_LEN: usize = 8;
const _: () = assert!(GRANBOND_COUNTS_ROW_LEN == COUNTS_ROW_LEN);

/// `granbond_ledger_notice`: LIGGGHTS pair bonds lost by a link, counts
/// by cause (owner gone, partner unreached, id reused, no model).
pub const GRANBOND_NOTICE_PAIRS_LOST_LIGGGHTS: i32 = 0;
/// LAMMPS `pair_style granbond`'s bonds lost by a link, counts as above.
pub const GRANBOND_NOTICE_PAIRS_LOST_LAMMPS: i32 = 1;
/// LIGGGHTS wall bonds lost (the sphere left the system, left the wall's
/// reach, its id taken over); `name` the wall fix's id.
pub const GRANBOND_NOTICE_WALL_LOST_LIGGGHTS: i32 = 2;
/// LAMMPS `bond_style granbond`'s bonds that left the topology (with their
/// atom, to a new atom under an old id, by `delete_bonds`).
pub const GRANBOND_NOTICE_TOPOLOGY_LEFT_LAMMPS: i32 = 3;
/// LIGGGHTS intact bonds dropped with the model that held them
/// (`counts[0]`).
pub const GRANBOND_NOTICE_DROPPED_LIGGGHTS: i32 = 4;
/// Atoms whose ids changed while bonds exist (`counts[0]`); `name` the
/// style.
pub const GRANBOND_NOTICE_RENUMBERED: i32 = 5;

/// The store's counts as the engines' count computes give them, written to
/// `row` (`GRANBOND_COUNTS_ROW_LEN` doubles): created, broken, intact,
/// broken by distance, tension, compression and shear, lost.
///
/// # Safety
/// `counts` must be null or a `GbStoreCounts`; `row` null or valid for
/// `GRANBOND_COUNTS_ROW_LEN` doubles.
#[entry(counts: reference, row: array_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_store_counts_row(counts: *const StoreCounts, row: *mut f64) -> Status {
    *row = counts_row(counts);
    Ok(())
}

/// The warning `notice` (a `GRANBOND_NOTICE_*`) for `counts` (4 numbers,
/// summed over the ranks, none negative; the notice says which it reads) at
/// time step `step`, written to `out`: level 1 and the message, or level 0
/// and no message when no bond is concerned. `name` (the wall fix's id, or
/// the style) is read by the notices that say so, and may be null for the
/// others.
///
/// # Safety
/// `counts` must be null or 4 `int64_t`; `name` null or a NUL-terminated
/// string; `out` null or valid for writes.
#[entry(counts: slice(4), out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_ledger_notice(
    notice_id: i32,
    counts: *const i64,
    step: i64,
    name: *const c_char,
    out: *mut CheckReport,
) -> Status {
    let which = usize::try_from(notice_id)
        .ok()
        .and_then(|k| Notice::ALL.get(k).copied())
        .ok_or_else(|| {
            Failure::new(
                Status::InvalidArgument,
                format!("notice_id must be 0..{}; got {notice_id}", Notice::ALL.len() - 1),
            )
        })?;
    let counts: [i64; 4] = counts.try_into().expect("four counts");
    if let Some(n) = counts.iter().find(|n| **n < 0) {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("counts hold {n}: a number of bonds or atoms is not negative"),
        ));
    }
    let name = if which.takes_name() {
        text(name, "argument `name`")?
    } else {
        ""
    };
    match notice(which, &counts, step, name) {
        Some(message) => out.write(1, &message),
        None => out.write(0, ""),
    }
    Ok(())
}

/// The break log's event of a bond of `model` that broke with `out` at
/// time step `step`, written to `event`: sphere i (id `tag_i`, radius
/// `radius_i`, centre `x_i`) and sphere j (id `tag_j`; a wall: id 0, radius
/// 0 at the wall point `x_j`), the smaller id first; its centre, mode,
/// stresses and their limits.
///
/// # Safety
/// `model` must be null or a model; `out` null or a `GbBondOutput`; `x_i`,
/// `x_j` null or three doubles; `event` null or valid for writes.
#[entry(model: reference, out: reference, x_i: finite_vector3, x_j: finite_vector3, radius_i: positive, radius_j: non_negative, event: reference_mut)]
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn granbond_break_event(
    model: *const BondModel,
    out: *const BondOutput,
    x_i: *const f64,
    x_j: *const f64,
    radius_i: f64,
    radius_j: f64,
    tag_i: f64,
    tag_j: f64,
    step: f64,
    event: *mut BreakEvent,
) -> Status {
    if !(out.delta.is_finite() && out.sigma.is_finite() && out.tau.is_finite()) {
        return Err(Failure::new(
            Status::NonFiniteInput,
            format!(
                "`out` holds delta {}, sigma {}, tau {}",
                out.delta, out.sigma, out.tau
            ),
        ));
    }
    let e = BreakEvent::new(model, out, x_i, x_j, radius_i, radius_j, tag_i, tag_j, step);
    if let Some(why) = e.refusal() {
        return Err(Failure::new(Status::InvalidArgument, why));
    }
    if !e.x.iter().all(|v| v.is_finite()) {
        return Err(Failure::new(
            Status::NonFiniteResult,
            format!("the centre of `x_i` and `x_j` (too far apart) is {:?}", e.x),
        ));
    }
    *event = e;
    Ok(())
}

/// The lines of the break log for `events` (`count` of them, sorted here
/// by step and ids in place), the file's header first where `header` is 1,
/// written to `text` as one NUL-terminated string. `capacity`
/// `(count + 1) * GRANBOND_BREAK_LOG_LINE_LEN` always suffices; a smaller
/// one that the text does not fit is refused, `text` left alone. An event
/// whose step or ids are not integers in 0..=2^53 is refused.
///
/// # Safety
/// `events` must be null or `count` events; `text` null or `capacity`
/// writable bytes.
#[entry(events: slice_mut(count), text: slice_mut(capacity))]
#[no_mangle]
pub unsafe extern "C" fn granbond_break_log_text(
    events: *mut BreakEvent,
    count: usize,
    header: i32,
    text: *mut c_char,
    capacity: usize,
) -> Status {
    if let Some((k, why)) = events
        .iter()
        .enumerate()
        .find_map(|(k, e)| e.refusal().map(|w| (k, w)))
    {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("events[{k}]: {why}"),
        ));
    }
    if !(0..=1).contains(&header) {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("header must be 0 or 1; got {header}"),
        ));
    }
    let lines = break_log::log_text(events, header == 1);
    if lines.len() >= text.len() {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!(
                "capacity {} is less than the {} bytes of the text",
                text.len(),
                lines.len() + 1
            ),
        ));
    }
    for (d, s) in text.iter_mut().zip(lines.bytes()) {
        *d = s as c_char;
    }
    text[lines.len()] = 0;
    Ok(())
}

/// Reads the words of `fix ID group bond/breaklog FILE [every N]` (`count`
/// words, the fix's id first): `every`, how many steps apart the log is
/// written (100 unless given). Words that do not read are
/// `GB_STATUS_INVALID_ARGUMENT`, the message naming the word.
///
/// # Safety
/// `words` must be null or `count` pointers, each null or a NUL-terminated
/// string; `every` null or valid for writes.
#[entry(words: slice(count), every: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_break_log_words(
    words: *const *const c_char,
    count: usize,
    every: *mut i32,
) -> Status {
    let line = word_list(words)?;
    *every = break_log::read_words(&line).map_err(|m| Failure::new(Status::InvalidArgument, m))?;
    Ok(())
}

/// The columns of a per-bond output, written to `columns` (free them with
/// `granbond_bond_columns_free`): those the keywords `words` name (`count`
/// of them: `id`, `pos`, `state`, `output`, `all`, a field of
/// `granbond_bond_field_info` or `granbond_bond_energy_field_info`), or,
/// where `inl_layout` is 1 (no words), LIGGGHTS-INL's columns after its
/// first nine: the loads on sphere i in their parts, then the bond's state.
/// A keyword that is not is `GB_STATUS_INVALID_ARGUMENT`, the message
/// naming it and every keyword.
///
/// # Safety
/// `words` as in `granbond_break_log_words`; `columns` null or valid for
/// writes.
#[entry(words: slice(count), columns: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_columns_new(
    words: *const *const c_char,
    count: usize,
    inl_layout: i32,
    columns: *mut *mut BondColumns,
) -> Status {
    let made = match inl_layout {
        0 => BondColumns::parse(&word_list(words)?).map_err(|m| Failure::new(Status::InvalidArgument, m))?,
        1 if words.is_empty() => BondColumns::inl_layout(),
        _ => {
            return Err(Failure::new(
                Status::InvalidArgument,
                format!("inl_layout must be 0, or 1 without words; got {inl_layout} with {count} words"),
            ))
        }
    };
    *columns = Box::into_raw(Box::new(made));
    Ok(())
}

/// Frees columns from `granbond_bond_columns_new` (null is ignored).
///
/// # Safety
/// `columns` must come from `granbond_bond_columns_new` and not be used
/// again.
#[entry(or = ())]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_columns_free(columns: *mut BondColumns) {
    if !columns.is_null() {
        drop(Box::from_raw(columns));
    }
}

/// How many values a row of `columns` has, written to `count`, and 1 in
/// `wants_energy` where a column is one of the bond store's energies (the
/// row then reads them), else 0.
///
/// # Safety
/// `columns` must be null or from `granbond_bond_columns_new`; `count` and
/// `wants_energy` null or valid for writes.
#[entry(columns: reference, count: reference_mut, wants_energy: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_columns_info(
    columns: *const BondColumns,
    count: *mut usize,
    wants_energy: *mut i32,
) -> Status {
    *count = columns.columns().len();
    *wants_energy = i32::from(columns.wants_energy());
    Ok(())
}

/// The row of one bond of `model`, written to `row` (one value a column):
/// its `record` as sphere i sees it (as `granbond_bond_fields` reads it),
/// its `energy` (`granbond_bond_energy_field_count()` doubles, read where
/// a column asks), the spheres' ids and centres. Refused as
/// `granbond_bond_fields`, `row` left alone.
///
/// # Safety
/// `columns` must be null or from `granbond_bond_columns_new`; `model` null
/// or a model; `record` null or `GRANBOND_BOND_STATE_LEN +
/// GRANBOND_BOND_OUTPUT_LEN` doubles; `energy` null or the energy field
/// count of doubles; `x_i`, `x_j` null or three doubles; `row` null or the
/// column count of writable doubles.
#[entry(columns: reference, model: reference, x_i: finite_vector3, x_j: finite_vector3)]
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn granbond_bond_columns_row(
    columns: *const BondColumns,
    model: *const BondModel,
    record: *const f64,
    energy: *const f64,
    tag_i: f64,
    tag_j: f64,
    x_i: *const f64,
    x_j: *const f64,
    row: *mut f64,
) -> Status {
    let record = slice(record, BOND_STATE_LEN + BOND_OUTPUT_LEN, "record")?;
    let energy = slice(energy, BOND_ENERGY_FIELD_COUNT, "energy")?;
    let row = slice_mut(row, columns.columns().len(), "row")?;
    let fields = record_fields(model, record, x_i, x_j)?;
    columns.row(record, &fields, energy, tag_i, tag_j, x_i, x_j, row);
    Ok(())
}

/// The check of a periodic box too short for the engines' per-pair
/// history, written to `out` (level 1 and the error naming the first such
/// direction, else level 0): `dimension` 2 or 3, `periodic` (3 `int32_t`,
/// non-zero where periodic) and `length` (3 doubles) of the box, the
/// neighbour list's reach `list_reach` (the pair reach plus the skin
/// `skin`); `step` >= 0 where the box changed during a run, at that step,
/// else -1. The message leads with `style`.
///
/// # Safety
/// `style` must be null or a NUL-terminated string; `periodic` null or 3
/// `int32_t`; `length` null or 3 doubles; `out` null or valid for writes.
#[entry(periodic: slice(3), length: array, list_reach: non_negative, skin: non_negative, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_thin_periodic_box_check(
    style: *const c_char,
    dimension: i32,
    periodic: *const i32,
    length: *const f64,
    list_reach: f64,
    skin: f64,
    step: i64,
    out: *mut CheckReport,
) -> Status {
    let style = text(style, "argument `style`")?;
    if !(2..=3).contains(&dimension) {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("dimension must be 2 or 3; got {dimension}"),
        ));
    }
    let b = PeriodicBox {
        dimension,
        periodic: periodic.try_into().expect("three flags"),
        length: *length,
    };
    match thin_periodic_box(style, &b, list_reach, skin, step) {
        Some(message) => out.write(1, &message),
        None => out.write(0, ""),
    }
    Ok(())
}

/// The findings of the store check over all ranks, written to `out` (level
/// 1 and the first finding, else level 0): a key held twice among `keys`
/// (`count` keys of two doubles each, all ranks' bonds: the atoms' ids of
/// pair bonds, or sphere id and wall number where `walls` is 1; sorted
/// here in place), else `sums` (4 `int64_t` summed over the ranks:
/// created, broken, intact, lost; for walls created includes the bonds
/// taken from a restart file) that do not balance.
///
/// # Safety
/// `keys` must be null or `2 * count` doubles; `sums` null or 4 `int64_t`;
/// `out` null or valid for writes.
#[entry(sums: slice(4), out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_store_check_findings(
    keys: *mut f64,
    count: usize,
    sums: *const i64,
    walls: i32,
    out: *mut CheckReport,
) -> Status {
    let of = match walls {
        0 => Keys::Pairs,
        1 => Keys::Walls,
        _ => {
            return Err(Failure::new(
                Status::InvalidArgument,
                format!("walls must be 0 or 1; got {walls}"),
            ))
        }
    };
    let len = count
        .checked_mul(2)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("count {count} keys overflow")))?;
    let flat = slice_mut(keys, len, "keys")?;
    let keys: &mut [[f64; 2]] = std::slice::from_raw_parts_mut(flat.as_mut_ptr().cast(), count);
    let sums: [i64; 4] = sums.try_into().expect("four sums");
    match findings(keys, &sums, of) {
        Some(message) => out.write(1, &message),
        None => out.write(0, ""),
    }
    Ok(())
}

/// Writes the keys `keys` (two doubles each: the bonds' written to
/// `written`) and the finding `out` (level 1 and its words, no key
/// written) of one rank's part of the store check.
fn write_keys(
    found: Result<Vec<[f64; 2]>, String>,
    keys: &mut [f64],
    written: &mut usize,
    out: &mut CheckReport,
) -> Result<(), Failure> {
    *written = 0;
    match found {
        Err(message) => out.write(1, &message),
        Ok(found) => {
            if 2 * found.len() > keys.len() {
                return Err(Failure::new(
                    Status::InvalidArgument,
                    format!(
                        "capacity {} is less than the {} doubles of the keys",
                        keys.len(),
                        2 * found.len()
                    ),
                ));
            }
            for (d, key) in keys.chunks_exact_mut(2).zip(&found) {
                d.copy_from_slice(key);
            }
            *written = found.len();
            out.write(0, "");
        }
    }
    Ok(())
}

/// This rank's part of the store check of pair bonds (`GRANBOND_CHECK_STORE`):
/// each bond of `store` joins one of the `nlocal` local atoms (its owner)
/// and an atom (local or ghost, ids `ids`) of the id it names; its key (the
/// lower and the higher id) written to `keys` (`capacity` doubles,
/// `2 * granbond_bond_store_len(store)` suffice) and their number to
/// `written`, for `granbond_store_check_findings` over all ranks. A bond
/// that does not: level 1 in `out` and its words, no key written.
///
/// # Safety
/// `store` must be null or a store; `ids` null or a `GbAtomIds` whose
/// arrays hold `ids->count` ids; `keys` null or `capacity` writable
/// doubles; `written` and `out` null or valid for writes.
#[entry(store: reference, ids: reference, keys: slice_mut(capacity), written: reference_mut, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_check_keys(
    store: *const BondStore,
    ids: *const AtomIds,
    nlocal: usize,
    keys: *mut f64,
    capacity: usize,
    written: *mut usize,
    out: *mut CheckReport,
) -> Status {
    let ids = id_list(ids)?;
    if nlocal > ids.len() {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("nlocal {nlocal} exceeds the {} atoms of ids", ids.len()),
        ));
    }
    write_keys(pair_keys(store, ids, nlocal), keys, written, out)
}

/// This rank's part of the store check of a listed pair: whether the flag
/// `flagged` (1 or 0) that local atom `i` and atom `j` (local or ghost, ids
/// `ids`) carry in the engine's contact history, a cache of whether they
/// are bonded, agrees with `store` and its view; level 1 in `out` and the
/// words where it does not, else level 0.
///
/// # Safety
/// `store` must be null or a store; `ids` null or a `GbAtomIds` whose
/// arrays hold `ids->count` ids; `out` null or valid for writes.
#[entry(store: reference, ids: reference, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_store_check_flag(
    store: *const BondStore,
    i: usize,
    j: usize,
    ids: *const AtomIds,
    flagged: i32,
    out: *mut CheckReport,
) -> Status {
    let ids = id_list(ids)?;
    if i >= ids.len() || j >= ids.len() || !(0..=1).contains(&flagged) {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!(
                "i {i} and j {j} must be below the {} atoms of ids, flagged 0 or 1 (got {flagged})",
                ids.len()
            ),
        ));
    }
    match flag_finding(store, i, j, ids, flagged == 1) {
        Some(message) => out.write(1, &message),
        None => out.write(0, ""),
    }
    Ok(())
}

/// The same for the wall bonds of `store`: each held by the rank of its
/// sphere, one of the local atoms `ids`; its key (the sphere's id and the
/// wall) written to `keys` (`2 * granbond_wall_store_len(store)` doubles
/// suffice).
///
/// # Safety
/// As `granbond_bond_store_check_keys`, `store` null or a wall store.
#[entry(store: reference, ids: reference, keys: slice_mut(capacity), written: reference_mut, out: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_wall_store_check_keys(
    store: *const WallStore,
    ids: *const AtomIds,
    keys: *mut f64,
    capacity: usize,
    written: *mut usize,
    out: *mut CheckReport,
) -> Status {
    write_keys(wall_keys(store, id_list(ids)?), keys, written, out)
}

/// The bond store's record in a restart file, written to `record`
/// (`capacity` bytes, `GRANBOND_STORE_RECORD_LEN` of them written): the
/// counts `counts` and energy sums `energy` summed over the ranks, and the
/// layout of the bonds' state (`GRANBOND_STATE_LAYOUT_VERSION`), each
/// number in the machine's byte order after the record's length.
///
/// # Safety
/// `counts` must be null or a `GbStoreCounts`; `energy` null or a
/// `GbEnergySums`; `record` null or `capacity` writable bytes.
#[entry(counts: reference, energy: reference, record: slice_mut(capacity))]
#[no_mangle]
pub unsafe extern "C" fn granbond_store_record_write(
    counts: *const StoreCounts,
    energy: *const EnergySums,
    record: *mut u8,
    capacity: usize,
) -> Status {
    let written = record::write(counts, energy, GRANBOND_STATE_LAYOUT_VERSION);
    record
        .get_mut(..RECORD_LEN)
        .ok_or_else(|| {
            Failure::new(
                Status::InvalidArgument,
                format!("capacity {capacity} is less than the {RECORD_LEN} bytes of the record"),
            )
        })?
        .copy_from_slice(&written);
    Ok(())
}

/// Reads a bond store's record of a restart file (as
/// `granbond_store_record_write` wrote it) into `counts` and `energy`. A
/// record of another layout, or one whose bonds were written with another
/// state layout, is `GB_STATUS_INVALID_ARGUMENT`, the message saying with
/// which layout and what to do, before a bond is read.
///
/// # Safety
/// `record` must be null or point to 8 readable bytes, and to
/// `GRANBOND_STORE_RECORD_LEN` where they hold this record's length (the
/// engine hands what the file holds); `counts` and `energy` null or valid
/// for writes.
#[entry(counts: reference_mut, energy: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_store_record_read(
    record: *const u8,
    counts: *mut StoreCounts,
    energy: *mut EnergySums,
) -> Status {
    let head: [u8; 8] = slice(record, 8, "record")?.try_into().expect("8 bytes");
    if !record::is_current(record::body_len(head)) {
        // a record without the state layout holds bonds of layout 3 or earlier
        return Err(Failure::new(
            Status::InvalidArgument,
            record::refusal("an older bond state layout", GRANBOND_STATE_LAYOUT_VERSION),
        ));
    }
    let whole: &[u8; RECORD_LEN] = slice(record, RECORD_LEN, "record")?
        .try_into()
        .expect("the record's bytes");
    (*counts, *energy) = record::read(whole, GRANBOND_STATE_LAYOUT_VERSION)
        .map_err(|m| Failure::new(Status::InvalidArgument, m))?;
    Ok(())
}
