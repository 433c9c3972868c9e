//! Per-contact state of the Voigt model.

use crate::state_layout::{slot, StateSlot};

/// The history of one Voigt contact (docs/models/voigt.md), as
/// [`CONTACT_STATE_LEN`] doubles in the order of [`CONTACT_SLOTS`]. Vectors
/// are seen from sphere `i`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactState {
    /// Cundall-Strack tangential spring elongation `xi_t`.
    pub tangential_spring: [f64; 3],
    /// Accumulated rolling angle `theta_r`.
    pub rolling_angle: [f64; 3],
}

/// The number of `f64` slots of [`ContactState`].
pub const CONTACT_STATE_LEN: usize = 6;

const _: () = assert!(std::mem::size_of::<ContactState>() == CONTACT_STATE_LEN * 8);

/// Both are built from `i - j` quantities, so both flip on swap.
pub const CONTACT_SLOTS: [StateSlot; CONTACT_STATE_LEN] = [
    slot("tangential_spring_x", true),
    slot("tangential_spring_y", true),
    slot("tangential_spring_z", true),
    slot("rolling_angle_x", true),
    slot("rolling_angle_y", true),
    slot("rolling_angle_z", true),
];

/// What one contact step produced. `force_j = -force_i`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactOutput {
    /// Force on `i` (N): normal and tangential.
    pub force_i: [f64; 3],
    /// Torque on `i` (N m): the tangential couple plus the rolling torque.
    pub torque_i: [f64; 3],
    /// Torque on `j` (N m): the tangential couple minus the rolling torque.
    pub torque_j: [f64; 3],
    /// Normal force (after the no-attraction clamp), positive = repulsive.
    pub normal_force: f64,
    /// Overlap `delta_n` (m): positive while the bodies touch.
    pub overlap: f64,
    /// 1 if the spheres touch this step.
    pub touching: i32,
    /// 1 if the tangential force sits on the Coulomb cap.
    pub sliding: i32,
    /// 1 if the rolling torque sits on its cap.
    pub rolling_slip: i32,
}

impl ContactState {
    /// The state as the flat array engines store.
    pub fn as_slots(&self) -> &[f64; CONTACT_STATE_LEN] {
        // SAFETY: repr(C) struct of exactly CONTACT_STATE_LEN f64.
        unsafe { &*(self as *const Self as *const [f64; CONTACT_STATE_LEN]) }
    }

    /// A flat array as stored by an engine, read as the state it holds.
    pub fn from_slots_mut(slots: &mut [f64; CONTACT_STATE_LEN]) -> &mut Self {
        // SAFETY: same layout, f64 alignment.
        unsafe { &mut *(slots as *mut [f64; CONTACT_STATE_LEN] as *mut Self) }
    }
}
