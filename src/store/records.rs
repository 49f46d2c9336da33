//! The names the records of an output folder give its files: a pass's key (its cache entry's
//! file) and the files the no-op record vouches for; and the findings the no-op record keeps.
//! Records are untrusted (anyone can edit and seal one again), so each name parses into a type
//! that can name nothing else, and each finding's place is verified before it is said.

use super::cache::hash;
use crate::manifest::PackPath;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Identifies a pass across builds: a [`hash`] of its shader file and place. It names the pass's
/// cache entry (`.cache/pass/<key>.json`) and is read from shard records, so nothing but 32
/// lowercase hexadecimal digits parses.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(transparent)]
pub struct PassKey(String);

impl PassKey {
    /// The key of the pass whose identity (shader file and place) reads `identity`.
    pub fn of(identity: &str) -> PassKey {
        PassKey(hash(identity.as_bytes()))
    }

    /// The key as text.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl std::ops::Deref for PassKey {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl<'de> Deserialize<'de> for PassKey {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = String::deserialize(deserializer)?;
        let hex = text.len() == 32 && text.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b));
        if hex {
            Ok(PassKey(text))
        } else {
            Err(serde::de::Error::custom(format_args!("`{}` is not a pass's key", text.escape_debug())))
        }
    }
}

/// A file a build leaves in its output folder, as the no-op record names it: the manifest, the
/// materials or a pack, and nothing else (a record is untrusted: anyone can edit and re-seal it).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub enum OutputFile {
    /// `manifest.json`.
    Manifest,
    /// `materials.json`.
    Materials,
    /// A pack of modules.
    Pack(PackPath),
}

impl OutputFile {
    /// Its path relative to the output folder, with `/` separators.
    pub fn as_str(&self) -> &str {
        match self {
            OutputFile::Manifest => crate::manifest::FILE_NAME,
            OutputFile::Materials => crate::manifest::MATERIALS_FILE,
            OutputFile::Pack(pack) => pack.as_str(),
        }
    }

    /// Where it is under `output`.
    pub fn under(&self, output: &Path) -> PathBuf {
        match self {
            OutputFile::Pack(pack) => pack.under(output),
            _ => output.join(self.as_str()),
        }
    }
}

impl Serialize for OutputFile {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

impl<'de> Deserialize<'de> for OutputFile {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = std::borrow::Cow::<str>::deserialize(deserializer)?;
        match &*text {
            crate::manifest::FILE_NAME => Ok(OutputFile::Manifest),
            crate::manifest::MATERIALS_FILE => Ok(OutputFile::Materials),
            pack => PackPath::parse(pack).map(OutputFile::Pack).map_err(serde::de::Error::custom),
        }
    }
}

/// A warning or remark a clean build reported, as its record keeps it: every place is a file of
/// the record's `read`, by its index there, and the bytes it spans. Nothing in it is trusted:
/// the no-op check verifies each place against the file it names before saying it again.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordedFinding {
    /// How serious it is (an error is never recorded, and refused when read).
    pub severity: crate::diagnostics::Severity,
    /// Its code, which must be registered.
    pub code: String,
    /// What is wrong.
    pub message: String,
    /// The primary place, then the others.
    pub labels: Vec<RecordedLabel>,
    /// Further facts.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// What to do about it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub help: Option<String>,
    /// The variants it occurs in.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub occurrence: Option<crate::diagnostics::Occurrence>,
}

/// A place in a [`RecordedFinding`]: the `file`-th of the files read, bytes `start..end`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordedLabel {
    /// Its index in the record's `read`.
    pub file: usize,
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
    /// What is there.
    pub message: String,
}
