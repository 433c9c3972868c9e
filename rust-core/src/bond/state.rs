//! Per-bond state: a plain `#[repr(C)]` struct of `f64`, which engines store
//! as a flat array described by [`BOND_SLOTS`].

use crate::state_layout::{slot, StateSlot};

/// Lifecycle of a pair's bond, stored as the sign of the rest length
/// ([`BondState::rest`]).
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BondStatus {
    /// Never bonded (fresh, all-zero history).
    Unbonded = 0,
    /// Bonded: the bond carries the loads of the pair.
    Intact = 1,
    /// Broken: the bond exerts nothing, and is created again only under
    /// `create_always`.
    Broken = 2,
}

impl BondStatus {
    /// The status a rest-length slot ([`BondState::rest`]) holds: intact
    /// above zero, broken below it (negative zero included), anything else
    /// (zero, NaN) [`BondStatus::Unbonded`].
    #[inline(always)]
    pub fn from_rest(v: f64) -> Self {
        if v > 0.0 {
            BondStatus::Intact
        } else if v <= 0.0 && v.is_sign_negative() {
            BondStatus::Broken
        } else {
            BondStatus::Unbonded
        }
    }
}

/// The history of one bond between two spheres (docs/models/bond-nonlinear.md,
/// "Bond state"), as [`BOND_STATE_LEN`] doubles in the order of
/// [`BOND_SLOTS`]. Vectors are seen from sphere `i`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BondState {
    /// The centre distance at creation `r0`, signed by the bond's
    /// [`BondStatus`]: `r0` while intact, `-r0` once broken, zero never
    /// bonded (one slot for both: a rest length is positive).
    pub rest: f64,
    /// `dmax`: the largest compression `delta` reached (m; eq. 4).
    pub delta_max: f64,
    /// `dmin`: the smallest `delta` reached, the largest stretch (m; eq. 4).
    pub delta_min: f64,
    /// Undamped shear spring force on `i`.
    pub shear_force: [f64; 3],
    /// Accumulated relative rotation about the axis (parallel to `n`).
    pub twist_angle: [f64; 3],
    /// Accumulated relative rotation across the axis (normal to `n`).
    pub bend_angle: [f64; 3],
    /// Largest signed twisting angle `phi = theta_n . n` reached (`>= 0`).
    pub twist_max: f64,
    /// Smallest signed twisting angle reached (`<= 0`).
    pub twist_min: f64,
    /// `beta`: the bending angle of the extreme reached on the leading side
    /// (in the tangent plane; zero until the bond bends).
    pub bend_history: [f64; 3],
    /// `beta_opp`: the extreme `|theta_t|` reached on the opposite side.
    pub bend_opposite: f64,
}

/// The number of `f64` slots of [`BondState`].
pub const BOND_STATE_LEN: usize = 18;

/// Names and swap rules of the slots of [`BondState`], in memory order.
pub const BOND_SLOTS: [StateSlot; BOND_STATE_LEN] = [
    slot("rest", false),
    slot("delta_max", false),
    slot("delta_min", false),
    slot("shear_force_x", true),
    slot("shear_force_y", true),
    slot("shear_force_z", true),
    slot("twist_angle_x", true),
    slot("twist_angle_y", true),
    slot("twist_angle_z", true),
    slot("bend_angle_x", true),
    slot("bend_angle_y", true),
    slot("bend_angle_z", true),
    slot("twist_max", false),
    slot("twist_min", false),
    slot("bend_history_x", true),
    slot("bend_history_y", true),
    slot("bend_history_z", true),
    slot("bend_opposite", false),
];

const _: () = assert!(std::mem::size_of::<BondState>() == BOND_STATE_LEN * 8);

/// Where a field of [`BondState`] starts, in slots of [`BOND_SLOTS`].
macro_rules! slot_of {
    ($field:ident) => {
        std::mem::offset_of!($crate::bond::BondState, $field) / std::mem::size_of::<f64>()
    };
}
pub(crate) use slot_of;

impl BondState {
    /// The bond's [`BondStatus`].
    #[inline(always)]
    pub fn status(&self) -> BondStatus {
        BondStatus::from_rest(self.rest)
    }

    /// The centre distance at creation, whatever the status (zero never
    /// bonded).
    #[inline(always)]
    pub fn r0(&self) -> f64 {
        self.rest.abs()
    }

    /// Marks the bond broken; its rest length stays readable ([`Self::r0`]).
    #[inline(always)]
    pub fn mark_broken(&mut self) {
        self.rest = -self.rest.abs();
    }

    /// A freshly created bond of rest length `r0` (> 0): no load history.
    pub fn created(r0: f64) -> Self {
        Self {
            rest: r0,
            ..Self::default()
        }
    }

    /// The state as the flat array engines store.
    pub fn as_slots(&self) -> &[f64; BOND_STATE_LEN] {
        // SAFETY: repr(C) struct of exactly BOND_STATE_LEN f64 (checked above).
        unsafe { &*(self as *const Self as *const [f64; BOND_STATE_LEN]) }
    }

    /// The state as the flat array engines store, writable.
    pub fn as_slots_mut(&mut self) -> &mut [f64; BOND_STATE_LEN] {
        // SAFETY: as above.
        unsafe { &mut *(self as *mut Self as *mut [f64; BOND_STATE_LEN]) }
    }

    /// A flat array as stored by an engine, read as the state it holds.
    pub fn from_slots_mut(slots: &mut [f64; BOND_STATE_LEN]) -> &mut Self {
        // SAFETY: same layout, f64 alignment.
        unsafe { &mut *(slots as *mut [f64; BOND_STATE_LEN] as *mut Self) }
    }
}

/// What one bond step produced. `force_j = -force_i`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BondOutput {
    /// Force on `i` (N; eq. 13), damped.
    pub force_i: [f64; 3],
    /// Torque on `i` (N m; eq. 13), damped.
    pub torque_i: [f64; 3],
    /// Torque on `j` (N m; eq. 13), damped.
    pub torque_j: [f64; 3],
    /// Undamped normal force, positive = repulsive.
    pub normal_force: f64,
    /// Normal stress `sigma` of the section from the undamped loads (Pa;
    /// docs/models/bond-nonlinear.md eq. 14).
    pub sigma: f64,
    /// Shear stress `tau` of the section from the undamped loads (Pa;
    /// docs/models/bond-nonlinear.md eq. 14).
    pub tau: f64,
    /// `delta = r0 - r` (compression positive).
    pub delta: f64,
    /// [`BondStatus`] after the step.
    pub status: i32,
    /// [`super::BreakMode`]: non-zero only in the step the bond broke.
    pub break_mode: i32,
}
