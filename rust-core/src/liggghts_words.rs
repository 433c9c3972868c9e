//! The granbond words of LIGGGHTS decks, checked before the engine's
//! parsers read them so that a bad one ends the run with a message naming
//! it: the switches of `pair_style gran` and `fix wall/gran` (the engine's
//! settings parser reads past the end of the line after a switch without a
//! value, and lets a repeated switch win silently), and the values of
//! granbond's `fix property/global` lines (the engine's reader names no
//! property).

use crate::bond::PARAMETERS;
use crate::coeff::c_read;
use crate::contact::VOIGT_PARAMETERS;
use crate::parameters::{LiggghtsSource, ParameterInfo, Range};

/// What a deck's `fix property/global` line must be for a granbond
/// property: its name, whether it is a per-type-pair matrix (else a
/// scalar), and whether `inf` is one of its values.
struct Property {
    name: &'static str,
    per_type_pair: bool,
    infinite: bool,
}

fn property_of<T>(table: &[ParameterInfo<T>], name: &str) -> Option<Property> {
    let row = table.iter().find(|r| r.liggghts_name == name)?;
    let per_type_pair = matches!(
        row.source,
        LiggghtsSource::PerTypePair | LiggghtsSource::OptionalPerTypePair
    );
    (per_type_pair || row.source == LiggghtsSource::Scalar).then_some(Property {
        name: row.liggghts_name,
        per_type_pair,
        infinite: row.range == Range::PositiveOrInfinite,
    })
}

/// Checks the words of `fix ID group property/global NAME ...` (`words`,
/// after `fix`) where NAME is a granbond property; `infinite[k]` set where
/// word k is an infinity, which the engine's reader takes only as `1e999`.
/// `Ok(false)`: not a granbond property, left to the engine.
pub fn check_property_line(words: &[&str], infinite: &mut [bool]) -> Result<bool, String> {
    let Some(row) = words
        .get(3)
        .and_then(|n| property_of(PARAMETERS, n).or_else(|| property_of(VOIGT_PARAMETERS, n)))
    else {
        return Ok(false);
    };
    let command = format!("fix {} property/global {}", words[0], row.name);
    let need = if row.per_type_pair {
        "peratomtypepair N followed by N*N values"
    } else {
        "scalar VALUE"
    };
    let Some(&style) = words.get(4) else {
        return Err(format!(
            "{command}: no style and values; write {} {need}",
            row.name
        ));
    };
    let pair_style = style == "peratomtypepair" || style == "atomtypepair";
    if row.per_type_pair != pair_style || (!row.per_type_pair && style != "scalar") {
        return Err(format!(
            "{command}: given as '{style}'; granbond reads {} only as {need}",
            row.name
        ));
    }
    let (mut first, mut n) = (5, 1usize);
    if row.per_type_pair {
        let given = words.get(5).copied().unwrap_or("");
        match c_read(given, true) {
            Some((v, _)) if (1.0..=32767.0).contains(&v) => n = v as usize,
            _ => {
                return Err(format!(
                    "{command}: peratomtypepair needs the number of atom types N (an integer >= 1), got '{given}'"
                ))
            }
        }
        first = 6;
    }
    // the engine's own options between N and the values are its to read
    while first + 1 < words.len() && (words[first] == "type" || words[first] == "warn_out_of_bounds") {
        first += 2;
    }
    let got = words.len().saturating_sub(first);
    if got != n * n {
        let want = if row.per_type_pair {
            format!("peratomtypepair {n} needs {} values", n * n)
        } else {
            "scalar needs one value".to_string()
        };
        return Err(format!("{command}: {want}, got {got}"));
    }
    for (k, word) in words.iter().enumerate().skip(first) {
        let at = k - first;
        let types = if row.per_type_pair {
            format!(" (atom types {} and {})", at / n + 1, at % n + 1)
        } else {
            String::new()
        };
        match c_read(word, false) {
            Some((v, _)) if v.is_infinite() => {
                if !row.infinite || v < 0.0 {
                    return Err(format!("{command}{types}: '{word}' is not a finite number"));
                }
                if let Some(flag) = infinite.get_mut(k) {
                    *flag = true;
                }
            }
            // a number, in the characters the engine's number reader takes
            Some(_) if word.chars().all(|c| "0123456789+-.eE".contains(c)) => {}
            _ => return Err(format!("{command}{types}: '{word}' is not a number")),
        }
    }
    Ok(true)
}

/// Checks the settings words of `command` (`pair_style gran ...`, `fix
/// wall/gran ...`): a name left without a value at the end of the line, or
/// a switch given twice with different values, is refused. Every setting of
/// the engine's parser is a name and one value; a value that is not a
/// switch's ends the check (the engine's parser refuses a wrong one itself,
/// naming the setting, before it reaches the end of the line).
pub fn check_settings(command: &str, words: &[&str]) -> Result<(), String> {
    let mut given: Vec<(&str, &str)> = Vec::new();
    for pair in words.chunks(2) {
        let &[name, value] = pair else {
            return Err(format!(
                "{command}: '{}' has no value at the end of the line (a switch takes on or off: {} on)",
                pair[0], pair[0]
            ));
        };
        if !matches!(value, "on" | "off" | "yes" | "no") {
            return Ok(());
        }
        if let Some((_, before)) = given.iter().find(|(n, v)| *n == name && *v != value) {
            return Err(format!(
                "{command}: switch {name} is given twice, {before} and then {value}; give it once"
            ));
        }
        given.push((name, value));
    }
    Ok(())
}
