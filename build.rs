//! Embeds the bundled shader library (`shaderlib/*.wgsl`, and its HLSL mirror `*.hlsl`) into the
//! crate, so kiln finds its library from any working directory, and records the optimisation
//! level kiln is built with.

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    // Read when the script runs, not when it was compiled: cargo reuses a compiled build script
    // for the same sources in another checkout (a worktree sharing the target folder).
    let manifest_dir = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let dir = Path::new(&manifest_dir).join("shaderlib");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("shaderlib/ exists")
        .filter_map(|entry| entry.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|name| name.ends_with(".wgsl") || name.ends_with(".hlsl"))
        .collect();
    names.sort();
    let mut module = String::from("/// The bundled library: (file name, text), sorted by name.\n");
    module.push_str("pub static FILES: &[(&str, &str)] = &[\n");
    for name in &names {
        let path = dir.join(name);
        println!("cargo:rerun-if-changed={}", path.display());
        let _ = writeln!(module, "    ({name:?}, include_str!({:?})),", path.display().to_string());
    }
    module.push_str("];\n");
    let out = Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("shaderlib.rs");
    std::fs::write(out, module).expect("OUT_DIR is writable");
    // `kiln::Build` warns when it compiles many modules unoptimised (a plain build-dependency).
    println!("cargo:rustc-env=KILN_OPT_LEVEL={}", std::env::var("OPT_LEVEL").unwrap_or_default());
}
