//! The link: after every neighbour-list build, each bond finds its atoms
//! again from their ids. The owner is the local atom whose list holds the
//! bond; the partner is the image of its id closest to the owner among the
//! local and ghost atoms. A bond whose atom is not found, or whose atom is
//! a new one that took over an old id, is lost: dropped and counted by
//! cause. The bonds are then laid out in their owners' order, in place, so
//! a pass reads the atoms' arrays in order.

use super::id_map::Ids;
use super::{BondStore, NONE};
use crate::bond::BondStatus;

/// A rank's atoms as the link reads them: `ids`, `x` and `types` hold the
/// local atoms first (`nlocal` of them), then the ghost atoms.
#[derive(Clone, Copy, Debug)]
pub struct LinkAtoms<'a> {
    /// Atom ids.
    pub ids: Ids<'a>,
    /// The number of local atoms.
    pub nlocal: usize,
    /// Positions, 3 numbers per atom.
    pub x: &'a [f64],
    /// Atom types (1-based, as the engines number them).
    pub types: &'a [i32],
    /// The bond kind of each pair of types: `kinds[ti * (ntypes + 1) + tj]`,
    /// negative where the types have no bond model.
    pub kinds: &'a [i32],
    /// The number of atom types.
    pub ntypes: usize,
    /// The farthest a bond's atoms may be apart and still be found (the
    /// reach of the ghost atoms), so that a bond is found alike on one rank
    /// and on several; not above 0: no limit.
    pub reach: f64,
}

/// Why a bond left the store without breaking.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LossCause {
    /// Its owner atom left the system (deleted, or lost through a
    /// boundary).
    OwnerGone = 0,
    /// Its partner was not among the rank's atoms: deleted, lost, or
    /// farther than the communication cutoff.
    PartnerUnreached = 1,
    /// One of its atoms' ids was taken over by a new atom.
    IdReused = 2,
    /// Its atoms' types have no bond model.
    NoModel = 3,
}

/// What one link found: the bonds it lost, by cause.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LinkReport {
    /// Bonds held after the link.
    pub linked: i64,
    /// Lost: the owner left.
    pub owner_gone: i64,
    /// Lost: the partner was not found.
    pub partner_unreached: i64,
    /// Lost: an id was taken over by a new atom.
    pub id_reused: i64,
    /// Lost: no bond model for the atoms' types.
    pub no_model: i64,
}

impl LinkReport {
    pub(super) fn count(&mut self, cause: LossCause) {
        match cause {
            LossCause::OwnerGone => self.owner_gone += 1,
            LossCause::PartnerUnreached => self.partner_unreached += 1,
            LossCause::IdReused => self.id_reused += 1,
            LossCause::NoModel => self.no_model += 1,
        }
    }

    /// Bonds lost, all causes.
    pub fn lost(&self) -> i64 {
        self.owner_gone + self.partner_unreached + self.id_reused + self.no_model
    }
}

/// Why the link could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkError(pub String);

impl BondStore {
    /// Finds every bond's atoms in `atoms` (see the module's text), drops
    /// and counts the bonds lost, and marks every local atom seen.
    pub fn link(&mut self, atoms: &LinkAtoms<'_>) -> Result<LinkReport, LinkError> {
        let nall = atoms.ids.len();
        if atoms.nlocal > nall || atoms.x.len() < 3 * nall || atoms.types.len() < nall {
            return Err(LinkError(format!(
                "the atoms' arrays are shorter than {nall} atoms ({} local)",
                atoms.nlocal
            )));
        }
        let nt1 = atoms.ntypes + 1;
        if atoms.kinds.len() < nt1 * nt1 {
            return Err(LinkError(format!(
                "the kinds of type pairs hold {} entries, {} types need {}",
                atoms.kinds.len(),
                atoms.ntypes,
                nt1 * nt1
            )));
        }
        self.grow(nall);
        // the view names atoms by the indices of the previous link
        self.view.clear();
        self.view_before.clear();
        let mut report = LinkReport::default();
        let count = self.bonds.len();
        // ends[b]: the owner from the local atoms' lists, then the partner;
        // an owner of -1 is none, -2 an atom that took over a used slot
        self.ends.clear();
        self.ends.resize(count, [-1, -1]);
        self.kinds.clear();
        self.kinds.resize(count, 0);
        // ghost slots own nothing: what a copy left there goes too
        self.head[atoms.nlocal..].fill(NONE);
        for i in 0..atoms.nlocal {
            let mut k = std::mem::replace(&mut self.head[i], NONE);
            // a list left on an atom the engine created without telling the
            // store belongs to the atom that held the slot before
            let reused = self.seen[i] != atoms.ids.get(i);
            while (k as usize) < count {
                let b = k as usize;
                if self.ends[b][0] == -1 && self.status(b) == BondStatus::Intact {
                    self.ends[b][0] = if reused { -2 } else { i as i32 };
                }
                k = self.next[b];
            }
        }
        self.map.build(atoms.ids);
        // bonds kept per owner, counted for their places in owner order
        let mut first = vec![0u32; atoms.nlocal + 1];
        let mut keep = vec![false; count];
        for b in 0..count {
            if self.status(b) != BondStatus::Intact {
                continue; // packed away to another rank: not a loss
            }
            match self.find_partner(atoms, b) {
                Ok(()) => {
                    keep[b] = true;
                    first[self.ends[b][0] as usize + 1] += 1;
                }
                Err(cause) => report.count(cause),
            }
        }
        for i in 0..atoms.nlocal {
            first[i + 1] += first[i];
        }
        let kept = first[atoms.nlocal] as usize;
        // each bond's place: kept ones by owner, in their order; the rest after
        let mut place = vec![0u32; count];
        let mut rest = kept as u32;
        for b in 0..count {
            if keep[b] {
                let i = self.ends[b][0] as usize;
                place[b] = first[i];
                first[i] += 1;
            } else {
                place[b] = rest;
                rest += 1;
            }
        }
        drop((first, keep));
        self.permute(&mut place);
        self.bonds.truncate(kept);
        self.ends.truncate(kept);
        self.kinds.truncate(kept);
        if let Some(budget) = &mut self.budget {
            budget.truncate(kept);
        }
        self.rebuild_lists();
        Ok(self.finish_link(report, atoms.ids, atoms.nlocal))
    }

    /// The end of a link: every local atom marked seen, the losses
    /// counted, the store linked.
    pub(super) fn finish_link(&mut self, mut report: LinkReport, ids: Ids<'_>, nlocal: usize) -> LinkReport {
        for i in 0..nlocal {
            self.seen[i] = ids.get(i);
        }
        report.linked = self.bonds.len() as i64;
        self.nlocal = nlocal;
        self.counts.lost_owner_gone += report.owner_gone;
        self.counts.lost_partner_unreached += report.partner_unreached;
        self.counts.lost_id_reused += report.id_reused;
        self.counts.lost_no_model += report.no_model;
        self.linked = true;
        report
    }

    /// Bond `b`'s partner (its image closest to the owner) and kind, or why
    /// the bond is lost.
    fn find_partner(&mut self, atoms: &LinkAtoms<'_>, b: usize) -> Result<(), LossCause> {
        let i = match self.ends[b][0] {
            -1 => return Err(LossCause::OwnerGone),
            -2 => return Err(LossCause::IdReused),
            i => i as usize,
        };
        let j = self
            .closest_image(atoms, i, self.bonds[b].partner)
            .ok_or(LossCause::PartnerUnreached)?;
        if atoms.reach > 0.0 {
            let d2: f64 = (0..3)
                .map(|c| (atoms.x[3 * i + c] - atoms.x[3 * j + c]).powi(2))
                .sum();
            if d2 > atoms.reach * atoms.reach {
                return Err(LossCause::PartnerUnreached);
            }
        }
        // an atom no link has seen under this id is a new atom that took it
        // over (its owner rank marks it seen at every link, and the mark
        // reaches its ghost images with the next border exchange)
        if self.seen[j] != atoms.ids.get(j) {
            return Err(LossCause::IdReused);
        }
        let kind = type_pair(atoms.types[i], atoms.types[j], atoms.ntypes).map(|p| atoms.kinds[p]);
        match kind {
            Some(kind) if (0..i32::from(u16::MAX)).contains(&kind) => {
                self.ends[b][1] = j as i32;
                self.kinds[b] = kind as u16;
                Ok(())
            }
            _ => Err(LossCause::NoModel),
        }
    }

    /// The image of `id` closest to atom `i`.
    fn closest_image(&self, atoms: &LinkAtoms<'_>, i: usize, id: i64) -> Option<usize> {
        let xi = &atoms.x[3 * i..3 * i + 3];
        let mut best: Option<(f64, usize)> = None;
        for j in self.map.images(atoms.ids, id) {
            if j == i {
                continue;
            }
            let xj = &atoms.x[3 * j..3 * j + 3];
            let d = (xi[0] - xj[0]).powi(2) + (xi[1] - xj[1]).powi(2) + (xi[2] - xj[2]).powi(2);
            // the lower index wins a tie, so every rank picks alike
            if best.is_none_or(|(bd, bj)| d < bd || (d == bd && j < bj)) {
                best = Some((d, j));
            }
        }
        best.map(|(_, j)| j)
    }

    /// Moves bond `b` (with its ends and kind) to `place[b]`, in place:
    /// `place` is a permutation, and is left as the identity.
    pub(super) fn permute(&mut self, place: &mut [u32]) {
        for b in 0..place.len() {
            while place[b] as usize != b {
                let to = place[b] as usize;
                self.bonds.swap(b, to);
                self.ends.swap(b, to);
                self.kinds.swap(b, to);
                if let Some(budget) = &mut self.budget {
                    budget.swap(b, to);
                }
                place.swap(b, to);
            }
        }
    }

    /// The owners' lists from the ends of the bonds, each in store order.
    /// The heads of the owners must have been cleared.
    pub(super) fn rebuild_lists(&mut self) {
        self.next.clear();
        self.next.resize(self.bonds.len(), NONE);
        for k in (0..self.bonds.len()).rev() {
            let i = self.ends[k][0] as usize;
            self.next[k] = self.head[i];
            self.head[i] = k as u32;
        }
        // counted along the lists: a per-atom count would cost a row an atom
        self.most_owned = (0..self.head.len())
            .map(|i| self.owned(i).count())
            .max()
            .unwrap_or(0);
    }
}

/// Where the pair of types `ti`, `tj` sits in a table of kinds, if both are
/// in range.
fn type_pair(ti: i32, tj: i32, ntypes: usize) -> Option<usize> {
    let (ti, tj) = (usize::try_from(ti).ok()?, usize::try_from(tj).ok()?);
    (ti <= ntypes && tj <= ntypes).then_some(ti * (ntypes + 1) + tj)
}
