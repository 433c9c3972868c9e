//! The findings of the store check both adapters run after every pass
//! under `GRANBOND_CHECK_STORE` (docs/development.md, "Where a bond
//! lives"): each bond held by the rank of its owner (a pair bond's partner
//! the atom it names), each bond held once over all ranks, and created =
//! broken + intact + lost over all ranks. The adapters gather the keys and
//! sum the counts over their ranks; the judgement and its words are here.

use crate::bond_store::{BondStore, Ids, WallStore};

/// What the keys of a check name: the atoms of pair bonds, or the sphere
/// and wall of wall bonds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keys {
    /// (lower atom id, higher atom id) of each pair bond.
    Pairs,
    /// (sphere id, wall number) of each wall bond.
    Walls,
}

/// The first key held twice among `keys` (all ranks' bonds, two numbers a
/// key; sorted here), in words, or `None`.
pub fn repeated_key(keys: &mut [[f64; 2]], of: Keys) -> Option<String> {
    keys.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    let twice = keys.windows(2).find(|w| w[0] == w[1])?[0];
    let (a, b) = (twice[0] as i64, twice[1] as i64);
    Some(match of {
        Keys::Pairs => format!("the bond of atoms {a} and {b} is stored twice"),
        Keys::Walls => format!("the bond of sphere {a} and wall {b} is held twice"),
    })
}

/// What is wrong with the counts of all ranks (created, broken, intact,
/// lost; for walls created includes the bonds taken from a restart file),
/// or `None` when created = broken + intact + lost.
pub fn unbalanced(sums: &[i64; 4], of: Keys) -> Option<String> {
    let [created, broken, intact, lost] = sums.map(i128::from);
    if created == broken + intact + lost {
        return None;
    }
    let what = match of {
        Keys::Pairs => "bonds created",
        Keys::Walls => "wall bonds created or restored",
    };
    Some(format!(
        "{} {what}, {} broken, {} intact, {} lost",
        sums[0], sums[1], sums[2], sums[3]
    ))
}

/// The first finding of a check: a key held twice, else counts that do not
/// balance; `None` when all is well.
pub fn findings(keys: &mut [[f64; 2]], sums: &[i64; 4], of: Keys) -> Option<String> {
    repeated_key(keys, of).or_else(|| unbalanced(sums, of))
}

/// The keys of the pair bonds of one rank's `store` (each the lower and
/// the higher id of its atoms), or the first bond that does not join one
/// of the `nlocal` local atoms (its owner) and an atom (local or ghost,
/// ids `ids`) of the id it names as its partner.
pub fn pair_keys(store: &BondStore, ids: Ids<'_>, nlocal: usize) -> Result<Vec<[f64; 2]>, String> {
    (0..store.len())
        .map(|k| {
            let (bond, [owner, partner]) = store
                .bond(k)
                .ok_or_else(|| format!("bond {k}: the store is not linked"))?;
            let local = usize::try_from(owner).ok().filter(|&o| o < nlocal.min(ids.len()));
            let found = usize::try_from(partner).ok().filter(|&p| p < ids.len());
            match (local, found) {
                (Some(o), Some(p)) if ids.get(p) == bond.partner => {
                    let (a, b) = (ids.get(o) as f64, bond.partner as f64);
                    Ok([a.min(b), a.max(b)])
                }
                _ => Err(format!(
                    "bond {k} does not join its owner and its partner {}",
                    bond.partner
                )),
            }
        })
        .collect()
}

/// The keys of the wall bonds of one rank's `store` (each its sphere's id
/// and its wall), or the first bond whose sphere is not among the rank's
/// local atoms (ids `local`).
pub fn wall_keys(store: &WallStore, local: Ids<'_>) -> Result<Vec<[f64; 2]>, String> {
    let mut here: Vec<i64> = (0..local.len()).map(|a| local.get(a)).collect();
    here.sort_unstable();
    store
        .keys()
        .map(|(id, wall)| match here.binary_search(&id) {
            Ok(_) => Ok([id as f64, f64::from(wall)]),
            Err(_) => Err(format!(
                "the bond of sphere {id} and wall {wall} is held by a rank without the sphere"
            )),
        })
        .collect()
}

/// What is wrong with the flag a listed pair of local atom `i` and atom `j`
/// (local or ghost, ids `ids`) carries in the engine's contact history (a
/// cache of whether the pair is bonded), against what `store` and its view
/// hold, in words; `None` when they agree.
pub fn flag_finding(store: &BondStore, i: usize, j: usize, ids: Ids<'_>, flagged: bool) -> Option<String> {
    if store.bonded(i, j, ids) == flagged {
        return None;
    }
    let what = if flagged {
        "is flagged bonded, but no bond"
    } else {
        "is bonded, but not flagged"
    };
    Some(format!(
        "the pair of atoms {} and {} {what}",
        ids.get(i),
        ids.get(j)
    ))
}
