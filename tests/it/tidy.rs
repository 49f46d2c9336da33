//! Keeps docs and code in sync: module docs present, every diagnostic code documented in
//! `docs/diagnostics.md` and shown by at least one golden file.

use crate::support::root;
use std::path::{Path, PathBuf};

fn files_under(dir: &Path, extension: &str) -> Vec<PathBuf> {
    walkdir::WalkDir::new(dir)
        .sort_by_file_name()
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file() && e.path().extension().is_some_and(|x| x == extension))
        .map(|e| e.into_path())
        .collect()
}

/// Codes the goldens cannot show, with the reason.
const NOT_IN_GOLDENS: &[(&str, &str)] = &[
    ("K0002", "an I/O failure while reading a file that exists (tests/it/cli.rs reads a folder as a file)"),
    ("K0004", "a file over 16 MiB (tests/it/robustness.rs makes a sparse one)"),
    ("K0409", "a naga back end failing on a module naga validated (tests/it/trust.rs injects one)"),
    ("K0416", "a panic while compiling: tests/it/trust.rs injects one with KILN_INJECT_PANIC (debug builds)"),
    ("K0410", "the output folder cannot be written (tests/it/build.rs checks it, its text is the OS's)"),
    (
        "K0412",
        "a shard's pack damaged after it was built (tests/it/shards.rs checks it; the path is a temporary folder)",
    ),
];

fn diagnostic_codes() -> Vec<String> {
    let mut codes = Vec::new();
    // The registry names every code: the codes used are those elsewhere.
    for file in files_under(&root().join("src"), "rs").into_iter().filter(|f| !f.ends_with("src/codes.rs")) {
        let text = std::fs::read_to_string(&file).expect("source is UTF-8");
        for (i, _) in text.match_indices("\"K") {
            let code = &text[i + 1..(i + 6).min(text.len())];
            if code.len() == 5
                && code[1..].bytes().all(|b| b.is_ascii_digit())
                && text[i + 6..].starts_with('"')
            {
                codes.push(code.to_string());
            }
        }
    }
    codes.sort();
    codes.dedup();
    codes
}

#[test]
fn the_code_registry_is_the_documented_list_and_every_code_in_it_is_used() {
    let docs = std::fs::read_to_string(root().join("docs/diagnostics.md")).expect("docs/diagnostics.md");
    let documented: Vec<(String, String)> = docs
        .lines()
        .filter_map(|l| l.strip_prefix("## "))
        .filter_map(|l| l.split_once(' '))
        .map(|(code, title)| (code.to_string(), title.to_string()))
        .collect();
    let mut documented_sorted = documented.clone();
    documented_sorted.sort();
    let registry: Vec<(String, String)> =
        kiln::codes::CODES.iter().map(|(c, t)| (c.to_string(), t.to_string())).collect();
    assert_eq!(
        registry, documented_sorted,
        "src/codes.rs and docs/diagnostics.md list the same codes and titles"
    );
    assert!(registry.windows(2).all(|w| w[0].0 < w[1].0), "the registry is sorted, each code once");
    let used = diagnostic_codes();
    let registered: Vec<String> = registry.into_iter().map(|(c, _)| c).collect();
    assert_eq!(
        used, registered,
        "every code the source reports is registered, and every registered one is reported"
    );
}

#[test]
fn every_source_file_says_its_role() {
    for file in files_under(&root().join("src"), "rs") {
        let text = std::fs::read_to_string(&file).expect("source is UTF-8");
        assert!(text.starts_with("//!"), "{} must open with a `//!` line saying its role", file.display());
    }
}

/// Settings are resolved once (`config::Settings::resolve`, from `config::Environment`): the
/// layers that build read no environment variable of their own, or a setting could differ
/// between the passes of one build and bypass the precedence rule. Debug builds' fault
/// injections (`cfg!(debug_assertions) && std::env::var(...)`) are the one exception.
#[test]
fn the_build_reads_its_settings_from_settings_not_from_the_environment() {
    let mut readers = Vec::new();
    for layer in ["orchestrate", "compile", "preprocess", "reflect", "catalog.rs", "keywords", "shaderlab"] {
        let path = root().join("src").join(layer);
        let files = if path.is_dir() { files_under(&path, "rs") } else { vec![path] };
        for file in files {
            let text = std::fs::read_to_string(&file).expect("source is UTF-8");
            for (number, line) in text.lines().enumerate() {
                let reads = line.contains("env::var") || line.contains("Environment::of_process");
                if reads && !line.contains("cfg!(debug_assertions)") {
                    readers.push(format!("{}:{}: {}", file.display(), number + 1, line.trim()));
                }
            }
        }
    }
    assert!(readers.is_empty(), "read through `config::Settings` instead:\n{}", readers.join("\n"));
}

#[test]
fn every_diagnostic_code_is_documented_and_shown() {
    let codes = diagnostic_codes();
    assert!(codes.len() > 20, "found only {codes:?}");
    let docs = std::fs::read_to_string(root().join("docs/diagnostics.md")).expect("docs/diagnostics.md");
    let mut goldens = String::new();
    for dir in ["fixtures", "tests/golden"] {
        for file in files_under(&root().join(dir), "stderr") {
            goldens.push_str(&std::fs::read_to_string(file).expect("golden is UTF-8"));
        }
    }
    for code in &codes {
        assert!(docs.contains(&format!("## {code}")), "{code} is not documented in docs/diagnostics.md");
        let exempt = NOT_IN_GOLDENS.iter().any(|(c, _)| c == code);
        assert!(exempt || goldens.contains(&format!("[{code}]")), "no golden shows {code}");
    }
    for line in docs.lines().filter_map(|l| l.strip_prefix("## ")) {
        let code = line.split_whitespace().next().unwrap_or("");
        assert!(
            codes.iter().any(|c| c == code),
            "docs/diagnostics.md documents {code}, which the code never reports"
        );
    }
}

/// The packages after `apt-get install` (and its options) on the first such line of a text.
fn apt_packages(text: &str) -> Vec<String> {
    let line = text.lines().find(|l| l.contains("apt-get install")).unwrap_or_default();
    let after = line.split("apt-get install").nth(1).unwrap_or_default();
    let mut packages: Vec<String> =
        after.split_whitespace().filter(|w| !w.starts_with('-')).map(str::to_string).collect();
    packages.sort();
    packages
}

#[test]
fn the_readme_s_set_up_line_installs_what_ci_installs() {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README");
    let ci = std::fs::read_to_string(root().join(".ci/run")).expect(".ci/run");
    let (readme_packages, ci_packages) = (apt_packages(&readme), apt_packages(&ci));
    assert!(ci_packages.contains(&"mesa-vulkan-drivers".to_string()), "{ci_packages:?}");
    assert_eq!(
        readme_packages, ci_packages,
        "the README's set-up line and .ci/run install different packages"
    );
    // The set-up line is on the README's first screen, before its first section.
    let first_screen = readme.split("\n## ").next().unwrap_or_default();
    assert!(
        first_screen.contains("apt-get install"),
        "the set-up line is not before the README's first section"
    );
}
