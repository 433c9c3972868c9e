//! A small standalone DEM driver (pairs, chains, clusters) with the
//! symplectic Euler integrator, so studies and examples can run the models
//! without an engine. Not a replacement for LIGGGHTS/LAMMPS: no MPI, no
//! walls other than planes, O(N) cell-list contact search.

// `!(x > 0.0)` rejects NaN along with the values it names.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod builders;
pub mod cells;
pub mod csv;
/// cbindgen:ignore
pub mod reference;
pub mod runner;
pub mod sweep;
pub mod vtk;

pub use runner::{Scene, SceneError, Sphere, StepReport};
