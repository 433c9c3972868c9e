//! Minimal CSV output for scene runs (a header line, then numbers).

use std::io::{self, Write};

pub struct CsvWriter<W: Write> {
    out: W,
    columns: usize,
}

impl<W: Write> CsvWriter<W> {
    pub fn new(mut out: W, header: &[&str]) -> io::Result<Self> {
        writeln!(out, "{}", header.join(","))?;
        Ok(Self {
            out,
            columns: header.len(),
        })
    }

    pub fn row(&mut self, values: &[f64]) -> io::Result<()> {
        assert_eq!(values.len(), self.columns, "row width must match the header");
        let text: Vec<String> = values.iter().map(|v| format!("{v:.12e}")).collect();
        writeln!(self.out, "{}", text.join(","))
    }

    pub fn into_inner(self) -> W {
        self.out
    }
}
