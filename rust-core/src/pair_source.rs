//! Where a batch of bonds reads its kinematics: an array of
//! [`PairKinematics`], one per bond, or the engine's own per-atom arrays with
//! each bond given as two atom indices ([`IndexedPairs`]). The second spares
//! the engine a copy of positions, velocities and spins it already holds:
//! 24 numbers per bond and step, written and read back once.

use crate::kinematics::PairKinematics;

/// The kinematics of the bonds of a batch.
pub trait PairSource {
    /// The number of bonds.
    fn len(&self) -> usize;

    /// Whether the batch holds no bond.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The kinematics of bond `b` (`b < len()`).
    fn pair(&self, b: usize) -> PairKinematics;
}

impl PairSource for [PairKinematics] {
    #[inline(always)]
    fn len(&self) -> usize {
        <[PairKinematics]>::len(self)
    }

    #[inline(always)]
    fn pair(&self, b: usize) -> PairKinematics {
        self[b]
    }
}

/// An engine's per-atom arrays (local and ghost atoms): positions,
/// velocities and angular velocities with 3 numbers per atom, one radius per
/// atom (LAMMPS and LIGGGHTS keep `x`, `v`, `omega` as one block of
/// `3 * nmax` doubles).
#[derive(Clone, Copy, Debug)]
pub struct AtomArrays<'a> {
    /// Positions, 3 numbers per atom.
    pub x: &'a [f64],
    /// Velocities, 3 numbers per atom.
    pub v: &'a [f64],
    /// Angular velocities, 3 numbers per atom.
    pub omega: &'a [f64],
    /// Radii, one per atom.
    pub radius: &'a [f64],
}

impl AtomArrays<'_> {
    /// The number of atoms all four arrays hold.
    pub fn count(&self) -> usize {
        (self.x.len() / 3)
            .min(self.v.len() / 3)
            .min(self.omega.len() / 3)
            .min(self.radius.len())
    }
}

/// Bonds as pairs of indices `[i, j]` into [`AtomArrays`], each index checked
/// once, when the batch is made.
#[derive(Clone, Copy, Debug)]
pub struct IndexedPairs<'a> {
    atoms: AtomArrays<'a>,
    pairs: &'a [[i32; 2]],
}

/// A bond whose atom index lies outside the arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexOutOfRange {
    /// The bond (position in `pairs`).
    pub bond: usize,
    /// The offending index.
    pub index: i32,
    /// The number of atoms the arrays hold.
    pub atoms: usize,
}

impl<'a> IndexedPairs<'a> {
    /// The bonds `pairs` over `atoms`, every index checked against
    /// [`AtomArrays::count`]; the error names the first out of range.
    pub fn new(atoms: AtomArrays<'a>, pairs: &'a [[i32; 2]]) -> Result<Self, IndexOutOfRange> {
        let count = atoms.count();
        // All in range, as a negative index read as unsigned is beyond any
        // count below 2^31: one pass without a branch, before the search
        // for the first out of range.
        // (an index is out of range where it or count - 1 - it is negative:
        // the sign bits or'd)
        let last = (count.min(i32::MAX as usize) as i32).wrapping_sub(1);
        if count <= i32::MAX as usize
            && pairs
                .as_flattened()
                .iter()
                .fold(0, |beyond, &a| beyond | a | last.wrapping_sub(a))
                >= 0
        {
            return Ok(Self { atoms, pairs });
        }
        for (bond, p) in pairs.iter().enumerate() {
            for &index in p {
                if usize::try_from(index).map_or(true, |i| i >= count) {
                    return Err(IndexOutOfRange {
                        bond,
                        index,
                        atoms: count,
                    });
                }
            }
        }
        Ok(Self { atoms, pairs })
    }

    /// The bonds' atom indices, each checked below [`Self::atom_count`].
    pub fn pairs(&self) -> &'a [[i32; 2]] {
        self.pairs
    }

    /// The number of atoms the arrays hold.
    pub fn atom_count(&self) -> usize {
        self.atoms.count()
    }

    /// The bonds `range` of this batch, whose indices were checked with it.
    pub fn sub(&self, range: std::ops::Range<usize>) -> Self {
        Self {
            atoms: self.atoms,
            pairs: &self.pairs[range],
        }
    }
}

impl PairSource for IndexedPairs<'_> {
    #[inline(always)]
    fn len(&self) -> usize {
        self.pairs.len()
    }

    #[inline(always)]
    fn pair(&self, b: usize) -> PairKinematics {
        let [i, j] = self.pairs[b].map(|index| index as usize);
        let a = &self.atoms;
        // SAFETY: `new` checked that i and j are below `count`, so the three
        // numbers of each atom lie in each array. Unchecked, so that the reads
        // a kernel does not use are dropped.
        unsafe {
            let three = |array: &[f64], atom: usize| {
                let p = array.as_ptr().add(3 * atom);
                [*p, *p.add(1), *p.add(2)]
            };
            PairKinematics {
                x_i: three(a.x, i),
                x_j: three(a.x, j),
                v_i: three(a.v, i),
                v_j: three(a.v, j),
                w_i: three(a.omega, i),
                w_j: three(a.omega, j),
                radius_i: *a.radius.get_unchecked(i),
                radius_j: *a.radius.get_unchecked(j),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_each_atom_by_its_index() {
        let x: Vec<f64> = (0..9).map(f64::from).collect();
        let v: Vec<f64> = (0..9).map(|k| f64::from(k) + 10.0).collect();
        let w: Vec<f64> = (0..9).map(|k| f64::from(k) + 20.0).collect();
        let radius = [0.5, 0.6, 0.7];
        let atoms = AtomArrays {
            x: &x,
            v: &v,
            omega: &w,
            radius: &radius,
        };
        let pairs = [[2, 0], [1, 2]];
        let src = IndexedPairs::new(atoms, &pairs).unwrap();
        assert_eq!(src.len(), 2);
        let k = src.pair(1);
        assert_eq!(k.x_i, [3.0, 4.0, 5.0]);
        assert_eq!(k.x_j, [6.0, 7.0, 8.0]);
        assert_eq!(k.v_i, [13.0, 14.0, 15.0]);
        assert_eq!(k.w_j, [26.0, 27.0, 28.0]);
        assert_eq!((k.radius_i, k.radius_j), (0.6, 0.7));
        assert_eq!(src.pair(0).x_j, [0.0, 1.0, 2.0]);
    }

    #[test]
    fn refuses_indices_outside_the_shortest_array() {
        let x = [0.0; 9];
        let radius = [1.0; 2]; // 2 atoms, though x, v, omega hold 3
        let atoms = AtomArrays {
            x: &x,
            v: &x,
            omega: &x,
            radius: &radius,
        };
        assert_eq!(atoms.count(), 2);
        let err = |pairs: &[[i32; 2]]| IndexedPairs::new(atoms, pairs).unwrap_err();
        assert_eq!(
            err(&[[0, 1], [1, 2]]),
            IndexOutOfRange {
                bond: 1,
                index: 2,
                atoms: 2
            }
        );
        assert_eq!(
            err(&[[-1, 1]]),
            IndexOutOfRange {
                bond: 0,
                index: -1,
                atoms: 2
            }
        );
        assert!(IndexedPairs::new(atoms, &[[0, 1], [1, 0]]).is_ok());
    }
}
