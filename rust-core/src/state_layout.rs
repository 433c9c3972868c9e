//! Run-time description of the flat `f64` state the engines store for us.

/// One slot of a per-bond or per-contact state array.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateSlot {
    /// The slot's name, as restart files and dumps show it.
    pub name: &'static str,
    /// The value changes sign when the pair is seen from the other sphere
    /// (vectors built from `i - j` quantities). Scalars are copied unchanged.
    pub flips_on_swap: bool,
}

/// The slot `name` with its swap rule, for `const` tables.
pub const fn slot(name: &'static str, flips_on_swap: bool) -> StateSlot {
    StateSlot { name, flips_on_swap }
}

/// Applies the swap rule of `layout` to a state array, giving the state as
/// the other sphere stores it.
pub fn swap_state(layout: &[StateSlot], state: &mut [f64]) {
    for (value, s) in state.iter_mut().zip(layout) {
        if s.flips_on_swap {
            *value = -*value;
        }
    }
}
