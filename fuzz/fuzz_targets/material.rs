//! Any text as a material for the bundled Lit shader: loading, drawers, presets, set checks.
#![no_main]

use kiln::catalog::CatalogInput;
use kiln::preprocess::{IncludeConfig, Includes};
use kiln::source::SourceStore;
use libfuzzer_sys::fuzz_target;

const LIT: &str = include_str!("../../fixtures/project/shaders/Lit.shader");

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let mut store = SourceStore::new();
    let shader = store.add("Lit.shader", LIT);
    let material = store.add("fuzz.mat", text);
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let input = CatalogInput { shaders: vec![shader], materials: vec![material], ..CatalogInput::default() };
    let (_, diagnostics) = kiln::listing::list_shaders(&mut store, &mut includes, &input);
    let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
});
