//! Atom ids to local indices: every image of an id among a rank's local and
//! ghost atoms, so that a bond finds its partner's image closest to its
//! owner. Rebuilt at every link; its arrays are kept for the next.

/// The ids of a rank's atoms as the engine keeps them (LAMMPS `tagint`:
/// 32 or 64 bits).
#[derive(Clone, Copy, Debug)]
pub enum Ids<'a> {
    /// 32-bit ids.
    Narrow(&'a [i32]),
    /// 64-bit ids.
    Wide(&'a [i64]),
}

impl Ids<'_> {
    /// The number of atoms.
    pub fn len(&self) -> usize {
        match self {
            Ids::Narrow(ids) => ids.len(),
            Ids::Wide(ids) => ids.len(),
        }
    }

    /// Whether there are no atoms.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Atom `a`'s id.
    #[inline]
    pub fn get(&self, a: usize) -> i64 {
        match self {
            Ids::Narrow(ids) => i64::from(ids[a]),
            Ids::Wide(ids) => ids[a],
        }
    }
}

/// An open-addressing table of ids, each slot the first atom (plus one) of
/// its id, the atom's other images chained in `images`.
#[derive(Debug, Default)]
pub struct IdMap {
    slots: Vec<u32>,
    images: Vec<u32>,
    shift: u32,
}

const EMPTY: u32 = 0;

impl IdMap {
    /// The map of `ids`, atom `a` holding `ids[a]`.
    pub fn build(&mut self, ids: Ids<'_>) {
        // filled to at most three quarters: the ids of a rank are mostly
        // runs of consecutive numbers, which the multiplicative hash spreads
        // evenly, so the probes stay short at half the slots of a half-full
        // table (4 bytes a slot, 2-3 bytes a bond)
        let wanted = (ids.len() + ids.len() / 3 + 1).max(16).next_power_of_two();
        self.slots.clear();
        self.slots.resize(wanted, EMPTY);
        self.shift = 64 - wanted.trailing_zeros();
        self.images.clear();
        self.images.resize(ids.len(), EMPTY);
        let mask = wanted - 1;
        for a in 0..ids.len() {
            let id = ids.get(a);
            let mut s = self.home(id);
            loop {
                let held = self.slots[s];
                if held == EMPTY {
                    self.slots[s] = a as u32 + 1;
                    break;
                }
                if ids.get(held as usize - 1) == id {
                    // another image of the same atom: chained behind this one
                    self.images[a] = held;
                    self.slots[s] = a as u32 + 1;
                    break;
                }
                s = (s + 1) & mask;
            }
        }
    }

    /// The bytes the map holds on the heap.
    pub fn bytes(&self) -> usize {
        (self.slots.capacity() + self.images.capacity()) * std::mem::size_of::<u32>()
    }

    fn home(&self, id: i64) -> usize {
        ((id as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> self.shift) as usize
    }

    /// Every atom holding `id`, in no particular order.
    pub fn images<'m>(&'m self, ids: Ids<'m>, id: i64) -> impl Iterator<Item = usize> + 'm {
        let mask = self.slots.len().wrapping_sub(1);
        let mut first = EMPTY;
        if !self.slots.is_empty() {
            let mut s = self.home(id);
            loop {
                let held = self.slots[s];
                if held == EMPTY || ids.get(held as usize - 1) == id {
                    first = held;
                    break;
                }
                s = (s + 1) & mask;
            }
        }
        std::iter::successors((first != EMPTY).then_some(first), move |&a| {
            let next = self.images[a as usize - 1];
            (next != EMPTY).then_some(next)
        })
        .map(|a| a as usize - 1)
    }
}
