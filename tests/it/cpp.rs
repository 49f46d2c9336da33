//! kiln's preprocessor against gcc's: generated programs (thousands of random `#if`
//! expressions, hundreds of lines of nested function-like macro calls with `##` and variadic
//! macros) preprocessed by both, compared token by token. Required in CI (`KILN_REQUIRE_TOOLS`),
//! skipped with a printed reason where `cpp` is missing.

use crate::support::tool;
use kiln::preprocess::{IncludeConfig, Includes, Stage};
use kiln::source::{SourceStore, Span};
use std::fmt::Write as _;
use std::process::Command;

/// A small deterministic generator (xorshift64*), so a failure reproduces.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

/// Macros both preprocessors see before each generated program (the variant's keyword `K1` too).
const PRELUDE: &str = "\
#define A 3
#define B -2
#define U 5u
#define BIG 0xFFFFFFFFFFFFFFFF
#define Z0 0
#define F(x, y) ((x) * (y))
#define G(x) (x + 1)
#define H(x, ...) (x - (__VA_ARGS__))
#define CAT(a, b) a ## b
#define XCAT(a, b) CAT(a, b)
#define ID(x) x
#define PAIR(a, b) a, b
#define FIRST(a, ...) a
#define REST(a, ...) __VA_ARGS__
#define APPLY(f, x) f(x)
#define TWICE(x) x x
#define N -1
#define ONE 1
#define EMPTY
#define OBJ_CAT foo ## bar
#define SELF SELF + 1
#define REC(x) REC(x) + x
#define SAMPLE SAMPLE_TEXTURE2D
#define SAMPLE_TEXTURE2D(t, s, uv) textureSample(t, s, uv)
#define TEXTURE2D(name) var name: texture_2d<f32>
#define T vec3<f32>
#define CALL(m, ...) m(__VA_ARGS__)
#define OPT(a, ...) (a __VA_OPT__(+ __VA_ARGS__))
";

fn literal(rng: &mut Rng) -> String {
    let value = rng.below(40);
    let suffix = rng.pick(&["", "", "", "u", "U", "l", "L", "ul", "LL", "ull", "LLu"]);
    match rng.below(4) {
        0 => format!("0x{value:X}{suffix}"),
        1 if value > 0 => format!("0{value:o}{suffix}"),
        _ => format!("{value}{suffix}"),
    }
}

/// A random `#if` expression with no operation C leaves undefined (no division by a zero that is
/// evaluated, no shift out of range, no `defined` inside a macro's arguments, which gcc expands
/// first).
fn expression(rng: &mut Rng, depth: usize, in_macro: bool) -> String {
    if depth == 0 || rng.below(4) == 0 {
        return match rng.below(if in_macro { 4 } else { 9 }) {
            0..=2 => literal(rng),
            3 => rng.pick(&["A", "B", "U", "Z0", "ONE", "MISSING", "K1", "K2"]).to_string(),
            4 => format!("defined({})", rng.pick(&["A", "K1", "K2", "F", "MISSING"])),
            5 => format!("defined {}", rng.pick(&["U", "K1", "K2", "EMPTY"])),
            6 => format!("F({}, {})", expression(rng, 0, true), expression(rng, 0, true)),
            7 => format!("G({})", expression(rng, 0, true)),
            _ => format!(
                "H({}, {}, {})",
                expression(rng, 0, true),
                expression(rng, 0, true),
                expression(rng, 0, true)
            ),
        };
    }
    let e = |rng: &mut Rng| expression(rng, depth - 1, in_macro);
    match rng.below(11) {
        0 => format!("{} ({})", rng.pick(&["-", "+", "~", "!"]), e(rng)),
        1 => format!("({}) ? ({}) : ({})", e(rng), e(rng), e(rng)),
        // A divisor that is never 0 when evaluated: 1 + (x & 7).
        2 => format!("({}) {} (1 + (({}) & 7))", e(rng), rng.pick(&["/", "%"]), e(rng)),
        // Short circuits around operations that would fail if evaluated.
        3 => format!("(0 && (1 / 0)) || ({})", e(rng)),
        4 => format!("({}) {} {}", e(rng), rng.pick(&["<<", ">>"]), rng.below(63)),
        5 => format!("F({}, G({}))", expression(rng, depth - 1, true), expression(rng, depth - 1, true)),
        _ => {
            let op = rng.pick(&["+", "-", "*", "<", ">", "<=", ">=", "==", "!=", "&", "^", "|", "&&", "||"]);
            format!("({}) {op} ({})", e(rng), e(rng))
        }
    }
}

/// A random line of macro calls. With `comma_free`, nothing that expands to a top-level comma:
/// such a call passed on to another function-like macro would give it extra arguments, an error
/// in C too.
fn call(rng: &mut Rng, depth: usize, comma_free: bool) -> String {
    if depth == 0 || rng.below(3) == 0 {
        let leaves = ["x", "y1", "2", "0.5", "N", "ONE", "EMPTY", "OBJ_CAT", "SELF", "T", "a.b", "1.0f"];
        return rng.pick(&leaves).to_string();
    }
    let c = |rng: &mut Rng| call(rng, depth - 1, comma_free);
    let free = |rng: &mut Rng| call(rng, depth - 1, true);
    match rng.below(if comma_free { 14 } else { 16 }) {
        0 => format!("CAT({}, {})", rng.pick(&["x", "foo", "_", "v"]), rng.pick(&["1", "bar", "y", ""])),
        1 => format!("XCAT({}, {})", rng.pick(&["ON", "x"]), rng.pick(&["E", "1"])),
        2 => format!("ID({})", c(rng)),
        3 => format!("FIRST({}, {})", c(rng), c(rng)),
        4 => format!("APPLY(ID, {})", free(rng)),
        5 => format!("TWICE({})", c(rng)),
        6 => format!("F({}, {})", c(rng), c(rng)),
        7 => format!("1-N+{}", c(rng)),
        8 => format!("SAMPLE(tex, samp, {})", free(rng)),
        9 => format!("REC({})", c(rng)),
        10 => format!("CALL(F, {}, {})", free(rng), free(rng)),
        11 => format!("T=={}", c(rng)),
        12 => format!("OPT({})", c(rng)),
        13 => format!("OPT({}, {}, {})", c(rng), c(rng), c(rng)),
        14 => format!("REST({}, {}, {})", c(rng), c(rng), c(rng)),
        _ => format!("ID(PAIR({}, (({}, {}))))", c(rng), c(rng), c(rng)),
    }
}

/// kiln's output for `text` with keyword `K1` on.
fn kiln_output(text: &str) -> String {
    let (out, rendered, _) = kiln_run(text, &["K1"]);
    assert!(rendered.is_empty(), "{rendered}");
    out
}

/// kiln's output for `text` with `keywords` on, its errors rendered (empty when none), and how
/// many warnings it gave.
pub(crate) fn kiln_run(text: &str, keywords: &[&str]) -> (String, String, usize) {
    let mut store = SourceStore::new();
    let file = store.add("input.wgsl", text);
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let (program, mut diagnostics) = includes.load_program(&mut store, &[Span::new(file, 0..text.len())]);
    let out = kiln::preprocess::preprocess(&includes, &store, &program, keywords, Stage::Vertex);
    diagnostics.extend(out.diagnostics);
    let errors: Vec<_> = diagnostics.iter().filter(|d| d.is_error()).cloned().collect();
    let warnings = diagnostics.len() - errors.len();
    (out.text, kiln::diagnostics::render_plain(&store, &errors), warnings)
}

/// gcc's output for `text` with `K1` defined as 1.
fn cpp_output(text: &str) -> String {
    cpp_run(&format!("#define K1 1\n{text}")).unwrap_or_else(|e| panic!("cpp failed: {e}")).0
}

/// gcc's output for `text` as C (`cpp -P -undef -nostdinc`, warning of `defined` that a macro
/// writes, as kiln does) with what it printed on stderr
/// (warnings), or its error output.
pub(crate) fn cpp_run(text: &str) -> Result<(String, String), String> {
    let dir = tempfile::tempdir().expect("temp dir");
    let input = dir.path().join("input.c");
    std::fs::write(&input, text).expect("write");
    let out = Command::new("cpp")
        .args(["-P", "-undef", "-nostdinc", "-Wexpansion-to-defined", "-x", "c"])
        .arg(&input)
        .output()
        .expect("cpp runs");
    if out.status.success() {
        Ok((
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        ))
    } else {
        Err(String::from_utf8_lossy(&out.stderr).into_owned())
    }
}

/// C's preprocessing tokens of a text (spacing is not compared).
pub(crate) fn tokens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    const PUNCTS: [&str; 24] = [
        "...", "<<=", ">>=", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "*=", "/=",
        "%=", "+=", "-=", "&=", "^=", "|=", "##", "::",
    ];
    while i < bytes.len() {
        let b = bytes[i];
        let start = i;
        if b.is_ascii_whitespace() {
            i += 1;
            continue;
        } else if b.is_ascii_alphabetic() || b == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
        } else if b.is_ascii_digit() || (b == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)) {
            i += 1;
            while i < bytes.len() {
                let c = bytes[i];
                let exponent = matches!(c, b'+' | b'-') && matches!(bytes[i - 1], b'e' | b'E' | b'p' | b'P');
                if !(exponent || c.is_ascii_alphanumeric() || c == b'_' || c == b'.') {
                    break;
                }
                i += 1;
            }
        } else if let Some(p) = PUNCTS.iter().find(|p| text[i..].starts_with(**p)) {
            i += p.len();
        } else {
            i += 1;
        }
        out.push(text[start..i].to_string());
    }
    out
}

/// The first difference between two token streams, with some context.
pub(crate) fn first_difference(ours: &[String], theirs: &[String]) -> Option<String> {
    let at = ours
        .iter()
        .zip(theirs)
        .position(|(a, b)| a != b)
        .or_else(|| (ours.len() != theirs.len()).then(|| ours.len().min(theirs.len())))?;
    let window = |t: &[String]| t[at.saturating_sub(12)..(at + 12).min(t.len())].join(" ");
    Some(format!("at token {at}:\n kiln: {}\n  cpp: {}", window(ours), window(theirs)))
}

#[test]
fn if_expressions_take_the_branches_cpp_takes() {
    if !tool("cpp", "cpp", "if_expressions_take_the_branches_cpp_takes") {
        return;
    }
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut text = String::from(PRELUDE);
    let count = 3000;
    for i in 0..count {
        let _ = writeln!(text, "#if {}\nTAKEN_{i}\n#else\nNOT_{i}\n#endif", expression(&mut rng, 4, false));
    }
    let (ours, theirs) = (tokens(&kiln_output(&text)), tokens(&cpp_output(&text)));
    let taken = ours.iter().filter(|t| t.starts_with("TAKEN_")).count();
    println!("{count} #if expressions: {taken} true, {} false, all as cpp decides", count - taken);
    assert!(taken > count / 10 && taken < count * 9 / 10, "the generator tests both outcomes: {taken}");
    if let Some(difference) = first_difference(&ours, &theirs) {
        panic!("kiln and cpp disagree {difference}");
    }
}

#[test]
fn macro_expansion_gives_the_tokens_cpp_gives() {
    if !tool("cpp", "cpp", "macro_expansion_gives_the_tokens_cpp_gives") {
        return;
    }
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    let mut text = String::from(PRELUDE);
    let lines = 600;
    for i in 0..lines {
        // Some calls span lines, as arguments may.
        let line = call(&mut rng, 4, false).replacen(", ", if i % 7 == 0 { ",\n    " } else { ", " }, 1);
        let _ = writeln!(text, "let v{i} = {line};");
    }
    let (ours, theirs) = (tokens(&kiln_output(&text)), tokens(&cpp_output(&text)));
    println!("{lines} lines of macro calls: {} tokens, the same as cpp's", ours.len());
    if let Some(difference) = first_difference(&ours, &theirs) {
        panic!("kiln and cpp disagree {difference}");
    }
}

#[test]
fn the_cases_kiln_once_got_wrong_expand_as_c_expands_them() {
    let cases = [
        // Tokens that were apart stay apart.
        ("#define N -1\n1-N\n", "1- -1"),
        ("#define ONE 1\nONE.5\n", "1 .5"),
        ("#define T vec3<f32>\nT==x\n", "vec3<f32> ==x"),
        // A string literal in a macro's value is not looked into.
        ("#define A 1\n#define MSG \"A B\"\nMSG\n", "\"A B\""),
        // `##` pastes in object-like macros too.
        ("#define AB a ## b\nAB\n", "ab"),
        // A function-like macro's name without `(` is left alone; with it, even on the next line.
        ("#define F(x) [x]\nF + F\n(2)\n", "F + [2]"),
        // Painted blue: `f` in its own expansion never expands again.
        ("#define f(x) x f\nf(f)(1)\n", "f f(1)"),
        // An expansion ending in a function-like macro's name takes its arguments from the text.
        ("#define G(x) <x>\n#define H G\nH(3)\n", "<3>"),
        // Arguments are expanded before substitution, except next to `##`.
        (
            "#define ONE 1\n#define CAT(a, b) a ## b\n#define XCAT(a, b) CAT(a, b)\nCAT(ONE, 2) XCAT(ONE, 2)\n",
            "ONE2 12",
        ),
        // Variadic macros, empty arguments and __VA_OPT__.
        ("#define V(a, ...) a __VA_OPT__(: __VA_ARGS__)\nV(1) V(1, 2, 3) V(, x)\n", "1 1 : 2, 3 : x"),
        // `__VA_OPT__` looks at the arguments once expanded: a macro expanding to nothing is none.
        (
            "#define EMPTY\n#define OPT(a, ...) (a __VA_OPT__(+ __VA_ARGS__))\nOPT(1, EMPTY) OPT(1,) OPT(1, 2)\n",
            "(1) (1) (1 + 2)",
        ),
    ];
    let cpp = tool("cpp", "cpp", "the_cases_kiln_once_got_wrong_expand_as_c_expands_them");
    for (text, expected) in cases {
        let ours = kiln_output(text);
        assert_eq!(tokens(&ours), tokens(expected), "{text} gave {ours}");
        // Where tokens were apart in the source, they are apart in the output.
        if expected.contains(" .") || expected.contains("- -") || expected.contains("> =") {
            assert!(ours.contains(expected), "{text} gave {ours}");
        }
        // gcc agrees on the tokens.
        if cpp {
            assert_eq!(tokens(&ours), tokens(&cpp_output(text)), "{text}");
        }
    }
}

/// Preprocesses each case with kiln and gcc: the tokens must be the expected ones, the same for
/// both, and kiln warns exactly where gcc does. `(input, expected tokens, whether both warn)`.
fn agree_with_cpp(test: &str, cases: &[(&str, &str, bool)]) {
    let cpp = tool("cpp", "cpp", test);
    for &(text, expected, warns) in cases {
        let (ours, errors, warnings) = kiln_run(text, &[]);
        assert!(errors.is_empty(), "{text}: {errors}");
        assert_eq!(tokens(&ours), tokens(expected), "{text} gave {ours}");
        assert_eq!(warnings > 0, warns, "{text}: {warnings} warnings");
        if cpp {
            let (theirs, their_warnings) = cpp_run(text).unwrap_or_else(|e| panic!("{text}: cpp: {e}"));
            assert_eq!(tokens(&ours), tokens(&theirs), "{text}");
            assert_eq!(their_warnings.contains("warning"), warns, "{text}: cpp says {their_warnings}");
        }
    }
}

// C's translation phases, each class a conformance suite found kiln getting wrong.

#[test]
fn a_block_comment_spanning_lines_inside_a_directive_does_not_end_it() {
    agree_with_cpp(
        "a_block_comment_spanning_lines_inside_a_directive_does_not_end_it",
        &[(
            "#define FTN_LIKE( a )( /* note the white space */ \\\na /* other stuff on this line\n * spanning lines */ )\nFTN_LIKE( c);\n",
            "( c ) ;",
            false,
        )],
    );
}

#[test]
fn preprocessing_numbers_are_one_token_and_hide_no_macro() {
    agree_with_cpp(
        "preprocessing_numbers_are_one_token_and_hide_no_macro",
        &[(
            "#define EXP 1\n12E+EXP .2e-EXP 0x1p+EXP 1e+EXP+EXP 1.0+EXP\n",
            "12E+EXP .2e-EXP 0x1p+EXP 1e+EXP+EXP 1.0 + 1",
            false,
        )],
    );
}

#[test]
fn comments_may_stand_before_and_inside_a_directive_name() {
    agree_with_cpp(
        "comments_may_stand_before_and_inside_a_directive_name",
        &[
            ("/**/ # /**/ define /**/ MACRO_abcde /**/ abcde /**/\nMACRO_abcde\n", "abcde", false),
            ("/* a */ /* b */ #define TWO 2\nTWO\n", "2", false),
        ],
    );
}

#[test]
fn line_splices_join_lines_everywhere() {
    agree_with_cpp(
        "line_splices_join_lines_everywhere",
        &[
            ("#define abcde spliced\nabc\\\nde x\\\ny\n", "spliced xy", false),
            ("#define F(a, b) a + b\nF(1,\\\n 2) F\\\n(3, 4)\n", "1 + 2 3 + 4", false),
        ],
    );
}

#[test]
fn a_redefinition_differing_in_whitespace_is_a_redefinition() {
    agree_with_cpp(
        "a_redefinition_differing_in_whitespace_is_a_redefinition",
        &[
            ("#define OBJ_LIKE (1-1)\n#define OBJ_LIKE (1 - 1)\nOBJ_LIKE\n", "( 1 - 1 )", true),
            // The amount of whitespace does not count.
            ("#define SAME (1 -  1)\n#define SAME  (1 - 1)\nSAME\n", "( 1 - 1 )", false),
        ],
    );
}

#[test]
fn defined_written_by_a_macro_in_if_is_evaluated_with_a_warning() {
    agree_with_cpp(
        "defined_written_by_a_macro_in_if_is_evaluated_with_a_warning",
        &[(
            "#define A\n#define HAVE_X defined(A) && !defined(B)\n#if HAVE_X\nyes\n#else\nno\n#endif\n",
            "yes",
            true,
        )],
    );
}

#[test]
fn unary_operators_do_not_count_toward_the_nesting_limit() {
    let long_run = format!("#if {}1\nfar\n#endif\n", "- ".repeat(101));
    agree_with_cpp(
        "unary_operators_do_not_count_toward_the_nesting_limit",
        &[(&UNARY_40, "deep", false), (&long_run, "far", false)],
    );
}

/// `#if` with 40 nested unary minus and complement operators, each parenthesised.
static UNARY_40: std::sync::LazyLock<String> = std::sync::LazyLock::new(|| {
    let (open, close) = ("-(~(".repeat(20), "))".repeat(20));
    format!("#if {open}1{close}\ndeep\n#endif\n")
});

/// A directive whose last line ends in `\` followed by an empty line ends at that empty line, as
/// in C: kiln once carried it on to the next line with text, so a macro swallowed the function
/// after it, silently.
#[test]
fn a_splice_before_an_empty_line_ends_the_directive_there() {
    agree_with_cpp(
        "a_splice_before_an_empty_line_ends_the_directive_there",
        &[
            ("#define X 1 \\\n\nfn keep() {}\nX\n", "fn keep ( ) { } 1", false),
            ("#define Y(a) a + \\\n  2 \\\n\nfn after() {}\nY(1)\n", "fn after ( ) { } 1 + 2", false),
            ("#define Z 3 \\\r\n\r\nfn z() {}\nZ\n", "fn z ( ) { } 3", false),
        ],
    );
}

/// A block comment the file never closes is an error in cpp, and in kiln (K0332), where kiln once
/// took the rest of the file as comment silently; one closed on a later line is not.
#[test]
fn a_block_comment_never_closed_is_an_error_as_in_cpp() {
    let cpp = tool("cpp", "cpp", "a_block_comment_never_closed_is_an_error_as_in_cpp");
    for (text, open) in
        [("fn kept() {}\n/* never closed\nfn lost() {}\n", true), ("a /* spans\nlines */ b\n", false)]
    {
        let (_, errors, _) = kiln_run(text, &[]);
        assert_eq!(errors.contains("error[K0332]: block comment never closed"), open, "{text}: {errors}");
        if cpp {
            let theirs = cpp_run(text);
            assert_eq!(theirs.is_err(), open, "{text}: cpp gave {theirs:?}");
            if let Err(message) = theirs {
                assert!(message.contains("unterminated comment"), "{message}");
            }
        }
    }
}

/// gcc joins `\`, blanks and a line break as a splice, with a warning; kiln once kept the `\` and
/// ended the directive there.
#[test]
fn a_splice_with_blanks_before_the_line_break_joins_with_a_warning() {
    agree_with_cpp(
        "a_splice_with_blanks_before_the_line_break_joins_with_a_warning",
        &[("#define S 1 \\  \n+ 2\nS\n", "1 + 2", true), ("#define T(a) a \\\t\n* 3\nT(2)\n", "2 * 3", true)],
    );
}

/// C reads only the names of directives in a group it skips (for nesting): what would be an error
/// in a taken group is none there; `#elif` after a taken group is not evaluated, so it may be
/// empty (C's DR 412).
#[test]
fn directives_in_a_skipped_group_are_not_checked() {
    agree_with_cpp(
        "directives_in_a_skipped_group_are_not_checked",
        &[
            ("#if 0\n#define foo __VA_ARGS__\n#bogus\n#define\n#if\n#endif\n#endif\nkept\n", "kept", false),
            ("#ifdef NOPE\n#undef 1\n#include\n#else\nelse_kept\n#endif\n", "else_kept", false),
            ("#if 1\ntaken\n#elif\nskipped\n#endif\n", "taken", false),
        ],
    );
}

/// `#else` and `#endif` followed by tokens (`#endif _GUARD_H`, common in old headers): gcc warns
/// and goes on.
#[test]
fn tokens_after_else_and_endif_warn() {
    agree_with_cpp(
        "tokens_after_else_and_endif_warn",
        &[
            ("#ifdef G\na\n#else G\nb\n#endif G\n", "b", true),
            ("#ifndef _GUARD_H\n#define _GUARD_H\nguarded\n#endif _GUARD_H\n", "guarded", true),
        ],
    );
}

/// C23's `#elifdef` and `#elifndef` (gcc 12 on), and `defined` as the name `#ifdef` asks about.
#[test]
fn elifdef_elifndef_and_ifdef_defined_are_cs() {
    agree_with_cpp(
        "elifdef_elifndef_and_ifdef_defined_are_cs",
        &[
            ("#define X 1\n#if 0\na\n#elifdef X\nb\n#else\nc\n#endif\n", "b", false),
            ("#if 0\na\n#elifndef Y\nb\n#endif\n", "b", false),
            ("#define X 1\n#ifdef Y\na\n#elifndef X\nb\n#elifdef X\nc\n#endif\n", "c", false),
            ("#ifdef defined\na\n#else\nb\n#endif\n#ifndef defined\nc\n#endif\n", "b c", false),
        ],
    );
}

/// A pasted preprocessing number is kept apart from the token after it in the output, as cpp
/// keeps it (`1.0e` then `-1` is not the number `1.0e-1`).
#[test]
fn a_pasted_number_is_not_glued_to_the_next_token() {
    let cpp = tool("cpp", "cpp", "a_pasted_number_is_not_glued_to_the_next_token");
    for (text, expected) in [
        ("#define E(x) x ## e\nE(1.0)-1\n", "1.0e -1"),
        ("#define P(a, b) a ## b\nP(1.0e, -)1\n", "1.0e- 1"),
        ("#define P(a, b) a ## b\nP(1, e)+2\n", "1e +2"),
    ] {
        let (ours, errors, _) = kiln_run(text, &[]);
        assert!(errors.is_empty(), "{text}: {errors}");
        let squeeze = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
        assert_eq!(squeeze(&ours), expected, "{text}");
        if cpp {
            let (theirs, _) = cpp_run(text).unwrap_or_else(|e| panic!("{text}: cpp: {e}"));
            assert_eq!(squeeze(&theirs), expected, "{text}: cpp");
        }
    }
}

/// `#elifdef` and `#elifndef` (C23) after a taken group are skipped unread, as C skips them: no
/// name, or more after it, is an error only where the directive is evaluated. There gcc refuses a
/// missing name, and warns of more after it, which kiln refuses as it refuses it after `#ifdef`.
#[test]
fn an_elifdef_is_checked_only_where_it_is_evaluated() {
    let cpp = tool("cpp", "cpp", "an_elifdef_is_checked_only_where_it_is_evaluated");
    // (text, kiln refuses it, gcc refuses it)
    let cases = [
        ("#if 0\n#elifdef\n#endif\n", true, true),
        ("#if 0\n#elifndef\n#endif\n", true, true),
        ("#if 1\nx\n#elifdef\n#endif\n", false, false),
        ("#if 1\nx\n#elifdef FOO junk\n#endif\n", false, false),
        ("#if 1\nx\n#elifndef FOO junk\n#endif\n", false, false),
        ("#if 0\n#elifdef FOO junk\n#endif\n", true, false),
    ];
    for (text, kiln_refuses, gcc_refuses) in cases {
        let (_, errors, _) = kiln_run(text, &[]);
        assert_eq!(errors.contains("error[K0312]"), kiln_refuses, "{text}: {errors}");
        if cpp {
            let dir = tempfile::tempdir().expect("temp dir");
            std::fs::write(dir.path().join("input.c"), text).expect("write");
            let run = Command::new("cpp")
                .args(["-std=c2x", "-P", "-undef", "-nostdinc", "input.c"])
                .current_dir(dir.path())
                .output()
                .expect("cpp runs");
            assert_eq!(
                !run.status.success(),
                gcc_refuses,
                "{text}: {}",
                String::from_utf8_lossy(&run.stderr)
            );
        }
    }
}
