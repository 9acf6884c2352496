//! Exported files that reopen their state. Every PNG (an iTXt chunk), SVG
//! (a `<metadata>` element) and CSV (`#` comment lines at the top) written by
//! grainscope carries the program version and the preset that produced it,
//! as RON. [`read`] takes such a file back to that text, and
//! [`crate::preset::resolve`] to the preset, so `grainscope run figure.png`
//! recomputes exactly what the figure shows.
//!
//! This module carries the preset as text and knows nothing of presets
//! themselves: [`crate::preset`] builds a [`Stamp`] of a preset
//! ([`Stamp::of`]) and parses what [`read`] returns.

use crate::figure::{ExportError, Figure};
use std::path::Path;

/// Keyword of the PNG text chunk and name of the SVG element holding the preset.
pub const PRESET_KEY: &str = "grainscope-preset";

/// Keyword of the PNG text chunk naming the program and its version.
pub const SOFTWARE_KEY: &str = "Software";

/// The first line of the comment block of an exported CSV file.
const CSV_HEAD: &str = "# grainscope-preset (RON) follows, one line per comment; data below";

/// What an exported file carries about its origin.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Stamp {
    /// Program and version, e.g. "grainscope 0.1.0".
    pub program: String,
    /// The preset that produced the file, as RON.
    pub preset: String,
}

/// Why no state could be read from a file.
#[derive(Debug, thiserror::Error)]
pub enum ProvenanceError {
    /// The file could not be read.
    #[error("cannot read {path}: {cause}")]
    Read {
        /// File.
        path: String,
        /// What the operating system said.
        cause: std::io::Error,
    },
    /// The file is of a kind that carries no state.
    #[error("{0}: not a PNG, SVG or CSV file exported by grainscope")]
    Kind(String),
    /// The file carries no embedded preset.
    #[error(
        "{0} carries no grainscope state (only figures exported by grainscope 0.1 or later do; a preset file or a shipped preset name works instead)"
    )]
    Missing(String),
}

impl Stamp {
    /// PNG text chunks: (keyword, text).
    pub fn png_text(&self) -> [(&str, &str); 2] {
        [(SOFTWARE_KEY, self.program.as_str()), (PRESET_KEY, self.preset.as_str())]
    }

    /// The SVG document with a `<metadata>` element right after its root tag.
    pub fn svg(&self, svg: &str) -> String {
        let Some(start) = svg.find("<svg") else { return svg.to_string() };
        let Some(end) = svg[start..].find('>').map(|e| start + e + 1) else { return svg.to_string() };
        // Inside CDATA only "]]>" needs care: split it across two sections.
        let body = self.preset.replace("]]>", "]]]]><![CDATA[>");
        let program = escape(&self.program);
        format!(
            "{}\n<metadata><{PRESET_KEY} program=\"{program}\"><![CDATA[{body}]]></{PRESET_KEY}></metadata>{}",
            &svg[..end],
            &svg[end..]
        )
    }

    /// The CSV data preceded by comment lines: the program, then the preset.
    pub fn csv(&self, csv: &[u8]) -> Vec<u8> {
        let mut out = format!("# {}\n{CSV_HEAD}\n", self.program);
        for line in self.preset.lines() {
            out.push_str("#  ");
            out.push_str(line);
            out.push('\n');
        }
        let mut out = out.into_bytes();
        out.extend_from_slice(csv);
        out
    }
}

/// The bytes of `fig` as a file of kind `ext` ("png", "svg" or "csv";
/// images at `size` pixels), carrying `stamp` when given.
pub fn figure_bytes(fig: &Figure, ext: &str, size: (u32, u32), stamp: Option<&Stamp>) -> Result<Vec<u8>, ExportError> {
    let draw_err = |message: String| ExportError::Draw { id: fig.id.clone(), message };
    match (ext, stamp) {
        ("png", Some(st)) => crate::figure::png_bytes_with_text(fig, size, &st.png_text()),
        ("png", None) => crate::figure::png_bytes(fig, size),
        ("svg", _) => {
            let svg = crate::figure::svg_string(fig, size)?;
            Ok(stamp.map_or(svg.clone(), |st| st.svg(&svg)).into_bytes())
        }
        ("csv", _) => {
            let csv = crate::figure::csv_bytes(fig).map_err(|e| draw_err(e.to_string()))?;
            Ok(stamp.map_or(csv.clone(), |st| st.csv(&csv)))
        }
        _ => Err(draw_err(format!("cannot write a '.{ext}' file: use .png, .svg or .csv"))),
    }
}

/// Stages every figure as CSV, SVG and PNG (at [`crate::figure::EXPORT_SIZE`],
/// each carrying `stamp`) into `set`, as `dir/PREFIX ID.EXT`; nothing is
/// written until the set is committed.
pub fn stage_figures(
    set: &mut crate::files::FileSet,
    figures: &[Figure],
    dir: &Path,
    prefix: &str,
    stamp: Option<&Stamp>,
) -> anyhow::Result<()> {
    use anyhow::Context as _;
    for fig in figures {
        for ext in ["csv", "svg", "png"] {
            let bytes = figure_bytes(fig, ext, crate::figure::EXPORT_SIZE, stamp)
                .with_context(|| format!("cannot write figure '{}' as {ext}", fig.id))?;
            set.stage(&dir.join(format!("{prefix}{}.{ext}", fig.id)), &bytes)?;
        }
    }
    Ok(())
}

/// Which build a result came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Build {
    /// The program's version, e.g. "0.1.0".
    pub version: &'static str,
    /// The commit the build was made from (12 hex digits), or "unknown"
    /// where the sources were not a git checkout.
    pub commit: &'static str,
    /// Whether tracked files differed from that commit.
    pub dirty: bool,
    /// The commit's date (YYYY-MM-DD), or "unknown".
    pub date: &'static str,
}

/// This build.
pub fn build() -> Build {
    Build {
        version: env!("CARGO_PKG_VERSION"),
        commit: env!("GRAINSCOPE_COMMIT"),
        dirty: env!("GRAINSCOPE_DIRTY") == "1",
        date: env!("GRAINSCOPE_COMMIT_DATE"),
    }
}

impl std::fmt::Display for Build {
    /// "0.1.0 (commit 8359ffd1a2b3, 2026-11-27)", "+ local changes" when dirty
    /// (the text of `grainscope --version`).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(env!("GRAINSCOPE_BUILD"))
    }
}

/// "grainscope VERSION (commit …, DATE)": the program and the build that made a result.
pub fn program() -> String {
    format!("grainscope {}", build())
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('"', "&quot;")
}

/// Whether `path` names a file kind that can carry a stamp (PNG, SVG, CSV).
pub fn may_carry_state(path: &Path) -> bool {
    matches!(extension(path).as_str(), "png" | "svg" | "csv")
}

fn extension(path: &Path) -> String {
    path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase()
}

/// The preset embedded in an exported PNG, SVG or CSV file, as the RON text
/// it was written as (see [`crate::preset::resolve`] for the preset).
pub fn read(path: &Path) -> Result<String, ProvenanceError> {
    let origin = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|cause| ProvenanceError::Read { path: origin.clone(), cause })?;
    from_bytes(&bytes, &origin)
}

/// The preset embedded in the bytes of an exported PNG, SVG or CSV file, as
/// its RON text;
/// `name` (a file name or path) gives the kind by its extension and names
/// the file in errors.
pub fn from_bytes(bytes: &[u8], name: &str) -> Result<String, ProvenanceError> {
    let origin = name.to_string();
    let text = match extension(Path::new(name)).as_str() {
        "png" => png_text(bytes),
        "svg" => std::str::from_utf8(bytes).ok().and_then(svg_text),
        "csv" => std::str::from_utf8(bytes).ok().and_then(csv_text),
        _ => return Err(ProvenanceError::Kind(origin)),
    };
    text.ok_or(ProvenanceError::Missing(origin))
}

fn png_text(bytes: &[u8]) -> Option<String> {
    let reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().ok()?;
    let info = reader.info();
    info.utf8_text.iter().find(|c| c.keyword == PRESET_KEY).and_then(|c| c.get_text().ok())
}

fn svg_text(svg: &str) -> Option<String> {
    let open = format!("<{PRESET_KEY}");
    let start = svg.find(&open)?;
    let after = start + svg[start..].find('>')? + 1;
    let end = after + svg[after..].find(&format!("</{PRESET_KEY}>"))?;
    let inner = &svg[after..end];
    // Join the CDATA sections.
    let mut out = String::new();
    let mut rest = inner;
    while let Some(s) = rest.find("<![CDATA[") {
        let body = &rest[s + 9..];
        let e = body.find("]]>")?;
        out.push_str(&body[..e]);
        rest = &body[e + 3..];
    }
    Some(out)
}

fn csv_text(csv: &str) -> Option<String> {
    let mut lines = csv.lines();
    lines.next().filter(|l| l.starts_with("# grainscope"))?;
    lines.next().filter(|l| *l == CSV_HEAD)?;
    let body: Vec<&str> = lines.map_while(|l| l.strip_prefix("#  ")).collect();
    (!body.is_empty()).then(|| body.join("\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file without a stamp is refused with a message naming it, and a
    /// file of another kind is refused as such.
    #[test]
    fn files_without_state_are_refused() {
        let dir = tempfile::tempdir().expect("tempdir");
        let plain = dir.path().join("plain.csv");
        std::fs::write(&plain, "x,y\n1,2\n").expect("write");
        let err = read(&plain).expect_err("no state").to_string();
        assert!(err.contains("plain.csv") && err.contains("carries no grainscope state"), "{err}");
        let other = dir.path().join("notes.txt");
        std::fs::write(&other, "hello").expect("write");
        assert!(read(&other).expect_err("kind").to_string().contains("not a PNG, SVG or CSV"));
    }

    /// Text containing the CDATA terminator still round-trips through SVG.
    #[test]
    fn cdata_terminators_are_split() {
        let stamp = Stamp { program: program(), preset: "(description: \"a ]]> b\")".into() };
        let svg = stamp.svg("<svg width=\"1\">\n</svg>");
        assert_eq!(svg_text(&svg).expect("found"), stamp.preset);
    }
}
