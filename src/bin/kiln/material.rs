//! `kiln material new` and `kiln material preset`.

use crate::args::MaterialCommand;
use crate::output::host_failure;
use std::process::ExitCode;

/// Runs a material command.
pub fn run(command: MaterialCommand) -> ExitCode {
    let done = match command {
        MaterialCommand::New { path, shader, preset, project } => {
            let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
            kiln::project::new_material(&path, &shader, preset.as_deref(), &project)
        }
        MaterialCommand::Preset { path, preset, project } => {
            let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
            kiln::project::apply_preset(&path, &preset, &project)
        }
    };
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => host_failure(&error.to_string()),
    }
}
