//! `extern "C"` surface of what decks write beyond the parameter tables'
//! rows: the phrases of a LAMMPS `pair_coeff` clause that are more than a
//! row's keyword and one value (`break stress ...`, the values after
//! `voigt`), and the part of the Voigt contact each parameter belongs to
//! (LIGGGHTS composes the contact from one sub-model per part), so the
//! engines translate words to table rows without rules of their own; and
//! LAMMPS's `pair_coeff` and `bond_coeff` lines read whole (`coeff`), and
//! LIGGGHTS's settings and property lines checked (`liggghts_words`).

use super::entry;
use super::error::{Failure, Status};
use super::guard::{reference, reference_mut, slice, slice_mut};
use crate::bond::{BondParams, PHRASES};
use crate::coeff;
use crate::contact::{ContactPart, VoigtParams, VOIGT_PARTS, VOIGT_PHRASES, VOIGT_SUB_MODELS};
use crate::liggghts_words;
use crate::parameters::Phrase;
use std::ffi::{c_char, CStr, CString};
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

/// A voigt sub-model of LIGGGHTS (strings in static storage).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct SubModelRow {
    /// The words of `pair_style gran` and `fix wall/gran` that name it
    /// ("tangential voigt"), as messages name it.
    pub words: *const c_char,
    /// The parts whose rows it reads from the deck, as bits `1 << part`.
    pub reads: u32,
}

// SAFETY: `words` points into `CString`s that live in a `static`.
unsafe impl Send for SubModelRow {}
unsafe impl Sync for SubModelRow {}

/// The voigt sub-model of LIGGGHTS that computes part `part` (a
/// `GbContactPart`): what a deck calls it and which parts of the Voigt table
/// it reads. `GB_STATUS_INVALID_ARGUMENT` past the last part.
///
/// # Safety
/// `row` must be null or valid for writes.
#[entry(row: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_sub_model(part: usize, row: *mut SubModelRow) -> Status {
    static WORDS: OnceLock<Vec<CString>> = OnceLock::new();
    let words = WORDS.get_or_init(|| {
        VOIGT_SUB_MODELS
            .iter()
            .map(|s| CString::new(s.words).expect("no NUL in a sub-model's words"))
            .collect()
    });
    let sub = VOIGT_SUB_MODELS
        .get(part)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("part {part} out of range")))?;
    *row = SubModelRow {
        words: words[part].as_ptr(),
        reads: sub.reads.iter().fold(0, |bits, p| bits | 1 << *p as u32),
    };
    Ok(())
}

/// A C string argument as UTF-8; `what` names it in the error.
///
/// # Safety
/// `s` must point to a NUL-terminated string.
pub(super) unsafe fn text<'a>(s: *const c_char, what: &str) -> Result<&'a str, Failure> {
    if s.is_null() {
        return Err(Failure::new(Status::NullPointer, format!("{what} is null")));
    }
    CStr::from_ptr(s)
        .to_str()
        .map_err(|_| Failure::new(Status::InvalidArgument, format!("{what} is not UTF-8")))
}

/// The words of a command, as `coeff` reads them.
///
/// # Safety
/// Each pointer of `words` must be null or a NUL-terminated string.
pub(super) unsafe fn word_list<'a>(words: &[*const c_char]) -> Result<Vec<&'a str>, Failure> {
    words
        .iter()
        .enumerate()
        .map(|(k, &w)| text(w, &format!("word {k}")))
        .collect()
}

/// Reads the words of a `pair_coeff` line of `pair_style granbond` after
/// its type pair (`count` words: `voigt <values> [keyword ...]
/// [bond/nonlinear | bond/linear keyword ...]`) into `voigt` and `bond`;
/// `has_bond` 1 where the line has a bond clause (else `bond` holds the
/// bond law's defaults in `units`, the engine's units style). Where the
/// line does not give `contact_under_bond`, it follows the bond's law.
/// A line that does not read is `GB_STATUS_INVALID_ARGUMENT`, the message
/// naming `command` (the command as the deck wrote it, "pair_coeff 1 2"),
/// the clause and the word.
///
/// # Safety
/// `command` and `units` must be null or NUL-terminated strings; `words`
/// null or `count` pointers, each null or a NUL-terminated string; `voigt`,
/// `bond` and `has_bond` null or valid for writes.
#[entry(command: reference, words: slice(count), units: reference, voigt: reference_mut, bond: reference_mut, has_bond: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_pair_coeff_read(
    command: *const c_char,
    words: *const *const c_char,
    count: usize,
    units: *const c_char,
    voigt: *mut VoigtParams,
    bond: *mut BondParams,
    has_bond: *mut i32,
) -> Status {
    let line = word_list(words)?;
    let read = coeff::read_pair_coeff(text(command, "command")?, &line, text(units, "units")?)
        .map_err(|message| Failure::new(Status::InvalidArgument, message))?;
    *voigt = read.voigt;
    *bond = read.bond;
    *has_bond = i32::from(read.has_bond);
    Ok(())
}

/// Reads the words of a `bond_coeff` line of `bond_style granbond` after
/// its bond type (`count` words, the bond/nonlinear keywords) into `bond`,
/// from the defaults. The rows of bonds a pair style forms (when bonds
/// form, the contact under them) are refused: the topology names these
/// bonds. Errors as `granbond_pair_coeff_read`'s ("bond_coeff 1").
///
/// # Safety
/// As `granbond_pair_coeff_read`.
#[entry(command: reference, words: slice(count), bond: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_coeff_read(
    command: *const c_char,
    words: *const *const c_char,
    count: usize,
    bond: *mut BondParams,
) -> Status {
    let line = word_list(words)?;
    *bond = coeff::read_bond_coeff(text(command, "command")?, &line)
        .map_err(|message| Failure::new(Status::InvalidArgument, message))?;
    Ok(())
}

/// Checks a LIGGGHTS `fix ID group property/global NAME ...` line (`count`
/// words after `fix`) where NAME is a granbond property: its style, its
/// number of atom types and its values, each refusal
/// (`GB_STATUS_INVALID_ARGUMENT`) naming the fix, the property and the
/// word. `ours` 1 for a granbond property, 0 for a line left to the engine;
/// `infinite[k]` 1 where word k is an infinity the property takes, which
/// the engine's number reader takes only as `1e999`, else 0.
///
/// # Safety
/// `words` null or `count` pointers, each null or a NUL-terminated string;
/// `infinite` null or `count` writable `int32_t`; `ours` null or valid for
/// writes.
#[entry(words: slice(count), infinite: slice_mut(count), ours: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_liggghts_property_line_check(
    words: *const *const c_char,
    count: usize,
    infinite: *mut i32,
    ours: *mut i32,
) -> Status {
    let line = word_list(words)?;
    let mut flags = vec![false; line.len()];
    let checked = liggghts_words::check_property_line(&line, &mut flags)
        .map_err(|message| Failure::new(Status::InvalidArgument, message))?;
    for (out, flag) in infinite.iter_mut().zip(flags) {
        *out = i32::from(flag);
    }
    *ours = i32::from(checked);
    Ok(())
}

/// Checks the settings words (`count` words) of a LIGGGHTS `command`
/// (`pair_style gran`, `fix ID group wall/gran`): a name left without a
/// value at the end of the line, or a switch given twice with different
/// values, is `GB_STATUS_INVALID_ARGUMENT`, the message naming `command`
/// and the word.
///
/// # Safety
/// `command` null or a NUL-terminated string; `words` as in
/// `granbond_liggghts_property_line_check`.
#[entry(command: reference, words: slice(count))]
#[no_mangle]
pub unsafe extern "C" fn granbond_liggghts_settings_check(
    command: *const c_char,
    words: *const *const c_char,
    count: usize,
) -> Status {
    let line = word_list(words)?;
    liggghts_words::check_settings(text(command, "command")?, &line)
        .map_err(|message| Failure::new(Status::InvalidArgument, message))
}
