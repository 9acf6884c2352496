//! Reading measured coefficients of restitution from CSV.
//!
//! The first row names the columns: a velocity column with its unit in
//! brackets (`velocity [m/s]`, `v [cm/s]` or `[mm/s]`), a restitution column
//! (`restitution` or `e`), and optionally an uncertainty column
//! (`uncertainty`, `error`, `sigma` or `de`). Empty lines and lines starting
//! with `#` are skipped.

use crate::physics::fit::Measurement;
use std::path::Path;

/// Why a CSV file was rejected; `line` is 1-based.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CsvError {
    /// The file could not be read.
    #[error("cannot read {path}: {message}")]
    Read {
        /// File.
        path: String,
        /// Cause.
        message: String,
    },
    /// The header lacks a required column or has an unknown unit.
    #[error("line 1: {0}")]
    Header(String),
    /// A data row is malformed.
    #[error("line {line}: {reason}")]
    Row {
        /// Line number.
        line: usize,
        /// What is wrong.
        reason: String,
    },
    /// No data rows.
    #[error("no measurements in the file")]
    Empty,
}

fn velocity_scale(header: &str) -> Result<Option<f64>, CsvError> {
    let lower = header.trim().to_ascii_lowercase();
    let name = lower.split('[').next().unwrap_or("").trim();
    if !(name == "v" || name == "velocity" || name == "v_in" || name.starts_with("velocity")) {
        return Ok(None);
    }
    let unit = lower.split_once('[').and_then(|(_, u)| u.split_once(']')).map(|(u, _)| u.trim().replace(' ', ""));
    match unit.as_deref() {
        Some("m/s") | Some("ms^-1") | Some("ms-1") => Ok(Some(1.0)),
        Some("cm/s") | Some("cms^-1") | Some("cms-1") => Ok(Some(0.01)),
        Some("mm/s") | Some("mms^-1") | Some("mms-1") => Ok(Some(0.001)),
        Some(u) => Err(CsvError::Header(format!("unknown velocity unit [{u}] (use m/s, cm/s or mm/s)"))),
        None => Err(CsvError::Header(format!("the velocity column '{header}' needs its unit, e.g. 'velocity [m/s]'"))),
    }
}

/// Parses CSV text into measurements.
pub fn parse(text: &str) -> Result<Vec<Measurement>, CsvError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut records = reader.records();
    let header = loop {
        match records.next() {
            None => return Err(CsvError::Empty),
            Some(Err(e)) => return Err(CsvError::Header(e.to_string())),
            Some(Ok(r)) if r.iter().all(|f| f.is_empty()) => continue,
            Some(Ok(r)) => break r,
        }
    };
    let mut v_col = None;
    let mut e_col = None;
    let mut s_col = None;
    for (i, h) in header.iter().enumerate() {
        if let Some(scale) = velocity_scale(h)? {
            v_col = Some((i, scale));
            continue;
        }
        let name = h.to_ascii_lowercase();
        let name = name.split('[').next().unwrap_or("").trim().to_string();
        match name.as_str() {
            "restitution" | "e" | "cor" | "coefficient of restitution" => e_col = Some(i),
            "uncertainty" | "error" | "sigma" | "de" | "e_err" => s_col = Some(i),
            _ => {}
        }
    }
    let (v_col, scale) =
        v_col.ok_or_else(|| CsvError::Header("missing a velocity column, e.g. 'velocity [m/s]'".into()))?;
    let e_col = e_col.ok_or_else(|| CsvError::Header("missing a 'restitution' column".into()))?;

    let mut out = Vec::new();
    for record in records {
        let record = record.map_err(|e| CsvError::Row {
            line: e.position().map_or(0, |p| p.line() as usize),
            reason: e.to_string(),
        })?;
        let line = record.position().map_or(0, |p| p.line() as usize);
        if record.iter().all(|f| f.is_empty()) {
            continue;
        }
        let field = |col: usize, what: &str| -> Result<f64, CsvError> {
            let raw =
                record.get(col).ok_or_else(|| CsvError::Row { line, reason: format!("missing the {what} column") })?;
            let x: f64 =
                raw.parse().map_err(|_| CsvError::Row { line, reason: format!("{what} '{raw}' is not a number") })?;
            if x.is_finite() {
                Ok(x)
            } else {
                Err(CsvError::Row { line, reason: format!("{what} '{raw}' is not finite") })
            }
        };
        let velocity = field(v_col, "velocity")? * scale;
        if velocity <= 0.0 {
            return Err(CsvError::Row { line, reason: format!("velocity {velocity} m/s must be positive") });
        }
        let restitution = field(e_col, "restitution")?;
        if !(0.0..=1.2).contains(&restitution) {
            return Err(CsvError::Row { line, reason: format!("restitution {restitution} is outside 0 … 1.2") });
        }
        let uncertainty = match s_col {
            Some(c) if record.get(c).is_some_and(|f| !f.is_empty()) => {
                let s = field(c, "uncertainty")?;
                if s < 0.0 {
                    return Err(CsvError::Row { line, reason: "uncertainty must not be negative".into() });
                }
                Some(s)
            }
            _ => None,
        };
        out.push(Measurement { velocity, restitution, uncertainty });
    }
    if out.is_empty() { Err(CsvError::Empty) } else { Ok(out) }
}

/// Reads a CSV file of measurements.
pub fn load(path: &Path) -> Result<Vec<Measurement>, CsvError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CsvError::Read { path: path.display().to_string(), message: e.to_string() })?;
    parse(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_units_and_optional_uncertainty() {
        let m =
            parse("velocity [cm/s],restitution,uncertainty\n# a comment\n50,0.8,0.02\n\n120,0.9,\n").expect("parses");
        assert_eq!(m.len(), 2);
        assert!((m[0].velocity - 0.5).abs() < 1e-12 && m[0].uncertainty == Some(0.02));
        assert_eq!(m[1].uncertainty, None);
    }

    #[test]
    fn malformed_files_name_the_line_and_reason() {
        let cases = [
            ("restitution\n0.5\n", "velocity column"),
            ("velocity [m/s]\n3\n", "restitution"),
            ("velocity,restitution\n3,0.5\n", "unit"),
            ("velocity [furlongs/s],restitution\n3,0.5\n", "unknown velocity unit"),
            ("velocity [m/s],restitution\n3,abc\n", "line 2: restitution 'abc' is not a number"),
            ("velocity [m/s],restitution\n3,0.5\n-1,0.5\n", "line 3: velocity"),
            ("velocity [m/s],restitution\n3,1.5\n", "line 2: restitution 1.5 is outside"),
            ("velocity [m/s],restitution\n3\n", "line 2: missing the restitution column"),
            ("velocity [m/s],restitution\n", "no measurements"),
        ];
        for (text, expected) in cases {
            let err = parse(text).expect_err(text).to_string();
            assert!(err.contains(expected), "{text:?}: {err}");
        }
    }
}
