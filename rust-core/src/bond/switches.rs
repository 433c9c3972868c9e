//! How a compiled step reads the [`super::features`] bits: fixed when it is
//! compiled for one combination ([`Fixed`]), or from the model at run time
//! ([`Switched`]); [`super::dispatch`] says which combinations get which.

use super::laws::BondLaws;

/// The switches a compiled step reads.
pub(crate) trait Switches: Copy {
    /// Whether the bits are known when the step is compiled, so that what
    /// a step leaves out for them costs no branch.
    const FIXED: bool;
    /// Whether the step is LIGGGHTS-INL's law (`super::inl`) rather than
    /// the write-up's.
    const INL: bool = false;
    /// Whether the step is LIGGGHTS-INL's linear bond (`super::linear`).
    const LINEAR: bool = false;

    fn of(laws: &BondLaws) -> Self;
    fn bits(self) -> u32;

    /// Whether any of `bits` is on.
    #[inline(always)]
    fn any(self, bits: u32) -> bool {
        self.bits() & bits != 0
    }
}

/// The combination `F`, known to the compiler: a switched-off part is not
/// in the code at all.
#[derive(Clone, Copy)]
pub(crate) struct Fixed<const F: u32>;

impl<const F: u32> Switches for Fixed<F> {
    const FIXED: bool = true;

    #[inline(always)]
    fn of(_: &BondLaws) -> Self {
        Fixed
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        F
    }
}

/// The model's own combination, read at run time: one copy of the code for
/// every combination, whose branches on the bits go the same way for every
/// bond of a call.
#[derive(Clone, Copy)]
pub(crate) struct Switched(u32);

impl Switches for Switched {
    const FIXED: bool = false;

    #[inline(always)]
    fn of(laws: &BondLaws) -> Self {
        Switched(laws.features)
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        self.0
    }
}

/// One of LIGGGHTS-INL's laws, which the scalar paths step one bond at a
/// time: its code for `bond/nonlinear` (`inl_compatible`, [`Inl`],
/// `super::inl`) or its linear bond (`linear`, [`Linear`],
/// `super::linear`); the bits are the model's.
#[derive(Clone, Copy)]
pub(crate) struct InlLaw<const L: bool>(u32);

impl<const L: bool> Switches for InlLaw<L> {
    const FIXED: bool = false;
    const INL: bool = !L;
    const LINEAR: bool = L;

    #[inline(always)]
    fn of(laws: &BondLaws) -> Self {
        InlLaw(laws.features)
    }

    #[inline(always)]
    fn bits(self) -> u32 {
        self.0
    }
}

/// LIGGGHTS-INL's code for `bond/nonlinear` (`inl_compatible`).
pub(crate) type Inl = InlLaw<false>;
/// LIGGGHTS-INL's linear bond (`linear`).
pub(crate) type Linear = InlLaw<true>;
