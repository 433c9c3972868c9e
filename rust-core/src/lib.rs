//! granbond: a nonlinear hysteretic DEM bond (`bond/nonlinear`) and a Voigt
//! contact model, written once in Rust and driven from LIGGGHTS / LAMMPS
//! through the C ABI in [`ffi`].
//!
//! Every formula of the models (`docs/models/*.md`) lives in one
//! module of [`bond`] or [`contact`]; the engine adapters and the scene runner
//! (crate `granbond-scene`) only call them.

// Every public item carries a doc comment, so `cargo doc` is the Rust API
// reference.
#![deny(missing_docs)]
// `!(x > 0.0)` is how the models reject NaN along with the non-positive
// values: `x <= 0.0` would let NaN through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod bond;
pub mod bond_store;
pub mod coeff;
pub mod contact;
pub mod ffi;
pub mod integrate;
pub mod kinematics;
pub mod ledger;
pub mod liggghts_words;
pub mod pair_source;
pub mod parameters;
pub mod real;
pub mod restart_rows;
pub mod simd;
pub mod stability;
pub mod state_layout;
pub mod timestep_check;
pub mod under_bond;
pub mod vector;
