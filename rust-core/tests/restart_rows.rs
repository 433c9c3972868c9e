//! Parameters in restart files as rows by keyword (`granbond::restart_rows`):
//! a file names what it sets, and one of another table is refused with the
//! keywords named.

use granbond::bond::{BondParams, PARAMETERS};
use granbond::contact::{VoigtParams, VOIGT_PARAMETERS};
use granbond::restart_rows::{read, write};

fn bond() -> BondParams {
    BondParams {
        k_fn1: 1234.5,
        damping: 1,
        ..BondParams::default()
    }
}

#[test]
fn rows_written_and_read_back_give_the_same_parameters() {
    let rows = write(PARAMETERS, &bond());
    assert_eq!(
        read("bond/nonlinear", PARAMETERS, &rows, "atom types 1 2"),
        Ok(bond())
    );
    let v = VoigtParams {
        k_n: 7e4,
        rolling: 1,
        ..VoigtParams::default()
    };
    assert_eq!(
        read(
            "voigt",
            VOIGT_PARAMETERS,
            &write(VOIGT_PARAMETERS, &v),
            "atom types 1 2"
        ),
        Ok(v)
    );
}

#[test]
fn a_file_that_sets_a_keyword_the_table_lacks_is_refused_naming_it() {
    let rows = write(PARAMETERS, &bond());
    let first = PARAMETERS[0].name;
    let at = 8;
    assert_eq!(&rows[at..at + first.len()], first.as_bytes());
    let mut renamed = rows.clone();
    renamed[at + first.len() - 1] = b'X';
    let e = read("bond/nonlinear", PARAMETERS, &renamed, "atom types 1 2").unwrap_err();
    let name = format!("{}X", &first[..first.len() - 1]);
    assert!(
        e.contains(&format!("sets '{name}' for atom types 1 2 (bond/nonlinear)")),
        "{e}"
    );
}

#[test]
fn a_file_that_leaves_out_a_row_is_refused_naming_it() {
    let rows = write(PARAMETERS, &bond());
    let last = PARAMETERS.last().unwrap().name;
    let cut = rows.len() - (4 + last.len() + 8);
    let mut short = rows[..cut].to_vec();
    short[..4].copy_from_slice(&(PARAMETERS.len() as i32 - 1).to_ne_bytes());
    let e = read("bond/nonlinear", PARAMETERS, &short, "bond type 3").unwrap_err();
    assert!(e.contains(&format!("does not set {last} for bond type 3")), "{e}");
}

#[test]
fn a_damaged_table_is_refused_as_damaged() {
    let mut rows = write(PARAMETERS, &bond());
    rows[..4].copy_from_slice(&(-3i32).to_ne_bytes());
    let e = read("bond/nonlinear", PARAMETERS, &rows, "atom types 1 1").unwrap_err();
    assert_eq!(
        e,
        "granbond: the restart file is damaged (a table of -3 parameters)"
    );
    let rows = write(PARAMETERS, &bond());
    let e = read(
        "bond/nonlinear",
        PARAMETERS,
        &rows[..rows.len() - 3],
        "atom types 1 1",
    )
    .unwrap_err();
    assert_eq!(e, "granbond: the restart file is damaged (a table cut short)");
}

#[test]
fn a_value_out_of_range_in_a_file_is_refused_naming_the_parameter() {
    let rows = write(
        PARAMETERS,
        &BondParams {
            k_fn1: -1.0,
            ..bond()
        },
    );
    let e = read("bond/nonlinear", PARAMETERS, &rows, "atom types 1 1").unwrap_err();
    assert!(
        e.starts_with(
            "granbond: the restart file's atom types 1 1 (bond/nonlinear): bond/nonlinear parameter k_fn1"
        ),
        "{e}"
    );
}
