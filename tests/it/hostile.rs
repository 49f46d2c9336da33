//! Names and paths from a project as an adversary writes them: the generated Rust compiles (cargo
//! checks it) with nothing injected, names that would become one identifier are refused with
//! both named, and no path reaches cargo's build-script protocol unless it can be said there.

use std::path::Path;

fn write(root: &Path, path: &str, text: &str) {
    let path = root.join(path);
    std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
    std::fs::write(path, text).expect("write");
}

/// A render shader named `name` with a uniform block of `members` (WGSL member declarations).
fn shader(name: &str, keyword: &str, struct_name: &str, members: &str) -> String {
    format!(
        "Shader \"{name}\" {{\n    SubShader {{\n        Pass {{\n            WGSLPROGRAM\n            \
         #pragma multi_compile _ {keyword}\n            #pragma vertex Vertex\n            #pragma fragment Fragment\n            \
         struct {struct_name} {{ {members} }}\n            \
         @group(1) @binding(0) var<uniform> block: {struct_name};\n            \
         @vertex fn Vertex(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {{ return vec4<f32>(p, block.last); }}\n            \
         @fragment fn Fragment() -> @location(0) vec4<f32> {{ return vec4<f32>(block.last); }}\n            \
         ENDWGSL\n        }}\n    }}\n}}\n"
    )
}

/// Shader names, keywords, struct and member names that the issue found breaking the generated
/// module, each in a shader of its own.
fn hostile_project(root: &Path) {
    let cases: [(&str, &str, &str, &str); 11] = [
        ("Inject/Doc", "_A", "S", ""),
        ("Core", "in", "S", "_pad0: f32, dyn: vec4<f32>,"),
        ("Box", "_B", "materials", "gen: f32, dyn_: f32,"),
        ("Self", "_C", "Default", "self_: u32,"),
        ("着色器", "_D", "S", ""),
        ("光照", "_E", "S", ""),
        ("\u{c5}", "_F", "S", ""),
        ("\u{212b}", "_G", "S", ""),
        ("Bidi \u{202e}kcilc", "_H", "Option", ""),
        ("Quote */ /* x", "_I", "S", ""),
        // The prelude's `variant`, the pass's keyword type and its `name` method.
        ("Variant", "name", "Pass0Keyword", ""),
    ];
    let mut names = Vec::new();
    for (n, (name, keyword, struct_name, members)) in cases.into_iter().enumerate() {
        let members = format!("{members} last: f32,");
        write(root, &format!("shaders/{n}.shader"), &shader(name, keyword, struct_name, &members));
        // TOML's basic strings take these characters as they are.
        names.push(format!("\"{name}\""));
    }
    write(root, "kiln.toml", &format!("shaders = [\"shaders\"]\nalways_include = [{}]\n", names.join(", ")));
}

/// The crate's `lib.rs`: every shader module by the name the rules give it, and the fields of the
/// structs whose member names the rules change, so that another spelling fails to compile.
const USES: &str = r#"#![allow(dead_code)]
pub mod shaders {
    include!("shaders.rs");
}

#[test]
fn names_are_the_shaders_own() {
    let names = [
        shaders::inject_doc::NAME,
        shaders::core_::NAME,
        shaders::r#box::NAME,
        shaders::self_::NAME,
        shaders::u7740_u8272_u5668::NAME,
        shaders::u5149_u7167::NAME,
        shaders::uc5::NAME,
        shaders::u212b::NAME,
        shaders::bidi_u202e_kcilc::NAME,
        shaders::quote_x::NAME,
        shaders::variant_::NAME,
    ];
    assert_eq!(names[4], "着色器");
    assert_eq!(names[6], "\u{c5}");
    assert_eq!(names[7], "\u{212b}");
    assert_eq!(names[8], "Bidi \u{202e}kcilc");
    assert_eq!(names[9], "Quote */ /* x");
    assert_eq!(shaders::core_::keywords::r#in, "in");
    let s = shaders::core_::S { _pad0: 0.0, _pad1: [0; 12], r#dyn: [0.0; 4], last: 0.0, _pad2: [0; 12] };
    assert_eq!(core::mem::size_of_val(&s), 48);
    let _ = shaders::r#box::materials_ { r#gen: 0.0, dyn_: 0.0, last: 0.0 };
    let _ = shaders::self_::Default_ { self_: 0, last: 0.0 };
    let _ = shaders::bidi_u202e_kcilc::Option_ { last: 0.0 };
    let _ = shaders::variant_::Pass0Keyword_ { last: 0.0 };
    use shaders::PassKeyword as _;
    assert_eq!(shaders::variant_::Pass0Keyword::name_.name(), "name");
    assert!(shaders::variant(&[shaders::variant_::Pass0Keyword::name_]).is_ok());
}
"#;

#[test]
fn hostile_names_make_a_generated_module_that_compiles_with_nothing_injected() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    hostile_project(&project);
    let out = dir.path().join("out");
    let built = kiln::Build::new(&project).out_dir(&out).execute().expect("the hostile project builds");
    assert_eq!(built.manifest.shaders.len(), 11, "every shader built");
    // A manifest is input too (`Build::prebuilt` takes another machine's): a file name with a
    // line break must not end the doc comment that names it.
    let mut manifest = built.manifest;
    manifest.shaders[0].file = "a\nfn injected() { compile_error!(\"injected\"); }\r\n//".into();
    let module = kiln::codegen::generate(&manifest, "kiln").expect("no names clash");
    assert!(
        !module.lines().any(|line| line.trim_start().starts_with("fn injected")),
        "a file name's line break ended a comment:\n{module}"
    );
    // Cargo compiles it and runs `USES`' test, which names every item as the rules spell it.
    std::fs::write(out.join("kiln_shaders.rs"), module).expect("write");
    crate::support::test_generated_module(&out, USES);
}

/// The rendered diagnostics of a build script's build that must fail.
fn build_script_errors(project: &Path, out: &Path) -> (String, Vec<String>) {
    match kiln::Build::new(project).out_dir(out).execute() {
        Err(kiln::BuildError::Diagnostics { rendered, cargo_lines }) => (rendered, cargo_lines),
        other => panic!("the build must fail with diagnostics: {other:?}"),
    }
}

#[test]
fn names_that_would_be_one_identifier_are_refused_with_both_named() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    write(&project, "shaders/a.shader", &shader("Custom/Lit", "_A", "S", "last: f32,"));
    write(&project, "shaders/b.shader", &shader("Custom Lit", "_B", "S", "last: f32,"));
    write(
        &project,
        "shaders/Kernels.compute",
        "#pragma kernel fooBar\n#pragma kernel foo_bar\nvar<storage, read_write> v: array<f32>;\n\
         @compute @workgroup_size(1) fn fooBar() { v[0] = 1.0; }\n\
         @compute @workgroup_size(1) fn foo_bar() { v[0] = 2.0; }\n",
    );
    write(
        &project,
        "kiln.toml",
        "shaders = [\"shaders\"]\nalways_include = [\"Custom/Lit\", \"Custom Lit\"]\n[compute.Kernels]\nvariants = [[]]\n",
    );
    let (rendered, _) = build_script_errors(&project, &dir.path().join("out"));
    expect_test::expect_file![crate::support::root().join("tests/golden/build/name_clash.stderr")]
        .assert_eq(&rendered);
    assert!(!dir.path().join("out/kiln_shaders.rs").exists(), "no module is written");
}

#[test]
fn a_path_with_a_line_break_never_reaches_cargo_and_the_build_says_why() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    write(&project, "shaders/a.shader", &shader("Plain", "_A", "S", "last: f32,"));
    write(&project, "kiln.toml", "shaders = [\"shaders\"]\nalways_include = [\"Plain\"]\n");
    // A material whose name is a second directive, as an attacker would name it.
    write(&project, "x\ncargo:rustc-cfg=evil\ncargo:rustc-link-arg=-lpwned\n.mat", "shader = \"Plain\"\n");
    let (rendered, cargo_lines) = build_script_errors(&project, &dir.path().join("out"));
    assert!(rendered.contains("error[K0420]: cargo cannot watch"), "{rendered}");
    assert!(rendered.contains("x\\ncargo:rustc-cfg=evil"), "the name is shown escaped: {rendered}");
    let refused: String = rendered
        .replace(&project.display().to_string(), "PROJECT")
        .lines()
        .skip_while(|l| !l.starts_with("error[K0420]"))
        .take_while(|l| !l.is_empty())
        .map(|l| format!("{l}\n"))
        .collect();
    expect_test::expect_file![crate::support::root().join("tests/golden/build/cargo_cannot_watch.stderr")]
        .assert_eq(&refused);
    for line in &cargo_lines {
        assert!(!line.contains('\n') && !line.contains("rustc-cfg=evil\n"), "{line:?}");
        assert!(
            line.starts_with("cargo:rerun-if-changed=") || line.starts_with("cargo:warning="),
            "{line:?}"
        );
    }
}

#[test]
fn project_paths_that_leave_the_project_are_refused_and_nothing_outside_is_quoted() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    write(&project, "shaders/a.shader", &shader("Plain", "_A", "S", "last: f32,"));
    // A file beside the project whose text a diagnostic would quote if kiln read it.
    write(dir.path(), "secret/Key.mat", "shader = \"AWS_SECRET_ACCESS_KEY=hunter2\"\n");
    write(
        &project,
        "kiln.toml",
        "shaders = [\"shaders\"]\nmaterials = [\".\", \"../secret\"]\ninclude_paths = ['/etc']\n\
         variant_logs = [\"/proc/self/environ\"]\nalways_include = [\"Plain\"]\n",
    );
    let run = crate::support::kiln_in(&project, &["check", "."]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("hunter2") && !stderr.contains("PATH="), "quoted a file outside: {stderr}");
    let refused: String =
        stderr.lines().take_while(|l| !l.starts_with("checked ")).map(|l| format!("{l}\n")).collect();
    expect_test::expect_file![crate::support::root().join("tests/golden/cli/outside_the_project.stderr")]
        .assert_eq(&refused);
}

#[test]
fn the_language_server_refuses_a_message_larger_than_its_limit_before_reading_it() {
    use std::io::Write as _;
    let mut server = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .arg("lsp")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("kiln lsp runs");
    // The header alone, and the input kept open: the server must not wait for 4 GB, nor make room.
    let mut stdin = server.stdin.take().expect("stdin");
    stdin.write_all(b"Content-Length: 4000000000\r\n\r\n").expect("write");
    stdin.flush().expect("flush");
    let run = crate::support::output_within_a_minute(server, "kiln lsp");
    drop(stdin);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_ne!(run.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("4000000000 bytes") && stderr.contains("limit"), "{stderr}");
}

#[test]
fn a_missing_include_outside_the_project_gets_no_suggestion_naming_what_is_there() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    let outside = shader("Plain", "_A", "S", "last: f32,").replace(
        "            #pragma vertex",
        "            #include \"/etc/hostnam\"\n            #pragma vertex",
    );
    write(&project, "shaders/a.shader", &outside);
    write(&project, "shaders/Tint.wgsl", "fn tint() -> f32 { return 1.0; }\n");
    let with_typo = shader("Typo", "_B", "S", "last: f32,").replace(
        "            #pragma vertex",
        "            #include \"Tnt.wgsl\"\n            #pragma vertex",
    );
    write(&project, "shaders/b.shader", &with_typo);
    let run = crate::support::kiln_in(&project, &["check", "."]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("`/etc/hostnam`"), "{stderr}");
    assert!(!stderr.contains("hostname"), "a name outside the project was suggested: {stderr}");
    // Inside the project the suggestion stays.
    assert!(stderr.contains("did you mean `Tint.wgsl`"), "{stderr}");
}

#[test]
fn ten_thousand_warnings_on_one_long_line_are_a_few_lines_of_output() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    // One pragma of 10,000 keywords (a 90 KB line): each is declared and never tested (K0320).
    // And 80,000 properties, which took 12.5 s to check for duplicates one against another.
    let keywords: Vec<String> = (0..10_000).map(|k| format!("_K{k}")).collect();
    let properties: String = (0..80_000).map(|p| format!("        _P{p} (\"P\", Float) = 0\n")).collect();
    let text = shader("Many", &keywords.join(" "), "S", "last: f32,")
        .replace("#pragma multi_compile _ ", "#pragma shader_feature _ ")
        .replace(
            "Shader \"Many\" {\n",
            &format!("Shader \"Many\" {{\n    Properties {{\n{properties}    }}\n"),
        );
    write(&project, "shaders/many.shader", &text);
    let run = crate::support::kiln_in(&project, &["list", "."]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.len() < 64 << 10, "{} bytes of diagnostics", stderr.len());
    assert!(stderr.contains("9990 more like the last, not shown"), "{}", &stderr[..stderr.len().min(4000)]);
    assert!(
        stderr.contains("(the line is over 1000 bytes: not quoted)"),
        "{}",
        &stderr[..stderr.len().min(4000)]
    );
}

#[test]
fn a_long_sum_builds_on_a_worker_s_stack_instead_of_aborting_the_process() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    // 24,000 terms: the issue's 5,000 (a 20 KB line) overflowed rayon's 2 MiB stacks, exit 134;
    // under the 50,000 operands and operators kiln takes in one function.
    let sum = vec!["x"; 24_000].join(" + ");
    let text = shader("Long", "_A", "S", "last: f32,").replace(
        "{ return vec4<f32>(block.last); }",
        &format!("{{ let x = block.last; let sum = {sum}; return vec4<f32>(sum); }}"),
    );
    write(&project, "shaders/long.shader", &text);
    write(&project, "kiln.toml", "shaders = [\"shaders\"]\nalways_include = [\"Long\"]\n");
    let run = crate::support::kiln_in(&project, &["check", "."]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{}", &stderr[..stderr.len().min(2000)]);
}
