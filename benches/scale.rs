//! kiln against naga alone, and scaling from 10 to 10,000 used variants, in one run:
//! `cargo bench --bench scale` (sizes: `-- 10,100,1000,10000`). For each size it generates a
//! synthetic project (shaders with the Lit pass as their body, eight `shader_feature_fragment`
//! sets and a `multi_compile_fragment` set, materials choosing distinct combinations), then
//! measures: naga alone (parse, validate, WGSL and SPIR-V) on the very stage texts kiln compiles;
//! kiln's cold build; a no-op rebuild; a rebuild after touching one include; kiln's peak memory in
//! the cold and the no-op build; the manifest's bytes per variant and the generated Rust's size.
//! `-- generate N DIR` only writes the project of N variants; `-- rust OUTPUT FILE` the Rust
//! module generated for a build's output; `-- cut PROJECT` how much of each stage kind's text a
//! build of a project hands naga. `-- compute 1000` builds a project of
//! compute shaders instead (100 variants each, two kernels a variant) against naga alone on the
//! same kernel texts. Both sides allocate with mimalloc, as the CLI does. Results and how to read
//! them: docs/performance.md.

use kiln::config::ParseScope;
use kiln::preprocess::Stage;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[path = "support/generate.rs"]
mod generate;
#[path = "support/measure.rs"]
mod measure;
use generate::{SHARED_INCLUDES, generate};
use measure::{median, spread, whole_texts};

// kiln and naga alone both allocate through the CLI's allocator, as `kiln build` does: on the
// system allocator, sixteen threads spend part of a build contending for it (docs/performance.md).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Peak resident memory since the last reset, in MiB (Linux; 0 elsewhere).
fn peak_mib() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let kib: f64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0.0);
    kib / 1024.0
}

fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

/// Interleaved rounds at a size: five, fewer past 10,000 variants; `KILN_SCALE_ROUNDS` says.
fn rounds(variants: usize) -> usize {
    let asked = std::env::var("KILN_SCALE_ROUNDS").ok().and_then(|n| n.parse().ok());
    asked.unwrap_or(if variants <= 10_000 { 5 } else { 1 }).max(1)
}

/// `kiln build` (or, without `write`, `kiln check`: the same work, nothing written; with `parse`,
/// naga handed that much of each stage text, else what the command hands it).
fn kiln_build(
    project: &Path,
    output: &Path,
    write: bool,
    parse: Option<ParseScope>,
) -> (kiln::orchestrate::BuildSummary, Duration) {
    let started = Instant::now();
    let mut store = SourceStore::new();
    let mode = Request { write, output: Some(output.to_path_buf()), parse, ..Request::default() };
    let (result, diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
    let mut all = diagnostics;
    all.extend(result.diagnostics);
    assert!(
        all.is_empty(),
        "the synthetic project builds cleanly: {}",
        kiln::diagnostics::render_plain(&store, &all)
    );
    (result.summary, started.elapsed())
}

/// How much of each stage kind's text a build hands naga: per stage, the texts, their bytes whole
/// and the bytes of the declarations their entry points reach (`compile::reach`), and the
/// distinct texts once cut (a build parses each once).
fn cut_table(project: &Path) -> String {
    let texts = whole_texts(project);
    let mut table = String::from("  stage     texts  distinct cut  whole bytes   cut bytes  removed\n");
    for kind in [Stage::Vertex, Stage::Fragment, Stage::Compute] {
        let (mut count, mut whole, mut cut) = (0, 0, 0);
        let mut distinct = std::collections::HashSet::new();
        for (_, entry, text) in texts.iter().filter(|(stage, ..)| *stage == kind) {
            let kept = kiln::compile::reach::reachable(text, entry)
                .map_or_else(|| text.clone(), |ranges| kiln::compile::reach::joined(text, &ranges));
            (count, whole, cut) = (count + 1, whole + text.len(), cut + kept.len());
            distinct.insert(kept);
        }
        if count > 0 {
            let _ = writeln!(
                table,
                "  {:<8} {count:>6} {:>13} {whole:>12} {cut:>11} {:>7.1}%",
                kind.name(),
                distinct.len(),
                100.0 * (1.0 - cut as f64 / whole as f64)
            );
        }
    }
    table
}

/// naga alone on kiln's stage texts, whole: parse, validate, write WGSL and SPIR-V.
fn naga_alone(project: &Path) -> (usize, Duration) {
    let texts = whole_texts(project);
    let started = Instant::now();
    texts.par_iter().for_each(|(stage, entry, text)| {
        let module = naga::front::wgsl::parse_str(text).expect("parses");
        let flags = naga::valid::ValidationFlags::all() - naga::valid::ValidationFlags::BINDINGS;
        let info = naga::valid::Validator::new(flags, naga::valid::Capabilities::empty())
            .validate(&module)
            .expect("valid");
        let wgsl = naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty())
            .expect("wgsl");
        let options = naga::back::spv::Options { fake_missing_bindings: true, ..Default::default() };
        let shader_stage = match stage {
            Stage::Vertex => naga::ShaderStage::Vertex,
            Stage::Fragment => naga::ShaderStage::Fragment,
            Stage::Compute => naga::ShaderStage::Compute,
        };
        let pipeline = naga::back::spv::PipelineOptions { shader_stage, entry_point: entry.clone() };
        let spirv = naga::back::spv::write_vec(&module, &info, &options, Some(&pipeline)).expect("spir-v");
        std::hint::black_box((wgsl, spirv));
    });
    (texts.len(), started.elapsed())
}

/// Writes a project of compute shaders with `variants` variants in all (100 a file: two
/// `multi_compile` sets of ten, each keyword changing both kernels), every variant listed.
fn generate_compute(dir: &Path, variants: usize) {
    let files = variants.div_ceil(100);
    std::fs::create_dir_all(dir).expect("mkdir");
    let mut toml = String::from("shaders = [\".\"]\n");
    for f in 0..files {
        let mut text = String::from("#pragma kernel Integrate\n#pragma kernel Reduce\n");
        for set in ["A", "B"] {
            let keywords: Vec<String> = (1..10).map(|k| format!("_{set}{k}")).collect();
            let _ = writeln!(text, "#pragma multi_compile _ {}", keywords.join(" "));
        }
        let mut tweaks = String::new();
        for k in 1..10 {
            let _ = write!(
                tweaks,
                "#if defined(_A{k})\n    x = x * {:.2} + sin(x * {k}.0);\n#endif\n#if defined(_B{k})\n    x = mix(x, cos(x), {:.2});\n#endif\n",
                1.0 + k as f32 / 100.0,
                k as f32 / 10.0
            );
        }
        let _ = write!(
            text,
            "var<storage, read_write> data: array<vec4<f32>>;\nvar<workgroup> partial: array<vec4<f32>, 64>;\n\n\
             fn Shape(v: vec4<f32>) -> vec4<f32> {{\n    var x = v;\n{tweaks}    return x * {};\n}}\n\n\
             @compute @workgroup_size(64)\nfn Integrate(@builtin(global_invocation_id) id: vec3<u32>) {{\n    \
             let v = data[id.x];\n    data[id.x] = v + Shape(v) * 0.016;\n}}\n\n\
             @compute @workgroup_size(64)\nfn Reduce(@builtin(local_invocation_index) i: u32, @builtin(workgroup_id) g: vec3<u32>) {{\n    \
             partial[i] = Shape(data[g.x * 64u + i]);\n    workgroupBarrier();\n    \
             for (var step = 32u; step > 0u; step = step / 2u) {{\n        if (i < step) {{\n            partial[i] += partial[i + step];\n        }}\n        workgroupBarrier();\n    }}\n    \
             if (i == 0u) {{\n        data[g.x] = partial[0];\n    }}\n}}\n",
            1.0 + f as f32 / 1000.0
        );
        std::fs::write(dir.join(format!("Kernels{f}.compute")), text).expect("write");
        let _ = writeln!(toml, "\n[compute.Kernels{f}]\nvariants = \"all\"");
    }
    std::fs::write(dir.join("kiln.toml"), toml).expect("write");
}

/// `-- compute N`: a project of N compute variants, kiln against naga alone on its kernel texts.
fn compute_scale(variants: usize) {
    let dir: PathBuf = tempfile::tempdir().expect("temp dir").keep();
    let project = dir.join("project");
    generate_compute(&project, variants);
    let (mut naga_times, mut whole_ratios, mut alone_ratios, mut cut_ratios) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut modules, mut built) = (0, None);
    for round in 0..rounds(variants) {
        let (count, naga) = naga_alone(&project);
        modules = count;
        naga_times.push(naga);
        let whole = kiln_build(&project, &dir.join(format!("whole{round}")), true, Some(ParseScope::Whole)).1;
        let alone =
            kiln_build(&project, &dir.join(format!("alone{round}")), true, Some(ParseScope::Reachable)).1;
        let (summary, cut) = kiln_build(&project, &dir.join(format!("out{round}")), true, None);
        whole_ratios.push(whole.as_secs_f64() / naga.as_secs_f64());
        alone_ratios.push(alone.as_secs_f64() / naga.as_secs_f64());
        cut_ratios.push(cut.as_secs_f64() / naga.as_secs_f64());
        built = Some(summary);
    }
    let built = built.expect("built");
    assert_eq!(built.modules, modules, "kiln compiles the texts naga was given");
    println!(
        "{} threads: {} compute variants, {} kernel modules: naga alone {:.2?}; kiln build / naga: whole texts {}, cut texts each parsed alone {}, cut texts parsed together {} ({} texts preprocessed, naga parsed {} texts)",
        rayon::current_num_threads(),
        built.variants,
        built.modules,
        median(naga_times),
        spread(whole_ratios),
        spread(alone_ratios),
        spread(cut_ratios),
        built.preprocessed,
        built.parses,
    );
    print!("{}", cut_table(&project));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `-- open N`: what checking every module's hash costs `Library::open` of an N-variant build:
/// rounds of `open_verified` and of `open`, interleaved, with their medians and ranges.
fn open_cost(variants: usize) {
    let dir: PathBuf = tempfile::tempdir().expect("temp dir").keep();
    let project = dir.join("project");
    generate(&project, variants);
    let output = dir.join("out");
    kiln_build(&project, &output, true, None);
    let (mut checked, mut unchecked) = (Vec::new(), Vec::new());
    for _ in 0..9 {
        let started = Instant::now();
        drop(kiln::runtime::Library::open_verified(&output).expect("opens"));
        checked.push(started.elapsed());
        let started = Instant::now();
        drop(kiln::runtime::Library::open(&output).expect("opens"));
        unchecked.push(started.elapsed());
    }
    let range = |times: &[Duration]| {
        let (low, high) = (times.iter().min().expect("rounds"), times.iter().max().expect("rounds"));
        format!("{:.1}-{:.1} ms", low.as_secs_f64() * 1e3, high.as_secs_f64() * 1e3)
    };
    let (checked_range, unchecked_range) = (range(&checked), range(&unchecked));
    let (checked, unchecked) = (median(checked), median(unchecked));
    println!(
        "{variants} variants, {} threads: Library::open_verified {:.1} ms ({checked_range}), open {:.1} ms ({unchecked_range}): the module check costs {:+.1}%",
        rayon::current_num_threads(),
        checked.as_secs_f64() * 1e3,
        unchecked.as_secs_f64() * 1e3,
        100.0 * (checked.as_secs_f64() / unchecked.as_secs_f64() - 1.0)
    );
}

fn main() {
    // `-- generate N DIR` only writes the project, for one-off runs of the CLI on it.
    let args: Vec<String> = std::env::args().collect();
    if let Some(at) = args.iter().position(|a| a == "open") {
        open_cost(args.get(at + 1).and_then(|n| n.parse().ok()).unwrap_or(10_000));
        return;
    }
    if let Some(at) = args.iter().position(|a| a == "compute") {
        let size = args.get(at + 1).and_then(|n| n.parse().ok()).unwrap_or(1000);
        compute_scale(size);
        return;
    }
    // `-- cut PROJECT` prints how much of each stage kind's text a build hands naga.
    if let Some(at) = args.iter().position(|a| a == "cut") {
        print!("{}", cut_table(Path::new(args.get(at + 1).expect("cut PROJECT"))));
        return;
    }
    // `-- rust OUTPUT FILE` writes the Rust module generated for a build's output.
    if let Some(at) = args.iter().position(|a| a == "rust") {
        let output = PathBuf::from(args.get(at + 1).expect("rust OUTPUT FILE"));
        let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
        let rust = kiln::codegen::generate(&manifest, "kiln").expect("names do not clash");
        std::fs::write(args.get(at + 2).expect("rust OUTPUT FILE"), &rust).expect("write");
        println!("{} bytes of Rust", rust.len());
        return;
    }
    if let Some(at) = args.iter().position(|a| a == "generate") {
        let size = args.get(at + 1).and_then(|n| n.parse().ok()).expect("generate N DIR");
        let dir = PathBuf::from(args.get(at + 2).expect("generate N DIR"));
        let shaders = generate(&dir, size);
        println!("wrote {shaders} shaders for {size} variants to {}", dir.display());
        return;
    }
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .find(|a| a.chars().next().is_some_and(|c| c.is_ascii_digit()))
        .map(|a| a.split(',').filter_map(|n| n.parse().ok()).collect())
        .unwrap_or_else(|| vec![10, 100, 1000, 10000]);
    println!("{} threads", rayon::current_num_threads());
    println!(
        "{:>8} {:>7} {:>6} {:>9} {:>10} {:>6} {:>10} {:>6} {:>10} {:>6} {:>9} {:>9} {:>10} {:>10} {:>10} {:>8} {:>10}",
        "variants",
        "modules",
        "vertex",
        "naga",
        "kiln check",
        "ratio",
        "whole",
        "ratio",
        "kiln build",
        "ratio",
        "no-op",
        "touch",
        "recompiled",
        "peak mem",
        "no-op mem",
        "manifest",
        "Rust"
    );
    for size in sizes {
        let dir: PathBuf = tempfile::tempdir().expect("temp dir").keep();
        let shaders = generate(&dir.join("project"), size);
        let project = dir.join("project");
        // Rounds of naga, check, a cold build from whole texts (`--parse-whole`: kiln before the
        // cut), one from cut texts each parsed alone and a cold build, interleaved, each reported as its median: a shared machine's
        // noise moves all alike within a round. Each round's ratios to naga give the ranges.
        let (mut naga_times, mut check_times, mut whole_times, mut cold_times) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let (mut check_ratios, mut whole_ratios, mut alone_ratios, mut cold_ratios) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut modules = 0;
        let mut cold = None;
        let mut memory = 0.0;
        let rounds = rounds(size);
        for round in 0..rounds {
            let (count, naga) = naga_alone(&project);
            modules = count;
            naga_times.push(naga);
            let check = kiln_build(&project, &dir.join("unused"), false, None).1;
            // A new folder each round: deleting thousands of files just before creating as many
            // makes ext4 search its recently freed inodes, which a first build does not meet.
            let whole =
                kiln_build(&project, &dir.join(format!("whole{round}")), true, Some(ParseScope::Whole)).1;
            // Cut, each text parsed alone (`--parse-alone`: kiln before the parse together).
            let alone =
                kiln_build(&project, &dir.join(format!("alone{round}")), true, Some(ParseScope::Reachable)).1;
            alone_ratios.push(alone.as_secs_f64() / naga.as_secs_f64());
            reset_peak();
            let (summary, time) = kiln_build(&project, &dir.join(format!("out{round}")), true, None);
            if round == 0 {
                memory = peak_mib();
            }
            let ratio = |t: Duration| t.as_secs_f64() / naga.as_secs_f64();
            for (times, ratios, time) in [
                (&mut check_times, &mut check_ratios, check),
                (&mut whole_times, &mut whole_ratios, whole),
                (&mut cold_times, &mut cold_ratios, time),
            ] {
                times.push(time);
                ratios.push(ratio(time));
            }
            cold = Some(summary);
        }
        let cold = cold.expect("at least one round");
        let output = dir.join(format!("out{}", rounds - 1));
        let (naga, check_time, whole_time, cold_time) =
            (median(naga_times), median(check_times), median(whole_times), median(cold_times));
        assert_eq!(cold.modules, modules, "kiln compiles the texts naga was given");
        assert_eq!(cold.shared, 0, "each shader's stage texts are its own");
        reset_peak();
        let noops: Vec<(kiln::orchestrate::BuildSummary, Duration)> =
            (0..3).map(|_| kiln_build(&project, &output, true, None)).collect();
        let noop_memory = peak_mib();
        let manifest_bytes = std::fs::metadata(output.join("manifest.json")).expect("manifest").len();
        let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
        let rust_bytes = kiln::codegen::generate(&manifest, "kiln").expect("names do not clash").len();
        drop(manifest);
        assert!(noops.iter().all(|(noop, _)| noop.compiled == 0));
        let noop_time = median(noops.into_iter().map(|(_, time)| time).collect());
        // Touch one of the shared includes: only the shaders that include it recompile.
        let touched = project.join("shaders/Shared0.wgsl");
        let text = std::fs::read_to_string(&touched).expect("read");
        std::fs::write(&touched, text.replace("return ", "return 0.5 + 0.5 * ")).expect("write");
        let (touch, touch_time) = kiln_build(&project, &output, true, None);
        let including = shaders.div_ceil(SHARED_INCLUDES);
        let vertex_jobs = shaders; // one vertex module per shader: its keywords are fragment-only
        let ratio = |t: Duration| t.as_secs_f64() / naga.as_secs_f64();
        println!(
            "{:>8} {:>7} {:>6} {:>9.2?} {:>10.2?} {:>5.2}x {:>10.2?} {:>5.2}x {:>10.2?} {:>5.2}x {:>9.2?} {:>9.2?} {:>10} {:>6.0} MiB {:>6.0} MiB {:>6} B/v {:>7.2} MB",
            cold.variants,
            cold.modules,
            vertex_jobs,
            naga,
            check_time,
            ratio(check_time),
            whole_time,
            ratio(whole_time),
            cold_time,
            ratio(cold_time),
            noop_time,
            touch_time,
            format!("{}/{}", touch.compiled, cold.modules),
            memory,
            noop_memory,
            manifest_bytes / cold.variants as u64,
            rust_bytes as f64 / 1e6
        );
        assert!(
            touch.compiled <= cold.modules * including / shaders + 1,
            "only what includes the file recompiles"
        );
        println!(
            "  per round, / naga ({rounds} rounds): check {}, build from whole texts {}, from cut texts each parsed alone {}, build {}; naga parsed {} texts ({} modules cut out of parses together)",
            spread(check_ratios),
            spread(whole_ratios),
            spread(alone_ratios),
            spread(cold_ratios),
            cold.parses,
            cold.parsed_together
        );
        print!("{}", cut_table(&project));
        // For profiling a build of the same project: `KILN_SCALE_KEEP=1` keeps it.
        if std::env::var_os("KILN_SCALE_KEEP").is_some() {
            println!("kept {}", dir.display());
        } else {
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
}
