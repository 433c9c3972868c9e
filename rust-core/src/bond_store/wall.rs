//! Bonds to walls, owned by their spheres (docs/development.md, "Wall
//! bonds: one per sphere and wall").
//!
//! A wall bond belongs to its sphere and its wall, not to the wall element
//! (a mesh triangle) the engine finds the sphere on: a sphere on the edge
//! shared by two triangles is reported once per triangle, and which ones
//! depends on the decomposition. So the store keys each bond by the
//! sphere's id and the wall's number (given by the engine), steps it at the
//! first contact the wall's loop reports for the sphere in a pass, and tells
//! the other contacts of that pass that the sphere is held (their contact
//! loads are replaced, nothing is added). The anchor (the stand-in
//! sphere's centre, fixed to the wall) is in the bond's state, so it does
//! not depend on the element either.
//!
//! The bonds move with their spheres: packed by id for another rank or a
//! restart file ([`WallStore::pack`], [`WallStore::unpack`]). Per atom slot
//! the store keeps the id whose bonds the atom holds (0 for none), which
//! follows the engine's atom events ([`WallStore::copy`],
//! [`WallStore::clear`]); a contact of an atom without bonds costs one
//! comparison, and an atom that takes over the id of a deleted one does not
//! take over its bonds ([`WallStore::link`]).
//!
//! A broken bond stays in the store while its sphere stays in the wall's
//! reach, as the engine's contact record kept it: the creation rules read
//! its status (a broken bond forms again only under `create_always`). A
//! sphere that leaves the wall's reach (no contact in a force pass) loses
//! its broken bonds silently and its intact ones as lost, counted. The
//! counts are a [`StoreCounts`]: there the wall is the partner, so a bond
//! lost out of the wall's reach is one whose partner was not reached.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::hash::{BuildHasherDefault, Hasher};

use crate::bond::finite::bond_finite;
use crate::bond::output_slots::{load_output, store_output, BOND_OUTPUT_LEN};
use crate::bond::wall::wall_kinematics;
use crate::bond::{BondModel, BondOutput, BondStatus, WallBondState, WALL_BOND_STATE_LEN};
use crate::kinematics::{KinematicsError, SphereKinematics};

use super::id_map::Ids;
use super::pass::count_break;
use super::StoreCounts;

/// What kind of pass a contact belongs to.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WallPass {
    /// A force pass: the bond is advanced (and may form or break).
    Force = 0,
    /// A run's setup pass: the loads of the latest force pass (or those a
    /// law computes afresh), nothing advanced.
    Setup = 1,
    /// An engine's per-contact output pass: what the latest force pass
    /// applied, shown at the contact that applied it.
    Output = 2,
}

/// One contact of a sphere with a wall, as the wall's loop reports it.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct WallContact {
    /// The sphere's local index.
    pub atom: usize,
    /// The sphere's id.
    pub id: i64,
    /// The wall's number (the engine numbers its walls).
    pub wall: u32,
    /// A token of the wall element (triangle) the contact is with, the same
    /// for the same element within a step.
    pub element: i64,
    /// A number of the pass, the same for every contact of one force or
    /// setup pass and different from the previous pass's.
    pub pass: i64,
    /// [`WallPass`] as a number.
    pub kind: i32,
    /// The time step number.
    pub step: i64,
    /// The time step (s).
    pub dt: f64,
    /// Whether a bond may form in this pass (a creation step).
    pub may_create: i32,
    /// The sphere.
    pub sphere: SphereKinematics,
    /// The wall's velocity at the contact point (m/s).
    pub wall_velocity: [f64; 3],
    /// The contact point on the wall (m).
    pub contact_point: [f64; 3],
}

/// What a contact does under the store's answer.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WallAct {
    /// No intact bond: the contact models act alone.
    Contact = 0,
    /// The bond acts at this contact: its loads replace the contact's.
    Bond = 1,
    /// The bond acted at another contact of this pass: the contact's loads
    /// are replaced by nothing.
    Held = 2,
}

/// The store's answer for one contact.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct WallVisit {
    /// [`WallAct`] as a number.
    pub act: i32,
    /// Whether the bond formed at this contact.
    pub created: i32,
    /// The bond's output where it acts here ([`WallAct::Bond`]), or the
    /// step that broke it (its break mode set, no loads).
    pub out: BondOutput,
}

/// Why a contact could not be handled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WallError {
    /// The atom index lies beyond the atoms the store was told of.
    AtomOutOfRange,
    /// The pass kind is not a [`WallPass`].
    UnknownPass,
    /// The sphere's kinematics are unusable.
    Kinematics(KinematicsError),
    /// The bond's results are not finite.
    NonFinite,
    /// A packed row has another layout, or is cut short.
    Packed,
    /// A bond lies on a wall the new numbering has no place for (the wall
    /// of that number in the old numbering).
    WallGone(u32),
    /// A renumbering gives two walls the same number.
    WallTwice(i64),
}

impl std::fmt::Display for WallError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WallError::AtomOutOfRange => {
                write!(f, "the atom index lies beyond the atoms the store was grown to")
            }
            WallError::UnknownPass => write!(f, "the pass kind is none of force (0), setup (1), output (2)"),
            WallError::Kinematics(e) => write!(f, "the sphere's kinematics are unusable: {e:?}"),
            WallError::NonFinite => write!(f, "the bond's force, torque, stress or state is not finite"),
            WallError::Packed => write!(f, "the packed wall bonds have another layout or are cut short"),
            WallError::WallTwice(w) => write!(f, "the new numbering gives wall {w} to two walls"),
            WallError::WallGone(w) => write!(
                f,
                "bonds lie on wall {w}, which has no place in the new numbering"
            ),
        }
    }
}

impl From<KinematicsError> for WallError {
    fn from(e: KinematicsError) -> Self {
        WallError::Kinematics(e)
    }
}

/// Doubles one packed bond takes: its wall, its state, its latest output.
pub const WALL_PACKED_PER_BOND: usize = 1 + WALL_BOND_STATE_LEN + BOND_OUTPUT_LEN;

/// The hash of a (sphere id, wall) key: one multiplication, as the keys
/// are small integers the engine hands out (a look-up per contact must
/// cost little next to the bond's step).
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(b)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }
    fn write_i64(&mut self, n: i64) {
        self.0 = (self.0 ^ n as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
    fn write_u32(&mut self, n: u32) {
        self.0 = (self.0.rotate_left(29) ^ u64::from(n)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// One wall bond.
#[derive(Clone, Copy, Debug)]
struct WallBond {
    state: WallBondState,
    /// The output of the latest force pass, as engines keep it.
    output: [f64; BOND_OUTPUT_LEN],
    /// The pass that last visited the bond.
    pass: i64,
    /// The element it acted at in that pass.
    element: i64,
    /// The step of the latest force or setup pass that reached it.
    reached: i64,
}

impl WallBond {
    fn intact(&self) -> bool {
        self.state.bond.status() == BondStatus::Intact
    }
}

/// A rank's wall bonds.
#[derive(Debug, Default)]
pub struct WallStore {
    bonds: HashMap<(i64, u32), WallBond, BuildHasherDefault<KeyHasher>>,
    /// The highest wall number held: a sphere's bonds are found by trying
    /// each wall up to it.
    walls: u32,
    /// Per atom slot: the id whose bonds the atom holds, 0 for none.
    holds: Vec<i64>,
    pass: i64,
    /// The bonds the current pass has reached so far, and the step of that
    /// pass; those of the previous force or setup pass.
    reached: (usize, i64),
    reached_before: (usize, i64),
    counts: StoreCounts,
}

impl WallStore {
    /// An empty store.
    pub fn new() -> Self {
        Self {
            pass: i64::MIN,
            ..Self::default()
        }
    }

    /// The bonds held, intact or broken.
    pub fn len(&self) -> usize {
        self.bonds.len()
    }

    /// Whether the store holds no bond.
    pub fn is_empty(&self) -> bool {
        self.bonds.is_empty()
    }

    /// Counts since the store was made or restored.
    pub fn counts(&self) -> StoreCounts {
        self.counts
    }

    /// Restores the counts of a restart file (on one rank; the others keep
    /// zero, so the sums over ranks are the file's). The intact bonds are
    /// those held.
    pub fn restore_counts(&mut self, counts: &StoreCounts) {
        self.counts = StoreCounts {
            intact: self.counts.intact,
            ..*counts
        };
    }

    /// Drops every bond and zeroes the counts (the wall is gone; its
    /// engine took the counts).
    pub fn clear_all(&mut self) {
        self.bonds.clear();
        self.walls = 0;
        self.holds.iter_mut().for_each(|h| *h = 0);
        self.counts = StoreCounts::default();
    }

    /// The engine's per-atom arrays hold `nmax` atoms now.
    pub fn grow(&mut self, nmax: usize) {
        if self.holds.len() < nmax {
            self.holds.resize(nmax, 0);
        }
    }

    /// Atom `from` was copied over atom `to`.
    pub fn copy(&mut self, from: usize, to: usize) {
        if from < self.holds.len() && to < self.holds.len() {
            self.holds[to] = self.holds[from];
        }
    }

    /// Atom `i` was created: it holds no bond.
    pub fn clear(&mut self, i: usize) {
        if let Some(h) = self.holds.get_mut(i) {
            *h = 0;
        }
    }

    fn range(&self, id: i64) -> impl Iterator<Item = (&(i64, u32), &WallBond)> {
        (0..=self.walls).filter_map(move |w| self.bonds.get_key_value(&(id, w)))
    }

    /// Doubles [`Self::pack`] writes for sphere `id`.
    pub fn packed_len(&self, id: i64) -> usize {
        2 + self.range(id).count() * WALL_PACKED_PER_BOND
    }

    /// The most doubles one sphere's bonds take.
    pub fn most_packed_len(&self) -> usize {
        let mut per_sphere: HashMap<i64, usize, BuildHasherDefault<KeyHasher>> = HashMap::default();
        for &(id, _) in self.bonds.keys() {
            *per_sphere.entry(id).or_default() += 1;
        }
        2 + per_sphere.values().copied().max().unwrap_or(0) * WALL_PACKED_PER_BOND
    }

    /// Writes sphere `id`'s bonds to `buf` (their count, the doubles a bond
    /// takes, then each bond) and, with `remove` (the sphere leaves this
    /// rank, atom slot `i`), takes them out. Returns the doubles written,
    /// `None` if `buf` is too short.
    pub fn pack(&mut self, i: usize, id: i64, remove: bool, buf: &mut [f64]) -> Option<usize> {
        let n = self.packed_len(id);
        if buf.len() < n {
            return None;
        }
        let keys: Vec<(i64, u32)> = self.range(id).map(|(k, _)| *k).collect();
        buf[0] = keys.len() as f64;
        buf[1] = WALL_PACKED_PER_BOND as f64;
        for (k, key) in keys.iter().enumerate() {
            let b = self.bonds[key];
            let row = &mut buf[2 + k * WALL_PACKED_PER_BOND..2 + (k + 1) * WALL_PACKED_PER_BOND];
            row[0] = f64::from(key.1);
            row[1..=WALL_BOND_STATE_LEN].copy_from_slice(state_slots(&b.state));
            row[1 + WALL_BOND_STATE_LEN..].copy_from_slice(&b.output);
            if remove {
                if b.intact() {
                    self.counts.intact -= 1;
                }
                self.bonds.remove(key);
            }
        }
        if remove {
            self.clear(i);
        }
        Some(n)
    }

    /// The doubles a packed row at the head of `buf` takes (its count and
    /// width read from it).
    pub fn packed_len_in(buf: &[f64]) -> Result<usize, WallError> {
        if buf.len() < 2 || buf[1] != WALL_PACKED_PER_BOND as f64 || !(buf[0] >= 0.0) || buf[0].fract() != 0.0
        {
            return Err(WallError::Packed);
        }
        Ok(2 + buf[0] as usize * WALL_PACKED_PER_BOND)
    }

    /// Reads the bonds [`Self::pack`] wrote into the store, held by atom
    /// slot `i` of id `id`, reached at `step` (so that the next force pass
    /// does not count them out of the wall's reach). Returns the doubles
    /// read.
    pub fn unpack(&mut self, i: usize, id: i64, step: i64, buf: &[f64]) -> Result<usize, WallError> {
        let n = Self::packed_len_in(buf)?;
        if buf.len() < n || i >= self.holds.len() {
            return Err(if buf.len() < n {
                WallError::Packed
            } else {
                WallError::AtomOutOfRange
            });
        }
        let count = buf[0] as usize;
        for k in 0..count {
            let row = &buf[2 + k * WALL_PACKED_PER_BOND..2 + (k + 1) * WALL_PACKED_PER_BOND];
            if !(row[0] >= 0.0) || row[0] > f64::from(u32::MAX) || row[0].fract() != 0.0 {
                return Err(WallError::Packed);
            }
            let mut state = WallBondState::default();
            state_slots_mut(&mut state).copy_from_slice(&row[1..=WALL_BOND_STATE_LEN]);
            let mut output = [0.0; BOND_OUTPUT_LEN];
            output.copy_from_slice(&row[1 + WALL_BOND_STATE_LEN..]);
            let bond = WallBond {
                state,
                output,
                pass: i64::MIN,
                element: 0,
                reached: step,
            };
            if bond.intact() {
                self.counts.intact += 1;
            }
            self.walls = self.walls.max(row[0] as u32);
            if let Some(old) = self.bonds.insert((id, row[0] as u32), bond) {
                if old.intact() {
                    self.counts.intact -= 1;
                }
            }
        }
        self.holds[i] = if count > 0 { id } else { 0 };
        Ok(n)
    }

    /// Renumbers the walls: a bond on wall `w` moves to wall `map[w]` (the
    /// engine's walls listed in another order, as a restart deck may).
    /// A bond on a wall the map has no place for (`w` beyond it, or
    /// `map[w]` negative) is refused, and nothing changes: the engine
    /// says which wall is gone.
    pub fn renumber(&mut self, map: &[i64]) -> Result<(), WallError> {
        let place = |w: u32| map.get(w as usize).and_then(|&m| u32::try_from(m).ok());
        let mut taken = BTreeSet::new();
        if let Some(&m) = map.iter().find(|&&m| m >= 0 && !taken.insert(m)) {
            return Err(WallError::WallTwice(m));
        }
        if let Some(&(_, w)) = self.bonds.keys().find(|k| place(k.1).is_none()) {
            return Err(WallError::WallGone(w));
        }
        let old = std::mem::take(&mut self.bonds);
        self.walls = 0;
        for ((id, w), b) in old {
            let to = place(w).ok_or(WallError::WallGone(w))?;
            self.walls = self.walls.max(to);
            self.bonds.insert((id, to), b);
        }
        Ok(())
    }

    /// Each bond held, as (sphere id, wall), in no particular order (for
    /// the engines' recount of the store).
    pub fn keys(&self) -> impl Iterator<Item = (i64, u32)> + '_ {
        self.bonds.keys().copied()
    }

    /// After atoms moved (a neighbour-list build, a run's start): finds each
    /// bond's sphere among the `ids` of the local atoms. A bond whose sphere
    /// is not one of them (deleted, or lost through a boundary), or whose
    /// id a new atom has taken over, leaves the store; intact, it is
    /// counted lost with that cause.
    pub fn link(&mut self, ids: Ids<'_>) {
        if self.bonds.is_empty() {
            return;
        }
        // the local index of each bonded sphere's id: a scan of the atoms
        // against the few ids with bonds
        let mut at: BTreeMap<i64, usize> = BTreeMap::new();
        let wanted: BTreeSet<i64> = self.bonds.keys().map(|k| k.0).collect();
        for i in 0..ids.len() {
            let id = ids.get(i);
            if wanted.contains(&id) {
                at.insert(id, i);
            }
        }
        let holds = &self.holds;
        let counts = &mut self.counts;
        self.bonds.retain(|&(id, _), b| {
            let cause = match at.get(&id) {
                None => Some(&mut counts.lost_owner_gone),
                Some(&i) if holds.get(i) != Some(&id) => Some(&mut counts.lost_id_reused),
                Some(_) => None,
            };
            match cause {
                None => true,
                Some(c) => {
                    if b.intact() {
                        *c += 1;
                        counts.intact -= 1;
                    }
                    false
                }
            }
        });
        let n = ids.len().min(self.holds.len());
        self.holds[..n].iter_mut().for_each(|h| *h = 0);
        for &(id, _) in self.bonds.keys() {
            if let Some(&i) = at.get(&id) {
                self.holds[i] = id;
            }
        }
    }

    /// A new force pass at `step`: the bonds no contact reached in the
    /// previous one leave the store, the intact ones counted lost (their
    /// sphere left the wall's reach).
    fn begin_force_pass(&mut self, step: i64) {
        // every bond held was reached in the pass before: nothing to look for
        let (reached, at) = self.reached_before;
        if reached == self.bonds.len() && at >= step - 1 {
            return;
        }
        // the atoms' marks are rebuilt at the next link; a stale one costs
        // a look-up
        let counts = &mut self.counts;
        self.bonds.retain(|_, b| {
            if b.reached >= step - 1 {
                return true;
            }
            if b.intact() {
                counts.lost_partner_unreached += 1;
                counts.intact -= 1;
            }
            false
        });
    }

    /// Whether the sphere of atom slot `i` (id `id`) holds an intact bond to
    /// wall `wall`.
    pub fn bonded(&self, i: usize, id: i64, wall: u32) -> bool {
        self.holds.get(i) == Some(&id) && self.bonds.get(&(id, wall)).is_some_and(WallBond::intact)
    }

    /// One contact of a sphere with a wall (module docs): the bond of the
    /// sphere and the wall is stepped, formed or shown at the first contact
    /// of a pass, and holds the sphere at the others.
    pub fn visit(&mut self, model: &BondModel, c: &WallContact) -> Result<WallVisit, WallError> {
        let kind = match c.kind {
            0 => WallPass::Force,
            1 => WallPass::Setup,
            2 => WallPass::Output,
            _ => return Err(WallError::UnknownPass),
        };
        let holds = *self.holds.get(c.atom).ok_or(WallError::AtomOutOfRange)?;
        if kind != WallPass::Output && c.pass != self.pass {
            self.pass = c.pass;
            self.reached_before = self.reached;
            self.reached = (0, c.step);
            if kind == WallPass::Force {
                self.begin_force_pass(c.step);
            }
        }
        let none = WallVisit::default();
        let key = (c.id, c.wall);
        let may_create = kind == WallPass::Force && c.may_create != 0;
        if holds != c.id && !may_create {
            return Ok(none);
        }
        let Some(bond) = self.bonds.get_mut(&key) else {
            return if may_create {
                self.create(model, c)
            } else {
                Ok(none)
            };
        };
        let held = WallVisit {
            act: WallAct::Held as i32,
            ..none
        };
        match kind {
            WallPass::Output => {
                if !bond.intact() {
                    return Ok(none);
                }
                if bond.element != c.element {
                    return Ok(held);
                }
                Ok(WallVisit {
                    act: WallAct::Bond as i32,
                    out: load_output(&bond.output),
                    ..none
                })
            }
            WallPass::Setup => {
                if !bond.intact() {
                    return Ok(none);
                }
                if bond.pass == c.pass {
                    return Ok(held);
                }
                bond.pass = c.pass;
                bond.element = c.element;
                bond.reached = c.step;
                self.reached.0 += 1;
                let mut out = BondOutput::default();
                let kin = wall_kinematics(&c.sphere, bond.state.partner, c.wall_velocity);
                if model.setup_step(&kin, c.dt, &mut bond.state.bond, &mut out, true)? {
                    if !bond_finite(&bond.state.bond, &out) {
                        return Err(WallError::NonFinite);
                    }
                } else {
                    out = load_output(&bond.output);
                }
                Ok(WallVisit {
                    act: WallAct::Bond as i32,
                    out,
                    ..none
                })
            }
            WallPass::Force => {
                if bond.pass == c.pass {
                    return Ok(if bond.intact() { held } else { none });
                }
                bond.pass = c.pass;
                bond.element = c.element;
                bond.reached = c.step;
                self.reached.0 += 1;
                if bond.intact() {
                    let visit = step_bond(model, c, bond, false)?;
                    count_visit(&mut self.counts, &visit);
                    Ok(visit)
                } else if may_create {
                    self.create(model, c)
                } else {
                    Ok(none)
                }
            }
        }
    }

    /// Forms the bond of `c` if the creation rules allow it (on a broken
    /// bond's state, where one is held) and steps it.
    fn create(&mut self, model: &BondModel, c: &WallContact) -> Result<WallVisit, WallError> {
        let key = (c.id, c.wall);
        let mut bond = self.bonds.get(&key).copied().unwrap_or(WallBond {
            state: WallBondState::default(),
            output: [0.0; BOND_OUTPUT_LEN],
            pass: c.pass,
            element: c.element,
            reached: c.step,
        });
        let created = model.try_create_wall(&c.sphere, c.contact_point, c.step, &mut bond.state)?;
        if !created {
            return Ok(WallVisit::default());
        }
        bond.pass = c.pass;
        bond.element = c.element;
        bond.reached = c.step;
        if self.bonds.insert(key, bond).is_none() {
            self.reached.0 += 1;
        }
        self.walls = self.walls.max(c.wall);
        self.holds[c.atom] = c.id;
        self.counts.created += 1;
        self.counts.intact += 1;
        self.step(model, c, true)
    }

    /// Advances the intact bond of `c` by the pass's time step.
    fn step(&mut self, model: &BondModel, c: &WallContact, created: bool) -> Result<WallVisit, WallError> {
        let bond = self
            .bonds
            .get_mut(&(c.id, c.wall))
            .ok_or(WallError::AtomOutOfRange)?;
        let visit = step_bond(model, c, bond, created)?;
        count_visit(&mut self.counts, &visit);
        Ok(visit)
    }

    /// The bytes the store holds on the heap (about: a tree node a bond).
    pub fn bytes(&self) -> usize {
        self.bonds.capacity() * (std::mem::size_of::<WallBond>() + std::mem::size_of::<(i64, u32)>() + 1)
            + self.holds.capacity() * std::mem::size_of::<i64>()
    }
}

/// Advances `bond`, the intact bond of `c`; the loads of an intact bond
/// are kept as its latest output.
fn step_bond(
    model: &BondModel,
    c: &WallContact,
    bond: &mut WallBond,
    created: bool,
) -> Result<WallVisit, WallError> {
    let mut out = BondOutput::default();
    model.step_wall(&c.sphere, c.wall_velocity, c.dt, &mut bond.state, &mut out)?;
    if !bond_finite(&bond.state.bond, &out) || !bond.state.partner.iter().all(|p| p.is_finite()) {
        return Err(WallError::NonFinite);
    }
    let intact = out.status == BondStatus::Intact as i32;
    if intact {
        bond.output = store_output(&out);
    }
    Ok(WallVisit {
        act: if intact { WallAct::Bond } else { WallAct::Contact } as i32,
        created: created as i32,
        out,
    })
}

/// A bond that broke in `visit` counted by its mode.
fn count_visit(counts: &mut StoreCounts, visit: &WallVisit) {
    if visit.out.status != BondStatus::Intact as i32 {
        count_break(counts, visit.out.break_mode);
        counts.intact -= 1;
    }
}

fn state_slots(s: &WallBondState) -> &[f64; WALL_BOND_STATE_LEN] {
    // SAFETY: WallBondState is repr(C) of exactly WALL_BOND_STATE_LEN f64
    // (asserted where it is defined).
    unsafe { &*(s as *const WallBondState as *const [f64; WALL_BOND_STATE_LEN]) }
}

fn state_slots_mut(s: &mut WallBondState) -> &mut [f64; WALL_BOND_STATE_LEN] {
    // SAFETY: as above.
    unsafe { &mut *(s as *mut WallBondState as *mut [f64; WALL_BOND_STATE_LEN]) }
}
