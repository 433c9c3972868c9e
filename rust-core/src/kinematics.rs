//! What an engine knows about a pair of spheres at one step, and the geometry
//! derived from it.

use crate::real::Real;
use crate::vector::{v3, Vec3, Vector};

/// Positions, velocities, angular velocities and radii of spheres `i` and `j`.
/// A wall partner is a sphere too (see `bond::wall`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairKinematics {
    /// Centre of `i` (m).
    pub x_i: [f64; 3],
    /// Centre of `j` (m).
    pub x_j: [f64; 3],
    /// Velocity of `i` (m/s).
    pub v_i: [f64; 3],
    /// Velocity of `j` (m/s).
    pub v_j: [f64; 3],
    /// Angular velocity of `i` (rad/s).
    pub w_i: [f64; 3],
    /// Angular velocity of `j` (rad/s).
    pub w_j: [f64; 3],
    /// Radius of `i` (m).
    pub radius_i: f64,
    /// Radius of `j` (m).
    pub radius_j: f64,
}

/// One sphere against a wall.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SphereKinematics {
    /// Centre (m).
    pub x: [f64; 3],
    /// Velocity (m/s).
    pub v: [f64; 3],
    /// Angular velocity (rad/s).
    pub w: [f64; 3],
    /// Radius (m).
    pub radius: f64,
}

/// Why a pair's kinematics cannot be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KinematicsError {
    /// NaN or infinity in a position, velocity or radius.
    NonFinite,
    /// The centres coincide: the pair has no axis.
    CoincidentCentres,
    /// A radius is zero or negative.
    NonPositiveRadius,
    /// Finite centres so far apart that their distance overflows: no
    /// direction and no overlap to speak of.
    DistanceOverflows,
}

impl PairKinematics {
    /// The same pair seen from `j`.
    pub fn swapped(&self) -> Self {
        Self {
            x_i: self.x_j,
            x_j: self.x_i,
            v_i: self.v_j,
            v_j: self.v_i,
            w_i: self.w_j,
            w_j: self.w_i,
            radius_i: self.radius_j,
            radius_j: self.radius_i,
        }
    }

    /// Rejects NaN/Inf anywhere and non-positive radii (see [`usable`]).
    #[inline(always)]
    pub fn check(&self) -> Result<(), KinematicsError> {
        let vectors = [self.x_i, self.x_j, self.v_i, self.v_j, self.w_i, self.w_j];
        let (finite, positive) = usable(vectors, self.radius_i, self.radius_j);
        if !finite {
            return Err(KinematicsError::NonFinite);
        }
        if !positive {
            return Err(KinematicsError::NonPositiveRadius);
        }
        Ok(())
    }
}

/// Whether the 18 vector components and two radii of a pair are all finite,
/// and whether both radii are positive (per lane). `x - x` is zero for every
/// finite `x` and NaN otherwise, so one sum tests all 20 numbers without a
/// branch per value. The sum runs in four independent partial sums (zero iff
/// every term is zero, in any order), so it is a short tree of packed
/// additions rather than one chain of 20 dependent ones.
#[inline(always)]
#[allow(clippy::eq_op)]
pub fn usable<R: Real>(vectors: [[R; 3]; 6], radius_i: R, radius_j: R) -> (R::Mask, R::Mask) {
    let zero = R::splat(0.0);
    let mut acc = [zero; 4];
    let mut lane = 0;
    for a in vectors {
        for c in a {
            acc[lane % 4] = acc[lane % 4] + (c - c);
            lane += 1;
        }
    }
    acc[2] = acc[2] + (radius_i - radius_i);
    acc[3] = acc[3] + (radius_j - radius_j);
    // The sum is +0 or NaN: `>= 0` is `== 0`.
    let finite = ((acc[0] + acc[1]) + (acc[2] + acc[3])).ge(zero);
    (finite, radius_i.gt(zero) & radius_j.gt(zero))
}

/// Centre line of a pair: `n` points from `j` to `i`.
#[derive(Clone, Copy, Debug)]
pub struct CentreLine<R = f64, V = Vec3> {
    /// Centre distance `r = |x_i - x_j|` (m).
    pub r: R,
    /// Unit normal `n = (x_i - x_j) / r`.
    pub n: V,
}

/// The centre line of a pair (docs/models/bond-nonlinear.md, "Geometry");
/// `CoincidentCentres` when the centres are not [`separated`].
#[inline(always)]
pub fn centre_line(k: &PairKinematics) -> Result<CentreLine, KinematicsError> {
    let d = v3(k.x_i) - v3(k.x_j);
    let r2 = d.norm_squared();
    if !separated(r2) {
        return Err(KinematicsError::CoincidentCentres);
    }
    Ok(axis(d, r2))
}

/// Whether centres `r2.sqrt()` apart define an axis: below this the
/// direction is noise; the bond has no defined axis.
#[inline(always)]
pub fn separated<R: Real>(r2: R) -> R::Mask {
    r2.gt(R::splat(f64::MIN_POSITIVE))
}

/// The centre line along `d = x_i - x_j` with `r2 = |d|^2`, for [`separated`]
/// centres.
#[inline(always)]
pub fn axis<R: Real, V: Vector<R>>(d: V, r2: R) -> CentreLine<R, V> {
    let r = r2.sqrt();
    // One division for the three components.
    CentreLine {
        r,
        n: d * (R::splat(1.0) / r),
    }
}

/// Relative velocity of the material points of `i` and `j` that meet at the
/// point at distance `lever_i` from the centre of `i` and `lever_j` from that
/// of `j` along the centre line, with its normal part removed:
/// `vt - (lever_i w_i + lever_j w_j) x n`. It vanishes in rigid motion when
/// the levers add up to the centre distance.
#[inline(always)]
pub fn slip_velocity<R: Real, V: Vector<R>>(v_rel: V, w_i: V, w_j: V, n: V, lever_i: R, lever_j: R) -> V {
    let vt = v_rel - n * v_rel.dot(&n);
    vt - (w_i * lever_i + w_j * lever_j).cross(&n)
}

/// Centre of the bond between spheres of radii `radius_i` and `radius_j`
/// centred at `x_i` and `x_j`: the point of the centre line that divides it
/// in the ratio `radius_i : radius_j` (where the surfaces meet when the
/// spheres touch). A wall plays sphere `j` with `x_j` its point and
/// `radius_j = 0`: the centre is that point.
pub fn bond_centre(x_i: [f64; 3], x_j: [f64; 3], radius_i: f64, radius_j: f64) -> [f64; 3] {
    let w = radius_j / (radius_i + radius_j);
    std::array::from_fn(|c| x_j[c] + w * (x_i[c] - x_j[c]))
}
