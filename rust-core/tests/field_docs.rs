//! The column tables of the per-bond outputs' reference pages are the
//! core's field table (`bond::fields`), so the documented columns cannot
//! drift from what the engines write. `GRANBOND_BLESS=1 cargo test --test
//! field_docs` rewrites them.

use granbond::bond::fields::{BondField, BOND_ENERGY_FIELDS, BOND_FIELDS};
use std::path::Path;

const BEGIN: &str = "<!-- bond-fields: the core's field table (cargo test --test field_docs) -->";
const END: &str = "<!-- /bond-fields -->";
const PAGES: [&str; 2] = [
    "docs/reference/compute_granbond_local.md",
    "docs/reference/compute_pair_gran_local_bond.md",
];

const ENERGY_BEGIN: &str =
    "<!-- bond-energy-fields: the core's energy field table (cargo test --test field_docs) -->";
const ENERGY_END: &str = "<!-- /bond-energy-fields -->";

fn table(fields: &[BondField]) -> String {
    let mut t = String::from("| keyword | unit | value |\n|---|---|---|\n");
    for f in fields.iter() {
        t += &format!("| `{}` | {} | {} |\n", f.name, f.unit, f.description);
    }
    t
}

#[test]
fn reference_pages_list_the_cores_fields() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let tables = PAGES
        .iter()
        .map(|&page| (page, BEGIN, END, table(&BOND_FIELDS)))
        .chain(
            PAGES
                .iter()
                .map(|&page| (page, ENERGY_BEGIN, ENERGY_END, table(&BOND_ENERGY_FIELDS))),
        );
    for (page, begin, end, want) in tables {
        let path = root.join(page);
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{page}: {e}"));
        let start = text
            .find(begin)
            .unwrap_or_else(|| panic!("{page}: no line {begin}"))
            + begin.len()
            + 1;
        let stop = text[start..]
            .find(end)
            .unwrap_or_else(|| panic!("{page}: no line {end}"))
            + start;
        if std::env::var_os("GRANBOND_BLESS").is_some() {
            let blessed = format!("{}{}{}", &text[..start], want, &text[stop..]);
            std::fs::write(&path, blessed).expect("write the page");
            continue;
        }
        assert!(
            text[start..stop] == want,
            "{page}: the column table differs from the core's field table; run \
             GRANBOND_BLESS=1 cargo test --test field_docs and commit the page"
        );
    }
}
