//! The step limits of bonded packings, in the crate's scene runner.
//!
//! - `BondModel::coordinated_timestep`: below it, lattices with 6, 12 and 18
//!   bonds per sphere stay bounded.
//! - `BondModel::rattle_timestep`: a bonded block at rest whose bonds break
//!   in compression keeps every bond at the recommended step (which the
//!   rattle sets), and loses bonds well above it.
//! - The assemblies of the stability map (`sweep::ASSEMBLIES`): no run
//!   breaks a bond or blows up below the step the engines warn at.

use granbond::bond::{BondModel, BondParams};
use granbond::vector::Vec3;
use granbond_scene::reference::{study_bond, Noise, DENSITY, RADIUS};
use granbond_scene::runner::{Scene, Sphere};
use granbond_scene::sweep::{Verdict, ASSEMBLIES};

/// The lattices: centres and the creation distance that bonds the wanted
/// neighbours (spheres of radius `RADIUS`, nearest neighbours touching).
#[derive(Clone, Copy, Debug)]
enum Lattice {
    /// Simple cubic, nearest neighbours: 6 bonds.
    Cubic,
    /// Face-centred cubic, nearest neighbours: 12 bonds.
    FaceCentred,
    /// Simple cubic, nearest and second neighbours (2 sqrt(2) R): 18 bonds.
    CubicSecond,
}

impl Lattice {
    fn bonds_per_sphere(self) -> usize {
        match self {
            Lattice::Cubic => 6,
            Lattice::FaceCentred => 12,
            Lattice::CubicSecond => 18,
        }
    }

    /// Between the last bonded neighbour shell and the next one.
    fn create_distance(self) -> f64 {
        match self {
            Lattice::Cubic | Lattice::FaceCentred => 2.2 * RADIUS, // next shell 2.83 R
            Lattice::CubicSecond => 3.1 * RADIUS,                  // next shell 3.46 R
        }
    }

    fn centres(self, cells: usize) -> Vec<Vec3> {
        let d = 2.0 * RADIUS;
        let (spacing, basis): (f64, &[[f64; 3]]) = match self {
            Lattice::Cubic | Lattice::CubicSecond => (d, &[[0.0, 0.0, 0.0]]),
            Lattice::FaceCentred => (
                d * std::f64::consts::SQRT_2,
                &[[0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.5, 0.0, 0.5], [0.0, 0.5, 0.5]],
            ),
        };
        let mut out = Vec::new();
        for a in 0..cells {
            for b in 0..cells {
                for c in 0..cells {
                    for o in basis {
                        out.push(Vec3::new(a as f64 + o[0], b as f64 + o[1], c as f64 + o[2]) * spacing);
                    }
                }
            }
        }
        out
    }
}

fn mass() -> f64 {
    DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3)
}

/// A bonded lattice with random velocities and spins of scale `speed`,
/// bonds created in the first step.
fn bonded(lattice: Lattice, cells: usize, params: BondParams, dt: f64, speed: f64, seed: u64) -> Scene {
    let mut scene = Scene::new(dt);
    let mut noise = Noise::new(seed);
    for x in lattice.centres(cells) {
        let mut s = Sphere::new(x, RADIUS, DENSITY);
        s.body.v = noise.vector() * speed;
        s.body.w = noise.vector() * (speed / RADIUS);
        scene.spheres.push(s);
    }
    scene.bond_model = Some(
        BondModel::new(BondParams {
            create_distance: lattice.create_distance(),
            create_step: 0,
            ..params
        })
        .expect("valid bond parameters"),
    );
    scene
}

fn most_bonds_on_one_sphere(scene: &Scene) -> usize {
    let mut count = vec![0usize; scene.spheres.len()];
    for b in &scene.bonds {
        count[b.i] += 1;
        count[b.j] += 1;
    }
    count.into_iter().max().unwrap_or(0)
}

/// Largest total energy (kinetic + bond) over the first step's, NaN when
/// the run blew up.
fn energy_gain(scene: &mut Scene, steps: usize) -> f64 {
    let energy = |s: &Scene| s.kinetic_energy() + s.bond_energy();
    scene.advance().expect("first step");
    let start = energy(scene);
    let mut peak = start;
    for _ in 1..steps {
        if scene.advance().is_err() {
            return f64::NAN;
        }
        let e = energy(scene);
        if !e.is_finite() {
            return f64::NAN;
        }
        peak = peak.max(e);
    }
    peak / start
}

#[test]
fn lattices_stay_bounded_below_the_coordinated_step() {
    // elastic bonds, regularised: every law has a bounded stiffness, which
    // the bound assumes
    let params = BondParams {
        compression_linear_below: 1e-3 * 0.5 * RADIUS,
        ..study_bond(false)
    };
    let model = BondModel::new(params).unwrap();
    let m = mass();
    let critical = model.critical_timestep(RADIUS, RADIUS, m, m);
    for (lattice, cells) in [
        (Lattice::Cubic, 4),
        (Lattice::FaceCentred, 2),
        (Lattice::CubicSecond, 4),
    ] {
        let z = lattice.bonds_per_sphere();
        let limit = model.coordinated_timestep(RADIUS, RADIUS, m, m, z as u32);
        assert!(limit < critical, "{lattice:?}: {limit} vs one bond {critical}");
        let dt = 0.95 * limit;
        let mut scene = bonded(lattice, cells, params, dt, 0.1, 7);
        let gain = energy_gain(&mut scene, 1000);
        assert_eq!(most_bonds_on_one_sphere(&scene), z, "{lattice:?}");
        // bounded, as the stability sweep classifies it (docs/speed-accuracy.md):
        // finite, and the energy never ten times its start
        assert!(
            gain < 10.0,
            "{lattice:?}, {z} bonds per sphere, dt = 0.95 x {limit:e} s ({:.3} of the one-bond critical step): \
             energy x{gain}",
            dt / critical
        );
    }
}

#[test]
fn the_coordinated_step_falls_as_one_over_the_root_of_the_bond_count() {
    let model = BondModel::new(study_bond(true)).unwrap();
    let m = mass();
    let one = model.coordinated_timestep(RADIUS, RADIUS, m, m, 1);
    assert!(one <= model.critical_timestep(RADIUS, RADIUS, m, m));
    for z in [4u32, 6, 12, 18] {
        let limit = model.coordinated_timestep(RADIUS, RADIUS, m, m, z);
        assert!((limit * f64::from(z).sqrt() / one - 1.0).abs() < 1e-12);
    }
    // the recommended step covers the densest monodisperse packing
    let modes = model.mode_limits(RADIUS, RADIUS, m, m);
    assert!(modes.bonds_covered(model.recommended_timestep(RADIUS, RADIUS, m, m)) >= 12);
}

#[test]
fn a_block_at_rest_keeps_its_bonds_at_the_recommended_step() {
    let m = mass();
    let plain = ASSEMBLIES[0];
    assert!(!plain.falling && !plain.regularised);
    let model = BondModel::new(plain.bond()).unwrap();
    let recommended = model.recommended_timestep(RADIUS, RADIUS, m, m);
    let rattle = model.rattle_timestep(RADIUS, RADIUS, m, m);
    assert_eq!(recommended, rattle, "the rattle sets the step of this block");
    let f = recommended / plain.critical();
    assert_eq!(plain.run(4, 0.95 * f, 2000).broken, 0);
    // well above it the rattle breaks bonds that nothing loads
    assert!(plain.run(4, 4.0 * f, 2000).broken > 0);
    // the regularised law has no rattle: the step is the critical one's
    // fraction, and the block stays intact at it
    let regular = ASSEMBLIES[2];
    assert!(!regular.falling && regular.regularised);
    let model = BondModel::new(regular.bond()).unwrap();
    assert!(model.rattle_timestep(RADIUS, RADIUS, m, m).is_infinite());
    let step = model.recommended_timestep(RADIUS, RADIUS, m, m);
    assert!(step > 2.0 * recommended);
    assert_eq!(regular.run(4, step / regular.critical(), 2000).broken, 0);
}

#[test]
fn no_assembly_goes_silently_wrong() {
    // the map of docs/speed-accuracy.md on a coarse grid: a bond broken or
    // a run blown up is always above the step the engines warn at
    for a in ASSEMBLIES {
        for f in [0.05, 0.2, 0.5, 1.0] {
            let case = a.run(3, f, 1000);
            assert_ne!(
                case.verdict,
                Verdict::SilentlyWrong,
                "{} at {f} dt_c: {case:?}",
                a.name
            );
        }
    }
}
