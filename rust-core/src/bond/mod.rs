//! `bond/nonlinear`: the six-degree-of-freedom hysteretic bond
//! (docs/models/bond-nonlinear.md).
//!
//! One module per law (`normal_law`, `hysteresis`, `shear`, `twist_bend`,
//! `damping`, `breakage`, `section`, `energy`); the state and the output
//! engines keep (`state`, `wall`, `output_slots`) and when its results count
//! as finite (`finite`); each atom's share of the damping loads INL's
//! `computeDissipatedEnergy` files (`dissipated_shares`). Above them, each depending
//! only on the ones before: the laws of a bond type ([`laws`]) and the parts
//! switched on ([`features`]) and how a step reads them (`switches`); the
//! assembled step (`step`); the paths that
//! feed it one bond at a time (`scalar`) or in lanes (`wide`), and where
//! they put the loads besides the outputs: the engine's per-atom sums
//! ([`atom_loads`]); the compiled steps and the choice among them
//! (`dispatch`); the model ([`model`]).

pub mod atom_loads;
pub mod breakage;
pub mod creation;
pub mod creation_check;
pub mod damping;
mod dispatch;
pub mod dissipated_shares;
pub mod energy;
pub mod features;
pub mod fields;
pub mod finite;
pub mod hysteresis;
mod inl;
pub mod laws;
mod linear;
pub mod model;
pub mod normal_law;
pub mod output_slots;
pub mod paired;
pub mod params;
mod scalar;
pub mod section;
pub mod shear;
pub mod state;
mod step;
mod switches;
pub mod timestep;
pub mod twist_bend;
pub mod wall;
#[cfg(target_arch = "x86_64")]
mod wide;

pub use crate::simd::Simd;
pub use atom_loads::{AtomLoads, LoadsTooShort};
pub use breakage::BreakMode;
pub use energy::BondEnergy;
pub use laws::BondLaws;
pub use model::BondModel;
pub use params::{
    liggghts_name, BondParams, ParameterError, CREATION_ROWS, LINEAR_NAMES, PAIR_BOND_ROWS, PARAMETERS,
    PHRASES,
};
pub use state::{BondOutput, BondState, BondStatus, BOND_SLOTS, BOND_STATE_LEN};
pub use wall::{WallBondState, WALL_BOND_SLOTS, WALL_BOND_STATE_LEN};
