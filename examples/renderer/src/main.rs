//! Renders the scene to `renderer.png` (and the CPU reference to `reference.png`) and prints how
//! far apart they are. `cargo run --release -p kiln-renderer [-- OUTPUT.png]`.

use kiln_renderer::{Scene, compare, device, reference, reference_image, render};
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let output = std::env::args().nth(1).map_or_else(|| PathBuf::from("renderer.png"), PathBuf::from);
    let scene = Scene::parse(include_str!("../scene.toml"))?;
    let (device, queue, adapter) = device()?;
    let image = render(&device, &queue, &scene)?;
    image.write_png(&output)?;
    let (colors, edge) = reference(&scene);
    reference_image(&scene, &colors).write_png(&output.with_file_name("reference.png"))?;
    let (max, mean, pixels) = compare(&image, &colors, &edge);
    println!("rendered {} on {adapter}", output.display());
    println!("against the f64 reference over {pixels} interior pixels: max error {max:.4}, mean {mean:.5}");
    Ok(())
}
