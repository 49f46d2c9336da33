//! The no-op check: what a build's outcome depends on (its inputs key), and the record of the last
//! clean build, compared before anything is parsed.

use super::{BuildResult, BuildSummary, COMPILER_REVISION, NAGA_VERSION, Writes};
use crate::config::Settings;
use crate::diagnostics::{Diagnostic, Label, Severity};
use crate::manifest::SCHEMA_VERSION;
use crate::preprocess::LIBRARY_PREFIX;
use crate::source::Span;
use crate::source::{FileId, SourceStore, relative_to};
use crate::store::{Cache, RecordedFinding, RecordedLabel};
use rayon::prelude::*;
use std::time::Instant;

/// A file's name as the build records it: relative to the project folder for files read from
/// disk, so that nothing recorded depends on where the project sits.
pub(super) fn recorded_name(store: &SourceStore, file: FileId, root: &std::path::Path) -> String {
    match store.path(file) {
        Some(path) => relative_to(path, root),
        None => store.name(file).to_string(),
    }
}

/// The files of the store read from disk, in the order read.
pub(super) fn disk_files(store: &SourceStore) -> impl Iterator<Item = FileId> + '_ {
    store.ids().filter(|&f| store.path(f).is_some())
}

/// Raised when what a build writes changes shape (files added), so that an earlier build's
/// record no longer passes for a no-op. (A new manifest schema does the same.)
const OUTPUT_FORMAT: u32 = 3;

/// Everything a build's outcome depends on: the settings that change what it writes, the texts given in memory (global
/// keywords from a build script; the bundled library by its digest), and every file
/// read from disk (shaders, includes, materials, variant logs, the project file) by its name
/// relative to the project, in the order read: `read`, as [`disk_names`] gives them (a caller
/// that has them already need not name 50,000 files twice).
pub(super) fn inputs_key(store: &SourceStore, settings: &Settings, read: &[String]) -> String {
    key_with_library(store, settings, read, crate::shaderlib::digest())
}

fn key_with_library(store: &SourceStore, settings: &Settings, read: &[String], library: &str) -> String {
    // Each file hashed on its own (in parallel: a project reads tens of thousands), then their
    // hashes in order.
    // Texts kiln made itself (the bundled library, Unity's `CGPROGRAM` prelude) follow from what
    // is hashed here; a build makes them after the no-op check has looked.
    let made_by_kiln = |f: FileId| {
        store.name(f).starts_with(LIBRARY_PREFIX) || store.name(f) == crate::catalog::CG_PRELUDE_NAME
    };
    let in_memory: Vec<FileId> =
        (store.ids()).filter(|&f| store.path(f).is_none() && !made_by_kiln(f)).collect();
    let on_disk: Vec<FileId> = disk_files(store).collect();
    debug_assert_eq!(read.len(), on_disk.len(), "a name for each file read from disk");
    let file_hash = |name: &str, file: Option<FileId>| {
        let bytes = file.map_or(&[][..], |f| store.text(f).as_bytes());
        let mut hasher = blake3::Hasher::new();
        hasher.update(&(name.len() as u64).to_le_bytes());
        hasher.update(name.as_bytes());
        hasher.update(&(bytes.len() as u64).to_le_bytes());
        hasher.update(bytes);
        hasher.finalize()
    };
    let files = (in_memory.par_iter().map(|&f| file_hash(store.name(f), Some(f))))
        .chain(rayon::iter::once(file_hash("<read from disk>", None)))
        .chain(read.par_iter().zip(&on_disk).map(|(name, f)| file_hash(name, Some(*f))));
    let hashes: Vec<blake3::Hash> = files.collect();
    let mut hasher = blake3::Hasher::new();
    for hash in &hashes {
        hasher.update(hash.as_bytes());
    }
    let settings = format!(
        "{:?}{:?}{}{} library {library} revision {COMPILER_REVISION} {NAGA_VERSION} output {OUTPUT_FORMAT} manifest {SCHEMA_VERSION}",
        settings.backends,
        settings.unused_shaders,
        settings.pretty_manifest,
        env!("CARGO_PKG_VERSION")
    );
    hasher.update(settings.as_bytes());
    hasher.finalize().to_hex()[..32].to_string()
}

/// The recorded names ([`recorded_name`]) of the store's files read from disk, in the order read.
pub(super) fn disk_names(store: &SourceStore, settings: &Settings) -> Vec<String> {
    let files: Vec<FileId> = disk_files(store).collect();
    files.par_iter().map(|&f| recorded_name(store, f, &settings.root)).collect()
}

/// The no-op check, made before the catalogue is built: `store` holds the files found so far
/// (the project file, shaders, materials, variant logs). When they are exactly the files the last
/// clean build was given, the rest it read (includes, read again here into `store`) are
/// unchanged, nothing appeared where it looked in vain,
/// and every file it wrote is in place, nothing needs doing: no parsing, no preprocessing, no
/// naga, and the manifest is not read. A build that `writes` clears what a build stopped since
/// left.
pub fn unchanged(store: &mut SourceStore, settings: &Settings, writes: Writes) -> Option<BuildResult> {
    let started = Instant::now();
    let cache = Cache::new(&settings.output, false);
    let recorded = cache.recorded()?;
    let inputs = Inputs { given: recorded.given, read: &recorded.read, absent: &recorded.absent };
    if !same_inputs(store, settings, &inputs, &recorded.key) || !cache.files_in_place(&recorded) {
        return None;
    }
    // What the build reported is said again, each place verified against the file it names.
    let diagnostics = replayed(store, &recorded.findings)?;
    if writes.output() {
        // What a build stopped since left (its packs, its temporaries) goes, as after any build.
        Cache::new(&settings.output, true).sweep(&recorded.files);
    }
    let summary = BuildSummary {
        shaders: recorded.shaders,
        passes: recorded.passes,
        variants: recorded.variants,
        modules: recorded.modules,
        reused: recorded.modules,
        elapsed: started.elapsed(),
        ..BuildSummary::default()
    };
    Some(BuildResult { summary, manifest: None, diagnostics, output: settings.output.clone() })
}

/// What a record keeps of a build's `diagnostics`, so that a no-op says them again: `None`
/// when any cannot be said again from the files read alone (an error; a finding with no place,
/// such as a remote cache out of reach, which is about this run; a place in a text kiln made),
/// and then the build records no no-op.
pub(super) fn recordable<'a>(
    store: &SourceStore,
    diagnostics: impl IntoIterator<Item = &'a Diagnostic>,
) -> Option<Vec<RecordedFinding>> {
    let index: std::collections::HashMap<FileId, usize> =
        disk_files(store).enumerate().map(|(at, file)| (file, at)).collect();
    let label = |label: &Label| {
        Some(RecordedLabel {
            file: *index.get(&label.span.file)?,
            start: label.span.start,
            end: label.span.end,
            message: label.message.clone(),
        })
    };
    let finding = |d: &Diagnostic| {
        if d.severity == Severity::Error {
            return None;
        }
        let labels = std::iter::once(d.primary.as_ref()?).chain(&d.secondary).map(label);
        Some(RecordedFinding {
            severity: d.severity,
            code: d.code.to_string(),
            message: d.message.clone(),
            labels: labels.collect::<Option<_>>()?,
            notes: d.notes.clone(),
            help: d.help.clone(),
            occurrence: d.occurrence.clone(),
        })
    };
    diagnostics.into_iter().map(finding).collect()
}

/// The findings a record kept, as diagnostics on the files `store` read: `None` (a full build)
/// unless every one is a warning or remark with a registered code and every place is whole
/// characters inside a file read.
fn replayed(store: &SourceStore, findings: &[RecordedFinding]) -> Option<Vec<Diagnostic>> {
    let files: Vec<FileId> = disk_files(store).collect();
    let label = |label: &RecordedLabel| {
        let file = *files.get(label.file)?;
        let text = store.text(file);
        let (start, end) = (label.start as usize, label.end as usize);
        (start <= end && text.get(start..end).is_some())
            .then(|| Label { span: Span::new(file, start..end), message: label.message.clone() })
    };
    let diagnostic = |finding: &RecordedFinding| {
        let code = crate::codes::registered(&finding.code)?;
        let (primary, secondary) = finding.labels.split_first()?;
        let mut d = match finding.severity {
            Severity::Warning => Diagnostic::warning(code, finding.message.clone()),
            Severity::Note => Diagnostic::remark(code, finding.message.clone()),
            Severity::Error => return None,
        };
        d.primary = Some(label(primary)?);
        d.secondary = secondary.iter().map(label).collect::<Option<_>>()?;
        d.notes = finding.notes.clone();
        d.help = finding.help.clone();
        d.occurrence = finding.occurrence.clone();
        Some(d)
    };
    findings.iter().map(diagnostic).collect()
}

/// What an earlier build read: how many files it was given, every file it read (relative to the
/// project, in order) and every path it looked for in vain.
pub(super) struct Inputs<'a> {
    pub given: usize,
    pub read: &'a [String],
    pub absent: &'a [String],
}

/// Whether the project is still what an earlier build read (its inputs key `key`): `store` holds
/// the files found so far (the project file, shaders, materials, variant logs), which must be
/// exactly the files that build was given; nothing may have appeared where it looked in vain;
/// and the rest it read (includes) are loaded into `store` here and must hash alike.
pub(super) fn same_inputs(store: &mut SourceStore, settings: &Settings, inputs: &Inputs, key: &str) -> bool {
    let mut found = disk_names(store, settings);
    if found.len() != inputs.given || inputs.read.get(..found.len()) != Some(&found[..]) {
        return false;
    }
    if inputs.absent.par_iter().any(|path| std::fs::symlink_metadata(settings.root.join(path)).is_ok()) {
        return false;
    }
    // The includes are read through the store, as a build reads them, so that what it reports
    // as read (a build script's `rerun-if-changed`) is the same whether it compiled or not.
    for name in &inputs.read[found.len()..] {
        let path = settings.root.join(name);
        let Some(canonical) = store.canonical_file(&path) else { return false };
        if store.load_once(&path, canonical).is_err() {
            return false;
        }
    }
    let includes: Vec<FileId> = disk_files(store).skip(found.len()).collect();
    found.extend(includes.iter().map(|&f| recorded_name(store, f, &settings.root)));
    inputs_key(store, settings, &found) == key
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_findings_placed_in_files_read_are_recorded_and_they_come_back_as_they_were() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("a.shader");
        std::fs::write(&path, "Shader \"A\" {}\n").expect("write");
        let mut store = SourceStore::new();
        let made = store.add("<in memory>", "text");
        let read = store.load(&path).expect("read");
        let warning = Diagnostic::warning("K0321", "`X` is tested but never declared or defined")
            .at(Span::new(read, 0..6), "always off in this pass")
            .label(Span::new(read, 8..9), "and here")
            .note("a note")
            .help("a help");
        let recorded = recordable(&store, [&warning]).expect("recordable");
        assert_eq!(recorded[0].labels[0].file, 0, "by its index among the files read from disk");
        assert_eq!(replayed(&store, &recorded), Some(vec![warning.clone()]));
        let unplaced = Diagnostic::warning("K0620", "the remote cache could not be used");
        let in_memory = Diagnostic::warning("K0321", "m").at(Span::new(made, 0..4), "here");
        let error = Diagnostic::error("K0321", "e").at(Span::new(read, 0..6), "here");
        for finding in [unplaced, in_memory, error] {
            assert!(recordable(&store, [&warning, &finding]).is_none(), "{finding:?}");
        }
    }

    #[test]
    fn the_inputs_key_follows_the_bundled_library() {
        let mut store = SourceStore::new();
        store.add("given.shader", "Shader \"A\" {}");
        let settings = Settings::one_off(".".into(), "out".into());
        let read = disk_names(&store, &settings);
        let key = inputs_key(&store, &settings, &read);
        assert_eq!(key, key_with_library(&store, &settings, &read, crate::shaderlib::digest()));
        assert_ne!(key, key_with_library(&store, &settings, &read, "0123456789abcdef"), "an edited library");
    }
}
