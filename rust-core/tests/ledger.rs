//! The ledger (`ledger`, `ffi/ledger.rs`): what both engines count, warn
//! about and log for their bonds, composed once for both adapters.

use granbond_test_support as common;

use common::{model, params};
use granbond::bond::fields::{BOND_ENERGY_FIELDS, BOND_FIELDS};
use granbond::bond::output_slots::BOND_OUTPUT_LEN;
use granbond::bond::{BondOutput, BondParams, BOND_STATE_LEN};
use granbond::bond_store::{EnergySums, StoreCounts};
use granbond::ledger::break_log::{log_text, read_words, BreakEvent, HEADER, LINE_LEN};
use granbond::ledger::c_format::c_g;
use granbond::ledger::check::{findings, Keys};
use granbond::ledger::columns::{known, BondColumns, Column};
use granbond::ledger::run_checks::{thin_periodic_box, PeriodicBox};
use granbond::ledger::{counts_row, notice, record, Notice};
use proptest::prelude::*;
use std::ffi::{c_char, c_int, CStr};

extern "C" {
    fn snprintf(s: *mut c_char, n: usize, format: *const c_char, ...) -> c_int;
}

/// `v` as the C library writes it with `%.<precision>g`.
fn printf_g(v: f64, precision: i32) -> String {
    let mut buf = [0 as c_char; 64];
    // SAFETY: the buffer's size is given; the format takes an int and a double.
    unsafe {
        snprintf(
            buf.as_mut_ptr(),
            buf.len(),
            c"%.*g".as_ptr(),
            precision as c_int,
            v,
        )
    };
    // SAFETY: snprintf terminates what it writes.
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

#[test]
fn the_counts_row_is_created_broken_intact_the_modes_and_lost() {
    let c = StoreCounts {
        created: 20,
        broken_distance: 1,
        broken_tension: 2,
        broken_compression: 3,
        broken_shear: 4,
        lost_owner_gone: 1,
        lost_partner_unreached: 1,
        lost_id_reused: 1,
        lost_no_model: 2,
        intact: 5,
    };
    assert_eq!(counts_row(&c), [20.0, 10.0, 5.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
}

#[test]
fn a_loss_warning_names_each_cause_with_its_count_and_leaves_out_causes_of_none() {
    let said = notice(Notice::PairsLostLiggghts, &[2, 0, 1, 0], 300, "").unwrap();
    assert_eq!(
        said,
        "cohesion bond/nonlinear: 3 bonds vanished at step 300 without breaking: 2 because their atom left the \
         system (deleted, or lost through a boundary); 1 because an atom's id was taken over by a new atom; \
         they are counted as lost in compute bond/counter (column 7), later ones without a warning"
    );
    let lammps = notice(Notice::PairsLostLammps, &[0, 0, 0, 4], 7, "").unwrap();
    assert_eq!(
        lammps,
        "pair granbond (bond/nonlinear): 4 bonds lost at step 7 without breaking: 4 because their atoms' types \
         have no bond model any more (set type, or pair_coeff without bond/nonlinear) (counted in compute pair \
         granbond's 8th value)"
    );
}

#[test]
fn nothing_is_said_when_no_bond_is_concerned() {
    for n in Notice::ALL {
        assert_eq!(notice(n, &[0; 4], 1, "w"), None, "{n:?}");
    }
    // the wall's and the topology's notices read three causes
    assert_eq!(notice(Notice::WallLostLiggghts, &[0, 0, 0, 9], 1, "w"), None);
    assert_eq!(notice(Notice::TopologyLeftLammps, &[0, 0, 0, 9], 1, ""), None);
}

#[test]
fn a_wall_loss_warning_names_the_wall_fix_and_the_sphere_causes() {
    let said = notice(Notice::WallLostLiggghts, &[0, 3, 0, 0], 50, "walls").unwrap();
    assert_eq!(
        said,
        "cohesion bond/nonlinear (wall walls): 3 wall bonds lost by step 50 without breaking: 3 because their \
         sphere left the wall's reach (no contact with the wall in a force pass); they are counted as lost in \
         compute bond/counter (column 8)"
    );
}

#[test]
fn the_topology_warning_counts_each_way_a_bond_left() {
    let said = notice(Notice::TopologyLeftLammps, &[1, 0, 2, 0], 9, "").unwrap();
    assert!(
        said.starts_with("bond_style granbond: 3 bonds left the topology at step 9 without breaking (1 with")
    );
    assert!(
        said.contains("; 0 to a new atom under an old id; 2 by delete_bonds)"),
        "{said}"
    );
}

#[test]
fn dropped_and_renumbered_notices_give_the_count_and_the_remedy() {
    let dropped = notice(Notice::DroppedLiggghts, &[6, 0, 0, 0], 0, "").unwrap();
    assert!(dropped.starts_with("cohesion bond/nonlinear: 6 intact bonds were dropped with the model"));
    let renumbered = notice(
        Notice::Renumbered,
        &[2, 0, 0, 0],
        0,
        "pair granbond (bond/nonlinear)",
    )
    .unwrap();
    assert!(renumbered.starts_with("pair granbond (bond/nonlinear): 2 atoms changed their atom IDs"));
    assert!(renumbered.ends_with("Delete atoms with `delete_atoms ... compress no`"));
}

fn event(step: f64, tag_i: f64, tag_j: f64) -> BreakEvent {
    BreakEvent {
        step,
        tag_i,
        tag_j,
        x: [1e-3, -2.5e-4, 0.0],
        mode: 2.0,
        sigma: 1.5e7,
        tau: 3.0e6,
        sigma_max: 2.5e7,
        tau_max: f64::INFINITY,
    }
}

#[test]
fn break_log_lines_are_sorted_by_step_then_ids_whatever_order_the_ranks_gave() {
    let mut a = vec![
        event(20.0, 3.0, 9.0),
        event(10.0, 5.0, 0.0),
        event(10.0, 2.0, 7.0),
        event(10.0, 2.0, 4.0),
    ];
    let mut b = a.clone();
    b.reverse();
    let text = log_text(&mut a, true);
    assert_eq!(text, log_text(&mut b, true));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], HEADER.trim_end());
    let keys: Vec<String> = lines[1..]
        .iter()
        .map(|l| l.split(' ').take(3).collect::<Vec<_>>().join(" "))
        .collect();
    assert_eq!(keys, ["10 2 4", "10 2 7", "10 5 0", "20 3 9"]);
    assert_eq!(
        lines[1],
        "10 2 4 0.001 -0.00025 0 tension 1.5e+07 3e+06 2.5e+07 inf"
    );
    assert!(lines.iter().all(|l| l.len() < LINE_LEN));
}

#[test]
fn a_break_event_puts_the_smaller_id_first_and_a_wall_second() {
    let m = model(BondParams {
        stress_break: 1,
        max_sigma: 4e7,
        max_tau: 3e7,
        ..params()
    });
    let out = BondOutput {
        delta: 1e-7,
        sigma: 4.1e7,
        tau: 1e6,
        break_mode: 3,
        ..Default::default()
    };
    let pair = BreakEvent::new(&m, &out, [0.0; 3], [2e-3, 0.0, 0.0], 1e-3, 1e-3, 9.0, 4.0, 12.0);
    assert_eq!(
        (pair.tag_i, pair.tag_j, pair.step, pair.mode),
        (4.0, 9.0, 12.0, 3.0)
    );
    assert_eq!(pair.x, [1e-3, 0.0, 0.0]);
    assert_eq!((pair.sigma_max, pair.tau_max), m.stress_limits_at(out.delta));
    let wall = BreakEvent::new(&m, &out, [0.0; 3], [0.0, 0.0, -1e-3], 1e-3, 0.0, 9.0, 0.0, 12.0);
    assert_eq!((wall.tag_i, wall.tag_j), (9.0, 0.0));
    assert_eq!(
        wall.x,
        [0.0, 0.0, -1e-3],
        "a wall bond's centre is the wall point"
    );
}

proptest! {
    #[test]
    fn break_log_numbers_read_as_the_c_library_writes_them(
        bits in any::<u64>(),
        scale in -40i32..40,
        mantissa in -1.0e3f64..1.0e3,
    ) {
        for v in [f64::from_bits(bits), mantissa * 10f64.powi(scale)] {
            if v.is_nan() {
                continue;
            }
            prop_assert_eq!(c_g(v, 10), printf_g(v, 10));
            prop_assert_eq!(c_g(v, 6), printf_g(v, 6));
        }
    }
}

#[test]
fn break_log_numbers_read_as_the_c_library_writes_them_at_the_edges() {
    for v in [
        0.0,
        -0.0,
        1.0,
        1e-5,
        1e-4,
        9.9999995e-5,
        999999.5,
        1e6,
        123456789.0,
        1e15,
        5e-324,
        f64::MAX,
        f64::INFINITY,
        -f64::INFINITY,
    ] {
        assert_eq!(c_g(v, 10), printf_g(v, 10), "{v:e}");
        assert_eq!(c_g(v, 6), printf_g(v, 6), "{v:e}");
    }
}

#[test]
fn breaklog_words_write_every_100_steps_unless_told_and_refuse_other_keywords() {
    assert_eq!(read_words(&["b", "all", "bond/breaklog", "f.txt"]), Ok(100));
    assert_eq!(
        read_words(&["b", "all", "bond/breaklog", "f.txt", "every", "7"]),
        Ok(7)
    );
    assert_eq!(
        read_words(&["b", "all", "bond/breaklog"]),
        Err("expected fix ID group bond/breaklog FILE [every N]".into())
    );
    assert_eq!(
        read_words(&["b", "all", "bond/breaklog", "f", "often", "3"]),
        Err("unknown keyword 'often' (the only one is: every N)".into())
    );
    assert_eq!(
        read_words(&["b", "all", "bond/breaklog", "f", "every"]),
        Err("unknown keyword 'every' (the only one is: every N)".into())
    );
    for bad in ["0", "-3", "2.5", "7x", "", "1000000001"] {
        assert_eq!(
            read_words(&["b", "all", "bond/breaklog", "f", "every", bad]),
            Err(format!("every must be an integer >= 1, got '{bad}'"))
        );
    }
    // as strtol reads a number: a sign and leading blanks
    assert_eq!(
        read_words(&["b", "all", "bond/breaklog", "f", "every", " +5"]),
        Ok(5)
    );
}

#[test]
fn output_columns_follow_the_keywords_in_the_decks_order() {
    let c = BondColumns::parse(&["sigma", "id", "pos", "energy_stored"]).unwrap();
    let sigma = BOND_FIELDS.iter().position(|f| f.name == "sigma").unwrap();
    let stored = BOND_ENERGY_FIELDS
        .iter()
        .position(|f| f.name == "energy_stored")
        .unwrap();
    let mut want = vec![Column::Field(sigma), Column::IdI, Column::IdJ];
    want.extend((0..6).map(Column::Pos));
    want.push(Column::Energy(stored));
    assert_eq!(c.columns(), want.as_slice());
    assert!(c.wants_energy());
    let all = BondColumns::parse(&["all", "state", "output"]).unwrap();
    assert_eq!(
        all.columns().len(),
        BOND_FIELDS.len() + BOND_STATE_LEN + BOND_OUTPUT_LEN
    );
    assert!(!all.wants_energy());
    // a row takes each column's value from where it says
    let record: Vec<f64> = (0..BOND_STATE_LEN + BOND_OUTPUT_LEN).map(|k| k as f64).collect();
    let fields: Vec<f64> = (0..BOND_FIELDS.len()).map(|k| 100.0 + k as f64).collect();
    let energy: Vec<f64> = (0..BOND_ENERGY_FIELDS.len()).map(|k| 200.0 + k as f64).collect();
    let mut row = vec![0.0; c.columns().len()];
    c.row(
        &record,
        &fields,
        &energy,
        3.0,
        8.0,
        [1.0, 2.0, 3.0],
        [4.0, 5.0, 6.0],
        &mut row,
    );
    assert_eq!(
        row,
        [
            100.0 + sigma as f64,
            3.0,
            8.0,
            1.0,
            2.0,
            3.0,
            4.0,
            5.0,
            6.0,
            200.0 + stored as f64
        ]
    );
}

#[test]
fn an_unknown_column_keyword_is_refused_with_every_keyword() {
    let wrong = BondColumns::parse(&["id", "sigmaa"]).unwrap_err();
    assert_eq!(wrong, format!("unknown keyword 'sigmaa' (known: {})", known()));
    assert!(known().starts_with("id pos state output all "));
    for f in BOND_FIELDS.iter().chain(BOND_ENERGY_FIELDS.iter()) {
        assert!(known().split(' ').any(|w| w == f.name), "{} is a keyword", f.name);
    }
    assert_eq!(
        BondColumns::parse(&[]).unwrap_err(),
        format!("no keyword (known: {})", known())
    );
}

#[test]
fn liggghts_inl_columns_are_the_loads_on_i_in_their_parts_then_the_state() {
    let inl = BondColumns::inl_layout();
    assert_eq!(inl.columns().len(), 18 + BOND_STATE_LEN);
    let names: Vec<&str> = inl.columns()[..18]
        .iter()
        .map(|c| match c {
            Column::Field(k) => BOND_FIELDS[*k].name,
            other => panic!("a load is a field, not {other:?}"),
        })
        .collect();
    assert_eq!(names[0], "force_x");
    assert_eq!(names[3], "force_normal_x");
    assert_eq!(names[9], "torque_x");
    assert_eq!(names[17], "torque_tangential_z");
    assert_eq!(
        inl.columns()[18..],
        (0..BOND_STATE_LEN).map(Column::Record).collect::<Vec<_>>()[..]
    );
}

#[test]
fn a_periodic_box_shorter_than_twice_the_list_reach_is_refused() {
    let b = PeriodicBox {
        dimension: 3,
        periodic: [1, 1, 1],
        length: [1.0, 1.0, 0.003],
    };
    let said = thin_periodic_box("pair granbond", &b, 0.002, 0.0005, -1).unwrap();
    assert_eq!(
        said,
        "pair granbond: the periodic box is 0.003 long in z, less than twice the neighbour reach 0.002 (the pair \
         reach 0.0015 plus the skin 0.0005): a sphere can meet its own periodic image, or one partner twice, and \
         the engine keeps a pair's contact and bond history under the partner's atom ID, so those pairs would \
         share one record. Make the box at least 0.004 long in z (replicate it), or use a fixed boundary there"
    );
    let during = thin_periodic_box("s", &b, 0.002, 0.0005, 40).unwrap();
    assert!(
        during.contains("long in z at step 40, as the box changed,"),
        "{during}"
    );
    assert!(
        during.ends_with("Keep the box (fix deform's final size) at least 0.004 long in z"),
        "{during}"
    );
    // fixed there, a 2d run's z, a box long enough: nothing
    for b in [
        PeriodicBox {
            periodic: [1, 1, 0],
            ..b
        },
        PeriodicBox { dimension: 2, ..b },
        PeriodicBox {
            length: [1.0, 1.0, 0.004],
            ..b
        },
    ] {
        assert_eq!(thin_periodic_box("s", &b, 0.002, 0.0005, -1), None, "{b:?}");
    }
}

#[test]
fn the_store_check_finds_a_bond_held_twice_before_counts_that_do_not_balance() {
    let mut keys = [[4.0, 9.0], [1.0, 2.0], [4.0, 9.0]];
    assert_eq!(
        findings(&mut keys, &[5, 0, 1, 0], Keys::Pairs),
        Some("the bond of atoms 4 and 9 is stored twice".into())
    );
    let mut walls = [[7.0, 1.0], [7.0, 0.0], [7.0, 1.0]];
    assert_eq!(
        findings(&mut walls, &[3, 0, 3, 0], Keys::Walls),
        Some("the bond of sphere 7 and wall 1 is held twice".into())
    );
    let mut once = [[1.0, 2.0], [1.0, 3.0]];
    assert_eq!(
        findings(&mut once, &[5, 1, 3, 0], Keys::Pairs),
        Some("5 bonds created, 1 broken, 3 intact, 0 lost".into())
    );
    assert_eq!(
        findings(&mut once, &[5, 1, 3, 2], Keys::Walls),
        Some("5 wall bonds created or restored, 1 broken, 3 intact, 2 lost".into())
    );
    assert_eq!(findings(&mut once, &[5, 1, 3, 1], Keys::Pairs), None);
}

#[test]
fn the_stores_record_brings_back_the_counts_and_energies_bit_for_bit() {
    let c = StoreCounts {
        created: 9,
        broken_tension: 2,
        lost_partner_unreached: 1,
        intact: 6,
        ..Default::default()
    };
    let e = EnergySums {
        damping: 1.25e-9,
        hysteresis: 3.0e-10,
        released: 7.0e-11,
    };
    let r = record::write(&c, &e, 4);
    assert_eq!(r.len(), record::RECORD_LEN);
    assert!(record::is_current(record::body_len(r[..8].try_into().unwrap())));
    assert_eq!(record::read(&r, 4), Ok((c, e)));
    // the bonds' state of another layout is refused, naming both
    assert_eq!(
        record::read(&r, 5),
        Err(
            "the restart file's bonds were written with bond state layout 4, and this granbond reads layout 5 \
             only: continue the run with the granbond that wrote the file, or start it again from its data file \
             or deck"
                .into()
        )
    );
    // a record of another length is of an older layout
    assert!(!record::is_current(record::body_len((96i64).to_ne_bytes())));
}
