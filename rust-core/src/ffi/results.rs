//! The checked entries answer OK only with finite results. Inputs that are
//! finite but far outside any physical range (a subnormal radius, a tiny
//! `lambda`, velocities of 1e300, a huge `dt`) overflow or underflow inside
//! the laws; the engine would integrate the NaN or infinity it is handed,
//! so such an answer is refused as `GB_STATUS_NON_FINITE_RESULT`, naming
//! what went non-finite.

use super::error::{Failure, Status};
use super::guard::FailedIndex;
use crate::bond::finite::{bond_finite, BatchResult};
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

/// The `NonFiniteResult` failure, naming `what` went non-finite.
pub fn refused(what: &str) -> Failure {
    Failure::new(
        Status::NonFiniteResult,
        format!(
            "non-finite {what} from finite input: the input lies far outside the model's range \
             (radius, lambda, velocities or dt)"
        ),
    )
}

/// A bond step's loads, stresses and state.
pub fn bond(state: &BondState, out: &BondOutput) -> Result<(), Failure> {
    if bond_finite(state, out) {
        Ok(())
    } else {
        Err(refused(BOND_RESULTS))
    }
}

/// A batch step's answer as the entry's status: its first bond with
/// unusable kinematics, else its first bond whose results are not finite,
/// with the bond's index in `failed_index`.
pub fn bonds(stepped: BatchResult, failed_index: FailedIndex) -> Result<(), Failure> {
    match stepped {
        Ok(None) => Ok(()),
        Ok(Some(index)) => Err(failed_index.fail("bond", index, refused(BOND_RESULTS))),
        Err((index, e)) => Err(failed_index.fail("bond", index, e.into())),
    }
}

const BOND_RESULTS: &str = "force, torque, stress or bond state";

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
