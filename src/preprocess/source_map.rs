//! Where every byte of preprocessed output came from: a sorted list of output offsets, each the
//! start of a run copied from one place in one file (or of one macro expansion), found by binary
//! search. Includes form a tree, so each run also knows the chain of `#include`s that brought it.

use crate::source::{FileId, SourceStore, Span};
use std::ops::Range;

/// The include chain root: text of the program blocks themselves.
pub(crate) const ROOT: u32 = 0;

#[derive(Debug, Clone, Copy)]
struct Segment {
    /// Output offset where this run starts; it ends where the next one starts.
    out: u32,
    file: FileId,
    /// File offset of the run's first byte (for an expansion, of the macro's name).
    src: u32,
    /// For a macro expansion, the length of the name it replaced: every output byte of the
    /// expansion maps to that whole name. Zero for copied text.
    expansion: u32,
    inclusion: u32,
    /// For a macro expansion, 1 + the index of the macro's definition in `definitions` (0: none).
    definition: u32,
}

#[derive(Debug, Clone, Copy)]
struct Inclusion {
    /// The quoted name of the `#include` that opened this file (`None` for the root).
    directive: Option<Span>,
    parent: u32,
}

/// Maps output offsets of one preprocessed text back to original files.
#[derive(Debug, Clone)]
pub struct SourceMap {
    segments: Vec<Segment>,
    inclusions: Vec<Inclusion>,
    /// The `#define`s of expanded macros, once each.
    definitions: Vec<Span>,
    len: u32,
}

/// Where an output range came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Origin {
    /// The expansion's place in its file.
    pub span: Span,
    /// Identifies the include chain that brought the text; see [`SourceMap::include_chain`].
    pub inclusion: u32,
    /// For text a macro expansion wrote, the name in the macro's `#define`.
    pub definition: Option<Span>,
}

impl Default for SourceMap {
    fn default() -> SourceMap {
        SourceMap {
            segments: Vec::new(),
            inclusions: vec![Inclusion { directive: None, parent: ROOT }],
            definitions: Vec::new(),
            len: 0,
        }
    }
}

impl SourceMap {
    pub(crate) fn copied(&mut self, out: usize, file: FileId, src: usize, inclusion: u32) {
        if let Some(last) = self.segments.last()
            && last.expansion == 0
            && last.file == file
            && last.inclusion == inclusion
            && last.src as usize + (out - last.out as usize) == src
        {
            return;
        }
        self.push(Segment { out: out as u32, file, src: src as u32, expansion: 0, inclusion, definition: 0 });
    }

    /// Output from `out` on is a macro expansion written for the invocation at `name` (the name,
    /// and a function-like macro's arguments), of the macro defined at `definition`.
    pub(crate) fn expanded(&mut self, out: usize, name: Span, definition: Option<Span>, inclusion: u32) {
        let expansion = (name.end - name.start).max(1);
        let definition = match definition {
            None => 0,
            Some(span) => match self.definitions.iter().rposition(|d| *d == span) {
                Some(i) => i as u32 + 1,
                None => {
                    self.definitions.push(span);
                    self.definitions.len() as u32
                }
            },
        };
        let segment =
            Segment { out: out as u32, file: name.file, src: name.start, expansion, inclusion, definition };
        self.push(segment);
    }

    fn push(&mut self, segment: Segment) {
        // A run that produced no bytes is replaced by the one that follows it.
        if self.segments.last().is_some_and(|last| last.out == segment.out) {
            self.segments.pop();
        }
        self.segments.push(segment);
    }

    /// Opens a file included by the directive at `directive` from inside `parent`.
    pub(crate) fn enter(&mut self, directive: Span, parent: u32) -> u32 {
        self.inclusions.push(Inclusion { directive: Some(directive), parent });
        (self.inclusions.len() - 1) as u32
    }

    pub(crate) fn finish(&mut self, len: usize) {
        self.len = len as u32;
    }

    /// The map of the text made of `kept` ranges of this map's text, each followed by one line
    /// break (`compile::reach::joined`): every kept byte maps where it did.
    pub fn cut(&self, kept: &[Range<usize>]) -> SourceMap {
        let mut cut = SourceMap {
            segments: Vec::new(),
            inclusions: self.inclusions.clone(),
            definitions: self.definitions.clone(),
            len: 0,
        };
        let mut out = 0u32;
        for range in kept {
            self.copy_runs(&mut cut, out, range.start as u32, range.end as u32);
            out += (range.end - range.start) as u32 + 1;
        }
        cut.len = out;
        cut
    }

    /// The map of the text made from this map's text by `edits`: each an old range and the length
    /// of what replaces it, in order and apart. Kept bytes map where they did; each replacement
    /// maps, every byte of it, to where its old range starts (the whole old range, where that is
    /// one run of one file), as a macro's expansion maps to its invocation.
    pub fn edited(&self, edits: &[(Range<usize>, usize)]) -> SourceMap {
        let mut edited = SourceMap {
            segments: Vec::new(),
            inclusions: self.inclusions.clone(),
            definitions: self.definitions.clone(),
            len: 0,
        };
        let (mut out, mut kept_from) = (0u32, 0u32);
        for (range, written) in edits {
            let (start, end) = (range.start as u32, range.end as u32);
            self.copy_runs(&mut edited, out, kept_from, start);
            out += start.saturating_sub(kept_from);
            let at = start.min(self.len.saturating_sub(1));
            let index = self.segments.partition_point(|s| s.out <= at).saturating_sub(1);
            if let Some(s) = self.segments.get(index) {
                let mut segment = *s;
                if s.expansion == 0 {
                    segment.src += at - s.out;
                    // The old range, where it lies in this run; else its first byte.
                    let run_end = self.segments.get(index + 1).map_or(self.len, |next| next.out);
                    segment.expansion = if end <= run_end { (end - at).max(1) } else { 1 };
                }
                segment.out = out;
                if *written > 0 {
                    edited.push(segment);
                }
            }
            out += *written as u32;
            kept_from = end;
        }
        self.copy_runs(&mut edited, out, kept_from, self.len);
        edited.len = out + self.len.saturating_sub(kept_from);
        edited
    }

    /// Copies the runs of this map's output `start..end` into `into`, as output from `out` on:
    /// every byte maps where it did.
    fn copy_runs(&self, into: &mut SourceMap, out: u32, start: u32, end: u32) {
        if start >= end {
            return;
        }
        let first = self.segments.partition_point(|s| s.out <= start).saturating_sub(1);
        for s in self.segments[first..].iter().take_while(|s| s.out < end) {
            let mut segment = *s;
            if s.out <= start {
                // The run began before the range: it now begins at the range's first byte.
                if s.expansion == 0 {
                    segment.src += start - s.out;
                }
                segment.out = out;
            } else {
                segment.out = out + (s.out - start);
            }
            into.push(segment);
        }
    }

    /// The origin of one output byte. Offsets at or past the end map to the end of the last run.
    pub fn locate(&self, offset: usize) -> Option<Origin> {
        let offset = offset.min(self.len as usize) as u32;
        let index = self.segments.partition_point(|s| s.out <= offset).checked_sub(1)?;
        let s = self.segments[index];
        let (start, end) = if s.expansion > 0 {
            (s.src, s.src + s.expansion)
        } else {
            let at = s.src + (offset - s.out);
            (at, at + u32::from(offset < self.len))
        };
        let definition = s.definition.checked_sub(1).and_then(|i| self.definitions.get(i as usize)).copied();
        Some(Origin { span: Span { file: s.file, start, end }, inclusion: s.inclusion, definition })
    }

    /// The output a macro invocation at byte `offset` of `file` expanded to (its first expansion
    /// there), as an output range.
    pub fn expansion_at(&self, file: FileId, offset: usize) -> Option<Range<usize>> {
        let offset = offset as u32;
        let calls =
            |s: &Segment| s.expansion > 0 && s.file == file && (s.src..s.src + s.expansion).contains(&offset);
        let first = self.segments.iter().position(calls)?;
        // Macros its text expands in turn map to the same invocation: the expansion runs on
        // until a segment from elsewhere.
        let call = |s: &Segment| (s.file, s.src, s.expansion);
        let this = call(&self.segments[first]);
        let end =
            self.segments[first + 1..].iter().find(|s| call(s) != this).map_or(self.len, |next| next.out);
        Some(self.segments[first].out as usize..end as usize)
    }

    /// The origin of an output range: the original span from its first to its last byte when both
    /// lie in the same run of one file, otherwise just where it starts.
    pub fn map_range(&self, range: Range<usize>) -> Option<Origin> {
        let start = self.locate(range.start)?;
        if range.end <= range.start + 1 {
            return Some(start);
        }
        let last = self.locate(range.end - 1)?;
        if last.span.file == start.span.file
            && last.inclusion == start.inclusion
            && last.span.end >= start.span.start
        {
            return Some(Origin { span: start.span.to(last.span), ..start });
        }
        Some(start)
    }

    /// The `#include` names that brought an inclusion in, innermost first.
    pub fn include_chain(&self, inclusion: u32) -> impl Iterator<Item = Span> + '_ {
        let mut at = inclusion;
        std::iter::from_fn(move || {
            let step = self.inclusions.get(at as usize)?;
            let directive = step.directive?;
            at = step.parent;
            Some(directive)
        })
    }

    /// "included from FILE:LINE:COL" notes for a diagnostic, innermost first. Past ten levels the
    /// middle of the chain is summarised.
    pub fn included_from_notes(&self, store: &SourceStore, inclusion: u32) -> Vec<String> {
        let note = |span: Span| {
            let at = store.line_col(span.file, span.start as usize);
            format!("included from {}:{}:{}", store.name(span.file), at.line, at.column)
        };
        let chain: Vec<Span> = self.include_chain(inclusion).collect();
        if chain.len() <= 10 {
            return chain.into_iter().map(note).collect();
        }
        let mut notes: Vec<String> = chain[..5].iter().map(|&s| note(s)).collect();
        notes.push(format!("... {} more levels of includes ...", chain.len() - 9));
        notes.extend(chain[chain.len() - 4..].iter().map(|&s| note(s)));
        notes
    }

    /// One line per run of output lines that come from consecutive lines of one file:
    /// `12-40 <- Common.wgsl:3-31`. Golden files show this beside the preprocessed text.
    pub fn describe_lines(&self, store: &SourceStore, text: &str) -> String {
        struct Run {
            out: (usize, usize),
            file: FileId,
            src: (usize, usize),
            expanded: bool,
        }
        let mut runs: Vec<Run> = Vec::new();
        let mut offset = 0;
        for (index, line) in text.split_inclusive('\n').enumerate() {
            let out_line = index + 1;
            if let Some(origin) = self.locate(offset) {
                let src_line = store.line_col(origin.span.file, origin.span.start as usize).line;
                let expanded = self.is_expansion(offset);
                match runs.last_mut() {
                    Some(run)
                        if run.file == origin.span.file
                            && run.src.1 + 1 == src_line
                            && run.out.1 + 1 == out_line
                            && !expanded
                            && !run.expanded =>
                    {
                        run.out.1 = out_line;
                        run.src.1 = src_line;
                    }
                    _ => runs.push(Run {
                        out: (out_line, out_line),
                        file: origin.span.file,
                        src: (src_line, src_line),
                        expanded,
                    }),
                }
            }
            offset += line.len();
        }
        let range = |(a, b): (usize, usize)| if a == b { a.to_string() } else { format!("{a}-{b}") };
        runs.iter()
            .map(|r| {
                let how = if r.expanded { " (macro)" } else { "" };
                format!("{} <- {}:{}{how}\n", range(r.out), store.name(r.file), range(r.src))
            })
            .collect()
    }

    fn is_expansion(&self, offset: usize) -> bool {
        let offset = offset as u32;
        self.segments
            .partition_point(|s| s.out <= offset)
            .checked_sub(1)
            .is_some_and(|i| self.segments[i].expansion > 0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_edited_text_maps_kept_bytes_where_they_were_and_written_ones_to_what_they_replace() {
        let mut store = SourceStore::new();
        let file = store.add("a.hlsl", "sampler2D _T; float4 f() { return tex2D(_T, uv); }");
        let text = store.text(file).to_string();
        let mut map = SourceMap::default();
        map.copied(0, file, 0, ROOT);
        map.finish(text.len());
        // `sampler2D` becomes `Texture2D`, a state is inserted after the `;`, `tex2D` renamed.
        let call = text.find("tex2D").expect("call");
        let edits =
            [(0..9, "Texture2D".len()), (13..13, " SamplerState sampler_T;".len()), (call..call + 5, 11)];
        let edited = map.edited(&edits);
        let origin = |at: usize| edited.locate(at).expect("maps").span;
        // `_T` after the type: kept, at its own place.
        assert_eq!((origin(10).start, origin(10).end), (10, 11));
        // The inserted state maps to the byte it is inserted before; the renamed call to `tex2D`.
        let inserted = 9 + 4;
        assert_eq!(origin(inserted).start, 13);
        let renamed = call + 24;
        assert_eq!((origin(renamed).start, origin(renamed).end), (call as u32, call as u32 + 5));
        assert_eq!(edited.len as usize, text.len() + 24 + (11 - 5));
    }
}
