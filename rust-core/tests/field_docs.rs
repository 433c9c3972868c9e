//! The column tables of the per-bond outputs' reference pages are the
//! core's field table (`bond::fields`), so the documented columns cannot
//! drift from what the engines write. `GRANBOND_BLESS=1 cargo test --test
//! field_docs` rewrites them.

use granbond::bond::fields::BOND_FIELDS;
use std::path::Path;

const BEGIN: &str = "<!-- bond-fields: the core's field table (cargo test --test field_docs) -->";
const END: &str = "<!-- /bond-fields -->";
const PAGES: [&str; 2] = [
    "docs/reference/compute_granbond_local.md",
    "docs/reference/compute_pair_gran_local_bond.md",
];

fn table() -> String {
    let mut t = String::from("| keyword | unit | value |\n|---|---|---|\n");
    for f in BOND_FIELDS.iter() {
        t += &format!("| `{}` | {} | {} |\n", f.name, f.unit, f.description);
    }
    t
}

#[test]
fn reference_pages_list_the_cores_fields() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let want = table();
    for page in PAGES {
        let path = root.join(page);
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{page}: {e}"));
        let start = text
            .find(BEGIN)
            .unwrap_or_else(|| panic!("{page}: no line {BEGIN}"))
            + BEGIN.len()
            + 1;
        let stop = text[start..]
            .find(END)
            .unwrap_or_else(|| panic!("{page}: no line {END}"))
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
