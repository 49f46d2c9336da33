//! HLSL programs through glslang and naga: the same variants, layout and manifest as WGSL; the
//! constant buffers' packing against HLSL's rules written here fresh (and glslang's own
//! standalone validator, where it is installed); and the pixels an HLSL pass draws against its
//! WGSL twin's on the GPU (lavapipe in CI).

use crate::support::{build_without_errors, gpu, kiln, root, tool, verified_manifest};
use kiln::config::VariantSelection;
use kiln::manifest::{Manifest, PassManifest};
use kiln::project::{Request, build_project};
use kiln::runtime::{Drawable, PipelineRequest, Runtime};
use kiln::source::SourceStore;
use std::fmt::Write as _;
use std::path::Path;

fn pass<'a>(manifest: &'a Manifest, shader: &str) -> &'a PassManifest {
    let shader = manifest.shaders.iter().find(|s| s.name == shader).expect("shader built");
    &shader.passes[0]
}

#[test]
fn an_hlsl_pass_builds_every_variant_its_materials_use_with_one_layout_for_both_stages() {
    let output = tempfile::tempdir().expect("temp dir");
    build_without_errors(&root().join("fixtures/hlsl"), Some(output.path()), VariantSelection::Used);
    let manifest = verified_manifest(output.path());
    let unlit = pass(&manifest, "HLSL/Unlit");
    let mut keywords: Vec<Vec<String>> = unlit.variants.iter().map(|v| v.keywords.clone()).collect();
    keywords.sort();
    assert_eq!(keywords, [vec![], vec!["_CLIPPING".to_string()]]);
    // One slot per resource name for the whole pass, whatever glslang numbered each stage.
    let mut slots = std::collections::BTreeSet::new();
    for group in &unlit.layout {
        for entry in &group.entries {
            assert!(slots.insert((group.group, entry.binding)), "{} shares a slot", entry.name);
        }
    }
    let names: Vec<&str> = unlit.layout.iter().flat_map(|g| &g.entries).map(|e| e.name.as_str()).collect();
    for name in ["UnityPerDraw", "UnityPerFrame", "UnityPerMaterial", "_BaseMap", "sampler_BaseMap"] {
        assert!(names.contains(&name), "{name} missing from {names:?}");
    }
    let material =
        unlit.layout.iter().flat_map(|g| &g.entries).find(|e| e.name == "UnityPerMaterial").expect("entry");
    let visible = serde_json::to_value(&material.visibility).expect("json").to_string();
    assert!(visible.contains("vertex") && visible.contains("fragment"), "{visible}");
    // The vertex inputs are named as the HLSL struct names them.
    let inputs: Vec<&str> = unlit.interfaces[0].inputs.iter().map(|a| a.name.as_str()).collect();
    assert_eq!(inputs, ["positionOS", "baseUV"]);
    // The keyword reaches the HLSL: only the `_CLIPPING` fragment discards.
    for variant in &unlit.variants {
        let fragment = unlit.stage(variant.fragment.expect("fragment"));
        let wgsl = String::from_utf8(fragment.wgsl().expect("WGSL").read(output.path()).expect("read"))
            .expect("UTF-8");
        assert_eq!(wgsl.contains("discard"), !variant.keywords.is_empty(), "{:?}:\n{wgsl}", variant.keywords);
    }
}

#[test]
fn kiln_preprocess_and_reflect_work_on_an_hlsl_variant() {
    let reflected = kiln(&["reflect", "fixtures/hlsl/shaders/Unlit.shader", "--keywords", "_CLIPPING"]);
    assert!(reflected.status.success(), "{}", String::from_utf8_lossy(&reflected.stderr));
    let json: serde_json::Value = serde_json::from_slice(&reflected.stdout).expect("JSON");
    let names: Vec<&str> = json["layout"]
        .as_array()
        .expect("layout")
        .iter()
        .flat_map(|g| g["entries"].as_array().expect("entries"))
        .filter_map(|e| e["name"].as_str())
        .collect();
    assert!(names.contains(&"UnityPerMaterial") && names.contains(&"sampler_BaseMap"), "{names:?}");
    let printed = kiln(&["preprocess", "fixtures/hlsl/shaders/Unlit.shader", "--keywords", "_CLIPPING"]);
    assert!(printed.status.success(), "{}", String::from_utf8_lossy(&printed.stderr));
    let text = String::from_utf8(printed.stdout).expect("UTF-8");
    assert!(text.contains("cbuffer UnityPerMaterial") && text.contains("clip(base.a - _Cutoff)"), "{text}");
    assert!(!text.contains("#include") && !text.contains("#if"), "{text}");
}

/// A Unity shader inside its project: `kiln preprocess` and `kiln reflect` read the project's
/// `kiln.toml` (its `include_paths` give `UnityCG.cginc`), and `--reachable` prints the text a
/// build hands glslang, a small part of the whole.
#[test]
fn kiln_preprocess_and_reflect_take_a_unity_shader_s_includes_from_its_project() {
    let shader = "tests/corpus/unity/Unity-Built-in-Shaders/DefaultResourcesExtra/Unlit/Unlit-Normal.shader";
    let printed = |extra: &[&str]| {
        let run = kiln(&[&["preprocess", shader, "--stage", "vertex"], extra].concat());
        assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
        String::from_utf8(run.stdout).expect("UTF-8")
    };
    let (whole, cut) = (printed(&[]), printed(&["--reachable"]));
    assert!(whole.contains("UnityObjectToClipPos"), "UnityCG.cginc is spliced in");
    let lines = |text: &str| text.lines().filter(|l| !l.trim().is_empty()).count();
    assert!(cut.contains("v2f vert") && cut.contains("UnityObjectToClipPos"), "{cut}");
    assert!(lines(&cut) * 3 < lines(&whole), "cut {} of {} lines", lines(&cut), lines(&whole));
    let reflected = kiln(&["reflect", shader]);
    assert!(reflected.status.success(), "{}", String::from_utf8_lossy(&reflected.stderr));
    let json: serde_json::Value = serde_json::from_slice(&reflected.stdout).expect("JSON");
    let layout = json["layout"].to_string();
    assert!(layout.contains("\"_MainTex\"") && layout.contains("UnityPerDraw"), "{layout}");
}

// ---------------------------------------------------------------------------------------------
// HLSL's constant buffer packing, from its rules: a scalar or vector never straddles a 16-byte
// register; arrays and matrices start on a register; an array's elements (and a matrix's
// columns, column-major as HLSL packs by default) each take a register, the last unpadded.

#[derive(Clone, Copy, Debug)]
enum Member {
    /// `float`, `float2`, `float3`, `float4`.
    Vector(u32),
    /// `floatNxN`.
    Matrix(u32),
    /// `float4 x[n]` or `float x[n]`.
    Array(u32, u32),
}

impl Member {
    fn hlsl(self, name: &str) -> String {
        let vector = |n: u32| if n == 1 { "float".to_string() } else { format!("float{n}") };
        match self {
            Member::Vector(n) => format!("{} {name};", vector(n)),
            Member::Matrix(n) => format!("float{n}x{n} {name};"),
            Member::Array(n, count) => format!("{} {name}[{count}];", vector(n)),
        }
    }

    /// HLSL's offset after `end` and size.
    fn hlsl_place(self, end: u32) -> (u32, u32) {
        let register = |at: u32| at.div_ceil(16) * 16;
        match self {
            Member::Vector(n) => {
                let size = 4 * n;
                let straddles = end % 16 + size > 16;
                (if straddles { register(end) } else { end }, size)
            }
            Member::Matrix(n) => (register(end), 16 * (n - 1) + 4 * n),
            Member::Array(n, count) => (register(end), 16 * (count - 1) + 4 * n),
        }
    }

    /// WGSL's alignment, size and, for arrays, stride (the spec's table).
    fn wgsl(self) -> (u32, u32, Option<u32>) {
        let vector = |n: u32| (if n == 3 { 16 } else { 4 * n }, 4 * n);
        match self {
            Member::Vector(n) => (vector(n).0, vector(n).1, None),
            Member::Matrix(n) => (vector(n).0, n * vector(n).0, None),
            Member::Array(n, count) => {
                let (align, size) = vector(n);
                let stride = size.div_ceil(align) * align;
                (align, stride * count, Some(stride))
            }
        }
    }

    fn hlsl_stride(self) -> Option<u32> {
        matches!(self, Member::Array(..)).then_some(16)
    }
}

/// A small generator: the same cases on every run.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
}

fn random_member(rng: &mut Rng) -> Member {
    match rng.below(10) {
        0..=5 => Member::Vector(1 + rng.below(4) as u32),
        6 => Member::Matrix(if rng.below(2) == 0 { 3 } else { 4 }),
        7..=8 => Member::Array(4, 2 + rng.below(3) as u32),
        _ => Member::Array(1, 2 + rng.below(2) as u32),
    }
}

/// HLSL's offsets of a buffer's members, and whether WGSL's layout holds them all (each member on
/// its WGSL alignment, none inside the one before, arrays at WGSL's stride).
fn reference(members: &[Member]) -> (Vec<u32>, bool) {
    let (mut end, mut offsets) = (0, Vec::new());
    for member in members {
        let (offset, size) = member.hlsl_place(end);
        offsets.push(offset);
        end = offset + size;
    }
    let mut holds = true;
    for (i, member) in members.iter().enumerate() {
        let (align, size, stride) = member.wgsl();
        holds &= offsets[i] % align == 0;
        holds &= offsets.get(i + 1).is_none_or(|&next| next >= offsets[i] + size);
        holds &= stride == member.hlsl_stride();
    }
    (offsets, holds)
}

fn case_shader(index: usize, members: &[Member]) -> String {
    let mut declarations = String::new();
    let mut uses = String::new();
    for (i, member) in members.iter().enumerate() {
        let name = format!("m{i}");
        writeln!(declarations, "                {}", member.hlsl(&name)).expect("write");
        let read = match member {
            Member::Vector(n) => format!("{name}{}", if *n == 1 { "" } else { ".x" }),
            Member::Matrix(_) => format!("{name}[0].x"),
            Member::Array(n, _) => format!("{name}[1]{}", if *n == 1 { "" } else { ".x" }),
        };
        write!(uses, " + {read}").expect("write");
    }
    format!(
        "Shader \"Case/{index}\" {{\n    SubShader {{\n        Pass {{\n            HLSLPROGRAM\n            \
         #pragma vertex Vertex\n            #pragma fragment Fragment\n            cbuffer Block{index} {{\n\
         {declarations}            }};\n            float4 Vertex(float3 p : POSITION) : SV_POSITION {{ \
         return float4(p, 0.0{uses}); }}\n            float4 Fragment() : SV_TARGET {{ return 1; }}\n            \
         ENDHLSL\n        }}\n    }}\n}}\n"
    )
}

#[test]
fn constant_buffers_keep_hlsl_s_packing_or_are_refused_at_the_member() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut rng = Rng(0x6b69_6c6e);
    let (mut kept, mut refused) = (0, 0);
    for index in 0..48 {
        let members: Vec<Member> = (0..2 + rng.below(5)).map(|_| random_member(&mut rng)).collect();
        let (offsets, holds) = reference(&members);
        let project = dir.path().join(format!("case{index}"));
        std::fs::create_dir_all(&project).expect("mkdir");
        let shader = project.join("Case.shader");
        std::fs::write(&shader, case_shader(index, &members)).expect("write");
        let output = project.join("out");
        let mut store = SourceStore::new();
        let mode = Request {
            output: Some(output.clone()),
            unused_shaders: VariantSelection::All { limit: 16 },
            ..Request::default()
        };
        let (result, mut diagnostics) =
            build_project(&mut store, std::slice::from_ref(&shader), &mode, &|_, _| {}).expect("builds");
        diagnostics.extend(result.diagnostics);
        let rendered = kiln::diagnostics::render_plain(&store, &diagnostics);
        let what = format!("case {index} {members:?}, HLSL offsets {offsets:?}:\n{rendered}");
        if !holds {
            // Refused where the member is: K0427 (or naga's reader, K0426, for what it cannot
            // read at all), never a silent change.
            assert!(kiln::diagnostics::has_errors(&diagnostics), "kept what WGSL cannot hold: {what}");
            assert!(rendered.contains("K0427") || rendered.contains("K0426"), "{what}");
            refused += 1;
            continue;
        }
        assert!(!kiln::diagnostics::has_errors(&diagnostics), "refused: {what}");
        let manifest = verified_manifest(&output);
        let block = &manifest.shaders[0].passes[0].uniform_blocks[0];
        let found: Vec<u32> = block.members.iter().map(|m| m.offset).collect();
        assert_eq!(found, offsets, "{what}");
        // naga alone, reading the WGSL kiln wrote, lays the buffer out the same.
        let stage = manifest.stages().next().expect("a stage");
        let wgsl =
            String::from_utf8(stage.wgsl().expect("WGSL").read(&output).expect("read")).expect("UTF-8");
        let module = naga::front::wgsl::parse_str(&wgsl).unwrap_or_else(|e| panic!("{what}\n{e}\n{wgsl}"));
        // naga's namer writes `Block1_` for `Block1` (a name ending in a digit).
        let block_type = (module.types.iter()).find(|(_, t)| {
            t.name.as_deref().is_some_and(|n| n.trim_end_matches('_') == format!("Block{index}"))
        });
        let Some((_, ty)) = block_type else { panic!("no Block{index} in\n{wgsl}") };
        let naga::TypeInner::Struct { members: read, .. } = &ty.inner else { panic!("not a struct") };
        assert_eq!(read.iter().map(|m| m.offset).collect::<Vec<_>>(), offsets, "{what}\n{wgsl}");
        // The generated `#[repr(C)]` struct asserts the same offsets.
        let rust = kiln::codegen::generate(&manifest, "out").expect("names do not clash");
        for (i, offset) in offsets.iter().enumerate() {
            let asserted = rust
                .lines()
                .any(|l| l.contains("offset_of!(") && l.contains(&format!(", m{i}) == {offset})")));
            assert!(asserted, "the generated Rust places m{i} elsewhere than {offset}: {what}\n{rust}");
        }
        kept += 1;
    }
    println!("constant buffers: {kept} kept as HLSL packs them, {refused} refused");
    assert!(kept >= 10 && refused >= 10, "{kept} kept, {refused} refused: the cases cover too little");
}

#[test]
fn glslang_s_own_validator_packs_the_constant_buffers_as_the_manifest_says() {
    if !tool("glslangValidator", "glslang-tools", "glslang_s_own_validator_packs_the_constant_buffers") {
        return;
    }
    let output = tempfile::tempdir().expect("temp dir");
    build_without_errors(&root().join("fixtures/hlsl"), Some(output.path()), VariantSelection::Used);
    let manifest = verified_manifest(output.path());
    let unlit = pass(&manifest, "HLSL/Unlit");
    let printed = kiln(&["preprocess", "fixtures/hlsl/shaders/Unlit.shader", "--stage", "vertex"]);
    assert!(printed.status.success());
    let scratch = tempfile::tempdir().expect("temp dir");
    let text = scratch.path().join("Unlit.hlsl");
    std::fs::write(&text, &printed.stdout).expect("write");
    let run = std::process::Command::new("glslangValidator")
        .args(["-D", "-S", "vert", "-e", "UnlitPassVertex", "-V", "--target-env", "vulkan1.1", "-H", "-o"])
        .arg(scratch.path().join("Unlit.spv"))
        .arg(&text)
        .output()
        .expect("glslangValidator runs");
    let listing = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "{listing}");
    // `MemberName 56(UnityPerMaterial) 1  "_BaseColor"` and `MemberDecorate 56(UnityPerMaterial) 1 Offset 16`.
    let mut checked = 0;
    for block in &unlit.uniform_blocks {
        for (index, member) in block.members.iter().enumerate() {
            let named = format!("({}) {index}  \"{}\"", block.type_name, member.name);
            assert!(listing.contains(&named), "{named} not in glslang's listing");
            let offset = format!("({}) {index} Offset {}", block.type_name, member.offset);
            assert!(
                listing.contains(&offset),
                "glslang places {} elsewhere than {}",
                member.name,
                member.offset
            );
            checked += 1;
        }
    }
    assert!(checked >= 8, "{checked} members");
}

#[test]
fn an_hlsl_pass_draws_the_pixels_of_its_wgsl_twin() {
    let Some(gpu) = gpu("the HLSL pixel test") else { return };
    let output = tempfile::tempdir().expect("temp dir");
    build_without_errors(&root().join("fixtures/hlsl"), Some(output.path()), VariantSelection::Used);
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    let background = [0, 0, 255, 255];
    // What the fragment computes, by hand: red and green swapped by the matrix, scaled, mixed
    // with the tint (Mixed); clipped to the background (Clipped); written as it is (Kept).
    let expected: [(&str, [f64; 4]); 3] = [
        ("Mixed", [0.884375, 0.19375, 0.425, 1.0]),
        ("Clipped", [0.0, 0.0, 1.0, 1.0]),
        ("Kept", [0.1, 0.6, 0.8, 0.75]),
    ];
    for (case, want) in expected {
        let mut pixels = Vec::new();
        for language in ["Hlsl", "Wgsl"] {
            let name = format!("Pixels{language}{case}");
            let material = runtime.library().material(&name).expect("built material").clone();
            let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
            let shader = if language == "Hlsl" { "HLSL/Pixels" } else { "WGSL/Pixels" };
            let targets = crate::runtime::targets();
            let variant = runtime.variant(shader, 0, &keywords).expect("built variant");
            let request = PipelineRequest {
                variant,
                material: &material,
                targets: &targets,
                vertex_layout: None,
                overrides: &[],
            };
            let pipeline = runtime.pipeline(&request).unwrap_or_else(|e| panic!("{name}: {e}"));
            let pass = runtime.pass(shader, 0).expect("built pass");
            let group =
                runtime.material_bind_group(&material, pass, &()).unwrap_or_else(|e| panic!("{name}: {e}"));
            let drawable = Drawable::Ready(pipeline);
            let (pixel, _) = crate::runtime::draw_bound(&gpu, &drawable, &[(group.group, &group.bind_group)]);
            pixels.push(pixel);
        }
        let (hlsl, wgsl) = (pixels[0], pixels[1]);
        for (h, w) in hlsl.iter().zip(wgsl) {
            assert!(h.abs_diff(w) <= 1, "{case}: HLSL {hlsl:?}, WGSL {wgsl:?}");
        }
        assert_eq!(hlsl == background, case == "Clipped", "{case}: {hlsl:?}");
        for (channel, want) in hlsl.iter().zip(want) {
            assert!(
                (f64::from(*channel) / 255.0 - want).abs() <= 1.5 / 255.0,
                "{case}: {hlsl:?}, by hand {want:?}"
            );
        }
    }
}

/// An HLSL function past kiln's limit on one function's terms is refused before glslang reads it
/// (K0421, at the line it opens on), as a WGSL one is before naga: neither front end's time is
/// left unbounded by a hostile text.
#[test]
fn an_hlsl_function_past_the_limit_is_refused_before_glslang_reads_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    let statements: String = (0..9000).map(|i| format!("    x = x * 1.0001 + {i}.0;\n")).collect();
    let shader = format!(
        "Shader \"Hostile/Long\" {{ SubShader {{ Pass {{\nHLSLPROGRAM\n#pragma vertex Vertex\n#pragma fragment Fragment\n\
         float4 Vertex(float3 p : POSITION) : SV_POSITION {{ return float4(p, 1.0); }}\n\
         float4 Fragment() : SV_TARGET {{\n    float x = 0.0;\n{statements}    return x;\n}}\nENDHLSL\n}} }} }}\n"
    );
    let path = dir.path().join("Long.shader");
    std::fs::write(&path, shader).expect("write");
    let run = kiln(&["check", path.to_str().expect("UTF-8")]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[K0421]") && stderr.contains("past kiln's limit"), "{stderr}");
    assert!(stderr.contains("Long.shader:6:1"), "placed at the function's line: {stderr}");
}

/// HLSL modules are cached as WGSL ones are: a rebuild into the same output compiles nothing, a
/// build into a new output with the shared cache fetches every module, and the outputs are
/// byte for byte a cold build's.
#[test]
fn hlsl_modules_come_from_the_output_s_cache_and_the_shared_cache() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (cache, first, second) = (dir.path().join("cache"), dir.path().join("a"), dir.path().join("b"));
    let build = |output: &Path| {
        let mut store = SourceStore::new();
        let mode = Request {
            output: Some(output.to_path_buf()),
            cache_dir: Some(cache.clone()),
            ..Request::default()
        };
        let project = root().join("fixtures/hlsl");
        let (result, diagnostics) = build_project(&mut store, &[project], &mode, &|_, _| {}).expect("builds");
        assert!(diagnostics.iter().chain(&result.diagnostics).all(|d| !d.is_error()));
        result.summary
    };
    let cold = build(&first);
    assert!(cold.compiled >= 8, "{cold:?}");
    let again = build(&first);
    assert_eq!((again.compiled, again.reused), (0, cold.modules), "{again:?}");
    let fetched = build(&second);
    assert_eq!((fetched.compiled, fetched.reused), (0, cold.modules), "{fetched:?}");
    assert_eq!(crate::support::shipped(&first), crate::support::shipped(&second));
}

/// A Cg project whose include path has Unity's prelude files, rebuilt unchanged, is a no-op: the
/// `CGPROGRAM` prelude kiln makes in memory is not an input of its own (before, it kept the inputs
/// key from ever matching, and every rebuild preprocessed again). The prelude files here are
/// stand-ins: Unity's own test names no pragma declares (K0321), and a build that reports
/// anything records no no-op.
#[test]
fn an_unchanged_cg_project_with_unity_s_prelude_rebuilds_as_a_no_op() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = cg_project(dir.path(), "float4 _Tint;\n", "");
    let (first, said) = cg_build(&project);
    assert!(said.is_empty(), "{said}");
    assert!(first.manifest.is_some() && first.summary.compiled > 0, "the first build compiles");
    // A no-op reads no manifest and preprocesses nothing.
    let (again, said) = cg_build(&project);
    assert!(said.is_empty(), "{said}");
    assert!(again.manifest.is_none() && again.summary.preprocessed == 0, "{:?}", again.summary);
}

/// A Cg project on a two-file `CGIncludes/` (`variables` the second), with `settings` in its
/// `kiln.toml`.
pub(crate) fn cg_project(dir: &Path, variables: &str, settings: &str) -> std::path::PathBuf {
    let project = dir.join("cg");
    std::fs::create_dir_all(project.join("CGIncludes")).expect("mkdir");
    std::fs::write(project.join("CGIncludes/HLSLSupport.cginc"), "#define fixed4 float4\n").expect("write");
    std::fs::write(project.join("CGIncludes/UnityShaderVariables.cginc"), variables).expect("write");
    let shader = "Shader \"Cg/Tint\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n\
                  float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n\
                  fixed4 frag() : SV_Target { return _Tint; }\nENDCG\n} } }\n";
    std::fs::write(project.join("Tint.shader"), shader).expect("shader");
    let toml = format!("include_paths = [\"CGIncludes\"]\nglobal_keywords = []\n{settings}");
    std::fs::write(project.join("kiln.toml"), toml).expect("kiln.toml");
    std::fs::write(project.join("M.mat"), "shader = \"Cg/Tint\"\n").expect("material");
    project
}

/// A build of `project` into its own `build/`, and everything it said, rendered.
pub(crate) fn cg_build(project: &Path) -> (kiln::orchestrate::BuildResult, String) {
    let mut store = SourceStore::new();
    let (result, diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &Request::default(), &|_, _| {})
            .expect("project");
    let all: Vec<_> = diagnostics.into_iter().chain(result.diagnostics.iter().cloned()).collect();
    let said = kiln::diagnostics::render_plain(&store, &all);
    (result, said)
}

/// Unity's includes test macros no pragma declares (K0321 warnings): a build that said them is
/// still a no-op when nothing changed, and says them again, at the same places.
#[test]
fn an_unchanged_project_whose_includes_warn_is_a_no_op_that_says_the_warnings_again() {
    let dir = tempfile::tempdir().expect("temp dir");
    let variables = "#if defined(UNITY_SINGLE_PASS_STEREO)\nfloat4 _Eye;\n#endif\nfloat4 _Tint;\n";
    let project = cg_project(dir.path(), variables, "");
    let (first, said) = cg_build(&project);
    assert!(first.manifest.is_some(), "{said}");
    assert!(said.contains("warning[K0321]") && said.contains("UnityShaderVariables.cginc:1:"), "{said}");
    let (again, said_again) = cg_build(&project);
    assert!(again.manifest.is_none() && again.summary.preprocessed == 0, "{:?}", again.summary);
    assert_eq!(said_again, said, "the no-op says what the build said");
    // An edit to the include is seen: a full build, which says the warning where it now is.
    std::fs::write(project.join("CGIncludes/UnityShaderVariables.cginc"), format!("\n{variables}"))
        .expect("edit");
    let (edited, said) = cg_build(&project);
    assert!(edited.summary.preprocessed > 0, "{:?}", edited.summary);
    assert!(said.contains("UnityShaderVariables.cginc:2:"), "{said}");
}

/// Under `strict` the warnings a build says are errors, the catalogue's (K0321) and a pass's own
/// (K0316, found as its variants are preprocessed), and so are those a no-op says again.
#[test]
fn a_strict_project_s_no_op_fails_on_the_warnings_its_build_failed_on() {
    let dir = tempfile::tempdir().expect("temp dir");
    let variables =
        "#ifdef UNITY_SINGLE_PASS_STEREO\n#endif\n#define TWICE 1\n#define TWICE 2\nfloat4 _Tint;\n";
    let project = cg_project(dir.path(), variables, "strict = true\n");
    let (_, said) = cg_build(&project);
    assert!(said.contains("error[K0321]") && said.contains("error[K0316]"), "{said}");
    assert!(!said.contains("warning["), "{said}");
    let (again, said_again) = cg_build(&project);
    assert!(again.summary.preprocessed == 0, "a no-op: {:?}", again.summary);
    assert_eq!(said_again, said);
}
