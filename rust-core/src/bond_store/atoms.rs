//! The store's side of the engine's per-atom events: arrays grown, an atom
//! copied over another (sorting, deletion, migration), an atom created, and
//! an atom's bonds packed into a buffer and unpacked from one (migration,
//! restart files). The bonds move with their owner atom; the store keeps
//! them keyed by ids, so the link after the event finds them again.

use super::budget::{packed_extras, DAMPING_LOADS_LEN};
use super::{BondStore, StoredBond, NONE, PACKED_PER_BOND};
use crate::bond::{BondState, BondStatus, BOND_STATE_LEN};

/// Ids travel in doubles: exact up to 2^53.
const LARGEST_ID: i64 = 1 << 53;

/// Why a buffer could not be unpacked.
#[derive(Clone, Debug, PartialEq)]
pub enum UnpackError {
    /// The buffer ends before the bonds it announces.
    Short {
        /// Doubles the buffer holds.
        len: usize,
        /// Doubles its count announces.
        wanted: usize,
    },
    /// The count or an id is not a whole number in range.
    Malformed(&'static str),
}

impl std::fmt::Display for UnpackError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UnpackError::Short { len, wanted } => {
                write!(
                    f,
                    "the packed bonds need {wanted} doubles, the buffer holds {len}"
                )
            }
            UnpackError::Malformed(what) => write!(f, "the packed bonds hold a malformed {what}"),
        }
    }
}

fn whole(x: f64, what: &'static str) -> Result<i64, UnpackError> {
    if x.fract() == 0.0 && x.abs() < LARGEST_ID as f64 {
        Ok(x as i64)
    } else {
        Err(UnpackError::Malformed(what))
    }
}

/// The form of one atom's packed bonds, read from its head.
struct Packed {
    count: usize,
    /// Doubles before the first bond.
    head: usize,
    /// Doubles a bond takes.
    per_bond: usize,
    /// Doubles in all.
    len: usize,
}

fn packed_form(buf: &[f64]) -> Result<Packed, UnpackError> {
    let short = |wanted| UnpackError::Short {
        len: buf.len(),
        wanted,
    };
    let count = whole(*buf.get(1).ok_or(short(2))?, "bond count")?;
    // a negative count: each bond carries extras, their number next
    let (head, extras) = if count < 0 {
        let extras = whole(*buf.get(2).ok_or(short(3))?, "number of extras")?;
        let extras = usize::try_from(extras)
            .ok()
            .filter(|&e| e <= BOND_STATE_LEN)
            .ok_or(UnpackError::Malformed("number of extras"))?;
        (3, extras)
    } else {
        (2, 0)
    };
    let count = usize::try_from(count.unsigned_abs()).map_err(|_| UnpackError::Malformed("bond count"))?;
    let per_bond = PACKED_PER_BOND + extras;
    let len = count
        .checked_mul(per_bond)
        .and_then(|n| n.checked_add(head))
        .ok_or(UnpackError::Malformed("bond count"))?;
    Ok(Packed {
        count,
        head,
        per_bond,
        len,
    })
}

/// The doubles one atom's packed bonds take ([`BondStore::pack`]), read
/// from their head (`buf` holds at least the head: 2 doubles, 3 where the
/// count is negative): where an engine's buffer of several atoms holds the
/// next atom.
pub fn packed_len_in(buf: &[f64]) -> Result<usize, UnpackError> {
    Ok(packed_form(buf)?.len)
}

impl BondStore {
    /// Rows for atoms `0..n` at least. The store's per-atom rows follow the
    /// atoms it is told of (a link's local and ghost atoms, an unpacked
    /// atom, a ghost's seen id), not the room of the engine's per-atom
    /// arrays, which runs ahead of the atoms by up to 16,384 in LAMMPS: an
    /// engine need not call it when its arrays grow. A row beyond them
    /// reads as an atom that owns no bond and that no link has seen.
    pub fn grow(&mut self, n: usize) {
        if n > self.head.len() {
            self.head.resize(n, NONE);
            self.seen.resize(n, 0);
        }
    }

    /// Atom `from` was copied over atom `to` (LAMMPS/LIGGGHTS
    /// `copy_arrays`): `to` now owns `from`'s bonds. Bonds that `to` owned
    /// are no atom's now, and the next link counts them lost.
    pub fn copy(&mut self, from: usize, to: usize) {
        let head = self.head.get(from).copied().unwrap_or(NONE);
        let seen = self.seen(from);
        if to >= self.head.len() && head == NONE && seen == 0 {
            return; // a row beyond the store's reads so already
        }
        self.grow(to + 1);
        self.head[to] = head;
        self.seen[to] = seen;
    }

    /// Atom `i` was created: it owns no bond, and no pass has seen it.
    pub fn clear(&mut self, i: usize) {
        if i < self.head.len() {
            self.head[i] = NONE;
            self.seen[i] = 0;
        }
    }

    /// Atom `i`'s id as a link last saw it (0: never), for the engine to
    /// send to the atom's ghost images.
    pub fn seen(&self, i: usize) -> i64 {
        self.seen.get(i).copied().unwrap_or(0)
    }

    /// The seen id of a ghost image `i`, as its owner rank sent it.
    pub fn set_seen(&mut self, i: usize, id: i64) {
        if i >= self.seen.len() && id == 0 {
            return;
        }
        self.grow(i + 1);
        self.seen[i] = id;
    }

    pub(super) fn owned(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        // a list that leads out of the bonds held (a slot the engine
        // copied after the bonds were laid out again) ends there
        let valid = move |k: u32| (k as usize) < self.bonds.len();
        let first = self.head.get(i).copied().unwrap_or(NONE);
        std::iter::successors(valid(first).then_some(first), move |&k| {
            let next = self.next[k as usize];
            valid(next).then_some(next)
        })
        .map(|k| k as usize)
        .filter(move |&k| self.status(k) == BondStatus::Intact)
    }

    /// Doubles [`Self::pack`] writes for atom `i`.
    pub fn packed_len(&self, i: usize) -> usize {
        self.packed_len_of(self.owned(i).count())
    }

    fn packed_len_of(&self, bonds: usize) -> usize {
        let extras = packed_extras(self.budget.is_some());
        if bonds == 0 || extras == 0 {
            2 + PACKED_PER_BOND * bonds
        } else {
            3 + (PACKED_PER_BOND + extras) * bonds
        }
    }

    /// The most doubles [`Self::pack`] writes for one local atom, as of the
    /// latest link and the bonds created since (a bound for the engine's
    /// exchange and restart buffers).
    pub fn most_packed_len(&self) -> usize {
        self.packed_len_of(self.most_owned)
    }

    /// Packs atom `i`'s bonds into `buf` (at least [`Self::packed_len`]
    /// doubles): its seen id, the count, then per bond the partner's id and
    /// the state. While the energy budget is kept, the count is written
    /// negative and followed by the number of extras each bond carries
    /// after its state (its damping loads of the latest pass, its
    /// dissipated energies): a buffer says what it holds, whoever reads it.
    /// With `leaving` (the atom migrates to another rank) the bonds leave
    /// this store; without (a restart file) they stay. Returns the doubles
    /// written, or `None` if `buf` is too short.
    pub fn pack(&mut self, i: usize, leaving: bool, buf: &mut [f64]) -> Option<usize> {
        let len = self.packed_len(i);
        if buf.len() < len {
            return None;
        }
        buf[0] = self.seen(i) as f64;
        let owned: Vec<usize> = self.owned(i).collect();
        let extras = if owned.is_empty() {
            0
        } else {
            packed_extras(self.budget.is_some())
        };
        let mut at = 2;
        buf[1] = owned.len() as f64;
        if extras > 0 {
            buf[1] = -buf[1];
            buf[2] = extras as f64;
            at = 3;
        }
        for k in owned {
            let bond = &self.bonds[k];
            buf[at] = bond.partner as f64;
            buf[at + 1..at + 1 + BOND_STATE_LEN].copy_from_slice(bond.state.as_slots());
            at += PACKED_PER_BOND;
            if let (Some(budget), true) = (&self.budget, extras > 0) {
                buf[at..at + extras].copy_from_slice(&budget.packed(k));
                at += extras;
            }
            if leaving {
                // gone from this rank without a count: the next link drops it
                self.bonds[k].state.rest = 0.0;
            }
        }
        if leaving {
            if let Some(head) = self.head.get_mut(i) {
                *head = NONE;
            }
            self.linked = false;
        }
        Some(at)
    }

    /// Unpacks into atom `i` (arrived by migration, or read from a restart
    /// file) the bonds [`Self::pack`] wrote to `buf`; returns the doubles
    /// read. Atom `i` owns those bonds and no others.
    pub fn unpack(&mut self, i: usize, buf: &[f64]) -> Result<usize, UnpackError> {
        if buf.len() < 2 {
            return Err(UnpackError::Short {
                len: buf.len(),
                wanted: 2,
            });
        }
        let seen = whole(buf[0], "seen id")?;
        let Packed {
            count,
            head,
            per_bond,
            len: wanted,
        } = packed_form(buf)?;
        if buf.len() < wanted {
            return Err(UnpackError::Short {
                len: buf.len(),
                wanted,
            });
        }
        for b in 0..count {
            let at = head + b * per_bond;
            whole(buf[at], "partner id")?;
        }
        // bonds that carry the budget's extras (a restart file's, written
        // while the budget was kept) keep them until the run's start says
        // whether the budget is kept, so a bond's dissipated energies go on
        // through a restart file as the sums do
        let carried = per_bond - PACKED_PER_BOND;
        if count > 0 && carried > 0 && self.budget.is_none() {
            self.keep_energy_budget(true, carried > DAMPING_LOADS_LEN);
        }
        self.grow(i + 1);
        self.seen[i] = seen;
        // the slot's old list belongs to the atom the engine copied from it
        // (an atom that left, its slot taken by the last one): the arriving
        // atom owns only what it brings, or a later sort that moves it
        // ahead of that atom would hand it their bonds
        self.head[i] = NONE;
        for b in 0..count {
            let at = head + b * per_bond;
            let mut state = BondState::default();
            state
                .as_slots_mut()
                .copy_from_slice(&buf[at + 1..at + 1 + BOND_STATE_LEN]);
            let k = self.push(
                i,
                StoredBond {
                    partner: buf[at] as i64,
                    state,
                },
            );
            if let Some(budget) = &mut self.budget {
                budget.unpacked(k, &buf[at + PACKED_PER_BOND..at + per_bond]);
            }
        }
        self.most_owned = self.most_owned.max(count);
        self.linked = false;
        Ok(wanted)
    }

    /// Adds `bond` to those atom `i` owns.
    pub(super) fn push(&mut self, i: usize, bond: StoredBond) -> usize {
        let k = self.bonds.len();
        self.bonds.push(bond);
        if let Some(budget) = &mut self.budget {
            budget.push();
        }
        self.next.push(self.head[i]);
        self.head[i] = k as u32;
        k
    }
}
