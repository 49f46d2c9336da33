//! `kiln material new` and `kiln material preset`.

use crate::args::MaterialCommand;
use crate::output::host_failure;
use std::process::ExitCode;

/// Runs a material command.
pub fn run(command: MaterialCommand) -> ExitCode {
    // What was done, said once it is on disk (names as diagnostics show them: no control codes).
    let shown = |text: &str| kiln::diagnostics::shown_text(text, false).into_owned();
    let done = match command {
        MaterialCommand::New { path, shader, preset, project } => {
            let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
            kiln::project::new_material(&path, &shader, preset.as_deref(), &project).map(|()| {
                let preset = preset.map(|p| format!(", preset {}", shown(&p))).unwrap_or_default();
                format!(
                    "wrote {}: a material of `{}`{preset}",
                    shown(&path.display().to_string()),
                    shown(&shader)
                )
            })
        }
        MaterialCommand::Preset { path, preset, project } => {
            let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
            kiln::project::apply_preset(&path, &preset, &project).map(|()| {
                format!("applied preset {} to {}", shown(&preset), shown(&path.display().to_string()))
            })
        }
    };
    match done {
        Ok(said) => {
            eprintln!("{said}");
            ExitCode::SUCCESS
        }
        Err(error) => host_failure(&error.to_string()),
    }
}
