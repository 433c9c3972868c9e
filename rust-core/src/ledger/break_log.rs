//! The log of broken bonds, one line per bond, the same in both engines'
//! `fix bond/breaklog` (docs/reference/fix_bond_breaklog.md):
//!
//! ```text
//! step id_i id_j x y z mode sigma tau sigma_max tau_max
//! ```
//!
//! The adapters make one [`BreakEvent`] per bond that broke on the rank
//! that counts it; rank 0 gathers them and writes the lines of
//! [`log_text`], sorted by step and ids, so the file does not depend on the
//! number of ranks.

use super::c_format::{c_g, c_long};
use crate::bond::{BondModel, BondOutput, BreakMode};
use crate::kinematics::bond_centre;

/// One broken bond, doubles only: the events travel to rank 0 as one
/// array of doubles.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BreakEvent {
    /// The time step.
    pub step: f64,
    /// The lower atom id of a pair; the sphere of a wall bond.
    pub tag_i: f64,
    /// The other atom id; 0 for a wall.
    pub tag_j: f64,
    /// The bond's centre (a wall bond: the wall point).
    pub x: [f64; 3],
    /// The [`crate::bond::BreakMode`] it broke by.
    pub mode: f64,
    /// The section's normal stress in the step that broke it.
    pub sigma: f64,
    /// The section's shear stress in that step.
    pub tau: f64,
    /// The limit of `sigma` at that step (0 in distance mode).
    pub sigma_max: f64,
    /// The limit of `tau` at that step (0 in distance mode).
    pub tau_max: f64,
}

/// The first line of the file.
pub const HEADER: &str = "# step id_i id_j x y z mode sigma tau sigma_max tau_max   (id_j 0: a wall bond)\n";

/// Bytes a line of the log takes at most, its newline included: the step
/// and ids are integers below 2^53 (16 digits), the other numbers at most
/// 17 characters.
pub const LINE_LEN: usize = 256;

/// The largest step or id a line writes (2^53: a double holds every
/// integer up to it).
pub const LARGEST_ID: f64 = 9_007_199_254_740_992.0;

impl BreakEvent {
    /// The event of a bond of `model` that broke with `out` at `step`: sphere
    /// i (id `tag_i`, radius `radius_i`, at `x_i`) and sphere j (`tag_j`;
    /// a wall: id 0, radius 0 at the wall point); the smaller id first.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        model: &BondModel,
        out: &BondOutput,
        x_i: [f64; 3],
        x_j: [f64; 3],
        radius_i: f64,
        radius_j: f64,
        tag_i: f64,
        tag_j: f64,
        step: f64,
    ) -> BreakEvent {
        let (sigma_max, tau_max) = model.stress_limits_at(out.delta);
        let wall = tag_j == 0.0;
        BreakEvent {
            step,
            tag_i: if wall { tag_i } else { tag_i.min(tag_j) },
            tag_j: if wall { 0.0 } else { tag_i.max(tag_j) },
            x: bond_centre(x_i, x_j, radius_i, radius_j),
            mode: f64::from(out.break_mode),
            sigma: out.sigma,
            tau: out.tau,
            sigma_max,
            tau_max,
        }
    }

    /// What is wrong with the step or ids for a line of the log: each an
    /// integer in 0..=2^53.
    pub fn refusal(&self) -> Option<String> {
        [("step", self.step), ("tag_i", self.tag_i), ("tag_j", self.tag_j)]
            .into_iter()
            .find(|(_, v)| !(0.0..=LARGEST_ID).contains(v) || v.fract() != 0.0)
            .map(|(what, v)| format!("{what} {v} is not an integer in 0..=2^53"))
    }

    /// The event's line of the log, newline included.
    pub fn line(&self) -> String {
        let [x, y, z] = self.x.map(|v| c_g(v, 10));
        format!(
            "{:.0} {:.0} {:.0} {x} {y} {z} {} {} {} {} {}\n",
            self.step,
            self.tag_i,
            self.tag_j,
            mode_name(self.mode),
            c_g(self.sigma, 6),
            c_g(self.tau, 6),
            c_g(self.sigma_max, 6),
            c_g(self.tau_max, 6)
        )
    }
}

/// The word of a break mode in the log.
pub fn mode_name(mode: f64) -> &'static str {
    [
        (BreakMode::Distance, "distance"),
        (BreakMode::Tension, "tension"),
        (BreakMode::Compression, "compression"),
        (BreakMode::Shear, "shear"),
    ]
    .into_iter()
    .find(|(m, _)| f64::from(*m as i32) == mode)
    .map_or("unknown", |(_, name)| name)
}

/// The lines of `events`, sorted by step and ids (the events are sorted in
/// place), the file's header first where `header`.
pub fn log_text(events: &mut [BreakEvent], header: bool) -> String {
    events.sort_by(|a, b| {
        (a.step.total_cmp(&b.step))
            .then(a.tag_i.total_cmp(&b.tag_i))
            .then(a.tag_j.total_cmp(&b.tag_j))
    });
    let mut text = if header { HEADER.to_string() } else { String::new() };
    for e in events.iter() {
        text.push_str(&e.line());
    }
    text
}

/// Reads the words of `fix ID group bond/breaklog FILE [every N]` (all of
/// them, the fix's id first): how many steps apart the log is written
/// (100 unless given), or what is wrong, naming the word.
pub fn read_words(words: &[&str]) -> Result<i32, String> {
    if words.len() < 4 {
        return Err("expected fix ID group bond/breaklog FILE [every N]".into());
    }
    let mut every = 100;
    let mut rest = &words[4..];
    while let Some(&word) = rest.first() {
        let value = match rest.get(1) {
            Some(value) if word == "every" => *value,
            _ => return Err(format!("unknown keyword '{word}' (the only one is: every N)")),
        };
        every = c_long(value)
            .filter(|n| (1..=1_000_000_000).contains(n))
            .ok_or_else(|| format!("every must be an integer >= 1, got '{value}'"))? as i32;
        rest = &rest[2..];
    }
    Ok(every)
}
