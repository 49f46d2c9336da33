//! What the renderer's test files share.

/// Reports a skipped check where it stays visible: straight to the process's stderr, which the
/// test harness does not capture (a passing test's `println!` is hidden).
pub fn skipped(what: &str) {
    use std::io::Write as _;
    let _ = writeln!(std::io::stderr(), "SKIPPED {what}");
}
