//! Parameter tables: one row per field of a `#[repr(C)]` parameter struct,
//! with its names in the decks and its allowed range. Validation walks the
//! table, so a new field cannot be left unchecked without a row.

/// What values a parameter accepts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Range {
    /// Finite and > 0.
    Positive,
    /// Finite and >= 0.
    NonNegative,
    /// > 0, `inf` allowed (means "never").
    PositiveOrInfinite,
    /// 0 <= x < 1.
    Fraction,
    /// 0 or 1.
    Switch,
    /// Any integer.
    Step,
}

impl Range {
    pub fn describe(self) -> &'static str {
        match self {
            Range::Positive => "finite and > 0",
            Range::NonNegative => "finite and >= 0",
            Range::PositiveOrInfinite => "> 0 (inf for never)",
            Range::Fraction => "in [0, 1)",
            Range::Switch => "0 (off) or 1 (on)",
            Range::Step => "an integer",
        }
    }

    pub fn admits(self, x: f64) -> bool {
        match self {
            Range::Positive => x.is_finite() && x > 0.0,
            Range::NonNegative => x.is_finite() && x >= 0.0,
            Range::PositiveOrInfinite => x > 0.0 && !x.is_nan(),
            Range::Fraction => (0.0..1.0).contains(&x),
            Range::Switch => x == 0.0 || x == 1.0,
            Range::Step => true,
        }
    }
}

/// One row of a parameter table.
pub struct ParameterInfo<T> {
    /// Field name = LAMMPS keyword.
    pub name: &'static str,
    /// The name LIGGGHTS decks use (`fix property/global` or switch).
    pub liggghts_name: &'static str,
    pub range: Range,
    pub get: fn(&T) -> f64,
}

/// A refused parameter: its id (row of the model's table) and a message
/// naming it, the allowed range and the value given.
#[derive(Clone, Debug, PartialEq)]
pub struct ParameterError {
    pub parameter: usize,
    pub message: String,
}

/// Builds the error for row `name` of `table`.
pub fn refuse<T>(
    model: &str,
    table: &[ParameterInfo<T>],
    name: &str,
    requirement: &str,
    value: f64,
) -> ParameterError {
    let id = table
        .iter()
        .position(|p| p.name == name)
        .expect("the parameter table names every field");
    let info = &table[id];
    ParameterError {
        parameter: id,
        message: format!(
            "{} parameter {} ({}) must be {}; got {}",
            model, info.name, info.liggghts_name, requirement, value
        ),
    }
}

/// Checks every row's range.
pub fn check_ranges<T>(model: &str, table: &[ParameterInfo<T>], params: &T) -> Result<(), ParameterError> {
    for info in table {
        let x = (info.get)(params);
        if !info.range.admits(x) {
            return Err(refuse(model, table, info.name, info.range.describe(), x));
        }
    }
    Ok(())
}

/// `parameter_table!(NAME: Type { field, "liggghts name", Range; ... })`
/// defines the table `NAME` for the struct `Type`.
#[macro_export]
macro_rules! parameter_table {
    ($table:ident : $ty:ty { $( $field:ident, $liggghts:literal, $range:ident; )* }) => {
        pub const $table: &[$crate::parameters::ParameterInfo<$ty>] = &[
            $( $crate::parameters::ParameterInfo {
                name: stringify!($field),
                liggghts_name: $liggghts,
                range: $crate::parameters::Range::$range,
                get: |p: &$ty| p.$field as f64,
            }, )*
        ];
    };
}
