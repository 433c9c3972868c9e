//! The link of a store whose bonds an engine's topology names (LAMMPS's
//! `bond_style granbond`): the topology says which bonds exist, the store
//! holds their state (docs/development.md, "Topology bonds: the same store").
//!
//! After every list build the engine lists the bonds this rank steps, each
//! once over all ranks: its owner (a local atom), its partner (the image the
//! engine's topology names) and its kind (the bond type). A listed bond the
//! store holds keeps its state; one it does not hold is created at rest at
//! its present length; a stored bond the topology no longer lists is lost.

use super::id_map::Ids;
use super::link::{LinkError, LinkReport, LossCause};
use super::{BondStore, StoredBond, NONE};
use crate::bond::{BondState, BondStatus};

/// One bond of the engine's topology that this rank steps: its atoms' local
/// indices (the owner local, the partner local or ghost) and its kind.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ListedBond {
    /// The owner: a local atom, the one whose bonds travel with it.
    pub owner: i32,
    /// The partner: the image the topology names.
    pub partner: i32,
    /// The bond's kind (the engine's bond type).
    pub kind: i32,
}

/// A rank's atoms as [`BondStore::link_listed`] reads them: `ids` and `x`
/// hold the local atoms first (`nlocal` of them), then the ghost atoms.
#[derive(Clone, Copy, Debug)]
pub struct ListedAtoms<'a> {
    /// Atom ids.
    pub ids: Ids<'a>,
    /// The number of local atoms.
    pub nlocal: usize,
    /// Positions, 3 numbers per atom.
    pub x: &'a [f64],
}

impl BondStore {
    /// Makes the store hold exactly the `listed` bonds (see the module's
    /// text), in the order of their kinds and owners. A stored bond the list
    /// does not name is lost: its owner left (`owner_gone`), its owner's id
    /// was taken over by a new atom (`id_reused`), or the topology dropped
    /// it (counted as `no_model`: the bond has no entry, so no model).
    pub fn link_listed(
        &mut self,
        atoms: &ListedAtoms<'_>,
        listed: &[ListedBond],
    ) -> Result<LinkReport, LinkError> {
        let nall = atoms.ids.len();
        let nlocal = atoms.nlocal;
        if nlocal > nall || atoms.x.len() < 3 * nall {
            return Err(LinkError(format!(
                "the atoms' arrays are shorter than {nall} atoms ({nlocal} local)"
            )));
        }
        if listed.len() >= 1 << 31 {
            return Err(LinkError(format!(
                "{} listed bonds: a rank holds fewer than 2^31",
                listed.len()
            )));
        }
        for (n, l) in listed.iter().enumerate() {
            let owner_ok = usize::try_from(l.owner).is_ok_and(|o| o < nlocal);
            let partner_ok = usize::try_from(l.partner).is_ok_and(|p| p < nall && p != l.owner as usize);
            if !owner_ok || !partner_ok || !(0..i32::from(u16::MAX)).contains(&l.kind) {
                return Err(LinkError(format!(
                    "listed bond {n}: owner {} (of {nlocal} local atoms), partner {} (of {nall} atoms), kind {}",
                    l.owner, l.partner, l.kind
                )));
            }
        }
        self.grow(nall);
        self.view.clear();
        self.view_before.clear();
        let count = self.bonds.len();
        // the local owner of each stored bond: -1 none, -2 an atom that took
        // over a used slot
        let mut owner_of = vec![-1i32; count];
        for i in 0..nlocal {
            let reused = self.seen[i] != atoms.ids.get(i);
            let mut k = self.head[i];
            while (k as usize) < count {
                let b = k as usize;
                if owner_of[b] == -1 && self.status(b) == BondStatus::Intact {
                    owner_of[b] = if reused { -2 } else { i as i32 };
                }
                k = self.next[b];
            }
        }
        // 4 bytes a bond, sorted without a buffer (the index breaks ties, so
        // the order is the stable one)
        let mut order: Vec<u32> = (0..listed.len() as u32).collect();
        order.sort_unstable_by_key(|&n| (listed[n as usize].kind, listed[n as usize].owner, n));
        // the bonds are laid out again in place, as a link does: a second
        // copy of the store at every list build would double its memory
        // there. place[b]: where stored bond b goes, NONE for none yet;
        // order[p] carries MATCHED where place p takes a stored bond
        const MATCHED: u32 = 1 << 31;
        let length = |n: usize| {
            let (o, p) = (listed[n].owner as usize, listed[n].partner as usize);
            let r = (0..3)
                .map(|c| (atoms.x[3 * o + c] - atoms.x[3 * p + c]).powi(2))
                .sum::<f64>()
                .sqrt();
            if r > 0.0 && r.is_finite() {
                Ok(r)
            } else {
                Err(LinkError(format!(
                    "listed bond {n}: its atoms' centres are {r} apart (a bond needs a length)"
                )))
            }
        };
        let mut place = vec![NONE; count];
        let mut created = 0;
        for (at, slot) in order.iter_mut().enumerate() {
            let n = *slot as usize;
            let l = listed[n];
            let partner = atoms.ids.get(l.partner as usize);
            let mut k = self.head[l.owner as usize];
            let mut found = None;
            while (k as usize) < count {
                let b = k as usize;
                if place[b] == NONE && owner_of[b] == l.owner && self.bonds[b].partner == partner {
                    found = Some(b);
                    break;
                }
                k = self.next[b];
            }
            match found {
                Some(b) => {
                    place[b] = at as u32;
                    *slot |= MATCHED;
                }
                None => {
                    length(n)?;
                    created += 1;
                }
            }
        }
        let mut report = LinkReport::default();
        let mut rest = listed.len() as u32;
        for b in 0..count {
            if place[b] != NONE {
                continue;
            }
            // dropped: laid after the listed bonds, then cut off
            place[b] = rest;
            rest += 1;
            if self.status(b) != BondStatus::Intact {
                continue; // packed away to another rank
            }
            report.count(match owner_of[b] {
                -1 => LossCause::OwnerGone,
                -2 => LossCause::IdReused,
                _ => LossCause::NoModel,
            });
        }
        drop(owner_of);
        // the new bonds after the stored ones, each at its place; a store
        // that held none takes them in order, in place already
        let relaid = count > 0;
        self.bonds.reserve_exact(created);
        if relaid {
            place.reserve_exact(created);
        }
        for (at, &slot) in order.iter().enumerate() {
            if slot & MATCHED != 0 {
                continue;
            }
            let n = slot as usize;
            let partner = atoms.ids.get(listed[n].partner as usize);
            self.bonds.push(StoredBond {
                partner,
                state: BondState::created(length(n)?),
            });
            if let Some(budget) = &mut self.budget {
                budget.push();
            }
            if relaid {
                place.push(at as u32);
            }
        }
        let all = self.bonds.len();
        self.ends.clear();
        self.ends.resize(all, [-1, -1]);
        self.kinds.clear();
        self.kinds.resize(all, 0);
        if relaid {
            self.permute(&mut place);
        }
        drop(place);
        self.bonds.truncate(listed.len());
        self.ends.truncate(listed.len());
        self.kinds.truncate(listed.len());
        if let Some(budget) = &mut self.budget {
            budget.truncate(listed.len());
        }
        for (at, &slot) in order.iter().enumerate() {
            let l = listed[(slot & !MATCHED) as usize];
            self.ends[at] = [l.owner, l.partner];
            self.kinds[at] = l.kind as u16;
        }
        drop(order);
        self.next.clear();
        self.head.fill(NONE);
        self.rebuild_lists();
        self.map.build(atoms.ids);
        self.counts.created += created as i64;
        Ok(self.finish_link(report, atoms.ids, nlocal))
    }
}
