//! The build's files: content-addressed packs of stage modules, the cache that lets an unchanged
//! variant skip naga entirely, and atomic writes (a temporary file and a rename) for all of them.

use super::pass_index::{CachedStage, PassIndex, PassIndexView};
pub use super::records::{OutputFile, PassKey, RecordedFinding, RecordedLabel};
use crate::manifest::{Backend, FileRef, PackPath, open_regular};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeSet, HashMap};
use std::io::Write;
use std::path::{Path, PathBuf};

/// A content hash: BLAKE3, 128 bits in hexadecimal.
pub fn hash(bytes: &[u8]) -> String {
    let digest = blake3::hash(bytes);
    digest.to_hex()[..32].to_string()
}

/// The last clean build: its inputs' hash, its counts, the files it left (packs and the
/// manifest, relative to the output folder, with the length each must have at least), and what
/// it read (files, relative to the project, in the order read) and looked for in vain, so that
/// the next build can tell that nothing changed before parsing anything.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Recorded {
    /// The inputs hash ([`Recorded`] is valid only while it matches).
    pub key: String,
    /// How many of `read` were given to the build (the rest came through includes).
    pub given: usize,
    /// Shaders built.
    pub shaders: usize,
    /// Passes built.
    pub passes: usize,
    /// Variants built.
    pub variants: usize,
    /// Distinct stage modules.
    pub modules: usize,
    /// Files written (relative to the output folder).
    pub files: Vec<RecordedFile>,
    /// Files read, relative to the project, in the order read.
    pub read: Vec<String>,
    /// Paths looked for in vain.
    pub absent: Vec<String>,
    /// What the build reported (warnings and remarks, never an error), for a no-op to say again.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub findings: Vec<RecordedFinding>,
}

/// A file a clean build left (the manifest, the materials or a pack), with its length and hash.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordedFile {
    /// Which file, in the output folder.
    pub path: OutputFile,
    /// Its length.
    pub len: u64,
    /// Its [`hash`], against which the no-op check verifies its bytes (a file without one, as an
    /// older kiln recorded packs, is never taken as in place).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hash: Option<String>,
}

/// An output folder's cache and packs.
pub struct Cache {
    output: PathBuf,
    /// `kiln check` reads the cache but writes nothing.
    write: bool,
    /// Packs this build has stored: passes of identical code make the same pack, written once.
    stored: std::sync::Mutex<BTreeSet<PackPath>>,
}

impl Cache {
    /// The cache of the output folder `output` (read-only unless `write`).
    pub fn new(output: &Path, write: bool) -> Cache {
        Cache { output: output.to_path_buf(), write, stored: Default::default() }
    }

    fn entry(&self, kind: &str, key: &str) -> PathBuf {
        self.output.join(entry_path(kind, key))
    }

    /// Entries are `HASH\nJSON`: an unreadable, truncated or altered entry (the hash of its JSON
    /// no longer matches) is a miss, and the work is redone, never trusted.
    fn read<T: for<'de> Deserialize<'de>>(&self, kind: &str, key: &str) -> Option<T> {
        let bytes = std::fs::read(self.entry(kind, key)).ok()?;
        serde_json::from_slice(unsealed(&entry_path(kind, key), &bytes)?).ok()
    }

    fn put<T: Serialize>(&self, kind: &str, key: &str, value: &T) -> std::io::Result<()> {
        if !self.write {
            return Ok(());
        }
        self.put_entry(&sealed_entry(kind, key, value)?)
    }

    /// Writes an entry sealed beforehand (so that the work of serializing it can be done
    /// beside other work, and the write only once what it names is in place).
    pub fn put_entry(&self, entry: &SealedEntry) -> std::io::Result<()> {
        if !self.write {
            return Ok(());
        }
        write_atomically(&self.output.join(&entry.path), &entry.bytes)
    }

    /// What the last build of a pass left: one file per pass, read once and written once, so
    /// that the cache costs two file operations per pass rather than per module. Stage modules
    /// whose bytes are missing or damaged are dropped (and so compiled again): each pack they
    /// point into is read once and every module's range hashed.
    pub fn pass_index(&self, pass: &PassKey) -> PassIndex {
        let mut index: PassIndex = self.read("pass", pass).unwrap_or_default();
        let damaged: Vec<String> = {
            // Each pack read once, no further than the last module the entry places in it.
            let mut ends: HashMap<&PackPath, u64> = HashMap::new();
            for file in index.stage.values().flat_map(CachedStage::written) {
                let end = ends.entry(&file.path).or_default();
                *end = (*end).max(file.offset.saturating_add(file.size));
            }
            let packs: HashMap<&PackPath, Vec<u8>> = ends
                .into_par_iter()
                .filter_map(|(path, end)| Some((path, path.read(&self.output, end).ok()?)))
                .collect();
            let intact = |file: &FileRef| {
                let pack = packs.get(&file.path);
                pack.and_then(|pack| file.slice(pack)).is_some_and(|bytes| hash(bytes) == file.hash)
            };
            index
                .stage
                .par_iter()
                .filter(|(_, stage)| !stage.written().all(intact))
                .map(|(key, _)| key.clone())
                .collect()
        };
        for key in damaged {
            index.stage.remove(&key);
        }
        index
    }

    /// A pass's index serialized and sealed, for [`Cache::put_entry`].
    pub fn seal_pass_index(pass: &PassKey, index: &PassIndexView) -> std::io::Result<SealedEntry> {
        sealed_entry("pass", pass, index)
    }

    /// Whether every file the recorded build wrote is still in place (the manifest is not
    /// parsed): the manifest, the materials and each pack are the bytes recorded (their lengths
    /// and hashes), each read back whole, in parallel.
    pub fn files_in_place(&self, recorded: &Recorded) -> bool {
        // Every file read back whole (a regular file only: `Digest::of_file`) and hashed: a pack
        // damaged since the build is no no-op's.
        let in_place = |file: &RecordedFile| {
            let expected = file.hash.as_deref();
            expected.is_some_and(|expected| {
                Digest::of_file(&file.path.under(&self.output), file.len.saturating_add(1))
                    .is_ok_and(|d| d.len == file.len && d.finish().to_hex()[..32] == *expected)
            })
        };
        let named = |which: OutputFile| recorded.files.iter().filter(|f| f.path == which).count() == 1;
        named(OutputFile::Manifest) && named(OutputFile::Materials) && recorded.files.par_iter().all(in_place)
    }

    /// Removes the record of the last clean build, before a build replaces what it names: a
    /// build stopped after that leaves no record a no-op could trust.
    pub fn forget_inputs(&self) -> std::io::Result<()> {
        match std::fs::remove_file(self.entry("build", "inputs")) {
            Err(error) if error.kind() != std::io::ErrorKind::NotFound => Err(error),
            _ => Ok(()),
        }
    }

    /// What the last clean build recorded.
    pub fn recorded(&self) -> Option<Recorded> {
        self.read("build", "inputs")
    }

    /// Records that a build with these inputs finished cleanly.
    pub fn record_inputs(&self, recorded: &Recorded) -> std::io::Result<()> {
        self.put("build", "inputs", recorded)
    }

    /// Where modules go as one pack, the concatenation of their bytes (each distinct module
    /// once), named by the hash of their hashes, which fix its bytes (`modules/HASH.EXT`): each
    /// module's reference (returned in the order given) is known before a byte is written
    /// ([`Cache::write_pack`] writes it).
    pub fn plan_pack<'a>(modules: &[&'a ModuleBytes], backend: Backend) -> (PlannedPack<'a>, Vec<FileRef>) {
        let mut placed: HashMap<&str, u64> = HashMap::new();
        let mut distinct: Vec<&[u8]> = Vec::new();
        let mut names = String::new();
        let mut size = 0;
        let mut offsets = Vec::with_capacity(modules.len());
        for module in modules {
            let offset = *placed.entry(&module.hash).or_insert_with(|| {
                names.push_str(&module.hash);
                distinct.push(&module.bytes);
                size += module.bytes.len() as u64;
                size - module.bytes.len() as u64
            });
            offsets.push(offset);
        }
        let path = PackPath::new(&hash(names.as_bytes()), backend);
        let files = (modules.iter().zip(offsets))
            .map(|(module, offset)| FileRef {
                path: path.clone(),
                offset,
                size: module.bytes.len() as u64,
                hash: module.hash.clone(),
            })
            .collect();
        (PlannedPack { path, distinct, size }, files)
    }

    /// Writes a planned pack, streamed from the modules' own bytes (a copy of it all in one
    /// buffer would be fresh memory the allocator takes from the system for every pass). Returns
    /// the bytes written: 0 when the pack was there already, intact.
    pub fn write_pack(&self, pack: &PlannedPack) -> std::io::Result<u64> {
        let full = pack.path.under(&self.output);
        let first = self.stored.lock().map_or(true, |mut stored| stored.insert(pack.path.clone()));
        let present = !first
            || std::fs::metadata(&full).is_ok_and(|m| m.len() == pack.size)
                && pack.path.read(&self.output, pack.size).is_ok_and(|existing| {
                    let mut rest = existing.as_slice();
                    pack.distinct.iter().all(|bytes| {
                        rest.split_at_checked(bytes.len()).is_some_and(|(head, tail)| {
                            rest = tail;
                            head == *bytes
                        })
                    })
                });
        if !self.write || present {
            return Ok(0);
        }
        write_parts_atomically(&full, &pack.distinct)?;
        Ok(pack.size)
    }
}

/// A pack of modules named and laid out, not yet written ([`Cache::plan_pack`]).
pub struct PlannedPack<'a> {
    path: PackPath,
    distinct: Vec<&'a [u8]>,
    size: u64,
}

/// A cache entry serialized and sealed to its key, not yet written ([`Cache::put_entry`]).
pub struct SealedEntry {
    path: String,
    bytes: Vec<u8>,
}

/// An output folder held by one build (or merge) at a time, for as long as this lives: two
/// builds into one folder take turns rather than interleave their renames, and the sweep after a
/// build never removes what another build is writing.
pub struct OutputLock {
    _file: Option<std::fs::File>,
}

impl OutputLock {
    /// Waits for the folder `output` (made if missing) to be free and holds it. Where the
    /// folder cannot be made or its file system has no locks, the build runs unlocked, as before
    /// (its writes report what is wrong).
    pub fn acquire(output: &Path) -> OutputLock {
        let file = std::fs::create_dir_all(output.join(".cache")).ok().and_then(|()| {
            let file = std::fs::File::options()
                .create(true)
                .truncate(false)
                .write(true)
                .open(output.join(".cache").join("lock"))
                .ok()?;
            lock_exclusively(&file).ok()?;
            Some(file)
        });
        OutputLock { _file: file }
    }
}

impl Cache {
    /// Removes what the last clean build (`files`, as its record names them) does not name:
    /// packs under `modules/`, and temporaries a killed build left (`.NAME.RANDOM.tmp`) there,
    /// in the folder and in its cache, so that an output folder (`kiln watch`'s, a build
    /// script's) holds only what ships. Called with the folder's [`OutputLock`] held, after the
    /// build's files are in place. Returns the files removed. (Pass indices stay: their modules
    /// are verified when read.)
    pub fn sweep(&self, files: &[RecordedFile]) -> usize {
        let named: BTreeSet<&str> = files.iter().map(|f| f.path.as_str()).collect();
        let mut removed = 0;
        for folder in ["modules", ".", ".cache/pass", ".cache/build"] {
            let Ok(entries) = std::fs::read_dir(self.output.join(folder)) else { continue };
            for entry in entries.flatten() {
                let name = entry.file_name().to_string_lossy().into_owned();
                let temporary = name.starts_with('.') && name.ends_with(".tmp");
                let stale = folder == "modules" && !named.contains(format!("modules/{name}").as_str());
                let file = entry.file_type().is_ok_and(|t| t.is_file() || t.is_symlink());
                if file && (temporary || stale) && std::fs::remove_file(entry.path()).is_ok() {
                    removed += 1;
                }
            }
        }
        removed
    }
}

/// Waits for an exclusive `flock` on `file` (released when it closes).
#[cfg(target_os = "linux")]
fn lock_exclusively(file: &std::fs::File) -> std::io::Result<()> {
    use std::os::fd::AsRawFd;
    // SAFETY: `flock` takes a descriptor `file` keeps open for the call and touches no memory.
    match unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX) } {
        0 => Ok(()),
        _ => Err(std::io::Error::last_os_error()),
    }
}

/// Elsewhere builds into one folder are not serialized (`std`'s `File::lock` is newer than the
/// crate's minimum Rust).
#[cfg(not(target_os = "linux"))]
fn lock_exclusively(_: &std::fs::File) -> std::io::Result<()> {
    Ok(())
}

/// `value` serialized and sealed as the entry `key` of `kind`.
fn sealed_entry<T: Serialize>(kind: &str, key: &str, value: &T) -> std::io::Result<SealedEntry> {
    let path = entry_path(kind, key);
    Ok(SealedEntry { bytes: sealed(&path, value)?, path })
}

/// Where the cache keeps an entry, relative to the output folder.
fn entry_path(kind: &str, key: &str) -> String {
    format!(".cache/{kind}/{key}.json")
}

/// Where the cache keeps a pass's index, relative to the output folder.
pub fn pass_index_path(pass: &PassKey) -> String {
    entry_path("pass", pass)
}

/// A compiled module's bytes and their [`hash`].
pub struct ModuleBytes {
    /// The module.
    pub bytes: Vec<u8>,
    /// Its [`hash`].
    pub hash: String,
}

/// The folder `path` goes in (`.` for a bare name), made if missing.
fn folder_made_for(path: &Path) -> std::io::Result<&Path> {
    let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(folder)?;
    Ok(folder)
}

/// Writes through a temporary file in the same folder and a rename, so a reader never sees half a
/// file and a failed or interrupted write leaves the old one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_parts_atomically(path, &[bytes])
}

/// [`write_atomically`] for a file that is the concatenation of `parts`, written from them.
fn write_parts_atomically(path: &Path, parts: &[&[u8]]) -> std::io::Result<()> {
    stage(path, |file| parts.iter().try_for_each(|part| file.write_all(part)))?.commit(|_| true).map(drop)
}

/// A file's new bytes under a temporary name beside it, not yet in its place: [`Staged::commit`]
/// puts them there; dropped uncommitted, they are removed and the old file stays.
pub struct Staged {
    temporary: PathBuf,
    path: PathBuf,
    committed: bool,
}

/// Writes `path`'s new bytes, streamed by `write` (buffered, so a large file is never whole in
/// memory), under a temporary name in the same folder (see [`Staged`]).
pub fn stage(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> std::io::Result<Staged> {
    let (staged, file) = Staged::beside(path)?;
    let mut buffered = std::io::BufWriter::new(file);
    write(&mut buffered)?;
    durable(&buffered.into_inner().map_err(std::io::IntoInnerError::into_error)?)?;
    Ok(staged)
}

/// Makes a staged file's bytes durable before it is named: a rename is the commit point, and
/// without this a power cut after it can leave the new name on bytes never written (as SQLite and
/// git do, the data first, then the name).
pub fn durable(file: &std::fs::File) -> std::io::Result<()> {
    file.sync_data()
}

/// Makes the names a folder holds durable (the renames and links into it): after an output
/// folder's commit, and for its packs before the manifest that names them is renamed into place.
/// A folder that is not there has nothing to make durable.
pub fn durable_folder(folder: &Path) -> std::io::Result<()> {
    match std::fs::File::open(folder) {
        Ok(folder) => folder.sync_all(),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(error) => Err(error),
    }
}

impl Staged {
    /// A new, empty temporary file beside `path`, in a folder made if missing. Its name is random
    /// and it is created exclusively (`O_CREAT | O_EXCL`, which follows no symbolic link), so that
    /// nobody who can write the folder (a shared cache) can plant a file or link where a write
    /// will go; two jobs storing the same content-addressed file at once get two names.
    pub fn beside(path: &Path) -> std::io::Result<(Staged, std::fs::File)> {
        use std::hash::{BuildHasher, Hasher};
        let folder = folder_made_for(path)?;
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let mut tries = 0;
        loop {
            // `RandomState` is seeded from the system's randomness, anew for every hasher.
            let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
            hasher.write_u32(std::process::id());
            let temporary = folder.join(format!(".{name}.{:016x}.tmp", hasher.finish()));
            match std::fs::File::options().write(true).create_new(true).open(&temporary) {
                Ok(file) => {
                    return Ok((Staged { temporary, path: path.to_path_buf(), committed: false }, file));
                }
                Err(error) if error.kind() == std::io::ErrorKind::AlreadyExists && tries < 16 => tries += 1,
                Err(error) => return Err(error),
            }
        }
    }

    /// Renames the new bytes into place, unless `keep`, shown the old file (if any), says no:
    /// then the old file stays and the new bytes are dropped. Returns whether they were put there.
    pub fn commit(mut self, keep: impl FnOnce(&Path) -> bool) -> std::io::Result<bool> {
        if !keep(&self.path) {
            return Ok(false);
        }
        crash_point();
        std::fs::rename(&self.temporary, &self.path)?;
        self.committed = true;
        Ok(true)
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// The seal of `body` stored under `key`: a hash of both, so that bytes moved to another key (two
/// entries swapped) fail it as damaged ones do.
pub fn seal(key: &str, body: &[u8]) -> String {
    let mut hasher = blake3::Hasher::new();
    hasher.update(&(key.len() as u64).to_le_bytes());
    hasher.update(key.as_bytes());
    hasher.update(body);
    hasher.finalize().to_hex()[..32].to_string()
}

/// Debug builds only, for the crash tests: `KILN_KILL_AT=N` ends the process as a kill would
/// (abort: no destructor runs, temporaries stay) just before its N-th rename or link into place,
/// counted from 1 over the whole process. Every file a build puts in place goes through here.
fn crash_point() {
    if cfg!(debug_assertions) {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static PLACED: AtomicUsize = AtomicUsize::new(0);
        static AT: std::sync::OnceLock<Option<usize>> = std::sync::OnceLock::new();
        let at = *AT.get_or_init(|| std::env::var("KILN_KILL_AT").ok().and_then(|n| n.parse().ok()));
        if at.is_some_and(|at| PLACED.fetch_add(1, Ordering::SeqCst) + 1 == at) {
            std::process::abort();
        }
    }
}

/// `value` as JSON after a line with its [`seal`] under `key`, so that a reader can tell the
/// bytes from damaged or misplaced ones that still parse ([`unsealed`]): cache entries, the shared
/// cache's layouts, shard records.
pub fn sealed<T: Serialize>(key: &str, value: &T) -> std::io::Result<Vec<u8>> {
    let json = serde_json::to_vec(value).map_err(std::io::Error::other)?;
    let mut bytes = seal(key, &json).into_bytes();
    bytes.push(b'\n');
    bytes.extend(json);
    Ok(bytes)
}

/// The JSON of bytes [`sealed`] under `key`, if it is what was sealed there.
pub fn unsealed<'a>(key: &str, bytes: &'a [u8]) -> Option<&'a [u8]> {
    let split = bytes.iter().position(|&b| b == b'\n')?;
    let (recorded, json) = (&bytes[..split], &bytes[split + 1..]);
    (recorded == seal(key, json).as_bytes()).then_some(json)
}

/// A writer that only hashes and counts what it is given.
#[derive(Default)]
pub struct Digest {
    hasher: blake3::Hasher,
    /// Bytes seen.
    pub len: u64,
}

impl Digest {
    /// The hash of the bytes seen.
    pub fn finish(&self) -> blake3::Hash {
        self.hasher.finalize()
    }

    /// The digest of a file's bytes, read in chunks.
    /// The digest of at most `at_most` bytes of the regular file at `path` (a link or a device is
    /// refused: a record may name the file).
    pub fn of_file(path: &Path, at_most: u64) -> std::io::Result<Digest> {
        let mut digest = Digest::default();
        std::io::copy(&mut std::io::Read::take(open_regular(path)?.0, at_most), &mut digest)?;
        Ok(digest)
    }
}

/// Writes to `out` and hashes what it writes.
pub struct Hashed<'a> {
    /// Where the bytes go.
    pub out: &'a mut dyn Write,
    /// What has gone through.
    pub digest: Digest,
}

impl Write for Hashed<'_> {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        let written = self.out.write(bytes)?;
        self.digest.write_all(&bytes[..written])?;
        Ok(written)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.out.flush()
    }
}

impl Write for Digest {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.hasher.update(bytes);
        self.len += bytes.len() as u64;
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// Puts the file at `from` at `to` too, as a hard link where the file system allows one (no byte
/// rewritten) and a copy elsewhere; through a temporary name and a rename, like every write.
/// Returns the bytes copied (0 for a link, or when `to` already has the same length and bytes).
pub fn link_or_copy(from: &Path, to: &Path) -> std::io::Result<u64> {
    // A sandbox (Bazel's) stages a shard's files as links: the file linked is the one they name,
    // so that the output holds files, never links that lead out of it.
    let from = &std::fs::canonicalize(from)?;
    let length = std::fs::metadata(from)?.len();
    let existing = std::fs::metadata(to).ok();
    if existing.as_ref().is_some_and(|m| m.len() == length)
        && Digest::of_file(to, length + 1)?.finish() == Digest::of_file(from, length + 1)?.finish()
    {
        return Ok(0);
    }
    // A link appears whole, so where nothing is in the way it is made under its own name (half
    // the folder operations: a merge links thousands of packs into one folder).
    if existing.is_none()
        && folder_made_for(to).is_ok_and(|_| {
            crash_point();
            std::fs::hard_link(from, to).is_ok()
        })
    {
        return Ok(0);
    }
    // The random name is the link's, or the copy's: both refuse a name that is there already,
    // so neither goes through a file or link someone else made.
    let (staged, file) = Staged::beside(to)?;
    drop(file);
    std::fs::remove_file(&staged.temporary)?;
    let copied = match std::fs::hard_link(from, &staged.temporary) {
        Ok(()) => 0,
        Err(_) => {
            let mut file = std::fs::File::options().write(true).create_new(true).open(&staged.temporary)?;
            let copied = std::io::copy(&mut std::fs::File::open(from)?, &mut file)?;
            durable(&file)?;
            copied
        }
    };
    staged.commit(|_| true)?;
    Ok(copied)
}
