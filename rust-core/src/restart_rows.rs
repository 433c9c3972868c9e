//! A parameter set in restart files as rows by keyword, so that a file
//! names what it sets: the number of rows, then each row's keyword length,
//! keyword and value (`i32`, bytes, `f64`, in the machine's byte order, as
//! an engine's restart writer puts them). A file that sets a keyword this
//! table does not have, or leaves out one it has, is refused with the
//! keywords named: it was written by a granbond with another table.

use crate::parameters::{set_by_name, ParameterInfo, SetError};

/// A keyword longer than this marks a damaged file (the tables' longest is
/// far shorter).
pub const MAX_KEYWORD: usize = 200;

/// More rows than this mark a damaged file.
pub const MAX_ROWS: usize = 10_000;

/// The rows of `params`, every row of `table` in its order.
pub fn write<T>(table: &[ParameterInfo<T>], params: &T) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend_from_slice(&(table.len() as i32).to_ne_bytes());
    for row in table {
        out.extend_from_slice(&(row.name.len() as i32).to_ne_bytes());
        out.extend_from_slice(row.name.as_bytes());
        out.extend_from_slice(&(row.get)(params).to_ne_bytes());
    }
    out
}

/// Reads the next `N` bytes of `rows` at `*at`.
fn take<const N: usize>(rows: &[u8], at: &mut usize) -> Option<[u8; N]> {
    let bytes = rows.get(*at..*at + N)?.try_into().ok()?;
    *at += N;
    Some(bytes)
}

/// The (keyword, value) rows of `rows` as [`write()`] wrote them, or what is
/// damaged.
pub fn parse(rows: &[u8]) -> Result<Vec<(String, f64)>, String> {
    let damaged = |what: String| format!("granbond: the restart file is damaged ({what})");
    let mut at = 0;
    let count = take::<4>(rows, &mut at)
        .map(i32::from_ne_bytes)
        .ok_or_else(|| damaged("no table".into()))?;
    if !(0..=MAX_ROWS as i32).contains(&count) {
        return Err(damaged(format!("a table of {count} parameters")));
    }
    (0..count)
        .map(|_| {
            let short = || damaged("a table cut short".into());
            let length = take::<4>(rows, &mut at)
                .map(i32::from_ne_bytes)
                .ok_or_else(short)?;
            if !(1..=MAX_KEYWORD as i32).contains(&length) {
                return Err(damaged(format!("a parameter name of {length} characters")));
            }
            let name = rows.get(at..at + length as usize).ok_or_else(short)?;
            at += length as usize;
            let value = take::<8>(rows, &mut at)
                .map(f64::from_ne_bytes)
                .ok_or_else(short)?;
            Ok((String::from_utf8_lossy(name).into_owned(), value))
        })
        .collect()
}

/// The parameters `rows` set over `T::default()`: every keyword of `table`
/// once, no other, each value in its row's range. `model` and `what` (the
/// type pair or bond type) name the table in the messages.
pub fn read<T: Default>(
    model: &str,
    table: &[ParameterInfo<T>],
    rows: &[u8],
    what: &str,
) -> Result<T, String> {
    let mut params = T::default();
    let mut seen = vec![false; table.len()];
    for (name, value) in parse(rows)? {
        let Some(id) = table.iter().position(|r| r.name == name) else {
            return Err(format!(
                "granbond: the restart file sets '{name}' for {what} ({model}), a keyword this granbond does not \
                 know; write the restart file again with this granbond"
            ));
        };
        seen[id] = true;
        match set_by_name(model, table, &mut params, &name, value) {
            Ok(_) => {}
            Err(SetError::Refused(e)) => {
                return Err(format!("granbond: the restart file's {what} ({model}): {e}"))
            }
            Err(SetError::Unknown(m)) => {
                return Err(format!("granbond: the restart file's {what} ({model}): {m}"))
            }
        }
    }
    let missing: Vec<&str> = table
        .iter()
        .zip(&seen)
        .filter(|(_, s)| !**s)
        .map(|(r, _)| r.name)
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "granbond: the restart file does not set {} for {what} ({model}), which this granbond reads; write the \
             restart file again with this granbond",
            missing.join(" ")
        ));
    }
    Ok(params)
}
