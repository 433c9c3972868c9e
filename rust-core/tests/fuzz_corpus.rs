//! Replays the corpus of the C ABI fuzz target (`fuzz/corpus/abi/`, see
//! docs/fuzzing.md) through the same driver the fuzz target runs
//! (`tests/fuzz_driver`): every input that the fuzzer found, and every
//! input that once broke the ABI, must still be answered with OK or an
//! error code. `GRANBOND_FUZZ_CORPUS=<dir>` replays another directory
//! (scripts/fuzz.sh uses it for the summary of a run).

use granbond_test_support as common;
mod fuzz_driver;

use common::header::header_functions;
use fuzz_driver::{run, Tally, ENTRY_POINTS, STATUS_NAMES};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Entries that return no status (their answers are counted under OK).
const NO_STATUS: [&str; 14] = [
    "granbond_abi_version",
    "granbond_bond_keeps_contact_tangential",
    "granbond_bond_keeps_contact_loads",
    "granbond_bond_model_free",
    "granbond_bond_parameter_count",
    "granbond_bond_may_create",
    "granbond_bond_creates_at",
    "granbond_voigt_model_free",
    "granbond_voigt_parameter_count",
    "granbond_last_error_message",
    "granbond_last_error_parameter",
    "granbond_state_len",
    "granbond_bond_field_count",
    "granbond_bond_columns_free",
];

fn corpus_dir() -> PathBuf {
    match std::env::var_os("GRANBOND_FUZZ_CORPUS") {
        Some(dir) => PathBuf::from(dir),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/abi"),
    }
}

/// The corpus files, in name order.
fn corpus() -> Vec<(String, Vec<u8>)> {
    let dir = corpus_dir();
    let entries = std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("read {}: {e}", dir.display()));
    let mut files: Vec<(String, Vec<u8>)> = entries
        .flatten()
        .filter(|e| e.path().is_file())
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (name, std::fs::read(e.path()).expect("read a corpus file"))
        })
        .collect();
    files.sort();
    files
}

/// One replay of the whole corpus, shared by the tests: the inputs that
/// failed (name and message) and the answers of the others.
fn replay() -> &'static (Vec<String>, Tally) {
    static RESULT: OnceLock<(Vec<String>, Tally)> = OnceLock::new();
    RESULT.get_or_init(|| {
        let mut failures = Vec::new();
        let mut tally = Tally::default();
        for (name, data) in corpus() {
            let mut mine = Tally::default();
            match catch_unwind(AssertUnwindSafe(|| run(&data, &mut mine))) {
                Ok(()) => tally.merge(&mine),
                Err(panic) => {
                    let what = panic
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_default();
                    failures.push(format!("{name}: {what}"));
                }
            }
        }
        (failures, tally)
    })
}

#[test]
fn every_corpus_input_is_answered_with_ok_or_an_error_code() {
    let (failures, tally) = replay();
    println!("{tally}");
    assert!(
        tally.inputs + failures.len() as u64 > 0,
        "empty corpus in {}",
        corpus_dir().display()
    );
    assert!(
        failures.is_empty(),
        "{} corpus inputs broke the ABI's answers:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn the_corpus_reaches_every_entry_point_and_every_error_code() {
    let (_, tally) = replay();
    let missed: Vec<&str> = ENTRY_POINTS
        .iter()
        .copied()
        .filter(|f| !tally.answers.contains_key(f))
        .collect();
    assert!(missed.is_empty(), "the corpus never calls {missed:?}");
    // past the pointer checks: each entry that reports a status also succeeds
    let never_ok: Vec<&str> = ENTRY_POINTS
        .iter()
        .copied()
        .filter(|f| !NO_STATUS.contains(f) && tally.answers.get(f).is_some_and(|c| c[0] == 0))
        .collect();
    assert!(never_ok.is_empty(), "the corpus never gets OK from {never_ok:?}");
    let total = tally.by_status();
    let unseen: Vec<&str> = STATUS_NAMES
        .iter()
        .zip(total)
        .filter(|(name, c)| **name != "PANIC" && *c == 0)
        .map(|(name, _)| *name)
        .collect();
    assert!(unseen.is_empty(), "the corpus never gets the answers {unseen:?}");
}

#[test]
fn the_driver_calls_every_library_function_of_the_header() {
    // the header's static inline helper is compiled into the caller
    let library: Vec<String> = header_functions()
        .into_iter()
        .filter(|f| f != "granbond_header_layout")
        .collect();
    let missing: Vec<&String> = library
        .iter()
        .filter(|f| !ENTRY_POINTS.contains(&f.as_str()))
        .collect();
    let extra: Vec<&&str> = ENTRY_POINTS
        .iter()
        .filter(|f| !library.iter().any(|l| l == *f))
        .collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "tests/fuzz_driver ENTRY_POINTS is out of date: missing {missing:?}, not in the header {extra:?}"
    );
    assert!(
        library.len() >= 40,
        "found only {} functions in granbond.h",
        library.len()
    );
}
