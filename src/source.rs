//! Source files and spans: the one store of file text that every stage points into.
//!
//! Stages never read files themselves. The caller loads files here, the store remembers every file
//! it read (so a build script can print `rerun-if-changed` for exactly those), and diagnostics find
//! line and column through it.

use std::collections::HashMap;
use std::ops::Range;
use std::path::{Component, Path, PathBuf};

/// Index of a file inside a [`SourceStore`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FileId(u32);

/// A byte range inside one file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Span {
    /// The file.
    pub file: FileId,
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

impl Span {
    /// The bytes `range` of `file`.
    pub fn new(file: FileId, range: Range<usize>) -> Span {
        Span { file, start: range.start as u32, end: range.end as u32 }
    }

    /// Its bytes, as a range.
    pub fn range(self) -> Range<usize> {
        self.start as usize..self.end as usize
    }

    /// The smallest span covering both (which must be in the same file).
    pub fn to(self, other: Span) -> Span {
        debug_assert_eq!(self.file, other.file);
        Span { file: self.file, start: self.start.min(other.start), end: self.end.max(other.end) }
    }
}

/// A value together with the span it was read from.
#[derive(Debug, Clone, PartialEq)]
pub struct Spanned<T> {
    /// The value.
    pub value: T,
    /// Where it was written.
    pub span: Span,
}

impl<T> Spanned<T> {
    /// A value written at `span`.
    pub fn new(value: T, span: Span) -> Spanned<T> {
        Spanned { value, span }
    }
}

/// Removes `.` components and folds `a/..` without touching the file system, so that names in
/// diagnostics read as the user wrote them (`shaders/../lib/x.wgsl` becomes `lib/x.wgsl`).
pub fn normalize_lexically(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                let last_is_normal = matches!(out.components().next_back(), Some(Component::Normal(_)));
                if last_is_normal {
                    out.pop();
                } else if !matches!(out.components().next_back(), Some(Component::RootDir)) {
                    out.push("..");
                }
            }
            other => out.push(other),
        }
    }
    // `.` and `a/..` name the current folder; an empty path names nothing (`exists` is false).
    if out.as_os_str().is_empty() { PathBuf::from(".") } else { out }
}

/// 1-based line and column (in characters) of a byte offset.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineCol {
    /// 1-based line.
    pub line: usize,
    /// 1-based column, in characters.
    pub column: usize,
}

/// Why a file could not be loaded.
#[derive(Debug, thiserror::Error)]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
#[non_exhaustive]
pub enum LoadError {
    #[error("cannot read `{path}`: {source}")]
    Io { path: PathBuf, source: std::io::Error },
    #[error("`{path}` is not a text file (NUL byte at line {line}, column {column})")]
    NotText { path: PathBuf, line: usize, column: usize },
    #[error("`{path}` is {size} bytes, more than the {MAX_FILE_SIZE} bytes kiln reads")]
    TooLarge { path: PathBuf, size: u64 },
}

/// Files larger than this are refused: no shader, include or material is anywhere near it, and
/// spans are 32-bit.
pub const MAX_FILE_SIZE: u64 = 16 * 1024 * 1024;

/// Something about a file's bytes that its reader should hear about, though the file was read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
// Each variant's fields are named in its comment.
#[allow(missing_docs)]
pub enum TextProblem {
    /// Byte sequences that are not UTF-8 (`count` of them), each read as U+FFFD; `at` is the
    /// first, as an offset into the decoded text.
    NotUtf8 { at: usize, count: usize },
    /// A NUL byte: the file may be binary.
    Nul { at: usize },
}

/// How far into a file kiln looks to tell text from binary data (as git does).
const BINARY_SNIFF_LEN: usize = 8000;

/// Decodes a file's bytes. UTF-8 is read as is (a byte order mark is kept: the scanners skip it);
/// UTF-16 with a byte order mark is decoded; any other bytes are read as UTF-8 with what cannot be
/// decoded replaced, so that a file with comments in a legacy code page still builds. Bytes that
/// are neither UTF-8 nor free of NULs near the start are binary data, not text.
fn decode(path: &Path, bytes: Vec<u8>) -> Result<(String, Vec<TextProblem>), LoadError> {
    let utf16 = match bytes.get(..2) {
        Some([0xFF, 0xFE]) => Some(u16::from_le_bytes as fn([u8; 2]) -> u16),
        Some([0xFE, 0xFF]) => Some(u16::from_be_bytes as fn([u8; 2]) -> u16),
        _ => None,
    };
    let (text, mut problems) = match (utf16, String::from_utf8(bytes)) {
        (None, Ok(text)) => (text, Vec::new()),
        (Some(unit), text) => {
            let bytes = text.map_or_else(|e| e.into_bytes(), String::into_bytes);
            let units: Vec<u16> = bytes[2..].chunks_exact(2).map(|c| unit([c[0], c[1]])).collect();
            (String::from_utf16_lossy(&units), Vec::new())
        }
        (None, Err(error)) => {
            let bytes = error.into_bytes();
            let sniffed = &bytes[..bytes.len().min(BINARY_SNIFF_LEN)];
            if let Some(nul) = sniffed.iter().position(|&b| b == 0) {
                let before = String::from_utf8_lossy(&bytes[..nul]);
                let line = before.matches('\n').count() + 1;
                let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
                return Err(LoadError::NotText { path: path.to_path_buf(), line, column });
            }
            let count = bytes.utf8_chunks().filter(|chunk| !chunk.invalid().is_empty()).count();
            let at = bytes.utf8_chunks().next().map_or(0, |chunk| chunk.valid().len());
            (String::from_utf8_lossy(&bytes).into_owned(), vec![TextProblem::NotUtf8 { at, count }])
        }
    };
    if let Some(at) = text.find('\0') {
        problems.push(TextProblem::Nul { at });
    }
    Ok((text, problems))
}

struct SourceFile {
    name: String,
    path: Option<PathBuf>,
    text: String,
    line_starts: Vec<usize>,
    problems: Vec<TextProblem>,
    /// The text as diagnostics show it, when it holds control characters: each replaced by
    /// spaces of the same byte length, so that snippets never send a terminal a control code and
    /// every offset still points at the same place.
    display: Option<String>,
    /// The name as diagnostics show it, when it holds control characters: escaped (`\n`), so a
    /// file name cannot end a line of a log and forge the next.
    display_name: Option<String>,
}

impl SourceFile {
    fn new(name: String, path: Option<PathBuf>, text: String) -> SourceFile {
        let line_starts = codespan_reporting::files::line_starts(&text).collect();
        let shown_raw = |c: char| !c.is_control() || matches!(c, '\t' | '\n' | '\r');
        let display = (!text.chars().all(shown_raw)).then(|| {
            text.chars()
                .map(|c| if shown_raw(c) { c.to_string() } else { " ".repeat(c.len_utf8()) })
                .collect()
        });
        let display_name = name.contains(char::is_control).then(|| name.escape_debug().to_string());
        SourceFile { name, path, text, line_starts, problems: Vec::new(), display, display_name }
    }
}

/// Texts that stand in for files on disk, by canonical path: an editor's unsaved buffers, which a
/// language server checks instead of what was last saved.
pub type Overlay = HashMap<PathBuf, String>;

/// `read` of each path, in order, on as many threads as rayon's pool has. On Linux they are
/// threads of their own, each with its own table of open files: every open and close takes the
/// table's lock, so threads sharing one read no faster than four do (50,000 materials on a
/// 16-core host: 0.054 s on 16 threads sharing it, 0.018 s with tables of their own; see
/// docs/performance.md). Where the system refuses a thread its own table (a container's filter
/// of system calls), the threads share the process's, as rayon's would.
#[cfg(target_os = "linux")]
fn read_in_parallel<T: Send>(paths: &[PathBuf], read: impl Fn(&Path) -> T + Sync) -> Vec<T> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    // Paths taken a block at a time, so a thread held up does not hold up the rest.
    const BLOCK: usize = 64;
    let threads = rayon::current_num_threads().min(paths.len().div_ceil(BLOCK));
    if threads <= 1 {
        return paths.iter().map(|p| read(p)).collect();
    }
    let next = AtomicUsize::new(0);
    let reader = || {
        // SAFETY: `unshare` gives this thread a copy of the process's file table; the thread
        // holds no file before it, and closes every file it opens before it ends.
        unsafe { libc::unshare(libc::CLONE_FILES) };
        let mut blocks = Vec::new();
        loop {
            let start = next.fetch_add(BLOCK, Ordering::Relaxed);
            if start >= paths.len() {
                break blocks;
            }
            let block = &paths[start..(start + BLOCK).min(paths.len())];
            blocks.push((start, block.iter().map(|p| read(p)).collect::<Vec<T>>()));
        }
    };
    let mut blocks: Vec<(usize, Vec<T>)> = std::thread::scope(|scope| {
        let readers: Vec<_> = (0..threads).map(|_| scope.spawn(reader)).collect();
        let joined =
            readers.into_iter().map(|r| r.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)));
        joined.flatten().collect()
    });
    blocks.sort_unstable_by_key(|(start, _)| *start);
    blocks.into_iter().flat_map(|(_, read)| read).collect()
}

/// `read` of each path, in order, on rayon's pool.
#[cfg(not(target_os = "linux"))]
fn read_in_parallel<T: Send>(paths: &[PathBuf], read: impl Fn(&Path) -> T + Sync) -> Vec<T> {
    use rayon::prelude::*;
    paths.par_iter().map(|p| read(p)).collect()
}

/// A file's name as kiln shows it: the path with `/` between its parts and without `.` parts, so
/// that one file has one name whether it was reached as `./shaders/Lit.shader` (a project at
/// `.`) or `shaders/Lit.shader`.
fn file_name(path: &Path) -> String {
    let parts: Vec<_> =
        path.components().filter(|c| !matches!(c, Component::CurDir)).map(|c| c.as_os_str()).collect();
    if parts.is_empty() {
        return ".".to_string();
    }
    let joined: PathBuf = parts.iter().collect();
    joined.to_string_lossy().replace('\\', "/")
}

/// Reads a text file of at most [`MAX_FILE_SIZE`] bytes (see [`decode`]), or its stand-in in
/// `overlay`.
fn read_file(path: &Path, overlay: Option<&Overlay>) -> Result<SourceFile, LoadError> {
    let unsaved = overlay.filter(|o| !o.is_empty()).and_then(|o| o.get(&std::fs::canonicalize(path).ok()?));
    if let Some(text) = unsaved {
        let (text, problems) = decode(path, text.clone().into_bytes())?;
        let name = file_name(path);
        return Ok(SourceFile { problems, ..SourceFile::new(name, Some(path.to_path_buf()), text) });
    }
    let io = |source| LoadError::Io { path: path.to_path_buf(), source };
    // The size from the open file: one lookup of the path per file (a project reads tens of
    // thousands).
    let mut file = std::fs::File::open(path).map_err(io)?;
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    if size > MAX_FILE_SIZE {
        return Err(LoadError::TooLarge { path: path.to_path_buf(), size });
    }
    let mut bytes = Vec::with_capacity(size as usize);
    // Through `take`, which also stops a file that grows while it is read: `File`'s own
    // `read_to_end` asks the size and the position again first (two more system calls a file).
    std::io::Read::read_to_end(&mut std::io::Read::take(&mut file, MAX_FILE_SIZE + 1), &mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_FILE_SIZE {
        return Err(LoadError::TooLarge { path: path.to_path_buf(), size: bytes.len() as u64 });
    }
    let (text, problems) = decode(path, bytes)?;
    let name = file_name(path);
    Ok(SourceFile { problems, ..SourceFile::new(name, Some(path.to_path_buf()), text) })
}

/// Every file a run has seen, with its text and line index.
#[derive(Default)]
pub struct SourceStore {
    files: Vec<SourceFile>,
    /// Files loaded through [`SourceStore::load_once`], by canonical path.
    by_canonical_path: HashMap<PathBuf, FileId>,
    /// Paths looked for and not found: a file appearing there could change what is read.
    absent: Vec<PathBuf>,
    /// Folders searched for files (shaders, materials, includes): a new file there could too.
    searched: Vec<PathBuf>,
    /// Texts read instead of the files at their paths.
    overlay: Option<std::sync::Arc<Overlay>>,
}

impl SourceStore {
    /// An empty store.
    pub fn new() -> SourceStore {
        SourceStore::default()
    }

    /// An empty store that reads the texts of `overlay` instead of the files at their paths.
    pub fn with_overlay(overlay: std::sync::Arc<Overlay>) -> SourceStore {
        SourceStore { overlay: Some(overlay), ..SourceStore::default() }
    }

    /// Adds text that did not come from disk (tests, generated sources, embedded library files).
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        self.push(name.into(), None, text.into())
    }

    /// Reads a file from disk and records it as read.
    pub fn load(&mut self, path: &Path) -> Result<FileId, LoadError> {
        let file = read_file(path, self.overlay.as_deref())?;
        Ok(self.push_file(file))
    }

    /// [`SourceStore::load`] for many files, read in parallel (a project's materials); the ids
    /// come in the order of `paths`.
    pub fn load_all(&mut self, paths: &[PathBuf]) -> Vec<Result<FileId, LoadError>> {
        let overlay = self.overlay.as_deref();
        let files = read_in_parallel(paths, |p| read_file(p, overlay));
        files.into_iter().map(|file| file.map(|f| self.push_file(f))).collect()
    }

    /// The canonical path of an existing regular file (symlinks resolved), or `None` when there is
    /// no such file (recorded: see [`SourceStore::absent`]). Include resolution asks this before
    /// deciding where a name points.
    pub fn canonical_file(&mut self, path: &Path) -> Option<PathBuf> {
        let found = std::fs::canonicalize(path).ok().filter(|canonical| canonical.is_file());
        if found.is_none() {
            self.absent.push(path.to_path_buf());
        }
        found
    }

    /// Every path [`SourceStore::canonical_file`] found no file at, in the order asked.
    pub fn absent(&self) -> &[PathBuf] {
        &self.absent
    }

    /// Records a folder searched for files (a project's shader, material and include folders).
    pub fn record_searched(&mut self, folder: PathBuf) {
        self.searched.push(folder);
    }

    /// Every folder recorded as searched, in the order recorded.
    pub fn searched(&self) -> &[PathBuf] {
        &self.searched
    }

    /// Loads a file once: a second call with the same canonical path returns the first id.
    pub fn load_once(&mut self, path: &Path, canonical: PathBuf) -> Result<FileId, LoadError> {
        if let Some(&id) = self.by_canonical_path.get(&canonical) {
            return Ok(id);
        }
        let id = self.load(path)?;
        self.by_canonical_path.insert(canonical, id);
        Ok(id)
    }

    fn push(&mut self, name: String, path: Option<PathBuf>, text: String) -> FileId {
        self.push_file(SourceFile::new(name, path, text))
    }

    fn push_file(&mut self, file: SourceFile) -> FileId {
        let id = FileId(self.files.len() as u32);
        self.files.push(file);
        id
    }

    /// What reading `file` found in its bytes: sequences that are not UTF-8, NUL bytes
    /// (`diagnostics::text_warnings` makes them warnings).
    pub fn text_problems(&self, file: FileId) -> &[TextProblem] {
        &self.files[file.0 as usize].problems
    }

    /// A file's text.
    pub fn text(&self, file: FileId) -> &str {
        &self.files[file.0 as usize].text
    }

    /// The name diagnostics show for the file: its path as given, with `/` separators.
    pub fn name(&self, file: FileId) -> &str {
        &self.files[file.0 as usize].name
    }

    /// The name as diagnostics show it: [`SourceStore::name`] with control characters escaped.
    pub fn display_name(&self, file: FileId) -> &str {
        let f = &self.files[file.0 as usize];
        f.display_name.as_deref().unwrap_or(&f.name)
    }

    /// The path a file was read from (`None` for text added in memory).
    pub fn path(&self, file: FileId) -> Option<&Path> {
        self.files[file.0 as usize].path.as_deref()
    }

    /// The text a span covers.
    pub fn slice(&self, span: Span) -> &str {
        &self.text(span.file)[span.range()]
    }

    /// Every file of the store (read from disk or added), in the order it came in.
    pub fn ids(&self) -> impl Iterator<Item = FileId> + use<> {
        (0..self.files.len() as u32).map(FileId)
    }

    /// Every file read from disk, in the order it was read.
    pub fn files_read(&self) -> impl Iterator<Item = &Path> {
        self.files.iter().filter_map(|f| f.path.as_deref())
    }

    /// Line and column (1-based, columns counted in characters) of a byte offset.
    pub fn line_col(&self, file: FileId, offset: usize) -> LineCol {
        let f = &self.files[file.0 as usize];
        let offset = offset.min(f.text.len());
        let line = f.line_starts.partition_point(|&start| start <= offset) - 1;
        let column = f.text[f.line_starts[line]..offset].chars().count() + 1;
        LineCol { line: line + 1, column }
    }
}

impl<'a> codespan_reporting::files::Files<'a> for SourceStore {
    type FileId = FileId;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: FileId) -> Result<&'a str, codespan_reporting::files::Error> {
        self.files
            .get(id.0 as usize)
            .map(|f| f.display_name.as_deref().unwrap_or(&f.name))
            .ok_or(codespan_reporting::files::Error::FileMissing)
    }

    fn source(&'a self, id: FileId) -> Result<&'a str, codespan_reporting::files::Error> {
        self.files
            .get(id.0 as usize)
            .map(|f| f.display.as_deref().unwrap_or(&f.text))
            .ok_or(codespan_reporting::files::Error::FileMissing)
    }

    fn line_index(
        &'a self,
        id: FileId,
        byte_index: usize,
    ) -> Result<usize, codespan_reporting::files::Error> {
        let f = self.files.get(id.0 as usize).ok_or(codespan_reporting::files::Error::FileMissing)?;
        Ok(f.line_starts.partition_point(|&start| start <= byte_index).saturating_sub(1))
    }

    fn line_range(
        &'a self,
        id: FileId,
        line_index: usize,
    ) -> Result<Range<usize>, codespan_reporting::files::Error> {
        let f = self.files.get(id.0 as usize).ok_or(codespan_reporting::files::Error::FileMissing)?;
        let start = *f.line_starts.get(line_index).ok_or(codespan_reporting::files::Error::LineTooLarge {
            given: line_index,
            max: f.line_starts.len() - 1,
        })?;
        let end = f.line_starts.get(line_index + 1).copied().unwrap_or(f.text.len());
        Ok(start..end)
    }
}

/// `path` relative to `root`, lexically, with `/` separators (`..` where it lies outside), so
/// that what is written about a project does not depend on the folder it sits in. Both are taken
/// as given: relative paths are relative to the same folder.
pub fn relative_to(path: &Path, root: &Path) -> String {
    // The common case, a file under the root with nothing to fold, needs no normalising (a build
    // names tens of thousands of files this way).
    if let Ok(rest) = path.strip_prefix(root)
        && !rest.as_os_str().is_empty()
        && rest.components().all(|c| matches!(c, Component::Normal(_)))
    {
        let parts: Vec<_> = rest.components().map(|c| c.as_os_str().to_string_lossy()).collect();
        return parts.join("/");
    }
    let (path, root) = (normalize_lexically(path), normalize_lexically(root));
    let (mut path_parts, mut root_parts) = (path.components().peekable(), root.components().peekable());
    while let (Some(a), Some(b)) = (path_parts.peek(), root_parts.peek()) {
        if a != b {
            break;
        }
        path_parts.next();
        root_parts.next();
    }
    let ups = root_parts.filter(|c| matches!(c, Component::Normal(_))).map(|_| "..".to_string());
    let rest = path_parts.map(|c| c.as_os_str().to_string_lossy().into_owned());
    let parts: Vec<String> = ups.chain(rest).collect();
    if parts.is_empty() { ".".to_string() } else { parts.join("/") }
}

/// Whether links that lead out of a project are followed (`KILN_FOLLOW_LINKS=1`), decided once
/// when a project is opened. Refused by default: a link in a cloned project or a shader pack
/// could name any file the user can read (`~/.ssh/id_rsa`), and its lines would reach
/// diagnostics and logs. A sandbox that stages every input as a link (Bazel's) sets it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LinksOut {
    /// A link whose target is outside the project is not followed (the walk skips it; an
    /// include through it is K0304).
    #[default]
    Refused,
    /// Such links are the project's own files.
    Followed,
}

impl LinksOut {
    /// The environment's decision: `KILN_FOLLOW_LINKS=1` follows them.
    pub fn from_env() -> LinksOut {
        match std::env::var_os("KILN_FOLLOW_LINKS") {
            Some(value) if value == "1" => LinksOut::Followed,
            _ => LinksOut::Refused,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn many_files_load_in_their_order_with_each_failure_in_its_place() {
        let dir = tempfile::tempdir().expect("temp dir");
        let paths: Vec<PathBuf> = (0..1000).map(|i| dir.path().join(format!("{i}.mat"))).collect();
        for (i, path) in paths.iter().enumerate().filter(|(i, _)| i % 97 != 5) {
            std::fs::write(path, format!("file {i}\n")).expect("write");
        }
        // A file the process holds open stays readable: the readers' file tables are their own.
        let mut held = std::fs::File::open(&paths[0]).expect("open");
        let mut store = SourceStore::new();
        // More than one reader whatever the machine's cores.
        let pool = rayon::ThreadPoolBuilder::new().num_threads(4).build().expect("pool");
        let loaded = pool.install(|| store.load_all(&paths));
        assert_eq!(loaded.len(), paths.len());
        for (i, file) in loaded.iter().enumerate() {
            match file {
                Ok(id) => assert_eq!((i % 97 != 5, store.text(*id)), (true, format!("file {i}\n").as_str())),
                Err(error) => {
                    assert!(i % 97 == 5 && matches!(error, LoadError::Io { path, .. } if *path == paths[i]))
                }
            }
        }
        let mut text = String::new();
        std::io::Read::read_to_string(&mut held, &mut text).expect("read");
        assert_eq!(text, "file 0\n");
    }

    #[test]
    fn lexical_normalisation_folds_dots() {
        let n = |p: &str| normalize_lexically(Path::new(p)).to_string_lossy().replace('\\', "/");
        assert_eq!(n("a/./b/../c.wgsl"), "a/c.wgsl");
        assert_eq!(n("../x/../y"), "../y");
        assert_eq!(n("a/../../b"), "../b");
        assert_eq!(n("/../a"), "/a");
        // `kiln list .` searched an empty path, which exists nowhere.
        assert_eq!(n("./."), ".");
        assert_eq!(n("a/.."), ".");
    }

    #[test]
    fn line_col_counts_characters_not_bytes() {
        let mut store = SourceStore::new();
        let file = store.add("a", "ab\n// é é x\n");
        assert_eq!(store.line_col(file, 0), LineCol { line: 1, column: 1 });
        let x = store.text(file).find('x').unwrap();
        assert_eq!(store.line_col(file, x), LineCol { line: 2, column: 8 });
        let end = store.text(file).len();
        assert_eq!(store.line_col(file, end), LineCol { line: 3, column: 1 });
    }

    #[test]
    fn relative_paths_are_lexical_and_use_slashes() {
        use super::relative_to;
        let rel = |p: &str, r: &str| relative_to(Path::new(p), Path::new(r));
        assert_eq!(rel("proj/shaders/Lit.shader", "proj"), "shaders/Lit.shader");
        assert_eq!(rel("/a/b/proj/x.wgsl", "/a/b/proj"), "x.wgsl");
        assert_eq!(rel("/a/shared/x.wgsl", "/a/b/proj"), "../../shared/x.wgsl");
        assert_eq!(rel("proj/./lib/../x", "proj"), "x");
        assert_eq!(rel("out/kiln", "out"), "kiln");
        assert_eq!(rel("proj", "proj"), ".");
        // Roots that fold, under which the file needs no folding itself.
        assert_eq!(rel("a/../x/y", "a/.."), "x/y");
        assert_eq!(rel("../x", ".."), "x");
        assert_eq!(rel("./m/./a.mat", "."), "m/a.mat");
        assert_eq!(rel("/x", "/"), "x");
        assert_eq!(rel("/a/b/../c/x", "/a/b/.."), "c/x");
    }
}
