//! naga: parse and validate preprocessed WGSL, with every naga error re-mapped through the
//! preprocessor's source map to its original file:line:col. (Binding assignment, targets,
//! backends and caching grow here with the compile work.)

use crate::diagnostics::Diagnostic;
use crate::preprocess::{Origin, Preprocessed};
use crate::source::SourceStore;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use std::error::Error as _;

/// A parsed and validated module.
pub struct Checked {
    pub module: naga::Module,
    pub info: ModuleInfo,
}

/// Parses and validates one preprocessed text; naga stops at its first error. Bindings are not checked yet: resources without
/// `@group`/`@binding` get them later, by update frequency.
pub fn check(preprocessed: &Preprocessed, store: &SourceStore) -> Result<Checked, Vec<Diagnostic>> {
    let mapper = Mapper { preprocessed, store };
    let module = naga::front::wgsl::parse_str(&preprocessed.text).map_err(|error| {
        let labels = error.labels().map(|(span, message)| (span, message.to_string()));
        let mut diagnostic = mapper.diagnostic("K0401", error.message().to_string(), labels.collect());
        diagnostic.notes.extend(error.notes().map(str::to_string));
        vec![diagnostic]
    })?;
    let flags = ValidationFlags::all() - ValidationFlags::BINDINGS;
    let info = Validator::new(flags, Capabilities::all()).validate(&module).map_err(|error| {
        let mut message = error.as_inner().to_string();
        let mut source = error.as_inner().source();
        while let Some(inner) = source {
            message.push_str(": ");
            message.push_str(&inner.to_string());
            source = inner.source();
        }
        // naga lists the enclosing function too; the narrowest span is where the mistake is.
        let mut labels: Vec<(naga::Span, String)> =
            error.spans().map(|(span, text)| (*span, text.clone())).collect();
        labels.sort_by_key(|(span, _)| span.to_range().map_or(usize::MAX, |r| r.len()));
        vec![mapper.diagnostic("K0402", message, labels)]
    })?;
    Ok(Checked { module, info })
}

struct Mapper<'a> {
    preprocessed: &'a Preprocessed,
    store: &'a SourceStore,
}

impl Mapper<'_> {
    fn origin(&self, span: naga::Span) -> Option<Origin> {
        self.preprocessed.source_map.map_range(span.to_range()?)
    }

    /// The first label that maps is primary; its include chain becomes notes.
    fn diagnostic(
        &self,
        code: &'static str,
        message: String,
        labels: Vec<(naga::Span, String)>,
    ) -> Diagnostic {
        let mut diagnostic = Diagnostic::error(code, lowercase_first(&message));
        let mut primary_inclusion = None;
        for (span, text) in labels {
            let Some(origin) = self.origin(span) else { continue };
            if primary_inclusion.is_none() {
                primary_inclusion = Some(origin.inclusion);
                diagnostic = diagnostic.at(origin.span, text);
            } else {
                diagnostic = diagnostic.label(origin.span, text);
            }
        }
        if let Some(inclusion) = primary_inclusion {
            diagnostic.notes.extend(self.preprocessed.source_map.included_from_notes(self.store, inclusion));
        }
        diagnostic
    }
}

/// naga capitalises some messages; ours start lowercase.
fn lowercase_first(message: &str) -> String {
    let mut chars = message.chars();
    match chars.next() {
        Some(first) if chars.clone().next().is_some_and(char::is_lowercase) => {
            first.to_lowercase().chain(chars).collect()
        }
        _ => message.to_string(),
    }
}
