//! Every mistake the preprocessor reports, as a typed enum turned into diagnostics here.

use super::pass::MAX_UBERSHADER_KEYWORDS;
use crate::diagnostics::Diagnostic;
use crate::shaderlab::error::one_of;
use crate::source::Span;

/// A mistake found, with where it is. Each variant's meaning is the diagnostic it becomes (its
/// code and message, in the `From` impl below, documented in docs/diagnostics.md), so variants
/// and fields are not documented twice.
#[allow(missing_docs)]
#[derive(Debug, Clone, PartialEq)]
pub enum PreprocessError {
    IncludeNotFound {
        span: Span,
        name: String,
        searched: Vec<String>,
        suggestion: Option<String>,
    },
    /// `chain` runs from the file that includes itself again, through each include, back to it.
    IncludeCycle {
        span: Span,
        chain: Vec<String>,
    },
    IncludeTooDeep {
        span: Span,
        limit: usize,
    },
    ExpandedTooLarge {
        span: Span,
        what: String,
    },
    IncludeOutsideRoots {
        span: Span,
        name: String,
        resolved: String,
    },
    IncludeUnreadable {
        span: Span,
        name: String,
        reason: String,
    },
    UnterminatedComment {
        span: Span,
    },
    UnterminatedConditional {
        open: Span,
        directive: String,
    },
    StrayConditional {
        span: Span,
        directive: String,
    },
    BranchAfterElse {
        span: Span,
        directive: String,
        else_span: Span,
    },
    ConditionalTooDeep {
        span: Span,
        limit: usize,
    },
    MalformedExpression {
        span: Span,
        expected: &'static str,
    },
    DivisionByZero {
        span: Span,
    },
    ExpansionTooDeep {
        span: Span,
        name: String,
        limit: usize,
    },
    ExpansionTooLarge {
        span: Span,
        name: String,
        limit: usize,
    },
    ErrorDirective {
        span: Span,
        message: String,
    },
    WarningDirective {
        span: Span,
        message: String,
    },
    UnknownDirective {
        span: Span,
        name: String,
    },
    MalformedDirective {
        span: Span,
        directive: String,
        expected: &'static str,
    },
    /// `#x` in a function-like macro's body: C's stringification, which WGSL has no use for.
    Stringification {
        span: Span,
        name: String,
    },
    /// `##` first or last in a macro's body.
    PasteAtEdge {
        span: Span,
    },
    ArgumentCount {
        span: Span,
        name: String,
        expected: usize,
        variadic: bool,
        found: usize,
        definition: Option<Span>,
    },
    UnterminatedArguments {
        span: Span,
        name: String,
    },
    InvalidPaste {
        span: Span,
        name: String,
        left: String,
        right: String,
        definition: Option<Span>,
    },
    /// A shift by a negative count or by 64 or more: undefined in C.
    InvalidShift {
        span: Span,
        count: String,
    },
    MacroRedefined {
        span: Span,
        name: String,
        previous: Span,
    },
    KeywordNeverTested {
        span: Span,
        keyword: String,
    },
    KeywordNeverDeclared {
        span: Span,
        name: String,
        suggestion: Option<String>,
    },
    PragmaInPlainInclude {
        span: Span,
        pragma: String,
    },
    DefinedInExpansion {
        span: Span,
        name: String,
        definition: Option<Span>,
    },
    VariadicMisuse {
        span: Span,
        name: String,
        reason: &'static str,
    },
    DynamicKeywordInCondition {
        span: Span,
        keyword: String,
        declared: Span,
    },
    /// A variant keyword of a pass with `#pragma ubershader` tested by a conditional.
    UbershaderKeywordInCondition {
        span: Span,
        keyword: String,
        declared: Span,
        pragma: Span,
    },
    /// More keywords than an ubershader's immediate data has bits.
    UbershaderTooManyKeywords {
        pragma: Span,
        count: usize,
    },
    /// Tokens after `#else` or `#endif`.
    ExtraTokens {
        span: Span,
        directive: String,
    },
    /// `\`, blanks, then a line break.
    SpliceAfterBlanks {
        span: Span,
    },
}

/// The directives the preprocessor knows, for the "unknown directive" help.
pub(crate) const DIRECTIVES: [&str; 15] = [
    "include",
    "include_with_pragmas",
    "define",
    "undef",
    "if",
    "ifdef",
    "ifndef",
    "elif",
    "elifdef",
    "elifndef",
    "else",
    "endif",
    "error",
    "warning",
    "pragma",
];

impl From<PreprocessError> for Diagnostic {
    fn from(error: PreprocessError) -> Diagnostic {
        use PreprocessError::*;
        match error {
            IncludeNotFound { span, name, searched, suggestion } => {
                let mut d = Diagnostic::error("K0301", format!("cannot find include `{name}`"))
                    .at(span, "included here");
                for folder in searched {
                    d = d.note(format!("searched {folder}"));
                }
                match suggestion {
                    Some(s) => d.help(format!("did you mean `{s}`?")),
                    None => d.help("check the name, or add its folder to the project's include paths"),
                }
            }
            IncludeCycle { span, chain } => Diagnostic::error("K0302", "include cycle")
                .at(span, "this include leads back to a file that is still being included")
                .note(format!("the cycle: {}", chain.join(" -> ")))
                .help("break the cycle, or guard the file with `#pragma once`"),
            ExpandedTooLarge { span, what } => {
                Diagnostic::error("K0331", format!("a stage's preprocessing {what}"))
                    .at(span, "here; nothing after it is read")
                    .note("files included many times over (each including the next twice, say) or macros that expand to many copies of one another multiply what they are given")
                    .help("guard the headers (`#pragma once` or `#ifndef` guards) so each is read once")
            }
            IncludeTooDeep { span, limit } => {
                Diagnostic::error("K0303", format!("includes nested deeper than {limit} levels"))
                    .at(span, "this include is one level too deep")
                    .help("this usually means a file includes itself through a chain without a guard")
            }
            IncludeOutsideRoots { span, name, resolved } => Diagnostic::error(
                "K0304",
                format!("include `{name}` resolves outside the project"),
            )
            .at(span, format!("this names `{resolved}`"))
            .help("includes may only name files under the project's roots, its include paths or the bundled library"),
            IncludeUnreadable { span, name, reason } => {
                Diagnostic::error("K0315", format!("cannot read include `{name}`"))
                    .at(span, "included here")
                    .note(reason)
            }
            UnterminatedComment { span } => Diagnostic::error("K0332", "block comment never closed")
                .at(span, "this `/*` has no `*/` before the end of the file")
                .note("everything after it, to the end of the file, is comment and was not compiled")
                .help("close it with `*/` (WGSL's block comments nest: each `/*` needs its own)"),
            UnterminatedConditional { open, directive } => {
                Diagnostic::error("K0305", format!("`#{directive}` without `#endif`"))
                    .at(open, "this conditional is never closed")
                    .help("add `#endif` where the conditional block ends (in the same file)")
            }
            StrayConditional { span, directive } => {
                Diagnostic::error("K0306", format!("`#{directive}` without a matching `#if`"))
                    .at(span, "no open `#if`, `#ifdef` or `#ifndef` in this file")
            }
            BranchAfterElse { span, directive, else_span } => {
                Diagnostic::error("K0307", format!("`#{directive}` after `#else`"))
                    .at(span, format!("`#{directive}` cannot follow `#else`"))
                    .label(else_span, "the `#else` is here")
            }
            ConditionalTooDeep { span, limit } => {
                Diagnostic::error("K0314", format!("conditionals nested deeper than {limit} levels"))
                    .at(span, "this conditional is one level too deep")
            }
            MalformedExpression { span, expected } => {
                Diagnostic::error("K0308", "malformed `#if` expression").at(span, format!("expected {expected}"))
            }
            DivisionByZero { span } => {
                Diagnostic::error("K0309", "division by zero in `#if` expression").at(span, "this divisor is zero")
            }
            ExpansionTooDeep { span, name, limit } => Diagnostic::error(
                "K0313",
                format!("macro `{name}` expands more than {limit} levels deep"),
            )
            .at(span, "expanded here")
            .help("a chain of `#define`s probably refers back to itself"),
            ExpansionTooLarge { span, name, limit } => Diagnostic::error(
                "K0313",
                format!("macro `{name}` expands to more than {limit} tokens"),
            )
            .at(span, "expanded here")
            .note("each level of a chain that repeats its argument doubles what the next receives")
            .help("expand less at once: a loop in the shader, or a smaller table"),
            ErrorDirective { span, message } => Diagnostic::error("K0310", message).at(span, "`#error` reached"),
            WarningDirective { span, message } => {
                Diagnostic::warning("K0318", message).at(span, "`#warning` reached")
            }
            UnknownDirective { span, name } => {
                let known: Vec<String> = DIRECTIVES.iter().map(|d| format!("#{d}")).collect();
                let known: Vec<&str> = known.iter().map(String::as_str).collect();
                Diagnostic::error("K0311", format!("unknown preprocessor directive `#{name}`"))
                    .at(span, "not a directive")
                    .help(format!("directives are {}", one_of(&known)))
            }
            MalformedDirective { span, directive, expected } => {
                Diagnostic::error("K0312", format!("malformed `#{directive}`")).at(span, format!("expected {expected}"))
            }
            Stringification { span, name } => {
                Diagnostic::error("K0317", format!("`#{name}` (stringification) is not supported"))
                    .at(span, "this would make a string literal")
                    .note("WGSL has no string literals, so a stringified argument could only be a compile error")
                    .help("use the parameter without `#`, or `##` to paste it into a name")
            }
            PasteAtEdge { span } => Diagnostic::error("K0323", "`##` at the edge of a macro body")
                .at(span, "nothing to paste on this side")
                .help("`##` joins the tokens on either side of it"),
            ArgumentCount { span, name, expected, variadic, found, definition } => {
                let takes = match (expected, variadic) {
                    (n, true) => format!("at least {n} argument{}", if n == 1 { "" } else { "s" }),
                    (1, false) => "1 argument".to_string(),
                    (n, false) => format!("{n} arguments"),
                };
                let d = Diagnostic::error("K0324", format!("macro `{name}` takes {takes}, but {found} were given"))
                    .at(span, format!("{found} argument{}", if found == 1 { "" } else { "s" }));
                match definition {
                    Some(at) => d.label(at, "defined here"),
                    None => d,
                }
            }
            UnterminatedArguments { span, name } => {
                Diagnostic::error("K0325", format!("unterminated argument list of macro `{name}`"))
                    .at(span, "no `)` closes this call")
                    .note("a call's arguments end before the next preprocessor directive")
            }
            InvalidPaste { span, name, left, right, definition } => {
                let d = Diagnostic::error("K0326", format!("pasting `{left}` and `{right}` does not give a token"))
                    .at(span, format!("in expansion of macro `{name}`"));
                match definition {
                    Some(at) => d.label(at, "defined here"),
                    None => d,
                }
            }
            InvalidShift { span, count } => Diagnostic::error("K0327", format!("shift by {count} in `#if` expression"))
                .at(span, "this shift is undefined in C")
                .help("shift by 0 to 63"),
            MacroRedefined { span, name, previous } => {
                Diagnostic::warning("K0316", format!("macro `{name}` redefined with a different value"))
                    .at(span, "redefined here")
                    .label(previous, "first defined here")
                    .note("a redefinition is the same only with the same tokens and whitespace between the same ones, as C has it")
                    .help("`#undef` it first if the new value is intended")
            }
            KeywordNeverTested { span, keyword } => Diagnostic::warning(
                "K0320",
                format!("keyword `{keyword}` is declared but never tested"),
            )
            .at(span, "declared here")
            .note("no `#if`, `#ifdef` or `#ifndef` in the pass's source or its includes tests it, so it only multiplies variants")
            .help("test it with `#if defined(...)`, or remove it from the pragma"),
            KeywordNeverDeclared { span, name, suggestion } => {
                let d = Diagnostic::warning("K0321", format!("`{name}` is tested but never declared or defined"))
                    .at(span, "always off in this pass")
                    .note("no keyword pragma of the pass declares it and no `#define` defines it");
                match suggestion {
                    Some(s) => d.help(format!("did you mean the keyword `{s}`?")),
                    None => d.help("declare it with `#pragma shader_feature` or `#pragma multi_compile`"),
                }
            }
            PragmaInPlainInclude { span, pragma } => {
                Diagnostic::warning("K0322", format!("`#pragma {pragma}` in a plain `#include` is ignored"))
                    .at(span, "this pragma does not count for the pass")
                    .help("include the file with `#include_with_pragmas` to make its pragmas count")
            }
            DefinedInExpansion { span, name, definition } => {
                let d = Diagnostic::warning("K0330", format!("`defined` written by expanding `{name}` in `#if`"))
                    .at(span, "expanded here");
                let d = match definition {
                    Some(definition) => d.label(definition, "whose value uses `defined`"),
                    None => d,
                };
                d.note("C leaves this undefined; kiln evaluates it as gcc and clang do, on the name as written")
                    .help("test the names in the `#if` itself, or define the macro as 0 or 1")
            }
            VariadicMisuse { span, name, reason } => {
                Diagnostic::error("K0329", format!("`{name}` where C does not allow it"))
                    .at(span, "not allowed here")
                    .note(reason)
            }
            DynamicKeywordInCondition { span, keyword, declared } => Diagnostic::error(
                "K0328",
                format!("`{keyword}` is a `dynamic_branch` keyword: the preprocessor cannot test it"),
            )
            .at(span, "tested by the preprocessor here")
            .label(declared, "declared `dynamic_branch` here")
            .note("one module serves every value of a `dynamic_branch` keyword, so it is never a macro; it is an `override` constant set when the pipeline is created")
            .help(format!("branch with `if ({keyword}) {{ ... }}`, or declare it `shader_feature` to compile a variant for it")),
            UbershaderKeywordInCondition { span, keyword, declared, pragma } => Diagnostic::error(
                "K0335",
                format!("`{keyword}` is a keyword of a pass with an ubershader: the preprocessor cannot test it"),
            )
            .at(span, "tested by the preprocessor here")
            .label(declared, "declared here")
            .label(pragma, "the pass builds an ubershader here")
            .note("the ubershader reads every keyword at run time, so in this pass each is `true` or `false`, never a condition of `#if`")
            .help(format!("branch with `if ({keyword}) {{ ... }}`, or remove `#pragma ubershader`")),
            UbershaderTooManyKeywords { pragma, count } => Diagnostic::error(
                "K0336",
                format!("an ubershader reads at most {MAX_UBERSHADER_KEYWORDS} keywords; this pass has {count}"),
            )
            .at(pragma, "the pass builds an ubershader here")
            .note("each keyword is one bit of the ubershader's immediate data")
            .help("remove `#pragma ubershader`, or split the pass's keywords between passes"),
            ExtraTokens { span, directive } => {
                Diagnostic::warning("K0333", format!("tokens after `#{directive}` are ignored"))
                    .at(span, "ignored")
                    .note("C allows nothing after `#else` and `#endif`; gcc warns and goes on, as kiln does")
                    .help("put the remark in a comment: `#endif // NAME`")
            }
            SpliceAfterBlanks { span } => {
                Diagnostic::warning("K0334", "blanks between `\\` and the line break")
                    .at(span, "this `\\` still joins the next line to this one")
                    .note("gcc takes a `\\` followed by spaces or tabs at the end of a line as a line splice, and so does kiln")
                    .help("remove the blanks after the `\\`, or the `\\` if the lines are not meant to join")
            }
        }
    }
}
