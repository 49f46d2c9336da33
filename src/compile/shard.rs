//! Stage modules as objects, for work shared past one build:
//!
//! - sharded builds: `kiln build --shard I/N` compiles the stage modules whose key falls to shard I
//!   (a stable hash of what is compiled, so shards stay balanced whatever one shader weighs, and a
//!   module stays in its shard when others come and go) and stores each as an object in its
//!   output folder; `kiln merge` then builds the project with those objects standing in for naga,
//!   which gives the bytes a single build gives;
//! - the shared cache (`cache_dir`): the same objects, and each pass's parsed resources, in a
//!   folder that builds, processes and machines read and write at once. Entries are published by
//!   a rename (never seen half written), verified on every read (a damaged one is a miss), and
//!   their modification time is their last use, for `kiln cache gc`.

use super::cache::{ModuleBytes, hash, write_atomically};
use crate::reflect::StageReflection;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Which part of the work a build does: shard `index` (0-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    /// `I/N` with 1 ≤ I ≤ N, as the command line takes it.
    pub fn parse(text: &str) -> Result<Shard, String> {
        let bad = || format!("`{text}` is not a shard: write I/N with 1 <= I <= N, like 2/4");
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let (i, n): (u32, u32) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if i == 0 || i > n {
            return Err(bad());
        }
        Ok(Shard { index: i - 1, count: n })
    }

    /// Whether the stage module with this key is this shard's to compile.
    pub fn owns(&self, key: &str) -> bool {
        let head = u64::from_str_radix(key.get(..16).unwrap_or(key), 16).unwrap_or(0);
        head % u64::from(self.count) == u64::from(self.index)
    }
}

/// `shard.json`, at the top of a shard's output folder.
pub const SHARD_FILE: &str = "shard.json";

/// Where a shard's stage modules are, in its output folder.
const OBJECTS: &str = "objects";

/// What `kiln merge` checks before trusting a shard.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShardRecord {
    pub kiln_version: String,
    /// The hash of everything the build read and its options: shards of one merge share it.
    pub inputs: String,
    /// 1-based, as given.
    pub shard: u32,
    pub count: u32,
    /// The project folder as the shard build was given it.
    pub project: String,
    /// Stage modules this shard holds.
    pub modules: usize,
}

impl ShardRecord {
    pub fn read(folder: &Path) -> Result<ShardRecord, String> {
        let path = folder.join(SHARD_FILE);
        let bytes = std::fs::read(&path)
            .map_err(|e| format!("`{}` is not a shard's output: {e}", folder.display()))?;
        serde_json::from_slice(&bytes).map_err(|e| format!("`{}` is damaged: {e}", path.display()))
    }
}

/// A stage module as a shard stores it: one file per key, a JSON line (reflection, and each
/// backend's size and hash) and then the modules' bytes. Written whole or not at all; a file
/// whose bytes do not match their hashes is not a module.
#[derive(Serialize, Deserialize)]
struct ObjectHeader {
    reflection: StageReflection,
    modules: [Option<(u64, String)>; 2],
}

fn object_path(folder: &Path, key: &str) -> PathBuf {
    folder.join(OBJECTS).join(&key[..2.min(key.len())]).join(key)
}

pub(super) fn write_object(
    folder: &Path,
    key: &str,
    modules: &[Option<ModuleBytes>; 2],
    reflection: &StageReflection,
) -> std::io::Result<u64> {
    let header = ObjectHeader {
        reflection: reflection.clone(),
        modules: [0, 1].map(|i| modules[i].as_ref().map(|m| (m.bytes.len() as u64, m.hash.clone()))),
    };
    let mut bytes = serde_json::to_vec(&header).map_err(std::io::Error::other)?;
    bytes.push(b'\n');
    for module in modules.iter().flatten() {
        bytes.extend_from_slice(&module.bytes);
    }
    write_atomically(&object_path(folder, key), &bytes)?;
    Ok(bytes.len() as u64)
}

/// A stored module, or `None` when there is none or it is damaged.
pub(super) fn read_object(folder: &Path, key: &str) -> Option<([Option<ModuleBytes>; 2], StageReflection)> {
    let bytes = std::fs::read(object_path(folder, key)).ok()?;
    let split = bytes.iter().position(|&b| b == b'\n')?;
    let header: ObjectHeader = serde_json::from_slice(&bytes[..split]).ok()?;
    let mut at = split + 1;
    let mut modules: [Option<ModuleBytes>; 2] = [None, None];
    for (slot, entry) in header.modules.iter().enumerate() {
        let Some((size, expected)) = entry else { continue };
        let body = bytes.get(at..at + *size as usize)?;
        if hash(body) != *expected {
            return None;
        }
        modules[slot] = Some(ModuleBytes { bytes: body.to_vec(), hash: expected.clone() });
        at += *size as usize;
    }
    (at == bytes.len()).then_some((modules, header.reflection))
}

/// A module from the shared cache, marked as used now (for `kiln cache gc`), or `None`.
pub(super) fn fetch_object(folder: &Path, key: &str) -> Option<([Option<ModuleBytes>; 2], StageReflection)> {
    let found = read_object(folder, key)?;
    touch(&object_path(folder, key));
    Some(found)
}

/// Publishes a module to the shared cache, unless it is there (same key, same bytes).
pub(super) fn publish_object(
    folder: &Path,
    key: &str,
    modules: &[Option<ModuleBytes>; 2],
    reflection: &StageReflection,
) {
    if !object_path(folder, key).is_file() {
        // A cache that cannot be written only costs speed.
        let _ = write_object(folder, key, modules, reflection);
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

/// A pass's parsed resources from the shared cache (empty when there are none or they are
/// damaged).
pub(super) fn read_layouts(
    folder: &Path,
    pass: &str,
) -> std::collections::BTreeMap<String, Vec<super::bind::Declared>> {
    let path = layouts_path(folder, pass);
    let read = || {
        let bytes = std::fs::read(&path).ok()?;
        let split = bytes.iter().position(|&b| b == b'\n')?;
        let json = &bytes[split + 1..];
        (bytes[..split] == *hash(json).as_bytes()).then(|| serde_json::from_slice(json).ok())?
    };
    let found = read().unwrap_or_default();
    touch(&path);
    found
}

/// Publishes a pass's parsed resources, joined with what the cache already has for the pass (the
/// same file in another project, another variant set): entries are by text hash, so joining is
/// always right; two builds publishing at once may lose each other's additions, a miss later.
pub(super) fn publish_layouts(
    folder: &Path,
    pass: &str,
    layouts: &std::collections::BTreeMap<String, Vec<super::bind::Declared>>,
) {
    let mut all = read_layouts(folder, pass);
    let before = all.len();
    for (text, declared) in layouts {
        all.entry(text.clone()).or_insert_with(|| declared.clone());
    }
    if all.len() == before && before > 0 {
        return;
    }
    let Ok(json) = serde_json::to_vec(&all) else { return };
    let mut bytes = hash(&json).into_bytes();
    bytes.push(b'\n');
    bytes.extend(json);
    let _ = write_atomically(&layouts_path(folder, pass), &bytes);
}

/// What `kiln cache stats` prints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CacheStats {
    pub modules: usize,
    pub layouts: usize,
    pub bytes: u64,
    /// Modules whose bytes no longer match their hashes (misses until gc removes them).
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

pub fn cache_stats(folder: &Path) -> std::io::Result<CacheStats> {
    let mut stats = CacheStats::default();
    for (path, size, _) in entries(folder)? {
        stats.bytes += size;
        if path.starts_with(folder.join(OBJECTS)) {
            stats.modules += 1;
            let key = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            stats.damaged += usize::from(read_object(folder, &key).is_none());
        } else {
            stats.layouts += 1;
        }
    }
    Ok(stats)
}

/// Removes damaged modules, then the least recently used entries until the cache holds at most
/// `limit` bytes. Returns how many were removed and the bytes left. A build running meanwhile
/// loses nothing but the entries' use: an entry gone is a miss, and it is compiled again.
pub fn cache_gc(folder: &Path, limit: u64) -> std::io::Result<(usize, u64)> {
    let mut all = entries(folder)?;
    let mut removed = 0;
    all.retain(|(path, _, _)| {
        let key = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let damaged = path.starts_with(folder.join(OBJECTS)) && read_object(folder, &key).is_none();
        if damaged && std::fs::remove_file(path).is_ok() {
            removed += 1;
        }
        !damaged
    });
    all.sort_by_key(|(_, _, used)| *used);
    let mut total: u64 = all.iter().map(|(_, size, _)| size).sum();
    for (path, size, _) in all {
        if total <= limit {
            break;
        }
        // Another gc may have removed it first.
        if std::fs::remove_file(&path).is_ok() {
            removed += 1;
        }
        total -= size;
    }
    Ok((removed, total))
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

/// Shard outputs to merge, checked against each other: one kiln version, one count, every shard
/// once. Returns the inputs hash they share (checked against the project by the build).
pub fn check_shards(folders: &[PathBuf]) -> Result<(Vec<ShardRecord>, String), String> {
    let records = folders.iter().map(|f| ShardRecord::read(f)).collect::<Result<Vec<_>, _>>()?;
    let Some(first) = records.first() else { return Err("no shard outputs to merge".into()) };
    for (record, folder) in records.iter().zip(folders) {
        let differs = |what: &str| {
            Err(format!(
                "`{}` is shard {}/{} of {what} than `{}`; shards of one merge come from one build",
                folder.display(),
                record.shard,
                record.count,
                folders[0].display()
            ))
        };
        if record.kiln_version != first.kiln_version {
            return differs(&format!("kiln {} rather", record.kiln_version));
        }
        if record.count != first.count {
            return differs("a different number of shards");
        }
        if record.inputs != first.inputs {
            return differs("another project, another state of it, or other options");
        }
    }
    if first.kiln_version != env!("CARGO_PKG_VERSION") {
        return Err(format!(
            "the shards were built by kiln {}, this is kiln {}",
            first.kiln_version,
            env!("CARGO_PKG_VERSION")
        ));
    }
    let mut seen = vec![Vec::new(); first.count as usize];
    for (record, folder) in records.iter().zip(folders) {
        if let Some(slot) = seen.get_mut(record.shard as usize - 1) {
            slot.push(folder.display().to_string());
        }
    }
    for (i, holders) in seen.iter().enumerate() {
        match holders.len() {
            0 => return Err(format!("shard {}/{} is missing", i + 1, first.count)),
            1 => {}
            _ => {
                return Err(format!(
                    "shard {}/{} is given twice: {}",
                    i + 1,
                    first.count,
                    holders.join(", ")
                ));
            }
        }
    }
    let inputs = first.inputs.clone();
    Ok((records, inputs))
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

    #[test]
    fn shards_parse_and_split_keys_evenly() {
        assert_eq!(Shard::parse("2/4"), Ok(Shard { index: 1, count: 4 }));
        for bad in ["0/4", "5/4", "4", "a/b", "1/0"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        let shards: Vec<Shard> = (1..=4).map(|i| Shard::parse(&format!("{i}/4")).expect("shard")).collect();
        let keys: Vec<String> = (0..4000).map(|i| hash(format!("module {i}").as_bytes())).collect();
        for key in &keys {
            assert_eq!(shards.iter().filter(|s| s.owns(key)).count(), 1, "each key has one owner");
        }
        for shard in &shards {
            let owned = keys.iter().filter(|k| shard.owns(k)).count();
            assert!((800..1200).contains(&owned), "balanced: {owned} of 4000");
        }
    }
}
