//! Any bytes as the names of a build (shaders, files, passes, keywords, kernels, materials, WGSL
//! structs and members, entry points) in the example project's manifest, through
//! `codegen::generate`: the module must parse as Rust (syn, the grammar rustc's macros use), with
//! exactly the items a clean name gives (no text of a name became an item), or the names must be
//! refused as a clash. A name that injects code, or an identifier Rust refuses, is a crash.
#![no_main]

use kiln::manifest::Manifest;
use libfuzzer_sys::fuzz_target;

const MANIFEST: &str = include_str!("../../tests/golden/build/manifest.json");

/// The manifest with every name replaced by the next piece of `data` (split at NUL bytes).
fn renamed(data: &str) -> Manifest {
    let mut names = data.split('\0').cycle();
    let mut next = || names.next().unwrap_or_default().to_string();
    let mut manifest: Manifest = serde_json::from_str(MANIFEST).expect("the golden manifest");
    for shader in &mut manifest.shaders {
        shader.name = next();
        shader.file = next();
        for pass in &mut shader.passes {
            pass.name = Some(next());
            for keyword in pass.keywords.iter_mut().chain(pass.keyword_sets.iter_mut().flat_map(|s| &mut s.keywords)) {
                if keyword != "_" {
                    *keyword = next();
                }
            }
            for variant in &mut pass.variants {
                variant.materials.iter_mut().for_each(|m| *m = next());
                variant.keywords.clear();
            }
            for block in &mut pass.uniform_blocks {
                block.name = next();
                block.type_name = next();
                for member in &mut block.members {
                    member.name = next();
                }
            }
            for interface in &mut pass.interfaces {
                interface.entry_point = next();
            }
        }
    }
    manifest
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    if text.is_empty() {
        return;
    }
    let manifest = renamed(text);
    let Ok(module) = kiln::codegen::generate(&manifest, "kiln") else { return };
    let file = syn::parse_file(&module).unwrap_or_else(|e| panic!("not Rust: {e}\n{module}"));
    // One item per shader at the top level beside the prelude's, whatever the names hold.
    let modules = file.items.iter().filter(|i| matches!(i, syn::Item::Mod(_))).count();
    assert_eq!(modules, manifest.shaders.len(), "a name made or hid a module:\n{module}");
});
