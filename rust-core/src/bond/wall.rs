//! Bonds to walls. The wall plays sphere `j`: a sphere of the particle's
//! radius behind the wall, touching it at the contact point of the bond's
//! creation. As in LIGGGHTS-INL, that point is fixed to the wall: it moves
//! with the wall's velocity and does not spin. Its centre is kept in three
//! extra state slots, after the pair slots. (The reference measures `r` to
//! the contact point itself and doubles it only for creation; the mirror
//! sphere gives the same `r` throughout and lever arms of `R_i` on both
//! sides, so the shear and its torque see the same contact point.) Under
//! `inl_compatible` the partner slots hold the contact point itself and
//! the bond follows INL's geometry (`bond::inl`), as under its linear bond
//! (`bond::linear`).

use super::inl::inl_step;
use super::linear::linear_step;
use super::model::BondModel;
use super::state::{BondOutput, BondState, BOND_SLOTS, BOND_STATE_LEN};
use crate::kinematics::{KinematicsError, PairKinematics, SphereKinematics};
use crate::state_layout::{slot, StateSlot};
use crate::vector::{direction_or_zero, v3};

/// The state of a bond between a sphere and a wall: a pair bond's state,
/// then the centre of the wall's stand-in sphere ([`WALL_BOND_SLOTS`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WallBondState {
    /// The bond's state, as between two spheres.
    pub bond: BondState,
    /// Centre of the wall's stand-in sphere.
    pub partner: [f64; 3],
}

/// The number of `f64` slots of [`WallBondState`].
pub const WALL_BOND_STATE_LEN: usize = BOND_STATE_LEN + 3;

const _: () = assert!(std::mem::size_of::<WallBondState>() == WALL_BOND_STATE_LEN * 8);

/// Pair slots, then the partner centre (a position, so it never flips: a
/// wall bond is only ever seen from the particle).
pub const WALL_BOND_SLOTS: [StateSlot; WALL_BOND_STATE_LEN] = {
    let mut s = [slot("", false); WALL_BOND_STATE_LEN];
    let mut i = 0;
    while i < BOND_STATE_LEN {
        s[i] = BOND_SLOTS[i];
        i += 1;
    }
    s[BOND_STATE_LEN] = slot("partner_x", false);
    s[BOND_STATE_LEN + 1] = slot("partner_y", false);
    s[BOND_STATE_LEN + 2] = slot("partner_z", false);
    s
};

/// Centre of the stand-in sphere for a particle at `x_i` touching the wall
/// at `contact_point`: the mirror image of the particle's surface point,
/// `c - R_i (x_i - c)/|x_i - c|`.
pub fn wall_partner(x_i: [f64; 3], radius_i: f64, contact_point: [f64; 3]) -> [f64; 3] {
    let c = v3(contact_point);
    let outward = direction_or_zero(v3(x_i) - c);
    (c - outward * radius_i).into()
}

/// The pair seen by the bond laws: the stand-in sphere moves with the wall.
pub fn wall_kinematics(
    sphere: &SphereKinematics,
    partner: [f64; 3],
    wall_velocity: [f64; 3],
) -> PairKinematics {
    PairKinematics {
        x_i: sphere.x,
        x_j: partner,
        v_i: sphere.v,
        v_j: wall_velocity,
        w_i: sphere.w,
        w_j: [0.0; 3],
        radius_i: sphere.radius,
        radius_j: sphere.radius,
    }
}

impl BondModel {
    /// Bonds `sphere` to the wall it touches at `contact_point`, under the
    /// same rules as a pair (the centre distance is twice the distance to the
    /// contact point).
    pub fn try_create_wall(
        &self,
        sphere: &SphereKinematics,
        contact_point: [f64; 3],
        step: i64,
        state: &mut WallBondState,
    ) -> Result<bool, KinematicsError> {
        // LIGGGHTS-INL's wall bond (`inl_compatible`) forms on twice the
        // distance to the contact point (its stand-in for the rules is the
        // mirror image of the centre) and keeps that point itself as its
        // partner and the distance to it as its rest length.
        let (stand_in, partner) = if self.inl_wall() {
            ((v3(contact_point) * 2.0 - v3(sphere.x)).into(), contact_point)
        } else {
            let p = wall_partner(sphere.x, sphere.radius, contact_point);
            (p, p)
        };
        let kin = wall_kinematics(sphere, stand_in, [0.0; 3]);
        let created = self.try_create(&kin, step, &mut state.bond)?;
        if created {
            state.partner = partner;
            if self.inl_wall() {
                state.bond.rest = (v3(sphere.x) - v3(contact_point)).norm();
            }
        }
        Ok(created)
    }

    /// Advances a wall bond by `dt`; the stand-in sphere then moves with the
    /// wall. `force_i`/`torque_i` act on the particle.
    pub fn step_wall(
        &self,
        sphere: &SphereKinematics,
        wall_velocity: [f64; 3],
        dt: f64,
        state: &mut WallBondState,
        out: &mut BondOutput,
    ) -> Result<(), KinematicsError> {
        let kin = wall_kinematics(sphere, state.partner, wall_velocity);
        if self.linear {
            linear_step(self, &kin, dt, &mut state.bond, out, true, true)?;
        } else if self.inl {
            inl_step(self, &kin, dt, &mut state.bond, out, true, true)?;
        } else {
            self.step(&kin, dt, &mut state.bond, out)?;
        }
        if !wall_velocity.iter().all(|c| c.is_finite()) {
            return Err(KinematicsError::NonFinite);
        }
        state.partner = (v3(state.partner) + v3(wall_velocity) * dt).into();
        Ok(())
    }
}
