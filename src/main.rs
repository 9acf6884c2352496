//! The grainscope binary: the explorer window, or the headless harness when
//! given a command.

use clap::Parser;
use grainscope::cli::{Cli, Command};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => grainscope::app::run(None),
        Some(Command::Gui { preset }) => grainscope::app::run(preset),
        Some(command) => grainscope::cli::run(command),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
