//! `grainscope-bindgen INPUT.wasm OUT_DIR`: writes the JavaScript loader
//! (`grainscope.js`) and the WebAssembly module (`grainscope_bg.wasm`) of the
//! browser build into OUT_DIR, as
//! `wasm-bindgen --target web --no-typescript --out-name grainscope` does.
//!
//! It calls the library behind that command (`wasm-bindgen-cli-support`) with
//! the command's own defaults for every other option. The command's crate
//! also compiles a test runner with an HTTP server and a TLS stack, which the
//! page's build never runs: this tool needs about half the compiling.

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
    #[allow(deprecated)]
    bindgen
        .input_path(input)
        .nodejs(false)?
        .web(false)?
        .browser(false)?
        .no_modules(false)?
        .debug(false)
        .demangle(true)
        .keep_lld_exports(false)
        .keep_debug(false)
        .split_debug_info(false)
        .remove_name_section(false)
        .remove_producers_section(false)
        .typescript(false)
        .omit_imports(false)
        .omit_default_module_path(false)
        .split_linked_modules(false)
        .js_string_builtins(false)
        .ts_typed_array_buffers(false)
        .reference_types(false)
        .reset_state_function(false)
        .force_enable_abort_handler(false)
        .out_name("grainscope");
    bindgen.generate(out_dir)?;
    Ok(())
}
