//! The checked entries answer OK only with finite results. Inputs that are
//! finite but far outside any physical range (a subnormal radius, a tiny
//! `lambda`, velocities of 1e300, a huge `dt`) overflow or underflow inside
//! the laws; the engine would integrate the NaN or infinity it is handed,
//! so such an answer is refused as `GB_STATUS_NON_FINITE_INPUT`, naming
//! what went non-finite.

use super::error::{Failure, Status};
use crate::bond::{BondOutput, BondState};
use crate::contact::{ContactOutput, ContactState};

/// Whether every value is finite: one add per value, as the check runs on
/// the engines' hot paths. A value of infinity or NaN makes the sum
/// non-finite; so do finite values so large that their sum overflows
/// (beyond 1e308), which are as far outside any physical range.
#[inline]
fn finite(values: &[f64]) -> bool {
    values.iter().sum::<f64>().is_finite()
}

pub fn refused(what: &str) -> Failure {
    Failure::new(
        Status::NonFiniteInput,
        format!(
            "non-finite {what} from finite input: the input lies far outside the model's range \
             (radius, lambda, velocities or dt)"
        ),
    )
}

/// Whether a bond step's loads, stresses and state are finite.
#[inline]
pub fn bond_finite(state: &BondState, o: &BondOutput) -> bool {
    let (f, ti, tj) = (o.force_i, o.torque_i, o.torque_j);
    let loads = f[0] + f[1] + f[2] + ti[0] + ti[1] + ti[2] + tj[0] + tj[1] + tj[2];
    let scalars = o.normal_force + o.sigma + o.tau + o.delta;
    (loads + scalars).is_finite() && finite(state.as_slots())
}

/// A bond step's loads, stresses and state.
pub fn bond(state: &BondState, out: &BondOutput) -> Result<(), Failure> {
    if bond_finite(state, out) {
        Ok(())
    } else {
        Err(refused("force, torque, stress or bond state"))
    }
}

/// Checks bonds `0 .. count` (`state(k)`, `out[k]`); the first that is not
/// finite is refused with its index.
pub fn bonds<'a>(
    count: usize,
    state: impl Fn(usize) -> &'a BondState,
    out: &[BondOutput],
) -> Result<(), (usize, Failure)> {
    match (0..count).position(|k| !bond_finite(state(k), &out[k])) {
        None => Ok(()),
        Some(k) => Err((k, refused("force, torque, stress or bond state"))),
    }
}

/// A contact step's loads and state.
pub fn contact(state: &ContactState, out: &ContactOutput) -> Result<(), Failure> {
    let (f, ti, tj) = (out.force_i, out.torque_i, out.torque_j);
    let numbers = [
        f[0],
        f[1],
        f[2],
        ti[0],
        ti[1],
        ti[2],
        tj[0],
        tj[1],
        tj[2],
        out.normal_force,
        out.overlap,
    ];
    if !finite(&numbers) {
        return Err(refused("force or torque"));
    }
    vector("contact state", state.as_slots())
}

/// Any other result: a load, a spring or an angle.
pub fn vector(what: &str, values: &[f64]) -> Result<(), Failure> {
    if finite(values) {
        Ok(())
    } else {
        Err(refused(what))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_tells_infinity_and_nan_from_every_finite_class() {
        let good = [0.0, -0.0, 1.0, -1e308, 1e307, f64::MIN_POSITIVE, 5e-324, -5e-324];
        assert!(finite(&good));
        for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN, -f64::NAN] {
            let mut v = good;
            v[3] = bad;
            assert!(!finite(&v), "{bad}");
        }
    }
}
