//! The bond pass over an engine's index of bonded pairs
//! (`granbond_bond_sweep`, `crate::sweep`), on records laid out as
//! `granbond_record_layout` says.

use granbond_test_support as common;

use granbond::bond::{BondOutput, BondState, BondStatus, BreakMode, BOND_STATE_LEN};
use granbond::ffi::bond::{granbond_bond_compute_indexed, AtomArrayPointers};
use granbond::ffi::layout::StateKind;
use granbond::ffi::sweep::{granbond_bond_file_loads, granbond_bond_sweep, granbond_record_layout};
use granbond::ffi::Status;
use granbond::record::{record_slots, RecordLayout};
use granbond::state_layout::swap_state;
use granbond::sweep::{SweepPass, SweepTally};

/// Bonds `k` between atoms `2k` and `2k + 1`, stretched and sheared by
/// amounts that grow with `k`, so that the last ones exceed `max_distance`.
struct Scene {
    x: Vec<f64>,
    v: Vec<f64>,
    omega: Vec<f64>,
    radius: Vec<f64>,
    pairs: Vec<i32>,
}

const BONDS: usize = 150; // more than one of the sweep's chunks
const R: f64 = common::RADIUS;

fn scene() -> Scene {
    let mut s = Scene {
        x: vec![],
        v: vec![],
        omega: vec![],
        radius: vec![],
        pairs: vec![],
    };
    for k in 0..BONDS {
        let f = k as f64 / BONDS as f64;
        let stretch = 2.0 * R * (1.0 + 2e-3 * f);
        s.x.extend([
            0.01 * k as f64,
            0.0,
            0.0,
            0.01 * k as f64 + stretch,
            1e-5 * f,
            0.0,
        ]);
        s.v.extend([0.0, 0.0, 0.0, 1e-3 * f, -2e-3 * f, 5e-4]);
        s.omega.extend([0.1 * f, 0.0, -0.2, 0.0, 0.3 * f, 0.0]);
        s.radius.extend([R, R]);
        s.pairs.extend([2 * k as i32 + 1, 2 * k as i32]);
    }
    s
}

fn atoms(s: &Scene) -> AtomArrayPointers {
    AtomArrayPointers {
        x: s.x.as_ptr(),
        v: s.v.as_ptr(),
        omega: s.omega.as_ptr(),
        radius: s.radius.as_ptr(),
        count: s.radius.len(),
    }
}

fn layout(with_contact: bool) -> RecordLayout {
    let mut l = RecordLayout::new(false);
    assert_eq!(
        unsafe { granbond_record_layout(with_contact as i32, &mut l) },
        Status::Ok
    );
    l
}

/// Records of fresh bonds at the rest length `2R`, with a contact state
/// that is not zero (so that clearing it shows).
fn records(l: &RecordLayout) -> Vec<Vec<f64>> {
    (0..BONDS)
        .map(|k| {
            let mut r = vec![0.0; l.len];
            for (c, v) in r[..l.contact_len].iter_mut().enumerate() {
                *v = 1e-6 * (c + k + 1) as f64;
            }
            r[l.bond..l.bond + BOND_STATE_LEN].copy_from_slice(BondState::created(2.0 * R).as_slots());
            r
        })
        .collect()
}

fn model() -> Box<granbond::bond::BondModel> {
    let p = granbond::bond::BondParams {
        max_distance: 2.0 * R * (1.0 + 1e-3),
        ..common::params()
    };
    Box::new(common::model(p))
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[allow(clippy::too_many_arguments)]
fn sweep(
    m: &granbond::bond::BondModel,
    s: &Scene,
    pass: &SweepPass,
    counted: &[u8],
    recs: &mut [Vec<f64>],
    out: &mut [BondOutput],
    tally: &mut SweepTally,
    failed: &mut usize,
) -> Status {
    let pointers: Vec<*mut f64> = recs.iter_mut().map(|r| r.as_mut_ptr()).collect();
    unsafe {
        granbond_bond_sweep(
            m,
            pass,
            recs.len(),
            &atoms(s),
            s.pairs.as_ptr(),
            counted.as_ptr(),
            pointers.as_ptr(),
            out.as_mut_ptr(),
            tally,
            failed,
        )
    }
}

fn force_pass(contact_under_bond: bool) -> SweepPass {
    SweepPass {
        dt: 1e-7,
        advance: 1,
        contact_under_bond: contact_under_bond as i32,
        with_contact: 1,
        keep_loads: 1,
    }
}

#[test]
fn the_layout_names_each_part_where_the_slot_table_has_it() {
    for with_contact in [true, false] {
        let l = layout(with_contact);
        let names: Vec<&str> = record_slots(with_contact).map(|s| s.name).collect();
        assert_eq!(names.len(), l.len);
        assert_eq!(names[l.status], "rest");
        assert_eq!(names[l.bond], "rest");
        assert_eq!(names[l.loads], "bond_force_x");
        assert_eq!(l.loads, l.bond + BOND_STATE_LEN);
        let kind = if with_contact {
            StateKind::PairRecord
        } else {
            StateKind::BondRecord
        };
        assert_eq!(granbond::ffi::layout::granbond_state_len(kind as i32), l.len);
    }
    assert_eq!(layout(false).contact_len, 0);
    assert_eq!(layout(true).bond, layout(true).contact_len);
}

#[test]
fn a_force_pass_steps_as_the_indexed_entry_and_keeps_the_loads_a_setup_pass_applies() {
    let (m, s, l) = (model(), scene(), layout(true));
    // the reference: the indexed entry on copies of the bond states
    let mut states: Vec<BondState> = (0..BONDS).map(|_| BondState::created(2.0 * R)).collect();
    let mut want = vec![BondOutput::default(); BONDS];
    let mut ptrs: Vec<*mut f64> = states
        .iter_mut()
        .map(|b| b as *mut BondState as *mut f64)
        .collect();
    let mut failed = usize::MAX;
    let status = unsafe {
        granbond_bond_compute_indexed(
            &*m,
            BONDS,
            &atoms(&s),
            s.pairs.as_ptr(),
            1e-7,
            ptrs.as_mut_ptr(),
            want.as_mut_ptr(),
            &mut failed,
        )
    };
    assert_eq!(status, Status::Ok);

    let mut recs = records(&l);
    let counted: Vec<u8> = (0..BONDS).map(|k| (k % 3 != 0) as u8).collect();
    let mut out = vec![BondOutput::default(); BONDS];
    let mut tally = SweepTally::default();
    assert_eq!(
        sweep(
            &m,
            &s,
            &force_pass(false),
            &counted,
            &mut recs,
            &mut out,
            &mut tally,
            &mut failed
        ),
        Status::Ok
    );

    let mut intact = 0;
    let mut broken = 0;
    for k in 0..BONDS {
        assert_eq!(
            bits(&recs[k][l.bond..l.bond + BOND_STATE_LEN]),
            bits(states[k].as_slots()),
            "bond {k}"
        );
        assert_eq!(bits(&out[k].force_i), bits(&want[k].force_i));
        assert_eq!(bits(&out[k].torque_i), bits(&want[k].torque_i));
        assert_eq!(bits(&out[k].torque_j), bits(&want[k].torque_j));
        assert_eq!(
            (out[k].status, out[k].break_mode),
            (want[k].status, want[k].break_mode)
        );
        if out[k].status == BondStatus::Intact as i32 {
            intact += counted[k] as i64;
        } else {
            assert_eq!(out[k].break_mode, BreakMode::Distance as i32, "bond {k}");
            broken += counted[k] as i64;
            // the contact starts afresh, and no loads are kept
            assert!(recs[k][..l.contact_len].iter().all(|&v| v == 0.0));
            assert!(recs[k][l.loads..].iter().all(|&v| v == 0.0));
        }
    }
    assert!(
        intact > 0 && broken > 0,
        "the scene has both: {intact} intact, {broken} broken"
    );
    assert_eq!(
        tally,
        SweepTally {
            intact,
            broken_distance: broken,
            ..SweepTally::default()
        }
    );

    // the setup pass applies exactly the loads of the force pass
    let mut setup_out = vec![BondOutput::default(); BONDS];
    let mut setup_tally = SweepTally::default();
    let setup = SweepPass {
        advance: 0,
        ..force_pass(false)
    };
    let before: Vec<Vec<f64>> = recs.clone();
    assert_eq!(
        sweep(
            &m,
            &s,
            &setup,
            &counted,
            &mut recs,
            &mut setup_out,
            &mut setup_tally,
            &mut failed
        ),
        Status::Ok
    );
    assert_eq!(recs, before, "a setup pass changes no record");
    assert_eq!(
        setup_tally,
        SweepTally {
            intact,
            ..SweepTally::default()
        }
    );
    for k in 0..BONDS {
        assert_eq!(setup_out[k].status, out[k].status);
        if out[k].status != BondStatus::Intact as i32 {
            assert_eq!(bits(&setup_out[k].force_i), bits(&[0.0; 3]));
            continue;
        }
        assert_eq!(bits(&setup_out[k].force_i), bits(&out[k].force_i));
        assert_eq!(bits(&setup_out[k].torque_i), bits(&out[k].torque_i));
        assert_eq!(bits(&setup_out[k].torque_j), bits(&out[k].torque_j));
        assert_eq!((setup_out[k].sigma, setup_out[k].tau), (out[k].sigma, out[k].tau));
    }
}

#[test]
fn a_pass_over_the_bond_states_alone_and_its_outputs_filed_leave_the_records_a_keeping_pass_leaves() {
    let (m, s, l) = (model(), scene(), layout(true));
    let counted = vec![1u8; BONDS];
    let mut failed = usize::MAX;
    // the reference: a force pass that keeps the loads in the records
    let mut kept = records(&l);
    // old loads in every record: a pass that keeps none must not touch them
    for r in kept.iter_mut() {
        for (n, v) in r[l.loads..].iter_mut().enumerate() {
            *v = 1.0 + n as f64;
        }
    }
    // a bond broken before the pass: the pass leaves its record, so must filing
    kept[11][l.status] = BondStatus::Broken as i32 as f64;
    let stale = kept.clone();
    let mut kept_out = vec![BondOutput::default(); BONDS];
    let mut kept_tally = SweepTally::default();
    let status = sweep(
        &m,
        &s,
        &force_pass(false),
        &counted,
        &mut kept,
        &mut kept_out,
        &mut kept_tally,
        &mut failed,
    );
    assert_eq!(status, Status::Ok);

    // the same pass over the bond states alone, as an engine's rows: records
    // without the contact, cut before the loads
    let mut rows: Vec<Vec<f64>> = stale.iter().map(|r| r[l.bond..l.loads].to_vec()).collect();
    let mut out = vec![BondOutput::default(); BONDS];
    let mut tally = SweepTally::default();
    let pass = SweepPass {
        keep_loads: 0,
        with_contact: 0,
        ..force_pass(false)
    };
    assert_eq!(
        sweep(
            &m,
            &s,
            &pass,
            &counted,
            &mut rows,
            &mut out,
            &mut tally,
            &mut failed
        ),
        Status::Ok
    );
    assert_eq!(tally, kept_tally);
    assert!(kept_tally.intact > 0 && kept_tally.broken() > 0);
    for k in 0..BONDS {
        assert_eq!(bits(&rows[k]), bits(&kept[k][l.bond..l.loads]), "bond {k}");
        assert_eq!(bits(&out[k].force_i), bits(&kept_out[k].force_i));
    }

    // the rows back in the whole records and the outputs filed there: what
    // the keeping pass left, bit for bit, the contact of a bond that broke
    // cleared; the last bond's output as no pass wrote it leaves its record
    // alone
    let mut filed: Vec<Vec<f64>> = stale.clone();
    for (f, r) in filed.iter_mut().zip(&rows) {
        f[l.bond..l.loads].copy_from_slice(r);
    }
    out[BONDS - 1] = BondOutput::default();
    let whole = force_pass(false);
    let pointers: Vec<*mut f64> = filed.iter_mut().map(|r| r.as_mut_ptr()).collect();
    let status =
        unsafe { granbond_bond_file_loads(&whole, BONDS, pointers.as_ptr(), out.as_ptr(), &mut failed) };
    assert_eq!(status, Status::Ok);
    for k in 0..BONDS - 1 {
        assert_eq!(bits(&filed[k]), bits(&kept[k]), "bond {k}");
    }
    let last = BONDS - 1;
    assert_eq!(
        bits(&filed[last][..l.contact_len]),
        bits(&stale[last][..l.contact_len])
    );
    assert_eq!(bits(&filed[last][l.loads..]), bits(&stale[last][l.loads..]));

    // where the contact goes on under the bond, filing leaves it
    let mut under = stale.clone();
    let goes_on = SweepPass {
        contact_under_bond: 1,
        ..whole
    };
    let pointers: Vec<*mut f64> = under.iter_mut().map(|r| r.as_mut_ptr()).collect();
    let status =
        unsafe { granbond_bond_file_loads(&goes_on, BONDS, pointers.as_ptr(), out.as_ptr(), &mut failed) };
    assert_eq!(status, Status::Ok);
    for k in (0..BONDS).filter(|&k| out[k].break_mode != 0) {
        assert_eq!(
            bits(&under[k][..l.contact_len]),
            bits(&stale[k][..l.contact_len]),
            "bond {k}"
        );
        assert!(
            under[k][l.loads..].iter().all(|&v| v == 0.0),
            "bond {k}: no loads kept"
        );
    }

    // a null record is named before any is filed
    for (f, old) in filed.iter_mut().zip(&stale) {
        f[l.loads..].copy_from_slice(&old[l.loads..]);
    }
    let before = filed.clone();
    let mut pointers: Vec<*mut f64> = filed.iter_mut().map(|r| r.as_mut_ptr()).collect();
    pointers[7] = std::ptr::null_mut();
    failed = usize::MAX;
    let status =
        unsafe { granbond_bond_file_loads(&whole, BONDS, pointers.as_ptr(), out.as_ptr(), &mut failed) };
    assert_eq!(status, Status::NullPointer);
    assert_eq!(failed, 7);
    assert_eq!(bits(&filed.concat()), bits(&before.concat()));
}

#[test]
fn the_contact_under_a_bond_that_breaks_goes_on_only_where_the_pass_says_so() {
    let (m, s, l) = (model(), scene(), layout(true));
    let counted = vec![1u8; BONDS];
    let mut failed = 0;
    for under in [false, true] {
        let mut recs = records(&l);
        let fresh = recs.clone();
        let mut out = vec![BondOutput::default(); BONDS];
        let mut tally = SweepTally::default();
        assert_eq!(
            sweep(
                &m,
                &s,
                &force_pass(under),
                &counted,
                &mut recs,
                &mut out,
                &mut tally,
                &mut failed
            ),
            Status::Ok
        );
        let mut seen = 0;
        for k in (0..BONDS).filter(|&k| out[k].break_mode != 0) {
            seen += 1;
            let contact = &recs[k][..l.contact_len];
            if under {
                assert_eq!(
                    contact,
                    &fresh[k][..l.contact_len],
                    "bond {k}: the contact goes on"
                );
            } else {
                assert!(
                    contact.iter().all(|&v| v == 0.0),
                    "bond {k}: the contact starts afresh"
                );
            }
        }
        assert!(seen > 0);
        // an intact bond's contact is the engine's to step, not the sweep's
        let k = (0..BONDS)
            .find(|&k| out[k].status == BondStatus::Intact as i32)
            .unwrap();
        assert_eq!(recs[k][..l.contact_len], fresh[k][..l.contact_len]);
    }
}

#[test]
fn a_record_seen_from_the_other_sphere_gives_the_loads_on_that_sphere() {
    let (m, s, l) = (model(), scene(), layout(true));
    let counted = vec![1u8; BONDS];
    let (mut failed, mut tally) = (0, SweepTally::default());
    let mut recs = records(&l);
    let mut out = vec![BondOutput::default(); BONDS];
    assert_eq!(
        sweep(
            &m,
            &s,
            &force_pass(false),
            &counted,
            &mut recs,
            &mut out,
            &mut tally,
            &mut failed
        ),
        Status::Ok
    );
    let table: Vec<_> = record_slots(true).collect();
    for r in recs.iter_mut() {
        swap_state(&table, r);
    }
    // the swapped records as the other atoms index them
    let mut swapped_scene = scene();
    for p in swapped_scene.pairs.chunks_mut(2) {
        p.swap(0, 1);
    }
    let mut back = vec![BondOutput::default(); BONDS];
    let setup = SweepPass {
        advance: 0,
        ..force_pass(false)
    };
    assert_eq!(
        sweep(
            &m,
            &swapped_scene,
            &setup,
            &counted,
            &mut recs,
            &mut back,
            &mut tally,
            &mut failed
        ),
        Status::Ok
    );
    for k in (0..BONDS).filter(|&k| out[k].status == BondStatus::Intact as i32) {
        assert_eq!(bits(&back[k].force_i), bits(&out[k].force_i.map(|f| -f)));
        assert_eq!(bits(&back[k].torque_i), bits(&out[k].torque_j));
        assert_eq!(bits(&back[k].torque_j), bits(&out[k].torque_i));
    }
}

#[test]
fn bad_records_and_indices_are_named_before_any_bond_moves() {
    let (m, s, l) = (model(), scene(), layout(true));
    let counted = vec![1u8; BONDS];
    let mut recs = records(&l);
    let fresh = recs.clone();
    let mut pointers: Vec<*mut f64> = recs.iter_mut().map(|r| r.as_mut_ptr()).collect();
    pointers[97] = std::ptr::null_mut();
    let mut out = vec![BondOutput::default(); BONDS];
    let (mut tally, mut failed) = (SweepTally::default(), usize::MAX);
    let status = unsafe {
        granbond_bond_sweep(
            &*m,
            &force_pass(false),
            BONDS,
            &atoms(&s),
            s.pairs.as_ptr(),
            counted.as_ptr(),
            pointers.as_ptr(),
            out.as_mut_ptr(),
            &mut tally,
            &mut failed,
        )
    };
    assert_eq!(status, Status::NullPointer);
    assert_eq!(failed, 97);
    assert_eq!(recs, fresh);

    let mut bad = scene();
    bad.pairs[2 * 130 + 1] = 2 * BONDS as i32;
    failed = usize::MAX;
    let status = sweep(
        &m,
        &bad,
        &force_pass(false),
        &counted,
        &mut recs,
        &mut out,
        &mut tally,
        &mut failed,
    );
    assert_eq!(status, Status::InvalidArgument);
    assert_eq!(failed, 130);
    assert_eq!(recs, fresh);
    let message = unsafe { std::ffi::CStr::from_ptr(granbond::ffi::error::granbond_last_error_message()) };
    assert!(message.to_string_lossy().contains("bond 130"), "{message:?}");
}
