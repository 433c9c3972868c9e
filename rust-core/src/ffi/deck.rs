//! `extern "C"` surface of what decks write beyond the parameter tables'
//! rows: the phrases of a LAMMPS `pair_coeff` clause that are more than a
//! row's keyword and one value (`break stress ...`, the values after
//! `voigt`), and the part of the Voigt contact each parameter belongs to
//! (LIGGGHTS composes the contact from one sub-model per part), so the
//! engines translate words to table rows without rules of their own.

use super::entry;
use super::error::{Failure, Status};
use super::guard::reference_mut;
use crate::bond::PHRASES;
use crate::contact::{ContactPart, VOIGT_PARTS, VOIGT_PHRASES};
use crate::parameters::Phrase;
use std::ffi::{c_char, CString};
use std::sync::OnceLock;

/// One phrase (strings in static storage).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct PhraseRow {
    /// The opening words, space-separated; "" for the values that follow
    /// the model's name.
    pub words: *const c_char,
    /// The phrase this one may only follow directly; "" for anywhere.
    pub follows: *const c_char,
    /// Keywords of the rows that take the phrase's values, space-separated,
    /// in the order a deck writes the values.
    pub reads: *const c_char,
    /// What the phrase itself sets after its values: keyword and value
    /// pairs, space-separated ("stress_break 1").
    pub sets: *const c_char,
}

// SAFETY: the rows point into `CString`s that live in a `static`; they are
// read-only after construction.
unsafe impl Send for PhraseRow {}
unsafe impl Sync for PhraseRow {}

type Rows = (Vec<[CString; 4]>, Vec<PhraseRow>);

fn rows(table: &[Phrase]) -> Rows {
    let c = |s: String| CString::new(s).expect("no NUL in a phrase");
    let strings: Vec<[CString; 4]> = table
        .iter()
        .map(|p| {
            let sets: Vec<String> = p.sets.iter().map(|(name, v)| format!("{name} {v}")).collect();
            [
                c(p.words.to_string()),
                c(p.follows.to_string()),
                c(p.reads.join(" ")),
                c(sets.join(" ")),
            ]
        })
        .collect();
    let rows = strings
        .iter()
        .map(|s| PhraseRow {
            words: s[0].as_ptr(),
            follows: s[1].as_ptr(),
            reads: s[2].as_ptr(),
            sets: s[3].as_ptr(),
        })
        .collect();
    (strings, rows)
}

fn write_row(rows: &[PhraseRow], id: usize, out: &mut PhraseRow) -> Result<(), Failure> {
    *out = *rows
        .get(id)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("phrase id {id} out of range")))?;
    Ok(())
}

/// Phrase `id` of the `bond/nonlinear` clause; `GB_STATUS_INVALID_ARGUMENT`
/// past the last one.
///
/// # Safety
/// `phrase` must be null or valid for writes.
#[entry(phrase: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_phrase_info(id: usize, phrase: *mut PhraseRow) -> Status {
    static ROWS: OnceLock<Rows> = OnceLock::new();
    write_row(&ROWS.get_or_init(|| rows(PHRASES)).1, id, phrase)
}

/// Phrase `id` of the `voigt` clause; `GB_STATUS_INVALID_ARGUMENT` past the
/// last one.
///
/// # Safety
/// `phrase` must be null or valid for writes.
#[entry(phrase: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_phrase_info(id: usize, phrase: *mut PhraseRow) -> Status {
    static ROWS: OnceLock<Rows> = OnceLock::new();
    write_row(&ROWS.get_or_init(|| rows(VOIGT_PHRASES)).1, id, phrase)
}

/// The part of the Voigt contact whose law reads parameter `id` (a row of
/// `granbond_voigt_parameter_info`).
///
/// # Safety
/// `part` must be null or valid for writes.
#[entry(part: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_parameter_part(id: usize, part: *mut ContactPart) -> Status {
    *part = VOIGT_PARTS
        .get(id)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("parameter id {id} out of range")))?
        .1;
    Ok(())
}
