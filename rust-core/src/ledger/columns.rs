//! The columns of the per-bond local output of both engines (LAMMPS
//! `compute granbond/local`, LIGGGHTS `compute pair/gran/local/bond`),
//! chosen by keyword: `id` (both atom ids), `pos` (both centres), every
//! field of the core's table (`bond::fields`), `all` for all of those, the
//! bond store's energies, and the raw slots of the bond's record: `state`
//! (the bond state, in the core's order) and `output` (the loads of the
//! latest force pass as the core files them). A field the core gains is a
//! keyword in both engines.

use crate::bond::fields::{BOND_ENERGY_FIELDS, BOND_FIELDS};
use crate::bond::output_slots::BOND_OUTPUT_LEN;
use crate::bond::BOND_STATE_LEN;

/// What a column shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Column {
    /// Sphere i's id.
    IdI,
    /// Sphere j's id.
    IdJ,
    /// A centre's coordinate: 0-2 sphere i's, 3-5 sphere j's.
    Pos(usize),
    /// A slot of the record (the state, then the output).
    Record(usize),
    /// A field of `BOND_FIELDS`.
    Field(usize),
    /// A field of `BOND_ENERGY_FIELDS`.
    Energy(usize),
}

/// LIGGGHTS-INL's loads of `compute pair/gran/local/bond` (its columns
/// 10-27): the force on i, its normal and tangential parts, the torque on
/// i, its normal and tangential parts.
const INL_LOADS: [&str; 18] = [
    "force_x",
    "force_y",
    "force_z",
    "force_normal_x",
    "force_normal_y",
    "force_normal_z",
    "force_tangential_x",
    "force_tangential_y",
    "force_tangential_z",
    "torque_x",
    "torque_y",
    "torque_z",
    "torque_normal_x",
    "torque_normal_y",
    "torque_normal_z",
    "torque_tangential_x",
    "torque_tangential_y",
    "torque_tangential_z",
];

/// The columns of one output, in the deck's order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BondColumns {
    columns: Vec<Column>,
}

/// Every keyword, for the message of one that is not.
pub fn known() -> String {
    let mut words = vec!["id", "pos", "state", "output", "all"];
    words.extend(
        BOND_FIELDS
            .iter()
            .chain(BOND_ENERGY_FIELDS.iter())
            .map(|f| f.name),
    );
    words.join(" ")
}

impl BondColumns {
    /// The columns the keywords `words` name, or what is wrong (naming the
    /// keyword).
    pub fn parse(words: &[&str]) -> Result<BondColumns, String> {
        if words.is_empty() {
            return Err(format!("no keyword (known: {})", known()));
        }
        let mut columns = Vec::new();
        for &word in words {
            match word {
                "id" => columns.extend([Column::IdI, Column::IdJ]),
                "pos" => columns.extend((0..6).map(Column::Pos)),
                "state" => columns.extend((0..BOND_STATE_LEN).map(Column::Record)),
                "output" => {
                    columns.extend((BOND_STATE_LEN..BOND_STATE_LEN + BOND_OUTPUT_LEN).map(Column::Record))
                }
                "all" => columns.extend((0..BOND_FIELDS.len()).map(Column::Field)),
                _ => {
                    let field = BOND_FIELDS.iter().position(|f| f.name == word).map(Column::Field);
                    let energy = || {
                        BOND_ENERGY_FIELDS
                            .iter()
                            .position(|f| f.name == word)
                            .map(Column::Energy)
                    };
                    columns.push(
                        field
                            .or_else(energy)
                            .ok_or_else(|| format!("unknown keyword '{word}' (known: {})", known()))?,
                    );
                }
            }
        }
        Ok(BondColumns { columns })
    }

    /// LIGGGHTS-INL's columns after its first 9 (centres, ids, periodic
    /// flag, which the engine gives): the loads on sphere i in its parts,
    /// then the bond's state where INL has the pair's history.
    pub fn inl_layout() -> BondColumns {
        let mut words = INL_LOADS.to_vec();
        words.push("state");
        BondColumns::parse(&words).expect("INL's loads are fields of the table")
    }

    /// The columns, in order.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// Whether a column is one of the bond store's energies.
    pub fn wants_energy(&self) -> bool {
        self.columns.iter().any(|c| matches!(c, Column::Energy(_)))
    }

    /// The row of one bond, written to `row` (one value a column): its
    /// `record` (the state, then the output of the latest force pass), its
    /// `fields` (`BOND_FIELDS`' values), its `energy` (`BOND_ENERGY_FIELDS`'),
    /// the spheres' ids and centres.
    #[allow(clippy::too_many_arguments)]
    pub fn row(
        &self,
        record: &[f64],
        fields: &[f64],
        energy: &[f64],
        tag_i: f64,
        tag_j: f64,
        x_i: [f64; 3],
        x_j: [f64; 3],
        row: &mut [f64],
    ) {
        for (out, column) in row.iter_mut().zip(&self.columns) {
            *out = match *column {
                Column::IdI => tag_i,
                Column::IdJ => tag_j,
                Column::Pos(c) if c < 3 => x_i[c],
                Column::Pos(c) => x_j[c - 3],
                Column::Record(k) => record[k],
                Column::Field(k) => fields[k],
                Column::Energy(k) => energy[k],
            };
        }
    }
}
