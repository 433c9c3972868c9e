//! One bond step, generic over the active degrees of freedom: each switched
//! off part is removed at compile time, so it costs nothing. One
//! monomorphised kernel per combination of the seven feature bits.

use super::breakage::{distance_criterion, section_stresses, stress_criterion, BreakMode};
use super::chunk;
use super::damping::{damp_along, damp_scalar, reciprocal_unit, sign, unit_scale};
use super::lanes::{norms, reciprocals};
use super::model::BondModel;
use super::section::{lever_arms_scaled, section};
use super::shear::update_shear_force;
use super::state::{BondOutput, BondState, BondStatus};
use super::twist_bend::{advance_bend, advance_twist, split_relative_spin, BendHistory, TwistHistory};
use crate::kinematics::{centre_line, slip_velocity, CentreLine, KinematicsError, PairKinematics};
use crate::pair_source::IndexedPairs;
use crate::real::Real;
use crate::vector::{v3, Vec3, Vector};
use seq_macro::seq;

pub const TENSION: u32 = 1;
pub const COMPRESSION: u32 = 2;
pub const SHEAR: u32 = 4;
pub const TWIST: u32 = 8;
pub const BEND: u32 = 16;
pub const DAMPING: u32 = 32;
pub const SMOOTH: u32 = 64;
pub const FEATURE_COMBINATIONS: usize = 128;

pub type Kernel =
    fn(&BondModel, &PairKinematics, f64, &mut BondState, &mut BondOutput) -> Result<(), KinematicsError>;
pub type BatchKernel = fn(
    &BondModel,
    &[PairKinematics],
    f64,
    &mut [BondState],
    &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)>;
pub type ScatteredKernel = fn(
    &BondModel,
    &[PairKinematics],
    f64,
    &mut [&mut BondState],
    &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)>;
pub type IndexedKernel = fn(
    &BondModel,
    &IndexedPairs<'_>,
    f64,
    &mut [&mut BondState],
    &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)>;

#[inline(always)]
fn finish(state: &mut BondState, out: &mut BondOutput, status: BondStatus, mode: BreakMode) {
    state.status = status as i32 as f64;
    out.force_i = [0.0; 3];
    out.torque_i = [0.0; 3];
    out.torque_j = [0.0; 3];
    out.status = status as i32;
    out.break_mode = mode as i32;
}

/// What a step reads of a pair besides its centre line.
#[derive(Clone, Copy)]
pub(crate) struct Motion<R, V> {
    pub v_i: V,
    pub v_j: V,
    pub w_i: V,
    pub w_j: V,
    pub radius_i: R,
    pub radius_j: R,
}

/// The slots of [`BondState`] a step updates (all but the status).
#[derive(Clone, Copy)]
pub(crate) struct History<R, V> {
    pub r0: R,
    pub delta_max: R,
    pub delta_min: R,
    pub shear_force: V,
    pub twist_angle: V,
    pub bend_angle: V,
    pub twist: TwistHistory<R>,
    pub bend: BendHistory<R, V>,
}

impl<R: Real, V: Vector<R>> History<R, V> {
    #[inline(always)]
    fn select(m: R::Mask, a: Self, b: Self) -> Self {
        Self {
            r0: R::select(m, a.r0, b.r0),
            delta_max: R::select(m, a.delta_max, b.delta_max),
            delta_min: R::select(m, a.delta_min, b.delta_min),
            shear_force: V::select(m, a.shear_force, b.shear_force),
            twist_angle: V::select(m, a.twist_angle, b.twist_angle),
            bend_angle: V::select(m, a.bend_angle, b.bend_angle),
            twist: TwistHistory {
                max: R::select(m, a.twist.max, b.twist.max),
                min: R::select(m, a.twist.min, b.twist.min),
            },
            bend: BendHistory {
                leading: V::select(m, a.bend.leading, b.bend.leading),
                opposite: R::select(m, a.bend.opposite, b.bend.opposite),
            },
        }
    }
}

/// What a step produces: [`BondOutput`] but the status, which follows from
/// `mode`, the [`BreakMode`] as a number (0: the bond holds).
#[derive(Clone, Copy)]
pub(crate) struct Loads<R, V> {
    pub force_i: V,
    pub torque_i: V,
    pub torque_j: V,
    pub normal_force: R,
    pub sigma: R,
    pub tau: R,
    pub delta: R,
    pub mode: R,
}

/// Advances one bond by `dt` and writes the loads on both spheres. A bond
/// that is not intact, or breaks in this step, exerts nothing.
#[inline(always)]
pub fn bond_step<const F: u32>(
    model: &BondModel,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    let status = state.status();
    if status != BondStatus::Intact {
        *out = BondOutput::default();
        finish(state, out, status, BreakMode::None);
        return Ok(());
    }
    kin.check()?;
    let line = centre_line(kin)?;
    let motion = Motion {
        v_i: v3(kin.v_i),
        v_j: v3(kin.v_j),
        w_i: v3(kin.w_i),
        w_j: v3(kin.w_j),
        radius_i: kin.radius_i,
        radius_j: kin.radius_j,
    };
    let mut history = History {
        r0: state.r0,
        delta_max: state.delta_max,
        delta_min: state.delta_min,
        shear_force: v3(state.shear_force),
        twist_angle: v3(state.twist_angle),
        bend_angle: v3(state.bend_angle),
        twist: TwistHistory {
            max: state.twist_max,
            min: state.twist_min,
        },
        bend: BendHistory {
            leading: v3(state.bend_history),
            opposite: state.bend_opposite,
        },
    };
    let loads = advance::<F, f64, Vec3>(model, &motion, line, dt, &mut history);
    state.delta_max = history.delta_max;
    state.delta_min = history.delta_min;
    state.shear_force = history.shear_force.into();
    state.twist_angle = history.twist_angle.into();
    state.bend_angle = history.bend_angle.into();
    state.twist_max = history.twist.max;
    state.twist_min = history.twist.min;
    state.bend_history = history.bend.leading.into();
    state.bend_opposite = history.bend.opposite;
    out.delta = loads.delta;
    out.normal_force = loads.normal_force;
    out.sigma = loads.sigma;
    out.tau = loads.tau;
    out.force_i = loads.force_i.into();
    out.torque_i = loads.torque_i.into();
    out.torque_j = loads.torque_j.into();
    let mode = BreakMode::from_number(loads.mode);
    let status = if mode == BreakMode::None {
        BondStatus::Intact
    } else {
        BondStatus::Broken
    };
    state.status = status as i32 as f64;
    out.status = status as i32;
    out.break_mode = mode as i32;
    Ok(())
}

/// The physics of one step of an intact bond with usable kinematics, for one
/// bond (`f64`) or a chunk of lanes (see [`super::chunk`]): updates
/// `history` and returns the loads.
///
/// A bond that breaks exerts nothing. One broken by distance keeps its
/// history as it was and reports no stresses; one broken by stress has its
/// history updated and reports the stresses that broke it. The scalar
/// kernel returns as soon as its bond breaks; in lanes every lane is
/// computed and the broken ones are masked at the end (and the history of
/// the ones broken by distance restored), unless all of them broke.
#[inline(always)]
pub(crate) fn advance<const F: u32, R: Real, V: Vector<R>>(
    model: &BondModel,
    m: &Motion<R, V>,
    line: CentreLine<R, V>,
    dt: R,
    h: &mut History<R, V>,
) -> Loads<R, V> {
    let zero = R::splat(0.0);
    let n = line.n;
    let delta = h.r0 - line.r;
    let broken = |normal_force, sigma, tau, mode| Loads {
        force_i: V::zeros(),
        torque_i: V::zeros(),
        torque_j: V::zeros(),
        normal_force,
        sigma,
        tau,
        delta,
        mode,
    };
    let distance_mode = R::splat(BreakMode::Distance as i32 as f64);
    let gone = if model.stress_break {
        R::mask(false)
    } else {
        distance_criterion(line.r, model.params.max_distance)
    };
    if R::all(gone) {
        return broken(zero, zero, zero, distance_mode);
    }
    let before = *h;
    let sec = section(model.params.lambda, m.radius_i, m.radius_j);
    // The only divisions by the radii: the stresses and lever arms multiply.
    let (inv_rb, inv_radius_sum) = super::section::reciprocals(&sec, m.radius_i, m.radius_j);

    let mut normal_force = zero;
    if F & (TENSION | COMPRESSION) != 0 {
        let (hi, lo) = model.normal.update_history(delta, h.delta_max, h.delta_min);
        h.delta_max = hi;
        h.delta_min = lo;
        normal_force = sec.area
            * model
                .normal
                .stress(delta, hi, lo, F & TENSION != 0, F & COMPRESSION != 0);
    }

    let (mut lever_i, mut lever_j) = (zero, zero);
    let mut slip = V::zeros();
    let mut shear_force = V::zeros();
    if F & SHEAR != 0 {
        (lever_i, lever_j) = lever_arms_scaled(line.r, inv_radius_sum, m.radius_i, m.radius_j);
        slip = slip_velocity(m.v_i - m.v_j, m.w_i, m.w_j, n, lever_i, lever_j);
        let stiffness = R::splat(model.params.k_ft) * sec.area;
        shear_force = update_shear_force(h.shear_force, stiffness, dt, slip, n);
        h.shear_force = shear_force;
    }

    let (twist, bend) = (F & TWIST != 0, F & BEND != 0);
    let (w_along, w_across, spin_rate) = if twist || bend {
        split_relative_spin(m.w_i - m.w_j, n)
    } else {
        (V::zeros(), V::zeros(), zero)
    };
    let (mut twist_torque, mut bend_torque) = (V::zeros(), V::zeros());
    // |torque| = |h| * moment, from the laws (no square roots).
    let (mut twist_magnitude, mut bend_magnitude) = (zero, zero);
    if twist {
        let theta = advance_twist(h.twist_angle, w_along, n, dt);
        let (t, history) = model.twist.twist(theta, n, h.twist, sec.polar);
        h.twist_angle = theta;
        h.twist = history;
        (twist_torque, twist_magnitude) = (t.torque, t.magnitude);
    }
    if bend {
        let theta = advance_bend(h.bend_angle, w_across, n, dt);
        let (t, history) = model.bend.bend(theta, n, h.bend, sec.inertia);
        h.bend_angle = theta;
        h.bend = history;
        (bend_torque, bend_magnitude) = (t.torque, t.magnitude);
    }
    // Lanes broken by distance keep their history (a scalar bond returned
    // above; for it `gone` is false here and this vanishes).
    if R::any(gone) {
        *h = History::select(gone, before, *h);
    }

    // Lengths, two per instruction: the shear force (for the stresses and
    // the damping) and, with damping, the slip speed the damping opposes.
    let (shear, damping) = (F & SHEAR != 0, F & DAMPING != 0);
    let (shear_magnitude, slip_speed) = norms(shear_force, shear, slip, shear && damping);
    let (sigma, tau) = section_stresses(
        normal_force,
        shear_magnitude,
        twist_magnitude,
        bend_magnitude,
        inv_rb,
    );
    let undamped = normal_force;
    let stress_mode = if model.stress_break {
        stress_criterion(sigma, tau, delta, &model.limits)
    } else {
        zero
    };
    let snapped = stress_mode.gt(zero);
    if R::all(snapped) {
        return broken(normal_force, sigma, tau, stress_mode);
    }

    if damping {
        let smooth = F & SMOOTH != 0;
        let p = &model.params;
        let (ve, we) = (p.smooth_velocity, p.smooth_angular_velocity);
        if F & (TENSION | COMPRESSION) != 0 {
            let vn = (m.v_i - m.v_j).dot(&n);
            normal_force = damp_scalar(normal_force, p.eta_fn, vn, ve, smooth);
        }
        // The (smooth) unit vectors of the slip and of the bending spin: one
        // reciprocal each, both in one instruction.
        let spin_across = if bend { w_across.norm() } else { zero };
        let scale_s = unit_scale(slip_speed, ve, smooth);
        let scale_b = unit_scale(spin_across, we, smooth);
        let (inv_s, inv_b) = reciprocals(scale_s, shear, scale_b, bend);
        if shear {
            let direction = reciprocal_unit(slip, scale_s, inv_s);
            shear_force = damp_along(shear_force, shear_magnitude, p.eta_ft, direction);
        }
        if twist {
            // w_along = n (w . n), so its unit vector is n sgn(w . n) (and
            // the smooth one n clamp(w . n / we, -1, 1), the same thing).
            let direction = n * sign(spin_rate, we, smooth);
            twist_torque = damp_along(twist_torque, twist_magnitude, p.eta_tn, direction);
        }
        if bend {
            let direction = reciprocal_unit(w_across, scale_b, inv_b);
            bend_torque = damp_along(bend_torque, bend_magnitude, p.eta_tt, direction);
        }
    }

    let force = n * normal_force + shear_force;
    let couple = bend_torque + twist_torque;
    let (mut torque_i, mut torque_j) = (couple, -couple);
    if shear {
        let arm = n.cross(&shear_force);
        torque_i -= arm * lever_i;
        torque_j -= arm * lever_j;
    }
    // The lanes that broke (none for a scalar bond here) exert nothing.
    let off = gone | snapped;
    let load = |v| V::select(off, V::zeros(), v);
    Loads {
        force_i: load(force),
        torque_i: load(torque_i),
        torque_j: load(torque_j),
        normal_force: R::select(gone, zero, undamped),
        sigma: R::select(gone, zero, sigma),
        tau: R::select(gone, zero, tau),
        delta,
        // (`stress_mode` is 0 unless `snapped`; spelt out, the scalar
        // kernel sees a constant here.)
        mode: R::select(gone, distance_mode, R::select(snapped, stress_mode, zero)),
    }
}

fn single<const F: u32>(
    model: &BondModel,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    bond_step::<F>(model, kin, dt, state, out)
}

fn batch<const F: u32>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    chunk::all_one_by_one::<F, _, _>(model, kin, dt, states, outs)
}

fn scattered<const F: u32>(
    model: &BondModel,
    kin: &[PairKinematics],
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    chunk::all_one_by_one::<F, _, _>(model, kin, dt, states, outs)
}

fn indexed<const F: u32>(
    model: &BondModel,
    kin: &IndexedPairs<'_>,
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
) -> Result<(), (usize, KinematicsError)> {
    chunk::all_one_by_one::<F, _, _>(model, kin, dt, states, outs)
}

/// The instruction sets [`BondModel::step_scattered`] can run on: one bond
/// at a time, or chunks of 4 (AVX2) / 8 (AVX-512) bonds in lanes. All give
/// the same bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Simd {
    Scalar,
    Avx2,
    Avx512,
}

impl Simd {
    /// What `BondModel` uses: AVX2 where the CPU has it. AVX-512 is not
    /// chosen by itself: twice the lanes, but twice the transposing per
    /// chunk too, and on the Xeon this was measured on it was slower than
    /// AVX2 (`benches/kernels.rs`, `scattered_*`).
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if is_x86_feature_detected!("avx2") {
                return Simd::Avx2;
            }
        }
        Simd::Scalar
    }

    /// Whether this CPU runs `self`.
    pub fn available(self) -> bool {
        match self {
            Simd::Scalar => true,
            #[cfg(target_arch = "x86_64")]
            Simd::Avx2 => is_x86_feature_detected!("avx2"),
            #[cfg(target_arch = "x86_64")]
            Simd::Avx512 => is_x86_feature_detected!("avx512f"),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod wide {
    use super::*;
    use crate::pair_source::PairSource;
    use crate::real::packed::{F64x4, F64x8};

    /// The kernel compiled for AVX2, 4 bonds per instruction (the
    /// `#[inline(always)]` laws and lane operations take on this function's
    /// target features).
    #[target_feature(enable = "avx2")]
    fn avx2<const F: u32, K: PairSource + ?Sized>(
        model: &BondModel,
        kin: &K,
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        chunk::in_chunks::<F, F64x4, K>(model, kin, dt, states, outs)
    }

    /// The same for AVX-512, 8 bonds per instruction.
    #[target_feature(enable = "avx512f")]
    fn avx512<const F: u32, K: PairSource + ?Sized>(
        model: &BondModel,
        kin: &K,
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        chunk::in_chunks::<F, F64x8, K>(model, kin, dt, states, outs)
    }

    /// The entries of the kernel tables: one per instruction set and
    /// source of kinematics, the same safe shell around each.
    macro_rules! entry {
        ($name:ident, $kernel:ident, $source:ty) => {
            pub(super) fn $name<const F: u32>(
                model: &BondModel,
                kin: &$source,
                dt: f64,
                states: &mut [&mut BondState],
                outs: &mut [BondOutput],
            ) -> Result<(), (usize, KinematicsError)> {
                // SAFETY: only handed out by `scattered_kernels` for the
                // instruction set it names, which `BondModel` checks the
                // CPU runs.
                unsafe { $kernel::<F, _>(model, kin, dt, states, outs) }
            }
        };
    }
    entry!(scattered_avx2, avx2, [PairKinematics]);
    entry!(indexed_avx2, avx2, IndexedPairs<'_>);
    entry!(scattered_avx512, avx512, [PairKinematics]);
    entry!(indexed_avx512, avx512, IndexedPairs<'_>);
}

seq!(N in 0..128 {
    const SINGLE: [Kernel; FEATURE_COMBINATIONS] = [#(single::<N>,)*];
    const BATCH: [BatchKernel; FEATURE_COMBINATIONS] = [#(batch::<N>,)*];
    const SCATTERED: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(scattered::<N>,)*];
    const INDEXED: [IndexedKernel; FEATURE_COMBINATIONS] = [#(indexed::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const SCATTERED_AVX2: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(wide::scattered_avx2::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const INDEXED_AVX2: [IndexedKernel; FEATURE_COMBINATIONS] = [#(wide::indexed_avx2::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const SCATTERED_AVX512: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(wide::scattered_avx512::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const INDEXED_AVX512: [IndexedKernel; FEATURE_COMBINATIONS] = [#(wide::indexed_avx512::<N>,)*];
});

pub fn single_kernel(features: u32) -> Kernel {
    SINGLE[features as usize % FEATURE_COMBINATIONS]
}

pub fn batch_kernel(features: u32) -> BatchKernel {
    BATCH[features as usize % FEATURE_COMBINATIONS]
}

/// The kernels for bonds whose states lie apart, for `simd`, which the
/// caller has checked this CPU runs ([`Simd::available`]); `Scalar` for a
/// width not compiled in.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScatteredKernels {
    pub scattered: ScatteredKernel,
    pub indexed: IndexedKernel,
    pub simd: Simd,
}

pub(crate) fn scattered_kernels(features: u32, simd: Simd) -> ScatteredKernels {
    let f = features as usize % FEATURE_COMBINATIONS;
    let (scattered, indexed, simd) = match simd {
        #[cfg(target_arch = "x86_64")]
        Simd::Avx2 => (SCATTERED_AVX2[f], INDEXED_AVX2[f], Simd::Avx2),
        #[cfg(target_arch = "x86_64")]
        Simd::Avx512 => (SCATTERED_AVX512[f], INDEXED_AVX512[f], Simd::Avx512),
        _ => (SCATTERED[f], INDEXED[f], Simd::Scalar),
    };
    ScatteredKernels {
        scattered,
        indexed,
        simd,
    }
}

impl BondModel {
    /// Advances one bond (see [`bond_step`]).
    #[inline]
    pub fn step(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut BondState,
        out: &mut BondOutput,
    ) -> Result<(), KinematicsError> {
        (self.single)(self, kin, dt, state, out)
    }

    /// Advances every bond of equal-length slices; stops at the first bad
    /// input and reports its index.
    pub fn step_batch(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        (self.batch)(self, kin, dt, states, outs)
    }

    /// [`Self::step_batch`] for states that lie apart in memory (in an
    /// engine's contact history): one call per pass of the pair loop, and
    /// the same results, bit for bit, as one [`Self::step`] per bond.
    pub fn step_scattered(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        (self.kernels.scattered)(self, kin, dt, states, outs)
    }

    /// [`Self::step_scattered`] reading each bond's kinematics from the
    /// engine's per-atom arrays: the same results, bit for bit.
    pub fn step_indexed(
        &self,
        kin: &IndexedPairs<'_>,
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> Result<(), (usize, KinematicsError)> {
        (self.kernels.indexed)(self, kin, dt, states, outs)
    }
}
