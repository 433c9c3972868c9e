//! Speed vs accuracy study (issue 4, docs/speed-accuracy.md): error of each
//! reference scene's quantity against the step and the model variant, the
//! cost of each, the stability sweep, and the kernels' cost per bond-step.
//!
//!     cargo run --release -p granbond-scene --example study -- OUT_DIR [--quick] [--repeat N]
//!
//! Writes CSV files into OUT_DIR (docs/plots.py turns them into PNGs; the
//! one command is docs/make-figures.sh). Wall times are the minimum of
//! `--repeat` runs (default 3): the machine is shared, so a single timing is
//! noise. `--quick` runs a coarse grid (a smoke test, a minute).

use granbond::bond::{BondModel, BondOutput, BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond_scene::csv::CsvWriter;
use granbond_scene::reference::*;
use granbond_scene::sweep::{self, Setup, Verdict};
use granbond_scene::SceneError;
use std::fs::{self, File};
use std::io::{BufWriter, Write};
use std::path::Path;
use std::time::Instant;

type Csv = CsvWriter<BufWriter<File>>;

fn csv(dir: &Path, name: &str, header: &[&str]) -> Csv {
    CsvWriter::new(
        BufWriter::new(File::create(dir.join(name)).expect("create csv")),
        header,
    )
    .expect("write")
}

/// `delta_eps = 1e-3 rb` for the default section (rb = 0.5 mm).
const EPS: f64 = 5e-7;

/// The model variants of the study, as switches over a base parameter set.
fn variants(base: BondParams) -> Vec<(&'static str, BondParams)> {
    let damped = BondParams {
        damping: 1,
        eta_fn: 0.1,
        eta_ft: 0.1,
        eta_tn: 0.1,
        eta_tt: 0.1,
        ..base
    };
    vec![
        ("full 6-DOF", base),
        ("no twist", BondParams { twist: 0, ..base }),
        (
            "normal+shear (no twist/bend)",
            BondParams {
                twist: 0,
                bend: 0,
                ..base
            },
        ),
        (
            "normal only",
            BondParams {
                shear: 0,
                twist: 0,
                bend: 0,
                ..base
            },
        ),
        ("full + damping 0.1", damped),
        (
            "full + smooth damping 0.1",
            BondParams {
                damping_smooth: 1,
                ..damped
            },
        ),
    ]
}

fn critical(p: BondParams) -> f64 {
    let m = sphere_mass(RADIUS, DENSITY);
    BondModel::new(p).unwrap().critical_timestep(RADIUS, RADIUS, m, m)
}

/// Minimum wall time over `repeat` runs (one when a run takes over 2 s).
fn timed(repeat: usize, mut f: impl FnMut() -> Result<Run, SceneError>) -> Option<Run> {
    let mut best: Option<Run> = None;
    for _ in 0..repeat {
        let run = f().ok()?;
        let slow = run.seconds > 2.0;
        if best.is_none_or(|b| run.seconds < b.seconds) {
            best = Some(run);
        }
        if slow {
            break;
        }
    }
    best
}

struct Study {
    out: Csv,
    repeat: usize,
}

impl Study {
    fn row(&mut self, scene: &str, variant: &str, fraction: f64, run: Option<Run>, exact: f64) {
        let (error, cost, steps) = match run {
            Some(r) => ((r.value / exact - 1.0).abs(), r.cost(), r.steps as f64),
            None => (f64::NAN, f64::NAN, 0.0),
        };
        // A quantity that could not be measured (no oscillation) is an
        // error of 100%.
        let error = if error.is_finite() { error } else { 1.0 };
        eprintln!(
            "  {scene:<12} {variant:<30} dt/dt_c {fraction:<7.0e} error {error:.3e}  cost {cost:.3e} s/s"
        );
        self.out
            .row(&[scene_id(scene), variant_id(variant), fraction, error, cost, steps])
            .expect("write");
    }
}

const SCENES: [&str; 5] = ["tension", "sqrt", "cantilever", "cantilever-EB", "energy"];

fn scene_id(s: &str) -> f64 {
    SCENES.iter().position(|x| *x == s).unwrap() as f64
}

const VARIANTS: [&str; 9] = [
    "full 6-DOF",
    "no twist",
    "normal+shear (no twist/bend)",
    "normal only",
    "full + damping 0.1",
    "full + smooth damping 0.1",
    "delta_eps = 1e-4 rb",
    "delta_eps = 1e-3 rb",
    "delta_eps = 1e-2 rb",
];

fn variant_id(s: &str) -> f64 {
    VARIANTS.iter().position(|x| *x == s).unwrap() as f64
}

fn accuracy(dir: &Path, quick: bool, repeat: usize) {
    let mut study = Study {
        out: csv(
            dir,
            "accuracy.csv",
            &[
                "scene",
                "variant",
                "dt_fraction",
                "error",
                "wall_per_sim_second",
                "steps",
            ],
        ),
        repeat,
    };
    let fractions: Vec<f64> = if quick {
        vec![1e-2, 0.1, 0.4, 1.0]
    } else {
        vec![1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.2, 0.4, 0.7, 1.0]
    };
    let plain = study_bond(false);
    let dt_c = critical(plain);
    eprintln!("accuracy: dt_c = {dt_c:.4e} s (elastic study bond, plain square root)");

    // Linear tension oscillator: every variant (the motion is axial, so the
    // other parts cost time but change nothing unless damped).
    for (name, p) in variants(plain) {
        let osc = TensionOscillator::new(p);
        for &f in &fractions {
            let run = timed(study.repeat, || osc.run(f * dt_c, 4));
            study.row("tension", name, f, run, osc.period());
        }
    }

    // Square-root oscillator (amplitude 0.04 rb): the plain law and three
    // regularisations (the accuracy cost of delta_eps).
    for (name, eps) in [
        ("full 6-DOF", 0.0),
        ("delta_eps = 1e-4 rb", 0.1 * EPS),
        ("delta_eps = 1e-3 rb", EPS),
        ("delta_eps = 1e-2 rb", 10.0 * EPS),
    ] {
        let p = BondParams {
            compression_linear_below: eps,
            ..plain
        };
        let exact = SqrtOscillator::new(plain, 2e-5).period();
        let osc = SqrtOscillator::new(p, 2e-5);
        for &f in &fractions {
            let run = timed(study.repeat, || osc.run(f * dt_c, 4));
            study.row("sqrt", name, f, run, exact);
        }
    }

    // Cantilever (6 bonds, delta_eps = 1e-3 rb): first frequency against the
    // chain's eigenvalue (integration error) and Euler-Bernoulli (model).
    let regularised = BondParams {
        compression_linear_below: EPS,
        ..plain
    };
    let dt_c_reg = critical(regularised);
    let beam_fractions: Vec<f64> = fractions.iter().copied().filter(|f| *f >= 1e-2).collect();
    for (name, p) in variants(regularised) {
        let c = Cantilever::new(p, 6);
        let reference = Cantilever::new(regularised, 6);
        let (omega, _) = reference.chain_mode();
        let eb = reference.euler_bernoulli_frequency();
        for &f in &beam_fractions {
            let run = timed(study.repeat, || c.ring(f * dt_c_reg, 2));
            study.row("cantilever", name, f, run, omega);
            study.row("cantilever-EB", name, f, run, eb);
        }
    }

    // Energy of an undamped free cluster (7 spheres, 6 bonds): the
    // variants without damping (damping is meant to lose energy).
    for (name, p) in variants(regularised).into_iter().take(4) {
        for &f in &beam_fractions {
            let dt = f * dt_c_reg;
            let steps = (200.0 * dt_c_reg / dt) as u64;
            let run = timed(study.repeat, || {
                energy_error(&mut free_cluster(p, dt, 3.0, 0.01, 1), steps)
            });
            // Store the drift itself as the error: exact = 1 and value = 1 + drift.
            let run = run.map(|r| Run {
                value: 1.0 + r.value,
                ..r
            });
            study.row("energy", name, f, run, 1.0);
        }
    }
}

/// Nanoseconds per bond-step of each kernel variant: a batch of 1024 bonds
/// with small random deformations, stepped for ~0.2 s, minimum of `repeat`.
fn kernel_cost(dir: &Path, repeat: usize) {
    let mut out = csv(dir, "kernel_cost.csv", &["variant", "ns_per_bond_step"]);
    let base = study_bond(true);
    let mut all = variants(base);
    // The full kernel with the twisting and bending parts zeroed, not off.
    all.push((
        "full, twist/bend stiffness 0",
        BondParams {
            k_tn: 0.0,
            ku_tn: 0.0,
            kc_tn: 0.0,
            k_tt: 0.0,
            ku_tt: 0.0,
            kc_tt: 0.0,
            ..base
        },
    ));
    let mut noise = Noise::new(3);
    let kin: Vec<PairKinematics> = (0..1024)
        .map(|_| PairKinematics {
            x_i: (granbond::vector::Vec3::new(2.0 * RADIUS, 0.0, 0.0) + noise.vector() * 1e-6).into(),
            x_j: [0.0; 3],
            v_i: (noise.vector() * 0.01).into(),
            w_i: (noise.vector() * 10.0).into(),
            w_j: (noise.vector() * 10.0).into(),
            radius_i: RADIUS,
            radius_j: RADIUS,
            ..PairKinematics::default()
        })
        .collect();
    eprintln!("kernel cost (ns per bond-step, min of {repeat}):");
    for (id, (name, p)) in all.iter().enumerate() {
        let model = BondModel::new(*p).unwrap();
        let mut states = vec![BondState::created(2.0 * RADIUS); kin.len()];
        let mut outs = vec![BondOutput::default(); kin.len()];
        let mut best = f64::INFINITY;
        for _ in 0..repeat {
            let started = Instant::now();
            let mut calls = 0u64;
            while started.elapsed().as_secs_f64() < 0.2 {
                model.step_batch(&kin, 1e-8, &mut states, &mut outs).unwrap();
                calls += 1;
            }
            let ns = started.elapsed().as_secs_f64() * 1e9 / (calls as f64 * kin.len() as f64);
            best = best.min(ns);
        }
        std::hint::black_box(&outs);
        eprintln!("  {name:<32} {best:6.1}");
        out.row(&[id as f64, best]).unwrap();
    }
    let mut names = File::create(dir.join("kernel_cost_names.txt")).unwrap();
    for (name, _) in &all {
        writeln!(names, "{name}").unwrap();
    }
}

/// The stability sweep over six decades (half-decade grid), overlaps, the
/// coordinated-sphere step limit, and degenerate inputs.
fn stability(dir: &Path, quick: bool) {
    let steps = if quick { 500 } else { 5000 };
    let base = Setup::defaults(steps);
    let mut out = csv(
        dir,
        "sweep.csv",
        &["parameter", "log10_factor", "verdict", "flagged", "energy_gain"],
    );
    let exps: Vec<f64> = if quick {
        vec![-3.0, -1.0, 0.0, 1.0, 3.0]
    } else {
        (0..=12).map(|k| -3.0 + 0.5 * k as f64).collect()
    };
    let mut counts = [0usize; 3];
    let mut notes = File::create(dir.join("sweep_notes.txt")).unwrap();
    for (id, parameter) in sweep::PARAMETERS.iter().enumerate() {
        for &e in &exps {
            let case = if *parameter == "overlap / R" {
                sweep::run_overlap(&base, 10f64.powf(-15.0 + 14.0 * (e + 3.0) / 6.0))
            } else {
                sweep::run(&base, parameter, 10f64.powf(e))
            };
            let v = case.verdict as usize;
            counts[v] += 1;
            writeln!(
                notes,
                "{:<22} x{:<9.2e} {:?}: {}",
                parameter, case.factor, case.verdict, case.note
            )
            .unwrap();
            out.row(&[
                id as f64,
                case.factor.log10(),
                v as f64,
                case.flagged as u8 as f64,
                case.energy_gain,
            ])
            .unwrap();
        }
    }
    for case in sweep::degenerate_inputs(&base) {
        counts[case.verdict as usize] += 1;
        writeln!(notes, "{:<22} {:?}: {}", case.parameter, case.verdict, case.note).unwrap();
    }
    eprintln!(
        "sweep: {} stable, {} detected and reported, {} silently wrong",
        counts[Verdict::Stable as usize],
        counts[Verdict::Detected as usize],
        counts[Verdict::SilentlyWrong as usize]
    );

    // The step limit of a sphere with six bonds, against the estimate.
    let mut lim = csv(dir, "coordination.csv", &["bond", "dt_fraction", "energy_gain"]);
    let elastic = Setup {
        params: BondParams {
            compression_linear_below: EPS,
            ..study_bond(false)
        },
        ..base
    };
    for (id, setup) in [base, elastic].iter().enumerate() {
        let mut s = *setup;
        s.dt = critical(s.params);
        s.steps = if quick { 2000 } else { 20_000 };
        for k in 0..=16 {
            let f = 0.2 + 0.05 * k as f64;
            let case = sweep::run(&s, "dt", f);
            let gain = if case.energy_gain.is_finite() {
                case.energy_gain
            } else {
                1e30
            };
            lim.row(&[id as f64, f, gain]).unwrap();
        }
    }

    // Bonded blocks as users run them, at rest and in free fall, plain and
    // regularised, over the step: where bonds break, and whether the
    // engines warn first.
    let mut map = csv(
        dir,
        "assemblies.csv",
        &["assembly", "dt_fraction", "verdict", "flagged", "broken"],
    );
    let fractions: Vec<f64> = if quick {
        vec![0.05, 0.2, 0.5, 1.0]
    } else {
        (1..=20).map(|k| 0.05 * k as f64).collect()
    };
    let mut silent = 0;
    for (id, a) in sweep::ASSEMBLIES.iter().enumerate() {
        for &f in &fractions {
            let case = a.run(if quick { 3 } else { 5 }, f, if quick { 1000 } else { 3000 });
            silent += (case.verdict == Verdict::SilentlyWrong) as usize;
            writeln!(
                notes,
                "{:<32} {:.2} dt_c {:?}: {} bonds broken{}{}",
                a.name,
                f,
                case.verdict,
                case.broken,
                if case.finite { "" } else { ", blew up" },
                if case.flagged { ", warned" } else { "" }
            )
            .unwrap();
            map.row(&[
                id as f64,
                f,
                case.verdict as usize as f64,
                case.flagged as u8 as f64,
                case.broken as f64,
            ])
            .unwrap();
        }
    }
    eprintln!("assemblies: {silent} silently wrong");

    // The plain square root without tension at rest near zero: the rattle
    // amplitude against the step, and the reported floor.
    let mut rattle = csv(dir, "rattle.csv", &["dt_fraction", "peak", "floor", "peak_eps"]);
    let m = sphere_mass(RADIUS, DENSITY);
    let plain = study_bond(false);
    let model = BondModel::new(BondParams { tension: 0, ..plain }).unwrap();
    let dt_c = critical(plain);
    for f in [0.02, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0] {
        let peak = |eps: f64| {
            let p = BondParams {
                compression_linear_below: eps,
                ..plain
            };
            let mut scene = SqrtOscillator::new(p, 1e-18).scene(f * dt_c);
            scene.spheres[1].body.v.x = 0.0;
            scene.spheres[1].body.x.x = 1e-18;
            let mut peak = 0.0f64;
            for _ in 0..if quick { 5_000 } else { 50_000 } {
                if scene.advance().is_err() {
                    return f64::NAN;
                }
                peak = peak.max(scene.spheres[1].body.x.x.abs());
            }
            peak
        };
        let floor = model.compression_noise_floor(f * dt_c, RADIUS, RADIUS, m, m);
        rattle.row(&[f, peak(0.0), floor, peak(EPS)]).unwrap();
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(dir) = args.get(1) else {
        eprintln!("usage: study OUT_DIR [--quick] [--repeat N]");
        std::process::exit(2);
    };
    let quick = args.iter().any(|a| a == "--quick");
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .map(|v| v.parse().expect("--repeat N"))
        .unwrap_or(3);
    let dir = Path::new(dir);
    fs::create_dir_all(dir).expect("create the output directory");
    let started = Instant::now();
    kernel_cost(dir, repeat);
    stability(dir, quick);
    accuracy(dir, quick, repeat);
    let mut names = File::create(dir.join("names.txt")).unwrap();
    writeln!(names, "scenes: {}", SCENES.join("|")).unwrap();
    writeln!(names, "variants: {}", VARIANTS.join("|")).unwrap();
    writeln!(names, "parameters: {}", sweep::PARAMETERS.join("|")).unwrap();
    eprintln!(
        "study done in {:.0} s; CSV files in {}",
        started.elapsed().as_secs_f64(),
        dir.display()
    );
}
