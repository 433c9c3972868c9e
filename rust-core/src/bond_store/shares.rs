//! The atoms' shares of their bonds' damping loads
//! (`crate::bond::dissipated_shares`), added to an engine's per-atom table.

use super::BondStore;
use crate::bond::dissipated_shares::SHARE_LEN;
use crate::bond::{BondModel, BondStatus};

/// Why the shares could not be added.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SharesError {
    /// The budget, which holds the damping loads, is not kept.
    NotKept,
    /// The store was not linked since atoms moved.
    NotLinked,
    /// A row of `SHARE_LEN` doubles from the first column does not fit
    /// the table's width.
    Width,
}

impl BondStore {
    /// Adds to `table` (`width` doubles an atom, atom `a` at `a * width`)
    /// each intact bond's shares of its damping loads of the latest force
    /// pass, from column `column` on, for the atoms of its two ends among
    /// the first `rows` (an engine's local atoms); a bond whose kind has
    /// no model in `models`, or whose law files none, adds nothing. The
    /// store keeps the loads while it keeps the energy budget.
    pub fn add_dissipated_shares(
        &self,
        models: &[Option<&BondModel>],
        table: &mut [f64],
        width: usize,
        column: usize,
        rows: usize,
    ) -> Result<(), SharesError> {
        let budget = self.budget.as_ref().ok_or(SharesError::NotKept)?;
        if !self.linked {
            return Err(SharesError::NotLinked);
        }
        if column + SHARE_LEN > width {
            return Err(SharesError::Width);
        }
        let rows = rows.min(table.len() / width);
        for k in 0..self.bonds.len() {
            if self.status(k) != BondStatus::Intact {
                continue;
            }
            let Some(model) = models.get(usize::from(self.kinds[k])).copied().flatten() else {
                continue;
            };
            let Some(loads) = budget.damping_loads(k) else {
                continue;
            };
            let Some(shares) = model.dissipated_shares(loads) else {
                continue;
            };
            for (end, share) in self.ends[k].iter().zip(shares) {
                let a = *end as usize;
                if *end < 0 || a >= rows {
                    continue;
                }
                let at = a * width + column;
                for (slot, s) in table[at..at + SHARE_LEN].iter_mut().zip(share) {
                    *slot += s;
                }
            }
        }
        Ok(())
    }
}
