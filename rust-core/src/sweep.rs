//! The rule of a pass over bonded pairs, for engines that keep an index of
//! the records of intact bonds and sweep it once per pass
//! (docs/models/bond-nonlinear.md, "Creation" and "Breakage"):
//!
//! - a force pass advances each bond; a bond that breaks is counted by
//!   mode, and unless the contact goes on under the bond, the contact starts
//!   afresh, as in BPM and LAMMPS `pair granular`;
//! - a setup pass (a run's start) advances nothing and applies the loads of
//!   the latest force pass, so a second `run` or a restart continues the
//!   first bit for bit.
//!
//! The loads a setup pass applies are kept in the bond's record. A force
//! pass stores them there itself when the engine reads them within the pass
//! (`keep_loads`); otherwise the engine keeps the pass's outputs, which it
//! has anyway, and files them into the records ([`file_loads`]) only before
//! something reads or moves the records: a run's end, a restart file, an
//! output of the bonds. Storing them every step would cost each bond-step
//! the stores of data that only the next run's first pass reads.
//!
//! The bond step itself is [`crate::bond::BondModel`]'s; this module says
//! what the pass does around it.

use crate::bond::output_slots::{load_output, store_output};
use crate::bond::{BondOutput, BondStatus, BreakMode};
use crate::record::RecordLayout;

/// One pass, as the engine describes it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepPass {
    /// The time step (force passes).
    pub dt: f64,
    /// 1: a force pass, which advances the bonds; 0: a setup pass.
    pub advance: i32,
    /// 1: the contact's state goes on under an intact bond and acts, from
    /// where it stands, when the bond breaks; 0: it starts afresh.
    pub contact_under_bond: i32,
    /// 1: the records hold the Voigt contact's state first
    /// ([`RecordLayout::new`]).
    pub with_contact: i32,
    /// 1: a force pass stores an intact bond's loads in its record (and
    /// clears them at a break); 0: the caller keeps the pass's outputs and
    /// files them with [`file_loads`] before anything reads the records'
    /// loads, and a force pass reads and writes only the first
    /// [`RecordLayout::loads`] doubles of each record.
    pub keep_loads: i32,
}

/// The bonds one pass counted (only those its caller marked as counted:
/// each bond once over all ranks).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SweepTally {
    /// Intact after the pass.
    pub intact: i64,
    /// Broken in this pass by distance ([`BreakMode::Distance`]).
    pub broken_distance: i64,
    /// Broken in this pass by tension ([`BreakMode::Tension`]).
    pub broken_tension: i64,
    /// Broken in this pass by compression ([`BreakMode::Compression`]).
    pub broken_compression: i64,
    /// Broken in this pass by shear ([`BreakMode::Shear`]).
    pub broken_shear: i64,
}

impl SweepTally {
    fn count_break(&mut self, mode: i32) {
        let slot = match mode {
            m if m == BreakMode::Distance as i32 => &mut self.broken_distance,
            m if m == BreakMode::Tension as i32 => &mut self.broken_tension,
            m if m == BreakMode::Compression as i32 => &mut self.broken_compression,
            m if m == BreakMode::Shear as i32 => &mut self.broken_shear,
            _ => return,
        };
        *slot += 1;
    }

    /// Bonds broken in the pass, all modes.
    pub fn broken(&self) -> i64 {
        self.broken_distance + self.broken_tension + self.broken_compression + self.broken_shear
    }
}

/// The rest of a force pass for one bond its step left with `out`: the
/// count (intact, or broken by mode); the record settled as [`file_loads`]
/// would, if the pass keeps the loads, or else only the contact's state
/// cleared at a break (unless `contact_under_bond`).
#[inline]
pub fn after_force_step(
    layout: &RecordLayout,
    pass: &SweepPass,
    record: &mut [f64],
    out: &BondOutput,
    counted: bool,
    tally: &mut SweepTally,
) {
    if out.status == BondStatus::Intact as i32 {
        // the common case, kept to one test of the pass
        if pass.keep_loads != 0 {
            *layout.loads(record) = store_output(out);
        }
        tally.intact += i64::from(counted);
        return;
    }
    after_break(layout, pass, record, out, counted, tally);
}

/// [`after_force_step`] for a bond that did not hold (broke in the pass, or
/// was broken before): rare, so kept out of the common path's code.
#[cold]
#[inline(never)]
fn after_break(
    layout: &RecordLayout,
    pass: &SweepPass,
    record: &mut [f64],
    out: &BondOutput,
    counted: bool,
    tally: &mut SweepTally,
) {
    if counted {
        tally.count_break(out.break_mode);
    }
    if pass.keep_loads != 0 {
        file_loads(layout, pass, record, out);
    } else {
        clear_contact_at_break(layout, pass, record, out);
    }
}

/// Files the output of a bond's latest pass in its whole record, as a force
/// pass of `pass` that keeps the loads would have left it: an intact bond's
/// loads stored; those of a bond that broke in the pass cleared and, unless
/// the contact goes on under the bond, its contact's state (so an engine may
/// step the bond state alone and settle the rest of the record here). Any
/// other output (a bond broken before the pass; an output no pass wrote,
/// status unbonded as zeroed) leaves the record as it is.
#[inline]
pub fn file_loads(layout: &RecordLayout, pass: &SweepPass, record: &mut [f64], out: &BondOutput) {
    if out.status == BondStatus::Intact as i32 {
        *layout.loads(record) = store_output(out);
    } else if out.break_mode != BreakMode::None as i32 {
        layout.loads(record).fill(0.0);
    }
    clear_contact_at_break(layout, pass, record, out);
}

/// A bond that broke in the pass: unless the contact goes on under it, the
/// contact starts afresh, as in BPM and LAMMPS `pair granular`.
#[inline]
fn clear_contact_at_break(layout: &RecordLayout, pass: &SweepPass, record: &mut [f64], out: &BondOutput) {
    if out.break_mode != BreakMode::None as i32 && pass.contact_under_bond == 0 {
        record[..layout.contact_len].fill(0.0);
    }
}

/// A setup pass for one bond: the loads of its latest force pass (none for
/// a bond that is not intact).
pub fn setup_loads(
    layout: &RecordLayout,
    record: &mut [f64],
    counted: bool,
    tally: &mut SweepTally,
) -> BondOutput {
    let status = BondStatus::from_rest(record[layout.status]);
    if status != BondStatus::Intact {
        return BondOutput {
            status: status as i32,
            ..BondOutput::default()
        };
    }
    tally.intact += i64::from(counted);
    load_output(layout.loads(record))
}
