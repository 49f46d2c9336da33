//! Every mistake the ShaderLab stage reports, as a typed enum turned into diagnostics here.

use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramLanguage;
use crate::source::Span;

/// A mistake found, with where it is. Each variant's meaning is the diagnostic it becomes (its
/// code and message, in the `From` impl below, documented in docs/diagnostics.md), so variants
/// and fields are not documented twice.
#[allow(missing_docs)]
#[derive(Debug, Clone, PartialEq)]
pub enum ShaderLabError {
    UnterminatedString { span: Span },
    UnterminatedComment { span: Span },
    UnclosedProgram { open: Span, language: ProgramLanguage, include: bool },
    UnclosedBrace { open: Span, likely: Option<Span> },
    UnmatchedCloseBrace { span: Span },
    NestedTooDeep { span: Span, limit: usize },
    Syntax { span: Span, expected: Vec<String>, found: String },
    UnknownPropertyType { span: Span, found: String },
    RangeWithoutBounds { span: Span },
    RangeMinAboveMax { span: Span, min: f64, max: f64 },
    BoundsOnNonRange { span: Span, ty: &'static str },
    DefaultMismatch { span: Span, ty: &'static str, expected: &'static str },
    VectorComponents { span: Span, ty: &'static str, found: usize, expected: &'static str },
    DuplicateProperty { span: Span, first: Span, name: String },
    UnknownValue { span: Span, command: String, found: String, expected: &'static [&'static str] },
    ExpectedNumber { span: Span, command: String, found: String },
    OutOfRange { span: Span, what: String, found: String, range: &'static str },
    UnknownStencilCommand { span: Span, found: String },
    AttributeArguments { span: Span, attribute: String, expected: &'static str },
    ProgramOutsideSubShader { span: Span, keyword: &'static str },
    ForbiddenCharacter { span: Span, found: char },
}

/// Comma-separated list of backticked names, ending in "or": "`A`, `B` or `C`".
pub(crate) fn one_of(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    match quoted.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
    }
}

impl From<ShaderLabError> for Diagnostic {
    fn from(error: ShaderLabError) -> Diagnostic {
        use ShaderLabError::*;
        match error {
            UnterminatedString { span } => Diagnostic::error("K0101", "unterminated string")
                .at(span, "this string has no closing `\"` on its line")
                .help("strings end on the line they start; add the closing quote"),
            UnterminatedComment { span } => Diagnostic::error("K0102", "unterminated block comment")
                .at(span, "this `/*` is never closed")
                .help("add `*/` where the comment should end"),
            UnclosedProgram { open, language, include } => Diagnostic::error(
                "K0103",
                format!("`{}` block is never closed", language.open_keyword(include)),
            )
            .at(open, "program block opened here")
            .help(format!("end the block with `{}`", language.close_keyword())),
            UnclosedBrace { open, likely } => {
                let d = Diagnostic::error("K0104", "unclosed `{`");
                match likely {
                    Some(likely) => d
                        .at(likely, "this block is probably the one missing its `}`")
                        .label(open, "left open at the end of the file")
                        .note("the `}` that should close it is indented like a different block"),
                    None => d.at(open, "this `{` is never closed"),
                }
                .help("add the missing `}`")
            }
            UnmatchedCloseBrace { span } => Diagnostic::error("K0105", "unmatched `}`")
                .at(span, "this `}` closes nothing")
                .help("remove it, or add the `{` it was meant to close"),
            NestedTooDeep { span, limit } => {
                Diagnostic::error("K0107", format!("blocks are nested more than {limit} deep"))
                    .at(span, "this `{` goes past the limit")
                    .note("the limit keeps pathological input from exhausting the parser's stack")
            }
            Syntax { span, expected, found } => {
                let expected_text = match expected.as_slice() {
                    [] => "something else".to_string(),
                    [one] => one.clone(),
                    [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
                };
                let mut d = Diagnostic::error("K0106", format!("expected {expected_text}, found {found}"))
                    .at(span, format!("expected {expected_text}"))
                    .note("ShaderLab syntax errors stop the parse of this file at the first one");
                let word = found.trim_matches('`');
                if expected.iter().any(|e| e == "`}`") && word.starts_with(|c: char| c.is_ascii_alphabetic())
                {
                    d = d.help(format!("`{word}` is not a command ShaderLab accepts here"));
                }
                if found.contains(char::REPLACEMENT_CHARACTER) {
                    d = d.help("the file has bytes here that are not UTF-8: save it as UTF-8");
                }
                d
            }
            UnknownPropertyType { span, found } => {
                Diagnostic::error("K0110", format!("unknown property type `{found}`"))
                    .at(span, "not a property type")
                    .help(format!(
                        "use one of {}",
                        one_of(&[
                            "Float",
                            "Int",
                            "Integer",
                            "Range(min, max)",
                            "Color",
                            "Vector",
                            "2D",
                            "2DArray",
                            "3D",
                            "Cube",
                            "CubeArray",
                            "Any"
                        ])
                    ))
            }
            RangeWithoutBounds { span } => Diagnostic::error("K0111", "`Range` needs its bounds")
                .at(span, "missing `(min, max)`")
                .help("write `Range(0, 1)`"),
            RangeMinAboveMax { span, min, max } => {
                Diagnostic::warning("K0112", format!("range minimum {min} is above its maximum {max}"))
                    .at(span, "a reversed range")
                    .note("Unity accepts it and draws the slider from the first bound to the second; kiln accepts values between the two")
                    .help(format!("swap the bounds if that is not meant: `Range({max}, {min})`"))
            }
            BoundsOnNonRange { span, ty } => Diagnostic::error("K0113", format!("`{ty}` takes no bounds"))
                .at(span, "bounds are only allowed on `Range`")
                .help("remove the parentheses, or make the type `Range`"),
            DefaultMismatch { span, ty, expected } => {
                Diagnostic::error("K0114", format!("a `{ty}` property needs {expected} as its default"))
                    .at(span, "wrong kind of default")
            }
            VectorComponents { span, ty, found, expected } => Diagnostic::error(
                "K0115",
                format!("a `{ty}` default has {expected} components, found {found}"),
            )
            .at(span, format!("{found} components")),
            DuplicateProperty { span, first, name } => {
                Diagnostic::warning("K0116", format!("property `{name}` is declared twice"))
                    .at(span, "declared again here")
                    .label(first, "first declared here")
                    .note("as in Unity, both are one material value; its type and default are the first declaration's")
                    .help("give each property a name of its own, unless the repeat is meant (an inspector line)")
            }
            UnknownValue { span, command, found, expected } => {
                Diagnostic::error("K0120", format!("unknown `{command}` value `{found}`"))
                    .at(span, format!("not a `{command}` value"))
                    .help(format!("use {}, or a `[_Property]` reference", one_of(expected)))
            }
            ExpectedNumber { span, command, found } => {
                Diagnostic::error("K0121", format!("`{command}` takes a number, found `{found}`"))
                    .at(span, "expected a number or a `[_Property]` reference")
            }
            OutOfRange { span, what, found, range } => {
                Diagnostic::error("K0122", format!("{what} `{found}` is out of range"))
                    .at(span, format!("must be {range}"))
            }
            UnknownStencilCommand { span, found } => {
                Diagnostic::error("K0123", format!("unknown stencil command `{found}`"))
                    .at(span, "not a stencil command")
                    .help(format!("use one of {}", one_of(crate::shaderlab::ast::StencilField::NAMES)))
            }
            AttributeArguments { span, attribute, expected } => {
                Diagnostic::error("K0130", format!("`[{attribute}]` takes {expected}"))
                    .at(span, "wrong arguments")
            }
            ProgramOutsideSubShader { span, keyword } => {
                Diagnostic::error("K0131", format!("`{keyword}` block outside a SubShader"))
                    .at(span, "programs belong in a `Pass` or `SubShader`")
                    .help("only `*INCLUDE` blocks may sit directly in a `Shader`")
            }
            ForbiddenCharacter { span, found } if found == char::REPLACEMENT_CHARACTER => {
                Diagnostic::error("K0132", "string holds bytes that are not UTF-8")
                    .at(span, "not UTF-8 here")
                    .note("names, tags and display names reach the manifest and generated code")
                    .help("save the file as UTF-8")
            }
            ForbiddenCharacter { span, found } => {
                Diagnostic::error("K0132", format!("control character U+{:04X} in a string", found as u32))
                    .at(span, "control character")
                    .note("names, tags and display names reach the manifest and generated code")
                    .help("remove it; only tab is allowed inside a ShaderLab string")
            }
        }
    }
}
