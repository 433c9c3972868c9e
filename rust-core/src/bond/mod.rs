//! `bond/nonlinear`: the six-degree-of-freedom hysteretic bond
//! (docs/models/bond-nonlinear.md). One module per law; [`kernel`] assembles them.

pub mod breakage;
mod chunk;
pub mod creation;
pub mod creation_check;
pub mod damping;
pub mod energy;
pub mod hysteresis;
pub mod kernel;
pub mod lanes;
pub mod model;
pub mod normal_law;
pub mod output_slots;
pub mod params;
pub mod section;
pub mod shear;
pub mod state;
pub mod timestep;
pub mod twist_bend;
pub mod wall;

pub use breakage::BreakMode;
pub use energy::BondEnergy;
pub use kernel::Simd;
pub use model::BondModel;
pub use params::{BondParams, ParameterError, PARAMETERS};
pub use state::{BondOutput, BondState, BondStatus, BOND_SLOTS, BOND_STATE_LEN};
pub use wall::{WallBondState, WALL_BOND_SLOTS, WALL_BOND_STATE_LEN};
