//! Command-line scene runner: runs the models without an engine and writes
//! CSV (and VTK snapshots for the agglomerate).
//!
//!     cargo run --release -p granbond-scene --example scene -- agglomerate OUT_DIR [--steps N] [--speed V]
//!     cargo run --release -p granbond-scene --example scene -- cycle OUT_DIR
//!     cargo run --release -p granbond-scene --example scene -- collision OUT_DIR
//!
//! Progress goes to stderr; a summary line with the output files at the end.

use granbond::bond::{BondModel, BondParams};
use granbond::contact::{Plane, VoigtModel, VoigtParams};
use granbond::kinematics::PairKinematics;
use granbond::vector::Vec3;
use granbond_scene::builders::lattice_ball;
use granbond_scene::csv::CsvWriter;
use granbond_scene::vtk::write_snapshot;
use granbond_scene::{Scene, Sphere};
use std::fs::{self, File};
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use std::time::Instant;

const RADIUS: f64 = 1e-3;
const DENSITY: f64 = 2500.0;

/// A cemented-grain bond: E/L ~ 5e10 N/m^3 in tension, square-root law in
/// compression matched to it at 1e-5 m, ku = 2k, kc = k/10, 5e5 Pa strengths.
fn agglomerate_bond() -> BondParams {
    let (k_n2, k_s) = (5e10, 2e10);
    let k_n1 = k_n2 * 1e-5 / 1e-5f64.sqrt();
    BondParams {
        lambda: 1.0,
        k_fn1: k_n1,
        ku_fn1: 2.0 * k_n1,
        kc_fn1: 0.1 * k_n1,
        k_fn2: k_n2,
        ku_fn2: 2.0 * k_n2,
        kc_fn2: 0.1 * k_n2,
        k_ft: k_s,
        k_tn: k_s,
        ku_tn: 2.0 * k_s,
        kc_tn: 0.1 * k_s,
        k_tt: k_s,
        ku_tt: 2.0 * k_s,
        kc_tt: 0.1 * k_s,
        eta_fn: 0.1,
        eta_ft: 0.1,
        eta_tn: 0.1,
        eta_tt: 0.1,
        stress_break: 1,
        max_sigma: 5e5,
        max_tau: 5e5,
        create_distance: 2.05 * RADIUS,
        create_step: 0,
        ..BondParams::default()
    }
}

fn arg_value(args: &[String], flag: &str, default: f64) -> f64 {
    args.iter()
        .position(|a| a == flag)
        .and_then(|i| args.get(i + 1))
        .map(|v| {
            v.parse()
                .unwrap_or_else(|_| panic!("{flag} needs a number, got {v}"))
        })
        .unwrap_or(default)
}

fn agglomerate(out: &Path, args: &[String]) -> std::io::Result<Vec<PathBuf>> {
    let speed = arg_value(args, "--speed", 3.0);
    let ball = arg_value(args, "--ball-radius", 16.0) * RADIUS;
    let mut scene = Scene::new(1.0);
    let count = lattice_ball(
        &mut scene,
        Vec3::new(0.0, 0.0, ball + 0.5 * RADIUS),
        ball,
        RADIUS,
        DENSITY,
    );
    for s in &mut scene.spheres {
        s.body.v = Vec3::new(0.0, 0.0, -speed);
    }
    let bond = BondModel::new(agglomerate_bond()).expect("valid bond parameters");
    let contact = VoigtModel::new(VoigtParams {
        k_n: 1e5,
        k_t: 6e4,
        gamma_n: 5e-3,
        ..VoigtParams::default()
    })
    .expect("valid contact parameters");
    let mass = scene.spheres[0].body.mass;
    let dt_crit = bond
        .critical_timestep(RADIUS, RADIUS, mass, mass)
        .min(contact.critical_timestep(RADIUS, RADIUS, mass, mass));
    scene.dt = 0.2 * dt_crit;
    scene.bond_model = Some(bond);
    scene.contact_model = Some(contact);
    scene.planes.push(Plane {
        point: [0.0; 3],
        normal: [0.0, 0.0, 1.0],
        velocity: [0.0; 3],
    });
    let created = scene.create_bonds().expect("bonds form");
    let duration = arg_value(args, "--duration", 4e-3);
    let steps = (duration / scene.dt).ceil() as i64;
    eprintln!(
        "agglomerate: {count} spheres, {created} bonds, impact at {speed} m/s, dt = {:.3e} s (0.2 x critical), {steps} steps",
        scene.dt
    );
    let history_path = out.join("agglomerate.csv");
    let mut history = CsvWriter::new(
        BufWriter::new(File::create(&history_path)?),
        &[
            "time",
            "intact",
            "broken_tension",
            "broken_compression",
            "broken_shear",
            "contacts",
            "kinetic_energy",
        ],
    )?;
    let snapshots = out.join("vtk");
    fs::create_dir_all(&snapshots)?;
    let (mut tension, mut compression, mut shear) = (0usize, 0usize, 0usize);
    let started = Instant::now();
    let every = (steps / 200).max(1);
    for k in 0..=steps {
        let report = scene.advance().expect("the scene stays finite");
        tension += report.broken_by_tension;
        compression += report.broken_by_compression;
        shear += report.broken_by_shear;
        if k % every == 0 {
            history.row(&[
                scene.time(),
                scene.intact_bonds() as f64,
                tension as f64,
                compression as f64,
                shear as f64,
                report.contacts as f64,
                scene.kinetic_energy(),
            ])?;
        }
        if k % (steps / 20).max(1) == 0 {
            write_snapshot(&scene, &snapshots.join(format!("agglomerate_{:06}.vtk", k)))?;
            eprintln!(
                "  step {k:>7}/{steps}  t = {:.3e} s  intact bonds {:>6}  broken {:>6}  [{:.1} s]",
                scene.time(),
                scene.intact_bonds(),
                tension + compression + shear,
                started.elapsed().as_secs_f64()
            );
        }
    }
    let fragments_path = out.join("fragments.csv");
    let mut fragments = CsvWriter::new(BufWriter::new(File::create(&fragments_path)?), &["size"])?;
    for size in scene.fragment_sizes() {
        fragments.row(&[size as f64])?;
    }
    Ok(vec![history_path, fragments_path, snapshots])
}

/// Prescribed load/unload/reload of two bonded spheres (normal law only).
fn cycle(out: &Path) -> std::io::Result<Vec<PathBuf>> {
    let p = BondParams {
        shear: 0,
        twist: 0,
        bend: 0,
        damping: 0,
        ..agglomerate_bond()
    };
    let bond = BondModel::new(BondParams { stress_break: 0, ..p }).expect("valid");
    let r0 = 2.0 * RADIUS;
    let mut state = granbond::bond::BondState::created(r0);
    let path_points = [0.0, 2e-5, -4e-6, 1e-5, -8e-6, 4e-5];
    let file = out.join("cycle.csv");
    let mut csv = CsvWriter::new(BufWriter::new(File::create(&file)?), &["delta", "normal_force"])?;
    for w in path_points.windows(2) {
        for k in 0..=400 {
            let delta = w[0] + (w[1] - w[0]) * k as f64 / 400.0;
            let kin = PairKinematics {
                x_i: [r0 - delta, 0.0, 0.0],
                radius_i: RADIUS,
                radius_j: RADIUS,
                ..PairKinematics::default()
            };
            let mut o = Default::default();
            bond.step(&kin, 1e-7, &mut state, &mut o).expect("finite");
            csv.row(&[delta, o.normal_force])?;
        }
    }
    Ok(vec![file])
}

/// Head-on Voigt collision of two spheres: trajectories for the plot.
fn collision(out: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut scene = Scene::new(1e-8);
    let mut a = Sphere::new(Vec3::zeros(), RADIUS, DENSITY);
    let mut b = Sphere::new(Vec3::new(2.0 * RADIUS + 1e-6, 0.0, 0.0), RADIUS, DENSITY);
    a.body.v = Vec3::new(0.05, 0.0, 0.0);
    b.body.v = Vec3::new(-0.05, 0.0, 0.0);
    scene.spheres = vec![a, b];
    scene.contact_model = Some(
        VoigtModel::new(VoigtParams {
            gamma_n: 2e-2,
            ..VoigtParams::default()
        })
        .unwrap(),
    );
    let file = out.join("collision.csv");
    let mut csv = CsvWriter::new(
        BufWriter::new(File::create(&file)?),
        &["time", "overlap", "relative_velocity"],
    )?;
    for _ in 0..20_000 {
        scene.advance().expect("finite");
        let (x, y) = (&scene.spheres[0].body, &scene.spheres[1].body);
        csv.row(&[scene.time(), 2.0 * RADIUS - (y.x.x - x.x.x), y.v.x - x.v.x])?;
    }
    Ok(vec![file])
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage =
        "usage: scene (agglomerate|cycle|collision) OUT_DIR [--speed V] [--ball-radius RADII] [--duration S]";
    let (Some(which), Some(dir)) = (args.get(1), args.get(2)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let out = PathBuf::from(dir);
    fs::create_dir_all(&out).expect("create the output directory");
    let written = match which.as_str() {
        "agglomerate" => agglomerate(&out, &args[3..]),
        "cycle" => cycle(&out),
        "collision" => collision(&out),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    }
    .expect("write the results");
    for f in written {
        println!("wrote {}", f.display());
    }
}
