//! A bond type as engines use it: its laws ([`BondLaws`]) and the compiled
//! steps chosen for their switches on this CPU.

use super::atom_loads::LoadSink;
use super::dispatch::{inl_kernels, kernels, linear_kernels, Kernels};
use super::finite::BatchResult;
use super::inl::inl_step;
use super::laws::BondLaws;
use super::linear::linear_step;
use super::params::{BondParams, ParameterError};
use super::state::{BondOutput, BondState};
use crate::kinematics::{KinematicsError, PairKinematics};
use crate::pair_source::IndexedPairs;
use crate::simd::Simd;
use std::ops::Deref;
use std::sync::OnceLock;

/// A bond type as engines use it (`GbBondModel` in the C ABI): its
/// [`BondLaws`], read through `Deref`, and the compiled steps chosen for
/// its switches on this CPU.
#[derive(Clone, Debug)]
pub struct BondModel {
    laws: BondLaws,
    /// For every step entry, on the instruction set chosen once, at
    /// construction.
    kernels: Kernels,
    /// The same laws without damping, built when first asked for
    /// ([`Self::undamped`]).
    undamped: OnceLock<Option<Box<BondModel>>>,
}

/// A model is read as its laws (`model.params`, `model.features`, ...).
impl Deref for BondModel {
    type Target = BondLaws;

    fn deref(&self) -> &BondLaws {
        &self.laws
    }
}

impl BondModel {
    /// Validates `params` and builds the bond type, with its steps on the
    /// instruction set [`Simd::chosen`] picks.
    pub fn new(params: BondParams) -> Result<Self, ParameterError> {
        let laws = BondLaws::new(params)?;
        let kernels = Self::kernels_for(&laws, Simd::chosen(), true);
        Ok(Self {
            laws,
            kernels,
            undamped: OnceLock::new(),
        })
    }

    /// The same laws without damping, `None` for a model without it: a
    /// step of it from the same state gives the same history and the
    /// loads the laws alone exert, so the damping's loads are the
    /// difference (the energy budget, `crate::bond_store`).
    pub fn undamped(&self) -> Option<&BondModel> {
        self.undamped
            .get_or_init(|| {
                let p = &self.params;
                let any_eta = [p.eta_fn, p.eta_ft, p.eta_tn, p.eta_tt].iter().any(|&e| e > 0.0);
                if !p.damping_on() || !any_eta {
                    return None;
                }
                let params = BondParams {
                    damping: 0,
                    damping_smooth: 0,
                    ..self.params
                };
                // the parameters were valid with damping: they are without
                BondModel::new(params).ok().map(Box::new)
            })
            .as_deref()
    }

    /// The steps of `laws` on `simd`: LIGGGHTS-INL's law (`inl_compatible`)
    /// is stepped one bond at a time on every path.
    fn kernels_for(laws: &BondLaws, simd: Simd, own: bool) -> Kernels {
        if laws.linear {
            linear_kernels()
        } else if laws.inl {
            inl_kernels()
        } else {
            kernels(laws.features, simd, own)
        }
    }

    /// The instruction set [`Self::step_batch`], [`Self::step_scattered`]
    /// and [`Self::step_indexed`] run on.
    pub fn simd(&self) -> Simd {
        self.kernels.simd
    }

    /// The model with its batch entries on `simd` (the same results, only
    /// the speed differs), or `None` when this CPU does not run it or it is
    /// not compiled in. For tests and benchmarks.
    pub fn with_simd(mut self, simd: Simd) -> Option<Self> {
        if !simd.available() {
            return None;
        }
        let kernels = Self::kernels_for(&self.laws, simd, self.kernels.own);
        if kernels.simd != simd {
            return None;
        }
        self.kernels = kernels;
        Some(self)
    }

    /// Whether the model's steps are compiled for its combination of
    /// switches alone ([`super::features::COMPILED_ALONE`]) rather than
    /// reading the switches at run time.
    pub fn compiled_alone(&self) -> bool {
        self.kernels.own
    }

    /// The model with the steps that read the switches at run time, the ones
    /// every combination without steps of its own runs: the same results,
    /// only the speed differs. For tests and benchmarks.
    pub fn switched(mut self) -> Self {
        self.kernels = Self::kernels_for(&self.laws, self.kernels.simd, false);
        self
    }

    /// Advances one bond (see `bond::scalar::bond_step`).
    #[inline]
    pub fn step(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut BondState,
        out: &mut BondOutput,
    ) -> Result<(), KinematicsError> {
        (self.kernels.single)(&self.laws, kin, dt, state, out)
    }

    /// The loads a run's setup pass applies, where the law computes them
    /// afresh: LIGGGHTS-INL's code (`inl_compatible`) evaluates a trial
    /// step, which moves only the history extremes and breaks nothing, and
    /// its linear bond (`linear`) one that moves nothing.
    /// `Ok(false)` for the default law, whose setup pass evaluates its
    /// stored state over a zero time step (`crate::bond_store`'s pass):
    /// nothing is written.
    /// `wall`: `kin` is a wall bond's, its partner from
    /// [`super::wall::wall_kinematics`] (which does not move here).
    pub fn setup_step(
        &self,
        kin: &PairKinematics,
        dt: f64,
        state: &mut BondState,
        out: &mut BondOutput,
        wall: bool,
    ) -> Result<bool, KinematicsError> {
        if self.laws.linear {
            linear_step(&self.laws, kin, dt, state, out, wall, false)?;
            return Ok(true);
        }
        if !self.laws.inl {
            return Ok(false);
        }
        inl_step(&self.laws, kin, dt, state, out, wall, false)?;
        Ok(true)
    }

    /// Advances every bond of equal-length slices; stops at the first bond
    /// whose kinematics are unusable and reports its index, and otherwise
    /// names the first bond whose results are not finite ([`BatchResult`]).
    pub fn step_batch(
        &self,
        kin: &[PairKinematics],
        dt: f64,
        states: &mut [BondState],
        outs: &mut [BondOutput],
    ) -> BatchResult {
        (self.kernels.batch)(&self.laws, kin, dt, states, outs)
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
    ) -> BatchResult {
        (self.kernels.scattered)(&self.laws, kin, dt, states, outs)
    }

    /// [`Self::step_scattered`] reading each bond's kinematics from the
    /// engine's per-atom arrays: the same results, bit for bit.
    pub fn step_indexed(
        &self,
        kin: &IndexedPairs<'_>,
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
    ) -> BatchResult {
        (self.kernels.indexed)(&self.laws, kin, dt, states, outs, &LoadSink::outputs())
    }

    /// [`Self::step_indexed`] with the loads going to `sink` as each chunk
    /// of lanes is stepped (the bits of adding the outputs bond by bond).
    pub(crate) fn step_indexed_into(
        &self,
        kin: &IndexedPairs<'_>,
        dt: f64,
        states: &mut [&mut BondState],
        outs: &mut [BondOutput],
        sink: &LoadSink<'_>,
    ) -> BatchResult {
        (self.kernels.indexed)(&self.laws, kin, dt, states, outs, sink)
    }
}
