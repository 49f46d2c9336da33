//! Renders the scene to `renderer.png` (and the CPU reference to `reference.png`) and prints how
//! far apart they are. `cargo run --release -p kiln-renderer [-- OUTPUT.png]`.
//!
//! `-- --watch` is the hot-reload loop: it writes the scene's materials into a kiln project
//! (`target/kiln-watch`, shaders from `fixtures/project/shaders`), waits for `kiln watch` to build
//! it, and draws `renderer.png` again from the new build whenever a shader edit rebuilds it; a
//! broken edit prints its diagnostics and the last good pipelines stay.
//!
//! `-- --introduce [--trace FILE] [--warm-up FILE]` draws the scene as a game meets it, one more
//! object a frame, and prints per frame the pipelines created on the render thread and the frame
//! time: `--trace` records every pipeline created (docs/trace.md), `--warm-up` makes a trace's
//! pipelines on worker threads before the first frame, `--cache DIR` keeps the driver's pipeline
//! cache in DIR (loaded first, saved after warm-up and at the end).
//!
//! `-- --keywords pipeline|ubershader` draws a grid that meets a new keyword combination every
//! frame (`fixtures/ubershader`) and prints each frame's time on the render thread: `pipeline`
//! creates each new pipeline there, `ubershader` draws it with the pass's ubershader while a
//! worker creates it. Run each in its own process, so that neither finds the other's pipelines in
//! the driver's memory.

use kiln_renderer::{
    Geometry, Scene, Target, compare, device, difference, reference, reference_image, reference_with, render,
    render_with,
};
use kiln_runtime::{Reload, Runtime};
use std::path::{Path, PathBuf};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scene = Scene::bundled();
    let (device, queue, adapter) = device()?;
    if std::env::args().nth(1).as_deref() == Some("--watch") {
        return watch(&scene, &device, &queue);
    }
    if std::env::args().nth(1).as_deref() == Some("--introduce") {
        return introduce(&scene, &device, &queue);
    }
    if std::env::args().nth(1).as_deref() == Some("--keywords") {
        let fallback = match std::env::args().nth(2).as_deref() {
            Some("pipeline") => false,
            Some("ubershader") => true,
            _ => return Err("--keywords takes `pipeline` or `ubershader`".into()),
        };
        return introduce_keywords(&device, &queue, fallback);
    }
    let output = std::env::args().nth(1).map_or_else(|| PathBuf::from("renderer.png"), PathBuf::from);
    let image = render(&device, &queue, &scene)?;
    image.write_png(&output)?;
    let (colors, edge) = reference(&scene);
    reference_image(&scene, &colors).write_png(&output.with_file_name("reference.png"))?;
    let (max, mean, pixels) = compare(&image, &colors, &edge);
    println!("rendered {} on {adapter}", output.display());
    println!("against the f64 reference over {pixels} interior pixels: max error {max:.4}, mean {mean:.5}");
    explain(&scene, &image.colors(), &colors, &edge);
    Ok(())
}

/// Splits the difference into its parts: the reference on the triangles the GPU draws isolates
/// tessellation, blending what an 8-bit target stores isolates the target's rounding between
/// draws, and what is left between the image and that reference is the final rounding to 8 bits
/// plus the shader's arithmetic (and the rasteriser's and the blender's).
fn explain(scene: &Scene, image: &[[f64; 3]], analytic: &[[f64; 3]], edge: &[bool]) {
    let tessellated = reference_with(scene, Geometry::Tessellated, Target::Exact).colors;
    let stored = reference_with(scene, Geometry::Tessellated, Target::EightBit);
    let at = |i: usize| format!("pixel ({}, {})", i % scene.width as usize, i / scene.width as usize);
    let report = |what: &str, d: kiln_renderer::Difference| {
        println!(
            "  {what}: max {:.4} ({:.4} of an 8-bit step) at {}, mean {:.5}",
            d.max,
            d.max * 255.0,
            at(d.worst),
            d.mean
        )
    };
    report(
        "tessellation (the drawn triangles against analytic spheres)",
        difference(&tessellated, analytic, edge),
    );
    report(
        "8-bit target between draws (blending rounded colours)",
        difference(&stored.colors, &tessellated, edge),
    );
    // Rounding to 8 bits alone puts the image at most half a step from this reference.
    for (what, blended) in [("opaque", false), ("blended", true)] {
        let d = difference(image, &stored.colors, &stored.left_out_unless(blended));
        report(&format!("image against the reference with both, {what} pixels"), d);
    }
    let d = difference(image, &tessellated, &stored.left_out_unless(true));
    report("image against the drawn triangles blending exact colours, blended pixels", d);
}

fn introduce(
    scene: &Scene,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
) -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let value = |flag: &str| args.iter().position(|a| a == flag).and_then(|at| args.get(at + 1));
    let mut runtime = Runtime::new(device, kiln_renderer::library()?);
    if let Some(path) = value("--trace") {
        runtime.record_pipelines(kiln_runtime::PipelineTrace::append(Path::new(path))?);
    }
    if let Some(dir) = value("--cache") {
        let info = kiln_runtime::adapter(wgpu::Backends::from_env().unwrap_or_default())?.get_info();
        // SAFETY: the folder holds only what this program's `save_pipeline_cache` wrote.
        let opened = unsafe { runtime.open_pipeline_cache(&info, Path::new(dir)) };
        println!("pipeline cache: {opened:?}");
    }
    if let Some(path) = value("--warm-up") {
        let (entries, skipped) = kiln_runtime::read_trace(&std::fs::read_to_string(path)?);
        let started = std::time::Instant::now();
        let errors = runtime.warm_up_trace(&entries, 4);
        println!(
            "warm-up: {} pipelines from {} entries on 4 threads in {:.1} ms ({} entries skipped, {} failed)",
            runtime.pipelines_created(),
            entries.len(),
            started.elapsed().as_secs_f64() * 1e3,
            skipped.len(),
            errors.len()
        );
        runtime.save_pipeline_cache()?;
    }
    let (frames, _) = kiln_renderer::introduce(&mut runtime, device, queue, scene)?;
    for (frame, (created, time)) in frames.iter().enumerate() {
        println!(
            "frame {}: {created} pipelines created on the render thread, {:.2} ms",
            frame + 1,
            time.as_secs_f64() * 1e3
        );
    }
    let worst = frames.iter().map(|(_, time)| time.as_secs_f64() * 1e3).fold(0.0, f64::max);
    let created: usize = frames.iter().map(|(created, _)| created).sum();
    println!("{created} pipelines created on the render thread; worst frame {worst:.2} ms");
    runtime.save_pipeline_cache()?;
    Ok(())
}

fn introduce_keywords(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    fallback: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let introduced = kiln_renderer::keywords::introduce(device, queue, fallback)?;
    let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
    if let Some(warm_up) = introduced.warm_up {
        println!("warm-up: the ubershader's pipeline in {:.2} ms", ms(warm_up));
    }
    for (i, frame) in introduced.frames.iter().enumerate() {
        println!(
            "frame {}: {:.2} ms, {} cells drawn by the ubershader",
            i + 1,
            ms(frame.time),
            frame.fallbacks
        );
    }
    let main = std::thread::current().name().unwrap_or("main").to_string();
    let (here, elsewhere): (Vec<_>, Vec<_>) = introduced.created.iter().partition(|c| c.thread == main);
    let total = |c: &[&kiln_runtime::Creation]| c.iter().map(|c| ms(c.duration)).fold(0.0, |a, b| a + b);
    let worst = introduced.frames.iter().map(|f| ms(f.time)).fold(0.0, f64::max);
    let mut times: Vec<f64> = introduced.frames.iter().map(|f| ms(f.time)).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "{} pipelines created on the render thread ({:.1} ms), {} on workers ({:.1} ms); frames: median {:.2} ms, worst {worst:.2} ms",
        here.len(),
        total(&here),
        elsewhere.len(),
        total(&elsewhere),
        times[times.len() / 2]
    );
    Ok(())
}

fn watch(
    scene: &Scene,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
) -> Result<(), Box<dyn std::error::Error>> {
    let project = PathBuf::from("target/kiln-watch");
    let shaders =
        std::fs::canonicalize(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/project/shaders"))?;
    std::fs::create_dir_all(project.join("materials"))?;
    for (name, text) in scene.material_files() {
        std::fs::write(project.join("materials").join(name), text)?;
    }
    let globals: Vec<String> = scene.global_keywords().iter().map(|k| format!("{k:?}")).collect();
    std::fs::write(
        project.join("kiln.toml"),
        format!(
            "shaders = [{shaders:?}]\ninclude_paths = [{shaders:?}]\nmaterials = [\"materials\"]\noutput = \"build\"\n\
             global_keywords = [{}]\n",
            globals.join(", "),
            shaders = shaders.display().to_string()
        ),
    )?;
    let output = project.join("build");
    println!("in another terminal:  kiln watch {}", project.display());
    while !output.join(kiln_runtime::manifest::FILE_NAME).exists() {
        std::thread::sleep(std::time::Duration::from_millis(200));
    }
    let mut runtime = Runtime::open(device, &output)?;
    let draw = |runtime: &mut Runtime| match render_with(runtime, device, queue, scene) {
        Ok(image) => match image.write_png(Path::new("renderer.png")) {
            Ok(()) => {
                println!("rendered renderer.png ({} pipelines created so far)", runtime.pipelines_created())
            }
            Err(e) => eprintln!("{e}"),
        },
        Err(e) => eprintln!("{e}"),
    };
    draw(&mut runtime);
    let mut last_error = String::new();
    loop {
        match runtime.reload() {
            Ok(Reload::Swapped { dropped_pipelines }) => {
                println!("new build: {dropped_pipelines} pipelines replaced");
                last_error.clear();
                draw(&mut runtime);
            }
            Ok(Reload::Unchanged) => {}
            Err(error) => {
                let error = error.to_string();
                if error != last_error {
                    eprintln!("{error}");
                    last_error = error;
                }
            }
        }
        std::thread::sleep(std::time::Duration::from_millis(200));
    }
}
