//! The run check of a periodic box too short for the engines' per-pair
//! history, which both adapters run at every `run` and when the box
//! changes during one.

/// The box of a run, as the engine gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeriodicBox {
    /// 2 or 3: a 2d run has no images in z, whatever its extent.
    pub dimension: i32,
    /// Non-zero where the box is periodic, by direction.
    pub periodic: [i32; 3],
    /// The box's length in each direction.
    pub length: [f64; 3],
}

/// The engines keep a pair's history under the partner's atom ID, so two
/// images of one atom in a neighbour list share one record. That happens
/// in a periodic direction shorter than twice the list's reach (the pair
/// reach plus the skin `skin`): a sphere meets its own image, or one
/// partner twice. `step` >= 0: the box changed during a run (fix deform)
/// and is checked at that step. The error naming the first such direction,
/// or `None`.
pub fn thin_periodic_box(
    style: &str,
    b: &PeriodicBox,
    list_reach: f64,
    skin: f64,
    step: i64,
) -> Option<String> {
    let d = (0..b.dimension.clamp(0, 3) as usize)
        .find(|&d| b.periodic[d] != 0 && b.length[d] < 2.0 * list_reach)?;
    let axis = ['x', 'y', 'z'][d];
    let g = |v: f64| super::c_format::c_g(v, 6);
    let (when, keep, fix) = if step < 0 {
        (
            String::new(),
            "Make the box at least",
            " (replicate it), or use a fixed boundary there",
        )
    } else {
        (
            format!(" at step {step}, as the box changed"),
            "Keep the box (fix deform's final size) at least",
            "",
        )
    };
    Some(format!(
        "{style}: the periodic box is {} long in {axis}{when}, less than twice the neighbour reach {} (the pair \
         reach {} plus the skin {}): a sphere can meet its own periodic image, or one partner twice, and the \
         engine keeps a pair's contact and bond history under the partner's atom ID, so those pairs would \
         share one record. {keep} {} long in {axis}{fix}",
        g(b.length[d]),
        g(list_reach),
        g(list_reach - skin),
        g(skin),
        g(2.0 * list_reach)
    ))
}
