//! What of a contact acts on two spheres while their bond is intact: the
//! rule of the bond's law ([`BondLaws::keeps_contact_loads`],
//! [`BondLaws::keeps_contact_tangential`]) applied to the loads of the
//! contact's step. For an engine whose own loop steps the contact under the
//! bond (LAMMPS `pair granbond`); LIGGGHTS gets the same split from the
//! order in which it calls its sub-models.

use crate::bond::laws::BondLaws;
use crate::contact::ContactOutput;
use crate::vector::{v3, Vec3};

/// Leaves in `out`, the output of a contact step between the spheres of an
/// intact bond of `laws`, the loads that act under the bond: all of them
/// under LIGGGHTS-INL's linear bond, which adds its loads to the contact's;
/// the tangential and rolling ones under LIGGGHTS-INL's code, whose bond
/// takes the place of the normal force alone (`normal_force` along the
/// normal taken out of `force_i`); none where the bond replaces the
/// contact. `del = x_i - x_j` and `rsq = |del|^2 > 0` are the separation
/// the contact was stepped at, whose normal `del / sqrt(rsq)` the step used.
pub fn contact_loads_under_bond(laws: &BondLaws, del: [f64; 3], rsq: f64, out: &mut ContactOutput) {
    if laws.keeps_contact_loads() {
        return;
    }
    if laws.keeps_contact_tangential() {
        if out.touching != 0 {
            let n = v3(del) * (1.0 / rsq.sqrt());
            let tangential: Vec3 = v3(out.force_i) - n * out.normal_force;
            out.force_i = tangential.into();
        }
        return;
    }
    out.force_i = [0.0; 3];
    out.torque_i = [0.0; 3];
    out.torque_j = [0.0; 3];
}
