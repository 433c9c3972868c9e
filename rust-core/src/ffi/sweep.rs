//! `extern "C"` surface of the bond pass over an engine's index of bonded
//! pairs (`crate::sweep`), and of the pair record's layout
//! (`crate::record`).

use super::bond::{atom_arrays, indexed_pairs, AtomArrayPointers};
use super::entry;
use super::error::Status;
use super::guard::{reference, reference_mut, slice, slice_mut, time_step, FailedIndex};
use super::results;
use crate::bond::{BondModel, BondOutput, BondState};
use crate::record::RecordLayout;
use crate::sweep::{after_force_step, file_loads, setup_loads, SweepPass, SweepTally};

/// The layout of a pair record, with the Voigt contact's state first
/// (`with_contact` 1, LAMMPS `pair granbond`) or without it (0, where the
/// engine keeps the contact's state), written to `layout`. The slots'
/// names and swap rules are those of `granbond_state_slot` with
/// `GB_STATE_KIND_PAIR_RECORD` or `GB_STATE_KIND_BOND_RECORD`.
///
/// # Safety
/// `layout` must be null or valid for writes.
#[entry(layout: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_record_layout(with_contact: i32, layout: *mut RecordLayout) -> Status {
    *layout = RecordLayout::new(with_contact != 0);
    Ok(())
}

/// Bonds one core call sweeps through the lanes at a time: their state
/// pointers are gathered on the stack.
const CHUNK: usize = 64;

/// One pass (`pass`: a force or a setup pass) over `count` bonded pairs of
/// one bond model, as an engine's index of bonds holds them: bond `k`
/// joins atoms `pairs[2k]` (`i`) and `pairs[2k + 1]` (`j`) of the engine's
/// arrays `atoms`, and its pair record (`granbond_record_layout`, no two
/// the same) starts at `records[k]`.
///
/// A force pass advances every bond (bit for bit `granbond_bond_compute_indexed`
/// on the records' bond states) and writes its loads to `out[k]`; with
/// `pass->keep_loads`, an intact bond's loads are also kept in its record
/// (without, the caller files `out` with `granbond_bond_file_loads` before
/// anything reads them, and the pass reads and writes only the first
/// `layout.loads` doubles of each record); a bond that breaks has `status`
/// broken and its `break_mode` in `out[k]`, and unless
/// `pass->contact_under_bond`, its record's contact state is cleared. A
/// setup pass advances nothing and writes to `out[k]` the loads kept in
/// the records. Bonds with `counted[k]` non-zero (each bond on one rank
/// only) are added to `tally`: intact after the pass, broken by mode.
///
/// Stops at the first bad input and writes its index to `failed_index` (if
/// not null); a null or misaligned `records[k]` and an atom index outside
/// `0 .. atoms->count` are reported before any bond is advanced.
///
/// # Safety
/// Pointers must be null or valid for the sizes above (`pairs`: `2 count`
/// ints; `counted`: `count` bytes; each `records[k]`: a record's length, or
/// `layout.loads` doubles in a force pass without `keep_loads`).
#[entry(failed_index: FailedIndex::new, model: reference, pass: reference, atoms: reference, tally: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_sweep(
    model: *const BondModel,
    pass: *const SweepPass,
    count: usize,
    atoms: *const AtomArrayPointers,
    pairs: *const i32,
    counted: *const u8,
    records: *const *mut f64,
    out: *mut BondOutput,
    tally: *mut SweepTally,
    failed_index: *mut usize,
) -> Status {
    let layout = RecordLayout::new(pass.with_contact != 0);
    let len = if pass.advance != 0 && pass.keep_loads == 0 {
        layout.loads
    } else {
        layout.len
    };
    let arrays = atom_arrays(atoms)?;
    let pairs = slice(pairs as *const [i32; 2], count, "pairs")?;
    let counted = slice(counted, count, "counted")?;
    let records = slice(records, count, "records")?;
    for (k, &r) in records.iter().enumerate() {
        slice_mut(r, len, "records[k]").map_err(|f| failed_index.fail("bond", k, f))?;
    }
    let out = slice_mut(out, count, "out")?;
    // every index checked before any bond moves
    let all = indexed_pairs(arrays, pairs, 0, failed_index)?;
    let record = |k: usize| std::slice::from_raw_parts_mut(records[k], len);
    if pass.advance == 0 {
        for (k, o) in out.iter_mut().enumerate() {
            *o = setup_loads(&layout, record(k), counted[k] != 0, tally);
        }
        return Ok(());
    }
    let dt = time_step(pass.dt, "pass->dt")?;
    prefetch_records(&records[..count.min(CHUNK)], len);
    for first in (0..count).step_by(CHUNK) {
        let last = count.min(first + CHUNK);
        // the next chunk's records, requested while this one is stepped:
        // they lie apart in the engine's history pages, and each first read
        // would otherwise wait for memory
        prefetch_records(&records[last..count.min(last + CHUNK)], len);
        let kinematics = all.sub(first..last);
        let mut states = [std::ptr::null_mut::<BondState>(); CHUNK];
        for (s, &r) in states.iter_mut().zip(&records[first..last]) {
            *s = r.add(layout.bond) as *mut BondState;
        }
        // Every pointer is non-null and aligned (checked above), the records
        // are distinct, and `&mut BondState` has the layout of `*mut BondState`.
        let states = std::slice::from_raw_parts_mut(states.as_mut_ptr() as *mut &mut BondState, last - first);
        let stepped = model.step_indexed(&kinematics, dt, states, &mut out[first..last]);
        let stepped = match stepped {
            Ok(bad) => Ok(bad.map(|k| first + k)),
            Err((k, e)) => Err((first + k, e)),
        };
        results::bonds(stepped, failed_index)?;
        for k in first..last {
            after_force_step(&layout, pass, record(k), &out[k], counted[k] != 0, tally);
        }
    }
    Ok(())
}

/// Files the outputs `outs[k]` of the latest passes of `count` bonds in
/// their whole pair records `records[k]` (`granbond_record_layout` of
/// `pass->with_contact`), as a force pass of `pass` with `keep_loads` would
/// have left them: an intact bond's loads stored; those of a bond that broke
/// in the pass (a break mode) cleared and, unless
/// `pass->contact_under_bond`, its contact's state; any other output (a bond
/// broken before, or all zero as no pass wrote it) leaves its record alone. For
/// engines that sweep without `keep_loads` (or step copies of the bond
/// states alone, `with_contact` 0), at a break and before anything reads the
/// records' loads: a run's end, a restart file, an output of the bonds. A
/// null or misaligned record is reported, its index written to
/// `failed_index` (if not null), before any is filed.
///
/// # Safety
/// Pointers must be null or valid: `records` and `outs` hold `count`
/// entries, each `records[k]` a record's length.
#[entry(failed_index: FailedIndex::new, pass: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_file_loads(
    pass: *const SweepPass,
    count: usize,
    records: *const *mut f64,
    outs: *const BondOutput,
    failed_index: *mut usize,
) -> Status {
    let layout = RecordLayout::new(pass.with_contact != 0);
    let records = slice(records, count, "records")?;
    let outs = slice(outs, count, "outs")?;
    for (k, &r) in records.iter().enumerate() {
        slice_mut(r, layout.len, "records[k]").map_err(|f| failed_index.fail("bond", k, f))?;
    }
    for (&r, out) in records.iter().zip(outs) {
        file_loads(&layout, pass, std::slice::from_raw_parts_mut(r, layout.len), out);
    }
    Ok(())
}

/// Asks for every cache line of each record ahead of its use; a hint, with
/// no effect on results. Not for records that lie side by side in order
/// (an adapter's copies of them, told by the first and the last), which the
/// processor streams by itself.
#[inline]
fn prefetch_records(records: &[*mut f64], len: usize) {
    if let (Some(&first), Some(&last)) = (records.first(), records.last()) {
        let apart = (last as usize).wrapping_sub(first as usize);
        if apart == (records.len() - 1) * len * std::mem::size_of::<f64>() {
            return;
        }
    }
    #[cfg(target_arch = "x86_64")]
    for &r in records {
        for offset in (0..len).step_by(8) {
            // SAFETY: a prefetch never faults; the address is computed,
            // not dereferenced.
            unsafe {
                std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(
                    r.wrapping_add(offset) as *const i8
                )
            };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (records, len);
}
