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
        if listed.len() >= NONE as usize {
            return Err(LinkError(format!(
                "{} listed bonds: a rank holds fewer than {NONE}",
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
        let mut taken = vec![false; count];
        let mut bonds = Vec::with_capacity(listed.len());
        let mut ends = Vec::with_capacity(listed.len());
        let mut kinds = Vec::with_capacity(listed.len());
        let mut created = 0;
        for n in order {
            let n = n as usize;
            let l = listed[n];
            let (o, p) = (l.owner as usize, l.partner as usize);
            let partner = atoms.ids.get(p);
            let mut k = self.head[o];
            let mut found = None;
            while (k as usize) < count {
                let b = k as usize;
                if !taken[b] && owner_of[b] == l.owner && self.bonds[b].partner == partner {
                    found = Some(b);
                    break;
                }
                k = self.next[b];
            }
            let state = match found {
                Some(b) => {
                    taken[b] = true;
                    self.bonds[b].state
                }
                None => {
                    let r = (0..3)
                        .map(|c| (atoms.x[3 * o + c] - atoms.x[3 * p + c]).powi(2))
                        .sum::<f64>()
                        .sqrt();
                    if !(r > 0.0 && r.is_finite()) {
                        return Err(LinkError(format!(
                            "listed bond {n}: its atoms' centres are {r} apart (a bond needs a length)"
                        )));
                    }
                    created += 1;
                    BondState::created(r)
                }
            };
            bonds.push(StoredBond { partner, state });
            ends.push([l.owner, l.partner]);
            kinds.push(l.kind as u16);
        }
        let mut report = LinkReport::default();
        for b in 0..count {
            if taken[b] || self.status(b) != BondStatus::Intact {
                continue; // kept, or packed away to another rank
            }
            report.count(match owner_of[b] {
                -1 => LossCause::OwnerGone,
                -2 => LossCause::IdReused,
                _ => LossCause::NoModel,
            });
        }
        self.bonds = bonds;
        self.ends = ends;
        self.kinds = kinds;
        self.next.clear();
        self.head.fill(NONE);
        self.rebuild_lists();
        self.map.build(atoms.ids);
        self.counts.created += created;
        Ok(self.finish_link(report, atoms.ids, nlocal))
    }
}
