//! The rule of a pass over the store (docs/models/bond-nonlinear.md,
//! "Creation" and "Breakage"):
//!
//! - a force pass advances each bond with its kind's model, in chunks of
//!   bonds of one kind that lie side by side; a bond that breaks is counted
//!   by mode, reported, exerts nothing, and leaves the store when the pass
//!   finishes; it cannot form again in the same pass;
//! - a setup pass (a run's start) advances nothing: each bond's loads are
//!   those of its stored state, a step of a copy over a zero time step;
//! - a bond that forms in the pass is stepped in it too (the engine asks for
//!   the chunks left after its contact loop).
//!
//! The loads go back to the engine chunk by chunk: nothing is kept per bond.

use super::id_map::Ids;
use super::{BondStore, StoredBond, NONE};
use crate::bond::atom_loads::{LoadSink, Rows};
use crate::bond::{AtomLoads, BondModel, BondOutput, BondState, BondStatus, BreakMode, LoadsTooShort};
use crate::kinematics::{KinematicsError, PairKinematics};
use crate::pair_source::{AtomArrays, IndexedPairs, PairSource};

/// Bonds one [`BondStore::step_next`] steps at most. Each call pays the
/// entry's checks, the run and index passes and the kernel's set-up once:
/// 128 bonds spread that over twice as many bonds as 64, and their outputs
/// (about 15 KB) still sit in the first-level cache while the engine adds
/// them to its atoms.
pub const CHUNK: usize = 128;

/// Where the pass stands.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Cursor {
    active: bool,
    advance: bool,
    remember_breaks: bool,
    dt: f64,
    // the run's time step, also in a setup pass (a law's own setup step)
    run_dt: f64,
    next: usize,
    /// The first bond formed in this pass.
    fresh: usize,
}

/// A bond that broke in the pass.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BrokenBond {
    /// The ids of its owner and partner.
    pub ids: [i64; 2],
    /// Their local indices.
    pub ends: [i32; 2],
    /// Its last step's output: status broken, the break mode, the
    /// stresses; no loads.
    pub out: BondOutput,
}

/// Why a chunk could not be stepped.
#[derive(Clone, Debug, PartialEq)]
pub struct StepFailure {
    /// The bond (its place in the store).
    pub bond: usize,
    /// Its atoms' local indices.
    pub ends: [i32; 2],
    /// What went wrong.
    pub reason: StepFailureReason,
}

/// What went wrong in a step.
#[derive(Clone, Debug, PartialEq)]
pub enum StepFailureReason {
    /// The store was not linked since atoms moved (an engine's fault).
    NotLinked,
    /// No model for the bond's kind.
    NoModel(u16),
    /// An atom index beyond the atoms' arrays.
    IndexOutOfRange,
    /// The pair's kinematics are unusable (coincident centres, a non-finite
    /// number).
    Kinematics(KinematicsError),
    /// The results were not finite.
    NonFinite,
    /// The named array of the atoms' load sums holds fewer atoms than the
    /// atoms' arrays, or `nlocal` exceeds them.
    LoadsTooShort(&'static str),
}

/// Counts a break of `mode` in `c` (any mode not named otherwise is shear).
pub(super) fn count_break(c: &mut super::StoreCounts, mode: i32) {
    match mode {
        m if m == BreakMode::Distance as i32 => c.broken_distance += 1,
        m if m == BreakMode::Tension as i32 => c.broken_tension += 1,
        m if m == BreakMode::Compression as i32 => c.broken_compression += 1,
        _ => c.broken_shear += 1,
    }
}

/// Which atom of a pair the engine has just found to bond owns the bond on
/// this rank: `Some(false)` atom `i`, `Some(true)` atom `j`, `None` if
/// another rank creates it. The owner is a local atom, the one with the
/// smaller id where both are; a pair listed on two ranks (`newton off`,
/// one atom a ghost) is created by the rank that owns the smaller id.
pub fn creates_here(
    i_local: bool,
    j_local: bool,
    id_i: i64,
    id_j: i64,
    listed_on_both: bool,
) -> Option<bool> {
    match (i_local, j_local) {
        (true, true) => Some(id_j < id_i),
        (true, false) => (!listed_on_both || id_i < id_j).then_some(false),
        (false, true) => (!listed_on_both || id_j < id_i).then_some(true),
        (false, false) => None,
    }
}

impl BondStore {
    /// Starts a pass: a force pass over `dt` (`advance`) or a setup pass.
    /// With `remember_breaks` (a creation step lies ahead, without
    /// `create_always`), the pairs whose bonds break are kept so that the
    /// creation step does not bond them again.
    pub fn begin_pass(&mut self, dt: f64, advance: bool, remember_breaks: bool) {
        self.cursor = Cursor {
            active: true,
            advance,
            remember_breaks,
            dt: if advance { dt } else { 0.0 },
            run_dt: dt,
            next: 0,
            fresh: self.bonds.len(),
        };
        if !remember_breaks {
            self.broken_pairs = Vec::new();
        }
        self.broken_now.clear();
        self.left_view.clear();
    }

    /// Steps the next chunk of bonds the pass has not stepped (those formed
    /// since included): up to [`CHUNK`] bonds of one kind, whose atoms'
    /// local indices go to `ends` and outputs to `outs`; returns how many
    /// (0: none left). A bond that breaks carries no load and is in
    /// [`Self::broken`].
    pub fn step_next(
        &mut self,
        models: &[Option<&BondModel>],
        atoms: AtomArrays<'_>,
        ids: Ids<'_>,
        ends: &mut [[i32; 2]; CHUNK],
        outs: &mut [BondOutput; CHUNK],
    ) -> Result<usize, StepFailure> {
        let (first, n) = self.step_chunk(models, atoms, ids, None, outs, true)?;
        ends[..n].copy_from_slice(&self.ends[first..first + n]);
        Ok(n)
    }

    /// [`Self::step_next`], the chunk's loads added to `loads` as well
    /// ([`crate::bond::atom_loads`]): bond by bond, the owner's, then the
    /// partner's.
    pub fn step_next_adding(
        &mut self,
        models: &[Option<&BondModel>],
        atoms: AtomArrays<'_>,
        ids: Ids<'_>,
        loads: &mut AtomLoads<'_>,
        ends: &mut [[i32; 2]; CHUNK],
        outs: &mut [BondOutput; CHUNK],
    ) -> Result<usize, StepFailure> {
        let rows = self.rows_of(loads, &atoms)?;
        let (first, n) = self.step_chunk(models, atoms, ids, Some(rows), outs, true)?;
        ends[..n].copy_from_slice(&self.ends[first..first + n]);
        Ok(n)
    }

    /// Steps every bond the pass has not stepped, chunk after chunk, their
    /// loads added to `loads` as [`Self::step_next_adding`] adds them, no
    /// output handed back; returns how many. The loads of a chunk go to the
    /// atoms from the lanes as it is stepped, without a pass over outputs:
    /// where no output is wanted (no virial, no per-bond output), the pass
    /// in one call.
    pub fn step_rest(
        &mut self,
        models: &[Option<&BondModel>],
        atoms: AtomArrays<'_>,
        ids: Ids<'_>,
        loads: &mut AtomLoads<'_>,
    ) -> Result<usize, StepFailure> {
        let rows = self.rows_of(loads, &atoms)?;
        let mut outs = [BondOutput::default(); CHUNK];
        let mut stepped = 0;
        loop {
            match self.step_chunk(models, atoms, ids, Some(rows), &mut outs, false)? {
                (_, 0) => return Ok(stepped),
                (_, n) => stepped += n,
            }
        }
    }

    /// `loads`' rows for the atoms of `atoms`, each array's length checked.
    fn rows_of<'l>(
        &self,
        loads: &'l mut AtomLoads<'_>,
        atoms: &AtomArrays<'_>,
    ) -> Result<Rows<'l>, StepFailure> {
        loads
            .rows(atoms.count())
            .map_err(|LoadsTooShort(what)| StepFailure {
                bond: self.cursor.next,
                ends: [-1, -1],
                reason: StepFailureReason::LoadsTooShort(what),
            })
    }

    /// The next chunk stepped, its loads added to `rows` if given, every
    /// output written to `outs` if `outputs` (else the status and break
    /// mode at least); returns its first bond and its length.
    fn step_chunk(
        &mut self,
        models: &[Option<&BondModel>],
        atoms: AtomArrays<'_>,
        ids: Ids<'_>,
        rows: Option<Rows<'_>>,
        outs: &mut [BondOutput; CHUNK],
        outputs: bool,
    ) -> Result<(usize, usize), StepFailure> {
        let first = self.cursor.next;
        if !self.cursor.active || first >= self.bonds.len() {
            return Ok((first, 0));
        }
        let fail = |bond: usize, ends: [i32; 2], reason| StepFailure { bond, ends, reason };
        if !self.linked {
            return Err(fail(first, [-1, -1], StepFailureReason::NotLinked));
        }
        let kind = self.kinds[first];
        let last = first + same_kind_run(&self.kinds[first..self.bonds.len().min(first + CHUNK)], kind);
        let n = last - first;
        let model = models
            .get(usize::from(kind))
            .copied()
            .flatten()
            .ok_or_else(|| fail(first, self.ends[first], StepFailureReason::NoModel(kind)))?;
        let pairs = &self.ends[first..last];
        let kinematics = IndexedPairs::new(atoms, pairs).map_err(|e| {
            fail(
                first + e.bond,
                self.ends[first + e.bond],
                StepFailureReason::IndexOutOfRange,
            )
        })?;
        // the energy budget reads every output
        let outputs = outputs || self.budget.is_some();
        let sink = match rows {
            Some(rows) => LoadSink::adding(rows, &kinematics, outputs)
                .ok_or_else(|| fail(first, [-1, -1], StepFailureReason::LoadsTooShort("force")))?,
            None => LoadSink::outputs(),
        };
        let outs = &mut outs[..n];
        // the energy budget reads the states before the step (in its own
        // buffers, which it keeps from chunk to chunk)
        let mut scratch = self.budget.as_mut().map(|b| std::mem::take(&mut b.scratch));
        if let Some(s) = &mut scratch {
            s.before.clear();
            s.before.extend(self.bonds[first..last].iter().map(|b| b.state));
        }
        let stepped = if self.cursor.advance {
            // left uninitialised beyond the chunk: a chunk of a few bonds
            // would otherwise pay for clearing all CHUNK of them
            let mut states = [const { std::mem::MaybeUninit::<*mut BondState>::uninit() }; CHUNK];
            for (s, bond) in states.iter_mut().zip(&mut self.bonds[first..last]) {
                s.write(&mut bond.state);
            }
            // SAFETY: the first n pointers are written, to distinct bonds of
            // `self.bonds` borrowed mutably for this call, and `&mut
            // BondState` has the layout of `*mut BondState`.
            let states =
                unsafe { std::slice::from_raw_parts_mut(states.as_mut_ptr() as *mut &mut BondState, n) };
            model.step_indexed_into(&kinematics, self.cursor.dt, states, outs, &sink)
        } else if let Some(stepped) = setup_afresh(
            model,
            &kinematics,
            self.cursor.run_dt,
            &mut self.bonds[first..last],
            outs,
        ) {
            sink.add_outputs(0..n, outs);
            stepped
        } else {
            let mut copies = [BondState::default(); CHUNK];
            for (c, bond) in copies.iter_mut().zip(&self.bonds[first..last]) {
                *c = bond.state;
            }
            let mut refs: [*mut BondState; CHUNK] = [std::ptr::null_mut(); CHUNK];
            for (r, c) in refs.iter_mut().zip(copies.iter_mut()) {
                *r = c;
            }
            // SAFETY: as above, over the copies.
            let states =
                unsafe { std::slice::from_raw_parts_mut(refs.as_mut_ptr() as *mut &mut BondState, n) };
            model.step_indexed_into(&kinematics, 0.0, states, outs, &sink)
        };
        let all_direct = sink.all_direct.get();
        match stepped {
            Ok(None) => {}
            Ok(Some(k)) => {
                return Err(fail(
                    first + k,
                    self.ends[first + k],
                    StepFailureReason::NonFinite,
                ))
            }
            Err((k, e)) => {
                return Err(fail(
                    first + k,
                    self.ends[first + k],
                    StepFailureReason::Kinematics(e),
                ))
            }
        }
        if let Some(mut s) = scratch {
            // the same steps undamped: their loads less the step's are the
            // damping's
            let undamped = model.undamped().map(|u| {
                s.twin.clear();
                s.twin.extend_from_slice(&s.before);
                s.elastic.clear();
                s.elastic.resize(n, BondOutput::default());
                let mut refs: Vec<&mut BondState> = s.twin.iter_mut().collect();
                // the damped step succeeded on these kinematics and states
                let _ = u.step_indexed(&kinematics, self.cursor.dt, &mut refs, &mut s.elastic);
            });
            let elastic = undamped.map(|()| &s.elastic[..]);
            let (dt, fresh) = (self.cursor.dt, self.cursor.fresh);
            self.tally_energy(model, &atoms, dt, first, &s.before, outs, elastic, fresh);
            if let Some(b) = self.budget.as_mut() {
                b.scratch = s;
            }
        }
        self.cursor.next = last;
        // Breaks are rare: none where every bond went to the atoms from the
        // lanes, else one pass over the statuses without a branch says
        // whether the chunk has any.
        let intact = BondStatus::Intact as i32;
        if !self.cursor.advance || all_direct || outs.iter().fold(0, |any, o| any | (o.status ^ intact)) == 0
        {
            return Ok((first, n));
        }
        for (k, out) in outs.iter_mut().enumerate() {
            // a bond that is not intact carries no load (the step's rule);
            // one that broke in a force pass is counted and reported
            if out.status != BondStatus::Intact as i32 && self.cursor.advance {
                let b = first + k;
                let e = self.ends[b];
                let owner = e[0] as usize;
                if owner >= ids.len() {
                    return Err(fail(b, e, StepFailureReason::IndexOutOfRange));
                }
                let broken = BrokenBond {
                    ids: [ids.get(owner), self.bonds[b].partner],
                    ends: e,
                    out: *out,
                };
                self.count_break(out.break_mode);
                self.broken_now.push(broken);
            }
        }
        Ok((first, n))
    }

    fn count_break(&mut self, mode: i32) {
        count_break(&mut self.counts, mode);
    }

    /// The bonds broken so far in this pass.
    pub fn broken(&self) -> &[BrokenBond] {
        &self.broken_now
    }

    /// Creates a bond between local atom `owner` and atom `partner` (local
    /// or ghost, id `partner_id`) of kind `kind` if `model`'s creation rules
    /// allow it at `step` for the pair's kinematics `kin` (seen from the
    /// owner); returns whether it did. A pair whose bond broke in this pass
    /// is not bonded again in it, nor one whose bond broke before unless
    /// the model creates bonds always. The bond is stepped by the pass's
    /// next [`Self::step_next`]. The engine calls this only for pairs it
    /// knows unbonded and owned here ([`creates_here`]).
    #[allow(clippy::too_many_arguments)]
    pub fn try_create(
        &mut self,
        model: &BondModel,
        kind: u16,
        owner: usize,
        partner: usize,
        ids: [i64; 2],
        kin: &PairKinematics,
        step: i64,
    ) -> Result<bool, KinematicsError> {
        self.create_with(kind, owner, partner, ids, |state| {
            model.try_create(kin, step, state)
        })
    }

    /// As [`Self::try_create`], whatever the step: the pair bonds if it is
    /// closer than the model's creation distance (LIGGGHTS `bonded yes`:
    /// the spheres of one inserted clump, in their first force pass). A
    /// pair whose bond broke in this pass is not bonded again in it.
    pub fn create_now(
        &mut self,
        model: &BondModel,
        kind: u16,
        owner: usize,
        partner: usize,
        ids: [i64; 2],
        kin: &PairKinematics,
    ) -> Result<bool, KinematicsError> {
        self.create_with(kind, owner, partner, ids, |state| model.create_now(kin, state))
    }

    fn create_with(
        &mut self,
        kind: u16,
        owner: usize,
        partner: usize,
        ids: [i64; 2],
        create: impl FnOnce(&mut BondState) -> Result<bool, KinematicsError>,
    ) -> Result<bool, KinematicsError> {
        if !self.linked || owner >= self.head.len() {
            return Ok(false);
        }
        let same = |e: [i32; 2]| {
            (e[0] as usize == owner && e[1] as usize == partner)
                || (e[1] as usize == owner && e[0] as usize == partner)
        };
        if self.broken_now.iter().any(|b| same(b.ends)) {
            return Ok(false);
        }
        let mut state = BondState::default();
        let pair = ordered(ids);
        if self.broken_pairs.binary_search(&pair).is_ok() {
            state.mark_broken();
        }
        if !create(&mut state)? {
            return Ok(false);
        }
        self.push(
            owner,
            StoredBond {
                partner: ids[1],
                state,
            },
        );
        self.ends.push([owner as i32, partner as i32]);
        self.kinds.push(kind);
        self.counts.created += 1;
        let owned = self.owned(owner).count();
        self.most_owned = self.most_owned.max(owned);
        Ok(true)
    }

    /// Ends the pass: the bonds that broke in it leave the store.
    pub fn finish_pass(&mut self) {
        self.cursor.active = false;
        if self.broken_now.is_empty() {
            self.trim();
            return;
        }
        if self.cursor.remember_breaks {
            for b in &self.broken_now {
                self.broken_pairs.push(ordered(b.ids));
            }
            self.broken_pairs.sort_unstable();
            self.broken_pairs.dedup();
        }
        self.broken_now.clear();
        for k in 0..self.bonds.len() {
            let i = self.ends[k][0] as usize;
            self.head[i] = NONE;
        }
        let mut kept = 0;
        for k in 0..self.bonds.len() {
            if self.bonds[k].state.status() == BondStatus::Intact {
                self.bonds.swap(kept, k);
                self.ends.swap(kept, k);
                self.kinds.swap(kept, k);
                if let Some(budget) = &mut self.budget {
                    budget.swap(kept, k);
                }
                kept += 1;
            }
        }
        self.bonds.truncate(kept);
        self.ends.truncate(kept);
        self.kinds.truncate(kept);
        if let Some(budget) = &mut self.budget {
            budget.truncate(kept);
        }
        self.rebuild_lists();
        self.trim();
    }
}

/// A setup pass of a law that computes its loads afresh there
/// (LIGGGHTS-INL's code: a trial step over the run's time step that moves
/// only the history extremes and breaks nothing, [`BondModel::setup_step`]):
/// the chunk's bonds through it, in place, as `step_indexed` would report
/// them; `None` for any other law.
fn setup_afresh(
    model: &BondModel,
    kinematics: &IndexedPairs<'_>,
    dt: f64,
    bonds: &mut [StoredBond],
    outs: &mut [BondOutput],
) -> Option<Result<Option<usize>, (usize, KinematicsError)>> {
    for (k, (bond, out)) in bonds.iter_mut().zip(outs.iter_mut()).enumerate() {
        match model.setup_step(&kinematics.pair(k), dt, &mut bond.state, out, false) {
            Ok(true) => {}
            Ok(false) => return None,
            Err(e) => return Some(Err((k, e))),
        }
    }
    Some(Ok(None))
}

/// How many of `kinds`, from the first, are `kind`. Stores mostly hold one
/// kind: a pass without a branch over them says so, before a search.
fn same_kind_run(kinds: &[u16], kind: u16) -> usize {
    if kinds.iter().fold(0, |other, &k| other | (k ^ kind)) == 0 {
        kinds.len()
    } else {
        kinds.iter().position(|&k| k != kind).unwrap_or(kinds.len())
    }
}

fn ordered(ids: [i64; 2]) -> [i64; 2] {
    [ids[0].min(ids[1]), ids[0].max(ids[1])]
}

impl BondStore {
    /// The energy the bonds of this rank store now (J), each bond with its
    /// kind's model at its atoms' positions ([`BondModel::stored_energy`]);
    /// `None` before a link, or when a bond's atom lies beyond `atoms`.
    pub fn stored_energy(&self, models: &[Option<&BondModel>], atoms: AtomArrays<'_>) -> Option<f64> {
        if !self.linked {
            return None;
        }
        let mut sum = 0.0;
        for k in 0..self.bonds.len() {
            match self.energy_of(k, models, &atoms) {
                Err(()) => return None,
                Ok(e) => sum += e.unwrap_or(0.0),
            }
        }
        Some(sum)
    }

    /// The energy bond `k` stores now (J), as [`Self::stored_energy`] counts
    /// it; `None` beyond the bonds, before a link, for a kind without a
    /// model or atoms beyond `atoms`.
    pub fn bond_stored_energy(
        &self,
        k: usize,
        models: &[Option<&BondModel>],
        atoms: AtomArrays<'_>,
    ) -> Option<f64> {
        if !self.linked || k >= self.bonds.len() {
            return None;
        }
        self.energy_of(k, models, &atoms).ok().flatten()
    }

    /// Bond `k`'s stored energy: `Err` for atoms beyond `atoms`, `None` for
    /// a kind without a model (it counts nothing).
    fn energy_of(
        &self,
        k: usize,
        models: &[Option<&BondModel>],
        atoms: &AtomArrays<'_>,
    ) -> Result<Option<f64>, ()> {
        let n = atoms.count();
        let [i, j] = self.ends[k].map(|a| a as usize);
        if i >= n || j >= n {
            return Err(());
        }
        let Some(model) = models.get(usize::from(self.kinds[k])).copied().flatten() else {
            return Ok(None);
        };
        let d = [0, 1, 2].map(|c| atoms.x[3 * i + c] - atoms.x[3 * j + c]);
        let r = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if !(r > 0.0) {
            return Ok(Some(0.0));
        }
        let state = &self.bonds[k].state;
        let axis = d.map(|c| c / r);
        Ok(Some(
            model
                .stored_energy(state, axis, state.r0() - r, atoms.radius[i], atoms.radius[j])
                .total(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::same_kind_run;

    #[test]
    fn a_run_of_one_kind_ends_at_the_first_bond_of_another() {
        assert_eq!(same_kind_run(&[3, 3, 3], 3), 3);
        assert_eq!(same_kind_run(&[3], 3), 1);
        assert_eq!(same_kind_run(&[3, 3, 1, 3], 3), 2);
        assert_eq!(same_kind_run(&[3, 0x8003, 3], 3), 1);
        assert_eq!(same_kind_run(&[3; 64], 3), 64);
    }
}
