//! Cell-list search for pairs of spheres closer than a cut-off: O(N) for
//! clusters of roughly uniform density.

use granbond::vector::Vec3;
use std::collections::HashMap;

/// Every pair `(i, j)`, `i < j`, whose centres are closer than `cutoff`.
pub fn close_pairs(positions: &[Vec3], cutoff: f64) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    if positions.len() < 2 || !(cutoff > 0.0) {
        return pairs;
    }
    let cell_of = |x: &Vec3| -> [i64; 3] {
        [
            (x.x / cutoff).floor() as i64,
            (x.y / cutoff).floor() as i64,
            (x.z / cutoff).floor() as i64,
        ]
    };
    let mut cells: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for (i, x) in positions.iter().enumerate() {
        cells.entry(cell_of(x)).or_default().push(i);
    }
    let cut2 = cutoff * cutoff;
    for (i, x) in positions.iter().enumerate() {
        let c = cell_of(x);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(members) = cells.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) else {
                        continue;
                    };
                    for &j in members {
                        if j > i && (positions[j] - x).norm_squared() < cut2 {
                            pairs.push((i, j));
                        }
                    }
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs
}
