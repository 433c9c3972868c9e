//! The compiled steps, one per combination of [`super::features`] bits and
//! per instruction set, and the choice among them. Nothing here computes:
//! each entry is the scalar path ([`super::scalar`]) or the wide one
//! ([`super::wide`]) for a fixed set of bits.

use super::features::FEATURE_COMBINATIONS;
use super::finite::BatchResult;
use super::laws::BondLaws;
use super::scalar::{all_one_by_one, bond_step};
use super::state::{BondOutput, BondState};
use crate::kinematics::{KinematicsError, PairKinematics};
use crate::pair_source::IndexedPairs;
use crate::simd::Simd;
use seq_macro::seq;

pub type Kernel =
    fn(&BondLaws, &PairKinematics, f64, &mut BondState, &mut BondOutput) -> Result<(), KinematicsError>;
pub type BatchKernel =
    fn(&BondLaws, &[PairKinematics], f64, &mut [BondState], &mut [BondOutput]) -> BatchResult;
pub type ScatteredKernel =
    fn(&BondLaws, &[PairKinematics], f64, &mut [&mut BondState], &mut [BondOutput]) -> BatchResult;
pub type IndexedKernel =
    fn(&BondLaws, &IndexedPairs<'_>, f64, &mut [&mut BondState], &mut [BondOutput]) -> BatchResult;

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
}

/// The steps for `features` on `simd`, which the caller has checked this
/// CPU runs ([`Simd::available`]); `Scalar` for a width not compiled in.
pub(crate) fn kernels(features: u32, simd: Simd) -> Kernels {
    let f = features as usize % FEATURE_COMBINATIONS;
    let (batch, scattered, indexed, simd) = match simd {
        #[cfg(target_arch = "x86_64")]
        Simd::Avx2 => (BATCH_AVX2[f], SCATTERED_AVX2[f], INDEXED_AVX2[f], Simd::Avx2),
        #[cfg(target_arch = "x86_64")]
        Simd::Avx512 => (
            BATCH_AVX512[f],
            SCATTERED_AVX512[f],
            INDEXED_AVX512[f],
            Simd::Avx512,
        ),
        _ => (BATCH[f], SCATTERED[f], INDEXED[f], Simd::Scalar),
    };
    Kernels {
        single: SINGLE[f],
        batch,
        scattered,
        indexed,
        simd,
    }
}

fn single<const F: u32>(
    laws: &BondLaws,
    kin: &PairKinematics,
    dt: f64,
    state: &mut BondState,
    out: &mut BondOutput,
) -> Result<(), KinematicsError> {
    bond_step::<F>(laws, kin, dt, state, out)
}

/// The scalar entries of the tables, one per state layout and source of
/// kinematics.
macro_rules! scalar {
    ($name:ident, $source:ty, $state:ty) => {
        fn $name<const F: u32>(
            laws: &BondLaws,
            kin: &$source,
            dt: f64,
            states: &mut [$state],
            outs: &mut [BondOutput],
        ) -> BatchResult {
            all_one_by_one::<F, _, _>(laws, kin, dt, states, outs)
        }
    };
}
scalar!(batch, [PairKinematics], BondState);
scalar!(scattered, [PairKinematics], &mut BondState);
scalar!(indexed, IndexedPairs<'_>, &mut BondState);

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
            fn $name<const F: u32, K: PairSource + ?Sized, S: BorrowMut<BondState>>(
                laws: &BondLaws,
                kin: &K,
                dt: f64,
                states: &mut [S],
                outs: &mut [BondOutput],
            ) -> BatchResult {
                in_chunks::<F, $pack, K, S>(laws, kin, dt, states, outs)
            }
        };
    }
    compiled!(avx2, "avx2", F64x4);
    compiled!(avx512, "avx512f", F64x8);

    /// The wide entries of the tables: one per instruction set, state
    /// layout and source of kinematics, the same safe shell around each.
    macro_rules! entry {
        ($name:ident, $kernel:ident, $source:ty, $state:ty) => {
            pub(super) fn $name<const F: u32>(
                laws: &BondLaws,
                kin: &$source,
                dt: f64,
                states: &mut [$state],
                outs: &mut [BondOutput],
            ) -> BatchResult {
                // SAFETY: only handed out by `kernels` for the instruction
                // set it names, which `BondModel` checks the CPU runs.
                unsafe { $kernel::<F, _, _>(laws, kin, dt, states, outs) }
            }
        };
    }
    entry!(batch_avx2, avx2, [PairKinematics], BondState);
    entry!(scattered_avx2, avx2, [PairKinematics], &mut BondState);
    entry!(indexed_avx2, avx2, IndexedPairs<'_>, &mut BondState);
    entry!(batch_avx512, avx512, [PairKinematics], BondState);
    entry!(scattered_avx512, avx512, [PairKinematics], &mut BondState);
    entry!(indexed_avx512, avx512, IndexedPairs<'_>, &mut BondState);
}

seq!(N in 0..128 {
    const SINGLE: [Kernel; FEATURE_COMBINATIONS] = [#(single::<N>,)*];
    const BATCH: [BatchKernel; FEATURE_COMBINATIONS] = [#(batch::<N>,)*];
    const SCATTERED: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(scattered::<N>,)*];
    const INDEXED: [IndexedKernel; FEATURE_COMBINATIONS] = [#(indexed::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const BATCH_AVX2: [BatchKernel; FEATURE_COMBINATIONS] = [#(wide::batch_avx2::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const SCATTERED_AVX2: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(wide::scattered_avx2::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const INDEXED_AVX2: [IndexedKernel; FEATURE_COMBINATIONS] = [#(wide::indexed_avx2::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const BATCH_AVX512: [BatchKernel; FEATURE_COMBINATIONS] = [#(wide::batch_avx512::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const SCATTERED_AVX512: [ScatteredKernel; FEATURE_COMBINATIONS] = [#(wide::scattered_avx512::<N>,)*];
    #[cfg(target_arch = "x86_64")]
    const INDEXED_AVX512: [IndexedKernel; FEATURE_COMBINATIONS] = [#(wide::indexed_avx512::<N>,)*];
});
