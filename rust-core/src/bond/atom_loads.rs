//! A pass's loads added to the engine's per-atom sums by the step itself,
//! as the engines' own pair loops add theirs: for each bond in turn, the
//! owner's force and torque, then the partner's (minus the force, its own
//! torque), each scaled by the atom's factor where the engine has one
//! (LIGGGHTS's relaxation factor). A partner that is a ghost gets its
//! loads in rows of its own where the engine does not sum ghosts' loads to
//! their owners (`newton off`). The adds of one atom come in the bonds'
//! order, so the sums are the bits of an engine adding the outputs one
//! bond after another.
//!
//! Every length is checked once, when the sums are taken for a pass
//! (`AtomLoads::rows`), and every index once a chunk, with the chunk's
//! kinematics (`LoadSink::adding`): the adds themselves check nothing.

use super::state::BondOutput;
use crate::pair_source::IndexedPairs;
use std::cell::Cell;
use std::marker::PhantomData;
use std::ops::Range;

/// The engine's per-atom sums the bonds' loads go to.
#[derive(Debug)]
pub struct AtomLoads<'a> {
    /// Forces, 3 numbers per atom (local, then ghost).
    pub force: &'a mut [f64],
    /// Torques, 3 numbers per atom.
    pub torque: &'a mut [f64],
    /// The number of local atoms: a partner at or beyond it is a ghost.
    pub nlocal: usize,
    /// Where a ghost partner's loads go instead of its own rows: 6 numbers
    /// per ghost (force, then torque), ghost `j` at row `j - nlocal`, for
    /// the engine to send to the ghost's owner; `None`: the ghost's own rows.
    pub ghost_rows: Option<&'a mut [f64]>,
    /// Each atom's factor on the loads it receives; `None`: 1.
    pub relax: Option<&'a [f64]>,
}

/// Why [`AtomLoads`] cannot take the loads of atoms' bonds: the parameter
/// that is too short.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LoadsTooShort(pub &'static str);

impl AtomLoads<'_> {
    /// The rows of the sums for `atoms` atoms (local and ghost), each array
    /// checked to hold them all.
    pub(crate) fn rows(&mut self, atoms: usize) -> Result<Rows<'_>, LoadsTooShort> {
        let three = atoms.saturating_mul(3);
        if self.force.len() < three {
            return Err(LoadsTooShort("force"));
        }
        if self.torque.len() < three {
            return Err(LoadsTooShort("torque"));
        }
        if self.nlocal > atoms {
            return Err(LoadsTooShort("nlocal"));
        }
        if self.relax.is_some_and(|r| r.len() < atoms) {
            return Err(LoadsTooShort("relax"));
        }
        let ghosts = match &mut self.ghost_rows {
            Some(g) if g.len() < (atoms - self.nlocal).saturating_mul(6) => {
                return Err(LoadsTooShort("ghost_rows"))
            }
            Some(g) => g.as_mut_ptr(),
            None => std::ptr::null_mut(),
        };
        Ok(Rows {
            force: self.force.as_mut_ptr(),
            torque: self.torque.as_mut_ptr(),
            ghosts,
            relax: self.relax.map_or(std::ptr::null(), |r| r.as_ptr()),
            nlocal: self.nlocal,
            atoms,
            borrowed: PhantomData,
        })
    }
}

/// The sums of [`AtomLoads`] for a number of atoms, their lengths checked.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rows<'a> {
    force: *mut f64,
    torque: *mut f64,
    // null: none
    ghosts: *mut f64,
    // null: none
    relax: *const f64,
    nlocal: usize,
    atoms: usize,
    borrowed: PhantomData<&'a mut f64>,
}

/// Where a kernel's chunk of bonds puts its loads: into the outputs only, or
/// added to the atoms' sums too.
pub(crate) struct LoadSink<'a> {
    rows: Option<Rows<'a>>,
    pairs: *const [i32; 2],
    /// Whether every output is written: the loads and stresses, not only the
    /// status and break mode.
    pub(crate) outputs: bool,
    /// Whether the lanes add the loads from their registers (no factor per
    /// atom).
    pub(crate) direct: bool,
    /// Whether a ghost partner's loads go to the ghost rows.
    pub(crate) route: bool,
    /// Whether every bond stepped so far went to the atoms from the lanes:
    /// then none broke, and their statuses need no look.
    pub(crate) all_direct: Cell<bool>,
}

impl<'a> LoadSink<'a> {
    /// Every output written, nothing added.
    pub(crate) fn outputs() -> Self {
        Self {
            rows: None,
            pairs: std::ptr::null(),
            outputs: true,
            direct: false,
            route: false,
            all_direct: Cell::new(false),
        }
    }

    /// The loads of the bonds of `kin` added to `rows`, and every output
    /// written if `outputs`; `None` if `rows` hold fewer atoms than `kin`
    /// reads (whose indices `kin` checked).
    pub(crate) fn adding(rows: Rows<'a>, kin: &IndexedPairs<'a>, outputs: bool) -> Option<Self> {
        if rows.atoms < kin.atom_count() {
            return None;
        }
        let pairs = kin.pairs();
        // a ghost partner's rows are looked for lanes by lane, where it has
        // any
        let route = !rows.ghosts.is_null();
        Some(Self {
            direct: rows.relax.is_null(),
            rows: Some(rows),
            pairs: pairs.as_ptr(),
            outputs,
            route,
            all_direct: Cell::new(true),
        })
    }

    /// Adds the loads of bonds `range` from their outputs, bond by bond.
    #[inline(always)]
    pub(crate) fn add_outputs(&self, range: Range<usize>, outs: &[BondOutput]) {
        if !range.is_empty() {
            self.all_direct.set(false);
        }
        let Some(r) = &self.rows else { return };
        for b in range {
            let o = &outs[b];
            // SAFETY: `adding` checked that the rows hold every atom of the
            // kernel's pairs, and the kernel steps no bond beyond them.
            unsafe {
                let [i, j] = self.ends(b);
                r.add_scaled(i, j, o.force_i, o.torque_i, o.torque_j);
            }
        }
    }

    /// Bond `b`'s atoms.
    ///
    /// # Safety
    /// `b` must be a bond of the kinematics the sink was made with.
    #[inline(always)]
    pub(crate) unsafe fn ends(&self, b: usize) -> [usize; 2] {
        // SAFETY: the caller's; the indices were checked not negative.
        unsafe { (*self.pairs.add(b)).map(|a| a as usize) }
    }

    /// The rows of the sums; only for a sink made by [`Self::adding`].
    #[inline(always)]
    pub(crate) fn rows(&self) -> &Rows<'a> {
        self.rows.as_ref().expect("a sink that adds")
    }
}

impl Rows<'_> {
    /// The number of local atoms.
    #[inline(always)]
    pub(crate) fn nlocal(&self) -> usize {
        self.nlocal
    }

    /// Atom `i`'s force row.
    ///
    /// # Safety
    /// `i` must be below the atoms the rows were checked for.
    #[inline(always)]
    pub(crate) unsafe fn force_of(&self, i: usize) -> *mut f64 {
        // SAFETY: the caller's.
        unsafe { self.force.add(3 * i) }
    }

    /// Atom `i`'s torque row.
    ///
    /// # Safety
    /// As [`Self::force_of`].
    #[inline(always)]
    pub(crate) unsafe fn torque_of(&self, i: usize) -> *mut f64 {
        // SAFETY: the caller's.
        unsafe { self.torque.add(3 * i) }
    }

    /// Partner `j`'s force and torque rows: its ghost row where `ROUTE` and
    /// it is a ghost, else its own.
    ///
    /// # Safety
    /// As [`Self::force_of`]; `ROUTE` only where the rows have ghost rows.
    #[inline(always)]
    pub(crate) unsafe fn partner_of<const ROUTE: bool>(&self, j: usize) -> (*mut f64, *mut f64) {
        // SAFETY: the caller's; a ghost's row lies within the ghost rows,
        // checked for every ghost.
        unsafe {
            if ROUTE && j >= self.nlocal {
                let g = self.ghosts.add(6 * (j - self.nlocal));
                (g, g.add(3))
            } else {
                (self.force_of(j), self.torque_of(j))
            }
        }
    }

    /// One bond's loads added one component at a time, each scaled by its
    /// atom's factor.
    ///
    /// # Safety
    /// As [`Self::force_of`], for `i` and `j`.
    #[inline(always)]
    unsafe fn add_scaled(&self, i: usize, j: usize, f: [f64; 3], ti: [f64; 3], tj: [f64; 3]) {
        // SAFETY: the caller's.
        unsafe {
            let factor = |a: usize| {
                if self.relax.is_null() {
                    1.0
                } else {
                    *self.relax.add(a)
                }
            };
            let (ri, rj) = (factor(i), factor(j));
            let (fi, ti_row) = (self.force_of(i), self.torque_of(i));
            let (fj, tj_row) = match self.ghosts.is_null() {
                true => self.partner_of::<false>(j),
                false => self.partner_of::<true>(j),
            };
            for (c, x) in f.iter().enumerate() {
                *fi.add(c) += ri * x;
            }
            for (c, x) in ti.iter().enumerate() {
                *ti_row.add(c) += ri * x;
            }
            for (c, x) in f.iter().enumerate() {
                *fj.add(c) -= rj * x;
            }
            for (c, x) in tj.iter().enumerate() {
                *tj_row.add(c) += rj * x;
            }
        }
    }
}
