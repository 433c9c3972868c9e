//! Wall bonds owned by their spheres (`granbond::bond_store::WallStore`):
//! one bond per sphere and wall whichever wall elements report the sphere,
//! moved and restarted with the sphere, counted so that created = broken +
//! intact + lost.

use granbond_test_support as common;

use granbond::bond::{BondModel, BondParams, BreakMode};
use granbond::bond_store::{
    Ids, StoreCounts, WallAct, WallContact, WallPass, WallStore, WALL_PACKED_PER_BOND,
};
use granbond::kinematics::SphereKinematics;
use granbond::ledger::check::wall_keys;

const R: f64 = common::RADIUS;

fn model() -> BondModel {
    common::model(BondParams {
        create_distance: 2.2 * R,
        create_step: 1,
        max_distance: 2.6 * R,
        damping: 1,
        ..common::params()
    })
}

/// The sphere at step `step`: it rests on the wall z = 0 at first, then the
/// wall moves down (as the mesh of the repro deck is pulled) while the
/// sphere slides sideways and spins a little.
fn sphere(step: i64) -> SphereKinematics {
    let t = step as f64 * 1e-6;
    SphereKinematics {
        x: [1e-3 + 2e-3 * t, 1e-3, 0.99 * R],
        v: [2e-3, 0.0, 0.0],
        w: [0.0, 3.0, 0.5],
        radius: R,
    }
}

const WALL_V: [f64; 3] = [0.0, 0.0, -0.02];

/// A contact of atom slot `atom` (id 7) with wall 0 at element `element`,
/// in the force pass of `step`.
fn contact(atom: usize, element: i64, step: i64, kind: WallPass) -> WallContact {
    let s = sphere(step);
    WallContact {
        atom,
        id: 7,
        wall: 0,
        element,
        pass: 2 * step + (kind == WallPass::Setup) as i64,
        kind: kind as i32,
        step,
        dt: 1e-6,
        may_create: (kind == WallPass::Force) as i32,
        sphere: s,
        wall_velocity: WALL_V,
        contact_point: [s.x[0], s.x[1], 0.0],
    }
}

fn store(atoms: usize) -> WallStore {
    let mut s = WallStore::new();
    s.grow(atoms);
    s
}

fn balanced(c: &StoreCounts) -> bool {
    c.created == c.broken() + c.intact + c.lost()
}

/// The loads on the sphere over `steps` force passes, each contact of a
/// pass reported at the elements `elements` in that order.
fn run(s: &mut WallStore, m: &BondModel, steps: std::ops::Range<i64>, elements: &[i64]) -> Vec<[f64; 6]> {
    let mut loads = Vec::new();
    for step in steps {
        let mut acted = 0;
        let mut load = [0.0; 6];
        for &e in elements {
            let v = s.visit(m, &contact(0, e, step, WallPass::Force)).unwrap();
            if v.act == WallAct::Bond as i32 {
                acted += 1;
                load[..3].copy_from_slice(&v.out.force_i);
                load[3..].copy_from_slice(&v.out.torque_i);
            } else {
                assert_eq!(
                    v.act,
                    WallAct::Held as i32,
                    "step {step}: a bonded sphere's other contact is held"
                );
            }
        }
        assert_eq!(acted, 1, "step {step}: the bond acts at exactly one contact");
        loads.push(load);
    }
    loads
}

#[test]
fn a_sphere_on_the_edge_of_two_triangles_meets_one_bond() {
    let m = model();
    let mut edge = store(1);
    let mut face = store(1);
    let on_edge = run(&mut edge, &m, 1..50, &[3, 4]);
    let on_face = run(&mut face, &m, 1..50, &[3]);
    assert_eq!(on_edge, on_face, "two triangles give the loads of one");
    assert!(on_edge.iter().any(|l| l[2] != 0.0));
    let c = edge.counts();
    assert_eq!((c.created, c.intact), (1, 1));
    assert_eq!(edge.len(), 1);
}

#[test]
fn the_bond_steps_the_same_whichever_triangle_reports_it_first() {
    let m = model();
    let (mut a, mut b) = (store(1), store(1));
    assert_eq!(run(&mut a, &m, 1..40, &[3, 4]), run(&mut b, &m, 1..40, &[4, 3]));
}

#[test]
fn a_bond_restarted_on_other_ranks_is_one_bond_with_the_same_loads() {
    let m = model();
    let mut whole = store(1);
    let reference = run(&mut whole, &m, 1..80, &[3, 4]);

    let mut written = store(1);
    run(&mut written, &m, 1..40, &[3]);
    let mut buf = vec![0.0; written.packed_len(7)];
    assert_eq!(
        written.pack(0, 7, false, &mut buf),
        Some(2 + WALL_PACKED_PER_BOND)
    );
    assert_eq!(written.len(), 1, "a restart file leaves the bond where it is");

    // read back at another atom slot; both triangles report the sphere
    let mut read = store(3);
    assert_eq!(read.unpack(2, 7, 39, &buf), Ok(buf.len()));
    read.link(Ids::Wide(&[1, 5, 7]));
    let mut after = Vec::new();
    for step in 40..80 {
        let mut acted = Vec::new();
        for e in [4, 3] {
            let mut c = contact(2, e, step, WallPass::Force);
            c.atom = 2;
            let v = read.visit(&m, &c).unwrap();
            if v.act == WallAct::Bond as i32 {
                acted.push([
                    v.out.force_i[0],
                    v.out.force_i[1],
                    v.out.force_i[2],
                    v.out.torque_i[0],
                    v.out.torque_i[1],
                    v.out.torque_i[2],
                ]);
            }
        }
        assert_eq!(acted.len(), 1, "step {step}: one bond after the restart");
        after.push(acted[0]);
    }
    assert_eq!(
        after[..],
        reference[39..],
        "the restarted bond goes on as the uninterrupted one"
    );
    assert_eq!(read.counts().intact, 1);
    assert_eq!(read.len(), 1);
}

#[test]
fn a_bond_migrates_with_its_sphere_and_the_counts_add_up_over_ranks() {
    let m = model();
    let mut from = store(2);
    let mut c = contact(1, 3, 1, WallPass::Force);
    assert_eq!(from.visit(&m, &c).unwrap().created, 1);
    let mut buf = vec![0.0; from.most_packed_len()];
    let n = from.pack(1, 7, true, &mut buf).unwrap();
    assert!(from.is_empty());
    let mut to = store(1);
    assert_eq!(to.unpack(0, 7, 1, &buf[..n]), Ok(n));
    let sum = |a: StoreCounts, b: StoreCounts| StoreCounts {
        created: a.created + b.created,
        broken_distance: a.broken_distance + b.broken_distance,
        intact: a.intact + b.intact,
        ..StoreCounts::default()
    };
    let total = sum(from.counts(), to.counts());
    assert_eq!((total.created, total.intact), (1, 1));
    assert!(balanced(&total));
    c.atom = 0;
    c.step = 2;
    c.pass = 4;
    assert_eq!(to.visit(&m, &c).unwrap().act, WallAct::Bond as i32);
}

#[test]
fn a_sphere_out_of_the_walls_reach_loses_its_bond_counted() {
    let m = model();
    let mut s = store(1);
    run(&mut s, &m, 1..5, &[3]);
    // no contact at step 5; the force pass of step 6 finds the bond unreached
    let mut other = contact(0, 3, 6, WallPass::Force);
    other.id = 8;
    other.may_create = 0;
    s.visit(&m, &other).unwrap();
    let c = s.counts();
    assert_eq!((c.intact, c.lost_partner_unreached), (0, 1));
    assert!(balanced(&c));
    assert!(s.is_empty());
}

#[test]
fn a_new_atom_that_takes_a_deleted_spheres_id_does_not_take_its_bond() {
    let m = model();
    let mut s = store(2);
    run(&mut s, &m, 1..3, &[3]);
    // the sphere at slot 0 is deleted (the last atom copied over it) and a
    // new atom created at slot 1 gets its id
    s.copy(1, 0);
    s.clear(1);
    s.link(Ids::Wide(&[3, 7]));
    let c = s.counts();
    assert_eq!((c.intact, c.lost_id_reused, c.lost_owner_gone), (0, 1, 0));
    assert!(balanced(&c));
}

#[test]
fn a_sphere_that_left_the_system_loses_its_bond_counted() {
    let m = model();
    let mut s = store(1);
    run(&mut s, &m, 1..3, &[3]);
    s.link(Ids::Wide(&[4]));
    let c = s.counts();
    assert_eq!((c.intact, c.lost_owner_gone), (0, 1));
    assert!(balanced(&c));
}

#[test]
fn a_broken_bond_is_counted_once_and_does_not_form_again() {
    let m = model();
    let mut s = store(1);
    run(&mut s, &m, 1..3, &[3, 4]);
    // the wall drops away: the sphere is far beyond max_distance
    let far = |step: i64, e: i64| {
        let mut c = contact(0, e, step, WallPass::Force);
        c.sphere.x[2] += 2.0 * R;
        c.contact_point[2] = 0.0;
        c
    };
    let first = s.visit(&m, &far(3, 3)).unwrap();
    assert_eq!(first.act, WallAct::Contact as i32);
    assert_eq!(first.out.break_mode, BreakMode::Distance as i32);
    let second = s.visit(&m, &far(3, 4)).unwrap();
    assert_eq!((second.act, second.out.break_mode), (WallAct::Contact as i32, 0));
    // back on the wall at a later pass: it does not form again
    let again = s.visit(&m, &contact(0, 3, 4, WallPass::Force)).unwrap();
    assert_eq!((again.act, again.created), (WallAct::Contact as i32, 0));
    let c = s.counts();
    assert_eq!((c.created, c.broken_distance, c.intact), (1, 1, 0));
    assert!(balanced(&c));
}

#[test]
fn setup_and_output_passes_show_the_latest_force_pass_at_one_contact() {
    let m = model();
    let mut s = store(1);
    let loads = run(&mut s, &m, 1..10, &[3, 4]);
    let last = loads.last().unwrap();
    // the per-contact output pass of step 9: the loads at the contact that
    // applied them, the other contact held
    for (e, want) in [(3, WallAct::Bond), (4, WallAct::Held), (3, WallAct::Bond)] {
        let v = s.visit(&m, &contact(0, e, 9, WallPass::Output)).unwrap();
        assert_eq!(v.act, want as i32);
        if v.act == WallAct::Bond as i32 {
            assert_eq!(v.out.force_i[..], last[..3]);
        }
    }
    // the next run's setup pass applies them once, at whichever contact
    // comes first
    let mut acts = Vec::new();
    for e in [4, 3] {
        let v = s.visit(&m, &contact(0, e, 9, WallPass::Setup)).unwrap();
        acts.push(v.act);
        if v.act == WallAct::Bond as i32 {
            assert_eq!(v.out.force_i[..], last[..3]);
            assert_eq!(v.out.torque_i[..], last[3..]);
        }
    }
    assert_eq!(acts, [WallAct::Bond as i32, WallAct::Held as i32]);
    // and the force pass after it goes on as without the setup pass
    let mut plain = store(1);
    let reference = run(&mut plain, &m, 1..11, &[3]);
    assert_eq!(run(&mut s, &m, 10..11, &[3, 4])[0], reference[9]);
}

#[test]
fn packed_rows_of_another_layout_are_refused() {
    let mut s = store(1);
    let mut row = vec![1.0, (WALL_PACKED_PER_BOND - 1) as f64];
    row.resize(2 + WALL_PACKED_PER_BOND, 0.0);
    assert!(s.unpack(0, 7, 0, &row).is_err());
    row[1] = WALL_PACKED_PER_BOND as f64;
    assert!(s.unpack(0, 7, 0, &row[..row.len() - 1]).is_err());
    assert!(s.is_empty());
}

#[test]
fn renumbered_walls_keep_each_bond_on_its_wall() {
    let m = model();
    let mut s = store(1);
    // bonds on walls 0 and 1; the engine lists the walls the other way round
    for wall in [0, 1] {
        let mut c = contact(0, 3, 1, WallPass::Force);
        c.wall = wall;
        assert_eq!(s.visit(&m, &c).unwrap().created, 1);
    }
    assert_eq!(s.renumber(&[1, 0]), Ok(()));
    assert_eq!(s.len(), 2);
    assert!(s.bonded(0, 7, 0) && s.bonded(0, 7, 1));
    // a third wall listed first: the bonds move up by one
    assert_eq!(s.renumber(&[1, 2]), Ok(()));
    assert!(!s.bonded(0, 7, 0) && s.bonded(0, 7, 1) && s.bonded(0, 7, 2));
    let c = s.counts();
    assert_eq!((c.created, c.intact, c.lost()), (2, 2, 0));
}

#[test]
fn a_renumbering_without_a_place_for_a_bonds_wall_is_refused_and_changes_nothing() {
    let m = model();
    let mut s = store(1);
    let mut c = contact(0, 3, 1, WallPass::Force);
    c.wall = 1;
    assert_eq!(s.visit(&m, &c).unwrap().created, 1);
    assert_eq!(
        s.renumber(&[0, -1]),
        Err(granbond::bond_store::WallError::WallGone(1))
    );
    assert_eq!(
        s.renumber(&[0]),
        Err(granbond::bond_store::WallError::WallGone(1))
    );
    assert_eq!(
        s.renumber(&[0, 0]),
        Err(granbond::bond_store::WallError::WallTwice(0))
    );
    assert!(
        s.bonded(0, 7, 1),
        "the refused renumbering left the bond where it was"
    );
    // a wall without bonds may be gone
    assert_eq!(s.renumber(&[-1, 0]), Ok(()));
    assert!(s.bonded(0, 7, 0));
}

#[test]
fn the_store_checks_keys_name_each_wall_bond_and_refuse_one_whose_sphere_is_elsewhere() {
    let m = model();
    let mut s = store(1);
    s.visit(&m, &contact(0, 3, 1, WallPass::Force)).unwrap();
    assert_eq!(wall_keys(&s, Ids::Wide(&[7])), Ok(vec![[7.0, 0.0]]));
    assert_eq!(
        wall_keys(&s, Ids::Wide(&[8])),
        Err("the bond of sphere 7 and wall 0 is held by a rank without the sphere".into())
    );
}
