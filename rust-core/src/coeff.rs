//! The words of LAMMPS's coefficient commands read into the parameter
//! tables: `pair_coeff I J voigt <values> [keyword ...] [bond/nonlinear |
//! bond/linear keyword ...]` and `bond_coeff N keyword ...`
//! (docs/reference/pair_granbond.md, bond_granbond.md).
//!
//! A keyword is a row of its model's table with one value, written as the
//! row's kind says; a phrase ([`Phrase`]) opens with its words, gives values
//! to the rows it names and sets rows of its own. A row given twice on one
//! line with different values is refused. Every error names the command as
//! the deck wrote it, the clause being read, and the word.

use crate::bond::{BondParams, CREATION_ROWS, PAIR_BOND_ROWS, PARAMETERS, PHRASES};
use crate::contact::{VoigtParams, VOIGT_PARAMETERS, VOIGT_PHRASES};
use crate::parameters::{set_by_name, ParameterInfo, ParameterKind, Phrase, SetError};
use std::ffi::CString;

/// The contact's clause in `pair_coeff`.
pub const VOIGT: &str = "voigt";
/// The bond/nonlinear clause.
pub const BOND: &str = "bond/nonlinear";
/// LIGGGHTS-INL's linear bond's clause: the bond table's row `linear` on.
pub const LINEAR: &str = "bond/linear";

/// The words of one command, read left to right.
struct Words<'a> {
    words: &'a [&'a str],
    at: usize,
    /// The command and its leading words as the deck wrote them.
    command: &'a str,
    /// The clause being read ("" before the first).
    clause: &'static str,
}

impl<'a> Words<'a> {
    fn done(&self) -> bool {
        self.at >= self.words.len()
    }

    /// The word `ahead` of the next one, "" past the end.
    fn peek(&self, ahead: usize) -> &'a str {
        self.words.get(self.at + ahead).copied().unwrap_or("")
    }

    /// The next word; the error says `what` is missing.
    fn word(&mut self, what: &str) -> Result<&'a str, String> {
        if self.done() {
            return Err(self.fail(format!("missing {what}")));
        }
        self.at += 1;
        Ok(self.words[self.at - 1])
    }

    fn fail(&self, what: impl std::fmt::Display) -> String {
        let clause = if self.clause.is_empty() {
            String::new()
        } else {
            format!(" {}", self.clause)
        };
        format!("{}{}: {}", self.command, clause, what)
    }
}

/// `s` read whole by the C library as an integer or a number (`strtoll`,
/// `strtod`: the spellings every LAMMPS reader takes), and whether it is
/// within a double's range; `None` for anything else.
pub(crate) fn c_read(s: &str, integer: bool) -> Option<(f64, bool)> {
    let c = CString::new(s).ok()?;
    let mut end: *mut libc::c_char = std::ptr::null_mut();
    // SAFETY: `c` is a NUL-terminated string that outlives the calls; `end`
    // points into it; errno is this thread's.
    unsafe {
        *libc::__errno_location() = 0;
        let v = if integer {
            libc::strtoll(c.as_ptr(), &mut end, 10) as f64
        } else {
            libc::strtod(c.as_ptr(), &mut end)
        };
        let whole = !std::ptr::eq(end, c.as_ptr()) && *end == 0;
        whole.then_some((v, *libc::__errno_location() != libc::ERANGE))
    }
}

/// `s` as a value of a deck, in a double's range.
fn c_number(s: &str, integer: bool) -> Option<f64> {
    c_read(s, integer).filter(|r| r.1).map(|r| r.0)
}

/// Whether `s` is written as a number (in range or not: where the values
/// after a model's name are counted, the reader of each refuses it).
fn is_number(s: &str) -> bool {
    c_read(s, false).is_some()
}

/// The deck's value for a row of `kind` (switches 1 or 0, steps as exact
/// doubles); `what` names it in the error.
fn value(w: &mut Words, kind: ParameterKind, what: &str) -> Result<f64, String> {
    let s = w.word(what)?;
    match kind {
        ParameterKind::Switch => match s {
            "yes" | "on" => Ok(1.0),
            "no" | "off" => Ok(0.0),
            _ => Err(w.fail(format!("{what} expects yes|no (or on|off), got '{s}'"))),
        },
        ParameterKind::Integer => {
            c_number(s, true).ok_or_else(|| w.fail(format!("{what} expects an integer, got '{s}'")))
        }
        ParameterKind::Real => {
            c_number(s, false).ok_or_else(|| w.fail(format!("{what} expects a number, got '{s}'")))
        }
    }
}

/// One model's clause, read into its parameters through the table and the
/// phrases.
struct Clause<'t, T> {
    /// The model as `set_by_name` names it in its messages.
    model: &'static str,
    table: &'t [ParameterInfo<T>],
    phrases: &'t [Phrase],
    /// The phrase just read, for one that may only follow it.
    last: &'static str,
    /// Per row: the words that gave it on this line ("" not given), and
    /// the value they gave.
    given_by: Vec<String>,
    given_value: Vec<f64>,
}

impl<'t, T> Clause<'t, T> {
    fn new(model: &'static str, table: &'t [ParameterInfo<T>], phrases: &'t [Phrase]) -> Self {
        Self {
            model,
            table,
            phrases,
            last: "",
            given_by: vec![String::new(); table.len()],
            given_value: vec![0.0; table.len()],
        }
    }

    fn row(&self, keyword: &str) -> Option<usize> {
        self.table.iter().position(|r| r.name == keyword)
    }

    /// The values that follow the model's name.
    fn head(&mut self, w: &mut Words, params: &mut T) -> Result<(), String> {
        for p in self.phrases.iter().filter(|p| p.words.is_empty()) {
            // too few numbers: name the values the model expects, not the
            // word that stood where the last one should
            let k = (0..p.reads.len()).take_while(|&k| is_number(w.peek(k))).count();
            if k < p.reads.len() {
                let before = match w.peek(k) {
                    "" => String::new(),
                    next => format!(" before '{next}'"),
                };
                return Err(w.fail(format!(
                    "{} expects {} numbers ({}), got {k}{before}",
                    self.model,
                    p.reads.len(),
                    p.reads.join(" ")
                )));
            }
            self.read(w, params, p)?;
        }
        Ok(())
    }

    /// Reads the phrase or keyword at the next word; false when the word is
    /// neither (the caller's word, or an unknown one).
    fn next(&mut self, w: &mut Words, params: &mut T) -> Result<bool, String> {
        let word = w.peek(0);
        let mut best: Option<(&'t Phrase, usize)> = None;
        for p in self.phrases {
            let words: Vec<&str> = p.words.split_whitespace().collect();
            if words.is_empty() || (!p.follows.is_empty() && self.last != p.follows) {
                continue;
            }
            let k = (0..words.len()).take_while(|&k| w.peek(k) == words[k]).count();
            if k == words.len() && k > best.map_or(0, |b| b.1) {
                best = Some((p, k));
            }
        }
        if let Some((p, len)) = best {
            w.at += len;
            self.read(w, params, p)?;
            self.last = p.words;
            return Ok(true);
        }
        self.last = "";
        if let Some(id) = self.row(word) {
            w.at += 1;
            let v = value(w, self.table[id].kind(), word)?;
            let written = w.words[w.at - 1];
            self.store(w, params, id, v, written, &format!("{word} {written}"))?;
            return Ok(true);
        }
        // the opening word of phrases whose next word is wrong
        let choices: Vec<&str> = self
            .phrases
            .iter()
            .filter_map(|p| {
                let mut words = p.words.split_whitespace();
                (words.next() == Some(word)).then(|| words.next()).flatten()
            })
            .collect();
        if !choices.is_empty() {
            let choices = choices.join(" or ");
            w.at += 1;
            let got = w.word(&format!("{word} {choices}"))?;
            return Err(w.fail(format!("{word} expects {choices}, got '{got}'")));
        }
        Ok(false)
    }

    /// Every word this clause knows, for the message of an unknown one.
    fn known(&self) -> String {
        let mut words: Vec<&str> = Vec::new();
        let openers = self.phrases.iter().filter(|p| p.follows.is_empty());
        for word in openers
            .filter_map(|p| p.words.split_whitespace().next())
            .chain(self.table.iter().map(|r| r.name))
        {
            if !words.contains(&word) {
                words.push(word);
            }
        }
        words.join(" ")
    }

    /// A phrase's values, then what the phrase sets itself.
    fn read(&mut self, w: &mut Words, params: &mut T, p: &Phrase) -> Result<(), String> {
        for keyword in p.reads {
            let id = self.row(keyword).ok_or_else(|| {
                w.fail(format!(
                    "the core's phrase '{}' reads '{keyword}', which its table lacks",
                    p.words
                ))
            })?;
            let what = match (p.words, p.reads.len()) {
                ("", _) => keyword.to_string(),
                (name, 1) => name.to_string(),
                (name, _) => format!("{name} {keyword}"),
            };
            let v = value(w, self.table[id].kind(), &what)?;
            let origin = if p.words.is_empty() { w.clause } else { p.words };
            self.store(w, params, id, v, w.words[w.at - 1], origin)?;
        }
        // what the values after the model's name imply is a default that a
        // later phrase may change (`rolling` after `voigt`)
        for &(keyword, v) in p.sets {
            let id = self.row(keyword).ok_or_else(|| {
                w.fail(format!(
                    "the core's phrase '{}' sets '{keyword}', which its table lacks",
                    p.words
                ))
            })?;
            self.store(w, params, id, v, &v.to_string(), p.words)?;
        }
        Ok(())
    }

    /// Stores row `id`; a value out of range is refused naming the keyword
    /// and the value as the deck wrote it, and a row given twice on the
    /// line with different values naming both (`origin`: the words that
    /// gave it; "" for a default the values after the model's name imply).
    fn store(
        &mut self,
        w: &Words,
        params: &mut T,
        id: usize,
        v: f64,
        written: &str,
        origin: &str,
    ) -> Result<(), String> {
        let keyword = self.table[id].name;
        if !origin.is_empty() {
            if !self.given_by[id].is_empty() && self.given_value[id] != v {
                return Err(w.fail(format!(
                    "'{origin}' conflicts with '{}' given before on this line ({keyword} set twice to different \
                     values); give each keyword once",
                    self.given_by[id]
                )));
            }
            self.given_by[id] = origin.to_string();
            self.given_value[id] = v;
        }
        match set_by_name(self.model, self.table, params, keyword, v) {
            Ok(_) => Ok(()),
            Err(SetError::Refused(e)) => {
                let need = e
                    .requirement()
                    .unwrap_or(self.table[e.parameter].range.describe());
                Err(w.fail(format!("{keyword} must be {need}, got {written}")))
            }
            Err(SetError::Unknown(message)) => Err(w.fail(message)),
        }
    }

    /// The rest of the line as this clause; the error lists the known words.
    fn read_to_end(&mut self, w: &mut Words, params: &mut T) -> Result<(), String> {
        while !w.done() {
            if !self.next(w, params)? {
                return Err(w.fail(format!(
                    "unknown keyword '{}' (known: {})",
                    w.peek(0),
                    self.known()
                )));
            }
        }
        Ok(())
    }

    /// Whether the line gave row `name`.
    fn given(&self, name: &str) -> Option<&str> {
        self.row(name)
            .map(|id| self.given_by[id].as_str())
            .filter(|g| !g.is_empty())
    }
}

/// What a `pair_coeff` line of `pair_style granbond` sets for its type
/// pairs: the contact, and the bond where the line has a bond clause.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairCoeff {
    /// The Voigt contact.
    pub voigt: VoigtParams,
    /// The bond's parameters: those of the line's bond clause, else the
    /// bond law's defaults in `units`.
    pub bond: BondParams,
    /// Whether the line has a bond clause.
    pub has_bond: bool,
}

/// Reads the words of `pair_coeff` after the type pair (`words`);
/// `command` names the command as the deck wrote it ("pair_coeff 1 2"),
/// `units` the engine's units style (the bond's defaults). Where the line
/// does not give `contact_under_bond`, it follows the bond's law
/// ([`BondParams::contact_under_bond_by_law`]).
pub fn read_pair_coeff(command: &str, words: &[&str], units: &str) -> Result<PairCoeff, String> {
    let mut w = Words {
        words,
        at: 0,
        command,
        clause: "",
    };
    let mut out = PairCoeff {
        voigt: VoigtParams::default(),
        bond: BondParams::default_in_units(units),
        has_bond: false,
    };
    let model = w.word(&format!("model ({VOIGT})"))?;
    if model != VOIGT {
        return Err(w.fail(format!("unknown model '{model}' (expected {VOIGT})")));
    }
    w.clause = VOIGT;
    let mut voigt = Clause::new(VOIGT, VOIGT_PARAMETERS, VOIGT_PHRASES);
    voigt.head(&mut w, &mut out.voigt)?;
    while !w.done() && w.peek(0) != BOND && w.peek(0) != LINEAR {
        if !voigt.next(&mut w, &mut out.voigt)? {
            return Err(w.fail(format!(
                "unknown keyword '{}' (known: {}, then {BOND} or {LINEAR})",
                w.peek(0),
                voigt.known()
            )));
        }
    }
    if w.done() {
        return Ok(out);
    }
    let linear = w.word(BOND)? == LINEAR;
    w.clause = if linear { LINEAR } else { BOND };
    out.has_bond = true;
    // the law's own defaults (the linear bond's differ)
    out.bond = if linear {
        BondParams::linear_default_in_units(units)
    } else {
        BondParams::default_in_units(units)
    };
    let mut bond = Clause::new(BOND, PARAMETERS, PHRASES);
    bond.read_to_end(&mut w, &mut out.bond)?;
    if bond.given("contact_under_bond").is_none() {
        out.bond.contact_under_bond_by_law();
    }
    Ok(out)
}

/// Reads the words of `bond_coeff` after the bond type (`words`) into a
/// bond's parameters, from the defaults; `command` names the command as the
/// deck wrote it ("bond_coeff 1"). The rows of bonds a pair style forms
/// ([`CREATION_ROWS`], [`PAIR_BOND_ROWS`]) are refused: the topology names
/// these bonds, and `special_bonds` says whether their contact acts.
pub fn read_bond_coeff(command: &str, words: &[&str]) -> Result<BondParams, String> {
    let mut w = Words {
        words,
        at: 0,
        command,
        clause: BOND,
    };
    let mut params = BondParams::default();
    let mut bond = Clause::new(BOND, PARAMETERS, PHRASES);
    bond.read_to_end(&mut w, &mut params)?;
    for row in PARAMETERS {
        let Some(given) = bond.given(row.name) else {
            continue;
        };
        if CREATION_ROWS.contains(&row.name) {
            return Err(w.fail(format!(
                "'{given}' says when bonds form; under bond_style granbond the topology names the bonds \
                 (create_bonds, a data file's Bonds section, molecule templates), each at rest at its length when \
                 first seen"
            )));
        }
        if PAIR_BOND_ROWS.contains(&row.name) {
            return Err(w.fail(format!(
                "'{given}' says what pair_style granbond's contact does under its bonds; under bond_style \
                 granbond special_bonds says whether a bonded pair's contact acts"
            )));
        }
    }
    Ok(params)
}
