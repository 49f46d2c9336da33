//! Any text as a WGSL program (the bundled library reachable), preprocessed with keywords taken
//! from the input's first bytes; every output byte must map back into a file.
#![no_main]

use kiln::preprocess::{IncludeConfig, Includes, Stage, preprocess};
use kiln::source::{SourceStore, Span};
use libfuzzer_sys::fuzz_target;

const KEYWORDS: [&str; 4] = ["_A", "_B", "_CLIPPING", "_SPECULAR_STABLE"];

fuzz_target!(|data: &[u8]| {
    let Some((&mask, rest)) = data.split_first() else { return };
    let Ok(text) = std::str::from_utf8(rest) else { return };
    let keywords: Vec<&str> = (0..4).filter(|b| mask & (1 << b) != 0).map(|b| KEYWORDS[b]).collect();
    let mut store = SourceStore::new();
    let file = store.add("fuzz.wgsl", text);
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let (program, _) = includes.load_program(&mut store, &[Span::new(file, 0..text.len())]);
    let stage = if mask & 0x80 != 0 { Stage::Vertex } else { Stage::Fragment };
    let out = preprocess(&includes, &store, &program, &keywords, stage);
    for offset in 0..out.text.len() {
        let origin = out.source_map.locate(offset).expect("every output byte maps");
        assert!(origin.span.end as usize <= store.text(origin.span.file).len());
    }
    let _ = kiln::diagnostics::render_plain(&store, &out.diagnostics);
});
