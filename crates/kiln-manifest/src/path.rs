//! The only paths a record kiln wrote may name (a manifest, a shard record, a pass's cache entry,
//! the no-op record): a pack, `modules/<32 hex digits>.<pack extension>`, inside the folder the
//! record belongs to. Records are untrusted (anyone can edit and re-seal one), so a path is
//! checked when the record is read, by serde, and a reader opens only a regular file there and
//! reads at most the length the record gives.

use super::Backend;
use serde::{Deserialize, Serialize};
use std::io::Read;
use std::path::{Path, PathBuf};

/// The folder of an output that holds its packs.
pub const PACK_FOLDER: &str = "modules";

/// The hexadecimal digits of a pack's name (128 bits of BLAKE3).
const HASH_DIGITS: usize = 32;

/// A pack's path relative to the folder a record belongs to: `modules/<hash>.<extension>`, with
/// the hash 32 lowercase hexadecimal digits and the extension one back end's. Nothing else
/// parses, so a path read from a record can name no file outside its folder.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PackPath(String);

/// Why a text is not a [`PackPath`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{}` is not a pack's path (`modules/<32 hex digits>.<extension>`)", .0.escape_debug())]
pub struct NotAPackPath(pub String);

impl PackPath {
    /// The pack of modules whose hashes hash to `hash` for `backend`.
    ///
    /// # Panics
    /// When `hash` is not 32 lowercase hexadecimal digits (kiln's own hashes always are).
    pub fn new(hash: &str, backend: Backend) -> PackPath {
        assert!(is_hash(hash), "a pack is named by a 32-digit hash");
        PackPath(format!("{PACK_FOLDER}/{hash}.{}", backend.pack_extension()))
    }

    /// The path a record's text names, when it is a pack's.
    pub fn parse(text: &str) -> Result<PackPath, NotAPackPath> {
        let refused = || NotAPackPath(text.to_string());
        let name = text.strip_prefix(PACK_FOLDER).and_then(|r| r.strip_prefix('/')).ok_or_else(refused)?;
        let (hash, extension) = name.split_once('.').ok_or_else(refused)?;
        let known = Backend::ALL.iter().any(|backend| backend.pack_extension() == extension);
        if is_hash(hash) && known { Ok(PackPath(text.to_string())) } else { Err(refused()) }
    }

    /// The path as the record writes it, with `/` separators.
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The file name alone (`<hash>.<extension>`), inside [`PACK_FOLDER`].
    pub fn file_name(&self) -> &str {
        &self.0[PACK_FOLDER.len() + 1..]
    }

    /// Where it is under `folder`.
    pub fn under(&self, folder: &Path) -> PathBuf {
        folder.join(PACK_FOLDER).join(self.file_name())
    }

    /// Its bytes under `folder`, at most `at_most` of them (the length its record gives): only a
    /// regular file is read, never a link (which could name any file the user can read), a
    /// device (`/dev/zero` reads until memory runs out) or a pipe.
    pub fn read(&self, folder: &Path, at_most: u64) -> std::io::Result<Vec<u8>> {
        read_regular(&self.under(folder), at_most)
    }

    /// [`PackPath::read`] of a folder a sandbox staged (Bazel stages a shard's files as links
    /// into its own tree): a link is followed, to a regular file only. For a reader that checks
    /// the bytes against a hash its record holds (`kiln merge`), so a link can bring in no bytes
    /// but the ones the record names.
    pub fn read_staged(&self, folder: &Path, at_most: u64) -> std::io::Result<Vec<u8>> {
        read_regular(&std::fs::canonicalize(self.under(folder))?, at_most)
    }
}

/// Whether `text` is a pack's hash: 32 lowercase hexadecimal digits.
fn is_hash(text: &str) -> bool {
    text.len() == HASH_DIGITS && text.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// At most `at_most` bytes of `path`, which must be a regular file and not a link to one. The
/// file is checked again once open, so a link put in its place between the check and the open is
/// refused too (on Linux, where the open itself refuses to follow a link).
pub fn read_regular(path: &Path, at_most: u64) -> std::io::Result<Vec<u8>> {
    let (file, length) = open_regular(path)?;
    let mut bytes = Vec::with_capacity(length.min(at_most) as usize);
    file.take(at_most).read_to_end(&mut bytes)?;
    Ok(bytes)
}

/// `path` opened for reading, with its length, when it is a regular file and not a link to one
/// (see [`read_regular`]).
pub fn open_regular(path: &Path) -> std::io::Result<(std::fs::File, u64)> {
    let not_regular = || {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("`{}` is not a regular file", path.display()),
        )
    };
    if !std::fs::symlink_metadata(path)?.file_type().is_file() {
        return Err(not_regular());
    }
    let file = open_no_follow(path)?;
    let metadata = file.metadata()?;
    if !metadata.file_type().is_file() {
        return Err(not_regular());
    }
    Ok((file, metadata.len()))
}

#[cfg(target_os = "linux")]
fn open_no_follow(path: &Path) -> std::io::Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new().read(true).custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK).open(path)
}

#[cfg(not(target_os = "linux"))]
fn open_no_follow(path: &Path) -> std::io::Result<std::fs::File> {
    std::fs::File::open(path)
}

impl std::fmt::Display for PackPath {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::borrow::Borrow<str> for PackPath {
    fn borrow(&self) -> &str {
        &self.0
    }
}

/// Relative to the folder its record belongs to, and confined to it: `folder.join(pack)`.
impl AsRef<Path> for PackPath {
    fn as_ref(&self) -> &Path {
        Path::new(&self.0)
    }
}

impl AsRef<str> for PackPath {
    fn as_ref(&self) -> &str {
        &self.0
    }
}

impl Serialize for PackPath {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.0)
    }
}

impl<'de> Deserialize<'de> for PackPath {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let text = std::borrow::Cow::<str>::deserialize(deserializer)?;
        PackPath::parse(&text).map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HASH: &str = "0123456789abcdef0123456789abcdef";

    #[test]
    fn only_a_pack_in_the_pack_folder_parses() {
        for backend in Backend::ALL {
            let path = PackPath::new(HASH, *backend);
            assert_eq!(PackPath::parse(path.as_str()), Ok(path.clone()));
        }
        for hostile in [
            "../../../../../../../../../../etc/hostname",
            "/etc/hostname",
            "modules/../../s1/payload.spv.pack",
            "modules/0123456789abcdef0123456789abcdef.spv.pack/../../x",
            "modules/0123456789ABCDEF0123456789ABCDEF.spv.pack",
            "modules/0123456789abcdef0123456789abcde.spv.pack",
            "modules/0123456789abcdef0123456789abcdef.exe",
            "modules\\0123456789abcdef0123456789abcdef.spv.pack",
            "./modules/0123456789abcdef0123456789abcdef.spv.pack",
            "modules//0123456789abcdef0123456789abcdef.spv.pack",
            "",
        ] {
            assert!(PackPath::parse(hostile).is_err(), "{hostile:?} parsed");
        }
    }

    #[test]
    fn a_record_naming_a_path_outside_its_folder_does_not_deserialize() {
        let refused: Result<Vec<PackPath>, _> = serde_json::from_str(r#"["../../etc/hostname"]"#);
        assert!(refused.unwrap_err().to_string().contains("is not a pack's path"));
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn a_link_a_device_or_a_folder_in_a_packs_place_is_not_read() {
        let dir = tempfile::tempdir().expect("tempdir");
        let path = PackPath::new(HASH, Backend::Spirv);
        std::fs::create_dir_all(dir.path().join(PACK_FOLDER)).expect("mkdir");
        std::os::unix::fs::symlink("/etc/hostname", path.under(dir.path())).expect("link");
        assert!(path.read(dir.path(), 1 << 20).is_err(), "a link was followed");
        std::fs::remove_file(path.under(dir.path())).expect("remove");
        std::os::unix::fs::symlink("/dev/zero", path.under(dir.path())).expect("link");
        assert!(path.read(dir.path(), u64::MAX).is_err(), "a link to a device was read");
        std::fs::remove_file(path.under(dir.path())).expect("remove");
        std::fs::create_dir(path.under(dir.path())).expect("mkdir");
        assert!(path.read(dir.path(), 16).is_err(), "a folder was read");
        std::fs::remove_dir(path.under(dir.path())).expect("remove");
        std::fs::write(path.under(dir.path()), b"0123456789").expect("write");
        assert_eq!(path.read(dir.path(), 4).expect("read"), b"0123", "read past the length given");
        assert!(read_regular(Path::new("/dev/zero"), 16).is_err(), "a device was read");
    }
}
