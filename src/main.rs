//! The grainscope binary: the explorer window, or the headless harness when
//! given a command.

use clap::Parser;
use grainscope::cli::{Cli, Command};
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => open_window(Vec::new()),
        Some(Command::Gui { files }) => open_window(files),
        Some(command) => grainscope::cli::run(command),
    }
    .and_then(|()| Ok(std::io::stdout().flush()?));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of our output went away (`grainscope presets | head -1`): nothing to say.
        Err(e) if grainscope::cli::is_closed_pipe(&e) => ExitCode::SUCCESS,
        // A check that ran and failed (the audit): status 1.
        Err(e) if e.downcast_ref::<grainscope::cli::CheckFailed>().is_some() => {
            let _ = writeln!(std::io::stderr(), "{e}");
            ExitCode::from(1)
        }
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// Opens the explorer window.
#[cfg(feature = "gui")]
fn open_window(files: Vec<String>) -> anyhow::Result<()> {
    grainscope::app::run(files)
}

/// Without the `gui` feature there is no window: say so and point to the commands.
#[cfg(not(feature = "gui"))]
fn open_window(_files: Vec<String>) -> anyhow::Result<()> {
    anyhow::bail!(
        "this grainscope was built without the window (feature `gui`); run `grainscope --help` for the commands"
    )
}
