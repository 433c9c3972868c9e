//! Stability at the extremes (issue 4): one parameter at a time is scaled
//! over decades around the defaults while the time step stays what the
//! defaults chose, as a user who changes a material and keeps the deck's step
//! would; each run is classified as stable, unstable but detected and
//! reported, or silently wrong. Shared by `tests/stability_sweep.rs` (a small
//! grid) and `examples/study.rs` (the full one).

use super::reference::{study_bond, Noise, DENSITY, RADIUS};
use super::runner::{Scene, Sphere};
use granbond::bond::{BondModel, BondParams, BondState};
use granbond::kinematics::PairKinematics;
use granbond::vector::Vec3;

/// What a run showed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Finite, and the energy never grew past ten times its start.
    Stable,
    /// Rejected or failed with an error, or blew up after the core said so
    /// (dt above its recommended step, or compressions below the reported
    /// square-root noise floor).
    Detected,
    /// Blew up (non-finite or energy x10) with no report: must never happen.
    SilentlyWrong,
}

/// One run of the sweep.
#[derive(Clone, Debug)]
pub struct Case {
    pub parameter: &'static str,
    pub factor: f64,
    pub verdict: Verdict,
    /// `dt` above the core's recommended step (`RECOMMENDED_FRACTION` of its
    /// critical-step estimate), where it warns.
    pub flagged: bool,
    /// Largest total energy over the start (NaN when non-finite).
    pub energy_gain: f64,
    /// What reported it, or why it is stable.
    pub note: String,
}

/// The sweep's defaults: hysteretic bond (`ku = 3k`, `kc = k/10`) with 10%
/// damping on every law, radius [`RADIUS`], density [`DENSITY`], and the step
/// `0.2 dt_c` of those defaults.
#[derive(Clone, Copy, Debug)]
pub struct Setup {
    pub params: BondParams,
    pub radius: f64,
    pub density: f64,
    pub dt: f64,
    pub steps: u64,
}

impl Setup {
    pub fn defaults(steps: u64) -> Self {
        let params = BondParams {
            damping: 1,
            eta_fn: 0.1,
            eta_ft: 0.1,
            eta_tn: 0.1,
            eta_tt: 0.1,
            ..study_bond(true)
        };
        let mut s = Self {
            params,
            radius: RADIUS,
            density: DENSITY,
            dt: 0.0,
            steps,
        };
        s.dt = 0.2 * s.critical().expect("valid defaults");
        s
    }

    fn mass(&self) -> f64 {
        self.density * 4.0 / 3.0 * std::f64::consts::PI * self.radius.powi(3)
    }

    fn critical(&self) -> Result<f64, String> {
        let m = BondModel::new(self.params).map_err(|e| e.message)?;
        Ok(m.critical_timestep(self.radius, self.radius, self.mass(), self.mass()))
    }
}

/// Names of the swept parameters, for [`scaled`].
pub const PARAMETERS: [&str; 14] = [
    "all stiffnesses",
    "k_fn1 (compression)",
    "k_fn2 (tension)",
    "k_ft (shear)",
    "k_tn (twist)",
    "k_tt (bend)",
    "ku/k",
    "kc/k",
    "lambda",
    "radius",
    "density (mass)",
    "damping eta",
    "dt",
    "overlap / R",
];

fn scale_law(k: &mut f64, ku: &mut f64, kc: &mut f64, f: f64) {
    *k *= f;
    *ku *= f;
    *kc *= f;
}

/// The defaults with one parameter scaled by `factor` (the step is kept;
/// for `"dt"` it is the step that is scaled; `"overlap / R"` is handled by
/// [`run_overlap`]).
pub fn scaled(base: &Setup, parameter: &str, f: f64) -> Setup {
    let mut s = *base;
    let p = &mut s.params;
    match parameter {
        "all stiffnesses" => {
            scale_law(&mut p.k_fn1, &mut p.ku_fn1, &mut p.kc_fn1, f);
            scale_law(&mut p.k_fn2, &mut p.ku_fn2, &mut p.kc_fn2, f);
            scale_law(&mut p.k_tn, &mut p.ku_tn, &mut p.kc_tn, f);
            scale_law(&mut p.k_tt, &mut p.ku_tt, &mut p.kc_tt, f);
            p.k_ft *= f;
        }
        "k_fn1 (compression)" => scale_law(&mut p.k_fn1, &mut p.ku_fn1, &mut p.kc_fn1, f),
        "k_fn2 (tension)" => scale_law(&mut p.k_fn2, &mut p.ku_fn2, &mut p.kc_fn2, f),
        "k_ft (shear)" => p.k_ft *= f,
        "k_tn (twist)" => scale_law(&mut p.k_tn, &mut p.ku_tn, &mut p.kc_tn, f),
        "k_tt (bend)" => scale_law(&mut p.k_tt, &mut p.ku_tt, &mut p.kc_tt, f),
        "ku/k" => {
            p.ku_fn1 *= f;
            p.ku_fn2 *= f;
            p.ku_tn *= f;
            p.ku_tt *= f;
        }
        "kc/k" => {
            p.kc_fn1 *= f;
            p.kc_fn2 *= f;
            p.kc_tn *= f;
            p.kc_tt *= f;
        }
        "lambda" => p.lambda *= f,
        "radius" => {
            s.radius *= f;
            p.create_distance *= f;
        }
        "density (mass)" => s.density *= f,
        "damping eta" => {
            p.eta_fn *= f;
            p.eta_ft *= f;
            p.eta_tn *= f;
            p.eta_tt *= f;
        }
        "dt" => s.dt *= f,
        other => panic!("unknown parameter {other}"),
    }
    s
}

/// A sphere and its six neighbours on the axes, bonded, every sphere with a
/// random velocity of 0.1 m/s and spin of 0.1 m/s / R.
fn star(setup: &Setup, model: BondModel) -> Scene {
    let r = setup.radius;
    let mut scene = Scene::new(setup.dt);
    scene.spheres.push(Sphere::new(Vec3::zeros(), r, setup.density));
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let mut x = Vec3::zeros();
            x[axis] = sign * 2.0 * r;
            scene.spheres.push(Sphere::new(x, r, setup.density));
        }
    }
    let mut noise = Noise::new(7);
    for s in scene.spheres.iter_mut() {
        s.body.v = noise.vector() * 0.1;
        s.body.w = noise.vector() * (0.1 / r);
    }
    scene.bond_model = Some(model);
    scene
}

fn total_energy(scene: &Scene) -> f64 {
    scene.kinetic_energy() + scene.bond_energy()
}

/// Steps `scene` and classifies the run. `floor`: the compression below
/// which the core reported the square root as noise at this step (0: none).
fn classify(mut scene: Scene, steps: u64, flagged: bool, floor: f64) -> (Verdict, f64, String) {
    let start = total_energy(&scene);
    let mut peak = start;
    let mut deepest = 0.0f64;
    for _ in 0..steps {
        if let Err(e) = scene.advance() {
            return (Verdict::Detected, f64::NAN, format!("scene error {e:?}"));
        }
        let e = total_energy(&scene);
        if !e.is_finite() {
            peak = f64::NAN;
            break;
        }
        peak = peak.max(e);
        deepest = scene.bonds.iter().map(|b| b.last.delta).fold(deepest, f64::max);
    }
    let gain = peak / start;
    let blew_up = !(gain <= 10.0);
    let verdict = match (blew_up, flagged, deepest <= floor) {
        (false, _, _) => Verdict::Stable,
        (true, true, _) => Verdict::Detected,
        (true, false, true) => Verdict::Detected,
        (true, false, false) => Verdict::SilentlyWrong,
    };
    let note = match verdict {
        Verdict::Stable if flagged => "stable, though dt > recommended step".to_string(),
        Verdict::Stable => "stable".to_string(),
        Verdict::Detected if flagged => "blew up; dt > recommended_timestep (warned)".to_string(),
        Verdict::Detected => {
            format!("compression rattle {deepest:.2e} m within the reported noise floor {floor:.2e} m")
        }
        Verdict::SilentlyWrong => format!(
            "energy x{gain:.2e}, no report (deepest compression {deepest:.2e} m, floor {floor:.2e} m)"
        ),
    };
    (verdict, gain, note)
}

/// One run of the star cluster with one parameter scaled.
pub fn run(base: &Setup, parameter: &'static str, factor: f64) -> Case {
    let setup = scaled(base, parameter, factor);
    let case = |verdict, flagged, energy_gain, note| Case {
        parameter,
        factor,
        verdict,
        flagged,
        energy_gain,
        note,
    };
    let model = match BondModel::new(setup.params) {
        Ok(m) => m,
        Err(e) => {
            return case(
                Verdict::Detected,
                false,
                f64::NAN,
                format!("rejected: {}", e.message),
            )
        }
    };
    let m = setup.mass();
    let flagged = setup.dt > (1.0 + 1e-9) * model.recommended_timestep(setup.radius, setup.radius, m, m);
    let floor = model.compression_noise_floor(setup.dt, setup.radius, setup.radius, m, m);
    let mut scene = star(&setup, model);
    if let Err(e) = scene.create_bonds() {
        return case(Verdict::Detected, flagged, f64::NAN, format!("scene error {e:?}"));
    }
    let (verdict, gain, note) = classify(scene, setup.steps, flagged, floor);
    case(verdict, flagged, gain, note)
}

/// A bonded pair at rest, compressed by `overlap` (a fraction of the radius)
/// right after creation: the square root's stiffness at that compression is
/// `k A / (2 sqrt d)`, unbounded as `d -> 0`.
pub fn run_overlap(base: &Setup, overlap: f64) -> Case {
    let model = BondModel::new(base.params).expect("valid defaults");
    let m = base.mass();
    let r = base.radius;
    let flagged = base.dt > (1.0 + 1e-9) * model.recommended_timestep(r, r, m, m);
    let floor = model.compression_noise_floor(base.dt, r, r, m, m);
    let mut scene = Scene::new(base.dt);
    scene.spheres.push(Sphere::new(Vec3::zeros(), r, base.density));
    scene
        .spheres
        .push(Sphere::new(Vec3::new(2.0 * r, 0.0, 0.0), r, base.density));
    scene.bond_model = Some(model);
    scene.create_bonds().expect("finite");
    scene.spheres[1].body.x.x -= overlap * r;
    // Start from the energy of the compressed bond (the first step has not
    // run, so set the compression it will see).
    scene.bonds[0].last.delta = overlap * r;
    let (verdict, gain, note) = classify(scene, base.steps, flagged, floor);
    Case {
        parameter: "overlap / R",
        factor: overlap,
        verdict,
        flagged,
        energy_gain: gain,
        note,
    }
}

/// Coincident centres and NaN/Inf in every input of the kernel: each must be
/// an error, never a panic or a non-finite output. Returns the cases.
pub fn degenerate_inputs(base: &Setup) -> Vec<Case> {
    let model = BondModel::new(base.params).expect("valid defaults");
    let r = base.radius;
    let good = PairKinematics {
        x_i: [2.0 * r, 0.0, 0.0],
        v_i: [0.01, 0.02, 0.0],
        w_i: [0.0, 0.0, 1.0],
        radius_i: r,
        radius_j: r,
        ..PairKinematics::default()
    };
    let mut inputs: Vec<(&'static str, PairKinematics)> = vec![(
        "coincident centres",
        PairKinematics {
            x_i: [0.0; 3],
            ..good
        },
    )];
    for (name, bad) in [
        ("NaN", f64::NAN),
        ("+Inf", f64::INFINITY),
        ("-Inf", f64::NEG_INFINITY),
    ] {
        for field in 0..20 {
            let mut k = good;
            match field {
                0..=2 => k.x_i[field] = bad,
                3..=5 => k.x_j[field - 3] = bad,
                6..=8 => k.v_i[field - 6] = bad,
                9..=11 => k.v_j[field - 9] = bad,
                12..=14 => k.w_i[field - 12] = bad,
                15..=17 => k.w_j[field - 15] = bad,
                18 => k.radius_i = bad,
                _ => k.radius_j = bad,
            }
            inputs.push((name, k));
        }
    }
    inputs
        .into_iter()
        .map(|(name, k)| {
            let mut state = BondState::created(2.0 * r);
            let mut out = Default::default();
            let result = model.step(&k, base.dt, &mut state, &mut out);
            let finite = out.force_i.iter().chain(&out.torque_i).all(|v| v.is_finite());
            let (verdict, note) = match (result, finite) {
                (Err(e), _) => (Verdict::Detected, format!("error {e:?}")),
                (Ok(()), true) => (Verdict::Stable, "finite output".to_string()),
                (Ok(()), false) => (Verdict::SilentlyWrong, "non-finite output, no error".to_string()),
            };
            Case {
                parameter: name,
                factor: f64::NAN,
                verdict,
                flagged: false,
                energy_gain: f64::NAN,
                note,
            }
        })
        .collect()
}

/// A bonded assembly as users run one: a simple-cubic block of `edge^3`
/// touching spheres of radius [`RADIUS`] bonded in the first step, with
/// stress breakage on a square root that is plain or regularised, at rest
/// (velocities of round-off size) or falling freely (gravity and a uniform
/// velocity). Nothing loads its bonds, so a bond that breaks was broken by
/// the integration.
#[derive(Clone, Copy, Debug)]
pub struct Assembly {
    pub name: &'static str,
    pub falling: bool,
    pub regularised: bool,
}

/// The four assemblies of the map.
pub const ASSEMBLIES: [Assembly; 4] = [
    Assembly {
        name: "at rest, plain square root",
        falling: false,
        regularised: false,
    },
    Assembly {
        name: "free fall, plain square root",
        falling: true,
        regularised: false,
    },
    Assembly {
        name: "at rest, delta_eps = 1e-3 rb",
        falling: false,
        regularised: true,
    },
    Assembly {
        name: "free fall, delta_eps = 1e-3 rb",
        falling: true,
        regularised: true,
    },
];

impl Assembly {
    /// The bond of the free-fall report (`k_fn1 = 2e10`, `max_sigma =
    /// 1e6`: compression breakage from `(max_sigma / k_fn1)^2 = 2.5e-9`
    /// m), undamped.
    pub fn bond(&self) -> BondParams {
        let lambda = 0.8;
        BondParams {
            lambda,
            k_fn1: 2e10,
            ku_fn1: 4e10,
            kc_fn1: 2e9,
            k_fn2: 5e10,
            ku_fn2: 1e11,
            kc_fn2: 5e9,
            k_ft: 2e10,
            k_tn: 2e10,
            ku_tn: 4e10,
            kc_tn: 2e9,
            k_tt: 2e10,
            ku_tt: 4e10,
            kc_tt: 2e9,
            damping: 0,
            stress_break: 1,
            max_sigma: 1e6,
            max_tau: 1e6,
            compression_linear_below: if self.regularised {
                1e-3 * lambda * RADIUS
            } else {
                0.0
            },
            create_distance: 2.04 * RADIUS,
            create_step: 0,
            ..BondParams::default()
        }
    }

    /// The one-bond critical step of its bond between two of its spheres.
    pub fn critical(&self) -> f64 {
        let m = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
        BondModel::new(self.bond())
            .expect("valid bond")
            .critical_timestep(RADIUS, RADIUS, m, m)
    }

    /// Runs `steps` at `dt_fraction` of [`Assembly::critical`]. Wrong: a
    /// bond broke or the run stopped on non-finite kinematics; detected
    /// when the step is above the core's recommended step (the engines
    /// warn at the run's start).
    pub fn run(&self, edge: usize, dt_fraction: f64, steps: u64) -> AssemblyCase {
        let params = self.bond();
        let model = BondModel::new(params).expect("valid bond");
        let m = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
        let dt = dt_fraction * model.critical_timestep(RADIUS, RADIUS, m, m);
        let flagged = dt > (1.0 + 1e-9) * model.recommended_timestep(RADIUS, RADIUS, m, m);
        let mut scene = Scene::new(dt);
        let mut noise = Noise::new(11);
        let speed = if self.falling { 2.0 } else { 0.0 };
        for a in 0..edge {
            for b in 0..edge {
                for c in 0..edge {
                    let x = Vec3::new(a as f64, b as f64, c as f64) * (2.0 * RADIUS);
                    let mut s = Sphere::new(x, RADIUS, DENSITY);
                    s.body.v = Vec3::new(0.0, 0.0, -speed) + noise.vector() * 1e-12;
                    scene.spheres.push(s);
                }
            }
        }
        if self.falling {
            scene.gravity = Vec3::new(0.0, 0.0, -9.81);
        }
        scene.bond_model = Some(model);
        let mut broken = 0;
        let mut finite = true;
        for _ in 0..steps {
            match scene.advance() {
                Ok(report) => broken += report.bonds_broken,
                Err(_) => {
                    finite = false;
                    break;
                }
            }
        }
        let wrong = broken > 0 || !finite;
        let verdict = match (wrong, flagged) {
            (false, _) => Verdict::Stable,
            (true, true) => Verdict::Detected,
            (true, false) => Verdict::SilentlyWrong,
        };
        AssemblyCase {
            verdict,
            flagged,
            broken,
            finite,
        }
    }
}

/// One run of an [`Assembly`].
#[derive(Clone, Copy, Debug)]
pub struct AssemblyCase {
    pub verdict: Verdict,
    /// Above the core's recommended step (warned).
    pub flagged: bool,
    pub broken: usize,
    pub finite: bool,
}
