//! The view: what a rank knows of the bonds other ranks own whose partner
//! is one of its local atoms, so that its contact loop treats every listed
//! pair that is bonded as bonded, wherever the bond lives
//! (docs/development.md, "Pairs that cross ranks: the view").
//!
//! Each rank packs, for each of its local atoms, the partner ids of the
//! bonds the atom owns ([`BondStore::pack_view`]); the engine sends them to
//! the atom's ghost images (a forward communication), where
//! [`BondStore::unpack_view`] keeps the partners that are local there.

use super::id_map::Ids;
use super::BondStore;
use crate::bond::{BondModel, BondState};
use crate::kinematics::{KinematicsError, PairKinematics};

/// Why a view row could not be packed or unpacked.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ViewError(pub String);

impl BondStore {
    /// Doubles one atom's view row takes on this rank: the count and the
    /// partner ids of the most bonds one local atom owns. A forward
    /// communication sends rows of the largest width over all ranks.
    pub fn view_width(&self) -> usize {
        1 + self.most_owned
    }

    /// Packs local atom `i`'s row into `row` (the count, then the partner
    /// ids of its intact bonds; the rest of `row` zero).
    pub fn pack_view(&self, i: usize, row: &mut [f64]) -> Result<(), ViewError> {
        row.fill(0.0);
        let mut n = 0;
        for k in self.owned(i) {
            n += 1;
            if n >= row.len() {
                return Err(ViewError(format!(
                    "atom {i} owns more bonds than a view row of {} doubles holds",
                    row.len()
                )));
            }
            row[n] = self.bonds[k].partner as f64;
        }
        if let Some(count) = row.first_mut() {
            *count = n as f64;
        }
        Ok(())
    }

    /// Starts the view over: the rows of the ghost atoms follow.
    pub fn clear_view(&mut self) {
        std::mem::swap(&mut self.view, &mut self.view_before);
        self.view.clear();
    }

    /// Ghost atom `g`'s row, as its owner rank packed it: the bonds to
    /// local atoms of this rank join the view. `ids` and `nlocal` are the
    /// rank's atoms as the latest link saw them.
    pub fn unpack_view(
        &mut self,
        g: usize,
        row: &[f64],
        ids: Ids<'_>,
        nlocal: usize,
    ) -> Result<(), ViewError> {
        let count = row.first().copied().unwrap_or(0.0);
        if count.fract() != 0.0 || count < 0.0 || count as usize >= row.len().max(1) {
            return Err(ViewError(format!(
                "a view row announces {count} partners in {} doubles",
                row.len()
            )));
        }
        for &id in &row[1..=count as usize] {
            let locals: Vec<usize> = self.map.images(ids, id as i64).filter(|&i| i < nlocal).collect();
            self.view.extend(locals.into_iter().map(|i| (g as u32, i as u32)));
        }
        Ok(())
    }

    /// Ends the view: it can be asked now. Bonds that left it since the
    /// previous view (broken or lost on their owner's rank) cannot form
    /// again in this pass.
    pub fn finish_view(&mut self) {
        self.view.sort_unstable();
        self.view.dedup();
        let before = std::mem::take(&mut self.view_before);
        for pair in before {
            if self.view.binary_search(&pair).is_err() {
                self.left_view.push(pair);
            }
        }
    }

    /// The bonds of each local atom, wherever they are stored: those it
    /// owns, those it is the partner of on this rank, and those the view
    /// holds for it (owned on another rank), each bond once per atom.
    /// `counts` holds the local atoms; `ids` are the rank's atom ids as the
    /// latest link saw them.
    pub fn count_atoms(&self, counts: &mut [u32], ids: Ids<'_>) {
        counts.fill(0);
        if !self.linked {
            return;
        }
        let nlocal = counts.len().min(self.nlocal);
        // a ghost image of a local atom stands for that atom
        let local_of = |a: usize| -> Option<usize> {
            if a < nlocal {
                return Some(a);
            }
            (a < ids.len())
                .then(|| self.map.images(ids, ids.get(a)).find(|&l| l < nlocal))
                .flatten()
        };
        for e in &self.ends {
            for &a in e {
                if let Some(l) = local_of(a as usize) {
                    counts[l] += 1;
                }
            }
        }
        for &(g, i) in &self.view {
            if local_of(g as usize).is_none() && (i as usize) < nlocal {
                counts[i as usize] += 1;
            }
        }
    }

    /// Whether local atom `i` and atom `j` (local or ghost) are bonded, as
    /// far as this rank knows: a bond one of them owns here, or one the
    /// view holds. `ids` are the rank's atom ids.
    pub fn bonded(&self, i: usize, j: usize, ids: Ids<'_>) -> bool {
        let owns = |a: usize, b: usize| {
            self.owned(a)
                .any(|k| self.ends.get(k).is_some_and(|e| e[1] as usize == b))
        };
        if !self.linked || i >= ids.len() || j >= ids.len() {
            return false;
        }
        owns(i, j) || owns(j, i) || self.view.binary_search(&(j as u32, i as u32)).is_ok()
    }

    /// Whether the rank that owns the pair's bond-to-be creates it in this
    /// pass, for a rank that lists the pair but does not create the bond
    /// (`newton off`): `model`'s creation rules for the kinematics `kin`,
    /// and not a pair whose bond broke in this pass.
    pub fn would_create(
        &self,
        model: &BondModel,
        local: usize,
        ghost: usize,
        kin: &PairKinematics,
        step: i64,
    ) -> Result<bool, KinematicsError> {
        let left = self.left_view.contains(&(ghost as u32, local as u32));
        let broke = self.broken_now.iter().any(|b| {
            let e = b.ends.map(|x| x as usize);
            e == [local, ghost] || e == [ghost, local]
        });
        if left || broke {
            return Ok(false);
        }
        let mut state = BondState::default();
        model.try_create(kin, step, &mut state)
    }
}
