//! Include resolution: finds every file a program can include (in any branch, before variants
//! are known), scans each once, and records where each `#include` points or why it fails. Files
//! come in only through the [`SourceStore`], which records them for `rerun-if-changed`.

use super::error::PreprocessError;
use super::pass::DynamicKeyword;
use super::scan::{self, Item, Target, Unit};
use crate::diagnostics::Diagnostic;
use crate::source::{FileId, LinksOut, SourceStore, Span, normalize_lexically};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Where includes may come from.
#[derive(Debug, Clone)]
pub struct IncludeConfig {
    /// Folders includes may resolve into (symlinks are followed before checking).
    pub roots: Vec<PathBuf>,
    /// Folders searched after the including file's own folder, in order.
    pub include_paths: Vec<PathBuf>,
    /// The bundled library, searched last: `(name, text)` pairs such as `("BRDF.wgsl", ...)`.
    pub library: Vec<(String, String)>,
    /// Whether a link under a root to a file elsewhere is the project's file.
    pub links_out: LinksOut,
}

impl IncludeConfig {
    /// Includes may resolve under `roots`; the library is the one built into kiln.
    pub fn new(roots: Vec<PathBuf>) -> IncludeConfig {
        let library = crate::shaderlib::FILES.iter().map(|(n, t)| (n.to_string(), t.to_string())).collect();
        IncludeConfig { roots, include_paths: Vec::new(), library, links_out: LinksOut::Refused }
    }
}

/// The name bundled library files have in diagnostics.
pub const LIBRARY_PREFIX: &str = "<kiln>/shaderlib/";

/// Where a unit's own includes are searched first.
#[derive(Debug)]
enum Place {
    Folder(PathBuf),
    /// A library file: the folder inside the library, `""` at its top.
    Library(String),
    /// Text added in memory: there is no folder of its own.
    Nowhere,
}

/// Every file reachable from the programs loaded so far, scanned once and shared by all passes
/// and variants.
pub struct Includes {
    config: IncludeConfig,
    /// Roots and include paths, canonicalised once, and as written (made absolute): a file is
    /// inside when its target is under one canonicalised, or (links out followed: a sandbox's
    /// link to a file elsewhere is the project's file) its path is under one as written.
    allowed: Vec<PathBuf>,
    pub(crate) units: Vec<Unit>,
    places: Vec<Place>,
    on_disk: HashMap<PathBuf, usize>,
    in_library: HashMap<String, usize>,
    blocks: HashMap<(FileId, u32), usize>,
    /// Program blocks scanned ahead ([`Includes::add_scanned`]), taken by the first program that
    /// names each.
    scanned: HashMap<(FileId, u32), ScannedBlock>,
    /// Where each path looked at resolved to (`None`: no file there), asked of the file system
    /// once: every shader of a project names the same includes from the same folder.
    looked_up: HashMap<PathBuf, Option<PathBuf>>,
}

/// A `#define` as its unit has it.
#[derive(Debug, Clone, Copy)]
pub struct MacroDefinition<'a> {
    /// The macro's name.
    pub name: &'a str,
    /// The directive.
    pub span: Span,
    /// A function-like macro's parameters (`None`: object-like).
    pub params: Option<&'a [String]>,
    /// Whether its last parameter is `...`.
    pub variadic: bool,
    /// Its replacement text.
    pub value: &'a str,
}

impl MacroDefinition<'_> {
    /// The directive as written, spaced one way: `#define NAME(a, b) value`.
    pub fn directive(&self) -> String {
        let params = self.params.map(|params| {
            let dots = self.variadic.then_some("...");
            let list: Vec<&str> = params.iter().map(String::as_str).chain(dots).collect();
            format!("({})", list.join(", "))
        });
        format!("#define {}{} {}", self.name, params.unwrap_or_default(), self.value)
    }
}

/// A program block scanned where it is ([`ScannedBlock::scan`]): scanning needs nothing loaded, so
/// a catalogue scans every shader's blocks in parallel and loads the programs, which resolves
/// their includes, one after another.
pub struct ScannedBlock {
    block: Span,
    unit: Unit,
    errors: Vec<PreprocessError>,
}

impl ScannedBlock {
    /// Scans the program block whose body is at `block`.
    pub fn scan(store: &SourceStore, block: Span) -> ScannedBlock {
        let (unit, errors) = scan::scan(block.file, store.text(block.file), block.range());
        ScannedBlock { block, unit, errors }
    }
}

/// One pass's program: its blocks (include blocks first), as scanned units, and the
/// `dynamic_branch` keywords every variant's text declares.
#[derive(Debug, Clone)]
pub struct Program {
    pub(crate) blocks: Vec<usize>,
    pub(crate) dynamic_keywords: Vec<DynamicKeyword>,
}

impl Includes {
    /// Includes resolved with `config`, none scanned yet.
    pub fn new(config: IncludeConfig) -> Includes {
        let roots = || config.roots.iter().chain(&config.include_paths);
        let written = roots().filter_map(|p| std::path::absolute(p).ok()).map(|p| normalize_lexically(&p));
        let mut allowed: Vec<PathBuf> =
            roots().filter_map(|p| std::fs::canonicalize(p).ok()).chain(written).collect();
        allowed.sort();
        allowed.dedup();
        Includes {
            config,
            allowed,
            units: Vec::new(),
            places: Vec::new(),
            on_disk: HashMap::new(),
            in_library: HashMap::new(),
            blocks: HashMap::new(),
            scanned: HashMap::new(),
            looked_up: HashMap::new(),
        }
    }

    /// Blocks scanned ahead, for [`Includes::load_program`] to take instead of scanning them: what
    /// it reports of them is what it would have found.
    pub fn add_scanned(&mut self, blocks: impl IntoIterator<Item = ScannedBlock>) {
        for scanned in blocks {
            let key = (scanned.block.file, scanned.block.start);
            if !self.blocks.contains_key(&key) {
                self.scanned.insert(key, scanned);
            }
        }
    }

    /// The `#include` directive at `offset` in `file`: its span, its name and the file it resolved
    /// to (`None` when it did not).
    pub fn include_at(&self, file: FileId, offset: usize) -> Option<(Span, &str, Option<FileId>)> {
        self.units.iter().filter(|unit| unit.file == file).flat_map(|unit| &unit.items).find_map(|item| {
            match item {
                Item::Include { name, span, target, .. } if span.range().contains(&offset) => {
                    let resolved = match target {
                        Target::Unit(unit) => Some(self.units[*unit].file),
                        _ => None,
                    };
                    Some((*span, name.as_str(), resolved))
                }
                _ => None,
            }
        })
    }

    /// Every `#define` of every unit scanned.
    pub fn defines(&self) -> impl Iterator<Item = MacroDefinition<'_>> {
        self.units.iter().flat_map(|unit| &unit.items).filter_map(|item| match item {
            Item::Define { name, span, params, variadic, value, .. } => Some(MacroDefinition {
                name,
                span: *span,
                params: params.as_deref(),
                variadic: *variadic,
                value,
            }),
            _ => None,
        })
    }

    /// Whether a file of this name is in one of the include paths (not the including file's
    /// folder, nor the bundled library).
    pub fn on_include_path(&self, name: &str) -> bool {
        self.config.include_paths.iter().any(|folder| folder.join(name).is_file())
    }

    /// Every file a unit was scanned from, each once, in the order first scanned.
    pub fn files(&self) -> Vec<FileId> {
        let mut seen = std::collections::HashSet::new();
        self.units.iter().map(|unit| unit.file).filter(|&file| seen.insert(file)).collect()
    }

    /// Scans the program blocks at `blocks` and every file they can include. Diagnostics are for
    /// files scanned for the first time, so a library shared by many passes is reported once.
    pub fn load_program(&mut self, store: &mut SourceStore, blocks: &[Span]) -> (Program, Vec<Diagnostic>) {
        let mut diagnostics = Vec::new();
        let first_new = self.units.len();
        let mut program = Program { blocks: Vec::new(), dynamic_keywords: Vec::new() };
        for &block in blocks {
            let unit = match self.blocks.get(&(block.file, block.start)) {
                Some(&unit) => unit,
                None => {
                    let place = match store.path(block.file).and_then(Path::parent) {
                        Some(folder) => Place::Folder(folder.to_path_buf()),
                        None => Place::Nowhere,
                    };
                    let scanned = match self.scanned.remove(&(block.file, block.start)) {
                        Some(scanned) if scanned.block == block => scanned,
                        _ => ScannedBlock::scan(store, block),
                    };
                    let unit = self.add_scanned_unit(scanned.unit, scanned.errors, place, &mut diagnostics);
                    self.blocks.insert((block.file, block.start), unit);
                    unit
                }
            };
            program.blocks.push(unit);
        }
        // Units appended while resolving are resolved in turn: a worklist over the include graph.
        let mut next = first_new;
        while next < self.units.len() {
            self.resolve_includes(store, next, &mut diagnostics);
            next += 1;
        }
        (program, diagnostics)
    }

    fn add_unit(
        &mut self,
        store: &SourceStore,
        file: FileId,
        range: std::ops::Range<usize>,
        place: Place,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> usize {
        let (unit, errors) = scan::scan(file, store.text(file), range);
        self.add_scanned_unit(unit, errors, place, diagnostics)
    }

    fn add_scanned_unit(
        &mut self,
        unit: Unit,
        errors: Vec<PreprocessError>,
        place: Place,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> usize {
        diagnostics.extend(errors.into_iter().map(Diagnostic::from));
        self.units.push(unit);
        self.places.push(place);
        self.units.len() - 1
    }

    fn resolve_includes(&mut self, store: &mut SourceStore, unit: usize, diagnostics: &mut Vec<Diagnostic>) {
        for index in 0..self.units[unit].items.len() {
            let Item::Include { name, span, target: Target::Pending, .. } = &self.units[unit].items[index]
            else {
                continue;
            };
            let (name, span) = (name.clone(), *span);
            let target = self.resolve(store, unit, &name, span, diagnostics);
            if let Item::Include { target: slot, .. } = &mut self.units[unit].items[index] {
                *slot = target;
            }
        }
    }

    /// Search order: the including file's folder, the include paths, the bundled library.
    fn resolve(
        &mut self,
        store: &mut SourceStore,
        from: usize,
        name: &str,
        span: Span,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Target {
        let mut searched = Vec::new();
        let mut folders: Vec<PathBuf> = Vec::new();
        match &self.places[from] {
            Place::Folder(folder) => folders.push(folder.clone()),
            Place::Library(folder) => {
                let folder = folder.clone();
                let inside = if folder.is_empty() { name.to_string() } else { format!("{folder}/{name}") };
                if let Some(target) = self.library_unit(store, &inside, diagnostics) {
                    return target;
                }
                searched.push(format!("{LIBRARY_PREFIX}{folder}"));
            }
            Place::Nowhere => {}
        }
        folders.extend(self.config.include_paths.iter().cloned());
        // A path that leads out of the project is not looked at: whether a file is there must not
        // change what kiln says (K0304 either way, never K0301 for one that is absent).
        let mut outside = None;
        for folder in folders.iter() {
            let candidate = normalize_lexically(&folder.join(name));
            if !self.written_inside(&candidate) {
                outside.get_or_insert(candidate);
                continue;
            }
            let looked_up = self.looked_up.entry(candidate.clone());
            if let Some(canonical) = looked_up.or_insert_with(|| store.canonical_file(&candidate)).clone() {
                return self.disk_unit(store, candidate, canonical, name, span, diagnostics);
            }
            let shown = folder.to_string_lossy().replace('\\', "/");
            searched.push(if shown.is_empty() { ".".into() } else { shown });
        }
        if let Some(target) = self.library_unit(store, name, diagnostics) {
            return target;
        }
        if let Some(path) = outside {
            let resolved = path.to_string_lossy().replace('\\', "/");
            return Target::Failed(PreprocessError::IncludeOutsideRoots {
                span,
                name: name.to_string(),
                resolved,
            });
        }
        searched.push("the bundled shader library".into());
        let suggestion = self.closest_include(name, &folders);
        Target::Failed(PreprocessError::IncludeNotFound {
            span,
            name: name.to_string(),
            searched,
            suggestion,
        })
    }

    /// The file name nearest `name` in the folders searched and the bundled library, for a
    /// "did you mean" (read only when an include was not found). Only folders inside the project
    /// are listed: a suggestion must not reveal names kiln may not read (`#include "/etc/hostnam"`).
    fn closest_include(&self, name: &str, folders: &[PathBuf]) -> Option<String> {
        let wanted = Path::new(name);
        let (parent, file) = (wanted.parent().unwrap_or(Path::new("")), wanted.file_name()?.to_str()?);
        let on_disk: Vec<String> = folders
            .iter()
            .map(|folder| folder.join(parent))
            .filter(|folder| self.may_read(folder))
            .filter_map(|folder| std::fs::read_dir(folder).ok())
            .flatten()
            .filter_map(|entry| entry.ok()?.file_name().into_string().ok())
            .collect();
        let library = self.config.library.iter().map(|(n, _)| n.as_str());
        let found = crate::diagnostics::closest(file, on_disk.iter().map(String::as_str).chain(library))?;
        Some(parent.join(found).to_string_lossy().replace('\\', "/"))
    }

    /// Whether `path` is inside the project (see `allowed`).
    pub fn may_read(&self, path: &Path) -> bool {
        std::fs::canonicalize(path).is_ok_and(|canonical| self.inside(path, &canonical))
    }

    /// Whether the file at `path` (`canonical` once links are followed) is inside the project.
    fn inside(&self, path: &Path, canonical: &Path) -> bool {
        self.allowed.iter().any(|root| canonical.starts_with(root))
            || self.config.links_out == LinksOut::Followed && self.written_inside(path)
    }

    /// Whether `path`, as written (made absolute, `..` taken lexically), is under a root.
    fn written_inside(&self, path: &Path) -> bool {
        let written = std::path::absolute(path).map(|p| normalize_lexically(&p));
        written.is_ok_and(|written| self.allowed.iter().any(|root| written.starts_with(root)))
    }

    fn disk_unit(
        &mut self,
        store: &mut SourceStore,
        path: PathBuf,
        canonical: PathBuf,
        name: &str,
        span: Span,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Target {
        if !self.inside(&path, &canonical) {
            let resolved = path.to_string_lossy().replace('\\', "/");
            return Target::Failed(PreprocessError::IncludeOutsideRoots {
                span,
                name: name.to_string(),
                resolved,
            });
        }
        if let Some(&unit) = self.on_disk.get(&canonical) {
            return Target::Unit(unit);
        }
        match store.load_once(&path, canonical.clone()) {
            Ok(file) => {
                diagnostics.extend(crate::diagnostics::text_warnings(store, file));
                let place = Place::Folder(path.parent().map(Path::to_path_buf).unwrap_or_default());
                let len = store.text(file).len();
                let unit = self.add_unit(store, file, 0..len, place, diagnostics);
                self.on_disk.insert(canonical, unit);
                Target::Unit(unit)
            }
            Err(error) => Target::Failed(PreprocessError::IncludeUnreadable {
                span,
                name: name.to_string(),
                reason: error.to_string(),
            }),
        }
    }

    fn library_unit(
        &mut self,
        store: &mut SourceStore,
        name: &str,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Option<Target> {
        let normalized = normalize_lexically(Path::new(name)).to_string_lossy().replace('\\', "/");
        if let Some(&unit) = self.in_library.get(&normalized) {
            return Some(Target::Unit(unit));
        }
        let (_, text) = self.config.library.iter().find(|(n, _)| *n == normalized)?;
        let file = store.add(format!("{LIBRARY_PREFIX}{normalized}"), text.clone());
        let folder = normalized.rsplit_once('/').map_or("", |(folder, _)| folder).to_string();
        let unit = self.add_unit(store, file, 0..text.len(), Place::Library(folder), diagnostics);
        self.in_library.insert(normalized, unit);
        Some(Target::Unit(unit))
    }

    /// Whether a unit is part of the bundled library (whose optional keywords are not the
    /// project's concern).
    pub(crate) fn is_library(&self, unit: usize) -> bool {
        matches!(self.places[unit], Place::Library(_))
    }

    /// Every unit the program can reach through any `#include`, whatever the keywords, in first
    /// visit order; `only_with_pragmas` follows only `#include_with_pragmas` edges.
    pub(crate) fn reachable(&self, program: &Program, only_with_pragmas: bool) -> Vec<usize> {
        let mut seen = vec![false; self.units.len()];
        let mut order = Vec::new();
        let mut stack: Vec<usize> = program.blocks.iter().rev().copied().collect();
        while let Some(unit) = stack.pop() {
            if std::mem::replace(&mut seen[unit], true) {
                continue;
            }
            order.push(unit);
            let children = self.units[unit].items.iter().rev().filter_map(|item| match item {
                Item::Include { target: Target::Unit(child), with_pragmas, .. }
                    if *with_pragmas || !only_with_pragmas =>
                {
                    Some(*child)
                }
                _ => None,
            });
            stack.extend(children);
        }
        order
    }
}
