//! Shader module creation on a real device, from kiln's WGSL against from its SPIR-V: the same
//! modules (a project's stage modules without `override`s), created through wgpu's
//! `create_shader_module` in interleaved rounds, each round creating every module once per form.
//! wgpu parses and validates either form with naga before the driver sees it, so this measures
//! what the run time would gain by handing wgpu SPIR-V where the back end reads it.
//!
//! `cargo bench --bench module_creation -- [PROJECT] [ROUNDS]` (default: fixtures/project, 9).

use kiln::config::VariantSelection;
use kiln::project::{Request, build_project};
use kiln::runtime::Library;
use kiln::source::SourceStore;
use std::path::PathBuf;
use std::time::{Duration, Instant};

#[path = "support/measure.rs"]
#[allow(dead_code)]
mod measure;

fn main() {
    let mut args = std::env::args().skip(1).filter(|a| !a.starts_with("--"));
    let project = PathBuf::from(args.next().unwrap_or_else(|| "fixtures/project".into()));
    let rounds: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(9);
    let output = tempfile::tempdir().expect("temp dir");
    let mut store = SourceStore::new();
    let mode = Request {
        output: Some(output.path().to_path_buf()),
        unused_shaders: VariantSelection::All { limit: 4096 },
        ..Request::default()
    };
    let (result, _) =
        build_project(&mut store, std::slice::from_ref(&project), &mode, &|_, _| {}).expect("project");
    assert!(!kiln::diagnostics::has_errors(&result.diagnostics), "the project builds");
    let library = Library::open(output.path()).expect("the build opens");
    let mut modules: Vec<(String, Vec<u32>)> = Vec::new();
    for stage in library.manifest().stages() {
        let (Some(wgsl), Some(spirv)) = (&stage.module.wgsl, &stage.module.spirv) else { continue };
        if !stage.interface.overrides.is_empty() {
            continue;
        }
        let text = library.bytes(stage.pass, wgsl).expect("WGSL bytes");
        let words =
            wgpu::util::make_spirv_raw(library.bytes(stage.pass, spirv).expect("SPIR-V bytes")).into_owned();
        modules.push((String::from_utf8(text.to_vec()).expect("UTF-8"), words));
    }
    assert!(!modules.is_empty(), "no module without overrides in {}", project.display());
    let gpu = kiln::accuracy::gpu::device().expect("a device (lavapipe: mesa-vulkan-drivers)");
    let create_all = |spirv: bool| {
        let started = Instant::now();
        for (text, words) in &modules {
            let source = if spirv {
                wgpu::ShaderSource::SpirV(words.as_slice().into())
            } else {
                wgpu::ShaderSource::Wgsl(text.as_str().into())
            };
            drop(gpu.device.create_shader_module(wgpu::ShaderModuleDescriptor { label: None, source }));
        }
        started.elapsed()
    };
    // One round of each first, unmeasured: the driver's and wgpu's first-use costs.
    create_all(false);
    create_all(true);
    let (mut from_wgsl, mut from_spirv, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    for round in 0..rounds {
        let (w, s) = if round % 2 == 0 {
            let w = create_all(false);
            (w, create_all(true))
        } else {
            let s = create_all(true);
            (create_all(false), s)
        };
        from_wgsl.push(w);
        from_spirv.push(s);
        ratios.push(s.as_secs_f64() / w.as_secs_f64());
    }
    let per_module = |d: Duration| d.as_secs_f64() * 1e3 / modules.len() as f64;
    println!(
        "{} modules on {} ({rounds} interleaved rounds): from WGSL {:.3} ms a module, from SPIR-V {:.3} ms; SPIR-V/WGSL {}",
        modules.len(),
        gpu.adapter,
        per_module(measure::median(from_wgsl)),
        per_module(measure::median(from_spirv)),
        measure::spread(ratios)
    );
}
