//! WGSL test corpora nobody on kiln's team wrote, through kiln: naga's own test inputs
//! (tests/corpus/naga, MIT/Apache) and Tint's end-to-end test inputs from Dawn (tests/corpus/tint,
//! BSD-3; ORIGIN.md in each). Each file naga accepts on its own, with what kiln grants (WebGPU's
//! baseline and `f16`), must build through kiln wrapped as a pass per vertex or fragment entry
//! point and as a compute shader with a kernel per compute entry point, and each file naga refuses
//! must be refused by kiln too. Every module kiln writes must load again: each SPIR-V module passes
//! `spirv-val`, and each WGSL module parses and validates again in naga. Every file must come back
//! from `kiln preprocess` token for token.

use crate::support::{kiln, root, tool};
use kiln::config::{ParseScope, VariantSelection};
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use naga::valid::{Capabilities, ValidationFlags, Validator};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A corpus: its folder (under the root, or absolute), and the prefix of its shaders' names.
struct Corpus {
    folder: std::borrow::Cow<'static, str>,
    label: &'static str,
}

const NAGA: Corpus = Corpus { folder: std::borrow::Cow::Borrowed("tests/corpus/naga/in"), label: "Naga" };
const TINT: Corpus =
    Corpus { folder: std::borrow::Cow::Borrowed("tests/corpus/tint/test/tint"), label: "Tint" };

impl Corpus {
    /// Every `.wgsl` file under the folder, by a flat name (its path with `.` for `/`), sorted.
    fn files(&self) -> Vec<(String, PathBuf)> {
        let folder = root().join(self.folder.as_ref());
        let mut files: Vec<(String, PathBuf)> = walkdir::WalkDir::new(&folder)
            .into_iter()
            .map(|e| e.expect("entry").into_path())
            .filter(|p| p.extension().is_some_and(|e| e == "wgsl"))
            .map(|p| {
                let relative = p.strip_prefix(&folder).expect("under the folder");
                let name = relative.to_string_lossy().replace(['/', '\\'], ".");
                (name, p)
            })
            .collect();
        files.sort();
        files
    }
}

/// What naga grants a corpus file: what kiln's highest target allows.
fn capabilities() -> Capabilities {
    kiln::compile::target::webgpu_baseline() | Capabilities::SHADER_FLOAT16
}

/// What naga alone says of a text, its vertex and fragment entry points, and its compute ones.
struct NagaVerdict {
    accepted: Result<(), String>,
    entry_points: Vec<(&'static str, String)>,
    kernels: Vec<String>,
}

fn naga_alone(text: &str) -> NagaVerdict {
    match naga::front::wgsl::parse_str(text) {
        Err(error) => {
            // The entry points as written, for a text naga cannot parse.
            let mut entry_points = Vec::new();
            for (attribute, stage) in
                [("@vertex", "vertex"), ("@fragment", "fragment"), ("@compute", "compute")]
            {
                for (at, _) in text.match_indices(attribute) {
                    // `@compute @workgroup_size(...)` then `fn`: the name after the next `fn `.
                    let rest = &text[at + attribute.len()..];
                    let rest =
                        if stage == "compute" { rest.find("fn ").map_or("", |i| &rest[i..]) } else { rest };
                    if let Some(name) = rest.trim_start().strip_prefix("fn ") {
                        let name: String =
                            name.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                        entry_points.push((stage, name));
                    }
                }
            }
            let kernels =
                entry_points.iter().filter(|(s, _)| *s == "compute").map(|(_, n)| n.clone()).collect();
            entry_points.retain(|(stage, _)| *stage != "compute");
            NagaVerdict { accepted: Err(error.emit_to_string(text)), entry_points, kernels }
        }
        Ok(module) => {
            let accepted = Validator::new(ValidationFlags::all(), capabilities())
                .validate(&module)
                .map(|_| ())
                .map_err(|e| e.emit_to_string(text));
            let entry_points: Vec<(&'static str, String)> = module
                .entry_points
                .iter()
                .filter_map(|e| match e.stage {
                    naga::ShaderStage::Vertex => Some(("vertex", e.name.clone())),
                    naga::ShaderStage::Fragment => Some(("fragment", e.name.clone())),
                    _ => None,
                })
                .collect();
            let kernels = module
                .entry_points
                .iter()
                .filter(|e| e.stage == naga::ShaderStage::Compute)
                .map(|e| e.name.clone())
                .collect();
            NagaVerdict { accepted, entry_points, kernels }
        }
    }
}

/// The vertex entry point a fragment entry point's pass is given.
const CORPUS_VERTEX: &str = "kiln_corpus_vertex";

/// `file` as a shader of its own: a pass per entry point, each including the file whole, at the
/// highest target (so kiln's interpolator and colour-target limits are WebGPU's). A fragment
/// entry point's pass gets a vertex stage of its own after the file (a pass needs one, K0215).
fn wrapper(label: &str, name: &str, text: &str, entry_points: &[(&str, String)]) -> String {
    let require = if text.contains("enable f16") { "#pragma require native16bit\n" } else { "" };
    let mut out = format!("Shader \"{label}/{name}\" {{\n    SubShader {{\n");
    let passes: Vec<Option<&(&str, String)>> =
        if entry_points.is_empty() { vec![None] } else { entry_points.iter().map(Some).collect() };
    for entry in passes {
        let (pragma, after) = match entry {
            Some(("fragment", entry)) => (
                format!("#pragma vertex {CORPUS_VERTEX}\n#pragma fragment {entry}\n"),
                format!(
                    "@vertex fn {CORPUS_VERTEX}() -> @builtin(position) vec4<f32> {{ return vec4<f32>(); }}\n"
                ),
            ),
            Some((stage, entry)) => (format!("#pragma {stage} {entry}\n"), String::new()),
            None => (String::new(), String::new()),
        };
        let _ = write!(
            out,
            "        Pass {{\nWGSLPROGRAM\n#pragma target 5.0\n{require}{pragma}#include \"{name}\"\n{after}ENDWGSL\n        }}\n"
        );
    }
    out.push_str("    }\n}\n");
    out
}

/// `file` as a compute shader of its own: a kernel per compute entry point, at the highest target.
fn compute_wrapper(name: &str, text: &str, kernels: &[String]) -> String {
    let require = if text.contains("enable f16") { "#pragma require native16bit\n" } else { "" };
    let pragmas: String = kernels.iter().map(|k| format!("#pragma kernel {k}\n")).collect();
    format!("#pragma target 5.0\n{require}{pragmas}#include \"{name}\"\n")
}

/// WGSL tokens, comments and whitespace left out.
fn tokens(text: &str) -> Vec<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_whitespace() {
            i += 1;
        } else if bytes[i..].starts_with(b"//") {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if bytes[i..].starts_with(b"/*") {
            let mut depth = 0;
            while i < bytes.len() {
                if bytes[i..].starts_with(b"/*") {
                    depth += 1;
                    i += 2;
                } else if bytes[i..].starts_with(b"*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.' {
            let start = i;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.')
            {
                i += 1;
            }
            out.push(text[start..i].to_string());
        } else {
            let len = text[i..].chars().next().map_or(1, char::len_utf8);
            out.push(text[i..i + len].to_string());
            i += len;
        }
    }
    out
}

/// What a corpus gave: counts for the report, and what failed.
#[derive(Default)]
struct Report {
    files: usize,
    built: usize,
    compute_built: usize,
    refused_alike: usize,
    kiln_refusals: usize,
    no_entry_point: usize,
    spirv_modules: usize,
    wgsl_modules: usize,
    /// Per back end (MSL, HLSL, GLSL): the files it writes whole, and kiln's diagnostics for the
    /// rest by code (K0422 what the language lacks, K0409 a writer error, K0416 a writer panic,
    /// K0423 glslang refusing what naga wrote).
    backends: BTreeMap<&'static str, (usize, BTreeMap<&'static str, usize>)>,
    /// Modules built from their whole text: naga refused the cut one.
    uncut: usize,
    /// The build against one from whole texts (where `spirv-dis` is installed).
    cut: Option<crate::reach::Comparison>,
    failures: Vec<String>,
}

/// Builds a corpus through kiln and holds each file to naga's verdict, then every module kiln
/// wrote to `spirv-val` (when `spirv_tools`, which also compares the build with one from whole
/// texts) and to naga's WGSL front end and validator.
fn judge(corpus: &Corpus, spirv_tools: bool) -> Report {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    std::fs::create_dir_all(&project).expect("project");
    let mut verdicts = BTreeMap::new();
    let mut names = BTreeMap::new();
    for (name, file) in corpus.files() {
        let text = std::fs::read_to_string(&file).expect("corpus file");
        let verdict = naga_alone(&text);
        let mut shaders = Vec::new();
        if !verdict.entry_points.is_empty() {
            let wrapped = wrapper(corpus.label, &name, &text, &verdict.entry_points);
            std::fs::write(project.join(format!("{name}.shader")), wrapped).expect("wrapper");
            shaders.push(format!("{:?}", format!("{}/{name}", corpus.label)));
        }
        if !verdict.kernels.is_empty() {
            let wrapped = compute_wrapper(&name, &text, &verdict.kernels);
            std::fs::write(project.join(format!("{name}.compute")), wrapped).expect("wrapper");
            shaders.push(format!("{name:?}"));
        }
        if !shaders.is_empty() {
            std::fs::write(project.join(&name), &text).expect("copy");
        }
        names.insert(name.clone(), shaders);
        verdicts.insert(name, verdict);
    }
    let kiln_toml = |names: &mut dyn Iterator<Item = &String>| {
        format!("always_include = [{}]\n", names.map(String::as_str).collect::<Vec<_>>().join(", "))
    };
    std::fs::write(project.join("kiln.toml"), kiln_toml(&mut names.values().flatten())).expect("kiln.toml");
    let mut store = SourceStore::new();
    let mode = Request { unused_shaders: VariantSelection::All { limit: 16 }, ..Request::default() };
    let (result, mut diagnostics) =
        build_project(&mut store, std::slice::from_ref(&project), &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    // Each error by the corpus file it is about (its own text, or the wrapper including it).
    let mut errors: BTreeMap<String, Vec<kiln::diagnostics::Diagnostic>> = BTreeMap::new();
    for d in diagnostics.iter().filter(|d| d.severity == kiln::diagnostics::Severity::Error) {
        let file = d
            .primary
            .as_ref()
            .and_then(|p| store.path(p.span.file))
            .map(Path::to_path_buf)
            .unwrap_or_default();
        let name = file
            .file_name()
            .map(|n| n.to_string_lossy().trim_end_matches(".shader").trim_end_matches(".compute").to_string())
            .unwrap_or_default();
        errors.entry(name).or_default().push(d.clone());
    }
    let mut report = Report { files: verdicts.len(), ..Report::default() };
    for (name, verdict) in &verdicts {
        let found = errors.get(name).map(Vec::as_slice).unwrap_or_default();
        let rendered = kiln::diagnostics::render_plain(&store, found);
        let compute = usize::from(!verdict.kernels.is_empty());
        match (&verdict.accepted, verdict.entry_points.is_empty() && verdict.kernels.is_empty()) {
            (_, true) => report.no_entry_point += 1,
            (Ok(()), false) if found.is_empty() => {
                report.built += 1;
                report.compute_built += compute;
            }
            // Documented: valid WGSL no writer of naga's can express (docs/diagnostics.md).
            (Ok(()), false) if found.iter().all(|d| d.code == "K0418") => report.kiln_refusals += 1,
            (Ok(()), false) => {
                report.failures.push(format!("{name}: naga accepts it, kiln refuses:\n{rendered}"))
            }
            (Err(_), false) if !found.is_empty() => report.refused_alike += 1,
            // naga refuses a type too large that only a constant expression names
            // (`array<i32, 636109182>()[0]`); kiln validates the module cut to its entry point,
            // after naga folded the expression to 0 and the type went with it.
            (Err(_), false) if name == "bug.chromium.1449538.wgsl" => report.refused_alike += 1,
            (Err(why), false) => {
                report.failures.push(format!("{name}: naga refuses it, kiln builds it:\n{why}"))
            }
        }
    }
    // The files naga accepts and kiln builds, built again on their own with output, so that
    // every module they give is checked.
    let accepted = dir.path().join("accepted");
    std::fs::create_dir_all(&accepted).expect("folder");
    let built = |name: &&String| verdicts[*name].accepted.is_ok() && !errors.contains_key(*name);
    for name in names.keys().filter(built).filter(|n| !names[*n].is_empty()) {
        for file in [name.clone(), format!("{name}.shader"), format!("{name}.compute")] {
            if project.join(&file).exists() {
                std::fs::copy(project.join(&file), accepted.join(&file)).expect("copy");
            }
        }
    }
    let mut kept = names.iter().filter(|(n, _)| built(n)).flat_map(|(_, shaders)| shaders);
    std::fs::write(accepted.join("kiln.toml"), kiln_toml(&mut kept)).expect("kiln.toml");
    let output = dir.path().join("accepted-out");
    let (summary, _) =
        crate::support::build_without_errors(&accepted, Some(&output), VariantSelection::All { limit: 16 });
    report.uncut = summary.uncut;
    // Built again from whole texts: the cut to what entry points reach changes no module.
    if spirv_tools {
        let whole = dir.path().join("accepted-whole");
        let (_, errors) = crate::reach::build_with(
            &accepted,
            &whole,
            ParseScope::Whole,
            VariantSelection::All { limit: 16 },
        );
        report.failures.extend(errors);
        let comparison = crate::reach::compare(&whole, &output, &dir.path().join("disassembled"));
        report.failures.extend(comparison.failures.iter().map(|f| format!("cut against whole: {f}")));
        report.cut = Some(comparison);
    }
    let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
    let stages: Vec<_> = manifest.stages().collect();
    let failures = std::sync::Mutex::new(Vec::new());
    let counts = std::sync::Mutex::new((0, 0));
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get()).min(8);
    std::thread::scope(|scope| {
        for (t, part) in stages.chunks(stages.len().div_ceil(threads).max(1)).enumerate() {
            let (failures, counts, output, dir) = (&failures, &counts, &output, dir.path());
            scope.spawn(move || {
                for (i, stage) in part.iter().enumerate() {
                    let entry = format!(
                        "{} `{}`",
                        stage.files().next().map_or_else(|| "?".to_string(), |f| f.path.to_string()),
                        stage.interface.entry_point
                    );
                    if let Some(file) = stage.wgsl() {
                        let text = String::from_utf8(file.read(output).expect("module")).expect("UTF-8");
                        if let Err(why) = wgsl_loads(&text) {
                            failures.lock().expect("lock").push(format!(
                                "{entry}: kiln's WGSL does not load again in naga: {why}\n{text}"
                            ));
                        }
                        counts.lock().expect("lock").1 += 1;
                    }
                    let Some(file) = stage.spirv().filter(|_| spirv_tools) else { continue };
                    let bytes = file.read(output).expect("module");
                    let path = dir.join(format!("module-{t}-{i}.spv"));
                    std::fs::write(&path, &bytes).expect("write");
                    let environment = if bytes[6] == 1 && bytes[5] == 0 { "vulkan1.0" } else { "vulkan1.1" };
                    let run = std::process::Command::new("spirv-val")
                        .args(["--target-env", environment])
                        .arg(&path)
                        .output()
                        .expect("spirv-val");
                    if !run.status.success() {
                        failures
                            .lock()
                            .expect("lock")
                            .push(format!("{entry}: spirv-val: {}", String::from_utf8_lossy(&run.stderr)));
                    }
                    counts.lock().expect("lock").0 += 1;
                }
            });
        }
    });
    report.failures.extend(failures.into_inner().expect("lock"));
    (report.spirv_modules, report.wgsl_modules) = counts.into_inner().expect("lock");
    report.backends = other_backends(&accepted, &mut report.failures);
    report
}

/// The files of the project at `accepted` (each builds in WGSL and SPIR-V) checked in each other
/// back end on its own (a module's first failing back end would hide the rest), glslang reading
/// the GLSL and HLSL back where it is installed.
fn other_backends(
    accepted: &Path,
    failures: &mut Vec<String>,
) -> BTreeMap<&'static str, (usize, BTreeMap<&'static str, usize>)> {
    use kiln::manifest::Backend;
    let mut counts = BTreeMap::new();
    for backend in [Backend::Msl, Backend::Hlsl, Backend::Glsl] {
        let mut store = SourceStore::new();
        let mode = Request {
            write: false,
            backends: vec![backend],
            unused_shaders: VariantSelection::All { limit: 16 },
            ..Request::default()
        };
        let (result, mut diagnostics) =
            build_project(&mut store, &[accepted.to_path_buf()], &mode, &|_, _| {}).expect("project");
        diagnostics.extend(result.diagnostics);
        let mut codes: BTreeMap<&'static str, usize> = BTreeMap::new();
        let mut refused = std::collections::BTreeSet::new();
        for d in diagnostics.iter().filter(|d| d.severity == kiln::diagnostics::Severity::Error) {
            if !["K0409", "K0416", "K0422", "K0423"].contains(&d.code) {
                failures.push(format!(
                    "{backend}: {}",
                    kiln::diagnostics::render_plain(&store, std::slice::from_ref(d))
                ));
            }
            *codes.entry(d.code).or_default() += 1;
            refused.extend(d.primary.as_ref().map(|p| p.span.file));
        }
        let wrappers = std::fs::read_dir(accepted)
            .expect("folder")
            .filter(|e| {
                e.as_ref()
                    .is_ok_and(|e| e.path().extension().is_some_and(|x| x == "shader" || x == "compute"))
            })
            .count();
        counts.insert(backend.name(), (wrappers - refused.len(), codes));
    }
    counts
}

/// Whether a WGSL module kiln wrote parses and validates again in naga, as wgpu would load it.
fn wgsl_loads(text: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(text).map_err(|e| e.emit_to_string(text))?;
    Validator::new(ValidationFlags::all(), capabilities())
        .validate(&module)
        .map_err(|e| e.emit_to_string(text))?;
    Ok(())
}

fn check_corpus(corpus: &Corpus, test: &str, at_least: usize) {
    let spirv_val = tool("spirv-val", "spirv-tools", test);
    let report = judge(corpus, spirv_val);
    assert_eq!(report.uncut, 0, "naga refused a cut whose whole text it accepts");
    if let Some(cut) = &report.cut {
        let line = format!("{}\n", cut.line());
        print!("cut to what entry points reach, against whole texts: {line}");
        let golden = format!("tests/golden/reach/{}.txt", corpus.label.to_lowercase());
        expect_test::expect_file![root().join(golden)].assert_eq(&line);
    }
    println!(
        "{}'s {} WGSL files: {} built as naga accepts them ({} with compute kernels), {} refused as naga \
         refuses them, {} refused by kiln (K0418), {} with no entry point; {} WGSL modules loaded again \
         in naga, {} SPIR-V modules through spirv-val",
        corpus.label,
        report.files,
        report.built,
        report.compute_built,
        report.refused_alike,
        report.kiln_refusals,
        report.no_entry_point,
        report.wgsl_modules,
        report.spirv_modules,
    );
    let mut table = String::new();
    for (backend, (whole, codes)) in &report.backends {
        let _ = writeln!(table, "{backend}: {whole} shaders written whole; diagnostics {codes:?}");
    }
    print!("{table}");
    if tool("glslangValidator", "glslang-tools", test) {
        // Pinned where glslang reads the GLSL and HLSL back, as in CI (docs/backends.md).
        let golden = format!("tests/golden/backends/{}.txt", corpus.label.to_lowercase());
        expect_test::expect_file![root().join(golden)].assert_eq(&table);
    }
    assert!(
        report.failures.is_empty(),
        "{} failures:\n{}",
        report.failures.len(),
        report.failures.join("\n\n")
    );
    assert!(report.built >= at_least, "only {} built", report.built);
}

#[test]
fn naga_s_wgsl_tests_build_through_kiln_as_naga_judges_them() {
    check_corpus(&NAGA, "naga_s_wgsl_tests_build_through_kiln_as_naga_judges_them", 30);
}

#[test]
fn tint_s_wgsl_tests_build_through_kiln_as_naga_judges_them() {
    let test = "tint_s_wgsl_tests_build_through_kiln_as_naga_judges_them";
    if !crate::support::full_tier(test, "builds 1,500 files, minutes in a debug build") {
        return;
    }
    check_corpus(&TINT, "tint_s_wgsl_tests_build_through_kiln_as_naga_judges_them", 1500);
}

/// The whole of Tint's test inputs (11,638 files with `builtins/gen/`), from a Dawn checkout that
/// `KILN_TINT_DIR` names (its `test/tint`): too large to commit, run by hand
/// (`KILN_TINT_DIR=~/dawn/test/tint cargo test --release --test it whole_tint -- --ignored`).
#[test]
#[ignore = "needs a Dawn checkout in KILN_TINT_DIR"]
fn whole_tint_corpus_from_a_dawn_checkout() {
    let folder = std::env::var("KILN_TINT_DIR").expect("KILN_TINT_DIR names Dawn's test/tint");
    let corpus = Corpus { folder: folder.into(), label: "Tint" };
    check_corpus(&corpus, "whole_tint_corpus_from_a_dawn_checkout", 1500);
}

fn come_back_token_for_token(corpus: &Corpus) {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut failures = Vec::new();
    for (name, file) in corpus.files() {
        let text = std::fs::read_to_string(&file).expect("corpus file");
        std::fs::write(dir.path().join(&name), &text).expect("copy");
        let shader = dir.path().join(format!("{name}.shader"));
        // One pass, no entry point: preprocessing needs none.
        std::fs::write(&shader, wrapper(corpus.label, &name, &text, &[])).expect("wrapper");
        let run = kiln(&["preprocess", shader.to_str().expect("UTF-8")]);
        let out = String::from_utf8_lossy(&run.stdout);
        if run.status.code() != Some(0) {
            failures.push(format!(
                "{name}: exit {:?}: {}",
                run.status.code(),
                String::from_utf8_lossy(&run.stderr)
            ));
        } else if tokens(&out) != tokens(&text) {
            let (a, b) = (tokens(&text), tokens(&out));
            let at = a.iter().zip(&b).position(|(x, y)| x != y).unwrap_or(a.len().min(b.len()));
            failures.push(format!(
                "{name}: token {at} differs: {:?} vs {:?}",
                a.get(at..at + 5),
                b.get(at..at + 5)
            ));
        }
    }
    assert!(failures.is_empty(), "{} files:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn naga_s_wgsl_tests_come_back_from_kiln_preprocess_token_for_token() {
    come_back_token_for_token(&NAGA);
}

#[test]
fn tint_s_wgsl_tests_come_back_from_kiln_preprocess_token_for_token() {
    let test = "tint_s_wgsl_tests_come_back_from_kiln_preprocess_token_for_token";
    if !crate::support::full_tier(test, "preprocesses every file, about a minute in a debug build") {
        return;
    }
    come_back_token_for_token(&TINT);
}
