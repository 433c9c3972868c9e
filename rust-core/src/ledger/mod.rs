//! What both engines count, warn about and log for the bonds of a store:
//! the counts as a row, the warnings of bonds lost without breaking (with
//! their causes), of bonds dropped with their model and of renumbered atom
//! ids, the store check's findings (`check`), the break log (`break_log`),
//! the per-bond output columns (`columns`) and the run check of a thin
//! periodic box (`run_checks`), and the bond store's counts in restart files
//! (`record`). The adapters sum the numbers over their ranks and print what
//! is composed here; the words are written once.

pub mod break_log;
pub mod c_format;
pub mod check;
pub mod columns;
pub mod record;
pub mod run_checks;

use crate::bond_store::StoreCounts;

/// Values of [`counts_row`]: created, broken, intact, broken by distance,
/// tension, compression and shear, lost.
pub const COUNTS_ROW_LEN: usize = 8;

/// The counts as the engines' count computes give them: created, broken,
/// intact, broken by distance, tension, compression and shear, lost.
pub fn counts_row(c: &StoreCounts) -> [f64; COUNTS_ROW_LEN] {
    [
        c.created,
        c.broken(),
        c.intact,
        c.broken_distance,
        c.broken_tension,
        c.broken_compression,
        c.broken_shear,
        c.lost(),
    ]
    .map(|v| v as f64)
}

/// A warning the ledger composes from numbers summed over the ranks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notice {
    /// LIGGGHTS pair bonds lost by a link; counts by cause as
    /// [`crate::bond_store::LinkReport`] orders them (owner gone, partner
    /// unreached, id reused, no model).
    PairsLostLiggghts,
    /// LAMMPS `pair_style granbond`'s bonds lost by a link; as above.
    PairsLostLammps,
    /// LIGGGHTS wall bonds lost: the sphere left the system, left the
    /// wall's reach, or its id was taken over; `name` the wall fix's id.
    WallLostLiggghts,
    /// LAMMPS `bond_style granbond`'s bonds that left the topology: with
    /// their atom, to a new atom under an old id, by `delete_bonds`.
    TopologyLeftLammps,
    /// LIGGGHTS intact bonds dropped with the model that held them
    /// (`counts[0]`).
    DroppedLiggghts,
    /// Atoms that changed their ids while bonds exist (`counts[0]`);
    /// `name` the style.
    Renumbered,
}

impl Notice {
    /// Every notice, in the order of the C constants
    /// `GRANBOND_LEDGER_NOTICE_*`.
    pub const ALL: [Notice; 6] = [
        Notice::PairsLostLiggghts,
        Notice::PairsLostLammps,
        Notice::WallLostLiggghts,
        Notice::TopologyLeftLammps,
        Notice::DroppedLiggghts,
        Notice::Renumbered,
    ];

    /// Whether the message names something the caller gives (a wall fix's
    /// id, a style).
    pub fn takes_name(self) -> bool {
        matches!(self, Notice::WallLostLiggghts | Notice::Renumbered)
    }

    /// How many of the four counts the notice reads (the others are
    /// ignored).
    pub fn counts_read(self) -> usize {
        match self {
            Notice::PairsLostLiggghts | Notice::PairsLostLammps => 4,
            Notice::WallLostLiggghts | Notice::TopologyLeftLammps => 3,
            Notice::DroppedLiggghts | Notice::Renumbered => 1,
        }
    }
}

/// Counts by cause in words ("N because ...; ..."), those of 0 left out.
fn causes(counts: &[i64], why: &[&str]) -> String {
    counts
        .iter()
        .zip(why)
        .filter(|(n, _)| **n > 0)
        .map(|(n, why)| format!("{n} because {why}"))
        .collect::<Vec<_>>()
        .join("; ")
}

/// The causes of a pair style's link losses, in the order of `counts`;
/// `no_model` adds what takes a type pair's model away in the engine.
fn link_causes(counts: &[i64; 4], no_model: &str) -> String {
    let no_model = format!("their atoms' types have no bond model any more{no_model}");
    causes(
        counts,
        &[
            "their atom left the system (deleted, or lost through a boundary)",
            "their partner was not among the atoms within the communication cutoff (deleted, lost, or moved \
             farther than the bond's reach between runs)",
            "an atom's id was taken over by a new atom",
            &no_model,
        ],
    )
}

/// The warning of `notice` for `counts` (summed over the ranks, none
/// negative) at `step`, or `None` when there is nothing to say (no bond
/// concerned).
pub fn notice(notice: Notice, counts: &[i64; 4], step: i64, name: &str) -> Option<String> {
    let total = counts[..notice.counts_read()]
        .iter()
        .fold(0i64, |t, &n| t.saturating_add(n));
    if total <= 0 {
        return None;
    }
    Some(match notice {
        Notice::PairsLostLiggghts => format!(
            "cohesion bond/nonlinear: {total} bonds vanished at step {step} without breaking: {}; they are \
             counted as lost in compute bond/counter (column 7), later ones without a warning",
            link_causes(counts, "")
        ),
        Notice::PairsLostLammps => format!(
            "pair granbond (bond/nonlinear): {total} bonds lost at step {step} without breaking: {} (counted \
             in compute pair granbond's 8th value)",
            link_causes(counts, " (set type, or pair_coeff without bond/nonlinear)")
        ),
        Notice::WallLostLiggghts => format!(
            "cohesion bond/nonlinear (wall {name}): {total} wall bonds lost by step {step} without breaking: \
             {}; they are counted as lost in compute bond/counter (column 8)",
            causes(
                &counts[..3],
                &[
                    "their sphere left the system (deleted, or lost through a boundary)",
                    "their sphere left the wall's reach (no contact with the wall in a force pass)",
                    "their sphere's id was taken over by a new atom",
                ]
            )
        ),
        Notice::TopologyLeftLammps => format!(
            "bond_style granbond: {total} bonds left the topology at step {step} without breaking ({} with \
             their atom: delete_atoms or lost through a boundary; {} to a new atom under an old id; {} by \
             delete_bonds); their state is dropped, and a bond listed again starts at rest",
            counts[0], counts[1], counts[2]
        ),
        Notice::DroppedLiggghts => format!(
            "cohesion bond/nonlinear: {total} intact bonds were dropped with the model that held them (unfix \
             of a fix wall/gran, or a replaced pair style), without breaking; compute bond/counter counts \
             them as lost (columns 7-8)"
        ),
        Notice::Renumbered => format!(
            "{name}: {total} atoms changed their atom IDs since the previous run (delete_atoms with compress \
             yes, its default, or reset_atom_ids). Bonds are kept under the partner's atom ID, so a bond \
             would act on a pair that never bonded. Delete atoms with `delete_atoms ... compress no`"
        ),
    })
}
