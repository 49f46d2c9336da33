//! What the command writes: results on stdout, diagnostics rendered on stderr (colour only on a
//! terminal without `NO_COLOR`), and the exit code.

use kiln::diagnostics::{self, Diagnostic};
use kiln::source::SourceStore;
use std::io::{IsTerminal, Write};
use std::process::ExitCode;

/// A result on stdout.
pub fn print_out(text: &str) {
    // A closed pipe (`kiln list | head`) is not an error worth a panic.
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

/// Diagnostics on stderr.
pub fn report(store: &SourceStore, problems: &[Diagnostic]) {
    let stderr = std::io::stderr();
    let color = stderr.is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let _ = diagnostics::render_to(store, problems, color, &mut stderr.lock());
}

/// The run could not be made: the reason, and exit code 2.
pub fn host_failure(message: &str) -> ExitCode {
    report(&SourceStore::new(), &[Diagnostic::host_failure(message)]);
    ExitCode::from(2)
}

/// 1 when any diagnostic is an error.
pub fn exit_code(problems: &[Diagnostic]) -> ExitCode {
    if diagnostics::has_errors(problems) { ExitCode::from(1) } else { ExitCode::SUCCESS }
}

/// Returns `code` without freeing `built` (a build's manifest and files, millions of small
/// allocations at 100,000 variants): the process exits next, and the system frees it at once.
pub fn exit_leaving<T>(code: ExitCode, built: T) -> ExitCode {
    std::mem::forget(built);
    code
}
