//! The energy budget of a rank's bonds (docs/models/bond-nonlinear.md,
//! "Energy"): what the damping and the hysteresis dissipated and what
//! breaks released, summed in the pass, kept only while a deck asks for it.
//!
//! Each force pass `k` (the engine's velocity-Verlet step: positions at
//! `t_k`, velocities at `t_(k-1/2)`) adds, per bond:
//!
//! - damping: `-dt/2 (dL_(k-1) + dL_k) . V_(k-1/2)`, where `dL` are the
//!   damping's loads (force on `i`, torques on `i` and `j`: the loads of
//!   the step less those of the same step undamped) and `V` the pair's
//!   velocities (`v_i - v_j`, `w_i`, `w_j`). A load of pass `k` acts over
//!   the half steps on either side of `t_k`, so its work on the spheres is
//!   `dt/2 dL_k . (V_(k-1/2) + V_(k+1/2))` to the integrator's order; the
//!   second half is added by the next pass, which is why `dL_k` is kept
//!   per bond until then ([`BUDGET_BYTES_PER_BOND`]);
//! - hysteresis: the drop of the stored energy at the present deformation
//!   when the step moved the history, `E(q_k; h_(k-1)) - E(q_k; h_k) >= 0`;
//! - a break: the energy the bond stored half a step before (the loads of
//!   its last intact pass acted for that half step, then none),
//!   `E(q_(k-1); h_(k-1)) - dt/2 L_(k-1) . V_(k-1/2)`, with `q_(k-1)` at
//!   the positions `x_k - dt v_(k-1/2)` and `L_(k-1)` the undamped loads
//!   there.
//!
//! So kinetic energy + stored + dissipated + released is constant to the
//! integrator's error. A setup pass (a run's start) only keeps its damping
//! loads for the first step.

use super::{BondStore, StoredBond};
use crate::bond::{BondModel, BondOutput, BondState, BondStatus};
use crate::kinematics::PairKinematics;
use crate::pair_source::AtomArrays;

/// Doubles of a bond's damping loads kept between passes: the force on `i`
/// and the torques on `i` and `j`.
pub const DAMPING_LOADS_LEN: usize = 9;

/// The bytes a bond costs beyond [`super::BYTES_PER_BOND`] while the budget
/// is kept: its damping loads of the latest pass.
pub const BUDGET_BYTES_PER_BOND: usize = DAMPING_LOADS_LEN * 8;

/// The bytes a bond costs beyond those while its own dissipated energies
/// are kept too (damping, hysteresis).
pub const DISSIPATED_BYTES_PER_BOND: usize = 2 * 8;

/// Doubles a packed bond carries beyond its partner and state while the
/// budget is kept: its damping loads, then its dissipated energies.
const PACKED_EXTRAS: usize = DAMPING_LOADS_LEN + 2;

/// The energy of a rank's bonds that left them (J), since the budget was
/// first kept (or restored).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EnergySums {
    /// Dissipated by the damping.
    pub damping: f64,
    /// Dissipated by the hysteresis (the history's moves).
    pub hysteresis: f64,
    /// Released by breaks: what the broken bonds stored.
    pub released: f64,
}

/// What the budget keeps per bond, beside the store's bonds.
#[derive(Debug, Default)]
pub(super) struct Budget {
    /// Per bond: its damping loads of the latest pass.
    damping_loads: Vec<[f64; DAMPING_LOADS_LEN]>,
    /// Per bond, only while asked for: its dissipated energies (damping,
    /// hysteresis).
    dissipated: Option<Vec<[f64; 2]>>,
    /// The pass's buffers for one chunk.
    pub(super) scratch: Scratch,
}

/// A chunk's states before its step, and its undamped step's states and
/// outputs.
#[derive(Debug, Default)]
pub(super) struct Scratch {
    pub(super) before: Vec<BondState>,
    pub(super) twin: Vec<BondState>,
    pub(super) elastic: Vec<BondOutput>,
}

impl Budget {
    fn new(bonds: usize, per_bond: bool) -> Self {
        Self {
            damping_loads: vec![[0.0; DAMPING_LOADS_LEN]; bonds],
            dissipated: per_bond.then(|| vec![[0.0; 2]; bonds]),
            scratch: Scratch::default(),
        }
    }

    pub(super) fn push(&mut self) {
        self.damping_loads.push([0.0; DAMPING_LOADS_LEN]);
        if let Some(d) = &mut self.dissipated {
            d.push([0.0; 2]);
        }
    }

    pub(super) fn swap(&mut self, a: usize, b: usize) {
        self.damping_loads.swap(a, b);
        if let Some(d) = &mut self.dissipated {
            d.swap(a, b);
        }
    }

    pub(super) fn truncate(&mut self, n: usize) {
        self.damping_loads.truncate(n);
        if let Some(d) = &mut self.dissipated {
            d.truncate(n);
        }
    }

    pub(super) fn shrink_to_fit(&mut self) {
        self.damping_loads.shrink_to_fit();
        if let Some(d) = &mut self.dissipated {
            d.shrink_to_fit();
        }
    }

    /// Per bond, and the chunk's buffers (once a pass used them).
    pub(super) fn bytes(&self) -> usize {
        let s = &self.scratch;
        self.damping_loads.capacity() * BUDGET_BYTES_PER_BOND
            + self
                .dissipated
                .as_ref()
                .map_or(0, |d| d.capacity() * DISSIPATED_BYTES_PER_BOND)
            + (s.before.capacity() + s.twin.capacity()) * std::mem::size_of::<BondState>()
            + s.elastic.capacity() * std::mem::size_of::<BondOutput>()
    }

    /// Bond `k`'s damping loads of the latest pass.
    pub(super) fn damping_loads(&self, k: usize) -> Option<&[f64; DAMPING_LOADS_LEN]> {
        self.damping_loads.get(k)
    }

    /// Bond `k`'s extras as a packed bond carries them.
    pub(super) fn packed(&self, k: usize) -> [f64; PACKED_EXTRAS] {
        let mut extras = [0.0; PACKED_EXTRAS];
        extras[..DAMPING_LOADS_LEN].copy_from_slice(&self.damping_loads[k]);
        if let Some(d) = &self.dissipated {
            extras[DAMPING_LOADS_LEN..].copy_from_slice(&d[k]);
        }
        extras
    }

    /// Bond `k`'s extras from a packed bond (`extras` as long as it
    /// carried: what it lacks stays zero).
    pub(super) fn unpacked(&mut self, k: usize, extras: &[f64]) {
        let loads = extras.len().min(DAMPING_LOADS_LEN);
        self.damping_loads[k][..loads].copy_from_slice(&extras[..loads]);
        if let (Some(d), Some(rest)) = (&mut self.dissipated, extras.get(DAMPING_LOADS_LEN..)) {
            let n = rest.len().min(2);
            d[k][..n].copy_from_slice(&rest[..n]);
        }
    }
}

/// Doubles a packed bond carries beyond its partner and state: the
/// budget's extras while it is kept.
pub(super) fn packed_extras(kept: bool) -> usize {
    if kept {
        PACKED_EXTRAS
    } else {
        0
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The loads of `out` as one vector: force on `i`, torques on `i` and `j`.
fn loads(out: &BondOutput) -> [f64; DAMPING_LOADS_LEN] {
    let mut l = [0.0; DAMPING_LOADS_LEN];
    l[..3].copy_from_slice(&out.force_i);
    l[3..6].copy_from_slice(&out.torque_i);
    l[6..].copy_from_slice(&out.torque_j);
    l
}

/// Whether a step moved any of the history's extremes.
fn history_moved(before: &BondState, after: &BondState) -> bool {
    before.delta_max != after.delta_max
        || before.delta_min != after.delta_min
        || before.twist_max != after.twist_max
        || before.twist_min != after.twist_min
        || before.bend_history != after.bend_history
        || before.bend_opposite != after.bend_opposite
}

/// `state` with the history's extremes of `history`.
fn with_history(state: &BondState, history: &BondState) -> BondState {
    BondState {
        delta_max: history.delta_max,
        delta_min: history.delta_min,
        twist_max: history.twist_max,
        twist_min: history.twist_min,
        bend_history: history.bend_history,
        bend_opposite: history.bend_opposite,
        ..*state
    }
}

/// One pair's positions, velocities and radii, read from the atoms.
struct Pair {
    x: [[f64; 3]; 2],
    v: [[f64; 3]; 2],
    w: [[f64; 3]; 2],
    radius: [f64; 2],
}

impl Pair {
    fn read(atoms: &AtomArrays<'_>, ends: [i32; 2]) -> Self {
        let [i, j] = ends.map(|a| a as usize);
        let three = |a: &[f64], k: usize| [a[3 * k], a[3 * k + 1], a[3 * k + 2]];
        Self {
            x: [three(atoms.x, i), three(atoms.x, j)],
            v: [three(atoms.v, i), three(atoms.v, j)],
            w: [three(atoms.omega, i), three(atoms.omega, j)],
            radius: [atoms.radius[i], atoms.radius[j]],
        }
    }

    /// `(v_i - v_j, w_i, w_j)`: what the loads of [`loads`] do work on.
    fn velocities(&self) -> [f64; DAMPING_LOADS_LEN] {
        let mut v = [0.0; DAMPING_LOADS_LEN];
        for c in 0..3 {
            v[c] = self.v[0][c] - self.v[1][c];
            v[3 + c] = self.w[0][c];
            v[6 + c] = self.w[1][c];
        }
        v
    }

    /// The positions `back` seconds before, at the velocities now.
    fn moved_back(&self, back: f64) -> Self {
        let step = |x: [f64; 3], v: [f64; 3]| [0, 1, 2].map(|c| x[c] - back * v[c]);
        Self {
            x: [step(self.x[0], self.v[0]), step(self.x[1], self.v[1])],
            ..*self
        }
    }

    fn kinematics(&self) -> PairKinematics {
        PairKinematics {
            x_i: self.x[0],
            x_j: self.x[1],
            v_i: self.v[0],
            v_j: self.v[1],
            w_i: self.w[0],
            w_j: self.w[1],
            radius_i: self.radius[0],
            radius_j: self.radius[1],
        }
    }

    /// The energy a bond of `model` with `state` stores at these positions.
    fn stored(&self, model: &BondModel, state: &BondState) -> f64 {
        let d = [0, 1, 2].map(|c| self.x[0][c] - self.x[1][c]);
        let r = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if !(r > 0.0) {
            return 0.0;
        }
        model
            .stored_energy(
                state,
                d.map(|c| c / r),
                state.r0() - r,
                self.radius[0],
                self.radius[1],
            )
            .total()
    }
}

/// What one bond's pass added to the budget (J).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BondBudgetStep {
    /// Dissipated by the damping: the work its loads took from the
    /// spheres, counted over the half steps around the pass. One half step
    /// alone can be negative where the relative motion reverses; the law's
    /// own dissipation rate, `-dL_k . V_(k-1/2)`, never is.
    pub damping: f64,
    /// Dissipated by the hysteresis (never negative under the default
    /// history rule).
    pub hysteresis: f64,
    /// Released by a break.
    pub released: f64,
    /// The law's own damping work in this step, `-dt dL_k . V_(k-1/2)`.
    pub damping_law: f64,
}

/// The budget's terms of one bond of `model` over a force pass of `dt`
/// (`dt = 0`: a setup pass, which adds nothing): its state `before` and
/// `after` the step, the step's output `out` and that of the same step
/// undamped `elastic` (`None` without damping), its atoms now `pair`, the
/// damping loads of its previous pass `previous` (replaced by this pass's),
/// and whether it formed in this pass (`fresh`).
#[allow(clippy::too_many_arguments)]
fn bond_step_budget(
    model: &BondModel,
    dt: f64,
    before: &BondState,
    after: &BondState,
    out: &BondOutput,
    elastic: Option<&BondOutput>,
    pair: &Pair,
    previous: &mut [f64; DAMPING_LOADS_LEN],
    fresh: bool,
) -> BondBudgetStep {
    let v = pair.velocities();
    let mut step = BondBudgetStep::default();
    // without damping the loads kept stay zero
    if let Some(e) = elastic {
        let (l, le) = (loads(out), loads(e));
        let damping_loads = [0, 1, 2, 3, 4, 5, 6, 7, 8].map(|c| l[c] - le[c]);
        let now = dot(&damping_loads, &v);
        step.damping = -0.5 * dt * (dot(previous, &v) + now);
        step.damping_law = -dt * now;
        *previous = damping_loads;
    }
    if dt == 0.0 {
        return BondBudgetStep::default();
    }
    if out.status == BondStatus::Intact as i32 {
        if history_moved(before, after) {
            step.hysteresis = pair.stored(model, &with_history(after, before)) - pair.stored(model, after);
        }
    } else if fresh {
        step.released = pair.stored(model, before);
    } else {
        // half a step back: the positions of the previous pass, and the
        // undamped loads the bond exerted there (a zero step of its state)
        let back = pair.moved_back(dt);
        let law = model.undamped().unwrap_or(model);
        let mut state = *before;
        let mut last = BondOutput::default();
        let worked = match law.step(&back.kinematics(), 0.0, &mut state, &mut last) {
            Ok(()) => dot(&loads(&last), &v),
            Err(_) => 0.0,
        };
        step.released = back.stored(model, before) - 0.5 * dt * worked;
    }
    step
}

impl BondStore {
    /// Keeps the energy budget (`on`) or stops keeping it, with each bond's
    /// dissipated energies too (`per_bond`). Turned on, every bond starts
    /// without damping loads; the sums go on from where they were.
    pub fn keep_energy_budget(&mut self, on: bool, per_bond: bool) {
        match (&mut self.budget, on) {
            (_, false) => self.budget = None,
            (None, true) => self.budget = Some(Budget::new(self.bonds.len(), per_bond)),
            (Some(b), true) => match (&b.dissipated, per_bond) {
                (None, true) => b.dissipated = Some(vec![[0.0; 2]; self.bonds.len()]),
                (Some(_), false) => b.dissipated = None,
                _ => {}
            },
        }
    }

    /// Whether the energy budget is kept, and each bond's share of it.
    pub fn energy_budget_kept(&self) -> (bool, bool) {
        match &self.budget {
            None => (false, false),
            Some(b) => (true, b.dissipated.is_some()),
        }
    }

    /// The energy the bonds of this rank dissipated and released since the
    /// budget was first kept (or restored).
    pub fn energy_sums(&self) -> EnergySums {
        self.energy
    }

    /// Restores the sums of a restart file (on one rank; the others keep
    /// zero, so the sums over ranks are the file's).
    pub fn restore_energy_sums(&mut self, sums: &EnergySums) {
        self.energy = *sums;
    }

    /// Bond `k`'s dissipated energies (damping, hysteresis) since the store
    /// kept them; `None` while they are not kept, or beyond the bonds.
    pub fn dissipated(&self, k: usize) -> Option<[f64; 2]> {
        self.budget.as_ref()?.dissipated.as_ref()?.get(k).copied()
    }

    /// The budget's terms of the bonds `first..first + n` just stepped by
    /// `model` over `dt` (0: a setup pass) from the states `before`, with
    /// outputs `outs`; `elastic` are the outputs of the same steps undamped
    /// (`None` without damping). Bonds from `fresh` on formed in this pass.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn tally_energy(
        &mut self,
        model: &BondModel,
        atoms: &AtomArrays<'_>,
        dt: f64,
        first: usize,
        before: &[BondState],
        outs: &[BondOutput],
        elastic: Option<&[BondOutput]>,
        fresh: usize,
    ) {
        let Some(budget) = self.budget.as_mut() else {
            return;
        };
        for (b, out) in outs.iter().enumerate() {
            let k = first + b;
            let StoredBond { state, .. } = &self.bonds[k];
            let pair = Pair::read(atoms, self.ends[k]);
            let step = bond_step_budget(
                model,
                dt,
                &before[b],
                state,
                out,
                elastic.map(|e| &e[b]),
                &pair,
                &mut budget.damping_loads[k],
                k >= fresh,
            );
            self.energy.damping += step.damping;
            self.energy.hysteresis += step.hysteresis;
            self.energy.released += step.released;
            if let Some(d) = &mut budget.dissipated {
                d[k][0] += step.damping;
                d[k][1] += step.hysteresis;
            }
        }
    }
}

/// The budget's terms of one step of a lone bond of `model` between the
/// spheres of `kin` (velocities at the half step, as an engine's force pass
/// sees them) over `dt`: its state `before` and `after`, the step's output
/// `out`, and the damping loads of its previous step `previous` (replaced).
/// For tests of the budget's parts without a store.
pub fn step_budget(
    model: &BondModel,
    kin: &PairKinematics,
    dt: f64,
    before: &BondState,
    after: &BondState,
    out: &BondOutput,
    previous: &mut [f64; DAMPING_LOADS_LEN],
) -> BondBudgetStep {
    let elastic = model.undamped().map(|u| {
        let (mut s, mut e) = (*before, BondOutput::default());
        // the step itself succeeded on these kinematics
        let _ = u.step(kin, dt, &mut s, &mut e);
        e
    });
    let pair = Pair {
        x: [kin.x_i, kin.x_j],
        v: [kin.v_i, kin.v_j],
        w: [kin.w_i, kin.w_j],
        radius: [kin.radius_i, kin.radius_j],
    };
    bond_step_budget(
        model,
        dt,
        before,
        after,
        out,
        elastic.as_ref(),
        &pair,
        previous,
        false,
    )
}
