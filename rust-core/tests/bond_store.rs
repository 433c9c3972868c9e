//! The bond store (`granbond::bond_store`): each bond once, found again
//! from its atoms' ids after the engine sorts, deletes, inserts or moves
//! atoms, stepped by one pass, counted so that created = broken + intact +
//! lost.

use granbond_test_support as common;

use granbond::bond::{AtomLoads, BondModel, BondOutput, BondParams, BondState, BondStatus, BreakMode, Simd};
use granbond::bond_store::{
    creates_here, BondStore, Ids, LinkAtoms, LinkReport, StepFailureReason, StoreCounts, StoredBond,
    BOND_BUDGET_BYTES, BYTES_PER_BOND, CHUNK,
};
use granbond::kinematics::PairKinematics;
use granbond::ledger::check::{flag_finding, pair_keys};
use granbond::pair_source::AtomArrays;

const R: f64 = common::RADIUS;

/// A rank's atoms, local first, then ghosts.
#[derive(Clone, Debug, Default)]
struct Atoms {
    ids: Vec<i64>,
    x: Vec<f64>,
    v: Vec<f64>,
    omega: Vec<f64>,
    radius: Vec<f64>,
    types: Vec<i32>,
    nlocal: usize,
}

impl Atoms {
    fn add(&mut self, id: i64, x: [f64; 3], seed: u64) {
        let wobble = |k: u64| {
            ((seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(k * 1442695040888963407)
                >> 33) as f64
                / (1u64 << 31) as f64)
                - 0.5
        };
        self.ids.push(id);
        self.x.extend(x);
        self.v
            .extend([1e-2 * wobble(1), 1e-2 * wobble(2), 1e-2 * wobble(3)]);
        self.omega
            .extend([5.0 * wobble(4), 5.0 * wobble(5), 5.0 * wobble(6)]);
        self.radius.push(R);
        self.types.push(1);
    }

    fn len(&self) -> usize {
        self.ids.len()
    }

    /// A simple cubic lattice of touching spheres, n per side, ids from 1.
    fn lattice(n: usize) -> Self {
        let mut a = Atoms::default();
        for z in 0..n {
            for y in 0..n {
                for x in 0..n {
                    let id = 1 + (x + n * (y + n * z)) as i64;
                    // a little off the lattice, so bonds start sheared
                    let jitter = 1e-6 * ((id * 7919 % 13) as f64 - 6.0);
                    a.add(
                        id,
                        [
                            2.0 * R * x as f64 + jitter,
                            2.0 * R * y as f64,
                            2.0 * R * z as f64 - jitter,
                        ],
                        id as u64,
                    );
                }
            }
        }
        a.nlocal = a.len();
        a
    }

    fn arrays(&self) -> AtomArrays<'_> {
        AtomArrays {
            x: &self.x,
            v: &self.v,
            omega: &self.omega,
            radius: &self.radius,
        }
    }

    fn link_atoms<'a>(&'a self, kinds: &'a [i32]) -> LinkAtoms<'a> {
        LinkAtoms {
            ids: Ids::Wide(&self.ids),
            nlocal: self.nlocal,
            x: &self.x,
            types: &self.types,
            kinds,
            ntypes: 1,
            reach: 0.0,
        }
    }

    fn kinematics(&self, i: usize, j: usize) -> PairKinematics {
        let three = |a: &[f64], k: usize| [a[3 * k], a[3 * k + 1], a[3 * k + 2]];
        PairKinematics {
            x_i: three(&self.x, i),
            x_j: three(&self.x, j),
            v_i: three(&self.v, i),
            v_j: three(&self.v, j),
            w_i: three(&self.omega, i),
            w_j: three(&self.omega, j),
            radius_i: self.radius[i],
            radius_j: self.radius[j],
        }
    }

    /// Moves every atom by its velocity over `dt` (a drift, so that bonds
    /// load between passes).
    fn drift(&mut self, dt: f64) {
        for (x, v) in self.x.iter_mut().zip(&self.v) {
            *x += v * dt;
        }
    }

    /// The engine's permutation of the local atoms: new atom `n` is old atom
    /// `order[n]`, carried out as LAMMPS's sort does, through copies and a
    /// spare slot at `nlocal` (which may lie beyond the store's rows: the
    /// adapters do not grow them with the engine's arrays).
    fn permute(&mut self, store: &mut BondStore, order: &[usize]) {
        let n = self.nlocal;
        let old = self.clone();
        let mut at: Vec<usize> = (0..n).collect(); // where old atom k sits now
        let mut holds: Vec<usize> = (0..n).collect(); // which old atom slot s holds
        for dest in 0..n {
            let want = order[dest];
            let src = at[want];
            if src == dest {
                continue;
            }
            // move what dest holds to the spare slot, src into dest, spare into src
            store.copy(dest, n);
            store.copy(src, dest);
            store.copy(n, src);
            let displaced = holds[dest];
            holds[src] = displaced;
            at[displaced] = src;
            holds[dest] = want;
            at[want] = dest;
        }
        for (dest, &k) in order.iter().enumerate() {
            self.ids[dest] = old.ids[k];
            self.radius[dest] = old.radius[k];
            self.types[dest] = old.types[k];
            for c in 0..3 {
                self.x[3 * dest + c] = old.x[3 * k + c];
                self.v[3 * dest + c] = old.v[3 * k + c];
                self.omega[3 * dest + c] = old.omega[3 * k + c];
            }
        }
    }

    /// Deletes local atom `i` as the engines do: the last local atom is
    /// copied over it.
    fn delete(&mut self, store: &mut BondStore, i: usize) {
        let last = self.nlocal - 1;
        store.copy(last, i);
        self.ids.swap(i, last);
        self.radius.swap(i, last);
        self.types.swap(i, last);
        for c in 0..3 {
            self.x.swap(3 * i + c, 3 * last + c);
            self.v.swap(3 * i + c, 3 * last + c);
            self.omega.swap(3 * i + c, 3 * last + c);
        }
        self.truncate(last);
        self.nlocal = last;
    }

    fn truncate(&mut self, n: usize) {
        self.ids.truncate(n);
        self.radius.truncate(n);
        self.types.truncate(n);
        self.x.truncate(3 * n);
        self.v.truncate(3 * n);
        self.omega.truncate(3 * n);
    }
}

const KINDS: [i32; 4] = [-1, -1, -1, 0];

fn bond_model(p: BondParams) -> BondModel {
    common::model(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        ..p
    })
}

fn link(store: &mut BondStore, atoms: &Atoms) -> LinkReport {
    store.link(&atoms.link_atoms(&KINDS)).expect("a well-formed rank")
}

/// Bonds every pair of local atoms closer than the creation distance, as a
/// pair loop at the creation step would.
fn create_all(store: &mut BondStore, model: &BondModel, atoms: &Atoms) -> usize {
    let mut created = 0;
    for i in 0..atoms.nlocal {
        for j in i + 1..atoms.len() {
            let k = atoms.kinematics(i, j);
            let d: f64 = (0..3).map(|c| (k.x_i[c] - k.x_j[c]).powi(2)).sum::<f64>().sqrt();
            if d > 2.2 * R {
                continue;
            }
            let owner_is_j =
                creates_here(true, j < atoms.nlocal, atoms.ids[i], atoms.ids[j], false).expect("local");
            let (o, p) = if owner_is_j { (j, i) } else { (i, j) };
            let made = store
                .try_create(
                    model,
                    0,
                    o,
                    p,
                    [atoms.ids[o], atoms.ids[p]],
                    &atoms.kinematics(o, p),
                    1,
                )
                .expect("usable kinematics");
            created += usize::from(made);
        }
    }
    created
}

/// Steps the next chunk of a pass that has begun: each bond's ends and
/// output (none left: empty).
fn next_chunk(store: &mut BondStore, model: &BondModel, atoms: &Atoms) -> Vec<([i32; 2], BondOutput)> {
    let (mut ends, mut outs) = ([[0; 2]; CHUNK], [BondOutput::default(); CHUNK]);
    let n = store
        .step_next(
            &[Some(model)],
            atoms.arrays(),
            Ids::Wide(&atoms.ids),
            &mut ends,
            &mut outs,
        )
        .expect("a usable pass");
    ends[..n].iter().copied().zip(outs[..n].iter().copied()).collect()
}

/// One pass; the loads added to the atoms (forces, torques: 3 per atom)
/// and each bond's output by its ids.
struct Passed {
    force: Vec<f64>,
    torque: Vec<f64>,
    outs: Vec<([i64; 2], BondOutput)>,
}

fn pass(store: &mut BondStore, model: &BondModel, atoms: &Atoms, dt: f64, advance: bool) -> Passed {
    let mut p = Passed {
        force: vec![0.0; 3 * atoms.len()],
        torque: vec![0.0; 3 * atoms.len()],
        outs: vec![],
    };
    store.begin_pass(dt, advance, false);
    loop {
        let chunk = next_chunk(store, model, atoms);
        if chunk.is_empty() {
            break;
        }
        for (e, o) in chunk {
            let (i, j) = (e[0] as usize, e[1] as usize);
            for c in 0..3 {
                p.force[3 * i + c] += o.force_i[c];
                p.force[3 * j + c] -= o.force_i[c];
                p.torque[3 * i + c] += o.torque_i[c];
                p.torque[3 * j + c] += o.torque_j[c];
            }
            p.outs.push(([atoms.ids[i], atoms.ids[j]], o));
        }
    }
    store.finish_pass();
    p.outs.sort_by_key(|(ids, _)| *ids);
    p
}

/// Every bond's ids (owner's first) and state, in id order.
fn bonds_by_id(store: &BondStore, atoms: &Atoms) -> Vec<([i64; 2], BondState)> {
    let mut all: Vec<_> = (0..store.len())
        .map(|k| {
            let (bond, ends) = store.bond(k).expect("linked");
            ([atoms.ids[ends[0] as usize], bond.partner], bond.state)
        })
        .collect();
    all.sort_by_key(|(ids, _)| *ids);
    all
}

fn balanced(c: &StoreCounts) -> bool {
    c.created == c.broken() + c.intact + c.lost()
}

fn lattice_store(n: usize, model: &BondModel) -> (BondStore, Atoms) {
    let atoms = Atoms::lattice(n);
    let mut store = BondStore::new();
    store.grow(atoms.len());
    link(&mut store, &atoms);
    store.begin_pass(1e-7, true, false);
    create_all(&mut store, model, &atoms);
    store.finish_pass();
    (store, atoms)
}

#[test]
fn a_stored_bond_costs_no_more_than_the_budget() {
    let design = BYTES_PER_BOND;
    assert!(design <= BOND_BUDGET_BYTES, "{design} bytes a bond");
    let model = bond_model(common::params());
    // 6,084 bonds: growing by doubling leaves room for 8,192
    let (mut store, atoms) = lattice_store(13, &model);
    link(&mut store, &atoms);
    let bonds = store.len();
    assert_eq!(bonds, 3 * 12 * 13 * 13, "the lattice's touching pairs, each once");
    let per_bond = store.bytes() as f64 / bonds as f64;
    assert!(
        per_bond <= BOND_BUDGET_BYTES as f64,
        "the store holds {per_bond:.1} bytes a bond, over the budget of {BOND_BUDGET_BYTES}"
    );
    assert_eq!(std::mem::size_of::<StoredBond>(), 152);
}

#[test]
fn a_pass_over_the_store_gives_the_bits_of_one_step_per_bond() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(6, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    let before = bonds_by_id(&store, &atoms);
    let passed = pass(&mut store, &model, &atoms, 1e-6, true);
    let after = bonds_by_id(&store, &atoms);
    assert_eq!(passed.outs.len(), before.len());
    let index = |id: i64| atoms.ids.iter().position(|&x| x == id).unwrap();
    for (((ids, state), (ids_out, out)), (_, stepped)) in before.iter().zip(&passed.outs).zip(&after) {
        assert_eq!(ids, ids_out);
        let mut s = *state;
        let want = common::step(
            &model,
            &atoms.kinematics(index(ids[0]), index(ids[1])),
            1e-6,
            &mut s,
        );
        assert_eq!(*out, want, "bond {ids:?}: the pass's output");
        assert_eq!(*stepped, s, "bond {ids:?}: the pass's state");
    }
}

#[test]
fn loads_of_a_free_body_sum_to_no_force_and_no_moment() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(5, &model);
    atoms.drift(3e-6);
    link(&mut store, &atoms);
    let p = pass(&mut store, &model, &atoms, 1e-6, true);
    let (mut f, mut m) = ([0.0f64; 3], [0.0f64; 3]);
    let mut scale = 0.0f64;
    for a in 0..atoms.len() {
        let x = &atoms.x[3 * a..3 * a + 3];
        let fa = &p.force[3 * a..3 * a + 3];
        for c in 0..3 {
            f[c] += fa[c];
            scale = scale.max(fa[c].abs());
        }
        let cross = [
            x[1] * fa[2] - x[2] * fa[1],
            x[2] * fa[0] - x[0] * fa[2],
            x[0] * fa[1] - x[1] * fa[0],
        ];
        for c in 0..3 {
            m[c] += cross[c] + p.torque[3 * a + c];
        }
    }
    assert!(scale > 0.0, "the bonds carry loads");
    for c in 0..3 {
        assert!(f[c].abs() <= 1e-12 * scale, "net force {f:?}");
        assert!(m[c].abs() <= 1e-12 * scale * 20.0 * R, "net moment {m:?}");
    }
}

#[test]
fn a_setup_pass_advances_nothing() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(5, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    let forced = pass(&mut store, &model, &atoms, 1e-6, true);
    let before = bonds_by_id(&store, &atoms);
    let setup = pass(&mut store, &model, &atoms, 1e-6, false);
    assert_eq!(bonds_by_id(&store, &atoms), before);
    // undamped, at the positions of the force pass: the loads it left
    for ((ids, f), (_, s)) in forced.outs.iter().zip(&setup.outs) {
        let scale = common::norm(f.force_i) + common::norm(f.torque_i) / R;
        assert!(scale > 0.0, "bond {ids:?} carries a load");
        for (a, b) in [
            (f.force_i, s.force_i),
            (f.torque_i, s.torque_i),
            (f.torque_j, s.torque_j),
        ] {
            assert!(
                common::close3(a, b, 1e-9, scale),
                "bond {ids:?}: {a:?} then {b:?}"
            );
        }
    }
}

#[test]
fn sorted_atoms_find_the_same_bonds_and_loads() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(6, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    let before = bonds_by_id(&store, &atoms);
    let n = atoms.nlocal;
    // a scrambled order, as a spatial sort of another box would give
    let order: Vec<usize> = (0..n).map(|k| (k * 37 + 11) % n).collect();
    atoms.permute(&mut store, &order);
    let report = link(&mut store, &atoms);
    assert_eq!(report.lost(), 0);
    assert_eq!(bonds_by_id(&store, &atoms), before);
    let p = pass(&mut store, &model, &atoms, 1e-6, true);
    let (mut again, mut fresh_atoms) = lattice_store(6, &model);
    fresh_atoms.drift(2e-6);
    link(&mut again, &fresh_atoms);
    let q = pass(&mut again, &model, &fresh_atoms, 1e-6, true);
    assert_eq!(p.outs, q.outs, "each bond's output, whatever the atoms' order");
}

#[test]
fn a_sort_through_a_slot_beyond_the_stores_rows_keeps_every_bond() {
    let model = bond_model(common::params());
    // the store's rows are the linked atoms', however far the engine's
    // arrays run ahead of them: nothing grows them here
    let mut atoms = Atoms::lattice(5);
    let mut store = BondStore::new();
    link(&mut store, &atoms);
    store.begin_pass(1e-7, true, false);
    create_all(&mut store, &model, &atoms);
    store.finish_pass();
    link(&mut store, &atoms);
    let before = bonds_by_id(&store, &atoms);
    assert_eq!(before.len(), 3 * 4 * 5 * 5);
    let n = atoms.nlocal;
    let order: Vec<usize> = (0..n).rev().collect();
    atoms.permute(&mut store, &order);
    let report = link(&mut store, &atoms);
    assert_eq!(report.lost(), 0, "{report:?}");
    assert_eq!(bonds_by_id(&store, &atoms), before);
}

#[test]
fn atoms_beyond_the_stores_rows_cost_it_nothing() {
    // an engine's events for slots the store holds no row for: an empty
    // atom copied, an atom created, a ghost no link has seen
    let mut store = BondStore::new();
    store.copy(5_000, 20_000);
    store.clear(40_000);
    store.set_seen(30_000, 0);
    assert_eq!(store.bytes(), 0);
    assert_eq!(store.seen(20_000), 0);
    // a ghost's seen id is kept, in a row made for it
    store.set_seen(30, 7);
    assert_eq!(store.seen(30), 7);
    assert!(store.bytes() <= 31 * (4 + 8) * 2, "{} bytes", store.bytes());
}

#[test]
fn bonds_move_with_their_owner_to_another_rank() {
    let model = bond_model(common::params());
    let (mut one, mut atoms) = lattice_store(6, &model);
    atoms.drift(2e-6);
    link(&mut one, &atoms);
    let want = pass(&mut one, &model, &atoms.clone(), 1e-6, true).outs;
    let (mut a, atoms0) = lattice_store(6, &model);
    let mut atoms = atoms0;
    atoms.drift(2e-6);
    link(&mut a, &atoms);
    // the atoms with x beyond the middle migrate to rank B, bonds and all
    let middle = 5.0 * R;
    let mut b = BondStore::new();
    let mut on_b = Atoms::default();
    let mut i = 0;
    while i < atoms.nlocal {
        if atoms.x[3 * i] > middle {
            let mut buf = vec![0.0; a.packed_len(i)];
            let written = a.pack(i, true, &mut buf).expect("room");
            on_b.add(
                atoms.ids[i],
                [atoms.x[3 * i], atoms.x[3 * i + 1], atoms.x[3 * i + 2]],
                0,
            );
            let k = on_b.len() - 1;
            for c in 0..3 {
                on_b.v[3 * k + c] = atoms.v[3 * i + c];
                on_b.omega[3 * k + c] = atoms.omega[3 * i + c];
            }
            b.grow(on_b.len());
            assert_eq!(b.unpack(k, &buf[..written]), Ok(written));
            atoms.delete(&mut a, i);
        } else {
            i += 1;
        }
    }
    on_b.nlocal = on_b.len();
    // each rank sees the other's atoms as ghosts
    let with_ghosts = |local: &Atoms, other: &Atoms| {
        let mut all = local.clone();
        for k in 0..other.nlocal {
            all.ids.push(other.ids[k]);
            all.x.extend(&other.x[3 * k..3 * k + 3]);
            all.v.extend(&other.v[3 * k..3 * k + 3]);
            all.omega.extend(&other.omega[3 * k..3 * k + 3]);
            all.radius.push(other.radius[k]);
            all.types.push(other.types[k]);
        }
        all
    };
    let rank_a = with_ghosts(&atoms, &on_b);
    let rank_b = with_ghosts(&on_b, &atoms);
    // ghosts carry the seen ids their owners send
    let seen_a: Vec<i64> = (0..atoms.nlocal).map(|k| a.seen(k)).collect();
    let seen_b: Vec<i64> = (0..on_b.nlocal).map(|k| b.seen(k)).collect();
    for (store, rank, seen) in [(&mut a, &rank_a, &seen_b), (&mut b, &rank_b, &seen_a)] {
        store.grow(rank.len());
        for (k, &id) in seen.iter().enumerate() {
            store.set_seen(rank.nlocal + k, id);
        }
    }
    let (ra, rb) = (link(&mut a, &rank_a), link(&mut b, &rank_b));
    assert_eq!(ra.lost() + rb.lost(), 0);
    assert!(!a.is_empty() && !b.is_empty());
    assert_eq!(a.len() + b.len(), want.len(), "every bond once over both ranks");
    let mut got = pass(&mut a, &model, &rank_a, 1e-6, true).outs;
    got.extend(pass(&mut b, &model, &rank_b, 1e-6, true).outs);
    got.sort_by_key(|(ids, _)| *ids);
    assert_eq!(got, want, "each bond's output, on one rank or two");
    let counts = [a.counts(), b.counts()];
    let created: i64 = counts.iter().map(|c| c.created).sum();
    let intact: i64 = counts.iter().map(|c| c.intact).sum();
    assert_eq!(created, intact, "created = intact over the ranks");
}

#[test]
fn a_restart_file_brings_back_every_bond_bit_for_bit() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(5, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    pass(&mut store, &model, &atoms, 1e-6, true);
    let before = bonds_by_id(&store, &atoms);
    let mut read = BondStore::new();
    read.grow(atoms.len());
    // the restart file lists the atoms in reverse
    let mut back = atoms.clone();
    let order: Vec<usize> = (0..atoms.nlocal).rev().collect();
    for (dest, &k) in order.iter().enumerate() {
        let mut buf = vec![0.0; store.packed_len(k)];
        let n = store.pack(k, false, &mut buf).expect("room");
        assert_eq!(read.unpack(dest, &buf[..n]), Ok(n));
    }
    assert_eq!(
        bonds_by_id(&store, &atoms),
        before,
        "writing a restart file keeps the bonds"
    );
    let mut scratch = BondStore::new();
    back.permute(&mut scratch, &order);
    let report = link(&mut read, &back);
    assert_eq!(report.lost(), 0);
    assert_eq!(bonds_by_id(&read, &back), before);
}

/// A 4 x 4 x 4 lattice, bonded and linked, with one atom inside it (six
/// bonds, some owned, some as partner) deleted: the store, the atoms, the
/// bonds before, and the deleted atom's id and place.
fn lattice_less_an_inner_atom() -> (BondStore, Atoms, i64, i64, [f64; 3]) {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(4, &model);
    link(&mut store, &atoms);
    let total = store.len() as i64;
    let id = 1 + 1 + 4 * (1 + 4);
    let inner = atoms.ids.iter().position(|&x| x == id).unwrap();
    let at = [atoms.x[3 * inner], atoms.x[3 * inner + 1], atoms.x[3 * inner + 2]];
    atoms.delete(&mut store, inner);
    (store, atoms, total, id, at)
}

#[test]
fn a_deleted_atom_takes_its_bonds_and_they_are_counted_lost() {
    let (mut store, atoms, total, _, _) = lattice_less_an_inner_atom();
    let report = link(&mut store, &atoms);
    assert_eq!(report.lost(), 6, "{report:?}");
    assert!(
        report.owner_gone > 0 && report.partner_unreached > 0,
        "{report:?}"
    );
    let c = store.counts();
    assert_eq!(c.intact, total - 6);
    assert!(balanced(&c), "{c:?}");
}

#[test]
fn a_new_atom_under_a_deleted_atoms_id_takes_over_no_bond() {
    let (mut store, mut atoms, total, id, at) = lattice_less_an_inner_atom();
    // a new atom, in the same place and with the same id, at the end
    atoms.add(id, at, 3);
    atoms.nlocal += 1;
    store.grow(atoms.len());
    store.clear(atoms.nlocal - 1);
    let report = link(&mut store, &atoms);
    assert_eq!(report.lost(), 6, "{report:?}");
    assert_eq!(report.id_reused + report.owner_gone, 6, "{report:?}");
    assert_eq!(store.counts().intact, total - 6);
    assert!(balanced(&store.counts()));
}

#[test]
fn a_bond_across_a_periodic_boundary_takes_its_partners_closest_image() {
    let model = bond_model(common::params());
    let length = 0.1;
    let mut atoms = Atoms::default();
    atoms.add(1, [0.5 * R, 0.0, 0.0], 1);
    atoms.add(2, [length - 1.5 * R, 0.0, 0.0], 2);
    atoms.nlocal = 2;
    // ghost images: atom 2 to the left of atom 1, atom 1 to the right of 2
    atoms.add(2, [-1.5 * R, 0.0, 0.0], 0);
    atoms.add(1, [length + 0.5 * R, 0.0, 0.0], 0);
    for g in 2..4 {
        for c in 0..3 {
            atoms.v[3 * g + c] = atoms.v[3 * (3 - g) + c];
            atoms.omega[3 * g + c] = atoms.omega[3 * (3 - g) + c];
        }
    }
    let mut store = BondStore::new();
    store.grow(atoms.len());
    link(&mut store, &atoms);
    store.set_seen(2, 2);
    store.set_seen(3, 1);
    store.begin_pass(1e-7, true, false);
    let made = store
        .try_create(&model, 0, 0, 2, [1, 2], &atoms.kinematics(0, 2), 1)
        .unwrap();
    assert!(made);
    store.finish_pass();
    let report = link(&mut store, &atoms);
    assert_eq!(report.linked, 1);
    let (_, ends) = store.bond(0).unwrap();
    assert_eq!(
        ends,
        [0, 2],
        "the image next to the owner, not the one a box away"
    );
}

/// Atoms 1 and 2 touching, both local, linked to an empty store.
fn touching_pair() -> (BondStore, Atoms) {
    let mut atoms = Atoms::default();
    sphere(&mut atoms, 1, 0.0);
    sphere(&mut atoms, 2, 2.0 * R);
    atoms.nlocal = 2;
    let mut store = BondStore::new();
    store.grow(2);
    link(&mut store, &atoms);
    (store, atoms)
}

/// Atoms 1 and 2 touching, both local, bonded by `model`, linked.
fn bonded_pair(model: &BondModel) -> (BondStore, Atoms) {
    let (mut store, atoms) = touching_pair();
    store.begin_pass(1e-7, true, false);
    assert!(store
        .try_create(model, 0, 0, 1, [1, 2], &atoms.kinematics(0, 1), 1)
        .unwrap());
    store.finish_pass();
    (store, atoms)
}

#[test]
fn a_broken_bond_leaves_the_store_and_cannot_form_again_in_its_pass() {
    let p = BondParams {
        max_distance: 2.05 * R,
        ..common::params()
    };
    let model = bond_model(p);
    let (mut store, mut atoms) = bonded_pair(&model);
    atoms.x[3] = 2.1 * R;
    link(&mut store, &atoms);
    store.begin_pass(1e-7, true, false);
    let chunk = next_chunk(&mut store, &model, &atoms);
    assert_eq!(chunk.len(), 1);
    let out = chunk[0].1;
    assert_eq!(out.status, BondStatus::Broken as i32);
    assert_eq!(out.force_i, [0.0; 3], "a broken bond carries no load");
    assert_eq!(store.broken().len(), 1);
    assert_eq!(store.broken()[0].ids, [1, 2]);
    assert_eq!(store.broken()[0].out.break_mode, BreakMode::Distance as i32);
    atoms.x[3] = 2.0 * R;
    let again = BondModel::new(BondParams {
        create_always: 1,
        ..model.params
    })
    .unwrap();
    assert!(
        !store
            .try_create(&again, 0, 0, 1, [1, 2], &atoms.kinematics(0, 1), 2)
            .unwrap(),
        "not in the pass it broke in"
    );
    store.finish_pass();
    let c = store.counts();
    assert_eq!((c.created, c.broken_distance, c.intact), (1, 1, 0));
    assert!(balanced(&c));
    assert_eq!(store.len(), 0);
}

#[test]
fn each_break_is_counted_by_its_mode() {
    // stress mode: a normal strength that a 1e-7 m stretch or squeeze
    // exceeds, or a shear strength that one step of sliding exceeds
    let sigma = BondParams {
        stress_break: 1,
        max_sigma: 1.0,
        ..common::params()
    };
    let tau = BondParams {
        stress_break: 1,
        max_tau: 1.0,
        ..common::params()
    };
    for (p, moved_by, mode) in [
        (sigma, [1e-7, 0.0], BreakMode::Tension),
        (sigma, [-1e-7, 0.0], BreakMode::Compression),
        (tau, [0.0, 1.0], BreakMode::Shear),
    ] {
        let model = bond_model(p);
        let (mut store, mut atoms) = bonded_pair(&model);
        atoms.x[3] += moved_by[0];
        atoms.v[4] = moved_by[1];
        link(&mut store, &atoms);
        let passed = pass(&mut store, &model, &atoms, 1e-7, true);
        assert_eq!(passed.outs[0].1.break_mode, mode as i32, "{mode:?}");
        let c = store.counts();
        let by_mode = [
            (BreakMode::Distance, c.broken_distance),
            (BreakMode::Tension, c.broken_tension),
            (BreakMode::Compression, c.broken_compression),
            (BreakMode::Shear, c.broken_shear),
        ];
        for (m, n) in by_mode {
            assert_eq!(n, i64::from(m == mode), "{mode:?}: counted under {m:?}");
        }
        assert!(balanced(&c));
    }
}

#[test]
fn an_atom_index_beyond_the_arrays_is_named_before_any_bond_moves() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = lattice_store(3, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    let before = bonds_by_id(&store, &atoms);
    // arrays that end before the last atom, as an engine that shrank them
    // without linking again would pass
    let mut short = atoms.clone();
    short.truncate(atoms.len() - 1);
    store.begin_pass(1e-6, true, false);
    let (mut ends, mut outs) = ([[0; 2]; CHUNK], [BondOutput::default(); CHUNK]);
    let failure = store
        .step_next(
            &[Some(&model)],
            short.arrays(),
            Ids::Wide(&atoms.ids),
            &mut ends,
            &mut outs,
        )
        .expect_err("an atom beyond the arrays");
    assert_eq!(failure.reason, StepFailureReason::IndexOutOfRange);
    let last = (atoms.len() - 1) as i32;
    assert!(
        failure.ends.contains(&last),
        "{failure:?} names the bond of the last atom"
    );
    assert_eq!(bonds_by_id(&store, &atoms), before, "no bond moved");
}

#[test]
fn each_pair_is_created_by_exactly_one_rank() {
    for (id_i, id_j) in [(3, 8), (8, 3)] {
        // both local: once, owned by the smaller id
        assert_eq!(creates_here(true, true, id_i, id_j, false), Some(id_j < id_i));
        // newton off: the pair is listed on both ranks, each from its local atom
        let here = creates_here(true, false, id_i, id_j, true);
        let there = creates_here(true, false, id_j, id_i, true);
        assert_eq!(u8::from(here.is_some()) + u8::from(there.is_some()), 1);
        // newton on: listed on one rank, which creates it
        assert_eq!(creates_here(true, false, id_i, id_j, false), Some(false));
        assert_eq!(creates_here(false, true, id_i, id_j, false), Some(true));
    }
}

#[test]
fn unpacking_refuses_a_short_or_malformed_buffer() {
    let mut store = BondStore::new();
    store.grow(1);
    assert!(store.unpack(0, &[1.0]).is_err());
    assert!(
        store.unpack(0, &[1.0, 2.0, 3.0]).is_err(),
        "two bonds announced, none given"
    );
    assert!(
        store.unpack(0, &[1.0, 0.5]).is_err(),
        "a count that is no whole number"
    );
    assert!(store.unpack(0, &[1.0, -1.0]).is_err());
    assert_eq!(store.len(), 0, "nothing unpacked from a refused buffer");
}

/// Atom `id` of radius [`R`] at `x` on the x axis, at rest.
fn sphere(atoms: &mut Atoms, id: i64, x: f64) {
    atoms.add(id, [x, 0.0, 0.0], 0);
    let k = atoms.len() - 1;
    atoms.v[3 * k..3 * k + 3].fill(0.0);
    atoms.omega[3 * k..3 * k + 3].fill(0.0);
}

/// Rank `from`'s view rows of its local atoms, unpacked at their ghost
/// images on rank `to` (a forward communication): `ghost_of[k]` is local
/// atom k's ghost index on `to`.
fn send_view(from: &BondStore, from_atoms: &Atoms, to: &mut BondStore, to_atoms: &Atoms, ghost_of: &[usize]) {
    let width = from.view_width().max(to.view_width());
    to.clear_view();
    for (k, &g) in ghost_of.iter().enumerate().take(from_atoms.nlocal) {
        let mut row = vec![0.0; width];
        from.pack_view(k, &mut row).expect("a row wide enough");
        to.unpack_view(g, &row, Ids::Wide(&to_atoms.ids), to_atoms.nlocal)
            .expect("a well-formed row");
    }
    to.finish_view();
}

#[test]
fn a_rank_listing_a_pair_bonded_on_another_rank_sees_the_bond_and_its_break() {
    let model = bond_model(BondParams {
        max_distance: 2.05 * R,
        create_always: 1,
        ..common::params()
    });
    // rank A: atom 1 local, atom 2 a ghost; rank B the other way round
    let (mut on_a, mut on_b) = (Atoms::default(), Atoms::default());
    sphere(&mut on_a, 1, 0.0);
    sphere(&mut on_a, 2, 2.0 * R);
    sphere(&mut on_b, 2, 2.0 * R);
    sphere(&mut on_b, 1, 0.0);
    on_a.nlocal = 1;
    on_b.nlocal = 1;
    let (mut a, mut b) = (BondStore::new(), BondStore::new());
    for (s, atoms, ghost_id) in [(&mut a, &on_a, 2), (&mut b, &on_b, 1)] {
        s.grow(2);
        s.set_seen(1, ghost_id);
        link(s, atoms);
    }
    // newton off: both ranks list the pair; the rank of the smaller id bonds it
    assert_eq!(creates_here(true, false, 1, 2, true), Some(false));
    assert_eq!(creates_here(true, false, 2, 1, true), None);
    a.begin_pass(1e-7, true, false);
    b.begin_pass(1e-7, true, false);
    assert!(a
        .try_create(&model, 0, 0, 1, [1, 2], &on_a.kinematics(0, 1), 1)
        .unwrap());
    assert!(
        b.would_create(&model, 0, 1, &on_b.kinematics(0, 1), 1).unwrap(),
        "rank B knows rank A bonds the pair in this step"
    );
    a.finish_pass();
    b.finish_pass();
    for (s, atoms) in [(&mut a, &on_a), (&mut b, &on_b)] {
        link(s, atoms);
    }
    send_view(&a, &on_a, &mut b, &on_b, &[1]);
    send_view(&b, &on_b, &mut a, &on_a, &[1]);
    assert!(a.bonded(0, 1, Ids::Wide(&on_a.ids)), "the owner's rank");
    assert!(
        b.bonded(0, 1, Ids::Wide(&on_b.ids)),
        "the partner's rank, through the view"
    );
    assert_eq!(a.len() + b.len(), 1, "the bond is stored once");

    // stretched past max_distance: the bond breaks on rank A, and rank B
    // sees it gone in the same step, and not bonded again in it
    on_a.x[3] = 2.1 * R;
    on_b.x[0] = 2.1 * R;
    a.begin_pass(1e-7, true, false);
    b.begin_pass(1e-7, true, false);
    pass_chunks(&mut a, &model, &on_a);
    pass_chunks(&mut b, &model, &on_b);
    assert_eq!(a.broken().len(), 1);
    send_view(&a, &on_a, &mut b, &on_b, &[1]);
    assert!(!b.bonded(0, 1, Ids::Wide(&on_b.ids)), "rank B sees the break");
    on_b.x[0] = 2.0 * R;
    assert!(
        !b.would_create(&model, 0, 1, &on_b.kinematics(0, 1), 2).unwrap(),
        "nor a bond again in the pass it broke in"
    );
    a.finish_pass();
    b.finish_pass();
    let (ca, cb) = (a.counts(), b.counts());
    assert_eq!(ca.created + cb.created, 1);
    assert_eq!(ca.broken() + cb.broken(), 1);
    assert!(balanced(&ca) && balanced(&cb));
}

/// Steps every bond of a pass that has begun, without finishing it.
fn pass_chunks(store: &mut BondStore, model: &BondModel, atoms: &Atoms) {
    while !next_chunk(store, model, atoms).is_empty() {}
}

#[test]
fn a_bond_stretched_beyond_the_ghosts_reach_is_lost_on_one_rank_as_on_several() {
    let model = bond_model(common::params());
    let (mut store, mut atoms) = bonded_pair(&model);
    // moved far apart between runs: on several ranks the partner would be
    // beyond the ghost atoms; on one it is local, and is not taken either
    atoms.x[3] = 20.0 * R;
    let reached = LinkAtoms {
        reach: 5.0 * R,
        ..atoms.link_atoms(&KINDS)
    };
    let report = store.link(&reached).unwrap();
    assert_eq!(report.partner_unreached, 1, "{report:?}");
    assert!(balanced(&store.counts()));
}

#[test]
fn the_store_holds_the_energy_of_its_stretched_bonds() {
    let model = bond_model(common::elastic_params());
    let (mut store, mut atoms) = bonded_pair(&model);
    let stretch = 1e-6;
    atoms.x[3] = 2.0 * R + stretch;
    atoms.v.fill(0.0);
    atoms.omega.fill(0.0);
    link(&mut store, &atoms);
    pass(&mut store, &model, &atoms, 1e-9, true);
    let energy = store.stored_energy(&[Some(&model)], atoms.arrays()).unwrap();
    // linear in tension: F = k_fn2 A d, so E = k_fn2 A d^2 / 2
    let area = std::f64::consts::PI * (model.params.lambda * R).powi(2);
    let want = 0.5 * model.params.k_fn2 * area * stretch * stretch;
    assert!(
        (energy - want).abs() <= 1e-9 * want,
        "{energy} J against {want} J"
    );
}

#[test]
fn a_clump_pair_bonds_now_at_any_step_but_not_in_the_pass_its_bond_broke() {
    let model = bond_model(BondParams {
        create_step: 1_000_000,
        max_distance: 2.05 * R,
        ..common::params()
    });
    let (mut store, mut atoms) = touching_pair();
    store.begin_pass(1e-7, true, false);
    let k = atoms.kinematics(0, 1);
    assert!(
        !store.try_create(&model, 0, 0, 1, [1, 2], &k, 5).unwrap(),
        "the rules wait for the creation step"
    );
    assert!(store.create_now(&model, 0, 0, 1, [1, 2], &k).unwrap());
    assert_eq!(
        next_chunk(&mut store, &model, &atoms).len(),
        1,
        "stepped in the pass it formed in"
    );
    store.finish_pass();
    assert_eq!((store.len(), store.counts().created), (1, 1));
    // pulled apart: it breaks, and does not form again in that pass
    atoms.x[3] = 2.1 * R;
    link(&mut store, &atoms);
    store.begin_pass(1e-7, true, false);
    assert_eq!(
        next_chunk(&mut store, &model, &atoms)[0].1.status,
        BondStatus::Broken as i32
    );
    atoms.x[3] = 2.0 * R;
    assert!(!store
        .create_now(&model, 0, 0, 1, [1, 2], &atoms.kinematics(0, 1))
        .unwrap());
    store.finish_pass();
    assert!(balanced(&store.counts()));
}

#[test]
fn a_setup_pass_of_inl_code_is_its_own_trial_step() {
    let model = bond_model(BondParams {
        inl_compatible: 1,
        ..common::params()
    });
    let (mut store, mut atoms) = lattice_store(3, &model);
    atoms.drift(2e-6);
    link(&mut store, &atoms);
    pass(&mut store, &model, &atoms, 1e-6, true);
    atoms.drift(1e-6);
    // what LIGGGHTS-INL's setup does: each bond through BondModel::setup_step
    let mut want = vec![];
    for k in 0..store.len() {
        let (bond, ends) = store.bond(k).unwrap();
        let mut state = bond.state;
        let mut out = BondOutput::default();
        let kin = atoms.kinematics(ends[0] as usize, ends[1] as usize);
        assert!(model.setup_step(&kin, 1e-6, &mut state, &mut out, false).unwrap());
        want.push(([atoms.ids[ends[0] as usize], bond.partner], state, out));
    }
    want.sort_by_key(|(ids, _, _)| *ids);
    let setup = pass(&mut store, &model, &atoms, 1e-6, false);
    let states = bonds_by_id(&store, &atoms);
    assert_eq!(setup.outs.len(), want.len());
    for ((ids, state, out), ((_, got), (_, kept))) in want.iter().zip(setup.outs.iter().zip(&states)) {
        assert_eq!(
            (out.force_i, out.torque_i, out.torque_j),
            (got.force_i, got.torque_i, got.torque_j),
            "bond {ids:?}"
        );
        assert_eq!(
            state, kept,
            "bond {ids:?}: the trial step's history extremes are kept"
        );
    }
}

#[test]
fn the_store_checks_keys_name_each_bond_by_its_atoms_and_refuse_a_partner_not_found() {
    let model = bond_model(common::params());
    let (store, atoms) = bonded_pair(&model);
    let keys = pair_keys(&store, Ids::Wide(&atoms.ids), atoms.nlocal).unwrap();
    assert_eq!(keys, [[1.0, 2.0]]);
    // the partner's slot now holds another atom: the bond names no atom here
    let other = [1, 9];
    assert_eq!(
        pair_keys(&store, Ids::Wide(&other), atoms.nlocal),
        Err("bond 0 does not join its owner and its partner 2".into())
    );
    // the owner is not a local atom
    assert!(pair_keys(&store, Ids::Wide(&atoms.ids), 0).is_err());
}

#[test]
fn the_store_check_finds_a_pair_flag_that_disagrees_with_the_store() {
    let model = bond_model(common::params());
    let (store, atoms) = bonded_pair(&model);
    let ids = Ids::Wide(&atoms.ids);
    assert_eq!(flag_finding(&store, 0, 1, ids, true), None);
    assert_eq!(flag_finding(&store, 1, 0, ids, true), None, "either atom's list");
    assert_eq!(
        flag_finding(&store, 0, 1, ids, false),
        Some("the pair of atoms 1 and 2 is bonded, but not flagged".into())
    );
    let (unbonded, atoms) = touching_pair();
    assert_eq!(
        flag_finding(&unbonded, 0, 1, Ids::Wide(&atoms.ids), true),
        Some("the pair of atoms 1 and 2 is flagged bonded, but no bond".into())
    );
    assert_eq!(flag_finding(&unbonded, 0, 1, Ids::Wide(&atoms.ids), false), None);
}

/// Start values of an engine's load sums: not zero, so that the order of
/// the adds to each atom shows in the bits.
fn start_sums(len: usize, seed: f64) -> Vec<f64> {
    (0..len)
        .map(|k| seed * ((k * 7919 % 101) as f64 - 50.0))
        .collect()
}

/// The loads of a pass as an engine adds the outputs bond by bond (the
/// adapters' loop before the core added them): the owner's force and
/// torque, then the partner's, each times its atom's factor; a ghost
/// partner's in `ghost_rows` when given. Returns the sums (forces, torques,
/// ghost rows).
fn added_by_hand(
    store: &mut BondStore,
    model: &BondModel,
    atoms: &Atoms,
    relax: Option<&[f64]>,
    ghost_rows: bool,
) -> [Vec<f64>; 3] {
    let n = atoms.len();
    let (mut f, mut t) = (start_sums(3 * n, 1e-3), start_sums(3 * n, 1e-6));
    let mut g = start_sums(6 * (n - atoms.nlocal), 1e-4);
    store.begin_pass(1e-7, true, false);
    loop {
        let chunk = next_chunk(store, model, atoms);
        if chunk.is_empty() {
            break;
        }
        for (e, o) in chunk {
            let (i, j) = (e[0] as usize, e[1] as usize);
            let r = |a: usize| relax.map_or(1.0, |r| r[a]);
            for c in 0..3 {
                f[3 * i + c] += r(i) * o.force_i[c];
            }
            for c in 0..3 {
                t[3 * i + c] += r(i) * o.torque_i[c];
            }
            let (fj, tj) = if ghost_rows && j >= atoms.nlocal {
                let row = 6 * (j - atoms.nlocal);
                (&mut g[row..row + 3], (row + 3, true))
            } else {
                (&mut f[3 * j..3 * j + 3], (3 * j, false))
            };
            for (to, x) in fj.iter_mut().zip(o.force_i) {
                *to -= r(j) * x;
            }
            let tj = if tj.1 {
                &mut g[tj.0..tj.0 + 3]
            } else {
                &mut t[tj.0..tj.0 + 3]
            };
            for (to, x) in tj.iter_mut().zip(o.torque_j) {
                *to += r(j) * x;
            }
        }
    }
    store.finish_pass();
    [f, t, g]
}

/// The same pass with the core adding the loads: in one call
/// (`step_rest`), or chunk by chunk with the outputs handed back
/// (`step_next_adding`).
fn added_by_core(
    store: &mut BondStore,
    model: &BondModel,
    atoms: &Atoms,
    relax: Option<&[f64]>,
    ghost_rows: bool,
    chunk_by_chunk: bool,
) -> [Vec<f64>; 3] {
    let n = atoms.len();
    let (mut f, mut t) = (start_sums(3 * n, 1e-3), start_sums(3 * n, 1e-6));
    let mut g = start_sums(6 * (n - atoms.nlocal), 1e-4);
    store.begin_pass(1e-7, true, false);
    {
        let mut loads = AtomLoads {
            force: &mut f,
            torque: &mut t,
            nlocal: atoms.nlocal,
            ghost_rows: ghost_rows.then_some(&mut g[..]),
            relax,
        };
        let models = [Some(model)];
        let ids = Ids::Wide(&atoms.ids);
        if chunk_by_chunk {
            let (mut ends, mut outs) = ([[0; 2]; CHUNK], [BondOutput::default(); CHUNK]);
            while store
                .step_next_adding(&models, atoms.arrays(), ids, &mut loads, &mut ends, &mut outs)
                .expect("a usable pass")
                > 0
            {}
        } else {
            store
                .step_rest(&models, atoms.arrays(), ids, &mut loads)
                .expect("a usable pass");
        }
    }
    store.finish_pass();
    [f, t, g]
}

#[test]
fn the_core_adds_the_loads_as_an_engine_adding_the_outputs_bond_by_bond() {
    let p = BondParams {
        max_distance: 2.3 * R,
        ..common::params()
    };
    let models = [
        ("AVX2 or scalar as chosen", bond_model(p)),
        ("switched", bond_model(p).switched()),
        (
            "scalar",
            bond_model(p)
                .with_simd(Simd::Scalar)
                .expect("scalar runs anywhere"),
        ),
    ];
    for (name, model) in &models {
        // a lattice whose top layer is ghosts: bonds to ghost partners
        let n = 7;
        let mut created = Atoms::lattice(n);
        created.nlocal = created.len() - n * n;
        // one atom pulled away: its bonds break by distance in the pass
        let mut atoms = created.clone();
        atoms.x[3 * 20] += 0.3 * R;
        atoms.drift(1e-4);
        let store = || {
            let mut store = BondStore::new();
            store.grow(created.len());
            link(&mut store, &created);
            store.begin_pass(1e-7, true, false);
            assert!(create_all(&mut store, model, &created) > 2 * CHUNK);
            store.finish_pass();
            link(&mut store, &atoms);
            store
        };
        let relax: Vec<f64> = (0..atoms.len()).map(|a| 0.5 + (a % 5) as f64 * 0.125).collect();
        for relax in [None, Some(&relax[..])] {
            for ghost_rows in [false, true] {
                for chunk_by_chunk in [false, true] {
                    let (mut by_hand, mut by_core) = (store(), store());
                    let want = added_by_hand(&mut by_hand, model, &atoms, relax, ghost_rows);
                    let got = added_by_core(&mut by_core, model, &atoms, relax, ghost_rows, chunk_by_chunk);
                    for k in 0..3 {
                        let differs = got[k]
                            .iter()
                            .zip(&want[k])
                            .position(|(a, b)| a.to_bits() != b.to_bits());
                        assert_eq!(
                            differs,
                            None,
                            "{name}, factors {}, ghost rows {ghost_rows}, chunk by chunk {chunk_by_chunk}: \
                             sums {k} differ first at {differs:?}",
                            relax.is_some()
                        );
                    }
                    assert_eq!(by_core.counts(), by_hand.counts(), "{name}: the same breaks");
                    assert!(
                        by_core.counts().broken() > 0,
                        "{name}: the pulled atom's bonds broke"
                    );
                }
            }
        }
    }
}
