//! Critical time-step estimate of a bond: the shortest `2/omega` over its
//! modes, each with the stiffest slope of its hysteresis loop. Percentage
//! damping is not viscous and does not enter the limit.

use super::features::{BEND, COMPRESSION, DAMPING, SHEAR, SMOOTH, TENSION, TWIST};
use super::model::BondModel;
use super::params::BondParams;
use super::section::section;
use crate::stability::{oscillator_limit, sphere_inertia};

/// Compression the estimate assumes when the square root is not regularised
/// (its stiffness is unbounded at zero compression), as a fraction of `rb`.
pub const REFERENCE_COMPRESSION: f64 = 1e-3;

pub use crate::stability::RECOMMENDED_FRACTION;

/// How far below the compression break threshold the recommended step keeps
/// the noise floor of the square root's rattle
/// ([`BondModel::compression_noise_floor`], `16 d_c`, which bounds the
/// rattle of one bond between two spheres).
///
/// Derivation. A sphere rattling against its bonded neighbours is held by
/// the sum of their axial stiffnesses: for mass-weighted displacements,
/// `sum_b K_b (n_b . (x_i - x_j))^2 <= 2 sum_i x_i' (sum_(b at i) K_b n_b n_b') x_i`,
/// so the packing's axial eigenvalue is at most `c` times the pair's, `c`
/// the largest eigenvalue of `sum_(b at i) n_b n_b'` over the spheres (the
/// bond fabric; at most the bond count, and a third of it where the bonds
/// point in every direction: 2 for the simple-cubic packing's 6 bonds, 4
/// for the 12 of the densest monodisperse packing). The local stiffness
/// `k A / (2 sqrt d)` reaches the stability limit at `c^2 d_c` instead of
/// `d_c`, so the floor of the packing is `c^2` times the pair's. The margin
/// is that factor for `c = 4`: packings up to the densest monodisperse one
/// keep their rattle below the threshold at the recommended step.
pub const RATTLE_MARGIN: f64 = 16.0;

impl BondModel {
    /// Critical step of this bond type between spheres of the given radii and
    /// masses: the shortest of its modes' limits ([`BondModel::mode_limits`]).
    /// It is the limit of one bond between two spheres; a sphere with several
    /// bonds has a shorter one ([`BondModel::coordinated_timestep`]).
    pub fn critical_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let m = self.mode_limits(radius_i, radius_j, mass_i, mass_j);
        m.axial.min(m.shear).min(m.twist).min(m.bend)
    }

    /// The step limit `2/omega` of each mode of one bond between two spheres
    /// (infinite for a mode switched off). Modes: axial (reduced mass),
    /// shear (reduced mass plus the rotation each sphere takes about its
    /// own centre), twisting and bending (reduced moment of inertia), each
    /// with the stiffest slope of its hysteresis loop. The square-root
    /// branch is evaluated at `compression_linear_below`, or at
    /// [`REFERENCE_COMPRESSION`]`* rb` when that is off.
    pub fn mode_limits(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> ModeLimits {
        let p = &self.params;
        let f = self.features;
        let sec = section(p.lambda, radius_i, radius_j);
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let (inertia_i, inertia_j) = (sphere_inertia(mass_i, radius_i), sphere_inertia(mass_j, radius_j));
        let i_eff = inertia_i * inertia_j / (inertia_i + inertia_j);
        let mut limits = ModeLimits {
            axial: f64::INFINITY,
            shear: f64::INFINITY,
            twist: f64::INFINITY,
            bend: f64::INFINITY,
        };
        if self.linear {
            // k_n A, k_t A (with the levers of the spheres' rotation), k_t J, k_n I
            let mobility = 1.0 / mass_i
                + 1.0 / mass_j
                + radius_i * radius_i / inertia_i
                + radius_j * radius_j / inertia_j;
            let mode = |on: bool, mass: f64, stiffness: f64| {
                if on {
                    oscillator_limit(mass, stiffness, 0.0)
                } else {
                    f64::INFINITY
                }
            };
            return ModeLimits {
                axial: mode(f & (TENSION | COMPRESSION) != 0, m_eff, p.k_n * sec.area),
                shear: mode(f & SHEAR != 0, 1.0 / mobility, p.k_t * sec.area),
                twist: mode(f & TWIST != 0, i_eff, p.k_t * sec.polar),
                bend: mode(f & BEND != 0, i_eff, p.k_n * sec.inertia),
            };
        }
        if f & TENSION != 0 {
            limits.axial = oscillator_limit(m_eff, self.normal.tension.max_slope() * sec.area, 0.0);
        }
        if f & COMPRESSION != 0 {
            let d_ref = if p.compression_linear_below > 0.0 {
                p.compression_linear_below
            } else {
                REFERENCE_COMPRESSION * sec.rb
            };
            // d/dd of k sqrt(d) is k / (2 sqrt d); the linear continuation has
            // slope k / sqrt(eps), the larger of the two at eps.
            let slope = if p.compression_linear_below > 0.0 {
                1.0
            } else {
                0.5
            } / d_ref.sqrt();
            limits.axial = limits.axial.min(oscillator_limit(
                m_eff,
                self.normal.compression.max_slope() * slope * self.compression_area(sec.area),
                0.0,
            ));
        }
        if f & SHEAR != 0 {
            let (ri, rj) = (radius_i, radius_j); // lever arms at r = R_i + R_j
            let mobility = 1.0 / mass_i + 1.0 / mass_j + ri * ri / inertia_i + rj * rj / inertia_j;
            limits.shear = oscillator_limit(1.0 / mobility, p.k_ft * sec.area, 0.0);
        }
        if f & TWIST != 0 {
            limits.twist = oscillator_limit(i_eff, self.twist.hysteresis.max_slope() * sec.polar, 0.0);
        }
        if f & BEND != 0 {
            limits.bend = oscillator_limit(i_eff, self.bend.hysteresis.max_slope() * sec.inertia, 0.0);
        }
        limits
    }

    /// The step below which a packing whose spheres carry at most
    /// `bonds_per_sphere` bonds of this type (between spheres of these radii
    /// and masses) is stable.
    ///
    /// Derivation. In mass-weighted coordinates `x` (`x = M^(1/2) u`) the
    /// stiffness of the packing is a sum over bonds of `P_b`, each acting on
    /// the degrees of freedom of its two spheres only, and explicit
    /// integration is stable while `dt < 2 / sqrt(lambda_max)` of the sum.
    /// For each bond `x' P_b x <= lambda_b (|x_i|^2 + |x_j|^2)`, `lambda_b`
    /// the largest eigenvalue of one bond between two spheres, so the sum is
    /// at most `sum_i |x_i|^2 sum_(b at i) lambda_b <= z lambda_b |x|^2`
    /// with `z` the most bonds on one sphere: the limit is
    /// `2 / sqrt(z lambda_b)`. The modes of one bond act on separate degrees
    /// of freedom (axial: translation along the axis; twisting: rotation
    /// about it) except shear and bending, which share the rotations
    /// across the axis, so `lambda_b <= max(w_axial^2, w_twist^2,
    /// w_shear^2 + w_bend^2)`. The estimate is a bound: lattices measure
    /// above it (the simple-cubic packing, docs/speed-accuracy.md), never
    /// below.
    pub fn coordinated_timestep(
        &self,
        radius_i: f64,
        radius_j: f64,
        mass_i: f64,
        mass_j: f64,
        bonds_per_sphere: u32,
    ) -> f64 {
        self.mode_limits(radius_i, radius_j, mass_i, mass_j)
            .coordinated(bonds_per_sphere)
    }
}

/// The step limit `2/omega` of each mode of one bond between two spheres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModeLimits {
    /// Axial mode, tension and compression on the reduced mass (s).
    pub axial: f64,
    /// Shear mode, on the reduced mass with each sphere's rotation about its
    /// centre (s).
    pub shear: f64,
    /// Twisting mode, on the reduced moment of inertia (s).
    pub twist: f64,
    /// Bending mode, on the reduced moment of inertia (s).
    pub bend: f64,
}

impl ModeLimits {
    /// The limit of a sphere with `bonds_per_sphere` such bonds
    /// ([`BondModel::coordinated_timestep`] has the derivation); one bond
    /// between two free spheres for `bonds_per_sphere = 1`.
    pub fn coordinated(&self, bonds_per_sphere: u32) -> f64 {
        // omega^2 = 4 / limit^2, summed where modes share degrees of freedom
        let w2 = |limit: f64| 4.0 / (limit * limit);
        let lambda = w2(self.axial)
            .max(w2(self.twist))
            .max(w2(self.shear) + w2(self.bend));
        2.0 / (f64::from(bonds_per_sphere.max(1)) * lambda).sqrt()
    }

    /// The most bonds on one sphere for which a packing is stable at `dt`
    /// (0: not even one bond).
    pub fn bonds_covered(&self, dt: f64) -> u32 {
        let z = (self.coordinated(1) / dt).powi(2).floor();
        if z.is_finite() {
            z.clamp(0.0, f64::from(u32::MAX)) as u32
        } else {
            u32::MAX
        }
    }
}

impl BondModel {
    /// The step to use, and the one above which the engines warn:
    /// [`RECOMMENDED_FRACTION`] of [`BondModel::critical_timestep`], or
    /// [`BondModel::rattle_timestep`] where that is shorter.
    pub fn recommended_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let critical = self.critical_timestep(radius_i, radius_j, mass_i, mass_j);
        (RECOMMENDED_FRACTION * critical).min(self.rattle_timestep(radius_i, radius_j, mass_i, mass_j))
    }

    /// Compression at which the loading branch of the square root reaches
    /// the break stress, `(max_sigma / k_fn1)^2`: where stress breakage in
    /// compression starts. Infinite when bonds do not break in compression
    /// (distance mode, `max_sigma` infinite, compression off or no
    /// compression stiffness), under `inl_compatible`, whose threshold
    /// depends on the section (the rattle check does not cover it), and for
    /// the linear bond, which has no square root.
    pub fn compression_break_threshold(&self) -> f64 {
        let p = &self.params;
        let breaks = !self.inl
            && !self.linear
            && BondParams::switch(p.stress_break)
            && self.features & COMPRESSION != 0
            && p.k_fn1 > 0.0
            && p.max_sigma.is_finite();
        if !breaks {
            return f64::INFINITY;
        }
        let root = p.max_sigma / p.k_fn1;
        root * root
    }

    /// The longest step at which the square root's rattle stays
    /// [`RATTLE_MARGIN`] below [`BondModel::compression_break_threshold`]:
    /// `compression_noise_floor(dt) = threshold / RATTLE_MARGIN`. Infinite
    /// where there is no rattle (regularised law) or no breakage in
    /// compression.
    pub fn rattle_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let threshold = self.compression_break_threshold();
        if !threshold.is_finite() || self.params.compression_linear_below > 0.0 {
            return f64::INFINITY;
        }
        let sec = section(self.params.lambda, radius_i, radius_j);
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let stiffness = self.normal.compression.max_slope() * self.compression_area(sec.area);
        // 16 (k A dt^2 / (8 m_eff))^2 = floor, solved for dt
        let floor = threshold / RATTLE_MARGIN;
        (8.0 * m_eff / stiffness * (floor / 16.0).sqrt()).sqrt()
    }

    /// Compression below which the plain square root (no
    /// `compression_linear_below`) is not integrated at step `dt` but
    /// rattles. Its local stiffness `k_n1 A / (2 sqrt d)` reaches the limit
    /// `4 m_eff / dt^2` at `d_c = (k A dt^2 / (8 m_eff))^2` (`k` the stiffest
    /// compression slope); a bond left below `d_c` gains energy from round-off
    /// until it rattles with an amplitude of a few `d_c` (elastic and
    /// hysteretic, docs/speed-accuracy.md), then stays bounded. This returns
    /// `16 d_c`, where the local step is half the local limit: compressions
    /// above it are resolved, below it they are noise of at most this size.
    /// Zero when the law is regularised (`compression_linear_below > 0`:
    /// bounded stiffness, which [`BondModel::critical_timestep`] covers) or
    /// compression is off.
    pub fn compression_noise_floor(
        &self,
        dt: f64,
        radius_i: f64,
        radius_j: f64,
        mass_i: f64,
        mass_j: f64,
    ) -> f64 {
        if self.features & COMPRESSION == 0 || self.params.compression_linear_below > 0.0 || self.linear {
            return 0.0;
        }
        let sec = section(self.params.lambda, radius_i, radius_j);
        let m_eff = mass_i * mass_j / (mass_i + mass_j);
        let root =
            self.normal.compression.max_slope() * self.compression_area(sec.area) * dt * dt / (8.0 * m_eff);
        16.0 * root * root
    }
}

/// `ku_fn1 / k_fn1` of the measured rows of [`REST_STABLE`].
pub const REST_RATIOS: [f64; 9] = [1.0, 1.02, 1.05, 1.1, 1.2, 1.35, 1.5, 2.0, 3.0];

/// `eta_fn` of the measured columns of [`REST_STABLE`].
pub const REST_DAMPING: [f64; 6] = [0.0, 0.001, 0.003, 0.01, 0.03, 0.1];

/// The largest fraction of the recommended step at which bonds resting at
/// zero compression under the plain square root gained no energy, by
/// `ku_fn1 / k_fn1` (rows, [`REST_RATIOS`]) and `eta_fn` (columns,
/// [`REST_DAMPING`]); 1: none gained at any fraction up to 0.99, 0: all
/// gained, even at 0.05. Measured on the tetrahedron of
/// `shared/repro/energy/in.tetra` (four spheres, six bonds formed at zero
/// compression, one sphere started at 0.1 m/s, `ku = fu k` on every part,
/// `kc = 0`, percentage damping `eta` on every part), 0.2 to 0.3 s, at
/// 0.05, 0.1, 0.2, 0.3, 0.5, 0.7 and 0.99 of the deck's recommended step
/// (LAMMPS); stable: the kinetic energy never above its start.
/// docs/speed-accuracy.md has the table and the commands.
pub const REST_STABLE: [[f64; 6]; 9] = [
    // eta_fn: 0,  0.001, 0.003, 0.01, 0.03, 0.1
    [0.0, 0.3, 0.5, 0.5, 0.5, 1.0], // ku_fn1 = k_fn1
    [0.1, 0.3, 0.5, 0.7, 0.7, 1.0], // 1.02
    [0.1, 0.3, 0.5, 0.7, 1.0, 1.0], // 1.05
    [0.2, 0.5, 0.7, 0.7, 1.0, 1.0], // 1.1
    [0.3, 0.5, 0.7, 1.0, 1.0, 1.0], // 1.2
    [0.3, 0.7, 1.0, 1.0, 1.0, 1.0], // 1.35
    [0.5, 0.7, 1.0, 1.0, 1.0, 1.0], // 1.5
    [0.7, 1.0, 1.0, 1.0, 1.0, 1.0], // 2
    [1.0, 1.0, 1.0, 1.0, 1.0, 1.0], // 3
];

impl BondModel {
    /// The fraction of [`BondModel::recommended_timestep`] up to which bonds
    /// that rest at zero compression (every bond does when it is formed)
    /// are integrated without gaining energy: the plain square root's
    /// stiffness is unbounded there, and each crossing of zero compression
    /// feeds the vibration; hysteresis (`ku_fn1 > k_fn1`: the bond comes to
    /// rest at a permanent set instead) and damping take it out again.
    /// [`REST_STABLE`] at the measured point at or below this type's
    /// `ku_fn1 / k_fn1` and `eta_fn` (smooth damping counts as none: it
    /// fades at the small speeds of a bond at rest). 1 where it does not
    /// apply: compression off or without stiffness, or the law regularised
    /// (`compression_linear_below > 0`, bounded stiffness).
    pub fn rest_stable_fraction(&self) -> f64 {
        let p = &self.params;
        let f = self.features;
        if f & COMPRESSION == 0 || !(p.k_fn1 > 0.0) || p.compression_linear_below > 0.0 {
            return 1.0;
        }
        let (ratio, eta) = (p.ku_fn1 / p.k_fn1, self.rest_damping());
        // The measured point below: a ratio written as 1.1 is 1.1 here too.
        let row = REST_RATIOS
            .iter()
            .rposition(|&r| ratio >= r * (1.0 - 1e-9))
            .unwrap_or(0);
        let column = REST_DAMPING
            .iter()
            .rposition(|&e| eta >= e * (1.0 - 1e-9))
            .unwrap_or(0);
        REST_STABLE[row][column]
    }

    /// The `compression_linear_below` that lets bonds rest stably: where
    /// tension carries and it stays within the bond radius `rb`,
    /// `(k_fn1 / k_fn2)^2`, at which the compression slope at rest
    /// (`k_fn1 / sqrt(eps)`) equals the tension slope `k_fn2`, so a bond at
    /// rest sees one stiffness on both sides (measured stable up to the
    /// recommended step; a smaller one leaves a kink there, which still
    /// gains energy above 0.2 of the step, docs/speed-accuracy.md);
    /// otherwise `1e-3 rb`.
    pub fn rest_regularisation(&self, rb: f64) -> f64 {
        let p = &self.params;
        let matched = (p.k_fn1 / p.k_fn2).powi(2);
        if self.features & TENSION != 0 && matched.is_finite() && matched > 0.0 && matched <= rb {
            matched
        } else {
            1e-3 * rb
        }
    }

    /// The percentage damping of the normal force that holds bonds at rest
    /// ([`BondModel::rest_stable_fraction`]): `eta_fn` with plain damping,
    /// none without or with smooth damping.
    pub fn rest_damping(&self) -> f64 {
        if self.features & (DAMPING | SMOOTH) == DAMPING {
            self.params.eta_fn
        } else {
            0.0
        }
    }

    /// The longest step at which bonds resting at zero compression gain no
    /// energy ([`BondModel::rest_stable_fraction`] of the recommended
    /// step): infinite where the rule does not apply or every measured
    /// fraction was stable, 0 where none was.
    pub fn rest_timestep(&self, radius_i: f64, radius_j: f64, mass_i: f64, mass_j: f64) -> f64 {
        let fraction = self.rest_stable_fraction();
        if fraction >= 1.0 {
            f64::INFINITY
        } else {
            fraction * self.recommended_timestep(radius_i, radius_j, mass_i, mass_j)
        }
    }
}
