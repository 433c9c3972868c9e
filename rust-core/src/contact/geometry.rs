//! The contact frame's geometry from what an engine's pair loop already
//! has: the centre separation (or the engine's own normal and overlap) and
//! the two radii, a wall written as radius 0. So the levers and `R*` are
//! decided here, not in each adapter.

use super::rolling::effective_radius;

/// The geometric fields of a [`ContactFrame`](super::ContactFrame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    /// Unit normal from `j` to `i`.
    pub n: [f64; 3],
    pub overlap: f64,
    pub lever_i: f64,
    pub lever_j: f64,
    /// `R*` of the rolling cap; 0 when the model has no rolling (it is read
    /// nowhere else, so its division is left out).
    pub r_eff: f64,
}

/// Levers and `R*` of spheres of radii `radius_i`, `radius_j`; a wall
/// (`radius_j = 0`) has no lever and `R* = R_i`.
#[inline(always)]
pub fn levers(radius_i: f64, radius_j: f64, rolling: bool) -> (f64, f64, f64) {
    let r_eff = if !rolling {
        0.0
    } else if radius_j == 0.0 {
        effective_radius(radius_i, None)
    } else {
        effective_radius(radius_i, Some(radius_j))
    };
    (radius_i, radius_j, r_eff)
}

/// A touching pair from its separation `del = x_i - x_j` and
/// `rsq = |del|^2`: one square root, one reciprocal for the three normal
/// components, the same operations as the frame of
/// [`sphere_sphere`](super::sphere_sphere).
#[inline(always)]
pub fn from_separation(del: [f64; 3], rsq: f64, radius_i: f64, radius_j: f64, rolling: bool) -> Geometry {
    let r = rsq.sqrt();
    let rinv = 1.0 / r;
    let (lever_i, lever_j, r_eff) = levers(radius_i, radius_j, rolling);
    Geometry {
        n: [del[0] * rinv, del[1] * rinv, del[2] * rinv],
        overlap: (radius_i + radius_j) - r,
        lever_i,
        lever_j,
        r_eff,
    }
}

/// A contact whose unit normal `n` the engine has built, with the centre
/// distance `distance` (for a wall, `radius_j = 0`, the centre's distance
/// from the wall along `n`).
#[inline(always)]
pub fn from_normal(n: [f64; 3], distance: f64, radius_i: f64, radius_j: f64, rolling: bool) -> Geometry {
    let (lever_i, lever_j, r_eff) = levers(radius_i, radius_j, rolling);
    Geometry {
        n,
        overlap: (radius_i + radius_j) - distance,
        lever_i,
        lever_j,
        r_eff,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::{sphere_plane, sphere_sphere, Plane};
    use crate::kinematics::{PairKinematics, SphereKinematics};

    #[test]
    fn a_pair_from_its_separation_is_the_frame_of_its_kinematics_bit_for_bit() {
        let k = PairKinematics {
            x_i: [0.3, -1.7e-3, 2.2e-3],
            x_j: [0.3 + 1.9e-3, -0.4e-3, 1.1e-3],
            radius_i: 1.2e-3,
            radius_j: 1.4e-3,
            ..Default::default()
        };
        let frame = sphere_sphere(&k).unwrap();
        let del = [k.x_i[0] - k.x_j[0], k.x_i[1] - k.x_j[1], k.x_i[2] - k.x_j[2]];
        let rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        let g = from_separation(del, rsq, k.radius_i, k.radius_j, true);
        assert_eq!(g.n, frame.n);
        assert_eq!(g.overlap.to_bits(), frame.overlap.to_bits());
        assert_eq!((g.lever_i, g.lever_j), (frame.lever_i, frame.lever_j));
        assert_eq!(g.r_eff.to_bits(), frame.r_eff.to_bits());
        assert_eq!(
            from_separation(del, rsq, k.radius_i, k.radius_j, false).r_eff,
            0.0
        );
    }

    #[test]
    fn a_wall_is_radius_zero() {
        let sphere = SphereKinematics {
            x: [0.0, 0.0, 0.9e-3],
            radius: 1e-3,
            ..Default::default()
        };
        let plane = Plane {
            normal: [0.0, 0.0, 1.0],
            ..Default::default()
        };
        let frame = sphere_plane(&sphere, &plane);
        let g = from_normal(plane.normal, sphere.x[2], sphere.radius, 0.0, true);
        assert_eq!(g.overlap.to_bits(), frame.overlap.to_bits());
        assert_eq!(
            (g.lever_i, g.lever_j, g.r_eff),
            (frame.lever_i, frame.lever_j, frame.r_eff)
        );
    }
}
