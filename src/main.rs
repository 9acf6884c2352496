//! The grainscope binary: the explorer window, or the headless harness when
//! given a command.

use clap::Parser;
use grainscope::cli::{Cli, Command};
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => open_window(None),
        Some(Command::Gui { preset }) => open_window(preset),
        Some(command) => grainscope::cli::run(command),
    }
    .and_then(|()| Ok(std::io::stdout().flush()?));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of our output went away (`grainscope presets | head -1`): nothing to say.
        Err(e) if grainscope::cli::is_closed_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// Opens the explorer window.
#[cfg(feature = "gui")]
fn open_window(preset: Option<String>) -> anyhow::Result<()> {
    grainscope::app::run(preset)
}

/// Without the `gui` feature there is no window: say so and point to the commands.
#[cfg(not(feature = "gui"))]
fn open_window(_preset: Option<String>) -> anyhow::Result<()> {
    anyhow::bail!(
        "this grainscope was built without the window (feature `gui`); run `grainscope --help` for the commands"
    )
}
