//! The module cache builds share (`cache_dir`): stage modules as objects, one file per content
//! key (a JSON line with the reflection and each backend's size and hash, then the bytes), and
//! each pass's parsed resources, in a folder that builds, processes and machines use at once.
//! Entries are published by a rename (never seen half written), sealed to their key (header,
//! reflection and bytes under one hash with the key and the compiler inside) and verified on every
//! read: a damaged, misplaced or other compiler's entry is a miss. An entry's modification time is
//! its last use, for `kiln cache gc`. The trust model is in docs/security.md: whoever may write the
//! folder is trusted as much as the build's own compiler.

use super::cache::{ModuleBytes, hash, seal, sealed, unsealed, write_atomically};
use crate::compile::bind::Declared;
use crate::manifest::PerBackend;
use crate::reflect::StageReflection;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Where objects are, in a shard's output folder or the shared cache.
const OBJECTS: &str = "objects";

/// A stage module as an object: one file per key, a line with the [`seal`] of the rest under
/// the key, a JSON line (the key, the compiler, the reflection, and each backend's size and hash)
/// and then the modules' bytes. Written whole or not at all; a file whose seal, key or compiler
/// does not match is not the module asked for.
#[derive(Serialize, Deserialize)]
struct ObjectHeader {
    key: String,
    compiler: String,
    reflection: StageReflection,
    modules: PerBackend<Option<(u64, String)>>,
}

fn object_path(folder: &Path, key: &str) -> PathBuf {
    folder.join(OBJECTS).join(&key[..2.min(key.len())]).join(key)
}

/// A module's bytes as an object: the seal line, the header line, then the modules' bytes (what
/// the shared cache stores in a file and a remote cache under its SHA-256).
pub(super) fn object_bytes(
    key: &str,
    compiler: &str,
    modules: &PerBackend<Option<ModuleBytes>>,
    reflection: &StageReflection,
) -> std::io::Result<Vec<u8>> {
    let header = ObjectHeader {
        key: key.to_string(),
        compiler: compiler.to_string(),
        reflection: reflection.clone(),
        modules: PerBackend::from_fn(|b| modules[b].as_ref().map(|m| (m.bytes.len() as u64, m.hash.clone()))),
    };
    let mut body = serde_json::to_vec(&header).map_err(std::io::Error::other)?;
    body.push(b'\n');
    for module in modules.values().flatten() {
        body.extend_from_slice(&module.bytes);
    }
    let mut bytes = seal(key, &body).into_bytes();
    bytes.push(b'\n');
    bytes.extend(body);
    Ok(bytes)
}

fn write_object(
    folder: &Path,
    key: &str,
    compiler: &str,
    modules: &PerBackend<Option<ModuleBytes>>,
    reflection: &StageReflection,
) -> std::io::Result<u64> {
    let bytes = object_bytes(key, compiler, modules, reflection)?;
    write_atomically(&object_path(folder, key), &bytes)?;
    Ok(bytes.len() as u64)
}

/// A stored module, or `None` when there is none, or it is damaged, another key's or (given
/// `compiler`) another compiler's.
fn read_object(
    folder: &Path,
    key: &str,
    compiler: Option<&str>,
) -> Option<(PerBackend<Option<ModuleBytes>>, StageReflection)> {
    parse_object(&std::fs::read(object_path(folder, key)).ok()?, key, compiler)
}

/// The module in an object's bytes ([`object_bytes`]), if it is sealed under `key`, made by
/// `compiler` (when given) and each module's bytes are what its hash says.
pub(super) fn parse_object(
    file: &[u8],
    key: &str,
    compiler: Option<&str>,
) -> Option<(PerBackend<Option<ModuleBytes>>, StageReflection)> {
    let sealed_at = file.iter().position(|&b| b == b'\n')?;
    let bytes = &file[sealed_at + 1..];
    if file[..sealed_at] != *seal(key, bytes).as_bytes() {
        return None;
    }
    let split = bytes.iter().position(|&b| b == b'\n')?;
    let header: ObjectHeader = serde_json::from_slice(&bytes[..split]).ok()?;
    if header.key != key || compiler.is_some_and(|c| c != header.compiler) {
        return None;
    }
    let mut at = split + 1;
    let mut modules: PerBackend<Option<ModuleBytes>> = PerBackend::default();
    for (slot, entry) in header.modules.iter() {
        let Some((size, expected)) = entry else { continue };
        let body = bytes.get(at..at.checked_add(usize::try_from(*size).ok()?)?)?;
        if hash(body) != *expected {
            return None;
        }
        modules[slot] = Some(ModuleBytes { bytes: body.to_vec(), hash: expected.clone() });
        at += body.len();
    }
    (at == bytes.len()).then_some((modules, header.reflection))
}

/// A module from the shared cache, stored under `key` by `compiler` (kiln's version and revision,
/// naga's), marked as used now (for `kiln cache gc`), or `None`.
pub fn fetch_object(
    folder: &Path,
    key: &str,
    compiler: &str,
) -> Option<(PerBackend<Option<ModuleBytes>>, StageReflection)> {
    let found = read_object(folder, key, Some(compiler))?;
    touch(&object_path(folder, key));
    Some(found)
}

/// Publishes a module to the shared cache, unless it is there (same key, same bytes).
pub fn publish_object(
    folder: &Path,
    key: &str,
    compiler: &str,
    modules: &PerBackend<Option<ModuleBytes>>,
    reflection: &StageReflection,
) {
    // One there already is replaced only when it is not this key's (damaged, misplaced).
    if read_object(folder, key, Some(compiler)).is_none() {
        // A cache that cannot be written only costs speed.
        let _ = write_object(folder, key, compiler, modules, reflection);
    }
}

fn touch(path: &Path) {
    if let Ok(file) = std::fs::File::options().write(true).open(path) {
        let _ = file.set_modified(std::time::SystemTime::now());
    }
}

/// Where the shared cache keeps a pass's parsed resources (by stage text hash).
fn layouts_path(folder: &Path, pass: &str) -> PathBuf {
    folder.join("layouts").join(format!("{pass}.json"))
}

/// What a pass's layouts are sealed under (in the shared folder and on a remote cache).
pub(super) fn layouts_key(pass: &str) -> String {
    format!("layouts/{pass}")
}

/// A pass's layouts from bytes sealed under `key`, or none when they are not what was sealed.
pub(super) fn parse_layouts(
    key: &str,
    bytes: &[u8],
) -> Option<std::collections::BTreeMap<String, Vec<Declared>>> {
    serde_json::from_slice(unsealed(key, bytes)?).ok()
}

/// What a store holds for a pass (`known`) joined with what a build parsed, sealed under the
/// pass, or `None` when it adds nothing. Entries are by text hash, so joining is always right.
pub(super) fn joined_layouts(
    pass: &str,
    mut known: std::collections::BTreeMap<String, Vec<Declared>>,
    layouts: &std::collections::BTreeMap<String, Vec<Declared>>,
) -> Option<Vec<u8>> {
    let before = known.len();
    for (text, declared) in layouts {
        known.entry(text.clone()).or_insert_with(|| declared.clone());
    }
    if known.len() == before && before > 0 {
        return None;
    }
    sealed(&layouts_key(pass), &known).ok()
}

/// A pass's parsed resources from the shared cache (empty when there are none or they are
/// damaged).
pub fn read_layouts(folder: &Path, pass: &str) -> std::collections::BTreeMap<String, Vec<Declared>> {
    let path = layouts_path(folder, pass);
    let found =
        std::fs::read(&path).ok().and_then(|b| parse_layouts(&layouts_key(pass), &b)).unwrap_or_default();
    touch(&path);
    found
}

/// Publishes a pass's parsed resources, joined with what the cache already has for the pass (the
/// same file in another project, another variant set, [`joined_layouts`]); two builds publishing
/// at once may lose each other's additions, a miss later.
pub fn publish_layouts(
    folder: &Path,
    pass: &str,
    layouts: &std::collections::BTreeMap<String, Vec<Declared>>,
) {
    if let Some(bytes) = joined_layouts(pass, read_layouts(folder, pass), layouts) {
        let _ = write_atomically(&layouts_path(folder, pass), &bytes);
    }
}

/// What `kiln cache stats` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CacheStats {
    /// Stage modules in the cache.
    pub modules: usize,
    /// Passes with parsed resources in the cache.
    pub layouts: usize,
    /// Bytes in all.
    pub bytes: u64,
    /// Modules that are not what their key names: bytes or header damaged, or moved from another
    /// key (misses until gc removes them).
    pub damaged: usize,
}

/// Every entry of a shared cache: path, size, last use.
fn entries(folder: &Path) -> std::io::Result<Vec<(PathBuf, u64, std::time::SystemTime)>> {
    let mut found = Vec::new();
    for sub in [OBJECTS, "layouts"] {
        let root = folder.join(sub);
        if !root.is_dir() {
            continue;
        }
        for entry in walkdir::WalkDir::new(&root) {
            let entry = entry.map_err(std::io::Error::other)?;
            // Temporary files of writes in progress are not entries.
            let name = entry.file_name().to_string_lossy();
            if !entry.file_type().is_file() || name.starts_with('.') {
                continue;
            }
            let Ok(meta) = entry.metadata() else { continue };
            found.push((entry.into_path(), meta.len(), meta.modified().unwrap_or(std::time::UNIX_EPOCH)));
        }
    }
    Ok(found)
}

/// Counts the entries of the cache in `folder`, and the damaged ones.
pub fn cache_stats(folder: &Path) -> std::io::Result<CacheStats> {
    let mut stats = CacheStats::default();
    for (path, size, _) in entries(folder)? {
        stats.bytes += size;
        if path.starts_with(folder.join(OBJECTS)) {
            stats.modules += 1;
            let key = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            stats.damaged += usize::from(read_object(folder, &key, None).is_none());
        } else {
            stats.layouts += 1;
        }
    }
    Ok(stats)
}

/// Removes damaged modules, then the least recently used entries until the cache holds at most
/// `limit` bytes. Returns how many were removed and the bytes left, counting only what was really
/// removed; an entry that could not be removed (a read-only cache) is an error naming it, after the
/// rest is done. A build running meanwhile loses nothing but the entries' use: an entry gone is a
/// miss, and it is compiled again.
pub fn cache_gc(folder: &Path, limit: u64) -> std::io::Result<(usize, u64)> {
    let mut all = entries(folder)?;
    let mut removed = 0;
    let mut failed: Option<(PathBuf, std::io::Error)> = None;
    let mut remove = |path: &Path| match std::fs::remove_file(path) {
        Ok(()) => {
            removed += 1;
            true
        }
        // Another gc removed it first.
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => true,
        Err(error) => {
            failed.get_or_insert((path.to_path_buf(), error));
            false
        }
    };
    all.retain(|(path, _, _)| {
        let key = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let damaged = path.starts_with(folder.join(OBJECTS)) && read_object(folder, &key, None).is_none();
        !(damaged && remove(path))
    });
    all.sort_by_key(|(_, _, used)| *used);
    let mut total: u64 = all.iter().map(|(_, size, _)| size).sum();
    for (path, size, _) in all {
        if total <= limit {
            break;
        }
        if remove(&path) {
            total -= size;
        }
    }
    match failed {
        Some((path, error)) => Err(std::io::Error::new(
            error.kind(),
            format!("removed {removed} entries but not `{}` ({error}); {total} bytes left", path.display()),
        )),
        None => Ok((removed, total)),
    }
}

/// `500M`, `2G`, `64K` or a number of bytes.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let text = text.trim();
    let (digits, unit) = text.split_at(text.find(|c: char| !c.is_ascii_digit()).unwrap_or(text.len()));
    let scale: u64 = match unit.to_ascii_uppercase().trim_end_matches(['B', 'I']) {
        "" => 1,
        "K" => 1 << 10,
        "M" => 1 << 20,
        "G" => 1 << 30,
        "T" => 1 << 40,
        _ => return Err(format!("`{text}` is not a size: write bytes, or a number and K, M, G or T")),
    };
    let n: u64 = digits
        .parse()
        .map_err(|_| format!("`{text}` is not a size: write bytes, or a number and K, M, G or T"))?;
    Ok(n.saturating_mul(scale))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse() {
        assert_eq!(parse_size("500M"), Ok(500 << 20));
        assert_eq!(parse_size("2G"), Ok(2 << 30));
        assert_eq!(parse_size("64KiB"), Ok(64 << 10));
        assert_eq!(parse_size("1000"), Ok(1000));
        assert!(parse_size("lots").is_err() && parse_size("5X").is_err());
    }
}
