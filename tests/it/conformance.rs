//! A public C preprocessor conformance suite: Boost.Wave's test files (`tests/corpus/wave`,
//! BSL-1.0, origin in its `ORIGIN.md`). Each file in kiln's scope is preprocessed by kiln and by
//! gcc's `cpp -P -undef -nostdinc` and compared token for token, and with the output the file
//! itself expects (its `//R` lines); a file that expects an error (`//E`) must be an error for
//! kiln too. What is out of scope is counted by reason (docs/preprocessor.md).

use crate::cpp::{cpp_run, first_difference, kiln_run, tokens};
use crate::support::{root, tool};
use std::collections::BTreeMap;

/// Wave options that change nothing C's preprocessor does differently (language modes whose
/// differences the other rules catch, C99 features, warnings as errors, output hooks).
const C_OPTIONS: [&str; 9] = [
    "--variadics",
    "--c99",
    "--long_long",
    "-Werror",
    "--noguard",
    "--skipped_token_hooks",
    "--c++11",
    "--c++17",
    "--c++20",
];

/// The file's `-D` options (`//O -DNAME=VALUE`) as `#define` lines, for kiln and cpp alike.
fn defines(text: &str) -> String {
    text.lines()
        .filter_map(|l| l.strip_prefix("//O -D"))
        .map(|d| {
            let (name, value) = d.trim().split_once('=').unwrap_or((d.trim(), "1"));
            format!("#define {name} {value}\n")
        })
        .collect()
}

/// Why a file is out of kiln's scope, or `None` when it is in.
fn out_of_scope(text: &str) -> Option<&'static str> {
    let code = without_comments(text);
    let directives: Vec<(String, String)> = code
        .lines()
        .filter_map(|line| line.trim_start().strip_prefix('#'))
        .map(|rest| {
            let rest = rest.trim_start();
            let name: String = rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
            let args = rest[name.len()..].to_string();
            (name, args)
        })
        .collect();
    let words = |text: &str, list: &[&str]| {
        text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).any(|w| list.contains(&w))
    };
    let options = text.lines().filter_map(|l| l.strip_prefix("//O ")).map(str::trim);
    if options.clone().any(|o| !(C_OPTIONS.contains(&o) || o.starts_with("-D"))) {
        return Some("runs with Wave's own options (`//O`: include paths, forced includes, pass-through)");
    }
    if directives.iter().any(|(name, _)| name == "include" || name == "include_next") {
        return Some("includes other files or system headers");
    }
    if directives.iter().any(|(name, _)| name == "line")
        || words(
            &code,
            &[
                "__LINE__",
                "__FILE__",
                "__DATE__",
                "__TIME__",
                "__STDC__",
                "__STDC_VERSION__",
                "__STDC_HOSTED__",
                "__cplusplus",
                "__INCLUDE_LEVEL__",
                "__COUNTER__",
                "__BASE_FILE__",
                "__has_include",
            ],
        )
        || code.contains("__WAVE")
        || code.contains("__TESTWAVE")
        || code.contains("BOOST_")
    {
        return Some("`#line` or predefined macros");
    }
    if code.contains('"') || code.contains('\'') {
        return Some("string or character literals (WGSL has none)");
    }
    let stringifies =
        directives.iter().any(|(name, args)| name == "define" && args.replace("##", "").contains('#'));
    if stringifies {
        return Some("stringification (`#`, `#@`)");
    }
    if directives.iter().any(|(name, args)| name == "pragma" && args.trim() != "once")
        || code.contains("_Pragma")
    {
        return Some("pragmas other than `once`");
    }
    if directives.iter().any(|(name, _)| {
        ["ident", "sccs", "assert", "unassert", "region", "endregion", "import"].contains(&name.as_str())
    }) {
        return Some("directives C does not have (`#ident`, `#region`, `#assert`, ...)");
    }
    let cpp_words = [
        "true", "false", "and", "or", "not", "bitand", "bitor", "xor", "compl", "not_eq", "and_eq", "or_eq",
        "xor_eq",
    ];
    if directives.iter().any(|(name, args)| (name == "if" || name == "elif") && words(args, &cpp_words)) {
        return Some("C++'s `true`, `false` and alternative tokens in `#if`");
    }
    if code.contains("%:") || code.contains("<%") {
        return Some("digraphs (`%:`, `<%`)");
    }
    if code.contains("\\u") || code.contains("\\U") || !code.is_ascii() {
        return Some("universal character names and non-ASCII identifiers");
    }
    None
}

/// The text with C comments removed (each a space), for deciding what a file uses.
fn without_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
            out.push(' ');
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |i| &after[i + 2..]);
            out.push(' ');
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// The output the file expects: its `//R` lines, without Wave's `#line` markers.
fn expected(text: &str) -> String {
    text.lines()
        .filter_map(|line| line.find("//R").map(|at| &line[at + 3..]))
        .map(|line| line.strip_prefix(' ').unwrap_or(line))
        .filter(|line| !line.starts_with("#line"))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn boost_wave_test_files_in_scope_agree_with_cpp_and_their_expectations() {
    if !tool("cpp", "cpp", "boost_wave_test_files_in_scope_agree_with_cpp_and_their_expectations") {
        return;
    }
    let mut files: Vec<_> = std::fs::read_dir(root().join("tests/corpus/wave"))
        .expect("the suite")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "cpp"))
        .collect();
    files.sort();
    let mut out_of_scope_counts: BTreeMap<&str, usize> = BTreeMap::new();
    let (mut agree, mut errors_agree, mut errors_cpp_accepts) = (0, 0, 0);
    let (mut wave_only_errors, mut wave_differs, mut both_refuse) = (0, 0, 0);
    let mut failures = Vec::new();
    for path in &files {
        let bytes = std::fs::read(path).expect("read");
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("?");
        let Ok(text) = String::from_utf8(bytes) else {
            *out_of_scope_counts.entry("not UTF-8 (Latin-1 comments)").or_default() += 1;
            continue;
        };
        if let Some(reason) = out_of_scope(&text) {
            *out_of_scope_counts.entry(reason).or_default() += 1;
            continue;
        }
        let input = format!("{}{text}", defines(&text));
        let (ours, our_errors, our_warnings) = kiln_run(&input, &[]);
        let theirs = cpp_run(&input);
        // The suite expects an error: kiln must report one (gcc only warns about some of these).
        if text.contains("//E") && !our_errors.is_empty() {
            errors_agree += 1;
            errors_cpp_accepts += usize::from(theirs.is_ok());
            continue;
        }
        let (theirs, their_warnings) = match theirs {
            Ok(theirs) => theirs,
            // gcc refuses it (Wave's `--variadics` allows pastes C does not): so must kiln.
            Err(_) if !our_errors.is_empty() => {
                both_refuse += 1;
                continue;
            }
            Err(e) => {
                failures.push(format!("{name}: cpp refuses it, kiln does not: {e}"));
                continue;
            }
        };
        if !our_errors.is_empty() {
            failures.push(format!("{name}: kiln refuses it:\n{our_errors}"));
            continue;
        }
        // kiln keeps comments (WGSL's), cpp drops them: compare what is left.
        let (ours, theirs) = (tokens(&without_comments(&ours)), tokens(&theirs));
        let wanted = tokens(&expected(&text));
        if let Some(difference) = first_difference(&ours, &theirs) {
            failures.push(format!("{name}: kiln and cpp disagree {difference}"));
        } else if their_warnings.contains("warning:") && our_warnings == 0 {
            failures.push(format!("{name}: cpp warns, kiln does not:\n{their_warnings}"));
        } else if text.contains("//E") {
            // An error for Wave (C++ rules, or its own limits) that C allows: gcc's verdict.
            wave_only_errors += 1;
        } else if let Some(difference) = first_difference(&theirs, &wanted) {
            // Wave's expectation differs from gcc's output (its C++ lexer): gcc's counts.
            println!("{name}: Wave's `//R` lines (`cpp:` below) differ from gcc's and kiln's {difference}");
            wave_differs += 1;
        } else {
            agree += 1;
        }
    }
    let out: usize = out_of_scope_counts.values().sum();
    println!(
        "Boost.Wave: {} files; in scope {}, all agreeing with cpp: {agree} with their `//R` lines too, \
         {wave_differs} where Wave's `//R` lines differ from gcc's output, {errors_agree} expected errors \
         that are errors ({errors_cpp_accepts} of them only warnings for cpp), {wave_only_errors} \
         errors for Wave alone that gcc and kiln accept alike, {both_refuse} that gcc and kiln \
         refuse alike; out of scope {out}:",
        files.len(),
        files.len() - out
    );
    for (reason, count) in &out_of_scope_counts {
        println!("  {count:3} {reason}");
    }
    assert!(
        failures.is_empty(),
        "{} of {} in-scope files fail:\n{}",
        failures.len(),
        files.len() - out,
        failures.join("\n\n")
    );
    assert!(agree >= 40, "too few in scope: {agree}");
}
