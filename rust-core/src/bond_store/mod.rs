//! The bonds of one rank, each stored once with its partner's id and its
//! state, owned by one of its two atoms and moving with it; and the rule of
//! a pass over them (docs/development.md, "Where a bond lives: the bond
//! store").
//!
//! An engine keeps one [`BondStore`] per rank, behind a per-atom fix that
//! hands the store the engine's per-atom events ([`BondStore::grow`],
//! [`BondStore::copy`], [`BondStore::clear`], [`BondStore::pack`],
//! [`BondStore::unpack`]), and calls [`BondStore::link`] after every
//! neighbour-list build and the pass ([`BondStore::begin_pass`],
//! [`BondStore::step_next`], [`BondStore::try_create`],
//! [`BondStore::finish_pass`]) from its pair loop. The store is keyed by
//! atom ids: sorting, deleting or inserting atoms moves nothing in it.

mod atoms;
mod budget;
mod id_map;
mod link;
mod listed;
mod pass;
mod shares;
mod view;
mod wall;

pub use atoms::{packed_len_in, UnpackError};
pub use budget::{
    step_budget, BondBudgetStep, EnergySums, BUDGET_BYTES_PER_BOND, DAMPING_LOADS_LEN,
    DISSIPATED_BYTES_PER_BOND,
};
pub use id_map::Ids;
pub use link::{LinkAtoms, LinkError, LinkReport, LossCause};
pub use listed::{ListedAtoms, ListedBond};
pub use pass::{creates_here, BrokenBond, StepFailure, StepFailureReason, CHUNK};
pub use shares::SharesError;
pub use view::ViewError;
pub use wall::{WallAct, WallContact, WallError, WallPass, WallStore, WallVisit, WALL_PACKED_PER_BOND};

use crate::bond::{BondState, BondStatus, BOND_STATE_LEN};
use budget::Budget;
use id_map::IdMap;

/// One bond as the store keeps it. The owner is the atom whose list holds
/// the bond; the partner is named by its id, found again at every link.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StoredBond {
    /// The partner atom's id.
    pub partner: i64,
    /// The bond's state; vectors seen from the owner.
    pub state: BondState,
}

/// The bytes a bond costs the store at most: the bond itself, the link of
/// its owner's list, its atoms' local indices and its kind (the last two
/// rebuilt at every link).
pub const BYTES_PER_BOND: usize = std::mem::size_of::<StoredBond>()
    + std::mem::size_of::<u32>()
    + std::mem::size_of::<[i32; 2]>()
    + std::mem::size_of::<u16>();

/// What a bond may cost in memory: less than LAMMPS BPM's bonds (228 bytes
/// measured over the same block without bonds) and LIGGGHTS-INL's (214).
pub const BOND_BUDGET_BYTES: usize = 200;

const _: () = assert!(BYTES_PER_BOND <= BOND_BUDGET_BYTES);

/// The end of an owner's list.
const NONE: u32 = u32::MAX;

/// Doubles a packed bond takes: the partner's id and the state (and, while
/// the energy budget is kept, its extras: see [`BondStore::pack`]).
pub const PACKED_PER_BOND: usize = 1 + BOND_STATE_LEN;

/// Counts since the store was made (or restored), on this rank. Summed over
/// ranks, `created = broken + intact + lost` holds after every pass.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StoreCounts {
    /// Bonds created.
    pub created: i64,
    /// Bonds broken by distance.
    pub broken_distance: i64,
    /// Bonds broken by tension.
    pub broken_tension: i64,
    /// Bonds broken by compression.
    pub broken_compression: i64,
    /// Bonds broken by shear.
    pub broken_shear: i64,
    /// Bonds lost because their owner atom left the system (deleted, or
    /// lost through a boundary).
    pub lost_owner_gone: i64,
    /// Bonds lost because their partner was not among this rank's atoms
    /// (deleted, lost, or farther than the communication cutoff).
    pub lost_partner_unreached: i64,
    /// Bonds lost because an atom's id was taken over by a new atom.
    pub lost_id_reused: i64,
    /// Bonds lost because their atoms' types have no bond model any more.
    pub lost_no_model: i64,
    /// Bonds held now.
    pub intact: i64,
}

impl StoreCounts {
    /// Bonds broken, all modes.
    pub fn broken(&self) -> i64 {
        self.broken_distance + self.broken_tension + self.broken_compression + self.broken_shear
    }

    /// Bonds lost, all causes.
    pub fn lost(&self) -> i64 {
        self.lost_owner_gone + self.lost_partner_unreached + self.lost_id_reused + self.lost_no_model
    }
}

/// The bonds of one rank.
#[derive(Debug, Default)]
pub struct BondStore {
    bonds: Vec<StoredBond>,
    /// Per bond: the next bond of the same owner, [`NONE`] at the end.
    next: Vec<u32>,
    /// Per atom (local; sized like the engine's per-atom arrays): its first
    /// bond, [`NONE`] without one.
    head: Vec<u32>,
    /// Per atom (local and ghost): its id when a link last saw it, 0 for an
    /// atom created since.
    seen: Vec<i64>,
    /// Per bond, from the latest link: owner's and partner's local indices.
    ends: Vec<[i32; 2]>,
    /// Per bond, from the latest link: its bond kind (the engine's model
    /// index).
    kinds: Vec<u16>,
    /// Whether `ends` and `kinds` describe every bond held.
    linked: bool,
    /// The local atoms of the latest link.
    nlocal: usize,
    /// The most bonds one local atom owns, from the latest link and the
    /// bonds created since.
    most_owned: usize,
    map: IdMap,
    cursor: pass::Cursor,
    broken_now: Vec<BrokenBond>,
    /// Pairs whose bond broke, kept while a creation step lies ahead so
    /// that it cannot bond them again.
    broken_pairs: Vec<[i64; 2]>,
    /// Bonds other ranks own to this rank's local atoms, as (ghost owner,
    /// local partner), sorted; the previous view; the pairs that left the
    /// view in this pass.
    view: Vec<(u32, u32)>,
    view_before: Vec<(u32, u32)>,
    left_view: Vec<(u32, u32)>,
    counts: StoreCounts,
    /// The energy budget's per-bond part, while a deck asks for it.
    budget: Option<Budget>,
    energy: EnergySums,
}

impl BondStore {
    /// An empty store.
    pub fn new() -> Self {
        Self::default()
    }

    /// The bonds held.
    pub fn len(&self) -> usize {
        self.bonds.len()
    }

    /// Whether the store holds no bond.
    pub fn is_empty(&self) -> bool {
        self.bonds.is_empty()
    }

    /// Counts since the store was made or restored.
    pub fn counts(&self) -> StoreCounts {
        StoreCounts {
            intact: self.bonds.len() as i64,
            ..self.counts
        }
    }

    /// Restores the counts of a restart file (on one rank; the others keep
    /// zero, so the sums over ranks are the file's).
    pub fn restore_counts(&mut self, counts: &StoreCounts) {
        self.counts = StoreCounts { intact: 0, ..*counts };
    }

    /// Bond `k` and its atoms' local indices (owner first) from the latest
    /// link. `None` beyond the bonds held or before a link.
    pub fn bond(&self, k: usize) -> Option<(StoredBond, [i32; 2])> {
        if !self.linked || k >= self.bonds.len() {
            return None;
        }
        Some((self.bonds[k], self.ends[k]))
    }

    /// Whether the store was linked since atoms last moved into or out of
    /// it.
    pub fn is_linked(&self) -> bool {
        self.linked
    }

    /// The bytes the store holds on the heap now: its bonds and their links,
    /// the per-atom lists and seen ids, and the id map of the latest link.
    pub fn bytes(&self) -> usize {
        use std::mem::size_of;
        self.bonds.capacity() * size_of::<StoredBond>()
            + self.next.capacity() * size_of::<u32>()
            + self.ends.capacity() * size_of::<[i32; 2]>()
            + self.kinds.capacity() * size_of::<u16>()
            + self.head.capacity() * size_of::<u32>()
            + self.seen.capacity() * size_of::<i64>()
            + self.map.bytes()
            + self.broken_pairs.capacity() * size_of::<[i64; 2]>()
            + self.broken_now.capacity() * size_of::<BrokenBond>()
            + (self.view.capacity() + self.view_before.capacity() + self.left_view.capacity())
                * size_of::<(u32, u32)>()
            + self.budget.as_ref().map_or(0, Budget::bytes)
    }

    /// Gives back the room that growing left beyond the bonds held (more
    /// than a sixteenth): bonds are created in bursts, at a creation step.
    fn trim(&mut self) {
        let slack = self.bonds.capacity() - self.bonds.len();
        if slack > self.bonds.len() / 16 {
            self.bonds.shrink_to_fit();
            self.next.shrink_to_fit();
            self.ends.shrink_to_fit();
            self.kinds.shrink_to_fit();
            if let Some(b) = &mut self.budget {
                b.shrink_to_fit();
            }
        }
    }

    fn status(&self, k: usize) -> BondStatus {
        self.bonds[k].state.status()
    }
}
