//! A store whose bonds an engine's topology names (`BondStore::link_listed`,
//! LAMMPS `bond_style granbond`): the list says which bonds exist, the store
//! keeps their state across links, starts a new one at rest at its length,
//! and counts one the list drops as lost.

use granbond_test_support as common;

use granbond::bond::{BondModel, BondOutput, BondParams, BondStatus};
use granbond::bond_store::{BondStore, Ids, ListedAtoms, ListedBond, StoreCounts, CHUNK};
use granbond::pair_source::AtomArrays;

const R: f64 = common::RADIUS;

/// Spheres in a row on x, touching, at rest; ids from 1.
struct Row {
    ids: Vec<i64>,
    x: Vec<f64>,
    v: Vec<f64>,
    omega: Vec<f64>,
    radius: Vec<f64>,
}

impl Row {
    fn new(n: usize) -> Self {
        Row {
            ids: (1..=n as i64).collect(),
            x: (0..n).flat_map(|k| [2.0 * R * k as f64, 0.0, 0.0]).collect(),
            v: vec![0.0; 3 * n],
            omega: vec![0.0; 3 * n],
            radius: vec![R; n],
        }
    }

    fn atoms(&self) -> ListedAtoms<'_> {
        ListedAtoms {
            ids: Ids::Wide(&self.ids),
            nlocal: self.ids.len(),
            x: &self.x,
        }
    }

    fn arrays(&self) -> AtomArrays<'_> {
        AtomArrays {
            x: &self.x,
            v: &self.v,
            omega: &self.omega,
            radius: &self.radius,
        }
    }
}

fn bond(owner: i32, partner: i32, kind: i32) -> ListedBond {
    ListedBond { owner, partner, kind }
}

/// One force pass over `dt`: each bond's ids and output.
fn pass(
    store: &mut BondStore,
    models: &[Option<&BondModel>],
    row: &Row,
    dt: f64,
) -> Vec<([i64; 2], BondOutput)> {
    store.begin_pass(dt, true, false);
    let mut all = vec![];
    loop {
        let (mut ends, mut outs) = ([[0; 2]; CHUNK], [BondOutput::default(); CHUNK]);
        let n = store
            .step_next(models, row.arrays(), Ids::Wide(&row.ids), &mut ends, &mut outs)
            .expect("a usable pass");
        if n == 0 {
            break;
        }
        for k in 0..n {
            let [i, j] = ends[k].map(|a| row.ids[a as usize]);
            all.push(([i, j], outs[k]));
        }
    }
    store.finish_pass();
    all.sort_by_key(|(ids, _)| *ids);
    all
}

fn balanced(c: &StoreCounts) -> bool {
    c.created == c.broken() + c.intact + c.lost()
}

#[test]
fn a_listed_bond_keeps_its_state_and_a_new_one_starts_at_rest_at_its_length() {
    let model = common::model(common::params());
    let models = [Some(&model)];
    let mut row = Row::new(3);
    let mut store = BondStore::new();
    store
        .link_listed(&row.atoms(), &[bond(0, 1, 0)])
        .expect("a well-formed list");
    // stretch the pair 1-2 and load it: its state moves (tension history)
    row.x[3] += 1e-6;
    let loaded = pass(&mut store, &models, &row, 1e-7);
    assert!(
        loaded[0].1.force_i[0] > 0.0,
        "the stretched bond pulls atom 1 towards 2"
    );
    let (kept, _) = store.bond(0).expect("linked");
    // sphere 3 moves away a little, then the list names 2-3 as well
    row.x[6] += 3e-7;
    let report = store
        .link_listed(&row.atoms(), &[bond(1, 2, 0), bond(0, 1, 0)])
        .expect("a well-formed list");
    assert_eq!(report.linked, 2);
    assert_eq!(report.lost(), 0);
    let mut states: Vec<_> = (0..store.len())
        .map(|k| store.bond(k).expect("linked"))
        .map(|(b, e)| ([row.ids[e[0] as usize], b.partner], b.state))
        .collect();
    states.sort_by_key(|(ids, _)| *ids);
    assert_eq!(
        states[0],
        ([1, 2], kept.state),
        "the listed bond 1-2 keeps its state bit for bit"
    );
    assert_eq!(states[1].0, [2, 3]);
    assert_eq!(
        states[1].1.r0(),
        row.x[6] - row.x[3],
        "the new bond 2-3 rests at its length"
    );
    assert_eq!(states[1].1.status(), BondStatus::Intact);
    let after = pass(&mut store, &models, &row, 1e-7);
    assert!(
        after[1].1.force_i.iter().all(|f| f.abs() < 1e-12),
        "at rest: no load"
    );
    let c = store.counts();
    assert_eq!((c.created, c.intact), (2, 2));
    assert!(balanced(&c));
}

#[test]
fn a_bond_the_list_drops_is_lost_and_counted() {
    let model = common::model(common::params());
    let row = Row::new(3);
    let mut store = BondStore::new();
    store
        .link_listed(&row.atoms(), &[bond(0, 1, 0), bond(1, 2, 0)])
        .expect("a well-formed list");
    pass(&mut store, &[Some(&model)], &row, 1e-7);
    let report = store
        .link_listed(&row.atoms(), &[bond(1, 2, 0)])
        .expect("a well-formed list");
    assert_eq!((report.linked, report.no_model, report.lost()), (1, 1, 1));
    let c = store.counts();
    assert_eq!((c.created, c.intact, c.lost_no_model), (2, 1, 1));
    assert!(balanced(&c));
}

#[test]
fn each_kind_steps_with_its_own_law() {
    let soft = common::model(common::elastic_params());
    let stiff = common::model(BondParams {
        k_fn2: 4.0 * common::elastic_params().k_fn2,
        ku_fn2: 4.0 * common::elastic_params().k_fn2,
        ..common::elastic_params()
    });
    let mut row = Row::new(4);
    let mut store = BondStore::new();
    // 1-2 of kind 0 (soft), 3-4 of kind 1 (stiff); both stretched alike
    store
        .link_listed(&row.atoms(), &[bond(0, 1, 0), bond(2, 3, 1)])
        .expect("a well-formed list");
    row.x[3] += 1e-6;
    row.x[9] += 1e-6;
    let outs = pass(&mut store, &[Some(&soft), Some(&stiff)], &row, 1e-7);
    let f = |k: usize| outs[k].1.force_i[0];
    assert!((f(1) / f(0) - 4.0).abs() < 1e-9, "forces {} and {}", f(0), f(1));
}

#[test]
fn a_malformed_list_is_refused_naming_the_entry() {
    let row = Row::new(3);
    let mut store = BondStore::new();
    let atoms = ListedAtoms {
        nlocal: 2,
        ..row.atoms()
    };
    for (bad, what) in [
        (bond(2, 0, 0), "owner 2"),
        (bond(0, 0, 0), "partner 0"),
        (bond(0, 3, 0), "partner 3"),
        (bond(0, 1, -1), "kind -1"),
    ] {
        let e = store.link_listed(&atoms, &[bad]).expect_err("refused");
        assert!(e.0.contains(what) && e.0.contains("listed bond 0"), "{}", e.0);
    }
}

#[test]
fn an_atom_that_arrives_in_a_vacated_slot_and_is_sorted_ahead_takes_no_other_atoms_bonds() {
    let model = common::model(common::params());
    let models = [Some(&model)];
    let mut row = Row::new(4);
    let mut store = BondStore::new();
    // 1-2 owned by atom 1 (slot 0), 4-3 owned by atom 4 (slot 3); both loaded
    let listed = |row: &Row| {
        let at = |id: i64| row.ids.iter().position(|&x| x == id).expect("present") as i32;
        [bond(at(1), at(2), 0), bond(at(4), at(3), 0)]
    };
    store
        .link_listed(&row.atoms(), &listed(&row))
        .expect("a well-formed list");
    row.x[3] += 1e-6;
    row.x[9] += 2e-6;
    pass(&mut store, &models, &row, 1e-7);
    let before: Vec<_> = (0..2).map(|k| store.bond(k).expect("linked").0).collect();
    // atom 1 leaves (the last atom, 4, is copied into its slot), then comes
    // back into the vacated last slot, as an exchange between ranks does
    let mut buf = vec![0.0; store.packed_len(0)];
    store.pack(0, true, &mut buf).expect("room");
    store.copy(3, 0);
    let (id1, x1) = (row.ids[0], [row.x[0], row.x[1], row.x[2]]);
    row.ids[0] = row.ids[3];
    row.x.copy_within(9..12, 0);
    row.ids[3] = id1;
    row.x[9..12].copy_from_slice(&x1);
    store.unpack(3, &buf).expect("a well-formed buffer");
    // a sort swaps them back, through the spare slot 4
    store.grow(5);
    store.copy(0, 4);
    store.copy(3, 0);
    store.copy(4, 3);
    row.ids.swap(0, 3);
    for c in 0..3 {
        row.x.swap(c, 9 + c);
    }
    let report = store
        .link_listed(&row.atoms(), &listed(&row))
        .expect("a well-formed list");
    assert_eq!((report.linked, report.lost()), (2, 0), "{report:?}");
    let mut after: Vec<_> = (0..2).map(|k| store.bond(k).expect("linked").0).collect();
    after.sort_by_key(|b| b.partner);
    let mut before = before;
    before.sort_by_key(|b| b.partner);
    assert_eq!(after, before, "each bond keeps its state");
}
