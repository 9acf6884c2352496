//! `grainscope-bindgen INPUT.wasm OUT_DIR`: writes the JavaScript loader
//! (`grainscope.js`) and the WebAssembly module (`grainscope_bg.wasm`) of the
//! browser build into OUT_DIR, as
//! `wasm-bindgen --target web --no-typescript --out-name grainscope` does.
//!
//! It calls the library behind that command (`wasm-bindgen-cli-support`) with
//! the command's own defaults for every other option. The command's crate
//! also compiles a test runner with an HTTP server and a TLS stack, which the
//! page's build never runs: this tool needs a third of the compiling.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use wasm_bindgen_cli_support::Bindgen;

fn main() -> ExitCode {
    let args: Vec<PathBuf> = std::env::args_os().skip(1).map(PathBuf::from).collect();
    let [input, out_dir] = args.as_slice() else {
        eprintln!("usage: grainscope-bindgen INPUT.wasm OUT_DIR");
        return ExitCode::from(2);
    };
    match generate(input, out_dir) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("grainscope-bindgen: {}: {error:#}", input.display());
            ExitCode::FAILURE
        }
    }
}

/// The bindings of `input` into `out_dir`: `--target web --no-typescript
/// --out-name grainscope`, every other option at the command's default.
fn generate(input: &Path, out_dir: &Path) -> anyhow::Result<()> {
    let mut bindgen = Bindgen::new();
    bindgen.web(true)?;
    bindgen
        .input_path(input)
        .typescript(false)
        .out_name("grainscope")
        // The one option whose library default differs from the command's:
        // the command keeps the module's default path in the loader.
        .omit_default_module_path(false);
    bindgen.generate(out_dir)?;
    Ok(())
}
