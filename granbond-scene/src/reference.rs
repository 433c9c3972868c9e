//! Reference scenes with closed-form (or exactly computable) answers, shared
//! by the reference-solution tests and the speed/accuracy study
//! (`examples/study.rs`, docs/speed-accuracy.md). Each runs the real bond
//! kernel in the scene runner and returns the measured quantity with the
//! number of steps and the wall time it took.

use super::builders::lattice_ball;
use super::runner::{Scene, SceneError, Sphere};
use granbond::bond::section::section;
use granbond::bond::{BondModel, BondParams};
use granbond::stability::sphere_inertia;
use granbond::vector::Vec3;
use nalgebra::{DMatrix, SymmetricEigen};
use std::f64::consts::PI;
use std::time::Instant;

/// Sphere radius (m) and density (kg/m^3) of every reference scene.
pub const RADIUS: f64 = 1e-3;
pub const DENSITY: f64 = 2500.0;

/// `B(2/3, 1/2) = Gamma(2/3) Gamma(1/2) / Gamma(7/6)`, the constant of the
/// square-root oscillator's period (see [`SqrtOscillator::period`]).
pub const BETA_2_3_HALF: f64 = 2.587_109_559_229_79;

/// First root of `1 + cos b cosh b = 0` (clamped-free beam).
pub const CANTILEVER_BETA1: f64 = 1.875_104_068_711_96;

pub fn sphere_mass(radius: f64, density: f64) -> f64 {
    density * 4.0 / 3.0 * PI * radius.powi(3)
}

/// The study's bond: tension `k_n2`, square root `k_n1`, shear and both
/// torques `k_s`, `lambda = 0.5`, every degree of freedom on, no damping, no
/// breakage. `hysteresis`: `ku = 3k`, `kc = k/10` on every law; otherwise
/// elastic (`ku = k`, `kc = 0`).
pub fn study_bond(hysteresis: bool) -> BondParams {
    let (k_n1, k_n2, k_s) = (1e10, 1e13, 5e12);
    let (u, c) = if hysteresis { (3.0, 0.1) } else { (1.0, 0.0) };
    BondParams {
        lambda: 0.5,
        k_fn1: k_n1,
        ku_fn1: u * k_n1,
        kc_fn1: c * k_n1,
        k_fn2: k_n2,
        ku_fn2: u * k_n2,
        kc_fn2: c * k_n2,
        k_ft: k_s,
        k_tn: k_s,
        ku_tn: u * k_s,
        kc_tn: c * k_s,
        k_tt: k_s,
        ku_tt: u * k_s,
        kc_tt: c * k_s,
        damping: 0,
        create_distance: 2.5 * RADIUS,
        create_step: 0,
        ..BondParams::default()
    }
}

/// What one reference run produced.
#[derive(Clone, Copy, Debug)]
pub struct Run {
    /// The quantity of interest (NaN when it could not be measured).
    pub value: f64,
    pub steps: u64,
    /// Wall time of the stepping loop (s).
    pub seconds: f64,
    pub dt: f64,
}

impl Run {
    /// Wall seconds per simulated second.
    pub fn cost(&self) -> f64 {
        self.seconds / (self.steps as f64 * self.dt)
    }
}

/// Upward zero crossings of a sampled signal, linearly interpolated.
#[derive(Clone, Debug, Default)]
pub struct Crossings {
    last: Option<(f64, f64)>,
    pub times: Vec<f64>,
}

impl Crossings {
    pub fn push(&mut self, t: f64, y: f64) {
        if let Some((t0, y0)) = self.last {
            if y0 < 0.0 && y >= 0.0 {
                self.times.push(t0 + (t - t0) * (-y0) / (y - y0));
            }
        }
        self.last = Some((t, y));
    }

    /// Mean period between the first and the last crossing.
    pub fn period(&self) -> f64 {
        match self.times.as_slice() {
            [first, .., last] => (last - first) / (self.times.len() - 1) as f64,
            _ => f64::NAN,
        }
    }
}

/// Steps `scene` until `signal` has crossed zero upwards `periods + 1` times
/// (or `max_steps`): the mean period.
pub fn measure_period(
    scene: &mut Scene,
    periods: usize,
    max_steps: u64,
    signal: impl Fn(&Scene) -> f64,
) -> Result<Run, SceneError> {
    let mut clock = Crossings::default();
    clock.push(scene.time(), signal(scene));
    let started = Instant::now();
    let mut steps = 0;
    while clock.times.len() <= periods && steps < max_steps {
        scene.advance()?;
        steps += 1;
        clock.push(scene.time(), signal(scene));
    }
    Ok(Run {
        value: clock.period(),
        steps,
        seconds: started.elapsed().as_secs_f64(),
        dt: scene.dt,
    })
}

fn bonded_scene(params: BondParams, dt: f64, spheres: Vec<Sphere>) -> Scene {
    let mut scene = Scene::new(dt);
    scene.spheres = spheres;
    scene.bond_model = Some(BondModel::new(params).expect("valid bond parameters"));
    scene.create_bonds().expect("finite positions");
    scene
}

fn at(x: f64, fixed: bool) -> Sphere {
    let mut s = Sphere::new(Vec3::new(x, 0.0, 0.0), RADIUS, DENSITY);
    s.fixed = fixed;
    s
}

/// Linear tension oscillator: sphere 1 bonded to a fixed sphere 0 (the
/// two-sphere oscillator with `m_eff = m m_0/(m + m_0) -> m`), pulled by a
/// constant force so it oscillates about the stretch `d_eq = -F/(k_n2 A)`
/// without leaving the tension branch (amplitude `|d_eq|/2`).
#[derive(Clone, Copy, Debug)]
pub struct TensionOscillator {
    pub params: BondParams,
    /// Equilibrium stretch (m, > 0).
    pub stretch: f64,
}

impl TensionOscillator {
    pub fn new(params: BondParams) -> Self {
        Self {
            params,
            stretch: 1e-5,
        }
    }

    fn stiffness(&self) -> f64 {
        self.params.k_fn2 * section(self.params.lambda, RADIUS, RADIUS).area
    }

    /// `2 pi sqrt(m_eff / (k A))`.
    pub fn period(&self) -> f64 {
        2.0 * PI * (sphere_mass(RADIUS, DENSITY) / self.stiffness()).sqrt()
    }

    pub fn scene(&self, dt: f64) -> Scene {
        let mut scene = bonded_scene(self.params, dt, vec![at(0.0, true), at(2.0 * RADIUS, false)]);
        let tip = &mut scene.spheres[1];
        tip.external_force = Vec3::new(self.stiffness() * self.stretch, 0.0, 0.0);
        tip.body.x.x += 0.5 * self.stretch;
        scene
    }

    /// Measured period over `periods` periods.
    pub fn run(&self, dt: f64, periods: usize) -> Result<Run, SceneError> {
        let mut scene = self.scene(dt);
        let centre = 2.0 * RADIUS + self.stretch;
        let max = (periods as f64 + 2.0) * self.period() / dt;
        measure_period(&mut scene, periods, max as u64 + 10, |s| {
            s.spheres[1].body.x.x - centre
        })
    }
}

/// Square-root compression oscillator: a sphere between two fixed spheres,
/// bonded to both with tension switched off, so whichever bond is compressed
/// pushes it back with `F = c |x|^(1/2)`, `c = k_n1 A`.
#[derive(Clone, Copy, Debug)]
pub struct SqrtOscillator {
    pub params: BondParams,
    /// Amplitude (m).
    pub amplitude: f64,
}

impl SqrtOscillator {
    pub fn new(params: BondParams, amplitude: f64) -> Self {
        Self {
            params: BondParams { tension: 0, ..params },
            amplitude,
        }
    }

    fn c(&self) -> f64 {
        self.params.k_fn1 * section(self.params.lambda, RADIUS, RADIUS).area
    }

    /// Launch speed that reaches the amplitude: `m v0^2 / 2 = (2/3) c X^(3/2)`.
    pub fn speed(&self) -> f64 {
        (4.0 * self.c() * self.amplitude.powf(1.5) / (3.0 * sphere_mass(RADIUS, DENSITY))).sqrt()
    }

    /// Period of `m x'' = -c sgn(x) |x|^(1/2)` with amplitude `X`.
    ///
    /// Energy: `m v^2/2 + (2/3) c |x|^(3/2) = (2/3) c X^(3/2) = m v0^2/2`, so
    /// `v(x) = v0 sqrt(1 - (x/X)^(3/2))`. A quarter period is
    /// `t_q = int_0^X dx / v(x)`; with `u = (x/X)^(3/2)`,
    /// `x = X u^(2/3)`, `dx = (2/3) X u^(-1/3) du`:
    /// `t_q = (2X / (3 v0)) int_0^1 u^(-1/3) (1-u)^(-1/2) du
    ///      = (2X / (3 v0)) B(2/3, 1/2)`, and `T = 4 t_q = 8 X B(2/3,1/2) / (3 v0)`.
    /// Since `v0 ~ X^(3/4)`, `T ~ X^(1/4)`: small oscillations are fast.
    pub fn period(&self) -> f64 {
        8.0 * self.amplitude * BETA_2_3_HALF / (3.0 * self.speed())
    }

    pub fn scene(&self, dt: f64) -> Scene {
        let mut scene = bonded_scene(
            self.params,
            dt,
            vec![at(-2.0 * RADIUS, true), at(0.0, false), at(2.0 * RADIUS, true)],
        );
        scene.spheres[1].body.v.x = self.speed();
        scene
    }

    pub fn run(&self, dt: f64, periods: usize) -> Result<Run, SceneError> {
        let mut scene = self.scene(dt);
        let max = (periods as f64 + 2.0) * 2.0 * self.period() / dt;
        measure_period(&mut scene, periods, max as u64 + 10, |s| s.spheres[1].body.x.x)
    }
}

/// A straight chain of `bonds + 1` touching spheres along x, sphere 0 held
/// fixed (clamped: it neither moves nor turns), bending in the x-y plane.
///
/// Equivalent beam, from the bond laws (bond length `h = 2R`, `L = bonds h`):
/// a bond of relative rotation `theta` carries the moment `k_tt I theta`;
/// over its length the beam's curvature is `theta / h`, so
/// `EI = k_tt I h`. A shear force `V` slips the contact point by
/// `V / (k_t A)`, a shear strain `V / (k_t A h)`, so the Timoshenko shear
/// rigidity is `kappa G A = k_t A h`.
#[derive(Clone, Copy, Debug)]
pub struct Cantilever {
    pub params: BondParams,
    pub bonds: usize,
}

impl Cantilever {
    pub fn new(params: BondParams, bonds: usize) -> Self {
        Self { params, bonds }
    }

    pub fn bond_length(&self) -> f64 {
        2.0 * RADIUS
    }

    pub fn length(&self) -> f64 {
        self.bonds as f64 * self.bond_length()
    }

    /// `EI = k_tt I h`.
    pub fn bending_rigidity(&self) -> f64 {
        self.params.k_tt * section(self.params.lambda, RADIUS, RADIUS).inertia * self.bond_length()
    }

    /// `kappa G A = k_t A h`.
    pub fn shear_rigidity(&self) -> f64 {
        self.params.k_ft * section(self.params.lambda, RADIUS, RADIUS).area * self.bond_length()
    }

    /// Euler-Bernoulli tip deflection under a tip load: `P L^3 / (3 EI)`.
    pub fn euler_bernoulli_tip(&self, load: f64) -> f64 {
        load * self.length().powi(3) / (3.0 * self.bending_rigidity())
    }

    /// Timoshenko: Euler-Bernoulli plus the shear part `P L / (kappa G A)`.
    pub fn timoshenko_tip(&self, load: f64) -> f64 {
        self.euler_bernoulli_tip(load) + load * self.length() / self.shear_rigidity()
    }

    /// Exact small-deflection tip deflection of the chain. Bond `m` (centre
    /// at `s_m = (m + 1/2) h`) carries the moment `P (L - s_m)`, so the
    /// rotation jumps by `P h (L - s_m) / EI` across it: the midpoint rule of
    /// `int M/EI`, exact for a linear `M`, so the nodes turn exactly as the
    /// beam does. The deflection then grows by `h (phi_a + phi_b)/2` plus the
    /// shear slip `P / (k_t A)` per bond: the trapezoidal rule of the slope, a
    /// concave quadratic (`phi'' = -P/EI`), which falls short by
    /// `P h^3/(12 EI)` per bond. Total: Timoshenko minus `P L h^2 / (12 EI)`,
    /// i.e. Euler-Bernoulli times `1 - (h/L)^2/4` plus the shear part.
    pub fn chain_tip(&self, load: f64) -> f64 {
        let (h, l) = (self.bond_length(), self.length());
        self.timoshenko_tip(load) - load * l * h * h / (12.0 * self.bending_rigidity())
    }

    /// First natural frequency (rad/s) of the Euler-Bernoulli beam of mass
    /// per length `m/h`: `beta1^2 sqrt(EI / (mu L^4))`.
    pub fn euler_bernoulli_frequency(&self) -> f64 {
        let mu = sphere_mass(RADIUS, DENSITY) / self.bond_length();
        CANTILEVER_BETA1.powi(2) * (self.bending_rigidity() / (mu * self.length().powi(4))).sqrt()
    }

    /// Stiffness matrix and mass diagonal of the chain's small in-plane
    /// motion, degrees of freedom `(y_m, phi_m)` of spheres `1..=bonds`,
    /// assembled from the bond laws: per bond the shear slip
    /// `y_b - y_a - h (phi_a + phi_b) / 2` on `k_t A` and the bending angle
    /// `phi_b - phi_a` on `k_tt I`. Mass `m` and `0.4 m R^2`.
    pub fn stiffness_and_mass(&self) -> (DMatrix<f64>, Vec<f64>) {
        let n = 2 * self.bonds;
        let sec = section(self.params.lambda, RADIUS, RADIUS);
        let (ks, kb, h) = (
            self.params.k_ft * sec.area,
            self.params.k_tt * sec.inertia,
            self.bond_length(),
        );
        let mut k = DMatrix::zeros(n, n);
        for b in 1..=self.bonds {
            // DOF indices of node a = b - 1 (none for the clamped node) and b.
            let dofs = [
                (b >= 2).then(|| 2 * (b - 2)),
                (b >= 2).then(|| 2 * (b - 2) + 1),
                Some(2 * (b - 1)),
                Some(2 * (b - 1) + 1),
            ];
            for (g, stiffness) in [([-1.0, -0.5 * h, 1.0, -0.5 * h], ks), ([0.0, -1.0, 0.0, 1.0], kb)] {
                for (p, dp) in dofs.iter().enumerate() {
                    for (q, dq) in dofs.iter().enumerate() {
                        if let (Some(i), Some(j)) = (dp, dq) {
                            k[(*i, *j)] += stiffness * g[p] * g[q];
                        }
                    }
                }
            }
        }
        let m = sphere_mass(RADIUS, DENSITY);
        let mass = (0..n)
            .map(|i| if i % 2 == 0 { m } else { sphere_inertia(m, RADIUS) })
            .collect();
        (k, mass)
    }

    /// First natural frequency (rad/s) of the discrete chain and its mode
    /// (`y_m, phi_m` interleaved, tip deflection normalised to 1).
    pub fn chain_mode(&self) -> (f64, Vec<f64>) {
        let (k, mass) = self.stiffness_and_mass();
        let s: Vec<f64> = mass.iter().map(|m| 1.0 / m.sqrt()).collect();
        let scaled = DMatrix::from_fn(k.nrows(), k.ncols(), |i, j| s[i] * k[(i, j)] * s[j]);
        let eig = SymmetricEigen::new(scaled);
        let (first, lambda) = eig
            .eigenvalues
            .iter()
            .enumerate()
            .fold(
                (0, f64::INFINITY),
                |best, (i, &l)| if l < best.1 { (i, l) } else { best },
            );
        let mut mode: Vec<f64> = (0..k.nrows())
            .map(|i| eig.eigenvectors[(i, first)] * s[i])
            .collect();
        let tip = mode[k.nrows() - 2];
        mode.iter_mut().for_each(|v| *v /= tip);
        (lambda.sqrt(), mode)
    }

    pub fn scene(&self, dt: f64) -> Scene {
        let spheres = (0..=self.bonds)
            .map(|i| at(i as f64 * self.bond_length(), i == 0))
            .collect();
        bonded_scene(self.params, dt, spheres)
    }

    /// Free vibration launched with the velocities of the chain's first mode
    /// (tip amplitude `1e-3 h`): the measured angular frequency.
    pub fn ring(&self, dt: f64, periods: usize) -> Result<Run, SceneError> {
        let (omega, mode) = self.chain_mode();
        let mut scene = self.scene(dt);
        let speed = 1e-3 * self.bond_length() * omega;
        for (i, s) in scene.spheres.iter_mut().enumerate().skip(1) {
            s.body.v.y = speed * mode[2 * (i - 1)];
            s.body.w.z = speed * mode[2 * (i - 1) + 1];
        }
        let max = (periods as f64 + 2.0) * 4.0 * PI / omega / dt;
        let tip = self.bonds;
        let mut run = measure_period(&mut scene, periods, max as u64 + 10, |s| s.spheres[tip].body.x.y)?;
        run.value = 2.0 * PI / run.value;
        Ok(run)
    }

    /// Static tip deflection under a transverse tip load, found by kinetic
    /// damping: every velocity is zeroed whenever the kinetic energy passes a
    /// peak, until a peak falls below `1e-16` of the load's work `P y_tip`
    /// (a deflection error of order `1e-8`) or `max_steps`.
    pub fn sag(&self, dt: f64, load: f64, max_steps: u64) -> Result<Run, SceneError> {
        let mut scene = self.scene(dt);
        let tip = self.bonds;
        scene.spheres[tip].external_force = Vec3::new(0.0, load, 0.0);
        let started = Instant::now();
        let (mut steps, mut last_energy) = (0u64, 0.0);
        while steps < max_steps {
            scene.advance()?;
            steps += 1;
            let energy = scene.kinetic_energy();
            if energy < last_energy {
                for s in scene.spheres.iter_mut() {
                    s.body.v = Vec3::zeros();
                    s.body.w = Vec3::zeros();
                }
                if last_energy < 1e-16 * (load * scene.spheres[tip].body.x.y).abs() {
                    break;
                }
                last_energy = 0.0;
            } else {
                last_energy = energy;
            }
        }
        Ok(Run {
            value: scene.spheres[tip].body.x.y,
            steps,
            seconds: started.elapsed().as_secs_f64(),
            dt,
        })
    }
}

/// A small deterministic pseudo-random sequence in `[-1, 1)` (xorshift).
pub struct Noise(u64);

impl Noise {
    pub fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    pub fn next_f64(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    pub fn vector(&mut self) -> Vec3 {
        Vec3::new(self.next_f64(), self.next_f64(), self.next_f64())
    }
}

/// A free bonded ball of spheres on a cubic lattice (ball radius in sphere
/// radii), every sphere given a random velocity of scale `speed` and a
/// random spin of scale `speed / R`.
pub fn free_cluster(params: BondParams, dt: f64, ball_radii: f64, speed: f64, seed: u64) -> Scene {
    let mut scene = Scene::new(dt);
    lattice_ball(&mut scene, Vec3::zeros(), ball_radii * RADIUS, RADIUS, DENSITY);
    let mut noise = Noise::new(seed);
    for s in scene.spheres.iter_mut() {
        s.body.v = noise.vector() * speed;
        s.body.w = noise.vector() * (speed / RADIUS);
    }
    scene.bond_model = Some(BondModel::new(params).expect("valid bond parameters"));
    scene.create_bonds().expect("finite positions");
    scene
}

/// Total energy `E_n`: the kinetic energies before and after step `n`
/// averaged (symplectic Euler's velocities sit half a step either side of the
/// positions) plus the bonds' elastic energy at the positions of step `n`.
/// Returns `max_n |E_n - E_0| / E_0` over `steps` steps.
pub fn energy_error(scene: &mut Scene, steps: u64) -> Result<Run, SceneError> {
    let started = Instant::now();
    let (mut first, mut worst) = (f64::NAN, 0.0f64);
    for _ in 0..steps {
        let before = scene.kinetic_energy();
        scene.advance()?;
        let energy = 0.5 * (before + scene.kinetic_energy()) + scene.bond_energy();
        if first.is_nan() {
            first = energy;
        }
        worst = worst.max((energy - first).abs() / first);
    }
    Ok(Run {
        value: worst,
        steps,
        seconds: started.elapsed().as_secs_f64(),
        dt: scene.dt,
    })
}
