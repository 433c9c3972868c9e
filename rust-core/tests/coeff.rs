//! LAMMPS's coefficient lines read by the core (`granbond::coeff`): the
//! words a deck writes become rows of the parameter tables, and every
//! refusal names the command, the clause and the word.

use granbond::bond::BondParams;
use granbond::coeff::{read_bond_coeff, read_pair_coeff};

const CONTACT: [&str; 6] = ["voigt", "1e5", "0.1", "2e4", "0", "0.5"];

fn pair(rest: &[&str]) -> Result<granbond::coeff::PairCoeff, String> {
    let words: Vec<&str> = CONTACT.iter().chain(rest).copied().collect();
    read_pair_coeff("pair_coeff 1 2", &words, "si")
}

#[test]
fn the_values_after_voigt_fill_its_rows_in_order_and_rolling_stays_off() {
    let read = pair(&[]).unwrap();
    assert_eq!(
        [
            read.voigt.k_n,
            read.voigt.gamma_n,
            read.voigt.k_t,
            read.voigt.gamma_t,
            read.voigt.mu
        ],
        [1e5, 0.1, 2e4, 0.0, 0.5]
    );
    assert_eq!(read.voigt.rolling, 0);
    assert!(!read.has_bond);
    assert_eq!(read.bond, BondParams::default_in_units("si"));
}

#[test]
fn a_phrase_sets_its_switches_after_its_values() {
    let read = pair(&[
        "rolling",
        "1",
        "0",
        "0.2",
        "0",
        "bond/nonlinear",
        "break",
        "stress",
        "1e6",
        "2e6",
    ])
    .unwrap();
    assert_eq!(read.voigt.rolling, 1);
    assert_eq!(read.voigt.mu_r, 0.2);
    assert!(read.has_bond);
    assert_eq!((read.bond.stress_break, read.bond.bpm_break), (1, 0));
    assert_eq!((read.bond.max_sigma, read.bond.max_tau), (1e6, 2e6));
}

#[test]
fn a_phrase_that_may_only_follow_another_is_unknown_elsewhere() {
    let after = pair(&["bond/nonlinear", "break", "stress", "1e6", "2e6", "ratio", "0.5"]).unwrap();
    assert_eq!(
        (after.bond.use_ratio, after.bond.tension_compression_ratio),
        (1, 0.5)
    );
    let alone = pair(&["bond/nonlinear", "ratio", "0.5"]).unwrap_err();
    assert!(
        alone.starts_with(
            "pair_coeff 1 2 bond/nonlinear: unknown keyword 'ratio' (known: break smooth_damping"
        ),
        "{alone}"
    );
}

#[test]
fn a_row_given_twice_with_different_values_is_refused_naming_both() {
    let e = pair(&["k_n", "2e5"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 voigt: 'k_n 2e5' conflicts with 'voigt' given before on this line (k_n set twice to \
         different values); give each keyword once"
    );
    // the same value twice says the same thing: no conflict
    assert!(pair(&["k_n", "1e5"]).is_ok());
}

#[test]
fn too_few_values_after_the_model_name_are_counted_and_named() {
    let e = read_pair_coeff("pair_coeff 1 1", &["voigt", "1e5", "0.1", "rolling"], "si").unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 1 voigt: voigt expects 5 numbers (k_n gamma_n k_t gamma_t mu), got 2 before 'rolling'"
    );
}

#[test]
fn a_value_out_of_range_is_named_as_the_deck_wrote_it() {
    let e = pair(&["bond/nonlinear", "k_fn1", "-3e4"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 bond/nonlinear: k_fn1 must be finite and >= 0, got -3e4"
    );
    let e = pair(&["bond/nonlinear", "damping", "maybe"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 bond/nonlinear: damping expects yes|no (or on|off), got 'maybe'"
    );
    let e = pair(&["bond/nonlinear", "k_fn1", "1e999"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 bond/nonlinear: k_fn1 expects a number, got '1e999'"
    );
}

#[test]
fn a_phrase_with_a_wrong_second_word_lists_the_choices() {
    let e = pair(&["bond/nonlinear", "break", "force", "1"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 bond/nonlinear: break expects distance or stress or bpm, got 'force'"
    );
    let e = pair(&["bond/nonlinear", "break"]).unwrap_err();
    assert_eq!(
        e,
        "pair_coeff 1 2 bond/nonlinear: missing break distance or stress or bpm"
    );
}

#[test]
fn an_unknown_word_after_the_contact_names_the_bond_clauses() {
    let e = pair(&["spring", "1"]).unwrap_err();
    assert!(
        e.starts_with("pair_coeff 1 2 voigt: unknown keyword 'spring' (known: rolling noattraction k_n"),
        "{e}"
    );
    assert!(e.ends_with(", then bond/nonlinear or bond/linear)"), "{e}");
    let e = read_pair_coeff("pair_coeff 1 2", &["hertz"], "si").unwrap_err();
    assert_eq!(e, "pair_coeff 1 2: unknown model 'hertz' (expected voigt)");
}

#[test]
fn contact_under_bond_follows_the_law_where_the_line_does_not_give_it() {
    let linear = pair(&["bond/linear"]).unwrap();
    assert_eq!((linear.bond.linear, linear.bond.contact_under_bond), (1, 1));
    let inl = pair(&["bond/nonlinear", "inl_compatible", "on"]).unwrap();
    assert_eq!(
        inl.bond.contact_under_bond, 1,
        "INL's code keeps the contact's tangential loads"
    );
    let plain = pair(&["bond/nonlinear"]).unwrap();
    assert_eq!(plain.bond.contact_under_bond, 0);
    let given = pair(&[
        "bond/nonlinear",
        "inl_compatible",
        "on",
        "contact_under_bond",
        "off",
    ])
    .unwrap();
    assert_eq!(given.bond.contact_under_bond, 0, "the deck's word stands");
}

#[test]
fn bond_coeff_refuses_the_rows_of_bonds_a_pair_style_forms() {
    let read = read_bond_coeff("bond_coeff 2", &["k_fn1", "3e4"]).unwrap();
    assert_eq!(read.k_fn1, 3e4);
    assert_eq!(read.smooth_velocity, BondParams::default().smooth_velocity);
    let e = read_bond_coeff("bond_coeff 2", &["create_step", "5"]).unwrap_err();
    assert!(
        e.starts_with("bond_coeff 2 bond/nonlinear: 'create_step' says when bonds form;"),
        "{e}"
    );
    let e = read_bond_coeff("bond_coeff 2", &["contact_under_bond", "on"]).unwrap_err();
    assert!(
        e.starts_with(
            "bond_coeff 2 bond/nonlinear: 'contact_under_bond on' says what pair_style granbond's contact"
        ),
        "{e}"
    );
}
