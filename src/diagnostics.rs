//! The one diagnostic type every stage reports with, and the one place that renders it: as text
//! through codespan-reporting, or as JSON for machines.

use crate::source::{FileId, SourceStore, Span, TextProblem};
use codespan_reporting::diagnostic as cs;
use codespan_reporting::term;
use serde::Serialize;

/// How serious a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// A remark: nothing is wrong.
    Note,
    /// Worth a look; the build goes on (an error under `strict`).
    Warning,
    /// The input is wrong; nothing is written and `kiln` exits with 1.
    Error,
}

/// A span with a message attached.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// Where.
    pub span: Span,
    /// What is there.
    pub message: String,
}

/// A user mistake (or a hint about one), as plain data.
///
/// Codes are stable and documented in `docs/diagnostics.md`; messages are lowercase, without a
/// trailing period, and make sense on their own.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// How serious it is.
    pub severity: Severity,
    /// Its stable code (`src/codes.rs`).
    pub code: &'static str,
    /// What is wrong, in a line.
    pub message: String,
    /// Where, with what is there.
    pub primary: Option<Label>,
    /// Other places that explain it.
    pub secondary: Vec<Label>,
    /// Further facts (`= note:`).
    pub notes: Vec<String>,
    /// What to do about it (`= help:`).
    pub help: Option<String>,
    /// The variants of a pass it occurs in (a note after the others), when a stage found it.
    pub occurrence: Option<Occurrence>,
}

/// The variants of a pass a diagnostic occurs in, and where in them: `in variant `A` of `S`
/// pass 0, fragment stage`, or `in 2 variants `A` and `B` of ...` once repeats are merged.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct Occurrence {
    /// The variants, each as its keywords (`(no keywords)`, `_CLIPPING _FOG`).
    pub variants: Vec<String>,
    /// The pass they are variants of.
    pub pass: PassId,
    /// Where in the pass, after its name: `, fragment stage`, or nothing for its whole text.
    pub within: String,
}

/// A pass, by its shader's name and its index in the shader.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct PassId {
    /// The shader's name (`Custom RP/Lit`).
    pub shader: String,
    /// The pass's index, from 0.
    pub index: usize,
}

impl Occurrence {
    /// What follows the variants: ` of `S` pass 0, fragment stage`.
    pub fn place(&self) -> String {
        format!(" of `{}` pass {}{}", self.pass.shader, self.pass.index, self.within)
    }

    /// The note it is shown as.
    pub fn note(&self) -> String {
        const SHOWN: usize = 6;
        let names: Vec<String> = self.variants.iter().map(|n| format!("`{n}`")).collect();
        let shown = match &names[..] {
            [one] => return format!("in variant {one}{}", self.place()),
            _ if names.len() > SHOWN => {
                format!("{} and {} more", names[..SHOWN].join(", "), names.len() - SHOWN)
            }
            [first @ .., last] => format!("{} and {last}", first.join(", ")),
            [] => String::new(),
        };
        format!("in {} variants {shown}{}", names.len(), self.place())
    }
}

impl Diagnostic {
    /// An error with a registered code.
    pub fn error(code: &'static str, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Error, code, message)
    }

    /// A warning with a registered code.
    pub fn warning(code: &'static str, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code, message)
    }

    /// A remark that is neither an error nor a warning (a hint about what was left out).
    pub fn remark(code: &'static str, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Note, code, message)
    }

    /// The run could not be made at all (a path that does not exist, an output that cannot be
    /// written, arguments that do not fit): `kiln` exits with 2.
    pub fn host_failure(message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Error, "K0007", message)
    }

    fn new(severity: Severity, code: &'static str, message: impl Into<String>) -> Diagnostic {
        debug_assert!(crate::codes::is_registered(code), "{code} is not in the registry (src/codes.rs)");
        Diagnostic {
            severity,
            code,
            message: message.into(),
            primary: None,
            secondary: Vec::new(),
            notes: Vec::new(),
            help: None,
            occurrence: None,
        }
    }

    /// The primary place, with what is there.
    pub fn at(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.primary = Some(Label { span, message: message.into() });
        self
    }

    /// Another place that explains it.
    pub fn label(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.secondary.push(Label { span, message: message.into() });
        self
    }

    /// Adds a note.
    pub fn note(mut self, note: impl Into<String>) -> Diagnostic {
        self.notes.push(note.into());
        self
    }

    /// Says which variant of which pass it occurs in (`variant`: its keywords) and where in it
    /// (`within`: `, fragment stage`, or nothing).
    pub fn in_variant(
        mut self,
        variant: impl Into<String>,
        pass: &PassId,
        within: impl Into<String>,
    ) -> Diagnostic {
        let occurrence =
            Occurrence { variants: vec![variant.into()], pass: pass.clone(), within: within.into() };
        self.occurrence = Some(occurrence);
        self
    }

    /// Its notes as shown: the notes, then the variants it occurs in.
    pub fn shown_notes(&self) -> Vec<String> {
        self.notes.iter().cloned().chain(self.occurrence.as_ref().map(Occurrence::note)).collect()
    }

    /// Sets the help.
    pub fn help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    /// Whether it is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// The warnings reading `file` gave: bytes that are not UTF-8, NUL bytes.
pub fn text_warnings(store: &SourceStore, file: FileId) -> Vec<Diagnostic> {
    store.text_problems(file).iter().map(|&problem| text_warning(problem, file)).collect()
}

fn text_warning(problem: TextProblem, file: FileId) -> Diagnostic {
    match problem {
        TextProblem::NotUtf8 { at, count } => {
            let places = if count == 1 { "1 place".to_string() } else { format!("{count} places") };
            Diagnostic::warning("K0001", "file is not valid UTF-8")
                .at(Span::new(file, at..at + char::REPLACEMENT_CHARACTER.len_utf8()), "first byte that is not UTF-8")
                .note(format!(
                    "bytes that are not UTF-8 ({places}) are read as U+FFFD; they are harmless in \
                     comments, and an error anywhere kiln uses them"
                ))
                .help("this looks like a legacy code page (GBK, Shift-JIS, Windows-1252): save the file as UTF-8")
        }
        TextProblem::Nul { at } => Diagnostic::warning("K0006", "NUL byte in a text file")
            .at(Span::new(file, at..at + 1), "NUL byte")
            .note("a NUL byte is never part of shader text; the file may be binary or damaged"),
    }
}

/// Whether any of the diagnostics is an error.
pub fn has_errors(diagnostics: &[Diagnostic]) -> bool {
    diagnostics.iter().any(Diagnostic::is_error)
}

/// Drops repeats of a diagnostic (same code, message and primary span), keeping the first. Shared
/// include blocks and files, and variants of one pass, would otherwise report one mistake often.
/// The variants a repeat occurs in (at the same place of the pass) join the first's, so one
/// diagnostic says every variant a cause occurs in.
pub fn dedup(diagnostics: &mut Vec<Diagnostic>) {
    type Key = (&'static str, String, Option<crate::source::Span>);
    let mut first: std::collections::HashMap<Key, usize> = std::collections::HashMap::new();
    let mut keep = Vec::with_capacity(diagnostics.len());
    for i in 0..diagnostics.len() {
        let d = &diagnostics[i];
        let key = (d.code, d.message.clone(), d.primary.as_ref().map(|l| l.span));
        let Some(&f) = first.get(&key) else {
            first.insert(key, i);
            keep.push(true);
            continue;
        };
        keep.push(false);
        let more = diagnostics[i].occurrence.clone();
        if let (Some(more), Some(into)) = (more, diagnostics[f].occurrence.as_mut())
            && more.pass == into.pass
            && let Some(within) = joined_stages(&into.within, &more.within)
        {
            into.within = within;
            for variant in more.variants {
                if !into.variants.contains(&variant) {
                    into.variants.push(variant);
                }
            }
        }
    }
    let mut keep = keep.into_iter();
    diagnostics.retain(|_| keep.next().unwrap_or(true));
}

/// Where one cause occurs in a pass, said once for two occurrences: the same place, or two stages
/// (`, vertex stage` and `, fragment stage` are `, vertex and fragment stages`: a mistake in a file
/// both stages read is both stages'). `None` for places that do not join (a kernel, the text).
fn joined_stages(first: &str, second: &str) -> Option<String> {
    if first == second {
        return Some(first.to_string());
    }
    let stages = |within: &str| -> Option<Vec<String>> {
        let names = within.strip_prefix(", ")?;
        let names = names.strip_suffix(" stage").or_else(|| names.strip_suffix(" stages"))?;
        Some(names.split(" and ").map(str::to_string).collect())
    };
    let mut all = stages(first)?;
    for stage in stages(second)? {
        if !all.contains(&stage) {
            all.push(stage);
        }
    }
    Some(match &all[..] {
        [one] => format!(", {one} stage"),
        _ => format!(", {} stages", all.join(" and ")),
    })
}

pub(crate) use kiln_manifest::closest;

/// Strict mode: every warning becomes an error (with the same code).
pub fn promote_warnings(diagnostics: &mut [Diagnostic]) {
    for d in diagnostics.iter_mut().filter(|d| d.severity == Severity::Warning) {
        d.severity = Severity::Error;
        d.notes.push("this warning is an error because the project is strict".into());
    }
}

/// Diagnostics of one code in one file shown before the rest are summed up in a line: a file that
/// repeats one mistake ten thousand times gets ten, and a count.
const SHOWN_PER_CODE_AND_FILE: usize = 10;

/// A source line longer than this is not quoted: its place is said instead (a 60 KB line quoted
/// by each of 10,000 warnings was a gigabyte of output).
const LONGEST_QUOTED_LINE: usize = 1_000;

/// `diagnostics` as they are shown: after [`SHOWN_PER_CODE_AND_FILE`] of one code in one file,
/// the rest of them become one line that counts them, where the last shown one was.
fn summarized(diagnostics: &[Diagnostic]) -> Vec<std::borrow::Cow<'_, Diagnostic>> {
    use std::borrow::Cow;
    use std::collections::HashMap;
    let group = |d: &Diagnostic| (d.code, d.primary.as_ref().map(|p| p.span.file));
    let mut totals: HashMap<_, usize> = HashMap::new();
    for d in diagnostics {
        *totals.entry(group(d)).or_default() += 1;
    }
    let mut seen: HashMap<_, usize> = HashMap::new();
    let mut shown = Vec::with_capacity(diagnostics.len().min(1024));
    for d in diagnostics {
        let key = group(d);
        let count = seen.entry(key).or_default();
        *count += 1;
        if *count <= SHOWN_PER_CODE_AND_FILE {
            shown.push(Cow::Borrowed(d));
        }
        let total = totals[&key];
        if *count == SHOWN_PER_CODE_AND_FILE + 1 {
            let mut more = Diagnostic::remark(
                d.code,
                format!("{} more like the last, not shown", total - SHOWN_PER_CODE_AND_FILE),
            );
            more.severity = d.severity;
            shown.push(Cow::Owned(more));
        }
    }
    shown
}

/// `text` as a diagnostic shows it: every control character (a terminal's escape, a carriage
/// return, a line break where `breaks` is false) and bidirectional override written as `\u{..}`,
/// so that a name from any input (a shader's, a usage log's, a trace's) can neither send a terminal
/// a code nor forge a line of a log. The one place every message, label, note and help passes.
pub fn shown_text(text: &str, breaks: bool) -> std::borrow::Cow<'_, str> {
    let hidden = |c: char| {
        (c.is_control() && !(breaks && c == '\n'))
            || ('\u{202a}'..='\u{202e}').contains(&c)
            || ('\u{2066}'..='\u{2069}').contains(&c)
    };
    if !text.chars().any(hidden) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut shown = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if hidden(c) {
            shown.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            shown.push(c);
        }
    }
    std::borrow::Cow::Owned(shown)
}

fn to_codespan(store: &SourceStore, d: &Diagnostic) -> cs::Diagnostic<crate::source::FileId> {
    let severity = match d.severity {
        Severity::Error => cs::Severity::Error,
        Severity::Warning => cs::Severity::Warning,
        Severity::Note => cs::Severity::Note,
    };
    let mut labels = Vec::new();
    let mut places = Vec::new();
    let quoted = |label: &Label| {
        let text = store.text(label.span.file);
        let start = (label.span.start as usize).min(text.len());
        // A span off a character boundary is the reporting stage's bug: codespan says so.
        let (Some(before), Some(after)) = (text.get(..start), text.get(start..)) else { return true };
        let line_start = before.rfind('\n').map_or(0, |at| at + 1);
        let line_end = after.find('\n').map_or(text.len(), |at| start + at);
        line_end - line_start <= LONGEST_QUOTED_LINE
    };
    for (label, primary) in d.primary.iter().map(|p| (p, true)).chain(d.secondary.iter().map(|l| (l, false)))
    {
        if quoted(label) {
            let range = label.span.range();
            let made = if primary {
                cs::Label::primary(label.span.file, range)
            } else {
                cs::Label::secondary(label.span.file, range)
            };
            labels.push(made.with_message(shown_text(&label.message, false)));
        } else {
            let at = store.line_col(label.span.file, label.span.start as usize);
            places.push(format!(
                "at {}:{}:{}: {} (the line is over {LONGEST_QUOTED_LINE} bytes: not quoted)",
                store.display_name(label.span.file),
                at.line,
                at.column,
                shown_text(&label.message, false)
            ));
        }
    }
    let mut notes: Vec<String> = places;
    notes.extend(d.shown_notes().iter().map(|n| format!("note: {}", shown_text(n, true))));
    if let Some(h) = &d.help {
        notes.push(format!("help: {}", shown_text(h, true)));
    }
    cs::Diagnostic::new(severity)
        .with_code(d.code)
        .with_message(shown_text(&d.message, false))
        .with_labels(labels)
        .with_notes(notes)
}

/// Renders diagnostics as text, without colour (for files, pipes and golden tests).
pub fn render_plain(store: &SourceStore, diagnostics: &[Diagnostic]) -> String {
    let config = term::Config::default();
    let mut out = String::new();
    for d in summarized(diagnostics) {
        // A span pointing outside its file is a bug in the reporting stage; show the message anyway.
        match term::emit_into_string(&config, store, &to_codespan(store, &d)) {
            Ok(text) => out.push_str(&text),
            Err(_) => {
                out.push_str(&format!("{:?}[{}]: {}\n", d.severity, d.code, shown_text(&d.message, false)))
            }
        }
    }
    out
}

/// Writes diagnostics to a terminal-like stream, coloured when `color` is true.
pub fn render_to(
    store: &SourceStore,
    diagnostics: &[Diagnostic],
    color: bool,
    stream: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    if !color {
        return stream.write_all(render_plain(store, diagnostics).as_bytes());
    }
    let config = term::Config::default();
    let styles = term::Styles::default();
    let mut buffer = term::termcolor::Buffer::ansi();
    for d in summarized(diagnostics) {
        let mut writer = term::StylesWriter::new(&mut buffer, &styles);
        if term::emit_to_write_style(&mut writer, &config, store, &to_codespan(store, &d)).is_err() {
            return stream.write_all(render_plain(store, diagnostics).as_bytes());
        }
    }
    stream.write_all(buffer.as_slice())
}

/// A position for JSON output: file name, 1-based line and column, and byte offsets.
#[derive(Serialize)]
pub struct JsonLocation {
    /// The file's name as shown.
    pub file: String,
    /// 1-based line of the start.
    pub line: usize,
    /// 1-based column of the start, in characters.
    pub column: usize,
    /// 1-based line of the end.
    pub end_line: usize,
    /// 1-based column of the end.
    pub end_column: usize,
    /// Byte offset of the start.
    pub start: u32,
    /// Byte offset of the end.
    pub end: u32,
}

/// A label in JSON.
#[derive(Serialize)]
pub struct JsonLabel {
    /// What is there.
    pub message: String,
    /// Where.
    #[serde(flatten)]
    pub location: JsonLocation,
}

/// A diagnostic as JSON: its own schema, stable across releases.
#[derive(Serialize)]
pub struct JsonDiagnostic {
    /// How serious it is.
    pub severity: Severity,
    /// Its stable code.
    pub code: &'static str,
    /// What is wrong.
    pub message: String,
    /// The primary place.
    pub location: Option<JsonLabel>,
    /// Other places.
    pub labels: Vec<JsonLabel>,
    /// Further facts.
    pub notes: Vec<String>,
    /// What to do about it.
    pub help: Option<String>,
}

fn json_label(store: &SourceStore, label: &Label) -> JsonLabel {
    let start = store.line_col(label.span.file, label.span.start as usize);
    let end = store.line_col(label.span.file, label.span.end as usize);
    JsonLabel {
        message: label.message.clone(),
        location: JsonLocation {
            file: store.name(label.span.file).to_string(),
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
            start: label.span.start,
            end: label.span.end,
        },
    }
}

/// Converts diagnostics to their JSON form.
pub fn to_json(store: &SourceStore, diagnostics: &[Diagnostic]) -> Vec<JsonDiagnostic> {
    diagnostics
        .iter()
        .map(|d| JsonDiagnostic {
            severity: d.severity,
            code: d.code,
            message: d.message.clone(),
            location: d.primary.as_ref().map(|l| json_label(store, l)),
            labels: d.secondary.iter().map(|l| json_label(store, l)).collect(),
            notes: d.shown_notes(),
            help: d.help.clone(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_from_any_input_can_neither_forge_a_line_nor_send_a_terminal_a_code() {
        let mut store = SourceStore::new();
        let log = store.add("usage.log", "Hostile\u{1b}[2J\nerror[K0001]: forged 0\n");
        let name = "Hostile\u{1b}[2J\nerror[K0001]: forged\u{202e}";
        let diagnostic = Diagnostic::error("K0531", format!("no shader named `{name}` in the project"))
            .at(Span::new(log, 0..7), format!("`{name}` named here"))
            .note(format!("a trace names `{name}`"))
            .help(format!("rename `{name}`"));
        let shown = render_plain(&store, &[diagnostic]);
        assert!(!shown.contains(['\u{1b}', '\u{202e}', '\r']), "{shown:?}");
        assert!(!shown.lines().any(|line| line.starts_with("error[K0001]")), "{shown}");
        assert!(shown.contains("Hostile\\u{1b}[2J\\u{a}error[K0001]: forged"), "{shown}");
    }

    fn in_variant(variant: &str, stage: &str) -> Diagnostic {
        let pass = PassId { shader: "S".into(), index: 0 };
        Diagnostic::error("K0401", "the same mistake").in_variant(variant, &pass, format!(", {stage} stage"))
    }

    #[test]
    fn repeats_become_one_diagnostic_naming_every_variant_and_stage() {
        let mut found =
            vec![in_variant("A", "fragment"), in_variant("B", "fragment"), in_variant("A", "vertex")];
        dedup(&mut found);
        assert_eq!(found.len(), 1, "one cause");
        assert_eq!(
            found[0].shown_notes(),
            ["in 2 variants `A` and `B` of `S` pass 0, fragment and vertex stages"],
            "a cause both stages meet is said of both"
        );
        let mut many: Vec<Diagnostic> = (0..9).map(|i| in_variant(&format!("V{i}"), "fragment")).collect();
        dedup(&mut many);
        assert_eq!(
            many[0].shown_notes(),
            ["in 9 variants `V0`, `V1`, `V2`, `V3`, `V4`, `V5` and 3 more of `S` pass 0, fragment stage"]
        );
    }
}
