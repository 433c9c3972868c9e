//! `voigt`: linear spring-dashpot contact with Cundall-Strack tangential
//! history, Coulomb friction and Iwashita-Oda rolling resistance
//! (docs/models/voigt.md).

pub mod dispatch;
pub mod frame;
pub mod friction_cap;
pub mod model;
pub mod normal;
pub mod params;
pub mod rolling;
pub mod state;
pub mod tangential;
pub mod vectors;
#[cfg(target_arch = "x86_64")]
pub(crate) mod wide;

pub use frame::{sphere_plane, sphere_sphere, ContactFrame, FrameError, FrameIn, Motion, Plane};
pub use model::{TangentialLoad, VoigtModel};
pub use params::{
    ContactPart, SubModel, VoigtParams, VOIGT_PARAMETERS, VOIGT_PARTS, VOIGT_PHRASES, VOIGT_SUB_MODELS,
};
pub use state::{ContactOutput, ContactState, CONTACT_SLOTS, CONTACT_STATE_LEN};
