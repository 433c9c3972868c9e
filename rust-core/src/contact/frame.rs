//! The contact frame: the one place where a contact's normal, overlap,
//! levers and `R*` are built, whatever the engine hands over (two spheres'
//! kinematics, a sphere and a plane, the centre separation, or the
//! engine's own normal and distance). A wall is a partner of radius 0: no
//! lever, and `R* = R_i`.

use super::rolling::effective_radius;
use crate::kinematics::{centre_line, KinematicsError, PairKinematics, SphereKinematics};
use crate::vector::{v3, Vec3, Vector};

/// Where and how deep two bodies touch, how far from each centre the
/// contact point lies, and how the bodies move: everything a contact law
/// needs, for a sphere pair or a sphere on a wall alike.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactFrame {
    /// Unit normal from `j` to `i`.
    pub n: [f64; 3],
    /// `delta_n > 0` when touching.
    pub overlap: f64,
    /// Distance from the centre of `i` to the contact point: the arm of the
    /// tangential force's couple on `i`.
    pub lever_i: f64,
    /// The same for `j`; 0 for a wall, which the couple does not turn.
    pub lever_j: f64,
    /// `R*` of the rolling cap; 0 when built for a model without rolling
    /// (it is read nowhere else, so its division is left out).
    pub r_eff: f64,
    /// Velocity of the centre of `i`.
    pub v_i: [f64; 3],
    /// Velocity of the centre of `j` (of a wall, its velocity).
    pub v_j: [f64; 3],
    /// Angular velocity of `i`.
    pub w_i: [f64; 3],
    /// Angular velocity of `j` (zero for a wall).
    pub w_j: [f64; 3],
}

/// How the two bodies of a contact move: the frame's velocities, taken as
/// the engine has them (as arrays, or as the laws' vectors `V`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion<V = [f64; 3]> {
    /// Velocity of the centre of `i`.
    pub v_i: V,
    /// Velocity of the centre of `j` (of a wall, its velocity).
    pub v_j: V,
    /// Angular velocity of `i`.
    pub w_i: V,
    /// Angular velocity of `j` (zero for a wall).
    pub w_j: V,
}

/// [`ContactFrame`] with its vectors as the laws' vectors `V` (`Vec3`, or
/// one register each in the AVX2 step, `contact::dispatch`): what the
/// laws read.
#[derive(Clone, Copy, Debug)]
pub struct FrameIn<V> {
    /// [`ContactFrame::n`].
    pub n: V,
    /// [`ContactFrame::overlap`].
    pub overlap: f64,
    /// [`ContactFrame::lever_i`].
    pub lever_i: f64,
    /// [`ContactFrame::lever_j`].
    pub lever_j: f64,
    /// [`ContactFrame::r_eff`].
    pub r_eff: f64,
    /// [`ContactFrame::v_i`].
    pub v_i: V,
    /// [`ContactFrame::v_j`].
    pub v_j: V,
    /// [`ContactFrame::w_i`].
    pub w_i: V,
    /// [`ContactFrame::w_j`].
    pub w_j: V,
}

/// A plane wall: a point on it, its unit normal towards the particles, and
/// its velocity (walls do not spin).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    /// Any point of the plane.
    pub point: [f64; 3],
    /// Unit normal, pointing to the side the particles are on.
    pub normal: [f64; 3],
    /// Velocity of the wall (it slides or moves as a whole).
    pub velocity: [f64; 3],
}

/// Why a frame handed over whole cannot be used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrameError {
    /// NaN or infinity in the normal, overlap, levers, `R*` or velocities.
    NonFinite,
    /// The normal is not a unit vector; its length.
    NotUnitNormal(f64),
}

impl<V: Copy> FrameIn<V> {
    /// The frame of a contact whose unit normal `n` (from `j` to `i`) is
    /// known, with the centre distance `distance` along it; for a wall
    /// `radius_j = 0` and `distance` is the centre's distance from the
    /// wall. Every other constructor ends here.
    #[inline(always)]
    pub fn from_normal(
        n: V,
        distance: f64,
        radius_i: f64,
        radius_j: f64,
        rolling: bool,
        m: Motion<V>,
    ) -> Self {
        let r_eff = if !rolling {
            0.0
        } else if radius_j == 0.0 {
            effective_radius(radius_i, None)
        } else {
            effective_radius(radius_i, Some(radius_j))
        };
        Self {
            n,
            overlap: (radius_i + radius_j) - distance,
            lever_i: radius_i,
            lever_j: radius_j,
            r_eff,
            v_i: m.v_i,
            v_j: m.v_j,
            w_i: m.w_i,
            w_j: m.w_j,
        }
    }
}

impl<V: Vector<f64>> FrameIn<V> {
    /// A pair from its separation `del = x_i - x_j` and `rsq = |del|^2`:
    /// one square root, one reciprocal for the three normal components, the
    /// operations of [`centre_line`], so the frame of [`sphere_sphere`].
    #[inline(always)]
    pub fn from_separation(
        del: V,
        rsq: f64,
        radius_i: f64,
        radius_j: f64,
        rolling: bool,
        m: Motion<V>,
    ) -> Self {
        let r = rsq.sqrt();
        let rinv = 1.0 / r;
        Self::from_normal(del * rinv, r, radius_i, radius_j, rolling, m)
    }
}

impl From<FrameIn<Vec3>> for ContactFrame {
    #[inline(always)]
    fn from(f: FrameIn<Vec3>) -> Self {
        Self {
            n: f.n.into(),
            overlap: f.overlap,
            lever_i: f.lever_i,
            lever_j: f.lever_j,
            r_eff: f.r_eff,
            v_i: f.v_i.into(),
            v_j: f.v_j.into(),
            w_i: f.w_i.into(),
            w_j: f.w_j.into(),
        }
    }
}

impl<V> Motion<V> {
    /// Each velocity as `f` makes it.
    #[inline(always)]
    pub fn map<W>(self, f: impl Fn(V) -> W) -> Motion<W> {
        Motion {
            v_i: f(self.v_i),
            v_j: f(self.v_j),
            w_i: f(self.w_i),
            w_j: f(self.w_j),
        }
    }
}

impl ContactFrame {
    /// [`FrameIn::from_normal`] with the vectors as arrays.
    #[inline(always)]
    pub fn from_normal(
        n: [f64; 3],
        distance: f64,
        radius_i: f64,
        radius_j: f64,
        rolling: bool,
        m: Motion,
    ) -> Self {
        FrameIn::from_normal(v3(n), distance, radius_i, radius_j, rolling, m.map(v3)).into()
    }

    /// [`FrameIn::from_separation`] with the vectors as arrays.
    #[inline(always)]
    pub fn from_separation(
        del: [f64; 3],
        rsq: f64,
        radius_i: f64,
        radius_j: f64,
        rolling: bool,
        m: Motion,
    ) -> Self {
        FrameIn::from_separation(v3(del), rsq, radius_i, radius_j, rolling, m.map(v3)).into()
    }

    /// The frame with its vectors as `Vec3`, as the laws take it.
    #[inline(always)]
    pub fn vectors(&self) -> FrameIn<Vec3> {
        FrameIn {
            n: v3(self.n),
            overlap: self.overlap,
            lever_i: self.lever_i,
            lever_j: self.lever_j,
            r_eff: self.r_eff,
            v_i: v3(self.v_i),
            v_j: v3(self.v_j),
            w_i: v3(self.w_i),
            w_j: v3(self.w_j),
        }
    }

    /// Refuses a frame a caller built itself: every number finite, and a
    /// unit normal (to round-off).
    pub fn check(&self) -> Result<(), FrameError> {
        let numbers = self
            .n
            .iter()
            .chain(&self.v_i)
            .chain(&self.v_j)
            .chain(&self.w_i)
            .chain(&self.w_j);
        let scalars = [self.overlap, self.lever_i, self.lever_j, self.r_eff];
        if !numbers.chain(scalars.iter()).all(|x| x.is_finite()) {
            return Err(FrameError::NonFinite);
        }
        let len = self.n.iter().map(|c| c * c).sum::<f64>().sqrt();
        if (len - 1.0).abs() > 1e-9 {
            return Err(FrameError::NotUnitNormal(len));
        }
        Ok(())
    }
}

/// The frame of two spheres, after checking their kinematics.
pub fn sphere_sphere(kin: &PairKinematics) -> Result<ContactFrame, KinematicsError> {
    kin.check()?;
    let line = centre_line(kin)?;
    if line.r == f64::INFINITY {
        // n = d / inf would be 0: no direction
        return Err(KinematicsError::DistanceOverflows);
    }
    let motion = Motion {
        v_i: kin.v_i,
        v_j: kin.v_j,
        w_i: kin.w_i,
        w_j: kin.w_j,
    };
    Ok(ContactFrame::from_normal(
        line.n.into(),
        line.r,
        kin.radius_i,
        kin.radius_j,
        true,
        motion,
    ))
}

/// The frame of a sphere on a plane wall (unchecked: the plane's normal
/// must be a unit vector).
pub fn sphere_plane(sphere: &SphereKinematics, plane: &Plane) -> ContactFrame {
    let gap = (v3(sphere.x) - v3(plane.point)).dot(&v3(plane.normal));
    let motion = Motion {
        v_i: sphere.v,
        v_j: plane.velocity,
        w_i: sphere.w,
        w_j: [0.0; 3],
    };
    ContactFrame::from_normal(plane.normal, gap, sphere.radius, 0.0, true, motion)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn still() -> Motion {
        Motion::default()
    }

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
        let g = ContactFrame::from_separation(del, rsq, k.radius_i, k.radius_j, true, still());
        assert_eq!(g.n, frame.n);
        assert_eq!(g.overlap.to_bits(), frame.overlap.to_bits());
        assert_eq!((g.lever_i, g.lever_j), (frame.lever_i, frame.lever_j));
        assert_eq!(g.r_eff.to_bits(), frame.r_eff.to_bits());
        assert_eq!(
            ContactFrame::from_separation(del, rsq, k.radius_i, k.radius_j, false, still()).r_eff,
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
        let g = ContactFrame::from_normal(plane.normal, sphere.x[2], sphere.radius, 0.0, true, still());
        assert_eq!(g.overlap.to_bits(), frame.overlap.to_bits());
        assert_eq!(
            (g.lever_i, g.lever_j, g.r_eff),
            (frame.lever_i, frame.lever_j, frame.r_eff)
        );
    }

    #[test]
    fn a_frame_is_refused_for_a_non_finite_number_or_a_normal_off_unit_length() {
        let good = sphere_sphere(&PairKinematics {
            x_j: [-1.9e-3, 0.0, 0.0],
            radius_i: 1e-3,
            radius_j: 1e-3,
            ..Default::default()
        })
        .unwrap();
        assert_eq!(good.check(), Ok(()));
        let mut bad = good;
        bad.w_j[1] = f64::NAN;
        assert_eq!(bad.check(), Err(FrameError::NonFinite));
        let mut bad = good;
        bad.n = [0.0, 0.6, 0.0];
        assert!(matches!(bad.check(), Err(FrameError::NotUnitNormal(len)) if (len - 0.6).abs() < 1e-15));
    }
}
