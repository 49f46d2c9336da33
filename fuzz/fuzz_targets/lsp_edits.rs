//! Any bytes as a sequence of edits to the example project's `LitPass.wgsl`, open in an
//! in-process `kiln lsp`: after each edit the server must answer hover, completion and definition
//! at the edit, and it must end cleanly. Each edit is two bytes of start offset, one of length
//! removed, then the text inserted, up to a 0xFF byte.
#![no_main]

#[path = "../../tests/it/lsp_edits.rs"]
mod lsp_edits;

use libfuzzer_sys::fuzz_target;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn scratch() -> &'static Path {
    static SCRATCH: OnceLock<PathBuf> = OnceLock::new();
    SCRATCH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("kiln-fuzz-lsp-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("scratch folder");
        dir
    })
}

fuzz_target!(|data: &[u8]| {
    let edits: Vec<lsp_edits::Edit> = data
        .split(|&b| b == 0xFF)
        .take(16)
        .filter_map(|chunk| {
            let (head, text) = (chunk.get(..3)?, &chunk[3..]);
            Some(lsp_edits::Edit {
                start: usize::from(u16::from_le_bytes([head[0], head[1]])),
                removed: usize::from(head[2]),
                inserted: String::from_utf8_lossy(text).into_owned(),
            })
        })
        .collect();
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/project/shaders/LitPass.wgsl");
    lsp_edits::replay(&file, scratch(), &edits);
});
