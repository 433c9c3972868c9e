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
    /// Any integer a double holds exactly (magnitude below 9e15).
    Step,
}

impl Range {
    /// The allowed values in words, for messages and the parameter rows of
    /// the C ABI.
    pub fn describe(self) -> &'static str {
        match self {
            Range::Positive => "finite and > 0",
            Range::NonNegative => "finite and >= 0",
            Range::PositiveOrInfinite => "> 0 (inf for never)",
            Range::Fraction => "in [0, 1)",
            Range::Switch => "0 (off) or 1 (on)",
            Range::Step => "an integer of magnitude below 9e15",
        }
    }

    /// Whether `x` is an allowed value.
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

/// The magnitudes a finite, non-zero real parameter may have: beyond them
/// the products the models form (section areas and moments, stiffness
/// times area) overflow or vanish. No parameter of any engine's unit style
/// comes near them.
pub const MAGNITUDES: (f64, f64) = (1e-100, 1e100);

/// The requirement a finite value outside [`MAGNITUDES`] fails, for
/// messages.
fn magnitude_requirement(range: Range) -> String {
    format!(
        "{}, 0 or between {:e} and {:e} in magnitude (beyond, the model's products overflow or vanish)",
        range.describe(),
        MAGNITUDES.0,
        MAGNITUDES.1
    )
}

/// Whether a finite, non-zero real `x` lies outside [`MAGNITUDES`] (`inf`,
/// where a range admits it, is not a magnitude).
fn out_of_magnitude(kind: ParameterKind, x: f64) -> bool {
    kind == ParameterKind::Real
        && x.is_finite()
        && x != 0.0
        && !(MAGNITUDES.0..=MAGNITUDES.1).contains(&x.abs())
}

/// How a deck writes a value.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParameterKind {
    /// A real number.
    Real = 0,
    /// An integer (a time step).
    Integer = 1,
    /// On or off (1 or 0).
    Switch = 2,
}

/// Where a LIGGGHTS deck gives a value.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiggghtsSource {
    /// `fix property/global NAME peratomtypepair N ...`
    PerTypePair = 0,
    /// `fix property/global NAME scalar VALUE`
    Scalar = 1,
    /// An on/off switch of the `pair_style gran` command.
    Switch = 2,
    /// Not settable from LIGGGHTS decks: the default applies.
    Fixed = 3,
    /// `fix property/global NAME peratomtypepair N ...` when the deck
    /// defines it; the default applies when it does not (a setting the
    /// reference implementation does not have, so its decks keep its law).
    OptionalPerTypePair = 4,
}

/// When a model reads a parameter, judged from the switches of a parameter
/// set: engines that must ask the deck for each value (LIGGGHTS) ask only
/// for what is read.
pub struct Need<T> {
    /// For messages and documentation ("always", "damping on", ...).
    pub when: &'static str,
    /// Whether the model reads the parameter under the switches of a
    /// parameter set.
    pub applies: fn(&T) -> bool,
}

/// One row of a parameter table.
pub struct ParameterInfo<T> {
    /// Field name = LAMMPS keyword.
    pub name: &'static str,
    /// The name LIGGGHTS decks use (`fix property/global` or switch).
    pub liggghts_name: &'static str,
    /// Where a LIGGGHTS deck gives the value.
    pub source: LiggghtsSource,
    /// SI unit ("-" for dimensionless, "switch", "step").
    pub unit: &'static str,
    /// The allowed values.
    pub range: Range,
    /// When the model reads the value.
    pub need: Need<T>,
    /// Reads the field as a double.
    pub get: fn(&T) -> f64,
    /// Stores a value [`Range::admits`]; integers and switches arrive as
    /// exact doubles.
    pub set: fn(&mut T, f64),
}

impl<T> ParameterInfo<T> {
    /// How a deck writes the value, by its range.
    pub fn kind(&self) -> ParameterKind {
        match self.range {
            Range::Switch => ParameterKind::Switch,
            Range::Step => ParameterKind::Integer,
            _ => ParameterKind::Real,
        }
    }

    /// The value in `T::default()`, the one source of every default.
    pub fn default_value(&self) -> f64
    where
        T: Default,
    {
        (self.get)(&T::default())
    }

    /// Whether the model reads this parameter under the switches of `params`.
    pub fn needed(&self, params: &T) -> bool {
        (self.need.applies)(params)
    }
}

/// The row of `table` a deck names, by LAMMPS keyword or LIGGGHTS name.
pub fn find<'a, T>(table: &'a [ParameterInfo<T>], name: &str) -> Option<(usize, &'a ParameterInfo<T>)> {
    table
        .iter()
        .enumerate()
        .find(|(_, p)| p.name == name || p.liggghts_name == name)
}

/// Sets the parameter a deck names to `value`, refusing an unknown name
/// (the message lists the known keywords) and a value outside the row's
/// range (the message names the parameter, as model validation does).
pub fn set_by_name<T>(
    model: &str,
    table: &[ParameterInfo<T>],
    params: &mut T,
    name: &str,
    value: f64,
) -> Result<usize, SetError> {
    let Some((id, info)) = find(table, name) else {
        let known: Vec<&str> = table.iter().map(|p| p.name).collect();
        return Err(SetError::Unknown(format!(
            "{} has no parameter '{}' (known: {})",
            model,
            name,
            known.join(" ")
        )));
    };
    let integral = value.fract() == 0.0 && value.abs() < 9.0e15;
    if !info.range.admits(value) || (info.kind() != ParameterKind::Real && !integral) {
        return Err(SetError::Refused(refuse(
            model,
            table,
            info.name,
            info.range.describe(),
            value,
        )));
    }
    if out_of_magnitude(info.kind(), value) {
        return Err(SetError::Refused(refuse(
            model,
            table,
            info.name,
            &magnitude_requirement(info.range),
            value,
        )));
    }
    (info.set)(params, value);
    Ok(id)
}

/// Why [`set_by_name`] refused.
#[derive(Clone, Debug, PartialEq)]
pub enum SetError {
    /// No row has this name; the message lists the keywords.
    Unknown(String),
    /// The value is outside the row's range.
    Refused(ParameterError),
}

/// A refused parameter: its id (row of the model's table) and a message
/// naming it, the allowed range and the value given.
#[derive(Clone, Debug, PartialEq)]
pub struct ParameterError {
    /// The refused parameter's row in its model's table.
    pub parameter: usize,
    /// The message: the parameter, its allowed values and the value given.
    pub message: String,
}

impl ParameterError {
    /// What the parameter must be, as the message says it (between "must
    /// be" and the value given), for a message that names the value as a
    /// deck wrote it.
    pub fn requirement(&self) -> Option<&str> {
        let from = self.message.find(" must be ")? + " must be ".len();
        let to = self.message.rfind("; got ")?;
        (to > from).then(|| &self.message[from..to])
    }
}

impl std::fmt::Display for ParameterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ParameterError {}

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
        if out_of_magnitude(info.kind(), x) {
            return Err(refuse(
                model,
                table,
                info.name,
                &magnitude_requirement(info.range),
                x,
            ));
        }
    }
    Ok(())
}

/// A phrase of a LAMMPS deck: words that open it and the values that follow
/// them, each stored in the table row `reads` names, in order; then the rows
/// of `sets` take the values the phrase implies. A keyword without a phrase
/// is a row's own keyword with one value. The rules of a deck's grammar
/// (which switch a break mode means, what a creation step implies) are
/// these phrases, so an engine's parser only looks words up.
pub struct Phrase {
    /// The opening words, space-separated; empty for the values that follow
    /// the model's name in `pair_coeff`.
    pub words: &'static str,
    /// A phrase this one may only follow directly (empty: anywhere).
    pub follows: &'static str,
    /// Rows that take the phrase's values, in the order they are written.
    pub reads: &'static [&'static str],
    /// Rows set by the phrase itself, after its values.
    pub sets: &'static [(&'static str, f64)],
}

/// `parameter_table!(NAME: Type { field, "liggghts name", Source, "unit", Range, NEED; ... })`
/// defines the table `NAME` for the struct `Type`; `NEED` is a
/// [`Need<Type>`](Need) constant in scope. Doc comments written before
/// `NAME` become the table's.
#[macro_export]
macro_rules! parameter_table {
    ($(#[$attr:meta])* $table:ident : $ty:ty { $( $field:ident, $liggghts:literal, $source:ident, $unit:literal, $range:ident, $need:ident; )* }) => {
        $(#[$attr])*
        pub const $table: &[$crate::parameters::ParameterInfo<$ty>] = &[
            $( $crate::parameters::ParameterInfo {
                name: stringify!($field),
                liggghts_name: $liggghts,
                source: $crate::parameters::LiggghtsSource::$source,
                unit: $unit,
                range: $crate::parameters::Range::$range,
                need: $need,
                get: |p: &$ty| p.$field as f64,
                set: |p: &mut $ty, v: f64| p.$field = v as _,
            }, )*
        ];
    };
}
