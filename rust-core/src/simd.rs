//! The instruction set the wide code runs on: one choice per process, for
//! the bond kernels and the contact entries alike.

use std::sync::atomic::{AtomicU8, Ordering};

/// The instruction sets the bond kernels can run on: one bond at a time, or
/// chunks of 4 (AVX2) / 8 (AVX-512) bonds in lanes; the contact entries
/// have a baseline and an AVX2 copy. All give the same bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Simd {
    /// One bond at a time; the contact entries' baseline.
    Scalar = 0,
    /// Chunks of 4 bonds in AVX2 lanes; the contact entries' AVX2 copy.
    Avx2 = 1,
    /// Chunks of 8 bonds in AVX-512 lanes.
    Avx512 = 2,
}

impl Simd {
    /// What the models use: AVX2 where the CPU has it. AVX-512 is not
    /// chosen by itself: twice the lanes, but twice the transposing per
    /// chunk too, which makes it slower than AVX2 in the `scattered_*`
    /// benchmarks of `benches/kernels.rs` (docs/performance.md).
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if is_x86_feature_detected!("avx2") {
                return Simd::Avx2;
            }
        }
        Simd::Scalar
    }

    /// [`Self::detect`], found once and then only loaded (the contact
    /// entries ask at every call).
    #[inline]
    pub fn chosen() -> Self {
        Self::known().unwrap_or_else(Self::detect_and_keep)
    }

    /// [`Self::chosen`] once it has been found, else `None`: a caller that
    /// only jumps on to one copy or another keeps the finding (a call) off
    /// its own path.
    #[inline(always)]
    pub fn known() -> Option<Self> {
        match CHOSEN.load(Ordering::Relaxed) {
            UNKNOWN => None,
            1 => Some(Simd::Avx2),
            2 => Some(Simd::Avx512),
            _ => Some(Simd::Scalar),
        }
    }

    #[cold]
    fn detect_and_keep() -> Self {
        let simd = Self::detect();
        CHOSEN.store(simd as u8, Ordering::Relaxed);
        simd
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

/// [`Simd::chosen`]'s answer as its number; none yet while it is `UNKNOWN`.
const UNKNOWN: u8 = u8::MAX;
static CHOSEN: AtomicU8 = AtomicU8::new(UNKNOWN);
