//! kiln's HLSL route against glslang alone, on the same variants, in one run: `cargo bench
//! --bench hlsl` (sizes and shapes: `-- 64,256 lit unity`). For each size and shape it writes a project
//! of one HLSL shader (the fixture's unlit pass, the tutorial's lit pass with kiln's HLSL
//! library, or Unity's built-in `Unlit/Texture` in Cg with `UnityCG.cginc`, each with eight
//! `shader_feature_fragment` terms) and materials choosing distinct
//! combinations, then measures, in interleaved rounds: kiln's cold build; glslang alone in
//! process on each distinct preprocessed stage text, whole, as one would hand it to glslang (its
//! HLSL front end to SPIR-V, on every core, as kiln runs it; kiln cuts each text to what its entry
//! point reaches first); the same followed by naga's SPIR-V reader (kiln's front end, without
//! binding, validation or any back end); the tools alone making the same outputs (that, with
//! naga's validation and its WGSL and SPIR-V writers); Khronos' `glslangValidator`, one process
//! per stage text, where it is installed; and a no-op rebuild. Results: docs/performance.md
//! ("HLSL").

use kiln::preprocess::Stage;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use rayon::prelude::*;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[path = "support/measure.rs"]
mod measure;
use measure::{median, spread, whole_texts};

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

const KEYWORDS: usize = 8;

/// The shader a bench project builds: the fixture's unlit pass alone, the tutorial's lit pass
/// with kiln's HLSL library (Common, Surface, Light, BRDF, Lighting) in every stage text, or
/// Unity's built-in `Unlit/Texture` in Cg with Unity's own `UnityCG.cginc` (MIT, the corpus kiln's
/// tests use).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Shape {
    Unlit,
    Lit,
    Unity,
}

/// Eight terms on `result`, each behind its keyword `_F0`..`_F7`.
fn terms(result: &str) -> String {
    (0..KEYWORDS)
        .map(|k| {
            format!(
                "#if defined(_F{k})\n    {result} = lerp({result}, pow(saturate({result}.gbr * {s} + {o}), {p}) * exp2(-{result}), {t});\n#endif\n",
                s = 1.0 + k as f32 * 0.25,
                o = 0.1 * k as f32,
                p = 1.5 + k as f32 * 0.125,
                t = 0.5 / (k + 1) as f32
            )
        })
        .collect()
}

/// `text` with `what` inserted before `before`, which it must hold.
fn inserted(text: &str, before: &str, what: &str) -> String {
    assert!(text.contains(before), "the shader has `{before}` where the bench expects it");
    text.replacen(before, &format!("{what}{before}"), 1)
}

/// A project of `variants` materials of one HLSL shader of `shape`, each a distinct keyword
/// combination of eight fragment terms.
fn generate(dir: &Path, variants: usize, shape: Shape) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(dir.join("materials")).expect("mkdir");
    let pragmas: String =
        (0..KEYWORDS).map(|k| format!("            #pragma shader_feature_fragment _ _F{k}\n")).collect();
    let read = |path: PathBuf| std::fs::read_to_string(path).expect("the fixture");
    let (shader, config) = match shape {
        Shape::Unlit | Shape::Lit => {
            let (folder, pass_file, shader_file, name, result, returned) = match shape {
                Shape::Unlit => {
                    ("hlsl", "UnlitPass.hlsl", "Unlit.shader", "HLSL/Unlit", "base.rgb", "    return base;\n")
                }
                _ => (
                    "hlsl_lit",
                    "LitPass.hlsl",
                    "Lit.shader",
                    "Custom RP/Lit",
                    "color",
                    "    return float4(color, surface.alpha);\n",
                ),
            };
            let fixture = root.join("fixtures").join(folder).join("shaders");
            let pass = inserted(&read(fixture.join(pass_file)), returned, &terms(result));
            std::fs::write(dir.join("BenchPass.hlsl"), pass).expect("write");
            let shader = read(fixture.join(shader_file))
                .replace(&format!("Shader \"{name}\""), "Shader \"Bench/Hlsl\"")
                .replace(&format!("#include \"{pass_file}\""), "#include \"BenchPass.hlsl\"");
            (inserted(&shader, "            #pragma vertex", &pragmas), "global_keywords = []\n")
        }
        Shape::Unity => {
            let corpus = root.join("tests/corpus/unity/Unity-Built-in-Shaders");
            std::fs::create_dir_all(dir.join("CGIncludes")).expect("mkdir");
            for entry in std::fs::read_dir(corpus.join("CGIncludes")).expect("CGIncludes").flatten() {
                std::fs::copy(entry.path(), dir.join("CGIncludes").join(entry.file_name())).expect("copy");
            }
            let shader = read(corpus.join("DefaultResourcesExtra/Unlit/Unlit-Normal.shader"))
                .replace("Shader \"Unlit/Texture\"", "Shader \"Bench/Hlsl\"")
                .replace("            #pragma multi_compile_fog\n", &pragmas);
            let shader = inserted(&shader, "                return col;\n", &terms("col.rgb"));
            (shader, "global_keywords = []\ninclude_paths = [\"CGIncludes\"]\nshaders = [\"Bench.shader\"]\n")
        }
    };
    std::fs::write(dir.join("Bench.shader"), shader).expect("write");
    std::fs::write(dir.join("kiln.toml"), config).expect("write");
    for m in 0..variants {
        let keywords: Vec<String> =
            (0..KEYWORDS).filter(|b| m & (1 << b) != 0).map(|b| format!("\"_F{b}\"")).collect();
        // Past 256 the fixtures' `_Clipping` property adds a keyword; Unity's shader has none.
        let clip = m >> KEYWORDS & 1 == 1 && shape != Shape::Unity;
        let clip = if clip { "\n[properties]\n_Clipping = 1\n" } else { "" };
        let text = format!("shader = \"Bench/Hlsl\"\nkeywords = [{}]\n{clip}", keywords.join(", "));
        std::fs::write(dir.join(format!("materials/M{m:04}.mat")), text).expect("write");
    }
}

fn kiln_build(project: &Path, output: &Path) -> (usize, Duration) {
    let started = Instant::now();
    let mut store = SourceStore::new();
    let mode = Request { output: Some(output.to_path_buf()), ..Request::default() };
    let (result, diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
    let mut all = diagnostics;
    all.extend(result.diagnostics);
    // Warnings are Unity's includes' own (keywords they test that no pragma declares).
    all.retain(|d| d.is_error());
    assert!(all.is_empty(), "{}", kiln::diagnostics::render_plain(&store, &all));
    (result.summary.compiled, started.elapsed())
}

/// glslang's SPIR-V for one stage text, as kiln asks it.
fn glslang_spirv(stage: Stage, entry: &str, text: &str) -> Vec<u32> {
    use glslang::*;
    let compiler = Compiler::acquire().expect("glslang");
    let source = ShaderSource::from(text);
    let options = CompilerOptions {
        source_language: SourceLanguage::HLSL,
        target: Target::Vulkan { version: VulkanVersion::Vulkan1_1, spirv_version: SpirvVersion::SPIRV1_3 },
        version_profile: None,
        messages: ShaderMessage::DEFAULT | ShaderMessage::READ_HLSL,
    };
    let stage = if stage == Stage::Vertex { ShaderStage::Vertex } else { ShaderStage::Fragment };
    let input = ShaderInput::new(&source, stage, &options, None, None).expect("input");
    let mut builder = Shader::new(compiler, input);
    builder.entry_point(entry);
    builder.parse().expect("parses").compile().expect("compiles")
}

/// What the tools alone make of a SPIR-V module as kiln ships it: naga validates it and writes
/// WGSL and SPIR-V (no binding, compaction, layout check, reflection or files).
fn outputs(module: &naga::Module) -> usize {
    naga_steps(module, [true, true])
}

/// naga's validation of `module`, then its WGSL and SPIR-V writers where `writers` says: the
/// bytes written.
fn naga_steps(module: &naga::Module, [wgsl, spirv]: [bool; 2]) -> usize {
    use naga::valid::{Capabilities, ValidationFlags, Validator};
    // glslang numbers every resource 0: only kiln's binding makes them valid, so that check is off.
    let flags = ValidationFlags::all() - ValidationFlags::BINDINGS;
    let info = Validator::new(flags, Capabilities::all()).validate(module).expect("valid");
    let wgsl = wgsl.then(|| {
        naga::back::wgsl::write_string(module, &info, naga::back::wgsl::WriterFlags::empty()).expect("WGSL")
    });
    let spirv = spirv.then(|| {
        naga::back::spv::write_vec(module, &info, &naga::back::spv::Options::default(), None).expect("SPIR-V")
    });
    1 + wgsl.map_or(0, |w| w.len()) + spirv.map_or(0, |s| s.len() * 4)
}

fn spv_in(words: &[u32]) -> naga::Module {
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    let options = naga::front::spv::Options {
        adjust_coordinate_space: false,
        strict_capabilities: false,
        block_ctx_dump_prefix: None,
    };
    naga::front::spv::parse_u8_slice(&bytes, &options).expect("naga reads it")
}

/// `glslangValidator`, one process per text, as many at once as there are cores.
fn glslang_processes(texts: &[(Stage, String, String)], scratch: &Path) -> Option<Duration> {
    let found = std::process::Command::new("glslangValidator")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        return None;
    }
    let files: Vec<PathBuf> = texts
        .iter()
        .enumerate()
        .map(|(i, (_, _, text))| {
            let path = scratch.join(format!("{i}.hlsl"));
            std::fs::write(&path, text).expect("write");
            path
        })
        .collect();
    let started = Instant::now();
    texts.par_iter().zip(&files).for_each(|((stage, entry, _), file)| {
        let stage = if *stage == Stage::Vertex { "vert" } else { "frag" };
        let out = file.with_extension("spv");
        let run = std::process::Command::new("glslangValidator")
            .args(["-D", "-S", stage, "-e", entry, "-V", "--target-env", "vulkan1.1", "-o"])
            .arg(&out)
            .arg(file)
            .output()
            .expect("runs");
        assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stdout));
    });
    Some(started.elapsed())
}

fn main() {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .find(|a| a.chars().next().is_some_and(|c| c.is_ascii_digit()))
        .map(|list| list.split(',').filter_map(|n| n.parse().ok()).collect())
        .unwrap_or_else(|| vec![64, 256]);
    let rounds: usize =
        std::env::var("KILN_SCALE_ROUNDS").ok().and_then(|n| n.parse().ok()).unwrap_or(5).max(1);
    // `unlit`, `lit` or `unity` after the sizes picks shapes; all three by default.
    let args: Vec<String> = std::env::args().collect();
    let named = [(Shape::Unlit, "unlit"), (Shape::Lit, "lit"), (Shape::Unity, "unity")];
    let any_named = args.iter().any(|a| named.iter().any(|(_, n)| a == n));
    let shapes: Vec<Shape> = (named.into_iter())
        .filter(|(_, name)| !any_named || args.iter().any(|a| a == name))
        .map(|(shape, _)| shape)
        .collect();
    println!("threads: {}, rounds: {rounds}", rayon::current_num_threads());
    for (shape, size) in shapes.iter().flat_map(|&shape| sizes.iter().map(move |&size| (shape, size))) {
        let dir = tempfile::tempdir().expect("temp dir");
        let project = dir.path().join("project");
        generate(&project, size, shape);
        let texts = whole_texts(&project);
        let (mut kiln, mut alone, mut front, mut processes, mut noop) =
            (vec![], vec![], vec![], vec![], vec![]);
        let mut tools = vec![];
        // naga's steps alone, on the modules glslang and spv-in made: validation, then each writer.
        let read: Vec<naga::Module> = texts
            .par_iter()
            .map(|(stage, entry, text)| spv_in(&glslang_spirv(*stage, entry, text)))
            .collect();
        let steps = [[false, false], [true, false], [false, true]];
        let mut naga_alone: [Vec<Duration>; 3] = Default::default();
        let mut compiled = 0;
        for round in 0..rounds {
            let output = dir.path().join(format!("out{round}"));
            let (modules, took) = kiln_build(&project, &output);
            compiled = modules;
            kiln.push(took);
            let started = Instant::now();
            texts.par_iter().for_each(|(stage, entry, text)| drop(glslang_spirv(*stage, entry, text)));
            alone.push(started.elapsed());
            let started = Instant::now();
            texts
                .par_iter()
                .for_each(|(stage, entry, text)| drop(spv_in(&glslang_spirv(*stage, entry, text))));
            front.push(started.elapsed());
            let started = Instant::now();
            let written: usize = texts
                .par_iter()
                .map(|(stage, entry, text)| outputs(&spv_in(&glslang_spirv(*stage, entry, text))))
                .sum();
            tools.push(started.elapsed());
            assert!(written > 0, "the tools wrote nothing");
            for (step, times) in steps.iter().zip(&mut naga_alone) {
                let started = Instant::now();
                let written: usize = read.par_iter().map(|module| naga_steps(module, *step)).sum();
                times.push(started.elapsed());
                assert!(written > 0);
            }
            let scratch = dir.path().join(format!("cli{round}"));
            std::fs::create_dir_all(&scratch).expect("mkdir");
            if let Some(took) = glslang_processes(&texts, &scratch) {
                processes.push(took);
            }
            noop.push(kiln_build(&project, &output).1);
        }
        // Whole texts that differ only where no entry point reaches (a fragment keyword in the
        // vertex stage's text) are one module once cut.
        assert!(compiled <= texts.len(), "kiln compiles each distinct text at most once");
        let ratio = |a: &[Duration], b: &[Duration]| {
            spread(a.iter().zip(b).map(|(a, b)| a.as_secs_f64() / b.as_secs_f64()).collect())
        };
        let per = |d: Duration| d.as_secs_f64() * 1000.0 / texts.len() as f64;
        let (k, g, f) = (median(kiln.clone()), median(alone.clone()), median(front.clone()));
        println!(
            "{shape:?}, {size} materials: {} distinct stage texts (kiln compiled {compiled})",
            texts.len()
        );
        println!(
            "  kiln build          {:>8.1} ms  ({:.2} ms a stage module)",
            k.as_secs_f64() * 1000.0,
            per(k)
        );
        println!("  glslang in process  {:>8.1} ms  ({:.2} ms)", g.as_secs_f64() * 1000.0, per(g));
        println!("  + naga's spv-in     {:>8.1} ms  ({:.2} ms)", f.as_secs_f64() * 1000.0, per(f));
        if !processes.is_empty() {
            let p = median(processes.clone());
            println!(
                "  glslangValidator    {:>8.1} ms  ({:.2} ms, a process per text)",
                p.as_secs_f64() * 1000.0,
                per(p)
            );
            println!("  kiln / glslangValidator processes: {}", ratio(&kiln, &processes));
        }
        println!("  kiln / glslang in process: {}", ratio(&kiln, &alone));
        println!("  kiln / (glslang + spv-in): {}", ratio(&kiln, &front));
        let t = median(tools.clone());
        println!(
            "  the tools alone, same outputs (+ naga's validation, WGSL and SPIR-V): {:.1} ms",
            t.as_secs_f64() * 1000.0
        );
        println!("  kiln / the tools alone: {}", ratio(&kiln, &tools));
        let [valid, wgsl, spirv] = naga_alone.map(median);
        let of_glslang = |d: Duration| 100.0 * d.as_secs_f64() / g.as_secs_f64();
        println!(
            "  naga alone on the modules read: validation {:.1} ms ({:.0}% of glslang's time), WGSL writer {:.1} ms ({:.0}%), SPIR-V writer {:.1} ms ({:.0}%)",
            valid.as_secs_f64() * 1000.0,
            of_glslang(valid),
            wgsl.saturating_sub(valid).as_secs_f64() * 1000.0,
            of_glslang(wgsl.saturating_sub(valid)),
            spirv.saturating_sub(valid).as_secs_f64() * 1000.0,
            of_glslang(spirv.saturating_sub(valid))
        );
        let share = |part: Duration| 100.0 * part.as_secs_f64() / k.as_secs_f64();
        println!(
            "  the tools on whole texts against kiln's build: glslang {:.0}%, spv-in {:.0}%, kiln beyond both {:.0}%",
            share(g),
            share(f.saturating_sub(g)),
            share(k.saturating_sub(f))
        );
        println!(
            "  no-op rebuild       {:>8.1} ms  (cold / no-op: {})",
            median(noop.clone()).as_secs_f64() * 1000.0,
            ratio(&kiln, &noop)
        );
    }
}
