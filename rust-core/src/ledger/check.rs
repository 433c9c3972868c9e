//! The findings of the store check both adapters run after every pass
//! under `GRANBOND_CHECK_STORE` (docs/development.md, "Where a bond
//! lives"): each bond held once over all ranks, and created = broken +
//! intact + lost over all ranks. The adapters gather the keys and sum the
//! counts over their ranks; the judgement and its words are here.

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
