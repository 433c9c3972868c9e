//! The compiled steps and the choice among them. Nothing here computes:
//! each entry is the scalar path ([`super::scalar`]) or the wide one
//! ([`super::wide`]) for a way of reading the [`super::features`] bits.
//!
//! One step per instruction set reads the bits at run time
//! ([`Switched`]); its branches on them go the same way for every bond of a
//! call, so they are predicted, but the code around them is laid out for
//! every law. The combinations of [`COMPILED_ALONE`] also get steps
//! compiled for them alone ([`Fixed`]) on the scalar and AVX2 paths, where
//! a switched-off law is not in the code at all. Every one of the 128
//! combinations compiled on every path would make the build slow and the
//! library large, for combinations no deck uses (docs/development.md).

use super::atom_loads::LoadSink;
use super::features::COMPILED_ALONE;
use super::finite::BatchResult;
use super::laws::BondLaws;
use super::scalar::{all_one_by_one, bond_step};
use super::state::{BondOutput, BondState};
use super::switches::{Fixed, Inl, Linear, Switched, Switches};
use crate::kinematics::{KinematicsError, PairKinematics};
use crate::pair_source::{IndexedPairs, PairSource};
use crate::simd::Simd;
use seq_macro::seq;

pub type Kernel =
    fn(&BondLaws, &PairKinematics, f64, &mut BondState, &mut BondOutput) -> Result<(), KinematicsError>;
pub type BatchKernel =
    fn(&BondLaws, &[PairKinematics], f64, &mut [BondState], &mut [BondOutput]) -> BatchResult;
pub type ScatteredKernel =
    fn(&BondLaws, &[PairKinematics], f64, &mut [&mut BondState], &mut [BondOutput]) -> BatchResult;
pub type IndexedKernel = fn(
    &BondLaws,
    &IndexedPairs<'_>,
    f64,
    &mut [&mut BondState],
    &mut [BondOutput],
    &LoadSink<'_>,
) -> BatchResult;

/// The steps of one model: one bond, bonds whose states lie side by side
/// (`batch`), apart (`scattered`), or apart with kinematics read from the
/// engine's per-atom arrays (`indexed`), the last three on `simd`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Kernels {
    pub single: Kernel,
    pub batch: BatchKernel,
    pub scattered: ScatteredKernel,
    pub indexed: IndexedKernel,
    pub simd: Simd,
    /// Whether the steps are compiled for the model's combination alone
    /// (the AVX-512 ones never are).
    pub own: bool,
}

/// The steps for `features` on `simd`, which the caller has checked this
/// CPU runs ([`Simd::available`]); `Scalar` for a width not compiled in.
/// With `own`, the steps compiled for `features` alone where there are
/// such; otherwise the ones that read the bits.
pub(crate) fn kernels(features: u32, simd: Simd, own: bool) -> Kernels {
    let switched = COMPILED_ALONE.len();
    let f = match COMPILED_ALONE.iter().position(|&c| c == features) {
        Some(f) if own => f,
        _ => switched,
    };
    let (batch, scattered, indexed, simd, f) = match simd {
        #[cfg(target_arch = "x86_64")]
        Simd::Avx2 => (BATCH_AVX2[f], SCATTERED_AVX2[f], INDEXED_AVX2[f], Simd::Avx2, f),
        #[cfg(target_arch = "x86_64")]
        Simd::Avx512 => (
            wide::batch_avx512::<Switched> as BatchKernel,
            wide::scattered_avx512::<Switched> as ScatteredKernel,
            wide::indexed_avx512::<Switched> as IndexedKernel,
            Simd::Avx512,
            switched,
        ),
        _ => (BATCH[f], SCATTERED[f], INDEXED[f], Simd::Scalar, f),
    };
    Kernels {
        single: SINGLE[f],
        batch,
        scattered,
        indexed,
        simd,
        own: f != switched,
    }
}

/// The steps of LIGGGHTS-INL's law (`super::inl`): scalar on every path.
pub(crate) fn inl_kernels() -> Kernels {
    one_by_one_kernels::<Inl>()
}

/// The steps of LIGGGHTS-INL's linear bond (`super::linear`): scalar on
/// every path.
pub(crate) fn linear_kernels() -> Kernels {
    one_by_one_kernels::<Linear>()
}

/// The scalar steps of `S` on every path.
fn one_by_one_kernels<S: Switches>() -> Kernels {
    Kernels {
        single: single::<S>,
        batch: batch::<S>,
        scattered: scattered::<S>,
        indexed: indexed::<S>,
        simd: Simd::Scalar,
        own: false,
    }
}

fn single<S: Switches>(
    laws: &BondLaws,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    bond_step::<S>(laws, kin, dt, state, out)
}

/// The scalar entries of the tables, one per state layout and source of
/// kinematics.
macro_rules! scalar {
    ($name:ident, $source:ty, $state:ty) => {
        fn $name<S: Switches>(
            laws: &BondLaws,
            kin: &$source,
            dt: f64,
            states: &mut [$state],
            outs: &mut [BondOutput],
        ) -> BatchResult {
            all_one_by_one::<S, _, _>(laws, kin, dt, states, outs)
        }
    };
}
scalar!(batch, [PairKinematics], BondState);
scalar!(scattered, [PairKinematics], &mut BondState);

/// The scalar indexed step: the bonds one by one, then their loads from
/// the outputs to `sink`.
fn indexed<S: Switches>(
    laws: &BondLaws,
    kin: &IndexedPairs<'_>,
    dt: f64,
    states: &mut [&mut BondState],
    outs: &mut [BondOutput],
    sink: &LoadSink<'_>,
) -> BatchResult {
    let found = all_one_by_one::<S, _, _>(laws, kin, dt, states, outs)?;
    sink.add_outputs(0..kin.len().min(states.len()).min(outs.len()), outs);
    Ok(found)
}

#[cfg(target_arch = "x86_64")]
mod wide {
    use super::*;
    use crate::bond::wide::in_chunks;
    use crate::pair_source::PairSource;
    use crate::real::packed::{F64x4, F64x8};
    use std::borrow::BorrowMut;

    /// The step compiled for an instruction set, `$pack` bonds per
    /// instruction (the `#[inline(always)]` laws and lane operations take on
    /// this function's target features).
    macro_rules! compiled {
        ($name:ident, $feature:literal, $pack:ty) => {
            #[target_feature(enable = $feature)]
            fn $name<S: Switches, K: PairSource + ?Sized, T: BorrowMut<BondState>>(
                laws: &BondLaws,
                kin: &K,
                dt: f64,
                states: &mut [T],
                outs: &mut [BondOutput],
                sink: &LoadSink<'_>,
            ) -> BatchResult {
                in_chunks::<S, $pack, K, T>(laws, kin, dt, states, outs, sink)
            }
        };
    }
    compiled!(avx2, "avx2", F64x4);
    compiled!(avx512, "avx512f", F64x8);

    /// The wide entries of the tables: one per instruction set, state
    /// layout and source of kinematics, the same safe shell around each
    /// (the indexed ones with the sink of their loads, the others writing
    /// every output).
    macro_rules! entry {
        ($name:ident, $kernel:ident, $source:ty, $state:ty) => {
            pub(super) fn $name<S: Switches>(
                laws: &BondLaws,
                kin: &$source,
                dt: f64,
                states: &mut [$state],
                outs: &mut [BondOutput],
            ) -> BatchResult {
                // SAFETY: only handed out by `kernels` for the instruction
                // set it names, which `BondModel` checks the CPU runs.
                unsafe { $kernel::<S, _, _>(laws, kin, dt, states, outs, &LoadSink::outputs()) }
            }
        };
        ($name:ident, $kernel:ident, $source:ty, $state:ty, sink) => {
            pub(super) fn $name<S: Switches>(
                laws: &BondLaws,
                kin: &$source,
                dt: f64,
                states: &mut [$state],
                outs: &mut [BondOutput],
                sink: &LoadSink<'_>,
            ) -> BatchResult {
                // SAFETY: as above.
                unsafe { $kernel::<S, _, _>(laws, kin, dt, states, outs, sink) }
            }
        };
    }
    entry!(batch_avx2, avx2, [PairKinematics], BondState);
    entry!(scattered_avx2, avx2, [PairKinematics], &mut BondState);
    entry!(indexed_avx2, avx2, IndexedPairs<'_>, &mut BondState, sink);
    entry!(batch_avx512, avx512, [PairKinematics], BondState);
    entry!(scattered_avx512, avx512, [PairKinematics], &mut BondState);
    entry!(indexed_avx512, avx512, IndexedPairs<'_>, &mut BondState, sink);
}

/// The entries of the tables: one for each combination of
/// [`COMPILED_ALONE`], then the one that reads the bits.
const ENTRIES: usize = COMPILED_ALONE.len() + 1;

seq!(N in 0..18 {
    const SINGLE: [Kernel; ENTRIES] = [#(single::<Fixed<{ COMPILED_ALONE[N] }>>,)* single::<Switched>];
    const BATCH: [BatchKernel; ENTRIES] = [#(batch::<Fixed<{ COMPILED_ALONE[N] }>>,)* batch::<Switched>];
    const SCATTERED: [ScatteredKernel; ENTRIES] =
        [#(scattered::<Fixed<{ COMPILED_ALONE[N] }>>,)* scattered::<Switched>];
    const INDEXED: [IndexedKernel; ENTRIES] = [#(indexed::<Fixed<{ COMPILED_ALONE[N] }>>,)* indexed::<Switched>];
    #[cfg(target_arch = "x86_64")]
    const BATCH_AVX2: [BatchKernel; ENTRIES] =
        [#(wide::batch_avx2::<Fixed<{ COMPILED_ALONE[N] }>>,)* wide::batch_avx2::<Switched>];
    #[cfg(target_arch = "x86_64")]
    const SCATTERED_AVX2: [ScatteredKernel; ENTRIES] =
        [#(wide::scattered_avx2::<Fixed<{ COMPILED_ALONE[N] }>>,)* wide::scattered_avx2::<Switched>];
    #[cfg(target_arch = "x86_64")]
    const INDEXED_AVX2: [IndexedKernel; ENTRIES] =
        [#(wide::indexed_avx2::<Fixed<{ COMPILED_ALONE[N] }>>,)* wide::indexed_avx2::<Switched>];
});
