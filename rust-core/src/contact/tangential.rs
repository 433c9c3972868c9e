//! Cundall-Strack tangential history.

use super::vectors::ContactVector;
use crate::vector::tangential_part;

/// Turns the stored spring into the current tangent plane, keeping its
/// length (the contact frame has rotated since the last step).
///
/// The rescale after the projection multiplies the length by
/// `sqrt(1 + s^2 / |p|^2)` (`s`: the part along `n`, `p`: the projection).
/// Where `s^2 <= eps |p|^2` that factor is 1 to within half an ulp, so it is
/// left out: the result is the same to round-off, and a contact whose frame
/// has hardly turned (a packing at rest) skips a division and a square root
/// that stood on its critical path.
#[inline(always)]
pub fn carry_spring<V: ContactVector>(spring: V, n: V) -> V {
    let along = spring.dot(&n);
    let projected = tangential_part(spring, n);
    let after = projected.norm_squared();
    if along * along <= f64::EPSILON * after || !(after > 0.0) {
        return projected;
    }
    projected * (spring.norm_squared() / after).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::Vec3;
    use proptest::prelude::*;

    fn unit(v: Vec3) -> Vec3 {
        v / v.norm()
    }

    proptest! {
        /// In the plane, of the same length to round-off, whether or not the
        /// rescale is left out (angles from 1e-12 to 1 rad).
        #[test]
        fn carried_spring_lies_in_the_plane_with_its_length(
            x in -1.0..1.0f64, y in -1.0..1.0f64, z in -1.0..1.0f64,
            length in 1e-9..1e3f64, log_angle in -12.0..0.0f64, turn in 0.0..std::f64::consts::TAU,
        ) {
            let n = unit(Vec3::new(x, y, z + 2.0));
            let helper = if n.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
            let e1 = unit(n.cross(&helper));
            let e2 = n.cross(&e1);
            let in_plane = e1 * turn.cos() + e2 * turn.sin();
            let angle = 10f64.powf(log_angle);
            let spring = (in_plane * angle.cos() + n * angle.sin()) * length;
            let carried = carry_spring(spring, n);
            prop_assert!((carried.norm() - spring.norm()).abs() <= 4.0 * f64::EPSILON * spring.norm(),
                "length {} -> {}", spring.norm(), carried.norm());
            prop_assert!(carried.dot(&n).abs() <= 4.0 * f64::EPSILON * length);
        }
    }

    #[test]
    fn a_spring_along_the_normal_or_zero_is_dropped() {
        let n = Vec3::z();
        assert_eq!(carry_spring(Vec3::new(0.0, 0.0, 2.0), n), Vec3::zeros());
        assert_eq!(carry_spring(Vec3::zeros(), n), Vec3::zeros());
    }

    /// Tilted out of the plane by 1e-9 to 0.5 rad: back in the plane, with
    /// its length.
    #[test]
    fn a_turned_spring_keeps_its_length() {
        let n = Vec3::z();
        for angle in [1e-9f64, 1e-6, 1e-3, 0.5] {
            let spring = Vec3::new(angle.cos(), 0.0, angle.sin()) * 3.0;
            let carried = carry_spring(spring, n);
            assert_eq!(carried.z, 0.0);
            assert!(
                (carried.norm() - 3.0).abs() <= 4.0 * f64::EPSILON * 3.0,
                "{angle}: {}",
                carried.norm()
            );
        }
    }
}
