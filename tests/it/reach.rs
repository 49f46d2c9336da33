//! A build hands naga only the declarations each entry point reaches (`compile::reach`): the
//! modules it ships are those of the whole text. Held against the whole-text build of every
//! fixture and corpus, byte for byte where naga writes the same bytes, and through `spirv-dis`
//! with canonical ids where naga's SPIR-V declares types in another order.

use crate::support::{copy_tree, root, tool};
use kiln::config::{ParseScope, VariantSelection};
use kiln::orchestrate::BuildSummary;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

/// Builds `project` into `output`, naga parsing as `parse` says; the summary and the rendered
/// errors.
pub fn build_with(
    project: &Path,
    output: &Path,
    parse: ParseScope,
    unused_shaders: VariantSelection,
) -> (BuildSummary, Vec<String>) {
    let mut store = SourceStore::new();
    // One thread: with more, two passes sharing a text may both parse it before either has
    // finished (the other passes' source is "what they made lately"), and the counts the goldens
    // pin would move with the machine's load. The bytes written never do.
    let mode = Request {
        output: Some(output.to_path_buf()),
        unused_shaders,
        parse: Some(parse),
        threads: Some(1),
        ..Request::default()
    };
    let (result, mut diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    let errors = diagnostics
        .iter()
        .filter(|d| d.severity == kiln::diagnostics::Severity::Error)
        .map(|d| kiln::diagnostics::render_plain(&store, std::slice::from_ref(d)))
        .collect();
    (result.summary, errors)
}

/// Two builds of one project compared module by module.
#[derive(Default, Debug)]
pub struct Comparison {
    pub modules: usize,
    /// WGSL and SPIR-V byte for byte the same.
    pub identical: usize,
    /// WGSL the same; SPIR-V the same instructions once ids are canonical ([`Canonical`]),
    /// some declared in another order (naga numbers types as its parse first meets them).
    pub reordered: usize,
    /// The whole text's module also declares types nothing uses: its SPIR-V declares them, and its
    /// WGSL has a blank line more.
    pub unused_types: usize,
    pub failures: Vec<String>,
}

impl Comparison {
    /// Its counts, as the goldens pin them.
    pub fn line(&self) -> String {
        format!(
            "{} modules: {} identical, {} with SPIR-V types declared in another order, {} where the whole text's \
             SPIR-V also declares unused types",
            self.modules, self.identical, self.reordered, self.unused_types
        )
    }
}

/// Compares the build at `cut` with the build at `whole`: the manifests, hashes and pack names
/// aside, and every module. `scratch` holds the SPIR-V `spirv-dis` reads.
pub fn compare(whole: &Path, cut: &Path, scratch: &Path) -> Comparison {
    let mut comparison = Comparison::default();
    let manifest = |dir: &Path| {
        let text = std::fs::read_to_string(dir.join("manifest.json")).expect("manifest");
        let mut json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
        strip_file_names(&mut json);
        json
    };
    if let Some(at) = first_difference(&manifest(whole), &manifest(cut), String::new()) {
        let shader = at.split('/').nth(2).and_then(|i| i.parse::<usize>().ok());
        let name = shader.map(|i| manifest(cut)["shaders"][i]["name"].to_string()).unwrap_or_default();
        comparison
            .failures
            .push(format!("the manifests differ beyond hashes and pack names, at {at} ({name})"));
        return comparison;
    }
    let (a, b) = (
        kiln::manifest::Manifest::read(whole).expect("manifest"),
        kiln::manifest::Manifest::read(cut).expect("manifest"),
    );
    let named = a
        .shaders
        .iter()
        .flat_map(|s| s.passes.iter().flat_map(move |p| p.modules.iter().map(move |_| &s.name)));
    for (i, ((x, y), shader)) in a.stages().zip(b.stages()).zip(named).enumerate() {
        comparison.modules += 1;
        let read =
            |file: Option<kiln::manifest::FileRef>, dir: &Path| file.map(|f| f.read(dir).expect("module"));
        let entry = format!("{shader} {}", x.interface.entry_point);
        let (wgsl_whole, wgsl_cut) = (read(x.wgsl(), whole), read(y.wgsl(), cut));
        // naga's WGSL writer leaves a blank line after the types of a module that has any: a
        // whole text's module may keep types nothing uses (below), which the cut never made.
        let lines = |text: &Option<Vec<u8>>| {
            let text = String::from_utf8_lossy(text.as_deref().unwrap_or_default()).into_owned();
            text.lines().filter(|l| !l.trim().is_empty()).map(str::to_string).collect::<Vec<_>>()
        };
        let wgsl_same = wgsl_whole == wgsl_cut;
        if !wgsl_same && lines(&wgsl_whole) != lines(&wgsl_cut) {
            comparison.failures.push(format!("module {i} (`{entry}`): the WGSL differs"));
            continue;
        }
        let spirv = match (read(x.spirv(), whole), read(y.spirv(), cut)) {
            (p, q) if p == q => Ok(if p.is_some() { Spirv::Identical } else { Spirv::None }),
            (Some(p), Some(q)) => spirv_difference(&p, &q, scratch, i),
            _ => Err("SPIR-V in one build only".to_string()),
        };
        match (spirv, wgsl_same) {
            (Ok(Spirv::Identical | Spirv::None), true) => comparison.identical += 1,
            (Ok(Spirv::Reordered), true) => comparison.reordered += 1,
            (Ok(Spirv::UnusedTypes | Spirv::None), _) => comparison.unused_types += 1,
            (Ok(_), false) => {
                comparison.failures.push(format!("module {i} (`{entry}`): the WGSL's blank lines differ"))
            }
            (Err(why), _) => comparison.failures.push(format!("module {i} (`{entry}`): {why}")),
        }
    }
    comparison
}

/// Where two JSON values first differ: a path of keys and indices, and both values.
fn first_difference(a: &serde_json::Value, b: &serde_json::Value, at: String) -> Option<String> {
    use serde_json::Value::{Array, Object};
    match (a, b) {
        (Object(x), Object(y)) if x.len() == y.len() => {
            x.iter().find_map(|(k, v)| first_difference(v, y.get(k)?, format!("{at}/{k}")))
        }
        (Array(x), Array(y)) if x.len() == y.len() => {
            x.iter().zip(y).enumerate().find_map(|(i, (v, w))| first_difference(v, w, format!("{at}/{i}")))
        }
        _ if a == b => None,
        _ => Some(format!("{at}: {a} against {b}")),
    }
}

/// How two modules' SPIR-V compare.
enum Spirv {
    /// Neither build wrote SPIR-V (a module with `override`s ships as WGSL).
    None,
    Identical,
    /// The same instructions, types and constants declared in another order.
    Reordered,
    /// The whole text's module also declares types or constants nothing uses.
    UnusedTypes,
}

/// The manifest without what names bytes rather than describes them.
fn strip_file_names(json: &mut serde_json::Value) {
    match json {
        serde_json::Value::Object(map) => {
            map.remove("hash");
            map.remove("packs");
            // A module's place in its pack and its size follow from its bytes, compared as bytes.
            if map.contains_key("pack") {
                map.remove("offset");
                map.remove("size");
            }
            map.values_mut().for_each(strip_file_names);
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(strip_file_names),
        _ => {}
    }
}

/// How the SPIR-V of a cut text's module differs from the whole text's (they differ): the same
/// instructions with the types and constants declared in another order, or the whole text's module
/// also declaring types or constants nothing uses (naga keeps the result types of
/// `atomicCompareExchangeWeak`, `modf` and `frexp` that a function the cut left out made), or
/// else what differs. Read from `spirv-dis`'s text, ids made canonical by [`Canonical`].
fn spirv_difference(whole: &[u8], cut: &[u8], scratch: &Path, i: usize) -> Result<Spirv, String> {
    let read = |bytes: &[u8], side: &str| -> Canonical {
        let path = scratch.join(format!("{i}-{side}.spv"));
        std::fs::create_dir_all(scratch).expect("folder");
        std::fs::write(&path, bytes).expect("write");
        let dis = std::process::Command::new("spirv-dis")
            .args(["--no-header", "--raw-id"])
            .arg(&path)
            .output()
            .expect("spirv-dis");
        Canonical::new(&String::from_utf8_lossy(&dis.stdout))
    };
    let (whole, cut) = (read(whole, "whole"), read(cut, "cut"));
    if whole.functions != cut.functions {
        return Err("the functions' instructions differ, ids made canonical".into());
    }
    let mut extra = whole.globals.clone();
    for line in &cut.globals {
        match extra.binary_search(line) {
            Ok(at) => drop(extra.remove(at)),
            Err(_) => return Err(format!("the cut's SPIR-V declares `{line}` and the whole's not")),
        }
    }
    // A type's capability and extension come with it (`Float16` for an `f16` result type).
    let unused = [
        "OpType",
        "OpConstant",
        "OpName",
        "OpMemberName",
        "OpDecorate",
        "OpMemberDecorate",
        "OpCapability",
        "OpExtension",
    ];
    match extra.iter().find(|line| !unused.iter().any(|op| line.contains(op))) {
        None if extra.is_empty() => Ok(Spirv::Reordered),
        None => Ok(Spirv::UnusedTypes),
        Some(line) => Err(format!("the whole's SPIR-V declares `{line}` and the cut's not")),
    }
}

/// A SPIR-V module's disassembly with ids that do not depend on the order of declarations: an id
/// declared before the first function is named by what declares it (its opcode and operands, ids
/// named alike, recursively); an id in a function by the order functions meet it.
struct Canonical {
    /// The declarations, names and decorations before the first function, sorted.
    globals: Vec<String>,
    /// The functions' instructions, in order.
    functions: Vec<String>,
}

impl Canonical {
    fn new(text: &str) -> Canonical {
        let lines: Vec<&str> = text.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
        let first_function = lines.iter().position(|l| l.contains("OpFunction ")).unwrap_or(lines.len());
        let mut declarations: HashMap<&str, &str> = HashMap::new();
        for line in &lines[..first_function] {
            if let Some((id, rest)) = line.split_once(" = ") {
                declarations.insert(id, rest);
            }
        }
        let mut names: HashMap<String, String> = HashMap::new();
        let mut local = 0;
        let rename = |line: &str, names: &mut HashMap<String, String>, local: &mut usize| -> String {
            line.split(' ')
                .map(|word| match word.strip_prefix('%') {
                    Some(_) if declarations.contains_key(word) => global_name(word, &declarations, names),
                    Some(_) => names
                        .entry(word.to_string())
                        .or_insert_with(|| {
                            *local += 1;
                            format!("%l{local}")
                        })
                        .clone(),
                    None => word.to_string(),
                })
                .collect::<Vec<_>>()
                .join(" ")
        };
        let mut globals: Vec<String> =
            lines[..first_function].iter().map(|l| rename(l, &mut names, &mut local)).collect();
        globals.sort();
        let functions = lines[first_function..].iter().map(|l| rename(l, &mut names, &mut local)).collect();
        Canonical { globals, functions }
    }
}

/// The canonical name of a global id: a hash of its declaration, its operands' ids named alike.
fn global_name(id: &str, declarations: &HashMap<&str, &str>, names: &mut HashMap<String, String>) -> String {
    if let Some(name) = names.get(id) {
        return name.clone();
    }
    let declaration = declarations[id];
    let operands: Vec<String> = declaration
        .split(' ')
        .map(|word| match declarations.contains_key(word) && word != id {
            true => global_name(word, declarations, names),
            false => word.to_string(),
        })
        .collect();
    let name = format!("%g{}", kiln::store::hash(operands.join(" ").as_bytes()));
    names.insert(id.to_string(), name.clone());
    name
}

/// What of each fixture is built: what `kiln check` builds, the defaults and each keyword on its
/// own, of every shader.
const EVERY_KEYWORD: VariantSelection = VariantSelection::DefaultsAndEachKeyword;

/// The fixtures every build test builds.
pub const FIXTURES: &[&str] = &[
    "accepted",
    "bind_groups",
    "blocks",
    "compute",
    "dynamic",
    "half",
    "macros",
    "project",
    "runtime",
    "storage",
    "ubershader",
];

#[test]
fn every_fixture_ships_the_modules_its_whole_texts_give() {
    let test = "reach::every_fixture_ships_the_modules_its_whole_texts_give";
    if !tool("spirv-dis", "spirv-tools", test) {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let mut table = String::new();
    for fixture in FIXTURES {
        let project = root().join("fixtures").join(fixture);
        let (whole, cut) =
            (dir.path().join(format!("{fixture}-whole")), dir.path().join(format!("{fixture}-cut")));
        let (_, errors) = build_with(&project, &whole, ParseScope::Whole, EVERY_KEYWORD);
        assert!(errors.is_empty(), "{fixture}: {errors:?}");
        let (summary, errors) = build_with(&project, &cut, ParseScope::Reachable, EVERY_KEYWORD);
        assert!(errors.is_empty(), "{fixture}: {errors:?}");
        assert_eq!(summary.uncut, 0, "{fixture}: naga refused a cut its whole text passes");
        let comparison = compare(&whole, &cut, &dir.path().join(format!("{fixture}-spirv")));
        assert!(comparison.failures.is_empty(), "{fixture}: {:#?}", comparison.failures);
        let _ = writeln!(table, "{fixture}: {}", comparison.line());
    }
    expect_test::expect_file![root().join("tests/golden/reach/fixtures.txt")].assert_eq(&table);
}

/// A project of one shader whose program has a function no entry point calls.
fn project_with_unused(body: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("temp dir");
    let shader = format!(
        "Shader \"Cut\" {{ SubShader {{ Pass {{\nWGSLPROGRAM\n#pragma vertex vs\n#pragma fragment fs\n\
         fn unused() -> f32 {{ {body} }}\n\
         @vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {{ return vec4<f32>(f32(i)); }}\n\
         @fragment fn fs() -> @location(0) vec4<f32> {{ return vec4<f32>(1.0); }}\n\
         ENDWGSL\n}} }} }}\n"
    );
    std::fs::write(dir.path().join("Cut.shader"), shader).expect("shader");
    std::fs::write(dir.path().join("kiln.toml"), "always_include = [\"Cut\"]\n").expect("kiln.toml");
    dir
}

/// The same in HLSL, which glslang parses.
fn hlsl_project_with_unused() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("temp dir");
    let shader = "Shader \"Cut\" { SubShader { Pass {\nHLSLPROGRAM\n#pragma vertex vs\n#pragma fragment fs\n\
                  float unused() { return 1.0; }\n\
                  float4 vs(uint i : SV_VertexID) : SV_POSITION { return float4((float)i, 0.0, 0.0, 1.0); }\n\
                  float4 fs() : SV_TARGET { return float4(1.0, 1.0, 1.0, 1.0); }\n\
                  ENDHLSL\n} } }\n";
    std::fs::write(dir.path().join("Cut.shader"), shader).expect("shader");
    std::fs::write(dir.path().join("kiln.toml"), "always_include = [\"Cut\"]\n").expect("kiln.toml");
    dir
}

#[test]
fn a_cut_naga_refuses_is_built_whole_and_counted() {
    for project in [project_with_unused("return 1.0;"), hlsl_project_with_unused()] {
        a_cut_refused_is_built_whole(&project);
    }
}

/// A build whose cut of `fs` is spoiled (`KILN_INJECT_CUT_MISS`): its module is the whole text's,
/// and the miss is said.
fn a_cut_refused_is_built_whole(project: &tempfile::TempDir) {
    let out = tempfile::tempdir().expect("temp dir");
    let run = |inject: Option<&str>, output: &Path| {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"));
        command.arg("build").arg(project.path()).arg("--output").arg(output);
        if let Some(entry) = inject {
            command.env("KILN_INJECT_CUT_MISS", entry);
        }
        command.output().expect("kiln")
    };
    let spoiled = run(Some("fs"), &out.path().join("spoiled"));
    assert!(spoiled.status.success(), "{}", String::from_utf8_lossy(&spoiled.stderr));
    let plain = run(None, &out.path().join("plain"));
    assert!(plain.status.success());
    let (summary, errors) =
        build_with(project.path(), &out.path().join("whole"), ParseScope::Whole, VariantSelection::Used);
    assert!(errors.is_empty() && summary.uncut == 0);
    // The spoiled cut's module is the whole text's: the same bytes as `--parse-whole` gives.
    let modules = |dir: &str| {
        let manifest = kiln::manifest::Manifest::read(&out.path().join(dir)).expect("manifest");
        let read = |f: kiln::manifest::FileRef| f.read(&out.path().join(dir)).expect("module");
        manifest.stages().map(|s| (s.wgsl().map(read), s.spirv().map(read))).collect::<Vec<_>>()
    };
    assert_eq!(modules("spoiled")[1], modules("whole")[1]);
    let stderr = String::from_utf8_lossy(&spoiled.stderr);
    assert!(stderr.contains("1 built from the whole text"), "the miss is said:\n{stderr}");
    assert!(!String::from_utf8_lossy(&plain.stderr).contains("whole text"));
}

#[test]
fn an_error_no_entry_point_reaches_fails_kiln_check_and_not_kiln_build() {
    // Documented (docs/diagnostics.md): a build parses what its entry points reach.
    let project = project_with_unused("return undefined_name;");
    let out = tempfile::tempdir().expect("temp dir");
    let (summary, errors) =
        build_with(project.path(), out.path(), ParseScope::Reachable, VariantSelection::Used);
    assert!(errors.is_empty(), "{errors:?}");
    assert_eq!((summary.compiled, summary.uncut), (2, 0));
    let check = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .arg("check")
        .arg(project.path())
        .output()
        .expect("kiln");
    let stderr = String::from_utf8_lossy(&check.stderr);
    assert_eq!(check.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("K0401") && stderr.contains("undefined_name"), "{stderr}");
    let whole = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .arg("build")
        .arg(project.path())
        .arg("--parse-whole")
        .arg("--output")
        .arg(out.path().join("whole"))
        .output()
        .expect("kiln");
    assert_eq!(whole.status.code(), Some(1), "`--parse-whole` reports it as check does");
}

/// The HLSL fixtures and Unity's built-in unlit and UI shaders (with their own `CGIncludes`), each built from its whole stage texts and from the texts cut to what each entry
/// point reaches (`compile::hlsl_reach`): glslang refuses no cut text, and every module shipped is
/// the whole text's.
#[test]
fn hlsl_and_cg_cut_texts_ship_the_modules_their_whole_texts_give() {
    let test = "reach::hlsl_and_cg_cut_texts_ship_the_modules_their_whole_texts_give";
    if !tool("spirv-dis", "spirv-tools", test) {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    // Unity's shaders that build whole (no surface shader, no pass glslang or naga refuses).
    let unity = dir.path().join("unity");
    let corpus = root().join("tests/corpus/unity/Unity-Built-in-Shaders");
    let copied = [
        "CGIncludes",
        "DefaultResourcesExtra/Unlit",
        "DefaultResourcesExtra/UI/UI-CompositeOverdraw.shader",
        "DefaultResourcesExtra/UI/UI-Default.shader",
        "DefaultResourcesExtra/UI/UI-DefaultFont.shader",
        "DefaultResourcesExtra/UI/UI-Overdraw.shader",
        "DefaultResourcesExtra/UI/UI-Unlit-Detail.shader",
        "DefaultResourcesExtra/UI/UI-Unlit-Text.shader",
        "DefaultResourcesExtra/UI/UI-Unlit-TextDetail.shader",
        "DefaultResourcesExtra/UI/UI-Unlit-Transparent.shader",
    ];
    for path in copied {
        copy_tree(&corpus.join(path), &unity.join(path));
    }
    std::fs::write(
        unity.join("kiln.toml"),
        "shaders = [\"DefaultResourcesExtra\"]\ninclude_paths = [\"CGIncludes\"]\nglobal_keywords = []\n",
    )
    .expect("kiln.toml");
    let mut table = String::new();
    let projects = ["hlsl", "hlsl_lit", "compute_hlsl"].map(|f| root().join("fixtures").join(f));
    for project in projects.iter().chain([&unity]) {
        let name = project.file_name().expect("name").to_string_lossy().into_owned();
        let (whole, cut) = (dir.path().join(format!("{name}-whole")), dir.path().join(format!("{name}-cut")));
        let (whole_summary, errors) = build_with(project, &whole, ParseScope::Whole, EVERY_KEYWORD);
        assert!(errors.is_empty(), "{name}: {errors:#?}");
        let (summary, errors) = build_with(project, &cut, ParseScope::Reachable, EVERY_KEYWORD);
        assert!(errors.is_empty(), "{name}: {errors:#?}");
        assert_eq!(summary.uncut, 0, "{name}: glslang refused a cut its whole text passes");
        let comparison = compare(&whole, &cut, &dir.path().join(format!("{name}-spirv")));
        assert!(comparison.failures.is_empty(), "{name}: {:#?}", comparison.failures);
        let _ = writeln!(
            table,
            "{name}: {}; {} distinct stage texts whole, {} cut",
            comparison.line(),
            whole_summary.modules,
            summary.modules
        );
    }
    expect_test::expect_file![root().join("tests/golden/reach/hlsl.txt")].assert_eq(&table);
}
