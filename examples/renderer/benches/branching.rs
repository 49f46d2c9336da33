//! What `dynamic_branch` saves and what it costs, measured in one run: the seed's Lit pass with
//! `_CLIPPING` and `_PREMULTIPLY_ALPHA` chosen three ways, the scene's materials unchanged:
//!
//! - `variants`: `shader_feature` (as bundled): a module per keyword combination the materials use;
//! - `override`: `dynamic_branch`: one module, `if (_CLIPPING)` on an `override` constant that
//!   wgpu specialises per pipeline;
//! - `uniform`: no keyword; `if (UnityPerMaterial._Clipping != 0.0)`, a branch on the material's
//!   uniform at every pixel (Unity's implementation of `dynamic_branch`).
//!
//! For each: variants, modules, bytes and cold build time (median of 5), pipelines, and GPU time
//! per frame of the scene at WIDTH x HEIGHT (timestamp queries; median of 5 runs of FRAMES
//! frames), with every image compared to the `variants` one.
//!
//! `cargo bench -p kiln-renderer --bench branching [-- FRAMES WIDTH HEIGHT]`

use kiln::config::VariantSelection;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use kiln_renderer::{Image, Scene, device, render_frames};
use kiln_runtime::Runtime;
use std::path::{Path, PathBuf};
use std::time::Duration;

#[derive(Clone, Copy, PartialEq)]
enum Mechanism {
    Variants,
    Override,
    Uniform,
}

impl Mechanism {
    fn name(self) -> &'static str {
        match self {
            Mechanism::Variants => "variants (shader_feature)",
            Mechanism::Override => "override (dynamic_branch)",
            Mechanism::Uniform => "uniform branch",
        }
    }

    /// The bundled Lit shader and pass, rewritten for this mechanism.
    fn rewrite(self, file: &str, text: &str) -> String {
        let replace = |text: &str, pairs: &[(&str, &str)]| {
            pairs.iter().fold(text.to_string(), |text, (from, to)| {
                assert!(text.contains(from), "{file} has `{from}`");
                text.replace(from, to)
            })
        };
        let clip = "#if defined(_CLIPPING)\n    if (base.a < UnityPerMaterial._Cutoff) {\n        discard;\n    }\n#endif";
        let premultiply = "#if defined(_PREMULTIPLY_ALPHA)\n    let brdf = GetBRDF(surface, true);\n#else\n    let brdf = GetBRDF(surface, false);\n#endif";
        match (self, file) {
            (Mechanism::Variants, _) => text.to_string(),
            (Mechanism::Override, "Lit.shader") => replace(
                text,
                &[
                    ("#pragma shader_feature _CLIPPING", "#pragma dynamic_branch _CLIPPING"),
                    (
                        "#pragma shader_feature _PREMULTIPLY_ALPHA",
                        "#pragma dynamic_branch _PREMULTIPLY_ALPHA",
                    ),
                ],
            ),
            (Mechanism::Override, "LitPass.wgsl") => replace(
                text,
                &[
                    (
                        clip,
                        "    if (_CLIPPING && base.a < UnityPerMaterial._Cutoff) {\n        discard;\n    }",
                    ),
                    (premultiply, "    let brdf = GetBRDF(surface, _PREMULTIPLY_ALPHA);"),
                ],
            ),
            (Mechanism::Uniform, "Lit.shader") => replace(
                text,
                &[
                    ("#pragma shader_feature _CLIPPING\n", ""),
                    ("#pragma shader_feature _PREMULTIPLY_ALPHA\n", ""),
                    // Plain numbers the program reads: no keyword for the runtime to look up.
                    ("[Toggle(_CLIPPING)] _Clipping", "_Clipping"),
                    ("[Toggle(_PREMULTIPLY_ALPHA)] _PremulAlpha", "_PremulAlpha"),
                ],
            ),
            (Mechanism::Uniform, "LitPass.wgsl") => replace(
                text,
                &[
                    (
                        "    _Smoothness: f32,\n",
                        "    _Smoothness: f32,\n    _Clipping: f32,\n    _PremulAlpha: f32,\n",
                    ),
                    (
                        clip,
                        "    if (UnityPerMaterial._Clipping != 0.0 && base.a < UnityPerMaterial._Cutoff) {\n        discard;\n    }",
                    ),
                    (premultiply, "    let brdf = GetBRDF(surface, UnityPerMaterial._PremulAlpha != 0.0);"),
                ],
            ),
            _ => text.to_string(),
        }
    }
}

/// The bundled shaders (Lit rewritten) and the scene's materials, as a kiln project.
fn project(dir: &Path, mechanism: Mechanism, scene: &Scene) -> PathBuf {
    let root = dir.join(format!("{}", mechanism as u8));
    let bundled = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/project/shaders");
    std::fs::create_dir_all(root.join("shaders")).expect("mkdir");
    std::fs::create_dir_all(root.join("materials")).expect("mkdir");
    for entry in std::fs::read_dir(&bundled).expect("bundled shaders") {
        let path = entry.expect("entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).expect("a name").to_string();
        let text = std::fs::read_to_string(&path).expect("read");
        std::fs::write(root.join("shaders").join(&name), mechanism.rewrite(&name, &text)).expect("write");
    }
    for (name, text) in scene.material_files() {
        std::fs::write(root.join("materials").join(name), text).expect("write");
    }
    let globals: Vec<String> = scene.global_keywords().iter().map(|k| format!("{k:?}")).collect();
    std::fs::write(
        root.join("kiln.toml"),
        format!(
            "shaders = [\"shaders\"]\nmaterials = [\"materials\"]\nglobal_keywords = [{}]\n",
            globals.join(", ")
        ),
    )
    .expect("kiln.toml");
    root
}

struct Built {
    variants: usize,
    modules: usize,
    bytes: u64,
    build_time: Duration,
}

/// Five cold builds (a fresh output folder each: nothing reused), the median time.
fn build(project: &Path, output: &Path) -> Built {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..5 {
        let _ = std::fs::remove_dir_all(output);
        let mut store = SourceStore::new();
        let mode = Request {
            output: Some(output.to_path_buf()),
            unused_shaders: VariantSelection::Used,
            ..Request::default()
        };
        let (result, diagnostics) =
            build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
        let errors: Vec<_> = diagnostics.iter().chain(&result.diagnostics).cloned().collect();
        assert!(
            !kiln::diagnostics::has_errors(&errors),
            "{}",
            kiln::diagnostics::render_plain(&store, &errors)
        );
        times.push(result.summary.elapsed);
        last = Some(result.summary);
    }
    times.sort();
    let summary = last.expect("built");
    Built {
        variants: summary.variants,
        modules: summary.modules,
        bytes: summary.bytes_written,
        build_time: times[times.len() / 2],
    }
}

fn max_difference(a: &Image, b: &Image) -> u8 {
    a.pixels.iter().zip(&b.pixels).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0)
}

fn main() {
    let args: Vec<u32> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let frames = args.first().copied().unwrap_or(20);
    let mut scene = Scene::bundled();
    scene.width = args.get(1).copied().unwrap_or(1920);
    scene.height = args.get(2).copied().unwrap_or(1440);
    let gpu = device();
    let dir = tempfile::tempdir().expect("temp dir");
    let mut reference: Option<Image> = None;
    match &gpu {
        Ok((_, _, adapter)) => {
            println!("{adapter}: {} x {}, {frames} frames a run", scene.width, scene.height)
        }
        Err(reason) => println!("no GPU ({reason}): build numbers only"),
    }
    println!(
        "| mechanism | variants | modules | bytes | cold build | pipelines | GPU time per frame | ns per pixel | max difference |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for mechanism in [Mechanism::Variants, Mechanism::Override, Mechanism::Uniform] {
        let root = project(dir.path(), mechanism, &scene);
        let output = root.join("build");
        let built = build(&root, &output);
        let (mut pipelines, mut per_frame, mut difference) = (String::new(), String::new(), String::new());
        let mut per_pixel = String::new();
        if let Ok((device, queue, _)) = &gpu {
            let mut runtime = Runtime::open(device, &output).expect("opens");
            // The first run creates the pipelines; the next five are timed.
            let (image, _) = render_frames(&mut runtime, device, queue, &scene, 1).expect("renders");
            let mut times: Vec<f64> = (0..5)
                .filter_map(|_| {
                    render_frames(&mut runtime, device, queue, &scene, frames).expect("renders").1
                })
                .collect();
            times.sort_by(f64::total_cmp);
            pipelines = runtime.pipelines_created().to_string();
            if let Some(&median) = times.get(times.len() / 2) {
                per_frame = format!("{:.3} ms", median / 1e6);
                per_pixel = format!("{:.4}", median / f64::from(scene.width * scene.height));
            }
            difference = match &reference {
                Some(reference) => max_difference(reference, &image).to_string(),
                None => "(reference)".into(),
            };
            reference.get_or_insert(image);
        }
        println!(
            "| {} | {} | {} | {} | {:.1} ms | {pipelines} | {per_frame} | {per_pixel} | {difference} |",
            mechanism.name(),
            built.variants,
            built.modules,
            built.bytes,
            built.build_time.as_secs_f64() * 1e3,
        );
    }
}
