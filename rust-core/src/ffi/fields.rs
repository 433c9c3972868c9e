//! `extern "C"` surface of a bond's named output fields
//! (`crate::bond::fields`): the table engines build their keywords and
//! columns from, and the fields of one bond.

use super::entry;
use super::error::{Failure, Status};
use super::guard::{finite, finite_vector3, reference, reference_mut, slice, slice_mut};
use crate::bond::fields::{
    bond_fields, BondField, BOND_ENERGY_FIELDS, BOND_ENERGY_FIELD_COUNT, BOND_FIELDS, BOND_FIELD_COUNT,
};
use crate::bond::output_slots::BOND_OUTPUT_LEN;
use crate::bond::{BondModel, BondState, BOND_STATE_LEN};
use std::ffi::{c_char, CString};
use std::sync::OnceLock;

/// The name, unit and description of every field of `table`, as C strings.
fn strings_of(table: &[BondField]) -> Vec<[CString; 3]> {
    let c = |s: &str| CString::new(s).expect("no NUL in the field table");
    table
        .iter()
        .map(|f| [c(f.name), c(f.unit), c(f.description)])
        .collect()
}

/// The name, unit and description of every field, as C strings.
fn c_strings() -> &'static [[CString; 3]] {
    static TABLE: OnceLock<Vec<[CString; 3]>> = OnceLock::new();
    TABLE.get_or_init(|| strings_of(&BOND_FIELDS))
}

/// The same for the energy fields.
fn energy_strings() -> &'static [[CString; 3]] {
    static TABLE: OnceLock<Vec<[CString; 3]>> = OnceLock::new();
    TABLE.get_or_init(|| strings_of(&BOND_ENERGY_FIELDS))
}

/// Writes row `id` of `rows` (`what` names the table in the error).
fn write_info(
    rows: &'static [[CString; 3]],
    what: &str,
    id: usize,
    name: &mut *const c_char,
    unit: &mut *const c_char,
    description: &mut *const c_char,
) -> Result<(), Failure> {
    let row = rows.get(id).ok_or_else(|| {
        Failure::new(
            Status::InvalidArgument,
            format!("{what} id {id} out of range (there are {} fields)", rows.len()),
        )
    })?;
    *name = row[0].as_ptr();
    *unit = row[1].as_ptr();
    *description = row[2].as_ptr();
    Ok(())
}

/// Number of a bond's energy fields: those the bond store gives
/// (`granbond_bond_store_bond_energy` writes this many doubles).
#[entry(or = 0)]
#[no_mangle]
pub extern "C" fn granbond_bond_energy_field_count() -> usize {
    BOND_ENERGY_FIELD_COUNT
}

/// Name (the engines' keyword), SI unit and description of energy field
/// `id` (`id < granbond_bond_energy_field_count()`), in static storage.
///
/// # Safety
/// `name`, `unit` and `description` must be null or valid for writes.
#[entry(name: reference_mut, unit: reference_mut, description: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_energy_field_info(
    id: usize,
    name: *mut *const c_char,
    unit: *mut *const c_char,
    description: *mut *const c_char,
) -> Status {
    write_info(energy_strings(), "energy field", id, name, unit, description)
}

/// Number of a bond's output fields (`granbond_bond_fields` writes this
/// many doubles).
#[entry(or = 0)]
#[no_mangle]
pub extern "C" fn granbond_bond_field_count() -> usize {
    BOND_FIELD_COUNT
}

/// Name (the engines' keyword), SI unit ("-" when dimensionless) and
/// description of field `id` (`id < granbond_bond_field_count()`), in
/// static storage.
///
/// # Safety
/// `name`, `unit` and `description` must be null or valid for writes.
#[entry(name: reference_mut, unit: reference_mut, description: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_field_info(
    id: usize,
    name: *mut *const c_char,
    unit: *mut *const c_char,
    description: *mut *const c_char,
) -> Status {
    write_info(c_strings(), "field", id, name, unit, description)
}

/// The fields of a bond of `model` from its `record` (the state, then the
/// loads of its latest force pass) and the centres of its spheres, refused
/// as `granbond_bond_fields` says.
pub(super) fn record_fields(
    model: &BondModel,
    record: &[f64],
    x_i: [f64; 3],
    x_j: [f64; 3],
) -> Result<[f64; BOND_FIELD_COUNT], Failure> {
    if x_i == x_j {
        return Err(Failure::new(
            Status::InvalidArgument,
            format!("x_i and x_j coincide ({x_i:?}): a bond's spheres are apart"),
        ));
    }
    let state: &[f64; BOND_STATE_LEN] = record[..BOND_STATE_LEN]
        .try_into()
        .expect("the bond part has BOND_STATE_LEN slots");
    // SAFETY: BondState is repr(C) of exactly BOND_STATE_LEN f64.
    let state = unsafe { &*(state as *const [f64; BOND_STATE_LEN] as *const BondState) };
    let loads: &[f64; BOND_OUTPUT_LEN] = record[BOND_STATE_LEN..]
        .try_into()
        .expect("the loads part has BOND_OUTPUT_LEN slots");
    let read = state.as_slots().iter().chain(loads.iter());
    if let Some(v) = read.copied().find(|v| !v.is_finite()) {
        return Err(Failure::new(
            Status::NonFiniteInput,
            format!("`record` holds {v} in its bond state or loads"),
        ));
    }
    let fields = bond_fields(model, state, loads, x_i, x_j);
    // centres so close or so far apart that their distance under- or
    // overflows; a strength of inf is the documented "never"
    let never =
        |k: usize| fields[k] == f64::INFINITY && matches!(BOND_FIELDS[k].name, "sigma_max" | "tau_max");
    if let Some(k) = (0..fields.len()).find(|&k| !fields[k].is_finite() && !never(k)) {
        return Err(Failure::new(
            Status::NonFiniteResult,
            format!(
                "field {} is {} for centres x_i {x_i:?}, x_j {x_j:?}: their distance is out of range",
                BOND_FIELDS[k].name, fields[k]
            ),
        ));
    }
    Ok(fields)
}

/// The fields of one bond of `model`, written to `values`
/// (`double[granbond_bond_field_count()]`, in the table's order): its
/// `record` as sphere `i` sees it (its state, `GRANBOND_BOND_STATE_LEN`
/// doubles, then the output of its latest force pass as
/// `granbond_bond_output_store` writes it, `GRANBOND_BOND_OUTPUT_LEN`
/// doubles), and the centres `x_i`, `x_j` (`double[3]` each) of the two
/// spheres. Refused, `values` left alone: non-finite centres or a record
/// whose bond state or loads hold a non-finite number
/// (`GB_STATUS_NON_FINITE_INPUT`), coincident centres
/// (`GB_STATUS_INVALID_ARGUMENT`), each naming the argument, and fields
/// that come out non-finite (centres whose distance under- or overflows:
/// `GB_STATUS_NON_FINITE_RESULT`, naming the field). A strength of `inf`
/// (never breaks) is written as it is.
///
/// # Safety
/// `model` must be null or a model; `record` null or valid for
/// `GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN` doubles; `x_i`, `x_j` null or three doubles; `values` null or
/// valid for the field count.
#[entry(model: reference, x_i: finite_vector3, x_j: finite_vector3)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_fields(
    model: *const BondModel,
    record: *const f64,
    x_i: *const f64,
    x_j: *const f64,
    values: *mut f64,
) -> Status {
    let record = slice(record, BOND_STATE_LEN + BOND_OUTPUT_LEN, "record")?;
    let values = slice_mut(values, BOND_FIELD_COUNT, "values")?;
    let fields = record_fields(model, record, x_i, x_j)?;
    values.copy_from_slice(&fields);
    Ok(())
}

/// The limits a bond of `model` at compression `delta` (`r0 - r`, negative
/// when stretched) holds its section stresses against, written to
/// `sigma_max` and `tau_max`: `sigma_max` times `gamma` while stretched
/// with the tension/compression ratio; both 0 in distance mode, which has
/// no stress limits. For engines' logs of broken bonds.
///
/// # Safety
/// `model` must be null or a model; `sigma_max` and `tau_max` null or
/// valid for writes.
#[entry(model: reference, delta: finite, sigma_max: reference_mut, tau_max: reference_mut)]
#[no_mangle]
pub unsafe extern "C" fn granbond_bond_stress_limits(
    model: *const BondModel,
    delta: f64,
    sigma_max: *mut f64,
    tau_max: *mut f64,
) -> Status {
    (*sigma_max, *tau_max) = model.stress_limits_at(delta);
    Ok(())
}
