//! Any text as a `.shader` file: parse, pragmas, programs with includes, listing, rendering.
#![no_main]

use kiln::catalog::CatalogInput;
use kiln::preprocess::{IncludeConfig, Includes};
use kiln::source::SourceStore;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut store = SourceStore::new();
    let file = store.add("fuzz.shader", text);
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let input = CatalogInput { shaders: vec![file], ..CatalogInput::default() };
    let (_, diagnostics) = kiln::listing::list_shaders(&mut store, &mut includes, &input);
    let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
});
