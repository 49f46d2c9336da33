//! Builds exactly the shader variants the scene's materials use: the scene's materials become
//! `.mat` files in OUT_DIR, and kiln builds the bundled Lit shader with them, specialised for the
//! scene's lights.

// Only the material conversion is needed here; the renderer uses the rest.
#[allow(dead_code)]
#[path = "src/scene.rs"]
mod scene;

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let manifest_dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?);
    let scene_path = manifest_dir.join("scene.toml");
    println!("cargo:rerun-if-changed={}", scene_path.display());
    let scene: scene::Scene = toml::from_str(&std::fs::read_to_string(&scene_path)?)?;
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    std::fs::write(out_dir.join("scene.json"), serde_json::to_string(&scene)?)?;
    let materials = out_dir.join("scene-materials");
    // Materials of an earlier scene must not keep their variants alive.
    let _ = std::fs::remove_dir_all(&materials);
    std::fs::create_dir_all(&materials)?;
    for (name, text) in scene.material_files() {
        std::fs::write(materials.join(name), text)?;
    }
    kiln::Build::new(manifest_dir.join("../../fixtures/project/shaders"))
        .materials(materials)
        .global_keywords(scene.global_keywords())
        .run()?;
    // Uniform and storage blocks of every shape, for the GPU round trip of generated structs
    // (tests/uniform_blocks.rs), in a folder of their own.
    kiln::Build::new(manifest_dir.join("../../fixtures/blocks")).out_dir(out_dir.join("blocks")).run()?;
    // A pass with an ubershader, every variant built (`always_include`), for `--keywords`.
    kiln::Build::new(manifest_dir.join("../../fixtures/ubershader"))
        .out_dir(out_dir.join("ubershader"))
        .run()?;
    Ok(())
}
