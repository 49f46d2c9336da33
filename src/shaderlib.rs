//! The bundled shader library (`shaderlib/`: WGSL, and an HLSL mirror of it), embedded at build
//! time by `build.rs`.
//! `#include "Common.wgsl"` finds these files after the including file's folder and the
//! project's include paths.

include!(concat!(env!("OUT_DIR"), "/shaderlib.rs"));

/// The text of a bundled library file, by file name (`"Common.wgsl"`).
pub fn file(name: &str) -> Option<&'static str> {
    FILES.iter().find(|(file, _)| *file == name).map(|(_, text)| *text)
}

/// A digest of the bundled library (every file's name and text), recorded with each build: a
/// library edited without a new kiln version number (a git dependency, kiln's own development)
/// still makes the next build compile again instead of passing for a no-op.
pub fn digest() -> &'static str {
    static DIGEST: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    DIGEST.get_or_init(|| {
        let mut hasher = blake3::Hasher::new();
        for (name, text) in FILES {
            for part in [name.as_bytes(), text.as_bytes()] {
                hasher.update(&(part.len() as u64).to_le_bytes());
                hasher.update(part);
            }
        }
        hasher.finalize().to_hex()[..16].to_string()
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn embedded_files_match_the_folder() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaderlib");
        let mut on_disk = 0;
        for entry in std::fs::read_dir(dir).expect("shaderlib/") {
            let path = entry.expect("entry").path();
            let name = path.file_name().expect("name").to_string_lossy().into_owned();
            if name.ends_with(".wgsl") || name.ends_with(".hlsl") {
                on_disk += 1;
                let text = std::fs::read_to_string(&path).expect("UTF-8");
                assert_eq!(super::file(&name), Some(text.as_str()), "{name}");
            }
        }
        assert!(on_disk > 0);
        assert_eq!(super::FILES.len(), on_disk);
    }
}
