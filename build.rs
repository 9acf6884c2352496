//! Records which sources a build was made from: the commit, whether the
//! work tree differed from it, and the commit's date, read from git when
//! the sources are a git checkout ("unknown" otherwise). `provenance::build`
//! reads them.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn main() {
    let commit = git(&["rev-parse", "--short=12", "HEAD"]).filter(|c| !c.is_empty());
    let date = commit.as_ref().and_then(|_| git(&["log", "-1", "--format=%cs"]));
    // Tracked files that differ from the commit; untracked files do not count.
    let dirty = commit
        .as_ref()
        .and_then(|_| git(&["status", "--porcelain", "--untracked-files=no"]))
        .is_some_and(|s| !s.is_empty());
    println!("cargo:rustc-env=GRAINSCOPE_COMMIT={}", commit.as_deref().unwrap_or("unknown"));
    println!("cargo:rustc-env=GRAINSCOPE_COMMIT_DATE={}", date.as_deref().unwrap_or("unknown"));
    println!("cargo:rustc-env=GRAINSCOPE_DIRTY={}", u8::from(dirty));
    // The same as one line, for `grainscope --version`.
    let version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    println!(
        "cargo:rustc-env=GRAINSCOPE_BUILD={version} (commit {}{}, {})",
        commit.as_deref().unwrap_or("unknown"),
        if dirty { " + local changes" } else { "" },
        date.as_deref().unwrap_or("unknown")
    );
    // A new commit moves the branch's ref, not HEAD: watch both, and the
    // packed refs.
    if let Some(dir) = git(&["rev-parse", "--git-dir"]) {
        let branch = git(&["symbolic-ref", "-q", "HEAD"]);
        for f in ["HEAD", "index", "packed-refs"].into_iter().map(String::from).chain(branch) {
            // A path that does not exist would rerun this script on every build.
            let path = std::path::Path::new(&dir).join(&f);
            if path.exists() {
                println!("cargo:rerun-if-changed={}", path.display());
            }
        }
    }
    compress_font();
    for path in ["src", "assets", "presets", "Cargo.toml", "build.rs"] {
        println!("cargo:rerun-if-changed={path}");
    }
}

/// The bundled font, zlib-compressed into `OUT_DIR` (about half its size),
/// for `figure::font_ttf` to inflate once. The browser's module carries the
/// subset `assets/fonts/subset.sh` makes (the blocks the explorer and a
/// user's Latin, Greek or Cyrillic text use), the desktop the whole font.
fn compress_font() {
    let web = std::env::var("CARGO_CFG_TARGET_ARCH").is_ok_and(|a| a == "wasm32");
    let font = if web { "assets/fonts/DejaVuSans-web.ttf" } else { "assets/fonts/DejaVuSans.ttf" };
    println!("cargo:rerun-if-changed={font}");
    let root = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".into());
    let bytes = std::fs::read(std::path::Path::new(&root).join(font))
        .unwrap_or_else(|e| panic!("the bundled font {font}: {e}"));
    let packed = miniz_oxide::deflate::compress_to_vec_zlib(&bytes, 10);
    let out = std::path::Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("DejaVuSans.ttf.zlib");
    std::fs::write(out, packed).expect("OUT_DIR is writable");
}
