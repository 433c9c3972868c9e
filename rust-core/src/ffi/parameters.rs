//! `extern "C"` surface of the parameter tables: what each row is, and
//! setting a parameter by the name a deck uses. Adapters iterate these, so
//! a parameter added to a table reaches both engines' decks.

use super::entry;
use super::error::{Failure, Status};
use super::guard::{reference, reference_mut, slice, slice_mut};
use crate::bond::{liggghts_name, BondParams, CREATION_ROWS, PAIR_BOND_ROWS, PARAMETERS};
use crate::contact::{VoigtParams, VOIGT_PARAMETERS};
use crate::parameters::{set_by_name, ParameterInfo, SetError};
pub use crate::parameters::{LiggghtsSource, ParameterKind};
use crate::restart_rows;
use std::ffi::{c_char, CStr, CString};
use std::sync::OnceLock;

/// One row of a parameter table (strings in static storage).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ParameterRow {
    /// The LAMMPS keyword (the field name of the parameter struct).
    pub keyword: *const c_char,
    /// The LIGGGHTS property or switch name.
    pub liggghts_name: *const c_char,
    /// How a deck writes the value.
    pub kind: ParameterKind,
    /// Where a LIGGGHTS deck gives the value.
    pub liggghts_source: LiggghtsSource,
    /// SI unit, "-" when dimensionless.
    pub unit: *const c_char,
    /// The allowed values, in words.
    pub range: *const c_char,
    /// When the model reads it, in words (see `granbond_*_parameter_needed`).
    pub needed_when: *const c_char,
    /// The value a deck that does not set it gets.
    pub default_value: f64,
}

/// The C strings of a table's rows, built once per table.
struct RowStrings([CString; 5]);

// SAFETY: the rows point into `RowStrings` that live in a `static`; they
// are read-only after construction.
unsafe impl Send for ParameterRow {}
unsafe impl Sync for ParameterRow {}

fn rows<T: Default>(table: &[ParameterInfo<T>]) -> (Vec<RowStrings>, Vec<ParameterRow>) {
    let c = |s: &str| CString::new(s).expect("no NUL in a parameter table");
    let strings: Vec<RowStrings> = table
        .iter()
        .map(|p| {
            RowStrings([
                c(p.name),
                c(p.liggghts_name),
                c(p.unit),
                c(p.range.describe()),
                c(p.need.when),
            ])
        })
        .collect();
    let rows = table
        .iter()
        .zip(&strings)
        .map(|(p, s)| ParameterRow {
            keyword: s.0[0].as_ptr(),
            liggghts_name: s.0[1].as_ptr(),
            kind: p.kind(),
            liggghts_source: p.source,
            unit: s.0[2].as_ptr(),
            range: s.0[3].as_ptr(),
            needed_when: s.0[4].as_ptr(),
            default_value: p.default_value(),
        })
        .collect();
    (strings, rows)
}

type Rows = (Vec<RowStrings>, Vec<ParameterRow>);

pub(super) fn bond_rows() -> &'static [ParameterRow] {
    static ROWS: OnceLock<Rows> = OnceLock::new();
    &ROWS.get_or_init(|| rows(PARAMETERS)).1
}

pub(super) fn voigt_rows() -> &'static [ParameterRow] {
    static ROWS: OnceLock<Rows> = OnceLock::new();
    &ROWS.get_or_init(|| rows(VOIGT_PARAMETERS)).1
}

/// Row `id`, or the error of every entry that takes a row id.
fn row_at<R>(rows: &[R], id: usize) -> Result<&R, Failure> {
    rows.get(id)
        .ok_or_else(|| Failure::new(Status::InvalidArgument, format!("parameter id {id} out of range")))
}

fn write_row(rows: &[ParameterRow], id: usize, out: &mut ParameterRow) -> Result<(), Failure> {
    *out = *row_at(rows, id)?;
    Ok(())
}

unsafe fn set<T>(
    model: &str,
    table: &[ParameterInfo<T>],
    params: &mut T,
    name: &c_char,
    value: f64,
) -> Result<(), Failure> {
    let name = CStr::from_ptr(name)
        .to_str()
        .map_err(|_| Failure::new(Status::InvalidArgument, "parameter name is not UTF-8"))?;
    match set_by_name(model, table, params, name, value) {
        Ok(_) => Ok(()),
        Err(SetError::Unknown(message)) => Err(Failure::new(Status::InvalidArgument, message)),
        Err(SetError::Refused(e)) => Err(e.into()),
    }
}

fn needed_by<T>(table: &[ParameterInfo<T>], params: &T, id: usize, out: &mut i32) -> Result<(), Failure> {
    *out = row_at(table, id)?.needed(params) as i32;
    Ok(())
}

/// The LIGGGHTS names of the bond table's rows for each law, as C strings
/// (`None` where the law does not have the row).
fn law_names(linear: bool) -> &'static [Option<CString>] {
    static NAMES: OnceLock<[Vec<Option<CString>>; 2]> = OnceLock::new();
    let names = NAMES.get_or_init(|| {
        [false, true].map(|law| {
            (0..PARAMETERS.len())
                .map(|id| {
                    liggghts_name(law, id).map(|n| CString::new(n).expect("no NUL in a parameter name"))
                })
                .collect()
        })
    });
    &names[linear as usize]
}

/// Row `id` of the bond parameter table (`id < granbond_bond_parameter_count()`).
///
/// # Safety
/// `info` must be null or valid for writes.
#[entry(info: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_parameter_info(id: usize, info: *mut ParameterRow) -> Status {
    write_row(bond_rows(), id, info)
}

/// Row `id` of the Voigt parameter table.
///
/// # Safety
/// `info` must be null or valid for writes.
#[entry(info: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_parameter_info(id: usize, info: *mut ParameterRow) -> Status {
    write_row(voigt_rows(), id, info)
}

/// The name a LIGGGHTS deck gives row `id` of the bond table under the
/// law `linear` (0: `cohesion bond/nonlinear`, 1: LIGGGHTS-INL's linear
/// bond, `cohesion bond`), written to `name` (static storage); null when
/// that law does not have the row, so its decks cannot set it.
///
/// # Safety
/// `name` must be null or valid for writes.
#[entry(name: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_parameter_liggghts_name(
    linear: i32,
    id: usize,
    name: *mut *const c_char,
) -> Status {
    row_at(PARAMETERS, id)?;
    if linear != 0 && linear != 1 {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("linear must be 0 (bond/nonlinear) or 1 (the linear bond); got {linear}"),
        ));
    }
    *name = law_names(linear == 1)[id]
        .as_ref()
        .map_or(std::ptr::null(), |n| n.as_ptr());
    Ok(())
}

/// Sets the bond parameter a deck names (LAMMPS keyword or LIGGGHTS name)
/// to `value` (switches 1 or 0, steps as exact doubles). An unknown name
/// gives `GB_STATUS_INVALID_ARGUMENT` with the known keywords in the
/// message; a value out of range `GB_STATUS_INVALID_PARAMETER` naming the
/// parameter, as `granbond_bond_model_new` does.
///
/// # Safety
/// `params` must be null or point to a `GbBondParams`; `name` null or a
/// NUL-terminated string.
#[entry(params: reference_mut, name: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_set(
    params: *mut BondParams,
    name: *const c_char,
    value: f64,
) -> Status {
    set("bond/nonlinear", PARAMETERS, params, name, value)
}

/// `granbond_bond_params_set` for the Voigt contact.
///
/// # Safety
/// As `granbond_bond_params_set`, with a `GbVoigtParams`.
#[entry(params: reference_mut, name: reference)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_set(
    params: *mut VoigtParams,
    name: *const c_char,
    value: f64,
) -> Status {
    set("voigt", VOIGT_PARAMETERS, params, name, value)
}

/// The value of parameter `id` of the bond table in `params` (switches 1 or
/// 0, steps as exact doubles), written to `value`: with the table's
/// keywords, what an engine writes to a restart file by name.
///
/// # Safety
/// `params` must be null or point to a `GbBondParams`; `value` null or
/// valid for writes.
#[entry(params: reference, value: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_get(
    params: *const BondParams,
    id: usize,
    value: *mut f64,
) -> Status {
    *value = (row_at(PARAMETERS, id)?.get)(params);
    Ok(())
}

/// `granbond_bond_params_get` for the Voigt contact.
///
/// # Safety
/// As `granbond_bond_params_get`, with a `GbVoigtParams`.
#[entry(params: reference, value: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_get(
    params: *const VoigtParams,
    id: usize,
    value: *mut f64,
) -> Status {
    *value = (row_at(VOIGT_PARAMETERS, id)?.get)(params);
    Ok(())
}

/// Whether a bond model with the switches of `params` reads parameter `id`
/// (1) or ignores it (0): engines that ask the deck for every value ask only
/// for these.
///
/// # Safety
/// `params` must be null or point to a `GbBondParams`; `needed` null or
/// valid for writes.
#[entry(params: reference, needed: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_parameter_needed(
    params: *const BondParams,
    id: usize,
    needed: *mut i32,
) -> Status {
    row_at(PARAMETERS, id)?;
    *needed = params.reads(id) as i32;
    Ok(())
}

/// `granbond_bond_parameter_needed` for the Voigt contact.
///
/// # Safety
/// As `granbond_bond_parameter_needed`, with a `GbVoigtParams`.
#[entry(params: reference, needed: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_parameter_needed(
    params: *const VoigtParams,
    id: usize,
    needed: *mut i32,
) -> Status {
    needed_by(VOIGT_PARAMETERS, params, id, needed)
}

/// Whether row `id` of the bond table belongs to bonds a pair style forms
/// between touching spheres: 1 a row that says when bonds form, 2 one that
/// says what the contact does under the bond (`contact_under_bond`), 0
/// neither. A deck whose bonds come from an engine's topology gives none of
/// those rows. -1 for an `id` beyond the table.
#[entry(or = -1)]
#[no_mangle]
pub extern "C" fn granbond_bond_parameter_sets_creation(id: usize) -> i32 {
    match PARAMETERS.get(id) {
        Some(row) if CREATION_ROWS.contains(&row.name) => 1,
        Some(row) if PAIR_BOND_ROWS.contains(&row.name) => 2,
        Some(_) => 0,
        None => -1,
    }
}

/// The most rows a restart file's table may hold; a reader stops there (the
/// file is damaged) rather than read on.
pub const GRANBOND_RESTART_MAX_ROWS: usize = 10_000;

/// The longest keyword a restart file's row may hold.
pub const GRANBOND_RESTART_MAX_KEYWORD: usize = 200;

const _: () = assert!(
    GRANBOND_RESTART_MAX_ROWS == restart_rows::MAX_ROWS
        && GRANBOND_RESTART_MAX_KEYWORD == restart_rows::MAX_KEYWORD
);

/// `rows` into `buf` when it holds them, their length to `len` either way.
fn rows_out(rows: Vec<u8>, buf: &mut [u8], len: &mut usize) -> Result<(), Failure> {
    *len = rows.len();
    if buf.is_empty() {
        return Ok(());
    }
    let capacity = buf.len();
    buf.get_mut(..rows.len())
        .ok_or_else(|| {
            Failure::new(
                Status::InvalidArgument,
                format!(
                    "capacity {capacity} is less than the {} bytes of the rows",
                    rows.len()
                ),
            )
        })?
        .copy_from_slice(&rows);
    Ok(())
}

/// Reads restart rows with `read`, naming `what` (NUL-terminated).
unsafe fn rows_in<T>(
    read: impl FnOnce(&str) -> Result<T, String>,
    what: &c_char,
    params: &mut T,
) -> Result<(), Failure> {
    let what = CStr::from_ptr(what).to_string_lossy();
    *params = read(&what).map_err(|m| Failure::new(Status::InvalidArgument, m))?;
    Ok(())
}

/// The bond parameters `params` as a restart file's rows by keyword
/// (`restart_rows`: the row count, then each row's keyword length, keyword
/// and value, `int32_t`, bytes and `double` in the machine's byte order),
/// written to `buf` when `capacity` holds them; their length in bytes to
/// `len` either way (a `capacity` of 0 asks the length alone).
///
/// # Safety
/// `params` null or a `GbBondParams`; `buf` null or `capacity` writable
/// bytes; `len` null or valid for writes.
#[entry(params: reference, buf: slice_mut(capacity), len: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_rows(
    params: *const BondParams,
    buf: *mut u8,
    capacity: usize,
    len: *mut usize,
) -> Status {
    rows_out(restart_rows::write(PARAMETERS, params), buf, len)
}

/// `granbond_bond_params_rows` for the Voigt contact.
///
/// # Safety
/// As `granbond_bond_params_rows`, with a `GbVoigtParams`.
#[entry(params: reference, buf: slice_mut(capacity), len: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_rows(
    params: *const VoigtParams,
    buf: *mut u8,
    capacity: usize,
    len: *mut usize,
) -> Status {
    rows_out(restart_rows::write(VOIGT_PARAMETERS, params), buf, len)
}

/// The bond parameters a restart file's rows (`len` bytes at `rows`, as
/// `granbond_bond_params_rows` wrote them) set, into `params`. Every
/// keyword of the table once and no other, each value in its range: a
/// file of another table is `GB_STATUS_INVALID_ARGUMENT`, its message
/// naming the keywords, `what` (the type pair or bond type) and what to do.
///
/// # Safety
/// `rows` null or `len` readable bytes; `what` null or a NUL-terminated
/// string; `params` null or valid for writes.
#[entry(rows: slice(len), what: reference, params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_params_from_rows(
    rows: *const u8,
    len: usize,
    what: *const c_char,
    params: *mut BondParams,
) -> Status {
    rows_in(
        |w| restart_rows::read("bond/nonlinear", PARAMETERS, rows, w),
        what,
        params,
    )
}

/// `granbond_bond_params_from_rows` for the Voigt contact.
///
/// # Safety
/// As `granbond_bond_params_from_rows`, with a `GbVoigtParams`.
#[entry(rows: slice(len), what: reference, params: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_voigt_params_from_rows(
    rows: *const u8,
    len: usize,
    what: *const c_char,
    params: *mut VoigtParams,
) -> Status {
    rows_in(
        |w| restart_rows::read("voigt", VOIGT_PARAMETERS, rows, w),
        what,
        params,
    )
}
