//! The build's files: content-addressed stage modules, the cache that lets an unchanged variant
//! skip naga entirely, and atomic writes (a temporary file and a rename) for all of them.

use super::bind::Declared;
use crate::reflect::StageReflection;
use crate::reflect::manifest::FileRef;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// A content hash: BLAKE3, 128 bits in hexadecimal.
pub fn hash(bytes: &[u8]) -> String {
    let digest = blake3::hash(bytes);
    digest.to_hex()[..32].to_string()
}

/// What the cache remembers of a compiled stage module.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CachedStage {
    pub wgsl: Option<FileRef>,
    pub spirv: Option<FileRef>,
    pub reflection: StageReflection,
}

pub struct Cache {
    output: PathBuf,
    /// `kiln check` reads the cache but writes nothing.
    write: bool,
}

impl Cache {
    pub fn new(output: &Path, write: bool) -> Cache {
        Cache { output: output.to_path_buf(), write }
    }

    fn entry(&self, kind: &str, key: &str) -> PathBuf {
        self.output.join(".cache").join(kind).join(format!("{key}.json"))
    }

    fn read<T: for<'de> Deserialize<'de>>(&self, kind: &str, key: &str) -> Option<T> {
        // An unreadable or damaged entry is a miss: the work is redone, never trusted.
        let bytes = std::fs::read(self.entry(kind, key)).ok()?;
        serde_json::from_slice(&bytes).ok()
    }

    fn put<T: Serialize>(&self, kind: &str, key: &str, value: &T) -> std::io::Result<()> {
        if !self.write {
            return Ok(());
        }
        let bytes = serde_json::to_vec(value).map_err(std::io::Error::other)?;
        write_atomically(&self.entry(kind, key), &bytes)
    }

    /// The resources a preprocessed text declares, by the text's hash.
    pub fn front(&self, text_hash: &str) -> Option<Vec<Declared>> {
        self.read("front", text_hash)
    }

    pub fn put_front(&self, text_hash: &str, declared: &[Declared]) -> std::io::Result<()> {
        self.put("front", text_hash, &declared)
    }

    /// A compiled stage module, if its files are still in place.
    pub fn stage(&self, key: &str) -> Option<CachedStage> {
        let cached: CachedStage = self.read("stage", key)?;
        let present = |file: &Option<FileRef>| {
            file.as_ref()
                .is_none_or(|f| std::fs::metadata(self.output.join(&f.path)).is_ok_and(|m| m.len() == f.size))
        };
        (present(&cached.wgsl) && present(&cached.spirv)).then_some(cached)
    }

    pub fn put_stage(&self, key: &str, stage: &CachedStage) -> std::io::Result<()> {
        self.put("stage", key, stage)
    }

    /// Stores a module's bytes under their hash (`modules/HASH.EXT`); returns the reference and
    /// the bytes written (0 when the file was already there).
    pub fn module(&self, bytes: &[u8], extension: &str) -> std::io::Result<(FileRef, u64)> {
        let hash = hash(bytes);
        let path = format!("modules/{hash}.{extension}");
        let full = self.output.join(&path);
        let size = bytes.len() as u64;
        let present = std::fs::metadata(&full).is_ok_and(|m| m.len() == size);
        let written = if self.write && !present {
            write_atomically(&full, bytes)?;
            size
        } else {
            0
        };
        Ok((FileRef { path, hash, size }, written))
    }
}

/// Writes through a temporary file in the same folder and a rename, so a reader never sees half a
/// file and a failed or interrupted write leaves the old one.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    std::fs::create_dir_all(folder)?;
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let temporary = folder.join(format!(".{name}.{}.tmp", std::process::id()));
    std::fs::write(&temporary, bytes)?;
    std::fs::rename(&temporary, path).inspect_err(|_| {
        let _ = std::fs::remove_file(&temporary);
    })
}
