//! Starting geometries: a pair, a straight chain, a ball of spheres on a
//! cubic lattice.

use super::runner::{Scene, Sphere};
use granbond::vector::Vec3;

/// Two spheres on the x axis, centres `distance` apart, sphere 0 at the origin.
pub fn pair(scene: &mut Scene, radius: f64, density: f64, distance: f64) {
    scene.spheres.push(Sphere::new(Vec3::zeros(), radius, density));
    scene
        .spheres
        .push(Sphere::new(Vec3::new(distance, 0.0, 0.0), radius, density));
}

/// `count` touching spheres along x from the origin.
pub fn chain(scene: &mut Scene, count: usize, radius: f64, density: f64) {
    for k in 0..count {
        scene.spheres.push(Sphere::new(
            Vec3::new(2.0 * radius * k as f64, 0.0, 0.0),
            radius,
            density,
        ));
    }
}

/// Touching spheres on a simple cubic lattice inside a ball of radius
/// `ball_radius` centred at `centre`. Returns how many were added.
pub fn lattice_ball(scene: &mut Scene, centre: Vec3, ball_radius: f64, radius: f64, density: f64) -> usize {
    let spacing = 2.0 * radius;
    let reach = ((ball_radius - radius) / spacing).floor() as i64;
    let before = scene.spheres.len();
    for a in -reach..=reach {
        for b in -reach..=reach {
            for c in -reach..=reach {
                let offset = Vec3::new(a as f64, b as f64, c as f64) * spacing;
                if offset.norm() + radius <= ball_radius {
                    scene.spheres.push(Sphere::new(centre + offset, radius, density));
                }
            }
        }
    }
    scene.spheres.len() - before
}
