//! LIGGGHTS deck words the core checks before the engine reads them
//! (`granbond::liggghts_words`): each refusal names the command and the word.

use granbond::liggghts_words::{check_property_line, check_settings};

/// `fix b all property/global NAME` and `rest`, checked.
fn line(name: &str, rest: &str) -> (Result<bool, String>, Vec<bool>) {
    let words: Vec<&str> = ["b", "all", "property/global", name]
        .into_iter()
        .chain(rest.split_whitespace())
        .collect();
    let mut infinite = vec![false; words.len()];
    (check_property_line(&words, &mut infinite), infinite)
}

const SIGMA: &str = "maxSigmaBondnonlinear";

#[test]
fn a_property_that_is_not_granbonds_is_left_to_the_engine() {
    assert_eq!(line("youngsModulus", "peratomtype 5e6").0, Ok(false));
}

#[test]
fn a_per_type_pair_property_needs_n_squared_values() {
    assert_eq!(
        line(SIGMA, "peratomtypepair 2 1e6 1e6 1e6").0,
        Err(format!(
            "fix b property/global {SIGMA}: peratomtypepair 2 needs 4 values, got 3"
        ))
    );
    let e = line(SIGMA, "scalar 1e6").0.unwrap_err();
    assert!(
        e.contains(&format!(
            "given as 'scalar'; granbond reads {SIGMA} only as peratomtypepair"
        )),
        "{e}"
    );
    let e = line(SIGMA, "peratomtypepair two").0.unwrap_err();
    assert!(
        e.ends_with("needs the number of atom types N (an integer >= 1), got 'two'"),
        "{e}"
    );
}

#[test]
fn infinity_is_flagged_where_the_row_takes_it_and_refused_elsewhere() {
    let (read, infinite) = line(SIGMA, "peratomtypepair 1 inf");
    assert_eq!(read, Ok(true));
    assert_eq!(infinite, [false, false, false, false, false, false, true]);
    assert_eq!(
        line(SIGMA, "peratomtypepair 1 -inf").0,
        Err(format!(
            "fix b property/global {SIGMA} (atom types 1 and 1): '-inf' is not a finite number"
        ))
    );
}

#[test]
fn a_value_the_engine_cannot_read_is_named_with_its_types() {
    assert_eq!(
        line(SIGMA, "peratomtypepair 2 1e6 1e6 0x10 1e6").0,
        Err(format!(
            "fix b property/global {SIGMA} (atom types 2 and 1): '0x10' is not a number"
        ))
    );
}

#[test]
fn a_switch_without_a_value_or_given_twice_is_refused() {
    let switch = "contactUnderBond";
    assert_eq!(
        check_settings("pair_style gran", &[switch, "on", switch, "on"]),
        Ok(())
    );
    assert_eq!(
        check_settings("pair_style gran", &[switch, "on", switch, "off"]),
        Err(format!(
            "pair_style gran: switch {switch} is given twice, on and then off; give it once"
        ))
    );
    assert_eq!(
        check_settings("fix w all wall/gran", &["tangential_reduce", "on", switch]),
        Err(format!(
            "fix w all wall/gran: '{switch}' has no value at the end of the line (a switch takes on or off: {switch} on)"
        ))
    );
    // a value that is no switch's is the engine's parser's to refuse
    assert_eq!(
        check_settings("pair_style gran", &["model", "hertz", "x"]),
        Ok(())
    );
}
