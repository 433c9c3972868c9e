//! What the store holds at its peak while it links: the resident memory an
//! engine's run reports is its peak, so a link that held a second copy of
//! the bonds would cost that copy at every list build. One test in its own
//! binary, under an allocator that counts the bytes held and their peak.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use granbond::bond_store::{BondStore, Ids, ListedAtoms, ListedBond, StoredBond};

struct Counting;

static HELD: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = System.alloc(layout);
        if !p.is_null() {
            let now = HELD.fetch_add(layout.size(), Ordering::SeqCst) + layout.size();
            PEAK.fetch_max(now, Ordering::SeqCst);
        }
        p
    }
    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        System.dealloc(p, layout);
        HELD.fetch_sub(layout.size(), Ordering::SeqCst);
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// The peak of the bytes held while `f` runs, over those held before it.
fn peak_over(f: impl FnOnce()) -> usize {
    let before = HELD.load(Ordering::SeqCst);
    PEAK.store(before, Ordering::SeqCst);
    f();
    PEAK.load(Ordering::SeqCst) - before
}

#[test]
fn relinking_the_topology_holds_no_second_copy_of_its_bonds() {
    // a simple cubic lattice of n^3 touching atoms, each bonded to its
    // neighbours in +x, +y and +z
    let n = 24usize;
    let spacing = 2e-3;
    let at = |x: usize, y: usize, z: usize| (x + n * (y + n * z)) as i32;
    let ids: Vec<i64> = (1..=(n * n * n) as i64).collect();
    let mut x = Vec::with_capacity(3 * ids.len());
    let mut listed = vec![];
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                x.extend([i as f64 * spacing, j as f64 * spacing, k as f64 * spacing]);
                let me = at(i, j, k);
                for (di, dj, dk) in [(1, 0, 0), (0, 1, 0), (0, 0, 1)] {
                    let (a, b, c) = (i + di, j + dj, k + dk);
                    if a < n && b < n && c < n {
                        listed.push(ListedBond {
                            owner: me,
                            partner: at(a, b, c),
                            kind: 1,
                        });
                    }
                }
            }
        }
    }
    let atoms = ListedAtoms {
        ids: Ids::Wide(&ids),
        nlocal: ids.len(),
        x: &x,
    };
    let mut store = BondStore::new();
    store.link_listed(&atoms, &listed).expect("a usable list");
    let bonds = store.len();
    assert_eq!(bonds, listed.len());
    // the same list again, in another order, as the next list build gives it
    listed.reverse();
    let peak = peak_over(|| {
        let report = store.link_listed(&atoms, &listed).expect("a usable list");
        assert_eq!(report.lost(), 0);
    });
    assert_eq!(store.len(), bonds);
    let per_bond = peak as f64 / bonds as f64;
    // the link's own rows (owner, place and order: 4 bytes each a bond) and
    // the id map; a copy of the bonds alone would be 152
    assert_eq!(std::mem::size_of::<StoredBond>(), 152);
    assert!(
        per_bond < 40.0,
        "the relink held {peak} bytes more at its peak, {per_bond:.1} a bond"
    );
}
